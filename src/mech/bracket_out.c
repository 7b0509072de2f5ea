/*
 * src/mech/bracket_out.c - a Poisson bracket [F, G] or a rate dF/dt along
 * the motion written out as text, LaTeX or JSON (qd_phase_bracket_print,
 * qdot/canonical.h): what `qdot bracket` prints, for any caller.
 */
#include "qdot/canonical.h"
#include "qdot/json.h"
#include "qdot/print.h"
#include "base/args.h"

static void json_expr(qd_ctx *ctx, qd_json *j, const char *key, const qd_expr *x) {
    qd_json_key(j, key);
    qd_json_expr(j, ctx, x);
}

static void put_json(qd_ctx *ctx, const qd_phase *ph, const qd_expr *F, const qd_expr *G,
                     const qd_expr *r, qd_json *j) {
    qd_json_begin_object(j);
    qd_json_key(j, "momenta");
    qd_json_begin_array(j);
    for (size_t k = 0; k < ph->n; k++)
        qd_json_string(j, qd_expr_name(ph->p[k]));
    qd_json_end_array(j);
    json_expr(ctx, j, "F", F);
    if (!G) {
        json_expr(ctx, j, "H", ph->h->H);
        json_expr(ctx, j, "dF_dt", r);
        if (ph->h->implicit) { /* H and dF_dt are in q' too, defined by p = dL/dq' */
            qd_json_key(j, "implicit");
            qd_json_bool(j, true);
        }
    } else {
        json_expr(ctx, j, "G", G);
        json_expr(ctx, j, "bracket", r);
    }
    qd_json_end_object(j);
}

/* "[F, G] = r" or "d/dt(F) = r", in LaTeX \{F, G\} and \frac{d}{dt}. */
static qd_status put_line(qd_ctx *ctx, const qd_phase *ph, bool tex, const qd_expr *F,
                          const qd_expr *G, const qd_expr *r, qd_buf *b) {
    qd_format f = tex ? QD_FMT_LATEX : QD_FMT_TEXT;
    qd_buf_puts(b, G ? (tex ? "\\left\\{" : "[") : (tex ? "\\frac{d}{dt}\\left(" : "d/dt("));
    qd_status st = qd_print(ctx, F, f, b);
    if (G) {
        qd_buf_puts(b, ", ");
        st = st == QD_OK ? qd_print(ctx, G, f, b) : st;
    }
    qd_buf_puts(b, G ? (tex ? "\\right\\} = " : "] = ") : (tex ? "\\right) = " : ") = "));
    st = st == QD_OK ? qd_print(ctx, r, f, b) : st;
    qd_buf_puts(b, "\n");
    if (!G && ph->h->implicit)
        qd_buf_puts(b, tex ? "% q' solves p = dL/dq' (no closed form)\n"
                           : "  (q' solves p = dL/dq': no closed form)\n");
    return st == QD_ERR_NOMEM ? QD_OK : st; /* the buffer's failure is told below */
}

qd_status qd_phase_bracket_print(qd_ctx *ctx, const qd_phase *ph, const qd_expr *F,
                                 const qd_expr *G, const qd_expr *r, qd_format fmt, bool json,
                                 qd_buf *out) {
    QD_ARGS_CTX(ctx, ctx && ph && F && r && out);
    if ((ph->n && !ph->p) || (!G && !ph->h)) {
        qd_ctx_error(ctx, QD_ERR_ARG, "%s: %s", __func__,
                     !G && !ph->h ? "dF/dt needs H (qd_phase_dt or qd_phase_ham first)"
                                  : "the phase space has no momenta (qd_phase_init)");
        return QD_ERR_ARG;
    }
    if (!json && fmt != QD_FMT_TEXT && fmt != QD_FMT_LATEX) {
        qd_ctx_error(ctx, QD_ERR_ARG, "%s: a bracket is written as text, LaTeX or JSON",
                     __func__);
        return QD_ERR_ARG;
    }
    qd_buf b = QD_BUF_WITH(out->alloc);
    qd_json j;
    if (json) {
        qd_json_init(&j, &b);
        put_json(ctx, ph, F, G, r, &j);
        qd_buf_puts(&b, "\n");
    } else {
        qd_status st = put_line(ctx, ph, fmt == QD_FMT_LATEX, F, G, r, &b);
        if (st != QD_OK) {
            qd_buf_free(&b);
            return st;
        }
    }
    return qd_json_commit(ctx, &b, json ? &j : NULL, out);
}

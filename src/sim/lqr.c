/*
 * src/sim/lqr.c - an input of a simulation fed back by LQR (qdot/simsetup.h,
 * issue 31 "LQR on a model"): the model linearized about an operating point
 * read in its names, the CARE solved for the weights, and the input set to
 * u = u0 - K (x - x0), an expression in the state (qd_lqr_feedback), so the
 * integrator sees an input like any other.  What `qdot simulate --input
 * "F = lqr" --about ... --lqr ...` runs.
 */
#include "setup.h"

#include <ctype.h>
#include <stdlib.h>
#include <string.h>

#include "../base/args.h"
#include "qdot/read.h"
#include "qdot/state.h"

/* The error just recorded is about part (qd_sim_lqr.part). */
static qd_status fail(qd_sim_lqr *out, const char *part, qd_status st) {
    out->part = part;
    return st;
}

/* One item "NAME=VALUE" of text at [a, b): the symbol and its exact value. */
static qd_status point_item(qd_sim_setup *s, const char *text, size_t a, size_t b,
                            const qd_expr **sym, const qd_expr **val) {
    const char *eq = memchr(text + a, '=', b - a);
    if (!eq) {
        qd_ctx_error(s->ctx, QD_ERR_ARG, "expected NAME=VALUE, not '%.*s'", (int)(b - a),
                     text + a);
        qd_ctx_error_at(s->ctx, text, a, b - a);
        return QD_ERR_ARG;
    }
    size_t na = a, nb = (size_t)(eq - text);
    while (na < nb && isspace((unsigned char)text[na]))
        na++;
    while (nb > na && isspace((unsigned char)text[nb - 1]))
        nb--;
    char name[128];
    if (nb - na >= sizeof name || nb == na) {
        qd_ctx_error(s->ctx, QD_ERR_ARG, nb == na ? "a value without a name"
                                                   : "the name is too long");
        qd_ctx_error_at(s->ctx, text, na, nb > na ? nb - na : 1);
        return QD_ERR_ARG;
    }
    memcpy(name, text + na, nb - na);
    name[nb - na] = '\0';
    qd_diag err;
    const qd_read_opts ro = {.new_symbols = false};
    *sym = qd_read(s->ctx, name, &ro, &err);
    if (!*sym || qd_expr_kind(*sym) != QD_SYMBOL) {
        qd_ctx_clear_error(s->ctx);
        qd_ctx_error(s->ctx, QD_ERR_ARG, "'%s' is not a coordinate, velocity or input of the "
                     "model", name);
        qd_ctx_error_at(s->ctx, text, na, nb - na);
        return QD_ERR_ARG;
    }
    size_t va = (size_t)(eq - text) + 1;
    double v;
    return qd_state_value(s->ctx, s->m, text, va, b - va, val, &v);
}

/* The operating point text "NAME=VALUE, ..." into out->npt, syms, vals. */
static qd_status point_read(qd_sim_setup *s, const char *text, qd_sim_lqr *out) {
    size_t len = strlen(text), cap = len / 2 + 2;
    out->syms = calloc(2 * cap, sizeof *out->syms);
    if (!out->syms) {
        qd_ctx_error(s->ctx, QD_ERR_NOMEM, "out of memory");
        return QD_ERR_NOMEM;
    }
    out->vals = out->syms + cap;
    for (size_t i = 0; i < len;) {
        size_t end = qd_state_item_end(text, i);
        if (strspn(text + i, " \t") < end - i) {
            const qd_expr *sym, *val;
            qd_status st = point_item(s, text, i, end, &sym, &val);
            if (st != QD_OK)
                return st;
            for (size_t k = 0; k < out->npt; k++)
                if (out->syms[k] == sym) {
                    qd_ctx_error(s->ctx, QD_ERR_ARG, "%s is given twice", qd_expr_name(sym));
                    qd_ctx_error_at(s->ctx, text, i, end - i);
                    return QD_ERR_ARG;
                }
            out->syms[out->npt] = sym;
            out->vals[out->npt++] = val;
        }
        i = text[end] ? end + 1 : end;
    }
    return QD_OK;
}

qd_status qd_sim_setup_lqr(qd_sim_setup *s, const char *name, const char *about,
                           const char *weights, qd_sim_lqr *out) {
    QD_ARGS(QD_ERR_ARG, s);
    QD_ARGS_CTX(s->ctx, out);
    *out = (qd_sim_lqr){0};
    QD_ARGS_CTX(s->ctx, name && about && weights);
    if (!s->e) {
        qd_ctx_error(s->ctx, QD_ERR_ARG, "the feedback is designed on the equations in the "
                     "coordinates (a model given by T and V or L; with speeds, the "
                     "multiplier form)");
        return fail(out, "name", QD_ERR_ARG);
    }
    qd_status st = point_read(s, about, out);
    if (st != QD_OK)
        return fail(out, "about", st);
    if (qd_linearize(s->ctx, s->e, s->m, out->npt, out->syms, out->vals, &out->ss) != QD_OK)
        return fail(out, "point", qd_ctx_status(s->ctx));
    for (out->input = 0; out->input < out->ss.nu; out->input++)
        if (!strcmp(qd_expr_name(out->ss.inputs[out->input]), name))
            break;
    if (out->input == out->ss.nu) {
        qd_ctx_error(s->ctx, QD_ERR_ARG, "%s is not an input of the model", name);
        return fail(out, "name", QD_ERR_ARG);
    }
    if (qd_lqr_design(s->ctx, &out->ss, weights, &out->r) != QD_OK)
        return fail(out, "weights", qd_ctx_status(s->ctx));
    out->u = qd_lqr_feedback(s->ctx, &out->ss, &out->r, out->npt, out->syms, out->vals,
                             out->input);
    if (!out->u)
        return fail(out, "weights", qd_ctx_status(s->ctx));
    if (qd_sim_input_expr(s->sim, name, out->u) != QD_OK)
        return fail(out, "name", qd_ctx_status(s->ctx));
    return QD_OK;
}

qd_status qd_sim_lqr_note(const qd_sim_lqr *l, const char *prefix, qd_buf *out) {
    QD_ARGS(QD_ERR_ARG, l && prefix && out && l->u);
    const qd_statespace *s = &l->ss;
    const char *name = qd_expr_name(s->inputs[l->input]);
    qd_buf_printf(out, "%s%s = lqr: K =", prefix, name);
    for (size_t j = 0; j < s->nx; j++)
        qd_buf_printf(out, " %.6g (%s)", l->r.K[l->input * s->nx + j],
                      qd_expr_name(s->states[j]));
    qd_buf_printf(out, "; closed-loop eigenvalues, largest real part %.6g\n", l->r.eig_re[0]);
    /* away from an equilibrium x0 is no rest point of the loop: u0 - K (x -
     * x0) then regulates towards where the system cannot stay */
    for (size_t j = 0; j < s->nx; j++)
        if (s->xdot0[j] != 0) {
            qd_buf_printf(out, "%snote: the operating point is not an equilibrium (%s' = %.6g "
                          "there): the loop holds no rest at it\n", prefix, qd_expr_name(s->states[j]),
                          s->xdot0[j]);
            break;
        }
    return out->failed ? QD_ERR_NOMEM : QD_OK;
}

void qd_sim_lqr_free(qd_sim_lqr *l) {
    if (!l)
        return;
    qd_care_result_free(&l->r);
    qd_statespace_free(&l->ss);
    free(l->syms); /* vals live in the same block */
    *l = (qd_sim_lqr){0};
}

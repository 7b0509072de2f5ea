/*
 * src/linear/speeds_print.c - the equilibria and the modes of a model in
 * generalized speeds as text or JSON (qd_speeds_equilibria_print,
 * qdot/equilibria.h; qd_speeds_modes_print, qdot/modes.h): what `qdot
 * equilibria` and `qdot modes` print for a model with `speeds`, for any
 * caller.
 */
#include "qdot/equilibria.h"
#include "qdot/modes.h"
#include "qdot/json.h"
#include "qdot/print.h"
#include "qdot/speeds.h"
#include "../base/args.h"
#include "linear.h"

#include <math.h>

/* "a, b, c": the names of syms[j] for every j that pick marks (NULL: all). */
static void put_names(qd_buf *b, size_t n, const qd_expr *const *syms, const bool *pick) {
    bool first = true;
    for (size_t j = 0; j < n; j++)
        if (!pick || pick[j]) {
            qd_buf_printf(b, "%s%s", first ? "" : ", ", qd_expr_name(syms[j]));
            first = false;
        }
}

/* r appended to out when the printer succeeded: nothing on a JSON number
 * that is not finite (QD_ERR_NUMERIC) or a buffer that ran out. */
static qd_status finish(qd_ctx *ctx, qd_buf *b, bool ok, qd_buf *out, const char *what) {
    bool nomem = b->failed;
    if (ok && !nomem)
        qd_buf_putn(out, qd_buf_str(b), b->len);
    qd_buf_free(b);
    if (!ok && !nomem) {
        qd_ctx_error(ctx, QD_ERR_NUMERIC, "a number of the %s is not finite", what);
        return QD_ERR_NUMERIC;
    }
    if (nomem || out->failed) {
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory");
        return QD_ERR_NOMEM;
    }
    return QD_OK;
}

/* ---- equilibria --------------------------------------------------------------- */

static void eq_text(qd_ctx *ctx, const qd_speeds_eom *e, const qd_speeds_equilibria *s,
                    qd_buf *b) {
    const qd_equilibria *eq = &s->eq;
    qd_buf_printf(b, "%zu equilibri%s (%s%s) with every speed 0: ", eq->count,
                  eq->count == 1 ? "um" : "a", eq->method,
                  eq->exact ? ": the complete set, angles in (-pi, pi]" : "");
    put_names(b, e->m, e->u, NULL);
    qd_buf_puts(b, "\n");
    /* a family within the solved coordinates is sampled: a few samples say it */
    size_t shown = eq->continuum && eq->count > 10 ? 10 : eq->count;
    for (size_t i = 0; i < shown; i++) {
        const qd_equilibrium *p = &eq->pts[i];
        qd_buf_printf(b, "%3zu  ", i + 1);
        for (size_t j = 0; j < s->nsolved; j++) {
            qd_buf_printf(b, "%s%s = ", j ? ", " : "", qd_expr_name(e->q[s->solved[j]]));
            if (p->exact) {
                qd_print(ctx, p->exact[j], QD_FMT_TEXT, b);
                if (!qd_is_number(p->exact[j])) {
                    qd_buf_puts(b, " (");
                    qd_buf_put_result(b, p->q[j], 1);
                    qd_buf_puts(b, ")");
                }
            } else {
                qd_buf_put_result(b, p->q[j], 1);
            }
        }
        if (!s->nsolved)
            qd_buf_puts(b, "any configuration");
        if (p->residual < 1e-14)
            qd_buf_puts(b, ", residual < 1e-14\n");
        else
            qd_buf_printf(b, ", residual %.3g\n", p->residual);
    }
    if (shown < eq->count)
        qd_buf_printf(b, "  ... and %zu more samples (--format json lists them all)\n",
                      eq->count - shown);
    if (eq->continuum && s->nsolved)
        qd_buf_puts(b, "note: these equilibria are not isolated (a family along a null "
                       "direction of the equations at rest); the points listed are samples "
                       "of it\n");
    if (s->nsolved < e->n) {
        qd_buf_puts(b, "free (any value: no equation at rest involves them): ");
        put_names(b, e->n, e->q, s->free_coord);
        qd_buf_puts(b, "\n");
    }
    qd_buf_printf(b, "note: at rest u = 0 and f_u(q, 0) = 0: %zu equation%s not identically 0 "
                     "in %zu coordinate%s\n", s->nrows, s->nrows == 1 ? "" : "s", e->n,
                  e->n == 1 ? "" : "s");
}

static bool eq_json(qd_ctx *ctx, const qd_speeds_eom *e, const qd_speeds_equilibria *s,
                    qd_buf *b) {
    const qd_equilibria *eq = &s->eq;
    qd_json j;
    qd_json_init(&j, b);
    qd_json_begin_object(&j);
    qd__lin_eq_json_head(&j, eq);
    qd_json_key(&j, "speeds");
    qd_json_begin_array(&j);
    for (size_t k = 0; k < e->m; k++)
        qd_json_string(&j, qd_expr_name(e->u[k]));
    qd_json_end_array(&j);
    qd_json_key(&j, "free");
    qd_json_begin_array(&j);
    for (size_t k = 0; k < e->n; k++)
        if (s->free_coord[k])
            qd_json_string(&j, qd_expr_name(e->q[k]));
    qd_json_end_array(&j);
    qd_json_key(&j, "equilibria");
    qd_json_begin_array(&j);
    for (size_t i = 0; i < eq->count; i++) {
        const qd_equilibrium *p = &eq->pts[i];
        qd_json_begin_object(&j);
        qd__lin_eq_point_json(ctx, &j, p, s->nsolved, e->q, s->solved);
        qd_json_key(&j, "residual");
        qd_json_number(&j, p->residual);
        qd_json_end_object(&j);
    }
    qd_json_end_array(&j);
    qd_json_end_object(&j);
    qd_buf_puts(b, "\n");
    return qd_json_ok(&j);
}

qd_status qd_speeds_equilibria_print(qd_ctx *ctx, const struct qd_speeds_eom *e,
                                     const qd_speeds_equilibria *s, bool json, qd_buf *out) {
    QD_ARGS_CTX(ctx, ctx && e && s && out);
    if (s->n != e->n || (s->eq.count && !s->eq.pts) || (e->n && !s->free_coord) ||
        (s->nsolved && !s->solved)) {
        qd_ctx_error(ctx, QD_ERR_ARG, "qd_speeds_equilibria_print: equilibria not of these "
                                      "equations");
        return QD_ERR_ARG;
    }
    qd_buf b = QD_BUF_WITH(out->alloc);
    bool ok = true;
    if (json)
        ok = eq_json(ctx, e, s, &b);
    else
        eq_text(ctx, e, s, &b);
    return finish(ctx, &b, ok, out, "equilibria");
}

/* ---- modes ---------------------------------------------------------------------- */

/* The value of x in the state; NaN when it has none. */
static double value_of(size_t nvals, const qd_expr *const *syms, const double *vals,
                       const qd_expr *x) {
    for (size_t k = 0; k < nvals; k++)
        if (syms[k] == x)
            return vals[k];
    return NAN;
}

static const char *verdict_text(int stable) {
    return stable == 1 ? "stable (every Re s <= 0; the zero roots semisimple: neighbouring "
                         "steady motions)"
         : stable == 0 ? "unstable"
                       : "borderline (zero or imaginary roots that repeat without as many "
                         "eigenvectors: the linear motion may drift)";
}

/* What the modes printers read. */
typedef struct modes_view {
    const qd_speeds_eom *e;
    size_t nvals;
    const qd_expr *const *syms;
    const double *vals;
    const qd_speeds_linear *lin;
    const qd_modes_result *res;
} modes_view;

/* Coordinate k < n of e, else speed k - n. */
static const qd_expr *state_sym(const qd_speeds_eom *e, size_t k) {
    return k < e->n ? e->q[k] : e->u[k - e->n];
}

static void modes_text(const modes_view *v, qd_buf *b) {
    const qd_speeds_eom *e = v->e;
    const qd_speeds_linear *lin = v->lin;
    const qd_modes_result *res = v->res;
    qd_buf_puts(b, "state: ");
    for (size_t k = 0; k < e->n + e->m; k++) {
        const qd_expr *x = state_sym(e, k);
        qd_buf_printf(b, "%s%s = ", k ? ", " : "", qd_expr_name(x));
        qd_buf_put_result(b, value_of(v->nvals, v->syms, v->vals, x), 1);
    }
    qd_buf_puts(b, "\nreduced system: (");
    for (size_t i = 0; i < lin->nkept; i++)
        qd_buf_printf(b, "%s, ", qd_expr_name(e->q[lin->kept[i]]));
    put_names(b, e->m, e->u, NULL);
    qd_buf_puts(b, ")");
    if (lin->nkept < e->n) {
        qd_buf_puts(b, "; ignorable, dropped: ");
        put_names(b, e->n, e->q, lin->ignorable);
    }
    double rate = 0;
    for (size_t i = 0; i < lin->dim; i++)
        rate = fmax(rate, fabs(lin->rate[i]));
    qd_buf_puts(b, "\n");
    if (rate > 1e-8)
        qd_buf_printf(b, "note: not a stationary point of the reduced system: |y'| = %.3g "
                         "there; the linearization drops it\n", rate);
    qd_buf_printf(b, "eigenvalues s of its Jacobian (%zu):\n", res->neig);
    double big = 0;
    for (size_t i = 0; i < res->neig; i++)
        big = fmax(big, hypot(res->eig_re[i], res->eig_im[i]));
    for (size_t i = 0; i < res->neig; i++) {
        /* round-off about 0 is not printed: the verdict already judged it */
        double re = res->eig_re[i], im = res->eig_im[i];
        re = fabs(re) <= 1e-12 * big ? 0 : re;
        im = fabs(im) <= 1e-12 * big ? 0 : im;
        qd_buf_printf(b, "  s = %.10g %s %.10gi", re, im < 0 ? "-" : "+", fabs(im));
        if (im > 0)
            qd_buf_printf(b, "  (frequency %.10g rad/s)", im);
        qd_buf_puts(b, "\n");
    }
    qd_buf_printf(b, "%s\n", verdict_text(res->stable));
}

static bool modes_json(const modes_view *v, qd_buf *b) {
    const qd_speeds_eom *e = v->e;
    const qd_speeds_linear *lin = v->lin;
    const qd_modes_result *res = v->res;
    qd_json j;
    qd_json_init(&j, b);
    qd_json_begin_object(&j);
    qd_json_key(&j, "state");
    qd_json_begin_object(&j);
    for (size_t k = 0; k < e->n + e->m; k++) {
        const qd_expr *x = state_sym(e, k);
        qd_json_key(&j, qd_expr_name(x));
        qd_json_number(&j, value_of(v->nvals, v->syms, v->vals, x));
    }
    qd_json_end_object(&j);
    qd_json_key(&j, "kept");
    qd_json_begin_array(&j);
    for (size_t i = 0; i < lin->nkept; i++)
        qd_json_string(&j, qd_expr_name(e->q[lin->kept[i]]));
    qd_json_end_array(&j);
    qd_json_key(&j, "ignorable");
    qd_json_begin_array(&j);
    for (size_t i = 0; i < e->n; i++)
        if (lin->ignorable[i])
            qd_json_string(&j, qd_expr_name(e->q[i]));
    qd_json_end_array(&j);
    qd_json_key(&j, "eigenvalues");
    qd_json_begin_array(&j);
    for (size_t i = 0; i < res->neig; i++) {
        qd_json_begin_array(&j);
        qd_json_number(&j, res->eig_re[i]);
        qd_json_number(&j, res->eig_im[i]);
        qd_json_end_array(&j);
    }
    qd_json_end_array(&j);
    qd_json_key(&j, "verdict");
    qd_json_string(&j, res->stable == 1 ? "stable" : res->stable == 0 ? "unstable"
                                                                         : "borderline");
    qd_json_key(&j, "stable");
    if (res->stable < 0)
        qd_json_null(&j);
    else
        qd_json_bool(&j, res->stable == 1);
    qd_json_end_object(&j);
    qd_buf_puts(b, "\n");
    return qd_json_ok(&j);
}

qd_status qd_speeds_modes_print(qd_ctx *ctx, const struct qd_speeds_eom *e, size_t nvals,
                                const qd_expr *const *syms, const double *vals,
                                const qd_speeds_linear *lin, const qd_modes_result *res,
                                bool json, qd_buf *out) {
    QD_ARGS_CTX(ctx, ctx && e && (syms || !nvals) && (vals || !nvals) && lin && res && out);
    if (lin->n != e->n || lin->m != e->m || (lin->nkept && !lin->kept) ||
        (e->n && !lin->ignorable) || (lin->dim && !lin->rate) ||
        (res->neig && (!res->eig_re || !res->eig_im))) {
        qd_ctx_error(ctx, QD_ERR_ARG, "qd_speeds_modes_print: a linearization or result not "
                                      "of these equations");
        return QD_ERR_ARG;
    }
    const modes_view v = {e, nvals, syms, vals, lin, res};
    qd_buf b = QD_BUF_WITH(out->alloc);
    bool ok = true;
    if (json)
        ok = modes_json(&v, &b);
    else
        modes_text(&v, &b);
    return finish(ctx, &b, ok, out, "modes");
}

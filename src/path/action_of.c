/*
 * src/path/action_of.c - the action of a trial path and the size of its
 * first variation (Desloge ch. 83, Problems 1-3: trial paths compared).
 *
 * The path q_j = path_j(t) and its derivatives are substituted into L and
 * into Lagrange's residual r = M q'' - f (that is d/dt dL/dq' - dL/dq
 * + dD/dq' - Q, the forces and dissipation already in f), symbolically;
 * the results are compiled once and integrated over [t0, t1] by the
 * library's adaptive tanh-sinh rule (qd__num_quad_finite): the integrands
 * are smooth, where it converges double-exponentially, and it needs no
 * rule of its own here.  The first variation's size is the L2 norm
 * sqrt(integral of sum_j r_j^2 dt): 0 on a true path, and for a path
 * q + eps eta it is of order eps.
 */
#include "qdot/path.h"
#include "qdot/eval.h"

#include <math.h>

#include "base/mem.h"
#include "num/num.h"
#include "../base/args.h"

#define AO_TOL 1e-12

typedef struct ao {
    qd_prog *prog;
    size_t nout;
    double *in, *out;
} ao;

static double action_fn(void *data, double x, double xc) {
    ao *a = data;
    (void)xc;
    a->in[0] = x;
    qd_prog_run(a->prog, a->in, a->out);
    return a->out[0];
}

static double residual_fn(void *data, double x, double xc) {
    ao *a = data;
    (void)xc;
    a->in[0] = x;
    qd_prog_run(a->prog, a->in, a->out);
    double s = 0;
    for (size_t j = 1; j < a->nout; j++)
        s += a->out[j] * a->out[j];
    return s;
}

/* A trial path is a function of t and the parameters only. */
static qd_status check_path(qd_ctx *ctx, const qd_eom *e, size_t j, const qd_expr *p) {
    const qd_expr *sy[64];
    size_t ns = qd_free_symbols(ctx, p, sy, 64);
    if (ns > 64) {
        qd_ctx_error(ctx, QD_ERR_TOOBIG, "the trial path of %s has more than 64 symbols",
                     qd_expr_name(e->q[j]));
        return QD_ERR_TOOBIG;
    }
    for (size_t i = 0; i < ns; i++) {
        qd_role r = qd_symbol_role(sy[i]);
        if (r != QD_ROLE_TIME && r != QD_ROLE_PARAM) {
            qd_ctx_error(ctx, QD_ERR_ARG, "the trial path of %s names %s: a trial path is an "
                         "expression in t and the parameters", qd_expr_name(e->q[j]),
                         qd_expr_name(sy[i]));
            return QD_ERR_ARG;
        }
    }
    return qd_ctx_status(ctx) == QD_ERR_NOMEM ? QD_ERR_NOMEM : QD_OK;
}

/* outs[0] = L and outs[1 + j] = (M q'' - f)_j along the path. */
static qd_status integrands(qd_ctx *ctx, const qd_eom *e, const qd_expr *const *path,
                            const qd_expr **from, const qd_expr **to, const qd_expr **outs) {
    size_t n = e->n;
    const qd_expr *t = qd_time(ctx);
    for (size_t j = 0; j < n; j++) {
        qd_status st = check_path(ctx, e, j, path[j]);
        if (st != QD_OK)
            return st;
        from[j] = e->q[j], from[n + j] = e->qd[j], from[2 * n + j] = e->qdd[j];
        to[j] = path[j];
        to[n + j] = qd_diff(ctx, path[j], t);
        to[2 * n + j] = to[n + j] ? qd_diff(ctx, to[n + j], t) : NULL;
        if (!to[2 * n + j])
            return qd_ctx_status(ctx);
    }
    outs[0] = qd_subs(ctx, e->L, 3 * n, from, to);
    for (size_t j = 0; j < n && outs[0]; j++) {
        const qd_expr *r = qd_neg(ctx, e->f[j]);
        for (size_t k = 0; k < n && r; k++)
            r = qd_add(ctx, r, qd_mul(ctx, e->M[j * n + k], e->qdd[k]));
        outs[1 + j] = r ? qd_subs(ctx, r, 3 * n, from, to) : NULL;
        if (!outs[1 + j])
            return qd_ctx_status(ctx);
    }
    return outs[0] ? QD_OK : qd_ctx_status(ctx);
}

/* Compile outs over (t, parameters) with the model's parameter values. */
static qd_status compile(qd_ctx *ctx, const qd_model *m, const qd_expr *const *outs, ao *a) {
    size_t np = qd_model_nparams(m);
    const qd_expr **in = qd__calloc(ctx, 1 + np, sizeof *in);
    a->in = qd__calloc(ctx, 1 + np + a->nout, sizeof *a->in);
    if (!in || !a->in) {
        qd__free(in);
        return QD_ERR_NOMEM;
    }
    a->out = a->in + 1 + np;
    in[0] = qd_time(ctx);
    qd_status st = QD_OK;
    for (size_t i = 0; i < np && st == QD_OK; i++) {
        in[1 + i] = qd_model_param(m, i);
        if (qd_model_param_number(m, i, &a->in[1 + i]) != QD_OK) {
            qd_ctx_error(ctx, QD_ERR_ARG, "parameter %s has no finite value",
                         qd_expr_name(in[1 + i]));
            st = QD_ERR_ARG;
        }
    }
    if (st == QD_OK) {
        a->prog = qd_prog_new(ctx, 1 + np, in, a->nout, outs);
        st = a->prog ? QD_OK : qd_ctx_status(ctx);
    }
    qd__free(in);
    return st;
}

static qd_status integrate(qd_ctx *ctx, qd__num_fn fn, ao *a, double t0, double t1,
                           const char *what, double *out) {
    qd__num_quad r;
    if (!qd__num_quad_finite(fn, a, t0, t1, AO_TOL, &r) || !isfinite(r.value)) {
        qd_ctx_error(ctx, QD_ERR_NUMERIC, "the %s of the trial path did not converge on "
                     "[%g, %g] (estimate %g, error %g): is the path finite there?", what, t0,
                     t1, r.value, r.error);
        return QD_ERR_NUMERIC;
    }
    *out = r.value;
    return QD_OK;
}

static qd_status check_args(qd_ctx *ctx, const qd_eom *e, const qd_expr *const *path,
                            double t0, double t1) {
    if (e->ncon > 0) {
        qd_ctx_error(ctx, QD_ERR_ARG, "the action of a trial path: not yet for constrained "
                     "models (%zu constraint%s): eliminate them into the coordinates", e->ncon,
                     e->ncon == 1 ? "" : "s");
        return QD_ERR_ARG;
    }
    for (size_t j = 0; j < e->n; j++)
        if (!path[j]) {
            qd_ctx_error(ctx, QD_ERR_ARG, "no trial path for %s", qd_expr_name(e->q[j]));
            return QD_ERR_ARG;
        }
    if (!(isfinite(t0) && isfinite(t1) && t1 > t0)) {
        qd_ctx_error(ctx, QD_ERR_ARG, "the action of a trial path: t1 (%g) must be after t0 "
                     "(%g)", t1, t0);
        return QD_ERR_ARG;
    }
    return QD_OK;
}

qd_status qd_path_action_of(qd_ctx *ctx, const qd_model *m, const qd_eom *e,
                            const qd_expr *const *path, double t0, double t1, double *action,
                            double *first_variation) {
    QD_ARGS_CTX(ctx, ctx && m && e && path && action && first_variation);
    if (!ctx || !m || !e || !path) {
        if (ctx)
            qd_ctx_error(ctx, QD_ERR_ARG, "qd_path_action_of: a NULL argument");
        return QD_ERR_ARG;
    }
    qd_status st = check_args(ctx, e, path, t0, t1);
    if (st != QD_OK)
        return st;
    size_t n = e->n;
    const qd_expr **buf = qd__calloc(ctx, 7 * n + 1, sizeof *buf);
    if (!buf)
        return QD_ERR_NOMEM;
    ao a = {.nout = 1 + n};
    st = integrands(ctx, e, path, buf, buf + 3 * n, buf + 6 * n);
    if (st == QD_OK)
        st = compile(ctx, m, buf + 6 * n, &a);
    double S = 0, v2 = 0;
    if (st == QD_OK && action)
        st = integrate(ctx, action_fn, &a, t0, t1, "action", &S);
    if (st == QD_OK && first_variation)
        st = integrate(ctx, residual_fn, &a, t0, t1, "first variation", &v2);
    if (st == QD_OK && action)
        *action = S;
    if (st == QD_OK && first_variation)
        *first_variation = sqrt(fmax(v2, 0));
    qd_prog_free(a.prog);
    qd__free(a.in);
    qd__free(buf);
    return st;
}

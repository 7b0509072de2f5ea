/*
 * src/rel/proper.c - proper time along a worldline given by its velocity
 * v(t): tau = integral sqrt(1 - v.v/c^2) dt (Desloge vol. 2 ch. 87, ch. 91
 * dtau^2 = -ds^2/c^2; reference seed-desloge-D.md C6), by the numerics
 * home's adaptive tanh-sinh rule with its error estimate.
 */
#include "base/args.h"
#include "rel.h"

#include "num/num.h"
#include "qdot/eval.h"

#include <math.h>

typedef struct tau_fn {
    qd_prog *prog;
    double c, vmax, bad_t;
    bool bad;
} tau_fn;

static double integrand(void *data, double t, double tc) {
    (void)tc;
    tau_fn *f = data;
    double v[3];
    qd_prog_run(f->prog, &t, v);
    double v2 = qd__rel_dot(v, v);
    if (!isfinite(v2) || v2 >= f->c * f->c) {
        if (!f->bad)
            f->bad_t = t;
        f->bad = true;
        return NAN;
    }
    f->vmax = fmax(f->vmax, sqrt(v2));
    double b = sqrt(v2) / f->c;
    return sqrt((1 - b) * (1 + b));
}

qd_status qd_rel_proper_time(qd_ctx *ctx, double c, const qd_expr *const v[3], double t0,
                             double t1, double tol, qd_rel_tau *out) {
    QD_ARGS_CTX(ctx, ctx && v && out);
    *out = (qd_rel_tau){0};
    if (!(c > 0) || !isfinite(c) || !(t1 >= t0) || !isfinite(t1 - t0)) {
        qd_ctx_error(ctx, QD_ERR_ARG,
                     "proper time needs c > 0 and an interval t0 <= t1 (c = %g, t0 = %g, t1 = %g)",
                     c, t0, t1);
        return QD_ERR_ARG;
    }
    const qd_expr *t = qd_time(ctx);
    tau_fn f = {.c = c};
    f.prog = t ? qd_prog_new(ctx, 1, &t, 3, v) : NULL;
    if (!f.prog)
        return qd_ctx_status(ctx) != QD_OK ? qd_ctx_status(ctx) : QD_ERR_NOMEM;
    qd__num_quad q = {.value = 0, .converged = true};
    bool ok = t1 == t0 || qd__num_quad_finite(integrand, &f, t0, t1, tol > 0 ? tol : 1e-12, &q);
    qd_prog_free(f.prog);
    out->tau = q.value;
    out->error = q.error;
    out->evals = q.evals;
    out->vmax = f.vmax;
    if (f.bad) {
        qd_ctx_error(ctx, QD_ERR_ARG,
                     "the speed reaches c = %g (or is not finite) at t = %.17g: a worldline "
                     "stays below the speed of light", c, f.bad_t);
        return QD_ERR_ARG;
    }
    if (!ok) {
        qd_ctx_error(ctx, QD_ERR_NUMERIC,
                     "the proper-time quadrature did not converge (estimate %.17g, error %g)",
                     q.value, q.error);
        return QD_ERR_NUMERIC;
    }
    return QD_OK;
}

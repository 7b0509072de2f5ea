/*
 * src/sym/tangent.c - forward-mode Jacobians of compiled programs
 * (qdot/tangent.h): the Taylor mode of the program (taylor_prog.c) at order
 * 1.  Order 0 runs once per point; then each varying input in turn gets the
 * coefficient 1 (the others 0) and order 1 runs, so the outputs' order-1
 * coefficients are one column of the Jacobian (Griewank and Walther 2008,
 * ch. 3: the tangent of a straight-line program).
 */
#include "sym_export.h"
#include "qdot/tangent.h"
#include "base/mem.h"

#include <math.h>
#include <string.h>

struct qd_tangent {
    qd_prog *prog;
    qd__tay *tay;
    size_t nin, nvar, nout;
    size_t *var;      /* nvar: the varying inputs' indices */
};

static bool args_ok(qd_ctx *ctx, bool ok, const char *what) {
    if (!ok && ctx)
        qd_ctx_error(ctx, QD_ERR_ARG, "tangent: %s", what);
    return ok;
}

qd_tangent *qd_tangent_new(qd_ctx *ctx, size_t nin, const qd_expr *const *inputs,
                           const bool *vary, size_t nout, const qd_expr *const *outputs) {
    if (!ctx || !args_ok(ctx, (!nin || inputs) && (!nout || outputs),
                         "the input and output arrays are needed"))
        return NULL;
    qd_tangent *t = qd__calloc(ctx, 1, sizeof *t);
    if (!t)
        return NULL;
    t->nin = nin;
    t->nout = nout;
    t->var = qd__calloc(ctx, nin + 1, sizeof *t->var);
    t->prog = t->var ? qd_prog_new(ctx, nin, inputs, nout, outputs) : NULL;
    const qd_prog *progs[1] = {t->prog};
    t->tay = t->prog ? qd__tay_new(ctx, 1, progs, vary, 1, QD__TAY_DOUBLE) : NULL;
    if (!t->tay) {
        qd_tangent_free(t);
        return NULL;
    }
    for (size_t i = 0; i < nin; i++)
        if (!vary || vary[i])
            t->var[t->nvar++] = i;
    return t;
}

void qd_tangent_free(qd_tangent *t) {
    if (!t)
        return;
    qd__tay_free(t->tay);
    qd_prog_free(t->prog);
    qd__free(t->var);
    qd__free(t);
}

size_t qd_tangent_nin(const qd_tangent *t) { return t ? t->nin : 0; }
size_t qd_tangent_nvar(const qd_tangent *t) { return t ? t->nvar : 0; }
size_t qd_tangent_nout(const qd_tangent *t) { return t ? t->nout : 0; }

qd_status qd_tangent_eval(qd_tangent *t, const double *in, double *out) {
    if (!t || (t->nin && !in) || (t->nout && !out))
        return QD_ERR_ARG;
    qd_prog_run(t->prog, in, out);
    return QD_OK;
}

/* Order 0 at in, every input's order-1 coefficient 0. */
static void at_point(qd_tangent *t, const double *in) {
    for (size_t i = 0; i < t->nin; i++) {
        double *c = qd__tay_in(t->tay, i);
        c[0] = in[i];
        c[1] = 0;
    }
    qd__tay_run(t->tay, 0);
}

static double out_coef(qd_tangent *t, size_t j, size_t k) {
    if (k && qd__tay_out_flat(t->tay, j))
        return 0;
    return ((const double *)qd__tay_out(t->tay, j))[k];
}

static qd_status not_finite(qd_ctx *ctx, size_t j, size_t col, bool value) {
    if (value)
        qd_ctx_error(ctx, QD_ERR_NUMERIC, "tangent: output %zu is not finite at the point", j);
    else
        qd_ctx_error(ctx, QD_ERR_NUMERIC, "tangent: the derivative of output %zu in input %zu "
                     "is not finite at the point", j, col);
    return QD_ERR_NUMERIC;
}

qd_status qd_tangent_jacobian(qd_ctx *ctx, qd_tangent *t, const double *in, double *out,
                              double *J) {
    if (!args_ok(ctx, t && (!t->nin || in) && (!t->nout || !t->nvar || J),
                 "a tangent, its point and room for the Jacobian are needed"))
        return QD_ERR_ARG;
    at_point(t, in);
    for (size_t j = 0; j < t->nout; j++) {
        double y = out_coef(t, j, 0);
        if (!isfinite(y))
            return ctx ? not_finite(ctx, j, 0, true) : QD_ERR_NUMERIC;
        if (out)
            out[j] = y;
    }
    for (size_t k = 0; k < t->nvar; k++) {
        double *c = qd__tay_in(t->tay, t->var[k]);
        c[1] = 1;
        qd__tay_run(t->tay, 1);
        bool finite = true;
        for (size_t j = 0; j < t->nout; j++) {
            double d = out_coef(t, j, 1); /* before c[1] is cleared: an output may be x_k */
            finite = finite && isfinite(d);
            J[j * t->nvar + k] = d;
        }
        c[1] = 0;
        for (size_t j = 0; j < t->nout && !finite; j++)
            if (!isfinite(J[j * t->nvar + k]))
                return ctx ? not_finite(ctx, j, t->var[k], false) : QD_ERR_NUMERIC;
    }
    return QD_OK;
}

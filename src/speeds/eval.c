/*
 * src/speeds/eval.c - the equations in speeds in numbers: the kinematics,
 * M_u, f_u, the multipliers and the definitions compiled into one program
 * on first use; u' by the numerics home's dense solver.
 */
#include "spd.h"

#include "../base/mem.h"
#include "../num/num.h"
#include "../base/args.h"

/* Offsets of the outputs: kin (n), M (m*m), f (m), mult (ncon when made),
 * def (m). */
static size_t off_M(const qd_speeds_eom *e) { return e->n; }
static size_t off_f(const qd_speeds_eom *e) { return e->n + e->m * e->m; }
static size_t off_mult(const qd_speeds_eom *e) { return off_f(e) + e->m; }
static size_t nmult(const qd_speeds_eom *e) { return e->mult ? e->ncon : 0; }
static size_t off_def(const qd_speeds_eom *e) { return off_mult(e) + nmult(e); }

static qd_status compile(qd_ctx *ctx, const qd_speeds_eom *e) {
    qd__spd_priv *pv = e->priv;
    if (pv->prog)
        return QD_OK;
    size_t n = e->n, m = e->m, nout = off_def(e) + m;
    const qd_expr **outs = qd__malloc(ctx, (nout + 1) * sizeof *outs);
    if (!outs)
        goto nomem;
    for (size_t j = 0; j < n; j++)
        outs[j] = e->kin[j];
    for (size_t i = 0; i < m * m; i++)
        outs[off_M(e) + i] = e->M[i];
    for (size_t r = 0; r < m; r++) {
        outs[off_f(e) + r] = e->f[r];
        outs[off_def(e) + r] = e->def[r];
    }
    for (size_t k = 0; k < nmult(e); k++)
        outs[off_mult(e) + k] = e->mult[k];
    pv->in = qd__num_inputs(ctx, nout, outs, &pv->nin);
    pv->prog = pv->in ? qd_prog_new(ctx, pv->nin, pv->in, nout, outs) : NULL;
    qd__free(outs);
    if (!pv->prog)
        goto fail;
    pv->nout = nout;
    size_t nw = pv->nin + nout + qd_prog_work_size(pv->prog) + m * m + m + 1;
    pv->work = qd__malloc(ctx, nw * sizeof *pv->work);
    if (!pv->work)
        goto nomem;
    qd_prog_work_init(pv->prog, pv->work + pv->nin + nout);
    return QD_OK;
nomem:
    if (qd_ctx_status(ctx) == QD_OK)
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory compiling the equations in speeds");
fail:
    qd_prog_free(pv->prog);
    qd__free(pv->in);
    pv->prog = NULL;
    pv->in = NULL;
    return qd_ctx_status(ctx) != QD_OK ? qd_ctx_status(ctx) : QD_ERR_NOMEM;
}

/* Run the program at the state; the outputs after the inputs in work. */
static double *run(const qd_speeds_eom *e, size_t nvals, const qd_expr *const *syms,
                   const double *vals) {
    qd__spd_priv *pv = e->priv;
    double *in = pv->work, *out = in + pv->nin, *regs = out + pv->nout;
    for (size_t i = 0; i < pv->nin; i++) {
        in[i] = 0;
        for (size_t k = 0; k < nvals; k++)
            if (syms[k] == pv->in[i])
                in[i] = vals[k];
    }
    qd_prog_eval(pv->prog, regs, in, out);
    return out;
}

/* lambda at u' (the multipliers are linear in u', evaluated with it given). */
static qd_status multipliers(qd_ctx *ctx, const qd_speeds_eom *e, size_t nvals,
                             const qd_expr *const *syms, const double *vals, const double *ud,
                             double *lambda) {
    size_t total = nvals + e->m;
    const qd_expr **s2 = qd__malloc(ctx, (total + 1) * sizeof *s2);
    double *v2 = qd__malloc(ctx, (total + 1) * sizeof *v2);
    if (!s2 || !v2) {
        qd__free(s2);
        qd__free(v2);
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory evaluating the multipliers");
        return QD_ERR_NOMEM;
    }
    for (size_t i = 0; i < nvals; i++)
        s2[i] = syms[i], v2[i] = vals[i];
    for (size_t r = 0; r < e->m; r++)
        s2[nvals + r] = e->ud[r], v2[nvals + r] = ud[r];
    const double *out = run(e, total, s2, v2);
    for (size_t k = 0; k < e->ncon; k++)
        lambda[k] = out[off_mult(e) + k];
    qd__free(s2);
    qd__free(v2);
    return QD_OK;
}

qd_status qd_speeds_eval(qd_ctx *ctx, const qd_speeds_eom *e, size_t nvals,
                         const qd_expr *const *syms, const double *vals, double *qd, double *ud,
                         double *lambda) {
    QD_ARGS_CTX(ctx, ctx && e && (nvals == 0 || syms) && (nvals == 0 || vals));
    if (!ctx || !e || (nvals && (!syms || !vals)))
        return QD_ERR_ARG;
    if (lambda && e->ncon && !e->mult) {
        qd_ctx_error(ctx, QD_ERR_ARG, "the multipliers were not derived (opts.multipliers)");
        return QD_ERR_ARG;
    }
    qd_status st = compile(ctx, e);
    if (st != QD_OK)
        return st;
    qd__spd_priv *pv = e->priv;
    size_t n = e->n, m = e->m;
    const double *out = run(e, nvals, syms, vals);
    for (size_t j = 0; qd && j < n; j++)
        qd[j] = out[j];
    if (!ud && !lambda)
        return QD_OK;
    double *K = pv->work + pv->nin + pv->nout + qd_prog_work_size(pv->prog), *x = K + m * m;
    for (size_t i = 0; i < m * m; i++)
        K[i] = out[off_M(e) + i];
    for (size_t r = 0; r < m; r++)
        x[r] = out[off_f(e) + r];
    if (!qd__num_solve(m, K, x, 1e-12 * (double)m)) {
        qd_ctx_error(ctx, QD_ERR_SINGULAR, "the mass matrix of the speeds is singular at this state");
        return QD_ERR_SINGULAR;
    }
    double xs[64], *xx = m <= 64 ? xs : qd__malloc(ctx, m * sizeof *xx);
    if (!xx) {
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory evaluating the equations in speeds");
        return QD_ERR_NOMEM;
    }
    for (size_t r = 0; r < m; r++)
        xx[r] = x[r];
    for (size_t r = 0; ud && r < m; r++)
        ud[r] = xx[r];
    st = lambda && e->ncon ? multipliers(ctx, e, nvals, syms, vals, xx, lambda) : QD_OK;
    if (xx != xs)
        qd__free(xx);
    return st;
}

qd_status qd_speeds_from_velocities(qd_ctx *ctx, const qd_speeds_eom *e, size_t nvals,
                                    const qd_expr *const *syms, const double *vals, double *u) {
    QD_ARGS_CTX(ctx, ctx && e && (nvals == 0 || syms) && (nvals == 0 || vals) && u);
    if (!ctx || !e || !u || (nvals && (!syms || !vals)))
        return QD_ERR_ARG;
    qd_status st = compile(ctx, e);
    if (st != QD_OK)
        return st;
    const double *out = run(e, nvals, syms, vals);
    for (size_t r = 0; r < e->m; r++)
        u[r] = out[off_def(e) + r];
    return QD_OK;
}

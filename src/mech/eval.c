/*
 * src/mech/eval.c - the equations of motion in numbers: M, f (and A, b, g
 * with constraints) compiled into one program, q'' (and the multipliers)
 * by the numerics home's dense solver.
 *
 * Thread safety: qd_eom_compile makes an immutable qd_eom_prog; each thread
 * evaluates it with its own qd_eom_work (inputs, outputs, the program's
 * registers, solver scratch) and its own context.  qd_eom_eval is the
 * one-thread convenience that keeps such a pair in e->priv.
 */
#include "mech.h"

#include "num/num.h"
#include "base/mem.h"
#include "../base/args.h"

#include <stdlib.h>

/* Every output of the program, in the order of qd__out_*. */
static const qd_expr **outputs(qd_ctx *ctx, const qd_eom *e, size_t nout) {
    size_t n = e->n, m = e->ncon;
    const qd_expr **outs = qd__malloc(ctx, (nout + 1) * sizeof *outs);
    if (!outs)
        return NULL;
    for (size_t i = 0; i < n * n; i++)
        outs[i] = e->M[i];
    for (size_t i = 0; i < n; i++)
        outs[n * n + i] = e->f[i];
    for (size_t i = 0; i < m * n; i++)
        outs[qd__out_A(e) + i] = e->A[i];
    for (size_t k = 0; k < m; k++) {
        outs[qd__out_b(e) + k] = e->b[k];
        outs[qd__out_g(e) + k] = e->con[k].expr;
    }
    return outs;
}

void qd_eom_prog_free(qd_eom_prog *p) {
    if (!p)
        return;
    qd_prog_free(p->prog);
    qd__free(p->inputs);
    qd__free(p);
}

qd_eom_prog *qd_eom_compile(qd_ctx *ctx, const qd_eom *e) {
    QD_ARGS(NULL, ctx && e);
    qd_eom_prog *p = qd__calloc(ctx, 1, sizeof *p);
    size_t nout = qd__out_len(e);
    const qd_expr **outs = p ? outputs(ctx, e, nout) : NULL;
    if (!outs) {
        qd__free(p);
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory compiling the equations of motion");
        return NULL;
    }
    p->e = e;
    p->nout = nout;
    p->inputs = qd__num_inputs(ctx, nout, outs, &p->nin);
    if (p->inputs)
        p->prog = qd_prog_new(ctx, p->nin, p->inputs, nout, outs);
    qd__free(outs);
    if (!p->prog) {
        qd_eom_prog_free(p);
        return NULL;
    }
    return p;
}

void qd_eom_work_free(qd_eom_work *w) {
    if (!w)
        return;
    qd__free(w->in);
    qd__free(w);
}

qd_eom_work *qd_eom_work_new(qd_ctx *ctx, const qd_eom_prog *p) {
    QD_ARGS(NULL, ctx && p);
    qd_eom_work *w = qd__calloc(ctx, 1, sizeof *w);
    if (!w) {
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory for an evaluation workspace");
        return NULL;
    }
    size_t s = p->e->n + p->e->ncon, nregs = qd_prog_work_size(p->prog);
    /* one block: in, out, the registers, K (s*s) and its right-hand side */
    w->in = qd__malloc(ctx, (p->nin + p->nout + nregs + s * s + s + 1) * sizeof *w->in);
    if (!w->in) {
        qd__free(w);
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory for an evaluation workspace");
        return NULL;
    }
    w->p = p;
    w->out = w->in + p->nin;
    w->regs = w->out + p->nout;
    w->K = w->regs + nregs;
    qd_prog_work_init(p->prog, w->regs);
    return w;
}

/* The inputs in the program's order; symbols M and f do not have are
 * ignored, and the ones not given stay 0. */
static void fill_inputs(const qd_eom_prog *p, double *in, size_t nvals,
                        const qd_expr *const *syms, const double *vals) {
    for (size_t i = 0; i < p->nin; i++) {
        in[i] = 0;
        for (size_t k = 0; k < nvals; k++)
            if (syms[k] == p->inputs[i])
                in[i] = vals[k];
    }
}

/* M q'' = f in the scratch K. */
static qd_status solve_mass(qd_ctx *ctx, const qd_eom *e, const double *out, double *K,
                            double *qdd) {
    size_t n = e->n;
    for (size_t i = 0; i < n * n; i++)
        K[i] = out[i];
    for (size_t i = 0; i < n; i++)
        qdd[i] = out[n * n + i];
    if (qd__num_solve(n, K, qdd, 1e-12 * (double)n))
        return QD_OK;
    qd_ctx_error(ctx, QD_ERR_SINGULAR, "the mass matrix is singular at this state");
    return QD_ERR_SINGULAR;
}

qd_status qd_eom_prog_eval(qd_ctx *ctx, const qd_eom_prog *p, qd_eom_work *w, size_t nvals,
                           const qd_expr *const *syms, const double *vals, double *M, double *f,
                           double *qdd, double *lambda, double *R) {
    QD_ARGS_CTX(ctx, ctx && p && w && (nvals == 0 || syms) && (nvals == 0 || vals));
    const qd_eom *e = p->e;
    size_t n = e->n;
    if (w->p != p) {
        qd_ctx_error(ctx, QD_ERR_ARG, "a workspace evaluates the program it was made for");
        return QD_ERR_ARG;
    }
    fill_inputs(p, w->in, nvals, syms, vals);
    qd_prog_eval(p->prog, w->regs, w->in, w->out);
    for (size_t i = 0; M && i < n * n; i++)
        M[i] = w->out[i];
    for (size_t i = 0; f && i < n; i++)
        f[i] = w->out[n * n + i];
    if (e->ncon)
        return qdd || lambda || R ? qd__mech_saddle_solve(ctx, e, w->out, w->K, qdd, lambda, R)
                                  : QD_OK;
    for (size_t i = 0; R && i < n; i++)
        R[i] = 0;
    return qdd ? solve_mass(ctx, e, w->out, w->K, qdd) : QD_OK;
}

/* ---- qd_eom_eval's cache in e->priv (one thread) -------------------------- */

void qd__mech_eom_num_free(qd__eom_num *num) {
    if (!num)
        return;
    qd_eom_work_free(num->work);
    qd_eom_prog_free(num->prog);
    num->work = NULL;
    num->prog = NULL;
}

qd_status qd__mech_eom_compile(qd_ctx *ctx, const qd_eom *e) {
    qd__eom_num *num = e->priv;
    if (num->prog)
        return QD_OK;
    num->prog = qd_eom_compile(ctx, e);
    num->work = num->prog ? qd_eom_work_new(ctx, num->prog) : NULL;
    if (num->work)
        return QD_OK;
    qd__mech_eom_num_free(num);
    if (qd_ctx_status(ctx) == QD_OK)
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory compiling the equations of motion");
    return qd_ctx_status(ctx);
}

qd_status qd_eom_eval(qd_ctx *ctx, const qd_eom *e, size_t nvals, const qd_expr *const *syms,
                      const double *vals, double *M, double *f, double *qdd, double *lambda,
                      double *R) {
    QD_ARGS_CTX(ctx, ctx && e && (nvals == 0 || syms) && (nvals == 0 || vals));
    qd_status st = qd__mech_eom_compile(ctx, e);
    if (st != QD_OK)
        return st;
    qd__eom_num *num = e->priv;
    return qd_eom_prog_eval(ctx, num->prog, num->work, nvals, syms, vals, M, f, qdd, lambda, R);
}

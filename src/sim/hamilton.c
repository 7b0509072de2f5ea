/*
 * src/sim/hamilton.c - a model given by H compiled into Hamilton's
 * equations, y = (q, p):
 *
 *     q' = dH/dp,   p' = -dH/dq + Q - dD/dq'  (D at q' = dH/dp)
 *
 * (Goldstein sec. 8.1; Desloge ch. 71).  No Legendre transform is made, so
 * H need not be regular: with d^2H/dp^2 singular (H = p x, linear in p) q'
 * does not determine p and there is no Lagrangian, yet these equations are
 * well defined.  The programs take the momenta where the Lagrangian system
 * takes the velocities (simint.h, qd__sim_second).
 */
#include "simint.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "num/num.h"
#include "base/mem.h"
#include "../base/args.h"

static qd_status inputs(qd_sim *s) {
    size_t n = s->n;
    if (qd_model_ninputs(s->model)) {
        qd_ctx_error(s->ctx, QD_ERR_ARG, "a model given by H with inputs is not simulated: "
                     "inputs are simulated in the Lagrangian form (T and V, or L)");
        return QD_ERR_ARG;
    }
    s->np = qd_model_nparams(s->model);
    s->nin = 2 * n + 1 + s->np;
    s->in_syms = qd__malloc(s->ctx, s->nin * sizeof *s->in_syms);
    s->par = qd__calloc(s->ctx, s->np + 1, sizeof *s->par);
    if (!s->in_syms || !s->par)
        return QD_ERR_NOMEM;
    for (size_t j = 0; j < n; j++) {
        s->in_syms[j] = qd_model_coord(s->model, j);
        s->in_syms[n + j] = qd_model_momentum(s->model, j);
    }
    s->in_syms[2 * n] = qd_time(s->ctx);
    for (size_t i = 0; i < s->np; i++) {
        s->in_syms[2 * n + 1 + i] = qd_model_param(s->model, i);
        qd_status st = qd_model_param_number(s->model, i, &s->par[i]);
        if (st != QD_OK) {
            if (st == QD_ERR_ARG)
                qd_ctx_error(s->ctx, QD_ERR_ARG, "parameter %s has no finite value",
                             qd_expr_name(s->in_syms[2 * n + 1 + i]));
            return st;
        }
    }
    return QD_OK;
}

static bool has_any(const qd_expr *x, size_t n, const qd_expr *const *syms) {
    for (size_t i = 0; i < n; i++)
        if (qd_has(x, syms[i]))
            return true;
    return false;
}

/* v = dH/dp, F = -dH/dq + Q - dD/dq'|_{q' = v}, J = dv/dp; what the
 * system is. */
static qd_status equations(qd_sim *s, const qd_expr **v, const qd_expr **F, const qd_expr **J) {
    qd_ctx *ctx = s->ctx;
    size_t n = s->n;
    const qd_expr *H = qd_model_hamiltonian(s->model), *t = qd_time(ctx);
    const qd_expr *D = qd_model_dissipation(s->model);
    const qd_expr *const *q = s->in_syms, *const *p = s->in_syms + n;
    const qd_expr **qd = qd__malloc(ctx, (n + 1) * sizeof *qd);
    if (!qd)
        return QD_ERR_NOMEM;
    bool forces = false;
    for (size_t j = 0; j < n; j++) {
        qd[j] = qd_jet(ctx, q[j], 1);
        v[j] = qd_simplify(ctx, qd_diff(ctx, H, p[j]));
    }
    s->separable = !qd_has(H, t);
    for (size_t j = 0; j < n; j++) {
        const qd_expr *Q = qd_model_force(s->model, j);
        forces = forces || !qd_is_zero(Q);
        F[j] = qd_add(ctx, qd_neg(ctx, qd_diff(ctx, H, q[j])), Q);
        if (D)
            F[j] = qd_sub(ctx, F[j], qd_subs(ctx, qd_diff(ctx, D, qd[j]), n, qd, v));
        F[j] = qd_simplify(ctx, F[j]);
        for (size_t k = 0; k < n; k++)
            J[j * n + k] = qd_diff(ctx, v[j], p[k]);
        s->separable = s->separable && F[j] && v[j] && !has_any(F[j], n, p) &&
                       !has_any(v[j], n, q) && !qd_has(F[j], t);
    }
    qd__free(qd);
    s->h_expr = H;
    s->T_expr = qd_int(ctx, 0);
    s->b_expr = qd__calloc(ctx, n + 1, sizeof *s->b_expr);
    if (!s->b_expr)
        return QD_ERR_NOMEM;
    memcpy(s->b_expr, v, n * sizeof *v); /* q' = dH/dp, for the outputs */
    s->conservative = !qd_has(H, t) && !forces && !(D && !qd_is_zero(D));
    return qd_ctx_status(ctx);
}

static qd_status compile(qd_sim *s) {
    size_t n = s->n;
    const qd_expr **x = qd__calloc(s->ctx, 2 * n + n * n + 1, sizeof *x);
    if (!x)
        return QD_ERR_NOMEM;
    const qd_expr **v = x, **F = x + n, **J = x + 2 * n;
    qd_status st = equations(s, v, F, J);
    if (st == QD_OK)
        s->mom = qd__sim_prog(s, n, v, &s->mom_n);
    if (s->mom)
        s->force = qd__sim_prog(s, n, F, &s->force_n);
    /* acc: v then J, for the momenta from the initial velocities */
    memmove(x + n, J, n * n * sizeof *x);
    if (s->force)
        s->acc = qd__sim_prog(s, n + n * n, x, &s->acc_n);
    qd__free(x);
    return st == QD_OK && s->acc ? QD_OK : qd_ctx_status(s->ctx);
}

void qd__sim_hamilton_velocities(qd_sim *s, size_t n, const qd_expr **x) {
    const qd_expr **qd = qd__malloc(s->ctx, (s->n + 1) * sizeof *qd);
    for (size_t j = 0; qd && j < s->n; j++)
        qd[j] = qd_jet(s->ctx, s->in_syms[j], 1);
    /* out of memory: the velocities stay, and compiling names them */
    for (size_t i = 0; qd && i < n; i++)
        x[i] = qd_subs(s->ctx, x[i], s->n, qd, s->b_expr);
    qd__free(qd);
}

qd_sim *qd_sim_new_hamilton(qd_ctx *ctx, const qd_model *m) {
    QD_ARGS(NULL, ctx && m);
    if (!qd_model_hamiltonian_given(m)) {
        qd_ctx_error(ctx, QD_ERR_ARG, "the model is not given by H (momenta, H = ...)");
        return NULL;
    }
    if (qd_model_nconstraints(m)) {
        qd_ctx_error(ctx, QD_ERR_UNSUPPORTED,
                     "constraints on a model given by H are not simulated: give T and V");
        return NULL;
    }
    if (qd_model_nimpacts(m)) {
        qd_ctx_error(ctx, QD_ERR_UNSUPPORTED,
                     "impacts on a model given by H are not simulated (Newton's law needs the "
                     "mass matrix): give T and V");
        return NULL;
    }
    qd_sim *s = qd__calloc(ctx, 1, sizeof *s);
    if (!s) {
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory");
        return NULL;
    }
    *s = (qd_sim){.ctx = ctx, .model = m, .n = qd_model_ncoords(m), .hamilton = true,
                  .canonical = true};
    qd_status st = inputs(s);
    if (st == QD_OK)
        st = compile(s);
    if (st == QD_OK)
        st = qd__sim_names(s);
    if (st != QD_OK) {
        if (qd_ctx_status(ctx) == QD_OK)
            qd_ctx_error(ctx, st, "cannot compile Hamilton's equations for simulation");
        qd_sim_free(s);
        return NULL;
    }
    return s;
}

/* Newton's method on dH/dp (q, p, t) = qd from p = 0: one step when H is
 * quadratic in p.  Each step solves d^2H/dp^2 dp = qd - dH/dp. */
qd_status qd__sim_hamilton_momenta(qd_sim *s, double t, const double *q, const double *qd,
                               double *p) {
    size_t n = s->n;
    double *K = s->K, *r = s->rhs;
    for (size_t j = 0; j < n; j++)
        p[j] = 0;
    for (int iter = 0; iter < 50; iter++) {
        for (size_t j = 0; j < n; j++) {
            s->in[j] = q[j];
            s->in[n + j] = p[j];
        }
        s->in[2 * n] = t;
        qd_prog_eval(s->acc, s->acc_w, s->in, s->acc_out);
        double res = 0, size = 1;
        for (size_t j = 0; j < n; j++) {
            r[j] = qd[j] - s->acc_out[j];
            res = fmax(res, fabs(r[j]));
            size = fmax(size, fabs(qd[j]));
        }
        if (res <= 1e-14 * size)
            return QD_OK;
        memcpy(K, s->acc_out + n, n * n * sizeof *K);
        if (!qd__num_solve(n, K, r, 1e-13 * (double)n)) {
            qd__sim_stop(s, QD_STOP_SINGULAR, NAN, NAN);
            qd_ctx_error(s->ctx, QD_ERR_SINGULAR,
                         "d^2H/dp^2 is singular: the initial velocities do not determine the "
                         "momenta; give the momenta instead (p = ...)");
            return QD_ERR_SINGULAR;
        }
        for (size_t j = 0; j < n; j++)
            p[j] += r[j];
    }
    qd__sim_stop(s, QD_STOP_NO_CONVERGENCE, NAN, NAN);
    qd_ctx_error(s->ctx, QD_ERR_NUMERIC,
                 "no momenta give the initial velocities (dH/dp = q' has no solution near 0)");
    return QD_ERR_NUMERIC;
}

/*
 * src/linear/steady.c - steady motions of a system with cyclic coordinates:
 * the symbolic preparation (qd_steady_derive) and the search
 * (qd_steady_find).
 *
 * The search works on the full equations, not on V_eff: the kept rows of
 * M q'' = f at x' = 0, c'' = 0 vanish exactly at a steady motion, whether
 * the rates are free or driven (the two effective potentials have the same
 * gradient), and in that form a given momentum is one more equation
 * p_c = dL/dc' while a given point (--at) leaves the rate unknown.  So one
 * Gauss-Newton solve covers "p given, find x", "x given, find w or p" and
 * "w given, find x".
 */
#include "steady.h"
#include "../base/mem.h"

#include "num/num.h"
#include "../base/args.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static const qd_expr **arr(qd_ctx *ctx, size_t n) { return qd__calloc(ctx, n ? n : 1, sizeof(const qd_expr *)); }

void qd_steady_free(qd_steady *s) {
    if (!s)
        return;
    qd__free(s->keep);
    qd__free(s->keepd);
    qd__free(s->cyc);
    qd__free(s->cycd);
    qd__free(s->mom);
    qd__free(s->res);
    if (s->driven) {
        qd__free(s->M);
        qd__free(s->f);
    }
    qd_routh_free(s->routh);
    qd__free(s);
}

/* Is coordinate c cyclic for the purpose `what`?  Reports the first place
 * it appears. */
static bool cyclic(qd_ctx *ctx, const qd_model *m, const qd_eom *e, const qd_expr *c) {
    const char *where = NULL;
    const qd_expr *D = qd_model_dissipation(m);
    if (qd_has(e->L, c))
        where = "the Lagrangian";
    else if (D && qd_has(D, c))
        where = "the dissipation function";
    for (size_t j = 0; !where && j < e->n; j++)
        if (qd_has(e->f[j], c) || qd_has(qd_model_force(m, j), c))
            where = "the equations of motion";
    if (where)
        qd_ctx_error(ctx, QD_ERR_ARG,
                     "%s is not cyclic: it appears in %s, so it cannot turn steadily while the "
                     "others stay at rest", qd_expr_name(c), where);
    return !where;
}

/* Sort the coordinates into kept and cyclic. */
static qd_status split_coords(qd_ctx *ctx, const qd_model *m, const qd_eom *e, qd_steady *s,
                              size_t ncyc, const qd_expr *const *cyc) {
    size_t n = e->n, nk = 0;
    for (size_t c = 0; c < ncyc; c++) {
        size_t j = 0;
        while (j < n && e->q[j] != cyc[c])
            j++;
        if (j == n) {
            qd_ctx_error(ctx, QD_ERR_ARG, "%s is not a coordinate of the model",
                         cyc[c] ? qd_expr_name(cyc[c]) : "(null)");
            return QD_ERR_ARG;
        }
        for (size_t k = 0; k < c; k++)
            if (cyc[k] == cyc[c]) {
                qd_ctx_error(ctx, QD_ERR_ARG, "%s is listed twice", qd_expr_name(cyc[c]));
                return QD_ERR_ARG;
            }
        if (!cyclic(ctx, m, e, cyc[c]))
            return QD_ERR_ARG;
        s->cyc[c] = cyc[c];
        s->cycd[c] = e->qd[j];
    }
    for (size_t j = 0; j < n; j++) {
        bool ign = false;
        for (size_t c = 0; c < ncyc; c++)
            ign = ign || cyc[c] == e->q[j];
        if (!ign) {
            s->keep[nk] = e->q[j];
            s->keepd[nk++] = e->qd[j];
        }
    }
    return QD_OK;
}

/* x with every kept velocity set to 0. */
static const qd_expr *at_rest(qd_ctx *ctx, const qd_steady *s, const qd_expr *x) {
    const qd_expr **zero = arr(ctx, s->nkeep);
    if (!zero)
        return NULL;
    for (size_t j = 0; j < s->nkeep; j++)
        zero[j] = qd_int(ctx, 0);
    const qd_expr *y = qd_subs(ctx, x, s->nkeep, s->keepd, zero);
    qd__free(zero);
    return y ? qd_simplify(ctx, y) : NULL;
}

static size_t index_of(const qd_eom *e, const qd_expr *q) {
    size_t j = 0;
    while (j < e->n && e->q[j] != q)
        j++;
    return j;
}

static qd_status driven_equations(qd_ctx *ctx, const qd_eom *e, qd_steady *s) {
    size_t nk = s->nkeep;
    s->M = arr(ctx, nk * nk);
    s->f = arr(ctx, nk);
    if (!s->M || !s->f)
        return QD_ERR_NOMEM;
    for (size_t a = 0; a < nk; a++) {
        size_t i = index_of(e, s->keep[a]);
        s->f[a] = e->f[i];
        for (size_t b = 0; b < nk; b++)
            s->M[a * nk + b] = e->M[i * e->n + index_of(e, s->keep[b])];
    }
    /* V - T0 = -(L with the kept velocities at rest), U's velocity-free part
     * included. */
    s->Veff = at_rest(ctx, s, qd_neg(ctx, e->L));
    return s->Veff ? QD_OK : qd_ctx_status(ctx);
}

static qd_status free_equations(qd_ctx *ctx, const qd_model *m, const qd_eom *e, qd_steady *s) {
    s->routh = qd_routh_derive(ctx, m, e, s->ncyc, s->cyc);
    if (!s->routh)
        return qd_ctx_status(ctx) != QD_OK ? qd_ctx_status(ctx) : QD_ERR_ARG;
    s->beta = s->routh->beta;
    s->M = s->routh->M;
    s->f = s->routh->f;
    s->Veff = s->routh->Veff;
    return QD_OK;
}

qd_steady *qd_steady_derive(qd_ctx *ctx, const qd_model *m, const qd_eom *e, size_t ncyc,
                            const qd_expr *const *cyc, bool driven) {
    QD_ARGS(NULL, ctx && m && e && (ncyc == 0 || cyc));
    if (!e || !m || (ncyc && !cyc)) {
        qd_ctx_error(ctx, QD_ERR_ARG, "qd_steady_derive: missing argument");
        return NULL;
    }
    if (ncyc == 0 || ncyc >= e->n) {
        qd_ctx_error(ctx, QD_ERR_ARG, ncyc ? "every coordinate is listed as cyclic: nothing is "
                                             "left to be steady" : "no cyclic coordinate given");
        return NULL;
    }
    if (e->ncon || e->nelim) {
        qd_ctx_error(ctx, QD_ERR_ARG, "steady motions of models with constraints are not "
                                      "supported: choose independent coordinates");
        return NULL;
    }
    qd_steady *s = qd__calloc(ctx, 1, sizeof *s);
    if (!s)
        return NULL;
    s->driven = driven;
    s->ncyc = ncyc;
    s->nkeep = e->n - ncyc;
    s->keep = arr(ctx, s->nkeep);
    s->keepd = arr(ctx, s->nkeep);
    s->cyc = arr(ctx, ncyc);
    s->cycd = arr(ctx, ncyc);
    s->mom = arr(ctx, ncyc);
    s->res = arr(ctx, s->nkeep);
    qd_status st = s->keep && s->keepd && s->cyc && s->cycd && s->mom && s->res ? QD_OK
                                                                                : QD_ERR_NOMEM;
    if (st == QD_OK)
        st = split_coords(ctx, m, e, s, ncyc, cyc);
    for (size_t c = 0; st == QD_OK && c < ncyc; c++)
        if (!(s->mom[c] = at_rest(ctx, s, qd_diff(ctx, e->L, s->cycd[c]))))
            st = qd_ctx_status(ctx);
    for (size_t a = 0; st == QD_OK && a < s->nkeep; a++)
        if (!(s->res[a] = at_rest(ctx, s, e->f[index_of(e, s->keep[a])])))
            st = qd_ctx_status(ctx);
    if (st == QD_OK)
        st = driven ? driven_equations(ctx, e, s) : free_equations(ctx, m, e, s);
    if (st != QD_OK) {
        if (qd_ctx_status(ctx) == QD_OK)
            qd_ctx_error(ctx, st, "cannot prepare the steady-motion analysis");
        qd_steady_free(s);
        return NULL;
    }
    return s;
}

/* ---- evaluation environment ------------------------------------------------ */

qd_status qd__lin_steady_env_init(qd_ctx *ctx, const qd_steady *s, size_t nvals,
                                  const qd_expr *const *syms, const double *vals,
                                  qd__steady_env *env) {
    size_t nb = s->beta ? s->ncyc : 0;
    size_t cap = nvals + 2 * s->nkeep + s->ncyc + nb;
    env->syms = qd__calloc(ctx, cap ? cap : 1, sizeof *env->syms);
    env->vals = qd__calloc(ctx, cap ? cap : 1, sizeof *env->vals);
    if (!env->syms || !env->vals) {
        qd__lin_steady_env_free(env);
        return QD_ERR_NOMEM;
    }
    size_t n = 0;
    for (size_t i = 0; i < nvals; i++) {
        qd_role r = qd_expr_kind(syms[i]) == QD_SYMBOL ? qd_symbol_role(syms[i]) : QD_ROLE_COORD;
        if (r == QD_ROLE_PARAM || r == QD_ROLE_TIME || r == QD_ROLE_PLAIN) {
            env->syms[n] = syms[i];
            env->vals[n++] = vals[i];
        }
    }
    env->x = n;
    for (size_t j = 0; j < s->nkeep; j++)
        env->syms[n++] = s->keep[j];
    env->xd = n;
    for (size_t j = 0; j < s->nkeep; j++)
        env->syms[n++] = s->keepd[j];
    env->w = n;
    for (size_t c = 0; c < s->ncyc; c++)
        env->syms[n++] = s->cycd[c];
    env->p = n;
    for (size_t c = 0; c < nb; c++)
        env->syms[n++] = s->beta[c];
    env->n = n;
    return QD_OK;
}

void qd__lin_steady_env_free(qd__steady_env *env) {
    qd__free(env->syms);
    qd__free(env->vals);
    env->syms = NULL;
    env->vals = NULL;
}

qd_status qd__lin_steady_eval(qd_ctx *ctx, const qd__steady_env *env, const qd_expr *x,
                              double *out) {
    qd_status st = qd_eval(ctx, x, env->n, env->syms, env->vals, out);
    if (st == QD_OK && !isfinite(*out)) {
        qd_ctx_error(ctx, QD_ERR_SINGULAR,
                     "the equations are not defined at this steady motion (a division by zero: "
                     "a singular point of the coordinates? choose coordinates regular there)");
        return QD_ERR_SINGULAR;
    }
    return st;
}

/* ---- the search ----------------------------------------------------------- */

typedef qd__steady_search search;

static void search_free(search *S) {
    qd__lin_steady_env_free(&S->env);
    qd__free(S->uslot);
    qd__free(S->F);
    qd__free(S->pgiven);
    qd__free(S->dF);
}

static qd_status residual(search *S, const double *u, double *F, double *J) {
    for (size_t i = 0; i < S->nu; i++)
        S->env.vals[S->uslot[i]] = u[i];
    qd_status st = QD_OK;
    for (size_t k = 0; st == QD_OK && k < S->neq; k++) {
        st = qd__lin_steady_eval(S->ctx, &S->env, S->F[k], &F[k]);
        F[k] -= S->pgiven[k];
        for (size_t i = 0; st == QD_OK && J && i < S->nu; i++)
            st = qd__lin_steady_eval(S->ctx, &S->env, S->dF[k * S->nu + i], &J[k * S->nu + i]);
    }
    return st;
}

static double norm2(const double *v, size_t n) {
    double s = 0;
    for (size_t i = 0; i < n; i++)
        s += v[i] * v[i];
    return s;
}

/* One Levenberg-Marquardt step from u: d solves (J^T J + mu diag(J^T J)) d = -J^T F. */
static bool lm_step(const search *S, const double *F, const double *J, double mu, double *A,
                    double *d) {
    size_t nu = S->nu;
    for (size_t i = 0; i < nu; i++) {
        d[i] = 0;
        for (size_t k = 0; k < S->neq; k++)
            d[i] -= J[k * nu + i] * F[k];
        for (size_t j = 0; j < nu; j++) {
            double a = 0;
            for (size_t k = 0; k < S->neq; k++)
                a += J[k * nu + i] * J[k * nu + j];
            A[i * nu + j] = a;
        }
        A[i * nu + i] *= 1 + mu;
        if (A[i * nu + i] == 0)
            A[i * nu + i] = mu;
    }
    return qd__num_solve(nu, A, d, 0);
}

/* The scale of residual k, so that "zero" is relative to the size of the
 * terms that cancel: the sizes of its terms (qd__lin_steady_magnitude), the given
 * momentum, and |J_k| (|u| + 1) for how far a step could move it. */
static double scale_of(const search *S, const double *J, const double *u, size_t k) {
    double s = fabs(S->pgiven[k]);
    for (size_t i = 0; i < S->nu; i++)
        s += fabs(J[k * S->nu + i]) * (fabs(u[i]) + 1);
    double m = qd__lin_steady_magnitude(S->ctx, &S->env, S->F[k]);
    if (isfinite(m))
        s += m;
    return s > 0 ? s : 1;
}

static double abs_sum(const double *v, size_t n) {
    double s = 0;
    for (size_t i = 0; i < n; i++)
        s += fabs(v[i]);
    return s;
}

/* Levenberg-Marquardt creeps up on a root at 0 (a rate that must vanish, as
 * for a free particle) and stops at round-off, 1e-15, not 0; a "steady
 * motion" turning at 1e-15 rad/s then has a stiffness of order 1e-30 whose
 * sign is noise.  An unknown that tiny is set to 0 when the residual there is
 * no larger. */
static qd_status snap_zeros(search *S, double *u, const double *u0, double *F, double *F2) {
    qd_status st = residual(S, u, F, NULL);
    for (size_t i = 0; st == QD_OK && i < S->nu; i++) {
        if (u[i] == 0 || fabs(u[i]) > 1e-10 * fmax(1, fabs(u0[i])))
            continue;
        double keep = u[i], r = abs_sum(F, S->neq);
        u[i] = 0;
        qd_status s2 = residual(S, u, F2, NULL);
        if (s2 == QD_OK && abs_sum(F2, S->neq) <= r) {
            memcpy(F, F2, S->neq * sizeof *F);
            continue;
        }
        qd__ctx_recover(S->ctx);
        u[i] = keep;
        st = residual(S, u, F, NULL);
    }
    return st;
}

static qd_status iterate(search *S, double *u, double *res_out) {
    size_t nu = S->nu, neq = S->neq;
    double *F = qd__calloc(S->ctx, neq + 1, sizeof *F), *J = qd__calloc(S->ctx, neq * nu + 1, sizeof *J);
    double *A = qd__calloc(S->ctx, nu * nu + 1, sizeof *A), *d = qd__calloc(S->ctx, nu + 1, sizeof *d);
    double *u2 = qd__calloc(S->ctx, nu + 1, sizeof *u2), *F2 = qd__calloc(S->ctx, neq + 1, sizeof *F2);
    double *u0 = qd__calloc(S->ctx, nu + 1, sizeof *u0);
    qd_status st = F && J && A && d && u2 && F2 && u0 ? QD_OK : QD_ERR_NOMEM;
    if (st == QD_OK)
        memcpy(u0, u, nu * sizeof *u0);
    if (st == QD_OK)
        st = residual(S, u, F, J);
    double mu = 1e-3, f0 = st == QD_OK ? norm2(F, neq) : 0;
    bool done = false;
    for (int it = 0; st == QD_OK && !done && it < 200 && nu > 0; it++) {
        if (!lm_step(S, F, J, mu, A, d)) {
            mu *= 10;
            continue;
        }
        for (size_t i = 0; i < nu; i++)
            u2[i] = u[i] + d[i];
        qd_status s2 = residual(S, u2, F2, NULL);
        if (s2 == QD_ERR_SINGULAR) {  /* stepped onto a singular point: shorter steps */
            qd__ctx_recover(S->ctx);
            mu *= 10;
            continue;
        }
        if ((st = s2) != QD_OK)
            break;
        double f2 = norm2(F2, neq);
        if (f2 <= f0) {
            memcpy(u, u2, nu * sizeof *u);
            double du = sqrt(norm2(d, nu)), un = sqrt(norm2(u, nu));
            done = du <= 1e-14 * (1 + un) || f2 == 0;
            f0 = f2;
            mu = mu > 1e-12 ? mu / 10 : mu;
            st = residual(S, u, F, J);
        } else {
            mu *= 10;
            done = mu > 1e12;
        }
    }
    if (st == QD_OK && nu > 0)
        st = snap_zeros(S, u, u0, F, F2);
    if (st == QD_OK)
        st = residual(S, u, F, J);
    double worst = 0;
    for (size_t k = 0; st == QD_OK && k < neq; k++) {
        double r = fabs(F[k]) / scale_of(S, J, u, k);
        worst = r > worst ? r : worst;
    }
    if (res_out)
        *res_out = worst;
    if (st == QD_OK && worst > 1e-8) {
        qd_ctx_error(S->ctx, QD_ERR_NUMERIC,
                     nu ? "no steady motion found from these starting values (no convergence: "
                          "relative residual %.3g); give other starting values with --guess"
                        : "the values given are not a steady motion (relative residual %.3g)",
                     worst);
        st = QD_ERR_NUMERIC;
    }
    qd__free(F);
    qd__free(J);
    qd__free(A);
    qd__free(d);
    qd__free(u2);
    qd__free(F2);
    qd__free(u0);
    return st;
}

/* Count and check the unknowns and equations. */
static qd_status setup(search *S, const bool *xfix, const bool *wfix, const bool *pfix,
                       const qd_steady_point *pt) {
    const qd_steady *s = S->s;
    S->nu = S->neq = 0;
    for (size_t j = 0; j < s->nkeep; j++)
        S->nu += !xfix[j];
    for (size_t c = 0; c < s->ncyc; c++) {
        if (wfix[c] && pfix[c]) {
            qd_ctx_error(S->ctx, QD_ERR_ARG, "give either the rate %s or the momentum of %s, "
                         "not both", qd_expr_name(s->cycd[c]), qd_expr_name(s->cyc[c]));
            return QD_ERR_ARG;
        }
        S->nu += !wfix[c];
        S->neq += pfix[c];
    }
    S->neq += s->nkeep;
    if (S->nu > S->neq) {
        qd_ctx_error(S->ctx, QD_ERR_ARG,
                     "%zu unknowns for %zu equations: give the value of %zu more (a kept "
                     "coordinate's value, a rate or a momentum)", S->nu, S->neq, S->nu - S->neq);
        return QD_ERR_ARG;
    }
    S->uslot = qd__calloc(S->ctx, S->nu + 1, sizeof *S->uslot);
    S->F = arr(S->ctx, S->neq);
    S->pgiven = qd__calloc(S->ctx, S->neq + 1, sizeof *S->pgiven);
    S->dF = arr(S->ctx, S->neq * S->nu);
    if (!S->uslot || !S->F || !S->pgiven || !S->dF)
        return QD_ERR_NOMEM;
    size_t u = 0, k = 0;
    for (size_t j = 0; j < s->nkeep; j++) {
        S->env.vals[S->env.x + j] = pt->x[j];
        if (!xfix[j])
            S->uslot[u++] = S->env.x + j;
    }
    for (size_t c = 0; c < s->ncyc; c++) {
        S->env.vals[S->env.w + c] = pt->w[c];
        if (!wfix[c])
            S->uslot[u++] = S->env.w + c;
    }
    for (size_t a = 0; a < s->nkeep; a++)
        S->F[k++] = s->res[a];
    for (size_t c = 0; c < s->ncyc; c++)
        if (pfix[c]) {
            S->pgiven[k] = pt->p[c];
            S->F[k++] = s->mom[c];
        }
    for (size_t i = 0; i < S->neq; i++)
        for (size_t j = 0; j < S->nu; j++)
            if (!(S->dF[i * S->nu + j] = qd_diff(S->ctx, S->F[i], S->env.syms[S->uslot[j]])))
                return qd_ctx_status(S->ctx);
    return QD_OK;
}

qd_status qd_steady_find(qd_ctx *ctx, const qd_steady *s, size_t nvals,
                         const qd_expr *const *syms, const double *vals, const bool *xfix,
                         const bool *wfix, const bool *pfix, qd_steady_point *pt,
                         double *residual_out) {
    QD_ARGS_CTX(ctx, ctx && s && (nvals == 0 || syms) && (nvals == 0 || vals) && xfix && wfix && pfix && pt);
    search S = {.ctx = ctx, .s = s};
    qd_status st = qd__lin_steady_env_init(ctx, s, nvals, syms, vals, &S.env);
    if (st == QD_OK)
        st = setup(&S, xfix, wfix, pfix, pt);
    double *u = st == QD_OK ? qd__calloc(ctx, S.nu + 1, sizeof *u) : NULL;
    if (st == QD_OK && !u)
        st = QD_ERR_NOMEM;
    for (size_t i = 0; st == QD_OK && i < S.nu; i++)
        u[i] = S.env.vals[S.uslot[i]];
    if (st == QD_OK)
        st = iterate(&S, u, residual_out);
    if (st == QD_OK) {
        for (size_t j = 0; j < s->nkeep; j++)
            pt->x[j] = S.env.vals[S.env.x + j];
        for (size_t c = 0; c < s->ncyc && st == QD_OK; c++) {
            pt->w[c] = S.env.vals[S.env.w + c];
            st = qd__lin_steady_eval(ctx, &S.env, s->mom[c], &pt->p[c]);
        }
    }
    qd__free(u);
    search_free(&S);
    return st;
}

/* ---- what steady_all.c shares ---------------------------------------------- */

qd_status qd__lin_steady_search_init(search *S, const bool *xfix, const bool *wfix,
                                     const bool *pfix, const qd_steady_point *pt, size_t nvals,
                                     const qd_expr *const *syms, const double *vals) {
    qd_status st = qd__lin_steady_env_init(S->ctx, S->s, nvals, syms, vals, &S->env);
    return st == QD_OK ? setup(S, xfix, wfix, pfix, pt) : st;
}

void qd__lin_steady_search_free(search *S) { search_free(S); }

qd_status qd__lin_steady_residual(search *S, const double *u, double *F, double *J) {
    return residual(S, u, F, J);
}

qd_status qd__lin_steady_iterate(search *S, double *u, double *res) { return iterate(S, u, res); }

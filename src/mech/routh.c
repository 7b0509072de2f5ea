/*
 * src/mech/routh.c - Routh's reduction (qdot/routh.h): the ignored
 * velocities from the constant momenta, the Routhian, its split by degree
 * and the reduced equations of the kept coordinates.
 *
 * The reduced equations are derived afresh from -R as a Lagrangian rather
 * than by rewriting the full equations: that is the point of the method,
 * and it is what the cross-check against the full equations (tests) can
 * then confirm independently.
 */
#include "qdot/routh.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "legendre.h"
#include "mech.h"
#include "base/diag.h"
#include "base/mem.h"
#include "../base/args.h"

static const qd_expr **arr(qd_ctx *ctx, size_t n) { return qd__calloc(ctx, n ? n : 1, sizeof(const qd_expr *)); }

void qd_routh_free(qd_routh *r) {
    if (!r)
        return;
    qd__free(r->ign);
    qd__free(r->beta);
    qd__free(r->keep);
    qd__free(r->keepd);
    qd__free(r->keepdd);
    qd__free(r->ignvel);
    qd__free(r->pdef);
    qd__free(r->M);
    qd__free(r->f);
    qd__free(r->G);
    qd__free(r->betad);
    qd__free(r->pdot);
    qd__free(r->f_betad);
    qd__free(r->ign_index);
    qd__free(r->keep_index);
    qd__free(r);
}

static qd_routh *routh_alloc(qd_ctx *ctx, size_t n, size_t nign) {
    qd_routh *r = qd__calloc(ctx, 1, sizeof *r);
    if (!r)
        return NULL;
    size_t nk = n - nign;
    r->n = n;
    r->nign = nign;
    r->nkeep = nk;
    r->ign = arr(ctx, nign);
    r->beta = arr(ctx, nign);
    r->ignvel = arr(ctx, nign);
    r->pdef = arr(ctx, nign);
    r->keep = arr(ctx, nk);
    r->keepd = arr(ctx, nk);
    r->keepdd = arr(ctx, nk);
    r->M = arr(ctx, nk * nk);
    r->f = arr(ctx, nk);
    r->G = arr(ctx, nk * nk);
    r->ign_index = qd__calloc(ctx, nign ? nign : 1, sizeof *r->ign_index);
    r->keep_index = qd__calloc(ctx, nk ? nk : 1, sizeof *r->keep_index);
    if (!r->ign || !r->beta || !r->ignvel || !r->pdef || !r->keep || !r->keepd || !r->keepdd ||
        !r->M || !r->f || !r->G || !r->ign_index || !r->keep_index) {
        qd_routh_free(r);
        return NULL;
    }
    return r;
}

/* ---- names and cyclicity ---------------------------------------------------- */

const qd_expr *qd_routh_lookup(qd_ctx *ctx, const qd_model *m, const char *name) {
    QD_ARGS(NULL, ctx && m && name);
    size_t nc = qd_model_ncoords(m);
    const char **names = qd__malloc(ctx, (nc ? nc : 1) * sizeof *names);
    if (!names) {
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory");
        return NULL;
    }
    for (size_t i = 0; i < nc; i++) {
        names[i] = qd_expr_name(qd_model_coord(m, i));
        if (!strcmp(names[i], name)) {
            qd__free(names);
            return qd_model_coord(m, i);
        }
    }
    bool param = false;
    for (size_t i = 0; i < qd_model_nparams(m); i++)
        param = param || !strcmp(qd_expr_name(qd_model_param(m, i)), name);
    const char *near = qd__diag_nearest(name, strlen(name), names, nc);
    if (param)
        qd_ctx_error(ctx, QD_ERR_ARG, "'%s' is a parameter, not a coordinate", name);
    else if (near)
        qd_ctx_error(ctx, QD_ERR_ARG, "unknown coordinate '%s'; did you mean '%s'?", name, near);
    else
        qd_ctx_error(ctx, QD_ERR_ARG, "unknown coordinate '%s'", name);
    qd__free(names);
    return NULL;
}

static bool has(const qd_expr *x, const qd_expr *s) { return x && qd_has(x, s); }

/* The statement that makes coordinate index j of e not cyclic, or NULL. */
const char *qd_routh_not_cyclic(qd_ctx *ctx, const qd_model *m, const qd_eom *e, size_t j,
                                const char **why) {
    QD_ARGS(NULL, ctx && m && e && why);
    const qd_expr *c = e->q[j], *cd = e->qd[j], *D = qd_model_dissipation(m);
    const qd_expr *Q = qd_model_force(m, j);
    (void)ctx;
    *why = "it appears in the Lagrangian";
    if (has(e->L, c)) {
        if (qd_model_lagrangian_given(m))
            return "L";
        *why = "it appears in the potential energy";
        if (has(qd_model_potential(m), c))
            return "V";
        *why = "it appears in the generalized potential";
        if (has(qd_model_gen_potential(m), c))
            return "U";
        *why = "it appears in the kinetic energy";
        return "T";
    }
    *why = "it has a generalized force, so its momentum is not constant";
    if (Q && !qd_is_zero(Q))
        return qd_expr_name(c);
    *why = "the dissipation function depends on it, so its momentum is not constant";
    if (has(D, c) || has(D, cd))
        return "dissipation";
    for (size_t k = 0; k < e->n; k++) {
        const qd_expr *Qk = qd_model_force(m, k);
        *why = "the generalized force on another coordinate depends on it";
        if (k != j && has(Qk, c))
            return qd_expr_name(e->q[k]);
    }
    return NULL;
}

/* ---- the ignored velocities ------------------------------------------------- */

/* beta_i = dL/dc'_i = sum_j A_ij c'_j + (the rest, in k' and q): the row
 * [A_i | beta_i - rest]. */
static qd_status momentum_row(qd_ctx *ctx, const qd_eom *e, qd_routh *r, size_t i,
                              const qd_expr **row) {
    const qd_expr **co = arr(ctx, e->n);
    if (!co)
        return QD_ERR_NOMEM;
    const qd_expr *rest = NULL;
    qd_status st = qd_linear_coeffs(ctx, r->pdef[i], e->n, e->qd, co, &rest);
    if (st == QD_ERR_NONLINEAR && !qd__ctx_recover(ctx))
        st = QD_ERR_NOMEM;
    if (st == QD_OK) {
        for (size_t k = 0; k < r->nkeep; k++)
            rest = qd_add(ctx, rest, qd_mul(ctx, co[r->keep_index[k]], r->keepd[k]));
        for (size_t j = 0; j < r->nign; j++)
            row[j] = co[r->ign_index[j]];
        row[r->nign] = qd_sub(ctx, r->beta[i], rest);
        st = row[r->nign] ? QD_OK : qd_ctx_status(ctx);
    }
    qd__free(co);
    return st;
}

/* No closed form: each ignored velocity stands for itself, defined by
 * pdef = beta (qdot/routh.h, the implicit Routhian). */
static qd_status keep_implicit(qd_ctx *ctx, const qd_eom *e, qd_routh *r) {
    if (!qd__ctx_recover(ctx))
        return QD_ERR_NOMEM;
    for (size_t i = 0; i < r->nign; i++)
        r->ignvel[i] = e->qd[r->ign_index[i]];
    r->implicit = true;
    return QD_OK;
}

/* L not quadratic in the ignored velocities: the transform restricted to
 * them (legendre_family.c, the kept velocities passive), which gives R
 * itself: the relativistic particle in a central field, ignoring phi. */
static qd_status ignored_family(qd_ctx *ctx, const qd_eom *e, qd_routh *r, const qd_expr **R,
                                bool implicit_ok) {
    const qd_expr **cd = arr(ctx, r->nign);
    if (!cd)
        return QD_ERR_NOMEM;
    for (size_t i = 0; i < r->nign; i++)
        cd[i] = e->qd[r->ign_index[i]];
    qd_status st = qd__mech_legendre_family(ctx, e->L, r->nign, cd, r->beta, r->ignvel, R);
    qd__free(cd);
    if (st == QD_ERR_NONLINEAR && implicit_ok)
        return keep_implicit(ctx, e, r);
    if (st == QD_ERR_NONLINEAR)
        qd_ctx_error(ctx, st, "the momentum of %s is not linear in the velocities, and L is "
                              "not F(c'^T G c') + a.c' + L0 in the ignored velocities c' with a "
                              "closed-form inverse: no Routhian in closed form",
                     qd_expr_name(r->ign[0]));
    return st;
}

static qd_status ignored_velocities(qd_ctx *ctx, const qd_eom *e, qd_routh *r, const qd_expr **R,
                                    bool implicit_ok) {
    size_t ni = r->nign, w = ni + 1;
    const qd_expr **A = arr(ctx, ni * w);
    if (!A)
        return QD_ERR_NOMEM;
    qd_status st = QD_OK;
    for (size_t i = 0; st == QD_OK && i < ni; i++) {
        char name[256];
        snprintf(name, sizeof name, "p_%s", qd_expr_name(r->ign[i]));
        r->beta[i] = qd_symbol(ctx, name);
        r->pdef[i] = qd_simplify(ctx, qd_diff(ctx, e->L, e->qd[r->ign_index[i]]));
        st = r->beta[i] && r->pdef[i] ? QD_OK : qd_ctx_status(ctx);
    }
    for (size_t i = 0; st == QD_OK && i < ni; i++)
        st = momentum_row(ctx, e, r, i, A + i * w);
    size_t bad;
    if (st == QD_ERR_NONLINEAR)
        st = ignored_family(ctx, e, r, R, implicit_ok);
    else if (st == QD_OK &&
             (st = qd__mech_gauss_solve(ctx, ni, A, r->ignvel, &bad)) == QD_ERR_SINGULAR)
        qd_ctx_error(ctx, st, "the momenta of the ignored coordinates do not determine their "
                              "velocities (no pivot for %s')", qd_expr_name(r->ign[bad]));
    qd__free(A);
    return st;
}

/* ---- the Routhian and the reduced equations --------------------------------- */

/* x with the ignored velocities replaced by the quadratures' integrands. */
static const qd_expr *reduce(qd_ctx *ctx, const qd_eom *e, const qd_routh *r,
                             const qd_expr *x) {
    const qd_expr **from = arr(ctx, r->nign);
    if (!from)
        return NULL;
    for (size_t i = 0; i < r->nign; i++)
        from[i] = e->qd[r->ign_index[i]];
    const qd_expr *y = qd_subs(ctx, x, r->nign, from, r->ignvel);
    qd__free(from);
    return y;
}

/* R not polynomial in the kept velocities (from ignored_family): R0 = R at
 * k' = 0, R1 its linear part there.  The Jacobi integral of -R is
 * h = R - sum k' dR/dk', which is R0 - R2 when R is quadratic; R2 is
 * defined as R0 - h here so that it keeps that role (the part of R that
 * enters the energy as kinetic), and R = R2 + R1 + R0 no longer holds. */
static qd_status by_value(qd_ctx *ctx, qd_routh *r, const qd_expr *s) {
    const qd_expr **zero = arr(ctx, r->nkeep);
    if (!zero)
        return QD_ERR_NOMEM;
    for (size_t k = 0; k < r->nkeep; k++)
        zero[k] = qd_int(ctx, 0);
    const qd_expr *R1 = qd_int(ctx, 0), *kdR = qd_int(ctx, 0);
    for (size_t k = 0; k < r->nkeep; k++) {
        const qd_expr *d = qd_diff(ctx, s, r->keepd[k]);
        R1 = qd_add(ctx, R1, qd_mul(ctx, qd_subs(ctx, d, r->nkeep, r->keepd, zero), r->keepd[k]));
        kdR = qd_add(ctx, kdR, qd_mul(ctx, r->keepd[k], d));
    }
    r->R = s;
    r->R0 = qd_simplify(ctx, qd_subs(ctx, s, r->nkeep, r->keepd, zero));
    r->R1 = qd_simplify(ctx, R1);
    r->Veff = r->R0;
    r->h = qd_simplify(ctx, qd_sub(ctx, s, kdR));
    r->R2 = qd_simplify(ctx, qd_sub(ctx, r->R0, r->h));
    qd__free(zero);
    return r->R2 && r->h ? QD_OK : qd_ctx_status(ctx);
}

/* R = sum beta c' - L with c' implicit, and its Jacobi integral
 * h = R - sum k' dR/dk' = R + sum k' dL/dk' (envelope theorem: dR/dc' = 0). */
static qd_status implicit_routhian(qd_ctx *ctx, const qd_eom *e, qd_routh *r,
                                   const qd_expr *s) {
    const qd_expr *h = s;
    for (size_t k = 0; k < r->nkeep; k++)
        h = qd_add(ctx, h, qd_mul(ctx, r->keepd[k], qd_diff(ctx, e->L, r->keepd[k])));
    r->R = qd_simplify(ctx, s);
    r->h = qd_simplify(ctx, h);
    return r->R && r->h ? QD_OK : qd_ctx_status(ctx);
}

static qd_status routhian(qd_ctx *ctx, const qd_eom *e, qd_routh *r, const qd_expr *Rfam) {
    const qd_expr *s = qd_neg(ctx, e->L);
    for (size_t i = 0; i < r->nign; i++)
        s = qd_add(ctx, s, qd_mul(ctx, r->beta[i], e->qd[r->ign_index[i]]));
    if (r->implicit)
        return s ? implicit_routhian(ctx, e, r, s) : qd_ctx_status(ctx);
    s = Rfam ? Rfam : reduce(ctx, e, r, s);
    if (!s)
        return qd_ctx_status(ctx) ? qd_ctx_status(ctx) : QD_ERR_NOMEM;
    qd__vsum v;
    qd_status st = qd__mech_by_velocity(ctx, s, r->nkeep, r->keepd, &v);
    if (Rfam && (st == QD_ERR_NONLINEAR || (st == QD_OK && v.top > 2)))
        return by_value(ctx, r, s);
    if (st == QD_OK && v.top > 2)
        st = QD_ERR_NONLINEAR;
    if (st == QD_ERR_NONLINEAR)
        qd_ctx_error(ctx, st, "the Routhian is not quadratic in the kept velocities");
    if (st != QD_OK)
        return st;
    const qd_expr *zero = qd_int(ctx, 0);
    r->R2 = qd_simplify(ctx, v.deg[2] ? v.deg[2] : zero);
    r->R1 = qd_simplify(ctx, v.deg[1] ? v.deg[1] : zero);
    r->R0 = qd_simplify(ctx, v.deg[0] ? v.deg[0] : zero);
    r->R = qd_add(ctx, qd_add(ctx, r->R2, r->R1), r->R0);
    r->Veff = r->R0;
    r->h = qd_simplify(ctx, qd_sub(ctx, r->R0, r->R2));
    return r->R && r->h ? QD_OK : qd_ctx_status(ctx);
}

/* G_ij = dg_i/dk_j - dg_j/dk_i with R1 = sum g_j k'_j. */
static qd_status gyroscopic(qd_ctx *ctx, qd_routh *r) {
    size_t nk = r->nkeep;
    if (r->implicit)
        return QD_OK; /* no R1 to take it from: G stays NULL */
    const qd_expr **g = arr(ctx, nk);
    if (!g)
        return QD_ERR_NOMEM;
    for (size_t i = 0; i < nk; i++)
        g[i] = qd_diff(ctx, r->R1, r->keepd[i]);
    for (size_t i = 0; i < nk; i++)
        for (size_t j = 0; j < nk; j++)
            r->G[i * nk + j] = i == j ? qd_int(ctx, 0)
                                      : qd_simplify(ctx, qd_sub(ctx, qd_diff(ctx, g[i], r->keep[j]),
                                                                qd_diff(ctx, g[j], r->keep[i])));
    qd__free(g);
    return qd_ctx_status(ctx);
}

/* The generalized force on kept coordinate k, dissipation included, with
 * the ignored velocities replaced. */
static const qd_expr *extra(qd_ctx *ctx, const qd_model *m, const qd_eom *e, const qd_routh *r,
                            size_t k) {
    size_t j = r->keep_index[k];
    const qd_expr *Q = qd_model_force(m, j), *D = qd_model_dissipation(m);
    const qd_expr *x = Q ? Q : qd_int(ctx, 0);
    if (D)
        x = qd_sub(ctx, x, qd_diff(ctx, D, e->qd[j]));
    return reduce(ctx, e, r, x);
}

/* The ignored accelerations in terms of the kept ones, from
 * d/dt (dL/dc'_i) = 0 (beta constant), linear in all the accelerations:
 * A c'' = -(rest), solved exactly; acc receives c''_i. */
static qd_status ignored_accelerations(qd_ctx *ctx, const qd_eom *e, const qd_routh *r,
                                       const qd_expr **acc) {
    size_t ni = r->nign, w = ni + 1, bad = 0;
    const qd_expr **A = arr(ctx, ni * w), **cdd = arr(ctx, ni);
    qd_status st = A && cdd ? QD_OK : QD_ERR_NOMEM;
    for (size_t i = 0; st == QD_OK && i < ni; i++)
        cdd[i] = e->qdd[r->ign_index[i]];
    for (size_t i = 0; st == QD_OK && i < ni; i++) {
        const qd_expr *rest = NULL, *dp = qd_dt(ctx, r->pdef[i]);
        st = dp ? qd_linear_coeffs(ctx, dp, ni, cdd, A + i * w, &rest) : qd_ctx_status(ctx);
        if (st == QD_OK && !(A[i * w + ni] = qd_neg(ctx, rest)))
            st = qd_ctx_status(ctx);
    }
    if (st == QD_OK && (st = qd__mech_gauss_solve(ctx, ni, A, acc, &bad)) == QD_ERR_SINGULAR)
        qd_ctx_error(ctx, st, "d^2L/dc'dc' is singular in the ignored velocities: dp/dt = 0 "
                              "does not give %s''", qd_expr_name(r->ign[bad]));
    qd__free(A);
    qd__free(cdd);
    return st;
}

/* E with the ignored accelerations replaced (implicit R only). */
static const qd_expr *no_ignored_acc(qd_ctx *ctx, const qd_eom *e, const qd_routh *r,
                                     const qd_expr *const *acc, const qd_expr *E) {
    if (!r->implicit || !E)
        return E;
    const qd_expr **from = arr(ctx, r->nign);
    if (!from)
        return NULL;
    for (size_t i = 0; i < r->nign; i++)
        from[i] = e->qdd[r->ign_index[i]];
    const qd_expr *y = qd_subs(ctx, E, r->nign, from, acc);
    qd__free(from);
    return y;
}

static qd_status equations(qd_ctx *ctx, const qd_model *m, const qd_eom *e, qd_routh *r) {
    size_t nk = r->nkeep;
    const qd_expr *lag = qd_neg(ctx, r->R), *D = qd_model_dissipation(m);
    const qd_expr **co = arr(ctx, nk), **acc = arr(ctx, r->nign);
    qd_status st = co && acc ? QD_OK : QD_ERR_NOMEM;
    if (st == QD_OK && r->implicit)
        st = ignored_accelerations(ctx, e, r, acc);
    r->conserved = !r->forced && !qd_has(r->R, qd_time(ctx)) && (!D || qd_is_zero(D));
    for (size_t i = 0; st == QD_OK && r->forced && i < r->nign; i++) {
        const qd_expr *Qc = qd_model_force(m, r->ign_index[i]);
        if (!(r->pdot[i] = qd_simplify(ctx, reduce(ctx, e, r, Qc ? Qc : qd_int(ctx, 0)))))
            st = qd_ctx_status(ctx);
    }
    for (size_t pass = 0; st == QD_OK && pass < (r->forced ? 2u : 1u); pass++)
    for (size_t k = 0; st == QD_OK && k < nk; k++) {
        const qd_expr *Q = extra(ctx, m, e, r, k), *rest = NULL;
        r->conserved = r->conserved && Q && qd_is_zero(qd_simplify(ctx, Q));
        const qd_expr *dk = qd_diff(ctx, lag, r->keepd[k]);
        const qd_expr *E = qd_sub(ctx, qd_sub(ctx, qd_dt(ctx, dk), qd_diff(ctx, lag, r->keep[k])),
                                  Q);
        /* d/dt at fixed beta missed beta' (forced): + d(dk)/dbeta_i beta'_i,
         * beta'_i the symbol (pass 0) or Q_c (pass 1) */
        for (size_t i = 0; r->forced && i < r->nign; i++)
            E = qd_add(ctx, E, qd_mul(ctx, qd_diff(ctx, dk, r->beta[i]),
                                      pass == 0 ? r->betad[i] : r->pdot[i]));
        if (!(E = no_ignored_acc(ctx, e, r, acc, E))) {
            st = qd_ctx_status(ctx);
            break;
        }
        st = qd_linear_coeffs(ctx, E, nk, r->keepdd, co, &rest);
        if (st == QD_ERR_NONLINEAR)
            qd_ctx_error(ctx, st, "the reduced equation of %s is not linear in the accelerations",
                         qd_expr_name(r->keep[k]));
        for (size_t j = 0; st == QD_OK && j < nk; j++)
            if (!(r->M[k * nk + j] = qd_simplify(ctx, co[j])))
                st = qd_ctx_status(ctx);
        const qd_expr **fk = r->forced && pass == 0 ? &r->f_betad[k] : &r->f[k];
        if (st == QD_OK && !(*fk = qd_simplify(ctx, qd_neg(ctx, rest))))
            st = qd_ctx_status(ctx);
    }
    qd__free(co);
    qd__free(acc);
    return st;
}

/* ---- the whole reduction ---------------------------------------------------- */

/* Forced (opts.forced): only a generalized force on c itself makes c
 * not cyclic, and that force must not depend on an ignored coordinate. */
static bool forced_ok(const qd_model *m, const qd_eom *e, size_t j, const qd_expr *const *ign,
                      size_t nign, const char **why) {
    const qd_expr *Q = qd_model_force(m, j);
    if (!Q || qd_is_zero(Q))
        return false;
    if (has(e->L, e->q[j]))
        return false;
    const qd_expr *D = qd_model_dissipation(m);
    if (has(D, e->q[j]) || has(D, e->qd[j]))
        return false;
    for (size_t k = 0; k < e->n; k++)
        if (k != j && has(qd_model_force(m, k), e->q[j]))
            return false;
    for (size_t i = 0; i < nign; i++)
        if (has(Q, ign[i])) {
            *why = "its generalized force depends on an ignored coordinate";
            return false;
        }
    return true;
}

static qd_status split(qd_ctx *ctx, const qd_model *m, const qd_eom *e, qd_routh *r,
                       const qd_expr *const *ign, bool forced) {
    bool *is_ign = qd__calloc(ctx, e->n ? e->n : 1, sizeof *is_ign);
    if (!is_ign)
        return QD_ERR_NOMEM;
    qd_status st = QD_OK;
    for (size_t i = 0; st == QD_OK && i < r->nign; i++) {
        size_t j = 0;
        while (j < e->n && e->q[j] != ign[i])
            j++;
        const char *why = NULL;
        if (j == e->n) {
            qd_ctx_error(ctx, QD_ERR_ARG, "'%s' is not a coordinate of the model",
                         ign[i] ? qd_expr_name(ign[i]) : "(null)");
            st = QD_ERR_ARG;
        } else if (is_ign[j]) {
            qd_ctx_error(ctx, QD_ERR_ARG, "%s is ignored twice", qd_expr_name(ign[i]));
            st = QD_ERR_ARG;
        } else if (qd_routh_not_cyclic(ctx, m, e, j, &why) &&
                   !(forced && forced_ok(m, e, j, ign, r->nign, &why))) {
            qd_ctx_error(ctx, QD_ERR_ARG, "%s cannot be ignored: %s", qd_expr_name(ign[i]), why);
            st = QD_ERR_ARG;
        } else {
            if (!qd_is_zero(qd_model_force(m, j)))
                r->forced = true;
            is_ign[j] = true;
            r->ign[i] = e->q[j];
            r->ign_index[i] = j;
        }
    }
    for (size_t j = 0, k = 0; st == QD_OK && j < e->n; j++)
        if (!is_ign[j]) {
            r->keep_index[k] = j;
            r->keep[k] = e->q[j];
            r->keepd[k] = e->qd[j];
            r->keepdd[k++] = e->qdd[j];
        }
    qd__free(is_ign);
    return st;
}

/* betad (p_<c>_dot) and the slots of pdot and f_betad; pdot is filled
 * once the ignored velocities are known (forced_force). */
static qd_status forced_alloc(qd_ctx *ctx, const qd_model *m, qd_routh *r) {
    (void)m;
    r->betad = arr(ctx, r->nign);
    r->pdot = arr(ctx, r->nign);
    r->f_betad = arr(ctx, r->nkeep);
    if (!r->betad || !r->pdot || !r->f_betad)
        return QD_ERR_NOMEM;
    for (size_t i = 0; i < r->nign; i++) {
        char name[160];
        snprintf(name, sizeof name, "p_%s_dot", qd_expr_name(r->ign[i]));
        if (!(r->betad[i] = qd_symbol(ctx, name)))
            return qd_ctx_status(ctx);
    }
    return QD_OK;
}

qd_routh *qd_routh_derive(qd_ctx *ctx, const qd_model *m, const qd_eom *e, size_t nign,
                          const qd_expr *const *ign) {
    QD_ARGS(NULL, ctx && m && e && (nign == 0 || ign));
    return qd_routh_derive_opts(ctx, m, e, nign, ign, NULL);
}

qd_routh *qd_routh_derive_opts(qd_ctx *ctx, const qd_model *m, const qd_eom *e, size_t nign,
                               const qd_expr *const *ign, const qd_routh_opts *opts) {
    QD_ARGS(NULL, ctx && m && e && (nign == 0 || ign));
    if (!ctx || !m || !e || (nign && !ign))
        return NULL;
    if (e->ncon || e->nelim) {
        qd_ctx_error(ctx, QD_ERR_ARG, "Routh's reduction with constraints is not supported");
        return NULL;
    }
    if (!nign || nign >= e->n) {
        qd_ctx_error(ctx, QD_ERR_ARG, nign ? "every coordinate is ignored: nothing is left to reduce to"
                                           : "no coordinate to ignore");
        return NULL;
    }
    qd_routh *r = routh_alloc(ctx, e->n, nign);
    if (!r) {
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory forming the Routhian");
        return NULL;
    }
    const qd_expr *Rfam = NULL; /* R from legendre_family.c when L is not quadratic */
    qd_status st = split(ctx, m, e, r, ign, opts && opts->forced);
    if (st == QD_OK && r->forced)
        st = forced_alloc(ctx, m, r);
    if (st == QD_OK)
        st = ignored_velocities(ctx, e, r, &Rfam, opts && opts->implicit);
    if (st == QD_OK)
        st = routhian(ctx, e, r, Rfam);
    if (st == QD_OK)
        st = gyroscopic(ctx, r);
    if (st == QD_OK)
        st = equations(ctx, m, e, r);
    if (st != QD_OK) {
        if (qd_ctx_status(ctx) == QD_OK)
            qd_ctx_error(ctx, st, "forming the Routhian failed");
        qd_routh_free(r);
        return NULL;
    }
    return r;
}

/* Newton on beta = pdef through the Hamiltonian's solver: a qd_ham view of
 * the ignored velocities only, the kept ones passive among syms. */
qd_status qd_routh_velocities_at(qd_ctx *ctx, const qd_routh *r, const qd_eom *e, size_t nsyms,
                                 const qd_expr *const *syms, const double *vals, double *out) {
    QD_ARGS_CTX(ctx, ctx && r && e && (nsyms == 0 || syms) && (nsyms == 0 || vals) && out);
    if (!ctx || !r || !e || !out)
        return QD_ERR_ARG;
    const qd_expr **cd = arr(ctx, r->nign);
    if (!cd)
        return QD_ERR_NOMEM;
    for (size_t i = 0; i < r->nign; i++)
        cd[i] = e->qd[r->ign_index[i]];
    qd_ham view = {.n = r->nign, .qd = cd, .p = r->beta, .pdef = r->pdef, .implicit = true};
    qd_status st = qd_ham_velocities_at(ctx, &view, nsyms, syms, vals, out);
    qd__free(cd);
    return st;
}

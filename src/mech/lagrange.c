/*
 * src/mech/lagrange.c - Lagrange's equations of a model, M q'' = f.
 *
 * For each coordinate q_j the residual
 *     E_j = d/dt(dL/dq'_j) - dL/dq_j + dD/dq'_j - Q_j
 * is linear in the accelerations (d/dt only brings q'' in through the chain
 * rule on dL/dq'_j); its coefficients are row j of M and f_j is minus the
 * rest.  M_jk = d^2L/dq'_j dq'_k is symmetric, so only j <= k is simplified
 * unless D or Q bring accelerations of their own.  L is grouped by
 * velocity monomials, each coefficient simplified (split.c), before it is
 * differentiated: the trigonometric sums of a chain of links collapse there
 * (x'^2 + y'^2 of a link is a sum of cos(q_j - q_k) q'_j q'_k), and every
 * derivative inherits the short form.  f is grouped the same way.
 * Constraints add their rows afterwards (constraints.c); with
 * --eliminate some are substituted first (eliminate.c).
 */
#include "mech.h"
#include "qdot/hamilton.h"
#include "../base/mem.h"
#include "../base/args.h"

#include <assert.h>
#include <math.h>
#include <stdlib.h>

static qd_eom *eom_alloc(qd_ctx *ctx, size_t n) {
    qd_eom *e = qd__calloc(ctx, 1, sizeof *e);
    if (!e)
        return NULL;
    e->n = n;
    e->q = qd__calloc(ctx, n ? n : 1, sizeof *e->q);
    e->qd = qd__calloc(ctx, n ? n : 1, sizeof *e->qd);
    e->qdd = qd__calloc(ctx, n ? n : 1, sizeof *e->qdd);
    e->M = qd__calloc(ctx, n ? n * n : 1, sizeof *e->M);
    e->f = qd__calloc(ctx, n ? n : 1, sizeof *e->f);
    e->priv = qd__calloc(ctx, 1, sizeof(qd__eom_num));
    if (!e->q || !e->qd || !e->qdd || !e->M || !e->f || !e->priv) {
        qd_eom_free(e);
        return NULL;
    }
    return e;
}

void qd_eom_free(qd_eom *e) {
    if (!e)
        return;
    qd__mech_eom_num_free(e->priv);
    qd__free(e->priv);
    qd__free(e->q);
    qd__free(e->qd);
    qd__free(e->qdd);
    qd__free(e->M);
    qd__free(e->f);
    qd__free(e->acc);
    qd__free(e->mult);
    qd__free(e->con);
    qd__free(e->A);
    qd__free(e->b);
    qd__free(e->elim);
    qd__free(e->reduced);
    qd__free(e);
}

static bool has_any(const qd_expr *x, size_t n, const qd_expr *const *syms) {
    for (size_t i = 0; x && i < n; i++)
        if (qd_has(x, syms[i]))
            return true;
    return false;
}

#ifndef NDEBUG
/* Debug builds: the simplified M_jk must equal the raw coefficient of q''_j
 * in row k (symmetry and a sound simplifier at once), at one state. */
static void check_symmetric(qd_ctx *ctx, const qd_eom *e, size_t j, const qd_expr *raw_kj,
                            size_t k) {
    const qd_expr *syms[64];
    double vals[64], a, b;
    const qd_expr *diff = qd_sub(ctx, e->M[j * e->n + k], raw_kj);
    size_t ns = qd_free_symbols(ctx, diff, syms, 64);
    if (!diff || ns > 64 || qd__ctx_nomem(ctx)) /* no verdict; the error stays recorded */
        return;
    for (size_t i = 0; i < ns; i++)
        vals[i] = 0.37 + 0.61 * (double)((i * 7919 + 13) % 101) / 101.0;
    if (qd_eval(ctx, e->M[j * e->n + k], ns, syms, vals, &a) != QD_OK ||
        qd_eval(ctx, raw_kj, ns, syms, vals, &b) != QD_OK) {
        qd__ctx_recover(ctx);
        return;
    }
    if (isfinite(a) && isfinite(b))
        assert(fabs(a - b) <= 1e-8 * (1 + fabs(a) + fabs(b)));
}
#endif

/* x grouped by velocity monomials where it is a polynomial in them (the
 * common case), else as it is. */
static const qd_expr *grouped(qd_ctx *ctx, const qd_eom *e, const qd_expr *x) {
    qd__vsum v;
    qd_status st = qd__mech_by_velocity(ctx, x, e->n, e->qd, &v);
    return st == QD_OK ? v.all : st == QD_ERR_NONLINEAR ? x : NULL;
}

/* Row j: the coefficients of every acceleration (coeffs, n of them) and
 * f_j. */
static qd_status derive_row(qd_ctx *ctx, qd_eom *e, const qd_expr *L, const qd_expr *D,
                            const qd_expr *Q, size_t j, const qd_expr **coeffs, bool raw) {
    const qd_expr *p = qd_diff(ctx, L, e->qd[j]);
    const qd_expr *E = qd_sub(ctx, qd_dt(ctx, p), qd_diff(ctx, L, e->q[j]));
    if (D)
        E = qd_add(ctx, E, qd_diff(ctx, D, e->qd[j]));
    E = qd_sub(ctx, E, Q);
    if (!E)
        return qd_ctx_status(ctx);
    const qd_expr *rest = NULL;
    qd_status st = qd_linear_coeffs(ctx, E, e->n, e->qdd, coeffs, &rest);
    if (st != QD_OK) {
        if (st != QD_ERR_NONLINEAR)
            return st;
        qd__ctx_recover(ctx); /* the kernel's message names an acceleration, not the equation */
        qd_ctx_error(ctx, st, "the equation of %s is not linear in the accelerations",
                     qd_expr_name(e->q[j]));
        qd_ctx_error_about(ctx, QD_SUBJECT_COORD, j, qd_expr_name(e->q[j]), QD_REASON_NONE, NULL);
        return st;
    }
    e->f[j] = raw ? qd_neg(ctx, rest) : qd_simplify(ctx, grouped(ctx, e, qd_neg(ctx, rest)));
    return e->f[j] ? QD_OK : qd_ctx_status(ctx);
}

/* Fill M's row j from its coefficients: k >= j only when M is known to be
 * symmetric (the lower part is mirrored from earlier rows). */
static qd_status fill_row(qd_ctx *ctx, qd_eom *e, size_t j, const qd_expr **coeffs, bool sym,
                          bool raw) {
    size_t n = e->n;
    for (size_t k = sym ? j : 0; k < n; k++) {
        e->M[j * n + k] = raw ? coeffs[k] : qd_simplify(ctx, coeffs[k]);
        if (!e->M[j * n + k])
            return qd_ctx_status(ctx);
        if (sym)
            e->M[k * n + j] = e->M[j * n + k];
    }
#ifndef NDEBUG
    for (size_t k = 0; sym && !raw && k < j; k++)
        check_symmetric(ctx, e, k, coeffs[k], j);
#endif
    return QD_OK;
}

static qd_status derive_all(qd_ctx *ctx, qd_eom *e, const qd__sys *s, const qd_expr *L,
                            bool raw) {
    bool sym = !has_any(s->D, e->n, e->qdd);
    for (size_t j = 0; j < e->n; j++)
        sym = sym && !has_any(s->Q[j], e->n, e->qdd);
    const qd_expr **coeffs = qd__calloc(ctx, e->n ? e->n : 1, sizeof *coeffs);
    if (!coeffs)
        return QD_ERR_NOMEM;
    qd_status st = QD_OK;
    for (size_t j = 0; j < e->n && st == QD_OK; j++) {
        st = derive_row(ctx, e, L, s->D, s->Q[j], j, coeffs, raw);
        if (st == QD_OK)
            st = fill_row(ctx, e, j, coeffs, sym, raw);
    }
    qd__free(coeffs);
    return st;
}

static qd_status set_coords(qd_ctx *ctx, qd_eom *e, const qd__sys *s) {
    for (size_t j = 0; j < e->n; j++) {
        e->q[j] = s->q[j];
        e->qd[j] = qd_jet(ctx, e->q[j], 1);
        e->qdd[j] = qd_jet(ctx, e->q[j], 2);
        if (!e->qd[j] || !e->qdd[j])
            return qd_ctx_status(ctx);
    }
    return QD_OK;
}

/* L grouped by velocity monomials; when L is T - V - U, T's grouping is
 * reused and only V + U is grouped. */
static const qd_expr *grouped_lagrangian(qd_ctx *ctx, const qd_eom *e, const qd__sys *s,
                                         const qd_expr *Tg) {
    const qd_expr *zero = qd_int(ctx, 0), *Lg = NULL;
    if (Tg && !s->L_given)
        Lg = qd_sub(ctx, Tg, grouped(ctx, e, qd_add(ctx, s->V ? s->V : zero, s->U ? s->U : zero)));
    else
        Lg = grouped(ctx, e, s->L);
    return Lg == s->L ? qd_simplify(ctx, s->L) : Lg;
}

const qd_expr *qd__mech_sys_lagrangian(qd_ctx *ctx, qd_eom *e, const qd__sys *s) {
    qd__vsum vt = {NULL, {NULL, NULL, NULL}, 0, NULL};
    if (!s->L) {
        qd_ctx_error(ctx, QD_ERR_ARG, "the model gives neither T nor L");
        return NULL;
    }
    if (s->T && qd__mech_split_kinetic(ctx, s->T, e->n, e->qd, &vt) != QD_OK)
        return NULL;
    if (s->T && vt.top <= 2) {
        e->T2 = vt.deg[2];
        e->T1 = vt.deg[1];
        e->T0 = vt.deg[0];
    }
    return grouped_lagrangian(ctx, e, s, vt.all);
}

qd_eom *qd__mech_eom_shell(qd_ctx *ctx, const qd__sys *s) {
    qd_eom *e = eom_alloc(ctx, s->n);
    if (!e) {
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory deriving the equations of motion");
        return NULL;
    }
    if (set_coords(ctx, e, s) != QD_OK || qd__mech_con_setup(ctx, e, s, false) != QD_OK) {
        qd_eom_free(e);
        return NULL;
    }
    return e;
}

qd_status qd__mech_eom_rows(qd_ctx *ctx, qd_eom *e, const qd__sys *s, const qd_expr *L, bool raw) {
    e->L = L;
    return derive_all(ctx, e, s, L, raw);
}

static qd_status derive(qd_ctx *ctx, qd_eom *e, const qd__sys *s) {
    qd_status st = set_coords(ctx, e, s);
    if (st != QD_OK)
        return st;
    e->L = qd__mech_sys_lagrangian(ctx, e, s);
    if (!e->L)
        return qd_ctx_status(ctx);
    st = derive_all(ctx, e, s, e->L, false);
    if (st == QD_OK)
        st = qd__mech_con_setup(ctx, e, s, true);
    if (st == QD_OK && (st = qd__mech_check_singular(ctx, e, s->T)) == QD_ERR_SINGULAR)
        qd_ctx_error_about(ctx, QD_SUBJECT_STATEMENT, 0, s->L_given ? "L" : "T",
                           QD_REASON_SINGULAR_MASS,
                           "every coordinate needs inertia: its velocity must appear "
                           "quadratically in T (or L)");
    return st;
}

static qd_status derive_sys(qd_ctx *ctx, qd__sys *s, const qd_model *m, const qd_eom_opts *opts,
                            qd_eom **out) {
    qd_elim *elim = NULL;
    size_t nelim = 0;
    qd_status st = qd__mech_sys_from_model(ctx, m, s);
    if (st == QD_OK && opts && opts->eliminate)
        st = qd__mech_eliminate(ctx, s, &elim, &nelim);
    if (st == QD_OK && !(*out = eom_alloc(ctx, s->n))) {
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory deriving the equations of motion");
        st = QD_ERR_NOMEM;
    }
    if (st != QD_OK) {
        qd__free(elim);
        return st;
    }
    (*out)->elim = elim;
    (*out)->nelim = nelim;
    (*out)->reduced = s->reduced; /* the eom owns them now */
    (*out)->nreduced = s->nreduced;
    s->reduced = NULL;
    s->nreduced = 0;
    return derive(ctx, *out, s);
}

qd_eom *qd_eom_derive_opts(qd_ctx *ctx, const qd_model *m, const qd_eom_opts *opts) {
    QD_ARGS(NULL, ctx && m);
    if (!ctx || !m)
        return NULL;
    qd__sys s;
    qd_eom *e = NULL;
    qd_status st = derive_sys(ctx, &s, m, opts, &e);
    qd__mech_sys_free(&s);
    if (st != QD_OK) {
        if (qd_ctx_status(ctx) == QD_OK)
            qd_ctx_error(ctx, st, "deriving the equations of motion failed");
        qd_eom_free(e);
        return NULL;
    }
    return e;
}

qd_eom *qd_eom_derive(qd_ctx *ctx, const qd_model *m) { QD_ARGS(NULL, ctx && m); return qd_eom_derive_opts(ctx, m, NULL); }

/* ---- the system a model describes ---------------------------------------- */

void qd__mech_sys_free(qd__sys *s) {
    qd__free(s->q);
    qd__free(s->Q);
    qd__free(s->con_name);
    qd__free(s->con_expr);
    qd__free(s->reduced);
    *s = (qd__sys){0};
}

qd_status qd__mech_sys_from_model(qd_ctx *ctx, const qd_model *m, qd__sys *s) {
    size_t n = qd_model_ncoords(m), nc = qd_model_nconstraints(m);
    *s = (qd__sys){.n = n, .ncon = nc, .L_given = qd_model_lagrangian_given(m)};
    s->q = qd__malloc(ctx, (n + 1) * sizeof *s->q);
    s->Q = qd__malloc(ctx, (n + 1) * sizeof *s->Q);
    s->con_name = qd__malloc(ctx, (nc + 1) * sizeof *s->con_name);
    s->con_expr = qd__malloc(ctx, (nc + 1) * sizeof *s->con_expr);
    if (!s->q || !s->Q || !s->con_name || !s->con_expr) {
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory deriving the equations of motion");
        return QD_ERR_NOMEM;
    }
    for (size_t j = 0; j < n; j++) {
        s->q[j] = qd_model_coord(m, j);
        s->Q[j] = qd_model_force(m, j);
    }
    for (size_t k = 0; k < nc; k++) {
        s->con_name[k] = qd_model_constraint_name(m, k);
        s->con_expr[k] = qd_model_constraint(m, k);
    }
    s->T = qd_model_kinetic(m);
    s->V = qd_model_potential(m);
    s->U = qd_model_gen_potential(m);
    /* a model given by H: its Lagrangian by the inverse Legendre transform */
    s->L = qd_model_hamiltonian_given(m) ? qd_legendre_inverse(ctx, m) : qd_model_lagrangian(m);
    if (!s->L && qd_model_hamiltonian_given(m))
        return qd_ctx_status(ctx);
    s->D = qd_model_dissipation(m);
    return QD_OK;
}

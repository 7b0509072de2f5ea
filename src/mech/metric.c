/*
 * src/mech/metric.c - the metric of the generalized coordinates, its
 * conjugate, the Christoffel symbols, the geodesic form of Lagrange's
 * equations, and the chart's Jacobian (qdot/metric.h).
 *
 * Desloge vol. 2, App. 23 eqs. 14-23 (metric, conjugate, Christoffel
 * symbols), ch. 55 eqs. 5-12 (Lagrange's equations as the covariant form of
 * Newton's), ch. 47 eqs. 13-18 (generalized, physical and ordinary
 * components), App. 18 (a vanishing Jacobian: where the chart fails).
 */
#include "mech.h"

#include <math.h>
#include <string.h>

#include "base/args.h"
#include "base/mem.h"
#include "qdot/form.h"
#include "qdot/metric.h"

static const qd_expr **exprs(qd_ctx *ctx, size_t n) {
    return qd__calloc(ctx, n ? n : 1, sizeof(const qd_expr *));
}

void qd_metric_free(qd_metric *g) {
    if (!g)
        return;
    qd__free(g->q);
    qd__free(g->g);
    qd__free(g->first);
    qd__free(g->Q);
    qd__free(g->pos);
    qd__free(g->pos_particle);
    qd__free(g->pos_axis);
    qd__free(g->jac);
    qd__free(g->e);
    qd__free(g->sing);
    qd__free(g->h);
    qd__free(g);
}

/* Every entry of the arrays is set (an allocation failed otherwise). */
static qd_status all_set(qd_ctx *ctx, size_t k, const qd_expr *const *x) {
    for (size_t i = 0; i < k; i++)
        if (!x[i])
            return qd_ctx_status(ctx) != QD_OK ? qd_ctx_status(ctx) : QD_ERR_NOMEM;
    return QD_OK;
}

/* g_ij = d^2 T2 / dq'_i dq'_j from the velocity-quadratic part of T (or L). */
static qd_status metric_entries(qd_ctx *ctx, qd_metric *g, const qd_model *m) {
    size_t n = g->n;
    const qd_expr *T = qd_model_kinetic(m);
    g->source = T ? T : qd_model_lagrangian(m);
    g->from_L = !T;
    qd__vsum v;
    qd_status st = qd__mech_split_kinetic(ctx, g->source, n, g->qd, &v);
    if (st != QD_OK)
        return st;
    if (v.top > 2) {
        qd_ctx_error(ctx, QD_ERR_NONLINEAR, "%s is of degree %ld in the velocities: a metric "
                     "needs a kinetic energy quadratic in them", T ? "T" : "L", v.top);
        return QD_ERR_NONLINEAR;
    }
    const qd_expr *T2 = v.deg[2] ? v.deg[2] : qd_int(ctx, 0);
    g->T1 = v.deg[1] ? v.deg[1] : qd_int(ctx, 0);
    g->T0 = v.deg[0] ? v.deg[0] : qd_int(ctx, 0);
    if (!T)  /* L = T2 + (terms of degree 1, 0): only T2 is the metric's */
        g->T1 = g->T0 = qd_int(ctx, 0);
    for (size_t i = 0; i < n; i++)
        for (size_t j = i; j < n; j++) {
            const qd_expr *x = qd_diff(ctx, qd_diff(ctx, T2, g->qd[i]), g->qd[j]);
            g->g[i * n + j] = g->g[j * n + i] = x ? qd_simplify(ctx, x) : NULL;
        }
    st = all_set(ctx, n * n, g->g);
    g->T2 = T2;
    return st;
}

/* g^ij by solving g X = I, and det g. */
static qd_status conjugate(qd_ctx *ctx, qd_metric *g) {
    size_t n = g->n;
    const qd_expr **I = exprs(ctx, n * n);
    if (!I)
        return QD_ERR_NOMEM;
    for (size_t i = 0; i < n * n; i++)
        I[i] = qd_int(ctx, i / n == i % n);
    g->det = qd__mech_det(ctx, n, g->g);
    if (g->det)
        g->det = qd_simplify(ctx, g->det);
    qd_status st = g->det ? QD_OK : qd_ctx_status(ctx);
    if (st == QD_OK && qd_is_zero(g->det)) {
        qd_ctx_error(ctx, QD_ERR_SINGULAR, "the metric is singular: det g = 0 (the kinetic "
                     "energy does not determine every velocity)");
        st = QD_ERR_SINGULAR;
    }
    if (st == QD_OK)
        st = qd__mech_solve_cols(ctx, n, g->g, n, I, g->ginv, 0);
    if (st == QD_ERR_SINGULAR && qd_ctx_status(ctx) == QD_OK)
        qd_ctx_error(ctx, st, "the metric is singular");
    qd__free(I);
    return st;
}

/* [ij,l] and Gamma^l_ij, App. 23 eqs. 22-23. */
static qd_status christoffel(qd_ctx *ctx, qd_metric *g) {
    size_t n = g->n;
    const qd_expr *half = qd_rat(ctx, 1, 2);
    const qd_expr **dg = exprs(ctx, n * n * n); /* d_k g_ij at (k*n + i)*n + j */
    if (!dg)
        return QD_ERR_NOMEM;
    for (size_t k = 0; k < n; k++)
        for (size_t i = 0; i < n * n; i++)
            dg[k * n * n + i] = qd_diff(ctx, g->g[i], g->q[k]);
    qd_status st = all_set(ctx, n * n * n, dg);
    for (size_t l = 0; st == QD_OK && l < n; l++)
        for (size_t i = 0; i < n; i++)
            for (size_t j = 0; j < n; j++) {
                const qd_expr *s = qd_sub(ctx, qd_add(ctx, dg[(i * n + j) * n + l],
                                                      dg[(j * n + i) * n + l]),
                                          dg[(l * n + i) * n + j]);
                s = s ? qd_simplify(ctx, qd_mul(ctx, half, s)) : NULL;
                g->first[(l * n + i) * n + j] = s;
            }
    if (st == QD_OK)
        st = all_set(ctx, n * n * n, g->first);
    const qd_expr **terms = exprs(ctx, n);
    for (size_t l = 0; st == QD_OK && terms && l < n; l++)
        for (size_t i = 0; i < n; i++)
            for (size_t j = 0; j < n; j++) {
                for (size_t k = 0; k < n; k++)
                    terms[k] = qd_mul(ctx, g->ginv[l * n + k], g->first[(k * n + i) * n + j]);
                const qd_expr *s = all_set(ctx, n, terms) == QD_OK
                                       ? qd_add_n(ctx, n, terms) : NULL;
                g->second[(l * n + i) * n + j] = s ? qd_simplify(ctx, s) : NULL;
            }
    if (st == QD_OK)
        st = terms ? all_set(ctx, n * n * n, g->second) : QD_ERR_NOMEM;
    qd__free(terms);
    qd__free(dg);
    return st;
}

/* Q_k = dL'/dq_k - d/dt dL'/dq'_k - dD/dq'_k + force_k, L' = L - T2. */
static qd_status forces(qd_ctx *ctx, qd_metric *g, const qd_model *m) {
    size_t n = g->n;
    const qd_expr *L = qd_model_lagrangian(m), *D = qd_model_dissipation(m);
    const qd_expr *Lp = qd_sub(ctx, L, g->T2);
    for (size_t k = 0; Lp && k < n; k++) {
        const qd_expr *x = qd_sub(ctx, qd_diff(ctx, Lp, g->q[k]),
                                  qd_dt(ctx, qd_diff(ctx, Lp, g->qd[k])));
        if (D && x)
            x = qd_sub(ctx, x, qd_diff(ctx, D, g->qd[k]));
        x = x ? qd_add(ctx, x, qd_model_force(m, k)) : NULL;
        g->Q[k] = x ? qd_simplify(ctx, x) : NULL;
        for (size_t j = 0; g->Q[k] && j < n; j++)
            if (qd_has(g->Q[k], g->qdd[j])) {
                qd_ctx_error(ctx, QD_ERR_NONLINEAR, "the forces besides the metric's depend on "
                             "the accelerations (through L - T2): no geodesic form");
                return QD_ERR_NONLINEAR;
            }
    }
    qd_status st = Lp ? all_set(ctx, n, g->Q) : QD_ERR_NOMEM;
    if (st == QD_OK)
        st = qd_metric_force(ctx, g, g->Q, g->Qup, NULL, NULL);
    const qd_expr **terms = exprs(ctx, n * n + 2);
    for (size_t l = 0; st == QD_OK && terms && l < n; l++) {
        size_t k = 0;
        terms[k++] = g->qdd[l];
        terms[k++] = qd_neg(ctx, g->Qup[l]);
        for (size_t i = 0; i < n; i++)
            for (size_t j = 0; j < n; j++)
                terms[k++] = qd_mul_n(ctx, 3, (const qd_expr *[]){g->second[(l * n + i) * n + j],
                                                                   g->qd[i], g->qd[j]});
        const qd_expr *s = all_set(ctx, k, terms) == QD_OK ? qd_add_n(ctx, k, terms) : NULL;
        g->geodesic[l] = s ? qd_simplify(ctx, s) : NULL;
    }
    if (st == QD_OK)
        st = terms ? all_set(ctx, n, g->geodesic) : QD_ERR_NOMEM;
    qd__free(terms);
    return st;
}

/* ---- the chart ---------------------------------------------------------------- */

/* The particles' position components that are not identically zero. */
static qd_status positions(qd_ctx *ctx, qd_metric *g, const qd_model *m) {
    size_t np = qd_model_nparticles(m);
    if (!np || qd_model_nbodies(m))
        return QD_OK;
    g->pos = exprs(ctx, 3 * np);
    g->pos_particle = qd__calloc(ctx, 3 * np, sizeof *g->pos_particle);
    g->pos_axis = qd__calloc(ctx, 3 * np, sizeof *g->pos_axis);
    if (!g->pos || !g->pos_particle || !g->pos_axis)
        return QD_ERR_NOMEM;
    for (size_t p = 0; p < np; p++)
        for (unsigned k = 0; k < 3; k++) {
            const qd_expr *x = qd_model_particle_position(m, p, k);
            bool moves = false;
            for (size_t i = 0; x && i < g->n; i++)
                moves = moves || qd_has(x, g->q[i]);
            if (!moves)
                continue;
            g->pos[g->npos] = x;
            g->pos_particle[g->npos] = p;
            g->pos_axis[g->npos++] = k;
        }
    return QD_OK;
}

static qd_status chart(qd_ctx *ctx, qd_metric *g) {
    size_t n = g->n, r = g->npos;
    g->jac = exprs(ctx, r * n);
    g->e = exprs(ctx, n * n);
    const qd_expr **terms = exprs(ctx, r);
    if (!g->jac || !g->e || !terms) {
        qd__free(terms);
        return QD_ERR_NOMEM;
    }
    for (size_t a = 0; a < r; a++)
        for (size_t i = 0; i < n; i++) {
            const qd_expr *x = qd_diff(ctx, g->pos[a], g->q[i]);
            g->jac[a * n + i] = x ? qd_simplify(ctx, x) : NULL;
        }
    qd_status st = all_set(ctx, r * n, g->jac);
    for (size_t i = 0; st == QD_OK && i < n; i++)
        for (size_t j = i; j < n; j++) {
            for (size_t a = 0; a < r; a++)
                terms[a] = qd_mul(ctx, g->jac[a * n + i], g->jac[a * n + j]);
            const qd_expr *s = all_set(ctx, r, terms) == QD_OK ? qd_add_n(ctx, r, terms) : NULL;
            g->e[i * n + j] = g->e[j * n + i] = s ? qd_simplify(ctx, s) : NULL;
        }
    qd__free(terms);
    if (st == QD_OK)
        st = all_set(ctx, n * n, g->e);
    if (st == QD_OK && r == n) {
        g->jac_det = qd__mech_det(ctx, n, g->jac);
        g->jac_det = g->jac_det ? qd_simplify(ctx, g->jac_det) : NULL;
        st = g->jac_det ? QD_OK : qd_ctx_status(ctx);
    }
    if (st == QD_OK) {
        g->e_det = qd__mech_det(ctx, n, g->e);
        g->e_det = g->e_det ? qd_simplify(ctx, g->e_det) : NULL;
        st = g->e_det ? QD_OK : qd_ctx_status(ctx);
    }
    return st;
}

/* The zeros of det in the coordinates (qd__mech_zero_set, zero_set.c). */
static qd_status singular_set(qd_ctx *ctx, qd_metric *g, const qd_expr *det) {
    g->sing_of = det;
    return qd__mech_zero_set(ctx, det, g->n, g->q, &g->sing, &g->nsing);
}

/* h_i = sqrt(e_ii) (or sqrt(g_ii)) and whether the coordinates are orthogonal. */
static qd_status scales(qd_ctx *ctx, qd_metric *g) {
    size_t n = g->n;
    const qd_expr **e = g->e ? g->e : g->g;
    g->scale_geometric = g->e != NULL;
    g->orthogonal = true;
    for (size_t i = 0; i < n; i++)
        for (size_t j = 0; j < n; j++)
            g->orthogonal = g->orthogonal && (i == j || qd_is_zero(e[i * n + j]));
    for (size_t i = 0; i < n; i++) {
        const qd_expr *x = qd_sqrt(ctx, e[i * n + i]);
        g->h[i] = x ? qd_simplify(ctx, x) : NULL;
    }
    return all_set(ctx, n, g->h);
}

static qd_metric *metric_alloc(qd_ctx *ctx, const qd_model *m) {
    size_t n = qd_model_ncoords(m);
    qd_metric *g = qd__calloc(ctx, 1, sizeof *g);
    if (!g)
        return NULL;
    g->n = n;
    g->q = exprs(ctx, 3 * n);
    g->g = exprs(ctx, 2 * n * n);
    g->first = exprs(ctx, 2 * n * n * n);
    g->Q = exprs(ctx, 3 * n);
    g->h = exprs(ctx, n);
    if (!g->q || !g->g || !g->first || !g->Q || !g->h) {
        qd_metric_free(g);
        return NULL;
    }
    g->qd = g->q + n;
    g->qdd = g->qd + n;
    g->ginv = g->g + n * n;
    g->second = g->first + n * n * n;
    g->Qup = g->Q + n;
    g->geodesic = g->Qup + n;
    for (size_t i = 0; i < n; i++) {
        g->q[i] = qd_model_coord(m, i);
        g->qd[i] = qd_jet(ctx, g->q[i], 1);
        g->qdd[i] = qd_jet(ctx, g->q[i], 2);
    }
    return g;
}

qd_metric *qd_metric_new(qd_ctx *ctx, const qd_model *m) {
    if (!ctx || !m)
        return NULL;
    if (qd_model_hamiltonian_given(m) && !qd_model_kinetic(m)) {
        qd_ctx_error(ctx, QD_ERR_ARG, "the model is given by H: the metric is read from T "
                     "(give T and V, or L)");
        return NULL;
    }
    qd_metric *g = metric_alloc(ctx, m);
    qd_status st = g ? metric_entries(ctx, g, m) : QD_ERR_NOMEM;
    if (st == QD_OK)
        st = conjugate(ctx, g);
    if (st == QD_OK)
        st = christoffel(ctx, g);
    if (st == QD_OK)
        st = forces(ctx, g, m);
    if (st == QD_OK)
        st = positions(ctx, g, m);
    if (st == QD_OK && g->npos)
        st = chart(ctx, g);
    if (st == QD_OK)
        st = singular_set(ctx, g, g->jac_det ? g->jac_det : g->e_det ? g->e_det : g->det);
    if (st == QD_OK)
        st = scales(ctx, g);
    if (g)
        g->constrained = qd_model_nconstraints(m) > 0;
    if (st != QD_OK) {
        if (qd_ctx_status(ctx) == QD_OK)
            qd_ctx_error(ctx, st, "cannot form the metric: %s", qd_status_str(st));
        qd_metric_free(g);
        return NULL;
    }
    return g;
}

/* ---- components ----------------------------------------------------------------- */

/* out = A x (A n*n, x n), each entry simplified. */
static qd_status mat_vec(qd_ctx *ctx, size_t n, const qd_expr *const *A, const qd_expr *const *x,
                         const qd_expr **out) {
    const qd_expr **terms = exprs(ctx, n);
    if (!terms)
        return QD_ERR_NOMEM;
    for (size_t i = 0; i < n; i++) {
        for (size_t j = 0; j < n; j++)
            terms[j] = qd_mul(ctx, A[i * n + j], x[j]);
        const qd_expr *s = all_set(ctx, n, terms) == QD_OK ? qd_add_n(ctx, n, terms) : NULL;
        out[i] = s ? qd_simplify(ctx, s) : NULL;
    }
    qd__free(terms);
    return all_set(ctx, n, out);
}

qd_status qd_metric_lower(qd_ctx *ctx, const qd_metric *g, const qd_expr *const *A,
                          const qd_expr **low) {
    QD_ARGS_CTX(ctx, ctx && g && A && low);
    return mat_vec(ctx, g->n, g->g, A, low);
}

qd_status qd_metric_force(qd_ctx *ctx, const qd_metric *g, const qd_expr *const *G,
                          const qd_expr **up, const qd_expr **phys, const qd_expr **ord) {
    QD_ARGS_CTX(ctx, ctx && g && G);
    size_t n = g->n;
    qd_status st = up ? mat_vec(ctx, n, g->ginv, G, up) : QD_OK;
    for (size_t i = 0; st == QD_OK && phys && i < n; i++) {
        phys[i] = qd_simplify(ctx, qd_div(ctx, G[i], g->h[i]));
        st = phys[i] ? QD_OK : qd_ctx_status(ctx);
    }
    if (st != QD_OK || !ord)
        return st;
    /* e^ij G_j with the metric the scale factors come from */
    const qd_expr **einv = exprs(ctx, n * n + n), **I = exprs(ctx, n * n);
    if (!einv || !I) {
        qd__free(einv);
        qd__free(I);
        return QD_ERR_NOMEM;
    }
    for (size_t i = 0; i < n * n; i++)
        I[i] = qd_int(ctx, i / n == i % n);
    st = g->e ? qd__mech_solve_cols(ctx, n, g->e, n, I, einv, 0) : QD_OK;
    if (st == QD_ERR_SINGULAR)
        qd_ctx_error(ctx, st, "the positions' metric e_ij is singular: the particles' "
                     "positions do not determine the coordinates");
    if (st == QD_OK)
        st = mat_vec(ctx, n, g->e ? einv : g->ginv, G, einv + n * n);
    for (size_t i = 0; st == QD_OK && i < n; i++) {
        ord[i] = qd_simplify(ctx, qd_mul(ctx, g->h[i], einv[n * n + i]));
        st = ord[i] ? QD_OK : qd_ctx_status(ctx);
    }
    qd__free(einv);
    qd__free(I);
    return st;
}

qd_gram *qd_metric_gram_schmidt(qd_ctx *ctx, const qd_metric *g) {
    QD_ARGS(NULL, ctx && g);
    size_t n = g->n;
    const qd_expr **I = qd__calloc(ctx, n * n + 1, sizeof *I);
    if (!I)
        return NULL;
    for (size_t i = 0; i < n * n; i++)
        I[i] = qd_int(ctx, i / n == i % n);
    qd_gram *gs = qd_gram_schmidt(ctx, n, g->g, n, I);
    qd__free(I);
    return gs;
}

/*
 * src/speeds/appell.c - the Gibbs-Appell function S and its equations
 * dS/du'_r = Pi_r (Desloge ch. 69-70).
 *
 * S comes from the accelerations themselves where the model says what
 * moves: each particle gives m/2 |r''|^2, each body (Desloge ch. 70 thm 1,
 * thm 2) M/2 |c''|^2 + 1/2 a.I a + a.(w x I w), w and a = w' its body-axis
 * angular velocity and acceleration, with q' and q'' in speeds, so that the
 * constraints are in S before it is differentiated (seed pitfall 13).  The
 * part of T the model gives otherwise (`T = ...`; or L itself when `L = ...`
 * is given) has no accelerations to square; for it S is built from its own
 * Lagrange expression, E_j = M_jk q''_k + h_j, as 1/2 q''.M q'' + h.q'',
 * whose derivative by u'_r is sum_j W_jr E_j: the same dS/du' as the
 * particles' sum (Desloge ch. 69 lemma: dq''/du' = dq'/du = W).
 *
 * The terms of S free of u' are dropped: S - S(u' = 0).
 */
#include "spd.h"

#include "../base/mem.h"

static const qd_expr *dot3(qd_ctx *ctx, const qd_expr *const a[3], const qd_expr *const b[3]) {
    return qd_add(ctx, qd_add(ctx, qd_mul(ctx, a[0], b[0]), qd_mul(ctx, a[1], b[1])),
                  qd_mul(ctx, a[2], b[2]));
}

/* v = r' and a = r'' of a point r(q, t), in speeds. */
static void point_motion(qd__spd *d, const qd_expr *const r[3], const qd_expr *v[3],
                         const qd_expr *a[3]) {
    for (unsigned k = 0; k < 3; k++) {
        v[k] = qd__spd_on_motion(d, qd_dt(d->ctx, r[k]));
        a[k] = qd__spd_dt(d, v[k]);
    }
}

/* m/2 |a|^2 and m/2 |v|^2 of a particle or a body's centre. */
static void translation(qd__spd *d, const qd_expr *mass, const qd_expr *const r[3],
                        const qd_expr **S, const qd_expr **T) {
    qd_ctx *ctx = d->ctx;
    const qd_expr *v[3], *a[3], *half = qd_rat(ctx, 1, 2);
    point_motion(d, r, v, a);
    *S = qd_mul(ctx, qd_mul(ctx, half, mass), dot3(ctx, a, a));
    *T = qd_mul(ctx, qd_mul(ctx, half, mass), dot3(ctx, v, v));
}

/* 1/2 a.I a + a.(w x I w) and 1/2 w.I w of body i. */
static void rotation(qd__spd *d, size_t i, const qd_expr **S, const qd_expr **T) {
    qd_ctx *ctx = d->ctx;
    const qd_model *m = d->model;
    const qd_expr *w[3], *a[3], *Iw[3], *Ia[3], *wxIw[3], *half = qd_rat(ctx, 1, 2);
    for (unsigned k = 0; k < 3; k++) {
        w[k] = qd__spd_on_motion(d, qd_model_body_omega(m, i, k));
        a[k] = qd__spd_dt(d, w[k]);
    }
    for (unsigned r = 0; r < 3; r++) {
        Iw[r] = Ia[r] = qd_int(ctx, 0);
        for (unsigned c = 0; c < 3; c++) {
            const qd_expr *I = qd_model_body_inertia(m, i, r, c);
            Iw[r] = qd_add(ctx, Iw[r], qd_mul(ctx, I, w[c]));
            Ia[r] = qd_add(ctx, Ia[r], qd_mul(ctx, I, a[c]));
        }
    }
    for (unsigned k = 0; k < 3; k++)
        wxIw[k] = qd_sub(ctx, qd_mul(ctx, w[(k + 1) % 3], Iw[(k + 2) % 3]),
                         qd_mul(ctx, w[(k + 2) % 3], Iw[(k + 1) % 3]));
    *S = qd_add(ctx, qd_mul(ctx, half, dot3(ctx, a, Ia)), dot3(ctx, a, wxIw));
    *T = qd_mul(ctx, half, dot3(ctx, w, Iw));
}

/* S and T of every particle and body; *T in speeds. */
static const qd_expr *bodies(qd__spd *d, const qd_expr **T) {
    qd_ctx *ctx = d->ctx;
    const qd_model *m = d->model;
    const qd_expr *S = qd_int(ctx, 0), *s, *t;
    *T = qd_int(ctx, 0);
    for (size_t i = 0; i < qd_model_nparticles(m); i++) {
        const qd_expr *r[3];
        for (unsigned k = 0; k < 3; k++)
            r[k] = qd_model_particle_position(m, i, k);
        translation(d, qd_model_particle_mass(m, i), r, &s, &t);
        S = qd_add(ctx, S, s), *T = qd_add(ctx, *T, t);
    }
    for (size_t i = 0; i < qd_model_nbodies(m); i++) {
        const qd_expr *r[3];
        for (unsigned k = 0; k < 3; k++)
            r[k] = qd_model_body_position(m, i, k);
        translation(d, qd_model_body_mass(m, i), r, &s, &t);
        S = qd_add(ctx, S, s), *T = qd_add(ctx, *T, t);
        rotation(d, i, &s, &t);
        S = qd_add(ctx, S, s), *T = qd_add(ctx, *T, t);
    }
    return S;
}

/* 1/2 q''.M q'' + h.q'' of F's Lagrange expression, in speeds. */
static const qd_expr *from_lagrange(qd__spd *d, const qd_expr *F) {
    qd_ctx *ctx = d->ctx;
    size_t n = d->n;
    const qd_eom *sh = d->shell;
    const qd_expr **c = qd__malloc(ctx, (n + 1) * sizeof *c);
    if (!c)
        return NULL;
    const qd_expr *S = qd_int(ctx, 0), *half = qd_rat(ctx, 1, 2);
    for (size_t j = 0; S && j < n; j++) {
        const qd_expr *E = qd_sub(ctx, qd_dt(ctx, qd_diff(ctx, F, sh->qd[j])),
                                  qd_diff(ctx, F, sh->q[j]));
        const qd_expr *h = NULL;
        if (!E || qd_linear_coeffs(ctx, E, n, sh->qdd, c, &h) != QD_OK) {
            S = NULL;
            break;
        }
        for (size_t k = 0; k < n; k++)
            S = qd_add(ctx, S, qd_mul(ctx, qd_mul(ctx, half, c[k]),
                                      qd_mul(ctx, sh->qdd[j], sh->qdd[k])));
        S = qd_add(ctx, S, qd_mul(ctx, h, sh->qdd[j]));
    }
    qd__free(c);
    return qd__spd_on_motion(d, S);
}

/* S with the constant-in-u' part of the model's T (or L) that particles and
 * bodies do not account for. */
static const qd_expr *appell_function(qd__spd *d) {
    qd_ctx *ctx = d->ctx;
    if (d->sys.L_given)
        return from_lagrange(d, d->L);
    const qd_expr *Tpb = NULL, *S = bodies(d, &Tpb);
    const qd_expr *T = d->e->T ? d->e->T : qd__spd_on_motion(d, d->sys.T);
    const qd_expr *rest = qd__spd_tidy(d, qd_sub(ctx, T, Tpb));
    if (!S || !rest)
        return NULL;
    if (qd_is_zero(rest))
        return S;
    /* the remainder in q' again: T_rest as the model gives it, less particles and bodies */
    const qd_expr *Tq = qd_int(ctx, 0);
    const qd_model *m = d->model;
    for (size_t i = 0; i < qd_model_nparticles(m); i++) {
        const qd_expr *r[3], *v[3];
        for (unsigned k = 0; k < 3; k++)
            r[k] = qd_model_particle_position(m, i, k), v[k] = qd_dt(ctx, r[k]);
        Tq = qd_add(ctx, Tq, qd_mul(ctx, qd_mul(ctx, qd_rat(ctx, 1, 2),
                                                qd_model_particle_mass(m, i)), dot3(ctx, v, v)));
    }
    for (size_t i = 0; i < qd_model_nbodies(m); i++) {
        const qd_expr *r[3], *v[3], *w[3], *Iw[3];
        for (unsigned k = 0; k < 3; k++) {
            r[k] = qd_model_body_position(m, i, k), v[k] = qd_dt(ctx, r[k]);
            w[k] = qd_model_body_omega(m, i, k);
        }
        for (unsigned a = 0; a < 3; a++) {
            Iw[a] = qd_int(ctx, 0);
            for (unsigned b = 0; b < 3; b++)
                Iw[a] = qd_add(ctx, Iw[a], qd_mul(ctx, qd_model_body_inertia(m, i, a, b), w[b]));
        }
        Tq = qd_add(ctx, Tq, qd_mul(ctx, qd_rat(ctx, 1, 2),
                                    qd_add(ctx, qd_mul(ctx, qd_model_body_mass(m, i),
                                                       dot3(ctx, v, v)),
                                           dot3(ctx, w, Iw))));
    }
    return qd_add(ctx, S, from_lagrange(d, qd_sub(ctx, d->sys.T, Tq)));
}

/* S - S(u' = 0), grouped by monomials in u' and simplified. */
static const qd_expr *drop_free(qd__spd *d, const qd_expr *S) {
    qd_ctx *ctx = d->ctx;
    size_t m = d->m;
    const qd_expr **zero = qd__malloc(ctx, (m + 1) * sizeof *zero);
    if (!zero || !S) {
        qd__free(zero);
        return NULL;
    }
    for (size_t r = 0; r < m; r++)
        zero[r] = qd_int(ctx, 0);
    S = qd_sub(ctx, S, qd_subs(ctx, S, m, d->e->ud, zero));
    qd__free(zero);
    if (S && !qd__spd_small(d, S)) /* too large to group: kept as a DAG */
        return S;
    qd__vsum v;
    qd_status st = S ? qd__mech_by_velocity(ctx, S, m, d->e->ud, &v) : QD_ERR_NOMEM;
    if (st == QD_ERR_TOOBIG && qd__ctx_recover(ctx))
        return S;
    if (st != QD_OK && st != QD_ERR_NONLINEAR)
        return NULL;
    return qd__spd_simplify(d, st == QD_OK ? v.all : S);
}

qd_status qd__spd_appell(qd__spd *d, bool fill) {
    qd_ctx *ctx = d->ctx;
    qd_speeds_eom *e = d->e;
    size_t n = d->n, m = d->m;
    const qd_expr *S = appell_function(d);
    if (!S)
        return qd_ctx_status(ctx) != QD_OK ? qd_ctx_status(ctx) : QD_ERR_NOMEM;
    if (!fill) {
        e->S = drop_free(d, S);
        return e->S ? QD_OK : qd_ctx_status(ctx);
    }
    const qd_expr **G = qd__calloc(ctx, n + m + 1, sizeof *G), **rows = G + n;
    if (!G)
        return QD_ERR_NOMEM;
    qd_status st = QD_OK;
    for (size_t j = 0; st == QD_OK && j < n; j++)
        if (!(G[j] = qd__spd_force(d, j)))
            st = qd_ctx_status(ctx);
    for (size_t r = 0; st == QD_OK && r < m; r++) {
        const qd_expr *x = qd_diff(ctx, S, e->ud[r]);
        for (size_t j = 0; j < n; j++)
            if (!qd_is_zero(e->W[j * m + r]))
                x = qd_sub(ctx, x, qd_mul(ctx, e->W[j * m + r], G[j]));
        if (!(rows[r] = x))
            st = qd_ctx_status(ctx);
    }
    if (st == QD_OK)
        st = qd__spd_rows(d, rows);
    if (st == QD_OK && !(e->S = drop_free(d, S)))
        st = qd_ctx_status(ctx);
    qd__free(G);
    return st;
}

/*
 * src/speeds/hamel.c - the Boltzmann-Hamel equations (Desloge ch. 68).
 *
 * All n quasi-velocities v = (u, s): the speeds and s = C q' + c0, which is
 * 0 on the motion but not in L*(q, v, t) = L at q' = W u + Wc s + w, whose
 * derivatives by s carry the constraints' effect.  Projecting Lagrange's
 * equation on column r of P^-1 (the chain rule through v = P q' + p0):
 *
 *     d/dt d(L*)/du_r - sum_j W_jr d(L*)/dq_j
 *       + sum_s d(L*)/dv_s B_sr = sum_j W_jr (Q_j - dD/dq'_j),
 *     B_sr = sum_j W_jr (sum_k (dP_sj/dq_k - dP_sk/dq_j) q'_k
 *                        + dP_sj/dt - dp0_s/dq_j),
 *
 * every derivative of L* at fixed v, then s = 0 (s' = 0 too, so setting s
 * before d/dt is the same).  The dP/dq terms are Hamel's three-index
 * symbols gamma (seed-desloge-C.md pitfall 2: with Desloge's index order
 * Euler angles give gamma = -eps); the dt and dp0 terms are the rheonomic
 * and affine parts Desloge's ch. 68 leaves out (he takes a_i = b_i = 0).
 * A holonomic constraint's row is a gradient, so its B vanishes.
 */
#include "spd.h"

#include "../base/mem.h"
#include "../base/args.h"

#include <stdio.h>

typedef struct hamel {
    qd__spd *d;
    const qd_expr **sig;   /* ncon symbols s_k */
    const qd_expr **zero;  /* ncon zeros */
    const qd_expr *Lstar;  /* L*(q, u, s, t) */
} hamel;

static const qd_expr *at_rest(hamel *h, const qd_expr *x) {
    return x && h->d->nc ? qd_subs(h->d->ctx, x, h->d->nc, h->sig, h->zero) : x;
}

/* L*: the velocities written in all n quasi-velocities. */
static const qd_expr *lstar(hamel *h) {
    qd__spd *d = h->d;
    qd_ctx *ctx = d->ctx;
    size_t n = d->n, m = d->m;
    const qd_expr **v = qd__malloc(ctx, (n + 1) * sizeof *v);
    if (!v)
        return NULL;
    for (size_t j = 0; j < n; j++) {
        const qd_expr *x = d->e->kin[j];
        for (size_t k = 0; k < d->nc; k++)
            x = qd_add(ctx, x, qd_mul(ctx, d->Pinv[j * n + m + k], h->sig[k]));
        v[j] = x;
    }
    const qd_expr *L = qd_subs(ctx, d->L, n, d->e->qd, v);
    qd__free(v);
    return L;
}

/* d(L*)/dv_s at s = 0: v_s is speed s for s < m, else s_(s-m). */
static const qd_expr *dL_dv(hamel *h, size_t s) {
    qd__spd *d = h->d;
    const qd_expr *v = s < d->m ? d->e->u[s] : h->sig[s - d->m];
    return at_rest(h, qd_diff(d->ctx, h->Lstar, v));
}

/* B_sr of the head comment. */
static const qd_expr *bracket(hamel *h, size_t s, size_t r) {
    qd__spd *d = h->d;
    qd_ctx *ctx = d->ctx;
    size_t n = d->n, m = d->m;
    const qd_expr *t = qd_time(ctx), *B = qd_int(ctx, 0);
    const qd_expr *const *P = d->P + s * n;
    for (size_t j = 0; j < n; j++) {
        const qd_expr *Wjr = d->e->W[j * m + r];
        if (qd_is_zero(Wjr))
            continue;
        const qd_expr *x = qd_sub(ctx, qd_diff(ctx, P[j], t), qd_diff(ctx, d->p0[s], d->e->q[j]));
        for (size_t k = 0; k < n; k++) {
            const qd_expr *c = qd_sub(ctx, qd_diff(ctx, P[j], d->e->q[k]),
                                      qd_diff(ctx, P[k], d->e->q[j]));
            if (c && !qd_is_zero(c))
                x = qd_add(ctx, x, qd_mul(ctx, c, d->e->kin[k]));
        }
        B = qd_add(ctx, B, qd_mul(ctx, Wjr, x));
    }
    return B ? qd__spd_simplify(d, B) : NULL;
}

/* The nonconservative forces the kinetic part and L* leave: Q - dD/dq'. */
static const qd_expr *applied(qd__spd *d, size_t j) {
    qd_ctx *ctx = d->ctx;
    const qd_expr *G = d->sys.Q[j] ? d->sys.Q[j] : qd_int(ctx, 0);
    if (d->sys.D)
        G = qd_sub(ctx, G, qd_diff(ctx, d->sys.D, d->shell->qd[j]));
    return qd__spd_on_motion(d, G);
}

static const qd_expr *row(hamel *h, size_t r, const qd_expr *const *dLdv) {
    qd__spd *d = h->d;
    qd_ctx *ctx = d->ctx;
    size_t n = d->n, m = d->m;
    const qd_expr *x = qd__spd_dt(d, dLdv[r]);
    for (size_t j = 0; x && j < n; j++) {
        const qd_expr *Wjr = d->e->W[j * m + r];
        if (qd_is_zero(Wjr))
            continue;
        const qd_expr *dq = at_rest(h, qd_diff(ctx, h->Lstar, d->e->q[j]));
        x = qd_sub(ctx, x, qd_mul(ctx, Wjr, qd_add(ctx, dq, applied(d, j))));
    }
    for (size_t s = 0; x && s < n; s++) {
        if (qd_is_zero(dLdv[s]))
            continue;
        const qd_expr *B = bracket(h, s, r);
        if (B && !qd_is_zero(B))
            x = qd_add(ctx, x, qd_mul(ctx, dLdv[s], B));
    }
    return x;
}

qd_status qd__spd_hamel(qd__spd *d) {
    qd_ctx *ctx = d->ctx;
    size_t n = d->n, m = d->m, nc = d->nc;
    hamel h = {.d = d};
    h.sig = qd__calloc(ctx, 2 * nc + 2 * n + m + 1, sizeof *h.sig);
    if (!h.sig)
        return QD_ERR_NOMEM;
    h.zero = h.sig + nc;
    const qd_expr **dLdv = h.sig + 2 * nc, **rows = dLdv + n;
    qd_status st = QD_OK;
    for (size_t k = 0; k < nc; k++) {
        char name[48];
        snprintf(name, sizeof name, "_hamel_s%zu", k);
        h.sig[k] = qd_symbol(ctx, name);
        h.zero[k] = qd_int(ctx, 0);
    }
    h.Lstar = lstar(&h);
    for (size_t s = 0; h.Lstar && s < n; s++)
        if (!(dLdv[s] = dL_dv(&h, s)))
            h.Lstar = NULL;
    for (size_t r = 0; h.Lstar && r < m; r++)
        if (!(rows[r] = row(&h, r, dLdv)))
            h.Lstar = NULL;
    st = h.Lstar ? qd__spd_rows(d, rows) : qd_ctx_status(ctx);
    qd__free(h.sig);
    return st != QD_OK ? st : QD_OK;
}

/* ---- Hamel's coefficients gamma_ikm (Desloge ch. 68) ------------------------ */

qd_status qd_hamel_coefficients(qd_ctx *ctx, size_t n, const qd_expr *const *q,
                                const qd_expr *const *a, const qd_expr **out) {
    QD_ARGS_CTX(ctx, ctx && (n == 0 || (q && a && out)));
    const qd_expr **b = qd__calloc(ctx, 2 * n * n + 1, sizeof *b), **I = b + n * n;
    if (!b) {
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory forming Hamel's coefficients");
        return QD_ERR_NOMEM;
    }
    for (size_t i = 0; i < n * n; i++)
        I[i] = qd_int(ctx, i / n == i % n);
    qd_status st = qd__mech_solve_cols(ctx, n, a, n, I, b, 0);
    if (st == QD_ERR_SINGULAR)
        qd_ctx_error(ctx, st, "the velocity map is singular: the quasi-velocities are dependent");
    for (size_t i = 0; st == QD_OK && i < n; i++)
        for (size_t k = 0; k < n; k++)
            for (size_t m = 0; m < n; m++) {
                const qd_expr *g = qd_int(ctx, 0);
                for (size_t j = 0; j < n; j++)
                    for (size_t l = 0; l < n; l++) {
                        const qd_expr *c = qd_sub(ctx, qd_diff(ctx, a[k * n + j], q[l]),
                                                  qd_diff(ctx, a[k * n + l], q[j]));
                        if (c && !qd_is_zero(qd_simplify(ctx, c)))
                            g = qd_add(ctx, g, qd_mul(ctx, c, qd_mul(ctx, b[j * n + i], b[l * n + m])));
                    }
                out[(i * n + k) * n + m] = qd_simplify(ctx, g);
            }
    if (st == QD_OK)
        st = qd_ctx_status(ctx);
    qd__free(b);
    return st;
}

qd_status qd_speeds_hamel_coefficients(qd_ctx *ctx, const qd_speeds_eom *e, const qd_expr **out) {
    QD_ARGS_CTX(ctx, ctx && e && out);
    size_t n = e->n;
    const qd_expr **a = qd__calloc(ctx, n * n + 1, sizeof *a);
    if (!a) {
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory forming Hamel's coefficients");
        return QD_ERR_NOMEM;
    }
    for (size_t r = 0; r < e->m; r++)
        for (size_t j = 0; j < n; j++)
            a[r * n + j] = qd_simplify(ctx, qd_diff(ctx, e->def[r], e->qd[j]));
    for (size_t k = 0; k < e->ncon && e->m + k < n; k++)
        for (size_t j = 0; j < n; j++)
            a[(e->m + k) * n + j] = e->con[k].a[j];
    qd_status st = qd_ctx_status(ctx);
    if (st == QD_OK)
        st = qd_hamel_coefficients(ctx, n, e->q, a, out);
    qd__free(a);
    return st;
}

/*
 * src/render/ham_point.c - H and Hamilton's equations at one point
 * (qd_ham_point_eval, qdot/render.h): what `qdot hamiltonian --at` prints,
 * as numbers any caller may use.  For an implicit H (L not quadratic in
 * q', no closed form for the velocities) the velocities at the point come
 * first, by Newton's method on p = dL/dq' (qd_ham_velocities_at), since H
 * and the equations are then in q, q', p, t.
 */
#include "render.h"
#include "qdot/state.h"

#include <math.h>
#include <string.h>
#include "../base/args.h"
#include "../base/mem.h"

void qd_ham_point_free(qd_ham_point *pt) {
    if (!pt)
        return;
    qd__free(pt->q); /* one block: q, p, qd, dq, dp */
    memset(pt, 0, sizeof *pt);
}

static size_t slot_of(size_t nvals, const qd_expr *const *syms, const qd_expr *x) {
    size_t k = 0;
    while (k < nvals && syms[k] != x)
        k++;
    return k;
}

/* x at the state into *v: a finite number, else an error in ctx. */
static qd_status value(qd_ctx *ctx, const qd_expr *x, size_t n, const qd_expr *const *syms,
                       const double *vals, double *v) {
    qd_status st = qd_eval(ctx, x, n, syms, vals, v);
    if (st == QD_OK && !isfinite(*v)) {
        qd_ctx_error(ctx, QD_ERR_NUMERIC, "not a finite number: %g", *v);
        st = QD_ERR_NUMERIC;
    }
    return st;
}

/* The point's q, p and t from the state: each must be there. */
static qd_status read_point(qd_ctx *ctx, const qd_ham *h, size_t nvals,
                            const qd_expr *const *syms, const double *vals, qd_ham_point *out) {
    const qd_expr *t = qd_time(ctx);
    for (size_t j = 0; j < 2 * h->n + 1; j++) {
        const qd_expr *x = j < h->n ? h->q[j] : j < 2 * h->n ? h->p[j - h->n] : t;
        size_t k = x ? slot_of(nvals, syms, x) : nvals;
        if (k == nvals) {
            qd_ctx_error(ctx, QD_ERR_ARG, "the point gives no value to %s",
                         x ? qd_expr_name(x) : "t");
            return QD_ERR_ARG;
        }
        *(j < h->n ? &out->q[j] : j < 2 * h->n ? &out->p[j - h->n] : &out->t) = vals[k];
    }
    return QD_OK;
}

/* The state with the velocities h->qd at the point's (Newton's for an
 * implicit H): a copy of syms/vals, the velocities set or appended. */
static qd_status with_velocities(qd_ctx *ctx, const qd_ham *h, size_t nvals,
                                 const qd_expr *const *syms, const double *vals,
                                 const qd_expr **s2, double *v2, size_t *n2,
                                 qd_ham_point *out) {
    memcpy(s2, syms, nvals * sizeof *s2);
    memcpy(v2, vals, nvals * sizeof *v2);
    *n2 = nvals;
    if (!h->implicit)
        return QD_OK;
    qd_status st = qd_ham_velocities_at(ctx, h, nvals, syms, vals, out->qd);
    for (size_t j = 0; st == QD_OK && j < h->n; j++) {
        if (!isfinite(out->qd[j])) {
            qd_ctx_error(ctx, QD_ERR_NUMERIC, "not a finite number: %g", out->qd[j]);
            return QD_ERR_NUMERIC;
        }
        size_t k = slot_of(nvals, syms, h->qd[j]);
        if (k == nvals) {
            s2[*n2] = h->qd[j];
            k = (*n2)++;
        }
        v2[k] = out->qd[j];
    }
    out->solved = st == QD_OK;
    return st;
}

qd_status qd_ham_point_eval(qd_ctx *ctx, const qd_ham *h, size_t nvals,
                            const qd_expr *const *syms, const double *vals,
                            qd_ham_point *out) {
    QD_ARGS_CTX(ctx, ctx && h && (nvals == 0 || syms) && (nvals == 0 || vals) && out);
    memset(out, 0, sizeof *out);
    size_t n = h->n;
    out->n = n;
    double *block = qd__calloc(ctx, 5 * n + 1, sizeof *block);
    const qd_expr **s2 = qd__malloc(ctx, (nvals + n + 1) * sizeof *s2);
    double *v2 = qd__malloc(ctx, (nvals + n + 1) * sizeof *v2);
    qd_status st = block && s2 && v2 ? QD_OK : QD_ERR_NOMEM;
    if (block) {
        out->q = block;
        out->p = block + n;
        out->qd = block + 2 * n;
        out->dq = block + 3 * n;
        out->dp = block + 4 * n;
    }
    size_t n2 = 0;
    if (st == QD_OK)
        st = read_point(ctx, h, nvals, syms, vals, out);
    if (st == QD_OK)
        st = with_velocities(ctx, h, nvals, syms, vals, s2, v2, &n2, out);
    if (st == QD_OK)
        st = value(ctx, h->H, n2, s2, v2, &out->H);
    for (size_t j = 0; st == QD_OK && j < n; j++) {
        st = value(ctx, h->dq[j], n2, s2, v2, &out->dq[j]);
        if (st == QD_OK)
            st = value(ctx, h->dp[j], n2, s2, v2, &out->dp[j]);
    }
    for (size_t j = 0; st == QD_OK && !h->implicit && j < n; j++)
        st = value(ctx, h->vel[j], n2, s2, v2, &out->qd[j]);
    qd__free(s2);
    qd__free(v2);
    return st;
}

/* The state `qdot hamiltonian --at` reads: m's (every coordinate, velocity
 * and t 0, the parameters at their values) with h's momenta after it. */
qd_status qd_ham_point_at(qd_ctx *ctx, const qd_model *m, const qd_ham *h, const char *at,
                          qd_ham_point *out) {
    QD_ARGS_CTX(ctx, ctx && m && h && at && out);
    memset(out, 0, sizeof *out);
    qd_state st = {0};
    qd_status s = qd_state_init(ctx, m, &st);
    if (s == QD_OK)
        s = qd_state_append(ctx, &st, h->n, h->p, NULL);
    if (s == QD_OK)
        s = qd_state_read(ctx, m, &st, at, NULL);
    if (s == QD_OK)
        s = qd_ham_point_eval(ctx, h, st.n, st.syms, st.vals, out);
    qd_state_free(&st);
    return s;
}

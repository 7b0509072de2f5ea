/*
 * src/linear/symmetry_perm.c - the collection of symmetry operations, and
 * the operations of a model without particle geometry: the permutations of
 * the coordinates (q_i -> q_p(i)) that leave M0 and K0 invariant, found by
 * backtracking over the coordinates in order, each image checked against
 * the entries of M0 and K0 shared with the coordinates already placed.
 * Only when no permutation but the identity is one are signs allowed
 * (q_i -> s_i q_p(i)): -I leaves every quadratic form invariant, so a
 * signed group always holds it, and {I, -I} alone is no symmetry.
 */
#include "symmetry.h"

#include "base/mem.h"

#include <math.h>
#include <string.h>

void qd__lin_symm_matmul(size_t n, const double *A, const double *B, double *C) {
    for (size_t i = 0; i < n; i++)
        for (size_t j = 0; j < n; j++) {
            double t = 0;
            for (size_t k = 0; k < n; k++)
                t += A[i * n + k] * B[k * n + j];
            C[i * n + j] = t;
        }
}

static double max_abs(size_t len, const double *a) {
    double m = 0;
    for (size_t i = 0; i < len; i++)
        m = fmax(m, fabs(a[i]));
    return m;
}

bool qd__lin_symm_invariant(size_t n, const double *S, const double *A) {
    double tol = QD_SYMMETRY_TOL * max_abs(n * n, A);
    for (size_t i = 0; i < n; i++)
        for (size_t j = 0; j < n; j++) {
            double t = 0;   /* (S^T A S)_ij */
            for (size_t k = 0; k < n; k++) {
                double sk = S[k * n + i];
                if (sk == 0)
                    continue;
                for (size_t l = 0; l < n; l++)
                    t += sk * A[k * n + l] * S[l * n + j];
            }
            if (fabs(t - A[i * n + j]) > tol)
                return false;
        }
    return true;
}

static double trace3(const double *R) {
    return R[0] + R[4] + R[8];
}

bool qd__lin_symm_ops_add(qd_ctx *ctx, qd__symm_ops *o, const double *S, const double *R) {
    size_t nn = o->n * o->n;
    for (size_t g = 0; g < o->count; g++) {
        double *T = o->S + g * nn;
        size_t i = 0;
        while (i < nn && fabs(T[i] - S[i]) <= 1e-8)
            i++;
        if (i < nn)
            continue;
        if (R && trace3(R) > trace3(o->R + 9 * g) + 1e-9)
            memcpy(o->R + 9 * g, R, 9 * sizeof *R);
        return true;
    }
    if (o->count == QD_SYMMETRY_MAX_ORDER) {
        o->overflow = true;
        return true;
    }
    if (o->count == o->cap) {
        size_t cap = o->cap ? 2 * o->cap : 8;
        double *s2 = qd__realloc(ctx, o->S, cap * nn * sizeof *s2);
        if (!s2)
            return false;
        o->S = s2;
        double *r2 = qd__realloc(ctx, o->R, cap * 9 * sizeof *r2);
        if (!r2)
            return false;
        o->R = r2;
        o->cap = cap;
    }
    memcpy(o->S + o->count * nn, S, nn * sizeof *S);
    for (int k = 0; k < 9; k++)
        o->R[9 * o->count + k] = R ? R[k] : (k % 4 == 0);
    o->count++;
    return true;
}

void qd__lin_symm_ops_free(qd__symm_ops *o) {
    qd__free(o->S);
    qd__free(o->R);
    memset(o, 0, sizeof *o);
}

typedef struct perm_search {
    qd_ctx *ctx;
    const qd_linear *lin;
    qd__symm_ops *ops;
    size_t *p;
    int *sg;
    bool *used;
    double *S;
    double tolM, tolK;
    int lowest_sign;   /* 1: permutations only; -1: signed */
    bool nomem;
} perm_search;

/* Coordinate i going to s q_j agrees with M0 and K0 on the coordinates
 * placed before it. */
static bool fits(const perm_search *ps, size_t i, size_t j, int s) {
    size_t n = ps->lin->n;
    const double *M = ps->lin->M, *K = ps->lin->K;
    for (size_t a = 0; a <= i; a++) {
        size_t pa = a == i ? j : ps->p[a];
        double sa = a == i ? s : ps->sg[a];
        if (fabs(M[pa * n + j] * sa * s - M[a * n + i]) > ps->tolM ||
            fabs(K[pa * n + j] * sa * s - K[a * n + i]) > ps->tolK)
            return false;
    }
    return true;
}

static void place(perm_search *ps, size_t i) {
    size_t n = ps->lin->n;
    if (ps->nomem || ps->ops->overflow)
        return;
    if (i == n) {
        memset(ps->S, 0, n * n * sizeof *ps->S);
        for (size_t a = 0; a < n; a++)
            ps->S[ps->p[a] * n + a] = ps->sg[a];
        ps->nomem = !qd__lin_symm_ops_add(ps->ctx, ps->ops, ps->S, NULL);
        return;
    }
    for (size_t j = 0; j < n; j++)
        for (int s = 1; s >= ps->lowest_sign && !ps->used[j]; s -= 2)
            if (fits(ps, i, j, s)) {
                ps->p[i] = j;
                ps->sg[i] = s;
                ps->used[j] = true;
                place(ps, i + 1);
                ps->used[j] = false;
            }
}

qd_status qd__lin_symm_permutations(qd_ctx *ctx, const qd_linear *lin, qd__symm_ops *ops) {
    size_t n = lin->n;
    perm_search ps = {.ctx = ctx, .lin = lin, .ops = ops, .lowest_sign = 1};
    ps.tolM = QD_SYMMETRY_TOL * max_abs(n * n, lin->M);
    ps.tolK = QD_SYMMETRY_TOL * max_abs(n * n, lin->K);
    ps.p = qd__calloc(ctx, n + 1, sizeof *ps.p);
    ps.sg = qd__calloc(ctx, n + 1, sizeof *ps.sg);
    ps.used = qd__calloc(ctx, n + 1, sizeof *ps.used);
    ps.S = qd__calloc(ctx, n * n + 1, sizeof *ps.S);
    if (ps.p && ps.sg && ps.used && ps.S)
        place(&ps, 0);
    else
        ps.nomem = true;
    if (!ps.nomem && ops->count == 1) {
        ps.lowest_sign = -1;
        place(&ps, 0);
        if (ops->count == 2)
            ops->count = 1;   /* {I, -I}: nothing but the inversion of every form */
    }
    qd__free(ps.p);
    qd__free(ps.sg);
    qd__free(ps.used);
    qd__free(ps.S);
    return ps.nomem ? QD_ERR_NOMEM : QD_OK;
}

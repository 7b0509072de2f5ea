/*
 * src/mech/closure.c - how many relations among the coordinates do the
 * constraints imply together?
 *
 * The m constraint forms w_k = sum_j a_kj dq_j + a_k0 dt (holonomic ones as
 * their differentials, Pfaffian ones as given) annihilate a distribution D
 * on the N = n + 1 variables x = (q, t).  Every relation phi(q, t) = const
 * the motion must keep has d phi vanishing on D, hence on the smallest
 * involutive distribution containing D, and by Frobenius there are exactly
 * N - dim of that closure of them (Desloge ch. 49: the configurational
 * degrees of freedom are n minus their number; Goldstein ch. 1 derivation 5
 * and seed-goldstein-britannica.md P11: on the two-wheel axle no single
 * constraint is integrable, yet th - a (p1 - p2)/(2b) = const).
 *
 * The closure is D_{k+1} = D_k + [D_0, D_k] (Isidori, Nonlinear Control
 * Systems, sec. 1.8), computed with symbolic vector fields and measured by
 * its rank at a few random points: a kernel basis of the forms from Cramer's
 * rule (each field scaled by the pivot determinant, which spans the same
 * distribution without a division), Lie brackets [X, Y]^i = X(Y^i) - Y(X^i)
 * by differentiation, and a field kept only when it raises the rank at some
 * point (one in the span of the kept ones adds nothing: [X, f Y] lies in
 * f [X, Y] + span Y).  The rank is the one of the fields evaluated at the
 * points; a field is independent of the kept ones when what Gram-Schmidt
 * leaves of it exceeds RANK_TOL of its size, and a component counts as 0
 * when it simplifies to 0 or is below RANK_TOL of the terms it adds (round
 * off in an identity the simplifier missed).  Parameters take random values
 * too, and user functions stand-ins (generic()): the count holds for generic
 * values and functions.
 */
#include "mech.h"
#include "base/mem.h"
#include "../base/args.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#define NPTS 3
#define MAXV 32       /* variables (n + 1) and symbols in the forms */
#define RANK_TOL 1e-7
/* Forms with a coefficient of more than BIG_NODES DAG nodes take the
 * numeric path (measured: the examples' forms have at most 14 nodes and
 * close in milliseconds; the Whipple bicycle's front contact has 57, and
 * its determinants and simplified brackets ran out of memory): kernel
 * fields by elimination on the DAG, brackets unsimplified, and a field's
 * verdict only across a gap: what Gram-Schmidt leaves of it is below BIG_DEP
 * (dependent) or above BIG_IND (independent) of its size, else the count is
 * undecided (QD_ERR_NUMERIC, never a guess).  Measured on the bicycle: the
 * fields kept leave at least 4.7e-3, the dependent ones at most 5.8e-8
 * (round-off of deep brackets, most below 1e-11). */
#define BIG_NODES 32
#define BIG_DEP 1e-6
#define BIG_IND 1e-4

typedef struct closure {
    qd_ctx *ctx;
    size_t N;                     /* variables x = (q, t) */
    const qd_expr *x[MAXV];
    size_t ns;                    /* symbols given values: x, then the parameters */
    const qd_expr *syms[MAXV];
    double pt[NPTS][MAXV];
    size_t nbase;                 /* fields D_0 */
    const qd_expr **base;         /* nbase * N */
    size_t nkept;                 /* fields kept, the base ones first; at most N */
    const qd_expr *kept[MAXV][MAXV];
    double basis[NPTS][MAXV][MAXV]; /* orthonormal basis of the kept fields at each point */
    size_t rank[NPTS];
    size_t nrows, rows[MAXV];     /* the independent forms */
    const qd_expr **w;            /* m * N coefficients, user functions made generic */
    bool big;                     /* the numeric path (BIG_NODES) */
    bool undecided;               /* a field neither clearly in nor out of the span */
} closure;

static uint64_t splitmix(uint64_t *s) {
    uint64_t z = (*s += 0x9e3779b97f4a7c15u);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9u;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebu;
    return z ^ (z >> 31);
}

/* In 0.3..1.7 at the first point (inside log and sqrt domains), of either
 * sign at the others. */
static double random_value(uint64_t *s, int k) {
    double v = 0.3 + 1.4 * (double)(splitmix(s) >> 11) / 9007199254740992.0;
    return k > 0 && (splitmix(s) & 1) ? -v : v;
}

/* ---- evaluation ------------------------------------------------------------- */

/* e at point k; false when it has no finite value there. */
static bool value_at(closure *c, const qd_expr *e, int k, double *out) {
    if (qd_eval(c->ctx, e, c->ns, c->syms, c->pt[k], out) != QD_OK) {
        qd__ctx_recover(c->ctx);
        return false;
    }
    return isfinite(*out);
}

/* e at point k, 0 when it is round-off in a sum of larger terms. */
static bool component_at(closure *c, const qd_expr *e, int k, double *out) {
    if (qd_is_zero(e)) {
        *out = 0;
        return true;
    }
    if (!value_at(c, e, k, out))
        return false;
    double scale = fabs(*out), term;
    for (size_t i = 0; qd_expr_kind(e) == QD_ADD && i < qd_expr_nargs(e); i++)
        if (value_at(c, qd_expr_arg(e, i), k, &term))
            scale = fmax(scale, fabs(term));
    if (fabs(*out) <= RANK_TOL * 1e-3 * scale)
        *out = 0;
    return true;
}

/* What Gram-Schmidt leaves of v against the basis at point k, normalised;
 * true when it raises the rank there. */
static bool independent_at(closure *c, int k, double *v) {
    double norm0 = 0, norm = 0;
    for (size_t i = 0; i < c->N; i++)
        norm0 += v[i] * v[i];
    if (norm0 == 0)
        return false;
    for (int pass = 0; pass < 2; pass++) /* twice is enough (Kahan) */
        for (size_t b = 0; b < c->rank[k]; b++) {
            double dot = 0;
            for (size_t i = 0; i < c->N; i++)
                dot += c->basis[k][b][i] * v[i];
            for (size_t i = 0; i < c->N; i++)
                v[i] -= dot * c->basis[k][b][i];
        }
    for (size_t i = 0; i < c->N; i++)
        norm += v[i] * v[i];
    /* unsimplified fields carry the round-off of identities the simplifier
     * would have cancelled: in between BIG_DEP and BIG_IND no verdict */
    if (c->big && norm > BIG_DEP * BIG_DEP * norm0 && norm < BIG_IND * BIG_IND * norm0)
        c->undecided = true;
    if (norm <= (c->big ? BIG_DEP * BIG_DEP : RANK_TOL * RANK_TOL) * norm0)
        return false;
    for (size_t i = 0; i < c->N; i++)
        v[i] /= sqrt(norm);
    return true;
}

/* component_at for all N components at every point, for big fields: one
 * compiled program of the components and their top-level terms, run at
 * each point (qd_eval per component walks the shared DAG again each time).
 * ok[k] false where a value is not finite; false when it cannot compile. */
static bool big_values(closure *c, const qd_expr *const *f, double v[NPTS][MAXV], bool *ok) {
    size_t nout = 0;
    for (size_t i = 0; i < c->N; i++)
        nout += 1 + (qd_expr_kind(f[i]) == QD_ADD ? qd_expr_nargs(f[i]) : 0);
    const qd_expr **outs = qd__malloc(c->ctx, (nout + 1) * sizeof *outs);
    double *val = qd__malloc(c->ctx, (nout + 1) * sizeof *val);
    qd_prog *p = NULL;
    if (outs && val) {
        size_t o = 0;
        for (size_t i = 0; i < c->N; i++) {
            outs[o++] = f[i];
            for (size_t t = 0; qd_expr_kind(f[i]) == QD_ADD && t < qd_expr_nargs(f[i]); t++)
                outs[o++] = qd_expr_arg(f[i], t);
        }
        p = qd_prog_new(c->ctx, c->ns, c->syms, nout, outs);
    }
    for (int k = 0; p && k < NPTS; k++) {
        qd_prog_run(p, c->pt[k], val);
        ok[k] = true;
        for (size_t i = 0, o = 0; i < c->N; i++) {
            double x = val[o++], scale = fabs(x);
            for (size_t t = 0; qd_expr_kind(f[i]) == QD_ADD && t < qd_expr_nargs(f[i]); t++)
                scale = fmax(scale, fabs(val[o++]));
            ok[k] = ok[k] && isfinite(x);
            v[k][i] = qd_is_zero(f[i]) || fabs(x) <= RANK_TOL * 1e-3 * scale ? 0 : x;
        }
    }
    if (!p && !qd__ctx_nomem(c->ctx))
        qd__ctx_recover(c->ctx); /* not compilable: component by component */
    qd_prog_free(p);
    qd__free(outs);
    qd__free(val);
    return p != NULL;
}

/* Keep the field f (N components) when it raises the rank at some point. */
static void offer(closure *c, const qd_expr *const *f) {
    double v[NPTS][MAXV];
    bool raises[NPTS] = {false}, any = false, okb[NPTS];
    if (c->nkept >= c->N)
        return;
    bool fast = c->big && big_values(c, f, v, okb);
    for (int k = 0; k < NPTS; k++) {
        bool ok = true;
        if (fast)
            ok = okb[k];
        for (size_t i = 0; !fast && i < c->N && ok; i++)
            ok = component_at(c, f[i], k, &v[k][i]);
        raises[k] = ok && independent_at(c, k, v[k]);
        any |= raises[k];
    }
    if (!any)
        return;
    for (int k = 0; k < NPTS; k++)
        if (raises[k])
            memcpy(c->basis[k][c->rank[k]++], v[k], c->N * sizeof v[k][0]);
    memcpy(c->kept[c->nkept++], f, c->N * sizeof *f);
}

static size_t generic_rank(const closure *c) {
    size_t r = 0;
    for (int k = 0; k < NPTS; k++)
        r = r > c->rank[k] ? r : c->rank[k];
    return r;
}

/* ---- the forms and their kernel ---------------------------------------------- */

/* Row k of the forms: the coefficient of x_j. */
static const qd_expr *coef(closure *c, const qd_con *con, size_t k, size_t j) {
    if (j + 1 < c->N)
        return con[k].a[j];
    return con[k].a0 ? con[k].a0 : qd_int(c->ctx, 0);
}

/* The same with each user function f(u1, ...) replaced by a fixed random
 * analytic one, 11/10 + sin(k0 + k1 u1 + ...)/2: the count is for generic
 * functions as it is for generic parameters (f(y) = const could make a
 * combination integrable that generically is not). */
static const qd_expr *generic(const closure *c, size_t k, size_t j) { return c->w[k * c->N + j]; }

static size_t user_functions(const qd_expr *e, const qd_expr **out, size_t n, size_t cap) {
    if (qd_expr_kind(e) == QD_UFUNC) {
        for (size_t i = 0; i < n; i++)
            if (out[i] == e)
                return n;
        if (n < cap)
            out[n++] = e;
    }
    for (size_t i = 0; i < qd_expr_nargs(e); i++)
        n = user_functions(qd_expr_arg(e, i), out, n, cap);
    return n;
}

static const qd_expr *stand_in(qd_ctx *ctx, const qd_expr *call) {
    uint64_t h = 0;
    for (const char *s = qd_expr_name(call); *s; s++)
        h = h * 131u + (unsigned char)*s;
    const qd_expr *arg = qd_rat(ctx, (long)(h % 7u) + 1, 5);
    for (size_t i = 0; i < qd_expr_nargs(call); i++)
        arg = qd_add(ctx, arg, qd_mul(ctx, qd_rat(ctx, (long)((h >> (3 * i + 3)) % 9u) + 3, 7),
                                      qd_expr_arg(call, i)));
    return qd_add(ctx, qd_rat(ctx, 11, 10), qd_mul(ctx, qd_rat(ctx, 1, 2), qd_fn(ctx, QD_SIN, arg)));
}

static qd_status make_generic(closure *c, const qd_con *con, size_t m) {
    const qd_expr *calls[16], *repl[16];
    c->w = qd__malloc(c->ctx, m * c->N * sizeof *c->w + 1);
    if (!c->w)
        return QD_ERR_NOMEM;
    for (size_t k = 0; k < m; k++)
        for (size_t j = 0; j < c->N; j++) {
            const qd_expr *e = coef(c, con, k, j);
            size_t nf = user_functions(e, calls, 0, 16);
            for (size_t i = 0; i < nf; i++)
                repl[i] = stand_in(c->ctx, calls[i]);
            c->w[k * c->N + j] = nf ? qd_subs(c->ctx, e, nf, calls, repl) : e;
            if (!c->w[k * c->N + j])
                return qd_ctx_status(c->ctx) != QD_OK ? qd_ctx_status(c->ctx) : QD_ERR_NOMEM;
        }
    return QD_OK;
}

/* Gaussian elimination with partial pivoting on the m x N matrix at point
 * 0: its rank, the independent rows and the pivot columns.  false when an
 * entry has no value there. */
static bool pivots(closure *c, size_t m, size_t *rows, size_t *cols,
                   size_t *rank) {
    double *A = qd__malloc(c->ctx, (m ? m : 1) * c->N * sizeof *A);
    size_t *row_of = qd__malloc(c->ctx, (m ? m : 1) * sizeof *row_of), r = 0;
    bool ok = A && row_of;
    for (size_t k = 0; ok && k < m; k++) {
        row_of[k] = k;
        for (size_t j = 0; ok && j < c->N; j++)
            ok = value_at(c, generic(c, k, j), 0, &A[k * c->N + j]);
    }
    double big = 0;
    for (size_t i = 0; ok && i < m * c->N; i++)
        big = fmax(big, fabs(A[i]));
    for (size_t j = 0; ok && j < c->N && r < m; j++) {
        size_t p = r;
        for (size_t k = r + 1; k < m; k++)
            if (fabs(A[k * c->N + j]) > fabs(A[p * c->N + j]))
                p = k;
        if (fabs(A[p * c->N + j]) <= 1e-10 * big)
            continue;
        for (size_t i = 0; i < c->N; i++) {
            double t = A[r * c->N + i];
            A[r * c->N + i] = A[p * c->N + i];
            A[p * c->N + i] = t;
        }
        size_t t = row_of[r];
        row_of[r] = row_of[p];
        row_of[p] = t;
        for (size_t k = r + 1; k < m; k++) {
            double f = A[k * c->N + j] / A[r * c->N + j];
            for (size_t i = j; i < c->N; i++)
                A[k * c->N + i] -= f * A[r * c->N + i];
        }
        rows[r] = row_of[r];
        cols[r++] = j;
    }
    *rank = r;
    qd__free(A);
    qd__free(row_of);
    return ok;
}

static bool is_pivot(const size_t *cols, size_t r, size_t j) {
    for (size_t i = 0; i < r; i++)
        if (cols[i] == j)
            return true;
    return false;
}

/* The same field divided by det B, for big forms: e_j - sum_i z_i e_{cols[i]}
 * with B z = (column j), by Gaussian elimination on the DAG (nothing
 * expanded), pivoting on the largest value at point 0. */
static qd_status kernel_field_dag(closure *c, const size_t *rows, const size_t *cols, size_t r,
                                  size_t j, const qd_expr **f) {
    qd_ctx *ctx = c->ctx;
    const qd_expr *A[MAXV * (MAXV + 1)];
    double V[MAXV * (MAXV + 1)];
    size_t w = r + 1;
    for (size_t a = 0; a < r; a++)
        for (size_t b = 0; b <= r; b++) {
            A[a * w + b] = generic(c, rows[a], b < r ? cols[b] : j);
            if (!value_at(c, A[a * w + b], 0, &V[a * w + b]))
                return QD_ERR_UNBOUND;
        }
    for (size_t k = 0; k < r; k++) {
        size_t p = k;
        for (size_t a = k + 1; a < r; a++)
            if (fabs(V[a * w + k]) > fabs(V[p * w + k]))
                p = a;
        for (size_t b = 0; p != k && b < w; b++) {
            const qd_expr *t = A[p * w + b];
            double tv = V[p * w + b];
            A[p * w + b] = A[k * w + b], V[p * w + b] = V[k * w + b];
            A[k * w + b] = t, V[k * w + b] = tv;
        }
        for (size_t a = k + 1; a < r; a++) {
            if (qd_is_zero(A[a * w + k]))
                continue;
            const qd_expr *l = qd_div(ctx, A[a * w + k], A[k * w + k]);
            double lv = V[a * w + k] / V[k * w + k];
            for (size_t b = k + 1; l && b < w; b++) {
                if (!qd_is_zero(A[k * w + b]))
                    A[a * w + b] = qd_sub(ctx, A[a * w + b], qd_mul(ctx, l, A[k * w + b]));
                V[a * w + b] -= lv * V[k * w + b];
            }
            if (!l)
                return qd_ctx_status(ctx) != QD_OK ? qd_ctx_status(ctx) : QD_ERR_NOMEM;
        }
    }
    for (size_t i = 0; i < c->N; i++)
        f[i] = qd_int(ctx, 0);
    f[j] = qd_int(ctx, 1);
    for (size_t k = r; k-- > 0;) {
        const qd_expr *s = A[k * w + r];
        for (size_t b = k + 1; s && b < r; b++)
            if (!qd_is_zero(A[k * w + b]))
                s = qd_add(ctx, s, qd_mul(ctx, A[k * w + b], f[cols[b]]));
        /* f[cols[b]] holds -z_b: s = col_j - sum_b B_kb z_b */
        if (!s || !(f[cols[k]] = qd_neg(ctx, qd_div(ctx, s, A[k * w + k]))))
            return qd_ctx_status(ctx) != QD_OK ? qd_ctx_status(ctx) : QD_ERR_NOMEM;
    }
    return QD_OK;
}

/* The kernel field of the free column j: det B e_j - sum_i det(B with
 * column i replaced by the column j) e_{cols[i]}, B the pivot block. */
static qd_status kernel_field(closure *c, const size_t *rows,
                              const size_t *cols, size_t r, size_t j, const qd_expr **f) {
    qd_ctx *ctx = c->ctx;
    const qd_expr *B[MAXV * MAXV];
    if (c->big)
        return kernel_field_dag(c, rows, cols, r, j, f);
    for (size_t i = 0; i < c->N; i++)
        f[i] = qd_int(ctx, 0);
    for (size_t a = 0; a < r; a++)
        for (size_t b = 0; b < r; b++)
            B[a * r + b] = generic(c, rows[a], cols[b]);
    f[j] = qd_simplify(ctx, qd__mech_det(ctx, r, B));
    for (size_t i = 0; i < r; i++) {
        const qd_expr *Bi[MAXV * MAXV];
        for (size_t a = 0; a < r; a++)
            for (size_t b = 0; b < r; b++)
                Bi[a * r + b] = b == i ? generic(c, rows[a], j) : B[a * r + b];
        f[cols[i]] = qd_simplify(ctx, qd_neg(ctx, qd__mech_det(ctx, r, Bi)));
    }
    for (size_t i = 0; i < c->N; i++)
        if (!f[i])
            return qd_ctx_status(ctx) != QD_OK ? qd_ctx_status(ctx) : QD_ERR_NOMEM;
    return QD_OK;
}

/* The Jacobian dF^i/dx_j of a field into J (N*N): each field's once, since
 * it enters many brackets and differentiating a large DAG is the cost. */
static qd_status jacobian(closure *c, const qd_expr *const *F, const qd_expr **J) {
    for (size_t i = 0; i < c->N; i++)
        for (size_t j = 0; j < c->N; j++)
            if (!(J[i * c->N + j] = qd_is_zero(F[i]) ? F[i] : qd_diff(c->ctx, F[i], c->x[j])))
                return qd_ctx_status(c->ctx) != QD_OK ? qd_ctx_status(c->ctx) : QD_ERR_NOMEM;
    return QD_OK;
}

/* [X, Y]^i = sum_j X^j dY^i/dx_j - Y^j dX^i/dx_j (JX, JY the Jacobians),
 * simplified unless big. */
static qd_status bracket(closure *c, const qd_expr *const *X, const qd_expr *const *JX,
                         const qd_expr *const *Y, const qd_expr *const *JY, const qd_expr **out) {
    qd_ctx *ctx = c->ctx;
    for (size_t i = 0; i < c->N; i++) {
        const qd_expr *s = qd_int(ctx, 0);
        for (size_t j = 0; j < c->N; j++) {
            if (!qd_is_zero(X[j]))
                s = qd_add(ctx, s, qd_mul(ctx, X[j], JY[i * c->N + j]));
            if (!qd_is_zero(Y[j]))
                s = qd_sub(ctx, s, qd_mul(ctx, Y[j], JX[i * c->N + j]));
        }
        if (!(out[i] = c->big ? s : qd_simplify(ctx, s)))
            return qd_ctx_status(ctx) != QD_OK ? qd_ctx_status(ctx) : QD_ERR_NOMEM;
    }
    return QD_OK;
}

/* ---- setup and the iteration ----------------------------------------------- */

/* The variables, the symbols of the forms and the random points. */
static qd_status setup(closure *c, size_t n, const qd_expr *const *q, const qd_con *con,
                       size_t m) {
    c->N = n + 1;
    qd_status st = make_generic(c, con, m);
    if (st != QD_OK)
        return st;
    for (size_t j = 0; j < n; j++)
        c->x[j] = c->syms[j] = q[j];
    c->x[n] = c->syms[n] = qd_time(c->ctx);
    c->ns = c->N;
    for (size_t k = 0; k < m; k++)
        for (size_t j = 0; j < c->N; j++) {
            const qd_expr *s[MAXV];
            size_t ns = qd_free_symbols(c->ctx, generic(c, k, j), s, MAXV);
            if (qd__ctx_nomem(c->ctx)) /* 0 symbols may mean out of memory */
                return QD_ERR_NOMEM;
            if (ns > MAXV)
                return QD_ERR_TOOBIG;
            for (size_t i = 0; i < ns; i++) {
                size_t h = 0;
                while (h < c->ns && c->syms[h] != s[i])
                    h++;
                if (h == c->ns && c->ns == MAXV)
                    return QD_ERR_TOOBIG;
                if (h == c->ns)
                    c->syms[c->ns++] = s[i];
            }
        }
    for (size_t k = 0; k < m * c->N && !c->big; k++)
        c->big = qd_dag_size(c->ctx, c->w[k]) > BIG_NODES;
    uint64_t seed = 0x5eed0c105u;
    for (int k = 0; k < NPTS; k++)
        for (size_t i = 0; i < c->ns; i++)
            c->pt[k][i] = random_value(&seed, k);
    return QD_OK;
}

/* D_0: the kernel of the independent forms. */
static qd_status kernel(closure *c, size_t m, size_t *rank) {
    size_t rows[MAXV], cols[MAXV], r;
    if (m > MAXV)
        return QD_ERR_TOOBIG;
    if (!pivots(c, m, rows, cols, &r)) /* no value, or no memory for the matrix */
        return qd__ctx_nomem(c->ctx) ? QD_ERR_NOMEM : QD_ERR_UNBOUND;
    *rank = c->nrows = r;
    memcpy(c->rows, rows, r * sizeof rows[0]);
    c->base = qd__malloc(c->ctx, (c->N - r) * c->N * sizeof *c->base + 1);
    if (!c->base)
        return QD_ERR_NOMEM;
    for (size_t j = 0; j < c->N; j++) {
        if (is_pivot(cols, r, j))
            continue;
        const qd_expr **f = c->base + c->nbase * c->N;
        qd_status st = kernel_field(c, rows, cols, r, j, f);
        if (st != QD_OK)
            return st;
        c->nbase++;
        offer(c, f);
    }
    return QD_OK;
}

/* D_{k+1} = D_k + [D_0, D_k] until nothing is added. */
static qd_status close_up(closure *c) {
    const qd_expr *f[MAXV];
    size_t from = 0, NN = c->N * c->N, njk = 0;
    /* Jacobians: the base fields', then the kept ones' as they are needed */
    const qd_expr **jb = qd__malloc(c->ctx, (c->nbase + MAXV) * NN * sizeof *jb + 1);
    const qd_expr **jk = jb + c->nbase * NN;
    qd_status st = jb ? QD_OK : QD_ERR_NOMEM;
    for (size_t b = 0; st == QD_OK && b < c->nbase; b++)
        st = jacobian(c, c->base + b * c->N, jb + b * NN);
    while (st == QD_OK && from < c->nkept && generic_rank(c) < c->N) {
        size_t upto = c->nkept;
        for (; st == QD_OK && njk < upto; njk++)
            st = jacobian(c, c->kept[njk], jk + njk * NN);
        for (size_t b = 0; st == QD_OK && b < c->nbase; b++)
            for (size_t k = from; st == QD_OK && k < upto && c->nkept < c->N; k++) {
                st = bracket(c, c->base + b * c->N, jb + b * NN, c->kept[k], jk + k * NN, f);
                if (st == QD_OK)
                    offer(c, f);
            }
        from = upto;
    }
    qd__free(jb);
    return st;
}

/* ---- the relations themselves ------------------------------------------------ *
 *
 * A relation's differential is a combination sum_i c_i w_i of the forms that
 * vanishes on the closure.  At each point the c of all relations span the
 * null space of (w_i . Y_b) over the independent forms i and the closure's
 * basis Y_b; its reduced echelon basis is unique, so when it is the same at
 * every point (to 1e-9) and rational, the combinations have constant
 * coefficients (roll1 - roll2 on the axle) and are integrated as one form.
 * Combinations with varying coefficients are counted but not written. */

/* Reduced row echelon form of the rows x cols matrix A, in place; the pivot
 * column of each row into piv; its rank. */
static size_t rref(double *A, size_t rows, size_t cols, size_t *piv) {
    size_t r = 0;
    double big = 0;
    for (size_t i = 0; i < rows * cols; i++)
        big = fmax(big, fabs(A[i]));
    for (size_t j = 0; j < cols && r < rows; j++) {
        size_t p = r;
        for (size_t i = r + 1; i < rows; i++)
            if (fabs(A[i * cols + j]) > fabs(A[p * cols + j]))
                p = i;
        if (fabs(A[p * cols + j]) <= 1e-9 * big)
            continue;
        for (size_t k = 0; k < cols; k++) {
            double t = A[r * cols + k];
            A[r * cols + k] = A[p * cols + k];
            A[p * cols + k] = t;
        }
        double d = A[r * cols + j];
        for (size_t k = 0; k < cols; k++)
            A[r * cols + k] = k == j ? 1 : A[r * cols + k] / d;
        for (size_t i = 0; i < rows; i++) {
            double f = A[i * cols + j];
            for (size_t k = 0; i != r && k < cols; k++)
                A[i * cols + k] -= f * A[r * cols + k];
        }
        piv[r++] = j;
    }
    return r;
}

/* The null space of the forms against the closure at point k, as
 * nrel vectors of nrows coefficients in reduced form; false when the
 * point is degenerate or the dimensions disagree. */
static bool null_space(closure *c, int k, size_t nrel, double *out) {
    size_t r = c->nrows, d = c->rank[k], piv[MAXV];
    double G[MAXV * MAXV], w[MAXV];
    if (d != generic_rank(c) || r - nrel > d)
        return false;
    for (size_t i = 0; i < r; i++) {
        for (size_t j = 0; j < c->N; j++)
            if (!value_at(c, generic(c, c->rows[i], j), k, &w[j]))
                return false;
        for (size_t b = 0; b < d; b++) {
            double dot = 0;
            for (size_t j = 0; j < c->N; j++)
                dot += c->basis[k][b][j] * w[j];
            G[b * r + i] = dot;
        }
    }
    if (r - rref(G, d, r, piv) != nrel)
        return false;
    for (size_t f = 0, v = 0; f < r; f++) {
        bool pivot = false;
        for (size_t i = 0; i < r - nrel; i++)
            pivot |= piv[i] == f;
        if (pivot)
            continue;
        for (size_t i = 0; i < r; i++)
            out[v * r + i] = i == f ? 1 : 0;
        for (size_t i = 0; i < r - nrel; i++)
            out[v * r + piv[i]] = -G[i * r + f];
        v++;
    }
    return true;
}

/* x as a fraction with a denominator up to 1000, or false. */
static bool rational(double x, long *num, long *den) {
    for (long d = 1; d <= 1000; d++) {
        double n = round(x * (double)d);
        if (fabs(n - x * (double)d) <= 1e-8 * (double)d * (1 + fabs(x)) && fabs(n) < 1e9) {
            *num = (long)n;
            *den = d;
            return true;
        }
    }
    return false;
}

/* The integral of the combination coef (nrows numbers) of the forms, or
 * NULL; only combinations of two or more constraints. */
static const qd_expr *integrate_combination(closure *c, const qd_con *con, const double *coef_) {
    qd_ctx *ctx = c->ctx;
    const qd_expr *a[MAXV], *a0 = qd_int(ctx, 0);
    size_t n = c->N - 1, used = 0;
    for (size_t j = 0; j < n; j++)
        a[j] = qd_int(ctx, 0);
    for (size_t i = 0; i < c->nrows; i++) {
        long num, den;
        if (!rational(coef_[i], &num, &den))
            return NULL;
        if (num == 0)
            continue;
        used++;
        const qd_expr *k = qd_rat(ctx, num, den);
        for (size_t j = 0; j < n; j++)
            a[j] = qd_add(ctx, a[j], qd_mul(ctx, k, coef(c, con, c->rows[i], j)));
        a0 = qd_add(ctx, a0, qd_mul(ctx, k, coef(c, con, c->rows[i], n)));
    }
    if (used < 2)
        return NULL;
    for (size_t j = 0; j < n; j++)
        a[j] = qd_simplify(ctx, a[j]);
    qd_con sum = {.name = "combination", .a = a, .a0 = qd_simplify(ctx, a0)};
    const qd_expr *phi = qd__mech_con_integral(ctx, n, c->x, &sum);
    if (!phi && qd_ctx_status(ctx) != QD_ERR_NOMEM)
        qd__ctx_recover(ctx);
    return phi;
}

/* The integrals of the constant combinations of two or more constraints,
 * into out (at most cap); their number. */
static size_t combinations(closure *c, const qd_con *con, size_t nrel, const qd_expr **out,
                           size_t cap) {
    double v[NPTS][MAXV * MAXV];
    size_t r = c->nrows, found = 0;
    if (nrel == 0 || nrel > r)
        return 0;
    int good = -1;
    for (int k = 0; k < NPTS; k++) {
        if (!null_space(c, k, nrel, v[k]))
            continue;
        if (good < 0)
            good = k;
        for (size_t i = 0; i < nrel * r; i++)
            if (fabs(v[k][i] - v[good][i]) > 1e-9 * (1 + fabs(v[good][i])))
                return 0; /* coefficients that vary */
    }
    for (size_t b = 0; good >= 0 && b < nrel && found < cap; b++) {
        const qd_expr *phi = integrate_combination(c, con, v[good] + b * r);
        if (phi)
            out[found++] = phi;
    }
    return found;
}

qd_status qd__mech_con_closure(qd_ctx *ctx, size_t n, const qd_expr *const *q, const qd_con *con,
                          size_t m, size_t *rank, size_t *relations) {
    return qd__mech_con_relations(ctx, n, q, con, m, rank, relations, NULL, 0, NULL);
}

qd_status qd__mech_con_relations(qd_ctx *ctx, size_t n, const qd_expr *const *q, const qd_con *con,
                            size_t m, size_t *rank, size_t *relations, const qd_expr **integrals,
                            size_t cap, size_t *nintegrals) {
    *rank = *relations = 0;
    if (nintegrals)
        *nintegrals = 0;
    if (qd_ctx_status(ctx) != QD_OK)
        return qd_ctx_status(ctx);
    if (m == 0)
        return QD_OK;
    closure *c = qd__calloc(ctx, 1, sizeof *c);
    if (!c)
        return QD_ERR_NOMEM;
    c->ctx = ctx;
    qd_status st = n + 1 > MAXV ? QD_ERR_TOOBIG : setup(c, n, q, con, m);
    if (st == QD_OK)
        st = kernel(c, m, rank);
    if (st == QD_OK)
        st = close_up(c);
    if (st == QD_OK && c->undecided) {
        qd_ctx_error(ctx, QD_ERR_NUMERIC, "integrability of the constraints together: could not "
                     "decide (a bracket of the large forms is neither clearly in nor clearly out "
                     "of the span at the sample points)");
        st = QD_ERR_NUMERIC;
    }
    if (st == QD_OK)
        *relations = c->N - generic_rank(c);
    if (st == QD_OK && nintegrals)
        *nintegrals = combinations(c, con, *relations, integrals, cap);
    if (st == QD_OK && qd_ctx_status(ctx) != QD_OK)
        st = qd_ctx_status(ctx);
    qd__free(c->base);
    qd__free(c->w);
    qd__free(c);
    if (st == QD_ERR_TOOBIG && qd_ctx_status(ctx) == QD_OK)
        qd_ctx_error(ctx, st, "integrability of the constraints together: at most %d "
                     "coordinates and symbols", MAXV - 1);
    else if (st == QD_ERR_UNBOUND && qd_ctx_status(ctx) == QD_OK)
        qd_ctx_error(ctx, st, "integrability of the constraints together: a coefficient "
                     "cannot be evaluated (a function without a definition?)");
    else if (st == QD_ERR_NOMEM && qd_ctx_status(ctx) == QD_OK)
        qd_ctx_error(ctx, st, "out of memory testing the constraints for integrability");
    return st;
}

qd_status qd_eom_dof(qd_ctx *ctx, const qd_eom *e, qd_dof *d) {
    QD_ARGS_CTX(ctx, ctx && e && d);
    size_t rank, rel, nint;
    const qd_expr *found[QD_DOF_MAXCOMB];
    *d = (qd_dof){e->n, 0, 0, e->n, e->n, 0, {NULL}};
    qd_status st = qd__mech_con_relations(ctx, e->n, e->q, e->con, e->ncon, &rank, &rel, found,
                                     QD_DOF_MAXCOMB, &nint);
    if (st != QD_OK)
        return st;
    if (rel > e->n || rank > e->n) { /* they would fix t: refused when derived */
        qd_ctx_error(ctx, QD_ERR_ARG, "the constraints leave no motion");
        return QD_ERR_ARG;
    }
    *d = (qd_dof){e->n, rank, rel, e->n - rel, e->n - rank, nint, {NULL}};
    for (size_t i = 0; i < nint; i++)
        d->combined[i] = found[i];
    return QD_OK;
}

/*
 * src/mech/canonical.c - canonical transformations from a generating
 * function of any of the four types (Goldstein ch. 9.1, table 9.1).
 *
 * Every type is one pattern: F(x, y, t) with x an old variable (q or p), y
 * a new one (Q or P), cx = sx dF/dx the old conjugate of x and cy = sy dF/dy
 * the new conjugate of y.  Solving the first relation for y gives y(q, p, t)
 * and then cy(q, p, t); solving the second for x gives the inverse map that
 * K(Q, P, t) needs.  A relation linear in the unknowns is solved by
 * Cramer's rule; otherwise the unknowns are isolated (isolate.c), which
 * takes the harmonic oscillator's F1 = m w q^2 cot(Q)/2 (Goldstein ch. 9.3):
 * p = m w q cot(Q) gives Q = atan(m w q/p).
 */
#include <stdlib.h>
#include "qdot/canonical.h"
#include "mech/mech.h"
#include "../base/mem.h"
#include "../base/args.h"

typedef struct gen_shape {
    bool x_is_q, y_is_Q;
    int sx, sy;
} gen_shape;

static const gen_shape shapes[] = {
    [QD_GEN_F1] = {true, true, 1, -1},
    [QD_GEN_F2] = {true, false, 1, 1},
    [QD_GEN_F3] = {false, true, -1, -1},
    [QD_GEN_F4] = {false, false, -1, 1},
};

/* Solve the n equations eq_j = 0, linear in xs, by Cramer's rule into sol
 * (n).  QD_ERR_NONLINEAR or QD_ERR_SINGULAR, with the reason in ctx. */
static qd_status solve_linear(qd_ctx *ctx, size_t n, const qd_expr *const *eq,
                              const qd_expr *const *xs, const qd_expr **sol) {
    const qd_expr **A = qd__malloc(ctx, 2 * n * n * sizeof *A + n * sizeof *A);
    if (!A) {
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory");
        return QD_ERR_NOMEM;
    }
    const qd_expr **Ak = A + n * n, **r = Ak + n * n;
    qd_status st = QD_OK;
    for (size_t j = 0; j < n && st == QD_OK; j++)
        st = qd_linear_coeffs(ctx, qd_expand(ctx, eq[j]), n, xs, A + j * n, r + j);
    const qd_expr *det = st == QD_OK ? qd_simplify(ctx, qd__mech_det(ctx, n, A)) : NULL;
    if (st == QD_OK && !det)
        st = qd_ctx_status(ctx);
    if (st == QD_OK && qd_is_zero(det)) {
        qd_ctx_error(ctx, QD_ERR_SINGULAR, "the generating function's mixed Hessian is singular");
        st = QD_ERR_SINGULAR;
    }
    for (size_t k = 0; k < n && st == QD_OK; k++) {
        for (size_t i = 0; i < n * n; i++)
            Ak[i] = i % n == k ? qd_neg(ctx, r[i / n]) : A[i];
        sol[k] = qd_simplify(ctx, qd_div(ctx, qd__mech_det(ctx, n, Ak), det));
        if (!sol[k])
            st = qd_ctx_status(ctx);
    }
    qd__free(A);
    return st;
}

/* The n relations eq = 0 solved for xs: by Cramer's rule when linear, else
 * by isolation (QD_ERR_NONLINEAR with ctx clean and *failed the relation
 * when that fails too). */
static qd_status solve_for(qd_ctx *ctx, size_t n, const qd_expr *const *eq,
                           const qd_expr *const *xs, const qd_expr **sol, size_t *failed) {
    *failed = 0;
    qd_status st = solve_linear(ctx, n, eq, xs, sol);
    if (st != QD_ERR_NONLINEAR)
        return st;
    qd__ctx_recover(ctx);
    return qd__mech_isolate(ctx, n, eq, xs, sol, failed);
}

/* The forward relation cx_k = sx dF/dx_k could not be solved for y. */
static void unsolved(qd_ctx *ctx, const gen_shape *s, const qd_expr *const *x,
                     const qd_expr *const *cx, const qd_expr *const *y, size_t n, size_t k) {
    const char *ys = n == 1 ? qd_expr_name(y[0]) : s->y_is_Q ? "Q1..Qn" : "P1..Pn";
    qd_ctx_error(ctx, QD_ERR_NONLINEAR,
                 "cannot solve %s = %sdF/d%s for %s in closed form: qdot isolates a new "
                 "variable that occurs once (through sums, products, powers, sin, cos, tan, "
                 "exp, log and their inverses), sin and cos of it as a ratio, or one "
                 "subexpression of it repeated",
                 qd_expr_name(cx[k]), s->sx < 0 ? "-" : "", qd_expr_name(x[k]), ys);
}

/* rel_j = c_j - s dF/dv_j for the n variables v: zero along the map. */
static void relations(qd_ctx *ctx, size_t n, const qd_expr *F, const qd_expr *const *v,
                      const qd_expr *const *c, int s, const qd_expr **rel) {
    for (size_t j = 0; j < n; j++)
        rel[j] = qd_sub(ctx, c[j], qd_mul(ctx, qd_int(ctx, s), qd_diff(ctx, F, v[j])));
}

/* Substitute from[0..n) -> to[0..n) in each of e[0..n) and simplify. */
static void subs_all(qd_ctx *ctx, size_t n, const qd_expr **e, size_t m,
                     const qd_expr *const *from, const qd_expr *const *to) {
    for (size_t j = 0; j < n; j++)
        e[j] = qd_simplify(ctx, qd_subs(ctx, e[j], m, from, to));
}

/* K(Q, P, t): solve cy = sy dF/dy for x and substitute.  NULL, with the
 * context left clean, when x does not enter linearly (a square root would
 * need a branch the caller has to choose). */
static const qd_expr *new_hamiltonian(qd_ctx *ctx, size_t n, const gen_shape *s,
                                      const qd_expr *F, const qd_expr *const *x,
                                      const qd_expr *const *cx, const qd_expr *const *y,
                                      const qd_expr *const *cy, const qd_expr *K,
                                      const qd_expr **w) {
    const qd_expr **rel = w, **xs = w + n, **from = w + 2 * n, **to = w + 4 * n;
    size_t failed;
    relations(ctx, n, F, y, cy, s->sy, rel);
    qd_status st = solve_for(ctx, n, rel, x, xs, &failed);
    if (st == QD_ERR_NONLINEAR || st == QD_ERR_SINGULAR) {
        qd__ctx_recover(ctx);
        return NULL;
    }
    if (st != QD_OK)
        return NULL;
    for (size_t j = 0; j < n; j++) {
        from[j] = x[j];
        to[j] = xs[j];
        from[n + j] = cx[j];
        to[n + j] = qd_mul(ctx, qd_int(ctx, s->sx), qd_diff(ctx, F, x[j]));
    }
    subs_all(ctx, n, to + n, n, x, xs);
    return qd__mech_untrig(ctx, qd_simplify(ctx, qd_subs(ctx, K, 2 * n, from, to)));
}

qd_status qd_generate(qd_ctx *ctx, qd_gen_type type, size_t n, const qd_expr *const *old_q,
                      const qd_expr *const *old_p, const qd_expr *const *new_Q,
                      const qd_expr *const *new_P, const qd_expr *F, const qd_expr *t,
                      const qd_expr *H, qd_gen_result *out) {
    QD_ARGS_CTX(ctx, ctx && old_q && old_p && new_Q && new_P && F && t && out);
    if (!out || !F || !old_q || !old_p || !new_Q || !new_P || n == 0 || type < QD_GEN_F1 ||
        type > QD_GEN_F4) {
        qd_ctx_error(ctx, QD_ERR_ARG, "generating function: bad argument");
        return QD_ERR_ARG;
    }
    *out = (qd_gen_result){NULL, NULL, NULL, NULL};
    if (qd_ctx_status(ctx) != QD_OK)
        return qd_ctx_status(ctx);
    const gen_shape *s = &shapes[type];
    const qd_expr *const *x = s->x_is_q ? old_q : old_p, *const *cx = s->x_is_q ? old_p : old_q;
    const qd_expr *const *y = s->y_is_Q ? new_Q : new_P, *const *cy = s->y_is_Q ? new_P : new_Q;
    const qd_expr **res = qd__malloc(ctx, 2 * n * sizeof *res), **w = qd__malloc(ctx, 6 * n * sizeof *w);
    if (!res || !w) {
        qd__free(res);
        qd__free(w);
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory");
        return QD_ERR_NOMEM;
    }
    const qd_expr **ys = s->y_is_Q ? res : res + n, **cys = s->y_is_Q ? res + n : res;
    size_t failed;
    relations(ctx, n, F, x, cx, s->sx, w);
    qd_status st = solve_for(ctx, n, w, y, ys, &failed);
    if (st == QD_ERR_NONLINEAR && qd_ctx_status(ctx) == QD_OK)
        unsolved(ctx, s, x, cx, y, n, failed);
    if (st == QD_OK) {
        for (size_t j = 0; j < n; j++)
            cys[j] = qd_mul(ctx, qd_int(ctx, s->sy), qd_diff(ctx, F, y[j]));
        subs_all(ctx, n, cys, n, y, ys);
        for (size_t j = 0; j < n; j++) /* sin(atan(..)) from an isolated y */
            cys[j] = qd__mech_untrig(ctx, cys[j]);
        const qd_expr *K = H && t ? qd_add(ctx, H, qd_diff(ctx, F, t)) : H;
        if (K) {
            out->K_old = qd__mech_untrig(ctx, qd_simplify(ctx, qd_subs(ctx, K, n, y, ys)));
            out->K_new = new_hamiltonian(ctx, n, s, F, x, cx, y, cy, K, w);
        }
        st = qd_ctx_status(ctx);
    }
    qd__free(w);
    if (st != QD_OK) {
        qd__free(res);
        return st;
    }
    out->Q = res;
    out->P = res + n;
    return QD_OK;
}

qd_status qd_generate_f2(qd_ctx *ctx, size_t n, const qd_expr *const *q,
                         const qd_expr *const *p, const qd_expr *const *Q,
                         const qd_expr *const *P, const qd_expr *F2, const qd_expr *t,
                         const qd_expr *H, qd_gen_result *out) {
    QD_ARGS_CTX(ctx, ctx && (n == 0 || q) && (n == 0 || p) && (n == 0 || Q) && (n == 0 || P) && F2 && t && out);
    return qd_generate(ctx, QD_GEN_F2, n, q, p, Q, P, F2, t, H, out);
}

void qd_gen_result_free(qd_gen_result *r) {
    if (!r)
        return;
    qd__free(r->Q); /* P lives in the same block */
    *r = (qd_gen_result){NULL, NULL, NULL, NULL};
}

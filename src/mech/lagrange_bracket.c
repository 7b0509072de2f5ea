/*
 * src/mech/lagrange_bracket.c - Lagrange brackets of a map (q, p) -> (Q, P),
 * their duality with the Poisson brackets, and the transformed Hamiltonian
 * of a canonical or scaled map (Desloge ch. 74 eq. 14, ch. 75, ch. 77,
 * ch. 80 Thm 1, ch. 84 Thms 2-3; qdot/canonical.h).
 *
 * With r = (q, p), R = (Q, P) and J = dR/dr, the Lagrange-bracket matrix is
 * L = J^T mu J (mu = [[0, I], [-I, 0]]) and the Poisson brackets of the old
 * variables in the new ones are PB = J^-1 mu J^-T, so L^T PB = I for every
 * invertible map (mu^T mu = I): checked entry by entry, not assumed.
 *
 * K = c H + sum_i P_i dQ_i/dt + dF/dt (partial t-derivatives at fixed q,
 * p) from sum P dQ - K dt = c (sum p dq - H dt) - dF, F found by
 * integrating the exact form dF = sum_j (c p_j - sum_i P_i dQ_i/dq_j) dq_j
 * - sum_j (sum_i P_i dQ_i/dp_j) dp_j at fixed t one variable at a time.
 */
#include <stdlib.h>
#include "qdot/canonical.h"
#include "mech/mech.h"
#include "../base/mem.h"
#include "../base/args.h"

const qd_expr *qd_lagrange_bracket(qd_ctx *ctx, size_t n, const qd_expr *const *Q,
                                   const qd_expr *const *P, const qd_expr *u,
                                   const qd_expr *v) {
    QD_ARGS(NULL, ctx && (n == 0 || Q) && (n == 0 || P) && u && v);
    const qd_expr *sum = qd_int(ctx, 0);
    for (size_t i = 0; i < n; i++) {
        const qd_expr *a = qd_mul(ctx, qd_diff(ctx, Q[i], u), qd_diff(ctx, P[i], v));
        const qd_expr *b = qd_mul(ctx, qd_diff(ctx, Q[i], v), qd_diff(ctx, P[i], u));
        sum = qd_add(ctx, sum, qd_sub(ctx, a, b));
    }
    return qd_simplify(ctx, sum);
}

void qd_lagrange_result_free(qd_lagrange_result *r) {
    if (!r)
        return;
    qd__free(r->L); /* PB lives in the same block */
    *r = (qd_lagrange_result){0};
}

static const qd_expr *tidy(qd_ctx *ctx, const qd_expr *e) {
    return qd__mech_untrig(ctx, qd_simplify(ctx, qd_cancel(ctx, e)));
}

qd_status qd_lagrange_brackets(qd_ctx *ctx, size_t n, const qd_expr *const *q,
                               const qd_expr *const *p, const qd_expr *const *Q,
                               const qd_expr *const *P, qd_lagrange_result *out) {
    QD_ARGS_CTX(ctx, ctx && (n == 0 || (q && p && Q && P)) && out);
    *out = (qd_lagrange_result){0};
    if (n == 0) {
        qd_ctx_error(ctx, QD_ERR_ARG, "Lagrange brackets: no variables");
        return QD_ERR_ARG;
    }
    size_t m = 2 * n;
    const qd_expr **blk = qd__calloc(ctx, 5 * m * m + 2 * m + 1, sizeof *blk);
    if (!blk) {
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory forming Lagrange brackets");
        return QD_ERR_NOMEM;
    }
    const qd_expr **L = blk, **PB = L + m * m, **J = PB + m * m, **Ki = J + m * m,
                  **I = Ki + m * m, **r = I + m * m, **R = r + m;
    for (size_t k = 0; k < n; k++) {
        r[k] = q[k], r[n + k] = p[k];
        R[k] = Q[k], R[n + k] = P[k];
    }
    for (size_t a = 0; a < m; a++)
        for (size_t b = 0; b < m; b++) {
            J[a * m + b] = qd_diff(ctx, R[a], r[b]);
            I[a * m + b] = qd_int(ctx, a == b);
            L[a * m + b] = a == b ? qd_int(ctx, 0) : a < b ? qd_lagrange_bracket(ctx, n, Q, P, r[a], r[b])
                                                           : NULL;
        }
    for (size_t a = 0; a < m; a++)
        for (size_t b = 0; b < a; b++)
            L[a * m + b] = L[b * m + a] ? qd_simplify(ctx, qd_neg(ctx, L[b * m + a])) : NULL;
    qd_status st = qd_ctx_status(ctx);
    if (st == QD_OK) {
        st = qd__mech_solve_cols(ctx, m, J, m, I, Ki, 0); /* Ki = J^-1 = dr/dR */
        if (st == QD_ERR_SINGULAR) {
            out->singular = true;
            st = QD_OK;
        }
    }
    if (st == QD_OK && !out->singular) {
        /* PB_ab = sum_k dr_a/dQ_k dr_b/dP_k - dr_a/dP_k dr_b/dQ_k */
        for (size_t a = 0; a < m; a++)
            for (size_t b = 0; b < m; b++) {
                const qd_expr *s = qd_int(ctx, 0);
                for (size_t k = 0; k < n; k++)
                    s = qd_add(ctx, s, qd_sub(ctx, qd_mul(ctx, Ki[a * m + k], Ki[b * m + n + k]),
                                              qd_mul(ctx, Ki[a * m + n + k], Ki[b * m + k])));
                PB[a * m + b] = tidy(ctx, s);
            }
        out->dual = true; /* L^T PB = I */
        for (size_t a = 0; a < m && out->dual; a++)
            for (size_t b = 0; b < m && out->dual; b++) {
                const qd_expr *s = qd_int(ctx, -(long)(a == b));
                for (size_t k = 0; k < m; k++)
                    s = qd_add(ctx, s, qd_mul(ctx, L[k * m + a], PB[k * m + b]));
                s = tidy(ctx, s);
                out->dual = s && qd_is_zero(s);
            }
        st = qd_ctx_status(ctx);
    }
    if (st != QD_OK) {
        qd__free(blk);
        return st;
    }
    out->n = n;
    out->L = L;
    out->PB = out->singular ? NULL : PB;
    return QD_OK;
}

/* ---- F and K ---------------------------------------------------------------- */

/* An antiderivative of e in x: qd_integrate, else term by term with
 * integration by parts on x^k g(x) (k a positive integer, g integrable:
 * p e^p of Desloge ch. 74 P5).  NULL, ctx clean, when neither works. */
static const qd_expr *antiderivative(qd_ctx *ctx, const qd_expr *e, const qd_expr *x, int depth) {
    if (!qd_has(e, x))
        return qd_mul(ctx, e, x);
    const qd_expr *r = qd_integrate(ctx, e, x);
    if (r)
        return r;
    qd__ctx_recover(ctx);
    if (depth > 8)
        return NULL;
    if (qd_expr_kind(e) == QD_ADD) {
        const qd_expr *s = qd_int(ctx, 0);
        for (size_t i = 0; s && i < qd_expr_nargs(e); i++) {
            const qd_expr *t = antiderivative(ctx, qd_expr_arg(e, i), x, depth + 1);
            s = t ? qd_add(ctx, s, t) : NULL;
        }
        return s;
    }
    if (qd_expr_kind(e) != QD_MUL)
        return NULL;
    for (size_t i = 0; i < qd_expr_nargs(e); i++) {
        const qd_expr *f = qd_expr_arg(e, i);
        long k = 0;
        if (f == x)
            k = 1;
        else if (qd_expr_kind(f) == QD_POW && qd_expr_arg(f, 0) == x && qd_is_number(qd_expr_arg(f, 1))) {
            double v;
            if (qd_eval(ctx, qd_expr_arg(f, 1), 0, NULL, NULL, &v) == QD_OK && v >= 1 && v <= 8 &&
                v == (double)(long)v)
                k = (long)v;
        }
        if (!k)
            continue;
        const qd_expr *g = qd_simplify(ctx, qd_div(ctx, e, f));
        const qd_expr *G = g ? qd_integrate(ctx, g, x) : NULL;
        if (!G) {
            qd__ctx_recover(ctx);
            continue;
        }
        /* int x^k g = x^k G - k int x^(k-1) G */
        const qd_expr *rest = qd_expand(ctx, qd_mul(ctx, qd_mul(ctx, qd_int(ctx, k), qd_powi(ctx, x, k - 1)), G));
        const qd_expr *R = rest ? antiderivative(ctx, rest, x, depth + 1) : NULL;
        if (R)
            return qd_sub(ctx, qd_mul(ctx, f, G), R);
    }
    return NULL;
}

/* F with dF = sum_k w_k dr_k (the form exact); NULL, ctx clean, when an
 * antiderivative is not found or the remainder depends on the variables
 * already integrated (which an exact form never does). */
static const qd_expr *integrate_form(qd_ctx *ctx, size_t m, const qd_expr *const *r,
                                     const qd_expr *const *w) {
    const qd_expr *F = qd_int(ctx, 0);
    for (size_t k = 0; F && k < m; k++) {
        const qd_expr *rest = tidy(ctx, qd_sub(ctx, w[k], qd_diff(ctx, F, r[k])));
        if (!rest)
            return NULL;
        for (size_t j = 0; j < k; j++)
            if (qd_has(rest, r[j]))
                return NULL;
        if (qd_is_zero(rest))
            continue;
        const qd_expr *G = antiderivative(ctx, qd_expand(ctx, rest), r[k], 0);
        F = G ? qd_add(ctx, F, G) : NULL;
    }
    if (!F)
        return NULL;
    F = tidy(ctx, F);
    for (size_t k = 0; F && k < m; k++) { /* dF = w, checked */
        const qd_expr *d = tidy(ctx, qd_sub(ctx, qd_diff(ctx, F, r[k]), w[k]));
        if (!d || !qd_is_zero(d))
            return NULL;
    }
    return F;
}

/* The m relations eq = 0 solved for the old variables r: by elimination
 * when linear in them, else by isolation (mech.h). */
static qd_status solve_old(qd_ctx *ctx, size_t m, const qd_expr *const *eq,
                           const qd_expr *const *r, const qd_expr **sol) {
    const qd_expr **A = qd__calloc(ctx, m * m + 2 * m + 1, sizeof *A);
    if (!A)
        return QD_ERR_NOMEM;
    const qd_expr **b = A + m * m;
    qd_status st = QD_OK;
    for (size_t j = 0; j < m && st == QD_OK; j++) {
        const qd_expr *rest;
        st = qd_linear_coeffs(ctx, qd_expand(ctx, eq[j]), m, r, A + j * m, &rest);
        b[j] = st == QD_OK ? qd_neg(ctx, rest) : NULL;
    }
    if (st == QD_OK)
        st = qd__mech_solve_cols(ctx, m, A, 1, b, sol, 0);
    qd__free(A);
    if (st == QD_OK)
        return QD_OK;
    qd__ctx_recover(ctx);
    size_t failed;
    return qd__mech_isolate(ctx, m, eq, r, sol, &failed);
}

void qd_newham_free(qd_newham *k) {
    if (k)
        *k = (qd_newham){0};
}

qd_status qd_transformed_hamiltonian(qd_ctx *ctx, size_t n, const qd_expr *const *q,
                                     const qd_expr *const *p, const qd_expr *const *Q,
                                     const qd_expr *const *P, const qd_expr *const *newQ,
                                     const qd_expr *const *newP, const qd_expr *t,
                                     const qd_expr *H, qd_newham *out) {
    QD_ARGS_CTX(ctx, ctx && (n == 0 || (q && p && Q && P && newQ && newP)) && H && out);
    *out = (qd_newham){0};
    if (n == 0) {
        qd_ctx_error(ctx, QD_ERR_ARG, "transformed Hamiltonian: no variables");
        return QD_ERR_ARG;
    }
    qd_canon_verdict v;
    qd_status st = qd_canonical_check(ctx, n, q, p, Q, P, t, &v);
    if (st != QD_OK)
        return st;
    if (v.kind == QD_CANON_UNDECIDED) {
        qd_ctx_error(ctx, QD_ERR_ARG, "could not decide whether the map is canonical (a "
                     "fundamental bracket was neither proved nor refuted)");
        return QD_ERR_ARG;
    }
    if (v.kind == QD_CANON_NO) {
        qd_ctx_error(ctx, QD_ERR_ARG, "the map is neither canonical nor scaled (a fundamental "
                     "bracket fails): no Hamiltonian K keeps Hamilton's form for every H");
        return QD_ERR_ARG;
    }
    size_t m = 2 * n;
    const qd_expr **w = qd__calloc(ctx, 4 * m + 1, sizeof *w);
    if (!w) {
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory forming K");
        return QD_ERR_NOMEM;
    }
    const qd_expr **r = w + m, **eq = r + m, **sol = eq + m, *c = v.scale;
    for (size_t j = 0; j < m; j++) {
        r[j] = j < n ? q[j] : p[j - n];
        const qd_expr *s = j < n ? qd_mul(ctx, c, p[j]) : qd_int(ctx, 0);
        for (size_t i = 0; i < n; i++)
            s = qd_sub(ctx, s, qd_mul(ctx, P[i], qd_diff(ctx, Q[i], r[j])));
        w[j] = tidy(ctx, s);
    }
    out->valence = c;
    out->F = integrate_form(ctx, m, r, w);
    if (!out->F) {
        qd__ctx_recover(ctx);
        qd__free(w);
        return qd_ctx_status(ctx); /* QD_OK: K not found, F NULL */
    }
    const qd_expr *K = qd_mul(ctx, c, H);
    if (t) {
        for (size_t i = 0; i < n; i++)
            K = qd_add(ctx, K, qd_mul(ctx, P[i], qd_diff(ctx, Q[i], t)));
        K = qd_add(ctx, K, qd_diff(ctx, out->F, t));
    }
    out->K_old = tidy(ctx, K);
    /* K in the new variables: (q, p) solved from Q = newQ, P = newP */
    for (size_t i = 0; i < n; i++) {
        eq[i] = qd_sub(ctx, Q[i], newQ[i]);
        eq[n + i] = qd_sub(ctx, P[i], newP[i]);
    }
    st = solve_old(ctx, m, eq, r, sol);
    if (st == QD_OK)
        out->K_new = qd__mech_untrig(ctx, tidy(ctx, qd_subs(ctx, out->K_old, m, r, sol)));
    else
        qd__ctx_recover(ctx);
    qd__free(w);
    return qd__ctx_nomem(ctx) ? QD_ERR_NOMEM : QD_OK;
}

/*
 * src/mech/bracket.c - Poisson brackets and the canonicity test by the
 * fundamental brackets (Goldstein ch. 9.5; Desloge ch. 80 Thm 2).
 */
#include <stdlib.h>
#include "qdot/canonical.h"
#include "../base/args.h"

const qd_expr *qd_bracket(qd_ctx *ctx, size_t n, const qd_expr *const *q,
                          const qd_expr *const *p, const qd_expr *F, const qd_expr *G) {
    QD_ARGS(NULL, ctx && (n == 0 || q) && (n == 0 || p) && F && G);
    if (!F || !G)
        return NULL;
    const qd_expr *sum = qd_int(ctx, 0);
    for (size_t j = 0; j < n; j++) {
        const qd_expr *a = qd_mul(ctx, qd_diff(ctx, F, q[j]), qd_diff(ctx, G, p[j]));
        const qd_expr *b = qd_mul(ctx, qd_diff(ctx, F, p[j]), qd_diff(ctx, G, q[j]));
        sum = qd_add(ctx, sum, qd_sub(ctx, a, b));
    }
    return qd_simplify(ctx, sum);
}

static void set_fail(qd_canon_verdict *v, qd_canon_kind kind, qd_bracket_pair pair, size_t i,
                     size_t j, const qd_expr *value, const qd_expr *target,
                     const qd_zero_result *z) {
    v->kind = kind;
    v->scale = NULL;
    v->pair = pair;
    v->i = i;
    v->j = j;
    v->value = value;
    v->target = target;
    v->certainty = z->kind;
    v->check = *z;
}

/* Free of every old variable and of t: a scale that may be a parameter. */
static bool is_constant(size_t n, const qd_expr *const *q, const qd_expr *const *p,
                        const qd_expr *t, const qd_expr *c) {
    for (size_t k = 0; k < n; k++)
        if (qd_has(c, q[k]) || qd_has(c, p[k]))
            return false;
    return !t || !qd_has(c, t);
}

/* A bracket b that should equal target: true when it does (proved or
 * numerically, the weaker kept in v), false with the verdict set when it
 * certainly does not (NO) or cannot be decided (the first such is kept
 * while a later bracket may still give a NO). */
static bool agrees(qd_ctx *ctx, qd_canon_verdict *v, const qd_expr *b, const qd_expr *target,
                   qd_bracket_pair pair, size_t i, size_t j, qd_status *st,
                   qd_canon_verdict *undecided) {
    qd_zero_result z;
    *st = qd_equal_test(ctx, b, target, &z);
    if (*st != QD_OK)
        return false;
    if (z.kind == QD_ZERO_NONZERO) {
        set_fail(v, QD_CANON_NO, pair, i, j, b, target, &z);
        return false;
    }
    if (z.kind == QD_ZERO_UNKNOWN) {
        if (undecided->kind != QD_CANON_UNDECIDED)
            set_fail(undecided, QD_CANON_UNDECIDED, pair, i, j, b, target, &z);
        return true;
    }
    if (z.kind == QD_ZERO_NUMERIC && v->certainty == QD_ZERO_PROVEN) {
        v->certainty = QD_ZERO_NUMERIC;
        v->check = z;
    }
    return true;
}

/* [A_i, B_j] for all pairs (i < j when same, else all i != j) must vanish. */
static qd_status check_zero(qd_ctx *ctx, size_t n, const qd_expr *const *q,
                            const qd_expr *const *p, const qd_expr *const *A,
                            const qd_expr *const *B, bool same, qd_bracket_pair pair,
                            qd_canon_verdict *v, qd_canon_verdict *undecided) {
    qd_status st = QD_OK;
    for (size_t i = 0; i < n; i++)
        for (size_t j = same ? i + 1 : 0; j < n; j++) {
            if (!same && i == j)
                continue;
            const qd_expr *b = qd_bracket(ctx, n, q, p, A[i], B[j]);
            if (!b)
                return qd_ctx_status(ctx);
            if (!agrees(ctx, v, b, qd_int(ctx, 0), pair, i, j, &st, undecided))
                return st;
        }
    return QD_OK;
}

qd_status qd_canonical_check(qd_ctx *ctx, size_t n, const qd_expr *const *q,
                             const qd_expr *const *p, const qd_expr *const *Q,
                             const qd_expr *const *P, const qd_expr *t, qd_canon_verdict *v) {
    QD_ARGS_CTX(ctx, ctx && (n == 0 || q) && (n == 0 || p) && (n == 0 || Q) && (n == 0 || P) && v);
    if (!v || !q || !p || !Q || !P) {
        qd_ctx_error(ctx, QD_ERR_ARG, "canonical check: missing argument");
        return QD_ERR_ARG;
    }
    *v = (qd_canon_verdict){.kind = QD_CANON_YES, .pair = QD_PAIR_NONE,
                            .certainty = QD_ZERO_PROVEN};
    v->check.kind = QD_ZERO_PROVEN;
    qd_canon_verdict und = {.kind = QD_CANON_YES};
    qd_status st = check_zero(ctx, n, q, p, Q, Q, true, QD_PAIR_QQ, v, &und);
    if (st == QD_OK && v->kind == QD_CANON_YES)
        st = check_zero(ctx, n, q, p, P, P, true, QD_PAIR_PP, v, &und);
    if (st == QD_OK && v->kind == QD_CANON_YES)
        st = check_zero(ctx, n, q, p, Q, P, false, QD_PAIR_QP, v, &und);
    if (st != QD_OK || v->kind != QD_CANON_YES)
        return st;
    const qd_expr *c = NULL;
    for (size_t i = 0; i < n; i++) {
        const qd_expr *b = qd_bracket(ctx, n, q, p, Q[i], P[i]);
        if (!b)
            return qd_ctx_status(ctx);
        const qd_expr *target = c ? c : qd_int(ctx, 1);
        if (agrees(ctx, v, b, target, QD_PAIR_QP, i, i, &st, &und)) {
            c = target;
            continue;
        }
        if (st != QD_OK)
            return st;
        /* [Q_1, P_1] certainly not 1: a scale when it is a nonzero constant */
        if (!c && !qd_is_zero(b) && is_constant(n, q, p, t, b)) {
            v->kind = QD_CANON_YES;
            v->certainty = QD_ZERO_PROVEN;
            v->check = (qd_zero_result){.kind = QD_ZERO_PROVEN};
            v->pair = QD_PAIR_NONE;
            v->value = v->target = NULL;
            c = b;
            continue;
        }
        return QD_OK;
    }
    if (und.kind == QD_CANON_UNDECIDED) {
        *v = und;
        return QD_OK;
    }
    v->scale = c ? c : qd_int(ctx, 1);
    v->kind = qd_is_one(v->scale) ? QD_CANON_YES : QD_CANON_SCALED;
    return QD_OK;
}

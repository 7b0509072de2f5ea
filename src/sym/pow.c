/*
 * src/sym/pow.c - powers in canonical form.
 *
 * Rules (the real-valued ones every CAS applies on construction):
 *   b^0 = 1, b^1 = b, 1^e = 1, 0^e = 0 for numeric e > 0 (0^-1 is an error);
 *   numbers fold exactly where the result is rational (4^(1/2) = 2);
 *   (c*x*y)^n = c^n * x^n * y^n and (x^a)^n = x^(a*n) for integer n only:
 *   (x^2)^(1/2) is |x|, not x, so it stays as it is.
 */
#include "node.h"

static const qd_expr *pow_node(qd_ctx *ctx, const qd_expr *b, const qd_expr *e) {
    qd_expr proto = {0};
    proto.kind = QD_POW;
    const qd_expr *args[2] = {b, e};
    return qd__intern(ctx, &proto, 2, args);
}

static const qd_expr *distribute_pow(qd_ctx *ctx, const qd_expr *prod, const qd_expr *e) {
    const qd_expr *stack[16];
    size_t n = prod->nargs;
    const qd_expr **fs = n <= 16 ? stack : qd__alloc(ctx, n * sizeof *fs);
    if (!fs)
        return NULL;
    for (size_t i = 0; i < n; i++)
        fs[i] = qd_pow(ctx, prod->args[i], e);
    return qd_mul_n(ctx, n, fs);
}

const qd_expr *qd_pow(qd_ctx *ctx, const qd_expr *b, const qd_expr *e) {
    if (!b || !e)
        return NULL;
    if (qd_is_zero(e) && e->kind == QD_RATIONAL)
        return ctx->one;
    if (qd_is_one(e))
        return b;
    if (qd_is_one(b))
        return b;
    if (qd__is_num(b) && qd__is_num(e)) {
        bool folded;
        const qd_expr *r = qd__num_pow(ctx, b, e, &folded);
        if (folded)
            return r;
        if (!qd_is_zero(b))
            return pow_node(ctx, b, e);
        if (b->kind != QD_RATIONAL) { /* 0.0 to a negative power: inf */
            qd_ctx_error(ctx, QD_ERR_DIVZERO, "division by zero: 0 to a negative power");
            return NULL;
        }
        /* exact 0 to a power too large to fold (QD_MAX_FOLD_EXP): below */
    }
    if (qd_is_zero(b) && b->kind == QD_RATIONAL) {
        if (qd__is_num(e) && qd_number_sign(e) > 0)
            return b;
        if (qd__is_num(e)) {
            qd_ctx_error(ctx, QD_ERR_DIVZERO, "division by zero: 0 to a negative power");
            return NULL;
        }
    }
    if (qd_is_integer(e)) {
        if (b->kind == QD_MUL)
            return distribute_pow(ctx, b, e);
        if (b->kind == QD_POW)
            return qd_pow(ctx, b->args[0], qd_mul(ctx, b->args[1], e));
    }
    return pow_node(ctx, b, e);
}

const qd_expr *qd_powi(qd_ctx *ctx, const qd_expr *b, long n) {
    return qd_pow(ctx, b, qd_int(ctx, n));
}

const qd_expr *qd_sqrt(qd_ctx *ctx, const qd_expr *a) { return qd_pow(ctx, a, ctx->half); }

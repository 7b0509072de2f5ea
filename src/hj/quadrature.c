/*
 * src/hj/quadrature.c - W_k = int p_k dq_k = int sqrt(p2) dq in closed form
 * where it has an elementary one the kernel can write.
 *
 * The kernel's integrator (src/sym/integrate.c) takes sqrt(a + b q), the
 * projectile's and Desloge's H = p^2 - q (ch. 78).  The oscillators need
 * sqrt(a + b q + c q^2), which it does not take; the table rule is here
 * (Gradshteyn-Ryzhik 2.262.1, 2.261):
 *
 *     int sqrt(X) dq = (2 c q + b) sqrt(X) / (4 c) + (4 a c - b^2)/(8 c) int dq/sqrt(X)
 *     int dq/sqrt(X) = asin((2 |c| q - b)/sqrt(b^2 - 4 a c)) / sqrt(|c|)   (c < 0)
 *                    = log(2 sqrt(c X) + 2 c q + b) / sqrt(c)               (c > 0)
 *
 * so the sign of c must be known: a number times positive parameters.
 * Anything else stays integral(sqrt(p2), q), exact and unevaluated.
 */
#include "hj_priv.h"

#include "base/mem.h"

const qd_expr *qd__hj_integral(qd_ctx *ctx, const qd_expr *f, const qd_expr *x) {
    const qd_expr *args[2] = {f, x};
    return qd_ufunc(ctx, "integral", 2, args);
}

static int factor_sign(const qd_expr *f) {
    if (qd_is_number(f))
        return qd_number_sign(f);
    if (qd_expr_kind(f) == QD_SYMBOL)
        return qd_symbol_is_positive(f) ? 1 : 0;
    if (qd_expr_kind(f) == QD_CONSTANT)
        return 1;
    if (qd_expr_kind(f) == QD_POW) {
        const qd_expr *n = qd_expr_arg(f, 1);
        long num, den;
        if (qd_rational_get(n, &num, &den) && den == 1 && num % 2 == 0)
            return 1;
        return factor_sign(qd_expr_arg(f, 0)) > 0 ? 1 : 0;
    }
    return 0;
}

int qd__hj_sign(const qd_expr *c) {
    if (qd_expr_kind(c) != QD_MUL)
        return factor_sign(c);
    int sign = 1;
    for (size_t i = 0; i < qd_expr_nargs(c) && sign; i++)
        sign *= factor_sign(qd_expr_arg(c, i));
    return sign;
}

/* int dq / sqrt(a + b q + c q^2), c of known sign s. */
static const qd_expr *inverse_root(qd_ctx *ctx, const qd_expr *X, const qd_expr *a,
                                   const qd_expr *b, const qd_expr *c, int s, const qd_expr *q) {
    const qd_expr *two = qd_int(ctx, 2);
    if (s > 0) {
        const qd_expr *arg = qd_add(ctx, qd_mul(ctx, two, qd_sqrt(ctx, qd_mul(ctx, c, X))),
                                    qd_add(ctx, qd_mul(ctx, qd_mul(ctx, two, c), q), b));
        return qd_div(ctx, qd_fn(ctx, QD_LOG, arg), qd_sqrt(ctx, c));
    }
    const qd_expr *g = qd_neg(ctx, c);
    const qd_expr *D = qd_simplify(ctx, qd_add(ctx, qd_powi(ctx, b, 2),
                                               qd_mul(ctx, qd_int(ctx, 4), qd_mul(ctx, a, g))));
    const qd_expr *u = qd_div(ctx, qd_sub(ctx, qd_mul(ctx, qd_mul(ctx, two, g), q), b), qd_sqrt(ctx, D));
    return qd_div(ctx, qd_fn(ctx, QD_ASIN, u), qd_sqrt(ctx, g));
}

/* int sqrt(X) dq for X = a + b q + c q^2 (c != 0 of known sign). */
static const qd_expr *root_quadratic(qd_ctx *ctx, const qd_expr *X, const qd_expr *q) {
    const qd_expr *a = qd_coeff(ctx, X, q, 0), *b = qd_coeff(ctx, X, q, 1);
    const qd_expr *c = qd_coeff(ctx, X, q, 2);
    int s = c ? qd__hj_sign(c) : 0;
    if (!a || !b || !s)
        return NULL;
    const qd_expr *four = qd_int(ctx, 4);
    const qd_expr *lead = qd_div(ctx, qd_mul(ctx, qd_add(ctx, qd_mul(ctx, qd_int(ctx, 2), qd_mul(ctx, c, q)), b),
                                             qd_sqrt(ctx, X)),
                                 qd_mul(ctx, four, c));
    const qd_expr *k = qd_simplify(ctx, qd_div(ctx, qd_sub(ctx, qd_mul(ctx, four, qd_mul(ctx, a, c)),
                                                          qd_powi(ctx, b, 2)),
                                               qd_mul(ctx, qd_int(ctx, 8), c)));
    return qd_add(ctx, lead, qd_mul(ctx, k, inverse_root(ctx, X, a, b, c, s, q)));
}

/* The degree of X in q when it is a polynomial there (<= 2 is all we need), else -1. */
static int degree(qd_ctx *ctx, const qd_expr *X, const qd_expr *q) {
    const qd_expr *sum = qd_int(ctx, 0);
    int deg = -1;
    for (long k = 0; k <= 2; k++) {
        const qd_expr *c = qd_coeff(ctx, X, q, k);
        if (!c || qd_has(c, q))
            return -1;
        if (!qd_is_zero(c))
            deg = (int)k;
        sum = qd_add(ctx, sum, qd_mul(ctx, c, qd_powi(ctx, q, k)));
    }
    const qd_expr *d = qd_expand(ctx, qd_sub(ctx, X, sum));
    return d && qd_is_zero(d) ? deg : -1;
}

const qd_expr *qd__hj_quadrature(qd_ctx *ctx, const qd_expr *p2, const qd_expr *q) {
    const qd_expr *X = qd_expand(ctx, p2);
    if (!X)
        return NULL;
    const qd_expr *r = NULL;
    int deg = degree(ctx, X, q);
    if (deg == 0)
        r = qd_mul(ctx, qd_sqrt(ctx, p2), q);
    else if (deg == 1)
        r = qd_integrate(ctx, qd_sqrt(ctx, p2), q);
    else if (deg == 2)
        r = root_quadratic(ctx, X, q);
    if (!r && !qd__ctx_recover(ctx))
        return NULL;
    return r ? r : qd__hj_integral(ctx, qd_sqrt(ctx, p2), q);
}

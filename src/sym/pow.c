/*
 * src/sym/pow.c - powers in canonical form.
 *
 * Rules (the real-valued ones every CAS applies on construction):
 *   b^0 = 1, b^1 = b, 1^e = 1, 0^e = 0 for numeric e > 0 (0^-1 is an error);
 *   numbers fold exactly where the result is rational (4^(1/2) = 2);
 *   (c*x*y)^n = c^n * x^n * y^n and (x^a)^n = x^(a*n) for integer n.
 * Symbols are real (symbol.c), so for a fraction r (not an integer):
 *   (x^(2k))^r = |x|^(2k r), |x|^(2k) = x^(2k): sqrt(x^2) = |x|, sqrt(x^4) = x^2;
 *   (x^a)^r = x^(a r) when x >= 0 is known (qd__nonneg: a positive symbol,
 *   |u|, exp(u), a sum of such...);
 *   (c*F*R)^r = |c|^r * F^r * (sign(c)*R)^r when |c|^r is rational and F
 *   are the factors above (even powers, powers of nonnegative bases):
 *   sqrt(9*a^6*g^2*m^4) = 3*|a|^3*|g|*m^2, sqrt(4*x) = 2*sqrt(x); but not
 *   when sign(c)*R would be -1, whose odd roots fold to the real root
 *   ((-1)^(1/3) = -1) where (-x^2)^(1/3) is the principal one.
 * Other factors stay under the root (sqrt(2*g*l) is not split), as do
 * floats.  The checks look only at the base's own factors, so they cost a
 * pass over a product only when a product is raised to a fraction.
 */
#include "node.h"
#include "../base/args.h"
#include "sym_export.h"

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

/* ---- real powers ------------------------------------------------------- */

static bool is_even_int(const qd_expr *e) {
    return e->kind == QD_RATIONAL && mpz_cmp_ui(mpq_denref(e->u.q), 1) == 0 &&
           mpz_even_p(mpq_numref(e->u.q));
}

static bool is_fraction(const qd_expr *e) {
    return e->kind == QD_RATIONAL && mpz_cmp_ui(mpq_denref(e->u.q), 1) != 0;
}

static bool nonneg(const qd_expr *e, int depth) {
    switch ((qd_kind)e->kind) {
    case QD_RATIONAL:
    case QD_FLOAT: return qd_number_sign(e) >= 0;
    case QD_CONSTANT: return true;
    case QD_SYMBOL: return e->u.sym.positive;
    case QD_FUNC: return e->tag == QD_ABS || e->tag == QD_EXP || e->tag == QD_COSH;
    case QD_POW: return is_even_int(e->args[1]) || (depth > 0 && nonneg(e->args[0], depth - 1));
    case QD_MUL:
    case QD_ADD:
        for (size_t i = 0; depth > 0 && i < e->nargs; i++)
            if (!nonneg(e->args[i], depth - 1))
                return false;
        return depth > 0;
    default: return false;
    }
}

/* A shallow look (three levels): false means "not known". */
bool qd__nonneg(const qd_expr *e) { return nonneg(e, 3); }

/* A factor whose fractional power simplifies: (x^(2k))^r, (x^a)^r with x >= 0. */
static bool root_splits(const qd_expr *f) {
    return f->kind == QD_POW && (is_even_int(f->args[1]) || qd__nonneg(f->args[0]));
}

/* (c*F*R)^r as in the head comment; NULL when nothing comes out. */
static const qd_expr *split_root(qd_ctx *ctx, const qd_expr *prod, const qd_expr *r) {
    size_t n = prod->nargs, nout = 0, nin = 0;
    const qd_expr *stack[32];
    const qd_expr **out = 2 * n + 1 <= 32 ? stack : qd__alloc(ctx, (2 * n + 1) * sizeof *out);
    if (!out)
        return NULL;
    const qd_expr **in = out + n;
    for (size_t i = 0; i < n; i++) {
        const qd_expr *f = prod->args[i];
        bool folded = false;
        if (f->kind == QD_RATIONAL) {
            const qd_expr *c = qd_number_sign(f) < 0 ? qd_neg(ctx, f) : f;
            /* c is NULL when qd_neg ran out of memory (recorded): f stays inside */
            const qd_expr *cr = c ? qd__number_pow(ctx, c, r, &folded) : NULL;
            folded = folded && cr && !qd_is_one(c);
            if (folded) {
                out[nout++] = cr;
                if (c != f)
                    in[nin++] = ctx->sym->minus_one;
            }
        } else if (root_splits(f)) {
            out[nout++] = qd_pow(ctx, f, r);
            folded = true;
        }
        if (!folded)
            in[nin++] = f;
    }
    /* (-x^2)^(1/3): -1 alone under the root would fold to the real cube
     * root, -1, where (-x^2)^(1/3) itself is SymPy's principal root */
    if (!nout || (nin == 1 && in[0] == ctx->sym->minus_one))
        return NULL;
    out[nout++] = nin ? qd_pow(ctx, qd_mul_n(ctx, nin, in), r) : ctx->sym->one;
    return qd_mul_n(ctx, nout, out);
}

/* Fractional powers of powers and products, |x|^(2k); NULL when none applies. */
static const qd_expr *real_power(qd_ctx *ctx, const qd_expr *b, const qd_expr *e) {
    if (b->kind == QD_FUNC && b->tag == QD_ABS && is_even_int(e))
        return qd_pow(ctx, b->args[0], e);
    if (!is_fraction(e))
        return NULL;
    if (b->kind == QD_POW && is_even_int(b->args[1]))
        return qd_pow(ctx, qd_fn(ctx, QD_ABS, b->args[0]), qd_mul(ctx, b->args[1], e));
    if (b->kind == QD_POW && qd__nonneg(b->args[0]))
        return qd_pow(ctx, b->args[0], qd_mul(ctx, b->args[1], e));
    if (b->kind == QD_MUL)
        return split_root(ctx, b, e);
    return NULL;
}

const qd_expr *qd_pow(qd_ctx *ctx, const qd_expr *b, const qd_expr *e) {
    QD_ARGS(NULL, ctx && b && e);
    if (!b || !e)
        return NULL;
    if (qd_is_zero(e) && e->kind == QD_RATIONAL)
        return ctx->sym->one;
    if (qd_is_one(e))
        return b;
    if (qd_is_one(b))
        return b;
    if (qd__is_num(b) && qd__is_num(e)) {
        bool folded;
        const qd_expr *r = qd__number_pow(ctx, b, e, &folded);
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
    const qd_expr *r = real_power(ctx, b, e);
    return r ? r : pow_node(ctx, b, e);
}

const qd_expr *qd_powi(qd_ctx *ctx, const qd_expr *b, long n) {
    QD_ARGS(NULL, ctx && b);
    return qd_pow(ctx, b, qd_int(ctx, n));
}

const qd_expr *qd_sqrt(qd_ctx *ctx, const qd_expr *a) { QD_ARGS(NULL, ctx && a); return qd_pow(ctx, a, ctx->sym->half); }

const qd_expr *qd__pow_written(qd_ctx *ctx, const qd_expr *b, const qd_expr *e) {
    if (b && e && b->kind == QD_RATIONAL && qd_is_zero(b) && !qd__is_num(e)) {
        qd_ctx_error(ctx, QD_ERR_ARG,
                     "0 to a power that is not a number: 0^x is 0 for x > 0 and undefined "
                     "otherwise; write 0");
        return NULL;
    }
    return qd_pow(ctx, b, e);
}

/*
 * src/sym/func.c - built-in and user-named functions.
 *
 * On construction: exact values at 0, 1 and multiples of pi/2 where they are
 * rational; a float argument is evaluated; odd functions take a leading minus
 * sign out (sin(-x) = -sin(x)) and even ones drop it (cos(b - a) = cos(a - b)),
 * so that equal values meet as one node; exp and log cancel.
 */
#include "node.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static const char *const names[QD_FUNC_COUNT] = {
    "sin", "cos", "tan", "asin", "acos", "atan", "atan2",
    "sinh", "cosh", "tanh", "exp", "log", "abs", "sign",
};

const char *qd_func_name(qd_func f) { return (unsigned)f < QD_FUNC_COUNT ? names[f] : "?"; }

bool qd_func_from_name(const char *name, qd_func *out) {
    for (int i = 0; i < QD_FUNC_COUNT; i++)
        if (strcmp(names[i], name) == 0) {
            *out = (qd_func)i;
            return true;
        }
    return false;
}

static const qd_expr *call_node(qd_ctx *ctx, qd_func f, size_t n, const qd_expr *const *args) {
    qd_expr proto = {0};
    proto.kind = QD_FUNC;
    proto.tag = (uint8_t)f;
    return qd__intern(ctx, &proto, n, args);
}

static double eval1(qd_func f, double x) {
    switch (f) {
    case QD_SIN: return sin(x);
    case QD_COS: return cos(x);
    case QD_TAN: return tan(x);
    case QD_ASIN: return asin(x);
    case QD_ACOS: return acos(x);
    case QD_ATAN: return atan(x);
    case QD_SINH: return sinh(x);
    case QD_COSH: return cosh(x);
    case QD_TANH: return tanh(x);
    case QD_EXP: return exp(x);
    case QD_LOG: return log(x);
    case QD_ABS: return fabs(x);
    case QD_SIGN: return (x > 0) - (x < 0);
    default: return NAN;
    }
}

static bool is_odd(qd_func f) {
    return f == QD_SIN || f == QD_TAN || f == QD_ASIN || f == QD_ATAN || f == QD_SINH ||
           f == QD_TANH || f == QD_SIGN;
}

static bool is_even(qd_func f) { return f == QD_COS || f == QD_COSH || f == QD_ABS; }

/* If a = k*pi/2 with integer k, set *k (mod 4) and return true. */
static bool half_pi_multiple(qd_ctx *ctx, const qd_expr *a, long *k) {
    const qd_expr *pi = qd_const(ctx, QD_PI);
    long num, den;
    if (a == pi) {
        *k = 2;
        return true;
    }
    if (a->kind != QD_MUL || a->nargs != 2 || a->args[1] != pi ||
        !qd_rational_get(a->args[0], &num, &den))
        return false;
    if (den != 1 && den != 2)
        return false;
    long twice = den == 1 ? 2 * (num % 4) : num % 4;
    *k = ((twice % 4) + 4) % 4;
    return true;
}

/* The exact value of f(a) when there is a simple one; *err for log(0). */
static const qd_expr *exact_value(qd_ctx *ctx, qd_func f, const qd_expr *a, bool *err) {
    if (qd_is_zero(a) && a->kind == QD_RATIONAL) {
        switch (f) {
        case QD_SIN: case QD_TAN: case QD_ASIN: case QD_ATAN: case QD_SINH:
        case QD_TANH: case QD_ABS: case QD_SIGN:
            return ctx->zero;
        case QD_COS: case QD_COSH: case QD_EXP:
            return ctx->one;
        case QD_ACOS:
            return qd_mul(ctx, ctx->half, qd_const(ctx, QD_PI));
        case QD_LOG:
            qd_ctx_error(ctx, QD_ERR_DIVZERO, "log(0) is not a number");
            *err = true;
            return NULL;
        default:
            return NULL;
        }
    }
    if (a->kind == QD_RATIONAL) {
        if (f == QD_ABS)
            return qd_number_sign(a) < 0 ? qd_neg(ctx, a) : a;
        if (f == QD_SIGN)
            return qd_int(ctx, qd_number_sign(a));
        if (qd_is_one(a) && (f == QD_LOG || f == QD_ACOS))
            return ctx->zero;
        return NULL;
    }
    long k;
    if ((f == QD_SIN || f == QD_COS) && half_pi_multiple(ctx, a, &k)) {
        static const int sin4[4] = {0, 1, 0, -1};
        return qd_int(ctx, f == QD_SIN ? sin4[k] : sin4[(k + 1) % 4]);
    }
    if (f == QD_LOG && a->kind == QD_CONSTANT && a->tag == QD_E)
        return ctx->one;
    if (f == QD_LOG && a->kind == QD_FUNC && a->tag == QD_EXP)
        return a->args[0];
    if (f == QD_EXP && a->kind == QD_FUNC && a->tag == QD_LOG)
        return a->args[0];
    if (f == QD_ABS && a->kind == QD_FUNC && a->tag == QD_ABS)
        return a;
    return NULL;
}

const qd_expr *qd_fn(qd_ctx *ctx, qd_func f, const qd_expr *a) {
    if (!a)
        return NULL;
    if (f == QD_ATAN2 || (unsigned)f >= QD_FUNC_COUNT) {
        qd_ctx_error(ctx, QD_ERR_ARG, "%s takes %s", qd_func_name(f),
                     f == QD_ATAN2 ? "two arguments" : "a known function");
        return NULL;
    }
    if (a->kind == QD_FLOAT)
        return qd_float(ctx, eval1(f, a->u.f));
    bool err = false;
    const qd_expr *v = exact_value(ctx, f, a, &err);
    if (v || err)
        return v;
    if (qd__has_minus(a) && (is_odd(f) || is_even(f))) {
        const qd_expr *r = qd_fn(ctx, f, qd_neg(ctx, a));
        return is_odd(f) ? qd_neg(ctx, r) : r;
    }
    return call_node(ctx, f, 1, &a);
}

const qd_expr *qd_fn2(qd_ctx *ctx, qd_func f, const qd_expr *y, const qd_expr *x) {
    if (!y || !x)
        return NULL;
    if (f != QD_ATAN2) {
        qd_ctx_error(ctx, QD_ERR_ARG, "%s takes one argument", qd_func_name(f));
        return NULL;
    }
    if (qd__is_num(y) && qd__is_num(x) && (y->kind == QD_FLOAT || x->kind == QD_FLOAT))
        return qd_float(ctx, atan2(qd_number_value(y), qd_number_value(x)));
    if (qd_is_zero(y) && y->kind == QD_RATIONAL && qd__is_num(x) && qd_number_sign(x) > 0)
        return ctx->zero;
    if (qd__has_minus(y)) /* atan2 is odd in y */
        return qd_neg(ctx, qd_fn2(ctx, f, qd_neg(ctx, y), x));
    const qd_expr *args[2] = {y, x};
    return call_node(ctx, f, 2, args);
}

/* ---- user-named functions ----------------------------------------------- */

static bool check_name(qd_ctx *ctx, const char *name) {
    qd_func f;
    if (!name || !*name) {
        qd_ctx_error(ctx, QD_ERR_ARG, "a function needs a name");
        return false;
    }
    if (qd_func_from_name(name, &f)) {
        qd_ctx_error(ctx, QD_ERR_ARG, "'%s' is a built-in function", name);
        return false;
    }
    return true;
}

const qd_expr *qd_ufunc(qd_ctx *ctx, const char *name, size_t n, const qd_expr *const *args) {
    if (!check_name(ctx, name))
        return NULL;
    qd_expr proto = {0};
    proto.kind = QD_UFUNC;
    proto.u.fn.name = qd__intern_name(ctx, name);
    if (!proto.u.fn.name)
        return NULL;
    return qd__intern(ctx, &proto, n, args);
}

static int cmp_unsigned(const void *a, const void *b) {
    unsigned x = *(const unsigned *)a, y = *(const unsigned *)b;
    return (x > y) - (x < y);
}

const qd_expr *qd_uderiv(qd_ctx *ctx, const char *name, size_t nslots, const unsigned *slots,
                         size_t n, const qd_expr *const *args) {
    if (!check_name(ctx, name))
        return NULL;
    if (nslots == 0 || nslots > 64) {
        qd_ctx_error(ctx, QD_ERR_ARG, "a derivative of %s needs 1 to 64 slots", name);
        return NULL;
    }
    unsigned sorted[64];
    for (size_t i = 0; i < nslots; i++) {
        if (slots[i] >= n) {
            qd_ctx_error(ctx, QD_ERR_ARG, "%s has no argument %u", name, slots[i] + 1);
            return NULL;
        }
        sorted[i] = slots[i];
    }
    qsort(sorted, nslots, sizeof sorted[0], cmp_unsigned);
    qd_expr proto = {0};
    proto.kind = QD_UDERIV;
    proto.u.fn.name = qd__intern_name(ctx, name);
    proto.u.fn.slots = sorted;
    proto.u.fn.nslots = (uint32_t)nslots;
    if (!proto.u.fn.name)
        return NULL;
    return qd__intern(ctx, &proto, n, args);
}

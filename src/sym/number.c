/*
 * src/sym/number.c - exact rationals (GMP, unbounded: never a silent
 * overflow), inexact doubles, the constants pi and e, and number folding.
 *
 * Arithmetic between two rationals stays exact; anything with a float in it
 * becomes a float, as in every CAS.
 */
#include "node.h"
#include "../base/args.h"

#include <ctype.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

const qd_expr *qd__rat_mpq(qd_ctx *ctx, const mpq_t q) {
    qd_expr proto = {0};
    proto.kind = QD_RATIONAL;
    proto.u.q[0] = q[0]; /* shallow: intern copies it */
    return qd__intern(ctx, &proto, 0, NULL);
}

const qd_expr *qd_int(qd_ctx *ctx, long v) {
    QD_ARGS(NULL, ctx);
    mpq_t q;
    mpq_init(q);
    mpq_set_si(q, v, 1);
    const qd_expr *e = qd__rat_mpq(ctx, q);
    mpq_clear(q);
    return e;
}

const qd_expr *qd_rat(qd_ctx *ctx, long num, long den) {
    QD_ARGS(NULL, ctx);
    if (den == 0) {
        qd_ctx_error(ctx, QD_ERR_DIVZERO, "division by zero: %ld/0", num);
        return NULL;
    }
    mpq_t q;
    mpq_init(q);
    mpz_set_si(mpq_numref(q), num);
    mpz_set_si(mpq_denref(q), den);
    mpq_canonicalize(q);
    const qd_expr *e = qd__rat_mpq(ctx, q);
    mpq_clear(q);
    return e;
}

/* "12", "-3/4", "2.5", "1e-3", "1.5E+2": all exact. */
static bool parse_decimal(mpq_t q, const char *s) {
    bool neg = false;
    if (*s == '+' || *s == '-')
        neg = *s++ == '-';
    mpz_t num, den, tmp;
    mpz_inits(num, den, tmp, NULL);
    mpz_set_ui(den, 1);
    bool ok = false, digits = false;
    for (; isdigit((unsigned char)*s); s++, digits = true) {
        mpz_mul_ui(num, num, 10);
        mpz_add_ui(num, num, (unsigned long)(*s - '0'));
    }
    if (*s == '/') {
        s++;
        if (!isdigit((unsigned char)*s) || !digits)
            goto done;
        mpz_set_ui(den, 0);
        for (; isdigit((unsigned char)*s); s++) {
            mpz_mul_ui(den, den, 10);
            mpz_add_ui(den, den, (unsigned long)(*s - '0'));
        }
        ok = *s == '\0' && mpz_sgn(den) != 0;
        goto done;
    }
    if (*s == '.') {
        for (s++; isdigit((unsigned char)*s); s++, digits = true) {
            mpz_mul_ui(num, num, 10);
            mpz_add_ui(num, num, (unsigned long)(*s - '0'));
            mpz_mul_ui(den, den, 10);
        }
    }
    if (!digits)
        goto done;
    if (*s == 'e' || *s == 'E') {
        s++;
        bool eneg = false;
        if (*s == '+' || *s == '-')
            eneg = *s++ == '-';
        if (!isdigit((unsigned char)*s))
            goto done;
        unsigned long ex = 0;
        for (; isdigit((unsigned char)*s); s++) {
            ex = ex * 10 + (unsigned long)(*s - '0');
            if (ex > 100000)
                goto done; /* an exponent this large is a mistake, not a number */
        }
        mpz_ui_pow_ui(tmp, 10, ex);
        if (eneg)
            mpz_mul(den, den, tmp);
        else
            mpz_mul(num, num, tmp);
    }
    ok = *s == '\0';
done:
    if (ok) {
        if (neg)
            mpz_neg(num, num);
        mpz_set(mpq_numref(q), num);
        mpz_set(mpq_denref(q), den);
        mpq_canonicalize(q);
    }
    mpz_clears(num, den, tmp, NULL);
    return ok;
}

const qd_expr *qd_rat_str(qd_ctx *ctx, const char *text) {
    QD_ARGS(NULL, ctx && text);
    mpq_t q;
    mpq_init(q);
    const qd_expr *e = NULL;
    if (parse_decimal(q, text))
        e = qd__rat_mpq(ctx, q);
    else
        qd_ctx_error(ctx, QD_ERR_ARG, "not a number: '%s'", text);
    mpq_clear(q);
    return e;
}

const qd_expr *qd_float(qd_ctx *ctx, double v) {
    QD_ARGS(NULL, ctx);
    if (!isfinite(v)) {
        qd_ctx_error(ctx, QD_ERR_NUMERIC, "not a finite number: %g", v);
        return NULL;
    }
    qd_expr proto = {0};
    proto.kind = QD_FLOAT;
    proto.u.f = v == 0.0 ? 0.0 : v; /* one zero: -0.0 and 0.0 are one node */
    return qd__intern(ctx, &proto, 0, NULL);
}

const qd_expr *qd_const(qd_ctx *ctx, qd_constant c) {
    QD_ARGS(NULL, ctx);
    qd_expr proto = {0};
    proto.kind = QD_CONSTANT;
    proto.tag = (uint8_t)c;
    return qd__intern(ctx, &proto, 0, NULL);
}

bool qd__is_rational(const qd_expr *e) { return e->kind == QD_RATIONAL; }
bool qd__is_float(const qd_expr *e) { return e->kind == QD_FLOAT; }

const qd_expr *qd__number_add(qd_ctx *ctx, const qd_expr *a, const qd_expr *b) {
    if (a->kind == QD_RATIONAL && b->kind == QD_RATIONAL) {
        if (mpq_sgn(a->u.q) == 0)
            return b;
        if (mpq_sgn(b->u.q) == 0)
            return a;
        mpq_t r;
        mpq_init(r);
        mpq_add(r, a->u.q, b->u.q);
        const qd_expr *e = qd__rat_mpq(ctx, r);
        mpq_clear(r);
        return e;
    }
    return qd_float(ctx, qd_number_value(a) + qd_number_value(b));
}

const qd_expr *qd__number_mul(qd_ctx *ctx, const qd_expr *a, const qd_expr *b) {
    if (a->kind == QD_RATIONAL && b->kind == QD_RATIONAL) {
        if (a == ctx->sym->one)
            return b;
        if (b == ctx->sym->one)
            return a;
        mpq_t r;
        mpq_init(r);
        mpq_mul(r, a->u.q, b->u.q);
        const qd_expr *e = qd__rat_mpq(ctx, r);
        mpq_clear(r);
        return e;
    }
    return qd_float(ctx, qd_number_value(a) * qd_number_value(b));
}

/* Exact k-th root of a nonnegative integer, if there is one. */
static bool exact_root(mpz_t out, const mpz_t z, unsigned long k) {
    return mpz_root(out, z, k) != 0;
}

/* Largest exponent we fold exactly: beyond it the number is astronomically
 * large and almost surely a modelling mistake; keep it as a power. */

const qd_expr *qd__number_pow(qd_ctx *ctx, const qd_expr *a, const qd_expr *e, bool *folded) {
    *folded = false;
    if (a->kind == QD_FLOAT || e->kind == QD_FLOAT) {
        double r = pow(qd_number_value(a), qd_number_value(e));
        if (!isfinite(r))
            return NULL; /* e.g. a negative base to a fractional power: stays symbolic */
        *folded = true;
        return qd_float(ctx, r);
    }
    mpz_srcptr en = mpq_numref(e->u.q), ed = mpq_denref(e->u.q);
    if (!mpz_fits_slong_p(en) || !mpz_fits_ulong_p(ed))
        return NULL;
    long p = mpz_get_si(en);
    unsigned long d = mpz_get_ui(ed);
    unsigned long ap = p < 0 ? (unsigned long)-p : (unsigned long)p;
    if (ap > QD_MAX_FOLD_EXP)
        return NULL;
    if (mpq_sgn(a->u.q) == 0) {
        if (p < 0) {
            if (p == -1 && d == 1) /* 1/0 is 0^-1 */
                qd_ctx_error(ctx, QD_ERR_DIVZERO, "division by zero");
            else if (d == 1)
                qd_ctx_error(ctx, QD_ERR_DIVZERO, "division by zero: 0 to the power %ld", p);
            else
                qd_ctx_error(ctx, QD_ERR_DIVZERO, "division by zero: 0 to the power %ld/%lu", p, d);
            *folded = true;
            return NULL;
        }
        *folded = true;
        return ctx->sym->zero;
    }
    /* too many bits to fold (after the root below they only shrink) */
    double bits = (double)ap * (double)mpz_sizeinbase(mpq_numref(a->u.q), 2) / (double)d;
    double dbits = (double)ap * (double)mpz_sizeinbase(mpq_denref(a->u.q), 2) / (double)d;
    if (bits > QD_MAX_FOLD_BITS || dbits > QD_MAX_FOLD_BITS)
        return NULL;
    qd__gmp_section outer = qd__gmp_enter(ctx);
    mpz_t num, den;
    mpz_inits(num, den, NULL);
    mpz_set(num, mpq_numref(a->u.q));
    mpz_set(den, mpq_denref(a->u.q));
    bool ok = true;
    if (d != 1) {
        /* a^(p/d) is rational only when a is a perfect d-th power. */
        if (mpz_sgn(num) < 0 && d % 2 == 0)
            ok = false;
        else
            ok = exact_root(num, num, d) && exact_root(den, den, d);
    }
    const qd_expr *r = NULL;
    if (ok) {
        mpz_pow_ui(num, num, ap);
        mpz_pow_ui(den, den, ap);
        mpq_t q;
        mpq_init(q);
        if (p < 0) {
            mpz_swap(num, den);
        }
        mpz_set(mpq_numref(q), num);
        mpz_set(mpq_denref(q), den);
        mpq_canonicalize(q);
        r = qd__rat_mpq(ctx, q);
        mpq_clear(q);
        *folded = true;
    }
    mpz_clears(num, den, NULL);
    if (!qd__gmp_leave(ctx, outer)) { /* GMP's memory was refused: QD_ERR_NOMEM */
        *folded = true;
        return NULL;
    }
    return r;
}

int qd__number_cmp(const qd_expr *a, const qd_expr *b) {
    if (a->kind == QD_RATIONAL && b->kind == QD_RATIONAL)
        return mpq_cmp(a->u.q, b->u.q);
    double x = qd_number_value(a), y = qd_number_value(b);
    if (x < y)
        return -1;
    if (x > y)
        return 1;
    return (int)a->kind - (int)b->kind; /* the rational before the equal float */
}

/* ---- inspection of numbers ------------------------------------------------ */

bool qd_is_number(const qd_expr *e) { QD_ARGS(false, e); return e && qd__is_num(e); }

bool qd_is_zero(const qd_expr *e) {
    QD_ARGS(false, e);
    if (!e)
        return false;
    if (e->kind == QD_RATIONAL)
        return mpq_sgn(e->u.q) == 0;
    return e->kind == QD_FLOAT && e->u.f == 0.0;
}

bool qd_is_one(const qd_expr *e) {
    QD_ARGS(false, e);
    return e && e->kind == QD_RATIONAL && mpz_cmp_ui(mpq_denref(e->u.q), 1) == 0 &&
           mpz_cmp_ui(mpq_numref(e->u.q), 1) == 0;
}

bool qd_is_integer(const qd_expr *e) {
    QD_ARGS(false, e);
    return e && e->kind == QD_RATIONAL && mpz_cmp_ui(mpq_denref(e->u.q), 1) == 0;
}

int qd_number_sign(const qd_expr *e) {
    QD_ARGS(0, e);
    if (e->kind == QD_RATIONAL)
        return mpq_sgn(e->u.q);
    if (e->kind == QD_FLOAT)
        return (e->u.f > 0) - (e->u.f < 0);
    return 0;
}

/* The double nearest to a rational.  mpq_get_d truncates (981/100 would be
 * 9.809999999999999); when numerator and denominator are exact doubles one
 * IEEE division rounds correctly, which covers every number a user types. */
static double rational_value(const mpq_t q) {
    mpz_srcptr n = mpq_numref(q), d = mpq_denref(q);
    if (mpz_sizeinbase(n, 2) <= 53 && mpz_sizeinbase(d, 2) <= 53)
        return mpz_get_d(n) / mpz_get_d(d);
    return mpq_get_d(q);
}

bool qd__number_finite(qd_ctx *ctx, const qd_expr *e) {
    if (e->kind != QD_RATIONAL || isfinite(rational_value(e->u.q)))
        return true;
    signed long en, ed;
    double mn = mpz_get_d_2exp(&en, mpq_numref(e->u.q));
    double md = mpz_get_d_2exp(&ed, mpq_denref(e->u.q));
    double lg = log10(fabs(mn / md)) + (double)(en - ed) * log10(2.0); /* log10 |e| */
    double ip = floor(lg);
    qd_ctx_error(ctx, QD_ERR_NUMERIC,
                 "the number %s%.3ge%.0f overflows a double (the largest is about 1.8e308)",
                 mpq_sgn(e->u.q) < 0 ? "-" : "", pow(10, lg - ip), ip);
    return false;
}

double qd_number_value(const qd_expr *e) {
    QD_ARGS(NAN, e);
    if (e->kind == QD_RATIONAL)
        return rational_value(e->u.q);
    if (e->kind == QD_FLOAT)
        return e->u.f;
    return NAN;
}

bool qd_rational_get(const qd_expr *e, long *num, long *den) {
    QD_ARGS(false, e && num && den);
    if (!e || e->kind != QD_RATIONAL || !mpz_fits_slong_p(mpq_numref(e->u.q)) ||
        !mpz_fits_slong_p(mpq_denref(e->u.q)))
        return false;
    *num = mpz_get_si(mpq_numref(e->u.q));
    *den = mpz_get_si(mpq_denref(e->u.q));
    return true;
}

const char *qd_rational_str(qd_ctx *ctx, const qd_expr *e) {
    QD_ARGS(NULL, ctx && e);
    if (!e || e->kind != QD_RATIONAL)
        return NULL;
    size_t n = mpz_sizeinbase(mpq_numref(e->u.q), 10) + mpz_sizeinbase(mpq_denref(e->u.q), 10) + 3;
    char *s = qd__alloc(ctx, n);
    if (!s)
        return NULL;
    return mpq_get_str(s, 10, e->u.q);
}

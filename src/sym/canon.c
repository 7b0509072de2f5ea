/*
 * src/sym/canon.c - the canonical forms of node.h, checked (SymEngine's
 * is_canonical in add.cpp and mul.cpp).
 *
 * qd__intern asserts qd__is_canonical on every new node when NDEBUG is not
 * defined, so the Debug and sanitizer builds check every node the whole test
 * suite makes, including those from the trusted constructors (qd__mul_raw and
 * the expanders) that skip the constructors' own normalisation.
 *
 * Valid and invalid examples (args as written in node.h):
 *   ADD [2, x, y]      valid;   ADD [x]  invalid (one term);  ADD [0, x, y] invalid;
 *   ADD [y, x]         invalid (unsorted); ADD [x, 3*x] invalid (one key twice);
 *   MUL [3, x, y^2]    valid;   MUL [1, x, y] invalid;  MUL [2, x + y] invalid
 *                      (distributed);  MUL [x, x^2] invalid (one base twice);
 *   POW [x, 2]         valid;   POW [2, 3] invalid (folds), POW [2, 10^6] valid
 *                      (too large to fold), POW [2^100000, 100000] valid (over
 *                      QD_MAX_FOLD_BITS bits);  POW [x*y, 2] invalid;
 *                      POW [x^a, 2] invalid;  POW [x, 1] invalid.
 */
#include "node.h"

#include <math.h>

static bool is_exact(const qd_expr *e, long v) {
    return e->kind == QD_RATIONAL && mpz_cmp_ui(mpq_denref(e->u.q), 1) == 0 &&
           mpz_cmp_si(mpq_numref(e->u.q), v) == 0;
}

static bool is_int(const qd_expr *e) {
    return e->kind == QD_RATIONAL && mpz_cmp_ui(mpq_denref(e->u.q), 1) == 0;
}

/* An integer exponent qd__number_pow folds the rational base b to (number.c):
 * |e| <= QD_MAX_FOLD_EXP and a result of at most QD_MAX_FOLD_BITS bits. */
static bool folds(const qd_expr *b, const qd_expr *e) {
    if (!is_int(e) || mpz_cmpabs_ui(mpq_numref(e->u.q), QD_MAX_FOLD_EXP) > 0)
        return false;
    double ap = fabs(mpz_get_d(mpq_numref(e->u.q)));
    return ap * (double)mpz_sizeinbase(mpq_numref(b->u.q), 2) <= (double)QD_MAX_FOLD_BITS &&
           ap * (double)mpz_sizeinbase(mpq_denref(b->u.q), 2) <= (double)QD_MAX_FOLD_BITS;
}

/* The factors of a term without its numeric coefficient (add.c's term key). */
static const qd_expr *const *term_key(const qd_expr *const *t, size_t *n) {
    const qd_expr *e = *t;
    if (e->kind == QD_MUL) {
        size_t off = qd__is_num(e->args[0]) ? 1 : 0;
        *n = e->nargs - off;
        return e->args + off;
    }
    *n = 1;
    return t;
}

static bool add_canonical(size_t n, const qd_expr *const *a) {
    size_t c = qd__is_num(a[0]) ? 1 : 0;
    if (n < 2 || n - c < 1 || (c && qd_is_zero(a[0])))
        return false;
    for (size_t i = c; i < n; i++) {
        if (qd__is_num(a[i]) || a[i]->kind == QD_ADD)
            return false;
        if (i > c) {
            size_t na, nb;
            const qd_expr *const *ka = term_key(&a[i - 1], &na), *const *kb = term_key(&a[i], &nb);
            if (qd__seq_cmp(ka, na, kb, nb) >= 0) /* sorted, no key twice */
                return false;
        }
    }
    return true;
}

static const qd_expr *base_of(const qd_expr *f) { return f->kind == QD_POW ? f->args[0] : f; }

static bool mul_canonical(size_t n, const qd_expr *const *a) {
    size_t c = qd__is_num(a[0]) ? 1 : 0;
    if (n - c < 1 || (c && is_exact(a[0], 1)) || (n == 1 && c))
        return false;
    if (c && n == 2 && a[0]->kind == QD_RATIONAL && a[1]->kind == QD_ADD)
        return false; /* c * (a + b) is distributed */
    if (n == 1 && !c)
        return false; /* a product of one factor is the factor */
    for (size_t i = c; i < n; i++) {
        if (qd__is_num(a[i]) || a[i]->kind == QD_MUL)
            return false;
        if (i > c && (base_of(a[i - 1]) == base_of(a[i]) || qd_expr_cmp(a[i - 1], a[i]) >= 0))
            return false;
    }
    return true;
}

static bool pow_canonical(const qd_expr *b, const qd_expr *e) {
    if (is_exact(e, 0) || is_exact(e, 1) || is_exact(b, 1))
        return false;
    /* 0^x stays as it is for a symbolic x (it is 0 only for x > 0), as in
     * SymPy; a number exponent folds */
    if (is_exact(b, 0) && qd__is_num(e))
        return false;
    if (b->kind == QD_RATIONAL && folds(b, e))
        return false;
    if (is_int(e) && (b->kind == QD_MUL || b->kind == QD_POW))
        return false;
    return true;
}

bool qd__is_canonical(const qd_expr *proto, size_t nargs, const qd_expr *const *args) {
    switch ((qd_kind)proto->kind) {
    case QD_RATIONAL: /* lowest terms, positive denominator */
        return mpz_sgn(mpq_denref(proto->u.q)) > 0;
    case QD_ADD:
        return nargs >= 1 && add_canonical(nargs, args);
    case QD_MUL:
        return nargs >= 1 && mul_canonical(nargs, args);
    case QD_POW:
        return nargs == 2 && pow_canonical(args[0], args[1]);
    default:
        return true;
    }
}

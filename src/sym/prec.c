/*
 * src/sym/prec.c - the precedence function and product split shared by the
 * printers (see prec.h), and exact spelling of numbers.
 */
#include "prec.h"
#include "../base/mem.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

bool qd__is_rat(const qd_expr *e, long num, long den) {
    return e->kind == QD_RATIONAL && mpz_cmp_si(mpq_numref(e->u.q), num) == 0 &&
           mpz_cmp_si(mpq_denref(e->u.q), den) == 0;
}

bool qd__is_recip(const qd_expr *e) {
    return e->kind == QD_POW && qd__is_num(e->args[1]) && qd_number_sign(e->args[1]) < 0;
}

int qd__prec(const qd_expr *e) {
    switch ((qd_kind)e->kind) {
    case QD_RATIONAL:
        if (mpq_sgn(e->u.q) < 0)
            return QD_PREC_NEG;
        return mpz_cmp_ui(mpq_denref(e->u.q), 1) == 0 ? QD_PREC_ATOM : QD_PREC_PRODUCT;
    case QD_FLOAT:
        return e->u.f < 0 ? QD_PREC_NEG : QD_PREC_ATOM;
    case QD_MUL:
        return qd__has_minus(e) ? QD_PREC_NEG : QD_PREC_PRODUCT;
    case QD_POW:
        if (qd__is_recip(e))
            return QD_PREC_PRODUCT;
        return qd__is_rat(e->args[1], 1, 2) ? QD_PREC_ATOM : QD_PREC_POW;
    case QD_ADD:
        return QD_PREC_SUM;
    default:
        return QD_PREC_ATOM;
    }
}

bool qd__split(qd_ctx *ctx, const qd_expr *e, qd__product_split *s) {
    memset(s, 0, sizeof *s);
    size_t n = e->kind == QD_MUL ? e->nargs : 1;
    const qd_expr *const *f = e->kind == QD_MUL ? e->args : &e;
    s->num = qd__malloc(ctx, n * sizeof *s->num);
    s->den = qd__malloc(ctx, n * sizeof *s->den);
    if (!s->num || !s->den) {
        qd__split_free(s);
        qd__oom(ctx);
        return false;
    }
    for (size_t i = 0; i < n; i++) {
        if (qd__is_num(f[i])) {
            s->neg = qd_number_sign(f[i]) < 0;
            bool unit = f[i]->kind == QD_RATIONAL && mpz_cmpabs_ui(mpq_numref(f[i]->u.q), 1) == 0 &&
                        mpz_cmp_ui(mpq_denref(f[i]->u.q), 1) == 0;
            s->coeff = unit ? NULL : f[i];
        } else if (qd__is_recip(f[i])) {
            s->den[s->nden++] = f[i];
        } else {
            s->num[s->nnum++] = f[i];
        }
    }
    return true;
}

void qd__split_free(qd__product_split *s) {
    qd__free(s->num);
    qd__free(s->den);
    s->num = s->den = NULL;
}

void qd__put_mpz(qd_buf *b, mpz_srcptr z) {
    char stack[64];
    size_t n = mpz_sizeinbase(z, 10) + 2;
    char *s = n <= sizeof stack ? stack : qd__mem_malloc(b->alloc, n);
    if (!s) {
        b->failed = true;
        return;
    }
    mpz_get_str(s, 10, z);
    qd_buf_puts(b, s[0] == '-' ? s + 1 : s);
    if (s != stack)
        qd__free(s);
}

void qd__put_double(qd_buf *b, double v) {
    char s[40];
    for (int digits = 15; digits <= 17; digits++) {
        snprintf(s, sizeof s, "%.*g", digits, v);
        if (strtod(s, NULL) == v)
            break;
    }
    qd_buf_puts(b, s);
    if (!strpbrk(s, ".e"))
        qd_buf_puts(b, ".0");
}

/*
 * src/sym/print_text.c - expressions in the model language's own syntax.
 *
 * The text reads back with qd_read to the same node.  Choices that make that
 * hold:
 *   - Plain decimals read as exact rationals (2.5 is 5/2), so a float prints
 *     with the suffix f: 2.5f, 1e-20f, 3.0f (the shortest of %.15g..%.17g
 *     that reads back as the same double).
 *   - A leading minus applies to the whole product after it, -2*x*(a + b)
 *     is -(2*x*(a + b)), and the reader multiplies a chain of factors in one
 *     call, so a coefficient is never distributed over a sum on the way back.
 *     For the same reason 1/(2*(a + b)) is printed 1/2/(a + b).
 *   - Factors with a negative numeric exponent go under '/', with the
 *     exponent flipped: x*y^-2 is x/y^2, and x^(-1/2) is 1/sqrt(x).
 *   - A sum prints its constant last and its negative terms with ' - '.
 */
#include "prec.h"

#include <math.h>

typedef struct tp {
    qd_ctx *ctx;
    qd_buf *b;
} tp;

static void expr(tp *p, const qd_expr *e);

static void operand(tp *p, const qd_expr *e, int need) {
    if (qd__prec(e) < need) {
        qd_buf_puts(p->b, "(");
        expr(p, e);
        qd_buf_puts(p->b, ")");
    } else {
        expr(p, e);
    }
}

/* |e| for a number. */
static void magnitude_number(tp *p, const qd_expr *e) {
    if (e->kind == QD_FLOAT) {
        qd__put_double(p->b, fabs(e->u.f));
        qd_buf_puts(p->b, "f");
        return;
    }
    qd__put_mpz(p->b, mpq_numref(e->u.q));
    if (mpz_cmp_ui(mpq_denref(e->u.q), 1) != 0) {
        qd_buf_puts(p->b, "/");
        qd__put_mpz(p->b, mpq_denref(e->u.q));
    }
}

/* An exponent that is a positive number: atoms bare, p/q in parentheses. */
static void positive_exponent(tp *p, const qd_expr *e) {
    bool frac = e->kind == QD_RATIONAL && mpz_cmp_ui(mpq_denref(e->u.q), 1) != 0;
    qd_buf_puts(p->b, frac ? "(" : "");
    magnitude_number(p, e);
    qd_buf_puts(p->b, frac ? ")" : "");
}

/* b^-e for a factor b^e with e a negative number. */
static void flipped(tp *p, const qd_expr *f, int need) {
    const qd_expr *b = f->args[0], *e = f->args[1];
    if (qd__is_rat(e, -1, 1)) {
        operand(p, b, need);
    } else if (qd__is_rat(e, -1, 2)) {
        qd_buf_puts(p->b, "sqrt(");
        expr(p, b);
        qd_buf_puts(p->b, ")");
    } else {
        operand(p, b, QD_PREC_ATOM);
        qd_buf_puts(p->b, "^");
        positive_exponent(p, e);
    }
}

static void numerator(tp *p, const qd__product_split *s) {
    bool any = false;
    if (s->coeff && !(s->coeff->kind == QD_RATIONAL &&
                      mpz_cmpabs_ui(mpq_numref(s->coeff->u.q), 1) == 0 && s->nnum)) {
        if (s->coeff->kind == QD_FLOAT)
            magnitude_number(p, s->coeff);
        else
            qd__put_mpz(p->b, mpq_numref(s->coeff->u.q));
        any = true;
    }
    for (size_t i = 0; i < s->nnum; i++) {
        qd_buf_puts(p->b, any ? "*" : "");
        operand(p, s->num[i], QD_PREC_POW);
        any = true;
    }
    if (!any)
        qd_buf_puts(p->b, "1");
}

static void denominator(tp *p, const qd__product_split *s) {
    bool q = s->coeff && s->coeff->kind == QD_RATIONAL &&
             mpz_cmp_ui(mpq_denref(s->coeff->u.q), 1) != 0;
    size_t n = q + s->nden;
    if (n == 0)
        return;
    bool lone_sum = s->nden == 1 && qd__is_rat(s->den[0]->args[1], -1, 1) &&
                    s->den[0]->args[0]->kind == QD_ADD;
    bool group = n > 1 && !(q && lone_sum);
    qd_buf_puts(p->b, group ? "/(" : "/");
    if (q) {
        qd__put_mpz(p->b, mpq_denref(s->coeff->u.q));
        qd_buf_puts(p->b, s->nden ? (group ? "*" : "/") : "");
    }
    for (size_t i = 0; i < s->nden; i++) {
        qd_buf_puts(p->b, i ? "*" : "");
        flipped(p, s->den[i], QD_PREC_POW);
    }
    qd_buf_puts(p->b, group ? ")" : "");
}

static void product(tp *p, const qd_expr *e, bool sign) {
    qd__product_split s;
    if (!qd__split(p->ctx, e, &s)) {
        p->b->failed = true;
        return;
    }
    if (s.neg && sign)
        qd_buf_puts(p->b, "-");
    numerator(p, &s);
    denominator(p, &s);
    qd__split_free(&s);
}

/* A term of a sum without its sign (the sum prints ' - '). */
static void magnitude(tp *p, const qd_expr *e) {
    if (qd__is_num(e))
        magnitude_number(p, e);
    else if (e->kind == QD_MUL)
        product(p, e, false);
    else
        expr(p, e);
}

static void sum(tp *p, const qd_expr *e) {
    size_t c = qd__is_num(e->args[0]) ? 1 : 0;
    for (size_t k = c; k < e->nargs + c; k++) {
        const qd_expr *t = e->args[k < e->nargs ? k : 0];
        bool minus = qd__has_minus(t);
        if (k == c)
            qd_buf_puts(p->b, minus ? "-" : "");
        else
            qd_buf_puts(p->b, minus ? " - " : " + ");
        magnitude(p, t);
    }
}

static void power(tp *p, const qd_expr *e) {
    const qd_expr *b = e->args[0], *x = e->args[1];
    if (qd__is_recip(e)) {
        product(p, e, true);
    } else if (qd__is_rat(x, 1, 2)) {
        qd_buf_puts(p->b, "sqrt(");
        expr(p, b);
        qd_buf_puts(p->b, ")");
    } else {
        operand(p, b, QD_PREC_ATOM);
        qd_buf_puts(p->b, "^");
        operand(p, x, QD_PREC_ATOM);
    }
}

static void call(tp *p, const char *name, const qd_expr *e) {
    qd_buf_puts(p->b, name);
    qd_buf_puts(p->b, "(");
    for (size_t i = 0; i < e->nargs; i++) {
        qd_buf_puts(p->b, i ? ", " : "");
        expr(p, e->args[i]);
    }
    qd_buf_puts(p->b, ")");
}

/* V'(r), V''(r) for one argument; V'[1,2](x, y) with 1-based slots otherwise. */
static void uderiv(tp *p, const qd_expr *e) {
    qd_buf_puts(p->b, e->u.fn.name);
    if (e->nargs == 1) {
        for (uint32_t i = 0; i < e->u.fn.nslots; i++)
            qd_buf_puts(p->b, "'");
        call(p, "", e);
        return;
    }
    qd_buf_puts(p->b, "'[");
    for (uint32_t i = 0; i < e->u.fn.nslots; i++)
        qd_buf_printf(p->b, "%s%u", i ? "," : "", e->u.fn.slots[i] + 1);
    qd_buf_puts(p->b, "]");
    call(p, "", e);
}

static void expr(tp *p, const qd_expr *e) {
    switch ((qd_kind)e->kind) {
    case QD_RATIONAL:
    case QD_FLOAT:
        qd_buf_puts(p->b, qd_number_sign(e) < 0 ? "-" : "");
        magnitude_number(p, e);
        break;
    case QD_CONSTANT: qd_buf_puts(p->b, e->tag == QD_PI ? "pi" : "e"); break;
    case QD_SYMBOL:
        qd_buf_puts(p->b, e->tag == QD_ROLE_TIME ? qd_print_time_name(p->ctx) : e->u.sym.name);
        break;
    case QD_FUNC: call(p, qd_func_name((qd_func)e->tag), e); break;
    case QD_UFUNC: call(p, e->u.fn.name, e); break;
    case QD_UDERIV: uderiv(p, e); break;
    case QD_POW: power(p, e); break;
    case QD_MUL: product(p, e, true); break;
    case QD_ADD: sum(p, e); break;
    }
}

qd_status qd__print_text(qd_ctx *ctx, const qd_expr *e, qd_buf *out) {
    tp p = {ctx, out};
    expr(&p, e);
    return out->failed ? QD_ERR_NOMEM : QD_OK;
}

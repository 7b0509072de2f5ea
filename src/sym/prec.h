/*
 * src/sym/prec.h - what every printer shares: one precedence function and
 * the split of a product into numerator and denominator.
 *
 * Each dialect (print_text.c, print_latex.c, print_c.c, print_sympy.c) walks
 * the same shapes: a sum prints its negative terms with a minus, a product
 * prints its factors with negative numeric exponents under a fraction bar.
 * The shapes are decided here once, so the dialects differ only in spelling.
 */
#ifndef QD_SYM_PREC_H
#define QD_SYM_PREC_H

#include "node.h"
#include "qdot/print.h"

/* Binding strength of an expression as printed in infix form, loosest first.
 * An operand needs parentheses when its level is below what its slot needs. */
enum {
    QD_PREC_SUM = 1,  /* a + b, a - b */
    QD_PREC_NEG,      /* -a: a leading minus (numbers and products) */
    QD_PREC_PRODUCT,  /* a*b, a/b, p/q */
    QD_PREC_POW,      /* a^b */
    QD_PREC_ATOM      /* names, calls, non-negative integers and floats */
};

int qd__prec(const qd_expr *e);

/* A product (or a lone power) as sign * coeff * num[0]*... / (den[0]*...).
 * den holds the factors b^e with e a negative number; they print as b^-e,
 * which reads back to the same node.  coeff is NULL when it is 1, and is
 * the numeric coefficient with its sign moved into neg otherwise. */
typedef struct qd__product_split {
    bool neg;
    const qd_expr *coeff;
    size_t nnum, nden;
    const qd_expr **num, **den;
} qd__product_split;

/* false when out of memory (recorded in ctx); free with qd__split_free. */
bool qd__split(qd_ctx *ctx, const qd_expr *e, qd__product_split *s);
void qd__split_free(qd__product_split *s);
/* A power whose exponent is a negative number: it prints as 1/b^-e. */
bool qd__is_recip(const qd_expr *e);
/* Is e (a number) exactly -1/2, 1/2, -1? */
bool qd__is_rat(const qd_expr *e, long num, long den);

/* Decimal digits of |z|. */
void qd__put_mpz(qd_buf *b, mpz_srcptr z);
/* The shortest %.Ng (N = 15..17) that reads back as v, with a '.' or an 'e'. */
void qd__put_double(qd_buf *b, double v);

/* Text, LaTeX, C and SymPy printers of one expression (print.c dispatches). */
qd_status qd__print_text(qd_ctx *ctx, const qd_expr *e, qd_buf *out);
qd_status qd__print_latex(qd_ctx *ctx, const qd_expr *e, qd_buf *out);
qd_status qd__print_c(qd_ctx *ctx, const qd_expr *e, qd_buf *out);
qd_status qd__print_sympy(qd_ctx *ctx, const qd_expr *e, qd_buf *out);

#endif

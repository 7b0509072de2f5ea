/*
 * src/sym/taylor_prog.h - Taylor mode of compiled straight-line programs:
 * the normalized Taylor coefficients x_k = x^(k)(t0)/k! of every register,
 * order by order, by the recurrences of automatic differentiation
 * (Moore 1966; Griewank and Walther 2008, ch. 13; Jorba and Zou 2005,
 * sec. 2).  The Taylor integrator (src/sim/taylor.c) is built on it.
 *
 * A qd__tay is made from one or more qd_progs over the same inputs: their
 * registers are renamed into single assignment (the evaluator reuses dead
 * registers, but order k of a register needs orders 0..k of its operands
 * kept), the n-ary sums and products become chains of binary ones, and each
 * function gets the auxiliary series its recurrence needs (sin with cos,
 * tan with 1 + tan^2, asin with sqrt(1 - x^2), ...).  Inputs marked
 * constant (parameters) and everything computed from them alone are "flat":
 * their coefficients beyond order 0 are 0 and never computed.
 *
 * Use: write every input's coefficient 0 (qd__tay_coef), run order 0; then
 * for k = 1, 2, ...: write the varying inputs' coefficient k, run order k.
 * Outputs are read as coefficient arrays.  One workspace per qd__tay, in the
 * floating type chosen at creation (double, long double, __float128).
 */
#ifndef QD_SYM_TAYLOR_PROG_H
#define QD_SYM_TAYLOR_PROG_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include "qdot/eval.h"
#include "qdot/print.h"

typedef struct qd__tay qd__tay;

#ifdef QD_HAVE_QUADMATH
__extension__ typedef __float128 qd__f128; /* (-Wpedantic: a GNU type) */
#endif

/* The floating type of a workspace. */
typedef enum qd__tay_prec { QD__TAY_DOUBLE, QD__TAY_LONG, QD__TAY_QUAD } qd__tay_prec;

/* The Taylor mode of progs[0..nprog) (all over the same nin inputs),
 * coefficients up to maxorder.  var[i]: input i varies (NULL: all do).
 * NULL on failure, reason in ctx (an operation with no recurrence). */
qd__tay *qd__tay_new(qd_ctx *ctx, size_t nprog, const qd_prog *const *progs, const bool *var,
                     size_t maxorder, qd__tay_prec prec);
void qd__tay_free(qd__tay *tp);

size_t qd__tay_nout(const qd__tay *tp);      /* the outputs of every program, in order */
size_t qd__tay_ninstr(const qd__tay *tp);    /* instructions after renaming */
size_t qd__tay_maxorder(const qd__tay *tp);
bool qd__tay_out_flat(const qd__tay *tp, size_t j); /* its coefficients beyond 0 vanish */
/* Coefficient arrays (maxorder + 1 entries) of input i and output j, in the
 * workspace's type: double *, long double * or __float128 *. */
void *qd__tay_in(qd__tay *tp, size_t i);
void *qd__tay_out(qd__tay *tp, size_t j);
/* Coefficient k of every register from orders 0..k of the inputs and
 * orders < k of the registers. */
void qd__tay_run(qd__tay *tp, size_t k);

/* Generated C for orders k >= 1 (qd__tay_emit_c): c the double workspace,
 * register r's coefficients at c + r * stride. */
typedef void (*qd__tay_native)(double *c, size_t stride, size_t k);

/* The C text of tp's recurrences of orders >= 1 in double, the same
 * operations in the same order as qd__tay_run (so the same results to the
 * bit): qdt_orderk (a qd__tay_native), and qdt_nreg, qdt_nlive, which a
 * loader compares with the qd__tay it is given to (qd__tay_native_fits). */
qd_status qd__tay_emit_c(const qd__tay *tp, qd_buf *out);
bool qd__tay_native_fits(const qd__tay *tp, unsigned long nreg, unsigned long nlive);
/* Orders >= 1 of a double workspace by fn from now on (NULL: interpreted). */
void qd__tay_set_native(qd__tay *tp, qd__tay_native fn);

#endif

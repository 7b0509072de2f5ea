/*
 * src/sym/sym_export.h - sym's interface to the modules above it beyond
 * the public expression API (docs/design.md, "Architecture"), in three parts.
 * Internal (prefix qd__), not public: each has one client, which builds a
 * public feature on it.
 *
 * 1. For src/sim's Taylor integrator: the Taylor mode of compiled
 * straight-line programs, the normalized Taylor coefficients
 * x_k = x^(k)(t0)/k! of every register, order by order, by the recurrences
 * of automatic differentiation (Moore 1966; Griewank and Walther 2008,
 * ch. 13; Jorba and Zou 2005, sec. 2), built on the programs' internals
 * (prog_int.h), which is why it lives here (taylor_prog.c, taylor_emit.c).
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
 *
 * 2. For src/model's parser: the constructors for what a reader has just
 * read (the expression reader, read.c, and the model files' parser,
 * model/expr.c), stricter than the constructors the library uses inside,
 * where an exact 0^q can arise from a substitution and stays a node.
 *
 * 3. For src/sim's right-hand side of (q, q'): a program whose outputs are
 * a mass matrix M (n*n, row-major) and f (n) jitted together with the
 * solve of M x = f (prog_jit.c, modules/llvm.c): one call where the
 * interpreter's path makes an evaluation, three copies and
 * qd__num_solve_spd, which on small systems cost more than the program
 * (issue 34: the double pendulum at --native's speed).
 */
#ifndef QD_SYM_SYM_EXPORT_H
#define QD_SYM_SYM_EXPORT_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include "qdot/eval.h"
#include "qdot/expr.h"
#include "qdot/print.h"

/* ---- 1. the Taylor mode of programs (taylor_prog.c, taylor_emit.c) ------- */

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

/* ---- 2. expressions as written (pow.c, func.c) ---------------------------- */

/* b^e as written: an exact 0 to a power that is not a number (0^q, defined
 * only for q > 0) is refused, QD_ERR_ARG; else qd_pow. */
const qd_expr *qd__pow_written(qd_ctx *ctx, const qd_expr *b, const qd_expr *e);
/* atan2(y, x) as written: atan2(0, 0) with exact zeros, which has no value,
 * is refused (QD_ERR_DIVZERO); else qd_fn2. */
const qd_expr *qd__atan2_written(qd_ctx *ctx, const qd_expr *y, const qd_expr *x);

/* ---- 3. a program jitted with its mass matrix's solve (prog_jit.c) ------- */

/* The fused function: the program's outputs into out, and when its first
 * n*n outputs M and next n outputs f pass qd__num_solve_spd's tests (and
 * solve_mass's: every entry of M finite), x = M^-1 f by that function's
 * Cholesky, operation for operation, and 1; else 0 and x unspecified, for
 * the caller's own solve to decide from out. */
typedef int (*qd__jit_spd_fn)(const double *in, double *out, double *x);

/* The fused function of p for an n-by-n M, tol as qd__num_solve_spd's;
 * QD_ERR_UNSUPPORTED without the JIT module (the program still runs
 * interpreted), QD_ERR_ARG when p has fewer than n*n + n outputs. */
qd_status qd__prog_jit_spd(qd_ctx *ctx, qd_prog *p, size_t n, double tol);
/* The fused function, or NULL before qd__prog_jit_spd. */
qd__jit_spd_fn qd__prog_spd(const qd_prog *p);

#endif

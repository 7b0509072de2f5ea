/*
 * qdot/tangent.h - forward-mode Jacobians of compiled programs.
 *
 * A qd_tangent compiles a vector of expressions y = F(x) (qdot/eval.h) and
 * gives its value and its Jacobian dF/dx at a point, column by column, by
 * forward-mode automatic differentiation of the compiled program: the
 * Taylor mode of the program (the recurrences of src/sym/taylor_prog.c) at
 * order 1, the input x_j seeded with the direction e_j.  Every opcode is
 * differentiated by its own rule on numbers, so the Jacobian is exact to
 * round-off (no differences) and costs one order-1 pass of the program per
 * column, whatever the size of F's expressions: nothing is expanded or
 * differentiated symbolically (Griewank and Walther, Evaluating
 * Derivatives, 2nd ed. 2008, ch. 3 and 13).
 *
 * Inputs may be marked constant (parameters): they take values but have no
 * column; the Jacobian is over the varying inputs, in their order.
 *
 * Ownership: a qd_tangent owns its program and workspace; the expressions
 * given are read at creation only.  One qd_tangent is for one thread.
 */
#ifndef QDOT_TANGENT_H
#define QDOT_TANGENT_H

#include <stdbool.h>
#include <stddef.h>
#include "expr.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct qd_tangent qd_tangent;

/* F = outputs[0..nout) as functions of the symbols inputs[0..nin).
 * vary[i]: input i has a Jacobian column (NULL: every input does).  A
 * symbol of an output that is not an input is QD_ERR_UNBOUND (as
 * qd_prog_new).  NULL on failure, reason in ctx. */
QD_API qd_tangent *qd_tangent_new(qd_ctx *ctx, size_t nin, const qd_expr *const *inputs,
                                  const bool *vary, size_t nout,
                                  const qd_expr *const *outputs);
QD_API void qd_tangent_free(qd_tangent *t);

QD_API size_t qd_tangent_nin(const qd_tangent *t);   /* inputs, all of them */
QD_API size_t qd_tangent_nvar(const qd_tangent *t);  /* varying inputs: the columns */
QD_API size_t qd_tangent_nout(const qd_tangent *t);

/* out[i] = F_i(in), in: nin values. */
QD_API qd_status qd_tangent_eval(qd_tangent *t, const double *in, double *out);

/* The value (out, nout; may be NULL) and the Jacobian J (nout * nvar,
 * row-major: J[i * nvar + k] = dF_i/dx_(k-th varying input)) at in.
 * QD_ERR_NUMERIC (message names the output) when a value or a derivative
 * is not finite there (sqrt at 0, a division by 0): never a silent NaN. */
QD_API qd_status qd_tangent_jacobian(qd_ctx *ctx, qd_tangent *t, const double *in, double *out,
                                     double *J);

#ifdef __cplusplus
}
#endif

/* NULL (issue 30): a function of this header given NULL for a pointer it
 * needs does nothing and returns QD_ERR_ARG (recorded in ctx when ctx is
 * given), NULL, 0, false or NaN, as its return type has it; a void function
 * returns, and every _free accepts NULL. NULL is an accepted value, as
 * documented at the function, for: qd_tangent_new (vary); qd_tangent_free
 * (t); qd_tangent_jacobian (out). An array whose count is 0 may be NULL. */
#endif

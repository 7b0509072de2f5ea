/*
 * qdot/eval.h - compiled numeric evaluation.
 *
 * qd_prog_new turns a set of expressions into a straight-line program over
 * doubles: every distinct node of the DAG is one instruction, computed once,
 * so shared subexpressions cost nothing extra.  Every numeric feature of qdot
 * evaluates through this path.
 */
#ifndef QDOT_EVAL_H
#define QDOT_EVAL_H

#include <stddef.h>
#include "expr.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct qd_prog qd_prog;

/* Compile outputs[0..nout) as functions of the symbols inputs[0..nin).  A
 * symbol in an output that is not an input is QD_ERR_UNBOUND (message names
 * it); a user-named function is QD_ERR_ARG.  NULL on failure, reason in ctx. */
QD_API qd_prog *qd_prog_new(qd_ctx *ctx, size_t nin, const qd_expr *const *inputs,
                     size_t nout, const qd_expr *const *outputs);
QD_API void qd_prog_free(qd_prog *p);

/* out[i] = outputs[i](in).  The program keeps its scratch space, so one
 * program must not run on two threads at once. */
QD_API void qd_prog_run(qd_prog *p, const double *in, double *out);

QD_API size_t qd_prog_ninstr(const qd_prog *p);  /* instructions after sharing */

#ifdef __cplusplus
}
#endif
#endif

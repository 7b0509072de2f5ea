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

/* out[i] = outputs[i](in).  The program keeps its own scratch space, so
 * one program must not run on two threads at once through this call. */
QD_API void qd_prog_run(qd_prog *p, const double *in, double *out);

/* Thread safety: a compiled program is immutable.  Any number of threads
 * may evaluate it at once with qd_prog_eval, each with its own workspace
 * of qd_prog_work_size(p) doubles, prepared once by qd_prog_work_init
 * (it holds the program's constants and intermediate values). */
QD_API size_t qd_prog_work_size(const qd_prog *p);
QD_API void qd_prog_work_init(const qd_prog *p, double *work);
QD_API void qd_prog_eval(const qd_prog *p, double *work, const double *in, double *out);

QD_API size_t qd_prog_ninstr(const qd_prog *p);  /* instructions after sharing */

/* Machine code for p in this process, by LLVM's ORC JIT (the optional
 * module qdot_llvm.so, opened on first use): qd_prog_eval then runs it,
 * giving the interpreter's numbers bit for bit (the same operations in
 * the same order, the same libm).  Call it before p is shared between
 * threads.  QD_ERR_UNSUPPORTED (p still interpreted) when the module is
 * missing or LLVM fails, saying why; QD_OK at once when already done. */
QD_API qd_status qd_prog_jit(qd_ctx *ctx, qd_prog *p);
QD_API bool qd_prog_jitted(const qd_prog *p); /* qd_prog_jit succeeded */

#ifdef __cplusplus
}
#endif

/* NULL (issue 30): a function of this header given NULL for a pointer it
 * needs does nothing and returns QD_ERR_ARG (recorded in ctx when ctx is
 * given), NULL, 0, false or NaN, as its return type has it; a void function
 * returns, and every _free accepts NULL. NULL is an accepted value, as
 * documented at the function, for: qd_prog_new (ctx, inputs, outputs);
 * qd_prog_free (p); qd_prog_run (in, out, p); qd_prog_ninstr (p). An array
 * whose count is 0 may be NULL. */
#endif

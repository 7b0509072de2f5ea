/*
 * src/sym/jit.h - what libqdot and its JIT module (modules/llvm.c,
 * qdot_llvm.so) share: a straight-line program (prog_int.h) handed over as
 * it is, and the machine code handed back.  The module is opened only by
 * qd_prog_jit, so no other call loads LLVM (libLLVM is 100 MB of code and
 * the loader's time; docs/design.md "The JIT").
 *
 * The code must compute what qd_prog_eval computes, bit for bit: the same
 * operations in the same order, no fast-math flags, no contraction into
 * fused multiply-adds, the same libm functions, and the library's own
 * qd__pow_value and qd__step_value through the pointers given.
 */
#ifndef QD_SYM_JIT_H
#define QD_SYM_JIT_H

#include <stddef.h>

#include "sym_export.h" /* qd__jit_spd_fn */

struct qd_prog;

#define QD__JIT_ABI 2

/* The generated function: out[k] = output k of the program at in. */
typedef void (*qd__jit_fn)(const double *in, double *out);


typedef struct qd__jit_env {
    double (*pow)(double b, double e); /* qd__pow_value */
    double (*step)(double x);          /* qd__step_value */
} qd__jit_env;

typedef struct qd__jit_ops {
    /* Machine code for p; *fn its entry.  NULL on failure, why in err
     * (cap bytes).  The code lives until release; it keeps no pointer
     * into p. */
    void *(*compile)(const struct qd_prog *p, const qd__jit_env *env, qd__jit_fn *fn, char *err,
                     size_t cap);
    void (*release)(void *code);
    /* The same program with M x = f solved in the same code (*fn above);
     * the code released by release. */
    void *(*compile_spd)(const struct qd_prog *p, size_t n, double tol, const qd__jit_env *env,
                         qd__jit_spd_fn *fn, char *err, size_t cap);
} qd__jit_ops;

#endif

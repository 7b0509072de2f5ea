/*
 * src/sym/prog_int.h - the straight-line program's instructions and layout,
 * shared by its compiler and evaluator (prog.c) and its Taylor mode
 * (taylor_prog.c), which reads the instructions to build the recurrences.
 */
#ifndef QD_SYM_PROG_INT_H
#define QD_SYM_PROG_INT_H

#include "node.h"
#include "jit.h"
#include "qdot/eval.h"

#include <stdatomic.h>
#include <stdint.h>

typedef enum op {
    OP_ADD, OP_SUB, OP_MUL, OP_DIV, OP_NEG, OP_RECIP, OP_SQRT, OP_POW,
    OP_ADD3, OP_MUL3, OP_SUMN, OP_PRODN,
    OP_SIN, OP_COS, OP_TAN, OP_ASIN, OP_ACOS, OP_ATAN, OP_ATAN2,
    OP_SINH, OP_COSH, OP_TANH, OP_EXP, OP_LOG, OP_ABS, OP_SIGN, OP_STEP
} op;

_Static_assert(OP_SIGN - OP_SIN == QD_SIGN - QD_SIN && OP_STEP - OP_SIN == QD_STEP - QD_SIN && OP_ATAN2 - OP_SIN == QD_ATAN2,
               "function opcodes follow qd_func");

/* A unary instruction reads arg[0] twice, so every instruction but the
 * n-ary ones reads two registers.  SUMN and PRODN find their operands in the
 * program's operand list at arg[0]: a count np, a count nn, then np + nn
 * registers; SUMN is the sum of the first np minus the rest, PRODN the
 * product of the first np over the product of the rest.  One dispatch for a
 * whole sum or product, the running value kept in a machine register.  ADD3
 * and MUL3, the most common n-ary cases, have just three registers there. */
typedef struct instr {
    uint32_t op, dst, arg[2];
} instr;

struct qd_prog {
    size_t nin, nout, ncode, nreg;
    instr *code;
    uint32_t *opnd; /* operand lists of ADD3, MUL3, SUMN and PRODN */
    double *regs;   /* qd_prog_run's workspace */
    double *consts; /* nconst constants, registers nin .. nin + nconst */
    size_t nconst;
    uint32_t *out;
    /* Machine code for the program (qd_prog_jit), or NULL.  Atomic: a run
     * may switch its programs to machine code while other threads evaluate
     * them (the tier-up of src/sim/jit.c), and either way gives the same
     * numbers. */
    _Atomic(qd__jit_fn) jit;
    void *jit_code;    /* what the JIT module releases */
    /* The program and the solve of its M x = f in one function
     * (qd__prog_jit_spd), or NULL; atomic for the same reason. */
    _Atomic(qd__jit_spd_fn) spd;
    void *spd_code;
};

/* The JIT's code released (prog_jit.c): qd_prog_free's. */
void qd__prog_jit_release(qd_prog *p);

#endif

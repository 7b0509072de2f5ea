/*
 * src/sym/taylor_int.h - the Taylor mode's renamed program, shared by its
 * builder and interpreter (taylor_prog.c) and its C emitter
 * (taylor_emit.c), which writes the same recurrences as straight-line C.
 */
#ifndef QD_SYM_TAYLOR_INT_H
#define QD_SYM_TAYLOR_INT_H

#include "sym_export.h"

typedef enum top {
    T_ADD, T_SUB, T_MUL, T_DIV, T_NEG, T_RECIP, T_SQRT, T_POWC, T_SINCOS, T_SINHCOSH,
    T_TAN, T_TANH, T_ASIN, T_ACOS, T_ATAN, T_ATAN2, T_EXP, T_LOG, T_ABS, T_SIGN, T_STEP,
    T_MULC, T_DIVC /* x * y with x flat, x / y with y flat: code only */
} top;

/* d = op(a, b); u: the auxiliary series (cos beside sin, ...), else d.
 * fa, fb: the operand is flat (its coefficients beyond 0 vanish). */
typedef struct tins {
    uint32_t op, d, a, b, u, w;
    uint8_t fa, fb;
} tins;

/* An instruction as the recurrences run it: registers as offsets into the
 * workspace (register * stride), a flat factor or divisor as its own
 * operation, so the hot loop neither multiplies indices nor tests flags. */
typedef struct tcode {
    uint32_t op, d, u, w, a, b;
} tcode;

struct qd__tay {
    qd__tay_prec prec;
    size_t nin, nreg, stride, maxorder;
    tins *ins;
    tcode *code;
    size_t nins;
    uint32_t *live; /* the instructions whose result is not flat */
    size_t nlive;
    uint32_t *out;
    uint8_t *oflat; /* per output: flat */
    size_t nout;
    void *work; /* nreg * stride coefficients */
    qd__tay_native native; /* orders >= 1 in generated C (double), or NULL */
};

#endif

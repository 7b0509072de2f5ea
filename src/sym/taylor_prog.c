/*
 * src/sym/taylor_prog.c - Taylor mode of the straight-line programs
 * (sym_export.h): the programs renamed into single assignment with binary
 * operations and auxiliary series, then the recurrences of taylor_rec.h
 * instantiated for double, long double and qd__f128.
 */
#include "prog_int.h"
#include "sym_export.h"
#include "taylor_int.h"
#include "base/mem.h"

#include <math.h>
#include <string.h>
#ifdef QD_HAVE_QUADMATH
#include <quadmath.h>
#endif

#define NONE UINT32_MAX

/* The builder: registers and instructions are bounded before it starts. */
typedef struct bld {
    qd__tay *tp;
    uint8_t *flat;
    uint32_t *sc, *sch; /* per register: its SINCOS (SINHCOSH) instruction */
    uint32_t *tmp;      /* operands of one n-ary instruction */
    uint32_t scratch;   /* the register w of the operations without one */
} bld;

static uint32_t new_reg(bld *b, bool flat) {
    uint32_t r = (uint32_t)b->tp->nreg++;
    b->flat[r] = flat;
    b->sc[r] = b->sch[r] = NONE;
    return r;
}

static bool has_aux(top o) { return o >= T_SINCOS && o <= T_ATAN2; }

/* The operations whose recurrences weigh x_j by j: they keep w_j = j x_j,
 * the series of x' shifted, as a register of its own, filled once per order
 * (sin and cos both read it).  The others write w into a scratch register. */
static bool has_weight(top o) { return o == T_SINCOS || o == T_SINHCOSH || o == T_TAN || o == T_TANH || o == T_EXP; }

/* The instruction d = o(x, y) (y = x when unary); returns d. */
static uint32_t add(bld *b, top o, uint32_t x, uint32_t y) {
    bool flat = o == T_SIGN || o == T_STEP || (b->flat[x] && b->flat[y]);
    uint32_t d = new_reg(b, flat), u = has_aux(o) ? new_reg(b, flat) : d;
    uint32_t w = has_weight(o) ? new_reg(b, flat) : b->scratch;
    qd__tay *tp = b->tp;
    if (!flat)
        tp->live[tp->nlive++] = (uint32_t)tp->nins;
    tp->ins[tp->nins++] = (tins){o, d, x, y, u, w, b->flat[x], b->flat[y]};
    return d;
}

/* sin x and cos x come from one instruction, whichever is asked first. */
static uint32_t sincos_of(bld *b, top o, uint32_t *of, uint32_t x, bool cosine) {
    if (of[x] == NONE) {
        add(b, o, x, x);
        of[x] = (uint32_t)b->tp->nins - 1;
    }
    const tins *in = &b->tp->ins[of[x]];
    return cosine ? in->u : in->d;
}

/* Flat operands first: their partial sum or product stays flat. */
static void flat_first(bld *b, uint32_t *r, size_t n) {
    size_t k = 0;
    for (size_t i = 0; i < n; i++)
        if (b->flat[r[i]]) {
            uint32_t t = r[i];
            memmove(r + k + 1, r + k, (i - k) * sizeof *r);
            r[k++] = t;
        }
}

static uint32_t chain(bld *b, top o, const uint32_t *r, size_t n) {
    uint32_t acc = r[0];
    for (size_t i = 1; i < n; i++)
        acc = add(b, o, acc, r[i]);
    return acc;
}

/* The sum of pos minus neg (SUMN, ADD3), as binary instructions. */
static uint32_t sum(bld *b, uint32_t *pos, size_t np, uint32_t *neg, size_t nn) {
    flat_first(b, pos, np);
    flat_first(b, neg, nn);
    uint32_t acc = np ? chain(b, T_ADD, pos, np) : add(b, T_NEG, neg[0], neg[0]);
    for (size_t i = np ? 0 : 1; i < nn; i++)
        acc = add(b, T_SUB, acc, neg[i]);
    return acc;
}

/* The product of pos over the product of neg (PRODN, MUL3). */
static uint32_t product(bld *b, uint32_t *pos, size_t np, uint32_t *neg, size_t nn) {
    flat_first(b, pos, np);
    flat_first(b, neg, nn);
    if (!nn)
        return chain(b, T_MUL, pos, np);
    uint32_t den = chain(b, T_MUL, neg, nn);
    return np ? add(b, T_DIV, chain(b, T_MUL, pos, np), den) : add(b, T_RECIP, den, den);
}

/* x^y: x^(constant) has its own recurrence, else exp(y log x). */
static uint32_t power(bld *b, uint32_t x, uint32_t y) {
    if (b->flat[y])
        return add(b, T_POWC, x, y);
    uint32_t l = add(b, T_LOG, x, x), m = add(b, T_MUL, l, y);
    return add(b, T_EXP, m, m);
}

static uint32_t nary(bld *b, const qd_prog *p, const instr *in, const uint32_t *cur) {
    const uint32_t *a = p->opnd + in->arg[0];
    size_t np = 3, nn = 0;
    if (in->op == OP_SUMN || in->op == OP_PRODN) {
        np = a[0];
        nn = a[1];
        a += 2;
    }
    for (size_t i = 0; i < np + nn; i++)
        b->tmp[i] = cur[a[i]];
    bool prod = in->op == OP_MUL3 || in->op == OP_PRODN;
    return prod ? product(b, b->tmp, np, b->tmp + np, nn) : sum(b, b->tmp, np, b->tmp + np, nn);
}

/* The renamed instruction in; its result register. */
static uint32_t translate(bld *b, const qd_prog *p, const instr *in, const uint32_t *cur) {
    /* an n-ary instruction's arg is an index into the operand lists, not a register */
    bool regs = !(in->op >= OP_ADD3 && in->op <= OP_PRODN);
    uint32_t x = regs ? cur[in->arg[0]] : 0, y = regs ? cur[in->arg[1]] : 0;
    switch ((op)in->op) {
    case OP_ADD: return add(b, T_ADD, x, y);
    case OP_SUB: return add(b, T_SUB, x, y);
    case OP_MUL: return add(b, T_MUL, x, y);
    case OP_DIV: return add(b, T_DIV, x, y);
    case OP_NEG: return add(b, T_NEG, x, x);
    case OP_RECIP: return add(b, T_RECIP, x, x);
    case OP_SQRT: return add(b, T_SQRT, x, x);
    case OP_POW: return power(b, x, y);
    case OP_ADD3: case OP_MUL3: case OP_SUMN: case OP_PRODN: return nary(b, p, in, cur);
    case OP_SIN: return sincos_of(b, T_SINCOS, b->sc, x, false);
    case OP_COS: return sincos_of(b, T_SINCOS, b->sc, x, true);
    case OP_SINH: return sincos_of(b, T_SINHCOSH, b->sch, x, false);
    case OP_COSH: return sincos_of(b, T_SINHCOSH, b->sch, x, true);
    case OP_TAN: return add(b, T_TAN, x, x);
    case OP_TANH: return add(b, T_TANH, x, x);
    case OP_ASIN: return add(b, T_ASIN, x, x);
    case OP_ACOS: return add(b, T_ACOS, x, x);
    case OP_ATAN: return add(b, T_ATAN, x, x);
    case OP_ATAN2: return add(b, T_ATAN2, x, y);
    case OP_EXP: return add(b, T_EXP, x, x);
    case OP_LOG: return add(b, T_LOG, x, x);
    case OP_ABS: return add(b, T_ABS, x, x);
    case OP_SIGN: return add(b, T_SIGN, x, x);
    case OP_STEP: return add(b, T_STEP, x, x);
    }
    return NONE;
}

/* Program p renamed: its inputs are registers 0..nin, its constants new
 * flat registers (values into kval/kreg), its outputs appended to out. */
static bool rename_prog(qd_ctx *ctx, bld *b, const qd_prog *p, double *kval, uint32_t *kreg,
                        size_t *nk) {
    qd__tay *tp = b->tp;
    uint32_t *cur = qd__malloc(ctx, (p->nreg + 1) * sizeof *cur);
    if (!cur)
        return false;
    for (size_t i = 0; i < p->nin; i++)
        cur[i] = (uint32_t)i;
    for (size_t c = 0; c < p->nconst; c++) {
        cur[p->nin + c] = new_reg(b, true);
        kreg[*nk] = cur[p->nin + c];
        kval[(*nk)++] = p->consts[c];
    }
    bool ok = true;
    for (size_t j = 0; j < p->ncode && ok; j++) {
        uint32_t r = translate(b, p, &p->code[j], cur);
        if (r == NONE) {
            qd_ctx_error(ctx, QD_ERR_ARG, "taylor: operation %u of a program has no Taylor "
                         "recurrence", (unsigned)p->code[j].op);
            ok = false;
        }
        cur[p->code[j].dst] = r;
    }
    for (size_t k = 0; ok && k < p->nout; k++) {
        tp->oflat[tp->nout] = b->flat[cur[p->out[k]]];
        tp->out[tp->nout++] = cur[p->out[k]];
    }
    qd__free(cur);
    return ok;
}

/* Registers and instructions a program can need after renaming: an n-ary
 * operation of m operands is m - 1 binary ones, a general power 3, a
 * function 2 registers. */
static void bounds(const qd_prog *p, size_t *nreg, size_t *nins, size_t *nopnd) {
    *nreg += p->nconst + 3 * p->ncode + 2 * p->ncode;
    *nins += 3 * p->ncode;
    size_t most = 3;
    for (size_t j = 0; j < p->ncode; j++) {
        const instr *in = &p->code[j];
        if (in->op != OP_SUMN && in->op != OP_PRODN)
            continue;
        size_t m = (size_t)p->opnd[in->arg[0]] + p->opnd[in->arg[0] + 1];
        *nreg += 2 * m;
        *nins += m;
        most = m > most ? m : most;
    }
    *nopnd = most > *nopnd ? most : *nopnd;
}

static size_t type_size(qd__tay_prec prec) {
#ifdef QD_HAVE_QUADMATH
    if (prec == QD__TAY_QUAD)
        return sizeof(qd__f128);
#endif
    return prec == QD__TAY_LONG ? sizeof(long double) : sizeof(double);
}

static void init_consts(qd__tay *tp, const double *kval, const uint32_t *kreg, size_t nk) {
    for (size_t i = 0; i < nk; i++) {
        size_t at = kreg[i] * tp->stride;
        if (tp->prec == QD__TAY_DOUBLE)
            ((double *)tp->work)[at] = kval[i];
        else if (tp->prec == QD__TAY_LONG)
            ((long double *)tp->work)[at] = kval[i];
#ifdef QD_HAVE_QUADMATH
        else
            ((qd__f128 *)tp->work)[at] = kval[i];
#endif
    }
}

static tcode to_code(const tins *in, uint32_t S) {
    tcode c = {in->op, in->d * S, in->u * S, in->w * S, in->a * S, in->b * S};
    if (in->op == T_MUL && (in->fa || in->fb)) {
        c.op = T_MULC;
        if (!in->fa) { /* the flat factor first */
            c.a = in->b * S;
            c.b = in->a * S;
        }
    } else if (in->op == T_DIV && in->fb) {
        c.op = T_DIVC;
    }
    return c;
}

static bool build(qd_ctx *ctx, qd__tay *tp, size_t nprog, const qd_prog *const *progs,
                  const bool *var) {
    size_t nreg = tp->nin + 2, nins = 1, nopnd = 3, nout = 0;
    if (tp->stride > 0xffffffffu / 64) {
        qd_ctx_error(ctx, QD_ERR_TOOBIG, "taylor: order %zu is too high", tp->maxorder);
        return false;
    }
    for (size_t i = 0; i < nprog; i++) {
        bounds(progs[i], &nreg, &nins, &nopnd);
        nout += progs[i]->nout;
    }
    bld b = {tp, qd__malloc(ctx, nreg), qd__malloc(ctx, nreg * sizeof *b.sc),
             qd__malloc(ctx, nreg * sizeof *b.sch), qd__malloc(ctx, nopnd * sizeof *b.tmp), 0};
    tp->ins = qd__malloc(ctx, nins * sizeof *tp->ins);
    tp->live = qd__malloc(ctx, nins * sizeof *tp->live);
    tp->out = qd__malloc(ctx, (nout + 1) * sizeof *tp->out);
    tp->oflat = qd__malloc(ctx, nout + 1);
    double *kval = qd__malloc(ctx, nreg * sizeof *kval);
    uint32_t *kreg = qd__malloc(ctx, nreg * sizeof *kreg);
    size_t nk = 0;
    bool ok = b.flat && b.sc && b.sch && b.tmp && tp->ins && tp->live && tp->out && tp->oflat && kval && kreg;
    for (size_t i = 0; ok && i < tp->nin; i++)
        new_reg(&b, var && !var[i]);
    if (ok)
        b.scratch = new_reg(&b, true);
    for (size_t i = 0; ok && i < nprog; i++)
        ok = rename_prog(ctx, &b, progs[i], kval, kreg, &nk);
    if (ok) {
        tp->work = qd__calloc(ctx, tp->nreg * tp->stride, type_size(tp->prec));
        ok = tp->work != NULL;
    }
    if (ok)
        init_consts(tp, kval, kreg, nk);
    if (ok)
        ok = (tp->code = qd__malloc(ctx, (tp->nins + 1) * sizeof *tp->code)) != NULL;
    for (size_t i = 0; ok && i < tp->nins; i++)
        tp->code[i] = to_code(&tp->ins[i], (uint32_t)tp->stride);
    qd__free(b.flat);
    qd__free(b.sc);
    qd__free(b.sch);
    qd__free(b.tmp);
    qd__free(kval);
    qd__free(kreg);
    return ok;
}

qd__tay *qd__tay_new(qd_ctx *ctx, size_t nprog, const qd_prog *const *progs, const bool *var,
                     size_t maxorder, qd__tay_prec prec) {
#ifndef QD_HAVE_QUADMATH
    if (prec == QD__TAY_QUAD) {
        qd_ctx_error(ctx, QD_ERR_UNSUPPORTED, "qd__f128 (libquadmath) is not available in "
                     "this build");
        return NULL;
    }
#endif
    for (size_t i = 1; i < nprog; i++)
        if (progs[i]->nin != progs[0]->nin) {
            qd_ctx_error(ctx, QD_ERR_ARG, "taylor: the programs do not share their inputs");
            return NULL;
        }
    qd__tay *tp = qd__calloc(ctx, 1, sizeof *tp);
    if (!tp)
        return NULL;
    tp->prec = prec;
    tp->nin = nprog ? progs[0]->nin : 0;
    tp->maxorder = maxorder;
    tp->stride = maxorder + 1;
    if (!build(ctx, tp, nprog, progs, var)) {
        qd__tay_free(tp);
        return NULL;
    }
    return tp;
}

void qd__tay_free(qd__tay *tp) {
    if (!tp)
        return;
    qd__free(tp->ins);
    qd__free(tp->code);
    qd__free(tp->live);
    qd__free(tp->out);
    qd__free(tp->oflat);
    qd__free(tp->work);
    qd__free(tp);
}

size_t qd__tay_nout(const qd__tay *tp) { return tp->nout; }
size_t qd__tay_ninstr(const qd__tay *tp) { return tp->nins; }
size_t qd__tay_maxorder(const qd__tay *tp) { return tp->maxorder; }
bool qd__tay_out_flat(const qd__tay *tp, size_t j) { return tp->oflat[j]; }

static void *reg_coef(qd__tay *tp, uint32_t r) {
    return (char *)tp->work + (size_t)r * tp->stride * type_size(tp->prec);
}

void *qd__tay_in(qd__tay *tp, size_t i) { return reg_coef(tp, (uint32_t)i); }
void *qd__tay_out(qd__tay *tp, size_t j) { return reg_coef(tp, tp->out[j]); }

/* ---- the recurrences, once per type ---------------------------------------- */

#define TAY_T double
#define TAY_S(name) name##_d
#define TAY_M(fn) fn
#define TAY_POWV(b, e) qd__pow_value(b, e)
#include "taylor_rec.h"
#undef TAY_T
#undef TAY_S
#undef TAY_M
#undef TAY_POWV

#define TAY_T long double
#define TAY_S(name) name##_l
#define TAY_M(fn) fn##l
#define TAY_POWV(b, e) powl(b, e)
#include "taylor_rec.h"
#undef TAY_T
#undef TAY_S
#undef TAY_M
#undef TAY_POWV

#ifdef QD_HAVE_QUADMATH
#define TAY_T qd__f128
#define TAY_S(name) name##_q
#define TAY_M(fn) fn##q
#define TAY_POWV(b, e) powq(b, e)
#include "taylor_rec.h"
#undef TAY_T
#undef TAY_S
#undef TAY_M
#undef TAY_POWV
#endif

void qd__tay_run(qd__tay *tp, size_t k) {
    switch (tp->prec) {
    case QD__TAY_DOUBLE:
        if (k && tp->native)
            tp->native(tp->work, tp->stride, k);
        else
            run_d(tp, k);
        break;
    case QD__TAY_LONG: run_l(tp, k); break;
    case QD__TAY_QUAD:
#ifdef QD_HAVE_QUADMATH
        run_q(tp, k);
#endif
        break;
    }
}

void qd__tay_set_native(qd__tay *tp, qd__tay_native fn) { tp->native = fn; }

/*
 * modules/llvm.c - qdot_llvm.so: machine code for a straight-line program
 * (src/sym/jit.h) by LLVM's ORC JIT, in the running process.  libqdot
 * opens it only from qd_prog_jit; this file calls nothing of libqdot's.
 *
 * Each register of the program becomes an SSA value as the instructions
 * are read in order (a register reused later is simply a new value), so
 * the code keeps its temporaries in machine registers and on the stack,
 * never in the interpreter's register file.  Arithmetic is LLVM's plain
 * fadd/fsub/fmul/fdiv/fneg without fast-math flags, sums and products in
 * the interpreter's order, sqrt and fabs as intrinsics (both exact), the
 * other functions calls to the same libm the interpreter calls, by
 * address: the result is the interpreter's bit for bit.
 */
#include <llvm-c/Core.h>
#include <llvm-c/Error.h>
#include <llvm-c/LLJIT.h>
#include <llvm-c/Orc.h>
#include <llvm-c/Target.h>
#include <llvm-c/TargetMachine.h>

#include <math.h>
#include <pthread.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sym/jit.h"
#include "sym/prog_int.h"

unsigned qd_ext_llvm_abi(void);
const qd__jit_ops *qd_ext_llvm_ops(void);

unsigned qd_ext_llvm_abi(void) { return QD__JIT_ABI; }

static pthread_once_t once = PTHREAD_ONCE_INIT;
static int ready; /* the native target initialized */

static void init(void) {
    ready = !LLVMInitializeNativeTarget() && !LLVMInitializeNativeAsmPrinter();
}

typedef struct build {
    LLVMContextRef c;
    LLVMBuilderRef b;
    LLVMModuleRef m;
    LLVMTypeRef d, fn1, fn2, ptr1, ptr2; /* double; double(double), double(double, double) */
    LLVMValueRef *v;                     /* the current value of each register */
    LLVMValueRef sqrt, fabs;             /* intrinsics */
} build;

static LLVMValueRef address(build *s, LLVMTypeRef ptr, void (*f)(void)) {
    LLVMTypeRef i64 = LLVMInt64TypeInContext(s->c);
    return LLVMConstIntToPtr(LLVMConstInt(i64, (uint64_t)(uintptr_t)f, 0), ptr);
}

/* ISO C has no cast between function and object pointers: the address of
 * a libm function as the generic function pointer address() takes. */
typedef double (*f1)(double);
typedef double (*f2)(double, double);
#define ADDR1(s, f) address(s, (s)->ptr1, (void (*)(void))(f1)(f))
#define ADDR2(s, f) address(s, (s)->ptr2, (void (*)(void))(f2)(f))

static LLVMValueRef call1(build *s, LLVMValueRef fn, LLVMValueRef x) {
    return LLVMBuildCall2(s->b, s->fn1, fn, &x, 1, "");
}

static LLVMValueRef call2(build *s, LLVMValueRef fn, LLVMValueRef x, LLVMValueRef y) {
    LLVMValueRef a[2] = {x, y};
    return LLVMBuildCall2(s->b, s->fn2, fn, a, 2, "");
}

static LLVMValueRef intrinsic(build *s, const char *name) {
    LLVMValueRef f = LLVMAddFunction(s->m, name, s->fn1);
    return f;
}

static void store(build *s, LLVMValueRef base, size_t k, LLVMValueRef v) {
    LLVMValueRef idx = LLVMConstInt(LLVMInt64TypeInContext(s->c), k, 0);
    LLVMBuildStore(s->b, v, LLVMBuildInBoundsGEP2(s->b, s->d, base, &idx, 1, ""));
}

/* SUMN and PRODN as prog.c's sumn and prodn compute them. */
static LLVMValueRef sumn(build *s, const uint32_t *a) {
    size_t np = a[0], n = np + a[1], k = 1;
    a += 2;
    LLVMValueRef x = np ? s->v[a[0]] : LLVMBuildFNeg(s->b, s->v[a[0]], "");
    for (; k < np; k++)
        x = LLVMBuildFAdd(s->b, x, s->v[a[k]], "");
    for (; k < n; k++)
        x = LLVMBuildFSub(s->b, x, s->v[a[k]], "");
    return x;
}

static LLVMValueRef prodn(build *s, const uint32_t *a) {
    size_t np = a[0], n = np + a[1], k = 1;
    a += 2;
    LLVMValueRef m = np ? s->v[a[0]] : LLVMConstReal(s->d, 1.0);
    for (; k < np; k++)
        m = LLVMBuildFMul(s->b, m, s->v[a[k]], "");
    if (np == n)
        return m;
    LLVMValueRef q = s->v[a[np]];
    for (k = np + 1; k < n; k++)
        q = LLVMBuildFMul(s->b, q, s->v[a[k]], "");
    return LLVMBuildFDiv(s->b, m, q, "");
}

static LLVMValueRef instruction(build *s, const qd_prog *p, const instr *i,
                                const qd__jit_env *env) {
    LLVMBuilderRef b = s->b;
    /* ADD3, MUL3, SUMN and PRODN find their registers in the operand
     * list at arg[0]; the others read the registers arg[0] and arg[1] */
    bool nary = i->op == OP_ADD3 || i->op == OP_MUL3 || i->op == OP_SUMN || i->op == OP_PRODN;
    const uint32_t *a = nary ? p->opnd + i->arg[0] : NULL;
    LLVMValueRef x = nary ? NULL : s->v[i->arg[0]], y = nary ? NULL : s->v[i->arg[1]];
    LLVMValueRef zero = LLVMConstReal(s->d, 0.0);
    switch ((op)i->op) {
    case OP_ADD: return LLVMBuildFAdd(b, x, y, "");
    case OP_SUB: return LLVMBuildFSub(b, x, y, "");
    case OP_MUL: return LLVMBuildFMul(b, x, y, "");
    case OP_DIV: return LLVMBuildFDiv(b, x, y, "");
    case OP_NEG: return LLVMBuildFNeg(b, x, "");
    case OP_RECIP: return LLVMBuildFDiv(b, LLVMConstReal(s->d, 1.0), x, "");
    case OP_SQRT: return call1(s, s->sqrt, x);
    case OP_POW: return call2(s, ADDR2(s, env->pow), x, y);
    case OP_ADD3:
        return LLVMBuildFAdd(b, LLVMBuildFAdd(b, s->v[a[0]], s->v[a[1]], ""), s->v[a[2]], "");
    case OP_MUL3:
        return LLVMBuildFMul(b, LLVMBuildFMul(b, s->v[a[0]], s->v[a[1]], ""), s->v[a[2]], "");
    case OP_SUMN: return sumn(s, a);
    case OP_PRODN: return prodn(s, a);
    case OP_SIN: return call1(s, ADDR1(s, sin), x);
    case OP_COS: return call1(s, ADDR1(s, cos), x);
    case OP_TAN: return call1(s, ADDR1(s, tan), x);
    case OP_ASIN: return call1(s, ADDR1(s, asin), x);
    case OP_ACOS: return call1(s, ADDR1(s, acos), x);
    case OP_ATAN: return call1(s, ADDR1(s, atan), x);
    case OP_ATAN2: return call2(s, ADDR2(s, atan2), x, y);
    case OP_SINH: return call1(s, ADDR1(s, sinh), x);
    case OP_COSH: return call1(s, ADDR1(s, cosh), x);
    case OP_TANH: return call1(s, ADDR1(s, tanh), x);
    case OP_EXP: return call1(s, ADDR1(s, exp), x);
    case OP_LOG: return call1(s, ADDR1(s, log), x);
    case OP_ABS: return call1(s, s->fabs, x);
    case OP_SIGN: { /* (x > 0) - (x < 0): 0 for 0 and NaN */
        LLVMValueRef gt = LLVMBuildUIToFP(b, LLVMBuildFCmp(b, LLVMRealOGT, x, zero, ""), s->d, "");
        LLVMValueRef lt = LLVMBuildUIToFP(b, LLVMBuildFCmp(b, LLVMRealOLT, x, zero, ""), s->d, "");
        return LLVMBuildFSub(b, gt, lt, "");
    }
    case OP_STEP: return call1(s, ADDR1(s, env->step), x);
    }
    return NULL;
}

/* The program's instructions into the current block of f: its inputs
 * loaded from in, each register an SSA value, the outputs stored to out. */
static void body(build *s, const qd_prog *p, const qd__jit_env *env, LLVMValueRef in,
                 LLVMValueRef out) {
    LLVMTypeRef i64 = LLVMInt64TypeInContext(s->c);
    for (size_t k = 0; k < p->nin; k++) {
        LLVMValueRef idx = LLVMConstInt(i64, k, 0);
        LLVMValueRef at = LLVMBuildInBoundsGEP2(s->b, s->d, in, &idx, 1, "");
        s->v[k] = LLVMBuildLoad2(s->b, s->d, at, "");
    }
    for (size_t k = 0; k < p->nconst; k++)
        s->v[p->nin + k] = LLVMConstReal(s->d, p->consts[k]);
    for (size_t k = 0; k < p->ncode; k++)
        s->v[p->code[k].dst] = instruction(s, p, &p->code[k], env);
    for (size_t k = 0; k < p->nout; k++)
        store(s, out, k, s->v[p->out[k]]);
}

/* void qd_jit(const double *in, double *out) */
static void function(build *s, const qd_prog *p, const qd__jit_env *env) {
    LLVMTypeRef dp = LLVMPointerType(s->d, 0), args[2] = {dp, dp};
    LLVMTypeRef ft = LLVMFunctionType(LLVMVoidTypeInContext(s->c), args, 2, 0);
    LLVMValueRef f = LLVMAddFunction(s->m, "qd_jit", ft);
    LLVMPositionBuilderAtEnd(s->b, LLVMAppendBasicBlockInContext(s->c, f, "entry"));
    body(s, p, env, LLVMGetParam(f, 0), LLVMGetParam(f, 1));
    LLVMBuildRetVoid(s->b);
}

/* int qd_jit(const double *in, double *out, double *x): the program, then
 * src/num/cholesky.c's qd__num_solve_spd on its outputs M and f unrolled,
 * the same operations in the same order (a - b*c as a separate multiply
 * and subtract, never fused), so that x is that function's bit for bit.
 * Its tests become one flag with no branch: a failed factor only makes
 * NaNs in x, which the caller then ignores for its own solve. */
static void spd_function(build *s, const qd_prog *p, size_t n, double tol,
                         const qd__jit_env *env) {
    LLVMTypeRef dp = LLVMPointerType(s->d, 0), args[3] = {dp, dp, dp};
    LLVMTypeRef i32 = LLVMInt32TypeInContext(s->c);
    LLVMValueRef f = LLVMAddFunction(s->m, "qd_jit", LLVMFunctionType(i32, args, 3, 0));
    LLVMBuilderRef b = s->b;
    LLVMPositionBuilderAtEnd(b, LLVMAppendBasicBlockInContext(s->c, f, "entry"));
    body(s, p, env, LLVMGetParam(f, 0), LLVMGetParam(f, 1));
    LLVMValueRef *A = s->v + p->nreg; /* M, then f: room past the registers */
    for (size_t k = 0; k < n * n + n; k++)
        A[k] = s->v[p->out[k]];
    LLVMValueRef *r = A + n * n, zero = LLVMConstReal(s->d, 0.0);
    LLVMValueRef inf = LLVMConstReal(s->d, HUGE_VAL), one = LLVMConstReal(s->d, 1.0);
    /* solve_mass's all_finite(M): |m| ordered and not inf */
    LLVMValueRef ok = LLVMConstInt(LLVMInt1TypeInContext(s->c), 1, 0);
    for (size_t k = 0; k < n * n; k++)
        ok = LLVMBuildAnd(b, ok, LLVMBuildFCmp(b, LLVMRealONE, call1(s, s->fabs, A[k]), inf, ""),
                          "");
    LLVMValueRef big = zero; /* big = A > big ? A : big, finite with M */
    for (size_t j = 0; j < n; j++) {
        LLVMValueRef a = A[j * n + j];
        big = LLVMBuildSelect(b, LLVMBuildFCmp(b, LLVMRealOGT, a, big, ""), a, big, "");
    }
    ok = LLVMBuildAnd(b, ok, LLVMBuildFCmp(b, LLVMRealOGT, big, zero, ""), "");
    LLVMValueRef tb = LLVMBuildFMul(b, LLVMConstReal(s->d, tol), big, "");
    for (size_t j = 0; j < n; j++) {
        LLVMValueRef d = A[j * n + j];
        for (size_t k = 0; k < j; k++)
            d = LLVMBuildFSub(b, d, LLVMBuildFMul(b, A[j * n + k], A[j * n + k], ""), "");
        ok = LLVMBuildAnd(b, ok, LLVMBuildFCmp(b, LLVMRealOGT, d, tb, ""), "");
        LLVMValueRef l = call1(s, s->sqrt, d), inv = LLVMBuildFDiv(b, one, l, "");
        A[j * n + j] = l;
        for (size_t i = j + 1; i < n; i++) {
            LLVMValueRef t = A[i * n + j];
            for (size_t k = 0; k < j; k++)
                t = LLVMBuildFSub(b, t, LLVMBuildFMul(b, A[i * n + k], A[j * n + k], ""), "");
            A[i * n + j] = LLVMBuildFMul(b, t, inv, "");
        }
    }
    for (size_t i = 0; i < n; i++) { /* L y = f */
        LLVMValueRef t = r[i];
        for (size_t k = 0; k < i; k++)
            t = LLVMBuildFSub(b, t, LLVMBuildFMul(b, A[i * n + k], r[k], ""), "");
        r[i] = LLVMBuildFDiv(b, t, A[i * n + i], "");
    }
    for (size_t i = n; i-- > 0;) { /* L^T x = y */
        LLVMValueRef t = r[i];
        for (size_t k = i + 1; k < n; k++)
            t = LLVMBuildFSub(b, t, LLVMBuildFMul(b, A[k * n + i], r[k], ""), "");
        r[i] = LLVMBuildFDiv(b, t, A[i * n + i], "");
    }
    for (size_t i = 0; i < n; i++)
        store(s, LLVMGetParam(f, 2), i, r[i]);
    LLVMBuildRet(b, LLVMBuildZExt(b, ok, i32, ""));
}

static void say(char *err, size_t cap, const char *what, LLVMErrorRef e) {
    char *m = e ? LLVMGetErrorMessage(e) : NULL;
    snprintf(err, cap, "%s%s%s", what, m ? ": " : "", m ? m : "");
    if (m)
        LLVMDisposeErrorMessage(m);
}

/* The JIT for the host, codegen at level "none": fast instruction
 * selection and the fast register allocator, both linear in the program.
 * The greedy allocator of the higher levels spends seconds on the one
 * long block of a 20-link pendulum (0.1 s here against 0.7 s at "less")
 * for run times within the noise, since libm and the linear solve take
 * most of an evaluation (docs/design.md "The JIT"). */
static LLVMOrcLLJITRef make_jit(char *err, size_t cap) {
    char *triple = LLVMGetDefaultTargetTriple(), *cpu = LLVMGetHostCPUName(),
         *features = LLVMGetHostCPUFeatures(), *msg = NULL;
    LLVMTargetRef target = NULL;
    LLVMOrcLLJITRef j = NULL;
    if (LLVMGetTargetFromTriple(triple, &target, &msg)) {
        snprintf(err, cap, "no LLVM target for %s: %s", triple, msg ? msg : "");
    } else {
        LLVMTargetMachineRef tm = LLVMCreateTargetMachine(target, triple, cpu, features,
                                                          LLVMCodeGenLevelNone, LLVMRelocDefault,
                                                          LLVMCodeModelJITDefault);
        LLVMOrcLLJITBuilderRef jb = LLVMOrcCreateLLJITBuilder();
        LLVMOrcLLJITBuilderSetJITTargetMachineBuilder(
            jb, LLVMOrcJITTargetMachineBuilderCreateFromTargetMachine(tm));
        LLVMErrorRef e = LLVMOrcCreateLLJIT(&j, jb);
        if (e) {
            say(err, cap, "LLVM's JIT did not start", e);
            j = NULL;
        }
    }
    LLVMDisposeMessage(msg);
    LLVMDisposeMessage(triple);
    LLVMDisposeMessage(cpu);
    LLVMDisposeMessage(features);
    return j;
}

/* Machine code for p: spd_n 0 the plain function, else the fused one of
 * spd_function; its address in *addr. */
static void *emit(const qd_prog *p, size_t spd_n, double tol, const qd__jit_env *env,
                  uintptr_t *addr, char *err, size_t cap) {
    pthread_once(&once, init);
    if (!ready) {
        snprintf(err, cap, "LLVM has no native target here");
        return NULL;
    }
    if (spd_n && p->nout < spd_n * spd_n + spd_n) {
        snprintf(err, cap, "the program has no %zu-by-%zu system to solve", spd_n, spd_n);
        return NULL;
    }
    LLVMOrcLLJITRef j = make_jit(err, cap);
    if (!j)
        return NULL;
    LLVMOrcThreadSafeContextRef tsc = LLVMOrcCreateNewThreadSafeContext();
    build s = {.c = LLVMOrcThreadSafeContextGetContext(tsc)};
    /* the fused function keeps M and f past the registers */
    size_t nv = p->nreg + (spd_n ? spd_n * spd_n + spd_n : 0);
    s.v = calloc(nv ? nv : 1, sizeof *s.v);
    if (!s.v) {
        snprintf(err, cap, "out of memory");
        LLVMOrcDisposeThreadSafeContext(tsc);
        LLVMOrcDisposeLLJIT(j);
        return NULL;
    }
    s.m = LLVMModuleCreateWithNameInContext("qdot", s.c);
    s.b = LLVMCreateBuilderInContext(s.c);
    s.d = LLVMDoubleTypeInContext(s.c);
    LLVMTypeRef two[2] = {s.d, s.d};
    s.fn1 = LLVMFunctionType(s.d, two, 1, 0);
    s.fn2 = LLVMFunctionType(s.d, two, 2, 0);
    s.ptr1 = LLVMPointerType(s.fn1, 0);
    s.ptr2 = LLVMPointerType(s.fn2, 0);
    s.sqrt = intrinsic(&s, "llvm.sqrt.f64");
    s.fabs = intrinsic(&s, "llvm.fabs.f64");
    if (spd_n)
        spd_function(&s, p, spd_n, tol, env);
    else
        function(&s, p, env);
    LLVMDisposeBuilder(s.b);
    free(s.v);
    LLVMOrcThreadSafeModuleRef tsm = LLVMOrcCreateNewThreadSafeModule(s.m, tsc);
    LLVMOrcDisposeThreadSafeContext(tsc); /* the module holds it now */
    LLVMErrorRef e = LLVMOrcLLJITAddLLVMIRModule(j, LLVMOrcLLJITGetMainJITDylib(j), tsm);
    LLVMOrcExecutorAddress a = 0;
    if (!e)
        e = LLVMOrcLLJITLookup(j, &a, "qd_jit");
    if (e || !a) {
        say(err, cap, "LLVM did not compile the program", e);
        LLVMOrcDisposeLLJIT(j);
        return NULL;
    }
    *addr = (uintptr_t)a;
    return j;
}

static void *compile(const qd_prog *p, const qd__jit_env *env, qd__jit_fn *fn, char *err,
                     size_t cap) {
    uintptr_t a = 0;
    void *j = emit(p, 0, 0, env, &a, err, cap);
    if (j)
        memcpy(fn, &a, sizeof *fn);
    return j;
}

static void *compile_spd(const qd_prog *p, size_t n, double tol, const qd__jit_env *env,
                         qd__jit_spd_fn *fn, char *err, size_t cap) {
    uintptr_t a = 0;
    void *j = emit(p, n, tol, env, &a, err, cap);
    if (j)
        memcpy(fn, &a, sizeof *fn);
    return j;
}

static void release(void *code) {
    if (code)
        LLVMOrcDisposeLLJIT(code);
}

static const qd__jit_ops ops = {compile, release, compile_spd};

const qd__jit_ops *qd_ext_llvm_ops(void) { return &ops; }

/*
 * src/sym/evaltree.c - direct numeric evaluation by one walk of the DAG.
 * The slow, simple path: tests and one-off values use it; anything repeated
 * compiles a qd_prog (prog.c).
 */
#include "node.h"
#include "../base/args.h"

#include <math.h>
#include <stdlib.h>

double qd__func_value(qd_func f, double a, double b) {
    switch (f) {
    case QD_SIN: return sin(a);
    case QD_COS: return cos(a);
    case QD_TAN: return tan(a);
    case QD_ASIN: return asin(a);
    case QD_ACOS: return acos(a);
    case QD_ATAN: return atan(a);
    case QD_ATAN2: return atan2(a, b);
    case QD_SINH: return sinh(a);
    case QD_COSH: return cosh(a);
    case QD_TANH: return tanh(a);
    case QD_EXP: return exp(a);
    case QD_LOG: return log(a);
    case QD_ABS: return fabs(a);
    case QD_SIGN: return (a > 0) - (a < 0);
    case QD_STEP: return qd__step_value(a);
    default: return NAN;
    }
}

/* Integer powers by multiplication: faster and exact where pow() may not be. */
/* Heaviside's step with SymPy's value 1/2 at 0; NaN stays NaN. */
double qd__step_value(double x) { return x > 0 ? 1.0 : x < 0 ? 0.0 : x == 0 ? 0.5 : x; }

double qd__pow_value(double b, double e) {
    if (fabs(e) <= 64 && e == (double)(long)e) { /* the range first: (long)e is undefined beyond it */
        long n = (long)e;
        unsigned long k = (unsigned long)(n < 0 ? -n : n);
        double r = 1, x = b;
        for (; k; k >>= 1, x *= x)
            if (k & 1)
                r *= x;
        return n < 0 ? 1 / r : r;
    }
    if (e == 0.5)
        return sqrt(b);
    if (e == -0.5)
        return 1 / sqrt(b);
    return pow(b, e);
}

typedef struct walk {
    qd_ctx *ctx;
    qd__ptrmap vals; /* node -> index into store */
    double *store;
    size_t n, cap;
    qd_status st;
} walk;

static double value(walk *w, const qd_expr *e);

static double remember(walk *w, const qd_expr *e, double v) {
    if (w->n == w->cap) {
        size_t cap = w->cap ? 2 * w->cap : 256;
        double *s = qd__realloc(w->ctx, w->store, cap * sizeof *s);
        if (!s) {
            w->st = QD_ERR_NOMEM;
            return v;
        }
        w->store = s;
        w->cap = cap;
    }
    w->store[w->n] = v;
    if (!qd__ptrmap_put(&w->vals, e, (void *)(uintptr_t)(w->n + 1)))
        w->st = QD_ERR_NOMEM;
    w->n++;
    return v;
}

static double value(walk *w, const qd_expr *e) {
    uintptr_t k = (uintptr_t)qd__ptrmap_get(&w->vals, e);
    if (k)
        return w->store[k - 1];
    double v = 0;
    switch ((qd_kind)e->kind) {
    case QD_RATIONAL:
    case QD_FLOAT:
        if (w->st == QD_OK && !qd__number_finite(w->ctx, e))
            w->st = QD_ERR_NUMERIC;
        return qd_number_value(e);
    case QD_CONSTANT:
        return e->tag == QD_PI ? 3.14159265358979323846 : 2.71828182845904523536;
    case QD_SYMBOL:
        if (w->st == QD_OK) { /* after running out of memory, a binding may be missing */
            qd_ctx_error(w->ctx, QD_ERR_UNBOUND, "'%s' has no value", e->u.sym.name);
            w->st = QD_ERR_UNBOUND;
        }
        return NAN;
    case QD_ADD:
        for (size_t i = 0; i < e->nargs; i++)
            v += value(w, e->args[i]);
        break;
    case QD_MUL:
        v = 1;
        for (size_t i = 0; i < e->nargs; i++)
            v *= value(w, e->args[i]);
        break;
    case QD_POW:
        v = qd__pow_value(value(w, e->args[0]), value(w, e->args[1]));
        break;
    case QD_FUNC:
        v = qd__func_value((qd_func)e->tag, value(w, e->args[0]),
                           e->nargs > 1 ? value(w, e->args[1]) : 0);
        break;
    case QD_UFUNC:
    case QD_UDERIV:
        if (w->st == QD_OK) {
            qd_ctx_error(w->ctx, QD_ERR_ARG, "the function '%s' has no numeric definition",
                         e->u.fn.name);
            w->st = QD_ERR_ARG;
        }
        return NAN;
    }
    return remember(w, e, v);
}

qd_status qd_eval(qd_ctx *ctx, const qd_expr *e, size_t n, const qd_expr *const *syms,
                  const double *vals, double *out) {
    QD_ARGS_CTX(ctx, ctx && e && out);
    if (!e)
        return ctx->status != QD_OK ? ctx->status : QD_ERR_ARG;
    walk w = {ctx, QD_PTRMAP_AL(qd__ctx_allocator(ctx)), NULL, 0, 0, QD_OK};
    for (size_t i = 0; i < n; i++)
        remember(&w, syms[i], vals[i]);
    *out = value(&w, e);
    qd__ptrmap_free(&w.vals);
    qd__free(w.store);
    if (w.st == QD_ERR_NOMEM)
        qd__oom(ctx);
    return w.st;
}

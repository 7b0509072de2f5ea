/*
 * src/sym/print_sympy.c - expressions as Python for SymPy.
 *
 * The caller runs the text after a preamble that binds, for every name
 * printed bare:
 *   t = Symbol('t'); each plain symbol and parameter x = Symbol('x');
 *   each coordinate q = Function('q'); each user function V = Function('V');
 *   and from sympy import * (sin ... tanh, exp, log, Abs, sign, Heaviside, atan2, sqrt,
 *   pi, E, Rational, Integer, Float, Symbol, Function, Derivative, Subs).
 * Coordinates print as q(t), their jet symbols as q(t).diff(t) and
 * q(t).diff(t, 2).  A derivative of a user function prints the way SymPy
 * writes one itself, Subs(Derivative(V(_u0), _u0), (_u0,), (r,)), with the
 * dummies spelled Symbol('_u0') so no preamble is needed for them.
 *
 * Names: a name that is a Python keyword or one this printer emits (E, pi,
 * sin, Rational, ...) cannot be bound by the preamble, so it is printed
 * self-contained as Symbol('name') or Function('name').  Every other name
 * prints bare; shadowing a SymPy name the printer never emits (beta, gamma,
 * S, N, I, ...) is harmless.
 *
 * qd_print_sympy_functions writes the preamble's user-function lines for a
 * set of expressions, so a script that prints them runs as it is.
 *
 * Numbers: integers bare except as the base of a power (Integer(2)**x, so
 * that Python never divides or powers two ints), other rationals as
 * Rational(p, q), floats as Float(<shortest round-trip literal>).
 */
#include "prec.h"
#include "base/mem.h"
#include "../base/args.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static const char *const reserved[] = {
    "False", "None", "True", "and", "as", "assert", "async", "await", "break", "class",
    "continue", "def", "del", "elif", "else", "except", "finally", "for", "from", "global",
    "if", "import", "in", "is", "lambda", "nonlocal", "not", "or", "pass", "raise", "return",
    "try", "while", "with", "yield", "sin", "cos", "tan", "asin", "acos", "atan", "atan2",
    "sinh", "cosh", "tanh", "exp", "log", "Abs", "sign", "Heaviside", "sqrt", "pi", "E", "Rational",
    "Integer", "Float", "Symbol", "Function", "Derivative", "Subs", "t"};

typedef struct sp {
    qd_ctx *ctx;
    qd_buf *b;
} sp;

static void expr(sp *p, const qd_expr *e);

static bool is_reserved(const char *name) {
    for (size_t i = 0; i < sizeof reserved / sizeof reserved[0]; i++)
        if (!strcmp(name, reserved[i]))
            return true;
    return false;
}

static void name(sp *p, const char *n, const char *kind) {
    if (is_reserved(n))
        qd_buf_printf(p->b, "%s('%s')", kind, n);
    else
        qd_buf_puts(p->b, n);
}

static void operand(sp *p, const qd_expr *e, int need) {
    bool paren = qd__prec(e) < need;
    qd_buf_puts(p->b, paren ? "(" : "");
    expr(p, e);
    qd_buf_puts(p->b, paren ? ")" : "");
}

static void magnitude_number(sp *p, const qd_expr *e, bool wrap_int) {
    if (e->kind == QD_FLOAT) {
        qd_buf_puts(p->b, "Float(");
        qd__put_double(p->b, fabs(e->u.f));
        qd_buf_puts(p->b, ")");
    } else if (mpz_cmp_ui(mpq_denref(e->u.q), 1) != 0) {
        qd_buf_puts(p->b, "Rational(");
        qd__put_mpz(p->b, mpq_numref(e->u.q));
        qd_buf_puts(p->b, ", ");
        qd__put_mpz(p->b, mpq_denref(e->u.q));
        qd_buf_puts(p->b, ")");
    } else {
        qd_buf_puts(p->b, wrap_int ? "Integer(" : "");
        qd__put_mpz(p->b, mpq_numref(e->u.q));
        qd_buf_puts(p->b, wrap_int ? ")" : "");
    }
}

static void number(sp *p, const qd_expr *e, bool wrap_int) {
    bool neg = qd_number_sign(e) < 0;
    qd_buf_puts(p->b, neg ? "(-" : "");
    magnitude_number(p, e, wrap_int);
    qd_buf_puts(p->b, neg ? ")" : "");
}

static void base(sp *p, const qd_expr *b) {
    if (qd__is_num(b))
        number(p, b, true);
    else
        operand(p, b, QD_PREC_ATOM);
}

static void flipped(sp *p, const qd_expr *f) {
    const qd_expr *b = f->args[0], *e = f->args[1];
    if (qd__is_rat(e, -1, 1)) {
        operand(p, b, QD_PREC_POW);
    } else if (qd__is_rat(e, -1, 2)) {
        qd_buf_puts(p->b, "sqrt(");
        expr(p, b);
        qd_buf_puts(p->b, ")");
    } else {
        base(p, b);
        qd_buf_puts(p->b, "**(");
        magnitude_number(p, e, false);
        qd_buf_puts(p->b, ")");
    }
}

static void product(sp *p, const qd_expr *e, bool sign) {
    qd__product_split s;
    if (!qd__split(p->ctx, e, &s)) {
        p->b->failed = true;
        return;
    }
    qd_buf_puts(p->b, s.neg && sign ? "-" : "");
    bool any = false;
    if (s.coeff) {
        magnitude_number(p, s.coeff, false);
        any = true;
    }
    for (size_t i = 0; i < s.nnum; i++) {
        qd_buf_puts(p->b, any ? "*" : "");
        operand(p, s.num[i], QD_PREC_POW);
        any = true;
    }
    qd_buf_puts(p->b, any ? "" : "1");
    if (s.nden)
        qd_buf_puts(p->b, s.nden > 1 ? "/(" : "/");
    for (size_t i = 0; i < s.nden; i++) {
        qd_buf_puts(p->b, i ? "*" : "");
        flipped(p, s.den[i]);
    }
    qd_buf_puts(p->b, s.nden > 1 ? ")" : "");
    qd__split_free(&s);
}

static void sum(sp *p, const qd_expr *e) {
    for (size_t i = 0; i < e->nargs; i++) {
        const qd_expr *t = e->args[i];
        bool minus = qd__has_minus(t);
        qd_buf_puts(p->b, i ? (minus ? " - " : " + ") : (minus ? "-" : ""));
        if (qd__is_num(t))
            magnitude_number(p, t, false);
        else if (t->kind == QD_MUL)
            product(p, t, false);
        else
            expr(p, t);
    }
}

static void args(sp *p, const qd_expr *e) {
    qd_buf_puts(p->b, "(");
    for (size_t i = 0; i < e->nargs; i++) {
        qd_buf_puts(p->b, i ? ", " : "");
        expr(p, e->args[i]);
    }
    qd_buf_puts(p->b, ")");
}

/* t, or the name set for it (qd_print_set_time_name), which the caller
 * binds in place of t. */
static void symbol(sp *p, const qd_expr *e) {
    const char *t = qd_print_time_name(p->ctx);
    if (e->tag == QD_ROLE_TIME) {
        qd_buf_puts(p->b, t);
    } else if (e->tag != QD_ROLE_COORD) {
        name(p, e->u.sym.name, "Symbol");
    } else {
        name(p, e->u.sym.coord->u.sym.name, "Function");
        qd_buf_printf(p->b, "(%s)", t);
        if (e->order == 1)
            qd_buf_printf(p->b, ".diff(%s)", t);
        else if (e->order > 1)
            qd_buf_printf(p->b, ".diff(%s, %u)", t, (unsigned)e->order);
    }
}

static void dummies(sp *p, size_t n, const unsigned *idx) {
    for (size_t i = 0; i < n; i++)
        qd_buf_printf(p->b, "%sSymbol('_u%u')", i ? ", " : "", idx ? idx[i] : (unsigned)i);
}

static void uderiv(sp *p, const qd_expr *e) {
    qd_buf_puts(p->b, "Subs(Derivative(");
    name(p, e->u.fn.name, "Function");
    qd_buf_puts(p->b, "(");
    dummies(p, e->nargs, NULL);
    qd_buf_puts(p->b, "), ");
    dummies(p, e->u.fn.nslots, e->u.fn.slots);
    qd_buf_puts(p->b, "), (");
    dummies(p, e->nargs, NULL);
    qd_buf_puts(p->b, e->nargs == 1 ? ",), (" : "), (");
    for (size_t i = 0; i < e->nargs; i++) {
        qd_buf_puts(p->b, i ? ", " : "");
        expr(p, e->args[i]);
    }
    qd_buf_puts(p->b, e->nargs == 1 ? ",))" : "))");
}

static void power(sp *p, const qd_expr *e) {
    if (qd__is_recip(e)) {
        product(p, e, true);
    } else if (qd__is_rat(e->args[1], 1, 2)) {
        qd_buf_puts(p->b, "sqrt(");
        expr(p, e->args[0]);
        qd_buf_puts(p->b, ")");
    } else {
        base(p, e->args[0]);
        qd_buf_puts(p->b, "**");
        if (qd__is_num(e->args[1]) && qd__prec(e->args[1]) == QD_PREC_ATOM)
            magnitude_number(p, e->args[1], false);
        else
            operand(p, e->args[1], QD_PREC_ATOM);
    }
}

static void expr(sp *p, const qd_expr *e) {
    static const char *const fn[QD_FUNC_COUNT] = {
        "sin", "cos", "tan", "asin", "acos", "atan", "atan2",
        "sinh", "cosh", "tanh", "exp", "log", "Abs", "sign", "Heaviside"};
    switch ((qd_kind)e->kind) {
    case QD_RATIONAL:
    case QD_FLOAT: number(p, e, false); break;
    case QD_CONSTANT: qd_buf_puts(p->b, e->tag == QD_PI ? "pi" : "E"); break;
    case QD_SYMBOL: symbol(p, e); break;
    case QD_FUNC:
        qd_buf_puts(p->b, fn[e->tag]);
        args(p, e);
        break;
    case QD_UFUNC:
        name(p, e->u.fn.name, "Function");
        args(p, e);
        break;
    case QD_UDERIV: uderiv(p, e); break;
    case QD_POW: power(p, e); break;
    case QD_MUL: product(p, e, true); break;
    case QD_ADD: sum(p, e); break;
    }
}

qd_status qd__print_sympy(qd_ctx *ctx, const qd_expr *e, qd_buf *out) {
    sp p = {ctx, out};
    expr(&p, e);
    return out->failed ? QD_ERR_NOMEM : QD_OK;
}

/* ---- the user functions a script must define ------------------------------ */

typedef struct fn_names {
    qd__ptrmap seen;     /* nodes visited */
    qd__ptrmap named;    /* interned names listed */
    const char **list;
    size_t n, cap;
    bool oom;
    qd_ctx *ctx;
} fn_names;

static void add_name(fn_names *c, const char *n) {
    if (is_reserved(n) || qd__ptrmap_has(&c->named, n))
        return;
    if (c->n == c->cap) {
        size_t cap = c->cap ? 2 * c->cap : 8;
        const char **l = qd__realloc(c->ctx, c->list, cap * sizeof *l);
        if (!l) {
            c->oom = true;
            return;
        }
        c->list = l;
        c->cap = cap;
    }
    c->list[c->n++] = n;
    c->oom |= !qd__ptrmap_put(&c->named, n, (void *)n);
}

static void collect_names(fn_names *c, const qd_expr *e) {
    if (!e || !e->nargs || c->oom || qd__ptrmap_has(&c->seen, e))
        return;
    if (e->kind == QD_UFUNC || e->kind == QD_UDERIV)
        add_name(c, e->u.fn.name);
    for (size_t i = 0; i < e->nargs; i++)
        collect_names(c, e->args[i]);
    c->oom |= !qd__ptrmap_put(&c->seen, e, (void *)e);
}

static int name_order(const void *a, const void *b) {
    return qd__name_cmp(*(const char *const *)a, *(const char *const *)b);
}

qd_status qd_print_sympy_functions(qd_ctx *ctx, size_t n, const qd_expr *const *exprs,
                                   qd_buf *out) {
    QD_ARGS_CTX(ctx, ctx && (n == 0 || exprs) && out);
    if (!ctx || !out || (n && !exprs))
        return QD_ERR_ARG;
    fn_names c = {QD_PTRMAP_AL(qd__ctx_allocator(ctx)), QD_PTRMAP_AL(qd__ctx_allocator(ctx)), NULL, 0, 0, false, ctx};
    for (size_t i = 0; i < n; i++)
        collect_names(&c, exprs[i]);
    if (!c.oom && c.n) {
        qsort(c.list, c.n, sizeof *c.list, name_order);
        for (size_t i = 0; i < c.n; i++)
            qd_buf_printf(out, "%s = Function('%s')\n", c.list[i], c.list[i]);
    }
    qd__ptrmap_free(&c.seen);
    qd__ptrmap_free(&c.named);
    qd__free(c.list);
    if (c.oom || out->failed) {
        qd__oom(ctx);
        return QD_ERR_NOMEM;
    }
    return QD_OK;
}

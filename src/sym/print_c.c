/*
 * src/sym/print_c.c - expressions as C99 over doubles (math.h).
 *
 * Spelling:
 *   - numbers as doubles: 3.0, 3.0/4.0 (a rational whose parts exceed 2^53
 *     prints as its double value), floats as the shortest %.Ng that reads
 *     back exactly; pi and e as the literals 3.141592653589793 and
 *     2.718281828459045 (M_PI and M_E are not C99);
 *   - x^2 .. x^4 of a name or a temporary as x*x ... (exact, and faster than
 *     pow); x^(1/2) as sqrt(x); a negative numeric exponent under a '/':
 *     x^-2 is 1.0/(x*x); every other power pow(b, e);
 *   - abs(x) as fabs(x); sign(x) as ((x > 0) - (x < 0)), an int that C
 *     converts to the double -1.0, 0.0 or 1.0; step(x) as
 *     (((x > 0) + (x >= 0))*0.5): 0, 1/2 at 0 (SymPy's Heaviside), 1;
 *   - symbols by qd_c_name: theta' is theta_d, theta'' theta_dd, the k-th
 *     derivative (k > 2) theta_d<k>; a name that is a C keyword gets a
 *     trailing underscore (double -> double_);
 *   - user functions by name, V(r); their derivatives V_d1(r) (dV/dr),
 *     V_d1_1(r), V_d1_2(x, y), with 1-based argument slots.
 *
 * qd_print_c_block hoists every non-leaf node used more than once over the
 * DAG of all outputs into `const double qd_tK = ...;`, children first.  The base
 * of a small integer power and the arguments of sign() and step() are printed twice, so
 * they count as used twice: a compound base becomes a temporary, t1*t1.
 */
#include "prec.h"
#include "../base/mem.h"
#include "../base/args.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

typedef struct cp {
    qd_ctx *ctx;
    qd_buf *b;
    qd__ptrmap *temps; /* node -> temporary number + 1; NULL outside blocks */
} cp;

static void expr(cp *p, const qd_expr *e);

static const char *const keywords[] = {
    "auto", "break", "case", "char", "const", "continue", "default", "do", "double", "else",
    "enum", "extern", "float", "for", "goto", "if", "inline", "int", "long", "register",
    "restrict", "return", "short", "signed", "sizeof", "static", "struct", "switch",
    "typedef", "union", "unsigned", "void", "volatile", "while", "_Bool", "_Complex",
    "_Imaginary"};

static bool is_keyword(const char *s) {
    for (size_t i = 0; i < sizeof keywords / sizeof keywords[0]; i++)
        if (!strcmp(s, keywords[i]))
            return true;
    return false;
}

static void put_name(qd_buf *b, const char *s) {
    qd_buf_puts(b, s);
    if (is_keyword(s))
        qd_buf_puts(b, "_");
}

qd_status qd_c_name(const qd_expr *sym, qd_buf *out) {
    QD_ARGS(QD_ERR_ARG, sym && out);
    if (!sym || !out || sym->kind != QD_SYMBOL)
        return QD_ERR_ARG;
    if (sym->tag != QD_ROLE_COORD || sym->order == 0) {
        put_name(out, sym->u.sym.name);
    } else {
        qd_buf_puts(out, sym->u.sym.coord->u.sym.name);
        if (sym->order <= 2)
            qd_buf_puts(out, sym->order == 1 ? "_d" : "_dd");
        else
            qd_buf_printf(out, "_d%u", (unsigned)sym->order);
    }
    return out->failed ? QD_ERR_NOMEM : QD_OK;
}

static bool is_leaf(const cp *p, const qd_expr *e) {
    return e->kind == QD_SYMBOL || e->kind == QD_CONSTANT || qd__is_num(e) ||
           (p->temps && qd__ptrmap_get(p->temps, e));
}

/* 2..4 for x^2..x^4 and x^-2..x^-4, else 0. */
static int small_power(const qd_expr *e) {
    long n, d;
    if (e->kind != QD_POW || !qd_rational_get(e->args[1], &n, &d) || d != 1)
        return 0;
    n = n < 0 ? -n : n;
    return n >= 2 && n <= 4 ? (int)n : 0;
}

static int prec(const cp *p, const qd_expr *e) {
    if (p->temps && qd__ptrmap_get(p->temps, e))
        return QD_PREC_ATOM;
    if (e->kind == QD_POW && !qd__is_recip(e))
        return small_power(e) && is_leaf(p, e->args[0]) ? QD_PREC_PRODUCT : QD_PREC_ATOM;
    return qd__prec(e);
}

static void operand(cp *p, const qd_expr *e, int need) {
    bool paren = prec(p, e) < need;
    qd_buf_puts(p->b, paren ? "(" : "");
    expr(p, e);
    qd_buf_puts(p->b, paren ? ")" : "");
}

static void put_int(cp *p, mpz_srcptr z) {
    if (mpz_sizeinbase(z, 2) <= 53) {
        qd__put_mpz(p->b, z);
        qd_buf_puts(p->b, ".0");
    } else {
        qd__put_double(p->b, fabs(mpz_get_d(z)));
    }
}

static void magnitude_number(cp *p, const qd_expr *e) {
    if (e->kind == QD_FLOAT) {
        qd__put_double(p->b, fabs(e->u.f));
    } else if (mpz_cmp_ui(mpq_denref(e->u.q), 1) == 0) {
        put_int(p, mpq_numref(e->u.q));
    } else if (mpz_sizeinbase(mpq_numref(e->u.q), 2) <= 53 &&
               mpz_sizeinbase(mpq_denref(e->u.q), 2) <= 53) {
        put_int(p, mpq_numref(e->u.q));
        qd_buf_puts(p->b, "/");
        put_int(p, mpq_denref(e->u.q));
    } else {
        qd__put_double(p->b, fabs(mpq_get_d(e->u.q)));
    }
}

static void repeat(cp *p, const qd_expr *b, int n) {
    for (int i = 0; i < n; i++) {
        qd_buf_puts(p->b, i ? "*" : "");
        expr(p, b);
    }
}

/* b^e for a number e given by magnitude (the caller handles the sign). */
static void pow_call(cp *p, const qd_expr *b, const qd_expr *e, bool flip) {
    qd_buf_puts(p->b, "pow(");
    expr(p, b);
    qd_buf_puts(p->b, ", ");
    if (flip)
        magnitude_number(p, e);
    else
        expr(p, e);
    qd_buf_puts(p->b, ")");
}

/* One denominator factor b^e (e < 0) printed as b^-e, parenthesized when
 * it is not an atom. */
static void flipped(cp *p, const qd_expr *f, bool group) {
    const qd_expr *b = f->args[0], *e = f->args[1];
    int n = small_power(f);
    if (qd__is_rat(e, -1, 1)) {
        operand(p, b, group ? QD_PREC_PRODUCT : QD_PREC_ATOM);
    } else if (qd__is_rat(e, -1, 2)) {
        qd_buf_puts(p->b, "sqrt(");
        expr(p, b);
        qd_buf_puts(p->b, ")");
    } else if (n && is_leaf(p, b)) {
        qd_buf_puts(p->b, group ? "" : "(");
        repeat(p, b, n);
        qd_buf_puts(p->b, group ? "" : ")");
    } else {
        pow_call(p, b, e, true);
    }
}

/* A hoisted reciprocal is a temporary: it multiplies instead of dividing. */
static void keep_temps_up(cp *p, qd__product_split *s) {
    size_t k = 0;
    for (size_t i = 0; i < s->nden; i++) {
        if (p->temps && qd__ptrmap_get(p->temps, s->den[i]))
            s->num[s->nnum++] = s->den[i];
        else
            s->den[k++] = s->den[i];
    }
    s->nden = k;
}

static void denominator(cp *p, const qd__product_split *s, bool q) {
    size_t n = q + s->nden;
    if (!n)
        return;
    bool group = n > 1;
    qd_buf_puts(p->b, group ? "/(" : "/");
    if (q)
        put_int(p, mpq_denref(s->coeff->u.q));
    for (size_t i = 0; i < s->nden; i++) {
        qd_buf_puts(p->b, i || q ? "*" : "");
        flipped(p, s->den[i], group);
    }
    qd_buf_puts(p->b, group ? ")" : "");
}

static void product(cp *p, const qd_expr *e, bool sign) {
    qd__product_split s;
    if (!qd__split(p->ctx, e, &s)) {
        p->b->failed = true;
        return;
    }
    keep_temps_up(p, &s);
    const qd_expr *c = s.coeff;
    /* exact p/q with small parts: p in the numerator, q in the denominator */
    bool q = c && c->kind == QD_RATIONAL && mpz_cmp_ui(mpq_denref(c->u.q), 1) != 0 &&
             mpz_sizeinbase(mpq_numref(c->u.q), 2) <= 53 &&
             mpz_sizeinbase(mpq_denref(c->u.q), 2) <= 53;
    bool unit = q && mpz_cmpabs_ui(mpq_numref(c->u.q), 1) == 0;
    bool any = false;
    qd_buf_puts(p->b, s.neg && sign ? "-" : "");
    if (c && !(unit && s.nnum)) {
        if (q)
            put_int(p, mpq_numref(c->u.q));
        else
            magnitude_number(p, c);
        any = true;
    }
    for (size_t i = 0; i < s.nnum; i++) {
        qd_buf_puts(p->b, any ? "*" : "");
        operand(p, s.num[i], QD_PREC_PRODUCT);
        any = true;
    }
    qd_buf_puts(p->b, any ? "" : "1.0");
    denominator(p, &s, q);
    qd__split_free(&s);
}

static void sum(cp *p, const qd_expr *e) {
    size_t c = qd__is_num(e->args[0]) ? 1 : 0;
    for (size_t k = c; k < e->nargs + c; k++) {
        const qd_expr *t = e->args[k < e->nargs ? k : 0];
        bool temp = p->temps && qd__ptrmap_get(p->temps, t);
        bool minus = !temp && qd__has_minus(t);
        qd_buf_puts(p->b, k == c ? (minus ? "-" : "") : (minus ? " - " : " + "));
        if (temp)
            expr(p, t);
        else if (qd__is_num(t))
            magnitude_number(p, t);
        else if (t->kind == QD_MUL)
            product(p, t, false);
        else
            expr(p, t);
    }
}

static void power(cp *p, const qd_expr *e) {
    const qd_expr *b = e->args[0], *x = e->args[1];
    int n = small_power(e);
    if (qd__is_recip(e))
        product(p, e, true);
    else if (qd__is_rat(x, 1, 2)) {
        qd_buf_puts(p->b, "sqrt(");
        expr(p, b);
        qd_buf_puts(p->b, ")");
    } else if (n && is_leaf(p, b))
        repeat(p, b, n);
    else
        pow_call(p, b, x, false);
}

static void call(cp *p, const char *name, const qd_expr *e) {
    put_name(p->b, name);
    qd_buf_puts(p->b, "(");
    for (size_t i = 0; i < e->nargs; i++) {
        qd_buf_puts(p->b, i ? ", " : "");
        expr(p, e->args[i]);
    }
    qd_buf_puts(p->b, ")");
}

static void func(cp *p, const qd_expr *e) {
    if (e->tag == QD_SIGN) {
        qd_buf_puts(p->b, "((");
        expr(p, e->args[0]);
        qd_buf_puts(p->b, " > 0) - (");
        expr(p, e->args[0]);
        qd_buf_puts(p->b, " < 0))");
        return;
    }
    if (e->tag == QD_STEP) { /* 1, 1/2 at 0 (SymPy's Heaviside), 0 */
        qd_buf_puts(p->b, "(((");
        expr(p, e->args[0]);
        qd_buf_puts(p->b, " > 0) + (");
        expr(p, e->args[0]);
        qd_buf_puts(p->b, " >= 0))*0.5)");
        return;
    }
    call(p, e->tag == QD_ABS ? "fabs" : qd_func_name((qd_func)e->tag), e);
}

static void uderiv(cp *p, const qd_expr *e) {
    qd_buf_puts(p->b, e->u.fn.name);
    for (uint32_t i = 0; i < e->u.fn.nslots; i++)
        qd_buf_printf(p->b, "%s%u", i ? "_" : "_d", e->u.fn.slots[i] + 1);
    call(p, "", e);
}

static void expr(cp *p, const qd_expr *e) {
    uintptr_t k = p->temps ? (uintptr_t)qd__ptrmap_get(p->temps, e) : 0;
    if (k) {
        qd_buf_printf(p->b, "qd_t%lu", (unsigned long)k);
        return;
    }
    switch ((qd_kind)e->kind) {
    case QD_RATIONAL:
    case QD_FLOAT:
        qd_buf_puts(p->b, qd_number_sign(e) < 0 ? "-" : "");
        magnitude_number(p, e);
        break;
    case QD_CONSTANT:
        qd_buf_puts(p->b, e->tag == QD_PI ? "3.141592653589793" : "2.718281828459045");
        break;
    case QD_SYMBOL: qd_c_name(e, p->b); break;
    case QD_FUNC: func(p, e); break;
    case QD_UFUNC: call(p, e->u.fn.name, e); break;
    case QD_UDERIV: uderiv(p, e); break;
    case QD_POW: power(p, e); break;
    case QD_MUL: product(p, e, true); break;
    case QD_ADD: sum(p, e); break;
    }
}

qd_status qd__print_c(qd_ctx *ctx, const qd_expr *e, qd_buf *out) {
    cp p = {ctx, out, NULL};
    expr(&p, e);
    return out->failed ? QD_ERR_NOMEM : QD_OK;
}

/* ---- blocks with common subexpressions -------------------------------------- */

typedef struct uses {
    qd__ptrmap count;        /* node -> uses */
    const qd_expr **order;  /* first visits in post-order: children first */
    size_t n, cap;
    bool oom;
} uses;

static void count(uses *u, const qd_expr *e) {
    uintptr_t c = (uintptr_t)qd__ptrmap_get(&u->count, e);
    if (!qd__ptrmap_put(&u->count, e, (void *)(c + 1)))
        u->oom = true;
    if (c || u->oom || e->kind == QD_SYMBOL || e->kind == QD_CONSTANT || qd__is_num(e))
        return;
    for (size_t i = 0; i < e->nargs; i++)
        count(u, e->args[i]);
    /* printed twice: x*x, sign's (x > 0) - (x < 0) */
    if (small_power(e) || (e->kind == QD_FUNC && (e->tag == QD_SIGN || e->tag == QD_STEP)))
        count(u, e->args[0]);
    if (u->n == u->cap) {
        size_t cap = u->cap ? 2 * u->cap : 64;
        const qd_expr **v = qd__mem_realloc(u->count.al, u->order, cap * sizeof *v);
        if (!v) {
            u->oom = true;
            return;
        }
        u->order = v;
        u->cap = cap;
    }
    u->order[u->n++] = e;
}

static void hoist(cp *p, const uses *u) {
    unsigned long k = 0;
    for (size_t i = 0; i < u->n && !p->b->failed; i++) {
        const qd_expr *e = u->order[i];
        if ((uintptr_t)qd__ptrmap_get(&u->count, e) < 2)
            continue;
        qd_buf_printf(p->b, "const double qd_t%lu = ", ++k);
        expr(p, e);
        qd_buf_puts(p->b, ";\n");
        if (!qd__ptrmap_put(p->temps, e, (void *)(uintptr_t)k))
            p->b->failed = true;
    }
}

qd_status qd_print_c_block(qd_ctx *ctx, size_t n, const qd_expr *const *exprs,
                           const char *const *lhs, qd_buf *out) {
    QD_ARGS_CTX(ctx, ctx && (n == 0 || exprs) && (n == 0 || lhs) && out);
    if (!ctx || !out || (n && (!exprs || !lhs)))
        return QD_ERR_ARG;
    for (size_t i = 0; i < n; i++) {
        if (!exprs[i] || !lhs[i]) {
            qd_ctx_error(ctx, QD_ERR_ARG, "output %zu of a C block is NULL", i);
            return QD_ERR_ARG;
        }
    }
    uses u = {QD_PTRMAP_AL(qd__ctx_allocator(ctx)), NULL, 0, 0, false};
    qd__ptrmap temps = QD_PTRMAP_AL(qd__ctx_allocator(ctx));
    cp p = {ctx, out, &temps};
    for (size_t i = 0; i < n; i++)
        count(&u, exprs[i]);
    if (u.oom)
        out->failed = true;
    else
        hoist(&p, &u);
    for (size_t i = 0; i < n && !out->failed; i++) {
        qd_buf_printf(out, "%s = ", lhs[i]);
        expr(&p, exprs[i]);
        qd_buf_puts(out, ";\n");
    }
    qd__ptrmap_free(&u.count);
    qd__ptrmap_free(&temps);
    qd__free(u.order);
    if (out->failed) {
        qd__oom(ctx);
        return QD_ERR_NOMEM;
    }
    return QD_OK;
}

/*
 * src/sym/count.c - the size of an expression.
 *
 * qd_count_ops counts operations the way SymPy's count_ops(visual=False)
 * does, so that sizes can be compared with SymPy's (the benchmarks do) and
 * the simplifier's "shorter" means what a SymPy user means:
 *   a sum of k terms: k - 1 (ADD or SUB: a negative term is a subtraction),
 *     plus one NEG when every term is negative;
 *   a product: split into numerator and denominator (negative exponents and
 *     the rational coefficient's denominator go below); k factors cost k - 1
 *     MUL on each side, one DIV when there is a denominator, one NEG for a
 *     negative coefficient:  -2*x/(3*y) = NEG + 2 MUL + DIV = 4;
 *   x^e: one POW plus the exponent's own cost (x^-2 = NEG + POW,
 *   x^(1/2) = DIV + POW), but x^-1 alone is one DIV;
 *   a rational p/q: DIV; a negative number: NEG; a function call: one each.
 */
#include "node.h"
#include "../base/args.h"

static size_t ops(const qd_expr *e);

/* A number's cost with its sign dropped. */
static size_t number_ops(const qd_expr *e) {
    return e->kind == QD_RATIONAL && mpz_cmp_ui(mpq_denref(e->u.q), 1) != 0;
}

static bool negative_exponent(const qd_expr *f) {
    return f->kind == QD_POW && qd__is_num(f->args[1]) && qd_number_sign(f->args[1]) < 0;
}

/* The cost of b^|e| in a denominator. */
static size_t denominator_factor_ops(const qd_expr *f) {
    const qd_expr *e = f->args[1];
    bool one = qd_is_number(e) && qd_number_value(e) == -1.0;
    return ops(f->args[0]) + (one ? 0 : 1 + number_ops(e));
}

/* A product's cost with its sign dropped. */
static size_t mul_ops(const qd_expr *e) {
    size_t i = 0, cost = 0, nnum = 0, nden = 0;
    if (qd__is_num(e->args[0])) {
        const qd_expr *c = e->args[0];
        bool unit = qd_number_value(c) == 1.0 || qd_number_value(c) == -1.0;
        if (c->kind == QD_RATIONAL) {
            nnum += mpz_cmpabs_ui(mpq_numref(c->u.q), 1) != 0;
            nden += mpz_cmp_ui(mpq_denref(c->u.q), 1) != 0;
        } else {
            nnum += !unit;
        }
        i = 1;
    }
    for (; i < e->nargs; i++) {
        const qd_expr *f = e->args[i];
        if (negative_exponent(f)) {
            nden++;
            cost += denominator_factor_ops(f);
        } else {
            nnum++;
            cost += ops(f);
        }
    }
    cost += nnum > 1 ? nnum - 1 : 0;
    cost += nden > 1 ? nden - 1 : 0;
    return cost + (nden > 0);
}

static bool term_negative(const qd_expr *t) {
    if (qd__is_num(t))
        return qd_number_sign(t) < 0;
    return t->kind == QD_MUL && qd__is_num(t->args[0]) && qd_number_sign(t->args[0]) < 0;
}

static size_t term_ops(const qd_expr *t) {
    if (qd__is_num(t))
        return number_ops(t);
    return t->kind == QD_MUL ? mul_ops(t) : ops(t);
}

static size_t ops_of(const qd_expr *e);

/* Interned nodes never change, so a compound node's count is kept in it
 * (the one field of the node written after it is made). */
static size_t ops(const qd_expr *e) {
    bool compound = e->kind == QD_ADD || e->kind == QD_MUL || e->kind == QD_POW ||
                    e->kind == QD_FUNC;
    if (compound && e->u.ops_memo)
        return e->u.ops_memo - 1;
    size_t n = ops_of(e);
    if (compound)
        ((qd_expr *)e)->u.ops_memo = n + 1;
    return n;
}

static size_t ops_of(const qd_expr *e) {
    size_t n = 0;
    switch ((qd_kind)e->kind) {
    case QD_RATIONAL:
    case QD_FLOAT:
        return number_ops(e) + (qd_number_sign(e) < 0);
    case QD_CONSTANT:
    case QD_SYMBOL:
        return 0;
    case QD_ADD: {
        bool all_negative = true;
        for (size_t i = 0; i < e->nargs; i++) {
            n += term_ops(e->args[i]);
            all_negative &= term_negative(e->args[i]);
        }
        return n + e->nargs - 1 + all_negative;
    }
    case QD_MUL:
        return mul_ops(e) + term_negative(e);
    case QD_POW:
        /* x^-1 alone is a division; any other exponent counts as itself */
        if (qd_is_number(e->args[1]) && qd_number_value(e->args[1]) == -1.0)
            return 1 + ops(e->args[0]);
        return 1 + ops(e->args[0]) + ops(e->args[1]);
    case QD_FUNC:
    case QD_UFUNC:
    case QD_UDERIV:
        for (size_t i = 0; i < e->nargs; i++)
            n += ops(e->args[i]);
        return n + 1;
    }
    return n;
}

size_t qd_count_ops(const qd_expr *e) { QD_ARGS(0, e); return e ? ops(e) : 0; }

static void count_dag(const qd_expr *e, qd__ptrmap *seen) {
    if (qd__ptrmap_has(seen, e))
        return;
    qd__ptrmap_put(seen, e, (void *)e);
    for (size_t i = 0; i < e->nargs; i++)
        count_dag(e->args[i], seen);
}

size_t qd_dag_size(qd_ctx *ctx, const qd_expr *e) {
    QD_ARGS(0, ctx && e);
    (void)ctx;
    if (!e)
        return 0;
    qd__ptrmap seen = QD_PTRMAP_AL(qd__ctx_allocator(ctx));
    count_dag(e, &seen);
    size_t n = seen.len;
    qd__ptrmap_free(&seen);
    return n;
}

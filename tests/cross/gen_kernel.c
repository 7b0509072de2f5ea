/*
 * tests/cross/gen_kernel.c - cases for the SymPy cross-check of the kernel
 * (tests/cross/check_kernel.py).
 *
 * For N random exact expressions over plain symbols, a parameter, a
 * coordinate q(t) with its velocity, and t, prints qdot's partial derivative,
 * total time derivative and expansion, all in SymPy syntax, one per line:
 *   expr <e>   var <name>   diff <de/dvar>   dt <de/dt>   expand <expand(e)>
 *   ops <qd_count_ops(e)>
 * Then N/4 cases of the constructor's rules, each an input SymPy reads and
 * evaluates by its own rules and the node qdot made of it:
 *   rule <input>   value <qdot's canonical form>
 * sin, cos, tan of e + k*pi/n (and of k*pi/n alone) for n in 1, 2, 3, 4, 5,
 * 6, 12, and fractional powers of products of numbers, powers of symbols and
 * squares of random expressions (the real roots of pow.c).
 * Usage: gen_kernel N SEED
 */
#include <stdio.h>
#include <stdlib.h>

#include "qdot/qdot.h"
#include "util/randexpr.h"

static int line(qd_ctx *ctx, const char *tag, const qd_expr *e) {
    qd_buf b = QD_BUF_INIT;
    if (!e || qd_print(ctx, e, QD_FMT_SYMPY, &b) != QD_OK) {
        fprintf(stderr, "gen_kernel: %s failed: %s\n", tag, qd_ctx_message(ctx));
        qd_buf_free(&b);
        return 1;
    }
    printf("%s %s\n", tag, qd_buf_str(&b));
    qd_buf_free(&b);
    return 0;
}

/* Append e in SymPy syntax to b. */
static int text(qd_ctx *ctx, const qd_expr *e, qd_buf *b) {
    if (!e || qd_print(ctx, e, QD_FMT_SYMPY, b) != QD_OK) {
        fprintf(stderr, "gen_kernel: rule failed: %s\n", qd_ctx_message(ctx));
        return 1;
    }
    return 0;
}

/* f(e + k pi/n), or f(k pi/n) alone; tan's poles are left out. */
static int trig_rule(qd_ctx *ctx, qt_rng *r, const qd_expr *const *syms, qd_buf *in,
                     const qd_expr **value) {
    static const long dens[7] = {1, 2, 3, 4, 5, 6, 12};
    static const qd_func fs[3] = {QD_SIN, QD_COS, QD_TAN};
    long n = dens[qt_below(r, 7)], k = (long)qt_below(r, (unsigned)(6 * n + 1)) - 3 * n;
    qd_func f = fs[qt_below(r, 3)];
    bool alone = qt_below(r, 4) == 0;
    if (alone && f == QD_TAN && (2 * k) % n == 0 && ((2 * k) / n) % 2)
        k++;
    const qd_expr *e = alone ? qd_int(ctx, 0) : qt_random_expr(ctx, r, syms, 5, 2, QT_POLY | QT_TRIG);
    qd_buf_printf(in, "%s(", qd_func_name(f));
    int bad = text(ctx, e, in);
    qd_buf_printf(in, " + Rational(%ld, %ld)*pi)", k, n);
    const qd_expr *kpi = qd_mul(ctx, qd_rat(ctx, k, n), qd_const(ctx, QD_PI));
    *value = qd_fn(ctx, f, qd_add(ctx, e, kpi));
    return bad;
}

/* (c * x^i * y^j * e^2 * ...)^(p/d): what has a known sign comes out. */
static int root_rule(qd_ctx *ctx, qt_rng *r, const qd_expr *const *syms, qd_buf *in,
                     const qd_expr **value) {
    static const long cs[8][2] = {{4, 1}, {9, 1}, {1, 4}, {2, 1}, {-9, 1}, {8, 1}, {-1, 1}, {27, 8}};
    static const long es[6][2] = {{1, 2}, {-1, 2}, {3, 2}, {1, 3}, {2, 3}, {-3, 2}};
    const long *c = cs[qt_below(r, 8)], *x = es[qt_below(r, 6)];
    const qd_expr *fs[4];
    fs[0] = qd_rat(ctx, c[0], c[1]);
    qd_buf_printf(in, "(Rational(%ld, %ld)", c[0], c[1]);
    int bad = 0;
    for (int i = 1; i < 4; i++) {
        const qd_expr *b = i < 3 ? syms[qt_below(r, 5)]
                                 : qt_random_expr(ctx, r, syms, 5, 2, QT_POLY | QT_TRIG);
        long k = (long)qt_below(r, 4) + 1;
        if (qd_is_zero(b)) /* a zero base has no negative power */
            b = qd_int(ctx, 3);
        fs[i] = qd_powi(ctx, b, i == 3 ? 2 : k);
        qd_buf_puts(in, "*(");
        bad |= text(ctx, b, in);
        qd_buf_printf(in, ")**%ld", i == 3 ? 2 : k);
    }
    qd_buf_printf(in, ")**Rational(%ld, %ld)", x[0], x[1]);
    *value = qd_pow(ctx, qd_mul_n(ctx, 4, fs), qd_rat(ctx, x[0], x[1]));
    return bad;
}

int main(int argc, char **argv) {
    if (argc != 3) {
        fprintf(stderr, "usage: gen_kernel N SEED\n");
        return 2;
    }
    long n = atol(argv[1]);
    qt_rng r = {(uint64_t)atoll(argv[2])};
    qd_ctx *ctx = qd_ctx_new();
    const qd_expr *q = qd_coord(ctx, "q");
    const qd_expr *syms[6] = {qd_symbol(ctx, "x"), qd_symbol(ctx, "y"), qd_param(ctx, "m"),
                              q, qd_jet(ctx, q, 1), qd_time(ctx)};
    printf("symbols x y m t\ncoordinates q\n");
    int bad = 0;
    for (long i = 0; i < n && !bad; i++) {
        const qd_expr *e = qt_random_expr(ctx, &r, syms, 6, 4, QT_ALL & ~QT_FLOAT);
        const qd_expr *v = syms[qt_below(&r, 5)]; /* x, y, m, q or q' */
        printf("case %ld\nvar %s\n", i, qd_expr_name(v));
        bad |= line(ctx, "expr", e);
        bad |= line(ctx, "diff", qd_diff(ctx, e, v));
        bad |= line(ctx, "dt", qd_dt(ctx, e));
        bad |= line(ctx, "expand", qd_expand(ctx, e));
        printf("ops %zu\n", qd_count_ops(e));
    }
    for (long i = 0; i < n / 4 && !bad; i++) {
        qd_buf in = QD_BUF_INIT;
        const qd_expr *v = NULL;
        bad |= (i % 2 ? root_rule : trig_rule)(ctx, &r, syms, &in, &v);
        printf("rule %s\n", qd_buf_str(&in));
        bad |= line(ctx, "value", v);
        qd_buf_free(&in);
    }
    qd_ctx_free(ctx);
    return bad;
}

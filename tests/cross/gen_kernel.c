/*
 * tests/cross/gen_kernel.c - cases for the SymPy cross-check of the kernel
 * (tests/cross/check_kernel.py).
 *
 * For N random exact expressions over plain symbols, a parameter, a
 * coordinate q(t) with its velocity, and t, prints qdot's partial derivative,
 * total time derivative and expansion, all in SymPy syntax, one per line:
 *   expr <e>   var <name>   diff <de/dvar>   dt <de/dt>   expand <expand(e)>
 *   ops <qd_count_ops(e)>
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
    qd_ctx_free(ctx);
    return bad;
}

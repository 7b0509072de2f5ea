/* tests/util/randexpr.c - see randexpr.h. */
#include "randexpr.h"

uint64_t qt_rand(qt_rng *r) {
    uint64_t z = (r->s += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

double qt_uniform(qt_rng *r, double lo, double hi) {
    return lo + (hi - lo) * (double)(qt_rand(r) >> 11) / 9007199254740992.0;
}

unsigned qt_below(qt_rng *r, unsigned n) { return (unsigned)(qt_rand(r) % n); }

static const qd_expr *leaf(qd_ctx *ctx, qt_rng *r, const qd_expr *const *syms, size_t nsyms,
                           unsigned flags) {
    unsigned k = qt_below(r, 10);
    if (k < 6 && nsyms)
        return syms[qt_below(r, (unsigned)nsyms)];
    if (k < 9 || !(flags & QT_FLOAT)) {
        long num = (long)qt_below(r, 11) - 5;
        long den = (long)qt_below(r, 3) + 1;
        return qd_rat(ctx, num, den);
    }
    return qd_float(ctx, qt_uniform(r, -3, 3));
}

/* c + e^2 with c in {1/2, 1, 2}: positive, so safe under log, sqrt and 1/x. */
static const qd_expr *positive(qd_ctx *ctx, qt_rng *r, const qd_expr *e) {
    static const long num[3] = {1, 1, 2}, den[3] = {2, 1, 1};
    unsigned k = qt_below(r, 3);
    return qd_add(ctx, qd_rat(ctx, num[k], den[k]), qd_powi(ctx, e, 2));
}

const qd_expr *qt_random_expr(qd_ctx *ctx, qt_rng *r, const qd_expr *const *syms,
                              size_t nsyms, int depth, unsigned flags) {
    if (depth <= 0 || qt_below(r, 5) == 0)
        return leaf(ctx, r, syms, nsyms, flags);
    const qd_expr *a = qt_random_expr(ctx, r, syms, nsyms, depth - 1, flags);
    /* Every draw from r happens in a statement of its own: the order in which
     * a compiler evaluates function arguments is unspecified, and the same
     * seed must give the same expression with gcc and clang. */
    for (;;) {
        const qd_expr *b;
        unsigned k;
        switch (qt_below(r, 9)) {
        case 0:
        case 1:
            b = qt_random_expr(ctx, r, syms, nsyms, depth - 1, flags);
            return qd_add(ctx, a, b);
        case 2:
        case 3:
            b = qt_random_expr(ctx, r, syms, nsyms, depth - 1, flags);
            return qd_mul(ctx, a, b);
        case 4:
            return qd_powi(ctx, a, (long)qt_below(r, 3) + 2);
        case 5:
            if (!(flags & QT_TRIG))
                continue;
            return qd_fn(ctx, qt_below(r, 2) ? QD_SIN : QD_COS, a);
        case 6:
            if (!(flags & QT_DIV))
                continue;
            if (qt_below(r, 2)) {
                b = qt_random_expr(ctx, r, syms, nsyms, depth - 1, flags);
                return qd_div(ctx, b, positive(ctx, r, a));
            }
            b = positive(ctx, r, a);
            k = qt_below(r, 3);
            return qd_pow(ctx, b, qd_rat(ctx, -(long)k - 1, 2));
        case 7:
            if (!(flags & QT_FLOAT))
                continue;
            return qd_mul(ctx, qd_float(ctx, qt_uniform(r, -2, 2)), a);
        default: {
            if (!(flags & QT_FUNCS))
                continue;
            const qd_expr *half_sin = qd_mul(ctx, qd_rat(ctx, 1, 2), qd_fn(ctx, QD_SIN, a));
            switch (qt_below(r, 12)) {
            case 0: return qd_fn(ctx, QD_TAN, half_sin);
            case 1: return qd_fn(ctx, QD_ASIN, half_sin);
            case 2: return qd_fn(ctx, QD_ACOS, half_sin);
            case 3: return qd_fn(ctx, QD_ATAN, a);
            case 4: b = positive(ctx, r, a); return qd_fn2(ctx, QD_ATAN2, a, b);
            case 5: return qd_fn(ctx, QD_SINH, half_sin);
            case 6: return qd_fn(ctx, QD_COSH, half_sin);
            case 7: return qd_fn(ctx, QD_TANH, a);
            case 8: return qd_fn(ctx, QD_EXP, half_sin);
            case 9: return qd_fn(ctx, QD_LOG, positive(ctx, r, a));
            case 10: return qd_sqrt(ctx, positive(ctx, r, a));
            default: return qd_fn(ctx, QD_ABS, positive(ctx, r, a));
            }
        }
        }
    }
}

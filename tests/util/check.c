/* tests/util/check.c - see check.h. */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <string.h>

#include "check.h"

qd_model *qt_parse_ok(qd_ctx *ctx, const char *text) {
    qd_diag d;
    memset(&d, 0, sizeof d);
    qd_model *m = qd_model_parse(ctx, text, &d);
    if (!m)
        fail_msg("%zu:%zu: %s [hint: %s]", d.line, d.col, d.message, d.hint);
    return m;
}

void qt_assert_is(qd_ctx *ctx, const qd_expr *e, const char *want) {
    const qd_read_opts opts = {.new_symbols = true};
    const qd_expr *w = qd_read(ctx, want, &opts, NULL);
    assert_non_null(w);
    assert_non_null(e);
    const qd_expr *d = qd_simplify(ctx, qd_sub(ctx, e, w));
    if (!d || !qd_is_zero(d)) {
        qd_buf b = QD_BUF_INIT;
        qd_print(ctx, e, QD_FMT_TEXT, &b);
        fail_msg("got %s, want %s", qd_buf_str(&b), want);
    }
}

bool qt_same_numeric(qd_ctx *ctx, const qd_expr *a, const qd_expr *b, double lo, double hi,
                     int npoints, double rel) {
    const qd_expr *syms[128];
    double vals[128];
    size_t na = qd_free_symbols(ctx, a, syms, 64);
    size_t nb = qd_free_symbols(ctx, b, syms + na, 64);
    if (na > 64 || nb > 64)
        return false;
    unsigned long seed = 12345;
    for (int p = 0; p < npoints; p++) {
        for (size_t i = 0; i < na + nb; i++) {
            seed = seed * 6364136223846793005UL + 1442695040888963407UL;
            vals[i] = lo + (hi - lo) * (double)(seed >> 11) / 9007199254740992.0;
        }
        /* a symbol both have takes b's draw in a and a's in b otherwise: one value each */
        for (size_t i = na; i < na + nb; i++)
            for (size_t k = 0; k < na; k++)
                if (syms[k] == syms[i])
                    vals[i] = vals[k];
        double x, y;
        if (qd_eval(ctx, a, na + nb, syms, vals, &x) != QD_OK ||
            qd_eval(ctx, b, na + nb, syms, vals, &y) != QD_OK)
            return false;
        if (!(fabs(x - y) <= rel * (1 + fabs(x) + fabs(y))))
            return false;
    }
    return true;
}

/*
 * tests/sym/test_print.c - the printers.  C output is compiled with the
 * system compiler and its values compared with qd_eval; LaTeX and SymPy are
 * checked for structure (balanced groups, the notation for derivatives) and
 * for printing every node kind; the text printer's read-back property lives
 * in test_read.c.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <dlfcn.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "util/randexpr.h"

#define NSYM 6
#define NOUT 80

typedef struct world {
    qd_ctx *ctx;
    const qd_expr *syms[NSYM]; /* x, y, q, q', m, t */
    const qd_expr *kinds[16];  /* one node of every kind */
    size_t nkinds;
} world;

static int setup(void **state) {
    static world w;
    qd_ctx *c = w.ctx = qd_ctx_new();
    const qd_expr *q = qd_coord(c, "theta1");
    const qd_expr *s[NSYM] = {qd_symbol(c, "x"), qd_symbol(c, "y"), q, qd_jet(c, q, 1),
                              qd_param(c, "m"), qd_time(c)};
    memcpy(w.syms, s, sizeof s);
    const qd_expr *x = s[0], *xy[2] = {s[0], s[1]};
    unsigned sl[2] = {0, 1};
    const qd_expr *k[] = {
        qd_rat(c, 3, 4), qd_float(c, -2.5), qd_const(c, QD_PI), qd_jet(c, q, 2),
        qd_fn2(c, QD_ATAN2, x, s[1]), qd_ufunc(c, "V", 1, &x), qd_uderiv(c, "W", 2, sl, 2, xy),
        qd_uderiv(c, "V", 1, sl, 1, &x), qd_pow(c, x, qd_rat(c, -3, 2)),
        qd_mul(c, qd_int(c, -2), qd_mul(c, x, s[1])), qd_add(c, x, qd_int(c, 1)),
        qd_symbol(c, "lambda"), qd_symbol(c, "E"), qd_fn(c, QD_SIGN, x)};
    for (size_t i = 0; i < sizeof k / sizeof k[0]; i++)
        w.kinds[w.nkinds++] = k[i];
    assert_int_equal(qd_ctx_status(c), QD_OK);
    *state = &w;
    return 0;
}

static int teardown(void **state) {
    world *w = *state;
    qd_ctx_free(w->ctx);
    return 0;
}

static const qd_expr *random_expr(world *w, uint64_t seed) {
    qt_rng r = {seed * 104729 + 17};
    return qt_random_expr(w->ctx, &r, w->syms, NSYM, 5, QT_ALL);
}

static const char *text(world *w, const qd_expr *e, qd_format f, qd_buf *b) {
    qd_buf_clear(b);
    assert_int_equal(qd_print(w->ctx, e, f, b), QD_OK);
    return qd_buf_str(b);
}

static void test_null(void **state) {
    world *w = *state;
    qd_buf b = QD_BUF_INIT;
    assert_int_not_equal(qd_print(w->ctx, NULL, QD_FMT_TEXT, &b), QD_OK);
    assert_int_equal(qd_ctx_status(w->ctx), QD_ERR_ARG);
    qd_ctx_clear_error(w->ctx);
    assert_int_not_equal(qd_print_c_block(w->ctx, 1, (const qd_expr *[]){NULL},
                                          (const char *[]){"y"}, &b), QD_OK);
    qd_ctx_clear_error(w->ctx);
    assert_int_not_equal(qd_c_name(qd_int(w->ctx, 1), &b), QD_OK);
    qd_buf_free(&b);
}

/* ---- C: compile, load, compare with qd_eval --------------------------------- */

static void declare_inputs(world *w, qd_buf *src) {
    for (size_t i = 0; i < NSYM; i++) {
        qd_buf_puts(src, "    const double ");
        qd_c_name(w->syms[i], src);
        qd_buf_printf(src, " = in[%zu];\n", i);
    }
}

static void write_source(world *w, const qd_expr *const *outs, qd_buf *src) {
    char lhs[NOUT][16];
    const char *lp[NOUT];
    qd_buf_puts(src, "#include <math.h>\nvoid qd_block(const double *in, double *out) {\n");
    declare_inputs(w, src);
    for (size_t i = 0; i < NOUT; i++) {
        snprintf(lhs[i], sizeof lhs[i], "out[%zu]", i);
        lp[i] = lhs[i];
    }
    assert_int_equal(qd_print_c_block(w->ctx, NOUT, outs, lp, src), QD_OK);
    qd_buf_puts(src, "}\nvoid qd_single(const double *in, double *out) {\n");
    declare_inputs(w, src);
    for (size_t i = 0; i < NOUT; i++) {
        qd_buf_printf(src, "    out[%zu] = ", i);
        assert_int_equal(qd_print(w->ctx, outs[i], QD_FMT_C, src), QD_OK);
        qd_buf_puts(src, ";\n");
    }
    qd_buf_puts(src, "}\n");
}

typedef void (*qd_fn_t)(const double *, double *);

static void *compile(const char *src, char *so, size_t n) {
    char c[64], cmd[256];
    snprintf(c, sizeof c, "/tmp/qd_test_print_%ld.c", (long)getpid());
    snprintf(so, n, "/tmp/qd_test_print_%ld.so", (long)getpid());
    FILE *f = fopen(c, "w");
    assert_non_null(f);
    fputs(src, f);
    fclose(f);
    snprintf(cmd, sizeof cmd, "cc -std=c99 -O1 -shared -fPIC -o %s %s -lm", so, c);
    int rc = system(cmd);
    remove(c);
    if (rc != 0)
        fail_msg("the generated C did not compile (%s):\n%s", cmd, src);
    void *h = dlopen(so, RTLD_NOW);
    if (!h)
        fail_msg("dlopen: %s", dlerror());
    return h;
}

static void compare(world *w, const qd_expr *const *outs, qd_fn_t block, qd_fn_t single) {
    qt_rng r = {99};
    for (int k = 0; k < 20; k++) {
        double in[NSYM], a[NOUT], b[NOUT];
        for (size_t i = 0; i < NSYM; i++)
            in[i] = qt_uniform(&r, -1, 1);
        block(in, a);
        single(in, b);
        for (size_t i = 0; i < NOUT; i++) {
            double v;
            assert_int_equal(qd_eval(w->ctx, outs[i], NSYM, w->syms, in, &v), QD_OK);
            double tol = 1e-12 * (1 + fabs(v));
            if (!(fabs(a[i] - v) <= tol && fabs(b[i] - v) <= tol)) {
                qd_buf t = QD_BUF_INIT;
                qd_print(w->ctx, outs[i], QD_FMT_C, &t);
                fail_msg("output %zu: block %.17g single %.17g eval %.17g\n%s", i, a[i], b[i],
                         v, qd_buf_str(&t));
            }
        }
    }
}

static void test_c_compiles_and_agrees(void **state) {
    world *w = *state;
    if (system("cc --version > /dev/null 2>&1") != 0) {
        print_message("no C compiler (cc): skipping the compile test\n");
        skip();
    }
    const qd_expr *outs[NOUT];
    for (size_t i = 0; i < NOUT; i++) {
        const qd_expr *e = random_expr(w, i + 1);
        /* derivatives share subexpressions with their expression */
        outs[i] = i % 3 == 2 ? qd_diff(w->ctx, outs[i - 1], w->syms[i % NSYM]) : e;
    }
    outs[0] = qd_fn(w->ctx, QD_SIGN, qd_add(w->ctx, w->syms[0], qd_rat(w->ctx, 1, 3)));
    outs[1] = qd_mul(w->ctx, qd_const(w->ctx, QD_E),
                     qd_pow(w->ctx, qd_add(w->ctx, w->syms[1], qd_int(w->ctx, 2)),
                            qd_rat(w->ctx, -5, 2)));
    qd_buf src = QD_BUF_INIT;
    write_source(w, outs, &src);
    char so[64];
    void *h = compile(qd_buf_str(&src), so, sizeof so);
    compare(w, outs, (qd_fn_t)(uintptr_t)dlsym(h, "qd_block"),
            (qd_fn_t)(uintptr_t)dlsym(h, "qd_single"));
    dlclose(h);
    remove(so);
    qd_buf_free(&src);
}

static size_t occurrences(const char *s, const char *what) {
    size_t n = 0;
    for (const char *p = strstr(s, what); p; p = strstr(p + 1, what))
        n++;
    return n;
}

static void test_c_block_shares(void **state) {
    world *w = *state;
    qd_ctx *c = w->ctx;
    const qd_expr *x = w->syms[0], *y = w->syms[1];
    const qd_expr *s = qd_fn(c, QD_SIN, qd_add(c, x, y));
    const qd_expr *outs[3] = {qd_mul(c, s, w->syms[4]), qd_add(c, s, x),
                              qd_powi(c, qd_add(c, x, qd_int(c, 1)), 2)};
    qd_buf b = QD_BUF_INIT;
    assert_int_equal(qd_print_c_block(c, 3, outs, (const char *[]){"a", "b", "d"}, &b), QD_OK);
    const char *str = qd_buf_str(&b);
    assert_int_equal(occurrences(str, "sin("), 1);    /* computed once */
    assert_int_equal(occurrences(str, "x + 1.0"), 1); /* the squared base too */
    assert_int_equal(occurrences(str, "pow("), 0);
    assert_int_equal(occurrences(str, "const double qd_t"), 2);
    qd_buf_clear(&b);
    assert_int_equal(qd_c_name(qd_jet(c, w->syms[2], 2), &b), QD_OK);
    assert_string_equal(qd_buf_str(&b), "theta1_dd"); /* the documented spelling */
    qd_buf_free(&b);
}

/* ---- LaTeX and SymPy ---------------------------------------------------------- */

static bool balanced(const char *s) {
    long brace = 0, left = 0;
    for (const char *p = s; *p; p++) {
        if (*p == '\\' && (p[1] == '{' || p[1] == '}')) {
            p++;
            continue;
        }
        brace += (*p == '{') - (*p == '}');
        if (brace < 0)
            return false;
    }
    left = (long)occurrences(s, "\\left") - (long)occurrences(s, "\\right");
    return brace == 0 && left == 0;
}

static void test_latex(void **state) {
    world *w = *state;
    qd_ctx *c = w->ctx;
    qd_buf b = QD_BUF_INIT;
    assert_string_equal(text(w, qd_rat(c, 1, 2), QD_FMT_LATEX, &b), "\\frac{1}{2}");
    assert_non_null(strstr(text(w, w->syms[3], QD_FMT_LATEX, &b), "\\dot{\\theta}"));
    assert_non_null(strstr(text(w, qd_jet(c, w->syms[2], 2), QD_FMT_LATEX, &b),
                           "\\ddot{\\theta}"));
    assert_non_null(strstr(text(w, qd_const(c, QD_PI), QD_FMT_LATEX, &b), "\\pi"));
    assert_non_null(strstr(text(w, qd_sqrt(c, w->syms[0]), QD_FMT_LATEX, &b), "\\sqrt{"));
    assert_non_null(strstr(text(w, qd_div(c, w->syms[0], w->syms[1]), QD_FMT_LATEX, &b),
                           "\\frac{"));
    for (uint64_t seed = 1; seed <= 300; seed++) {
        const char *s = text(w, qd_dt(c, random_expr(w, seed)), QD_FMT_LATEX, &b);
        if (!balanced(s) || strchr(s, '\'') || strstr(s, "+ -") || strstr(s, "--"))
            fail_msg("seed %llu: %s", (unsigned long long)seed, s);
    }
    for (size_t i = 0; i < w->nkinds; i++)
        assert_true(balanced(text(w, w->kinds[i], QD_FMT_LATEX, &b)));
    qd_buf_free(&b);
}

static void test_text_shape(void **state) {
    world *w = *state;
    qd_buf b = QD_BUF_INIT;
    for (uint64_t seed = 1; seed <= 300; seed++) {
        const char *s = text(w, random_expr(w, seed), QD_FMT_TEXT, &b);
        if (strstr(s, "+ -") || strstr(s, "--") || strstr(s, "*-") || strstr(s, "^-"))
            fail_msg("seed %llu: %s", (unsigned long long)seed, s);
    }
    qd_buf_free(&b);
}

static void test_sympy(void **state) {
    world *w = *state;
    qd_buf b = QD_BUF_INIT;
    for (size_t i = 0; i < w->nkinds; i++) {
        const char *s = text(w, w->kinds[i], QD_FMT_SYMPY, &b);
        assert_true(strlen(s) > 0);
        assert_null(strchr(s, '\''  ) && !strstr(s, "('") ? s : NULL); /* quotes only in Symbol('..') */
        assert_null(strchr(s, '^'));
    }
    assert_non_null(strstr(text(w, w->syms[3], QD_FMT_SYMPY, &b), "theta1(t).diff(t)"));
    assert_non_null(strstr(text(w, qd_rat(w->ctx, 3, 4), QD_FMT_SYMPY, &b), "Rational(3, 4)"));
    assert_non_null(strstr(text(w, w->kinds[11], QD_FMT_SYMPY, &b), "Symbol('lambda')"));
    for (uint64_t seed = 1; seed <= 300; seed++) {
        const char *s = text(w, random_expr(w, seed), QD_FMT_SYMPY, &b);
        long depth = 0;
        for (const char *p = s; *p; p++)
            depth += (*p == '(') - (*p == ')');
        if (depth != 0 || strchr(s, '^'))
            fail_msg("seed %llu: %s", (unsigned long long)seed, s);
    }
    qd_buf_free(&b);
}

/* The preamble lines for user functions: each name once (V and its
 * derivative V' are one function), in natural name order, none for a name
 * the printer spells self-contained (E), NULL entries skipped. */
static void test_sympy_functions(void **state) {
    world *w = *state;
    qd_ctx *c = w->ctx;
    const qd_expr *x = qd_symbol(c, "x"), *y = qd_symbol(c, "y");
    const qd_expr *xy[2] = {x, y};
    unsigned slot = 0;
    const qd_expr *V = qd_ufunc(c, "V", 1, &x), *dV = qd_uderiv(c, "V", 1, &slot, 1, &y);
    const qd_expr *f10 = qd_ufunc(c, "f10", 2, xy), *f2 = qd_ufunc(c, "f2", 1, &V);
    const qd_expr *E = qd_ufunc(c, "E", 1, &x);
    const qd_expr *exprs[5] = {qd_add(c, V, f10), NULL, qd_mul(c, dV, E), qd_fn(c, QD_SIN, f2), x};
    qd_buf b = QD_BUF_INIT;
    assert_int_equal(qd_print_sympy_functions(c, 5, exprs, &b), QD_OK);
    assert_string_equal(qd_buf_str(&b), "V = Function('V')\nf2 = Function('f2')\n"
                                        "f10 = Function('f10')\n");
    qd_buf_clear(&b);
    assert_int_equal(qd_print_sympy_functions(c, 1, &x, &b), QD_OK);
    assert_string_equal(qd_buf_str(&b), "");
    qd_buf_free(&b);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_null),        cmocka_unit_test(test_c_compiles_and_agrees),
        cmocka_unit_test(test_c_block_shares), cmocka_unit_test(test_latex),
        cmocka_unit_test(test_text_shape),  cmocka_unit_test(test_sympy),
        cmocka_unit_test(test_sympy_functions),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}

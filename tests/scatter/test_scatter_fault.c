/*
 * tests/scatter/test_scatter_fault.c - scattering with every allocation
 * made to fail in turn (the habit of tests/fault/test_fault.c, whose
 * failing allocator this copies): each run must give the right answer or
 * a clean QD_ERR_NOMEM, with every block given back.
 *
 * Body: the refracting sphere V = -3 step(2 - r) at E = 1 (n = 2; Desloge
 * ch. 60 problems, Landau sec. 18 pb. 2): the deflection at b = 1 against
 * Snell's 2 (asin(b/a) - asin(b/(n a))), and dsigma/dOmega at Theta = 1
 * against n^2 a^2 (n c - 1)(n - c)/(4 c (1 + n^2 - 2 n c)^2), c = cos(1/2).
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "qdot/qdot.h"

typedef struct faulty {
    long count;    /* requests so far (malloc and realloc) */
    long fail_at;  /* the request to refuse, 0: none */
    long live;     /* blocks outstanding */
    bool failed;   /* fail_at was reached */
} faulty;

static bool refuse(faulty *f) {
    if (++f->count != f->fail_at)
        return false;
    f->failed = true;
    return true;
}

static void *f_malloc(void *user, size_t size) {
    faulty *f = user;
    if (refuse(f))
        return NULL;
    void *p = malloc(size);
    if (p)
        f->live++;
    return p;
}

static void *f_realloc(void *user, void *p, size_t size) {
    return refuse(user) ? NULL : realloc(p, size);
}

static void f_free(void *user, void *p) {
    faulty *f = user;
    f->live--;
    free(p);
}

static qd_status sphere_body(qd_ctx *ctx) {
    const double a = 2, n = 2, c = cos(0.5);
    const qd_expr *V = qd_read(ctx, "-3*step(2 - r)", NULL, NULL);
    qd_scatter *s = qd_scatter_new(ctx, V, qd_symbol(ctx, "r"), 0);
    if (!s)
        return qd_ctx_status(ctx);
    qd_scatter_path p;
    qd_scatter_section x;
    qd_status st = qd_scatter_deflect(ctx, s, 1, 1, &p);
    if (st == QD_OK) {
        assert_true(fabs(-p.chi - 2 * (asin(1 / a) - asin(1 / (n * a)))) < 1e-11);
        st = qd_scatter_section_at(ctx, s, 1, 1, &x);
    }
    if (st == QD_OK) {
        double want = n * n * a * a * (n * c - 1) * (n - c) / (4 * c * pow(1 + n * n - 2 * n * c, 2));
        assert_int_equal(x.nbranch, 1);
        assert_true(fabs(x.sigma - want) < 1e-7 * want);
    }
    qd_scatter_free(s);
    return st;
}

static void test_sphere(void **state) {
    (void)state;
    long runs = 0;
    for (long k = 1;; k++, runs++) {
        faulty f = {0, k, 0, false};
        qd_allocator al = {f_malloc, f_realloc, f_free, &f};
        qd_ctx *ctx = qd_ctx_new_with(&al);
        qd_status st = ctx ? sphere_body(ctx) : QD_ERR_NOMEM;
        qd_status recorded = ctx ? qd_ctx_status(ctx) : QD_ERR_NOMEM;
        qd_ctx_free(ctx);
        if (f.live != 0)
            fail_msg("allocation %ld failed: %ld blocks leaked", k, f.live);
        if (st != QD_OK && (st != QD_ERR_NOMEM || recorded != QD_ERR_NOMEM || !f.failed))
            fail_msg("allocation %ld failed: status %s, recorded %s", k, qd_status_str(st),
                     qd_status_str(recorded));
        if (st == QD_OK && recorded == QD_ERR_NOMEM)
            fail_msg("allocation %ld failed: success, but out of memory recorded", k);
        if (!f.failed) {
            assert_int_equal(st, QD_OK);
            break;
        }
    }
    printf("refracting sphere: %ld runs\n", runs);
    assert_true(runs > 5);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_sphere),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

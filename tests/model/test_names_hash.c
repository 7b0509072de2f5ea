/*
 * tests/model/test_names_hash.c - the model's name table (src/model/names.c):
 * every one of many names is found, and finding a name costs a bounded
 * number of probes whatever the number of names (the O(n) parse of issue
 * 30: 32k definitions took 7.7 s when each lookup scanned every name).
 *
 * No timing: the property asserted is the count of table slots looked at
 * (qd__mdl_name_probes), which a linear scan would make grow with n^2.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "qdot/qdot.h"
#include "qdot/model.h"
#include "model/parser.h"

/* A model with n parameters p0..p(n-1) and n definitions d0..d(n-1), each
 * d_i = d_(i-1) + p_i, and V = d_(n-1). */
static char *chain_text(size_t n) {
    size_t cap = 64 + n * 64;
    char *s = malloc(cap);
    assert_non_null(s);
    size_t k = (size_t)snprintf(s, cap, "coordinates q\nparameters ");
    for (size_t i = 0; i < n; i++)
        k += (size_t)snprintf(s + k, cap - k, "%sp%zu = %zu", i ? ", " : "", i, i + 1);
    k += (size_t)snprintf(s + k, cap - k, "\nd0 = q*p0\n");
    for (size_t i = 1; i < n; i++)
        k += (size_t)snprintf(s + k, cap - k, "d%zu = d%zu + p%zu\n", i, i - 1, i);
    snprintf(s + k, cap - k, "T = q'^2/2\nV = d%zu\n", n - 1);
    return s;
}

static unsigned long probes_to_parse(size_t n) {
    qd_ctx *ctx = qd_ctx_new();
    char *text = chain_text(n);
    qd_diag d;
    memset(&d, 0, sizeof d);
    unsigned long before = qd__mdl_name_probes;
    qd_model *m = qd_model_parse(ctx, text, &d);
    unsigned long used = qd__mdl_name_probes - before;
    if (!m)
        fail_msg("%zu:%zu: %s", d.line, d.col, d.message);
    /* every name is found, with its own value */
    char name[32];
    for (size_t i = 0; i < n; i++) {
        snprintf(name, sizeof name, "d%zu", i);
        assert_non_null(qd_model_definition(m, name));
        assert_true(qd__mdl_find_def(m, name, strlen(name)) == &m->defs[i]);
        snprintf(name, sizeof name, "p%zu", i);
        long j = qd__mdl_names_find(m, QD_MDL_NAME_PARAM, name, strlen(name));
        assert_int_equal(j, (long)i);
        assert_string_equal(qd_expr_name(qd_model_param(m, (size_t)j)), name);
        double x;
        assert_int_equal(qd_model_param_number(m, (size_t)j, &x), QD_OK);
        assert_true(x == (double)(i + 1));
    }
    assert_null(qd_model_definition(m, "d"));
    snprintf(name, sizeof name, "d%zu", n);
    assert_null(qd_model_definition(m, name));
    qd_model_free(m);
    free(text);
    qd_ctx_free(ctx);
    return used;
}

/* Probes per name stay bounded: 8 times the names cost at most about 8
 * times the probes (a linear scan would cost 64 times). */
static void test_lookup_cost_is_linear(void **state) {
    (void)state;
    unsigned long a = probes_to_parse(500), b = probes_to_parse(4000);
    print_message("probes: %lu for 500 names, %lu for 4000\n", a, b);
    assert_true(a > 0);
    assert_true(b < 12 * a);
    assert_true(b < 40ul * 2 * 4000); /* a few probes per lookup */
}

/* Names that share a long prefix, and a name that differs only in its last
 * byte, are told apart. */
static void test_similar_names(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    char text[4096];
    size_t k = (size_t)snprintf(text, sizeof text, "coordinates q\nparameters ");
    const char *pre = "a_long_common_prefix_of_a_parameter_name_";
    for (int i = 0; i < 40; i++)
        k += (size_t)snprintf(text + k, sizeof text - k, "%s%s%d = %d", i ? ", " : "", pre, i,
                              i + 1);
    snprintf(text + k, sizeof text - k, "\nT = q'^2/2\n");
    qd_diag d;
    qd_model *m = qd_model_parse(ctx, text, &d);
    assert_non_null(m);
    char name[96];
    for (int i = 0; i < 40; i++) {
        snprintf(name, sizeof name, "%s%d", pre, i);
        assert_int_equal(qd__mdl_names_find(m, QD_MDL_NAME_PARAM, name, strlen(name)), i);
    }
    assert_int_equal(qd__mdl_names_find(m, QD_MDL_NAME_PARAM, pre, strlen(pre)), -1);
    assert_int_equal(qd__mdl_names_find(m, QD_MDL_NAME_COORD, "q", 1), 0);
    assert_int_equal(qd__mdl_names_find(m, QD_MDL_NAME_PARAM, "q", 1), -1);
    qd_model_free(m);
    qd_ctx_free(ctx);
}

/* A statement added to a model that fails leaves no name behind; one that
 * succeeds is found. */
static void test_added_statement_names(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_diag d;
    qd_model *m = qd_model_parse(ctx, "coordinates q\nparameters k = 2\nT = q'^2/2\n", &d);
    assert_non_null(m);
    assert_int_not_equal(qd_model_add_statement(m, "w = k*q + nosuch", &d), QD_OK);
    assert_null(qd_model_definition(m, "w"));
    assert_int_equal(qd_model_add_statement(m, "u = k*q", &d), QD_OK);
    assert_non_null(qd_model_definition(m, "u"));
    assert_null(qd_model_definition(m, "w"));
    assert_int_equal(qd_model_add_statement(m, "w = 3*q", &d), QD_OK);
    assert_non_null(qd_model_definition(m, "w"));
    qd_model_free(m);
    qd_ctx_free(ctx);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_lookup_cost_is_linear),
        cmocka_unit_test(test_similar_names),
        cmocka_unit_test(test_added_statement_names),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

/*
 * tests/cli/test_json_cli.c - the CLI's JSON writer (src/json/json.c) says why a
 * document could not be written (issue 30): a buffer that ran out of memory
 * is "out of memory", not "a non-finite number" as it once was; a NaN is a
 * non-finite number.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "qdot/json.h"

/* An allocator that refuses everything: the first append fails. */
static void *no_malloc(void *user, size_t size) { (void)user; (void)size; return NULL; }
static void *no_realloc(void *user, void *p, size_t size) {
    (void)user; (void)p; (void)size;
    return NULL;
}
static void plain_free(void *user, void *p) { (void)user; free(p); }

static void test_out_of_memory(void **state) {
    (void)state;
    const qd_allocator none = {no_malloc, no_realloc, plain_free, NULL};
    qd_buf b = QD_BUF_INIT;
    b.alloc = &none;
    qd_json j;
    qd_json_init(&j, &b);
    qd_json_begin_object(&j);
    qd_json_key(&j, "t");
    assert_true(qd_json_number(&j, 1.5));
    qd_json_end_object(&j);
    assert_false(qd_json_ok(&j));
    assert_string_equal(qd_json_why(&j), "out of memory");
    qd_buf_free(&b);
}

static void test_nonfinite(void **state) {
    (void)state;
    qd_buf b = QD_BUF_INIT;
    qd_json j;
    qd_json_init(&j, &b);
    qd_json_begin_object(&j);
    qd_json_key(&j, "t");
    assert_false(qd_json_number(&j, NAN));
    qd_json_end_object(&j);
    assert_false(qd_json_ok(&j));
    assert_non_null(strstr(qd_json_why(&j), "non-finite"));
    qd_buf_free(&b);
}

/* A 2 x 3 matrix stored by rows is written row by row; a NaN entry is refused. */
static void test_matrix(void **state) {
    (void)state;
    const double x[6] = {1, 2, 3, 4, 5, 6.5};
    qd_buf b = QD_BUF_INIT;
    qd_json j;
    qd_json_init(&j, &b);
    qd_json_begin_object(&j);
    assert_true(qd_json_matrix(&j, "A", 2, 3, x));
    qd_json_end_object(&j);
    assert_true(qd_json_ok(&j));
    assert_non_null(strstr(b.s, "[[1, 2, 3], [4, 5, 6.5]]"));
    qd_buf_free(&b);
    const double bad[1] = {NAN};
    qd_buf c = QD_BUF_INIT;
    qd_json_init(&j, &c);
    assert_false(qd_json_matrix(&j, NULL, 1, 1, bad));
    qd_buf_free(&c);
}

static int count(const char *s, const char *what) {
    int n = 0;
    for (const char *p = strstr(s, what); p; p = strstr(p + 1, what))
        n++;
    return n;
}

/* A vector is one flat array; a frequency: w^2 = 4 is omega 2 and period
 * 2 pi / 2 = pi; w^2 = -1 (a growing mode) has neither, w^2 = 0 no period. */
static void test_vector_frequency(void **state) {
    (void)state;
    const double x[3] = {1, -2.5, 0};
    qd_buf b = QD_BUF_INIT;
    qd_json j;
    qd_json_init(&j, &b);
    qd_json_begin_array(&j);
    assert_true(qd_json_vector(&j, NULL, 3, x));
    qd_json_begin_object(&j);
    qd_json_frequency(&j, 4);
    qd_json_end_object(&j);
    qd_json_begin_object(&j);
    qd_json_frequency(&j, -1);
    qd_json_end_object(&j);
    qd_json_begin_object(&j);
    qd_json_frequency(&j, 0);
    qd_json_end_object(&j);
    qd_json_end_array(&j);
    assert_true(qd_json_ok(&j));
    const char *s = qd_buf_str(&b);
    assert_non_null(strstr(s, "1,") && strstr(s, "-2.5,"));
    assert_non_null(strstr(s, "\"omega\": 2,"));
    assert_non_null(strstr(s, "\"period\": 3.14159265358979"));
    assert_int_equal(count(s, "\"omega\": null"), 1);  /* w2 = -1 */
    assert_int_equal(count(s, "\"omega\": 0"), 1);     /* w2 = 0 */
    assert_int_equal(count(s, "\"period\": null"), 2); /* w2 = -1 and 0 */
    qd_buf_free(&b);
}

static void test_whole(void **state) {
    (void)state;
    qd_buf b = QD_BUF_INIT;
    qd_json j;
    qd_json_init(&j, &b);
    qd_json_begin_object(&j);
    qd_json_key(&j, "t");
    assert_true(qd_json_number(&j, 2));
    qd_json_end_object(&j);
    assert_true(qd_json_ok(&j));
    assert_non_null(strstr(qd_buf_str(&b), "\"t\""));
    qd_buf_free(&b);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_out_of_memory),
        cmocka_unit_test(test_nonfinite),
        cmocka_unit_test(test_matrix),
        cmocka_unit_test(test_vector_frequency),
        cmocka_unit_test(test_whole),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

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
#include "qdot/read.h"

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

/* A document of the writer's layout: members name[i] = value[i] (strings). */
static void doc(qd_buf *b, size_t n, const char *const *name, const char *const *value) {
    qd_json j;
    qd_json_init(&j, b);
    qd_json_begin_object(&j);
    for (size_t i = 0; i < n; i++) {
        qd_json_key(&j, name[i]);
        qd_json_string(&j, value[i]);
    }
    qd_json_end_object(&j);
}

/* qd_json_add_model (issue 31): "model" put first is the document the writer
 * makes with it first, for an object with members and an empty one; a
 * document with its model first already, or not an object, is untouched; a
 * name with a quote is escaped; memory that runs out fails the document. */
static void test_add_model(void **state) {
    (void)state;
    const char *k[] = {"model", "a", "b"}, *v[] = {"dir/m \"1\".qd", "x", "y"};
    qd_buf got = QD_BUF_INIT, want = QD_BUF_INIT;
    doc(&got, 2, k + 1, v + 1);
    doc(&want, 3, k, v);
    assert_int_equal(qd_json_add_model(&got, v[0]), QD_OK);
    assert_string_equal(qd_buf_str(&got), qd_buf_str(&want));
    assert_int_equal(qd_json_add_model(&got, "other.qd"), QD_OK); /* it has one */
    assert_string_equal(qd_buf_str(&got), qd_buf_str(&want));
    qd_buf_clear(&got);
    qd_buf_clear(&want);
    doc(&got, 0, k, v);
    doc(&want, 1, k, v);
    assert_int_equal(qd_json_add_model(&got, v[0]), QD_OK);
    assert_string_equal(qd_buf_str(&got), qd_buf_str(&want));
    qd_buf_clear(&got);
    qd_buf_puts(&got, "[1, 2]");
    assert_int_equal(qd_json_add_model(&got, v[0]), QD_ERR_ARG);
    assert_string_equal(qd_buf_str(&got), "[1, 2]");
    qd_buf_free(&got);
    qd_buf_free(&want);
    const qd_allocator none = {no_malloc, no_realloc, plain_free, NULL};
    qd_buf b = QD_BUF_INIT;
    qd_buf_puts(&b, "{}");
    b.alloc = &none; /* the new document cannot be made */
    assert_int_equal(qd_json_add_model(&b, "m.qd"), QD_ERR_NOMEM);
    assert_true(b.failed);
    qd_buf_free(&b);
}

/* qd_json_expr_result: d(x^2 sin y)/dx = 2 x sin y, and the "result" text
 * reads back to the derivative's own node (hash-consing: the same pointer). */
static void test_expr_result(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    const qd_expr *e = qd_read(ctx, "x^2*sin(y)", NULL, NULL);
    const qd_expr *d = qd_diff(ctx, e, qd_lookup(ctx, "x"));
    const char *vars[] = {"x"};
    qd_buf b = QD_BUF_INIT;
    assert_int_equal(qd_json_expr_result(ctx, "diff", "x^2*sin(y)", 1, vars, d, &b), QD_OK);
    const char *s = qd_buf_str(&b), *r = strstr(s, "\"result\": \"");
    assert_non_null(strstr(s, "\"operation\": \"diff\""));
    assert_non_null(strstr(s, "\"variables\": [\"x\"]"));
    assert_non_null(r);
    char text[64] = "";
    r += strlen("\"result\": \"");
    memcpy(text, r, (size_t)(strchr(r, '"') - r));
    assert_ptr_equal(qd_read(ctx, text, NULL, NULL), d);
    assert_ptr_equal(d, qd_read(ctx, "2*x*sin(y)", NULL, NULL));
    qd_buf_free(&b);
    qd_ctx_free(ctx);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_out_of_memory),
        cmocka_unit_test(test_nonfinite),
        cmocka_unit_test(test_matrix),
        cmocka_unit_test(test_vector_frequency),
        cmocka_unit_test(test_whole),
        cmocka_unit_test(test_add_model),
        cmocka_unit_test(test_expr_result),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

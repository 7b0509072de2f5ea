/*
 * tests/model/test_diag.c - the error record both readers leave in the
 * context (qd_ctx_diag) and the one renderer, qd_diag_format.
 *
 * Asserted as data: status, subject, reason and the byte range, never the
 * English of the message.  The cases are the review's bad input (issue 11):
 * 10,000 nested brackets (was a stack overflow in the model parser), a byte
 * that is not UTF-8 and a Greek letter in a name (was "unexpected an
 * unexpected character"), and the unknown-statement hint that left out
 * `reaction` and `rolls`.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <stdlib.h>
#include <string.h>

#include "qdot/qdot.h"

/* Parse text, which must fail; the context's record, checked to be the copy
 * qd_model_parse hands back. */
static qd_diag parse_fail(qd_ctx *ctx, const char *text) {
    qd_diag d;
    memset(&d, 0, sizeof d);
    qd_model *m = qd_model_parse(ctx, text, &d);
    if (m)
        fail_msg("parsed but must fail: %.60s", text);
    const qd_diag *c = qd_ctx_diag(ctx);
    assert_int_equal(c->status, qd_ctx_status(ctx));
    assert_int_equal(d.status, c->status);
    assert_int_equal(d.offset, c->offset);
    assert_int_equal(d.length, c->length);
    assert_string_equal(d.message, c->message);
    assert_string_equal(d.hint, c->hint);
    return d;
}

/* "coordinates x\nT = x'^2/2\nV = " then depth '(' ... ')' around x. */
static char *nested(size_t depth) {
    const char *head = "coordinates x\nT = x'^2/2\nV = ";
    size_t h = strlen(head);
    char *s = malloc(h + 2 * depth + 3);
    assert_non_null(s);
    memcpy(s, head, h);
    memset(s + h, '(', depth);
    s[h + depth] = 'x';
    memset(s + h + depth + 1, ')', depth);
    strcpy(s + h + 2 * depth + 1, "\n");
    return s;
}

/* 10,000 brackets: a located error at the bracket one past the limit, as the
 * kernel's reader gives, instead of a crash; 255 still parse. */
static void deep_nesting(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    char *deep = nested(10000);
    qd_diag d = parse_fail(ctx, deep);
    assert_int_equal(d.status, QD_ERR_PARSE);
    assert_int_equal(d.subject, QD_SUBJECT_TEXT);
    assert_int_equal(d.reason, QD_REASON_TOO_DEEP);
    assert_true(d.located);
    size_t v = (size_t)(strchr(deep, 'V') - deep) + 4; /* the first '(' */
    /* the first factor is depth 1; each '(' one deeper: the one at depth
     * QD_MAX_NEST + 1 is bracket number QD_MAX_NEST */
    assert_int_equal(d.offset, v + QD_MAX_NEST);
    assert_int_equal(deep[d.offset], '(');
    assert_int_equal(d.line, 3);
    assert_int_equal(d.col, d.offset - (v - 4) + 1);
    free(deep);
    qd_ctx_clear_error(ctx);

    char *ok = nested(QD_MAX_NEST - 1);
    qd_model *m = qd_model_parse(ctx, ok, NULL);
    assert_non_null(m);
    /* V = x under all the brackets: the parse kept the expression */
    assert_ptr_equal(qd_model_potential(m), qd_lookup(ctx, "x"));
    qd_model_free(m);
    free(ok);

    /* signs nest too: - - - ... x, one sign past the limit */
    size_t n = QD_MAX_NEST + 10;
    char *signs = malloc(2 * n + 40);
    assert_non_null(signs);
    strcpy(signs, "coordinates x\nT = x'^2/2\nV = ");
    for (size_t i = 0; i < n; i++)
        strcat(signs, "-");
    strcat(signs, "x\n");
    d = parse_fail(ctx, signs);
    assert_int_equal(d.reason, QD_REASON_TOO_DEEP);
    assert_int_equal(signs[d.offset], '-');
    free(signs);
    qd_ctx_free(ctx);
}

/* The kernel's reader records the same kind of error the same way. */
static void kernel_reader_record(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    char text[2 * QD_MAX_NEST + 8];
    memset(text, '(', QD_MAX_NEST + 2);
    strcpy(text + QD_MAX_NEST + 2, "x");
    qd_read_error err;
    assert_null(qd_read(ctx, text, NULL, &err));
    const qd_diag *d = qd_ctx_diag(ctx);
    assert_int_equal(d->status, QD_ERR_PARSE);
    assert_int_equal(d->subject, QD_SUBJECT_TEXT);
    assert_int_equal(d->reason, QD_REASON_TOO_DEEP);
    assert_true(d->located);
    assert_int_equal(err.offset, d->offset);
    assert_int_equal(text[d->offset], '(');
    qd_ctx_clear_error(ctx);

    /* a bad byte in a state string: its offset and one byte */
    assert_null(qd_read(ctx, "x + \xff", NULL, &err));
    assert_int_equal(qd_ctx_diag(ctx)->reason, QD_REASON_BAD_BYTE);
    assert_int_equal(err.offset, 4);
    assert_int_equal(err.length, 1);
    assert_non_null(strstr(err.message, "0xff"));
    qd_ctx_free(ctx);
}

/* A byte that is not UTF-8 and a Greek letter: named, located, one
 * character wide (theta is two bytes). */
static void bad_bytes(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    const char *ff = "coordinates x\xff\nT = x'^2/2\n";
    qd_diag d = parse_fail(ctx, ff);
    assert_int_equal(d.reason, QD_REASON_BAD_BYTE);
    assert_int_equal(d.offset, 13);
    assert_int_equal(d.length, 1);
    assert_int_equal(d.line, 1);
    assert_int_equal(d.col, 14);
    assert_non_null(strstr(d.message, "byte 0xff"));
    assert_null(strstr(d.message, "unexpected an"));
    qd_ctx_clear_error(ctx);

    const char *theta = "coordinates x\nparameters \xce\xb8 = 1\nT = x'^2/2\n";
    d = parse_fail(ctx, theta);
    assert_int_equal(d.reason, QD_REASON_BAD_BYTE);
    assert_int_equal(d.offset, 25);
    assert_int_equal(d.length, 2);
    assert_int_equal(d.line, 2);
    assert_int_equal(d.col, 12);
    assert_non_null(strstr(d.message, "U+03B8"));
    qd_ctx_clear_error(ctx);

    /* a truncated UTF-8 sequence is not a character: one bad byte */
    d = parse_fail(ctx, "coordinates x\nT = x'^2/2 \xce\n");
    assert_int_equal(d.length, 1);
    assert_non_null(strstr(d.message, "0xce"));
    qd_ctx_free(ctx);
}

/* The hint lists every statement keyword the parser knows. */
static void unknown_statement_hint(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_diag d = parse_fail(ctx, "coordinates x\nT = x'^2/2\nfrobnicate x\n");
    assert_int_equal(d.line, 3);
    assert_int_equal(d.col, 1);
    assert_int_equal(d.length, 10);
    static const char *const words[] = {"coordinates", "parameters", "functions", "particle",
                                        "force", "initial", "constraint", "body", "torque",
                                        "rolls", "reaction", "momenta", "symmetry", "integral",
                                        "impulse", "impact", "prescribe", "speeds"};
    for (size_t i = 0; i < sizeof words / sizeof words[0]; i++)
        if (!strstr(d.hint, words[i]))
            fail_msg("the hint leaves out %s: %s", words[i], d.hint);
    qd_ctx_free(ctx);
}

/* The renderer: FILE:LINE:COL, the line, the caret one column per
 * character, the hint; a long line cut around the caret. */
static void renderer(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    const char *theta = "coordinates x\nparameters \xce\xb8 = 1\nT = x'^2/2\n";
    qd_diag d = parse_fail(ctx, theta);
    qd_buf b = QD_BUF_INIT;
    qd_diag_format(&d, "m.qd", theta, &b);
    const char *s = qd_buf_str(&b);
    assert_non_null(strstr(s, "m.qd:2:12: error: "));
    assert_non_null(strstr(s, "\n  parameters \xce\xb8 = 1\n             ^\n"));
    assert_non_null(strstr(s, "\n  hint: "));
    qd_buf_free(&b);
    qd_ctx_clear_error(ctx);

    char *deep = nested(10000);
    d = parse_fail(ctx, deep);
    b = (qd_buf)QD_BUF_INIT;
    qd_diag_format(&d, "deep.qd", deep, &b);
    assert_true(b.len < 600); /* not the 20,000-byte line */
    const char *line = strstr(qd_buf_str(&b), "\n  ...") + 3;
    const char *caret = strchr(line, '\n') + 1;
    assert_int_equal(strchr(caret, '^') - caret, 2 + 3 + 50); /* indent, "...", the offset in the window */
    qd_buf_free(&b);
    free(deep);

    /* a record with no location: FILE: error: and the hint */
    qd_diag plain = {.status = QD_ERR_SINGULAR, .message = "the mass matrix is singular",
                     .hint = "give it inertia"};
    b = (qd_buf)QD_BUF_INIT;
    qd_diag_format(&plain, "m.qd", theta, &b);
    assert_string_equal(qd_buf_str(&b),
                        "m.qd: error: the mass matrix is singular\n  hint: give it inertia\n");
    qd_buf_free(&b);
    qd_ctx_free(ctx);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(deep_nesting),   cmocka_unit_test(kernel_reader_record),
        cmocka_unit_test(bad_bytes),      cmocka_unit_test(unknown_statement_hint),
        cmocka_unit_test(renderer),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

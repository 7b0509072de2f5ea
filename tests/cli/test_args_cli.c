/*
 * tests/cli/test_args_cli.c - the option table parser (cli/args.c, issue 31):
 * values land in their fields, a table shared by several commands at its
 * base, lists repeat and nothing else does, a misspelt option or choice gets
 * "did you mean", and --help's usage lists every option with its line.
 */
#define _POSIX_C_SOURCE 200809L /* dup, dup2, fileno */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "cli.h"

typedef struct shared_args {
    const char *t_end;
    cli_list sets;
} shared_args;

typedef struct cmd_args {
    bool quiet;
    const char *out;
    const char *format;
    size_t n;
    shared_args sim;
    int calls;
    uint64_t seed;
    double tol;
    const char *mode;
} cmd_args;

static int count_call(const char *value, void *args) {
    cmd_args *a = args;
    a->calls += value && !strcmp(value, "bad") ? 100 : 1;
    return value && !strcmp(value, "bad") ? QD_EXIT_USAGE : QD_EXIT_OK;
}

static const char *const formats[] = {"text", "json", "latex", NULL};
static const char *const modes[] = {"matrix", "columns", NULL};

static const cli_opt cmd_opts[] = {
    {"--quiet", NULL, CLI_FLAG, offsetof(cmd_args, quiet), NULL, "print nothing", NULL, NULL},
    {"--out", "-o", CLI_TEXT, offsetof(cmd_args, out), "FILE", "write to FILE", NULL, NULL},
    {"--format", NULL, CLI_CHOICE, offsetof(cmd_args, format), "NAME", "output format", formats,
     NULL},
    {"--n", NULL, CLI_COUNT, offsetof(cmd_args, n), "N", "how many", NULL, NULL},
    {"--mark", NULL, CLI_CALL, 0, "X", "the command's own reader", NULL, count_call},
    CLI_OPT_IN(cmd_args, "--seed", CLI_WHOLE, seed, "S", "a seed", 0, 9007199254740992),
    CLI_OPT_IN(cmd_args, "--tol", CLI_RANGE, tol, "X", "a tolerance", 1e-14, 0.1),
    {"--mode", NULL, CLI_MAYBE, offsetof(cmd_args, mode), "[columns]", "a value that may be left "
     "out", modes, NULL},
    {NULL, NULL, CLI_FLAG, 0, NULL, NULL, NULL, NULL},
};

static const cli_opt shared_opts[] = {
    {"--t-end", NULL, CLI_TEXT, offsetof(shared_args, t_end), "T", "end time", NULL, NULL},
    {"--set", NULL, CLI_LIST, offsetof(shared_args, sets), "NAME=VALUE", "fix a parameter",
     NULL, NULL},
    {NULL, NULL, CLI_FLAG, 0, NULL, NULL, NULL, NULL},
};

static const cli_group groups[] = {{shared_opts, offsetof(cmd_args, sim)}, {NULL, 0}};

static const cli_spec spec = {"demo", "FILE [options]", "A command of the test.", cmd_opts,
                              groups, 1, 1, "FILE", false};

/* Run cli_parse on a NULL-terminated argument list with stderr captured. */
static int parse(const cli_spec *s, cmd_args *a, const char **pos, char *err, size_t nerr,
                 const char *first, ...) {
    char *argv[32];
    int argc = 0;
    va_list ap;
    va_start(ap, first);
    for (const char *x = first; x && argc < 32; x = va_arg(ap, const char *))
        argv[argc++] = (char *)x;
    va_end(ap);
    fflush(stderr);
    FILE *tmp = tmpfile();
    assert_non_null(tmp);
    int saved = dup(fileno(stderr));
    dup2(fileno(tmp), fileno(stderr));
    memset(a, 0, sizeof *a);
    int rc = cli_parse(s, argc, argv, a, pos);
    fflush(stderr);
    dup2(saved, fileno(stderr));
    close(saved);
    rewind(tmp);
    size_t n = fread(err, 1, nerr - 1, tmp);
    err[n] = 0;
    fclose(tmp);
    return rc;
}

static void test_values(void **state) {
    (void)state;
    cmd_args a;
    const char *pos[1];
    char err[1024];
    int rc = parse(&spec, &a, pos, err, sizeof err, "m.qd", "--quiet", "-o", "x.csv",
                   "--format=json", "--n", "12", "--t-end", "2*pi", "--set", "m=1", "--set=g=9.8",
                   "--mark", "a", (const char *)NULL);
    assert_int_equal(rc, QD_EXIT_OK);
    assert_string_equal(err, "");
    assert_string_equal(pos[0], "m.qd");
    assert_true(a.quiet);
    assert_string_equal(a.out, "x.csv");
    assert_string_equal(a.format, "json");
    assert_int_equal(a.n, 12);
    assert_string_equal(a.sim.t_end, "2*pi"); /* the shared table's field, at its base */
    assert_int_equal(a.sim.sets.n, 2);
    assert_string_equal(a.sim.sets.items[0], "m=1");
    assert_string_equal(a.sim.sets.items[1], "g=9.8");
    assert_int_equal(a.calls, 1); /* the command's reader, called with its value */
    /* the bounds are taken: 2^53 is the last whole number a double holds exactly */
    assert_int_equal(parse(&spec, &a, pos, err, sizeof err, "m.qd", "--seed", "9007199254740992",
                           "--tol", "1e-14", (const char *)NULL), QD_EXIT_OK);
    assert_true(a.seed == UINT64_C(9007199254740992));
    assert_true(a.tol == 1e-14);
    /* a value that may be left out: the next word only when it is a choice */
    assert_int_equal(parse(&spec, &a, pos, err, sizeof err, "--mode", "m.qd", (const char *)NULL),
                     QD_EXIT_OK);
    assert_string_equal(a.mode, "matrix");
    assert_string_equal(pos[0], "m.qd");
    assert_int_equal(parse(&spec, &a, pos, err, sizeof err, "m.qd", "--mode", "columns",
                           (const char *)NULL), QD_EXIT_OK);
    assert_string_equal(a.mode, "columns");
    assert_int_equal(parse(&spec, &a, pos, err, sizeof err, "m.qd", "--mode=colums",
                           (const char *)NULL), QD_EXIT_USAGE);
    assert_non_null(strstr(err, "did you mean 'columns'?"));
}

static void test_refusals(void **state) {
    (void)state;
    cmd_args a;
    const char *pos[1];
    char err[1024];
    assert_int_equal(parse(&spec, &a, pos, err, sizeof err, "m.qd", "--tend", "3",
                           (const char *)NULL), QD_EXIT_USAGE);
    assert_non_null(strstr(err, "did you mean '--t-end'?"));
    assert_int_equal(parse(&spec, &a, pos, err, sizeof err, "m.qd", "--out", "a", "-o", "b",
                           (const char *)NULL), QD_EXIT_USAGE);
    assert_non_null(strstr(err, "given twice"));
    assert_int_equal(parse(&spec, &a, pos, err, sizeof err, "m.qd", "--format", "jsn",
                           (const char *)NULL), QD_EXIT_USAGE);
    assert_non_null(strstr(err, "did you mean 'json'?"));
    assert_int_equal(parse(&spec, &a, pos, err, sizeof err, "m.qd", "--n", "0",
                           (const char *)NULL), QD_EXIT_USAGE);
    assert_non_null(strstr(err, "whole number"));
    assert_int_equal(parse(&spec, &a, pos, err, sizeof err, "m.qd", "--n", "3x",
                           (const char *)NULL), QD_EXIT_USAGE);
    assert_int_equal(parse(&spec, &a, pos, err, sizeof err, "m.qd", "--quiet=yes",
                           (const char *)NULL), QD_EXIT_USAGE);
    assert_non_null(strstr(err, "takes no value"));
    assert_int_equal(parse(&spec, &a, pos, err, sizeof err, "m.qd", "--t-end",
                           (const char *)NULL), QD_EXIT_USAGE);
    assert_non_null(strstr(err, "needs a value"));
    assert_int_equal(parse(&spec, &a, pos, err, sizeof err, "--quiet", (const char *)NULL),
                     QD_EXIT_USAGE);
    assert_non_null(strstr(err, "FILE is missing"));
    assert_int_equal(parse(&spec, &a, pos, err, sizeof err, "a.qd", "b.qd", (const char *)NULL),
                     QD_EXIT_USAGE);
    assert_non_null(strstr(err, "unexpected 'b.qd'"));
    assert_int_equal(parse(&spec, &a, pos, err, sizeof err, "m.qd", "--mark", "a", "--mark", "b",
                           (const char *)NULL), QD_EXIT_USAGE); /* only a list repeats */
    assert_int_equal(parse(&spec, &a, pos, err, sizeof err, "m.qd", "--mark", "bad",
                           (const char *)NULL), QD_EXIT_USAGE);
    const char *out_of_range[][2] = {{"--seed", "1.5"}, {"--seed", "-1"},
                                     {"--seed", "9007199254740993.5"}, {"--tol", "0.2"},
                                     {"--tol", "0"}, {"--tol", "nan"}, {"--tol", "1e-3x"}};
    for (size_t k = 0; k < sizeof out_of_range / sizeof out_of_range[0]; k++) {
        assert_int_equal(parse(&spec, &a, pos, err, sizeof err, "m.qd", out_of_range[k][0],
                               out_of_range[k][1], (const char *)NULL), QD_EXIT_USAGE);
        assert_non_null(strstr(err, out_of_range[k][0]));
        assert_non_null(strstr(err, "from"));
    }
}

/* A command whose positionals are expressions: "-x" is one. */
static void test_expressions(void **state) {
    (void)state;
    cli_spec ex = spec;
    ex.expressions = true;
    ex.min_pos = 1;
    ex.max_pos = 2;
    ex.pos_name = "EXPR";
    cmd_args a;
    const char *pos[2];
    char err[1024];
    assert_int_equal(parse(&ex, &a, pos, err, sizeof err, "-x^2", "-o", "f", "-1",
                           (const char *)NULL), QD_EXIT_OK);
    assert_string_equal(pos[0], "-x^2");
    assert_string_equal(pos[1], "-1");
    assert_string_equal(a.out, "f");
}

static void test_usage(void **state) {
    (void)state;
    FILE *tmp = tmpfile();
    assert_non_null(tmp);
    cli_usage(&spec, tmp);
    rewind(tmp);
    char text[4096];
    size_t n = fread(text, 1, sizeof text - 1, tmp);
    text[n] = 0;
    fclose(tmp);
    assert_non_null(strstr(text, "usage: qdot demo FILE [options]"));
    /* every option of both tables, with its own line of help */
    const cli_opt *tables[] = {cmd_opts, shared_opts};
    for (size_t t = 0; t < 2; t++)
        for (const cli_opt *o = tables[t]; o->name; o++) {
            const char *at = strstr(text, o->name);
            assert_non_null(at);
            const char *eol = strchr(at, '\n');
            assert_non_null(strstr(at, o->help));
            assert_true(strstr(at, o->help) < eol);
        }
    assert_non_null(strstr(text, "(text, json, latex)"));
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_values),
        cmocka_unit_test(test_refusals),
        cmocka_unit_test(test_expressions),
        cmocka_unit_test(test_usage),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

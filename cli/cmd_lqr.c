/*
 * cli/cmd_lqr.c - `qdot lqr --A ... --B ... --weights "Q = ..., R = ..."`:
 * the LQR gain of a state-space system given as matrices (qd_care_solve).
 * `qdot linearize --lqr` does the same on the A and B of a model.
 */
#include "cli.h"
#include "lqr_cli.h"
#include "model_cli.h"

#include <stdlib.h>
#include <string.h>

static const char usage_text[] =
    "usage: qdot lqr --A \"[[...], ...]\" --B \"[[...], ...]\" --weights \"Q = ..., R = ...\" "
    "[--format text|json|c]";

typedef struct lqr_args {
    const char *A, *B, *weights;
    int format;
} lqr_args;

typedef struct lqr_run {
    double *A, *B, *Q, *R;
    size_t n, m;
    const char **names; /* x1..xn, then u1..um, in store */
    char (*store)[24];
} lqr_run;

static int parse_args(int argc, char **argv, lqr_args *a) {
    static const char *const formats[] = {"text", "json", "c", NULL};
    for (int i = 0; i < argc; i++) {
        const char *v;
        int rc;
        if ((v = cli_value(argc, argv, &i, "--A")))
            rc = cli_once("--A", &a->A, v);
        else if ((v = cli_value(argc, argv, &i, "--B")))
            rc = cli_once("--B", &a->B, v);
        else if ((v = cli_value(argc, argv, &i, "--weights")))
            rc = cli_once("--weights", &a->weights, v);
        else if ((v = cli_value(argc, argv, &i, "--format")))
            rc = cli_choice("--format", v, formats, &a->format);
        else
            rc = cli_bad_option(argv[i], usage_text);
        if (rc != QD_EXIT_OK)
            return rc;
    }
    if (a->A && a->B && a->weights)
        return QD_EXIT_OK;
    cli_diag_error("qdot lqr needs --A, --B and --weights\n%s", usage_text);
    return QD_EXIT_USAGE;
}

static int read_system(const lqr_args *a, lqr_run *r) {
    char err[200];
    size_t where, rows, cols;
    if (!cli_matrix_parse(a->A, &r->n, &cols, &r->A, err, sizeof err, &where))
        return cli_lqr_read_error("--A", a->A, err, where);
    if (cols != r->n) {
        cli_diag_error("--A is %zu by %zu; A must be square", r->n, cols);
        return QD_EXIT_USAGE;
    }
    if (!cli_matrix_parse(a->B, &rows, &r->m, &r->B, err, sizeof err, &where))
        return cli_lqr_read_error("--B", a->B, err, where);
    if (rows != r->n) {
        cli_diag_error("--B has %zu rows; it needs one per state, %zu", rows, r->n);
        return QD_EXIT_USAGE;
    }
    r->Q = malloc(r->n * r->n * sizeof *r->Q);
    r->R = malloc(r->m * r->m * sizeof *r->R);
    if (!r->Q || !r->R) {
        cli_diag_error("out of memory");
        return QD_EXIT_FAIL;
    }
    if (!cli_lqr_parse(a->weights, r->n, r->m, r->Q, r->R, err, sizeof err, &where))
        return cli_lqr_read_error("--weights", a->weights, err, where);
    return QD_EXIT_OK;
}

static int name_variables(lqr_run *r) {
    size_t total = r->n + r->m;
    r->names = malloc(total * sizeof *r->names);
    r->store = malloc(total * sizeof *r->store);
    if (!r->names || !r->store) {
        cli_diag_error("out of memory");
        return QD_EXIT_FAIL;
    }
    for (size_t k = 0; k < total; k++) {
        bool state = k < r->n;
        snprintf(r->store[k], sizeof r->store[k], "%c%zu", state ? 'x' : 'u',
                 state ? k + 1 : k - r->n + 1);
        r->names[k] = r->store[k];
    }
    return QD_EXIT_OK;
}

static void run_free(lqr_run *r) {
    free(r->names);
    free(r->store);
    free(r->A), free(r->B), free(r->Q), free(r->R);
}

int cli_cmd_lqr(int argc, char **argv) {
    lqr_args a = {0};
    lqr_run r = {0};
    qd_ctx *ctx = NULL;
    qd_care_result res = {0};
    int rc = parse_args(argc, argv, &a);
    if (rc == QD_EXIT_OK)
        rc = read_system(&a, &r);
    if (rc == QD_EXIT_OK)
        rc = name_variables(&r);
    if (rc == QD_EXIT_OK && !(ctx = qd_ctx_new())) {
        cli_diag_error("out of memory");
        rc = QD_EXIT_FAIL;
    }
    if (rc == QD_EXIT_OK && qd_care_solve(ctx, r.n, r.m, r.A, r.B, r.Q, r.R, &res) != QD_OK)
        rc = cli_diag_ctx(ctx);
    if (rc == QD_EXIT_OK &&
        !cli_lqr_print(stdout, &res, r.names, r.names + r.n, (cli_lqr_format)a.format)) {
        cli_diag_error("out of memory, or a number that is not finite, printing the design");
        rc = QD_EXIT_FAIL;
    }
    qd_care_result_free(&res);
    qd_ctx_free(ctx);
    run_free(&r);
    return rc;
}

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
    qd_matrix A, B;
    double *Q, *R;
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

static int read_system(qd_ctx *ctx, const lqr_args *a, lqr_run *r) {
    if (qd_matrix_read(ctx, a->A, &r->A) != QD_OK)
        return cli_lqr_error(ctx, "--A", a->A);
    if (r->A.cols != r->A.rows) {
        cli_diag_error("--A is %zu by %zu; A must be square", r->A.rows, r->A.cols);
        return QD_EXIT_USAGE;
    }
    if (qd_matrix_read(ctx, a->B, &r->B) != QD_OK)
        return cli_lqr_error(ctx, "--B", a->B);
    size_t n = r->A.rows, m = r->B.cols;
    if (r->B.rows != n) {
        cli_diag_error("--B has %zu rows; it needs one per state, %zu", r->B.rows, n);
        return QD_EXIT_USAGE;
    }
    r->Q = malloc(n * n * sizeof *r->Q);
    r->R = malloc(m * m * sizeof *r->R);
    if (!r->Q || !r->R) {
        cli_diag_error("out of memory");
        return QD_EXIT_FAIL;
    }
    if (qd_lqr_weights_read(ctx, a->weights, n, m, r->Q, r->R) != QD_OK)
        return cli_lqr_error(ctx, "--weights", a->weights);
    return QD_EXIT_OK;
}

int cli_cmd_lqr(int argc, char **argv) {
    lqr_args a = {0};
    lqr_run r = {0};
    qd_care_result res = {0};
    int rc = parse_args(argc, argv, &a);
    if (rc != QD_EXIT_OK)
        return rc;
    qd_ctx *ctx = qd_ctx_new();
    if (!ctx) {
        cli_diag_error("out of memory");
        return QD_EXIT_FAIL;
    }
    rc = read_system(ctx, &a, &r);
    if (rc == QD_EXIT_OK && qd_care_solve(ctx, r.A.rows, r.B.cols, r.A.a, r.B.a, r.Q, r.R,
                                          &res) != QD_OK)
        rc = cli_diag_ctx(ctx);
    if (rc == QD_EXIT_OK)
        rc = cli_lqr_print_design(stdout, NULL, &res, (cli_lqr_format)a.format);
    qd_care_result_free(&res);
    qd_matrix_free(&r.A);
    qd_matrix_free(&r.B);
    free(r.Q);
    free(r.R);
    qd_ctx_free(ctx);
    return rc;
}

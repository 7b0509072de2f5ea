/*
 * cli/cmd_lqr.c - `qdot lqr --A ... --B ... --weights "Q = ..., R = ..."`:
 * the LQR gain of a state-space system given as matrices (qd_lqr_system_read,
 * qd_care_solve).
 * `qdot linearize --lqr` does the same on the A and B of a model.
 */
#include "driver.h"
#include "lqr_cli.h"

#include <stddef.h>
#include <string.h>

typedef struct lqr_args {
    const char *A, *B, *weights, *format;
} lqr_args;

static const char *const formats[] = {"text", "json", "c", NULL};

static const cli_opt opts[] = {
    {"--A", NULL, CLI_TEXT, offsetof(lqr_args, A), "\"[[a11, a12, ...], ...]\"",
     "the state matrix A, n by n, row by row", NULL, NULL},
    {"--B", NULL, CLI_TEXT, offsetof(lqr_args, B), "\"[[b11, ...], ...]\"",
     "the input matrix B, n by m", NULL, NULL},
    {"--weights", NULL, CLI_TEXT, offsetof(lqr_args, weights), "\"Q = W, R = W\"",
     "the cost: W a number, diag(...) or [[...], ...]", NULL, NULL},
    {"--format", NULL, CLI_CHOICE, offsetof(lqr_args, format), "NAME", "text, json or c",
     formats, NULL},
    {0},
};

static const cli_spec spec = {
    "lqr", "--A M --B M --weights \"Q = ..., R = ...\" [--format text|json|c]",
    "the LQR gain of x' = A x + B u (the Riccati equation)", opts, NULL, 0, 0, NULL, false};

typedef struct lqr_run {
    cli_run c;
    lqr_args a;
    qd_lqr_system sys;
} lqr_run;

/* The reader's error shown under the text it names (qd_lqr_system_read). */
static int system_error(qd_ctx *ctx, const lqr_args *a) {
    const char *f = qd_ctx_diag(ctx)->name;
    bool isA = !strcmp(f, "A"), isB = !strcmp(f, "B");
    return cli_lqr_error(ctx, isA ? "--A" : isB ? "--B" : "--weights",
                         isA ? a->A : isB ? a->B : a->weights);
}

static int check(cli_run *c) {
    const lqr_args *a = &((lqr_run *)c)->a;
    if (a->A && a->B && a->weights)
        return QD_EXIT_OK;
    return cli_usage_error("qdot lqr needs --A, --B and --weights (qdot lqr --help)");
}

static int run(cli_run *c) {
    lqr_run *r = (lqr_run *)c;
    const char *f = r->a.format;
    qd_care_result res = {0};
    const qd_lqr_system *s = &r->sys;
    int rc = qd_lqr_system_read(c->ctx, r->a.A, r->a.B, r->a.weights, &r->sys) == QD_OK
                 ? QD_EXIT_OK
                 : system_error(c->ctx, &r->a);
    if (rc == QD_EXIT_OK && qd_care_solve(c->ctx, s->A.rows, s->B.cols, s->A.a, s->B.a, s->Q,
                                          s->R, &res) != QD_OK)
        rc = cli_diag_ctx(c->ctx);
    if (rc == QD_EXIT_OK)
        rc = cli_lqr_print_design(stdout, NULL, &res,
                                  !f || !strcmp(f, "text") ? CLI_LQR_TEXT
                                  : !strcmp(f, "json")     ? CLI_LQR_JSON
                                                           : CLI_LQR_C);
    qd_care_result_free(&res);
    return rc;
}

static void run_free(cli_run *c) { qd_lqr_system_free(&((lqr_run *)c)->sys); }

int cli_cmd_lqr(int argc, char **argv) {
    static const cli_driver d = {&spec, offsetof(lqr_run, a), 0, check, run, run_free};
    lqr_run r = {0};
    return cli_drive(&d, &r.c, argc, argv);
}

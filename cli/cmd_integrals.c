/*
 * cli/cmd_integrals.c - `qdot integrals FILE`: cyclic coordinates, Jacobi's
 * integral and the energy, the energy balance, symmetries found by
 * coordinate names, Noether's integrals of the model's `symmetry`
 * statements and of --symmetry, and the check of the model's `integral`
 * statements and of --integral (qdot/integrals.h does the work).
 *
 * --symmetry and --integral take what the statements take, after the
 * keyword: "[NAME:] x -> x + eps, y -> y" or "[NAME:] delta x = -y,
 * delta y = x", and "[NAME:] EXPR".
 */
#include "cli.h"

#include <stddef.h>
#include <stdlib.h>
#include <string.h>
#include "model_cli.h"
#include "model_file.h"
#include "qdot/integrals.h"

typedef struct int_args {
    const char *format;
    bool no_search;
    cli_list set, symmetry, integral;
} int_args;

static const char *const formats[] = {"text", "json", NULL};

static const cli_opt opts[] = {
    {"--format", NULL, CLI_CHOICE, offsetof(int_args, format), "FORMAT", "how to write it",
     formats, NULL},
    {"--symmetry", NULL, CLI_LIST, offsetof(int_args, symmetry), "\"[NAME:] x -> x + eps, ...\"",
     "a symmetry to examine, as the model's `symmetry` statement takes it", NULL, NULL},
    {"--integral", NULL, CLI_LIST, offsetof(int_args, integral), "\"[NAME:] EXPR\"",
     "a proposed integral to check, as the `integral` statement takes it", NULL, NULL},
    {"--no-search", NULL, CLI_FLAG, offsetof(int_args, no_search), NULL,
     "do not look for symmetries by the coordinates' names", NULL, NULL},
    {"--set", NULL, CLI_LIST, offsetof(int_args, set), "NAME=VALUE",
     "read the model with this parameter value", NULL, NULL},
    {0},
};

static const cli_spec spec = {
    "integrals", "FILE [options]",
    "Integrals of motion: cyclic coordinates, Jacobi's integral, the energy balance, Noether.",
    opts, NULL, 1, 1, "FILE", false,
};

typedef struct int_run {
    qd_ctx *ctx;
    cli_model_file mf;
    qd_eom *e;
    qd_integrals *I;
    int_args a;
    const char *file;
    qd_integrals_given g;
} int_run;

/* ---- --symmetry and --integral ------------------------------------------- */

/* Added to the model as its own `symmetry` and `integral` statements (after
 * the file's); unnamed ones are S1, S2, ... and J1, J2, ... */
static int parse_given(int_run *r) {
    int rc = QD_EXIT_OK;
    char label[32];
    for (size_t k = 0; rc == QD_EXIT_OK && k < r->a.symmetry.n; k++) {
        snprintf(label, sizeof label, "S%zu", k + 1);
        rc = cli_symmetry(&r->mf, "--symmetry", r->a.symmetry.items[k], label);
    }
    for (size_t k = 0; rc == QD_EXIT_OK && k < r->a.integral.n; k++) {
        snprintf(label, sizeof label, "J%zu", k + 1);
        rc = cli_integral(&r->mf, "--integral", r->a.integral.items[k], label);
    }
    return rc;
}

static int emit(int_run *r) {
    qd_buf b = QD_BUF_INIT;
    bool json = r->a.format && !strcmp(r->a.format, "json");
    qd_status st = json ? qd_integrals_json(r->ctx, r->I, &r->g, r->mf.path, &b)
                        : qd_integrals_print(r->ctx, r->I, &r->g, r->mf.path, &b);
    if (st != QD_OK) {
        qd_buf_free(&b);
        return cli_diag_ctx(r->ctx);
    }
    return cli_emit(&b, "integrals");
}

static int run(int_run *r) {
    int rc = cli_load_derive(r->ctx, r->file, r->a.set.n, r->a.set.items, true, NULL, &r->mf, &r->e);
    if (rc == QD_EXIT_OK)
        rc = parse_given(r);
    qd_integrals_opts o = {.search = !r->a.no_search};
    if (rc == QD_EXIT_OK && !(r->I = qd_integrals_derive(r->ctx, r->mf.model, r->e, &o)))
        rc = cli_diag_ctx(r->ctx);
    if (rc == QD_EXIT_OK && qd_integrals_given_derive(r->ctx, r->I, r->mf.model, &r->g) != QD_OK)
        rc = cli_diag_ctx(r->ctx);
    return rc == QD_EXIT_OK ? emit(r) : rc;
}

int cli_cmd_integrals(int argc, char **argv) {
    int_run r = {0};
    int rc = cli_parse(&spec, argc, argv, &r.a, &r.file);
    if (rc != QD_EXIT_OK)
        return rc;
    if (!(r.ctx = qd_ctx_new())) {
        cli_diag_error("out of memory");
        return QD_EXIT_FAIL;
    }
    rc = run(&r);
    qd_integrals_given_free(&r.g);
    qd_integrals_free(r.I);
    qd_eom_free(r.e);
    cli_model_file_free(&r.mf);
    qd_ctx_free(r.ctx);
    return rc;
}

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

#include <stdlib.h>
#include <string.h>
#include "model_cli.h"
#include "model_file.h"
#include "state.h"
#include "qdot/integrals.h"

#define MAX_OPT QD_CLI_MAX_LIST

typedef struct int_run {
    qd_ctx *ctx;
    cli_model_file mf;
    qd_eom *e;
    qd_integrals *I;
    bool json, search;
    const char *file, *sets[MAX_OPT], *syms[MAX_OPT], *ints[MAX_OPT];
    size_t nsets, nsymopt, nintopt;
    qd_integrals_given g;
} int_run;

static const char usage_text[] =
    "usage: qdot integrals FILE [--format text|json] [--set NAME=VALUE]... "
    "[--symmetry \"[NAME:] x -> x + eps, ...\" | \"[NAME:] delta x = -y, ...\"]... "
    "[--integral \"[NAME:] EXPR\"]... [--no-search]";

static const char *const formats[] = {"text", "json", NULL};

static int parse_option(int argc, char **argv, int *i, void *data) {
    int_run *r = data;
    const char *v;
    int f;
    if ((v = cli_value(argc, argv, i, "--format"))) {
        int rc = cli_choice("--format", v, formats, &f);
        r->json = f == 1;
        return rc;
    }
    if (!strcmp(argv[*i], "--no-search")) {
        r->search = false;
        return QD_EXIT_OK;
    }
    if ((v = cli_value(argc, argv, i, "--set")))
        return cli_push("--set", r->sets, &r->nsets, MAX_OPT, v);
    if ((v = cli_value(argc, argv, i, "--symmetry")))
        return cli_push("--symmetry", r->syms, &r->nsymopt, MAX_OPT, v);
    if ((v = cli_value(argc, argv, i, "--integral")))
        return cli_push("--integral", r->ints, &r->nintopt, MAX_OPT, v);
    return cli_bad_option(argv[*i], usage_text);
}

/* ---- --symmetry and --integral ------------------------------------------- */

/* Added to the model as its own `symmetry` and `integral` statements (after
 * the file's); unnamed ones are S1, S2, ... and J1, J2, ... */
static int parse_given(int_run *r) {
    int rc = QD_EXIT_OK;
    char label[32];
    for (size_t k = 0; rc == QD_EXIT_OK && k < r->nsymopt; k++) {
        snprintf(label, sizeof label, "S%zu", k + 1);
        rc = cli_symmetry(&r->mf, "--symmetry", r->syms[k], label);
    }
    for (size_t k = 0; rc == QD_EXIT_OK && k < r->nintopt; k++) {
        snprintf(label, sizeof label, "J%zu", k + 1);
        rc = cli_integral(&r->mf, "--integral", r->ints[k], label);
    }
    return rc;
}

static int emit(int_run *r) {
    qd_buf b = QD_BUF_INIT;
    qd_status st = r->json ? qd_integrals_json(r->ctx, r->I, &r->g, r->mf.path, &b)
                           : qd_integrals_print(r->ctx, r->I, &r->g, r->mf.path, &b);
    if (st != QD_OK) {
        qd_buf_free(&b);
        return cli_diag_ctx(r->ctx);
    }
    return cli_emit(&b, "integrals");
}

static int run(int_run *r) {
    int rc = cli_load_derive(r->ctx, r->file, r->nsets, r->sets, true, NULL, &r->mf, &r->e);
    if (rc == QD_EXIT_OK)
        rc = parse_given(r);
    qd_integrals_opts o = {.search = r->search};
    if (rc == QD_EXIT_OK && !(r->I = qd_integrals_derive(r->ctx, r->mf.model, r->e, &o)))
        rc = cli_diag_ctx(r->ctx);
    if (rc == QD_EXIT_OK && qd_integrals_given_derive(r->ctx, r->I, r->mf.model, &r->g) != QD_OK)
        rc = cli_diag_ctx(r->ctx);
    return rc == QD_EXIT_OK ? emit(r) : rc;
}

int cli_cmd_integrals(int argc, char **argv) {
    int_run r = {.search = true};
    int rc = cli_file_args(argc, argv, "integrals", usage_text, &r.file, parse_option, &r);
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

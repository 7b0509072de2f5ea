/*
 * cli/cmd_hj.c - `qdot hj FILE`: the Hamilton-Jacobi equation of a model,
 * whether and how it separates, the separated equations with their
 * constants, and the complete integral W (qd_hj_derive; Desloge ch. 78-79).
 * --solve adds the motion from dW/dalpha = beta where the quadratures close.
 * A system that does not separate is an answer, not an error (exit 0).
 */
#include "cli.h"

#include <stdlib.h>
#include <string.h>
#include "eom_out.h"
#include "model_cli.h"
#include "model_file.h"

#define MAX_SETS QD_CLI_MAX_LIST

typedef enum { FMT_TEXT, FMT_JSON, FMT_LATEX, FMT_SYMPY } hj_fmt;

typedef struct hj_run {
    qd_ctx *ctx;
    cli_model_file mf;
    qd_hj *h;
    hj_fmt fmt;
    const char *file, *energy, *sets[MAX_SETS];
    size_t nsets;
    bool solve;
} hj_run;

static const char usage_text[] =
    "usage: qdot hj FILE [--format text|json|latex|sympy] [--set NAME=VALUE]... "
    "[--energy NAME] [--solve]";

static const char *const formats[] = {"text", "json", "latex", "sympy", NULL};

static int parse_option(int argc, char **argv, int *i, void *data) {
    hj_run *r = data;
    const char *v;
    int f;
    if ((v = cli_value(argc, argv, i, "--format"))) {
        int rc = cli_choice("--format", v, formats, &f);
        r->fmt = (hj_fmt)f;
        return rc;
    }
    if ((v = cli_value(argc, argv, i, "--set")))
        return cli_push("--set", r->sets, &r->nsets, MAX_SETS, v);
    if ((v = cli_value(argc, argv, i, "--energy")))
        return cli_once("--energy", &r->energy, v);
    if (!strcmp(argv[*i], "--solve")) {
        r->solve = true;
        return QD_EXIT_OK;
    }
    return cli_bad_option(argv[*i], usage_text);
}

static int emit(hj_run *r) {
    static const qd_format fmts[] = {QD_FMT_TEXT, QD_FMT_TEXT, QD_FMT_LATEX, QD_FMT_SYMPY};
    qd_buf b = QD_BUF_INIT;
    qd_status st = r->fmt == FMT_JSON ? qd_hj_json(r->ctx, r->h, r->mf.path, &b)
                                      : qd_hj_print(r->ctx, r->h, r->mf.model, r->mf.path,
                                                    fmts[r->fmt], &b);
    if (st != QD_OK) {
        qd_buf_free(&b);
        return cli_diag_ctx(r->ctx);
    }
    return cli_emit(&b, "Hamilton-Jacobi equation");
}

static int run(hj_run *r) {
    int rc = cli_load(r->ctx, r->file, r->nsets, r->sets, true, &r->mf);
    if (rc != QD_EXIT_OK)
        return rc;
    qd_hj_opts opts = {.energy_name = r->energy};
    if (!(r->h = qd_hj_derive(r->ctx, r->mf.model, &opts)))
        return cli_eom_derive_error(r->ctx, &r->mf);
    r->solve = r->solve && r->h->separable;
    if (r->solve && qd_hj_solve(r->ctx, r->h) != QD_OK)
        return cli_diag_ctx(r->ctx);
    return emit(r);
}

int cli_cmd_hj(int argc, char **argv) {
    hj_run r = {.fmt = FMT_TEXT};
    int rc = cli_file_args(argc, argv, "hj", usage_text, &r.file, parse_option, &r);
    if (rc != QD_EXIT_OK)
        return rc;
    if (!(r.ctx = qd_ctx_new())) {
        cli_diag_error("out of memory");
        return QD_EXIT_FAIL;
    }
    rc = run(&r);
    qd_hj_free(r.h);
    cli_model_file_free(&r.mf);
    qd_ctx_free(r.ctx);
    return rc;
}

/*
 * cli/cmd_hj.c - `qdot hj FILE`: the Hamilton-Jacobi equation of a model,
 * whether and how it separates, the separated equations with their
 * constants, and the complete integral W (qd_hj_derive; Desloge ch. 78-79).
 * --solve adds the motion from dW/dalpha = beta where the quadratures close.
 * A system that does not separate is an answer, not an error (exit 0).
 */
#include "cli.h"

#include <stddef.h>
#include <stdlib.h>
#include <string.h>
#include "eom_out.h"
#include "model_cli.h"
#include "model_file.h"

typedef struct hj_args {
    const char *format, *energy;
    bool solve;
    cli_list set;
} hj_args;

static const char *const formats[] = {"text", "json", "latex", "sympy", NULL};

static const cli_opt opts[] = {
    {"--format", NULL, CLI_CHOICE, offsetof(hj_args, format), "FORMAT", "how to write it",
     formats, NULL},
    {"--energy", NULL, CLI_TEXT, offsetof(hj_args, energy), "NAME",
     "the name of the energy constant (default E)", NULL, NULL},
    {"--solve", NULL, CLI_FLAG, offsetof(hj_args, solve), NULL,
     "the motion from dW/dalpha = beta where the quadratures close", NULL, NULL},
    {"--set", NULL, CLI_LIST, offsetof(hj_args, set), "NAME=VALUE",
     "read the model with this parameter value", NULL, NULL},
    {0},
};

static const cli_spec spec = {
    "hj", "FILE [options]",
    "The Hamilton-Jacobi equation, whether and how it separates, and W.",
    opts, NULL, 1, 1, "FILE", false,
};

typedef struct hj_run {
    qd_ctx *ctx;
    cli_model_file mf;
    qd_hj *h;
    hj_args a;
    const char *file;
} hj_run;

static int emit(hj_run *r) {
    const char *f = r->a.format ? r->a.format : "text";
    qd_buf b = QD_BUF_INIT;
    qd_status st = !strcmp(f, "json")
                       ? qd_hj_json(r->ctx, r->h, r->mf.path, &b)
                       : qd_hj_print(r->ctx, r->h, r->mf.model, r->mf.path,
                                     !strcmp(f, "latex")   ? QD_FMT_LATEX
                                     : !strcmp(f, "sympy") ? QD_FMT_SYMPY
                                                           : QD_FMT_TEXT,
                                     &b);
    if (st != QD_OK) {
        qd_buf_free(&b);
        return cli_diag_ctx(r->ctx);
    }
    return cli_emit(&b, "Hamilton-Jacobi equation");
}

static int run(hj_run *r) {
    int rc = cli_load(r->ctx, r->file, r->a.set.n, r->a.set.items, true, &r->mf);
    if (rc != QD_EXIT_OK)
        return rc;
    qd_hj_opts ho = {.energy_name = r->a.energy};
    if (!(r->h = qd_hj_derive(r->ctx, r->mf.model, &ho)))
        return cli_eom_derive_error(r->ctx, &r->mf);
    if (r->a.solve && r->h->separable && qd_hj_solve(r->ctx, r->h) != QD_OK)
        return cli_diag_ctx(r->ctx);
    return emit(r);
}

int cli_cmd_hj(int argc, char **argv) {
    hj_run r = {0};
    int rc = cli_parse(&spec, argc, argv, &r.a, &r.file);
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

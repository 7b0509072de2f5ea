/*
 * cli/cmd_routh.c - `qdot routh FILE --ignore phi[,psi...]`: Routh's
 * reduction (qd_routh_derive): the Routhian R = sum p q' - L of the ignored
 * coordinates (Goldstein's sign) split by degree in the kept velocities, the
 * effective potential V_eff = R0, the quadratures that give the ignored
 * velocities back, and the reduced equations M q'' = f of the kept
 * coordinates with their gyroscopic matrix.  --set gives parameters values.
 * When the ignored velocities have no closed form (L not quadratic in them,
 * outside legendre_family.c) R is kept implicit and said so (qdot/routh.h).
 */
#include "cli.h"

#include <stdlib.h>
#include <string.h>
#include "model_cli.h"
#include "model_file.h"
#include "qdot/routh.h"
#include "state.h"

#define MAX_SETS QD_CLI_MAX_LIST
#define MAX_IGN 32

typedef enum { FMT_TEXT, FMT_JSON, FMT_LATEX, FMT_SYMPY } routh_fmt;

typedef struct routh_run {
    qd_ctx *ctx;
    cli_model_file mf;
    qd_eom *e;
    qd_routh *r;
    routh_fmt fmt;
    const char *file, *ignore, *sets[MAX_SETS];
    size_t nsets, nign;
    const qd_expr *ign[MAX_IGN];
} routh_run;

static const char usage_text[] =
    "usage: qdot routh FILE --ignore q[,q...] [--format text|json|latex|sympy] "
    "[--set NAME=VALUE]...";

static const char *const formats[] = {"text", "json", "latex", "sympy", NULL};

static int parse_option(int argc, char **argv, int *i, void *data) {
    routh_run *r = data;
    const char *v;
    int f;
    if ((v = cli_value(argc, argv, i, "--format"))) {
        int rc = cli_choice("--format", v, formats, &f);
        r->fmt = (routh_fmt)f;
        return rc;
    }
    if ((v = cli_value(argc, argv, i, "--set")))
        return cli_push("--set", r->sets, &r->nsets, MAX_SETS, v);
    if ((v = cli_value(argc, argv, i, "--ignore")))
        return cli_once("--ignore", &r->ignore, v);
    return cli_bad_option(argv[*i], usage_text);
}

static int parse_args(int argc, char **argv, routh_run *r) {
    int rc = cli_file_args(argc, argv, "routh", usage_text, &r->file, parse_option, r);
    if (rc == QD_EXIT_OK && !r->ignore) {
        cli_diag_error("routh needs --ignore with the cyclic coordinates to ignore\n%s",
                      usage_text);
        rc = QD_EXIT_USAGE;
    }
    return rc;
}

static int emit(routh_run *r) {
    static const qd_format fmts[] = {QD_FMT_TEXT, QD_FMT_TEXT, QD_FMT_LATEX, QD_FMT_SYMPY};
    qd_buf b = QD_BUF_INIT;
    qd_status st = r->fmt == FMT_JSON
                       ? qd_routh_json(r->ctx, r->r, r->mf.model, r->e, r->mf.path, &b)
                       : qd_routh_print(r->ctx, r->r, r->mf.model, r->e, r->mf.path,
                                        fmts[r->fmt], &b);
    if (st != QD_OK) {
        qd_buf_free(&b);
        return cli_diag_ctx(r->ctx);
    }
    return cli_emit(&b, "Routhian");
}

static int run(routh_run *r) {
    int rc = cli_load_derive(r->ctx, r->file, r->nsets, r->sets, true, NULL, &r->mf, &r->e);
    if (rc == QD_EXIT_OK)
        rc = cli_ignore_parse(r->ctx, r->mf.model, r->ignore, r->ign, MAX_IGN, &r->nign);
    /* forced: a cyclic coordinate with a generalized force is reduced too
     * (Byerly Art. 20a); any other refusal is shown at its statement */
    qd_routh_opts opts = {.implicit = true, .forced = true};
    if (rc == QD_EXIT_OK &&
        !(r->r = qd_routh_derive_opts(r->ctx, r->mf.model, r->e, r->nign, r->ign, &opts))) {
        rc = cli_ignore_check(r->ctx, &r->mf, r->e, r->ign, r->nign);
        if (rc == QD_EXIT_OK)
            rc = cli_diag_ctx(r->ctx);
    }
    return rc == QD_EXIT_OK ? emit(r) : rc;
}

int cli_cmd_routh(int argc, char **argv) {
    routh_run r = {.fmt = FMT_TEXT};
    int rc = parse_args(argc, argv, &r);
    if (rc != QD_EXIT_OK)
        return rc;
    if (!(r.ctx = qd_ctx_new())) {
        cli_diag_error("out of memory");
        return QD_EXIT_FAIL;
    }
    rc = run(&r);
    qd_routh_free(r.r);
    qd_eom_free(r.e);
    cli_model_file_free(&r.mf);
    qd_ctx_free(r.ctx);
    return rc;
}

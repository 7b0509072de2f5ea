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

#include <stddef.h>
#include <stdlib.h>
#include <string.h>
#include "model_cli.h"
#include "model_file.h"
#include "qdot/routh.h"

#define MAX_IGN 32

typedef struct routh_args {
    const char *ignore, *format;
    cli_list set;
} routh_args;

static const char *const formats[] = {"text", "json", "latex", "sympy", NULL};

static const cli_opt opts[] = {
    {"--ignore", NULL, CLI_TEXT, offsetof(routh_args, ignore), "Q[,Q...]",
     "the cyclic coordinates to ignore (required)", NULL, NULL},
    {"--format", NULL, CLI_CHOICE, offsetof(routh_args, format), "FORMAT", "how to write it",
     formats, NULL},
    {"--set", NULL, CLI_LIST, offsetof(routh_args, set), "NAME=VALUE",
     "read the model with this parameter value", NULL, NULL},
    {0},
};

static const cli_spec spec = {
    "routh", "FILE --ignore Q[,Q...] [options]",
    "Routh's reduction: the Routhian, V_eff, the quadratures and the reduced equations.",
    opts, NULL, 1, 1, "FILE", false,
};

typedef struct routh_run {
    qd_ctx *ctx;
    cli_model_file mf;
    qd_eom *e;
    qd_routh *r;
    routh_args a;
    const char *file;
    size_t nign;
    const qd_expr *ign[MAX_IGN];
} routh_run;

static int emit(routh_run *r) {
    const char *f = r->a.format ? r->a.format : "text";
    qd_buf b = QD_BUF_INIT;
    qd_status st = !strcmp(f, "json")
                       ? qd_routh_json(r->ctx, r->r, r->mf.model, r->e, r->mf.path, &b)
                       : qd_routh_print(r->ctx, r->r, r->mf.model, r->e, r->mf.path,
                                        !strcmp(f, "latex")   ? QD_FMT_LATEX
                                        : !strcmp(f, "sympy") ? QD_FMT_SYMPY
                                                              : QD_FMT_TEXT,
                                        &b);
    if (st != QD_OK) {
        qd_buf_free(&b);
        return cli_diag_ctx(r->ctx);
    }
    return cli_emit(&b, "Routhian");
}

static int run(routh_run *r) {
    int rc = cli_load_derive(r->ctx, r->file, r->a.set.n, r->a.set.items, true, NULL, &r->mf, &r->e);
    if (rc == QD_EXIT_OK)
        rc = cli_ignore_parse(r->ctx, r->mf.model, r->a.ignore, r->ign, MAX_IGN, &r->nign);
    /* forced: a cyclic coordinate with a generalized force is reduced too
     * (Byerly Art. 20a); any other refusal is shown at its statement */
    qd_routh_opts ro = {.implicit = true, .forced = true};
    if (rc == QD_EXIT_OK &&
        !(r->r = qd_routh_derive_opts(r->ctx, r->mf.model, r->e, r->nign, r->ign, &ro))) {
        rc = cli_ignore_check(r->ctx, &r->mf, r->e, r->ign, r->nign);
        if (rc == QD_EXIT_OK)
            rc = cli_diag_ctx(r->ctx);
    }
    return rc == QD_EXIT_OK ? emit(r) : rc;
}

int cli_cmd_routh(int argc, char **argv) {
    routh_run r = {0};
    int rc = cli_parse(&spec, argc, argv, &r.a, &r.file);
    if (rc == QD_EXIT_OK && !r.a.ignore) {
        cli_diag_error("routh needs --ignore with the cyclic coordinates to ignore "
                       "(qdot routh --help)");
        rc = QD_EXIT_USAGE;
    }
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

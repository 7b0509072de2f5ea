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
#include "driver.h"

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
    CLI_OPT_FORMATS(routh_args, format, formats),
    CLI_OPT_SET(routh_args, set),
    {0},
};

static const cli_spec spec = {
    "routh", "FILE --ignore Q[,Q...] [options]",
    "Routh's reduction: the Routhian, V_eff, the quadratures and the reduced equations.",
    opts, NULL, 1, 1, "FILE", false,
};

typedef struct routh_run {
    cli_run c;
    qd_eom *e;
    qd_routh *r;
    routh_args a;
    size_t nign;
    const qd_expr *ign[MAX_IGN];
} routh_run;

static int emit(routh_run *r) {
    qd_buf b = QD_BUF_INIT;
    qd_status st = cli_json(r->a.format)
                       ? qd_routh_json(r->c.ctx, r->r, r->c.mf.model, r->e, r->c.mf.path, &b)
                       : qd_routh_print(r->c.ctx, r->r, r->c.mf.model, r->e, r->c.mf.path,
                                        cli_format_or_text(r->a.format), &b);
    return cli_emit_status(r->c.ctx, st, &b, "Routhian");
}

static int run(cli_run *c) {
    routh_run *r = (routh_run *)c;
    int rc = cli_load_derive(c->ctx, c->file, r->a.set.n, r->a.set.items, "routh", NULL, &c->mf,
                             &r->e);
    if (rc == QD_EXIT_OK)
        rc = cli_ignore(c->ctx, &c->mf, NULL, r->a.ignore, r->ign, MAX_IGN, &r->nign);
    /* forced: a cyclic coordinate with a generalized force is reduced too
     * (Byerly Art. 20a); any other refusal is shown at its statement */
    qd_routh_opts ro = {.implicit = true, .forced = true};
    if (rc == QD_EXIT_OK &&
        !(r->r = qd_routh_derive_opts(c->ctx, c->mf.model, r->e, r->nign, r->ign, &ro))) {
        qd_diag why = *qd_ctx_diag(c->ctx); /* shown when every one is cyclic */
        qd_ctx_clear_error(c->ctx);
        if ((rc = cli_ignore(c->ctx, &c->mf, r->e, r->a.ignore, r->ign, MAX_IGN, &r->nign)) ==
            QD_EXIT_OK) {
            cli_diag_show("qdot", NULL, &why);
            rc = cli_exit(why.status);
        }
    }
    return rc == QD_EXIT_OK ? emit(r) : rc;
}

static int check(cli_run *c) {
    if (((routh_run *)c)->a.ignore)
        return QD_EXIT_OK;
    return cli_usage_error("routh needs --ignore with the cyclic coordinates to ignore "
                           "(qdot routh --help)");
}

static void run_free(cli_run *c) {
    routh_run *r = (routh_run *)c;
    qd_routh_free(r->r);
    qd_eom_free(r->e);
}

CLI_COMMAND(routh, routh_run, &spec, offsetof(routh_run, a), 0, check, run, run_free)

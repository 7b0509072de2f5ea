/*
 * cli/cmd_hj.c - `qdot hj FILE`: the Hamilton-Jacobi equation of a model,
 * whether and how it separates, the separated equations with their
 * constants, and the complete integral W (qd_hj_derive; Desloge ch. 78-79).
 * --solve adds the motion from dW/dalpha = beta where the quadratures close.
 * A system that does not separate is an answer, not an error (exit 0).
 */
#include "driver.h"

#include "eom_out.h"

typedef struct hj_args {
    const char *format, *energy;
    bool solve;
    cli_list set;
} hj_args;

static const char *const formats[] = {"text", "json", "latex", "sympy", NULL};

static const cli_opt opts[] = {
    CLI_OPT_FORMATS(hj_args, format, formats),
    {"--energy", NULL, CLI_TEXT, offsetof(hj_args, energy), "NAME",
     "the name of the energy constant (default E)", NULL, NULL},
    {"--solve", NULL, CLI_FLAG, offsetof(hj_args, solve), NULL,
     "the motion from dW/dalpha = beta where the quadratures close", NULL, NULL},
    CLI_OPT_SET(hj_args, set),
    {0},
};

static const cli_spec spec = {
    "hj", "FILE [options]",
    "The Hamilton-Jacobi equation, whether and how it separates, and W.",
    opts, NULL, 1, 1, "FILE", false,
};

typedef struct hj_run {
    cli_run c;
    qd_hj *h;
    hj_args a;
} hj_run;

static int emit(hj_run *r) {
    qd_buf b = QD_BUF_INIT;
    qd_status st = cli_json(r->a.format)
                       ? qd_hj_json(r->c.ctx, r->h, r->c.mf.path, &b)
                       : qd_hj_print(r->c.ctx, r->h, r->c.mf.model, r->c.mf.path,
                                     cli_format_or_text(r->a.format), &b);
    return cli_emit_status(r->c.ctx, st, &b, "Hamilton-Jacobi equation");
}

static int run(cli_run *c) {
    hj_run *r = (hj_run *)c;
    int rc = cli_load(c->ctx, c->file, r->a.set.n, r->a.set.items, "hj", &c->mf);
    if (rc != QD_EXIT_OK)
        return rc;
    qd_hj_opts ho = {.energy_name = r->a.energy};
    if (!(r->h = qd_hj_derive(c->ctx, c->mf.model, &ho)))
        return cli_eom_derive_error(c->ctx, &c->mf);
    if (r->a.solve && r->h->separable && qd_hj_solve(c->ctx, r->h) != QD_OK)
        return cli_diag_ctx(c->ctx);
    return emit(r);
}

static void run_free(cli_run *c) { qd_hj_free(((hj_run *)c)->h); }

CLI_COMMAND(hj, hj_run, &spec, offsetof(hj_run, a), 0, NULL, run, run_free)

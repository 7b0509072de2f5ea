/*
 * cli/cmd_stability.c - `qdot stability FILE`: steady motions of a system
 * with cyclic coordinates and their stability (libqdot's qdot/stability.h).
 *
 *   --ignore phi[,psi]          the cyclic momenta are free (Routhian, V + K)
 *   --driven "phi' = Omega"     the rate is maintained (V - T0); "phi" alone
 *                               leaves Omega to be found from --at
 *   --momentum "p_phi=3"        free case: the momentum (else found from --at)
 *   --omega "phi'=2"            free case: the steady rate instead of p
 *   --at "theta=pi/3"           kept coordinates held at these values: the rate
 *                               (or momentum) that makes them steady is found
 *   --guess "r=1"               starting values of the search, not held: kept
 *                               coordinates, rates ("phi'=2") or momenta
 *                               ("p_phi=3", turned into rates at the start)
 * The library states, solves and scans the problem (qd_stability_problem:
 * every steady motion for the values given, the two precessions of a top,
 * each analysed; the first printed is the one nearest the starting values).
 * Values are expressions in the parameters (--set applies first).
 *   --scan NAME=A:B [--steps N] the steady motion followed as the parameter
 *                               goes from A to B (qd_stability_problem_scan),
 *                               the given values held at their numbers
 */
#include "driver.h"

#include <string.h>
#include "linear_cli.h"
#include "eom_out.h"
#include "qdot/conlin.h"
#include "qdot/stability.h"

typedef struct stab_args {
    const char *ignore, *momentum, *omega, *at, *guess, *scan, *format;
    cli_list driven, sets;
    uint64_t steps;
    bool json;
} stab_args;

typedef struct stab_run {
    cli_run c;
    stab_args a;
    qd_eom *e;
    qd_stability_problem p;  /* the steady motions and their analyses */
} stab_run;

#define OPT(...) CLI_OPT(stab_args, __VA_ARGS__)
static const cli_opt opts[] = {
    OPT("--ignore", CLI_TEXT, ignore, "Q[,Q...]", "the cyclic coordinates, momenta free "
        "(Routhian, V_eff = V + K)"),
    OPT("--driven", CLI_LIST, driven, "\"Q' = VALUE\"", "a maintained rate (V_eff = V - T0); "
        "a bare Q leaves it to be found; repeatable"),
    OPT("--momentum", CLI_TEXT, momentum, "\"p_Q=VALUE, ...\"", "with --ignore: held momenta "
        "of cyclic coordinates"),
    OPT("--omega", CLI_TEXT, omega, "\"Q'=VALUE, ...\"", "with --ignore: held steady rates "
        "instead of momenta"),
    OPT("--at", CLI_TEXT, at, "\"q=VALUE, ...\"", "kept coordinates held at these values"),
    OPT("--guess", CLI_TEXT, guess, "\"q=V, Q'=V, p_Q=V\"", "starting values of "
        "the search, not held (default: the model's initial values)"),
    OPT("--scan", CLI_TEXT, scan, "NAME=A:B", "follow the steady motion as the parameter goes "
        "from A to B"),
    CLI_OPT_IN(stab_args, "--steps", CLI_WHOLE, steps, "N", "steps of --scan (at most 100000)",
               1, 100000),
    CLI_OPT_SET(stab_args, sets),
    CLI_OPT_FORMAT(stab_args, format),
    {0},
};
#undef OPT

static const cli_spec spec = {
    "stability", "FILE (--ignore Q[,Q...] | --driven \"Q' = VALUE\"...) [options]",
    "steady motions of a system with cyclic coordinates, and their stability", opts, NULL,
    1, 1, "FILE", false};

static int check(cli_run *c) {
    stab_args *a = &((stab_run *)c)->a;
    a->json = cli_json(a->format);
    if (!a->ignore == !a->driven.n)
        return cli_usage_error("give the cyclic coordinates with either --ignore (free momenta) or "
                               "--driven (maintained rates) (qdot stability --help)");
    if (a->driven.n && (a->momentum || a->omega)) {
        cli_diag_error("--momentum and --omega go with --ignore; a driven rate is given as "
                       "--driven \"q' = VALUE\"");
        return QD_EXIT_USAGE;
    }
    if (a->steps && !a->scan)
        return cli_usage_error("--steps is the number of steps of --scan: give --scan NAME=A:B");
    return QD_EXIT_OK;
}

/* ---- the pipeline ---------------------------------------------------------- */

/* The context's error: one about an option's text under that text with a
 * caret (the library names its field), any other as cli_diag_ctx. */
static int steady_error(const stab_run *r, const stab_args *a) {
    const qd_diag *d = qd_ctx_diag(r->c.ctx);
    const struct { const char *field, *opt, *text; } texts[] = {
        {"ignore", "--ignore", a->ignore}, {"driven", "--driven", r->p.driven},
        {"omega", "--omega", a->omega},    {"momentum", "--momentum", a->momentum},
        {"guess", "--guess", a->guess},    {"at", "--at", a->at},
    };
    for (size_t k = 0; d->located && k < sizeof texts / sizeof texts[0]; k++)
        if (texts[k].text && !strcmp(d->name, texts[k].field)) {
            cli_diag_show(texts[k].opt, texts[k].text, d);
            return cli_exit(qd_ctx_status(r->c.ctx));
        }
    return cli_diag_ctx(r->c.ctx);
}

/* The steady motion followed along a parameter (qd_stability_problem_scan):
 * a table and the changes of its stability. */
static int scan(stab_run *r, const stab_args *a) {
    char name[128];
    double lo, hi;
    qd_ctx *ctx = r->c.ctx;
    int rc = cli_scan_range(ctx, a->scan, name, sizeof name, &lo, &hi);
    qd_scan sc = {0};
    qd_buf b = QD_BUF_INIT;
    qd_status st = QD_OK;
    if (rc == QD_EXIT_OK && qd_stability_problem_scan(ctx, &r->p, r->c.mf.model, name, lo, hi,
                                                      a->steps, &sc) != QD_OK) {
        rc = cli_exit(qd_ctx_status(ctx));
        cli_diag_error("--scan: %s", qd_ctx_message(ctx));
    } else if (rc == QD_EXIT_OK &&
               (st = qd_stability_scan_write(ctx, &r->p, name, &sc, a->json, &b)) != QD_OK) {
        cli_diag_error("cannot print the scan: %s", st == QD_ERR_NOMEM ? "out of memory"
                                                                     : "a number JSON cannot hold");
        rc = QD_EXIT_FAIL;
    } else if (rc == QD_EXIT_OK) {
        rc = cli_emit(&b, "scan");
    }
    qd_buf_free(&b);
    qd_scan_free(&sc);
    return rc;
}

static int emit(stab_run *r, bool json) {
    qd_buf b = QD_BUF_INIT;
    const qd_stability_problem *p = &r->p;
    qd_stability_report rep = {p->s, &p->given, &p->set, p->an, r->c.mf.path};
    if (qd_stability_print(r->c.ctx, &rep, json, &b) != QD_OK) {
        qd_buf_free(&b);
        return cli_diag_ctx(r->c.ctx);
    }
    return cli_emit(&b, "result");
}

/* A model that keeps constraints (the rolling disc, the bicycle): the steady
 * motion is its initial state with --at (rates too), linearized on its state
 * manifold as `linearize` does (cli_conlin), --ignore's coordinates ignorable. */
static int on_manifold(stab_run *r, const stab_args *a) {
    if (a->driven.n || a->momentum || a->omega || a->guess)
        return cli_usage_error("%s: a model that keeps constraints takes its steady motion from "
                               "its initial state and --at \"q=V, q'=V\", with --ignore naming "
                               "the cyclic coordinates", a->driven.n ? "--driven" : a->momentum
                               ? "--momentum" : a->omega ? "--omega" : "--guess");
    qd_eom_opts eo = {.eliminate = true};
    qd_eom_free(r->e);
    if (!(r->e = qd_eom_derive_opts(r->c.ctx, r->c.mf.model, &eo)))
        return cli_eom_derive_error(r->c.ctx, &r->c.mf);
    cli_lin_run lr = {.c = {.ctx = r->c.ctx, .mf = r->c.mf}, .e = r->e};
    const cli_conlin_args ca = {a->at, NULL, a->scan, NULL, a->json ? QD_SS_JSON : QD_SS_TEXT,
                                a->steps, true, a->scan ? NULL : a->ignore, "--at", NULL};
    int rc = r->e->ncon ? cli_lin_setup(&lr) : cli_usage_error("steady motions on constraints "
                                                               "that can be eliminated: write "
                                                               "the model in independent "
                                                               "coordinates");
    if (rc == QD_EXIT_OK)
        rc = cli_conlin(&lr, &ca);
    qd_linpoint_free(&lr.pt);
    return rc;
}

static int run(cli_run *c) {
    stab_run *r = (stab_run *)c;
    int rc = cli_load_derive(c->ctx, c->file, r->a.sets.n, r->a.sets.items, "stability", NULL, &c->mf,
                             &r->e);
    const stab_args *a = &r->a;
    if (rc == QD_EXIT_OK && r->e->ncon)
        return on_manifold(r, a);
    qd_stability_spec ss = {a->ignore, (const char *const *)a->driven.items, a->driven.n,
                            a->momentum, a->omega, a->at, a->guess};
    if (rc == QD_EXIT_OK && qd_stability_problem_read(c->ctx, c->mf.model, r->e, &ss, &r->p) !=
                                QD_OK)
        rc = steady_error(r, a);
    if (rc == QD_EXIT_OK && a->scan)
        return scan(r, a);
    if (rc == QD_EXIT_OK && qd_stability_problem_solve(c->ctx, &r->p) != QD_OK)
        rc = cli_diag_ctx(c->ctx);
    return rc == QD_EXIT_OK ? emit(r, a->json) : rc;
}

static void run_free(cli_run *c) {
    stab_run *r = (stab_run *)c;
    qd_stability_problem_free(&r->p);
    qd_eom_free(r->e);
}

CLI_COMMAND(stability, stab_run, &spec, offsetof(stab_run, a), 0, check, run, run_free)

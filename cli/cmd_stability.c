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
 * Every steady motion for the values given is found (qd_steady_find_all:
 * the two precessions of a top) and each is analysed; the first printed is
 * the one nearest the starting values.
 * Values are expressions in the parameters (--set applies first).
 *   --scan NAME=A:B [--steps N] the steady motion followed as the parameter
 *                               goes from A to B (qd_stability_scan), the
 *                               given values held at their numbers
 */
#include "driver.h"

#include <stdlib.h>
#include <string.h>
#include "linear_cli.h"
#include "qdot/stability.h"

typedef struct stab_args {
    const char *ignore, *momentum, *omega, *at, *guess, *scan, *format;
    cli_list driven, sets;
    size_t steps;
    bool json;
} stab_args;

typedef struct stab_run {
    cli_run c;
    stab_args a;
    qd_eom *e;
    qd_steady *s;
    char *driven;        /* the --driven items joined: "phi' = W, psi" */
    qd_steady_given g;   /* the values held and the starting guesses */
    qd_steady_set set;   /* every steady motion found */
    qd_stability *an;    /* set.count analyses */
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
    OPT("--steps", CLI_COUNT, steps, "N", "steps of --scan (at most 100000)"),
    OPT("--set", CLI_LIST, sets, "NAME=VALUE", "a parameter's value (before everything else)"),
    {"--format", NULL, CLI_CHOICE, offsetof(stab_args, format), "NAME", "text or json",
     cli_formats_text_json, NULL},
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
    if (a->steps > 100000)
        return cli_usage_error("--steps takes a number of steps from 1 to 100000, not %zu",
                               a->steps);
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
        {"ignore", "--ignore", a->ignore}, {"driven", "--driven", r->driven},
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

/* "a, b, c" of the --driven items, one list for the library. */
static char *join(const char *const *items, size_t n) {
    size_t len = 1;
    for (size_t i = 0; i < n; i++)
        len += strlen(items[i]) + 2;
    char *s = malloc(len);
    if (!s)
        return NULL;
    s[0] = '\0';
    for (size_t i = 0; i < n; i++) {
        strcat(s, i ? ", " : "");
        strcat(s, items[i]);
    }
    return s;
}

static int prepare(stab_run *r, const stab_args *a) {
    if (a->driven.n && !(r->driven = join(a->driven.items, a->driven.n)))
        return cli_out_of_memory();
    r->s = qd_steady_derive_named(r->c.ctx, r->c.mf.model, r->e, a->ignore ? "ignore" : "driven",
                                  a->ignore ? a->ignore : r->driven, a->driven.n > 0);
    if (!r->s)
        return steady_error(r, a);
    qd_steady_spec spec = {.rates = a->driven.n ? r->driven : a->omega,
                           .rates_field = a->driven.n ? "driven" : "omega",
                           .momenta = a->momentum, .guess = a->guess, .at = a->at};
    if (qd_steady_given_read(r->c.ctx, r->s, r->c.mf.model, &spec, &r->g) != QD_OK)
        return steady_error(r, a);
    return QD_EXIT_OK;
}

/* Every steady motion and its analysis: the library has left out the
 * motions where the coordinates are singular (counted in set.nsingular). */
static int solve(stab_run *r) {
    const qd_steady_given *g = &r->g;
    if (qd_steady_find_all(r->c.ctx, r->s, g->nvals, g->syms, g->vals, g->xfix, g->wfix, g->pfix,
                           g->pguess, &g->start, &r->set) != QD_OK)
        return cli_diag_ctx(r->c.ctx);
    r->an = calloc(r->set.count + 1, sizeof *r->an);
    if (!r->an)
        return cli_out_of_memory();
    for (size_t k = 0; k < r->set.count; k++)
        if (qd_stability_analyze(r->c.ctx, r->s, g->nvals, g->syms, g->vals, &r->set.pts[k],
                                 &r->an[k]) != QD_OK)
            return cli_diag_ctx(r->c.ctx);
    return QD_EXIT_OK;
}

/* ---- --scan ------------------------------------------------------------------ */

/* Column names: the kept coordinates, Q' and p_Q (qd_steady_unknown_name),
 * into one block of text. */
static char *scan_names(const qd_steady *s, size_t nu, const char **names) {
    size_t len = 0;
    for (size_t k = 0; k < nu; k++)
        len += qd_steady_unknown_name(s, k, NULL, 0) + 1;
    char *text = malloc(len + 1), *at = text;
    for (size_t k = 0; text && k < nu; k++) {
        size_t n = qd_steady_unknown_name(s, k, at, len + 1 - (size_t)(at - text));
        names[k] = at;
        at += n + 1;
    }
    return text;
}

/* The steady motion followed along a parameter: a table and the changes of
 * its stability. */
static int scan(stab_run *r, const stab_args *a) {
    char name[128];
    double lo, hi;
    int rc = cli_scan_range(r->c.ctx, a->scan, name, sizeof name, &lo, &hi);
    size_t nu = r->s->nkeep + 2 * r->s->ncyc;
    const char **names = calloc(nu + 1, sizeof *names);
    char *text = names ? scan_names(r->s, nu, names) : NULL;
    if (!names || !text)
        rc = QD_EXIT_FAIL;
    const qd_steady_given *g = &r->g;
    qd_scan_opts o = {.steps = a->steps, .about = g->held};
    qd_scan sc = {0};
    if (rc == QD_EXIT_OK && qd_stability_scan(r->c.ctx, r->s, r->c.mf.model, name, lo, hi, g->xfix,
                                              g->wfix, g->pfix, g->pguess, &g->start, &o,
                                              &sc) != QD_OK) {
        rc = cli_exit(qd_ctx_status(r->c.ctx));
        cli_diag_error("--scan: %s", qd_ctx_message(r->c.ctx));
    } else if (rc == QD_EXIT_OK) {
        qd_buf followed = QD_BUF_INIT;
        if (qd_stability_scan_followed(r->s, sc.damped, &followed) != QD_OK) {
            rc = cli_out_of_memory();
        } else {
            cli_scan_view v = {name, names, qd_buf_str(&followed), "steady_motion"};
            rc = cli_scan_emit(&v, &sc, a->json);
        }
        qd_buf_free(&followed);
    }
    qd_scan_free(&sc);
    free(names);
    free(text);
    return rc;
}

static int emit(stab_run *r, bool json) {
    qd_buf b = QD_BUF_INIT;
    qd_stability_report rep = {r->s, &r->g, &r->set, r->an, r->c.mf.path};
    if (qd_stability_print(r->c.ctx, &rep, json, &b) != QD_OK) {
        qd_buf_free(&b);
        return cli_diag_ctx(r->c.ctx);
    }
    return cli_emit(&b, "result");
}

static int run(cli_run *c) {
    stab_run *r = (stab_run *)c;
    int rc = cli_load_derive(c->ctx, c->file, r->a.sets.n, r->a.sets.items, "stability", NULL, &c->mf,
                             &r->e);
    if (rc == QD_EXIT_OK)
        rc = prepare(r, &r->a);
    if (rc == QD_EXIT_OK)
        rc = r->a.scan ? scan(r, &r->a) : solve(r);
    if (rc == QD_EXIT_OK && !r->a.scan)
        rc = emit(r, r->a.json);
    return rc;
}

static void run_free(cli_run *c) {
    stab_run *r = (stab_run *)c;
    for (size_t k = 0; r->an && k < r->set.count; k++)
        qd_stability_free(&r->an[k]);
    free(r->an);
    qd_steady_set_free(&r->set);
    qd_steady_given_free(&r->g);
    qd_steady_free(r->s);
    free(r->driven);
    qd_eom_free(r->e);
}

int cli_cmd_stability(int argc, char **argv) {
    static const cli_driver d = {&spec, offsetof(stab_run, a), 0, check, run, run_free};
    stab_run r = {0};
    return cli_drive(&d, &r.c, argc, argv);
}

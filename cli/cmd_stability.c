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
#include "cli.h"

#include <stdlib.h>
#include <string.h>
#include "linear_cli.h"
#include "model_cli.h"
#include "model_file.h"
#include "qdot/stability.h"

#define MAX_SETS QD_CLI_MAX_LIST
#define MAX_LIST 16

typedef struct stab_args {
    const char *file, *ignore, *driven[MAX_LIST], *momentum, *omega, *at, *guess, *scan;
    size_t steps;
    const char *sets[MAX_SETS];
    size_t nsets, ndriven;
    bool json;
} stab_args;

typedef struct stab_run {
    qd_ctx *ctx;
    cli_model_file mf;
    qd_eom *e;
    qd_steady *s;
    char *driven;        /* the --driven items joined: "phi' = W, psi" */
    qd_steady_given g;   /* the values held and the starting guesses */
    qd_steady_set set;   /* every steady motion found */
    qd_stability *an;    /* set.count analyses */
} stab_run;

static const char usage_text[] =
    "usage: qdot stability FILE (--ignore Q[,Q...] [--momentum \"p_Q=VALUE\"] [--omega \"Q'=VALUE\"]"
    " | --driven \"Q' = VALUE\"...) [--at \"q=VALUE, ...\"] [--guess \"q=VALUE, ...\"] "
    "[--scan NAME=A:B [--steps N]] [--set NAME=VALUE]... [--format text|json]";

static const char *const formats[] = {"text", "json", NULL};

static int steps_option(const char *v, size_t *steps) {
    char *end;
    long k = strtol(v, &end, 10);
    if (*end || k < 1 || k > 100000) {
        cli_diag_error("--steps takes a number of steps from 1 to 100000, not '%s'", v);
        return QD_EXIT_USAGE;
    }
    *steps = (size_t)k;
    return QD_EXIT_OK;
}
static int parse_option(int argc, char **argv, int *i, void *data) {
    stab_args *a = data;
    const char *v;
    int f;
    if ((v = cli_value(argc, argv, i, "--format"))) {
        int rc = cli_choice("--format", v, formats, &f);
        a->json = f == 1;
        return rc;
    }
    if ((v = cli_value(argc, argv, i, "--set")))
        return cli_push("--set", a->sets, &a->nsets, MAX_SETS, v);
    if ((v = cli_value(argc, argv, i, "--driven")))
        return cli_push("--driven", a->driven, &a->ndriven, MAX_LIST, v);
    if ((v = cli_value(argc, argv, i, "--ignore")))
        return cli_once("--ignore", &a->ignore, v);
    if ((v = cli_value(argc, argv, i, "--momentum")))
        return cli_once("--momentum", &a->momentum, v);
    if ((v = cli_value(argc, argv, i, "--omega")))
        return cli_once("--omega", &a->omega, v);
    if ((v = cli_value(argc, argv, i, "--at")))
        return cli_once("--at", &a->at, v);
    if ((v = cli_value(argc, argv, i, "--guess")))
        return cli_once("--guess", &a->guess, v);
    if ((v = cli_value(argc, argv, i, "--scan")))
        return cli_once("--scan", &a->scan, v);
    if ((v = cli_value(argc, argv, i, "--steps")))
        return steps_option(v, &a->steps);
    return cli_bad_option(argv[*i], usage_text);
}

static int parse_args(int argc, char **argv, stab_args *a) {
    *a = (stab_args){.json = false};
    int rc = cli_file_args(argc, argv, "stability", usage_text, &a->file, parse_option, a);
    if (rc != QD_EXIT_OK)
        return rc;
    if (!a->ignore == !a->ndriven) {
        cli_diag_error("give the cyclic coordinates with either --ignore (free momenta) or "
                      "--driven (maintained rates)\n%s", usage_text);
        return QD_EXIT_USAGE;
    }
    if (a->ndriven && (a->momentum || a->omega)) {
        cli_diag_error("--momentum and --omega go with --ignore; a driven rate is given as "
                      "--driven \"q' = VALUE\"");
        return QD_EXIT_USAGE;
    }
    if (a->steps && !a->scan) {
        cli_diag_error("--steps is the number of steps of --scan: give --scan NAME=A:B");
        return QD_EXIT_USAGE;
    }
    return QD_EXIT_OK;
}

/* ---- the pipeline ---------------------------------------------------------- */

/* The context's error: one about an option's text under that text with a
 * caret (the library names its field), any other as cli_diag_ctx. */
static int steady_error(const stab_run *r, const stab_args *a) {
    const qd_diag *d = qd_ctx_diag(r->ctx);
    const struct { const char *field, *opt, *text; } texts[] = {
        {"ignore", "--ignore", a->ignore}, {"driven", "--driven", r->driven},
        {"omega", "--omega", a->omega},    {"momentum", "--momentum", a->momentum},
        {"guess", "--guess", a->guess},    {"at", "--at", a->at},
    };
    for (size_t k = 0; d->located && k < sizeof texts / sizeof texts[0]; k++)
        if (texts[k].text && !strcmp(d->name, texts[k].field)) {
            cli_diag_show(texts[k].opt, texts[k].text, d);
            return cli_exit(qd_ctx_status(r->ctx));
        }
    return cli_diag_ctx(r->ctx);
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
    if (a->ndriven && !(r->driven = join(a->driven, a->ndriven))) {
        cli_diag_error("out of memory");
        return QD_EXIT_FAIL;
    }
    r->s = qd_steady_derive_named(r->ctx, r->mf.model, r->e, a->ignore ? "ignore" : "driven",
                                  a->ignore ? a->ignore : r->driven, a->ndriven > 0);
    if (!r->s)
        return steady_error(r, a);
    qd_steady_spec spec = {.rates = a->ndriven ? r->driven : a->omega,
                           .rates_field = a->ndriven ? "driven" : "omega",
                           .momenta = a->momentum, .guess = a->guess, .at = a->at};
    if (qd_steady_given_read(r->ctx, r->s, r->mf.model, &spec, &r->g) != QD_OK)
        return steady_error(r, a);
    return QD_EXIT_OK;
}

/* Every steady motion and its analysis: the library has left out the
 * motions where the coordinates are singular (counted in set.nsingular). */
static int solve(stab_run *r) {
    const qd_steady_given *g = &r->g;
    if (qd_steady_find_all(r->ctx, r->s, g->nvals, g->syms, g->vals, g->xfix, g->wfix, g->pfix,
                           g->pguess, &g->start, &r->set) != QD_OK)
        return cli_diag_ctx(r->ctx);
    r->an = calloc(r->set.count + 1, sizeof *r->an);
    if (!r->an) {
        cli_diag_error("out of memory");
        return QD_EXIT_FAIL;
    }
    for (size_t k = 0; k < r->set.count; k++)
        if (qd_stability_analyze(r->ctx, r->s, g->nvals, g->syms, g->vals, &r->set.pts[k],
                                 &r->an[k]) != QD_OK)
            return cli_diag_ctx(r->ctx);
    return QD_EXIT_OK;
}

/* ---- --scan ------------------------------------------------------------------ */

/* Column names: the kept coordinates, Q' and p_Q (room: 64 bytes each). */
static void scan_names(const qd_steady *s, char (*buf)[64], const char **names) {
    size_t nk = s->nkeep, nc = s->ncyc;
    for (size_t j = 0; j < nk; j++)
        names[j] = qd_expr_name(s->keep[j]);
    for (size_t c = 0; c < nc; c++) {
        snprintf(buf[c], sizeof buf[c], "%s'", qd_expr_name(s->cyc[c]));
        snprintf(buf[nc + c], sizeof buf[nc + c], "p_%s", qd_expr_name(s->cyc[c]));
        names[nk + c] = buf[c];
        names[nk + nc + c] = buf[nc + c];
    }
}

/* The steady motion followed along a parameter: a table and the changes of
 * its stability. */
static int scan(stab_run *r, const stab_args *a) {
    char name[128];
    double lo, hi;
    int rc = cli_scan_range(r->ctx, a->scan, name, sizeof name, &lo, &hi);
    size_t nu = r->s->nkeep + 2 * r->s->ncyc;
    const char **names = calloc(nu + 1, sizeof *names);
    char (*buf)[64] = calloc(2 * r->s->ncyc + 1, sizeof *buf);
    if (!names || !buf)
        rc = QD_EXIT_FAIL;
    const qd_steady_given *g = &r->g;
    qd_scan_opts o = {.steps = a->steps, .about = g->held};
    qd_scan sc = {0};
    if (rc == QD_EXIT_OK && qd_stability_scan(r->ctx, r->s, r->mf.model, name, lo, hi, g->xfix,
                                              g->wfix, g->pfix, g->pguess, &g->start, &o,
                                              &sc) != QD_OK) {
        rc = qd_ctx_status(r->ctx) == QD_ERR_ARG ? QD_EXIT_USAGE : QD_EXIT_FAIL;
        cli_diag_error("--scan: %s", qd_ctx_message(r->ctx));
    } else if (rc == QD_EXIT_OK) {
        scan_names(r->s, buf, names);
        const char *how = r->s->driven ? "rates maintained: V - T0" : "momenta free: Routhian";
        char followed[160];
        snprintf(followed, sizeof followed, "the steady motion (%s); %s stability", how,
                 sc.damped ? "with the model's damping" : "ordinary");
        cli_scan_view v = {name, names, followed, "steady_motion"};
        rc = cli_scan_emit(&v, &sc, a->json);
    }
    qd_scan_free(&sc);
    free(names);
    free(buf);
    return rc;
}

static int emit(stab_run *r, bool json) {
    qd_buf b = QD_BUF_INIT;
    qd_stability_report rep = {r->s, &r->g, &r->set, r->an, r->mf.path};
    if (qd_stability_print(r->ctx, &rep, json, &b) != QD_OK) {
        qd_buf_free(&b);
        return cli_diag_ctx(r->ctx);
    }
    return cli_emit(&b, "result");
}

int cli_cmd_stability(int argc, char **argv) {
    stab_args a;
    int rc = parse_args(argc, argv, &a);
    if (rc != QD_EXIT_OK)
        return rc;
    stab_run r = {.ctx = qd_ctx_new()};
    if (!r.ctx) {
        cli_diag_error("out of memory");
        return QD_EXIT_FAIL;
    }
    rc = cli_load_derive(r.ctx, a.file, a.nsets, a.sets, false, NULL, &r.mf, &r.e);
    if (rc == QD_EXIT_OK)
        rc = prepare(&r, &a);
    if (rc == QD_EXIT_OK)
        rc = a.scan ? scan(&r, &a) : solve(&r);
    if (rc == QD_EXIT_OK && !a.scan)
        rc = emit(&r, a.json);
    for (size_t k = 0; r.an && k < r.set.count; k++)
        qd_stability_free(&r.an[k]);
    free(r.an);
    qd_steady_set_free(&r.set);
    qd_steady_given_free(&r.g);
    qd_steady_free(r.s);
    free(r.driven);
    if (r.e)
        qd_eom_free(r.e);
    cli_model_file_free(&r.mf);
    qd_ctx_free(r.ctx);
    return rc;
}

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
#include "driver.h"

#include <stdio.h>
#include <string.h>
#include "qdot/integrals.h"

typedef struct int_args {
    const char *format;
    bool no_search;
    cli_list set, symmetry, integral;
} int_args;

static const char *const formats[] = {"text", "json", "latex", NULL};
static const cli_opt opts[] = {
    {"--format", NULL, CLI_CHOICE, offsetof(int_args, format), "FORMAT", "output format",
     formats, NULL},
    {"--symmetry", NULL, CLI_LIST, offsetof(int_args, symmetry), "\"[NAME:] x -> x + eps, ...\"",
     "a symmetry to examine, as the model's `symmetry` statement takes it", NULL, NULL},
    {"--integral", NULL, CLI_LIST, offsetof(int_args, integral), "\"[NAME:] EXPR\"",
     "a proposed integral to check, as the `integral` statement takes it", NULL, NULL},
    {"--no-search", NULL, CLI_FLAG, offsetof(int_args, no_search), NULL,
     "do not look for symmetries by the coordinates' names", NULL, NULL},
    CLI_OPT_SET(int_args, set),
    {0},
};

static const cli_spec spec = {
    "integrals", "FILE [options]",
    "Integrals of motion: cyclic coordinates, Jacobi's integral, the energy balance, Noether.",
    opts, NULL, 1, 1, "FILE", false,
};

typedef struct int_run {
    cli_run c;
    qd_eom *e;
    qd_integrals *I;
    int_args a;
    qd_integrals_given g;
} int_run;

/* ---- --symmetry and --integral ------------------------------------------- */

/* Added to the model as its own `symmetry` and `integral` statements (after
 * the file's); unnamed ones are S1, S2, ... and J1, J2, ... */
static int parse_given(int_run *r) {
    int rc = QD_EXIT_OK;
    char label[32];
    for (size_t k = 0; rc == QD_EXIT_OK && k < r->a.symmetry.n; k++) {
        snprintf(label, sizeof label, "S%zu", k + 1);
        rc = cli_model_add_given(&r->c.mf, "--symmetry", "symmetry", label,
                                 r->a.symmetry.items[k]);
    }
    for (size_t k = 0; rc == QD_EXIT_OK && k < r->a.integral.n; k++) {
        snprintf(label, sizeof label, "J%zu", k + 1);
        rc = cli_model_add_given(&r->c.mf, "--integral", "integral", label,
                                 r->a.integral.items[k]);
    }
    return rc;
}

static int emit(int_run *r) {
    qd_buf b = QD_BUF_INIT;
    bool latex = r->a.format && !strcmp(r->a.format, "latex");
    qd_status st = cli_json(r->a.format) ? qd_integrals_json(r->c.ctx, r->I, &r->g, r->c.mf.path, &b)
                   : latex ? qd_integrals_latex(r->c.ctx, r->I, &r->g, &b)
                           : qd_integrals_print(r->c.ctx, r->I, &r->g, r->c.mf.path, &b);
    return cli_emit_status(r->c.ctx, st, &b, "integrals");
}

static int run(cli_run *c) {
    int_run *r = (int_run *)c;
    int rc = cli_load_derive(c->ctx, c->file, r->a.set.n, r->a.set.items, "integrals", NULL, &c->mf,
                             &r->e);
    if (rc == QD_EXIT_OK)
        rc = parse_given(r);
    qd_integrals_opts o = {.search = !r->a.no_search};
    if (rc == QD_EXIT_OK && !(r->I = qd_integrals_derive(c->ctx, c->mf.model, r->e, &o)))
        rc = cli_diag_ctx(c->ctx);
    if (rc == QD_EXIT_OK && qd_integrals_given_derive(c->ctx, r->I, c->mf.model, &r->g) != QD_OK)
        rc = cli_diag_ctx(c->ctx);
    return rc == QD_EXIT_OK ? emit(r) : rc;
}

static void run_free(cli_run *c) {
    int_run *r = (int_run *)c;
    qd_integrals_given_free(&r->g);
    qd_integrals_free(r->I);
    qd_eom_free(r->e);
}

CLI_COMMAND(integrals, int_run, &spec, offsetof(int_run, a), 0, NULL, run, run_free)

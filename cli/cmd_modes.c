/*
 * cli/cmd_modes.c - `qdot modes FILE`: small oscillations about an
 * equilibrium (or any point at rest given with --about).  libqdot
 * linearizes (qd_linear_about: M0 q'' + (C0 + G0) q' + K0 q = 0) and solves
 * the eigenproblem (qd_modes_solve: K0 a = w^2 M0 a, or the state-space
 * eigenvalues when there is damping or a gyroscopic term); with 1 or 2
 * degrees of freedom about an exact equilibrium, w^2 is also printed as an
 * expression of the parameters (or, when the equilibrium itself depends on
 * the parameters' values, as an exact number at those values).  --initial
 * gives the motion from initial values through the normal coordinates
 * Q = a^T M0 (q - q0).
 *
 * Without --about or --at-equilibrium libqdot chooses the equilibrium
 * (qd_equilibria_choose: a minimum of the potential nearest the model's
 * `initial` state, or of lowest V without one); this file says which and
 * how many others there are on stderr (text); the JSON has it as "choice".
 * The printing is libqdot's (qd_modes_print, qdot/modes.h).
 *
 * --symmetry (modes_symmetry.c): the symmetry group of the point, its
 * character table and the modes labelled by irreps, in place of the plain
 * conservative modes.
 */
#include "linear_cli.h"

#include <stdlib.h>
#include <string.h>
#include "modes_plot.h"
#include "modes_symmetry.h"
#include "plot_cli.h"
#include "qdot/conlin.h"

typedef struct modes_args {
    const char *about, *initial, *scan, *format;
    const char *independent; /* --independent: a model that keeps constraints */
    uint64_t steps; /* --steps: 0 the library's default */
    size_t at_eq;   /* 1-based; 0: the first minimum, else the first */
    cli_list sets;
    bool json, field; /* from the above: --format json; FILE declares a field */
    const char *plot;  /* --plot FILE: the mode shapes drawn */
    bool symmetry;     /* --symmetry */
    cli_plot_args look; /* --title, --size, ... of --plot */
    uint64_t count;    /* --count: a field model's number of modes */
    double tol;        /* --tol: a field model's relative tolerance */
} modes_args;

typedef struct modes_run {
    cli_lin_run lr; /* first: the run state starts with its cli_run */
    modes_args a;
    qd_modes_at at;             /* the point and the modes there (qdot/modes.h) */
    double *Q, *Qd;             /* --initial: normal coordinates at t = 0 */
    cli_sym_run sym;            /* --symmetry */
} modes_run;

static const cli_group groups[] = {CLI_PLOT_LOOK_GROUP(modes_args, look), {NULL, 0}};

#define OPT(...) CLI_OPT(modes_args, __VA_ARGS__)
static const cli_opt opts[] = {
    OPT("--at-equilibrium", CLI_COUNT, at_eq, "N", "about equilibrium N, as `qdot equilibria` "
        "lists them"),
    OPT("--about", CLI_TEXT, about, "\"q1=VALUE, ...\"", "about this point at rest"),
    OPT("--initial", CLI_TEXT, initial, "\"q1=VALUE, q1'=VALUE, ...\"", "the motion from these "
        "initial values, through the normal coordinates"),
    OPT("--scan", CLI_TEXT, scan, "NAME=A:B", "follow the point as the parameter goes from A to "
        "B, and where its stability changes"),
    CLI_OPT_IN(modes_args, "--steps", CLI_WHOLE, steps, "N", "steps of --scan (at most 100000)",
               1, 100000),
    OPT("--symmetry", CLI_FLAG, symmetry, NULL, "the point's symmetry group and the modes "
        "labelled by irreps"),
    OPT("--independent", CLI_TEXT, independent, "\"q1, ...\"", "the independent coordinates "
        "of a model that keeps constraints"),
    OPT("--plot", CLI_TEXT, plot, "FILE.png|.svg|.pdf", "draw the mode shapes"),
    CLI_OPT_IN(modes_args, "--count", CLI_WHOLE, count, "N", "a field model: the number of modes "
               "(at most 1000)", 1, 1000),
    CLI_OPT_IN(modes_args, "--tol", CLI_RANGE, tol, "X", "a field model: the relative tolerance "
               "(1e-14 to 0.1)", 1e-14, 0.1),
    CLI_OPT_SET(modes_args, sets),
    CLI_OPT_FORMAT(modes_args, format),
    {0},
};
#undef OPT

static const cli_spec spec = {
    "modes", "FILE [--at-equilibrium N | --about \"q1=VALUE, ...\"] [options]",
    "small oscillations about an equilibrium: frequencies and mode shapes (a field model: "
    "FIELDFILE [--count N] [--tol X])", opts, groups, 1, 1, "FILE", false};

/* The point (qd_modes_at_choose): --about's, --at-equilibrium's or the
 * library's choice. */
static int choose_point(modes_run *r, const modes_args *a) {
    qd_ctx *ctx = r->lr.c.ctx;
    qd_status st = qd_modes_at_choose(ctx, &r->lr.pt, a->about, a->at_eq, &r->at);
    if (st == QD_OK)
        return QD_EXIT_OK;
    if (a->about && qd_ctx_diag(ctx)->located)
        return cli_state_diag(ctx, "--about", a->about);
    if (st == QD_ERR_ARG)
        return cli_usage_error("--at-equilibrium %zu: %s", a->at_eq, qd_ctx_message(ctx));
    if (st == QD_ERR_NUMERIC && !r->at.pt)
        cli_diag_error("no equilibrium found (qdot equilibria lists none): give a point "
                       "with --about");
    else
        cli_diag_error("%s", qd_ctx_message(ctx));
    return QD_EXIT_FAIL;
}

/* The modes at the point (qd_modes_at_solve); the state there, at rest, for
 * what follows (--initial, --symmetry, --plot). */
static int linearize(modes_run *r) {
    cli_lin_run *lr = &r->lr;
    const qd_state *s = &lr->pt.st;
    qd_linpoint_set(&lr->pt, r->at.q0, NULL);
    if (qd_modes_at_solve(lr->c.ctx, lr->e, lr->c.mf.model, s->n, s->syms, s->vals, &r->at) !=
        QD_OK) {
        cli_diag_error("%s", qd_ctx_message(lr->c.ctx));
        return QD_EXIT_FAIL;
    }
    return QD_EXIT_OK;
}

/* --initial in the normal coordinates (qd_modes_at_initial). */
static int initial(modes_run *r, const char *text) {
    qd_ctx *ctx = r->lr.c.ctx;
    size_t n = r->lr.e->n;
    if (!(r->Q = calloc(n + 1, sizeof *r->Q)) || !(r->Qd = calloc(n + 1, sizeof *r->Qd)))
        return cli_out_of_memory();
    if (qd_modes_at_initial(ctx, &r->lr.pt, &r->at, text, r->Q, r->Qd) == QD_OK)
        return QD_EXIT_OK;
    if (qd_ctx_diag(ctx)->located)
        return cli_state_diag(ctx, "--initial", text);
    if (qd_ctx_status(ctx) != QD_ERR_ARG)
        return cli_diag_ctx(ctx);
    return cli_usage_error("--initial: %s", qd_ctx_message(ctx));
}

/* The library's printer (qd_modes_print) on what was computed. */
static int emit(modes_run *r, bool json) {
    qd_modes_report rep = {
        .e = r->lr.e, .q0 = r->at.q0, .pt = r->at.pt, .choice = r->at.chosen ? &r->at.choice : NULL,
        .residual = r->at.residual, .lin = &r->at.lin, .res = &r->at.res,
        .w2exact = r->at.have_exact ? r->at.w2exact : NULL,
        .w2exact_in_params = r->at.exact_in_params,
        .Q = r->Q, .Qd = r->Qd,
        .sym = r->sym.active && !r->sym.cyc.n ? &r->sym.sym : NULL,
        .cyc = r->sym.active && r->sym.cyc.n ? &r->sym.cyc : NULL};
    qd_buf b = QD_BUF_INIT;
    if (qd_modes_print(r->lr.c.ctx, &rep, json, &b) != QD_OK) {
        b.failed = true; /* "cannot print the modes" */
        qd_ctx_clear_error(r->lr.c.ctx);
    }
    return cli_emit(&b, "modes");
}

/* Which equilibrium was taken without --about, and that there are others
 * (qd_equilibrium_choice_note). */
static void note_choice(const modes_run *r) {
    qd_buf b = QD_BUF_INIT;
    if (qd_equilibrium_choice_note(r->lr.e, &r->at.choice, &b) == QD_OK)
        fprintf(stderr, "qdot: note: modes about %s%s\n", qd_buf_str(&b),
                r->at.choice.others ? " (qdot equilibria lists them; choose with --at-equilibrium N "
                               "or --about)"
                             : "");
    qd_buf_free(&b);
}

/* The options that go together, before anything is read. */
static int check(cli_run *c) {
    modes_args *a = &((modes_run *)c)->a;
    int rc;
    a->json = cli_json(a->format);
    if ((a->field = cli_model_file_is_field(c->file))) {
        if (a->about || a->at_eq || a->initial || a->scan || a->plot || a->symmetry || a->steps)
            return cli_usage_error("a field model takes --count, --tol, --set and --format only");
        return QD_EXIT_OK;
    }
    if (a->count || a->tol)
        return cli_usage_error("--count and --tol are for a field model (`field y(x, t) on ...`)");
    if (a->about && a->at_eq)
        return cli_usage_error("give either --at-equilibrium or --about, not both");
    if (a->scan && (a->at_eq || a->initial))
        return cli_usage_error("--scan follows the point given with --about (or the equilibrium "
                               "chosen at the start of the range): give neither --at-equilibrium "
                               "nor --initial");
    if (a->plot && a->scan)
        return cli_usage_error("--plot draws the modes about one point: not with --scan");
    a->look.file = a->plot;
    if ((rc = cli_plot_check(&a->look, "modes")))
        return rc;
    if (a->symmetry && a->scan)
        return cli_usage_error("--symmetry labels the modes about one point: not with --scan");
    if (a->steps && !a->scan)
        return cli_usage_error("--steps is the number of steps of --scan: give --scan NAME=A:B");
    return QD_EXIT_OK;
}

static int run(cli_run *c) {
    modes_run *r = (modes_run *)c;
    const modes_args *a = &r->a;
    if (a->field)
        return cli_field_modes(c->ctx, &c->mf, c->file, a->sets.n, a->sets.items, a->count,
                               a->tol, a->json);
    int rc = cli_lin_load_model(&r->lr, c->file, a->sets.items, a->sets.n);
    if (rc == QD_EXIT_OK && a->plot && qd_model_nspeeds(c->mf.model))
        rc = cli_usage_error("--plot: the modes of a model in speeds are not drawn yet");
    if (rc == QD_EXIT_OK && a->symmetry && qd_model_nspeeds(c->mf.model))
        rc = cli_usage_error("--symmetry: the modes of a model in speeds are not analysed by "
                             "symmetry");
    if (rc == QD_EXIT_OK && qd_model_nspeeds(c->mf.model))
        return cli_speeds_modes(c->ctx, &c->mf, a->about, a->scan, a->steps, a->json,
                                a->at_eq ? "--at-equilibrium" : a->initial ? "--initial" : NULL);
    if (rc == QD_EXIT_OK)
        rc = cli_lin_derive(&r->lr);
    if (rc == QD_EXIT_OK && (r->lr.e->ncon ? a->symmetry || a->plot || a->initial ||
                                                 (a->at_eq && qd_conlin_needed(r->lr.e))
                                           : a->independent != NULL))
        rc = cli_usage_error(r->lr.e->ncon ? "%s: not yet on the constraint manifold of a model "
                                             "that keeps constraints with multipliers"
                                           : "%s: the model keeps no constraints",
                             r->lr.e->ncon ? (a->symmetry ? "--symmetry" : a->plot ? "--plot"
                                              : a->initial ? "--initial" : "--at-equilibrium")
                                           : "--independent");
    /* velocity constraints (steady motions: the rolling disc), --scan: the state manifold */
    const cli_conlin_args ca = {a->about, a->independent, a->scan, NULL,
                                a->json ? QD_SS_JSON : QD_SS_TEXT, a->steps, true, NULL, NULL, NULL};
    if (rc == QD_EXIT_OK && r->lr.e->ncon && (qd_conlin_needed(r->lr.e) || a->scan))
        return cli_conlin(&r->lr, &ca);
    if (rc == QD_EXIT_OK && a->scan)
        return cli_scan_modes(&r->lr, a->scan, a->about, a->steps, a->json);
    if (rc == QD_EXIT_OK)
        rc = choose_point(r, a);
    if (rc == QD_EXIT_OK && r->at.chosen && !a->json)
        note_choice(r);
    if (rc == QD_EXIT_OK && r->lr.e->ncon) /* on the manifold (constrained_cli.c) */
        return cli_con_modes(&r->lr, r->at.q0, a->independent, a->json);
    if (rc == QD_EXIT_OK)
        rc = linearize(r);
    if (rc == QD_EXIT_OK && a->symmetry)
        rc = cli_sym_compute(&r->lr, &r->at.lin, &r->sym);
    if (rc == QD_EXIT_OK && a->initial)
        rc = initial(r, a->initial);
    if (rc == QD_EXIT_OK)
        rc = emit(r, a->json);
    if (rc == QD_EXIT_OK && a->plot)
        rc = cli_modes_plot(&r->lr, r->at.q0, &r->at.res, &a->look, c->file, &r->sym);
    return rc;
}

static void run_free(cli_run *c) {
    modes_run *r = (modes_run *)c;
    free(r->Q);
    free(r->Qd);
    qd_modes_at_free(&r->at);
    cli_sym_free(&r->sym);
    cli_lin_free(&r->lr);
}

CLI_COMMAND(modes, modes_run, &spec, offsetof(modes_run, a), 0, check, run, run_free)

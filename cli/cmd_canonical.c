/*
 * cli/cmd_canonical.c - `qdot canonical FILE --Q "..." --P "..."`: is the
 * change of variables (q, p) -> (Q, P) canonical (qd_canonical_examine)?  A
 * yes/no question, so the status carries the answer: canonical exits 0; a
 * scaled map ([Q_i, P_i] = c, c != 1: Goldstein's extended canonical
 * transformation, not a canonical one) and a map with a failing fundamental
 * bracket are a certified "no", exit 3 (QD_EXIT_NO) with the verdict and its
 * witness printed; a bracket neither proved nor refuted exits 1.
 * `--generator F1..F4 EXPR` instead gives the transformation a generating
 * function defines and K = H + dF/dt (qd_generate).  The variables are the
 * library's phase space (qd_phase): new ones Q, P or Q1..Qn, P1..Pn.  The
 * `--condensed`: the map in Desloge's condensed notation (ch. 75;
 * qd_condensed_new), its Jacobian, M^T mu M and Thm 1.  The
 * library writes the answers (qd_canon_report_print, qd_gen_result_print);
 * this file reads the options, shows errors and maps the verdict to the
 * exit status.
 */
#include "driver.h"

#include <stdlib.h>

typedef struct can_args {
    const char *Q, *P, *gen, *format;
    bool lagrange, newham, condensed;
    cli_list set;
} can_args;

static const char *const gen_types[] = {"F1", "F2", "F3", "F4", NULL};

static const cli_opt opts[] = {
    {"--Q", NULL, CLI_TEXT, offsetof(can_args, Q), "\"Q1, ...\"",
     "the new coordinates, one expression in q, p_q, t per coordinate", NULL, NULL},
    {"--P", NULL, CLI_TEXT, offsetof(can_args, P), "\"P1, ...\"", "the new momenta, likewise",
     NULL, NULL},
    {"--lagrange", NULL, CLI_FLAG, offsetof(can_args, lagrange), NULL,
     "the Lagrange brackets of the old variables and their duality", NULL, NULL},
    {"--K", NULL, CLI_FLAG, offsetof(can_args, newham), NULL,
     "F and the new Hamiltonian K = c H + sum P dQ/dt + dF/dt", NULL, NULL},
    {"--condensed", NULL, CLI_FLAG, offsetof(can_args, condensed), NULL,
     "the map in the condensed notation: r, mu, r' = mu grad H, dR/dr, M^T mu M (ch. 75)",
     NULL, NULL},
    {"--generator", NULL, CLI_CHOICE, offsetof(can_args, gen), "TYPE",
     "the map of the generating function EXPR (the argument after FILE) of this type",
     gen_types, NULL},
    CLI_OPT_FORMAT(can_args, format),
    CLI_OPT_SET(can_args, set),
    {0},
};

static const cli_spec spec = {
    "canonical", "FILE --Q \"Q1, ...\" --P \"P1, ...\" [options] | FILE --generator TYPE EXPR",
    "Is (q, p) -> (Q, P) canonical (exit 0 yes, 3 no)?  Or the map a generating function "
    "gives, with K = H + dF/dt.",
    opts, NULL, 1, 2, "FILE", true,
};

typedef struct can_run {
    cli_run c;
    can_args a;
    const char *pos[2]; /* FILE and the generator's EXPR */
    qd_phase ph;
    const qd_expr **Q, **P; /* --Q and --P */
    qd_canon_report rep;
    bool json;
} can_run;

/* The library's document on stdout, or why it cannot be printed. */
static int emit(qd_status st, qd_buf *b) {
    b->failed = b->failed || st != QD_OK;
    return cli_emit(b, "result");
}

/* --Q or --P: one expression per coordinate; the error shown in the list. */
static int read_list(can_run *r, const char *what, const char *text, const qd_expr ***out) {
    qd_diag err;
    if (!(*out = calloc(r->ph.n + 1, sizeof **out)))
        return cli_out_of_memory();
    if (qd_phase_read_list(r->c.ctx, &r->ph, text, *out, &err) == QD_OK)
        return QD_EXIT_OK;
    cli_diag_read(what, text, &err);
    return cli_exit(err.status);
}

/* An error after the model was read: at its statement when it is about one. */
static int failure(const can_run *r) {
    return cli_diag_model(r->c.ctx, r->c.mf.path, r->c.mf.text, r->c.mf.model);
}

/* The verdict and the extras asked, or (--condensed) Thm 1 of ch. 75 on
 * M^T mu M with Hamilton's equations r' = mu grad H when the model's H is
 * closed (qd_phase_condensed); the exit status carries the answer: 0
 * canonical, 3 a certified no (scaled or a failing bracket), 1 undecided. */
static int examine(can_run *r, const can_args *a) {
    qd_ctx *ctx = r->c.ctx;
    int rc = read_list(r, "--Q", a->Q, &r->Q);
    if (rc == QD_EXIT_OK)
        rc = read_list(r, "--P", a->P, &r->P);
    if (rc != QD_EXIT_OK)
        return rc;
    qd_condensed cd = {0};
    if (a->condensed ? qd_phase_condensed(ctx, &r->ph, r->Q, r->P, &cd) != QD_OK
                     : qd_canonical_examine(ctx, &r->ph, r->Q, r->P, a->lagrange, a->newham,
                                            &r->rep) != QD_OK)
        return failure(r);
    qd_buf b = QD_BUF_INIT;
    rc = emit(a->condensed ? qd_condensed_print(ctx, &cd, r->json, &b)
                           : qd_canon_report_print(ctx, &r->ph, &r->rep, r->json, &b),
              &b);
    qd_canon_kind k = a->condensed ? cd.kind : r->rep.v.kind;
    if (a->condensed)
        qd_condensed_free(&cd);
    return rc != QD_EXIT_OK          ? rc
           : k == QD_CANON_YES       ? QD_EXIT_OK
           : k == QD_CANON_UNDECIDED ? QD_EXIT_FAIL
                                     : QD_EXIT_NO;
}

static int generate(can_run *r, const can_args *a, const char *text) {
    qd_ctx *ctx = r->c.ctx;
    qd_phase *ph = &r->ph;
    qd_diag err;
    if (qd_phase_new_vars(ctx, ph) != QD_OK) /* F is a function of them too */
        return failure(r);
    const qd_expr *F = qd_phase_read(ctx, ph, text, &err);
    if (!F) {
        cli_diag_read("generator", text, &err);
        return cli_exit(err.status);
    }
    if (qd_phase_ham(ctx, ph, true) != QD_OK)
        return failure(r);
    qd_gen_result g = {0};
    qd_gen_type type = (qd_gen_type)(a->gen[1] - '0');
    qd_status st = qd_generate(ctx, type, ph->n, ph->q, ph->p, ph->Q, ph->P, F, qd_time(ctx),
                               ph->h->H, &g);
    qd_buf b = QD_BUF_INIT;
    int rc = st != QD_OK ? failure(r)
                         : emit(qd_gen_result_print(ctx, ph, type, F, &g, r->json, &b), &b);
    qd_gen_result_free(&g);
    return rc;
}

/* The options' combinations: --Q with --P, or --generator with its EXPR. */
static int combination(cli_run *c) {
    can_run *r = (can_run *)c;
    const can_args *a = &r->a;
    const char *expr = r->pos[1];
    r->json = cli_json(a->format);
    const char *why = a->gen && (a->Q || a->P) ? "give either --Q and --P or --generator"
                      : a->gen && (a->lagrange || a->newham || a->condensed)
                          ? "--lagrange, --K and --condensed go with --Q and --P"
                      : a->condensed && (a->lagrange || a->newham)
                          ? "--condensed is not taken with --lagrange or --K"
                      : a->gen && !expr ? "--generator needs its expression EXPR after FILE"
                      : !a->gen && expr ? "an expression after FILE goes with --generator"
                      : !a->gen && !a->Q ? "--Q is missing"
                      : !a->gen && !a->P ? "--P is missing"
                                         : NULL;
    if (!why)
        return QD_EXIT_OK;
    return cli_usage_error("%s (qdot canonical --help)", why);
}

static int run(cli_run *c) {
    can_run *r = (can_run *)c;
    int rc = cli_load(c->ctx, r->pos[0], r->a.set.n, r->a.set.items, "canonical", &c->mf);
    if (rc == QD_EXIT_OK && qd_phase_init(c->ctx, c->mf.model, &r->ph) != QD_OK)
        rc = cli_diag_ctx(c->ctx);
    if (rc == QD_EXIT_OK)
        rc = r->a.gen ? generate(r, &r->a, r->pos[1]) : examine(r, &r->a);
    return rc;
}

static void run_free(cli_run *c) {
    can_run *r = (can_run *)c;
    free(r->Q);
    free(r->P);
    qd_canon_report_free(&r->rep);
    qd_phase_free(&r->ph);
}

CLI_COMMAND(canonical, can_run, &spec, offsetof(can_run, a),
            offsetof(can_run, pos), combination, run, run_free)

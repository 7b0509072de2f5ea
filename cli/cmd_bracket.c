/*
 * cli/cmd_bracket.c - `qdot bracket FILE F G`: the Poisson bracket [F, G]
 * (qd_bracket) in the model's canonical variables (qd_phase); `--dt F`
 * gives dF/dt along the motion (qd_phase_dt: [F, H], the explicit t and the
 * forces' part; for an implicit H in q' too).  F and G are expressions (H
 * the model's Hamiltonian), so "-x" is one and `--` ends the options.
 * Written by qd_phase_bracket_print (qdot/canonical.h).
 */
#include "driver.h"

typedef struct br_args {
    bool dt;
    const char *format;
} br_args;

static const char *const formats[] = {"text", "json", "latex", NULL};

static const cli_opt opts[] = {
    {"--dt", NULL, CLI_FLAG, offsetof(br_args, dt), NULL,
     "dF/dt along the motion instead of [F, G] (give F only)", NULL, NULL},
    CLI_OPT_FORMATS(br_args, format, formats),
    {0},
};

static const cli_spec spec = {
    "bracket", "FILE F G | FILE --dt F [options]",
    "The Poisson bracket [F, G] in the model's coordinates and momenta p_<q>, or dF/dt.",
    opts, NULL, 2, 3, "FILE and expressions", true,
};

/* Read what (F or G, H the model's H) on phase space; the error shown in it. */
static int read_fn(qd_ctx *ctx, qd_phase *ph, const char *what, const char *text,
                   const qd_expr **out) {
    qd_diag err;
    if ((*out = qd_phase_read_h(ctx, ph, text, &err)))
        return QD_EXIT_OK;
    cli_diag_read(what, text, &err);
    return cli_exit(err.status);
}

typedef struct br_run {
    cli_run c;
    br_args a;
    const char *pos[3]; /* FILE, F, G */
    qd_phase ph;
} br_run;

static int check(cli_run *c) {
    const br_run *r = (br_run *)c;
    if (r->a.dt ? r->pos[2] == NULL : r->pos[2] != NULL)
        return QD_EXIT_OK;
    cli_diag_error(r->a.dt ? "bracket --dt takes one expression F" : "bracket needs F and G");
    cli_usage(&spec, stderr);
    return QD_EXIT_USAGE;
}

static int run(cli_run *c) {
    br_run *rr = (br_run *)c;
    qd_ctx *ctx = c->ctx;
    const cli_model_file *mf = &c->mf;
    const br_args *a = &rr->a;
    qd_phase *ph = &rr->ph;
    int rc = cli_load(ctx, rr->pos[0], 0, NULL, "bracket", &c->mf);
    if (rc == QD_EXIT_OK && qd_phase_init(ctx, mf->model, ph) != QD_OK)
        rc = cli_diag_ctx(ctx);
    const qd_expr *F, *G = NULL, *r;
    if (rc == QD_EXIT_OK)
        rc = read_fn(ctx, ph, "F", rr->pos[1], &F);
    if (rc == QD_EXIT_OK && !a->dt)
        rc = read_fn(ctx, ph, "G", rr->pos[2], &G);
    if (rc != QD_EXIT_OK)
        return rc;
    r = a->dt ? qd_phase_dt(ctx, ph, F) : qd_bracket(ctx, ph->n, ph->q, ph->p, F, G);
    if (!r)
        return cli_diag_model(ctx, mf->path, mf->text, mf->model);
    qd_buf b = QD_BUF_INIT;
    return cli_emit_status(ctx, qd_phase_bracket_print(ctx, ph, F, G, r,
                                                       cli_format_or_text(a->format),
                                                       cli_json(a->format), &b),
                           &b, "bracket");
}

static void run_free(cli_run *c) { qd_phase_free(&((br_run *)c)->ph); }

CLI_COMMAND(bracket, br_run, &spec, offsetof(br_run, a),
            offsetof(br_run, pos), check, run, run_free)

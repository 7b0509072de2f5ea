/*
 * cli/cmd_hamiltonian.c - `qdot hamiltonian FILE`: the momenta, H(q, p, t)
 * and Hamilton's equations of a model (qd_ham_derive), with the verdicts
 * H = T + V? and H conserved?  --set gives parameters values; --at evaluates H
 * and the equations at a point (q, p, t): momenta are named there as they
 * are printed (p_r=0.3), everything else goes to the state parser.
 * A model given by H (`momenta ...`, `H = ...`) skips Lagrange's equations:
 * its equations come from H, and the Lagrangian printed is the inverse
 * Legendre transform (or the reason there is none).  What it prints is the
 * library's (qd_render_hamiltonian, qd_ham_point_eval); this is options,
 * loading and calls.
 */
#include "driver.h"

#include "qdot/render.h"
#include "eom_out.h"
#include "state.h"

typedef struct ham_run {
    cli_run c;
    qd_eom *e;
    qd_ham *h;
    const char *at, *format;
    bool second; /* --second-kind: qd_ham2_derive */
    cli_list sets;
    qd_ham_point pt; /* H and the equations at --at */
} ham_run;

static const char *const formats[] = {"text", "json", "latex", "sympy", NULL};

static const cli_opt opts[] = {
    {"--at", NULL, CLI_TEXT, offsetof(ham_run, at), "\"q=V, p_q=V, t=V\"",
     "evaluate H and the equations at this point (momenta named as printed)", NULL, NULL},
    {"--set", NULL, CLI_LIST, offsetof(ham_run, sets), "NAME=VALUE",
     "give a parameter another value (fixed into the expressions)", NULL, NULL},
    {"--second-kind", NULL, CLI_FLAG, offsetof(ham_run, second), NULL,
     "Hamilton's equations of the second kind: K from T, every other force in Q (Desloge ch. 72)",
     NULL, NULL},
    CLI_OPT_FORMATS(ham_run, format, formats),
    {NULL, NULL, CLI_FLAG, 0, NULL, NULL, NULL, NULL},
};

static const cli_spec spec = {
    "hamiltonian", "FILE [options]",
    "The momenta, H(q, p, t) and Hamilton's equations of a model, with the verdicts H = T + V? "
    "and H conserved?",
    opts, NULL, 1, 1, "FILE", false};

/* ---- --at ------------------------------------------------------------------ */

/* H and the equations at the --at point (qd_ham_point_at). */
static int evaluate(ham_run *r) {
    if (qd_ham_point_at(r->c.ctx, r->c.mf.model, r->h, r->at, &r->pt) == QD_OK)
        return QD_EXIT_OK;
    if (qd_ctx_diag(r->c.ctx)->located)
        return cli_state_diag(r->c.ctx, "--at", r->at);
    cli_diag_error("cannot evaluate at this point: %s", qd_ctx_message(r->c.ctx));
    return QD_EXIT_FAIL;
}

/* The library's rendering (qd_render_hamiltonian) of the format asked for. */
static int emit(ham_run *r) {
    qd_buf b = QD_BUF_INIT;
    b.failed = qd_render_hamiltonian(r->c.ctx, r->c.mf.model, r->h, r->c.mf.path,
                                     r->at ? &r->pt : NULL,
                                     cli_render_format(r->format), &b) != QD_OK;
    return cli_emit(&b, "Hamiltonian");
}

static int run(cli_run *c) {
    ham_run *r = (ham_run *)c;
    int rc = cli_load(c->ctx, c->file, r->sets.n, r->sets.items, "hamiltonian", &c->mf);
    bool given = rc == QD_EXIT_OK && qd_model_hamiltonian_given(c->mf.model);
    /* a singular Hessian named as the Legendre transform sees it, before
     * Lagrange's equations fail on the same matrix */
    if (rc == QD_EXIT_OK && !given && !r->second && qd_ham_regular(c->ctx, c->mf.model) != QD_OK)
        rc = cli_eom_derive_error(c->ctx, &c->mf);
    if (rc == QD_EXIT_OK && !given && !(r->e = qd_eom_derive(c->ctx, c->mf.model)))
        rc = cli_eom_derive_error(c->ctx, &c->mf);
    if (rc == QD_EXIT_OK && !(r->h = (r->second ? qd_ham2_derive : qd_ham_derive)(
                                  c->ctx, c->mf.model, r->e)))
        rc = cli_eom_derive_error(c->ctx, &c->mf);
    if (rc == QD_EXIT_OK && r->at)
        rc = evaluate(r);
    return rc == QD_EXIT_OK ? emit(r) : rc;
}

static void run_free(cli_run *c) {
    ham_run *r = (ham_run *)c;
    qd_ham_point_free(&r->pt);
    qd_ham_free(r->h);
    qd_eom_free(r->e);
}

CLI_COMMAND(hamiltonian, ham_run, &spec, 0, 0, NULL, run, run_free)

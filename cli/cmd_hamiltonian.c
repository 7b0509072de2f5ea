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
#include "cli.h"

#include "qdot/render.h"
#include "eom_out.h"
#include "model_cli.h"
#include "model_file.h"
#include "state.h"

typedef struct ham_run {
    qd_ctx *ctx;
    cli_model_file mf;
    qd_eom *e;
    qd_ham *h;
    qd_render_format fmt;
    const char *file, *at, *format;
    cli_list sets;
    cli_state st; /* q, q', t, the parameters, then the momenta */
    qd_ham_point pt; /* H and the equations at --at */
} ham_run;

static const char *const formats[] = {"text", "json", "latex", "sympy", NULL};

static const cli_opt opts[] = {
    {"--at", NULL, CLI_TEXT, offsetof(ham_run, at), "\"q=V, p_q=V, t=V\"",
     "evaluate H and the equations at this point (momenta named as printed)", NULL, NULL},
    {"--set", NULL, CLI_LIST, offsetof(ham_run, sets), "NAME=VALUE",
     "give a parameter another value (fixed into the expressions)", NULL, NULL},
    {"--format", NULL, CLI_CHOICE, offsetof(ham_run, format), "F", "output format", formats,
     NULL},
    {NULL, NULL, CLI_FLAG, 0, NULL, NULL, NULL, NULL},
};

static const cli_spec spec = {
    "hamiltonian", "FILE [options]",
    "The momenta, H(q, p, t) and Hamilton's equations of a model, with the verdicts H = T + V? "
    "and H conserved?",
    opts, NULL, 1, 1, "FILE", false};

static int parse_args(int argc, char **argv, ham_run *r) {
    const char *pos[1];
    int rc = cli_parse(&spec, argc, argv, r, pos);
    r->file = pos[0];
    if (r->format)
        qd_render_format_parse(r->format, &r->fmt); /* one of formats: cli_parse checked it */
    return rc;
}

/* ---- --at ------------------------------------------------------------------ */

/* The model's state with the momenta appended, named in --at as they are
 * printed (p_r=0.3). */
static int state_at(ham_run *r) {
    int rc = cli_state_init(r->ctx, r->mf.model, &r->st);
    if (rc == QD_EXIT_OK && qd_state_append(r->ctx, &r->st, r->h->n, r->h->p, NULL) != QD_OK)
        rc = cli_diag_ctx(r->ctx);
    return rc == QD_EXIT_OK ? cli_state_parse(r->ctx, r->mf.model, r->at, &r->st) : rc;
}

/* H and the equations at the --at point (qd_ham_point_eval). */
static int evaluate(ham_run *r) {
    int rc = state_at(r);
    if (rc == QD_EXIT_OK &&
        qd_ham_point_eval(r->ctx, r->h, r->st.n, r->st.syms, r->st.vals, &r->pt) != QD_OK) {
        cli_diag_error("cannot evaluate at this point: %s", qd_ctx_message(r->ctx));
        rc = QD_EXIT_FAIL;
    }
    return rc;
}

/* The library's rendering (qd_render_hamiltonian) of the format asked for. */
static int emit(ham_run *r) {
    qd_buf b = QD_BUF_INIT;
    b.failed = qd_render_hamiltonian(r->ctx, r->mf.model, r->h, r->mf.path,
                                     r->at ? &r->pt : NULL, r->fmt, &b) != QD_OK;
    return cli_emit(&b, "Hamiltonian");
}

static int run(ham_run *r) {
    int rc = cli_load(r->ctx, r->file, r->sets.n, r->sets.items, true, &r->mf);
    bool given = rc == QD_EXIT_OK && qd_model_hamiltonian_given(r->mf.model);
    /* a singular Hessian named as the Legendre transform sees it, before
     * Lagrange's equations fail on the same matrix */
    if (rc == QD_EXIT_OK && !given && qd_ham_regular(r->ctx, r->mf.model) != QD_OK)
        rc = cli_eom_derive_error(r->ctx, &r->mf);
    if (rc == QD_EXIT_OK && !given && !(r->e = qd_eom_derive(r->ctx, r->mf.model)))
        rc = cli_eom_derive_error(r->ctx, &r->mf);
    if (rc == QD_EXIT_OK && !(r->h = qd_ham_derive(r->ctx, r->mf.model, r->e)))
        rc = cli_eom_derive_error(r->ctx, &r->mf);
    if (rc == QD_EXIT_OK && r->at)
        rc = evaluate(r);
    return rc == QD_EXIT_OK ? emit(r) : rc;
}

int cli_cmd_hamiltonian(int argc, char **argv) {
    ham_run r = {.fmt = QD_RENDER_TEXT};
    int rc = parse_args(argc, argv, &r);
    if (rc != QD_EXIT_OK)
        return rc;
    if (!(r.ctx = qd_ctx_new())) {
        cli_diag_error("out of memory");
        return QD_EXIT_FAIL;
    }
    rc = run(&r);
    cli_state_free(&r.st);
    qd_ham_point_free(&r.pt);
    qd_ham_free(r.h);
    qd_eom_free(r.e);
    cli_model_file_free(&r.mf);
    qd_ctx_free(r.ctx);
    return rc;
}

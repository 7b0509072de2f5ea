/*
 * cli/sim_lqr_cli.c - `qdot simulate --input "F = lqr" --about "..." --lqr
 * "Q = ..., R = ..."`: the LQR feedback u = u0 - K (x - x0) about the
 * operating point (x0, u0), an expression in the state (qd_lqr_feedback)
 * handed to the simulation like any --input "F = EXPR", so the integrator
 * sees nothing new.
 */
#include "cli.h"
#include "lqr_cli.h"
#include "sim_cli.h"

#include <string.h>

static int input_index(const qd_statespace *s, const char *name, size_t *i) {
    for (*i = 0; *i < s->nu; ++*i)
        if (!strcmp(qd_expr_name(s->inputs[*i]), name))
            return QD_EXIT_OK;
    cli_diag_error("--input: %s = lqr: %s is not an input of the model", name, name);
    return QD_EXIT_USAGE;
}

/* The gain on stderr, so a run says which controller it simulated. */
static void note_gain(const qd_statespace *s, const qd_care_result *r, size_t i,
                      const char *name) {
    fprintf(stderr, "qdot: simulate: %s = lqr: K =", name);
    for (size_t j = 0; j < s->nx; j++)
        fprintf(stderr, " %.6g (%s)", r->K[i * s->nx + j], qd_expr_name(s->states[j]));
    fprintf(stderr, "; closed-loop eigenvalues, largest real part %.6g\n", r->eig_re[0]);
}

/* Away from an equilibrium x0 is no rest point of the loop: u0 - K (x - x0)
 * then regulates towards where the system cannot stay, so say so. */
static void note_not_equilibrium(const qd_statespace *s) {
    for (size_t j = 0; j < s->nx; j++)
        if (s->xdot0[j] != 0) {
            fprintf(stderr, "qdot: simulate: note: --about is not an equilibrium (%s' = %.6g "
                            "there): the loop holds no rest at it\n",
                    qd_expr_name(s->states[j]), s->xdot0[j]);
            return;
        }
}

static int linearized_gain(cli_sim *c, const char *name) {
    cli_point pt = {0};
    qd_statespace s = {0};
    qd_care_result r = {0};
    size_t i = 0;
    int rc = cli_point_read(c->ctx, c->about, &pt);
    if (rc == QD_EXIT_OK &&
        qd_linearize(c->ctx, c->e, c->mf.model, pt.n, pt.syms, pt.vals, &s) != QD_OK) {
        rc = qd_ctx_status(c->ctx) == QD_ERR_ARG ? QD_EXIT_USAGE : QD_EXIT_FAIL;
        cli_diag_error("--input: %s = lqr: %s", name, qd_ctx_message(c->ctx));
    }
    if (rc == QD_EXIT_OK)
        rc = input_index(&s, name, &i);
    if (rc == QD_EXIT_OK)
        rc = cli_lqr_design(c->ctx, &s, c->lqr, &r);
    const qd_expr *u =
        rc == QD_EXIT_OK ? qd_lqr_feedback(c->ctx, &s, &r, pt.n, pt.syms, pt.vals, i) : NULL;
    if (rc == QD_EXIT_OK && !u)
        rc = cli_diag_ctx(c->ctx);
    if (rc == QD_EXIT_OK && qd_sim_input_expr(c->s, name, u) != QD_OK) {
        cli_diag_error("--input: %s", qd_ctx_message(c->ctx));
        rc = QD_EXIT_USAGE;
    }
    if (rc == QD_EXIT_OK) {
        note_gain(&s, &r, i, name);
        note_not_equilibrium(&s);
    }
    qd_care_result_free(&r);
    qd_statespace_free(&s);
    cli_point_free(&pt);
    return rc;
}

int cli_sim_input_lqr(cli_sim *c, const char *name) {
    if (!c->lqr || !c->about) {
        cli_diag_error("--input \"%s = lqr\" needs %s: the weights --lqr \"Q = diag(...), "
                       "R = ...\" and the operating point --about \"q=VALUE, q'=VALUE, "
                       "%s=VALUE\"", name, !c->lqr && !c->about ? "--lqr and --about"
                                           : !c->lqr ? "--lqr" : "--about", name);
        return QD_EXIT_USAGE;
    }
    if (!c->e) {
        cli_diag_error("--input \"%s = lqr\": the feedback is designed on the equations in "
                       "the coordinates (a model given by T and V or L; with speeds, use "
                       "--no-speeds)", name);
        return QD_EXIT_USAGE;
    }
    c->lqr_used = true;
    return linearized_gain(c, name);
}

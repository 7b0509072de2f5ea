/*
 * cli/constrained_cli.c - `qdot modes` and `qdot linearize` on a model that
 * keeps holonomic constraints with multipliers (a pendulum as
 * x^2 + y^2 = l^2): the library reduces onto the constraint manifold
 * (qd_constrained_linear_about); this file finds the point, runs the
 * reduction and writes what the library prints (qd_constrained_modes_print,
 * qd_constrained_statespace_print).
 */
#include "linear_cli.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "qdot/constrained.h"

static int reduce(cli_lin_run *r, const double *q0, const char *indep,
                  qd_constrained_linear *c) {
    size_t *ix = NULL;
    int rc = QD_EXIT_OK;
    if (indep) {
        ix = calloc(r->e->n + 1, sizeof *ix);
        if (!ix)
            return cli_out_of_memory();
        if (qd_constrained_indep_read(r->c.ctx, r->e, indep, ix) != QD_OK)
            rc = cli_state_diag(r->c.ctx, "--independent", indep);
    }
    cli_lin_set_state(r, q0, NULL);
    if (rc == QD_EXIT_OK &&
        qd_constrained_linear_about(r->c.ctx, r->e, r->st.n, r->st.syms, r->st.vals, ix, c) !=
            QD_OK) {
        cli_diag_error("%s", qd_ctx_message(r->c.ctx));
        rc = qd_ctx_status(r->c.ctx) == QD_ERR_ARG || qd_ctx_status(r->c.ctx) == QD_ERR_UNSUPPORTED
                 ? QD_EXIT_USAGE
                 : QD_EXIT_FAIL;
    }
    free(ix);
    return rc;
}

int cli_con_point(cli_lin_run *r, const char *about, bool quiet, double *q0) {
    if (about)
        return cli_lin_coords(r, "--about", about, q0);
    qd_equilibrium_choice ch = {0};
    int rc = QD_EXIT_OK;
    if (qd_equilibria_choose(r->c.ctx, r->e, r->c.mf.model, r->st.n, r->st.syms, r->st.vals, &ch) !=
        QD_OK) {
        cli_diag_error("%s", qd_ctx_message(r->c.ctx));
        rc = QD_EXIT_FAIL;
    } else if (!ch.pt) {
        cli_diag_error("no equilibrium found on the constraints (qdot equilibria lists none): "
                      "give a point with --about");
        rc = QD_EXIT_FAIL;
    } else {
        memcpy(q0, ch.pt->q, r->e->n * sizeof *q0);
        if (!quiet) {
            fprintf(stderr, "qdot: note: about ");
            for (size_t j = 0; j < r->e->n; j++)
                fprintf(stderr, "%s%s = %.12g", j ? ", " : "", qd_expr_name(r->e->q[j]), q0[j]);
            fprintf(stderr, ", %s (%zu other equilibri%s found; choose with --about)\n",
                    ch.pt->kind == QD_EQ_MINIMUM ? "a minimum of the potential on the constraints"
                                                 : "the first equilibrium found",
                    ch.others, ch.others == 1 ? "um" : "a");
        }
    }
    qd_equilibrium_choice_free(&ch);
    return rc;
}

int cli_con_modes(cli_lin_run *r, const double *q0, const char *indep, bool json) {
    qd_constrained_linear c = {0};
    qd_modes_result res = {0};
    int rc = reduce(r, q0, indep, &c);
    if (rc == QD_EXIT_OK && qd_modes_solve(r->c.ctx, &c.lin, &res) != QD_OK) {
        cli_diag_error("%s", qd_ctx_message(r->c.ctx));
        rc = QD_EXIT_FAIL;
    }
    if (rc == QD_EXIT_OK) {
        qd_buf b = QD_BUF_INIT;
        rc = cli_emit_status(r->c.ctx,
                             qd_constrained_modes_print(r->c.ctx, r->e, &c, &res, json, &b),
                             &b, "modes");
    }
    qd_modes_result_free(&res);
    qd_constrained_linear_free(&c);
    return rc;
}

int cli_con_linearize(cli_lin_run *r, const double *q0, const char *indep, bool json) {
    qd_constrained_linear c = {0};
    qd_modes_result res = {0};
    size_t nu = qd_model_ninputs(r->c.mf.model);
    double *A = NULL, *B = NULL;
    const qd_expr **u = NULL;
    int rc = reduce(r, q0, indep, &c);
    if (rc == QD_EXIT_OK && (!(A = calloc(4 * c.r * c.r + 1, sizeof *A)) ||
                             !(B = calloc(2 * c.r * nu + 1, sizeof *B)) ||
                             !(u = calloc(nu + 1, sizeof *u))))
        rc = cli_out_of_memory();
    for (size_t k = 0; rc == QD_EXIT_OK && k < nu; k++)
        u[k] = qd_model_input(r->c.mf.model, k);
    if (rc == QD_EXIT_OK && (qd_constrained_state_matrix(r->c.ctx, &c, A) != QD_OK ||
                             qd_constrained_input_matrix(r->c.ctx, r->e, &c, nu, u, r->st.n,
                                                         r->st.syms, r->st.vals, B) != QD_OK ||
                             qd_modes_solve(r->c.ctx, &c.lin, &res) != QD_OK)) {
        cli_diag_error("%s", qd_ctx_message(r->c.ctx));
        rc = QD_EXIT_FAIL;
    }
    if (rc == QD_EXIT_OK) {
        const qd_constrained_statespace ss = {A, nu, u, B};
        qd_buf b = QD_BUF_INIT;
        rc = cli_emit_status(
            r->c.ctx, qd_constrained_statespace_print(r->c.ctx, r->e, &c, &ss, &res, json, &b),
            &b, "state-space form");
    }
    free(A);
    free(B);
    free(u);
    qd_modes_result_free(&res);
    qd_constrained_linear_free(&c);
    return rc;
}

/*
 * cli/speeds_lin_cli.c - `qdot equilibria` and `qdot modes` on a model with
 * `speeds` (linear_cli.h): the state is (q, u).  Equilibria are u = 0 with
 * f_u(q, 0) = 0, the coordinates no equation at rest involves reported as
 * free (qd_speeds_equilibria_find); modes are the eigenvalues of the
 * reduced first-order system's Jacobian (qd_speeds_linear_about), about an
 * equilibrium or a state given with --about (a steady motion: the disk
 * rolling upright at spin u3 = 6).  What they print is the library's
 * (qd_speeds_equilibria_print, qd_speeds_modes_print); this is loading,
 * options and calls.
 */
#include "linear_cli.h"

#include "eom_out.h"
#include "model_cli.h"
#include "qdot/speeds.h"

typedef struct sp_run {
    qd_ctx *ctx;
    cli_model_file *mf;   /* borrowed */
    qd_speeds_eom *e;
    cli_state st;         /* q, q', t, the parameters, then the speeds */
} sp_run;

static void sp_free(sp_run *r) {
    qd_speeds_eom_free(r->e);
    cli_state_free(&r->st);
}

/* Derive, and the state: coordinates, speeds, t at 0, parameters at their values. */
static int sp_load(sp_run *r, const char *refuse) {
    if (refuse)
        return cli_usage_error("%s is not available for a model with speeds (the state is q and u)",
                               refuse);
    if (!(r->e = qd_speeds_derive(r->ctx, r->mf->model, NULL)))
        return cli_eom_derive_error(r->ctx, r->mf);
    int rc = cli_state_init(r->ctx, r->mf->model, &r->st);
    if (rc == QD_EXIT_OK && qd_state_append(r->ctx, &r->st, r->e->m, r->e->u, NULL) != QD_OK)
        rc = cli_diag_ctx(r->ctx);
    return rc;
}

/* ---- equilibria --------------------------------------------------------------- */

int cli_speeds_equilibria(qd_ctx *ctx, cli_model_file *mf, bool json, const char *refuse) {
    sp_run r = {.ctx = ctx, .mf = mf};
    qd_speeds_equilibria s = {0};
    int rc = sp_load(&r, refuse);
    if (rc == QD_EXIT_OK &&
        qd_speeds_equilibria_find(ctx, r.e, r.mf->model, r.st.n, r.st.syms, r.st.vals, NULL, &s) !=
            QD_OK)
        rc = cli_diag_ctx(ctx);
    if (rc == QD_EXIT_OK) {
        qd_buf b = QD_BUF_INIT;
        b.failed = qd_speeds_equilibria_print(ctx, r.e, &s, json, &b) != QD_OK;
        rc = cli_emit(&b, "equilibria");
    }
    qd_speeds_equilibria_free(&s);
    sp_free(&r);
    return rc;
}

/* ---- modes ---------------------------------------------------------------------- */

/* "theta=pi/2, u3=6": coordinates and speeds (others keep their values). */
static int parse_about(sp_run *r, const char *text) {
    qd_state_read_opts o = {.refuse = QD_STATE_VELOCITIES | QD_STATE_TIME | QD_STATE_PARAMS};
    return cli_state_read(r->ctx, r->mf->model, "--about", text, &r->st, &o);
}

/* No --about: the first equilibrium listed, at rest (qd_speeds_equilibria_choose). */
static int at_equilibrium(sp_run *r) {
    bool found;
    if (qd_speeds_equilibria_choose(r->ctx, r->e, r->mf->model, r->st.n, r->st.syms, r->st.vals,
                                    &found) != QD_OK)
        return cli_diag_ctx(r->ctx);
    if (!found) {
        cli_diag_error("no equilibrium found (qdot equilibria lists none): give a state with "
                       "--about");
        return QD_EXIT_FAIL;
    }
    return QD_EXIT_OK;
}

/* --scan NAME=A:B: the verdict at the state as NAME (a parameter, speed or
 * coordinate) goes from A to B (qd_speeds_modes_scan_text). */
static int scan(sp_run *r, const char *range, const char *about, size_t steps, bool json) {
    const char *where = NULL;
    qd_buf out = QD_BUF_INIT;
    if (qd_speeds_modes_scan_text(r->ctx, r->e, r->st.n, r->st.syms, r->st.vals, range, about,
                                  steps, json, &out, &where) == QD_OK)
        return cli_emit(&out, "scan");
    qd_buf_free(&out);
    if (where && qd_ctx_diag(r->ctx)->located)
        return cli_state_diag(r->ctx, "--scan", range);
    if (where)
        return cli_usage_error("--scan: %s", qd_ctx_message(r->ctx));
    cli_diag_error("--scan: %s", qd_ctx_message(r->ctx));
    return cli_exit(qd_ctx_status(r->ctx));
}

int cli_speeds_modes(qd_ctx *ctx, cli_model_file *mf, const char *about, const char *range,
                     size_t steps, bool json, const char *refuse) {
    sp_run r = {.ctx = ctx, .mf = mf};
    qd_speeds_linear lin = {0};
    qd_modes_result res = {0};
    int rc = sp_load(&r, refuse);
    if (rc == QD_EXIT_OK)
        rc = about ? parse_about(&r, about) : at_equilibrium(&r);
    if (rc == QD_EXIT_OK && range) {
        rc = scan(&r, range, about, steps, json);
        sp_free(&r);
        return rc;
    }
    if (rc == QD_EXIT_OK &&
        (qd_speeds_linear_about(ctx, r.e, r.st.n, r.st.syms, r.st.vals, &lin) != QD_OK ||
         qd_speeds_modes_solve(ctx, &lin, &res) != QD_OK))
        rc = cli_diag_ctx(ctx);
    if (rc == QD_EXIT_OK) {
        qd_buf b = QD_BUF_INIT;
        b.failed = qd_speeds_modes_print(ctx, r.e, r.st.n, r.st.syms, r.st.vals, &lin, &res, json,
                                         &b) != QD_OK;
        rc = cli_emit(&b, "modes");
    }
    qd_modes_result_free(&res);
    qd_speeds_linear_free(&lin);
    sp_free(&r);
    return rc;
}

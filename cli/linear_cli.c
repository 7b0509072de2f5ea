/*
 * cli/linear_cli.c - what `qdot equilibria` and `qdot modes` share (see
 * linear_cli.h).  The equations are derived with the holonomic constraints
 * eliminated, so their coordinates e->q may be fewer than the model's: every
 * value read from the command line is matched to e->q by symbol, and a
 * coordinate that a constraint eliminated is refused by name rather than
 * taken for another one.
 */
#include "linear_cli.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include "eom_out.h"
#include "model_cli.h"

int cli_lin_load_model(cli_lin_run *r, const char *file, const char *const *sets,
                       size_t nsets) {
    return cli_load(r->c.ctx, file, nsets, sets, "modes", &r->c.mf);
}

int cli_lin_load(cli_lin_run *r, const char *file, const char *const *sets, size_t nsets) {
    int rc = cli_lin_load_model(r, file, sets, nsets);
    return rc == QD_EXIT_OK ? cli_lin_derive(r) : rc;
}

int cli_lin_derive(cli_lin_run *r) {
    qd_eom_opts opts = {.eliminate = true};
    if (!(r->e = qd_eom_derive_opts(r->c.ctx, r->c.mf.model, &opts)))
        return cli_eom_derive_error(r->c.ctx, &r->c.mf);
    return cli_lin_setup(r);
}

/* The constraints kept with multipliers are reduced on their manifold by
 * the library (qdot/constrained.h). */
int cli_lin_setup(cli_lin_run *r) {
    int rc = cli_state_init(r->c.ctx, r->c.mf.model, &r->st);
    if (rc != QD_EXIT_OK)
        return rc;
    /* the slot of each independent coordinate in the model's state */
    size_t nq = qd_model_ncoords(r->c.mf.model);
    r->slot = malloc((r->e->n + 1) * sizeof *r->slot);
    if (!r->slot)
        return cli_out_of_memory();
    for (size_t j = 0; j < r->e->n; j++) {
        r->slot[j] = SIZE_MAX;
        for (size_t i = 0; i < nq; i++)
            if (r->st.syms[i] == r->e->q[j])
                r->slot[j] = i;
        if (r->slot[j] == SIZE_MAX) {
            cli_diag_error("internal error: coordinate %s of the equations is not in the model",
                          qd_expr_name(r->e->q[j]));
            return QD_EXIT_FAIL;
        }
    }
    return QD_EXIT_OK;
}

void cli_lin_free(cli_lin_run *r) {
    cli_state_free(&r->st);
    free(r->slot);
    r->slot = NULL;
    qd_eom_free(r->e);
    r->e = NULL;
    cli_model_file_free(&r->c.mf);
}

void cli_lin_set_state(cli_lin_run *r, const double *q, const double *qd) {
    size_t nq = qd_model_ncoords(r->c.mf.model);
    for (size_t j = 0; j < r->e->n; j++) {
        r->st.vals[r->slot[j]] = q[j];
        r->st.vals[nq + r->slot[j]] = qd ? qd[j] : 0;
    }
}

/* The index in e->q of the model's coordinate i, or e->n when a constraint
 * eliminated it. */
static size_t eom_index(const cli_lin_run *r, size_t i) {
    size_t j = 0;
    while (j < r->e->n && r->slot[j] != i)
        j++;
    return j;
}

/* The reader refuses t, the parameters, the coordinates a constraint
 * eliminated and, for a point at rest (qd NULL), the velocities. */
int cli_lin_point(cli_lin_run *r, const char *what, const char *text, double *q, double *qd) {
    const qd_model *m = r->c.mf.model;
    size_t nq = qd_model_ncoords(m);
    cli_state s = {0};
    int rc = cli_state_init(r->c.ctx, m, &s);
    bool *given = rc == QD_EXIT_OK ? calloc(s.n, sizeof *given) : NULL;
    if (rc == QD_EXIT_OK && !given)
        rc = cli_out_of_memory();
    qd_state_read_opts o = {
        .refuse = QD_STATE_TIME | QD_STATE_PARAMS | (qd ? 0 : QD_STATE_VELOCITIES),
        .independent = r->e->q, .nindependent = r->e->n, .given = given};
    if (rc == QD_EXIT_OK)
        rc = cli_state_read(r->c.ctx, m, what, text, &s, &o);
    for (size_t i = 0; rc == QD_EXIT_OK && i < nq; i++) {
        size_t j = eom_index(r, i);
        if (given[qd_slot_coord(nq, i)])
            q[j] = s.vals[qd_slot_coord(nq, i)];
        if (given[qd_slot_velocity(nq, i)])
            qd[j] = s.vals[qd_slot_velocity(nq, i)];
    }
    free(given);
    cli_state_free(&s);
    return rc;
}

int cli_lin_coords(cli_lin_run *r, const char *what, const char *text, double *q) {
    for (size_t j = 0; j < r->e->n; j++)
        q[j] = 0;
    return cli_lin_point(r, what, text, q, NULL);
}

/* ---- --box ------------------------------------------------------------------ */

/* "q1=A:B, ...": the state reader's ranges (located errors), by slot, put at
 * the equations' coordinates. */
int cli_lin_box(cli_lin_run *r, const char *text, double *lo, double *hi) {
    size_t ns = r->st.n;
    double *l = malloc((ns + 1) * sizeof *l), *h = malloc((ns + 1) * sizeof *h);
    bool *given = calloc(ns + 1, sizeof *given);
    int rc = l && h && given ? QD_EXIT_OK : QD_EXIT_FAIL;
    if (rc != QD_EXIT_OK)
        cli_diag_error("out of memory");
    qd_state_read_opts o = {
        .refuse = QD_STATE_TIME | QD_STATE_PARAMS | QD_STATE_VELOCITIES | QD_STATE_EXTRA,
        .independent = r->e->q, .nindependent = r->e->n, .given = given};
    if (rc == QD_EXIT_OK && qd_state_read_ranges(r->c.ctx, r->c.mf.model, &r->st, text, &o, l, h) !=
                                QD_OK)
        rc = cli_state_diag(r->c.ctx, "--box", text);
    for (size_t j = 0; rc == QD_EXIT_OK && j < r->e->n; j++)
        if (given[r->slot[j]]) {
            lo[j] = l[r->slot[j]];
            hi[j] = h[r->slot[j]];
        }
    free(l);
    free(h);
    free(given);
    return rc;
}

/* ---- the search -------------------------------------------------------------- */

int cli_lin_equilibria(cli_lin_run *r, const char *near, const char *box, qd_equilibria *out) {
    size_t n = r->e->n;
    double *q = malloc((n + 1) * sizeof *q), *lo = malloc((n + 1) * sizeof *lo);
    double *hi = malloc((n + 1) * sizeof *hi);
    bool *angle = malloc((n + 1) * sizeof *angle);
    int rc = q && lo && hi && angle ? QD_EXIT_OK : QD_EXIT_FAIL;
    qd_equilibria_opts o = {0};
    if (rc == QD_EXIT_OK &&
        qd_equilibria_default_box(r->c.ctx, r->e, r->c.mf.model, angle, lo, hi) != QD_OK)
        rc = cli_diag_ctx(r->c.ctx);
    if (rc == QD_EXIT_OK && near && (rc = cli_lin_coords(r, "--near", near, q)) == QD_EXIT_OK)
        o.near = q;
    if (rc == QD_EXIT_OK && box && (rc = cli_lin_box(r, box, lo, hi)) == QD_EXIT_OK) {
        o.lo = lo;
        o.hi = hi;
        o.numeric_only = true;
    }
    if (rc == QD_EXIT_OK &&
        qd_equilibria_find(r->c.ctx, r->e, r->c.mf.model, r->st.n, r->st.syms, r->st.vals, &o,
                           out) != QD_OK) {
        cli_diag_error("%s", qd_ctx_message(r->c.ctx));
        /* a constraint the manifold search does not take (with t, with velocities) */
        rc = qd_ctx_status(r->c.ctx) == QD_ERR_UNSUPPORTED ? QD_EXIT_USAGE : QD_EXIT_FAIL;
    }
    free(q);
    free(lo);
    free(hi);
    free(angle);
    return rc;
}

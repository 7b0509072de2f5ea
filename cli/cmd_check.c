/*
 * cli/cmd_check.c - `qdot check FILE`: validate a model and summarize it.
 *
 * Valid means it parses (every name known, every parameter valued, T or L
 * given) and its equations can be derived (the mass matrix is not
 * identically singular).  The summary says what each energy depends on, which
 * coordinates are cyclic and whether time appears explicitly: a coordinate
 * q_j is cyclic when L does not contain it, and its momentum p_j = dL/dq'_j
 * is conserved when moreover Q_j = 0 and D does not contain q'_j, since
 * Lagrange's equation then reads dp_j/dt = 0.
 *
 * Constraints are listed with their kind (holonomic, integrable with its
 * integral, nonholonomic) and the degrees of freedom are counted as in
 * Desloge ch. 49: configurational = coordinates - the relations among them
 * the constraints imply together (qd_eom_dof: more than the holonomic and
 * integrable ones when a combination of Pfaffian constraints integrates,
 * as on the two-wheel axle), motional = coordinates - constraints.
 */
#include "cli.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "eom_out.h"
#include "model_file.h"
#include "state.h"
#include "qdot/integrals.h"
#include "qdot/mech.h"

typedef struct check {
    qd_ctx *ctx;
    const qd_model *m;
    qd_buf out;
} check;

static void put_expr(check *c, const qd_expr *e) { qd_print(c->ctx, e, QD_FMT_TEXT, &c->out); }

/* One group of "depends on": the symbols of the group that x contains. */
static bool group(check *c, const qd_expr *x, const char *label, bool first, size_t n,
                  const qd_expr *(*sym)(check *, size_t)) {
    bool any = false;
    for (size_t i = 0; i < n; i++) {
        const qd_expr *s = sym(c, i);
        if (!qd_has(x, s))
            continue;
        qd_buf_puts(&c->out, any ? ", " : first ? " " : "; ");
        if (!any)
            qd_buf_printf(&c->out, "%s ", label);
        put_expr(c, s);
        any = true;
    }
    return any;
}

static const qd_expr *coord_at(check *c, size_t i) { return qd_model_coord(c->m, i); }
static const qd_expr *vel_at(check *c, size_t i) {
    return qd_jet(c->ctx, qd_model_coord(c->m, i), 1);
}
static const qd_expr *param_at(check *c, size_t i) { return qd_model_param(c->m, i); }
static const qd_expr *time_at(check *c, size_t i) { (void)i; return qd_time(c->ctx); }

/* x simplified: an unsimplified energy can hide that a symbol cancels
 * (cos(w*t)^2 + sin(w*t)^2 has no t). */
static void depends(check *c, const char *name, const qd_expr *x) {
    if (!x || !(x = qd_simplify(c->ctx, x)))
        return;
    size_t nq = qd_model_ncoords(c->m);
    qd_buf_printf(&c->out, "%-12s", name);
    bool any = group(c, x, "coordinates", true, nq, coord_at);
    any |= group(c, x, "velocities", !any, nq, vel_at);
    any |= group(c, x, "time", !any, 1, time_at);
    any |= group(c, x, "parameters", !any, qd_model_nparams(c->m), param_at);
    qd_buf_puts(&c->out, any ? "\n" : " constant\n");
}

static void dof(check *c, const qd_eom *e) {
    size_t count[3] = {0, 0, 0};
    for (size_t k = 0; k < e->ncon; k++)
        count[e->con[k].kind]++;
    if (!e->ncon) {
        qd_buf_printf(&c->out, "degrees of freedom: %zu\n", e->n);
        return;
    }
    size_t one_by_one = count[QD_CON_HOLONOMIC] + count[QD_CON_INTEGRABLE];
    qd_dof d;
    if (qd_eom_dof(c->ctx, e, &d) != QD_OK) { /* a coefficient with no value: one by one */
        qd_ctx_clear_error(c->ctx);
        d = (qd_dof){e->n, e->ncon, one_by_one, e->n - one_by_one, e->n - e->ncon, 0, {NULL}};
    }
    qd_buf_printf(&c->out,
                  "degrees of freedom: %zu configurational, %zu motional (%zu coordinates; "
                  "constraints: %zu holonomic, %zu integrable, %zu nonholonomic)\n",
                  d.configurational, d.motional, e->n + e->nelim, count[QD_CON_HOLONOMIC],
                  count[QD_CON_INTEGRABLE], count[QD_CON_NONHOLONOMIC]);
    if (d.relations > one_by_one)
        qd_buf_printf(&c->out,
                      "integrable combinations: %zu (the constraints together imply %zu "
                      "relation%s among the coordinates that none gives alone)\n",
                      d.relations - one_by_one, d.relations - one_by_one,
                      d.relations - one_by_one == 1 ? "" : "s");
    for (size_t i = 0; i < d.ncombined; i++) {
        qd_buf_puts(&c->out, "  integral of a combination: ");
        put_expr(c, d.combined[i]);
        qd_buf_puts(&c->out, " = const\n");
    }
}

static void header(check *c, const char *path, const qd_eom *e) {
    const qd_model *m = c->m;
    size_t nq = qd_model_ncoords(m);
    qd_buf_printf(&c->out, "%s: ok\ncoordinates:", path);
    for (size_t i = 0; i < nq; i++)
        qd_buf_printf(&c->out, "%s %s", i ? "," : "", qd_expr_name(qd_model_coord(m, i)));
    qd_buf_puts(&c->out, "\n");
    dof(c, e);
    qd_buf_puts(&c->out, "parameters:");
    for (size_t i = 0; i < qd_model_nparams(m); i++) {
        qd_buf_printf(&c->out, "%s %s = ", i ? "," : "", qd_expr_name(qd_model_param(m, i)));
        cli_state_put_double(&c->out, cli_param_value(m, i));
    }
    qd_buf_puts(&c->out, qd_model_nparams(m) ? "\n" : " none\n");
}

static void constraints(check *c, const qd_eom *e) {
    for (size_t k = 0; k < e->ncon; k++) {
        const qd_con *con = &e->con[k];
        qd_buf_printf(&c->out, "constraint %s: ", con->name);
        put_expr(c, con->expr);
        qd_buf_puts(&c->out, " = 0, ");
        if (con->kind == QD_CON_HOLONOMIC) {
            qd_buf_puts(&c->out, "holonomic\n");
        } else if (con->kind == QD_CON_NONHOLONOMIC) {
            qd_buf_puts(&c->out, "nonholonomic (Pfaffian, not integrable)\n");
        } else if (!con->integral) {
            qd_buf_puts(&c->out, "integrable (Pfaffian; integral not found in closed form)\n");
        } else {
            qd_buf_puts(&c->out, "integrable: ");
            put_expr(c, con->integral);
            qd_buf_puts(&c->out, " = const");
            if (con->factor && !qd_is_one(con->factor)) {
                qd_buf_puts(&c->out, " (integrating factor ");
                put_expr(c, con->factor);
                qd_buf_puts(&c->out, ")");
            }
            qd_buf_puts(&c->out, "\n");
        }
    }
}

/* What acts only at an instant (`qdot impulse`, the contacts of
 * `qdot simulate`). */
static void impulsive(check *c) {
    const qd_model *m = c->m;
    for (size_t j = 0; j < qd_model_ncoords(m); j++) {
        const qd_expr *P = qd_simplify(c->ctx, qd_model_impulse(m, j));
        if (!P || qd_is_zero(P))
            continue;
        qd_buf_printf(&c->out, "generalized impulse Qhat[%s] = ", qd_expr_name(qd_model_coord(m, j)));
        put_expr(c, P);
        qd_buf_puts(&c->out, "\n");
    }
    struct {
        const char *what;
        size_t n;
        const char *(*name)(const qd_model *, size_t);
        const qd_expr *(*expr)(const qd_model *, size_t);
        const qd_expr *(*E)(const qd_model *, size_t);
        const char *rel;
    } kinds[] = {
        {"sudden constraint", qd_model_nimpact_constraints(m), qd_model_impact_constraint_name,
         qd_model_impact_constraint, qd_model_impact_constraint_restitution, " = 0"},
        {"contact", qd_model_nimpacts(m), qd_model_impact_name, qd_model_impact_gap,
         qd_model_impact_restitution, " >= 0"},
        {"prescribed", qd_model_nprescribed(m), qd_model_prescribed_name, qd_model_prescribed,
         NULL, " = 0"},
    };
    for (size_t k = 0; k < sizeof kinds / sizeof kinds[0]; k++)
        for (size_t i = 0; i < kinds[k].n; i++) {
            qd_buf_printf(&c->out, "%s %s: ", kinds[k].what, kinds[k].name(m, i));
            put_expr(c, kinds[k].expr(m, i));
            qd_buf_puts(&c->out, kinds[k].rel);
            if (kinds[k].E) {
                qd_buf_puts(&c->out, ", restitution ");
                put_expr(c, kinds[k].E(m, i));
            }
            qd_buf_puts(&c->out, "\n");
        }
}

static void forces(check *c) {
    for (size_t j = 0; j < qd_model_ncoords(c->m); j++) {
        const qd_expr *Q = qd_simplify(c->ctx, qd_model_force(c->m, j));
        if (!Q || qd_is_zero(Q))
            continue;
        qd_buf_printf(&c->out, "generalized force Q[%s] = ", qd_expr_name(qd_model_coord(c->m, j)));
        put_expr(c, Q);
        qd_buf_puts(&c->out, "\n");
    }
}

/* Cyclic coordinates, with their conserved momenta (qd_integrals_cyclic;
 * `qdot integrals` says more). */
static void cyclic(check *c, const qd_eom *e) {
    qd_int_cyclic *cyc = calloc(e->n ? e->n : 1, sizeof *cyc);
    size_t nc = 0;
    if (!cyc || qd_integrals_cyclic(c->ctx, c->m, e, cyc, &nc) != QD_OK)
        nc = 0;
    qd_buf_puts(&c->out, "cyclic coordinates:");
    for (size_t i = 0; i < nc; i++) {
        const char *q = qd_expr_name(e->q[cyc[i].coord]);
        qd_buf_printf(&c->out, "%s %s", i ? "," : "", q);
        if (cyc[i].conserved) {
            qd_buf_printf(&c->out, " (p_%s = ", q);
            put_expr(c, cyc[i].momentum);
            qd_buf_puts(&c->out, " is conserved)");
        } else if (!strcmp(cyc[i].obstruction, "a constraint acts on it")) {
            qd_buf_puts(&c->out, " (but a constraint acts on it)");
        } else {
            qd_buf_puts(&c->out, " (but a force or dissipation acts on it)");
        }
    }
    qd_buf_puts(&c->out, nc ? "\n" : " none\n");
    free(cyc);
}

/* Forces, dissipation or constraints that work (a0 != 0: the power of the
 * constraint forces is R . q' = -sum_k lambda_k a0_k) present: then h is
 * not conserved in general. */
static bool nonconservative(check *c, const qd_eom *e) {
    for (size_t k = 0; k < e->ncon; k++)
        if (!qd_is_zero(e->con[k].a0))
            return true;
    const qd_expr *D = qd_model_dissipation(c->m);
    if (D && !qd_is_zero(qd_simplify(c->ctx, D)))
        return true;
    for (size_t j = 0; j < qd_model_ncoords(c->m); j++) {
        const qd_expr *Q = qd_simplify(c->ctx, qd_model_force(c->m, j));
        if (!Q || !qd_is_zero(Q))
            return true;
    }
    return false;
}

static void time_dependence(check *c, const qd_eom *e, const qd_expr *L) {
    bool explicit_t = qd_has(L, qd_time(c->ctx));
    const char *t = qd_print_time_name(c->ctx); /* x for `independent x` */
    if (explicit_t)
        qd_buf_printf(&c->out, "explicit time dependence: L depends on %s explicitly\n", t);
    else
        qd_buf_printf(&c->out, "explicit time dependence: none (L does not contain %s)\n", t);
    for (size_t k = 0; k < e->ncon; k++)
        if (qd_has(e->con[k].expr, qd_time(c->ctx)))
            qd_buf_printf(&c->out, "rheonomic constraint: %s depends on %s explicitly\n",
                          e->con[k].name, t);
    if (!explicit_t && !nonconservative(c, e))
        qd_buf_puts(&c->out, "energy integral: h = sum_j q'_j dL/dq'_j - L is conserved\n");
    if (e->T1 && e->T0 && (!qd_is_zero(e->T1) || !qd_is_zero(e->T0)))
        qd_buf_puts(&c->out,
                    "kinetic energy: T = T2 + T1 + T0 (rheonomic: T1 or T0 is not zero)\n");
    else if (e->T2)
        qd_buf_puts(&c->out, "kinetic energy: T = T2, quadratic in the velocities\n");
}

/* The statement an error about the mass matrix is shown at. */
static const char *mass_place(const qd_model *m, size_t coord) {
    if (qd_model_where(m, "T", NULL))
        return "T";
    if (qd_model_where(m, "L", NULL))
        return "L";
    return qd_expr_name(qd_model_coord(m, coord));
}

/* The model's numbers (qd_eom_audit): a mass matrix that is not positive
 * definite and a constraint with no real solution are errors; an initial
 * state off the constraints is a note, as a run projects it. */
static int audit(check *c, const cli_model_file *mf, const qd_eom *e) {
    qd_audit a;
    qd_status st = qd_eom_audit(c->ctx, c->m, e, &a);
    if (st == QD_ERR_NOMEM)
        return cli_diag_ctx(c->ctx);
    qd_ctx_clear_error(c->ctx);
    if (st != QD_OK)
        return QD_EXIT_OK; /* no numbers to judge */
    char msg[256];
    if (!a.mass_ok) {
        snprintf(msg, sizeof msg, "the mass matrix is not positive definite with these parameter "
                 "values (its pivot for %s is %.3g): a mass or moment of inertia is zero or "
                 "negative", qd_expr_name(e->q[a.mass_coord]), a.mass_pivot);
        cli_model_file_error(mf, mass_place(c->m, a.mass_coord), msg,
                             "every mass and moment of inertia must be positive: check the "
                             "parameters' values");
        return QD_EXIT_USAGE;
    }
    if (!a.con_ok) {
        char what[160];
        snprintf(what, sizeof what, "constraint:%s", e->con[a.con].name);
        snprintf(msg, sizeof msg, "constraint %s has no real solution near the initial state: "
                 "its residual stays at %.3g", e->con[a.con].name, a.con_min);
        cli_model_file_error(mf, what, msg, "check its sign and the parameters' values");
        return QD_EXIT_USAGE;
    }
    if (a.residual > 1e-4) /* far off, not rounding */
        fprintf(stderr, "%s: note: the initial state is off constraint %s by %.3g; a run "
                "projects it onto the constraints first\n", mf->path,
                e->con[a.residual_con].name, a.residual);
    return QD_EXIT_OK;
}

static int summarize(check *c, const cli_model_file *mf) {
    qd_eom *e = qd_eom_derive(c->ctx, c->m);
    if (!e)
        return cli_eom_derive_error(c->ctx, mf);
    int rc = audit(c, mf, e);
    if (rc != QD_EXIT_OK) {
        qd_eom_free(e);
        return rc;
    }
    header(c, mf->path, e);
    depends(c, "T:", qd_model_kinetic(c->m));
    depends(c, "V:", qd_model_potential(c->m));
    depends(c, "U:", qd_model_gen_potential(c->m));
    depends(c, "dissipation:", qd_model_dissipation(c->m));
    /* a model given by H has its L from the inverse Legendre transform */
    const qd_expr *Lm = qd_model_hamiltonian_given(c->m) ? e->L : qd_model_lagrangian(c->m);
    depends(c, "L:", Lm);
    forces(c);
    constraints(c, e);
    impulsive(c);
    const qd_expr *L = qd_simplify(c->ctx, Lm);
    if (L) {
        cyclic(c, e);
        time_dependence(c, e, L);
    }
    if (e->ncon)
        qd_buf_printf(&c->out,
                      "equations: [M -A^T; A 0] is %zu x %zu, not identically singular\n",
                      e->n + e->ncon, e->n + e->ncon);
    else
        qd_buf_printf(&c->out, "mass matrix: %zu x %zu, not identically singular\n", e->n,
                      e->n);
    qd_eom_free(e);
    return qd_ctx_status(c->ctx) == QD_OK ? QD_EXIT_OK : cli_diag_ctx(c->ctx);
}

int cli_cmd_check(int argc, char **argv) {
    if (argc != 1 || (argv[0][0] == '-' && argv[0][1])) {
        cli_diag_error("usage: qdot check FILE");
        return QD_EXIT_USAGE;
    }
    check c = {.ctx = qd_ctx_new(), .out = QD_BUF_INIT};
    if (!c.ctx) {
        cli_diag_error("out of memory");
        return QD_EXIT_FAIL;
    }
    cli_model_file mf;
    int rc = cli_model_file_load(c.ctx, argv[0], &mf);
    if (rc == QD_EXIT_OK) {
        c.m = mf.model;
        rc = summarize(&c, &mf);
    }
    if (rc == QD_EXIT_OK)
        fputs(qd_buf_str(&c.out), stdout);
    qd_buf_free(&c.out);
    cli_model_file_free(&mf);
    qd_ctx_free(c.ctx);
    return rc;
}

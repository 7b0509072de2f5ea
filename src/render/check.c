/*
 * src/render/check.c - what `qdot check` says of a model (qd_render_check,
 * qdot/render.h): its verdict from the numbers (qd_eom_audit) and its
 * summary, in text or JSON.
 *
 * The summary says what each energy depends on, which coordinates are
 * cyclic and whether time appears explicitly: a coordinate q_j is cyclic
 * when L does not contain it, and its momentum p_j = dL/dq'_j is conserved
 * when moreover Q_j = 0 and D does not contain q'_j, since Lagrange's
 * equation then reads dp_j/dt = 0.  Constraints are listed with their kind
 * and the degrees of freedom counted as in Desloge ch. 49: configurational
 * = coordinates - the relations among them the constraints imply together
 * (qd_eom_dof), motional = coordinates - constraints.
 */
#include "render.h"

#include <stdio.h>
#include <string.h>
#include "qdot/integrals.h"
#include "qdot/json.h"
#include "../base/args.h"
#include "../base/mem.h"

typedef struct check {
    qd_ctx *ctx;
    const qd_model *m;
    qd_buf *out;
} check;

static void put_expr(check *c, const qd_expr *e) { qd_print(c->ctx, e, QD_FMT_TEXT, c->out); }

/* One group of "depends on": the symbols of the group that x contains. */
static bool group(check *c, const qd_expr *x, const char *label, bool first, size_t n,
                  const qd_expr *(*sym)(check *, size_t)) {
    bool any = false;
    for (size_t i = 0; i < n; i++) {
        const qd_expr *s = sym(c, i);
        if (!qd_has(x, s))
            continue;
        qd_buf_puts(c->out, any ? ", " : first ? " " : "; ");
        if (!any)
            qd_buf_printf(c->out, "%s ", label);
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
    qd_buf_printf(c->out, "%-12s", name);
    bool any = group(c, x, "coordinates", true, nq, coord_at);
    any |= group(c, x, "velocities", !any, nq, vel_at);
    any |= group(c, x, "time", !any, 1, time_at);
    any |= group(c, x, "parameters", !any, qd_model_nparams(c->m), param_at);
    qd_buf_puts(c->out, any ? "\n" : " constant\n");
}

static void dof(check *c, const qd_eom *e) {
    size_t count[3] = {0, 0, 0};
    for (size_t k = 0; k < e->ncon; k++)
        count[e->con[k].kind]++;
    if (!e->ncon) {
        qd_buf_printf(c->out, "degrees of freedom: %zu\n", e->n);
        return;
    }
    size_t one_by_one = count[QD_CON_HOLONOMIC] + count[QD_CON_INTEGRABLE];
    qd_dof d;
    bool undecided = false;
    if (qd_eom_dof(c->ctx, e, &d) != QD_OK) { /* a coefficient with no value: one by one */
        undecided = qd_ctx_status(c->ctx) == QD_ERR_NUMERIC; /* the numeric closure's doubt */
        qd_ctx_clear_error(c->ctx);
        d = (qd_dof){e->n, e->ncon, one_by_one, e->n - one_by_one, e->n - e->ncon, 0, {NULL}};
    }
    qd_buf_printf(c->out,
                  "degrees of freedom: %zu configurational, %zu motional (%zu coordinates; "
                  "constraints: %zu holonomic, %zu integrable, %zu nonholonomic)\n",
                  d.configurational, d.motional, e->n + e->nelim, count[QD_CON_HOLONOMIC],
                  count[QD_CON_INTEGRABLE], count[QD_CON_NONHOLONOMIC]);
    if (undecided)
        qd_buf_printf(c->out, "note: could not decide whether the constraints together imply "
                              "more relations: the counts are the constraints' one by one\n");
    if (d.relations > one_by_one)
        qd_buf_printf(c->out,
                      "integrable combinations: %zu (the constraints together imply %zu "
                      "relation%s among the coordinates that none gives alone)\n",
                      d.relations - one_by_one, d.relations - one_by_one,
                      d.relations - one_by_one == 1 ? "" : "s");
    for (size_t i = 0; i < e->nreduced; i++)
        qd_buf_printf(c->out,
                      "note: constraint %s is redundant (its row is a combination of the others' "
                      "on the constraint manifold, consistently): left out by rank, its "
                      "multiplier is not determined\n", e->reduced[i]);
    for (size_t i = 0; i < d.ncombined; i++) {
        qd_buf_puts(c->out, "  integral of a combination: ");
        put_expr(c, d.combined[i]);
        qd_buf_puts(c->out, " = const\n");
    }
}

static double param_value(const qd_model *m, size_t i) {
    double x;
    qd_model_param_number(m, i, &x); /* NaN when it has none */
    return x;
}

static void header(check *c, const char *path, const qd_eom *e) {
    const qd_model *m = c->m;
    size_t nq = qd_model_ncoords(m);
    qd_buf_printf(c->out, "%s: ok\ncoordinates:", path);
    for (size_t i = 0; i < nq; i++)
        qd_buf_printf(c->out, "%s %s", i ? "," : "", qd_expr_name(qd_model_coord(m, i)));
    qd_buf_puts(c->out, "\n");
    dof(c, e);
    qd_buf_puts(c->out, "parameters:");
    for (size_t i = 0; i < qd_model_nparams(m); i++) {
        qd_buf_printf(c->out, "%s %s = ", i ? "," : "", qd_expr_name(qd_model_param(m, i)));
        qd__render_number(c->out, param_value(m, i));
    }
    qd_buf_puts(c->out, qd_model_nparams(m) ? "\n" : " none\n");
}

static void constraints(check *c, const qd_eom *e) {
    for (size_t k = 0; k < e->ncon; k++) {
        const qd_con *con = &e->con[k];
        qd_buf_printf(c->out, "constraint %s: ", con->name);
        put_expr(c, con->expr);
        qd_buf_puts(c->out, " = 0, ");
        if (con->kind == QD_CON_HOLONOMIC) {
            qd_buf_puts(c->out, "holonomic\n");
        } else if (con->kind == QD_CON_NONHOLONOMIC) {
            qd_buf_puts(c->out, "nonholonomic (Pfaffian, not integrable)\n");
        } else if (!con->integral) {
            qd_buf_puts(c->out, "integrable (Pfaffian; integral not found in closed form)\n");
        } else {
            qd_buf_puts(c->out, "integrable: ");
            put_expr(c, con->integral);
            qd_buf_puts(c->out, " = const");
            if (con->factor && !qd_is_one(con->factor)) {
                qd_buf_puts(c->out, " (integrating factor ");
                put_expr(c, con->factor);
                qd_buf_puts(c->out, ")");
            }
            qd_buf_puts(c->out, "\n");
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
        qd_buf_printf(c->out, "generalized impulse Qhat[%s] = ", qd_expr_name(qd_model_coord(m, j)));
        put_expr(c, P);
        qd_buf_puts(c->out, "\n");
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
            qd_buf_printf(c->out, "%s %s: ", kinds[k].what, kinds[k].name(m, i));
            put_expr(c, kinds[k].expr(m, i));
            qd_buf_puts(c->out, kinds[k].rel);
            if (kinds[k].E) {
                qd_buf_puts(c->out, ", restitution ");
                put_expr(c, kinds[k].E(m, i));
            }
            qd_buf_puts(c->out, "\n");
        }
}

static void forces(check *c) {
    for (size_t j = 0; j < qd_model_ncoords(c->m); j++) {
        const qd_expr *Q = qd_simplify(c->ctx, qd_model_force(c->m, j));
        if (!Q || qd_is_zero(Q))
            continue;
        qd_buf_printf(c->out, "generalized force Q[%s] = ", qd_expr_name(qd_model_coord(c->m, j)));
        put_expr(c, Q);
        qd_buf_puts(c->out, "\n");
    }
}

/* Cyclic coordinates, with their conserved momenta (qd_integrals_cyclic;
 * `qdot integrals` says more). */
static void cyclic(check *c, const qd_eom *e) {
    qd_int_cyclic *cyc = qd__calloc(c->ctx, e->n ? e->n : 1, sizeof *cyc);
    size_t nc = 0;
    if (!cyc || qd_integrals_cyclic(c->ctx, c->m, e, cyc, &nc) != QD_OK)
        nc = 0;
    qd_buf_puts(c->out, "cyclic coordinates:");
    for (size_t i = 0; i < nc; i++) {
        const char *q = qd_expr_name(e->q[cyc[i].coord]);
        qd_buf_printf(c->out, "%s %s", i ? "," : "", q);
        if (cyc[i].conserved) {
            qd_buf_printf(c->out, " (p_%s = ", q);
            put_expr(c, cyc[i].momentum);
            qd_buf_puts(c->out, " is conserved)");
        } else if (!strcmp(cyc[i].obstruction, "a constraint acts on it")) {
            qd_buf_puts(c->out, " (but a constraint acts on it)");
        } else {
            qd_buf_puts(c->out, " (but a force or dissipation acts on it)");
        }
    }
    qd_buf_puts(c->out, nc ? "\n" : " none\n");
    qd__free(cyc);
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
        qd_buf_printf(c->out, "explicit time dependence: L depends on %s explicitly\n", t);
    else
        qd_buf_printf(c->out, "explicit time dependence: none (L does not contain %s)\n", t);
    for (size_t k = 0; k < e->ncon; k++)
        if (qd_has(e->con[k].expr, qd_time(c->ctx)))
            qd_buf_printf(c->out, "rheonomic constraint: %s depends on %s explicitly\n",
                          e->con[k].name, t);
    if (!explicit_t && !nonconservative(c, e))
        qd_buf_puts(c->out, "energy integral: h = sum_j q'_j dL/dq'_j - L is conserved\n");
    if (e->T1 && e->T0 && (!qd_is_zero(e->T1) || !qd_is_zero(e->T0)))
        qd_buf_puts(c->out,
                    "kinetic energy: T = T2 + T1 + T0 (rheonomic: T1 or T0 is not zero)\n");
    else if (e->T2)
        qd_buf_puts(c->out, "kinetic energy: T = T2, quadratic in the velocities\n");
}

/* The statement an error about the mass matrix is shown at. */
static const char *mass_place(const qd_model *m, size_t coord) {
    if (qd_model_where(m, "T", NULL))
        return "T";
    if (qd_model_where(m, "L", NULL))
        return "L";
    return qd_expr_name(qd_model_coord(m, coord));
}

qd_status qd_check_verdict_of(qd_ctx *ctx, const qd_model *m, const qd_eom *e,
                              qd_check_verdict *v) {
    QD_ARGS_CTX(ctx, ctx && m && e && v);
    memset(v, 0, sizeof *v);
    v->ok = true;
    qd_audit a;
    qd_status st = qd_eom_audit(ctx, m, e, &a);
    if (st == QD_ERR_NOMEM)
        return st;
    qd_ctx_clear_error(ctx);
    if (st != QD_OK)
        return QD_OK; /* no numbers to judge */
    v->judged = true;
    if (!a.mass_ok) {
        v->ok = false;
        v->reason = "mass_not_positive_definite";
        v->about = qd_expr_name(e->q[a.mass_coord]);
        v->witness = a.mass_pivot;
        snprintf(v->message, sizeof v->message, "the mass matrix is not positive definite with "
                 "these parameter values (its pivot for %s is %.3g): a mass or moment of "
                 "inertia is zero or negative", v->about, a.mass_pivot);
        snprintf(v->statement, sizeof v->statement, "%s", mass_place(m, a.mass_coord));
        v->hint = "every mass and moment of inertia must be positive: check the parameters' "
                  "values";
    } else if (!a.con_ok) {
        v->ok = false;
        v->reason = "constraint_not_real";
        v->about = e->con[a.con].name;
        v->witness = a.con_min;
        snprintf(v->message, sizeof v->message, "constraint %s has no real solution near the "
                 "initial state: its residual stays at %.3g", v->about, a.con_min);
        snprintf(v->statement, sizeof v->statement, "constraint:%s", v->about);
        v->hint = "check its sign and the parameters' values";
    } else if (a.residual > 1e-4) { /* far off, not rounding */
        v->off_constraint = true;
        v->residual = a.residual;
        v->residual_con = e->con[a.residual_con].name;
    }
    return QD_OK;
}

/* ---- JSON ------------------------------------------------------------------- */

static void json_names(qd_json *j, const char *key, size_t n, const qd_expr *const *x) {
    qd_json_key(j, key);
    qd_json_begin_array(j);
    for (size_t i = 0; i < n; i++)
        qd_json_string(j, qd_expr_name(x[i]));
    qd_json_end_array(j);
}

/* "NAME": {"coordinates": [...], "velocities": [...], "time": b, "parameters": [...]} */
static void json_depends(check *c, qd_json *j, const char *name, const qd_expr *x) {
    if (!x || !(x = qd_simplify(c->ctx, x)))
        return;
    size_t nq = qd_model_ncoords(c->m);
    qd_json_key(j, name);
    qd_json_begin_object(j);
    const char *keys[] = {"coordinates", "velocities", "parameters"};
    size_t counts[] = {nq, nq, qd_model_nparams(c->m)};
    const qd_expr *(*syms[])(check *, size_t) = {coord_at, vel_at, param_at};
    for (int g = 0; g < 3; g++) {
        qd_json_key(j, keys[g]);
        qd_json_begin_array(j);
        for (size_t i = 0; i < counts[g]; i++)
            if (qd_has(x, syms[g](c, i)))
                qd_json_expr(j, c->ctx, syms[g](c, i));
        qd_json_end_array(j);
    }
    qd_json_key(j, "time");
    qd_json_bool(j, qd_has(x, qd_time(c->ctx)));
    qd_json_end_object(j);
}

static void json_constraints(check *c, qd_json *j, const qd_eom *e) {
    qd_json_key(j, "constraints");
    qd_json_begin_array(j);
    for (size_t k = 0; k < e->ncon; k++) {
        const qd_con *con = &e->con[k];
        qd_json_begin_object(j);
        qd_json_key(j, "name");
        qd_json_string(j, con->name);
        qd_json_key(j, "expression");
        qd_json_expr(j, c->ctx, con->expr);
        qd_json_key(j, "kind");
        qd_json_string(j, qd_con_kind_name(con->kind));
        qd_json_key(j, "integral");
        qd_json_expr(j, c->ctx, con->kind == QD_CON_INTEGRABLE ? con->integral : NULL);
        qd_json_key(j, "rheonomic");
        qd_json_bool(j, qd_has(con->expr, qd_time(c->ctx)));
        qd_json_end_object(j);
    }
    qd_json_end_array(j);
    qd_json_key(j, "reduced_by_rank"); /* redundant constraints left out */
    qd_json_begin_array(j);
    for (size_t k = 0; k < e->nreduced; k++)
        qd_json_string(j, e->reduced[k]);
    qd_json_end_array(j);
}

static void json_dof(check *c, qd_json *j, const qd_eom *e) {
    size_t count[3] = {0, 0, 0};
    for (size_t k = 0; k < e->ncon; k++)
        count[e->con[k].kind]++;
    size_t one_by_one = count[QD_CON_HOLONOMIC] + count[QD_CON_INTEGRABLE];
    qd_dof d = {e->n, e->ncon, one_by_one, e->n - one_by_one, e->n - e->ncon, 0, {NULL}};
    if (e->ncon && qd_eom_dof(c->ctx, e, &d) != QD_OK)
        qd_ctx_clear_error(c->ctx);
    qd_json_key(j, "degrees_of_freedom");
    qd_json_begin_object(j);
    qd_json_key(j, "configurational");
    qd_json_number(j, (double)d.configurational);
    qd_json_key(j, "motional");
    qd_json_number(j, (double)d.motional);
    qd_json_key(j, "integrable_combinations");
    qd_json_begin_array(j);
    for (size_t i = 0; i < d.ncombined; i++)
        qd_json_expr(j, c->ctx, d.combined[i]);
    qd_json_end_array(j);
    qd_json_end_object(j);
}

static void json_cyclic(check *c, qd_json *j, const qd_eom *e) {
    qd_int_cyclic *cyc = qd__calloc(c->ctx, e->n ? e->n : 1, sizeof *cyc);
    size_t nc = 0;
    if (!cyc || qd_integrals_cyclic(c->ctx, c->m, e, cyc, &nc) != QD_OK)
        nc = 0;
    qd_json_key(j, "cyclic");
    qd_json_begin_array(j);
    for (size_t i = 0; i < nc; i++) {
        qd_json_begin_object(j);
        qd_json_key(j, "coordinate");
        qd_json_string(j, qd_expr_name(e->q[cyc[i].coord]));
        qd_json_key(j, "conserved");
        qd_json_bool(j, cyc[i].conserved);
        qd_json_key(j, "momentum");
        qd_json_expr(j, c->ctx, cyc[i].momentum);
        qd_json_key(j, "obstruction");
        qd_json_string(j, cyc[i].conserved ? NULL : cyc[i].obstruction);
        qd_json_end_object(j);
    }
    qd_json_end_array(j);
    qd__free(cyc);
}

static void json_forces(check *c, qd_json *j) {
    qd_json_key(j, "forces");
    qd_json_begin_object(j);
    for (size_t k = 0; k < qd_model_ncoords(c->m); k++) {
        const qd_expr *Q = qd_simplify(c->ctx, qd_model_force(c->m, k));
        if (!Q || qd_is_zero(Q))
            continue;
        qd_json_key(j, qd_expr_name(qd_model_coord(c->m, k)));
        qd_json_expr(j, c->ctx, Q);
    }
    qd_json_end_object(j);
}

/* The English of a verdict's machine code (v->reason), for JSON's "reason". */
static const char *verdict_words(const char *code) {
    if (code && !strcmp(code, "mass_not_positive_definite"))
        return "the mass matrix is not positive definite";
    if (code && !strcmp(code, "constraint_not_real"))
        return "a constraint has no real solution near the initial state";
    return code;
}

static void json_verdict(qd_json *j, const qd_check_verdict *v) {
    qd_json_key(j, "ok");
    qd_json_bool(j, v->ok);
    qd_json_key(j, "judged");
    qd_json_bool(j, v->judged);
    if (!v->ok) {
        qd_json_key(j, "code"); /* until issue 31 "reason" held the code */
        qd_json_string(j, v->reason);
        qd_json_key(j, "reason");
        qd_json_string(j, verdict_words(v->reason));
        qd_json_key(j, "message");
        qd_json_string(j, v->message);
        qd_json_key(j, "about");
        qd_json_string(j, v->about);
        qd_json_key(j, "witness");
        qd_json_number(j, v->witness);
    }
    if (v->off_constraint) {
        qd_json_key(j, "initial_residual");
        qd_json_number(j, v->residual);
        qd_json_key(j, "initial_residual_constraint");
        qd_json_string(j, v->residual_con);
    }
}

static void write_json(check *c, const char *path, const qd_eom *e, const qd_check_verdict *v) {
    qd_json j;
    qd_json_init(&j, c->out);
    qd_json_begin_object(&j);
    qd_json_key(&j, "model");
    qd_json_string(&j, path);
    json_verdict(&j, v);
    if (v->ok) {
        json_names(&j, "coordinates", e->n, e->q);
        qd__render_json_params(&j, c->m);
        json_dof(c, &j, e);
        qd_json_key(&j, "depends");
        qd_json_begin_object(&j);
        json_depends(c, &j, "T", qd_model_kinetic(c->m));
        json_depends(c, &j, "V", qd_model_potential(c->m));
        json_depends(c, &j, "U", qd_model_gen_potential(c->m));
        json_depends(c, &j, "dissipation", qd_model_dissipation(c->m));
        const qd_expr *Lm = qd_model_hamiltonian_given(c->m) ? e->L : qd_model_lagrangian(c->m);
        json_depends(c, &j, "L", Lm);
        qd_json_end_object(&j);
        json_forces(c, &j);
        json_constraints(c, &j, e);
        json_cyclic(c, &j, e);
        const qd_expr *L = qd_simplify(c->ctx, Lm);
        bool explicit_t = L && qd_has(L, qd_time(c->ctx));
        qd_json_key(&j, "explicit_time");
        qd_json_bool(&j, explicit_t);
        qd_json_key(&j, "energy_conserved");
        qd_json_bool(&j, L && !explicit_t && !nonconservative(c, e));
        qd_json_key(&j, "kinetic_energy");
        qd_json_string(&j, e->T1 && e->T0 && (!qd_is_zero(e->T1) || !qd_is_zero(e->T0))
                               ? "T2 + T1 + T0" : e->T2 ? "T2" : NULL);
    }
    qd_json_end_object(&j);
    qd_buf_puts(c->out, "\n");
}

/* ---- text ------------------------------------------------------------------- */

static void write_text(check *c, const char *path, const qd_eom *e) {
    header(c, path, e);
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
        qd_buf_printf(c->out, "equations: [M -A^T; A 0] is %zu x %zu, not identically singular\n",
                      e->n + e->ncon, e->n + e->ncon);
    else
        qd_buf_printf(c->out, "mass matrix: %zu x %zu, not identically singular\n", e->n, e->n);
}

qd_status qd_render_check(qd_ctx *ctx, const qd_model *m, const qd_eom *e,
                          const qd_render_opts *o, const qd_check_verdict *v,
                          qd_render_format fmt, qd_buf *out) {
    QD_ARGS_CTX(ctx, ctx && m && e && v && out);
    if (fmt != QD_RENDER_TEXT && fmt != QD_RENDER_JSON) {
        qd_ctx_error(ctx, QD_ERR_ARG, "the summary of a check prints as text or json");
        return QD_ERR_ARG;
    }
    check c = {ctx, m, out};
    const char *path = o && o->source ? o->source : "model";
    if (fmt == QD_RENDER_JSON)
        write_json(&c, path, e, v);
    else if (v->ok)
        write_text(&c, path, e);
    if (out->failed) {
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory printing the check");
        return QD_ERR_NOMEM;
    }
    return qd_ctx_status(ctx);
}

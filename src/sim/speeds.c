/*
 * src/sim/speeds.c - a model's equations in generalized speeds (qdot/speeds.h)
 * compiled into a first-order system, y = (q, u):
 *
 *     q' = W(q, t) u + w(q, t)   (the kinematics),
 *     M_u(q, t) u' = f_u(q, u, t),
 *
 * the third form beside (q, q') and (q, p) (system.c, hamilton.c).  The
 * constraints are eliminated (Desloge ch. 69 C12; Kane and Levinson 1985,
 * ch. 6): q' from the kinematics satisfies every Pfaffian row C q' + c0 = 0
 * for every u, so the motion keeps them to round-off with no projection and
 * no multiplier; a holonomic phi(q, t) = 0 is kept only in its velocity form
 * and the positions are projected back onto it (project.c; u stays, and
 * q' = kin(q, u) stays on the velocity constraints).
 *
 * The programs take the inputs of system.c with the speeds in the block
 * where the multipliers stand there: (q, q', t, parameters, u).  Outputs,
 * events, the energy h and the residuals are read at (q, q', t) with
 * q' = kin(q, u, t); a speed named in an output stands for its definition.
 */
#include "simint.h"

#include <math.h>
#include <string.h>

#include "num/num.h"
#include "base/mem.h"
#include "../base/args.h"

static qd_status inputs(qd_sim *s) {
    const qd_speeds_eom *e = s->se;
    qd_status st = qd__sim_inputs(s, e->q, e->qd, s->nu);
    for (size_t r = 0; st == QD_OK && r < s->nu; r++)
        s->in_syms[2 * s->n + 1 + s->np + r] = e->u[r];
    return st;
}

/* acc = (kin, M_u, f_u): one program per right-hand side; kin alone for
 * the rows, udef for the initial speeds, con for the residuals. */
static qd_status compile(qd_sim *s) {
    const qd_speeds_eom *e = s->se;
    size_t n = s->n, nu = s->nu;
    const qd_expr *const *parts[] = {e->kin, e->M, e->f};
    const size_t size[] = {n, nu * nu, nu};
    s->acc = qd__sim_prog_of(s, 3, parts, size, &s->acc_n);
    if (s->acc)
        s->kin = qd__sim_prog(s, n, e->kin, &s->kin_n);
    if (s->kin)
        s->udef = qd__sim_prog(s, nu, e->def, &s->udef_n);
    if (!s->udef)
        return qd_ctx_status(s->ctx);
    return qd__sim_con_prog(s);
}

/* h = sum q' dL/dq' - L from the model's Lagrangian (read at q' = kin),
 * T, and whether h is conserved. */
static qd_status analyse(qd_sim *s) {
    qd_ctx *ctx = s->ctx;
    const qd_speeds_eom *e = s->se;
    const qd_expr *L = qd_model_lagrangian(s->model), *D = qd_model_dissipation(s->model);
    if (!L)
        return qd_ctx_status(ctx) != QD_OK ? qd_ctx_status(ctx) : QD_ERR_ARG;
    const qd_expr *h = qd_neg(ctx, L);
    bool forces = false;
    for (size_t j = 0; j < s->n; j++) {
        h = qd_add(ctx, h, qd_mul(ctx, e->qd[j], qd_diff(ctx, L, e->qd[j])));
        const qd_expr *Q = qd_model_force(s->model, j);
        forces = forces || (Q && !qd_is_zero(Q));
    }
    s->h_expr = qd_simplify(ctx, h);
    s->has_T = e->T != NULL;
    s->T_expr = s->has_T ? e->T : qd_int(ctx, 0);
    if (s->has_T)
        qd__sim_speeds_defs(s, 1, &s->T_expr);
    s->conservative = !qd_has(L, qd_time(ctx)) && !forces && !(D && !qd_is_zero(D));
    return qd_ctx_status(ctx) == QD_OK && s->h_expr && s->T_expr ? QD_OK : qd_ctx_status(ctx);
}

void qd__sim_speeds_defs(qd_sim *s, size_t n, const qd_expr **x) {
    const qd_speeds_eom *e = s->se;
    for (size_t i = 0; i < n; i++)
        x[i] = qd_subs(s->ctx, x[i], s->nu, e->u, e->def);
}

static qd_status refuse(qd_ctx *ctx, const char *why) {
    qd_ctx_error(ctx, QD_ERR_ARG, "%s", why);
    return QD_ERR_ARG;
}

static qd_status check(qd_ctx *ctx, const qd_model *m, const qd_speeds_eom *e) {
    if (!e || !m)
        return refuse(ctx, "qd_sim_new_speeds needs a model and its equations in speeds");
    if (e->n != qd_model_ncoords(m) || e->m == 0)
        return refuse(ctx, "the equations in speeds are not this model's");
    if (qd_model_nimpacts(m))
        return refuse(ctx, "impacts are not simulated in generalized speeds (Newton's law "
                           "is written for the velocities): integrate the multiplier form "
                           "(--no-speeds)");
    return qd__sim_fric_refuse(ctx, m, "in generalized speeds (--no-speeds)");
}

qd_sim *qd_sim_new_speeds(qd_ctx *ctx, const qd_model *m, const qd_speeds_eom *e) {
    QD_ARGS(NULL, ctx && m && e);
    if (check(ctx, m, e) != QD_OK)
        return NULL;
    qd_sim *s = qd__sim_alloc(ctx, &(qd_sim){.ctx = ctx, .model = m, .se = e, .n = e->n,
                                            .m = e->ncon, .nu = e->m, .cons = e->con});
    if (!s)
        return NULL;
    qd_status st = inputs(s);
    if (st == QD_OK)
        st = compile(s);
    if (st == QD_OK)
        st = analyse(s);
    if (st == QD_OK)
        st = qd__sim_names(s);
    return qd__sim_made(s, st, "cannot compile the equations in speeds for simulation");
}

size_t qd_sim_nspeeds(const qd_sim *s) { QD_ARGS(0, s); return s->nu; }

/* q, t and u into the inputs (the velocities' block is left as it is). */
static void set_qu(qd_sim *s, double t, const double *y) {
    size_t n = s->n;
    double *u = qd__sim_in_speeds(s);
    for (size_t j = 0; j < n; j++)
        s->in[j] = y[j];
    s->in[2 * n] = t;
    for (size_t r = 0; r < s->nu; r++)
        u[r] = y[n + r];
}

qd_status qd__sim_speeds_rhs(qd_sim *s, double t, const double *y, double *dy) {
    size_t n = s->n, nu = s->nu;
    set_qu(s, t, y);
    qd_prog_eval(s->acc, s->acc_w, s->in, s->acc_out);
    const double *M = s->acc_out + n, *f = M + nu * nu;
    for (size_t j = 0; j < n; j++)
        dy[j] = s->acc_out[j];
    for (size_t i = 0; i < nu * nu; i++)
        s->K[i] = M[i];
    for (size_t r = 0; r < nu; r++)
        dy[n + r] = f[r];
    if (qd__num_solve(nu, s->K, dy + n, 1e-13 * (double)nu))
        return QD_OK;
    qd__sim_stop(s, QD_STOP_SINGULAR, t, NAN);
    qd_ctx_error(s->ctx, QD_ERR_SINGULAR,
                 "singular mass matrix M_u at t = %.17g: the speeds' rates are not "
                 "determined there", t);
    return QD_ERR_SINGULAR;
}

void qd__sim_speeds_velocity(qd_sim *s, double t, const double *y, double *qd) {
    set_qu(s, t, y);
    qd_prog_eval(s->kin, s->kin_w, s->in, qd);
}

void qd__sim_speeds_from(qd_sim *s, double t, const double *q, const double *qd, double *u) {
    qd__sim_prog_at(s, s->udef, s->udef_w, t, q, qd, u);
}

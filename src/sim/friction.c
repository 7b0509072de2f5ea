/*
 * src/sim/friction.c - Coulomb friction contacts in a simulation: the
 * compiled contacts, the modes of a run, the saddle system of a mode set,
 * the dissipated power and the switching functions.
 *
 * A contact's constraints (velocity constraints: LHS - RHS the slip
 * velocity v of the contact point, so that the multiplier lambda is the
 * friction force along it, M q'' = f + A^T lambda) stay in the saddle
 * system [M -A^T; A 0] in both modes.  Sticking, their rows are A q'' = b.
 * Slipping, each row becomes lambda_i = -mu_k |N| u_i, u the unit slip
 * direction: the kinetic force of Coulomb's law (Byerly ch. I; Goldstein
 * sec. 1.5 for the dissipation).  With N a multiplier lambda_N, |N| =
 * sn lambda_N for the sign sn assumed, so the row stays linear:
 * lambda_i + mu_k sn u_i lambda_N = 0, and the solve gives friction and
 * normal force together (the Painleve rod's coupling).  The dissipated
 * energy is integrated as one more state, y[2n], with the power
 * -sum lambda_i v_i = mu_k |N| |v| >= 0.  On a moving surface (a0 != 0
 * in some row A q' + a0 = 0) the work the surface's motion does, the
 * integral of -sum lambda a0, is y[2n + 1]: the balance is then
 * E + dissipated - surface_work = E0 (docs/design.md, "the energy balance
 * on a moving surface").
 */
#include "simint.h"
#include "../base/mem.h"
#include "../base/args.h"

#include <math.h>
#include <string.h>

struct qd__sim_fric_last {
    qd_sim_transition *tr;
    size_t n;
};

qd_status qd__sim_fric_refuse(qd_ctx *ctx, const qd_model *m, const char *what) {
    if (!qd_model_ncontacts(m))
        return QD_OK;
    qd_ctx_error(ctx, QD_ERR_ARG,
                 "friction contact '%s' cannot be simulated %s: integrate the Lagrangian "
                 "form (dop853)", qd_model_contact_name(m, 0), what);
    return QD_ERR_ARG;
}

/* The index in s->cons of the model's constraint i, or (size_t)-1. */
static size_t con_index(const qd_sim *s, const char *name) {
    for (size_t k = 0; name && k < s->m; k++)
        if (!strcmp(s->cons[k].name, name))
            return k;
    return (size_t)-1;
}

static qd_status map_contact(qd_sim *s, size_t i, qd__sim_fcon *c) {
    const qd_model *m = s->model;
    size_t con[2];
    c->name = qd_model_contact_name(m, i);
    c->ncon = qd_model_contact_constraints(m, i, con);
    for (size_t k = 0; k < c->ncon; k++) {
        c->con[k] = con_index(s, qd_model_constraint_name(m, con[k]));
        if (c->con[k] == (size_t)-1 || s->cons[c->con[k]].kind == QD_CON_HOLONOMIC) {
            qd_ctx_error(s->ctx, QD_ERR_ARG, "friction contact '%s': its constraint %s is not "
                         "a velocity constraint of the equations", c->name,
                         qd_model_constraint_name(m, con[k]));
            return QD_ERR_ARG;
        }
    }
    const char *nc = qd_model_contact_normal_constraint(m, i);
    c->normal = con_index(s, nc);
    if (nc && c->normal == (size_t)-1) {
        qd_ctx_error(s->ctx, QD_ERR_ARG, "friction contact '%s': its normal constraint %s was "
                     "eliminated from the equations", c->name, nc);
        return QD_ERR_ARG;
    }
    return QD_OK;
}

/* mu_s, mu_k, N, s1, s2 per contact, over the programs' inputs. */
static qd_status compile_fprog(qd_sim *s) {
    size_t k = 0;
    const qd_expr **outs = qd__malloc(s->ctx, (QD__FSTRIDE * s->nfc + 1) * sizeof *outs);
    if (!outs)
        return QD_ERR_NOMEM;
    const qd_expr *zero = qd_int(s->ctx, 0);
    for (size_t i = 0; i < s->nfc; i++) {
        const qd__sim_fcon *c = &s->fc[i];
        const qd_expr *N = qd_model_contact_normal(s->model, i);
        outs[k++] = qd_model_contact_mu(s->model, i, false);
        outs[k++] = qd_model_contact_mu(s->model, i, true);
        outs[k++] = N ? N : qd_model_contact_normal_scale(s->model, i);
        outs[k++] = s->cons[c->con[0]].expr;
        outs[k++] = c->ncon > 1 ? s->cons[c->con[1]].expr : zero;
    }
    s->fprog = qd__sim_prog(s, k, outs, &s->fprog_n);
    qd__free(outs);
    return s->fprog ? QD_OK : qd_ctx_status(s->ctx);
}

qd_status qd__sim_fric_setup(qd_sim *s) {
    size_t nfc = qd_model_ncontacts(s->model);
    if (!nfc)
        return QD_OK;
    if (nfc > QD__FMAX) {
        qd_ctx_error(s->ctx, QD_ERR_ARG, "%zu friction contacts: at most %d are simulated "
                     "(the choice of modes tries every combination)", nfc, QD__FMAX);
        return QD_ERR_ARG;
    }
    if (qd_model_nimpacts(s->model)) {
        qd_ctx_error(s->ctx, QD_ERR_ARG, "a model with both friction contacts and impacts is "
                     "not simulated");
        return QD_ERR_ARG;
    }
    s->fc = qd__calloc(s->ctx, nfc, sizeof *s->fc);
    s->flast = qd__calloc(s->ctx, 1, sizeof *s->flast);
    if (!s->fc || !s->flast)
        return QD_ERR_NOMEM;
    s->nfc = nfc;
    for (size_t i = 0; i < nfc; i++) {
        qd_status st = map_contact(s, i, &s->fc[i]);
        if (st != QD_OK)
            return st;
    }
    for (size_t c = 0; c < s->m; c++)
        s->rheo = s->rheo || !qd_is_zero(s->cons[c].a0);
    return compile_fprog(s);
}

size_t qd__sim_fric_nextra(const qd_sim *s) { return s->nfc ? 1 + (s->rheo ? 1 : 0) : 0; }

void qd__sim_fric_free(qd_sim *s) {
    qd_prog_free(s->fprog);
    qd__free(s->fc);
    if (s->flast)
        qd__free(s->flast->tr);
    qd__free(s->flast);
}

size_t qd_sim_ncontacts(const qd_sim *s) { QD_ARGS(0, s); return s->nfc; }

const qd_sim_transition *qd_sim_transitions(const qd_sim *s, size_t *n) {
    QD_ARGS(NULL, s && n);
    *n = s->flast ? s->flast->n : 0;
    return s->flast ? s->flast->tr : NULL;
}

/* ---- a run's modes --------------------------------------------------------- */

qd_status qd__sim_fric_run_new(qd_sim *s) {
    s->fr = NULL;
    s->fprog_out = s->fprog_w = NULL;
    if (!s->nfc)
        return QD_OK;
    qd__sim_fric_run *fr = qd__calloc(s->ctx, 1, sizeof *fr);
    s->fr = fr;
    if (!fr)
        return QD_ERR_NOMEM;
    fr->mode = qd__calloc(s->ctx, 3 * s->nfc, sizeof *fr->mode);
    fr->on = qd__calloc(s->ctx, s->m + 1, sizeof *fr->on);
    fr->fresh = qd__calloc(s->ctx, s->nfc, sizeof *fr->fresh);
    s->fprog_out = qd__malloc(s->ctx, (s->fprog_n + 1) * sizeof *s->fprog_out);
    s->fprog_w = qd__malloc(s->ctx, qd_prog_work_size(s->fprog) * sizeof *s->fprog_w);
    if (!fr->mode || !fr->on || !fr->fresh || !s->fprog_out || !s->fprog_w)
        return QD_ERR_NOMEM;
    qd_prog_work_init(s->fprog, s->fprog_w);
    fr->trial = fr->mode + s->nfc;
    fr->best = fr->trial + s->nfc;
    for (size_t i = 0; i < s->nfc; i++)
        fr->mode[i] = (qd__sim_fmode){.slip = false, .dir = {1, 0}, .sn = 1};
    for (size_t k = 0; k < s->m; k++)
        fr->on[k] = true;
    return QD_OK;
}

/* The switches of a finished run kept for qd_sim_transitions (orig: the
 * caller's qd_sim, which qd_sim_run may write). */
static void keep_transitions(qd_sim *orig, qd__sim_fric_run *fr) {
    struct qd__sim_fric_last *last = orig->flast;
    qd__free(last->tr);
    last->tr = fr->tr;
    last->n = fr->ntr;
    fr->tr = NULL;
}

void qd__sim_fric_run_free(qd_sim *s) {
    qd__sim_fric_run *fr = s->fr;
    if (fr) {
        qd__free(fr->mode);
        qd__free(fr->on);
        qd__free(fr->fresh);
        qd__free(fr->tr);
        qd__free(fr);
    }
    qd__free(s->fprog_out);
    qd__free(s->fprog_w);
    s->fr = NULL;
}

void qd__sim_fric_keep(qd_sim *orig, qd_sim *run) {
    if (run->fr && orig->flast)
        keep_transitions(orig, run->fr);
}

/* ---- the saddle system of a mode set --------------------------------------- */

static const double *fvals(const qd_sim *s, size_t c) {
    return s->fprog_out + QD__FSTRIDE * c;
}

double qd__sim_fric_slip(const qd_sim *s, size_t c) {
    const double *f = fvals(s, c);
    return s->fc[c].ncon > 1 ? hypot(f[3], f[4]) : f[3];
}

/* The unit direction of contact c's kinetic force's opposite: v/|v|, or the
 * mode's direction while v is 0 (the instant it starts to slip). */
static void slip_dir(const qd_sim *s, size_t c, const qd__sim_fmode *md, double u[2]) {
    const double *f = fvals(s, c);
    if (s->fc[c].ncon == 1) {
        u[0] = md->dir[0];
        u[1] = 0;
        return;
    }
    double v = hypot(f[3], f[4]);
    u[0] = v > 0 ? f[3] / v : md->dir[0];
    u[1] = v > 0 ? f[4] / v : md->dir[1];
}

void qd__sim_fric_saddle(qd_sim *s, double *K, double *rhs) {
    qd__sim_fric_run *fr = s->fr;
    size_t n = s->n, N = n + s->m;
    qd_prog_eval(s->fprog, s->fprog_w, s->in, s->fprog_out);
    for (size_t c = 0; c < s->nfc; c++) {
        const qd__sim_fcon *fc = &s->fc[c];
        const qd__sim_fmode *md = &fr->mode[c];
        if (!md->slip)
            continue;
        const double *f = fvals(s, c);
        double u[2];
        slip_dir(s, c, md, u);
        for (size_t i = 0; i < fc->ncon; i++) {
            size_t row = n + fc->con[i];
            for (size_t j = 0; j < N; j++)
                K[row * N + j] = 0;
            K[row * N + row] = 1;
            if (fc->normal != (size_t)-1) {
                K[row * N + n + fc->normal] = f[1] * md->sn * u[i] * fabs(f[2]);
                rhs[row] = 0;
            } else {
                rhs[row] = -f[1] * fabs(f[2]) * u[i];
            }
        }
    }
}

double qd__sim_fric_power(const qd_sim *s) {
    double P = 0;
    const double *lambda = s->rhs + s->n;
    for (size_t c = 0; c < s->nfc; c++) {
        const qd__sim_fcon *fc = &s->fc[c];
        if (!s->fr->mode[c].slip)
            continue;
        const double *f = fvals(s, c);
        for (size_t i = 0; i < fc->ncon; i++)
            P -= lambda[fc->con[i]] * f[3 + i];
    }
    return P;
}

/* A slipping row's lambda is its friction force and its slip velocity
 * A q' + a0: lambda . A q' = lambda s - lambda a0 splits the friction's
 * power on the system into the dissipation and the surface's share, so one
 * sum over every row serves both modes. */
double qd__sim_fric_surface_power(qd_sim *s) {
    const double *lambda = s->rhs + s->n;
    qd_prog_eval(s->con, s->con_w, s->in, s->con_out);
    const double *a0 = s->con_out + s->m * s->n;
    double P = 0;
    for (size_t c = 0; c < s->m; c++)
        P -= lambda[c] * a0[c];
    return P;
}

/* |N| of contact c after a saddle solve. */
double qd__sim_fric_normal(const qd_sim *s, size_t c) {
    const qd__sim_fcon *fc = &s->fc[c];
    double scale = fabs(fvals(s, c)[2]); /* N's value, or |N| / |lambda_N| */
    return fc->normal != (size_t)-1 ? scale * fabs(s->rhs[s->n + fc->normal]) : scale;
}

/* The friction force's size |lambda| of contact c after a saddle solve. */
double qd__sim_fric_force(const qd_sim *s, size_t c) {
    const qd__sim_fcon *fc = &s->fc[c];
    const double *lambda = s->rhs + s->n;
    return fc->ncon > 1 ? hypot(lambda[fc->con[0]], lambda[fc->con[1]])
                        : fabs(lambda[fc->con[0]]);
}

/* Event 2c: sticking, |lambda| - mu_s |N| (slips as it rises through 0);
 * slipping, v . u_entry (stops as it falls through 0).  Event 2c + 1: the
 * normal multiplier times its assumed sign, while slipping (its sign
 * change makes the kinetic law inconsistent), else 1. */
qd_status qd__sim_fric_event(qd__sim_run *r, size_t k, double t, const double *y, double *g) {
    qd_sim *s = r->s;
    size_t c = k / 2;
    const qd__sim_fcon *fc = &s->fc[c];
    const qd__sim_fmode *md = &s->fr->mode[c];
    if (k % 2 && (!md->slip || fc->normal == (size_t)-1)) {
        *g = 1;
        return QD_OK;
    }
    if (!qd__sim_saddle(s, t, y)) {
        qd__sim_stop(s, QD_STOP_SINGULAR, t, NAN);
        qd_ctx_error(s->ctx, QD_ERR_SINGULAR, "singular constrained equations at t = %.17g "
                     "(friction contact '%s')", t, fc->name);
        return QD_ERR_SINGULAR;
    }
    const double *f = fvals(s, c);
    if (k % 2)
        *g = md->sn * s->rhs[s->n + fc->normal];
    else if (!md->slip)
        *g = qd__sim_fric_force(s, c) - f[0] * qd__sim_fric_normal(s, c);
    else
        *g = md->dir[0] * f[3] + (fc->ncon > 1 ? md->dir[1] * f[4] : 0);
    return QD_OK;
}

bool qd__sim_fric_crossing(const qd_sim *s, size_t k, double ga) {
    bool rising = k % 2 == 0 && !s->fr->mode[k / 2].slip;
    return rising ? ga < 0 : ga > 0;
}

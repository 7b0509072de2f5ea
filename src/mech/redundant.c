/*
 * src/mech/redundant.c - constraints whose rows A are dependent: redundant
 * (left out by rank, named in e->reduced) or inconsistent (refused, with
 * the state that shows it).
 *
 * Dependence must be judged where the motion lives: on the configurations
 * the holonomic constraints allow.  A disk on an axle pivoted at a fixed
 * ball joint has the rolling rows and the contact's velocity form
 * dependent at every state (the contact point's velocity is perpendicular
 * to its arm from the pivot), but the contact's own value is 0 only on the
 * manifold, so a combination of the values at a random state says nothing.
 * So each random state is first moved onto the holonomic constraints
 * (Gauss-Newton, minimum-norm steps), and there, with mu^T A = 0 (the
 * scale-aware rank test of qd__num_rank on equilibrated rows), the velocity
 * forms A q' + a0 combine to mu . a0 for every q': not 0 (relative to the
 * rows' size) means no velocity meets them all at that configuration, the
 * witness of inconsistency.  A combination that is 0 at every state is a
 * redundancy; then the acceleration rows agree too (they are the time
 * derivative of an identity along the motion).  The constraint left out is
 * the one whose weight in mu stays largest over the states, so the others
 * stay independent everywhere tried (the contact on the axle, whose
 * weight is the pivot's height; a rolling row's weight vanishes where the
 * axle points along its tangent).  A holonomic set that the projection
 * cannot meet (x = 1 and x = 2) is inconsistent with the least-squares
 * point as witness.
 */
#include "mech.h"

#include "num/num.h"
#include "qdot/print.h"
#include "../base/mem.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#define NSTATES 4
#define RANK_TOL 1e-9
#define NEWTON_MAX 60
#define FEAS_TOL 1e-12
#define CONSIST_TOL 1e-8

typedef struct red {
    qd_ctx *ctx;
    qd_eom *e;
    qd_prog *p, *p0;   /* the eom program; the a0 of each constraint */
    size_t nin, nout;
    double *in, *out, *a0, *mu, *w, *J, *G, *y;
    size_t *qi;        /* input index of q_j, SIZE_MAX when not an input */
    const qd_expr *const *inputs;
} red;

static void input_index(red *r, const qd_expr *const *inputs) {
    for (size_t j = 0; j < r->e->n; j++) {
        r->qi[j] = SIZE_MAX;
        for (size_t i = 0; i < r->nin; i++)
            if (inputs[i] == r->e->q[j])
                r->qi[j] = i;
    }
}

static bool finite_all(size_t n, const double *x) {
    for (size_t i = 0; i < n; i++)
        if (!isfinite(x[i]))
            return false;
    return true;
}

/* Residual of the holonomic constraints at r->in and its size relative to
 * their rows' size times the coordinates'. */
static double holo_residual(red *r, double *scale) {
    const qd_eom *e = r->e;
    double res = 0, s = 0;
    for (size_t k = 0; k < e->ncon; k++) {
        if (e->con[k].kind != QD_CON_HOLONOMIC)
            continue;
        res = fmax(res, fabs(r->out[qd__out_g(e) + k]));
        for (size_t j = 0; j < e->n; j++)
            if (r->qi[j] != SIZE_MAX)
                s = fmax(s, fabs(r->out[qd__out_A(e) + k * e->n + j]) *
                                (1 + fabs(r->in[r->qi[j]])));
    }
    *scale = s;
    return res;
}

/* One minimum-norm Gauss-Newton step dq = -J^T (J J^T + d I)^-1 g on the
 * holonomic rows; false when the step cannot be formed. */
static bool newton_step(red *r) {
    const qd_eom *e = r->e;
    size_t n = e->n, h = 0;
    for (size_t k = 0; k < e->ncon; k++) {
        if (e->con[k].kind != QD_CON_HOLONOMIC)
            continue;
        for (size_t j = 0; j < n; j++)
            r->J[h * n + j] = r->qi[j] != SIZE_MAX ? r->out[qd__out_A(e) + k * n + j] : 0;
        r->y[h++] = r->out[qd__out_g(e) + k];
    }
    double tr = 0;
    for (size_t a = 0; a < h; a++)
        for (size_t b = 0; b < h; b++) {
            double s = 0;
            for (size_t j = 0; j < n; j++)
                s += r->J[a * n + j] * r->J[b * n + j];
            r->G[a * h + b] = s;
            tr += a == b ? s : 0;
        }
    for (size_t a = 0; a < h; a++)
        r->G[a * h + a] += 1e-14 * (tr + 1e-300);
    if (!qd__num_solve(h, r->G, r->y, 0))
        return false;
    for (size_t j = 0; j < n; j++) {
        if (r->qi[j] == SIZE_MAX)
            continue;
        double d = 0;
        for (size_t a = 0; a < h; a++)
            d += r->J[a * n + j] * r->y[a];
        r->in[r->qi[j]] -= d;
    }
    return true;
}

/* Move r->in onto the holonomic constraints; false when they cannot be
 * met from there (the residual stalls), r->in then the closest point. */
static bool project(red *r) {
    double scale, res = 0;
    for (int it = 0; it < NEWTON_MAX; it++) {
        qd_prog_run(r->p, r->in, r->out);
        if (!finite_all(r->nout, r->out))
            return false;
        res = holo_residual(r, &scale);
        if (res <= FEAS_TOL * (1 + scale))
            return true;
        if (!newton_step(r))
            return false;
    }
    return false;
}

/* The values in r->in of the coordinates and parameters the constraints
 * depend on (the witness: the parameters were drawn too). */
static void put_state(red *r, char *buf, size_t len) {
    size_t used = 0;
    for (size_t i = 0; i < r->nin && used + 48 < len; i++) {
        const char *name = qd_expr_name(r->inputs[i]);
        bool in_con = false; /* only what the constraints depend on */
        for (size_t k = 0; k < r->e->ncon && !in_con; k++)
            in_con = qd_has(r->e->con[k].expr, r->inputs[i]);
        if (!name || strchr(name, '\'') || !in_con)
            continue;
        char num[40];
        qd_double_format(num, r->in[i]);
        used += (size_t)snprintf(buf + used, len - used, "%s%s = %s", used ? ", " : "", name, num);
    }
}

/* Drop constraint k from e: rows compacted, the name recorded. */
static qd_status drop(qd_ctx *ctx, qd_eom *e, size_t k) {
    const char **names = qd__malloc(ctx, (e->nreduced + 1) * sizeof *names);
    if (!names)
        return QD_ERR_NOMEM;
    for (size_t i = 0; i < e->nreduced; i++)
        names[i] = e->reduced[i];
    names[e->nreduced++] = e->con[k].name;
    qd__free(e->reduced);
    e->reduced = names;
    size_t n = e->n, m = e->ncon;
    for (size_t i = k; i + 1 < m; i++) {
        e->con[i] = e->con[i + 1];
        e->b[i] = e->b[i + 1];
        memmove(e->A + i * n, e->A + (i + 1) * n, n * sizeof *e->A);
    }
    e->ncon = m - 1;
    for (size_t i = 0; i < e->ncon; i++)
        e->con[i].a = e->A + i * n;
    qd__mech_eom_num_free(e->priv); /* its outputs were laid out for m rows */
    return QD_OK;
}

static qd_status refuse(red *r, bool stalled) {
    char where[512], state[400] = "";
    put_state(r, state, sizeof state);
    if (stalled)
        snprintf(where, sizeof where,
                 " (no configuration meets them: the least-squares one, %s, leaves a residual)",
                 state);
    else
        snprintf(where, sizeof where,
                 " (%s%s: a combination of their velocity forms is %.3g whatever the velocities)",
                 *state ? "at " : "at every configuration", *state ? state : "", r->a0[0]);
    return qd__mech_con_report(r->ctx, r->e, r->mu, true, where);
}

/* One state: onto the manifold, the rank there, consistency. 1: dependent
 * and consistent (weights updated), 0: independent here, -1: refused,
 * -2: no verdict from this state. */
static int one_state(red *r, unsigned k) {
    const qd_eom *e = r->e;
    size_t m = e->ncon, n = e->n;
    qd__mech_random_state(r->nin, r->in, k + 17);
    bool feasible = project(r);
    qd_prog_run(r->p, r->in, r->out);
    if (!finite_all(r->nout, r->out))
        return -2;
    if (!qd__mech_con_deficient(r->ctx, n, m, r->out + qd__out_A(e), RANK_TOL, r->mu))
        return feasible ? 0 : -2;
    if (!feasible) {
        bool holo_only = true;
        for (size_t i = 0; i < m; i++)
            holo_only = holo_only && (r->mu[i] == 0 || e->con[i].kind == QD_CON_HOLONOMIC);
        return holo_only ? (refuse(r, true), -1) : -2;
    }
    qd_prog_run(r->p0, r->in, r->a0 + 1);
    double s = 0, scale = 0;
    for (size_t i = 0; i < m; i++) {
        double row = 0;
        for (size_t j = 0; j < n; j++)
            row += fabs(r->out[qd__out_A(e) + i * n + j]);
        s += r->mu[i] * r->a0[1 + i];
        scale += fabs(r->mu[i]) * (fabs(r->a0[1 + i]) + row);
    }
    if (fabs(s) > CONSIST_TOL * scale) {
        r->a0[0] = s;
        refuse(r, false);
        return -1;
    }
    for (size_t i = 0; i < m; i++)
        r->w[i] = fmin(r->w[i], fabs(r->mu[i]));
    return 1;
}

static qd_status setup(red *r, const qd_expr *const *inputs) {
    const qd_eom *e = r->e;
    size_t n = e->n, m = e->ncon;
    r->nout = qd__out_len(e);
    r->in = qd__malloc(r->ctx, (r->nin + r->nout + 4 * m + 2 + n * m + m * m + 1) *
                                   sizeof *r->in);
    r->qi = qd__malloc(r->ctx, (n + 1) * sizeof *r->qi);
    const qd_expr **a0 = qd__malloc(r->ctx, (m + 1) * sizeof *a0);
    if (!r->in || !r->qi || !a0) {
        qd__free(a0);
        return QD_ERR_NOMEM;
    }
    r->out = r->in + r->nin;
    r->a0 = r->out + r->nout;          /* a0[0]: the combination, then m values */
    r->mu = r->a0 + m + 1;
    r->w = r->mu + m + 1;
    r->J = r->w + m;
    r->G = r->J + n * m;
    r->y = r->G + m * m;
    for (size_t k = 0; k < m; k++) {
        a0[k] = e->con[k].a0;
        r->w[k] = 1;
    }
    r->inputs = inputs;
    input_index(r, inputs);
    r->p0 = qd_prog_new(r->ctx, r->nin, inputs, m, a0);
    qd__free(a0);
    return r->p0 ? QD_OK : qd_ctx_status(r->ctx);
}

/* No verdict to act on, said so (never silently "inconsistent"): the rows
 * are dependent at every random state, but either too few states reached
 * the manifold, or the dependence moves between the constraints so that
 * no one of them can be left out everywhere. */
static qd_status undecided(qd_ctx *ctx, const qd_eom *e, const double *w, bool consistent) {
    qd_buf names = QD_BUF_WITH(qd__ctx_allocator(ctx));
    size_t first = e->ncon, count = 0;
    for (size_t k = 0; k < e->ncon; k++)
        if (w[k] > 1e-6) {
            qd_buf_printf(&names, "%s%s", count++ ? ", " : "", e->con[k].name);
            first = first < e->ncon ? first : k;
        }
    if (consistent)
        qd_ctx_error(ctx, QD_ERR_SINGULAR,
                     "constraints %s are redundant (consistent at every state tried), but no "
                     "one of them can be left out at every state", qd_buf_str(&names));
    else
        qd_ctx_error(ctx, QD_ERR_SINGULAR,
                     "constraints %s are dependent at every state tried; too few states could "
                     "be brought onto them to decide whether they are redundant or "
                     "inconsistent", qd_buf_str(&names));
    qd_buf_free(&names);
    qd_ctx_error_about(ctx, QD_SUBJECT_CONSTRAINT, first, first < e->ncon ? e->con[first].name : NULL,
                       QD_REASON_REDUNDANT, "remove the constraints that repeat what the others say");
    return QD_ERR_SINGULAR;
}

qd_status qd__mech_con_reduce(qd_ctx *ctx, qd_eom *e, bool *dropped) {
    *dropped = false;
    qd__eom_num *num = e->priv;
    red r = {.ctx = ctx, .e = e, .p = num->prog->prog, .nin = num->prog->nin};
    qd_status st = setup(&r, num->prog->inputs);
    /* a state the projection cannot bring onto the manifold (random
     * parameters for which the contact has no solution) gives no verdict */
    int dependent = 0, verdict = 0;
    for (unsigned k = 0; st == QD_OK && k < NSTATES + 4 && verdict != -1 && dependent < NSTATES;
         k++) {
        verdict = one_state(&r, k);
        dependent += verdict == 1;
        if (verdict == 0) /* independent on the manifold: nothing to reduce */
            break;
    }
    size_t pick = 0;
    for (size_t i = 1; i < e->ncon; i++)
        if (r.w[i] >= r.w[pick])
            pick = i;
    bool reduce = st == QD_OK && verdict != 0 && dependent >= 2 && r.w[pick] > 1e-6;
    qd_prog_free(r.p0);
    qd__free(r.in);
    qd__free(r.qi);
    if (st != QD_OK || verdict == -1)
        return st != QD_OK ? st : QD_ERR_SINGULAR;
    if (reduce) {
        *dropped = true;
        return drop(ctx, e, pick);
    }
    if (verdict == 0) /* independent where the motion lives */
        return QD_OK;
    return undecided(ctx, e, r.w, dependent >= 2);
}

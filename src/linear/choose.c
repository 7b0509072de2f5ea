/*
 * src/linear/choose.c - which equilibrium to oscillate about when the
 * caller names none (qd_equilibria_choose), and whether an exact
 * equilibrium holds whatever the parameters' values are
 * (qd_equilibrium_exact_in_parameters).
 *
 * The choice prefers what a user means by "the" equilibrium of a model
 * with an `initial` state: the spring triangle started nearly equilateral
 * must oscillate about the equilateral triangle, not about the first (a
 * collinear, unstable) configuration in the sorted list.
 *
 * When the model's initial state is itself a minimum-like equilibrium it is
 * taken as it is and no multistart is run (issue 34).
 *
 * Allocations (for the context allocator): work_init (calloc x2),
 * qd_equilibria_choose (calloc x2), qd_equilibrium_exact_in_parameters
 * (calloc x3); each freed before return.
 */
#include "qdot/equilibria.h"
#include "base/mem.h"
#include "../base/args.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* Relative tolerances: two minima as near or as low are a tie (the first
 * listed stays); Newton's end point is a listed equilibrium when every
 * coordinate agrees this closely (the listed one carries exact values). */
#define TIE_TOL 1e-12
#define SAME_TOL 1e-7
/* The equations at an exact point vanish when |F| is this small against
 * the sum of its terms' sizes. */
#define ZERO_TOL 1e-9

static const double PI = 3.14159265358979323846;

/* The caller's values with the equations' coordinates movable: the slot in
 * syms of each q_j and q'_j (SIZE_MAX when absent). */
typedef struct work {
    size_t n, nvals;
    const qd_expr *const *syms;
    double *vals;
    size_t *qslot, *vslot;
} work;

static size_t slot_of(size_t nvals, const qd_expr *const *syms, const qd_expr *x) {
    for (size_t i = 0; i < nvals; i++)
        if (syms[i] == x)
            return i;
    return SIZE_MAX;
}

static bool work_init(qd_ctx *ctx, work *w, const qd_eom *e, size_t nvals, const qd_expr *const *syms,
                      const double *vals) {
    *w = (work){.n = e->n, .nvals = nvals, .syms = syms};
    w->vals = qd__calloc(ctx, nvals + 1, sizeof *w->vals);
    w->qslot = qd__calloc(ctx, 2 * e->n + 1, sizeof *w->qslot);
    if (!w->vals || !w->qslot)
        return false;
    w->vslot = w->qslot + e->n;
    if (nvals)
        memcpy(w->vals, vals, nvals * sizeof *w->vals);
    for (size_t j = 0; j < e->n; j++) {
        w->qslot[j] = slot_of(nvals, syms, e->q[j]);
        w->vslot[j] = slot_of(nvals, syms, e->qd[j]);
    }
    return true;
}

static void work_free(work *w) {
    qd__free(w->vals);
    qd__free(w->qslot);
}

/* At q (n values), at rest. */
static void work_set(work *w, const double *q) {
    for (size_t j = 0; j < w->n; j++) {
        if (w->qslot[j] != SIZE_MAX)
            w->vals[w->qslot[j]] = q[j];
        if (w->vslot[j] != SIZE_MAX)
            w->vals[w->vslot[j]] = 0;
    }
}

/* The model's initial values of the equations' coordinates (0 where it
 * gives none); false when it gives none at all. */
static bool initial_state(qd_ctx *ctx, const qd_eom *e, const qd_model *m, const work *w,
                          double *q) {
    size_t nq = qd_model_ncoords(m);
    bool any = false;
    for (size_t j = 0; j < e->n; j++) {
        size_t i = 0;
        while (i < nq && qd_model_coord(m, i) != e->q[j])
            i++;
        const qd_expr *x = i < nq ? qd_model_initial(m, i, 0) : NULL;
        q[j] = 0;
        if (x && qd_eval(ctx, x, w->nvals, w->syms, w->vals, &q[j]) == QD_OK && isfinite(q[j]))
            any = true;
        else
            q[j] = 0;
        qd__ctx_recover(ctx);
    }
    return any;
}

/* V at q; 0 where it cannot be evaluated (it only ranks minima). */
static double potential_at(qd_ctx *ctx, const qd_model *m, work *w, const double *q) {
    const qd_expr *V = qd_model_potential(m);
    double v = 0;
    work_set(w, q);
    if (!V || qd_eval(ctx, V, w->nvals, w->syms, w->vals, &v) != QD_OK || !isfinite(v))
        v = 0;
    qd__ctx_recover(ctx);
    return v;
}

typedef struct chooser {
    qd_ctx *ctx;
    const qd_model *m;
    work w;
    const double *init;   /* NULL: the model gives no initial state */
    bool *angle;          /* n: angles are compared modulo 2 pi */
} chooser;

/* a_j - b_j, angles modulo 2 pi: Newton from th = 3 stops at pi + 1e-16,
 * which wraps to -pi + 1e-16, the same point as the listed pi. */
static double gap(const chooser *c, size_t j, double a, double b) {
    return c->angle[j] ? remainder(a - b, 2 * PI) : a - b;
}

static double dist2(const chooser *c, const double *a, const double *b) {
    double d = 0;
    for (size_t j = 0; j < c->w.n; j++)
        d += gap(c, j, a[j], b[j]) * gap(c, j, a[j], b[j]);
    return d;
}

/* a better than b: nearer the initial state, or lower V without one. */
static bool better(chooser *c, const qd_equilibrium *a, const qd_equilibrium *b) {
    if (c->init)
        return dist2(c, a->q, c->init) < dist2(c, b->q, c->init) * (1 - TIE_TOL);
    double vb = potential_at(c->ctx, c->m, &c->w, b->q);
    return potential_at(c->ctx, c->m, &c->w, a->q) < vb - TIE_TOL * fabs(vb);
}

/* A minimum of the potential up to directions of zero stiffness (rigid
 * motions of a free system): no negative direction, some positive one. */
static bool minimum_like(const qd_equilibrium *p) {
    return p->nneg == 0 && (p->npos > 0 || p->nzero == 0);
}

/* The listed equilibrium that Newton from the initial state reached, if
 * it is one of them (it carries the exact values), else Newton's point. */
static const qd_equilibrium *reached(const chooser *c, const qd_equilibrium_choice *ch) {
    if (!ch->from_initial.count)
        return NULL;
    const qd_equilibrium *p = &ch->from_initial.pts[0];
    for (size_t k = 0; k < ch->found.count; k++) {
        bool same = true;
        for (size_t j = 0; j < ch->found.n && same; j++)
            same = fabs(gap(c, j, ch->found.pts[k].q[j], p->q[j])) <=
                   SAME_TOL * (1 + fabs(p->q[j]));
        if (same)
            return &ch->found.pts[k];
    }
    return p;
}

static void pick(chooser *c, qd_equilibrium_choice *ch) {
    const qd_equilibria *eq = &ch->found;
    const qd_equilibrium *best = NULL, *start = reached(c, ch);
    if (start && minimum_like(start))
        best = start;
    for (size_t k = 0; k < eq->count; k++)
        if (minimum_like(&eq->pts[k]) && (!best || better(c, &eq->pts[k], best)))
            best = &eq->pts[k];
    if (best) {
        ch->reason = c->init ? QD_EQ_CHOSEN_NEAREST_MINIMUM : QD_EQ_CHOSEN_LOWEST_MINIMUM;
    } else if (start) {
        best = start;
        ch->reason = QD_EQ_CHOSEN_NEWTON_FROM_INITIAL;
    } else if (eq->count) {
        best = &eq->pts[0];
        ch->reason = QD_EQ_CHOSEN_FIRST_LISTED;
    }
    ch->pt = best;
    ch->others = eq->count - (best && best >= eq->pts && best < eq->pts + eq->count);
}

/* Newton from the initial state stayed on it, and it is a minimum up to
 * rigid motions: the initial state is the choice, found or not. */
static bool initial_is_minimum(const chooser *c, const qd_equilibrium_choice *ch) {
    if (!c->init || !ch->from_initial.count || !minimum_like(&ch->from_initial.pts[0]))
        return false;
    const double *q = ch->from_initial.pts[0].q;
    for (size_t j = 0; j < c->w.n; j++)
        if (!(fabs(gap(c, j, q[j], c->init[j])) <= SAME_TOL * (1 + fabs(c->init[j]))))
            return false;
    return true;
}

static void pick_initial(const chooser *c, qd_equilibrium_choice *ch) {
    const qd_equilibrium *p = reached(c, ch);
    ch->pt = p;
    ch->reason = QD_EQ_CHOSEN_INITIAL_STATE;
    ch->others = ch->found.count - (p >= ch->found.pts && p < ch->found.pts + ch->found.count);
}

qd_status qd_equilibria_choose(qd_ctx *ctx, const qd_eom *e, const qd_model *m, size_t nvals,
                               const qd_expr *const *syms, const double *vals,
                               qd_equilibrium_choice *out) {
    QD_ARGS_CTX(ctx, ctx && e && m && (nvals == 0 || syms) && (nvals == 0 || vals) && out);
    memset(out, 0, sizeof *out);
    chooser c = {.ctx = ctx, .m = m};
    size_t n = e->n;
    /* init, then the box qd_equilibria_default_box fills beside the angle flags */
    double *init = qd__calloc(ctx, 3 * n + 1, sizeof *init);
    c.angle = qd__calloc(ctx, n + 1, sizeof *c.angle);
    if (!init || !c.angle || !work_init(ctx, &c.w, e, nvals, syms, vals)) {
        qd__free(init);
        qd__free(c.angle);
        work_free(&c.w);
        return QD_ERR_NOMEM;
    }
    if (qd_equilibria_default_box(ctx, e, m, c.angle, init + n, init + 2 * n) != QD_OK)
        qd__ctx_recover(ctx); /* no angles known: plain distances */
    if (initial_state(ctx, e, m, &c.w, init)) {
        c.init = init;
        qd_equilibria_opts o = {.near = init};
        if (qd_equilibria_find(ctx, e, m, nvals, syms, vals, &o, &out->from_initial) != QD_OK)
            qd__ctx_recover(ctx); /* Newton failing from there only leaves the list */
    }
    /* the initial state an equilibrium: no search (a ring of 100 springs took
       72-109 s in the multistart, issue 34), only the exact set when there is one */
    bool at_init = initial_is_minimum(&c, out);
    qd_equilibria_opts o = {.no_search = at_init};
    qd_status st = qd_equilibria_find(ctx, e, m, nvals, syms, vals, &o, &out->found);
    if (st == QD_OK && at_init)
        pick_initial(&c, out);
    else if (st == QD_OK)
        pick(&c, out);
    qd__free(init);
    qd__free(c.angle);
    work_free(&c.w);
    return st;
}

void qd_equilibrium_choice_free(qd_equilibrium_choice *c) {
    if (!c)
        return;
    qd_equilibria_free(&c->found);
    qd_equilibria_free(&c->from_initial);
    c->pt = NULL;
}

/* ---- an exact point free of the parameters' values ------------------------- */

/* |F_j| at the point against the sum of the sizes of its terms. */
static bool vanishes(qd_ctx *ctx, const qd_expr *f, size_t nvals, const qd_expr *const *syms,
                     const double *vals) {
    double v = 0, size = 0, t;
    if (!f || qd_eval(ctx, f, nvals, syms, vals, &v) != QD_OK)
        return false;
    size_t nt = qd_expr_kind(f) == QD_ADD ? qd_expr_nargs(f) : 1;
    for (size_t k = 0; k < nt; k++)
        if (qd_eval(ctx, nt > 1 ? qd_expr_arg(f, k) : f, nvals, syms, vals, &t) == QD_OK)
            size += fabs(t);
    return fabs(v) <= ZERO_TOL * size;
}

/* theta = 0 stays an equilibrium of the bead on a spinning hoop when g and
 * omega change; acos(g/(a w^2)) taken at g = 9.81 does not.  So: move
 * every parameter off its value and see whether F(q0) stays 0. */
bool qd_equilibrium_exact_in_parameters(qd_ctx *ctx, const qd_eom *e, const qd_model *m,
                                        size_t nvals, const qd_expr *const *syms,
                                        const double *vals, const qd_expr *const *q0) {
    QD_ARGS(false, ctx && e && m && (nvals == 0 || syms) && (nvals == 0 || vals) && q0);
    size_t n = e->n, np = qd_model_nparams(m);
    const qd_expr **from = qd__calloc(ctx, 2 * n + 1, sizeof *from), **to = qd__calloc(ctx, 2 * n + 1, sizeof *to);
    double *moved = qd__calloc(ctx, nvals + 1, sizeof *moved);
    bool ok = from && to && moved && q0;
    for (size_t j = 0; ok && j < n; j++) {
        from[j] = e->q[j];
        to[j] = q0[j];
        from[n + j] = e->qd[j];
        to[n + j] = qd_int(ctx, 0);
        ok = q0[j] != NULL;
    }
    for (size_t i = 0; ok && i < nvals; i++) {
        moved[i] = vals[i];
        for (size_t p = 0; p < np; p++)
            if (syms[i] == qd_model_param(m, p))
                moved[i] = vals[i] * 1.37 + 0.11;
    }
    for (size_t j = 0; ok && j < n; j++)
        ok = vanishes(ctx, qd_expand(ctx, qd_subs(ctx, e->f[j], 2 * n, from, to)), nvals, syms,
                      moved);
    qd__ctx_recover(ctx);
    qd__free(from);
    qd__free(to);
    qd__free(moved);
    return ok;
}

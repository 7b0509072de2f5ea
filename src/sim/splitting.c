/*
 * src/sim/splitting.c - Stormer-Verlet and Yoshida's symmetric compositions
 * of it, for H = T(p) + V(q) with T = p^T M^-1 p / 2, M constant (Hairer,
 * Lubich & Wanner, GNI sec. I.3 and V.3; H. Yoshida, Phys. Lett. A 150
 * (1990) 262, table 1 for the weights).
 *
 * One Verlet step of size h: p += h/2 F(q); q += h M^-1 p; p += h/2 F(q),
 * F = dL/dq + Q = -dV/dq.  The composition S(w_m h) ... S(w_1 h) S(w_0 h)
 * S(w_1 h) ... S(w_m h) with sum 1 raises the order to 4, 6, 8; the last
 * half kick of one substep and the first of the next use the same F.
 */
#include "simint.h"
#include "../base/mem.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

typedef struct split {
    const double *w;  /* 2m+1 weights in the order applied */
    size_t nw;
    double *F, *v, *qd; /* force at the current q (valid flag), velocity, scratch */
    double wbuf[15];    /* the symmetric sequences of Y6, Y8: per run, as runs may
                           share nothing mutable (docs/design.md, thread safety) */
    bool F_valid;
} split;

static const double W2[1] = {1};
#define CBRT2 1.2599210498948731648
static const double W4[3] = {1 / (2 - CBRT2), -CBRT2 / (2 - CBRT2), 1 / (2 - CBRT2)};
/* Yoshida's solution A (order 6) and D (order 8), w_1..w_m; w_0 = 1 - 2 sum */
static const double Y6[3] = {-1.17767998417887, 0.235573213359357, 0.784513610477560};
static const double Y8[7] = {0.102799849391985, -1.96061023297549, 1.93813913762276,
                             -0.158240635368243, -1.44485223686048, 0.253693336566229,
                             0.914844246229740};

/* m weights w_1..w_m into the symmetric sequence w_m .. w_1 w_0 w_1 .. w_m */
static void symmetric(const double *y, size_t m, double *out) {
    double sum = 0;
    for (size_t i = 0; i < m; i++)
        sum += y[i];
    for (size_t i = 0; i < m; i++) {
        out[i] = y[m - 1 - i];
        out[2 * m - i] = y[m - 1 - i];
    }
    out[m] = 1 - 2 * sum;
}

static qd_status init_w(qd__sim_integ *it, const double *w, size_t nw) {
    qd_sim *s = it->s;
    if (!s->separable) {
        qd_ctx_error(s->ctx, QD_ERR_ARG,
                     "%s needs a separable Hamiltonian H = T(p) + V(q) (constant mass "
                     "matrix, no velocity- or time-dependent forces); this H is not "
                     "separable: use gl2, gl4 or gl6", qd_sim_method_name(it->method));
        return QD_ERR_ARG;
    }
    size_t n = s->n;
    split *sp = qd__calloc(s->ctx, 1, sizeof *sp);
    double *mem = qd__malloc(s->ctx, (3 * n + 1) * sizeof *mem);
    if (!sp || !mem) {
        qd__free(sp);
        qd__free(mem);
        return QD_ERR_NOMEM;
    }
    sp->w = w;
    sp->nw = nw;
    sp->F = mem;
    sp->v = mem + n;
    sp->qd = mem + 2 * n;
    it->priv = sp;
    return QD_OK;
}

static void split_free(qd__sim_integ *it) {
    split *sp = it->priv;
    if (sp)
        qd__free(sp->F);
    qd__free(sp);
    it->priv = NULL;
}

static void force(qd__sim_integ *it, split *sp, const double *q) {
    /* F depends on q only: the velocity slots are ignored */
    memset(sp->qd, 0, it->s->n * sizeof *sp->qd);
    qd__sim_force(it->s, it->t, q, sp->qd, sp->F);
    it->s->evals++;
    sp->F_valid = true;
}

/* The composition from (q, p) in y, in place. */
static qd_status compose(qd__sim_integ *it, split *sp, double *y, double h) {
    size_t n = it->s->n;
    double *q = y, *p = y + n;
    for (size_t k = 0; k < sp->nw; k++) {
        double hk = sp->w[k] * h;
        if (!sp->F_valid)
            force(it, sp, q);
        for (size_t j = 0; j < n; j++)
            p[j] += 0.5 * hk * sp->F[j];
        qd_status st = qd__sim_drift_velocity(it->s, p, sp->v);
        if (st != QD_OK)
            return st;
        for (size_t j = 0; j < n; j++)
            q[j] += hk * sp->v[j];
        force(it, sp, q);
        for (size_t j = 0; j < n; j++)
            p[j] += 0.5 * hk * sp->F[j];
    }
    return QD_OK;
}

static qd_status split_step(qd__sim_integ *it) {
    split *sp = it->priv;
    if (it->y_changed)
        sp->F_valid = false;
    it->y_changed = false;
    it->told = it->t;
    memcpy(it->yold, it->y, it->dim * sizeof *it->y);
    qd_status st = compose(it, sp, it->y, it->h);
    it->t = it->told + it->h;
    return st;
}

static qd_status split_redo(qd__sim_integ *it, double h, double *y) {
    split *sp = it->priv;
    memcpy(y, it->yold, it->dim * sizeof *y);
    sp->F_valid = false;
    qd_status st = compose(it, sp, y, h);
    sp->F_valid = false;
    return st;
}

static qd_status init2(qd__sim_integ *it) { return init_w(it, W2, 1); }
static qd_status init4(qd__sim_integ *it) { return init_w(it, W4, 3); }
/* The weights w_m .. w_0 .. w_m from Yoshida's m into the run's own buffer. */
static qd_status init_yoshida(qd__sim_integ *it, const double *y, size_t m) {
    qd_status st = init_w(it, NULL, 2 * m + 1);
    if (st == QD_OK) {
        split *sp = it->priv;
        symmetric(y, m, sp->wbuf);
        sp->w = sp->wbuf;
    }
    return st;
}
static qd_status init6(qd__sim_integ *it) { return init_yoshida(it, Y6, 3); }
static qd_status init8(qd__sim_integ *it) { return init_yoshida(it, Y8, 7); }

const qd__sim_method qd__sim_verlet = {init2, split_step, NULL, split_redo, split_free};
const qd__sim_method qd__sim_yoshida4 = {init4, split_step, NULL, split_redo, split_free};
const qd__sim_method qd__sim_yoshida6 = {init6, split_step, NULL, split_redo, split_free};
const qd__sim_method qd__sim_yoshida8 = {init8, split_step, NULL, split_redo, split_free};

/*
 * src/hj/hj.c - the Hamilton-Jacobi equation of a model, its separation and
 * the complete integral W (qdot/hj.h; Desloge ch. 78-79, Goldstein ch. 10).
 *
 * H comes from the model (given, or the Legendre transform of L).  The
 * equation is written with S(q, t) a user function: H(q, dS/dq, t) + dS/dt.
 * When H has no t, S = W - E t and H(q, dW/dq) = E is separated by peeling
 * one coordinate at a time (separate.c); W = sum_k int sqrt(p2_k) dq_k
 * (quadrature.c), cyclic coordinates giving alpha_k q_k.  The constants'
 * first integrals are in q and p for a model given by H, in q and q' for a
 * Lagrangian one (p = dL/dq').
 */
#include "hj_priv.h"

#include <stdio.h>
#include <string.h>
#include "base/mem.h"
#include "qdot/hamilton.h"
#include "qdot/mech.h"
#include "../base/args.h"

/* The working copy of what qd_ham gives: coordinates, momenta, p(q, q'). */
typedef struct hj_in {
    const qd_expr **q, **p, **pdef;
    bool H_given;
} hj_in;

void qd_hj_free(qd_hj *h) {
    if (!h)
        return;
    qd__free(h->sep);
    qd__free(h->constants);
    qd__free(h);
}

static qd_hj *hj_alloc(qd_ctx *ctx, size_t n, hj_in *in) {
    qd_hj *h = qd__calloc(ctx, 1, sizeof *h);
    if (!h)
        return NULL;
    h->n = n;
    h->sep = qd__calloc(ctx, n ? n : 1, sizeof *h->sep);
    h->constants = qd__calloc(ctx, n ? n : 1, sizeof *h->constants);
    in->q = qd__calloc(ctx, 3 * (n ? n : 1), sizeof *in->q);
    if (!h->sep || !h->constants || !in->q) {
        qd__free(in->q);
        qd_hj_free(h);
        return NULL;
    }
    in->p = in->q + n;
    in->pdef = in->p + n;
    return h;
}

/* H in q, p (and t) from the model; qd_ham's arrays copied into in. */
static const qd_expr *hamiltonian(qd_ctx *ctx, const qd_model *m, hj_in *in) {
    in->H_given = qd_model_hamiltonian_given(m);
    qd_eom *e = in->H_given ? NULL : qd_eom_derive(ctx, m);
    if (!in->H_given && !e)
        return NULL;
    qd_ham *ham = qd_ham_derive(ctx, m, e);
    const qd_expr *H = ham && qd_ham_require_closed(ctx, ham, "the Hamilton-Jacobi equation") == QD_OK
                       ? ham->H : NULL;
    for (size_t k = 0; ham && k < ham->n; k++) {
        in->q[k] = ham->q[k];
        in->p[k] = ham->p[k];
        in->pdef[k] = ham->pdef[k];
    }
    qd_ham_free(ham);
    qd_eom_free(e);
    return H;
}

/* H(q, dS/dq, t) + dS/dt with S(q_1, ..., q_n, t) a user function. */
static const qd_expr *hj_equation(qd_ctx *ctx, const qd_hj *h, const hj_in *in) {
    size_t n = h->n;
    const qd_expr **args = qd__calloc(ctx, 2 * n + 1, sizeof *args);
    if (!args)
        return NULL;
    const qd_expr **dS = args + n + 1;
    memcpy(args, in->q, n * sizeof *args);
    args[n] = qd_time(ctx);
    for (unsigned k = 0; k <= n; k++) {
        const qd_expr *d = qd_uderiv(ctx, "S", 1, &k, n + 1, args);
        if (k < n)
            dS[k] = d;
        else
            args[n] = d; /* dS/dt: args[n] is not read again */
    }
    const qd_expr *dSdt = args[n];
    const qd_expr *eq = qd_add(ctx, qd_subs(ctx, h->H, n, in->p, dS), dSdt);
    qd__free(args);
    return eq;
}

/* The energy constant: opts' name or E, with underscores while the name is
 * taken by a coordinate or parameter. */
static const qd_expr *energy_symbol(qd_ctx *ctx, const qd_hj_opts *opts) {
    char name[64];
    snprintf(name, sizeof name, "%s", opts && opts->energy_name ? opts->energy_name : "E");
    while (qd_lookup(ctx, name) && qd_symbol_role(qd_lookup(ctx, name)) != QD_ROLE_PLAIN &&
           strlen(name) + 2 < sizeof name)
        strcat(name, "_");
    return qd_symbol(ctx, name);
}

/* W_k = int pk dq_k, or -int qk dp_k in the momentum representation:
 * closed where qd_integrate finds it, else integral(...). */
static const qd_expr *linear_quadrature(qd_ctx *ctx, const qd_hj_sep *s) {
    const qd_expr *f = s->pk ? s->pk : qd_neg(ctx, s->qk), *x = s->pk ? s->q : s->p;
    const qd_expr *r = qd_integrate(ctx, qd_expand(ctx, f), x);
    if (!r) {
        qd__ctx_recover(ctx);
        r = qd__hj_integral(ctx, f, x);
    }
    return r;
}

/* W = sum_k W_k; a cyclic coordinate (not the last) gives alpha_k q_k. */
static const qd_expr *complete_integral(qd_ctx *ctx, const qd_hj *h) {
    const qd_expr *W = qd_int(ctx, 0);
    for (size_t k = 0; W && k < h->n; k++) {
        const qd_hj_sep *s = &h->sep[k];
        if (s->cyclic && s->constant != h->energy)
            W = qd_add(ctx, W, qd_mul(ctx, s->constant, s->q));
        else if (s->pk || s->qk)
            W = qd_add(ctx, W, linear_quadrature(ctx, s));
        else
            W = qd_add(ctx, W, qd__hj_quadrature(ctx, s->p2, s->q));
    }
    return W;
}

/* The first integrals in q and q' for a Lagrangian model. */
static void integrals_in_velocities(qd_ctx *ctx, qd_hj *h, const hj_in *in) {
    if (in->H_given)
        return;
    for (size_t k = 0; k < h->n; k++)
        if (h->sep[k].integral)
            h->sep[k].integral =
                qd_simplify(ctx, qd_subs(ctx, h->sep[k].integral, h->n, in->p, in->pdef));
}

static qd_status separate(qd_ctx *ctx, qd_hj *h, const hj_in *in) {
    qd__hj_sep_state s = {.ctx = ctx, .h = h, .q = in->q, .p = in->p, .nleft = h->n};
    s.left = qd__calloc(ctx, h->n ? h->n : 1, sizeof *s.left);
    s.value = qd__calloc(ctx, h->n ? h->n : 1, sizeof *s.value);
    if (!s.left || !s.value) {
        qd__free(s.left);
        qd__free(s.value);
        return QD_ERR_NOMEM;
    }
    for (size_t k = 0; k < h->n; k++)
        s.left[k] = true;
    s.value[h->n - 1] = h->H;
    s.F = qd_expand(ctx, qd_sub(ctx, h->H, h->energy));
    qd_status st = s.F ? qd__hj_separate(&s) : QD_ERR_NOMEM;
    qd__free(s.left);
    qd__free(s.value);
    return st;
}

static qd_status fill(qd_ctx *ctx, const qd_model *m, const qd_hj_opts *opts, qd_hj *h, hj_in *in) {
    if (!(h->H = hamiltonian(ctx, m, in)))
        return qd_ctx_status(ctx) != QD_OK ? qd_ctx_status(ctx) : QD_ERR_ARG;
    if (!(h->equation = hj_equation(ctx, h, in)) || !(h->energy = energy_symbol(ctx, opts)))
        return QD_ERR_NOMEM;
    h->time_independent = !qd_has(h->H, qd_time(ctx));
    if (!h->time_independent) {
        snprintf(h->why, sizeof h->why, "H depends on t explicitly: only the time-independent "
                 "equation H(q, dW/dq) = E, or every coordinate cyclic, is separated here");
        qd_status st = qd__hj_time_part(ctx, h, in->q, in->p);
        if (st == QD_OK && h->separable)
            integrals_in_velocities(ctx, h, in);
        return st;
    }
    qd_status st = separate(ctx, h, in);
    if (st != QD_OK || !h->separable) {
        h->nconst = 0;
        return st;
    }
    if (!(h->W = complete_integral(ctx, h)))
        return QD_ERR_NOMEM;
    integrals_in_velocities(ctx, h, in);
    if (h->n == 1)
        snprintf(h->why, sizeof h->why, "one coordinate: H = E is its equation%s",
                 h->sep[0].pk ? ", linear in the momentum" : h->sep[0].qk ?
                 ", solved for the coordinate (the momentum representation)" : "");
    else
        snprintf(h->why, sizeof h->why, "%s: H = E splits into one equation per coordinate",
                 h->form);
    return qd_ctx_status(ctx);
}

/* Generalized forces or dissipation make the motion non-Hamiltonian: the
 * HJ equation of H alone would describe another system. */
static bool conservative(qd_ctx *ctx, const qd_model *m) {
    const qd_expr *D = qd_model_dissipation(m);
    if (D && !qd_is_zero(D)) {
        qd_ctx_error(ctx, QD_ERR_ARG, "the Hamilton-Jacobi equation needs a Hamiltonian "
                     "system: the model has a dissipation function");
        qd_ctx_error_about(ctx, QD_SUBJECT_STATEMENT, 0, "dissipation", QD_REASON_NONE, NULL);
        return false;
    }
    for (size_t i = 0; i < qd_model_ncoords(m); i++)
        if (!qd_is_zero(qd_model_force(m, i))) {
            qd_ctx_error(ctx, QD_ERR_ARG, "the Hamilton-Jacobi equation needs a Hamiltonian "
                         "system: the model has a generalized force on %s",
                         qd_expr_name(qd_model_coord(m, i)));
            qd_ctx_error_about(ctx, QD_SUBJECT_COORD, i, NULL, QD_REASON_NONE,
                               "write the force as a potential, or drop it");
            return false;
        }
    return true;
}

qd_hj *qd_hj_derive(qd_ctx *ctx, const qd_model *m, const qd_hj_opts *opts) {
    QD_ARGS(NULL, ctx && m);
    if (!ctx || !m || !conservative(ctx, m))
        return NULL;
    if (qd_model_nconstraints(m)) {
        qd_ctx_error(ctx, QD_ERR_ARG, "the Hamilton-Jacobi equation needs independent "
                     "coordinates: the model has %zu constraint%s", qd_model_nconstraints(m),
                     qd_model_nconstraints(m) == 1 ? "" : "s");
        qd_ctx_error_about(ctx, QD_SUBJECT_CONSTRAINT, 0, qd_model_constraint_name(m, 0),
                           QD_REASON_NONE, "eliminate the constrained coordinates");
        return NULL;
    }
    size_t n = qd_model_ncoords(m);
    hj_in in = {0};
    qd_hj *h = hj_alloc(ctx, n, &in);
    if (!h) {
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory forming the Hamilton-Jacobi equation");
        return NULL;
    }
    qd_status st = n ? fill(ctx, m, opts, h, &in) : QD_ERR_ARG;
    qd__free(in.q);
    if (st != QD_OK) {
        if (qd_ctx_status(ctx) == QD_OK)
            qd_ctx_error(ctx, st, "forming the Hamilton-Jacobi equation failed");
        qd_hj_free(h);
        return NULL;
    }
    return h;
}

/*
 * src/mech/eliminate.c - holonomic constraints solved for one coordinate
 * and substituted before Lagrange's equations are formed (--eliminate).
 *
 * Desloge ch. 50: the reduced equations come from T, V, ... of the
 * constrained motion, so the substitution q_j = g(q, t) (with q'_j = g' and
 * q''_j = g'') is made in T, V, U, L and D before differentiating, never
 * after (seed pitfall 3).  Generalized forces transform as virtual work at
 * frozen time: Q_i += Q_j dg/dq_i.  Only a constraint that is linear in a
 * coordinate with a coefficient free of coordinates and t is solved (x1 +
 * x2 = l, r = a): dividing by anything else could divide by zero somewhere.
 * Velocity (Pfaffian) constraints are never substituted, not even the
 * integrable ones: putting a velocity relation into L gives wrong equations
 * (pitfall 4); they keep their multipliers.
 */
#include "mech.h"

#include "qdot/print.h"
#include "../base/mem.h"

#include <stdlib.h>

static bool has_velocity(const qd_expr *x, const qd__sys *s, qd_ctx *ctx) {
    for (size_t j = 0; j < s->n; j++)
        if (qd_has(x, qd_jet(ctx, s->q[j], 1)) || qd_has(x, qd_jet(ctx, s->q[j], 2)))
            return true;
    return false;
}

/* Only parameters and numbers in c, and c not zero. */
static bool safe_divisor(qd_ctx *ctx, const qd_expr *c) {
    const qd_expr *syms[32];
    size_t ns = qd_free_symbols(ctx, c, syms, 32);
    if (!c || qd_is_zero(c) || ns > 32)
        return false;
    for (size_t i = 0; i < ns; i++)
        if (qd_symbol_role(syms[i]) != QD_ROLE_PARAM)
            return false;
    return true;
}

/* The coordinate constraint k can be solved for (the last declared that
 * qualifies) and its value; false when there is none. */
static bool solvable(qd_ctx *ctx, const qd__sys *s, size_t k, size_t *which,
                     const qd_expr **value) {
    const qd_expr *phi = s->con_expr[k];
    if (has_velocity(phi, s, ctx))
        return false;
    for (size_t j = s->n; j-- > 0;) {
        const qd_expr *c = NULL, *rest = NULL;
        if (!qd_has(phi, s->q[j]) ||
            qd_linear_coeffs(ctx, phi, 1, &s->q[j], &c, &rest) != QD_OK) {
            qd__ctx_recover(ctx);
            continue;
        }
        c = qd_simplify(ctx, c);
        if (!safe_divisor(ctx, c))
            continue;
        *which = j;
        *value = qd_simplify(ctx, qd_neg(ctx, qd_div(ctx, rest, c)));
        return *value != NULL;
    }
    return false;
}

typedef struct subst {
    const qd_expr *from[3], *to[3];
} subst;

static const qd_expr *apply(qd_ctx *ctx, const subst *u, const qd_expr *x) {
    return x ? qd_subs(ctx, x, 3, u->from, u->to) : NULL;
}

/* Q_i + Q_j dg/dq_i for the remaining coordinates; coordinate j dropped. */
static void reduce_forces(qd_ctx *ctx, qd__sys *s, size_t j, const qd_expr *g, const subst *u) {
    const qd_expr *Qj = apply(ctx, u, s->Q[j]);
    for (size_t i = 0, o = 0; i < s->n; i++) {
        if (i == j)
            continue;
        const qd_expr *Qi = qd_add(ctx, apply(ctx, u, s->Q[i]),
                                   qd_mul(ctx, Qj, qd_diff(ctx, g, s->q[i])));
        s->q[o] = s->q[i];
        s->Q[o++] = qd_simplify(ctx, Qi);
    }
    s->n--;
}

/* Substitute into the other constraints; drop constraint k.  One that
 * then holds identically is redundant (left out, named in s->reduced); one
 * that never holds is inconsistent. */
static qd_status reduce_constraints(qd_ctx *ctx, qd__sys *s, size_t k, const qd_expr *q,
                                    const subst *u) {
    size_t o = 0;
    for (size_t i = 0; i < s->ncon; i++) {
        if (i == k)
            continue;
        const qd_expr *c = qd_simplify(ctx, apply(ctx, u, s->con_expr[i]));
        if (!c)
            return qd_ctx_status(ctx);
        if (qd_is_zero(c)) { /* redundant: left out, named like a rank reduction */
            s->reduced[s->nreduced++] = s->con_name[i];
            continue;
        }
        if (qd_is_number(c)) {
            qd_ctx_error(ctx, QD_ERR_SINGULAR,
                         "constraints %s and %s are %s: %s %s once %s is used to eliminate %s",
                         s->con_name[k], s->con_name[i],
                         qd_is_zero(c) ? "redundant" : "inconsistent", s->con_name[i],
                         qd_is_zero(c) ? "holds identically" : "can never hold",
                         s->con_name[k], qd_expr_name(q));
            return QD_ERR_SINGULAR;
        }
        s->con_name[o] = s->con_name[i];
        s->con_expr[o++] = c;
    }
    s->ncon = o;
    return QD_OK;
}

static qd_status eliminate_one(qd_ctx *ctx, qd__sys *s, size_t k, size_t j, const qd_expr *g,
                               qd_elim *rec, size_t nrec) {
    const qd_expr *q = s->q[j], *gd = qd_dt(ctx, g);
    subst u = {{q, qd_jet(ctx, q, 1), qd_jet(ctx, q, 2)}, {g, gd, qd_dt(ctx, gd)}};
    if (!u.to[2] || !u.from[2])
        return qd_ctx_status(ctx);
    for (size_t i = 0; i < nrec; i++)
        rec[i].value = qd_simplify(ctx, apply(ctx, &u, rec[i].value));
    rec[nrec] = (qd_elim){s->con_name[k], q, g};
    s->T = apply(ctx, &u, s->T);
    s->V = apply(ctx, &u, s->V);
    s->U = apply(ctx, &u, s->U);
    s->L = apply(ctx, &u, s->L);
    s->D = apply(ctx, &u, s->D);
    reduce_forces(ctx, s, j, g, &u);
    if (qd_ctx_status(ctx) != QD_OK)
        return qd_ctx_status(ctx);
    return reduce_constraints(ctx, s, k, q, &u);
}

qd_status qd__mech_eliminate(qd_ctx *ctx, qd__sys *s, qd_elim **elim, size_t *nelim) {
    qd_elim *rec = qd__malloc(ctx, (s->ncon + 1) * sizeof *rec);
    size_t nrec = 0, k = 0;
    if (!s->reduced)
        s->reduced = qd__malloc(ctx, (s->ncon + 1) * sizeof *s->reduced);
    qd_status st = rec && s->reduced ? QD_OK : QD_ERR_NOMEM;
    while (st == QD_OK && k < s->ncon) {
        size_t j;
        const qd_expr *g;
        if (s->n > 1 && solvable(ctx, s, k, &j, &g))
            st = eliminate_one(ctx, s, k, j, g, rec, nrec++);
        else if (qd__ctx_nomem(ctx)) /* "not solvable" may only mean out of memory */
            st = QD_ERR_NOMEM;
        else
            k++;
    }
    if (st != QD_OK) {
        qd__free(rec);
        if (st == QD_ERR_NOMEM && qd_ctx_status(ctx) == QD_OK)
            qd_ctx_error(ctx, st, "out of memory eliminating coordinates");
        return st;
    }
    *elim = rec;
    *nelim = nrec;
    return QD_OK;
}

/*
 * src/mech/noether.c - Noether's integral of a field q_j -> q_j + eps xi_j
 * (Desloge vol. 2, ch. 56, Noether's theorem with tau = t), and the search
 * for translations and rotations by coordinate names (qdot/integrals.h).
 *
 * Quasi-symmetries.  When dL/deps does not vanish it may still be dF/dt for
 * some F(q, t): then it is affine in the velocities, sum_j c_j q'_j + c_0,
 * with c_j = dF/dq_j and c_0 = dF/dt.  F is built one variable at a time,
 * F += integral of (c_x - dF/dx) dx over x = q_1 .. q_n, t (qd_integrate),
 * and accepted only when dF/dt - dL/deps then vanishes identically; the
 * charge is sum_j p_j xi_j - F (Desloge's C; reference pitfall 9: the F term
 * must be subtracted).  The integration is not complete: an F it cannot find
 * leaves the field reported as not a symmetry, with dL/deps shown.
 */
#include "integrals_priv.h"
#include "../base/mem.h"
#include "../base/args.h"

#include <ctype.h>
#include <stdlib.h>
#include <string.h>

void qd_noether_clear(qd_noether *nt) {
    if (!nt)
        return;
    qd__free(nt->xi);
    nt->xi = NULL;
}

static bool has_velocity(const qd__intsys *s, const qd_expr *x) {
    for (size_t j = 0; j < s->n; j++)
        if (qd_has(x, s->e->qd[j]) || qd_has(x, s->e->qdd[j]))
            return true;
    return false;
}

/* F(q, t) with dF/dt = dL (affine in the velocities), or NULL. */
static const qd_expr *gauge(qd_ctx *ctx, const qd__intsys *s, const qd_expr *dL) {
    size_t n = s->n;
    const qd_expr **c = qd__calloc(ctx, n + 1, sizeof *c), *c0 = NULL, *F = qd_int(ctx, 0);
    if (!c)
        return NULL;
    if (qd_linear_coeffs(ctx, dL, n, s->e->qd, c, &c0) != QD_OK) {
        qd__ctx_recover(ctx);
        qd__free(c);
        return NULL;
    }
    c[n] = c0;
    for (size_t j = 0; F && j <= n; j++) {
        const qd_expr *x = j < n ? s->e->q[j] : qd_time(ctx);
        if (has_velocity(s, c[j])) {
            F = NULL;
            break;
        }
        const qd_expr *r = qd_simplify(ctx, qd_sub(ctx, c[j], qd_diff(ctx, F, x)));
        if (!r || qd_is_zero(r))
            continue;
        const qd_expr *g = qd_integrate(ctx, r, x);
        if (!g) {
            qd__ctx_recover(ctx);
            F = NULL;
            break;
        }
        F = qd_add(ctx, F, g);
    }
    qd__free(c);
    if (!F)
        return NULL;
    F = qd_simplify(ctx, F);
    bool z, num;
    if (!F ||
        qd__mech_int_identically_zero(ctx, s, qd_sub(ctx, qd_dt(ctx, F), dL), &z, &num) != QD_OK ||
        !z)
        return NULL;
    return F;
}

static qd_status field(qd_ctx *ctx, const qd__intsys *s, const qd_expr *const *xi,
                       qd_noether *out) {
    out->xi = qd__calloc(ctx, s->n ? s->n : 1, sizeof *out->xi);
    if (!out->xi)
        return QD_ERR_NOMEM;
    for (size_t j = 0; j < s->n; j++) {
        const qd_expr *x = xi && xi[j] ? xi[j] : qd_int(ctx, 0);
        out->xi[j] = qd_simplify(ctx, x);
        if (!out->xi[j])
            return qd_ctx_status(ctx);
        if (has_velocity(s, out->xi[j])) {
            qd_ctx_error(ctx, QD_ERR_ARG, "the field of symmetry %s depends on velocities: only "
                                          "point transformations q -> q + eps xi(q, t) are taken",
                         out->name ? out->name : "");
            return QD_ERR_ARG;
        }
    }
    return QD_OK;
}

qd_status qd_integrals_noether(qd_ctx *ctx, qd_integrals *I, const char *name,
                               const qd_expr *const *xi, qd_noether *out) {
    QD_ARGS_CTX(ctx, ctx && I && name && xi && out);
    if (!ctx || !I || !out)
        return QD_ERR_ARG;
    qd__intsys *s = I->priv;
    *out = (qd_noether){.name = name};
    if (s->e->ncon) {
        qd_ctx_error(ctx, QD_ERR_ARG, "Noether's integral with constraints is not supported: "
                                      "write the model in independent coordinates");
        return QD_ERR_ARG;
    }
    qd_status st = field(ctx, s, xi, out);
    if (st != QD_OK)
        return st;
    const qd_expr *dL = qd_int(ctx, 0), *Ix = qd_int(ctx, 0), *work = qd_int(ctx, 0);
    for (size_t j = 0; j < s->n; j++) {
        const qd_expr *x = out->xi[j];
        dL = qd_add(ctx, dL, qd_mul(ctx, qd_diff(ctx, s->L, s->e->q[j]), x));
        dL = qd_add(ctx, dL, qd_mul(ctx, s->p[j], qd_dt(ctx, x)));
        Ix = qd_add(ctx, Ix, qd_mul(ctx, s->p[j], x));
        const qd_expr *f = s->Q[j];
        if (s->D)
            f = qd_sub(ctx, f, qd_diff(ctx, s->D, s->e->qd[j]));
        work = qd_add(ctx, work, qd_mul(ctx, x, f));
    }
    out->dL = qd_simplify(ctx, dL);
    out->work = qd_simplify(ctx, work);
    if (!out->dL || !out->work)
        return qd_ctx_status(ctx);
    bool num = false;
    st = qd__mech_int_identically_zero(ctx, s, out->dL, &out->invariant, &num);
    if (st != QD_OK)
        return st;
    out->numeric = num;
    if (!out->invariant && (out->F = gauge(ctx, s, out->dL)))
        out->invariant = true;
    if (qd_ctx_status(ctx) != QD_OK)
        return qd_ctx_status(ctx);
    out->integral = qd_simplify(ctx, out->F ? qd_sub(ctx, Ix, out->F) : Ix);
    if (!out->integral)
        return qd_ctx_status(ctx);
    st = qd__mech_int_zero(ctx, s, qd_dt(ctx, out->integral), &out->remainder, &out->conserved,
                           &num, &out->cert);
    out->numeric = out->numeric || num;
    return st;
}

/* ---- the search by names ------------------------------------------------- */

/* 'x', 'y' or 'z' when the name is that letter and a suffix of digits and
 * underscores; 0 otherwise. */
static char axis_of(const char *name) {
    if (!name || (name[0] != 'x' && name[0] != 'y' && name[0] != 'z'))
        return 0;
    for (const char *c = name + 1; *c; c++)
        if (!isdigit((unsigned char)*c) && *c != '_')
            return 0;
    return name[0];
}

/* The coordinate named letter + suffix, or -1. */
static long partner(const qd__intsys *s, char letter, const char *suffix) {
    for (size_t j = 0; j < s->n; j++) {
        const char *nm = qd_expr_name(s->e->q[j]);
        if (nm[0] == letter && !strcmp(nm + 1, suffix))
            return (long)j;
    }
    return -1;
}

static qd_status try_field(qd_ctx *ctx, qd_integrals *I, const char *name, const qd_expr **xi) {
    I->tested[I->ntested++] = name;
    qd_noether nt;
    qd_status st = qd_integrals_noether(ctx, I, name, xi, &nt);
    if (st == QD_OK && nt.invariant) {
        I->found[I->nfound++] = nt;
        return QD_OK;
    }
    qd_noether_clear(&nt);
    return st;
}

static qd_status translation(qd_ctx *ctx, qd_integrals *I, char axis, const char *name,
                             const qd_expr **xi) {
    qd__intsys *s = I->priv;
    bool any = false;
    for (size_t j = 0; j < s->n; j++) {
        any |= axis_of(qd_expr_name(s->e->q[j])) == axis;
        xi[j] = qd_int(ctx, axis_of(qd_expr_name(s->e->q[j])) == axis);
    }
    return any ? try_field(ctx, I, name, xi) : QD_OK;
}

/* Rotation in the plane (a, b): a_s -> -b_s, b_s -> a_s, every a- and
 * b-named coordinate paired. */
static qd_status rotation(qd_ctx *ctx, qd_integrals *I, char a, char b, const char *name,
                          const qd_expr **xi) {
    qd__intsys *s = I->priv;
    bool any = false;
    for (size_t j = 0; j < s->n; j++) {
        const char *nm = qd_expr_name(s->e->q[j]);
        char ax = axis_of(nm);
        xi[j] = qd_int(ctx, 0);
        if (ax != a && ax != b)
            continue;
        long k = partner(s, ax == a ? b : a, nm + 1);
        if (k < 0)
            return QD_OK;
        xi[j] = ax == a ? qd_neg(ctx, s->e->q[k]) : s->e->q[k];
        any = true;
    }
    return any ? try_field(ctx, I, name, xi) : QD_OK;
}

qd_status qd__mech_int_search(qd_ctx *ctx, qd_integrals *I) {
    qd__intsys *s = I->priv;
    const qd_expr **xi = qd__calloc(ctx, s->n ? s->n : 1, sizeof *xi);
    I->found = qd__calloc(ctx, 6, sizeof *I->found);
    I->tested = qd__calloc(ctx, 6, sizeof *I->tested);
    if (!xi || !I->found || !I->tested) {
        qd__free(xi);
        return QD_ERR_NOMEM;
    }
    qd_status st = translation(ctx, I, 'x', "linear momentum along x", xi);
    if (st == QD_OK)
        st = translation(ctx, I, 'y', "linear momentum along y", xi);
    if (st == QD_OK)
        st = translation(ctx, I, 'z', "linear momentum along z", xi);
    if (st == QD_OK)
        st = rotation(ctx, I, 'y', 'z', "angular momentum about x", xi);
    if (st == QD_OK)
        st = rotation(ctx, I, 'z', 'x', "angular momentum about y", xi);
    if (st == QD_OK)
        st = rotation(ctx, I, 'x', 'y', "angular momentum about z", xi);
    qd__free(xi);
    return st;
}

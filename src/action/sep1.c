/*
 * src/action/sep1.c - one degree of freedom, separated without qd_hj:
 * H(q, p) = a(q) p^2 + c(q) = E is its own separated equation, with
 * p^2 = (E - c(q)) / a(q), or p^2 isolated from H = E when H is even in p
 * (Desloge ch. 79: the energy is the one constant
 * of a conservative system with one coordinate).  Also which coordinates
 * are angles, for every separation.
 */
#include "act.h"

#include <stdio.h>

#include "base/mem.h"
#include "base/ptrmap.h"

/* ---- the separation ------------------------------------------------------------ */

/* H even in p but not a p^2 + c (the relativistic oscillator H =
 * sqrt(p^2 + 1) + x^2/2, Desloge D T25): H(q, p) = E solved for u = p^2 by
 * isolating it (p = sqrt(u), u > 0).  Isolation squares on principal
 * branches (sqrt(A) = B gives A = B^2, true only where B >= 0), so the
 * result is checked where the motion is: one_coord (action.c) refuses a
 * p^2(q) that does not give the state's p.  NULL, ctx clean, when H is not
 * even or u does not isolate. */
static const qd_expr *p_squared_even(qd_ctx *ctx, const qd_ham *h, const qd_expr *E) {
    const qd_expr *p = h->p[0], *H = h->H, *mp = qd_neg(ctx, p);
    const qd_expr *odd = qd_simplify(ctx, qd_sub(ctx, qd_subs(ctx, H, 1, &p, &mp), H));
    if (!odd || !qd_is_zero(odd))
        return NULL;
    char name[256];
    snprintf(name, sizeof name, "__%s_squared", qd_expr_name(p));
    const qd_expr *u = qd_symbol_positive(ctx, name, QD_ROLE_PLAIN), *su = qd_sqrt(ctx, u);
    const qd_expr *eq = qd_simplify(ctx, qd_sub(ctx, qd_subs(ctx, H, 1, &p, &su), E));
    const qd_expr *sol = NULL;
    if (!eq || qd_has(eq, p) || qd_isolate(ctx, eq, u, &sol) != QD_OK || qd_has(sol, u)) {
        qd_ctx_clear_error(ctx);
        return NULL;
    }
    return qd_simplify(ctx, sol);
}

/* p^2 = (E - c)/a from H = a p^2 + b p + c with b = 0. */
static const qd_expr *p_squared(qd_ctx *ctx, const qd_ham *h, const qd_expr *E) {
    const qd_expr *p = h->p[0], *H = h->H;
    const qd_expr *a = qd_simplify(ctx, qd_coeff(ctx, H, p, 2));
    const qd_expr *b = qd_simplify(ctx, qd_coeff(ctx, H, p, 1));
    const qd_expr *c = qd_simplify(ctx, qd_coeff(ctx, H, p, 0));
    if (!a || !b || !c)
        return NULL;
    const qd_expr *rest = qd_simplify(
        ctx, qd_sub(ctx, H, qd_add(ctx, qd_mul(ctx, a, qd_powi(ctx, p, 2)), c)));
    if (!rest)
        return NULL;
    /* c(q) holds p too when H is not polynomial in it */
    const qd_expr *even = qd_is_zero(rest) && !qd_has(c, p) ? NULL : p_squared_even(ctx, h, E);
    if (even)
        return even;
    if (!qd_is_zero(rest) || qd_is_zero(a)) {
        qd_ctx_error(ctx, QD_ERR_NONLINEAR, "H is not a(q) %s^2 + c(q)", qd_expr_name(p));
        /* the hint says which it is: a relativistic H has no linear term,
         * and "gyroscopic" would send its user looking for one */
        const char *why =
            !qd_is_zero(b) ? "a term linear in the momentum (a gyroscopic or moving frame) "
                             "makes the action depend on the sense of the motion"
            : qd_has(c, p) ? "the momentum enters H beyond its square, and H is not even in "
                             "it or p^2 does not isolate from H = E: `qdot simulate` gives "
                             "the period of such a motion"
                           : "H does not depend on the momentum's square";
        qd_ctx_error_about(ctx, QD_SUBJECT_COORD, 0, qd_expr_name(h->q[0]),
                           QD_REASON_NOT_QUADRATIC, why);
        return NULL;
    }
    return qd_simplify(ctx, qd_div(ctx, qd_sub(ctx, E, c), a));
}

qd_hj *qd__act_sep1(qd_ctx *ctx, const qd_ham *h, const char *energy_name) {
    if (h->n != 1) {
        qd_ctx_error(ctx, QD_ERR_ARG, "one degree of freedom is separated here, not %zu", h->n);
        return NULL;
    }
    qd_hj *s = qd__calloc(ctx, 1, sizeof *s);
    qd_hj_sep *sep = qd__calloc(ctx, 1, sizeof *sep);
    const qd_expr **cs = qd__calloc(ctx, 1, sizeof *cs);
    const qd_expr *E = qd_symbol(ctx, energy_name ? energy_name : "E");
    if (!s || !sep || !cs || !E)
        goto fail;
    *sep = (qd_hj_sep){.q = h->q[0], .p = h->p[0], .constant = E, .p2 = p_squared(ctx, h, E),
                       .integral = h->H};
    sep->equation = qd_sub(ctx, h->H, E);
    if (!sep->p2 || !sep->integral || !sep->equation)
        goto fail;
    cs[0] = E;
    /* H with t is separated all the same: qd_action_of_sep refuses it */
    *s = (qd_hj){.n = 1, .H = h->H, .time_independent = !qd_has(h->H, qd_time(ctx)),
                 .separable = true,
                 .form = "one degree of freedom", .sep = sep, .nconst = 1, .constants = cs,
                 .energy = E};
    return s;
fail:
    qd__free(cs);
    qd__free(sep);
    qd__free(s);
    return NULL;
}

void qd__act_sep1_free(qd_hj *h) {
    if (!h)
        return;
    qd__free(h->constants);
    qd__free(h->sep);
    qd__free(h);
}

/* ---- angles -------------------------------------------------------------------- */

typedef struct angle_walk {
    size_t n;
    const qd_expr *const *q;
    bool *angle;
    qd__ptrmap seen;
    bool nomem;
} angle_walk;

static void mark(angle_walk *w, const qd_expr *x) {
    if (!x || w->nomem || qd__ptrmap_has(&w->seen, x))
        return;
    if (!qd__ptrmap_put(&w->seen, x, (void *)x)) {
        w->nomem = true; /* an angle missed would read a rotation as unbounded */
        return;
    }
    if (qd_expr_kind(x) == QD_FUNC) {
        qd_func fn = qd_expr_func(x);
        if (fn == QD_SIN || fn == QD_COS || fn == QD_TAN) {
            for (size_t k = 0; k < w->n; k++)
                w->angle[k] = w->angle[k] || qd_has(qd_expr_arg(x, 0), w->q[k]);
            return;
        }
    }
    for (size_t i = 0; i < qd_expr_nargs(x); i++)
        mark(w, qd_expr_arg(x, i));
}

bool qd__act_angles(qd_ctx *ctx, const qd_model *m, size_t n, const qd_expr *const *q,
                    bool *angle) {
    angle_walk w = {n, q, angle, QD_PTRMAP_AL(qd__ctx_allocator(ctx)), false};
    for (size_t k = 0; k < n; k++)
        angle[k] = false;
    mark(&w, qd_model_kinetic(m));
    mark(&w, qd_model_potential(m));
    mark(&w, qd_model_lagrangian(m));
    mark(&w, qd_model_hamiltonian(m));
    for (size_t i = 0; i < qd_model_nparticles(m); i++)
        for (unsigned k = 0; k < 3; k++)
            mark(&w, qd_model_particle_position(m, i, k));
    for (size_t i = 0; i < qd_model_nbodies(m); i++)
        for (unsigned k = 0; k < 9; k++) {
            if (k < 3)
                mark(&w, qd_model_body_position(m, i, k));
            mark(&w, qd_model_body_rotation(m, i, k / 3, k % 3));
        }
    qd__ptrmap_free(&w.seen);
    if (w.nomem)
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory");
    return !w.nomem;
}

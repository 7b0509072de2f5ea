/*
 * qdot/hj.h - the Hamilton-Jacobi equation and its separation (Desloge
 * ch. 78-79; Goldstein ch. 10).
 *
 * For H(q, p, t) the Hamilton-Jacobi equation is
 *
 *     H(q, dS/dq, t) + dS/dt = 0,
 *
 * and when H has no t, S = W(q, alpha) - E t with Hamilton's characteristic
 * function W solving H(q, dW/dq) = E.  W is separable in the coordinates
 * when W = sum_k W_k(q_k; alpha): each coordinate then has an equation of
 * its own,
 *
 *     F_k(q_k, p_k = dW_k/dq_k; alpha) = 0,
 *
 * with one separation constant per coordinate (the energy E among them),
 * and W_k = int p_k(q_k; alpha) dq_k.  qd_hj_derive finds the separation by
 * exact tests on the kernel's expressions: cyclic coordinates (p_k =
 * alpha_k), additive separation (H = sum_k H_k(q_k, p_k)), and the
 * Liouville/Staeckel forms (the separations of polar, spherical, parabolic
 * and elliptic coordinates).  An equation of one coordinate always reduces
 * to a quadrature: when it is not of the form A p_k^2 + C = 0 it is solved
 * for p_k where p_k enters linearly (H = p + a q^2, Desloge ch. 78 P1), or,
 * in the momentum representation, for q_k where q_k does (H = p + sin p + q,
 * ch. 78 Thm 1a).
 */
#ifndef QDOT_HJ_H
#define QDOT_HJ_H

#include <stdbool.h>
#include <stddef.h>
#include "expr.h"
#include "model.h"
#include "print.h"

#ifdef __cplusplus
extern "C" {
#endif

/* One separated coordinate. */
typedef struct qd_hj_sep {
    const qd_expr *q;          /* the coordinate q_k */
    const qd_expr *p;          /* its momentum: p_<q>, or the model's name for it */
    const qd_expr *constant;   /* the separation constant this equation introduces
                                  (a plain symbol: alpha_<q>, or the energy E) */
    /* F_k = 0 in q_k, p_k (the symbol p_<q>, or the model's momentum name)
     * and the constants */
    const qd_expr *equation;
    /* p_k^2 as a function of q_k and the constants: the motion in q_k is
     * where it is >= 0, its simple roots are the turning points */
    const qd_expr *p2;
    /* one equation may not be quadratic in p_k (Desloge ch. 78 Thm 1a, P1):
     * pk: p_k itself when it enters F_k linearly (p2 is then pk^2, no
     * turning points), W_k = int pk dq_k; qk: the momentum representation
     * (x, y) = (p_k, -q_k), when p_k can be isolated neither way but q_k
     * enters linearly: q_k as a function of p_k, W_k = -int qk dp_k (W is
     * then a function of p_k), and p2 is NULL.  Both NULL otherwise. */
    const qd_expr *pk;
    const qd_expr *qk;
    bool cyclic;               /* q_k absent from what was left: p_k is a constant
                                  (alpha_k; for the last coordinate, a function of
                                  the constants) */
    /* the constant as a first integral: an expression in q and the model's
     * velocities (q') for a Lagrangian model, or q and p for a model given
     * by H; evaluating it at a state gives the constant's value there */
    const qd_expr *integral;
    /* filled by qd_hj_solve where the quadrature closes: q_k = motion, a
     * function of clock - beta_<q>, clock the time t or (an orbit) a cyclic
     * coordinate; NULL otherwise */
    const qd_expr *motion;
    const qd_expr *clock;
    const qd_expr *beta;       /* the phase constant beta_<q> in motion */
} qd_hj_sep;

typedef struct qd_hj {
    size_t n;
    const qd_expr *H;          /* the Hamiltonian, in q, p, t */
    const qd_expr *equation;   /* H(q, dS/dq, t) + dS/dt (= 0) */
    bool time_independent;     /* S = W - E t */
    bool separable;
    const char *form;          /* "cyclic", "additive", "Liouville", "Staeckel",
                                  a combination ("cyclic + Liouville"), or "one
                                  coordinate"; a static string; NULL when not
                                  separable */
    char why[256];             /* why (not) separable, for the reader */
    qd_hj_sep *sep;            /* n, in coordinate order, when separable */
    size_t nconst;
    const qd_expr **constants; /* the separation constants in the order the
                                  peeling found them, energy last */
    const qd_expr *energy;     /* the energy constant (E), or NULL */
    /* W = sum_k int p_k dq_k: closed forms where the kernel integrates,
     * integral(EXPR, VAR) otherwise; NULL when not separable */
    const qd_expr *W;
    /* an explicit t with every coordinate cyclic (form "cyclic, explicit t"):
     * S = W + time_part, time_part = f(t) = -int_0^t H(alpha, t') dt', and
     * qd_hj_solve's motion is q_k = beta_k - df/dalpha_k; NULL otherwise */
    const qd_expr *time_part;
    bool solved;               /* qd_hj_solve has filled motion, clock and beta */
} qd_hj;

typedef struct qd_hj_opts {
    const char *energy_name;   /* NULL: "E" */
} qd_hj_opts;

/* Derive the HJ equation of m (given by L or by H) and separate it.  A
 * system that does not separate is not an error: separable = false with
 * the obstruction in why.  NULL on failure (reason in ctx): constraints
 * (the equation needs independent coordinates), generalized forces or
 * dissipation (QD_ERR_ARG), a singular Legendre transform, out of memory.
 * The result is freed with qd_hj_free; its expressions belong to ctx. */
QD_API qd_hj *qd_hj_derive(qd_ctx *ctx, const qd_model *m, const qd_hj_opts *opts);
QD_API void qd_hj_free(qd_hj *h);

/* The motion from dW/dalpha = beta where the quadratures close (Desloge
 * ch. 78): for each coordinate q_k, dq_k/dt = dH/dp_k with p = sqrt(p2)
 * (cyclic momenta their constants); when that is a function of q_k alone,
 * t - beta_k = int dq_k / (dH/dp_k), and when it is not, the orbit against a
 * cyclic coordinate q_j, q_j - beta_k = int (dH/dp_j)/(dH/dp_k) dq_k.  The
 * integrals closed and inverted: a constant velocity, kappa/sqrt(a + b q),
 * kappa/sqrt(a + b q + c q^2) with c < 0 (the oscillators, the projectile),
 * kappa/(q^2 sqrt(a + b/q + c/q^2)) (Kepler's conic, u = 1/q) and
 * kappa/(sin(q)^2 sqrt(P(cot q))) (the plane of a central orbit).  Fills
 * sep[k].motion, clock and beta; the other coordinates keep NULL.  h must be
 * separable (QD_ERR_ARG otherwise). */
QD_API qd_status qd_hj_solve(qd_ctx *ctx, qd_hj *h);

/* h (derived from m; model_name names m in the heading, may be NULL)
 * written for a reader, appended to out.  QD_FMT_TEXT and QD_FMT_LATEX:
 * H, the equation, whether it separates and why, the separated equations
 * with p (or p^2, or q of p) and each constant as a first integral, W, and
 * the motion once solved (LaTeX with "% " before the prose lines).
 * QD_FMT_SYMPY: a Python script defining H, HJ, separable, W, p2 and
 * integrals (in coordinate order; None where a representation has none)
 * and, solved, motion = {coordinate: (clock, q)}; each name gets
 * underscores appended while the model uses it.  QD_ERR_ARG for another
 * format, QD_ERR_NOMEM when out could not grow. */
QD_API qd_status qd_hj_print(qd_ctx *ctx, const qd_hj *h, const qd_model *m,
                             const char *model_name, qd_format fmt, qd_buf *out);
/* The same as one JSON document and a newline: "model", "H", "equation",
 * "time_independent", "separable", "form", "why", "separation" (per
 * coordinate: "coordinate", "momentum", "constant", "equation", "p2", "p",
 * "q_of_p", "cyclic", "integral", and once solved "motion", "clock"), "W",
 * "constants", "energy_constant". */
QD_API qd_status qd_hj_json(qd_ctx *ctx, const qd_hj *h, const char *model_name, qd_buf *out);

#ifdef __cplusplus
}
#endif

/* NULL (issue 30): a function of this header given NULL for a pointer it
 * needs does nothing and returns QD_ERR_ARG (recorded in ctx when ctx is
 * given), NULL, 0, false or NaN, as its return type has it; a void function
 * returns, and every _free accepts NULL. NULL is an accepted value, as
 * documented at the function, for: qd_hj_derive (opts); qd_hj_print (model_name); qd_hj_json
 * (model_name). An array whose count
 * is 0 may be NULL. */
#endif

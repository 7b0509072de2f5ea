/*
 * qdot/routh.h - Routh's reduction: ignoring cyclic coordinates.
 *
 * Split the coordinates of an unconstrained model into ignored ones c
 * (cyclic: absent from L, no generalized force, no dissipation through c')
 * and kept ones k.  The momenta of the ignored coordinates are constant,
 * p_c = dL/dc' = beta (plain symbols named p_<c>), which is linear in c'
 * because L is quadratic in the velocities:
 *
 *     c' = A^-1 (beta - B k' - b_c)            (ignvel: the quadratures'
 *                                               integrands, c = int c' dt)
 *     R(k, k', beta, t) = sum_c beta_c c' - L   (c' substituted everywhere,
 *                                               the p c' term included)
 *
 * This is Goldstein's and Landau's sign, and Desloge's (ch. 72 thm 2, who
 * notes that the opposite sign is common).  Byerly's "modified Lagrangian"
 * M = T - sum p q' (Art. 17, V kept apart as forces) and the Britannica
 * article's R = T - sum kappa chi' are of the opposite sign, M - V = -R:
 * mixing the two flips the centrifugal and gyroscopic terms.

 * -R is a Lagrangian for the kept coordinates: the reduced equations are
 *
 *     d/dt d(-R)/dk'_j - d(-R)/dk_j = Q_j - dD/dk'_j,
 *
 * i.e. d/dt dR/dk' - dR/dk = -(Q - dD/dk'), written M k'' = f with
 * M = d^2(-R)/dk'dk' (positive definite for a positive T) and everything
 * else in f.  Putting p_c = beta into L and using L as the Lagrangian
 * instead is the classic error: it flips the sign of the centrifugal term
 * (and drops the gyroscopic one's factor).
 *
 * R splits by degree in the kept velocities, R = R2 + R1 + R0.  The
 * effective potential is the velocity-free part with R's sign,
 *
 *     V_eff = R0 = -(velocity-free part of -R),
 *
 * so that -R = -R2 - R1 - V_eff looks like T - V: for a particle in a
 * central potential (or a spherical pendulum) V_eff = V + p^2/(2 m r^2),
 * a positive centrifugal barrier.  Steady motions with constant beta are
 * the stationary points of V_eff when R1 has no explicit t.
 *
 * R1 = sum_j g_j k'_j gives the gyroscopic force G k' in f, with
 * G_ij = dg_i/dk_j - dg_j/dk_i (skew; 0 with one kept coordinate).
 */
#ifndef QDOT_ROUTH_H
#define QDOT_ROUTH_H

#include <stdbool.h>
#include <stddef.h>
#include "expr.h"
#include "mech.h"
#include "model.h"
#include "print.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct qd_routh {
    size_t n, nign, nkeep;
    const qd_expr **ign;      /* ignored coordinates (cyclic) */
    const qd_expr **beta;     /* their constant momenta: plain symbols p_<q> */
    const qd_expr **keep;     /* the remaining coordinates, in model order */
    const qd_expr **keepd;    /* their velocities */
    const qd_expr **keepdd;   /* their accelerations */
    const qd_expr **ignvel;   /* q'_ign in keep, keep', beta, t (the quadratures' integrands) */
    const qd_expr **pdef;     /* dL/dq'_ign in q, q', t: what beta stands for */
    const qd_expr *R;         /* Routhian, Goldstein sign, in keep, keep', beta, t */
    const qd_expr *R2, *R1, *R0;  /* parts of degree 2, 1, 0 in keep' */
    const qd_expr *Veff;      /* effective potential (velocity-free): V_eff = R0 */
    const qd_expr **M, **f;   /* reduced equations M keep'' = f (M nkeep*nkeep row-major,
                                 f nkeep), from -R as Lagrangian, plus generalized
                                 forces/dissipation of kept coordinates */
    const qd_expr **G;        /* nkeep*nkeep gyroscopic matrix from R1 (skew), row-major:
                                 the force G k' is part of f */
    const qd_expr *h;         /* Jacobi integral of -R: R0 - R2 (E = T + V when scleronomic);
                                 conserved when `conserved` */
    bool conserved;           /* no explicit t in R, no Q and no D on kept coordinates */
    size_t *ign_index;        /* position of each ignored coordinate in the eom's q */
    size_t *keep_index;       /* position of each kept coordinate in the eom's q */
    /* forced ignored coordinates (qd_routh_opts.forced; Byerly Art. 20a): c
     * absent from L but with a generalized force Q_c, so beta_c is not
     * constant but p_c' = Q_c.  R is the same function of beta; the reduced
     * equations gain the terms of beta' that d/dt brings in. */
    bool forced;
    const qd_expr **betad;    /* nign symbols p_<c>_dot standing for p_c' (forced only) */
    const qd_expr **pdot;     /* nign: Q_c in keep, keep', beta, t: p_c' = pdot_c */
    const qd_expr **f_betad;  /* nkeep: f with the p_c' kept as betad (forced only):
                                 M keep'' = f_betad is the reduced equation with the
                                 p' term, f the same with p_c' = Q_c put in */
    bool implicit;            /* L is not quadratic in the ignored velocities c' and
                                 p = dL/dc' has no closed-form inverse (only with
                                 qd_routh_opts.implicit): see below */
} qd_routh;

/*
 * The implicit Routhian (issue 17), kept the way qd_ham keeps an implicit H.
 * ignvel_i is c'_i itself, standing for the solution of pdef_i = beta_i
 * (qd_routh_velocities_at finds it at a point), and
 *
 *     R(k, k', c', beta, t) = sum beta c' - L        (c' not substituted).
 *
 * Since dR/dc' = beta - dL/dc' = 0 there, the envelope theorem gives
 * dR/dk = -dL/dk and dR/dk' = -dL/dk' at fixed beta: Lagrange's equations
 * of -R are those of L for the kept coordinates, and the c'' that d/dt
 * brings in is eliminated with d/dt (dL/dc') = 0 (beta constant).  M, f are
 * then in k, k', c', beta, t; M is d^2(-R)/dk'dk' at fixed beta, the Schur
 * complement of d^2L/dc'dc' in the full Hessian.  h = R + sum k' dL/dk' is
 * the Jacobi integral of -R.  R is not split by degree: R2, R1, R0 and Veff
 * are NULL and so are the entries of G (the split needs c' as a function).
 */

/* Reduce the model m (derived as e by qd_eom_derive) by ignoring the nign
 * coordinates ign (coordinate symbols of the model).  QD_ERR_ARG with a
 * message naming the coordinate when one is not a coordinate, is repeated,
 * appears in L, has a generalized force or enters the dissipation through
 * its velocity (it is then not cyclic), when every coordinate is ignored,
 * and for models with constraints or eliminated coordinates;
 * QD_ERR_NONLINEAR when L is not quadratic in the velocities and
 * QD_ERR_SINGULAR when the ignored momenta do not determine the ignored
 * velocities.  NULL on failure, reason in the context. */
QD_API qd_routh *qd_routh_derive(qd_ctx *ctx, const qd_model *m, const qd_eom *e,
                          size_t nign, const qd_expr *const *ign);

/* qd_routh_derive with options (opts may be NULL: the defaults, all false).
 * implicit: keep the Routhian implicit (r->implicit) instead of failing with
 * QD_ERR_NONLINEAR when the ignored velocities have no closed form.  Off by
 * default because callers that read R0 or V_eff need them in closed form.
 * forced: an ignored coordinate c absent from L (and from the dissipation)
 * may carry a generalized force Q_c (not depending on any ignored
 * coordinate): its momentum then changes, p_c' = Q_c, and the reduced
 * equations d/dt d(-R)/dk' - d(-R)/dk = Q_k contain p_c' (Byerly Art. 20a,
 * the tractrix modified for x: m a^2 (sin^2 th th'' + sin th cos th th'^2)
 * - a cos th p_x' = 0).  h is then not conserved. */
typedef struct qd_routh_opts {
    bool implicit;
    bool forced;   /* accept ignored coordinates that carry a generalized force
                      (free of the ignored coordinates themselves): r->forced */
} qd_routh_opts;
QD_API qd_routh *qd_routh_derive_opts(qd_ctx *ctx, const qd_model *m, const qd_eom *e,
                                      size_t nign, const qd_expr *const *ign,
                                      const qd_routh_opts *opts);

/* The ignored velocities at a point: Newton's method on beta = pdef (as
 * qd_ham_velocities_at, the Jacobian d^2L/dc'dc').  syms/vals (nsyms) give
 * the kept coordinates and velocities, the momenta beta, t and parameters;
 * values given for the ignored velocities are the first guess (else 0).
 * out receives r->nign velocities.  Any r works; for a closed-form r the
 * answer is ignvel's value.  QD_ERR_NUMERIC or QD_ERR_SINGULAR, message in
 * the context, when Newton fails. */
QD_API qd_status qd_routh_velocities_at(qd_ctx *ctx, const qd_routh *r, const qd_eom *e,
                                        size_t nsyms, const qd_expr *const *syms,
                                        const double *vals, double *out);
QD_API void qd_routh_free(qd_routh *r);

/* The reduction r of m (e: its equations, as given to qd_routh_derive)
 * written for a reader, appended to out: fmt QD_FMT_TEXT or QD_FMT_LATEX
 * gives the heading (model_name, the ignored and kept coordinates), the
 * momenta and quadratures, R by degree, V_eff, the reduced equations
 * M q'' = f (entries j <= k of the symmetric M), the forced terms, G and
 * the Jacobi integral, LaTeX with "% " before the prose lines;
 * QD_FMT_SYMPY a Python script defining routh_ignored, routh_kept,
 * routh_momenta, routh_pdef, routh_quadratures, routh_R, routh_R2,
 * routh_R1, routh_R0, routh_V_eff, routh_jacobi, routh_M, routh_f,
 * routh_G, routh_conserved (None for the parts an implicit R lacks, and
 * routh_implicit = True).  model_name may be NULL ("model").  QD_ERR_ARG
 * for another format, QD_ERR_NOMEM when out could not grow. */
QD_API qd_status qd_routh_print(qd_ctx *ctx, const qd_routh *r, const qd_model *m,
                                const qd_eom *e, const char *model_name, qd_format fmt,
                                qd_buf *out);
/* The same as one JSON document (and a newline): "model" (model_name, or
 * null), "ignored", "momenta", "kept", "momentum_definitions", "R", "R2",
 * "R1", "R0", "effective_potential", "jacobi_integral", "equations" (per
 * kept coordinate: "q", its row of "M", "f"), "gyroscopic", "quadratures",
 * "conserved"; for forced coordinates "momentum_rates",
 * "momentum_rate_values", "f_with_momentum_rates"; "implicit": true only for
 * an implicit R.  Expressions are strings in the text format. */
QD_API qd_status qd_routh_json(qd_ctx *ctx, const qd_routh *r, const qd_model *m,
                               const qd_eom *e, const char *model_name, qd_buf *out);

/* The coordinate of m named name; NULL with QD_ERR_ARG and a message
 * ("unknown coordinate 'phy'; did you mean 'phi'?", "'g' is a parameter,
 * not a coordinate") otherwise. */
QD_API const qd_expr *qd_routh_lookup(qd_ctx *ctx, const qd_model *m, const char *name);

/* Why coordinate j of e (index into e->q) cannot be ignored: NULL when it
 * is cyclic; else the statement to point at (for qd_model_where: "L", "T",
 * "V", "U", "dissipation" or a coordinate's name for its generalized
 * force), with *why set to the reason in words. */
QD_API const char *qd_routh_not_cyclic(qd_ctx *ctx, const qd_model *m, const qd_eom *e, size_t j,
                                const char **why);

/* The coordinates named in list, comma-separated ("theta, phi"), into
 * ign[0, cap) and their count into *n: each a coordinate of m
 * (qd_routh_lookup), none twice, and, when e is given, each cyclic in e
 * (qd_routh_not_cyclic).  QD_OK; else QD_ERR_ARG with the context's message
 * ("phi is listed twice", "r cannot be ignored: it appears in the kinetic
 * energy") and, for a coordinate that is not cyclic, *where (where may be
 * NULL) the statement to point at, as qd_routh_not_cyclic returns it (NULL
 * otherwise); QD_ERR_NOMEM.  ign's entries are borrowed from m. */
QD_API qd_status qd_routh_ignore_read(qd_ctx *ctx, const qd_model *m, const qd_eom *e,
                                      const char *list, const qd_expr **ign, size_t cap,
                                      size_t *n, const char **where);

#ifdef __cplusplus
}
#endif

/* NULL (issue 30): a function of this header given NULL for a pointer it
 * needs does nothing and returns QD_ERR_ARG (recorded in ctx when ctx is
 * given), NULL, 0, false or NaN, as its return type has it; a void function
 * returns, and every _free accepts NULL. NULL is an accepted value, as
 * documented at the function, for: qd_routh_derive_opts (opts); qd_routh_print
 * (model_name); qd_routh_json (model_name); qd_routh_ignore_read (e, where).
 * An array whose count is 0 may be NULL. */
#endif

/*
 * qdot/metric.h - the tensors of a model's generalized coordinates
 * (Desloge App. 23, ch. 47 and ch. 55).
 *
 * The kinetic energy's part quadratic in the velocities is the metric,
 *
 *     T2 = 1/2 g_ij q'^i q'^j,          g_ij = d^2 T / dq'^i dq'^j,
 *
 * with conjugate g^ij (g^ik g_kj = delta^i_j, App. 23 Thms 7-8), the
 * Christoffel symbols of the first and second kinds
 *
 *     [ij,l] = 1/2 (d_i g_jl + d_j g_il - d_l g_ij),   Gamma^l_ij = g^lk [ij,k]
 *
 * (App. 23 eqs. 22-23), and Lagrange's equations in geodesic form
 * (ch. 55 eqs. 5-6 with m g_ij there the g_ij here):
 *
 *     q''^l + Gamma^l_ij q'^i q'^j = g^lk Q_k.
 *
 * Q_k is the covariant (generalized) component of every force but the
 * metric's: Q_k = dL'/dq_k - d/dt dL'/dq'_k - dD/dq'_k + (the model's
 * `force` on q_k), with L' = L - T2.  For T = T2 and V alone that is
 * -dV/dq_k; the terms of T linear in and free of the velocities (T1, T0:
 * rheonomic coordinates, a rotating frame) are not part of the metric and
 * act through L' as gyroscopic and centrifugal forces.
 *
 * The chart: when the model gives its mass points as `particle`s (and no
 * rigid bodies), x_a(q, t) stacked over the particles' components that are
 * not identically zero, the Jacobian J_ai = dx_a/dq_i at frozen t, its
 * determinant when it is square, the unweighted metric of ch. 47 eq. 18,
 * e_ij = sum_a J_ai J_aj (the mass-free one: physical components use it,
 * Desloge ch. 47; pitfall 2 of the reference notes), and the points where
 * the chart is singular: the zero set of det J (square), else of det e
 * (else of det g), factor by factor (r = 0 for polar coordinates; r = 0
 * and theta = 0 + k pi for spherical ones).
 *
 * Every expression belongs to the context; the struct and its arrays are
 * the library's (qd_metric_free).
 */
#ifndef QDOT_METRIC_H
#define QDOT_METRIC_H

#include <stddef.h>
#include "expr.h"
#include "model.h"
#include "print.h"

#ifdef __cplusplus
extern "C" {
#endif

/* One factor of the chart's determinant set to zero: lhs = rhs, lhs a
 * coordinate when the factor was solved for one (r = 0, theta = pi/2),
 * else the factor itself with rhs 0; period, when not NULL, means
 * rhs + k period for every integer k (the zeros of sin and cos). */
typedef struct qd_metric_singular {
    const qd_expr *lhs, *rhs, *period;
} qd_metric_singular;

typedef struct qd_metric {
    size_t n;
    const qd_expr **q, **qd, **qdd;   /* n coordinates, velocities, accelerations */
    const qd_expr *source;            /* what the metric was read from: T, or L without T */
    bool from_L;                      /* source is L (the model gives no T) */
    const qd_expr *T2;                /* its part quadratic in the velocities, 1/2 g_ij q'^i q'^j */
    const qd_expr *T1, *T0;           /* T's parts of degree 1 and 0 in the velocities (0 if none) */
    const qd_expr **g, **ginv;        /* n*n row-major, simplified */
    const qd_expr *det;               /* det g */
    /* [l][i][j] at (l*n + i)*n + j: first[...] = [ij,l], second[...] = Gamma^l_ij */
    const qd_expr **first, **second;
    const qd_expr **Q, **Qup;         /* n: Q_k as above, and g^lk Q_k */
    const qd_expr **geodesic;         /* n: q''^l + Gamma^l_ij q'^i q'^j - g^lk Q_k (= 0) */
    bool constrained;                 /* the model has constraints: their forces are not in Q */
    /* ---- the chart (npos 0 when the model gives no particles, or has bodies) */
    size_t npos;
    const qd_expr **pos;              /* npos: the position components kept */
    size_t *pos_particle;             /* npos: the particle (0-based) and */
    unsigned *pos_axis;               /* its axis 0..2 of each */
    const qd_expr **jac;              /* npos*n: dx_a/dq_i at frozen t */
    const qd_expr *jac_det;           /* npos == n: det J; else NULL */
    const qd_expr **e, *e_det;        /* n*n unweighted metric and det; NULL without positions */
    size_t nsing;
    qd_metric_singular *sing;
    const qd_expr *sing_of;           /* the determinant whose zeros they are */
    /* ---- components of forces: scale factors h_i = sqrt(e_ii), or sqrt(g_ii)
     * when the model gives no positions (scale_geometric false) */
    const qd_expr **h;
    bool scale_geometric;
    bool orthogonal;                  /* the off-diagonal e_ij (or g_ij) are identically 0 */
} qd_metric;

/* The metric and everything above for model m.  NULL on failure, reason in
 * ctx: QD_ERR_NONLINEAR when T (or L) is not a polynomial of degree 2 in the
 * velocities (a relativistic L has no metric), QD_ERR_ARG for a model given
 * by H, QD_ERR_SINGULAR when det g simplifies to 0. */
QD_API qd_metric *qd_metric_new(qd_ctx *ctx, const qd_model *m);
QD_API void qd_metric_free(qd_metric *g);

struct qd_gram; /* qdot/form.h */
/* The coordinate tangents e_1..e_n orthogonalized under g_ij (Desloge
 * App. 21 Thm 2; `qdot metric --gram-schmidt`): qd_gram_schmidt of the
 * unit vectors, printed by qd_render_gram over g->q and g->g.  NULL on
 * failure, reason in ctx.  Free with qd_gram_free. */
QD_API struct qd_gram *qd_metric_gram_schmidt(qd_ctx *ctx, const qd_metric *g);

/* A force given by its covariant components G (n, the generalized forces
 * G_i = F . dx/dq_i): up[i] = g^ij G_j (raised), phys[i] = G_i / h_i (the
 * orthogonal projection on the q_i direction, ch. 47 eq. 18), ord[i] =
 * h_i sum_j e^ij G_j (the ordinary components, along the tangents, with e
 * the metric the h come from; equal to phys when the coordinates are
 * orthogonal).  Any output may be NULL.  Each entry simplified. */
QD_API qd_status qd_metric_force(qd_ctx *ctx, const qd_metric *g, const qd_expr *const *G,
                                 const qd_expr **up, const qd_expr **phys, const qd_expr **ord);
/* A force by its covariant components read from text, "G1, G2, ..." (split
 * at the commas outside brackets, qd_state_item_end; a trailing comma ends
 * the list): exactly g->n expressions into G[0 .. g->n), each read as
 * qd_read reads with no new symbols (the model's coordinates, velocities,
 * t and parameters, and names the context already knows).  On failure the
 * context's error record is located in text (qd_ctx_diag: a caret under
 * the component that does not read, under the components beyond g->n, or
 * under the whole text when too few are given), its hint how many to
 * give; QD_ERR_ARG for the wrong count, the reader's status (QD_ERR_PARSE,
 * QD_ERR_UNBOUND) for a component, QD_ERR_NOMEM.  G's entries before the
 * failure are written. */
QD_API qd_status qd_metric_force_read(qd_ctx *ctx, const qd_metric *g, const char *text,
                                      const qd_expr **G);
/* Lowering: low[i] = g_ij A^j for contravariant A (n). */
QD_API qd_status qd_metric_lower(qd_ctx *ctx, const qd_metric *g, const qd_expr *const *A,
                                 const qd_expr **low);


/* g written for a reader, appended to out: as text (fmt QD_FMT_TEXT) the
 * metric, det g, the conjugate, the Christoffel symbols of both kinds (the
 * nonzero ones, i <= j), the geodesic form, a force's components
 * (covariant, contravariant, physical, ordinary) and the chart's Jacobian
 * with its singular points.  G: the force's n covariant components, or NULL
 * for the model's Q (then said so).  QD_ERR_ARG for another format,
 * QD_ERR_NOMEM when out could not grow, a failure of qd_metric_force. */
QD_API qd_status qd_metric_print(qd_ctx *ctx, const qd_metric *g, const qd_expr *const *G,
                                 qd_format fmt, qd_buf *out);
/* The same as one JSON document: "coordinates", "source", "T2", "T1",
 * "T0", "metric", "metric_inverse", "det", "christoffel_first",
 * "christoffel_second", "Q", "geodesic", "constrained", "force" ("given",
 * "covariant", "contravariant", "physical", "ordinary"), "scale_factors",
 * "scale_from", "orthogonal", "chart"; tensors as objects keyed by the
 * coordinates' names. */
QD_API qd_status qd_metric_json(qd_ctx *ctx, const qd_metric *g, const qd_expr *const *G,
                                qd_buf *out);

#ifdef __cplusplus
}
#endif

/* NULL (issue 30): a function of this header given NULL for a pointer it
 * needs does nothing and returns QD_ERR_ARG (recorded in ctx when ctx is
 * given), NULL, 0, false or NaN, as its return type has it; a void function
 * returns, and every _free accepts NULL. NULL is an accepted value, as
 * documented at the function, for: qd_metric_force (up, phys, ord); qd_metric_print (G);
 * qd_metric_json (G). */
#endif

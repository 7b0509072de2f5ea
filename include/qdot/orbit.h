/*
 * qdot/orbit.h - motion reduced to one degree of freedom: turning points,
 * periods, apsidal angles, circular orbits and Kepler's conics.
 *
 * Ignoring the cyclic coordinates c of a model (Routh's reduction,
 * qdot/routh.h) leaves one coordinate x moving under
 *
 *     E = M(x) x'^2 / 2 + V_eff(x),      V_eff = R0 at the constant momenta,
 *
 * (Desloge ch. 58, reference seed-desloge-B.md C3: U(r) = V + h^2/(2 m r^2)).
 * The motion fills the interval around the state where E >= V_eff; its ends
 * are the turning points.  Over one radial period
 *
 *     T_r = 2 int_{x1}^{x2} sqrt(M / (2 (E - V_eff))) dx
 *
 * each ignored coordinate advances by
 *
 *     Delta c = 2 int_{x1}^{x2} c'(x) sqrt(M / (2 (E - V_eff))) dx,
 *
 * c'(x) the ignored velocity at x' = 0 (a term of c' linear in x' integrates
 * to zero over a closed excursion). The apsidal angle is |Delta c|/2 and the
 * precession per period Delta c -+ 2 pi (one revolution either way). Circular
 * motions are the stationary points of V_eff; near a stable one x oscillates
 * at omega_r = sqrt(V_eff''/M) and the near-circular apsidal angle is pi
 * c'/omega_r, which for a central force is Bertrand's pi/sqrt(3 + r f'/f)
 * (Desloge ch. 59 eq. 31). docs/design.md, "Orbits", states the conventions
 * and tolerances.
 */
#ifndef QDOT_ORBIT_H
#define QDOT_ORBIT_H

#include <stdbool.h>
#include <stddef.h>
#include "expr.h"
#include "mech.h"
#include "model.h"
#include "routh.h"

#ifdef __cplusplus
extern "C" {
#endif

struct qd__orb_num;

/* The symbolic side, prepared once per model and choice of ignored
 * coordinates.  Expressions are in x, the momenta beta and the parameters. */
typedef struct qd_orbit {
    qd_routh *routh;
    const qd_expr *x, *xd;      /* the remaining coordinate and its velocity */
    const qd_expr *Veff;        /* V_eff(x; beta) */
    const qd_expr *dV[4];       /* its derivatives of order 1..4 in x */
    const qd_expr *mass;        /* M(x): the kinetic part of -R is M x'^2/2 (at x' = 0
                                   when general) */
    const qd_expr **rate;       /* nign: the ignored velocities at x' = 0 */
    bool general;               /* -R is not quadratic in x' (a relativistic L: M and
                                   the rates depend on x'): the quadratures solve
                                   h(x, x') = E for x' at each point */
    bool central;               /* one ignored coordinate, M free of x and c' x^2 free
                                   of x: a central force in the plane of the orbit */
    bool kepler;                /* central and V_eff = c0 + c1/x + c2/x^2 exactly: the
                                   orbit is r = p/(1 + e cos(nu (c - c_peri))) */
    const qd_expr *k0, *k1, *k2; /* when kepler: c0, c1 and c2 */
    struct qd__orb_num *num;    /* the compiled evaluator (private) */
} qd_orbit;

/* Prepare the orbit analysis of model m (derived as e) with the nign
 * coordinates ign ignored.  QD_ERR_ARG naming the coordinate when none is
 * ignored, when one is not cyclic (qd_routh_derive's errors), when more
 * than one coordinate is left ("orbit reduces to one coordinate: r, z are
 * left; ignore all but one"), and when the reduced motion is not
 * conservative (explicit t, forces or dissipation on x). */
QD_API qd_orbit *qd_orbit_derive(qd_ctx *ctx, const qd_model *m, const qd_eom *e, size_t nign,
                                 const qd_expr *const *ign);
QD_API void qd_orbit_free(qd_orbit *o);

typedef enum qd_orbit_kind {
    QD_ORBIT_BOUND,     /* between two turning points */
    QD_ORBIT_UNBOUND,   /* one turning point (or none): the motion goes to infinity */
    QD_ORBIT_CIRCULAR,  /* at rest at a minimum of V_eff */
    QD_ORBIT_CAPTURE,   /* from a turning point into a singular point of V_eff (the centre) */
    QD_ORBIT_ASYMPTOTIC /* E is the top of V_eff at an unstable circle bounding the interval:
                           the motion creeps towards it without end (no period; an ignored
                           coordinate with a rate there advances by +-inf) */
} qd_orbit_kind;

QD_API const char *qd_orbit_kind_name(qd_orbit_kind k); /* "bound", "unbound", ... */

/* A circular motion: a stationary point x of V_eff at the given momenta. */
typedef struct qd_orbit_circle {
    double x;
    double energy;       /* V_eff(x) */
    double curvature;    /* V_eff''(x) */
    int stable;          /* 1 a minimum, 0 a maximum, -1 flat (V_eff'' = 0 to round-off) */
    double omega;        /* sqrt(V_eff''/M): small radial oscillations (NAN unless stable) */
    double *apsidal;     /* nign: pi c'/omega (NAN unless stable) */
    double bertrand;     /* central: pi/sqrt(3 + r f'/f), f = -V' the force of the
                            potential without the centrifugal term; else NAN */
} qd_orbit_circle;

typedef struct qd_orbit_result {
    size_t nign;
    double x0;               /* the state's coordinate */
    double energy;           /* E */
    double *momenta;         /* nign: beta */
    qd_orbit_kind kind;
    size_t nturn;            /* 0, 1 or 2 */
    double turn[2];          /* the turning points, ascending */
    double lo, hi;           /* the interval the motion fills (+-INFINITY when open) */
    double period;           /* radial period (circular: 2 pi/omega); NAN otherwise */
    double *advance;         /* nign: per radial period; capture: from the turning point
                                to the singular point; unbound with one turning point
                                below an open end: the whole turn, in from infinity and
                                out again (NAN otherwise) */
    double *apsidal;         /* nign: |advance|/2 (bound and circular) */
    double *precession;      /* nign: advance - 2 pi, or + 2 pi for a negative advance
                                (bound and circular) */
    double fall_time;        /* capture: time from the turning point to the centre */
    double quad_error;       /* the largest error estimate of the quadratures */
    size_t ncircle;
    qd_orbit_circle *circle; /* every circular motion found, ascending in x */
    bool conic;              /* kepler: the closed form below */
    double p, e, a, nu;      /* semi-latus rectum, eccentricity, semi-major axis (negative
                                for a hyperbola, INFINITY for a parabola), angle factor */
    double periapsis;        /* the ignored coordinate's value at periapsis (NAN: e = 0) */
    bool repulsive;          /* kepler with a repulsive force (c1 > 0): the branch
                                r = p/(e cos(nu (c - c_peri)) - 1), p = 2 c2/c1 > 0 */
} qd_orbit_result;

/* Analyse the motion through a state.  syms/vals (n) give the parameters,
 * the coordinates and velocities of the state (those not given are 0, the
 * ignored coordinates included); a momentum symbol p_<c> among them is
 * used as that momentum instead of its value at the state.  energy (may be
 * NULL) gives E instead of its value at the state; the motion is then the
 * one in the allowed interval nearest x.  Errors: QD_ERR_ARG when E is below
 * every value of V_eff ("no motion", naming E and the minimum found),
 * QD_ERR_UNBOUND for a parameter without a value, QD_ERR_NUMERIC when a
 * turning point or quadrature does not converge.  Free with
 * qd_orbit_result_free. */
QD_API qd_status qd_orbit_solve(qd_ctx *ctx, const qd_orbit *o, size_t n,
                                const qd_expr *const *syms, const double *vals,
                                const double *energy, qd_orbit_result *out);
QD_API void qd_orbit_result_free(qd_orbit_result *r);

/* The radial period of r, or QD_ERR_ARG when the orbit has none: unbound
 * ("the orbit is unbound: one turning point, r = 1.5; no period"), capture. */
QD_API qd_status qd_orbit_period(qd_ctx *ctx, const qd_orbit *o, const qd_orbit_result *r,
                                 double *period);

/* The orbit equation of the first ignored coordinate c: Kepler-type,
 * r = p/(1 + e cos(nu (c - c_peri))) with the numbers of r (*lhs = x), or
 * r = p/(e cos(nu (c - c_peri)) - 1) when r->repulsive; else
 * c - c_1 = integral(c'(x) sqrt(M/(2 (E - V_eff))), x, x_1, x), the
 * quadrature from a turning point x_1 (the lower one of a bound orbit; a user function "integral"
 * of integrand, variable and limits; E, the momenta and the parameters as
 * symbols).  NULL when out of memory. */
QD_API const qd_expr *qd_orbit_equation(qd_ctx *ctx, const qd_orbit *o, const qd_orbit_result *r,
                                        const qd_expr **lhs);

/* ---- the analysis from text, and its output (issue 31) -------------------
 *
 * What `qdot orbit` reads: the state is the model's `initial` values (0
 * where it gives none), then at, "r=r0, r'=0, theta'=1" (a coordinate, a
 * velocity with a prime, t or a parameter; values constant expressions in
 * the parameters); momentum, "p_theta=3" (momenta of ignored coordinates,
 * used instead of their values at the state); energy, an expression in the
 * parameters and the state's values ("m*g*a").  Each may be NULL.  Errors
 * name the field (qd_diag.name "at", "momentum", "energy", subject
 * QD_SUBJECT_NONE) and are located in its text; an unknown name gets "did
 * you mean"; then qd_orbit_solve's errors.  *out is zeroed first (free it
 * with qd_orbit_result_free also after an error). */
typedef struct qd_orbit_text {
    const char *at, *momentum, *energy;
} qd_orbit_text;
QD_API qd_status qd_orbit_solve_text(qd_ctx *ctx, const qd_orbit *o, const qd_model *m,
                                     const qd_orbit_text *t, qd_orbit_result *out);

/* The analysis as `qdot orbit` prints it, appended to b: text (12
 * significant digits, "inf" for an open end) or JSON (every digit, null for
 * what the orbit does not have; the keys of docs/cli.md); model names the
 * model file; equation adds the orbit equation (qd_orbit_equation, or the
 * conic with its numbers). */
QD_API qd_status qd_orbit_render(qd_ctx *ctx, const qd_orbit *o, const qd_orbit_result *r,
                                 const char *model, bool equation, bool json, qd_buf *b);

#ifdef __cplusplus
}
#endif

/* NULL (issue 30): a function of this header given NULL for a pointer it
 * needs does nothing and returns QD_ERR_ARG (recorded in ctx when ctx is
 * given), NULL, 0, false or NaN, as its return type has it; a void function
 * returns, and every _free accepts NULL. NULL is an accepted value, as
 * documented at the function, for: qd_orbit_derive (ign); qd_orbit_solve
 * (energy). An array whose count is 0 may be NULL. */
#endif

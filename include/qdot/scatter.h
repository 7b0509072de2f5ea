/*
 * qdot/scatter.h - classical scattering by a central potential V(r)
 * (Desloge ch. 60-61; reference seed-desloge-B.md C4, C5).
 *
 * A particle (or the relative coordinate of two, with the reduced mass)
 * comes in from infinity with energy E > 0 and impact parameter b.  Its
 * angle turns by
 *
 *     alpha = integral_{r0}^inf b dr / (r^2 sqrt(1 - V(r)/E - b^2/r^2))
 *
 * on the way out from the distance of closest approach r0 (the first root
 * met coming in, or a wall), and the deflection is chi = pi - 2 alpha
 * (deflection_signed: negative for an attraction, below -pi when the
 * particle winds round the centre); the observed centre-of-mass angle is
 * Theta = arccos(cos chi) in [0, pi].  The differential cross section sums
 * every impact parameter that gives Theta:
 *
 *     dsigma/dOmega = sum_i b_i / (sin Theta |dchi/db|_i)
 *
 * Discontinuous potentials are exact, never smoothed: every step(x) of V
 * (x a function of r) splits the radial integral at its jump, and a jump
 * that the particle cannot climb is a wall where it turns back (the
 * refracting sphere is a momentum jump at r = a).  A hard core of radius
 * `core` (V = +inf inside) is a wall too.
 *
 * Lengths and energies are plain numbers; the potential's features should
 * lie within 1e-8 .. 1e4 times the largest of b, the core, the jumps and 1
 * (the radial scan covers that range).
 */
#ifndef QDOT_SCATTER_H
#define QDOT_SCATTER_H

#include <stdbool.h>
#include <stddef.h>
#include "expr.h"
#include "print.h"
#include "mech.h"
#include "model.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct qd_scatter qd_scatter;

/* The potential V, a function of the symbol r alone (every parameter given
 * its value), vanishing at infinity unless it has a finite range; core >= 0
 * is the hard core's radius (0: none).  QD_ERR_UNBOUND naming a symbol
 * other than r, QD_ERR_ARG for a negative core or a V that does not tend
 * to 0.  NULL on failure, reason in ctx. */
QD_API qd_scatter *qd_scatter_new(qd_ctx *ctx, const qd_expr *V, const qd_expr *r, double core);

/* The central potential of a model in a plane: two coordinates, one an
 * angle that is cyclic (ignore names it, or NULL: the one cyclic
 * coordinate), the other the radius, with T = m/2 (r'^2 + r^2 phi'^2)
 * for a constant m: Routh's reduction (routh.h) gives
 * V_eff = V(r) + p^2/(2 m r^2), and V is V_eff at p = 0.  QD_ERR_ARG when
 * the model is not of that form (the message says why).  *mass receives m
 * (may be NULL). */
QD_API qd_scatter *qd_scatter_from_model(qd_ctx *ctx, const qd_model *m, const qd_eom *e,
                                         const char *ignore, double core, double *mass);
QD_API void qd_scatter_free(qd_scatter *s);
/* Make the hard core absorb what reaches it (on) or reflect it (off, the
 * default): an orbit that meets r = core is then captured, and the capture
 * cross section pi b_c^2 has b_c^2 = min over r >= core of r^2 (1 - V/E)
 * (Desloge ch. 60 P5: pi a^2 (1 + k/(E a^n)) for -k/r^n when the core a is
 * outside the barrier).  No effect without a core. */
QD_API void qd_scatter_set_absorbing(qd_scatter *s, bool on);

QD_API const qd_expr *qd_scatter_potential(const qd_scatter *s); /* V(r) */
QD_API const qd_expr *qd_scatter_radius(const qd_scatter *s);    /* r */
/* The radii where V jumps (the zeros of its step arguments), ascending. */
QD_API size_t qd_scatter_njumps(const qd_scatter *s);
QD_API double qd_scatter_jump(const qd_scatter *s, size_t i);
/* The range: V = 0 exactly beyond it (the last jump or the core), or
 * +inf for a potential of infinite range. */
QD_API double qd_scatter_range(const qd_scatter *s);

typedef enum qd_scatter_kind {
    QD_SCATTER_DEFLECTED, /* turns at r0 and leaves */
    QD_SCATTER_REFLECTED, /* turns at a wall: a jump it cannot climb, or the core */
    QD_SCATTER_ORBITING,  /* r0 is a double root: it circles for ever (chi -> -inf) */
    QD_SCATTER_CAPTURED   /* no turning point: it falls to the centre */
} qd_scatter_kind;

QD_API const char *qd_scatter_kind_name(qd_scatter_kind k); /* "deflected", ... */

typedef struct qd_scatter_path {
    double E, b;
    qd_scatter_kind kind;
    double r0;    /* distance of closest approach (0 when captured) */
    double alpha; /* the angle swept from r0 to infinity */
    double chi;   /* deflection_signed: pi - 2 alpha (NaN captured, -inf orbiting) */
    double theta; /* the centre-of-mass angle Theta = arccos(cos chi) in [0, pi] */
} qd_scatter_path;

/* The deflection at energy E > 0 and impact parameter b >= 0 (b = 0:
 * head-on, chi = pi when it turns, 0 when it passes through a centre where
 * V is finite, captured when V -> -inf there).
 * QD_ERR_ARG for E <= 0 or b < 0; QD_ERR_NUMERIC when the quadrature
 * does not converge. */
QD_API qd_status qd_scatter_deflect(qd_ctx *ctx, qd_scatter *s, double E, double b,
                                    qd_scatter_path *out);

/* dchi/db at b (5-point differences kept on one side of every kink). */
QD_API qd_status qd_scatter_dchi_db(qd_ctx *ctx, qd_scatter *s, double E, double b,
                                    double *out);

#define QD_SCATTER_MAX_BRANCH 16
#define QD_SCATTER_MAX_FEATURE 8

typedef struct qd_scatter_branch {
    double b, chi, dchi_db;
    double sigma; /* this branch's b / (sin Theta |dchi/db|) */
} qd_scatter_branch;

/* What the deflection function chi(b) of one energy shows. */
typedef struct qd_scatter_features {
    double E;
    double range;          /* qd_scatter_range */
    double total;          /* pi range^2, or +inf */
    size_t nrainbow;       /* dchi/db = 0 at b > 0: sigma diverges at that angle */
    double rainbow_b[QD_SCATTER_MAX_FEATURE], rainbow_theta[QD_SCATTER_MAX_FEATURE];
    size_t nglory;         /* sin Theta = 0 at b > 0: forward (0) or backward (pi) glory */
    double glory_b[QD_SCATTER_MAX_FEATURE], glory_theta[QD_SCATTER_MAX_FEATURE];
    bool orbiting;         /* an unstable circular orbit at this energy */
    double orbit_b, orbit_r; /* where: chi -> -inf as b -> orbit_b */
    bool capture;          /* b < capture_b fall to the centre */
    double capture_b;      /* capture cross section pi capture_b^2 (Desloge ch. 60 P5) */
} qd_scatter_features;

QD_API qd_status qd_scatter_features_at(qd_ctx *ctx, qd_scatter *s, double E,
                                        qd_scatter_features *out);

typedef struct qd_scatter_section {
    double E, theta;
    double sigma;          /* dsigma/dOmega summed over the branches */
    size_t nbranch;
    qd_scatter_branch branch[QD_SCATTER_MAX_BRANCH];
    bool truncated;        /* more branches than QD_SCATTER_MAX_BRANCH (orbiting) */
} qd_scatter_section;

/* dsigma/dOmega at the centre-of-mass angle theta in (0, pi): every impact
 * parameter found by scanning chi(b) (a grid fine near the kinks, then
 * bisection).  QD_ERR_ARG for theta outside (0, pi) or E <= 0. */
QD_API qd_status qd_scatter_section_at(qd_ctx *ctx, qd_scatter *s, double E, double theta,
                                       qd_scatter_section *out);

/* ---- the laboratory frame, target at rest (Desloge ch. 61, C5) ------------
 *
 * gamma = w / s*: m1/m2 for an elastic collision of m1 on m2 at rest.  The
 * lab angle of the projectile is tan theta_lab = sin Theta/(cos Theta +
 * gamma), its cross section
 *
 *     Q = q (1 + gamma^2 + 2 gamma cos Theta)^(3/2) / |1 + gamma cos Theta|
 *
 * and the target recoils at (pi - Theta)/2 on the other side with the
 * fraction 4 m1 m2/(m1 + m2)^2 sin^2(Theta/2) of the projectile's energy,
 * into the solid angle dOmega_cm/dOmega_rec = 4 sin(Theta/2). */
typedef struct qd_scatter_lab {
    double gamma;
    double theta_lab;      /* the projectile's lab angle */
    double jacobian;       /* dOmega_cm/dOmega_lab: sigma_lab = jacobian * sigma_cm */
    double energy_ratio;   /* the projectile's lab energy after / before */
    double recoil_angle;   /* the target's lab angle */
    double recoil_ratio;   /* the target's energy / the projectile's before */
    double recoil_jacobian;/* dOmega_cm/dOmega_recoil */
} qd_scatter_lab;

/* The maps at the CM angle theta in [0, pi] for masses m1 (projectile) and
 * m2 (target) > 0 (elastic: gamma = m1/m2).  QD_ERR_ARG otherwise. */
QD_API qd_status qd_scatter_lab_map(qd_ctx *ctx, double m1, double m2, double theta,
                                    qd_scatter_lab *out);

/* The lab angle and Jacobian for any gamma >= 0 (an inelastic collision,
 * Desloge's gamma vector along the beam). */
QD_API void qd_scatter_lab_gamma(double gamma, double theta, double *theta_lab,
                                 double *jacobian);

/* The CM angles that give the lab angle theta_lab: one when gamma < 1,
 * two (or none beyond theta_max = asin(1/gamma)) when gamma > 1.  Returns
 * the count, angles in cm[0..count). */
QD_API size_t qd_scatter_lab_to_cm(double gamma, double theta_lab, double cm[2]);

/* ---- one question, as `qdot scatter` asks it (issue 31) ------------------
 *
 * At the energy E: the orbit of one impact parameter b (and the cross
 * section at its angle), the cross section at one centre-of-mass angle, or
 * at one laboratory angle (every CM angle that reaches it, summed through
 * the Jacobians, Desloge ch. 61 eqs. 36, 67); always the features of the
 * deflection function at E; with the masses, the laboratory frame. */
typedef enum qd_scatter_at {
    QD_SCATTER_AT_B,     /* b */
    QD_SCATTER_AT_THETA, /* theta in (0, pi) */
    QD_SCATTER_AT_LAB    /* lab_theta in (0, pi), masses needed */
} qd_scatter_at;

typedef struct qd_scatter_query {
    double E;
    qd_scatter_at at;
    double b, theta, lab_theta;
    double core;         /* the hard core's radius (for qd_scatter_from_model), 0: none */
    bool absorbing;      /* the core absorbs (qd_scatter_set_absorbing) */
    bool masses;         /* m1 (projectile) and m2 (target at rest) given */
    bool recoil;         /* count the recoiling target too (identical particles, both
                            detected): the lab cross section adds the CM angle
                            pi - 2 theta_lab through the recoil's Jacobian */
    double m1, m2;
} qd_scatter_query;

/* The query as the text of `qdot scatter`'s options, each NULL when not
 * given, every value a constant expression in the parameters of m
 * (qd_model_number): energy, exactly one of b, theta and lab_theta, core,
 * masses "m1, m2".  QD_ERR_ARG naming the field (qd_diag.name) for a
 * missing or second angle, lab_theta without masses or outside (0, pi),
 * masses that are not two positive numbers. */
typedef struct qd_scatter_text {
    const char *energy, *b, *theta, *lab_theta, *core, *masses;
    bool absorbing, recoil; /* copied to the query */
} qd_scatter_text;
QD_API qd_status qd_scatter_read(qd_ctx *ctx, const qd_model *m, const qd_scatter_text *text,
                                 qd_scatter_query *out);

typedef struct qd_scatter_answer {
    qd_scatter_query q;
    qd_scatter_path path;          /* AT_B: the orbit */
    qd_scatter_section section;    /* at theta, or at the orbit's angle; sigma NaN: none */
    size_t ncm;                    /* AT_LAB: the CM angles that reach lab_theta */
    double cm[2], cm_sigma[2], cm_jacobian[2];
    double lab_sigma;              /* AT_LAB, or masses: the lab cross section (NaN: none),
                                      the recoil's part included when q.recoil */
    double recoil_sigma;           /* q.recoil: the recoil's part of lab_sigma (0 beyond
                                      pi/2, where no recoil goes; NaN: not counted) */
    bool lab;                      /* masses and a CM angle in [0, pi]: lab_map holds */
    qd_scatter_lab lab_map;
    size_t lab_ncm;                /* the CM angles summed into lab_sigma */
    qd_scatter_features features;
} qd_scatter_answer;

/* Answer q for s (made absorbing as q says).  The errors of qd_scatter_deflect, _section_at and
 * _features_at. */
QD_API qd_status qd_scatter_answer_query(qd_ctx *ctx, qd_scatter *s, const qd_scatter_query *q,
                                         qd_scatter_answer *out);

/* The answer as `qdot scatter` prints it, appended to b: text (nine
 * significant digits: the cross sections come from differences of the
 * deflection) or JSON (every digit; the keys of docs/cli.md); model names
 * the model file. */
QD_API qd_status qd_scatter_render(qd_ctx *ctx, const qd_scatter *s, const qd_scatter_answer *a,
                                   const char *model, bool json, qd_buf *b);

#ifdef __cplusplus
}
#endif

/* NULL (issue 30): a function of this header given NULL for a pointer it
 * needs does nothing and returns QD_ERR_ARG (recorded in ctx when ctx is
 * given), NULL, 0, false or NaN, as its return type has it; a void function
 * returns, and every _free accepts NULL. NULL is an accepted value, as
 * documented at the function, for: qd_scatter_from_model (ignore, mass). An
 * array whose count is 0 may be NULL. */
#endif

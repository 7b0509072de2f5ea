/*
 * qdot/relativity.h - special relativity's kinematics and two-particle
 * dynamics (Desloge vol. 2 ch. 86-91; seed 000_46d037099a6cfcd7.txt,
 * reference seed-desloge-D.md C6, C7).
 *
 * Conventions (Desloge's, pitfalls P8 and P9 of the reference):
 *   - V is the velocity of the new frame S' relative to the old S; the
 *     transformations take a quantity measured in S to its value in S'.
 *   - c is a parameter (> 0); every speed must be below it, else QD_ERR_ARG
 *     with a message naming the speed.
 *   - Events are (t, x, y, z); the 4x4 boost acts on (x, y, z, c t) with the
 *     metric g = diag(1, 1, 1, -1) (ch. 91), so O^T g O = g.
 *   - m is the invariant (rest) mass; E = m gamma c^2 includes the rest
 *     energy; p = m gamma v.
 * Functions take three-vectors as double[3]; an output may not alias an
 * input.  Errors are recorded in ctx as everywhere in libqdot.
 */
#ifndef QDOT_RELATIVITY_H
#define QDOT_RELATIVITY_H

#include <stddef.h>
#include "expr.h"

#ifdef __cplusplus
extern "C" {
#endif

/* gamma = (1 - v.v/c^2)^(-1/2) (ch. 86 eq 49's gamma). */
QD_API qd_status qd_rel_gamma(qd_ctx *ctx, double c, const double v[3], double *gamma);

/* ch. 86 eqs 6-7: r' = r + (G - 1)(r.n)n - G V t, t' = G (t - r.V/c^2),
 * ev and out as (t, x, y, z). */
QD_API qd_status qd_lorentz_event(qd_ctx *ctx, double c, const double V[3], const double ev[4],
                                  double out[4]);
/* ch. 86 eq 30: v' = [v + (G - 1)(v.n)n - G V] / (G (1 - v.V/c^2)). */
QD_API qd_status qd_lorentz_velocity(qd_ctx *ctx, double c, const double V[3], const double v[3],
                                     double out[3]);
/* ch. 86 eq 44: the acceleration a of a particle moving with v:
 * a' = {(1 - v.V/c^2) a + [(1 - G) V/(G V^2) + v/c^2](V.a)} / (G^2 (1 - v.V/c^2)^3). */
QD_API qd_status qd_lorentz_acceleration(qd_ctx *ctx, double c, const double V[3],
                                         const double v[3], const double a[3], double out[3]);
/* ch. 88 eq 53, ch. 90 eq 2: E' = G (E - p.V), p' = p + (G - 1)(p.n)n - G E V/c^2.
 * Any four-momentum (also of a massless particle, E = |p| c). */
QD_API qd_status qd_lorentz_momentum(qd_ctx *ctx, double c, const double V[3], double E,
                                     const double p[3], double *E_out, double p_out[3]);

/* The boost as a 4x4 matrix on (x, y, z, c t) (ch. 91: for V along x,
 * [[G,0,0,-G V/c],[0,1,0,0],[0,0,1,0],[-G V/c,0,0,G]]), row-major. */
QD_API qd_status qd_lorentz_boost(qd_ctx *ctx, double c, const double V[3], double O[16]);
/* max |(O^T g O - g)_ij|, g = diag(1, 1, 1, -1): 0 for a Lorentz matrix. */
QD_API double qd_lorentz_metric_error(const double O[16]);

/* E = m gamma c^2 and p = m gamma v of a particle of rest mass m >= 0 (ch. 88
 * eq 52, ch. 90). */
QD_API qd_status qd_rel_momentum(qd_ctx *ctx, double c, double m, const double v[3], double *E,
                                 double p[3]);
/* The invariant mass sqrt(E^2 - p.p c^2)/c^2 of a four-momentum; QD_ERR_ARG
 * when E <= 0 or E < |p| c beyond round-off (no particle has it). */
QD_API qd_status qd_rel_mass(qd_ctx *ctx, double c, double E, const double p[3], double *m);

/* Velocity composition (ch. 87 eq 1): w = u (+) v, the velocity in S of a
 * particle moving with v in the frame S' that moves with u relative to S
 * (the inverse of ch. 86 eq 30).  Not commutative in direction. */
QD_API qd_status qd_rel_compose(qd_ctx *ctx, double c, const double u[3], const double v[3],
                                double w[3]);
/* The angle between u (+) v and v (+) u, radians in [0, pi]: the
 * Thomas-Wigner rotation angle of the two boosts (pitfall P7). */
QD_API qd_status qd_rel_wigner_angle(qd_ctx *ctx, double c, const double u[3], const double v[3],
                                     double *angle);

/* Time dilation (ch. 87): a clock moving with V measures the proper
 * interval dtau; in S it lasts G dtau. */
QD_API qd_status qd_rel_dilate(qd_ctx *ctx, double c, const double V[3], double dtau, double *dt);
/* Length contraction (ch. 87): a displacement d at rest in the frame that
 * moves with V, measured at one time of S: its component along V shrinks
 * by 1/G, the perpendicular part stays. */
QD_API qd_status qd_rel_contract(qd_ctx *ctx, double c, const double V[3], const double d[3],
                                 double out[3]);

/* Proper time along a worldline of velocity v(t) (three expressions in the
 * time symbol t and no other symbol): tau = integral_t0^t1 sqrt(1 - v.v/c^2) dt
 * by adaptive tanh-sinh quadrature.  QD_ERR_ARG when v reaches c at a
 * sample or a symbol other than t is left; QD_ERR_NUMERIC when the
 * quadrature does not reach tol (relative, 0: 1e-12). */
typedef struct qd_rel_tau {
    double tau;      /* the proper time */
    double error;    /* the quadrature's error estimate */
    double vmax;     /* the largest speed met at the abscissas */
    size_t evals;
} qd_rel_tau;
QD_API qd_status qd_rel_proper_time(qd_ctx *ctx, double c, const qd_expr *const v[3], double t0,
                                    double t1, double tol, qd_rel_tau *out);

/* ---- collisions (ch. 88-91: conservation of four-momentum) ------------- */

/* A particle: rest mass m and velocity v, and its E and p. */
typedef struct qd_rel_particle {
    double m, v[3];
    double E, p[3];
} qd_rel_particle;

/* *out from m and v (qd_rel_momentum). */
QD_API qd_status qd_rel_particle_make(qd_ctx *ctx, double c, double m, const double v[3],
                                      qd_rel_particle *out);
/* *out from E and p: m = qd_rel_mass, v = p c^2 / E. */
QD_API qd_status qd_rel_particle_from_momentum(qd_ctx *ctx, double c, double E,
                                               const double p[3], qd_rel_particle *out);

/* The sum of n four-momenta as one particle: m the invariant mass
 * M = sqrt(E^2 - p^2 c^2)/c^2 and v = p c^2/E the velocity of the
 * centre-of-momentum frame, which is also the velocity of the particle a
 * perfectly inelastic merge makes (C7). */
QD_API qd_status qd_rel_total(qd_ctx *ctx, double c, size_t n, const qd_rel_particle *in,
                              qd_rel_particle *out);

/* An elastic collision of in[0] and in[1] (rest masses kept): in the
 * centre-of-momentum frame particle 1's momentum turns by chi (radians in
 * [0, pi]) in the plane of e1 (its direction before) and e2 rotated by the
 * azimuth phi about e1, e2 being the unit vector perpendicular to e1 built
 * from the first coordinate axis least aligned with e1; out[1] gets the
 * opposite momentum.  Both are boosted back to the lab. */
QD_API qd_status qd_rel_elastic(qd_ctx *ctx, double c, const qd_rel_particle in[2], double chi,
                                double phi, qd_rel_particle out[2]);
/* The angle between particle k's velocity after and particle 1's velocity
 * before in the lab (when particle 1 is at rest before: its direction in
 * the centre-of-momentum frame), radians in [0, pi]. */
QD_API double qd_rel_lab_angle(const qd_rel_particle in[2], const qd_rel_particle out[2],
                               unsigned k);
/* The centre-of-momentum angles chi (phi = 0) at which particle 1 leaves at
 * the lab angle theta: up to two, in increasing order, in chi[]; *count
 * how many (0: theta is beyond the largest angle that particle reaches). */
QD_API qd_status qd_rel_elastic_lab(qd_ctx *ctx, double c, const qd_rel_particle in[2],
                                    double theta, double chi[2], size_t *count);

/* A reaction a + b -> products of rest masses summing to M, b at rest: the
 * threshold is where the invariant mass of a + b reaches M,
 * E_a = (M^2 - m_a^2 - m_b^2) c^2 / (2 m_b), kinetic energy
 * K = E_a - m_a c^2 = ((M^2 - (m_a + m_b)^2) c^2 / (2 m_b)), speed v_a.
 * K = 0 when M <= m_a + m_b (no threshold).  QD_ERR_ARG for m_b <= 0. */
typedef struct qd_rel_threshold {
    double E, K, speed;
} qd_rel_threshold;
QD_API qd_status qd_rel_threshold_of(qd_ctx *ctx, double c, double m_a, double m_b, double M,
                                     qd_rel_threshold *out);

/* A two-body decay of parent into rest masses m1, m2 (m1 + m2 < M): in the
 * parent's rest frame p* = c sqrt((M^2 - (m1+m2)^2)(M^2 - (m1-m2)^2))/(2 M),
 * E1* = (M^2 + m1^2 - m2^2) c^2/(2 M); product 1 leaves at angle chi from
 * the parent's direction of motion (the x axis for a parent at rest), azimuth
 * phi as in qd_rel_elastic; out in the lab.  A massless product moves at c. */
QD_API qd_status qd_rel_decay(qd_ctx *ctx, double c, const qd_rel_particle *parent, double m1,
                              double m2, double chi, double phi, qd_rel_particle out[2],
                              double *pstar);

#ifdef __cplusplus
}
#endif

/* NULL (issue 30): a function of this header given NULL for a pointer it
 * needs does nothing and returns QD_ERR_ARG (recorded in ctx when ctx is
 * given), or NaN for a function returning a double. An array whose count
 * is 0 may be NULL. */
#endif

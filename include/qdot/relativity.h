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

#include <stdbool.h>
#include <stddef.h>
#include "expr.h"
#include "print.h"

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

/* ---- text: numbers in which c is the speed of light (issue 31) ---------
 *
 * What `qdot lorentz` and `qdot collide` read, for any caller: every value
 * is an expression in c (the run's speed of light), pi and e ("0.6*c",
 * "sqrt(3)/2*c").  An error names the value by field (qd_diag.name, subject
 * QD_SUBJECT_NONE: "frame", "particle") and is located in text (a caller
 * shows the caret under the item at fault).  Lists are split at the commas
 * outside brackets, and one bracket around the whole list is dropped. */

/* c itself: a positive finite constant expression (pi, e). */
QD_API qd_status qd_rel_read_c(qd_ctx *ctx, const char *field, const char *text, double *c);
/* One number. */
QD_API qd_status qd_rel_read_number(qd_ctx *ctx, double c, const char *field, const char *text,
                                    double *out);
/* "a, b, c" or "(a, b, c)": exactly n numbers (n <= 16). */
QD_API qd_status qd_rel_read_numbers(qd_ctx *ctx, double c, const char *field, const char *text,
                                     size_t n, double *out);
/* "m=MASS, v=(VX, VY, VZ)" (v defaults to rest) as a particle. */
QD_API qd_status qd_rel_read_particle(qd_ctx *ctx, double c, const char *field, const char *text,
                                      qd_rel_particle *out);

/* ---- the Lorentz transformation of several quantities at once ----------
 *
 * What `qdot lorentz` asks and Python's qdot.lorentz: each part is
 * computed when its bit is in ask. */
enum {
    QD_LORENTZ_FRAME = 1u << 0,        /* gamma of V, the boost and O^T g O - g */
    QD_LORENTZ_EVENT = 1u << 1,        /* an event (t, x, y, z) */
    QD_LORENTZ_VELOCITY = 1u << 2,     /* a velocity, and gamma of its image */
    QD_LORENTZ_ACCELERATION = 1u << 3, /* an acceleration (needs the velocity) */
    QD_LORENTZ_MOMENTUM = 1u << 4,     /* a four-momentum, and its invariant mass */
    QD_LORENTZ_COMPOSE = 1u << 5,      /* V (+) u, u (+) V and the Wigner angle */
    QD_LORENTZ_DILATE = 1u << 6,       /* a proper interval of a clock moving with V */
    QD_LORENTZ_CONTRACT = 1u << 7,     /* a displacement at rest in S' */
    QD_LORENTZ_PROPER_TIME = 1u << 8   /* proper time along v(t), t0 <= t <= t1 (no V) */
};

typedef struct qd_lorentz_in {
    unsigned ask;          /* the QD_LORENTZ_ bits */
    double c;              /* the speed of light, > 0 */
    double frame[3];       /* V (every part but PROPER_TIME needs it) */
    double event[4], velocity[3], acceleration[3];
    double energy, momentum[3];
    double compose[3], dilate, contract[3];
    const qd_expr *worldline[3]; /* v(t): expressions in t */
    double t0, t1;
} qd_lorentz_in;

typedef struct qd_lorentz_out {
    double gamma, boost[16], metric_error;
    double event[4], velocity[3], particle_gamma, acceleration[3];
    double energy, momentum[3], invariant_mass;
    double composed[3], composed_reverse[3], wigner_angle;
    double dilated, contracted[3];
    qd_rel_tau tau;
} qd_lorentz_out;

/* Every part asked for.  QD_ERR_ARG (the field named, as above) when a
 * part needs the frame and ask lacks it, an acceleration comes without the
 * particle's velocity (ch. 86 eq 44 needs it), or a speed reaches c. */
QD_API qd_status qd_lorentz_run(qd_ctx *ctx, const qd_lorentz_in *in, qd_lorentz_out *out);

/* The same question as text (the values of `qdot lorentz`'s options, NULL
 * when not given): c (default 1), then each part, momentum as "E, px, py,
 * pz" or "m=M, v=(...)", proper_time three expressions in t over t as
 * "T0:T1".  *in gets the numbers and ask the parts given. */
typedef struct qd_lorentz_text {
    const char *c, *frame, *event, *velocity, *acceleration, *momentum, *compose, *dilate,
        *contract, *proper_time, *t;
} qd_lorentz_text;
QD_API qd_status qd_lorentz_read(qd_ctx *ctx, const qd_lorentz_text *text, qd_lorentz_in *in);

/* The result as `qdot lorentz` prints it, appended to b: text (12
 * significant digits) or JSON (every digit; the keys of docs/cli.md). */
QD_API qd_status qd_lorentz_render(qd_ctx *ctx, const qd_lorentz_in *in,
                                   const qd_lorentz_out *out, bool json, qd_buf *b);

/* ---- collisions as one question ----------------------------------------- */

#define QD_COLLIDE_MAX 64     /* particles */
#define QD_COLLIDE_PRODUCTS 16

typedef enum qd_collide_final {
    QD_COLLIDE_NONE,     /* only the sum */
    QD_COLLIDE_ELASTIC,  /* two particles' elastic final states */
    QD_COLLIDE_DECAY     /* one particle's two-body decay */
} qd_collide_final;

typedef struct qd_collide_in {
    double c;
    size_t n;                          /* particles, 1 .. QD_COLLIDE_MAX */
    qd_rel_particle particle[QD_COLLIDE_MAX];
    bool merge;                        /* report the perfectly inelastic merge */
    qd_collide_final final;
    bool lab;                          /* elastic: at particle 1's lab angle, not cm_angle */
    double lab_angle, cm_angle, azimuth;
    size_t nproducts;                  /* threshold (> 0: asked) or decay (2) */
    double product[QD_COLLIDE_PRODUCTS];
    bool threshold;
} qd_collide_in;

typedef struct qd_collide_out {
    qd_rel_particle total;             /* m the invariant mass, v the CM velocity */
    size_t nfinal;                     /* final states: elastic 0..2, decay 1 */
    double cm_angle[2];
    double lab_angles[2][2];           /* elastic: both particles' lab angles */
    qd_rel_particle final[2][2];
    double conservation_error;         /* the largest imbalance of E and p c */
    double pstar;                      /* decay: the momentum in the parent's frame */
    double products_mass;              /* threshold: the sum of the products' masses */
    qd_rel_threshold threshold;
    bool allowed;                      /* threshold: total.m >= products_mass */
} qd_collide_out;

/* The sum, and the final states or threshold asked.  QD_ERR_ARG (field
 * named) when elastic or threshold has not two particles, a decay not one,
 * or a decay's products are too heavy. */
QD_API qd_status qd_collide_run(qd_ctx *ctx, const qd_collide_in *in, qd_collide_out *out);

/* The question as the text of `qdot collide`'s options: c (default 1),
 * the particles ("m=..., v=(...)"), angle (elastic at a lab angle),
 * cm_angle, azimuth, threshold ("M1, M2, ...") and decay ("m1, m2"). */
typedef struct qd_collide_text {
    const char *c;
    size_t n;
    const char *const *particle;
    bool merge, elastic;
    const char *angle, *cm_angle, *azimuth, *threshold, *decay;
} qd_collide_text;
QD_API qd_status qd_collide_read(qd_ctx *ctx, const qd_collide_text *text, qd_collide_in *in);

/* The result as `qdot collide` prints it (text or JSON), appended to b. */
QD_API qd_status qd_collide_render(qd_ctx *ctx, const qd_collide_in *in,
                                   const qd_collide_out *out, bool json, qd_buf *b);

#ifdef __cplusplus
}
#endif

/* NULL (issue 30): a function of this header given NULL for a pointer it
 * needs does nothing and returns QD_ERR_ARG (recorded in ctx when ctx is
 * given), or NaN for a function returning a double. An array whose count
 * is 0 may be NULL. */
#endif

/*
 * src/orbit/orb.h - the orbit module's internals (prefix qd__orb_): the
 * compiled evaluator of V_eff, its derivatives, M and the ignored rates,
 * and the scans that find turning points and circular motions.
 */
#ifndef QD_ORBIT_ORB_H
#define QD_ORBIT_ORB_H

#include <stdbool.h>
#include <stddef.h>

#include "qdot/eval.h"
#include "qdot/orbit.h"

/* The outputs of the compiled program, in order; the rates follow. */
enum { QD__ORB_V, QD__ORB_V1, QD__ORB_V2, QD__ORB_V3, QD__ORB_V4, QD__ORB_M, QD__ORB_RATE };

struct qd__orb_num {
    qd_prog *prog;
    size_t nin, nout;
    const qd_expr **ins;   /* the program's inputs: x, the momenta, the parameters */
    /* o->general only: h(x, x'), dh/dx' and the ignored rates c'(x, x'), of
     * the inputs ins2 (x, x', the momenta, the parameters); and prog's
     * outputs ih4, ih6: d^4h/dx'^4 and d^6h/dx'^6 at x' = 0 */
    qd_prog *prog2;
    size_t nin2, ih4;
    const qd_expr **ins2;
};

/* The outputs of prog2. */
enum { QD__ORB_H, QD__ORB_DH, QD__ORB_RATE2 };

/* One evaluation environment per solve (the program is shared, read-only). */
typedef struct qd__orb_env {
    const qd_orbit *o;
    double *work, *in, *out;
    double *work2, *in2, *out2; /* prog2's (o->general) */
    size_t ix2, ixd2;           /* x's and x''s slots in in2 (SIZE_MAX: absent) */
    size_t ix;             /* x's slot in in[] (SIZE_MAX: V_eff is free of x) */
    double E;              /* the energy */
    double scale;          /* the length of x's scans: |x0|, or 1 */
    bool sing0;            /* V_eff is not finite at x = 0: a singular point */
} qd__orb_env;

/* Bind the parameters (syms/vals) and the momenta beta.  QD_ERR_UNBOUND
 * naming a parameter with no value. */
qd_status qd__orb_env_init(qd_ctx *ctx, const qd_orbit *o, size_t n, const qd_expr *const *syms,
                           const double *vals, const double *beta, qd__orb_env *env);
void qd__orb_env_free(qd__orb_env *env);
/* Evaluate every output at x; the values are env->out[QD__ORB_...]. */
const double *qd__orb_at(qd__orb_env *env, double x);

/* A function of x scanned for sign changes. */
typedef double (*qd__orb_fn)(qd__orb_env *env, double x);
double qd__orb_gap(qd__orb_env *env, double x);   /* E - V_eff(x) */
/* o->general: prog2's outputs at (x, xd). */
const double *qd__orb_at2(qd__orb_env *env, double x, double xd);
/* o->general: the speed x' > 0 with h(x, x') = E where E - V_eff(x) = gap
 * (formed by the caller without cancellation), after qd__orb_at(env, x);
 * NaN when none is found. */
double qd__orb_speed(qd__orb_env *env, double x, double gap);
double qd__orb_slope(qd__orb_env *env, double x); /* V_eff'(x) */

/* How a scan from x0 in direction dir (+1, -1) ended. */
typedef enum { QD__ORB_FOUND, QD__ORB_OPEN, QD__ORB_SINGULAR } qd__orb_end;

/* Walk from x0 in direction dir with steps growing from 1e-3 scale by 5%
 * until f changes sign from its sign at x0 (FOUND: *a, *b bracket it, a
 * nearer x0), f is not finite or the walk crosses 0 where V_eff is not
 * finite (SINGULAR: *a the last good point, *b the singular one), or the
 * walk goes 1e8 scale away (OPEN).  A zero f at x0 takes the sign of the
 * first step. */
qd__orb_end qd__orb_scan(qd__orb_env *env, qd__orb_fn f, double x0, int dir, double *a, double *b);

/* A root of f in [a, b] with f(a) f(b) <= 0 (Brent's zeroin, Brent 1973
 * ch. 4), to round-off. */
double qd__orb_brent(qd__orb_env *env, qd__orb_fn f, double a, double b);

/* The stationary points of V_eff between the singular points around x0
 * (the nearest 8 each way), ascending, in a malloc'd array (*n of them);
 * false when out of memory. */
bool qd__orb_circles(qd_ctx *ctx, qd__orb_env *env, double x0, double **xs, size_t *n);

/* The quadratures of a bound or capture orbit (quad.c's tanh-sinh). */
qd_status qd__orb_quadratures(qd_ctx *ctx, qd__orb_env *env, qd_orbit_result *r);

/* Kepler's conic in closed form (o->kepler), from the state (x0, xd0,
 * the ignored coordinate's value c0). */
void qd__orb_conic(qd__orb_env *env, double x0, double xd0, double c0, qd_orbit_result *r);

#endif

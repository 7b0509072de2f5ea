/*
 * src/action/act.h - the action module's internals (prefix qd__act_):
 * one separated coordinate as a numeric function p^2(q) (cycle.c), its
 * cycle and integrals, and the separation of one degree of freedom made
 * here without qd_hj (sep1.c).
 */
#ifndef QD_ACTION_ACT_H
#define QD_ACTION_ACT_H

#include "qdot/action.h"
#include "qdot/eval.h"
#include "qdot/hamilton.h"

/* p_k^2 of one coordinate compiled with the constants and parameters as
 * inputs: out[0..4) = p^2 and its first three derivatives in q (the
 * Taylor steps at the turning points), out[4 + j] = dp^2/dalpha_j. */
typedef struct qd__act_fn {
    qd_prog *prog;
    size_t nc;           /* the constants */
    double *in, *out;
} qd__act_fn;

/* Compile p2 (in q, the nc constants and symbols given by syms/vals) with
 * the constants at cvals.  false on failure (reason in ctx). */
bool qd__act_fn_init(qd_ctx *ctx, qd__act_fn *f, const qd_expr *p2, const qd_expr *q, size_t nc,
                     const qd_expr *const *constants, const double *cvals, size_t nvals,
                     const qd_expr *const *syms, const double *vals);
void qd__act_fn_free(qd__act_fn *f);
/* p^2 at x (out[] filled with every output at x). */
double qd__act_p2(qd__act_fn *f, double x);

/* The cycle of q through q0: the turning points around q0 (a libration),
 * or a whole period of an angle (a rotation). */
typedef struct qd__act_cycle {
    qd_act_kind kind;
    double lo, hi;
    double dlo[3], dhi[3];  /* p^2', p^2'', p^2''' at the turning points */
} qd__act_cycle;

/* QD_ACT_OK, or why there is no cycle. */
qd_act_fail qd__act_cycle_find(qd__act_fn *f, double q0, bool angle, qd__act_cycle *c);

/* J = oint p dq and dJ[j] = dJ/dalpha_j over the cycle; false (NaN
 * results) when a quadrature did not converge. */
bool qd__act_integrals(qd__act_fn *f, const qd__act_cycle *c, double *J, double *dJ);

/* beta[j] = dW/dalpha_j of this coordinate at x, W = int p dq along the
 * cycle from its origin (the lower turning point; a multiple of 2 pi for a
 * rotation), the state moving with p of that sign; dJ[j] = dJ/dalpha_j.
 * false (NaN results) when a quadrature did not converge. */
bool qd__act_phase(qd__act_fn *f, const qd__act_cycle *c, double x, int sign, const double *dJ,
                   double *beta);

/* Which of q[0..n) are angles: they enter the model (T, V, L, H, the
 * positions of particles and bodies) inside sin, cos or tan.  false when
 * out of memory (recorded in ctx). */
bool qd__act_angles(qd_ctx *ctx, const qd_model *m, size_t n, const qd_expr *const *q,
                    bool *angle);

/* One degree of freedom separated without qd_hj: H = a(q) p^2 + c(q) = E
 * gives p^2 = (E - c)/a; the constant is E, its integral H in q and p
 * (qd_action_at puts the state's momenta beside its velocities).
 * NULL when H is not of that form (reason in ctx); freed by
 * qd__act_sep1_free. */
qd_hj *qd__act_sep1(qd_ctx *ctx, const qd_ham *h, const char *energy_name);
void qd__act_sep1_free(qd_hj *h);

#endif

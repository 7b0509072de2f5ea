/*
 * src/rel/rel.h - what the relativity toolkit's files share (prefix qd__rel_).
 */
#ifndef QD_REL_PRIV_H
#define QD_REL_PRIV_H

#include "qdot/relativity.h"

double qd__rel_dot(const double a[3], const double b[3]);
/* c > 0 and finite, and |v| < c; what names v in the message. */
qd_status qd__rel_check(qd_ctx *ctx, double c, const double v[3], const char *what);
/* Gamma of V and k = (Gamma - 1)/V^2 = Gamma^2/((Gamma + 1) c^2), finite at V = 0. */
void qd__rel_gk(double c, const double V[3], double *G, double *k);

#endif

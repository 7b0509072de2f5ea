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

/* read.c: three expressions in t, c replaced ("0.8*c, 0, 0"); how many
 * comma-separated items text holds. */
qd_status qd__rel_read_exprs(qd_ctx *ctx, double c, const char *field, const char *text,
                             const qd_expr *out[3]);
size_t qd__rel_count(const char *text);
/* qd_rel_read_particle for item index of a list (in the error record). */
qd_status qd__rel_read_particle(qd_ctx *ctx, double c, const char *field, size_t index,
                                const char *text, qd_rel_particle *out);

/* An error about field (qd_diag.name, subject NONE) with the message fmt. */
qd_status qd__rel_refuse(qd_ctx *ctx, const char *field, const char *fmt, ...)
#ifdef __GNUC__
    __attribute__((format(printf, 3, 4)))
#endif
    ;

#endif

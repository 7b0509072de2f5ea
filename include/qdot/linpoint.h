/*
 * qdot/linpoint.h - the point a linear analysis is taken about, read
 * against the equations' coordinates (issue 31: what `qdot modes`,
 * `equilibria`, `linearize` and `zvc` share).
 *
 * The equations may be derived with holonomic constraints eliminated, so
 * their coordinates e->q are fewer than the model's: a qd_linpoint is the
 * model's state (qdot/state.h's layout) with the slot of each of e's
 * coordinates in it.  Every value read from text is matched to e->q by
 * symbol, and a coordinate that a constraint eliminated is refused by name
 * (the state reader's error, located in the text) rather than taken for
 * another one.  Arrays of values here have e->n entries in the order of
 * e->q.
 */
#ifndef QDOT_LINPOINT_H
#define QDOT_LINPOINT_H

#include <stdbool.h>
#include <stddef.h>
#include "mech.h"
#include "model.h"
#include "state.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct qd_linpoint {
    const qd_model *m;   /* borrowed */
    const qd_eom *e;     /* borrowed: derived from m */
    qd_state st;         /* m's state: coordinates, velocities and t 0, parameters at their
                            values */
    size_t *slot;        /* e->n: the slot in st of e->q[j] */
} qd_linpoint;

/* m's state and the slots of e's coordinates (e derived from m).
 * QD_ERR_ARG when a coordinate of e is not m's; QD_ERR_NOMEM.  *out is
 * overwritten; free it with qd_linpoint_free (also after a failure). */
QD_API qd_status qd_linpoint_init(qd_ctx *ctx, const qd_model *m, const qd_eom *e,
                                  qd_linpoint *out);
QD_API void qd_linpoint_free(qd_linpoint *p);

/* q and qd (NULL: at rest) into p->st at the coordinates' slots. */
QD_API void qd_linpoint_set(qd_linpoint *p, const double *q, const double *qd);

/* "q1=VALUE, q1'=VALUE, ...": the values named go to q and qd (the others
 * keep theirs).  Refused, as errors of qd_state_read located in text: t,
 * the parameters, an eliminated coordinate and, when qd is NULL (a point at
 * rest), the velocities.  p->st is not changed. */
QD_API qd_status qd_linpoint_read(qd_ctx *ctx, const qd_linpoint *p, const char *text,
                                  double *q, double *qd);
/* The same for coordinates alone, the unnamed ones 0. */
QD_API qd_status qd_linpoint_read_coords(qd_ctx *ctx, const qd_linpoint *p, const char *text,
                                         double *q);
/* "q1=A:B, ...": a box (qd_state_read_ranges); the unnamed coordinates keep
 * lo and hi as given. */
QD_API qd_status qd_linpoint_read_box(qd_ctx *ctx, const qd_linpoint *p, const char *text,
                                      double *lo, double *hi);
/* "x = 1/2 - mu, ...": each coordinate's value as read, an exact expression
 * in the parameters (unnamed ones 0): the point a scan follows
 * (qd_scan_opts.about). */
QD_API qd_status qd_linpoint_read_exact(qd_ctx *ctx, const qd_linpoint *p, const char *text,
                                        const qd_expr **about);

#ifdef __cplusplus
}
#endif

/* NULL (issue 30): a function of this header given NULL for a pointer it
 * needs does nothing and returns QD_ERR_ARG (recorded in ctx when ctx is
 * given); a void function returns, and qd_linpoint_free accepts NULL. NULL
 * is an accepted value, as documented at the function, for:
 * qd_linpoint_set (qd); qd_linpoint_read (qd). */
#endif

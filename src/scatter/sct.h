/*
 * src/scatter/sct.h - the scattering module's internals (prefix qd__sct_):
 * the compiled potential with its jumps, the radial scan that finds the
 * turning point, and the deflection integral (deflect.c), shared with the
 * cross sections (section.c).
 */
#ifndef QD_SCATTER_SCT_H
#define QD_SCATTER_SCT_H

#include "qdot/scatter.h"
#include "qdot/eval.h"

#define QD_SCT_MAX_JUMPS 16

struct qd_scatter {
    const qd_expr *V, *r;
    qd_prog *prog;      /* r -> V, V', V'', V''' (the derivatives away from the jumps) */
    double core;        /* hard core radius, 0 when none */
    bool absorbing;     /* the core absorbs what reaches it (qd_scatter_set_absorbing) */
    size_t njump;
    double jump[QD_SCT_MAX_JUMPS]; /* ascending, all > core */
    double range;       /* V = 0 beyond it, or +inf */
};

/* V and its first three derivatives at r, taken on the side of r's
 * segment [lo, hi] between jumps (r clamped inside it, so a point at the
 * jump itself sees that side's value, not step's 1/2). */
void qd__sct_eval(qd_scatter *s, double r, double lo, double hi, double out[4]);
double qd__sct_V(qd_scatter *s, double r, double lo, double hi);

/* The segment of the jumps (and core, and 0, inf) that contains r, with r
 * taken just above a jump when it sits on one (side > 0) or just below. */
void qd__sct_segment(const qd_scatter *s, double r, int side, double *lo, double *hi);

/* The length the scans are measured in: max(b, core, the last jump, 1). */
double qd__sct_scale(const qd_scatter *s, double b);

#endif

/*
 * include/qdot/scanplot.h - the eigenvalues of a constrained linearization
 * against the parameter a scan follows, as a picture (issue 37: the
 * Whipple bicycle's eigenvalues against its speed v, with the weave and
 * capsize speeds marked; src/linear/conlin_scan_plot.c).
 */
#ifndef QDOT_SCANPLOT_H
#define QDOT_SCANPLOT_H

#include "qdot/conlin.h"
#include "qdot/plot.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Two panels against the parameter name (the x axis): the real parts of
 * every eigenvalue of every sample of s (dots: the branches are not
 * followed, so that a crossing is never drawn as a wrong join), and their
 * imaginary parts (s = +-omega i drawn once, omega >= 0).  Each change of
 * stability in s->cross is a vertical line in both panels, its legend
 * "NAME = V: a complex pair crosses (stable above)" or "... a real
 * eigenvalue crosses 0 (unstable above)".  title may be NULL.  *out a new
 * plot (qd_plot_free) on QD_OK, NULL otherwise; QD_ERR_ARG for a scan
 * with no samples. */
QD_API qd_status qd_conlin_scan_plot(qd_ctx *ctx, const qd_conlin_scan *s, const char *name,
                                     const char *title, qd_plot **out);

#ifdef __cplusplus
}
#endif

#endif

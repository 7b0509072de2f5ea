/*
 * cli/progress.h - the progress bar of the long runs (simulate, poincare,
 * animate): on a terminal only, so redirected output stays clean.
 */
#ifndef QDOT_CLI_PROGRESS_H
#define QDOT_CLI_PROGRESS_H

#include <stdbool.h>
#include <stddef.h>
#include <time.h>

typedef struct cli_progress {
    const char *what;        /* the command's name, shown before the bar */
    const char *label;       /* what t counts: "t" (set by start), "runs" (sweep) */
    struct timespec start, last;
    double delay;            /* seconds before the first bar: QDOT_PROGRESS_DELAY or 1 */
    bool on, shown, estimated; /* estimated: a bar with the time left was drawn */
} cli_progress;

/* Start timing; the bar is on when stderr is a terminal.  It first shows
 * after QDOT_PROGRESS_DELAY seconds (environment; 1 when unset). */
void cli_progress_start(cli_progress *p, const char *what);
/* The run is frac (0..1) done, at time t of the motion: redraw the bar
 * with the time left, once the run has taken the delay and at most ten
 * times a second (the first bar with a time left is drawn at once). */
void cli_progress_update(cli_progress *p, double frac, double t);
/* Erase the bar (when it was shown); returns the wall time in seconds. */
double cli_progress_end(cli_progress *p);
/* A qd_progress_fn (qd_ctx_set_progress) drawing p, erased at done == total. */
int cli_progress_steps(void *p, const char *what, size_t done, size_t total);

#endif

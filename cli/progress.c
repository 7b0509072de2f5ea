/*
 * cli/progress.c - the progress bar on stderr: a run that ends within a
 * second never shows one, and a redirected stderr never does (isatty), so
 * logs and pipes get only the summary lines.  QDOT_PROGRESS_DELAY (seconds,
 * >= 0) replaces that second: tests set it to 0 to see the bar however
 * fast the machine is (docs/cli.md, Progress).
 */
#define _POSIX_C_SOURCE 200809L
#include "progress.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

#define BAR_WIDTH 30
#define FIRST_SHOW_S 1.0 /* short runs stay silent */
#define REDRAW_S 0.1

static double seconds(const struct timespec *a, const struct timespec *b) {
    return (double)(b->tv_sec - a->tv_sec) + 1e-9 * (double)(b->tv_nsec - a->tv_nsec);
}

/* The delay before the first bar: QDOT_PROGRESS_DELAY, else a second.  A
 * value that is not a number of seconds >= 0 is named and not used. */
static double first_show(void) {
    const char *v = getenv("QDOT_PROGRESS_DELAY");
    if (!v || !*v)
        return FIRST_SHOW_S;
    char *end;
    double d = strtod(v, &end);
    if (*end || !isfinite(d) || d < 0) {
        fprintf(stderr, "qdot: warning: QDOT_PROGRESS_DELAY='%s' is not a number of seconds "
                        ">= 0; the bar waits %g s\n", v, FIRST_SHOW_S);
        return FIRST_SHOW_S;
    }
    return d;
}

void cli_progress_start(cli_progress *p, const char *what) {
    p->what = what;
    p->label = "t";
    p->on = isatty(2);
    p->shown = false;
    p->estimated = false;
    p->delay = p->on ? first_show() : FIRST_SHOW_S;
    clock_gettime(CLOCK_MONOTONIC, &p->start);
    p->last = p->start;
}

/* "1m05s" or "12s": the estimate is rough, so whole seconds. */
static void format_left(char *out, size_t cap, double s) {
    long n = s > 0 && s < 1e7 ? (long)(s + 0.5) : 0;
    if (n >= 60)
        snprintf(out, cap, "%ldm%02lds", n / 60, n % 60);
    else
        snprintf(out, cap, "%lds", n);
}

void cli_progress_update(cli_progress *p, double frac, double t) {
    if (!p->on)
        return;
    struct timespec now;
    clock_gettime(CLOCK_MONOTONIC, &now);
    double wall = seconds(&p->start, &now);
    frac = frac < 0 ? 0 : frac > 1 ? 1 : frac;
    /* At most ten redraws a second, but the first bar that can tell the
     * time left is drawn at once, so that a bar shown says it. */
    bool first_estimate = frac > 0 && !p->estimated;
    if (wall < p->delay || (p->shown && !first_estimate && seconds(&p->last, &now) < REDRAW_S))
        return;
    p->last = now;
    p->estimated = p->estimated || frac > 0;
    char left[32] = "?";
    if (frac > 0)
        format_left(left, sizeof left, wall * (1 - frac) / frac);
    fprintf(stderr, "\rqdot: %s [%-*.*s] %3.0f%%  %s = %-10.4g  %s left   ", p->what, BAR_WIDTH,
            (int)(frac * BAR_WIDTH), "##############################", 100 * frac, p->label, t,
            left);
    p->shown = true;
}

double cli_progress_end(cli_progress *p) {
    struct timespec now;
    clock_gettime(CLOCK_MONOTONIC, &now);
    if (p->shown)
        fprintf(stderr, "\r%90s\r", "");
    p->shown = false;
    return seconds(&p->start, &now);
}

int cli_progress_steps(void *p, const char *what, size_t done, size_t total) {
    cli_progress *bar = p;
    (void)what;
    bar->label = "step";
    cli_progress_update(bar, total ? (double)done / (double)total : 1, (double)done);
    if (done >= total)
        cli_progress_end(bar);
    return 0;
}

/*
 * cli/progress.c - the progress bar on stderr: a run that ends within a
 * second never shows one, and a redirected stderr never does (isatty), so
 * logs and pipes get only the summary lines.
 */
#define _POSIX_C_SOURCE 200809L
#include "progress.h"

#include <stdio.h>
#include <unistd.h>

#define BAR_WIDTH 30
#define FIRST_SHOW_S 1.0 /* short runs stay silent */
#define REDRAW_S 0.1

static double seconds(const struct timespec *a, const struct timespec *b) {
    return (double)(b->tv_sec - a->tv_sec) + 1e-9 * (double)(b->tv_nsec - a->tv_nsec);
}

void cli_progress_start(cli_progress *p, const char *what) {
    p->what = what;
    p->label = "t";
    p->on = isatty(2);
    p->shown = false;
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
    if (wall < FIRST_SHOW_S || (p->shown && seconds(&p->last, &now) < REDRAW_S))
        return;
    p->last = now;
    frac = frac < 0 ? 0 : frac > 1 ? 1 : frac;
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

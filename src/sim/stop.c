/*
 * src/sim/stop.c - why a run stopped, as data (issue 31): the failing site
 * records a code, the time and the quantity next to the sentence it words,
 * and the run hands the record to its caller in qd_sim_stats, so that a
 * sweep, Python or a test reads the reason without parsing English.
 */
#include "simint.h"

void qd__sim_stop(qd_sim *s, qd_stop_code code, double t, double value) {
    if (s->stop.code == QD_STOP_NONE)
        s->stop = (qd_sim_stop){code, t, value};
}

/* One row per code: the machine name (qd_stop_name) beside the English
 * (qd_stop_str), so that a new code is given both in one place.  In the
 * enum's order, QD_STOP_FAILURE last: the count below then catches a code
 * added without its row. */
static const struct {
    qd_stop_code code;
    const char *name, *words;
} stops[] = {
    {QD_STOP_NONE, "none", "not run"},
    {QD_STOP_END, "end", "reached the end time"},
    {QD_STOP_EVENT, "event", "a terminal event"},
    {QD_STOP_CONTACT, "contact", "ended in contact"},
    {QD_STOP_CALLBACK, "callback", "stopped by the row callback"},
    {QD_STOP_REFUSED, "refused", "refused before the first step"},
    {QD_STOP_STEP_UNDERFLOW, "step_underflow", "step size underflow"},
    {QD_STOP_NO_CONVERGENCE, "no_convergence", "no convergence"},
    {QD_STOP_SOLVER_FAILURE, "solver_failure", "solver failure"},
    {QD_STOP_STEP_LIMIT, "step_limit", "step limit"},
    {QD_STOP_SINGULAR, "singular", "singular equations"},
    {QD_STOP_PROJECTION, "projection", "projection failure"},
    {QD_STOP_NONFINITE, "nonfinite", "non-finite state"},
    {QD_STOP_PAINLEVE, "painleve", "Painleve paradox"},
    {QD_STOP_STEP_COLLAPSE, "step_collapse", "step size collapse"},
    {QD_STOP_FAILURE, "failure", "failure"},
};
_Static_assert(sizeof stops / sizeof *stops == QD_STOP_FAILURE + 1, "a row for every stop code");

/* code's row, -1 outside the enum (a cast integer) */
static int row(qd_stop_code code) {
    for (size_t i = 0; i < sizeof stops / sizeof *stops; i++)
        if (stops[i].code == code)
            return (int)i;
    return -1;
}

const char *qd_stop_str(qd_stop_code code) {
    int i = row(code);
    return i < 0 ? "unknown" : stops[i].words;
}

const char *qd_stop_name(qd_stop_code code) {
    int i = row(code);
    return i < 0 ? "unknown" : stops[i].name;
}

bool qd_stop_ok(qd_stop_code code) {
    return code == QD_STOP_END || code == QD_STOP_EVENT || code == QD_STOP_CONTACT;
}

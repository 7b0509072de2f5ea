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

const char *qd_stop_str(qd_stop_code code) {
    switch (code) {
    case QD_STOP_NONE: return "not run";
    case QD_STOP_END: return "reached the end time";
    case QD_STOP_EVENT: return "a terminal event";
    case QD_STOP_CONTACT: return "ended in contact";
    case QD_STOP_CALLBACK: return "stopped by the row callback";
    case QD_STOP_REFUSED: return "refused before the first step";
    case QD_STOP_STEP_UNDERFLOW: return "step size underflow";
    case QD_STOP_NO_CONVERGENCE: return "no convergence";
    case QD_STOP_SOLVER_FAILURE: return "solver failure";
    case QD_STOP_STEP_LIMIT: return "step limit";
    case QD_STOP_SINGULAR: return "singular equations";
    case QD_STOP_PROJECTION: return "projection failure";
    case QD_STOP_NONFINITE: return "non-finite state";
    case QD_STOP_PAINLEVE: return "Painleve paradox";
    case QD_STOP_FAILURE: return "failure";
    }
    return "unknown";
}

const char *qd_stop_name(qd_stop_code code) {
    switch (code) {
    case QD_STOP_NONE: return "none";
    case QD_STOP_END: return "end";
    case QD_STOP_EVENT: return "event";
    case QD_STOP_CONTACT: return "contact";
    case QD_STOP_CALLBACK: return "callback";
    case QD_STOP_REFUSED: return "refused";
    case QD_STOP_STEP_UNDERFLOW: return "step_underflow";
    case QD_STOP_NO_CONVERGENCE: return "no_convergence";
    case QD_STOP_SOLVER_FAILURE: return "solver_failure";
    case QD_STOP_STEP_LIMIT: return "step_limit";
    case QD_STOP_SINGULAR: return "singular";
    case QD_STOP_PROJECTION: return "projection";
    case QD_STOP_NONFINITE: return "nonfinite";
    case QD_STOP_PAINLEVE: return "painleve";
    case QD_STOP_FAILURE: return "failure";
    }
    return "unknown";
}

bool qd_stop_ok(qd_stop_code code) {
    return code == QD_STOP_END || code == QD_STOP_EVENT || code == QD_STOP_CONTACT;
}

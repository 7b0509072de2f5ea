/*
 * src/sim/summary.c - the summary of a run (qdot/sim.h): its method,
 * steps, energy and constraint errors, events, impacts, friction switches
 * and why it stopped, as text (qd_sim_summary_print) or as members of a
 * JSON object (qd_sim_summary_json); the stop codes' machine names
 * (qd_stop_name).  `qdot simulate` prints these; Python and a sweep read
 * the same words.
 */
#include "simint.h"
#include "qdot/json.h"
#include "../base/args.h"
#include "../base/mem.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>

static bool report_ok(const qd_sim_report *r) {
    return r && r->s && r->opts && r->stats;
}

/* ---- text ------------------------------------------------------------------- */

/* One line: the prefix, then fmt. */
static void line(qd_buf *b, const char *prefix, const char *fmt, ...)
#ifdef __GNUC__
    __attribute__((format(printf, 3, 4)))
#endif
    ;
static void line(qd_buf *b, const char *prefix, const char *fmt, ...) {
    char small[512];
    va_list ap;
    va_start(ap, fmt);
    int n = vsnprintf(small, sizeof small, fmt, ap);
    va_end(ap);
    qd_buf_puts(b, prefix);
    if (n < 0)
        return;
    if ((size_t)n < sizeof small) {
        qd_buf_putn(b, small, (size_t)n);
        return;
    }
    /* a long line (long names): formatted again into the buffer's own memory */
    char *big = qd__mem_malloc(b->alloc, (size_t)n + 1);
    if (!big) {
        b->failed = true;
        return;
    }
    va_start(ap, fmt);
    vsnprintf(big, (size_t)n + 1, fmt, ap);
    va_end(ap);
    qd_buf_putn(b, big, (size_t)n);
    qd__free(big);
}

static const char *plural(size_t n) { return n == 1 ? "" : "s"; }

static void text_impacts(const qd_sim_report *r, const char *pre, qd_buf *b) {
    const qd_sim_stats *st = r->stats;
    const qd_model *m = r->s->model;
    line(b, pre, "%zu impact%s, energy lost %.6g\n", st->impacts, plural(st->impacts),
         st->impact_energy_lost);
    if (st->in_contact)
        line(b, pre, "impact '%s': %s%s from t = %.6g after %zu impact%s; the run ends there\n",
             qd_model_impact_name(m, st->contact), st->chattering ? "chattering; " : "",
             st->at_rest ? "at rest in contact"
                         : "in sustained contact, still moving (not simulated)",
             st->t, st->impacts, plural(st->impacts));
}

/* The velocities the start solved from the constraints (qd0_given). */
static void text_solved(const qd_sim_report *r, const char *pre, qd_buf *b) {
    const qd_sim *s = r->s;
    size_t at = 1 + s->n + (s->se ? s->nu : 0);
    qd_buf_printf(b, "%snote: solved from the velocity constraints, the velocities given kept:",
                  pre);
    for (size_t j = 0, k = 0; j < s->n; j++)
        if (qd_sim_initial_solved(s, j))
            qd_buf_printf(b, "%s %s", k++ ? "," : "", s->names[at + j]);
    qd_buf_printf(b, "\n");
}

static void text_friction(const qd_sim_report *r, const char *pre, qd_buf *b) {
    const qd_sim_stats *st = r->stats;
    /* the surfaces' work only where they moved */
    char work[64] = "";
    if (st->surface_work != 0)
        snprintf(work, sizeof work, ", work done by moving surfaces %.6g", st->surface_work);
    line(b, pre, "%zu stick/slip transition%s, energy dissipated by friction %.6g%s, energy "
                 "balance error %.3g\n",
         st->transitions, plural(st->transitions), st->friction_dissipated, work,
         st->energy_balance_error);
}

static void text_out(const qd_sim_report *r, const char *pre, qd_buf *b) {
    const qd_sim_stats *st = r->stats;
    /* where h is not conserved its drift is physics, not an error of the
     * integrator: "energy error 2.14" read like a fault (audit) */
    bool cons = qd_sim_conservative(r->s);
    line(b, pre,
         "%s, t = %g..%g: %zu steps, %zu evaluations, %zu rejected, %.3g s; energy %s %.3g "
         "over the rows written (%.3g at the steps), constraint error %.3g%s\n",
         qd_sim_method_name(r->opts->method), r->opts->t0, st->t, st->steps, st->evals,
         st->rejected, r->wall, cons ? "error" : "change", st->energy_error_max,
         st->energy_error_steps, st->constraint_error_max,
         cons ? "" : " (not conserved: forces, damping, t in L or a moving constraint)");
    if (!qd_stop_ok(st->stop.code))
        line(b, pre, "stopped early: %s at t = %.17g\n", qd_stop_str(st->stop.code),
             st->stop.t);
    if (st->events)
        line(b, pre, "%zu event%s\n", st->events, plural(st->events));
    if (st->events_unresolved)
        line(b, pre, "note: event %zu oscillates faster than the event search resolves in %zu "
                     "step%s (the first at t = %.17g): its crossings closer together than %.3g "
                     "(more than about %.3g per unit time) may have been missed; shorter steps "
                     "(a smaller rtol) resolve more\n",
             st->events_unresolved_event + 1, st->events_unresolved,
             plural(st->events_unresolved), st->events_unresolved_t,
             st->events_unresolved_spacing, 1 / st->events_unresolved_spacing);
    if (st->initial_moved_q > QD_SIM_MOVED_NOTE ||
        (st->initial_moved_qd > QD_SIM_MOVED_NOTE && !st->initial_solved))
        line(b, pre, "note: the initial state was off the constraints and was projected onto "
                     "them: q moved by %.3g, q' by %.3g\n",
             st->initial_moved_q, st->initial_moved_qd);
    if (st->initial_solved)
        text_solved(r, pre, b);
    if (qd_model_nimpacts(r->s->model))
        text_impacts(r, pre, b);
    if (qd_sim_ncontacts(r->s))
        text_friction(r, pre, b);
}

qd_status qd_sim_summary_print(const qd_sim_report *r, const char *prefix, qd_buf *out) {
    QD_ARGS(QD_ERR_ARG, report_ok(r) && out);
    text_out(r, prefix ? prefix : "", out);
    return out->failed ? QD_ERR_NOMEM : QD_OK;
}

/* ---- JSON ------------------------------------------------------------------- */

void qd_sim_stop_json(qd_json *j, const qd_sim_stop *stop) {
    QD_ARGS(, j && stop);
    qd_json_begin_object(j);
    qd_json_key(j, "code");
    qd_json_string(j, qd_stop_name(stop->code));
    qd_json_key(j, "reason");
    qd_json_string(j, qd_stop_str(stop->code));
    qd_json_key(j, "ok");
    qd_json_bool(j, qd_stop_ok(stop->code));
    qd_json_key(j, "t");
    qd_json_number_or_null(j, stop->t);
    qd_json_key(j, "value");
    qd_json_number_or_null(j, stop->value);
    qd_json_end_object(j);
}

static void json_impacts(qd_json *j, const qd_sim_report *r) {
    const qd_sim_stats *st = r->stats;
    qd_json_key(j, "impacts");
    qd_json_number(j, (double)st->impacts);
    qd_json_key(j, "impact_energy_lost");
    qd_json_number(j, st->impact_energy_lost);
    qd_json_key(j, "contact");
    if (!st->in_contact) {
        qd_json_null(j);
        return;
    }
    qd_json_begin_object(j);
    qd_json_key(j, "impact");
    qd_json_string(j, qd_model_impact_name(r->s->model, st->contact));
    qd_json_key(j, "t");
    qd_json_number(j, st->t);
    qd_json_key(j, "chattering");
    qd_json_bool(j, st->chattering);
    qd_json_key(j, "at_rest");
    qd_json_bool(j, st->at_rest);
    qd_json_end_object(j);
}

static void json_friction(qd_json *j, const qd_sim_report *r) {
    static const char *const mode[] = {"stick", "slip"};
    const qd_sim_stats *st = r->stats;
    size_t n = 0;
    const qd_sim_transition *tr = qd_sim_transitions(r->s, &n);
    qd_json_key(j, "friction_dissipated");
    qd_json_number(j, st->friction_dissipated);
    qd_json_key(j, "energy_balance_error");
    qd_json_number(j, st->energy_balance_error);
    qd_json_key(j, "surface_work");
    qd_json_number(j, st->surface_work);
    qd_json_key(j, "transitions");
    qd_json_begin_array(j);
    for (size_t i = 0; tr && i < n; i++) {
        qd_json_begin_object(j);
        qd_json_key(j, "t");
        qd_json_number(j, tr[i].t);
        qd_json_key(j, "contact");
        qd_json_string(j, qd_model_contact_name(r->s->model, tr[i].contact));
        qd_json_key(j, "from");
        qd_json_string(j, mode[tr[i].from]);
        qd_json_key(j, "to");
        qd_json_string(j, mode[tr[i].to]);
        qd_json_end_object(j);
    }
    qd_json_end_array(j);
}

static void json_unresolved(qd_json *j, const qd_sim_stats *st) {
    /* steps where an event function oscillated faster than the search resolves */
    qd_json_key(j, "events_unresolved");
    qd_json_begin_object(j);
    qd_json_key(j, "steps");
    qd_json_number(j, (double)st->events_unresolved);
    qd_json_key(j, "event");
    qd_json_number(j, (double)st->events_unresolved_event + 1);
    qd_json_key(j, "t");
    qd_json_number(j, st->events_unresolved_t);
    qd_json_key(j, "spacing");
    qd_json_number(j, st->events_unresolved_spacing);
    qd_json_end_object(j);
}

/* "final": the last row under the columns' names. */
static void json_final(qd_json *j, const qd_sim_report *r) {
    size_t n = qd_sim_columns(r->s, r->opts->method, NULL, 0);
    const char **names = qd__mem_malloc(j->out->alloc, (n + 1) * sizeof *names);
    if (!names) {
        j->out->failed = true;
        return;
    }
    qd_sim_columns(r->s, r->opts->method, names, n);
    qd_json_key(j, "final");
    qd_json_begin_object(j);
    for (size_t i = 0; i < n; i++) {
        qd_json_key(j, names[i]);
        qd_json_number(j, r->final[i]);
    }
    qd_json_end_object(j);
    qd__free(names);
}

static void json_out(qd_json *j, const qd_sim_report *r) {
    const qd_sim *s = r->s;
    const qd_sim_stats *st = r->stats;
    qd_json_key(j, "method");
    qd_json_string(j, qd_sim_method_name(r->opts->method));
    qd_json_key(j, "speeds"); /* integrated in the model's speeds */
    qd_json_bool(j, s->se != NULL);
    qd_json_key(j, "steps");
    qd_json_number(j, (double)st->steps);
    qd_json_key(j, "evaluations");
    qd_json_number(j, (double)st->evals);
    qd_json_key(j, "rejected");
    qd_json_number(j, (double)st->rejected);
    qd_json_key(j, "wall_s");
    qd_json_number(j, r->wall);
    qd_json_key(j, "energy_error_max"); /* over the rows written */
    qd_json_number(j, st->energy_error_max);
    qd_json_key(j, "energy_error_steps"); /* at the integrator's steps */
    qd_json_number(j, st->energy_error_steps);
    qd_json_key(j, "constraint_error_max");
    qd_json_number(j, st->constraint_error_max);
    qd_json_key(j, "constraint_errors"); /* by constraint: the worst residual of each */
    qd_json_begin_object(j);
    for (size_t k = 0; k < s->m; k++) {
        qd_json_key(j, s->cons[k].name);
        qd_json_number(j, qd_sim_constraint_error(s, k));
    }
    qd_json_end_object(j);
    qd_json_key(j, "events");
    qd_json_number(j, (double)st->events);
    if (st->events_unresolved)
        json_unresolved(j, st);
    if (st->stop.code != QD_STOP_END) {
        qd_json_key(j, "stop");
        qd_sim_stop_json(j, &st->stop);
    }
    if (qd_model_nimpacts(s->model))
        json_impacts(j, r);
    if (qd_sim_ncontacts(s))
        json_friction(j, r);
    if (r->final)
        json_final(j, r);
}

qd_status qd_sim_summary_json(qd_json *j, const qd_sim_report *r) {
    QD_ARGS(QD_ERR_ARG, j && j->out && report_ok(r));
    json_out(j, r);
    if (j->out->failed || j->nomem)
        return QD_ERR_NOMEM;
    return j->failed ? QD_ERR_NUMERIC : QD_OK;
}

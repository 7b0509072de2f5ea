/*
 * src/lyap/section_out.c - a surface of section written out as JSON
 * (qdot/lyapunov.h: qd_poincare_json_begin, qd_poincare_json_end; the
 * text summary of its runs is qd_poincare_print, orbits.c), of the shape
 * of simulate's: "model", "columns", "rows", then the run's
 * summary (qd_sim_summary_json's keys) and the crossings counted.
 */
#include "qdot/lyapunov.h"

#include "qdot/json.h"
#include "base/args.h"

qd_status qd_poincare_json_begin(qd_json *j, const char *model, size_t ncols,
                                 const char *const *names, bool rows) {
    QD_ARGS(QD_ERR_ARG, j && j->out && (names || !ncols || !rows));
    qd_json_begin_object(j);
    qd_json_key(j, "model");
    qd_json_string(j, model);
    if (rows) {
        qd_json_key(j, "columns");
        qd_json_begin_array(j);
        for (size_t i = 0; i < ncols; i++)
            qd_json_string(j, names[i]);
        qd_json_end_array(j);
        qd_json_key(j, "rows");
        qd_json_begin_array(j);
    }
    return j->out->failed ? QD_ERR_NOMEM : QD_OK;
}

qd_status qd_poincare_json_end(qd_json *j, const qd_sim *s, const qd_sim_opts *opts,
                               const qd_poincare_opts *o, const qd_poincare_result *r,
                               double wall, bool rows) {
    QD_ARGS(QD_ERR_ARG, j && j->out && s && opts && o && r);
    if (rows)
        qd_json_end_array(j);
    /* the run asked for want crossings ends at the last one: a terminal
     * event of the section, as the run's stop says it, not the sink's stop */
    qd_sim_stats stats = r->stats;
    if (r->got >= o->want && stats.stop.code == QD_STOP_CALLBACK)
        stats.stop = (qd_sim_stop){QD_STOP_EVENT, r->last_t, (double)o->event};
    qd_sim_report rep = {.s = s, .opts = opts, .stats = &stats, .final = NULL, .wall = wall};
    qd_status st = qd_sim_summary_json(j, &rep);
    qd_json_key(j, "crossings");
    qd_json_number(j, (double)r->got);
    qd_json_key(j, "wanted");
    qd_json_number(j, (double)o->want);
    qd_json_end_object(j);
    if (j->out->failed || j->nomem)
        return QD_ERR_NOMEM;
    return st != QD_OK ? st : j->failed ? QD_ERR_NUMERIC : QD_OK;
}

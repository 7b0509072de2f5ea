/*
 * src/sim/rows.c - what a run's rows carry and how they are sampled, as
 * `qdot simulate` writes them (qdot/sim.h): the event column, the JSON
 * description of the columns, the output grid of a run that is only drawn,
 * and the JSON description of the picture drawn.
 */
#include "simint.h"

#include <stdlib.h>

#include "../base/args.h"

/* j's state once its part is written: QD_ERR_NUMERIC for a number refused
 * (or nesting too deep), QD_ERR_NOMEM when its buffer failed. */
static qd_status failed(const qd_json *j) {
    if (j->failed)
        return j->nonfinite ? QD_ERR_NUMERIC : QD_ERR_ARG;
    return j->nomem || (j->out && j->out->failed) ? QD_ERR_NOMEM : QD_OK;
}

bool qd_sim_event_column(const qd_sim *s) {
    QD_ARGS(false, s);
    return s->nev > 0 || s->nimp > 0 || s->nfc > 0 ||
           (s->model && qd_model_nimpacts(s->model) > 0);
}

qd_status qd_sim_columns_json(qd_json *j, const qd_sim *s, qd_sim_method method) {
    QD_ARGS(QD_ERR_ARG, j && s);
    size_t n = qd_sim_columns(s, method, NULL, 0);
    const char **names = malloc((n + 1) * sizeof *names);
    if (!names)
        return QD_ERR_NOMEM;
    qd_sim_columns(s, method, names, n);
    qd_json_key(j, "columns");
    qd_json_begin_array(j);
    for (size_t i = 0; i < n; i++)
        qd_json_string(j, names[i]);
    if (qd_sim_event_column(s))
        qd_json_string(j, "event");
    qd_json_end_array(j);
    free(names);
    return failed(j);
}

void qd_sim_opts_sample(qd_sim_opts *o, size_t rows) {
    QD_ARGS(, o && rows > 0);
    /* a step of an adaptive method can span a swing: its dense output
     * sampled on a grid instead, so a picture shows the motion */
    if (qd_sim_method_adaptive(o->method) && !o->fixed && !(o->dt > 0))
        o->dt = (o->t_end - o->t0) / (double)rows;
}

qd_status qd_sim_plot_json(qd_json *j, const char *file, size_t npanels, const double *range) {
    QD_ARGS(QD_ERR_ARG, j && file && (npanels == 0 || range));
    qd_json_key(j, "plot");
    qd_json_begin_object(j);
    qd_json_key(j, "file");
    qd_json_string(j, file);
    qd_json_key(j, "panels");
    qd_json_begin_array(j);
    static const char *const keys[] = {"x0", "x1", "y0", "y1"};
    for (size_t g = 0; g < npanels; g++) {
        qd_json_begin_object(j);
        for (int k = 0; k < 4; k++) {
            qd_json_key(j, keys[k]);
            qd_json_number(j, range[4 * g + (size_t)k]);
        }
        qd_json_end_object(j);
    }
    qd_json_end_array(j);
    qd_json_end_object(j);
    return failed(j);
}

/*
 * src/sweep/write.c - a sweep's rows written as CSV or JSON: the columns
 * (inputs, then measures), and per run its numbers and its status, "ok" or
 * why it failed.  One writer for the CLI and any other caller.
 */
#include "sweep_int.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "qdot/json.h"
#include "qdot/print.h"
#include "../base/args.h"

const char *qd_sweep_outcome_str(const qd_sweep_outcome *o, char *out, size_t cap) {
    QD_ARGS(NULL, o && out && cap);
    const qd_sim_stop *s = &o->stop;
    if (o->status == QD_OK)
        snprintf(out, cap, "ok");
    else if (s->code != QD_STOP_NONE && !qd_stop_ok(s->code) && isfinite(s->t))
        snprintf(out, cap, "%s at t = %.6g", qd_stop_str(s->code), s->t);
    else if (s->code != QD_STOP_NONE && !qd_stop_ok(s->code))
        snprintf(out, cap, "%s", qd_stop_str(s->code));
    else /* not an integration's failure: before it, or in what follows it */
        snprintf(out, cap, "%s", qd_status_str(o->status));
    return out;
}

/* A CSV field, quoted when it holds a comma, a quote or a newline. */
static void csv_field(qd_buf *out, const char *s) {
    if (!strpbrk(s, ",\"\n\r")) {
        qd_buf_puts(out, s);
        return;
    }
    qd_buf_puts(out, "\"");
    for (; *s; s++)
        qd_buf_puts(out, *s == '"' ? "\"\"" : (char[2]){*s, 0});
    qd_buf_puts(out, "\"");
}

qd_status qd_sweep_csv(const qd_sweep *w, const double *rows, const qd_sweep_outcome *outcome,
                       qd_buf *out) {
    QD_ARGS(QD_ERR_ARG, w && (rows || !w->nruns) && (outcome || !w->nruns) && out);
    char num[QD_DOUBLE_MAX], why[QD_SWEEP_OUTCOME_MAX];
    for (size_t j = 0; j < w->ncols; j++) {
        csv_field(out, w->cols[j]);
        qd_buf_puts(out, ",");
    }
    qd_buf_puts(out, "status\n");
    for (size_t k = 0; k < w->nruns; k++) {
        for (size_t j = 0; j < w->ncols; j++) {
            qd_double_format(num, rows[k * w->ncols + j]);
            qd_buf_puts(out, num);
            qd_buf_puts(out, ",");
        }
        csv_field(out, qd_sweep_outcome_str(&outcome[k], why, sizeof why));
        qd_buf_puts(out, "\n");
    }
    return out->failed ? QD_ERR_NOMEM : QD_OK;
}

qd_status qd_sweep_json(const qd_sweep *w, const double *rows, const qd_sweep_outcome *outcome,
                        qd_buf *out) {
    QD_ARGS(QD_ERR_ARG, w && (rows || !w->nruns) && (outcome || !w->nruns) && out);
    char why[QD_SWEEP_OUTCOME_MAX];
    qd_json j;
    qd_json_init(&j, out);
    qd_json_begin_object(&j);
    qd_json_key(&j, "columns");
    qd_json_begin_array(&j);
    for (size_t c = 0; c < w->ncols; c++)
        qd_json_string(&j, w->cols[c]);
    qd_json_end_array(&j);
    qd_json_key(&j, "rows"); /* NaN (no value) as null */
    qd_json_begin_array(&j);
    for (size_t k = 0; k < w->nruns; k++) {
        qd_json_begin_array(&j);
        for (size_t c = 0; c < w->ncols; c++)
            qd_json_number_or_null(&j, rows[k * w->ncols + c]);
        qd_json_end_array(&j);
    }
    qd_json_end_array(&j);
    qd_json_key(&j, "status");
    qd_json_begin_array(&j);
    for (size_t k = 0; k < w->nruns; k++)
        qd_json_string(&j, qd_sweep_outcome_str(&outcome[k], why, sizeof why));
    qd_json_end_array(&j);
    qd_json_key(&j, "stop");
    qd_json_begin_array(&j);
    for (size_t k = 0; k < w->nruns; k++)
        qd_sim_stop_json(&j, &outcome[k].stop);
    qd_json_end_array(&j);
    qd_json_end_object(&j);
    qd_buf_puts(out, "\n");
    return out->failed ? QD_ERR_NOMEM : j.failed ? QD_ERR_ARG : QD_OK;
}

/*
 * src/sim/writer.c - a run's rows as `qdot simulate` writes them
 * (qdot/sim.h): the CSV header and lines, a row as JSON, and the writer a
 * run's sink hands each row to.  The CLI, Python and a C caller get the
 * same bytes from here.
 */
#include "simint.h"

#include <math.h>
#include <stdlib.h>

#include "../base/args.h"

qd_status qd_sim_csv_header(const qd_sim *s, qd_sim_method method, qd_buf *out) {
    QD_ARGS(QD_ERR_ARG, s && out);
    size_t n = qd_sim_columns(s, method, NULL, 0);
    const char **names = malloc((n + 1) * sizeof *names);
    if (!names)
        return QD_ERR_NOMEM;
    qd_sim_columns(s, method, names, n);
    for (size_t i = 0; i < n; i++) {
        qd_buf_puts(out, i ? "," : "");
        qd_buf_puts(out, names[i]);
    }
    free(names);
    qd_buf_puts(out, qd_sim_event_column(s) ? ",event\n" : "\n");
    return out->failed ? QD_ERR_NOMEM : QD_OK;
}

qd_status qd_sim_csv_row(size_t ncols, const double *row, bool event_column, int event,
                         qd_buf *out) {
    QD_ARGS(QD_ERR_ARG, (row || ncols == 0) && out);
    for (size_t i = 0; i < ncols; i++) {
        qd_buf_puts(out, i ? "," : "");
        qd_buf_put_double(out, row[i]);
    }
    if (event_column)
        qd_buf_printf(out, ",%d", event + 1);
    qd_buf_puts(out, "\n");
    return out->failed ? QD_ERR_NOMEM : QD_OK;
}

qd_status qd_sim_json_row(qd_json *j, size_t ncols, const double *row, bool event_column,
                          int event) {
    QD_ARGS(QD_ERR_ARG, j && (row || ncols == 0));
    qd_json_begin_array(j);
    for (size_t i = 0; i < ncols; i++)
        qd_json_number(j, row[i]);
    if (event_column)
        qd_json_number(j, event + 1);
    qd_json_end_array(j);
    if (j->failed)
        return j->nonfinite ? QD_ERR_NUMERIC : QD_ERR_ARG;
    return j->nomem || (j->out && j->out->failed) ? QD_ERR_NOMEM : QD_OK;
}

qd_status qd_sim_writer_init(qd_sim_writer *w, const qd_sim *s, qd_sim_method method) {
    QD_ARGS(QD_ERR_ARG, w && s);
    w->s = s;
    w->method = method;
    w->ncols = qd_sim_columns(s, method, NULL, 0);
    w->rows = 0;
    w->event_column = qd_sim_event_column(s);
    w->header = w->failed = false;
    w->last_t = NAN;
    w->line = (qd_buf)QD_BUF_INIT;
    return QD_OK;
}

/* The row's CSV line (after the header, the first time) handed to write. */
static bool write_csv(qd_sim_writer *w, int event, const double *row) {
    qd_buf_clear(&w->line);
    if (!w->header && qd_sim_csv_header(w->s, w->method, &w->line) != QD_OK)
        return false;
    w->header = true;
    return qd_sim_csv_row(w->ncols, row, w->event_column, event, &w->line) == QD_OK &&
           w->write(w->data, w->line.s, w->line.len) == 0;
}

int qd_sim_writer_sink(void *data, int event, const double *row) {
    qd_sim_writer *w = data;
    QD_ARGS(-1, w && w->s && row);
    if (w->failed)
        return -1;
    bool ok = w->write ? write_csv(w, event, row)
              : w->json ? qd_sim_json_row(w->json, w->ncols, row, w->event_column, event) == QD_OK
                        : true;
    if (!ok) {
        w->failed = true; /* the data is lost: the run stops here */
        return -1;
    }
    w->rows++;
    w->last_t = row[0];
    return w->tap ? w->tap(w->tap_data, event, row) : 0;
}

void qd_sim_writer_free(qd_sim_writer *w) {
    if (w)
        qd_buf_free(&w->line);
}

/*
 * src/lyap/flow_rows.c - the flow Jacobian along a run as CSV rows
 * (qd_flow_run_csv, qdot/lyapunov.h): t, the state, then d y_i/d y_j(t0)
 * column by column, as `qdot simulate --variational columns` writes them.
 */
#include "qdot/lyapunov.h"
#include "../base/args.h"

typedef struct rows_out {
    qd_sim_write_fn write;
    void *data;
    size_t d;
    qd_buf line;
    bool lost;
} rows_out;

/* The line in o->line handed on; a loss is kept in o->lost. */
static bool hand_on(rows_out *o) {
    o->lost = o->lost || o->line.failed || o->write(o->data, o->line.s, o->line.len) != 0;
    qd_buf_clear(&o->line);
    return !o->lost;
}

static int row(void *data, double t, const double *y, const double *phi) {
    rows_out *o = data;
    qd_buf_put_double(&o->line, t);
    for (size_t i = 0; i < o->d; i++) {
        qd_buf_puts(&o->line, ",");
        qd_buf_put_double(&o->line, y[i]);
    }
    for (size_t j = 0; j < o->d; j++) /* phi column by column, as the header names it */
        for (size_t i = 0; i < o->d; i++) {
            qd_buf_puts(&o->line, ",");
            qd_buf_put_double(&o->line, phi[i * o->d + j]);
        }
    qd_buf_puts(&o->line, "\n");
    return hand_on(o) ? 0 : 1;
}

/* The header and the row at t0: the initial state, phi = I. */
static bool first_rows(rows_out *o, const qd_eom *e, const qd_sim_opts *opts) {
    for (size_t k = 0; k < 1 + o->d + o->d * o->d; k++) {
        qd_buf_puts(&o->line, k ? "," : "");
        qd_flow_column_name(e, k, &o->line);
    }
    qd_buf_puts(&o->line, "\n");
    if (!hand_on(o))
        return false;
    qd_buf_put_double(&o->line, opts->t0);
    for (size_t i = 0; i < o->d; i++) {
        qd_buf_puts(&o->line, ",");
        qd_buf_put_double(&o->line, i < e->n ? opts->q0[i] : opts->qd0[i - e->n]);
    }
    for (size_t k = 0; k < o->d * o->d; k++)
        qd_buf_puts(&o->line, k % (o->d + 1) ? ",0" : ",1");
    qd_buf_puts(&o->line, "\n");
    return hand_on(o);
}

qd_status qd_flow_run_csv(qd_ctx *ctx, const qd_lyap *l, const qd_eom *e,
                          const qd_sim_opts *opts, double every, qd_sim_write_fn write,
                          void *data, qd_flow *out) {
    QD_ARGS_CTX(ctx, l && e && opts && opts->q0 && opts->qd0 && write && out);
    *out = (qd_flow){0};
    rows_out o = {.write = write, .data = data, .d = 2 * e->n};
    /* the spacing asked for, else the run's own (rows every --dt, or a
     * fixed step), else 100 rows */
    every = every > 0         ? every
            : opts->every > 0 ? opts->every
            : opts->dt > 0    ? opts->dt
                              : (opts->t_end - opts->t0) / 100;
    qd_flow_opts fo = {.every = every, .sink = row, .data = &o};
    qd_status st = first_rows(&o, e, opts) ? qd_flow_run(ctx, l, opts, &fo, out) : QD_OK;
    qd_buf_free(&o.line);
    if (!o.lost)
        return st;
    /* the stop a lost row asked for is not the run's failure: the rows are */
    qd_ctx_clear_error(ctx);
    qd_ctx_error(ctx, QD_ERR_IO, "the flow's rows could not be written");
    return QD_ERR_IO;
}

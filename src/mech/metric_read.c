/*
 * src/mech/metric_read.c - a force read by its covariant components from
 * text, "G1, G2, ..." (qd_metric_force_read, qdot/metric.h): the reading
 * `qdot metric --force` and any other caller share, errors located in the
 * text.
 */
#include <stdio.h>
#include <stdlib.h>
#include "qdot/metric.h"
#include "qdot/read.h"
#include "qdot/state.h"
#include "base/args.h"
#include "base/diag.h"

/* The error at text[off, off + len), a QD_ERR_ARG with a hint. */
static qd_status mr_fail(qd_ctx *ctx, const char *text, size_t off, size_t len,
                         const char *msg, const char *hint) {
    qd_ctx_error(ctx, QD_ERR_ARG, "%s", msg);
    qd_ctx_error_about(ctx, QD_SUBJECT_TEXT, 0, NULL, QD_REASON_NONE, hint);
    qd_ctx_error_at(ctx, text, off, len ? len : 1);
    return QD_ERR_ARG;
}

qd_status qd_metric_force_read(qd_ctx *ctx, const qd_metric *g, const char *text,
                               const qd_expr **G) {
    QD_ARGS_CTX(ctx, ctx && g && text && G);
    size_t n = g->n, k = 0, a = 0, len = 0;
    while (text[len])
        len++;
    char hint[160];
    snprintf(hint, sizeof hint, "give %zu covariant component%s G_i = F . dx/dq_i, one per "
             "coordinate, separated by commas", n, n == 1 ? "" : "s");
    for (; text[a]; k++) { /* a trailing comma ends the list */
        size_t b = qd_state_item_end(text, a);
        if (k == n) {
            while (text[a] == ' ' || text[a] == '\t')
                a++;
            char msg[128];
            snprintf(msg, sizeof msg, "the model has %zu coordinate%s; more components given",
                     n, n == 1 ? "" : "s");
            return mr_fail(ctx, text, a, len - a, msg, hint);
        }
        char *copy = qd__diag_blanked(text, a, b); /* the reader's place is the text's */
        if (!copy) {
            qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory");
            return QD_ERR_NOMEM;
        }
        const qd_read_opts opts = {.new_symbols = false};
        G[k] = qd_read(ctx, copy, &opts, NULL);
        free(copy);
        if (!G[k]) {
            qd_status st = qd_ctx_status(ctx);
            return st != QD_OK ? st : QD_ERR_PARSE;
        }
        a = text[b] ? b + 1 : b;
    }
    if (k != n) {
        char msg[128];
        snprintf(msg, sizeof msg, "%zu component%s for %zu coordinate%s", k, k == 1 ? "" : "s",
                 n, n == 1 ? "" : "s");
        return mr_fail(ctx, text, 0, len, msg, hint);
    }
    return QD_OK;
}

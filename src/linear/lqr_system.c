/*
 * src/linear/lqr_system.c - a state-space system and its weights read from
 * text (qd_lqr_system_read, qdot/control.h), each error named by the text
 * it is about so that a caller can point into that text.
 */
#include "qdot/control.h"

#include <string.h>

#include "../base/args.h"
#include "../base/mem.h"

/* The current error said to be about field (its location kept). */
static qd_status about(qd_ctx *ctx, qd_status st, const char *field) {
    qd_ctx_error_about(ctx, qd_ctx_diag(ctx)->located ? QD_SUBJECT_TEXT : QD_SUBJECT_NONE, 0,
                       field, QD_REASON_NONE, NULL);
    return st;
}

qd_status qd_lqr_system_read(qd_ctx *ctx, const char *A, const char *B, const char *weights,
                             qd_lqr_system *out) {
    QD_ARGS_CTX(ctx, ctx && A && B && weights && out);
    memset(out, 0, sizeof *out);
    qd_status st = qd_matrix_read(ctx, A, &out->A);
    if (st != QD_OK)
        return about(ctx, st, "A");
    size_t n = out->A.rows;
    if (out->A.cols != n) {
        qd_ctx_error(ctx, QD_ERR_ARG, "A is %zu by %zu; A must be square", n, out->A.cols);
        return about(ctx, QD_ERR_ARG, "A");
    }
    if ((st = qd_matrix_read(ctx, B, &out->B)) != QD_OK)
        return about(ctx, st, "B");
    if (out->B.rows != n) {
        qd_ctx_error(ctx, QD_ERR_ARG, "B has %zu rows; it needs one per state, %zu", out->B.rows,
                     n);
        return about(ctx, QD_ERR_ARG, "B");
    }
    size_t m = out->B.cols;
    out->Q = qd__malloc(ctx, (n * n + 1) * sizeof *out->Q);
    out->R = qd__malloc(ctx, (m * m + 1) * sizeof *out->R);
    if (!out->Q || !out->R)
        return QD_ERR_NOMEM;
    if ((st = qd_lqr_weights_read(ctx, weights, n, m, out->Q, out->R)) != QD_OK)
        return about(ctx, st, "weights");
    return QD_OK;
}

void qd_lqr_system_free(qd_lqr_system *s) {
    if (!s)
        return;
    qd_matrix_free(&s->A);
    qd_matrix_free(&s->B);
    qd__free(s->Q);
    qd__free(s->R);
    memset(s, 0, sizeof *s);
}

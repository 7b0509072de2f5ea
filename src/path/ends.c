/*
 * src/path/ends.c - one end of a path as the command line and Python give
 * it, "x=0, y=free, t=2" (qd_path_end_read, qdot/path.h).
 *
 * The state reader (qdot/state.h) reads every item but `free`: those are
 * marked and blanked in a copy of the same length, so the reader's errors
 * keep their offsets in the caller's text.
 */
#include "qdot/path.h"

#include <ctype.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "qdot/state.h"
#include "../base/args.h"

/* text[*a, *b) without its surrounding blanks. */
static void trim(const char *text, size_t *a, size_t *b) {
    while (*a < *b && isspace((unsigned char)text[*a]))
        (*a)++;
    while (*b > *a && isspace((unsigned char)text[*b - 1]))
        (*b)--;
}

/* The coordinate of e named text[a, b), or e->n. */
static size_t coord_named(const qd_eom *e, const char *text, size_t a, size_t b) {
    for (size_t j = 0; j < e->n; j++) {
        const char *s = qd_expr_name(e->q[j]);
        if (s && strlen(s) == b - a && !strncmp(s, text + a, b - a))
            return j;
    }
    return e->n;
}

/* Mark the `NAME=free` items in is_free[] and blank them in copy. */
static qd_status mark_free(qd_ctx *ctx, const qd_eom *e, const char *text, char *copy,
                           bool *is_free) {
    for (size_t i = 0; text[i];) {
        size_t end = qd_state_item_end(text, i);
        const char *eq = memchr(text + i, '=', end - i);
        if (eq) {
            size_t na = i, nb = (size_t)(eq - text), va = nb + 1, vb = end;
            trim(text, &na, &nb);
            trim(text, &va, &vb);
            if (vb - va == 4 && !strncmp(text + va, "free", 4)) {
                size_t j = coord_named(e, text, na, nb);
                if (j == e->n) {
                    qd_ctx_error(ctx, QD_ERR_ARG, "%.*s=free: only a coordinate can be free",
                                 (int)(nb - na), text + na);
                    qd_ctx_error_at(ctx, text, na, nb > na ? nb - na : 1);
                    return QD_ERR_ARG;
                }
                is_free[j] = true;
                memset(copy + i, ' ', end - i);
            }
        }
        i = text[end] ? end + 1 : end;
    }
    return QD_OK;
}

qd_status qd_path_end_read(qd_ctx *ctx, const qd_model *m, const qd_eom *e, const char *text,
                           double *q, double *t, bool *is_free) {
    QD_ARGS_CTX(ctx, ctx && m && e && text && q && t && is_free);
    size_t len = strlen(text);
    char *copy = malloc(len + 1);
    qd_state st = {0};
    bool *given = NULL;
    qd_status s = copy ? QD_OK : QD_ERR_NOMEM;
    if (copy)
        memcpy(copy, text, len + 1);
    if (s == QD_OK)
        s = mark_free(ctx, e, text, copy, is_free);
    if (s == QD_OK)
        s = qd_state_init(ctx, m, &st);
    if (s == QD_OK && !(given = calloc(st.n, sizeof *given)))
        s = QD_ERR_NOMEM;
    if (s == QD_OK) {
        qd_state_read_opts o = {.refuse = QD_STATE_VELOCITIES | QD_STATE_PARAMS | QD_STATE_EXTRA,
                                .independent = e->q, .nindependent = e->n, .given = given};
        s = qd_state_read(ctx, m, &st, copy, &o);
    }
    if (s == QD_OK) {
        for (size_t j = 0; j < e->n; j++) {
            size_t k = qd_state_find(&st, e->q[j]);
            if (k < st.n && given[k])
                q[j] = st.vals[k];
        }
        size_t kt = qd_slot_time(qd_model_ncoords(m));
        if (given[kt])
            *t = st.vals[kt];
    }
    if (s == QD_ERR_NOMEM && qd_ctx_status(ctx) == QD_OK)
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory reading a path's end");
    free(given);
    qd_state_free(&st);
    free(copy);
    return s;
}

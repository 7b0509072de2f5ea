/*
 * src/path/ends.c - one end of a path as the command line and Python give
 * it, "x=0, y=free, t=2" (qd_path_end_read, qdot/path.h), and a trial
 * path, "x = t^2, y = sin(t)" (qd_path_trial_read).
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

#include "qdot/read.h"
#include "qdot/state.h"
#include "../base/args.h"
#include "../base/diag.h"

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


/* One "NAME = EXPR" of a trial path, text[a, b). */
static qd_status trial_item(qd_ctx *ctx, const qd_model *m, const char *text, size_t a,
                            size_t b, const qd_expr **q) {
    const char *eq = memchr(text + a, '=', b - a);
    size_t na = a, nb = eq ? (size_t)(eq - text) : b, n = qd_model_ncoords(m), j = n;
    trim(text, &na, &nb);
    for (size_t k = 0; eq && k < n; k++) {
        const char *s = qd_expr_name(qd_model_coord(m, k));
        if (strlen(s) == nb - na && !strncmp(s, text + na, nb - na))
            j = k;
    }
    if (j == n || q[j]) {
        size_t ia = a, ib = b;
        trim(text, &ia, &ib);
        if (j == n)
            qd_ctx_error(ctx, QD_ERR_ARG, "expected COORDINATE = EXPR(t), not '%.*s'",
                         (int)(ib - ia), text + ia);
        else
            qd_ctx_error(ctx, QD_ERR_ARG, "'%.*s' is given twice", (int)(nb - na), text + na);
        qd_ctx_error_at(ctx, text, j == n ? ia : na, j == n ? ib - ia : nb - na);
        return QD_ERR_ARG;
    }
    char *copy = qd__diag_blanked(text, (size_t)(eq - text) + 1, b);
    if (!copy) {
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory reading a trial path");
        return QD_ERR_NOMEM;
    }
    const qd_read_opts opts = {.new_symbols = false}; /* t, the parameters, known names */
    q[j] = qd_read(ctx, copy, &opts, NULL);
    free(copy);
    return q[j] ? QD_OK : qd_ctx_status(ctx); /* located by the reader */
}

qd_status qd_path_trial_read(qd_ctx *ctx, const qd_model *m, const char *text,
                             const qd_expr **q) {
    QD_ARGS_CTX(ctx, ctx && m && text && q);
    size_t n = qd_model_ncoords(m);
    for (size_t j = 0; j < n; j++)
        q[j] = NULL;
    for (size_t a = 0; text[a];) {
        size_t b = qd_state_item_end(text, a);
        size_t ia = a, ib = b;
        trim(text, &ia, &ib);
        qd_status s = ia < ib ? trial_item(ctx, m, text, a, b, q) : QD_OK;
        if (s != QD_OK)
            return s;
        a = text[b] ? b + 1 : b;
    }
    for (size_t j = 0; j < n; j++)
        if (!q[j]) {
            qd_ctx_error(ctx, QD_ERR_ARG, "no trial path for %s (give every coordinate as an "
                         "expression in t)", qd_expr_name(qd_model_coord(m, j)));
            return QD_ERR_ARG;
        }
    return QD_OK;
}

/* ---- the whole problem's ends (qd_path_ends_read) ------------------------------ */

/* The error just recorded is about the text of field (its item index),
 * where it was located. */
static qd_status about(qd_ctx *ctx, const char *field, size_t index) {
    const qd_diag *d = qd_ctx_diag(ctx);
    qd_ctx_error_about(ctx, d->subject, index, field, d->reason, NULL);
    return qd_ctx_status(ctx);
}

static qd_status refuse(qd_ctx *ctx, const char *field, const char *msg, double a, double b) {
    qd_ctx_error(ctx, QD_ERR_ARG, msg, a, b);
    return about(ctx, field, 0);
}

/* Guess k: the velocities of text read over a state at rest. */
static qd_status guess_row(qd_ctx *ctx, const qd_model *m, size_t n, const char *text,
                           double *row) {
    qd_state st = {0};
    qd_status s = qd_state_init(ctx, m, &st);
    if (s == QD_OK)
        s = qd_state_read(ctx, m, &st, text, NULL);
    if (s == QD_OK)
        memcpy(row, st.vals + n, n * sizeof *row);
    qd_state_free(&st);
    return s;
}

qd_status qd_path_ends_read(qd_ctx *ctx, const qd_model *m, const qd_eom *e, const char *from,
                            const char *to, size_t nguess, const char *const *guess,
                            bool energy, qd_path_ends *ends, qd_path_opts *opts) {
    if (ends)
        *ends = (qd_path_ends){0};
    QD_ARGS_CTX(ctx, ctx && m && e && from && to && (guess || !nguess) && ends && opts);
    size_t n = e->n;
    ends->q0 = calloc(2 * n + nguess * n + 1, sizeof *ends->q0);
    ends->free0 = calloc(2 * n + 1, sizeof *ends->free0);
    if (!ends->q0 || !ends->free0) {
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory reading a path's ends");
        return QD_ERR_NOMEM;
    }
    ends->q1 = ends->q0 + n;
    ends->guess = ends->q1 + n;
    ends->free1 = ends->free0 + n;
    double t0 = 0, t1 = NAN;
    if (qd_path_end_read(ctx, m, e, from, ends->q0, &t0, ends->free0) != QD_OK)
        return about(ctx, "from", 0);
    if (qd_path_end_read(ctx, m, e, to, ends->q1, &t1, ends->free1) != QD_OK)
        return about(ctx, "to", 0);
    bool any_free = false;
    for (size_t j = 0; j < 2 * n; j++)
        any_free = any_free || ends->free0[j];
    if (energy && any_free)
        return refuse(ctx, "energy", "free ends need the end times, not an energy", 0, 0);
    if (!energy && isnan(t1)) {
        const char *x = qd_model_independent(m) ? qd_model_independent(m) : "t";
        qd_ctx_error(ctx, QD_ERR_ARG, "the end needs its time %s=T1 (or an energy)", x);
        return about(ctx, "to", 0);
    }
    for (size_t j = 0; j < n; j++) { /* a free coordinate starts from the other end's value */
        if (ends->free0[j])
            ends->q0[j] = ends->free1[j] ? 0 : ends->q1[j];
        if (ends->free1[j])
            ends->q1[j] = ends->free0[j] ? 0 : ends->q0[j];
    }
    for (size_t k = 0; k < nguess; k++)
        if (guess_row(ctx, m, n, guess[k], ends->guess + k * n) != QD_OK)
            return about(ctx, "guess", k);
    if (!energy && !(t1 > t0))
        return refuse(ctx, "to", "the end time %g is not after the start time %g", t1, t0);
    opts->t0 = t0;
    opts->t1 = t1;
    opts->q0 = ends->q0;
    opts->q1 = ends->q1;
    opts->nguess = nguess;
    opts->guess = nguess ? ends->guess : NULL;
    opts->free0 = any_free ? ends->free0 : NULL;
    opts->free1 = any_free ? ends->free1 : NULL;
    return QD_OK;
}

void qd_path_ends_free(qd_path_ends *ends) {
    if (!ends)
        return;
    free(ends->q0);
    free(ends->free0);
    *ends = (qd_path_ends){0};
}

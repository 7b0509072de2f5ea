/*
 * src/speeds/state.c - a state of a model in generalized speeds read from
 * text (qd_speeds_state_read, qdot/speeds.h): q, t, the parameters and the
 * speeds, as `qdot eom --at` takes it; the velocities follow from the
 * speeds and are refused where they are named.
 */
#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "qdot/speeds.h"
#include "qdot/state.h"
#include "../base/args.h"

/* The item of text that names "q'" (its name's span), or false. */
static bool velocity_item(const char *text, const char *q, size_t *off, size_t *len) {
    size_t nq = strlen(q);
    for (size_t a = 0;;) {
        size_t b = qd_state_item_end(text, a), s = a;
        while (s < b && isspace((unsigned char)text[s]))
            s++;
        size_t e = s;
        while (e < b && text[e] != '=' && !isspace((unsigned char)text[e]))
            e++;
        if (e - s == nq + 1 && !strncmp(text + s, q, nq) && text[s + nq] == '\'') {
            *off = s;
            *len = e - s;
            return true;
        }
        if (!text[b])
            return false;
        a = b + 1;
    }
}

qd_status qd_speeds_state_read(qd_ctx *ctx, const qd_model *m, const qd_speeds_eom *e,
                               const char *text, qd_state *st) {
    QD_ARGS_CTX(ctx, ctx && m && e && text && st);
    qd_status s = qd_state_init(ctx, m, st);
    if (s == QD_OK)
        s = qd_state_append(ctx, st, e->m, e->u, NULL);
    if (s != QD_OK)
        return s;
    bool *given = calloc(st->n, sizeof *given);
    if (!given) {
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory");
        return QD_ERR_NOMEM;
    }
    qd_state_read_opts o = {.given = given};
    s = qd_state_read(ctx, m, st, text, &o);
    for (size_t j = 0; s == QD_OK && j < e->n; j++) {
        const qd_expr *v = qd_jet(ctx, e->q[j], 1);
        size_t k = v ? qd_state_find(st, v) : st->n;
        if (k == st->n || !given[k])
            continue;
        const char *q = qd_expr_name(e->q[j]);
        size_t off = 0, len = strlen(text);
        velocity_item(text, q, &off, &len);
        char hint[128];
        snprintf(hint, sizeof hint, "give the speeds (%s%s)", qd_expr_name(e->u[0]),
                 e->m > 1 ? ", ..." : "");
        qd_ctx_error(ctx, QD_ERR_ARG, "%s' is given, but with speeds the velocities follow "
                     "from them", q);
        qd_ctx_error_about(ctx, QD_SUBJECT_TEXT, 0, NULL, QD_REASON_NONE, hint);
        qd_ctx_error_at(ctx, text, off, len ? len : 1);
        s = QD_ERR_ARG;
    }
    free(given);
    return s;
}

/*
 * src/model/state_point.c - the text of a scan's parameter and range
 * ("NAME=A:B": qd_state_named_range) and of a point kept as expressions in
 * the parameters ("x = 1/2 - mu": qd_state_read_point), so that a scan
 * along mu evaluates the point afresh at every value.
 */
#include <ctype.h>
#include <stdlib.h>
#include <string.h>

#include "base/args.h"
#include "base/mem.h"
#include "qdot/state.h"

qd_status qd_state_named_range(qd_ctx *ctx, const qd_model *m, const char *text, char *name,
                               size_t cap, double *a, double *b) {
    QD_ARGS_CTX(ctx, text && name && cap > 0 && a && b);
    const char *eq = strchr(text, '=');
    size_t s = 0, e = eq ? (size_t)(eq - text) : 0;
    while (s < e && isspace((unsigned char)text[s]))
        s++;
    while (e > s && isspace((unsigned char)text[e - 1]))
        e--;
    if (!eq || e == s || e - s >= cap) {
        qd_ctx_error(ctx, QD_ERR_ARG, "expected NAME=A:B (a parameter and its range), not '%s'",
                     text);
        qd_ctx_error_about(ctx, QD_SUBJECT_TEXT, 0, NULL, QD_REASON_NONE, NULL);
        qd_ctx_error_at(ctx, text, eq ? s : 0, eq && e > s ? e - s : strlen(text));
        return QD_ERR_ARG;
    }
    memcpy(name, text + s, e - s);
    name[e - s] = '\0';
    size_t at = (size_t)(eq - text) + 1;
    return qd_state_range(ctx, m, text, at, strlen(text) - at, a, b);
}

qd_status qd_state_read_point(qd_ctx *ctx, const qd_model *m, const qd_state *st,
                              const char *text, size_t n, const qd_expr *const *q,
                              const qd_expr **at) {
    QD_ARGS_CTX(ctx, m && st && text && (n == 0 || (q && at)));
    size_t ns = st->n;
    const qd_expr **exact = qd__calloc(ctx, ns + 1, sizeof *exact);
    bool *given = qd__calloc(ctx, ns + 1, sizeof *given);
    double *vals = qd__malloc(ctx, (ns + 1) * sizeof *vals); /* NOMEM recorded */
    qd_status r = exact && given && vals ? QD_OK : QD_ERR_NOMEM;
    if (r == QD_OK) {
        memcpy(vals, st->vals, ns * sizeof *vals); /* st itself stays as it is */
        qd_state copy = {ns, st->syms, vals};
        qd_state_read_opts o = {.refuse = QD_STATE_VELOCITIES | QD_STATE_TIME |
                                          QD_STATE_PARAMS | QD_STATE_EXTRA,
                                .independent = q, .nindependent = n, .given = given,
                                .exact = exact};
        r = qd_state_read(ctx, m, &copy, text, &o);
        for (size_t j = 0; r == QD_OK && j < n; j++) {
            size_t k = qd_state_find(&copy, q[j]);
            at[j] = k < ns && given[k] ? exact[k] : qd_int(ctx, 0);
        }
    }
    qd__free(exact);
    qd__free(given);
    qd__free(vals);
    return r;
}

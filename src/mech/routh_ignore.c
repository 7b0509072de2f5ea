/*
 * src/mech/routh_ignore.c - the coordinates a reduction ignores, read from
 * a list of names ("theta, phi"): what `qdot routh --ignore`, `qdot orbit
 * --ignore` and Python's Model.routh and Model.orbit take alike.
 */
#include "qdot/routh.h"

#include <ctype.h>
#include <string.h>
#include "../base/args.h"

/* The item s[0, len) of list, spaces trimmed, looked up and added. */
static qd_status item(qd_ctx *ctx, const qd_model *m, const char *list, const char *s,
                      size_t len, const qd_expr **ign, size_t cap, size_t *n) {
    char name[128];
    while (len && isspace((unsigned char)*s))
        s++, len--;
    while (len && isspace((unsigned char)s[len - 1]))
        len--;
    if (!len || len >= sizeof name || *n == cap) {
        qd_ctx_error(ctx, QD_ERR_ARG, "a comma-separated list of at most %zu coordinates is "
                     "wanted, not '%s'", cap, list);
        return QD_ERR_ARG;
    }
    memcpy(name, s, len);
    name[len] = '\0';
    const qd_expr *c = qd_routh_lookup(ctx, m, name);
    if (!c)
        return qd_ctx_status(ctx);
    for (size_t k = 0; k < *n; k++)
        if (ign[k] == c) {
            qd_ctx_error(ctx, QD_ERR_ARG, "%s is listed twice", name);
            return QD_ERR_ARG;
        }
    ign[(*n)++] = c;
    return QD_OK;
}

qd_status qd_routh_ignore_read(qd_ctx *ctx, const qd_model *m, const qd_eom *e,
                               const char *list, const qd_expr **ign, size_t cap, size_t *n,
                               const char **where) {
    QD_ARGS(QD_ERR_ARG, ctx && m && list && ign && n);
    *n = 0;
    if (where)
        *where = NULL;
    for (const char *s = list;;) {
        const char *comma = strchr(s, ',');
        qd_status st = item(ctx, m, list, s, comma ? (size_t)(comma - s) : strlen(s), ign, cap, n);
        if (st != QD_OK)
            return st;
        if (!comma)
            break;
        s = comma + 1;
    }
    for (size_t i = 0; e && i < *n; i++)
        for (size_t j = 0; j < e->n; j++) {
            const char *why = NULL, *stmt;
            if (e->q[j] != ign[i] || !(stmt = qd_routh_not_cyclic(ctx, m, e, j, &why)))
                continue;
            qd_ctx_error(ctx, QD_ERR_ARG, "%s cannot be ignored: %s", qd_expr_name(ign[i]), why);
            if (where)
                *where = stmt;
            return QD_ERR_ARG;
        }
    return QD_OK;
}

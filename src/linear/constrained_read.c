/*
 * src/linear/constrained_read.c - the independent coordinates of a
 * reduction named in a text, "x, y" (qd_constrained_indep_read,
 * qdot/constrained.h): the names read against the equations' coordinates,
 * a wrong one located in the text.
 */
#include "qdot/constrained.h"
#include "../base/args.h"

#include <ctype.h>
#include <string.h>

static bool is_sep(char c) {
    return c == ',' || isspace((unsigned char)c);
}

/* The coordinate of e named text[0, len), or e->n. */
static size_t coord(const qd_eom *e, const char *text, size_t len) {
    size_t j = 0;
    while (j < e->n && !(strlen(qd_expr_name(e->q[j])) == len &&
                         strncmp(qd_expr_name(e->q[j]), text, len) == 0))
        j++;
    return j;
}

qd_status qd_constrained_indep_read(qd_ctx *ctx, const qd_eom *e, const char *text,
                                    size_t *out) {
    QD_ARGS_CTX(ctx, ctx && e && text && out);
    size_t want = e->ncon < e->n ? e->n - e->ncon : 0, got = 0;
    size_t at = 0, len = strlen(text);
    for (size_t p = 0; text[p];) {
        while (text[p] && is_sep(text[p]))
            p++;
        if (!text[p])
            break;
        size_t s = p;
        while (text[p] && !is_sep(text[p]))
            p++;
        size_t n = p - s, j = coord(e, text + s, n);
        if (j == e->n) {
            qd_ctx_error(ctx, QD_ERR_ARG, "'%.*s' is not a coordinate of the equations", (int)n,
                         text + s);
            qd_ctx_error_at(ctx, text, s, n);
            return QD_ERR_ARG;
        }
        for (size_t i = 0; i < got; i++)
            if (out[i] == j) {
                qd_ctx_error(ctx, QD_ERR_ARG, "%.*s is named twice", (int)n, text + s);
                qd_ctx_error_at(ctx, text, s, n);
                return QD_ERR_ARG;
            }
        if (got == want) { /* one too many: point at it */
            at = s;
            len = n;
            got++;
            break;
        }
        out[got++] = j;
    }
    if (got != want) {
        qd_ctx_error(ctx, QD_ERR_ARG, "the %zu constraint%s leave%s %zu independent "
                                      "coordinate%s; name exactly %zu",
                     e->ncon, e->ncon == 1 ? "" : "s", e->ncon == 1 ? "s" : "", want,
                     want == 1 ? "" : "s", want);
        qd_ctx_error_at(ctx, text, at, len);
        return QD_ERR_ARG;
    }
    for (size_t a = 1; a < want; a++) /* ascending, as qd_constrained_linear has them */
        for (size_t b = a; b > 0 && out[b - 1] > out[b]; b--) {
            size_t t = out[b];
            out[b] = out[b - 1];
            out[b - 1] = t;
        }
    return QD_OK;
}

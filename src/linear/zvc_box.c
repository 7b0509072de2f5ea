/*
 * src/linear/zvc_box.c - the box of the zero-velocity curves read from its
 * text, "x=A:B, y=C:D" (qdot/zvc.h): the one reading the program and
 * Python share, ranges written A:B as everywhere in qdot.
 */
#include <ctype.h>
#include <stdio.h>
#include <string.h>
#include "base/args.h"
#include "base/mem.h"
#include "qdot/zvc.h"

/* The error at text[off, off + len), a QD_ERR_ARG. */
static qd_status zb_error(qd_ctx *ctx, const char *text, size_t off, size_t len,
                          const char *msg) {
    qd_ctx_error(ctx, QD_ERR_ARG, "%s", msg);
    qd_ctx_error_at(ctx, text, off, len ? len : 1);
    return QD_ERR_ARG;
}

/* The number text[a, b) (an expression in the parameters) into *out; its
 * error moved from the piece to the whole text. */
static qd_status zb_number(qd_ctx *ctx, const qd_model *m, const char *text, size_t a, size_t b,
                           double *out) {
    char *piece = qd__malloc(ctx, b - a + 1);
    if (!piece)
        return QD_ERR_NOMEM;
    memcpy(piece, text + a, b - a);
    piece[b - a] = '\0';
    qd_status st = qd_model_number(ctx, m, piece, out);
    qd__free(piece);
    if (st != QD_OK && st != QD_ERR_NOMEM) {
        qd_diag d = *qd_ctx_diag(ctx);
        char msg[sizeof d.message + sizeof d.hint + 2];
        snprintf(msg, sizeof msg, d.hint[0] ? "%s; %s" : "%s", d.message, d.hint);
        qd_ctx_clear_error(ctx);
        st = zb_error(ctx, text, a + (d.located ? d.offset : 0),
                      d.located ? d.length : b - a, msg);
    }
    return st;
}

/* One item text[a, b), NAME=A:B: the k-th coordinate of the box. */
static qd_status zb_item(qd_ctx *ctx, const qd_model *m, const qd_eom *e, const char *text,
                         size_t a, size_t b, size_t k, qd_zvc_box *box) {
    while (a < b && isspace((unsigned char)text[a]))
        a++;
    while (b > a && isspace((unsigned char)text[b - 1]))
        b--;
    const char *eq = memchr(text + a, '=', b - a);
    size_t ne = eq ? (size_t)(eq - text) : b, colon = b;
    for (size_t i = ne, depth = 0; eq && i < b && colon == b; i++) {
        depth += text[i] == '(' ? 1 : text[i] == ')' && depth ? (size_t)-1 : 0;
        colon = text[i] == ':' && !depth ? i : b;
    }
    size_t ns = a;
    while (ne > ns && isspace((unsigned char)text[ne - 1]))
        ne--;
    if (!eq || colon == b || ne == ns)
        return zb_error(ctx, text, a, b - a, "a box item is NAME=A:B, a coordinate and its range");
    const char *names[64];
    size_t j = 0, nn = e->n < 64 ? e->n : 64;
    for (size_t i = 0; i < nn; i++)
        names[i] = qd_expr_name(e->q[i]);
    while (j < e->n && (strlen(qd_expr_name(e->q[j])) != ne - ns ||
                        strncmp(qd_expr_name(e->q[j]), text + ns, ne - ns)))
        j++;
    if (j == e->n) {
        const char *near = qd_nearest_name(text + ns, ne - ns, names, nn);
        char msg[256];
        snprintf(msg, sizeof msg, "'%.*s' is not an independent coordinate%s%s%s", (int)(ne - ns),
                 text + ns, near ? "; did you mean '" : "", near ? near : "", near ? "'?" : "");
        return zb_error(ctx, text, ns, ne - ns, msg);
    }
    qd_status st = zb_number(ctx, m, text, (size_t)(eq - text) + 1, colon, &box->lo[k]);
    if (st == QD_OK)
        st = zb_number(ctx, m, text, colon + 1, b, &box->hi[k]);
    if (st == QD_OK && !(box->lo[k] < box->hi[k])) {
        char msg[256];
        snprintf(msg, sizeof msg, "the range of %s is empty (A:B needs A < B)",
                 qd_expr_name(e->q[j]));
        return zb_error(ctx, text, a, b - a, msg);
    }
    *(k ? &box->iy : &box->ix) = j;
    return st;
}

qd_status qd_zvc_box_read(qd_ctx *ctx, const qd_model *m, const qd_eom *e, const char *text,
                          qd_zvc_box *box) {
    QD_ARGS_CTX(ctx, ctx && m && e && text && box);
    size_t len = strlen(text), start = 0, k = 0;
    qd_status st = QD_OK;
    for (size_t i = 0, depth = 0; st == QD_OK; i++) {
        depth += text[i] == '(' ? 1 : text[i] == ')' && depth ? (size_t)-1 : 0;
        if (text[i] && (text[i] != ',' || depth))
            continue;
        if (k == 2)
            return zb_error(ctx, text, start, len - start,
                            "the box has two items, \"x=A:B, y=C:D\"");
        st = zb_item(ctx, m, e, text, start, i, k++, box);
        if (!text[i])
            break;
        start = i + 1;
    }
    if (st == QD_OK && k != 2)
        return zb_error(ctx, text, 0, len, "the box has two items, \"x=A:B, y=C:D\"");
    if (st == QD_OK && box->ix == box->iy) {
        char msg[256];
        snprintf(msg, sizeof msg, "the box names %s twice: give two coordinates",
                 qd_expr_name(e->q[box->ix]));
        return zb_error(ctx, text, 0, len, msg);
    }
    return st;
}

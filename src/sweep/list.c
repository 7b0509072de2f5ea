/*
 * src/sweep/list.c - the runs of a sweep read from CSV text: a header of
 * input names, then one row of numbers per run (qdot sweep --list
 * FILE.csv).  Every error is located in the text, so a caller can show the
 * line and a caret under the field at fault.
 */
#include "sweep_int.h"

#include <ctype.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/mem.h"
#include "../base/args.h"

typedef struct csv {
    qd_ctx *ctx;
    const char *text;
    char **names;
    size_t nnames, nrows, cap;
    double *values;
} csv;

static qd_status fail_at(csv *c, qd_status st, size_t a, size_t b, const char *msg) {
    qd_ctx_error(c->ctx, st, "%s", msg);
    qd_ctx_error_about(c->ctx, QD_SUBJECT_TEXT, 0, NULL, QD_REASON_NONE, NULL);
    qd_ctx_error_at(c->ctx, c->text, a, b > a ? b - a : 1);
    return st;
}

static bool blank(const char *text, size_t a, size_t b) {
    while (a < b && isspace((unsigned char)text[a]))
        a++;
    return a == b;
}

/* The header line text[a, b): names between commas, spaces trimmed. */
static qd_status header(csv *c, size_t a, size_t b) {
    for (size_t p = a; p <= b;) {
        size_t e = p;
        while (e < b && c->text[e] != ',')
            e++;
        size_t h = p, t = e;
        while (h < t && isspace((unsigned char)c->text[h]))
            h++;
        while (t > h && isspace((unsigned char)c->text[t - 1]))
            t--;
        if (h == t)
            return fail_at(c, QD_ERR_PARSE, p, e, "an empty name in the header");
        char **grown = qd__realloc(c->ctx, c->names, (c->nnames + 1) * sizeof *grown);
        if (!grown)
            return QD_ERR_NOMEM;
        c->names = grown;
        if (!(c->names[c->nnames] = qd__malloc(c->ctx, t - h + 1)))
            return QD_ERR_NOMEM;
        memcpy(c->names[c->nnames], c->text + h, t - h);
        c->names[c->nnames++][t - h] = '\0';
        p = e + 1;
    }
    return QD_OK;
}

/* A row text[a, b): nnames numbers between commas. */
static qd_status row(csv *c, size_t a, size_t b) {
    if (c->nrows == c->cap) {
        size_t cap = c->cap ? 2 * c->cap : 64;
        if (cap > SIZE_MAX / sizeof(double) / c->nnames)
            return QD_ERR_NOMEM;
        double *grown = qd__realloc(c->ctx, c->values, cap * c->nnames * sizeof *grown);
        if (!grown)
            return QD_ERR_NOMEM;
        c->values = grown;
        c->cap = cap;
    }
    size_t p = a;
    for (size_t k = 0; k < c->nnames; k++) {
        char num[128];
        size_t e = p;
        while (e < b && c->text[e] != ',')
            e++;
        size_t len = e - p;
        char *end = num;
        if (len < sizeof num) {
            memcpy(num, c->text + p, len);
            num[len] = '\0';
            c->values[c->nrows * c->nnames + k] = strtod(num, &end);
            while (isspace((unsigned char)*end))
                end++;
        }
        bool last = k + 1 == c->nnames;
        size_t h = p; /* the caret under the field, not its spaces */
        while (h < e && isspace((unsigned char)c->text[h]))
            h++;
        if (len >= sizeof num || end == num || *end || (last ? e != b : e == b))
            return fail_at(c, QD_ERR_PARSE, h, last ? b : e,
                           "expected a number for each name of the header, separated by commas");
        p = e + 1;
    }
    c->nrows++;
    return QD_OK;
}

qd_status qd_sweep_list_csv(qd_sweep *w, const char *text) {
    QD_ARGS(QD_ERR_ARG, w && text);
    csv c = {.ctx = w->ctx, .text = text};
    qd_status st = QD_OK;
    for (size_t p = 0; st == QD_OK && text[p];) {
        size_t e = p + strcspn(text + p, "\r\n");
        if (!blank(text, p, e))
            st = c.nnames ? row(&c, p, e) : header(&c, p, e);
        p = e + strspn(text + e, "\r\n");
    }
    if (st == QD_OK && !c.nrows)
        st = fail_at(&c, QD_ERR_PARSE, 0, strlen(text) ? strlen(text) : 1,
                     "a list of runs is a header of names and at least one row of numbers");
    if (st == QD_OK)
        st = qd_sweep_list(w, c.nnames, (const char *const *)c.names, c.nrows, c.values);
    for (size_t k = 0; k < c.nnames; k++)
        qd__free(c.names[k]);
    qd__free(c.names);
    qd__free(c.values);
    return st;
}

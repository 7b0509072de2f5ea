/*
 * src/sim/input_text.c - an input's source as one text gives it, "NAME =
 * EXPR", NAME=FILE.csv or "NAME = lqr" (qd_sim_setup_input_text,
 * qdot/simsetup.h): which kind, the name and the value's place, each input
 * named once.  The file and the feedback are the caller's to make: a
 * library that reads no files, and LQR's own options.
 */
#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../base/args.h"
#include "setup.h"

/* [*a, *b) with the blanks at both ends skipped. */
static void trim(const char *text, size_t *a, size_t *b) {
    while (*a < *b && isspace((unsigned char)text[*a]))
        (*a)++;
    while (*b > *a && isspace((unsigned char)text[*b - 1]))
        (*b)--;
}

/* name as input k of the model, marked as given; false when it was, or
 * when no memory (then *nomem). */
static bool mark(qd_sim_setup *s, const char *name, bool *nomem) {
    size_t n = qd_model_ninputs(s->m);
    if (!s->input_given && n && !(s->input_given = calloc(n, sizeof *s->input_given))) {
        *nomem = true;
        return false;
    }
    for (size_t k = 0; k < n; k++)
        if (!strcmp(qd_expr_name(qd_model_input(s->m, k)), name)) {
            bool first = !s->input_given[k];
            s->input_given[k] = true;
            return first;
        }
    return true; /* not an input: the source's own call says so */
}

static bool ends_with(const char *text, size_t a, size_t b, const char *tail) {
    size_t n = strlen(tail);
    return b - a >= n && !strncmp(text + b - n, tail, n);
}

qd_status qd_sim_setup_input_text(qd_sim_setup *s, const char *text, qd_sim_input_kind *kind,
                                  char *name, size_t cap, size_t *a, size_t *b) {
    QD_ARGS(QD_ERR_ARG, s);
    QD_ARGS_CTX(s->ctx, text && kind && name && cap > 0 && a && b);
    const char *eq = strchr(text, '=');
    size_t na = 0, nb = eq ? (size_t)(eq - text) : 0;
    trim(text, &na, &nb);
    snprintf(name, cap, "%.*s", (int)(nb - na < cap ? nb - na : cap - 1), text + na);
    if (!eq || !name[0]) {
        qd_ctx_error(s->ctx, QD_ERR_ARG, "expected \"NAME = EXPR\" or NAME=FILE.csv, not '%s'",
                     text);
        return QD_ERR_ARG;
    }
    bool nomem = false;
    if (!mark(s, name, &nomem)) {
        if (nomem)
            qd_ctx_error(s->ctx, QD_ERR_NOMEM, "out of memory");
        else
            qd_ctx_error(s->ctx, QD_ERR_ARG, "%s is given twice", name);
        return nomem ? QD_ERR_NOMEM : QD_ERR_ARG;
    }
    *a = (size_t)(eq + 1 - text);
    *b = strlen(text);
    trim(text, a, b);
    *kind = *b - *a > 4 && ends_with(text, *a, *b, ".csv")                ? QD_SIM_INPUT_TABLE
            : *b - *a == 3 && !strncmp(text + *a, "lqr", 3)               ? QD_SIM_INPUT_LQR
                                                                           : QD_SIM_INPUT_EXPR;
    if (*kind != QD_SIM_INPUT_EXPR)
        return QD_OK;
    return qd_sim_setup_input(s, name, text, *a, *b);
}

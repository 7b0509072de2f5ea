/*
 * src/sim/names.c - expressions in a model's names (qdot/simsetup.h): what
 * --output, --event, --input, a sweep's measures and Python's outputs,
 * events and inputs read.  A name the kernel reader does not know is
 * looked up among the model's definitions and replaced by its value, and a
 * definition's name with a prime (x2') is its time derivative; the
 * multipliers, momenta and inputs stay symbols, which the run compiles.
 * Errors are located in the caller's whole text, so that a command shows
 * its option with a caret under the mistake.
 */
#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../base/args.h"
#include "../base/ctx.h"
#include "qdot/read.h"
#include "qdot/state.h" /* qd_state_item_end: the one item splitter */
#include "setup.h"

static bool is_multiplier(const qd_sim_setup *s, const qd_expr *x) {
    for (size_t k = 0; s->e && k < s->e->ncon; k++)
        if (s->e->con[k].lambda == x)
            return true;
    return false;
}

static bool is_momentum(const qd_sim_setup *s, const qd_expr *x) {
    for (size_t j = 0; s->form == QD_SIM_FORM_HAMILTON && j < s->nq; j++)
        if (qd_model_momentum(s->m, j) == x)
            return true;
    return false;
}

static bool is_input(const qd_sim_setup *s, const qd_expr *x) {
    for (size_t k = 0; k < qd_model_ninputs(s->m); k++)
        if (qd_model_input(s->m, k) == x)
            return true;
    return false;
}

/* A definition's value: `NAME = EXPR`, or a speed's definition. */
static const qd_expr *definition(const qd_sim_setup *s, const char *name) {
    const qd_expr *d = qd_model_definition(s->m, name);
    for (size_t r = 0; !d && r < qd_model_nspeeds(s->m); r++)
        if (!strcmp(qd_expr_name(qd_model_speed(s->m, r)), name))
            d = qd_model_speed_definition(s->m, r);
    return d;
}

/* Simulating in speeds, a constraint's multiplier lambda_NAME by name. */
static bool speeds_multiplier(const qd_sim_setup *s, const char *name) {
    for (size_t k = 0; s->se && k < s->se->ncon; k++)
        if (!strcmp(qd_expr_name(s->se->con[k].lambda), name))
            return true;
    return false;
}

/* Where name stands in text[a, b) as a whole word, or a. */
static size_t word_in(const char *text, size_t a, size_t b, const char *name) {
    size_t n = strlen(name);
    for (size_t p = a; n && p + n <= b; p++)
        if (!strncmp(text + p, name, n) &&
            (p == a || !(isalnum((unsigned char)text[p - 1]) || text[p - 1] == '_')) &&
            (p + n == b || !(isalnum((unsigned char)text[p + n]) || text[p + n] == '_')))
            return p;
    return a;
}

/* The nearest known name to name, for "did you mean": the coordinates,
 * parameters, speeds, multipliers, momenta and inputs. */
static const char *nearest(const qd_sim_setup *s, const char *name) {
    size_t cap = s->n + qd_model_ninputs(s->m) + (s->e ? s->e->ncon : 0) + 1, k = 0;
    const char **names = malloc(cap * sizeof *names);
    if (!names)
        return NULL;
    for (size_t i = 0; i < s->n; i++)
        if (i < s->nq || i > 2 * s->nq) /* q, parameters, momenta, speeds (not q', t) */
            names[k++] = qd_expr_name(s->syms[i]);
    for (size_t i = 0; i < qd_model_ninputs(s->m); i++)
        names[k++] = qd_expr_name(qd_model_input(s->m, i));
    for (size_t i = 0; s->e && i < s->e->ncon; i++)
        names[k++] = qd_expr_name(s->e->con[i].lambda);
    const char *near = qd_nearest_name(name, strlen(name), names, k);
    free(names);
    return near;
}

/* Is name one of the model's vectors (P = (x, y, 0))?  The model's own
 * reader knows: it refuses the name alone with QD_REASON_WRONG_KIND (a
 * vector where a scalar is needed).  The context is left as it was. */
static bool is_vector(qd_sim_setup *s, const char *name) {
    if (qd_ctx_status(s->ctx) != QD_OK)
        return false;
    bool vec = !qd_model_read_expr(s->ctx, s->m, name, 0, strlen(name)) &&
               qd_ctx_diag(s->ctx)->reason == QD_REASON_WRONG_KIND;
    qd_ctx_clear_error(s->ctx);
    return vec;
}

static const qd_expr *refuse(qd_sim_setup *s, const char *text, size_t a, size_t b,
                             const char *name) {
    bool mult = speeds_multiplier(s, name), vec = !mult && is_vector(s, name);
    const char *near = mult || vec ? NULL : nearest(s, name);
    if (vec)
        qd_ctx_error(s->ctx, QD_ERR_ARG, "'%s' is a vector where a scalar is needed", name);
    else if (mult)
        qd_ctx_error(s->ctx, QD_ERR_ARG, "the multipliers are not computed in generalized "
                                         "speeds (use --no-speeds): '%s'", name);
    else
        qd_ctx_error(s->ctx, QD_ERR_ARG, "unknown name '%s'", name);
    char hint[256];
    if (vec)
        snprintf(hint, sizeof hint, "give a component: %s.x, %s.y or %s.z", name, name, name);
    else if (near)
        snprintf(hint, sizeof hint, "did you mean '%s'?", near);
    else
        snprintf(hint, sizeof hint, "use coordinates, velocities q', t, parameters, the model's "
                                    "definitions (a vector by a component: P.x) and the "
                                    "multipliers lambda_<constraint>");
    qd_ctx_error_about(s->ctx, QD_SUBJECT_TEXT, 0, name, QD_REASON_NONE, mult ? NULL : hint);
    qd_ctx_error_at(s->ctx, text, word_in(text, a, b, name), strlen(name));
    return NULL;
}

/* x with every plain name that is not a multiplier, a momentum or an input
 * replaced by the model's definition of it; an unknown one is an error
 * located in text[a, b). */
static const qd_expr *resolve_names(qd_sim_setup *s, const char *text, size_t a, size_t b,
                                    const qd_expr *x) {
    size_t k = qd_free_symbols(s->ctx, x, NULL, 0);
    const qd_expr **syms = malloc((k + 1) * sizeof *syms);
    if (!syms) {
        qd_ctx_error(s->ctx, QD_ERR_NOMEM, "out of memory");
        return NULL;
    }
    qd_free_symbols(s->ctx, x, syms, k);
    for (size_t i = 0; x && i < k; i++) {
        if (qd_symbol_role(syms[i]) != QD_ROLE_PLAIN || is_multiplier(s, syms[i]) ||
            is_momentum(s, syms[i]) || is_input(s, syms[i]))
            continue;
        const qd_expr *d = definition(s, qd_expr_name(syms[i]));
        x = d ? qd_subs(s->ctx, x, 1, &syms[i], &d) : refuse(s, text, a, b, qd_expr_name(syms[i]));
    }
    free(syms);
    return x;
}

const qd_expr *qd_sim_setup_read(qd_sim_setup *s, const char *text, size_t a, size_t b) {
    QD_ARGS(NULL, s && text);
    size_t len = strlen(text);
    b = b < len ? b : len;
    a = a < b ? a : b;
    while (a < b && isspace((unsigned char)text[a]))
        a++;
    while (b > a && isspace((unsigned char)text[b - 1]))
        b--;
    /* the whole text with blanks outside [a, b): the reader's offsets are
     * then offsets in text */
    char *copy = malloc(len + 1);
    if (!copy) {
        qd_ctx_error(s->ctx, QD_ERR_NOMEM, "out of memory");
        return NULL;
    }
    memset(copy, ' ', len);
    memcpy(copy + a, text + a, b - a);
    copy[len] = '\0';
    const qd_expr *x = NULL;
    if (b - a > 1 && text[b - 1] == '\'') { /* NAME' of a definition: its rate */
        copy[b - 1] = '\0';
        const qd_expr *d = definition(s, copy + a);
        copy[b - 1] = '\'';
        if (d)
            x = qd_dt(s->ctx, d);
    }
    const qd_read_opts opts = {.new_symbols = true};
    if (!x && a == b) {
        qd_ctx_error(s->ctx, QD_ERR_ARG, "an expression is missing");
        qd_ctx_error_at(s->ctx, text, a, 1);
    } else if (!x) {
        x = qd_read(s->ctx, copy, &opts, NULL);
    }
    free(copy);
    bool syntax = !x; /* the kernel's grammar refused the text (not a name in it) */
    x = x ? resolve_names(s, text, a, b, x) : NULL;
    if (x || a == b || qd_ctx_status(s->ctx) == QD_ERR_NOMEM)
        return x;
    /* beyond the kernel's grammar: vectors and their components (P.x, P'.x),
     * position(BODY), omega(BODY), read as the model language reads them.
     * When that fails too, the error of the larger grammar is the better one
     * for a syntax error; for a name, the kernel's (it knows the multipliers,
     * momenta and inputs, and says so) */
    qd_diag first = *qd_ctx_diag(s->ctx);
    qd_ctx_clear_error(s->ctx);
    x = qd_model_read_expr(s->ctx, s->m, text, a, b);
    x = x ? resolve_names(s, text, a, b, x) : NULL;
    if (!x && !syntax && qd_ctx_status(s->ctx) != QD_ERR_NOMEM)
        qd__ctx_restore(s->ctx, &first);
    return x;
}


qd_status qd_sim_setup_output(qd_sim_setup *s, const char *name, const char *text, size_t a,
                              size_t b) {
    QD_ARGS(QD_ERR_ARG, s);
    QD_ARGS_CTX(s->ctx, name && text);
    const qd_expr *x = qd_sim_setup_read(s, text, a, b);
    return x ? qd_sim_add_output(s->sim, name, x) : qd_ctx_status(s->ctx);
}

qd_status qd_sim_setup_outputs(qd_sim_setup *s, const char *text) {
    QD_ARGS(QD_ERR_ARG, s);
    QD_ARGS_CTX(s->ctx, text);
    for (size_t p = 0; text[p];) {
        size_t end = qd_state_item_end(text, p), a = p, b = end;
        while (a < b && isspace((unsigned char)text[a]))
            a++;
        while (b > a && isspace((unsigned char)text[b - 1]))
            b--;
        if (a < b) {
            char name[128];
            snprintf(name, sizeof name, "%.*s", (int)(b - a), text + a);
            qd_status st = qd_sim_setup_output(s, name, text, a, b);
            if (st != QD_OK)
                return st;
        }
        p = text[end] ? end + 1 : end;
    }
    return QD_OK;
}

static qd_status grammar(qd_sim_setup *s, const char *text, size_t a, size_t b) {
    qd_ctx_error(s->ctx, QD_ERR_ARG, "an event takes \"EXPR = EXPR[, EXPR > EXPR]...\" (the "
                                     "crossing first, then conditions with > or <)");
    qd_ctx_error_at(s->ctx, text, a, b > a ? b - a : 1);
    return QD_ERR_ARG;
}

qd_status qd_sim_setup_event(qd_sim_setup *s, const char *text, bool stop) {
    QD_ARGS(QD_ERR_ARG, s);
    QD_ARGS_CTX(s->ctx, text);
    const qd_expr *g = NULL, *guards[64];
    size_t ng = 0;
    for (size_t p = 0; text[p] || !g;) {
        size_t end = qd_state_item_end(text, p), op = p;
        while (op < end && text[op] != '=' && text[op] != '>' && text[op] != '<')
            op++;
        if (op == end || (g == NULL) != (text[op] == '=') || ng == 64)
            return grammar(s, text, p, end);
        const qd_expr *l = qd_sim_setup_read(s, text, p, op);
        const qd_expr *r = l ? qd_sim_setup_read(s, text, op + 1, end) : NULL;
        if (!r)
            return qd_ctx_status(s->ctx);
        if (text[op] == '=')
            g = qd_sub(s->ctx, l, r);
        else
            guards[ng++] = text[op] == '>' ? qd_sub(s->ctx, l, r) : qd_sub(s->ctx, r, l);
        p = text[end] ? end + 1 : end;
    }
    return qd_sim_add_event(s->sim, g, ng, guards, stop);
}

qd_status qd_sim_setup_crossing(qd_sim_setup *s, const char *text, size_t a0, size_t a1,
                                size_t b0, size_t b1) {
    QD_ARGS(QD_ERR_ARG, s);
    QD_ARGS_CTX(s->ctx, text);
    const qd_expr *l = qd_sim_setup_read(s, text, a0, a1);
    const qd_expr *r = l ? qd_sim_setup_read(s, text, b0, b1) : NULL;
    if (!r)
        return qd_ctx_status(s->ctx);
    return qd_sim_add_event(s->sim, qd_sub(s->ctx, l, r), 0, NULL, false);
}

qd_status qd_sim_setup_input(qd_sim_setup *s, const char *name, const char *text, size_t a,
                             size_t b) {
    QD_ARGS(QD_ERR_ARG, s);
    QD_ARGS_CTX(s->ctx, name && text);
    const qd_expr *x = qd_sim_setup_read(s, text, a, b);
    return x ? qd_sim_input_expr(s->sim, name, x) : qd_ctx_status(s->ctx);
}

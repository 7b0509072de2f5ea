/*
 * src/orbit/text.c - the state of `qdot orbit` from text (qd_orbit_solve_text,
 * orbit.h): the model's `initial` values, then "r=r0, theta'=1" (values are
 * constant expressions in the parameters), the momenta "p_theta=3" of
 * ignored coordinates and an energy that may use the state's values
 * ("m*g*a", "V0 + r").  Errors name the field and are located in its text.
 *
 * The at reader is small and private: it reads what the orbit needs (the
 * coordinates, velocities, t and parameters); a general reader of states
 * is qdot/state.h's work (issue 31).
 */
#include "base/args.h"
#include "orb.h"

#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "qdot/read.h"
#include "qdot/state.h"

typedef struct ost {
    size_t n, cap, nq;
    const qd_expr **syms;
    double *vals;
} ost;

static qd_status nomem(qd_ctx *ctx) {
    qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory");
    return QD_ERR_NOMEM;
}

static qd_status refuse(qd_ctx *ctx, const char *field, const char *text, size_t off,
                        size_t len, const char *hint, const char *fmt, const char *name) {
    qd_ctx_error(ctx, QD_ERR_ARG, fmt, name);
    qd_ctx_error_about(ctx, QD_SUBJECT_NONE, 0, field, QD_REASON_NONE, hint);
    qd_ctx_error_at(ctx, text, off, len ? len : 1);
    return QD_ERR_ARG;
}

/* q_j, q'_j, t and the parameters at their values, then the model's
 * `initial` values; room for the momenta of the ignored coordinates. */
static qd_status init_state(qd_ctx *ctx, const qd_orbit *o, const qd_model *m, ost *s) {
    size_t nq = qd_model_ncoords(m), np = qd_model_nparams(m);
    s->nq = nq;
    s->n = 2 * nq + 1 + np;
    s->cap = s->n + o->routh->nign;
    s->syms = calloc(s->cap, sizeof *s->syms);
    s->vals = calloc(s->cap, sizeof *s->vals);
    if (!s->syms || !s->vals)
        return nomem(ctx);
    for (size_t i = 0; i < nq; i++) {
        s->syms[i] = qd_model_coord(m, i);
        s->syms[nq + i] = qd_jet(ctx, qd_model_coord(m, i), 1);
    }
    s->syms[2 * nq] = qd_time(ctx);
    for (size_t i = 0; i < np; i++) {
        s->syms[2 * nq + 1 + i] = qd_model_param(m, i);
        if (qd_model_param_number(m, i, &s->vals[2 * nq + 1 + i]) != QD_OK)
            s->vals[2 * nq + 1 + i] = NAN; /* an error only where it is used */
    }
    for (size_t i = 0; i < nq; i++)
        for (unsigned k = 0; k < 2; k++) {
            const qd_expr *v = qd_model_initial(m, i, k);
            if (v && qd_eval(ctx, v, s->n, s->syms, s->vals, &s->vals[k * nq + i]) != QD_OK)
                return qd_ctx_status(ctx);
        }
    return QD_OK;
}

/* The slot named text[a, b) among the first s->n, or s->n. */
static size_t slot_of(const ost *s, const char *text, size_t a, size_t b) {
    for (size_t i = 0; i < s->n; i++) {
        char name[160];
        const qd_expr *x = s->syms[i];
        if (i >= s->nq && i < 2 * s->nq)
            snprintf(name, sizeof name, "%s'", qd_expr_name(s->syms[i - s->nq]));
        else
            snprintf(name, sizeof name, "%s", qd_expr_name(x));
        if (strlen(name) == b - a && !strncmp(name, text + a, b - a))
            return i;
    }
    return s->n;
}

/* "unknown name", with the nearest slot's name as "did you mean". */
static qd_status unknown(qd_ctx *ctx, const ost *s, const char *field, const char *text,
                         size_t a, size_t b) {
    char (*names)[160] = malloc(s->n * sizeof *names);
    const char **ptr = malloc(s->n * sizeof *ptr);
    if (!names || !ptr) {
        free(names);
        free(ptr);
        return nomem(ctx);
    }
    for (size_t i = 0; i < s->n; i++) {
        if (i >= s->nq && i < 2 * s->nq)
            snprintf(names[i], sizeof names[i], "%s'", qd_expr_name(s->syms[i - s->nq]));
        else
            snprintf(names[i], sizeof names[i], "%s", qd_expr_name(s->syms[i]));
        ptr[i] = names[i];
    }
    const char *near = qd_nearest_name(text + a, b - a, ptr, s->n);
    char hint[200], word[160];
    snprintf(hint, sizeof hint, "did you mean '%s'?", near ? near : "");
    snprintf(word, sizeof word, "%.*s", (int)(b - a), text + a);
    qd_status st = refuse(ctx, field, text, a, b - a, near ? hint : NULL,
                          "unknown name '%s' (a state names the coordinates, their velocities "
                          "with a prime, t and the parameters)", word);
    free(names);
    free(ptr);
    return st;
}

static void trim(const char *text, size_t *a, size_t *b) {
    while (*a < *b && isspace((unsigned char)text[*a]))
        (*a)++;
    while (*b > *a && isspace((unsigned char)text[*b - 1]))
        (*b)--;
}

/* One NAME=VALUE of text[a, b): *na, *nb the name, *va, *vb the value. */
static qd_status split(qd_ctx *ctx, const char *field, const char *text, size_t a, size_t b,
                       size_t *na, size_t *nb, size_t *va, size_t *vb) {
    const char *eq = memchr(text + a, '=', b - a);
    char item[160];
    snprintf(item, sizeof item, "%.*s", (int)(b - a), text + a);
    if (!eq)
        return refuse(ctx, field, text, a, b - a, NULL, "'%s' is not NAME=VALUE", item);
    *na = a, *nb = (size_t)(eq - text), *va = *nb + 1, *vb = b;
    trim(text, na, nb);
    trim(text, va, vb);
    return *na < *nb ? QD_OK
                     : refuse(ctx, field, text, a, b - a, NULL, "'%s' has no name", item);
}

/* The at text: each NAME=VALUE into its slot. */
static qd_status read_at(qd_ctx *ctx, const qd_model *m, const char *text, ost *s) {
    bool *given = calloc(s->n, sizeof *given);
    if (!given)
        return nomem(ctx);
    qd_status st = QD_OK;
    for (size_t i = 0; st == QD_OK && text[i];) {
        size_t end = qd_state_item_end(text, i), a = i, b = end, na, nb, va, vb;
        trim(text, &a, &b);
        if (a < b && (st = split(ctx, "at", text, a, b, &na, &nb, &va, &vb)) == QD_OK) {
            size_t k = slot_of(s, text, na, nb);
            const char *x = qd_model_independent(m); /* `independent x`: x is t */
            if (k == s->n && x && strlen(x) == nb - na && !strncmp(x, text + na, nb - na))
                k = 2 * s->nq;
            char word[160];
            snprintf(word, sizeof word, "%.*s", (int)(nb - na), text + na);
            st = k == s->n    ? unknown(ctx, s, "at", text, na, nb)
                 : given[k]   ? refuse(ctx, "at", text, na, nb - na, NULL,
                                       "'%s' is given twice", word)
                              : qd_model_number_field(ctx, m, "at", text, va, vb - va,
                                                      &s->vals[k]);
            if (k < s->n)
                given[k] = true;
        }
        i = text[end] ? end + 1 : end;
    }
    free(given);
    return st;
}

/* "p_theta=VALUE, ...": each the momentum of an ignored coordinate. */
static qd_status read_momenta(qd_ctx *ctx, const qd_orbit *o, const qd_model *m,
                              const char *text, ost *s) {
    const qd_routh *h = o->routh;
    qd_status st = QD_OK;
    for (size_t i = 0; st == QD_OK && text[i];) {
        size_t end = qd_state_item_end(text, i), a = i, b = end, na, nb, va, vb;
        trim(text, &a, &b);
        if (a < b && (st = split(ctx, "momentum", text, a, b, &na, &nb, &va, &vb)) == QD_OK) {
            size_t k = 0;
            while (k < h->nign && (strlen(qd_expr_name(h->beta[k])) != nb - na ||
                                   strncmp(qd_expr_name(h->beta[k]), text + na, nb - na)))
                k++;
            char word[160];
            snprintf(word, sizeof word, "%.*s", (int)(nb - na), text + na);
            if (k == h->nign)
                return refuse(ctx, "momentum", text, na, nb - na, NULL,
                              "'%s' is not the momentum of an ignored coordinate (they are "
                              "p_<q>)", word);
            for (size_t j = s->cap - h->nign; j < s->n; j++)
                if (s->syms[j] == h->beta[k])
                    return refuse(ctx, "momentum", text, na, nb - na, NULL,
                                  "the momentum '%s' is given twice", word);
            s->syms[s->n] = h->beta[k];
            st = qd_model_number_field(ctx, m, "momentum", text, va, vb - va, &s->vals[s->n++]);
        }
        i = text[end] ? end + 1 : end;
    }
    return st;
}

/* The energy: an expression in the parameters and the state's values. */
static qd_status read_energy(qd_ctx *ctx, const char *text, const ost *s, double *E) {
    const qd_read_opts opts = {.new_symbols = false};
    qd_diag err;
    const qd_expr *e = qd_read(ctx, text, &opts, &err);
    if (!e) {
        qd_ctx_clear_error(ctx);
        qd_ctx_error(ctx, err.status ? err.status : QD_ERR_PARSE, "%s", err.message);
        qd_ctx_error_about(ctx, QD_SUBJECT_NONE, 0, "energy", err.reason,
                           err.hint[0] ? err.hint : NULL);
        qd_ctx_error_at(ctx, text, err.located ? err.offset : 0,
                        err.located ? err.length : strlen(text));
        return qd_ctx_status(ctx);
    }
    if (qd_eval(ctx, e, s->n, s->syms, s->vals, E) != QD_OK || !isfinite(*E)) {
        qd_ctx_clear_error(ctx);
        return refuse(ctx, "energy", text, 0, strlen(text), NULL,
                      "'%s' does not evaluate to a finite number", text);
    }
    return QD_OK;
}

qd_status qd_orbit_solve_text(qd_ctx *ctx, const qd_orbit *o, const qd_model *m,
                              const qd_orbit_text *t, qd_orbit_result *out) {
    QD_ARGS_CTX(ctx, ctx && o && m && t && out);
    memset(out, 0, sizeof *out);
    ost s = {0};
    double E = NAN;
    qd_status st = init_state(ctx, o, m, &s);
    if (st == QD_OK && t->at)
        st = read_at(ctx, m, t->at, &s);
    if (st == QD_OK && t->momentum)
        st = read_momenta(ctx, o, m, t->momentum, &s);
    if (st == QD_OK && t->energy)
        st = read_energy(ctx, t->energy, &s, &E);
    if (st == QD_OK)
        st = qd_orbit_solve(ctx, o, s.n, s.syms, s.vals, t->energy ? &E : NULL, out);
    free(s.syms);
    free(s.vals);
    return st;
}

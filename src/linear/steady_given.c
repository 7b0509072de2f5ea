/*
 * src/linear/steady_given.c - a steady-motion problem stated by name
 * (qdot/stability.h): the cyclic coordinates named in text, and the held
 * values and starting guesses "theta = pi/3, phi' = 2, p_psi = 24" read
 * against the qd_steady into the flags and point that qd_steady_find_all
 * and qd_stability_scan take.
 *
 * Every error names the field it was read from (qd_diag.name: "at",
 * "guess", ...) and is located in that field's text (SUBJECT_TEXT), so a
 * caller can show it under the text with a caret; a value's own error (an
 * unknown name, "did you mean") is moved from the value to its place in the
 * whole text.
 */
#include "qdot/stability.h"
#include "qdot/read.h"
#include "../base/args.h"
#include "../base/diag.h"
#include "../base/mem.h"

#include <ctype.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

/* At most this many cyclic coordinates in one list. */
#define GIVEN_MAX_CYC 16

typedef struct given_reader {
    qd_ctx *ctx;
    const qd_model *m;
    const qd_steady *s;   /* NULL while the cyclic list is read */
    qd_steady_given *g;
    const char *field, *text;
    bool *seen;            /* nkeep: named in the text being read */
    const qd_expr **cyc;   /* the cyclic list being read (GIVEN_MAX_CYC) */
    size_t ncyc;
} given_reader;

/* An error about text[off, off + len) of the field being read. */
static qd_status refuse(given_reader *r, size_t off, size_t len, const char *fmt, ...)
#ifdef __GNUC__
    __attribute__((format(printf, 4, 5)))
#endif
    ;
static qd_status refuse(given_reader *r, size_t off, size_t len, const char *fmt, ...) {
    char msg[256];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    qd_ctx_error(r->ctx, QD_ERR_ARG, "%s", msg);
    qd_ctx_error_about(r->ctx, QD_SUBJECT_TEXT, 0, r->field, QD_REASON_NONE, NULL);
    qd_ctx_error_at(r->ctx, r->text, off, len);
    return QD_ERR_ARG;
}

static size_t off_of(const given_reader *r, const char *p) { return (size_t)(p - r->text); }

static void trim(const char **a, const char **b) {
    while (*a < *b && isspace((unsigned char)**a))
        (*a)++;
    while (*b > *a && isspace((unsigned char)(*b)[-1]))
        (*b)--;
}

static bool is_name(const char *a, const char *b, const char *name) {
    return strlen(name) == (size_t)(b - a) && !strncmp(name, a, (size_t)(b - a));
}

/* A value text[a, b): a constant expression in the parameters, its number
 * and its expression; its error moved to its place in the field's text. */
static qd_status value_of(given_reader *r, const char *a, const char *b, double *out,
                          const qd_expr **expr) {
    trim(&a, &b);
    size_t n = (size_t)(b - a);
    char *text = qd__malloc(r->ctx, n + 1);
    if (!text)
        return QD_ERR_NOMEM;
    memcpy(text, a, n);
    text[n] = '\0';
    qd_status st = qd_model_number(r->ctx, r->m, text, out);
    if (st == QD_OK) {
        const qd_read_opts opts = {.new_symbols = false};
        *expr = qd_read(r->ctx, text, &opts, NULL); /* read once already: the names exist */
        st = *expr ? QD_OK : qd_ctx_status(r->ctx);
    } else if (st != QD_ERR_NOMEM) {
        qd_diag d = *qd_ctx_diag(r->ctx);
        qd_ctx_clear_error(r->ctx);
        qd_ctx_error(r->ctx, st, "%s", d.message);
        qd_ctx_error_about(r->ctx, QD_SUBJECT_TEXT, 0, r->field, QD_REASON_NONE,
                           d.hint[0] ? d.hint : NULL);
        qd_ctx_error_at(r->ctx, r->text, off_of(r, a) + (d.located ? d.offset : 0),
                        d.located ? d.length : n);
    }
    qd__free(text);
    return st;
}

static int coord_index(const given_reader *r, const char *a, const char *b) {
    for (size_t i = 0; i < qd_model_ncoords(r->m); i++)
        if (is_name(a, b, qd_expr_name(qd_model_coord(r->m, i))))
            return (int)i;
    return -1;
}

/* "did you mean" the nearest coordinate, as model files say it. */
static qd_status unknown_coord(given_reader *r, const char *a, const char *b) {
    size_t nq = qd_model_ncoords(r->m);
    const char **names = qd__malloc(r->ctx, (nq + 1) * sizeof *names);
    const char *near = NULL;
    for (size_t i = 0; names && i < nq; i++)
        names[i] = qd_expr_name(qd_model_coord(r->m, i));
    if (names)
        near = qd__diag_nearest(a, (size_t)(b - a), names, nq);
    char hint[160];
    snprintf(hint, sizeof hint, "did you mean '%s'?", near ? near : "");
    qd__free(names);
    qd_ctx_error(r->ctx, QD_ERR_ARG, "'%.*s' is not a coordinate of the model", (int)(b - a), a);
    qd_ctx_error_about(r->ctx, QD_SUBJECT_TEXT, 0, r->field, QD_REASON_NONE, near ? hint : NULL);
    qd_ctx_error_at(r->ctx, r->text, off_of(r, a), (size_t)(b - a));
    return QD_ERR_ARG;
}

/* The end of a name written as a rate, "phi'": before its primes. */
static const char *before_primes(const char *a, const char *b) {
    while (b > a && b[-1] == '\'')
        b--;
    return b;
}

/* Call fn(r, name_a, name_b, value_a, value_b) on each NAME=VALUE (or NAME
 * alone when bare) of the comma-separated text, commas inside brackets kept. */
typedef qd_status (*item_fn)(given_reader *r, const char *na, const char *nb, const char *va,
                             const char *vb);

static qd_status each_item(given_reader *r, bool bare, item_fn fn) {
    const char *p = r->text;
    while (*p) {
        const char *end = p;
        int depth = 0;
        for (; *end && (*end != ',' || depth > 0); end++)
            depth += (*end == '(' || *end == '[') - ((*end == ')' || *end == ']') && depth > 0);
        const char *eq = memchr(p, '=', (size_t)(end - p)), *na = p, *nb = eq ? eq : end;
        trim(&na, &nb);
        if (na < nb || eq) {
            if (na == nb)
                return refuse(r, off_of(r, p), (size_t)(end - p), "a name is missing before '='");
            if (!eq && !bare)
                return refuse(r, off_of(r, na), (size_t)(nb - na), "expected NAME=VALUE, not "
                              "'%.*s'", (int)(nb - na), na);
            qd_status st = fn(r, na, nb, eq ? eq + 1 : NULL, end);
            if (st != QD_OK)
                return st;
        }
        p = *end ? end + 1 : end;
    }
    return QD_OK;
}

/* ---- the cyclic coordinates ---------------------------------------------- */

/* A name of the list ("phi", or "phi' = VALUE" of a driven rate: its
 * coordinate), added once; a name listed twice is refused only when bare. */
static qd_status cyc_item(given_reader *r, const char *na, const char *nb, const char *va,
                          const char *vb) {
    (void)vb;
    const char *qe = before_primes(na, nb);
    bool driven = r->g != NULL;
    if (driven && va && qe == nb)
        return refuse(r, off_of(r, na), (size_t)(nb - na), "a rate is written with a prime, "
                      "%.*s' = VALUE", (int)(nb - na), na);
    if (!driven && (va || qe < nb))
        return refuse(r, off_of(r, na), (size_t)((va ? vb : nb) - na), "the cyclic coordinates "
                      "are names (phi, psi), not '%.*s'", (int)((va ? vb : nb) - na), na);
    int i = coord_index(r, na, qe);
    if (i < 0)
        return unknown_coord(r, na, qe);
    const qd_expr *q = qd_model_coord(r->m, (size_t)i);
    for (size_t c = 0; c < r->ncyc; c++)
        if (r->cyc[c] == q)
            return r->g ? QD_OK
                        : refuse(r, off_of(r, na), (size_t)(qe - na), "%.*s is listed twice",
                                 (int)(qe - na), na);
    if (r->ncyc == GIVEN_MAX_CYC)
        return refuse(r, off_of(r, na), (size_t)(nb - na), "at most %d cyclic coordinates",
                      GIVEN_MAX_CYC);
    r->cyc[r->ncyc++] = q;
    return QD_OK;
}

qd_steady *qd_steady_derive_named(qd_ctx *ctx, const qd_model *m, const qd_eom *e,
                                  const char *field, const char *names, bool driven) {
    QD_ARGS(NULL, ctx && m && e && field && names);
    const qd_expr *cyc[GIVEN_MAX_CYC];
    /* g marks the driven reading: "phi' = VALUE" items, each name once or more */
    qd_steady_given mark = {0};
    given_reader r = {.ctx = ctx, .m = m, .g = driven ? &mark : NULL, .field = field,
                      .text = names, .cyc = cyc};
    if (each_item(&r, true, cyc_item) != QD_OK)
        return NULL;
    qd_steady *s = qd_steady_derive(ctx, m, e, r.ncyc, cyc, driven);
    if (!s && qd_ctx_diag(ctx)->subject == QD_SUBJECT_NONE && !qd_ctx_diag(ctx)->name[0])
        qd_ctx_error_about(ctx, QD_SUBJECT_NONE, 0, field, QD_REASON_NONE, NULL);
    return s;
}

/* ---- the values ---------------------------------------------------------- */

static size_t cyc_slot(const given_reader *r, const char *a, const char *b) {
    size_t c = 0;
    while (c < r->s->ncyc && !is_name(a, b, qd_expr_name(r->s->cyc[c])))
        c++;
    return c;
}

/* "phi' = VALUE" (a bare "phi" of the driven list holds nothing). */
static qd_status rate_item(given_reader *r, const char *na, const char *nb, const char *va,
                           const char *vb) {
    const char *qe = before_primes(na, nb);
    if (va && qe == nb)
        return refuse(r, off_of(r, na), (size_t)(nb - na), "a rate is written with a prime, "
                      "%.*s' = VALUE", (int)(nb - na), na);
    if (coord_index(r, na, qe) < 0)
        return unknown_coord(r, na, qe);
    size_t c = cyc_slot(r, na, qe);
    if (c == r->s->ncyc)
        return refuse(r, off_of(r, na), (size_t)(qe - na), "%.*s is not among the cyclic "
                      "coordinates", (int)(qe - na), na);
    if (!va)
        return QD_OK;
    qd_steady_given *g = r->g;
    if (g->wfix[c])
        return refuse(r, off_of(r, na), (size_t)(nb - na), "the rate %.*s' is given twice",
                      (int)(qe - na), na);
    g->wfix[c] = true;
    return value_of(r, va, vb, &g->start.w[c], &g->held[r->s->nkeep + c]);
}

static qd_status momentum_item(given_reader *r, const char *na, const char *nb, const char *va,
                               const char *vb) {
    const qd_steady *s = r->s;
    qd_steady_given *g = r->g;
    for (size_t c = 0; c < s->ncyc; c++) {
        if (!is_name(na, nb, qd_expr_name(s->beta[c])))
            continue;
        if (g->pfix[c])
            return refuse(r, off_of(r, na), (size_t)(nb - na), "%s is given twice",
                          qd_expr_name(s->beta[c]));
        g->pfix[c] = true;
        return value_of(r, va, vb, &g->start.p[c], &g->held[s->nkeep + s->ncyc + c]);
    }
    return refuse(r, off_of(r, na), (size_t)(nb - na), "'%.*s' is not the momentum of an "
                  "ignored coordinate (they are p_<q>)", (int)(nb - na), na);
}

/* A kept coordinate: held (at) or a starting value (guess). */
static qd_status kept_item(given_reader *r, const char *na, const char *nb, const char *va,
                           const char *vb, bool hold) {
    int i = coord_index(r, na, nb);
    if (i < 0)
        return unknown_coord(r, na, nb);
    size_t j = 0;
    while (j < r->s->nkeep && r->s->keep[j] != qd_model_coord(r->m, (size_t)i))
        j++;
    if (j == r->s->nkeep)
        return refuse(r, off_of(r, na), (size_t)(nb - na), "%.*s is cyclic here: give its "
                      "rate, %.*s' = VALUE, instead", (int)(nb - na), na, (int)(nb - na), na);
    if (r->seen[j])
        return refuse(r, off_of(r, na), (size_t)(nb - na), "%.*s is given twice",
                      (int)(nb - na), na);
    r->seen[j] = true;
    const qd_expr *x = NULL;
    qd_status st = value_of(r, va, vb, &r->g->start.x[j], &x);
    if (st == QD_OK && hold) {
        r->g->xfix[j] = true;
        r->g->held[j] = x;
    }
    return st;
}

static qd_status at_item(given_reader *r, const char *na, const char *nb, const char *va,
                         const char *vb) {
    return kept_item(r, na, nb, va, vb, true);
}

/* A kept coordinate, a rate "Q'" or a momentum "p_Q", none held. */
static qd_status guess_item(given_reader *r, const char *na, const char *nb, const char *va,
                            const char *vb) {
    const qd_steady *s = r->s;
    qd_steady_given *g = r->g;
    const char *qe = before_primes(na, nb);
    for (size_t c = 0; c < s->ncyc; c++) {
        const char *q = qd_expr_name(s->cyc[c]);
        size_t len = strlen(q);
        bool rate = qe < nb && is_name(na, qe, q);
        bool mom = qe == nb && (size_t)(nb - na) == len + 2 && !strncmp(na, "p_", 2) &&
                   !strncmp(na + 2, q, len);
        if (!rate && !mom)
            continue;
        /* a rate whose momentum is held is still unknown: guessing it is fine */
        if (g->wfix[c] || (mom && g->pfix[c]))
            return refuse(r, off_of(r, na), (size_t)(nb - na), "%.*s is given: a guess cannot "
                          "change it", (int)(nb - na), na);
        if (g->wguess[c] || g->pguess[c])
            return refuse(r, off_of(r, na), (size_t)(nb - na), "a starting value for %s is "
                          "given twice", q);
        *(rate ? &g->wguess[c] : &g->pguess[c]) = true;
        const qd_expr *x;
        return value_of(r, va, vb, rate ? &g->start.w[c] : &g->start.p[c], &x);
    }
    if (qe < nb || (coord_index(r, na, nb) < 0 && !strncmp(na, "p_", 2)))
        return refuse(r, off_of(r, na), (size_t)(nb - na), "%.*s is not the rate or momentum "
                      "of a cyclic coordinate (the kept coordinates are at rest)",
                      (int)(nb - na), na);
    return kept_item(r, na, nb, va, vb, false);
}

/* t = 0 and the parameters at their values; the starting values from the
 * model's `initial` (else 0 for coordinates and 1 for rates). */
static qd_status given_start(qd_ctx *ctx, const qd_steady *s, const qd_model *m,
                             qd_steady_given *g) {
    size_t np = qd_model_nparams(m);
    g->nvals = np + 1;
    g->syms = qd__calloc(ctx, np + 1, sizeof *g->syms);
    g->vals = qd__calloc(ctx, np + 1, sizeof *g->vals);
    if (!g->syms || !g->vals)
        return QD_ERR_NOMEM;
    g->syms[0] = qd_time(ctx);
    for (size_t i = 0; i < np; i++) {
        g->syms[i + 1] = qd_model_param(m, i);
        if (qd_model_param_number(m, i, &g->vals[i + 1]) != QD_OK) {
            if (qd__ctx_nomem(ctx))
                return QD_ERR_NOMEM;
            qd_ctx_clear_error(ctx);
            qd_ctx_error(ctx, QD_ERR_ARG, "parameter %s has no finite value",
                         qd_expr_name(qd_model_param(m, i)));
            return QD_ERR_ARG;
        }
    }
    for (size_t i = 0; i < qd_model_ncoords(m); i++) {
        const qd_expr *q = qd_model_coord(m, i);
        size_t c = 0, j = 0;
        while (c < s->ncyc && s->cyc[c] != q)
            c++;
        bool cyclic = c < s->ncyc;
        const qd_expr *x = qd_model_initial(m, i, cyclic ? 1 : 0);
        double v = cyclic ? 1 : 0;
        if (x && (qd_eval(ctx, x, g->nvals, g->syms, g->vals, &v) != QD_OK || !isfinite(v))) {
            if (!qd__ctx_recover(ctx))
                return QD_ERR_NOMEM;
            v = cyclic ? 1 : 0; /* an initial value in the coordinates: the default */
        }
        if (cyclic) {
            g->start.w[c] = v != 0 ? v : 1;
            continue;
        }
        while (j < s->nkeep && s->keep[j] != q)
            j++;
        if (j < s->nkeep)
            g->start.x[j] = v;
    }
    return QD_OK;
}

static qd_status read_field(given_reader *r, const char *field, const char *text, bool bare,
                            item_fn fn) {
    if (!text)
        return QD_OK;
    r->field = field;
    r->text = text;
    memset(r->seen, 0, (r->s->nkeep + 1) * sizeof *r->seen);
    return each_item(r, bare, fn);
}

qd_status qd_steady_given_read(qd_ctx *ctx, const qd_steady *s, const qd_model *m,
                               const qd_steady_spec *spec, qd_steady_given *out) {
    QD_ARGS_CTX(ctx, ctx && s && m && spec && out);
    *out = (qd_steady_given){0};
    size_t nk = s->nkeep, nc = s->ncyc;
    qd_steady_given *g = out;
    g->start.x = qd__calloc(ctx, nk + 1, sizeof *g->start.x);
    g->start.w = qd__calloc(ctx, nc + 1, sizeof *g->start.w);
    g->start.p = qd__calloc(ctx, nc + 1, sizeof *g->start.p);
    g->xfix = qd__calloc(ctx, nk + 1, sizeof *g->xfix);
    g->wfix = qd__calloc(ctx, nc + 1, sizeof *g->wfix);
    g->pfix = qd__calloc(ctx, nc + 1, sizeof *g->pfix);
    g->wguess = qd__calloc(ctx, nc + 1, sizeof *g->wguess);
    g->pguess = qd__calloc(ctx, nc + 1, sizeof *g->pguess);
    g->held = qd__calloc(ctx, nk + 2 * nc + 1, sizeof *g->held);
    bool *seen = qd__calloc(ctx, nk + 1, sizeof *seen);
    qd_status st = g->start.x && g->start.w && g->start.p && g->xfix && g->wfix && g->pfix &&
                           g->wguess && g->pguess && g->held && seen
                       ? QD_OK
                       : QD_ERR_NOMEM;
    if (st == QD_OK)
        st = given_start(ctx, s, m, g);
    given_reader r = {.ctx = ctx, .m = m, .s = s, .g = g, .seen = seen, .field = "momentum",
                      .text = spec->momenta};
    if (st == QD_OK && spec->momenta && s->driven)
        st = refuse(&r, 0, strlen(spec->momenta), "momenta are given when they are free: a "
                    "driven rate is given as Q' = VALUE");
    /* the held values first: a guess may not change one */
    if (st == QD_OK)
        st = read_field(&r, spec->rates_field ? spec->rates_field : "rates", spec->rates,
                        s->driven, rate_item);
    if (st == QD_OK)
        st = read_field(&r, "momentum", spec->momenta, false, momentum_item);
    if (st == QD_OK)
        st = read_field(&r, "guess", spec->guess, false, guess_item);
    if (st == QD_OK)
        st = read_field(&r, "at", spec->at, false, at_item);
    qd__free(seen);
    if (st != QD_OK)
        qd_steady_given_free(g);
    return st;
}

void qd_steady_given_free(qd_steady_given *g) {
    if (!g)
        return;
    qd__free(g->syms);
    qd__free(g->vals);
    qd__free(g->start.x);
    qd__free(g->start.w);
    qd__free(g->start.p);
    qd__free(g->xfix);
    qd__free(g->wfix);
    qd__free(g->pfix);
    qd__free(g->wguess);
    qd__free(g->pguess);
    qd__free(g->held);
    *g = (qd_steady_given){0};
}

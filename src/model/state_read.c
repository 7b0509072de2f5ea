/*
 * src/model/state_read.c - the reader of "NAME=VALUE, ..." states
 * (qd_state_read, qdot/state.h): names resolved against the model and the
 * state's slots, values read as constant expressions in the parameters.
 *
 * Every error is located in the caller's text.  A value is read from a copy
 * of the whole text with everything outside it blanked (line breaks kept),
 * so the expression reader's own errors already carry offsets, lines and
 * columns of the caller's text and need no translation.
 */
#include <ctype.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/args.h"
#include "base/diag.h"
#include "qdot/read.h"
#include "qdot/state.h"

/* A located error: message, hint (may be NULL), at text[off, off + len). */
#ifdef __GNUC__
__attribute__((format(printf, 6, 7)))
#endif
static qd_status fail(qd_ctx *ctx, const char *text, size_t off, size_t len, const char *hint,
                      const char *fmt, ...) {
    char msg[256];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    qd_ctx_error(ctx, QD_ERR_ARG, "%s", msg);
    qd_ctx_error_about(ctx, QD_SUBJECT_TEXT, 0, NULL, QD_REASON_NONE, hint);
    qd_ctx_error_at(ctx, text, off, len ? len : 1);
    return QD_ERR_ARG;
}

static qd_status nomem(qd_ctx *ctx) {
    qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory");
    return QD_ERR_NOMEM;
}

size_t qd_state_item_end(const char *text, size_t i) {
    QD_ARGS(0, text);
    int depth = 0;
    for (; text[i]; i++) {
        if (text[i] == '(' || text[i] == '[')
            depth++;
        else if ((text[i] == ')' || text[i] == ']') && depth > 0)
            depth--;
        else if (text[i] == ',' && depth == 0)
            break;
    }
    return i;
}

/* ---- a value ----------------------------------------------------------------- */

/* A number node as the nearest double: an exact rational p/q that fits is
 * (double)p/q, correctly rounded (9.81 stays 9.81). */
static double number_value(const qd_expr *x) {
    long p, q;
    if (qd_rational_get(x, &p, &q) && fabs((double)p) <= 0x1p53 && (double)q <= 0x1p53)
        return (double)p / (double)q;
    return qd_number_value(x);
}

/* The first place name stands as a whole word in text[start, end). */
static size_t word_at(const char *text, size_t start, size_t end, const char *name) {
    size_t n = strlen(name);
    for (size_t i = start; n && i + n <= end; i++) {
        const char *p = text + i;
        bool before = i == 0 || !(isalnum((unsigned char)p[-1]) || p[-1] == '_');
        bool after = !(isalnum((unsigned char)p[n]) || p[n] == '_');
        if (before && after && !strncmp(p, name, n))
            return i;
    }
    return start;
}

/* Is s one of m's parameters?  Its index, or np. */
static size_t param_index(const qd_model *m, const qd_expr *s) {
    size_t np = m ? qd_model_nparams(m) : 0, i = 0;
    while (i < np && qd_model_param(m, i) != s)
        i++;
    return i;
}

/* A name in a value that is not pi, e or a parameter. */
static qd_status refuse_symbol(qd_ctx *ctx, const qd_model *m, const char *text, size_t start,
                               size_t end, const qd_expr *s) {
    const char *name = qd_expr_name(s);
    size_t at = word_at(text, start, end, name), np = m ? qd_model_nparams(m) : 0;
    const char **names = malloc((np + 2) * sizeof *names);
    if (!names)
        return nomem(ctx);
    names[0] = "pi";
    names[1] = "e";
    for (size_t i = 0; i < np; i++)
        names[i + 2] = qd_expr_name(qd_model_param(m, i));
    const char *near = qd_nearest_name(name, strlen(name), names, np + 2);
    char hint[160];
    snprintf(hint, sizeof hint, "did you mean '%s'?", near ? near : "");
    qd_role role = qd_symbol_role(s);
    qd_status st;
    if (role == QD_ROLE_TIME || role == QD_ROLE_COORD)
        st = fail(ctx, text, at, strlen(name), near ? hint : NULL,
                  "'%s' is not a constant: only pi, e and the parameters may appear in a value",
                  name);
    else
        st = fail(ctx, text, at, strlen(name), near ? hint : NULL,
                  "unknown name '%s' (a value takes pi, e and the model's parameters)", name);
    free(names);
    return st;
}


/* x's value at m's parameters. */
static qd_status eval_params(qd_ctx *ctx, const qd_model *m, const qd_expr *x, double *out) {
    size_t np = m ? qd_model_nparams(m) : 0;
    const qd_expr **syms = malloc((np + 1) * sizeof *syms);
    double *vals = malloc((np + 1) * sizeof *vals);
    qd_status st = syms && vals ? QD_OK : nomem(ctx);
    for (size_t i = 0; st == QD_OK && i < np; i++) {
        syms[i] = qd_model_param(m, i);
        if (qd_model_param_number(m, i, &vals[i]) != QD_OK)
            vals[i] = NAN; /* an error only if x uses it */
    }
    if (st == QD_OK)
        st = qd_eval(ctx, x, np, syms, vals, out);
    free(syms);
    free(vals);
    return st;
}

qd_status qd_state_value(qd_ctx *ctx, const qd_model *m, const char *text, size_t start,
                         size_t len, const qd_expr **exact, double *val) {
    QD_ARGS_CTX(ctx, text && exact && val);
    size_t n = strlen(text), end = start + len;
    if (start > n || len > n - start) {
        qd_ctx_error(ctx, QD_ERR_ARG, "qd_state_value: the value's span is outside the text");
        return QD_ERR_ARG;
    }
    char *copy = qd__diag_blanked(text, start, end);
    if (!copy)
        return nomem(ctx);
    const qd_read_opts ro = {.new_symbols = true};
    const qd_expr *x = qd_read(ctx, copy, &ro, NULL);
    qd_status st = x ? QD_OK : qd_ctx_status(ctx); /* located by the reader */
    free(copy);
    size_t k = x ? qd_free_symbols(ctx, x, NULL, 0) : 0;
    const qd_expr **free_syms = k ? malloc(k * sizeof *free_syms) : NULL;
    if (st == QD_OK && k && !free_syms)
        st = nomem(ctx);
    if (st == QD_OK && k)
        qd_free_symbols(ctx, x, free_syms, k);
    for (size_t i = 0; st == QD_OK && i < k; i++)
        if (!m || param_index(m, free_syms[i]) == qd_model_nparams(m))
            st = refuse_symbol(ctx, m, text, start, end, free_syms[i]);
    free(free_syms);
    /* the value as it is written, trimmed, for messages */
    while (start < end && isspace((unsigned char)text[start]))
        start++;
    while (end > start && isspace((unsigned char)text[end - 1]))
        end--;
    int w = (int)(end - start);
    double v = NAN;
    if (st == QD_OK && qd_is_number(x)) {
        v = number_value(x);
        if (!isfinite(v)) /* exact, but beyond a double: nothing can compute with it */
            st = fail(ctx, text, start, end - start, NULL, "'%.*s' is too large to compute with",
                      w, text + start);
    } else if (st == QD_OK) {
        st = eval_params(ctx, m, x, &v);
        if (st == QD_ERR_NOMEM)
            return st;
        if (st != QD_OK) {
            qd_ctx_error_at(ctx, text, start, end - start);
        } else if (!isfinite(v)) {
            st = fail(ctx, text, start, end - start, NULL,
                      "'%.*s' does not evaluate to a finite number", w, text + start);
        }
    }
    if (st == QD_OK) {
        *exact = x;
        *val = v;
    }
    return st;
}

/* ---- a name ------------------------------------------------------------------ */

/* The coordinates (and the speeds that are slots of st) in words, for
 * "unknown name": a state of q, q' (Lagrange's form of a model with
 * speeds) does not take its speeds, so it does not name them. */
static void put_known(const qd_model *m, const qd_state *st, qd_buf *b) {
    for (size_t i = 0; i < qd_model_ncoords(m); i++)
        qd_buf_printf(b, "%s%s", i ? ", " : "", qd_expr_name(qd_model_coord(m, i)));
    size_t listed = 0;
    for (size_t i = 0; i < qd_model_nspeeds(m); i++)
        if (qd_state_find(st, qd_model_speed(m, i)) < st->n)
            qd_buf_printf(b, "%s%s", listed++ ? ", " : "; the speeds are ",
                          qd_expr_name(qd_model_speed(m, i)));
}

/* The model's speed named name[0, len) that st has no slot for, or NULL. */
static const qd_expr *absent_speed(const qd_model *m, const qd_state *st, const char *name,
                                   size_t len) {
    for (size_t i = 0; i < qd_model_nspeeds(m); i++) {
        const qd_expr *u = qd_model_speed(m, i);
        const char *s = qd_expr_name(u);
        if (strlen(s) == len && !strncmp(s, name, len) && qd_state_find(st, u) == st->n)
            return u;
    }
    return NULL;
}

/* "did you mean": the nearest coordinate (with the primes written),
 * t, or the name of another slot. */
static void nearest_hint(const qd_model *m, const qd_state *st, const char *name, size_t len,
                         size_t primes, char *hint, size_t cap) {
    size_t nq = qd_model_ncoords(m), count = 0;
    const char **names = malloc((st->n + 2) * sizeof *names);
    hint[0] = '\0';
    if (!names)
        return;
    for (size_t j = 0; j < nq; j++)
        names[count++] = qd_expr_name(qd_model_coord(m, j));
    size_t ncoord = count;
    if (!primes) {
        names[count++] = qd_model_independent(m) ? qd_model_independent(m) : "t";
        for (size_t k = qd_slot_time(nq) + 1; k < st->n; k++)
            if (qd_expr_name(st->syms[k]))
                names[count++] = qd_expr_name(st->syms[k]);
    }
    const char *near = qd_nearest_name(name, len, names, count);
    bool coord = false;
    for (size_t j = 0; near && j < ncoord; j++)
        coord = coord || near == names[j];
    if (near)
        snprintf(hint, cap, "did you mean '%s%s'?", near,
                 coord && primes == 1 ? "'" : coord && primes > 1 ? "''" : "");
    free(names);
}

/* The independent coordinates in words. */
static void put_independent(const qd_state_read_opts *o, qd_buf *b) {
    for (size_t j = 0; j < o->nindependent; j++)
        qd_buf_printf(b, "%s%s", j ? ", " : "", qd_expr_name(o->independent[j]));
}

static bool independent(const qd_state_read_opts *o, const qd_expr *q) {
    if (!o || !o->independent)
        return true;
    for (size_t j = 0; j < o->nindependent; j++)
        if (o->independent[j] == q)
            return true;
    return false;
}

/* The slot named text[a, a + len), or an error at it. */
static qd_status resolve(qd_ctx *ctx, const qd_model *m, const qd_state *st, const char *text,
                         size_t a, size_t len, const qd_state_read_opts *o, size_t *slot) {
    const char *name = text + a;
    unsigned refuse = o ? o->refuse : 0;
    size_t base = len, primes = 0, nq = qd_model_ncoords(m), np = qd_model_nparams(m);
    int w = (int)len;
    while (base && name[base - 1] == '\'') {
        base--;
        primes++;
    }
    for (size_t j = 0; j < nq; j++) {
        const char *q = qd_expr_name(qd_model_coord(m, j));
        if (strlen(q) != base || strncmp(q, name, base))
            continue;
        if (primes > 1)
            return fail(ctx, text, a, len, NULL, "'%.*s' is an acceleration, which the equations "
                        "of motion give: give %s and %s'", w, name, q, q);
        if (!independent(o, qd_model_coord(m, j))) {
            qd_buf b = QD_BUF_INIT;
            put_independent(o, &b);
            qd_status s = fail(ctx, text, a, len, NULL, "%s is not an independent coordinate "
                               "here (a constraint eliminates it); give values of %s", q,
                               b.failed ? "the others" : qd_buf_str(&b));
            qd_buf_free(&b);
            return s;
        }
        if (primes && (refuse & QD_STATE_VELOCITIES))
            return fail(ctx, text, a, len, NULL,
                        "give coordinates only (a point at rest), not %s'", q);
        *slot = primes ? qd_slot_velocity(nq, j) : qd_slot_coord(nq, j);
        return QD_OK;
    }
    const char *x = qd_model_independent(m), *tn = x ? x : "t";
    bool is_t = !primes && ((base == 1 && name[0] == 't') ||
                            (x && strlen(x) == base && !strncmp(x, name, base)));
    if (is_t && (refuse & QD_STATE_TIME))
        return fail(ctx, text, a, len, NULL, "give coordinates%s only, not the time %s",
                    refuse & QD_STATE_VELOCITIES ? "" : " and velocities", tn);
    if (is_t) {
        *slot = qd_slot_time(nq);
        return QD_OK;
    }
    for (size_t k = qd_slot_time(nq) + 1; !primes && k < st->n; k++) {
        const char *s = qd_expr_name(st->syms[k]);
        if (!s || strlen(s) != base || strncmp(s, name, base))
            continue;
        bool param = k < qd_slot_count(nq, np);
        if (param && (refuse & QD_STATE_PARAMS))
            return fail(ctx, text, a, len, NULL, "%s is a parameter: its value is the model's, "
                        "not a point's", s);
        if (!param && (refuse & QD_STATE_EXTRA))
            return fail(ctx, text, a, len, NULL, "%s cannot be given here", s);
        *slot = k;
        return QD_OK;
    }
    if (!primes && absent_speed(m, st, name, base))
        return fail(ctx, text, a, len, "give the coordinates and their velocities (q')",
                    "'%.*s' is a speed: this state is of the coordinates and their velocities, "
                    "not of the speeds", w, name);
    char hint[192];
    nearest_hint(m, st, name, base, primes, hint, sizeof hint);
    qd_buf b = QD_BUF_INIT;
    put_known(m, st, &b);
    qd_status s = fail(ctx, text, a, len, hint[0] ? hint : NULL,
                       "unknown name '%.*s' (the coordinates are %s; velocities are written "
                       "with a prime, and %s is the %s)", w, name,
                       b.failed ? "..." : qd_buf_str(&b), tn,
                       x ? "independent variable" : "time");
    qd_buf_free(&b);
    return s;
}

/* The first place of sep in text[start, end) outside brackets; end if none. */
static size_t range_split(const char *text, size_t start, size_t end, const char *sep) {
    size_t k = strlen(sep);
    for (int depth = 0; start + k <= end; start++) {
        depth += (text[start] == '(' || text[start] == '[') -
                 (text[start] == ')' || text[start] == ']');
        if (depth == 0 && !strncmp(text + start, sep, k))
            return start;
    }
    return end;
}

qd_status qd_state_range(qd_ctx *ctx, const qd_model *m, const char *text, size_t start,
                         size_t len, double *a, double *b) {
    QD_ARGS_CTX(ctx, text && a && b);
    size_t n = strlen(text), end = start + len;
    if (start > n || len > n - start) {
        qd_ctx_error(ctx, QD_ERR_ARG, "qd_state_range: the range's span is outside the text");
        return QD_ERR_ARG;
    }
    /* A:B; the old spelling A..B (equilibria --box before issue 31) is still
     * read: ".." is no part of an expression, so it cannot be misread */
    size_t sep = 1, colon = range_split(text, start, end, ":");
    if (colon == end && (colon = range_split(text, start, end, "..")) != end)
        sep = 2;
    if (colon == end) {
        size_t ia = start, ib = end;
        while (ia < ib && isspace((unsigned char)text[ia]))
            ia++;
        while (ib > ia && isspace((unsigned char)text[ib - 1]))
            ib--;
        return fail(ctx, text, ia, ib - ia, "a range is A:B, each a number or an expression in "
                    "the parameters", "expected a range A:B, not '%.*s'", (int)(ib - ia),
                    text + ia);
    }
    const qd_expr *x;
    qd_status st = qd_state_value(ctx, m, text, start, colon - start, &x, a);
    return st == QD_OK ? qd_state_value(ctx, m, text, colon + sep, end - colon - sep, &x, b) : st;
}

/* ---- the list ---------------------------------------------------------------- */

static bool blank(const char *s, size_t a, size_t b) {
    while (a < b && isspace((unsigned char)s[a]))
        a++;
    return a == b;
}

/* One NAME=VALUE, text[a, b); with lo and hi (a range reader), NAME=A:B
 * into lo[slot] and hi[slot]. */
static qd_status read_item(qd_ctx *ctx, const qd_model *m, qd_state *st, const char *text,
                           size_t a, size_t b, bool *seen, const qd_state_read_opts *o,
                           double *lo, double *hi) {
    const char *eq = memchr(text + a, '=', b - a);
    size_t na = a, nb = eq ? (size_t)(eq - text) : b;
    while (na < nb && isspace((unsigned char)text[na]))
        na++;
    while (nb > na && isspace((unsigned char)text[nb - 1]))
        nb--;
    if (!eq || na == nb) {
        size_t ia = a, ib = b;
        while (ia < ib && isspace((unsigned char)text[ia]))
            ia++;
        while (ib > ia && isspace((unsigned char)text[ib - 1]))
            ib--;
        return fail(ctx, text, ia, ib - ia, NULL, "expected NAME=%s, not '%.*s'",
                    lo ? "A:B" : "VALUE", (int)(ib - ia), text + ia);
    }
    size_t slot;
    qd_status s = resolve(ctx, m, st, text, na, nb - na, o, &slot);
    if (s != QD_OK)
        return s;
    if (seen[slot])
        return fail(ctx, text, na, nb - na, NULL, "'%.*s' is given twice", (int)(nb - na),
                    text + na);
    seen[slot] = true;
    size_t v = (size_t)(eq + 1 - text);
    if (lo) {
        if ((s = qd_state_range(ctx, m, text, v, b - v, &lo[slot], &hi[slot])) != QD_OK)
            return s;
        size_t va = v, vb = b;
        while (va < vb && isspace((unsigned char)text[va]))
            va++;
        while (vb > va && isspace((unsigned char)text[vb - 1]))
            vb--;
        if (!(lo[slot] < hi[slot]) || !isfinite(hi[slot] - lo[slot]))
            return fail(ctx, text, va, vb - va, "give A < B, both finite and their difference too",
                        "the range of %.*s is %s", (int)(nb - na), text + na,
                        lo[slot] < hi[slot] ? "too wide: its width overflows a double"
                                            : "empty");
        if (o && o->given)
            o->given[slot] = true;
        return QD_OK;
    }
    const qd_expr *exact;
    double val;
    if ((s = qd_state_value(ctx, m, text, v, b - v, &exact, &val)) != QD_OK)
        return s;
    st->vals[slot] = val;
    if (o && o->exact)
        o->exact[slot] = exact;
    if (o && o->given)
        o->given[slot] = true;
    return QD_OK;
}

static qd_status read_list(qd_ctx *ctx, const qd_model *m, qd_state *st, const char *text,
                           const qd_state_read_opts *opts, double *lo, double *hi);

qd_status qd_state_read(qd_ctx *ctx, const qd_model *m, qd_state *st, const char *text,
                        const qd_state_read_opts *opts) {
    QD_ARGS_CTX(ctx, m && st && st->syms && st->vals && text);
    return read_list(ctx, m, st, text, opts, NULL, NULL);
}

qd_status qd_state_read_ranges(qd_ctx *ctx, const qd_model *m, const qd_state *st,
                               const char *text, const qd_state_read_opts *opts, double *lo,
                               double *hi) {
    QD_ARGS_CTX(ctx, m && st && st->syms && st->vals && text && lo && hi);
    return read_list(ctx, m, (qd_state *)st, text, opts, lo, hi); /* st is only looked up */
}

static qd_status read_list(qd_ctx *ctx, const qd_model *m, qd_state *st, const char *text,
                           const qd_state_read_opts *opts, double *lo, double *hi) {
    if (st->n < qd_slot_time(qd_model_ncoords(m)) + 1) {
        qd_ctx_error(ctx, QD_ERR_ARG, "qd_state_read: the state has fewer slots than the "
                                      "model's coordinates, velocities and t");
        return QD_ERR_ARG;
    }
    if (opts && opts->nindependent && !opts->independent)
        return qd__args_null(ctx, __func__);
    bool *seen = calloc(st->n, sizeof *seen);
    if (!seen)
        return nomem(ctx);
    qd_status s = QD_OK;
    for (size_t i = 0; text[i] && s == QD_OK;) {
        size_t end = qd_state_item_end(text, i);
        if (!blank(text, i, end))
            s = read_item(ctx, m, st, text, i, end, seen, opts, lo, hi);
        i = text[end] ? end + 1 : end;
    }
    free(seen);
    return s;
}

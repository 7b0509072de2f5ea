/*
 * src/mech/change_vars.c - a change of variables in an integral (Desloge
 * App. 19; qd_change_vars, qdot/form.h): the Jacobian matrix dx_i/dy_j of
 * x = x(y), its determinant J(x/y), J(y/x) = 1/J(x/y) (App. 18), the sign
 * of J where its form shows it, its zero set (where the region must be
 * split, App. 19 p. 913), and f(x(y)) |J(x/y)|, the integrand of eq. 1.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "qdot/form.h"
#include "qdot/read.h"
#include "qdot/state.h"
#include "base/args.h"
#include "base/diag.h"
#include "base/mem.h"
#include "mech.h"

void qd_change_free(qd_change *c) {
    if (!c)
        return;
    qd__free(c->x);
    qd__free(c->sing);
    qd__free(c);
}

static const qd_expr *tidy(qd_ctx *ctx, const qd_expr *e) {
    return e ? qd_simplify(ctx, qd_cancel(ctx, e)) : NULL;
}

static qd_change *change_alloc(qd_ctx *ctx, size_t n) {
    qd_change *c = qd__calloc(ctx, 1, sizeof *c);
    const qd_expr **blk = c ? qd__calloc(ctx, 3 * n + n * n + 1, sizeof *blk) : NULL;
    if (!blk) {
        qd__free(c);
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory changing variables");
        return NULL;
    }
    *c = (qd_change){.n = n, .x = blk, .y = blk + n, .map = blk + 2 * n, .jac = blk + 3 * n};
    return c;
}

/* The map's checks: x(y) free of the old variables, y symbols none twice. */
static bool well_formed(qd_ctx *ctx, size_t n, const qd_expr *const *x, const qd_expr *const *y,
                        const qd_expr *const *map) {
    for (size_t i = 0; i < n; i++) {
        if (!x[i] || !y[i] || !map[i] || qd_expr_kind(x[i]) != QD_SYMBOL ||
            qd_expr_kind(y[i]) != QD_SYMBOL) {
            qd_ctx_error(ctx, QD_ERR_ARG, "change of variables: variable %zu is not a symbol",
                         i + 1);
            return false;
        }
        for (size_t j = 0; j < n; j++) {
            if (qd_has(map[i], x[j])) {
                qd_ctx_error(ctx, QD_ERR_ARG, "change of variables: %s = ... depends on %s: "
                             "give the old variables in terms of the new ones only",
                             qd_expr_name(x[i]), qd_expr_name(x[j]));
                return false;
            }
            if (j < i && (y[j] == y[i] || x[j] == x[i] || y[i] == x[j])) {
                qd_ctx_error(ctx, QD_ERR_ARG, "change of variables: %s is given twice",
                             qd_expr_name(y[j] == y[i] ? y[i] : x[i]));
                return false;
            }
        }
    }
    return true;
}

/* 1 when x >= 0 by its form (qd__mech_nonneg), -1 when -x is, else 0. */
static int form_sign(qd_ctx *ctx, const qd_expr *x, const qd_expr **neg) {
    bool pos;
    *neg = tidy(ctx, qd_neg(ctx, x));
    return qd__mech_nonneg(x, &pos) ? 1 : *neg && qd__mech_nonneg(*neg, &pos) ? -1 : 0;
}

/* |x| factor by factor: a factor of known sign leaves abs (r^2 abs(sin(th))). */
static const qd_expr *abs_of(qd_ctx *ctx, const qd_expr *x) {
    const qd_expr *neg;
    int s = form_sign(ctx, x, &neg);
    if (s)
        return s > 0 ? x : neg;
    if (qd_expr_kind(x) != QD_MUL)
        return qd_fn(ctx, QD_ABS, x);
    const qd_expr *p = qd_int(ctx, 1);
    for (size_t i = 0; i < qd_expr_nargs(x); i++)
        p = qd_mul(ctx, p, abs_of(ctx, qd_expr_arg(x, i)));
    return p;
}

/* sign and |J|: J's form decides the sign, else |J| keeps abs. */
static void magnitude(qd_ctx *ctx, qd_change *c) {
    const qd_expr *neg;
    c->sign = form_sign(ctx, c->det, &neg);
    c->absdet = tidy(ctx, abs_of(ctx, c->det));
}

qd_change *qd_change_vars(qd_ctx *ctx, const qd_expr *f, size_t n, const qd_expr *const *x,
                          const qd_expr *const *y, const qd_expr *const *map) {
    QD_ARGS(NULL, ctx && x && y && map);
    if (n == 0) {
        qd_ctx_error(ctx, QD_ERR_ARG, "change of variables: no variables");
        return NULL;
    }
    if (!well_formed(ctx, n, x, y, map))
        return NULL;
    qd_change *c = change_alloc(ctx, n);
    if (!c)
        return NULL;
    memcpy(c->x, x, n * sizeof *x);
    memcpy(c->y, y, n * sizeof *y);
    for (size_t i = 0; i < n; i++) {
        c->map[i] = tidy(ctx, map[i]);
        for (size_t j = 0; j < n; j++)
            c->jac[i * n + j] = tidy(ctx, qd_diff(ctx, c->map[i], y[j]));
    }
    c->det = qd__mech_det(ctx, n, c->jac);
    c->det = c->det ? qd_simplify(ctx, qd_trigsimp(ctx, tidy(ctx, c->det))) : NULL;
    if (c->det && qd_is_zero(c->det)) {
        qd_ctx_error(ctx, QD_ERR_SINGULAR, "the Jacobian J(x/y) of the change is 0 everywhere: "
                     "the new variables do not determine the old ones (Desloge App. 18)");
        qd_change_free(c);
        return NULL;
    }
    if (c->det) {
        c->inverse = tidy(ctx, qd_div(ctx, qd_int(ctx, 1), c->det));
        magnitude(ctx, c);
        c->f = f;
        if (f)
            c->integrand = tidy(ctx, qd_mul(ctx, qd_subs(ctx, f, n, x, c->map), c->absdet));
    }
    if (qd_ctx_status(ctx) == QD_OK && c->det)
        qd__mech_zero_set(ctx, c->det, n, y, &c->sing, &c->nsing);
    if (qd_ctx_status(ctx) != QD_OK || !c->det || !c->absdet || (f && !c->integrand)) {
        if (qd_ctx_status(ctx) == QD_OK)
            qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory changing variables");
        qd_change_free(c);
        return NULL;
    }
    return c;
}

/* ---- "x = r*cos(th), y = r*sin(th)" --------------------------------------- */

static qd_status cr_fail(qd_ctx *ctx, const char *text, size_t off, size_t len, const char *msg) {
    qd_ctx_error(ctx, QD_ERR_ARG, "%s", msg);
    qd_ctx_error_about(ctx, QD_SUBJECT_TEXT, 0, NULL, QD_REASON_NONE,
                       "give each old variable once in terms of the new ones: "
                       "\"x = r*cos(th), y = r*sin(th)\"");
    qd_ctx_error_at(ctx, text, off, len ? len : 1);
    return QD_ERR_ARG;
}

/* The old variable named in text[a, e) (blanks around it skipped): its index or n. */
static size_t old_index(const char *text, size_t a, size_t e, size_t n, const qd_expr *const *x,
                        size_t *na, size_t *ne) {
    while (a < e && (text[a] == ' ' || text[a] == '\t'))
        a++;
    while (e > a && (text[e - 1] == ' ' || text[e - 1] == '\t'))
        e--;
    *na = a;
    *ne = e;
    for (size_t i = 0; i < n; i++) {
        const char *nm = qd_expr_name(x[i]);
        if (strlen(nm) == e - a && strncmp(nm, text + a, e - a) == 0)
            return i;
    }
    return n;
}

static qd_status read_item(qd_ctx *ctx, const char *text, size_t a, size_t b, size_t n,
                           const qd_expr *const *x, const qd_expr **map) {
    size_t eq = a, na, ne;
    while (eq < b && text[eq] != '=')
        eq++;
    if (eq == b)
        return cr_fail(ctx, text, a, b - a, "expected 'OLD = expression in the new variables'");
    size_t i = old_index(text, a, eq, n, x, &na, &ne);
    char msg[160];
    if (i == n) {
        snprintf(msg, sizeof msg, "'%.*s' is not one of the variables of --vars", (int)(ne - na),
                 text + na);
        return cr_fail(ctx, text, na, ne - na, msg);
    }
    if (map[i]) {
        snprintf(msg, sizeof msg, "%s is given twice", qd_expr_name(x[i]));
        return cr_fail(ctx, text, na, ne - na, msg);
    }
    char *copy = qd__diag_blanked(text, eq + 1, b); /* the reader's place is the text's */
    if (!copy) {
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory");
        return QD_ERR_NOMEM;
    }
    map[i] = qd_read(ctx, copy, NULL, NULL);
    free(copy);
    if (!map[i]) {
        qd_status st = qd_ctx_status(ctx);
        return st != QD_OK ? st : QD_ERR_PARSE;
    }
    return QD_OK;
}

qd_status qd_change_read(qd_ctx *ctx, const char *text, size_t n, const qd_expr *const *x,
                         const qd_expr **map) {
    QD_ARGS_CTX(ctx, ctx && text && x && map && n);
    size_t a = 0, len = strlen(text);
    for (size_t i = 0; i < n; i++)
        map[i] = NULL;
    while (text[a]) { /* a trailing comma ends the list */
        size_t b = qd_state_item_end(text, a);
        qd_status st = read_item(ctx, text, a, b, n, x, map);
        if (st != QD_OK)
            return st;
        a = text[b] ? b + 1 : b;
    }
    for (size_t i = 0; i < n; i++)
        if (!map[i]) {
            char msg[160];
            snprintf(msg, sizeof msg, "%s is not given in terms of the new variables",
                     qd_expr_name(x[i]));
            return cr_fail(ctx, text, 0, len, msg);
        }
    return QD_OK;
}

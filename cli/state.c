/*
 * cli/state.c - --set and --at: names resolved against the model, values
 * read as expressions and required to evaluate to finite numbers.
 */
#include "state.h"

#include <ctype.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "cli.h"

double cli_state_value(const qd_expr *number) {
    long p, q;
    /* both exact in a double, so the one division rounds correctly */
    if (qd_rational_get(number, &p, &q) && fabs((double)p) <= 0x1p53 && (double)q <= 0x1p53)
        return (double)p / (double)q;
    return qd_number_value(number);
}

double cli_param_value(const qd_model *m, size_t i) {
    double x;
    qd_model_param_number(m, i, &x); /* NaN when it has none */
    return x;
}

void cli_state_put_double(qd_buf *b, double x) {
    qd_buf_put_double(b, x == 0 ? 0.0 : x); /* -0 reads "0" */
}

void cli_state_put_result(qd_buf *b, double x) {
    char s[40];
    if (fabs(x) < 1e-13) {
        qd_buf_puts(b, "0");
        return;
    }
    snprintf(s, sizeof s, "%.12g", x);
    qd_buf_puts(b, s);
}

int cli_state_init(qd_ctx *ctx, const qd_model *m, cli_state *st) {
    size_t nq = qd_model_ncoords(m), np = qd_model_nparams(m), n = 2 * nq + 1 + np;
    st->n = n;
    st->syms = calloc(n, sizeof *st->syms);
    st->vals = calloc(n, sizeof *st->vals);
    if (!st->syms || !st->vals) {
        cli_state_free(st);
        cli_diag_error("out of memory");
        return QD_EXIT_FAIL;
    }
    for (size_t i = 0; i < nq; i++) {
        st->syms[i] = qd_model_coord(m, i);
        st->syms[nq + i] = qd_jet(ctx, qd_model_coord(m, i), 1);
    }
    st->syms[2 * nq] = qd_time(ctx);
    for (size_t i = 0; i < np; i++) {
        st->syms[2 * nq + 1 + i] = qd_model_param(m, i);
        qd_status s = qd_model_param_number(m, i, &st->vals[2 * nq + 1 + i]);
        if (s == QD_ERR_NOMEM)
            return cli_diag_ctx(ctx);
        if (s != QD_OK) {
            cli_diag_error("parameter %s has no finite value", qd_expr_name(qd_model_param(m, i)));
            return QD_EXIT_FAIL;
        }
    }
    return QD_EXIT_OK;
}

void cli_state_free(cli_state *st) {
    free(st->syms);
    free(st->vals);
    st->syms = NULL;
    st->vals = NULL;
    st->n = 0;
}

/* The value text[start, start+len) of a NAME=VALUE in the option `label`;
 * errors are shown against the whole option text. */
static int read_value(qd_ctx *ctx, const char *label, const char *what, const char *text,
                      size_t start, size_t len, const qd_expr **exact, double *val) {
    char *copy = malloc(len + 1);
    if (!copy)
        return QD_EXIT_FAIL;
    memcpy(copy, text + start, len);
    copy[len] = '\0';
    qd_diag err;
    const qd_read_opts opts = {.new_symbols = false};
    const qd_expr *e = qd_read(ctx, copy, &opts, &err);
    int rc = QD_EXIT_OK;
    if (!e) {
        err.offset += start;
        cli_diag_read(label, text, &err);
        rc = QD_EXIT_USAGE;
    } else if (qd_is_number(e) && isfinite(cli_state_value(e))) {
        *val = cli_state_value(e);
        *exact = e;
    } else if (qd_is_number(e)) {
        /* exact, but beyond a double (1e400): no command can compute with it */
        cli_diag_error("%s: '%s' is too large to compute with", what, copy);
        rc = QD_EXIT_USAGE;
    } else if (qd_eval(ctx, e, 0, &e, val, val) != QD_OK || !isfinite(*val)) {
        qd_ctx_clear_error(ctx);
        cli_diag_error("%s: '%s' does not evaluate to a finite number", what, copy);
        rc = QD_EXIT_USAGE;
    } else {
        *exact = qd_is_number(e) ? e : qd_float(ctx, *val);
    }
    free(copy);
    return rc;
}

int cli_state_number(qd_ctx *ctx, const char *what, const char *text, const qd_expr **exact,
                    double *val) {
    return read_value(ctx, what, what, text, 0, strlen(text), exact, val);
}

int cli_state_read_set(qd_ctx *ctx, const char *arg, char *name, size_t cap,
                       const qd_expr **value) {
    const char *eq = strchr(arg, '=');
    if (!eq || eq == arg) {
        cli_diag_error("--set takes NAME=VALUE, not '%s'", arg);
        return QD_EXIT_USAGE;
    }
    size_t n = (size_t)(eq - arg);
    while (n && isspace((unsigned char)arg[n - 1]))
        n--;
    if (n >= cap) {
        cli_diag_error("--set: the name in '%s' is too long", arg);
        return QD_EXIT_USAGE;
    }
    memcpy(name, arg, n);
    name[n] = '\0';
    double v;
    return read_value(ctx, "--set", "--set", arg, (size_t)(eq + 1 - arg), strlen(eq + 1), value,
                      &v);
}

/* ---- --at ------------------------------------------------------------------ */

/* The coordinates, and the speeds when the model has some. */
static void list_coords(const qd_model *m, char *out, size_t cap) {
    size_t used = 0;
    out[0] = '\0';
    for (size_t i = 0; i < qd_model_ncoords(m) && used < cap; i++)
        used += (size_t)snprintf(out + used, cap - used, "%s%s", i ? ", " : "",
                                 qd_expr_name(qd_model_coord(m, i)));
    for (size_t i = 0; i < qd_model_nspeeds(m) && used < cap; i++)
        used += (size_t)snprintf(out + used, cap - used, "%s%s", i ? ", " : "; the speeds are ",
                                 qd_expr_name(qd_model_speed(m, i)));
}

/* The slot of NAME (a coordinate, a velocity NAME', t or a parameter) in st. */
static int find_slot(const char *opt, const qd_model *m, const cli_state *st, const char *name,
                     size_t *slot) {
    size_t len = strlen(name), primes = 0;
    while (len && name[len - 1] == '\'') {
        len--;
        primes++;
    }
    size_t nq = qd_model_ncoords(m);
    for (size_t i = 0; i < nq; i++) {
        const char *q = qd_expr_name(qd_model_coord(m, i));
        if (strlen(q) != len || strncmp(q, name, len))
            continue;
        if (primes > 1) {
            cli_diag_error("%s: '%s' is an acceleration: qdot computes it; give %.*s and %.*s'",
                          opt, name, (int)len, name, (int)len, name);
            return QD_EXIT_USAGE;
        }
        *slot = primes ? nq + i : i;
        return QD_EXIT_OK;
    }
    const char *x = qd_model_independent(m), *tn = x ? x : "t"; /* `independent x`: x is t */
    for (size_t i = 2 * nq; i < st->n && !primes; i++)
        if (!strcmp(qd_expr_name(st->syms[i]), x && !strcmp(name, x) ? "t" : name)) {
            *slot = i;
            return QD_EXIT_OK;
        }
    char known[512];
    list_coords(m, known, sizeof known);
    cli_diag_error("%s: unknown name '%s' (the coordinates are %s; velocities are written "
                  "with a prime, and %s is the %s)", opt, name, known, tn,
                  x ? "independent variable" : "time");
    return QD_EXIT_USAGE;
}

/* End of the item starting at i: the next comma outside brackets. */
static size_t item_end(const char *text, size_t i) {
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

/* One NAME=VALUE in text[a, b). */
static int parse_item(qd_ctx *ctx, const char *opt, const qd_model *m, const char *text,
                      size_t a, size_t b, cli_state *st, bool *given) {
    const char *eq = memchr(text + a, '=', b - a);
    size_t na = a, nb = eq ? (size_t)(eq - text) : b;
    while (na < nb && isspace((unsigned char)text[na]))
        na++;
    while (nb > na && isspace((unsigned char)text[nb - 1]))
        nb--;
    if (!eq || na == nb || nb - na >= 128) {
        cli_diag_error("%s: expected NAME=VALUE, not '%.*s'", opt, (int)(b - a), text + a);
        return QD_EXIT_USAGE;
    }
    char name[128], what[160];
    memcpy(name, text + na, nb - na);
    name[nb - na] = '\0';
    size_t slot;
    int rc = find_slot(opt, m, st, name, &slot);
    if (rc != QD_EXIT_OK)
        return rc;
    if (given[slot]) {
        cli_diag_error("%s: '%s' is given twice", opt, name);
        return QD_EXIT_USAGE;
    }
    given[slot] = true;
    snprintf(what, sizeof what, "%s %s", opt, name);
    size_t v = (size_t)(eq + 1 - text);
    const qd_expr *exact;
    return read_value(ctx, opt, what, text, v, b - v, &exact, &st->vals[slot]);
}

int cli_state_parse(qd_ctx *ctx, const qd_model *m, const char *text, cli_state *st) {
    return cli_state_parse_as(ctx, m, "--at", text, st);
}

int cli_state_parse_as(qd_ctx *ctx, const qd_model *m, const char *what, const char *text,
                      cli_state *st) {
    bool *given = calloc(st->n ? st->n : 1, sizeof *given);
    if (!given)
        return QD_EXIT_FAIL;
    int rc = QD_EXIT_OK;
    for (size_t i = 0; text[i] && rc == QD_EXIT_OK;) {
        size_t end = item_end(text, i);
        size_t k = i;
        while (k < end && isspace((unsigned char)text[k]))
            k++;
        if (k < end)  /* empty items ("a=1,") are allowed */
            rc = parse_item(ctx, what, m, text, i, end, st, given);
        i = text[end] ? end + 1 : end;
    }
    free(given);
    return rc;
}

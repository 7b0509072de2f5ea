/*
 * cli/scan_cli.c - `qdot modes FILE --scan NAME=A:B`: the equilibrium
 * followed along a parameter (qd_modes_scan) and the values where its
 * stability changes, as a table (text) or samples and `transitions`
 * (JSON).  The --about point may be written in the parameters
 * (x = 1/2 - mu): it is kept as expressions and evaluated at each value.
 */
#include "linear_cli.h"

#include <ctype.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "qdot/state.h"
#include "qdot/json.h"
#include "model_cli.h"

static const char *verdict_name(int s) {
    return s == 1 ? "stable" : s == 0 ? "unstable" : "borderline";
}

/* ---- reading --------------------------------------------------------------- */

int cli_scan_range(qd_ctx *ctx, const char *text, char *name, size_t cap, double *a,
                   double *b) {
    const char *eq = strchr(text, '='), *colon = eq ? strchr(eq, ':') : NULL;
    if (!eq || !colon) {
        cli_diag_error("--scan takes NAME=A:B (a parameter and its range), not '%s'", text);
        return QD_EXIT_USAGE;
    }
    size_t s = 0, e = (size_t)(eq - text);
    while (s < e && isspace((unsigned char)text[s]))
        s++;
    while (e > s && isspace((unsigned char)text[e - 1]))
        e--;
    if (e == s || e - s >= cap) {
        cli_diag_error("--scan: no parameter name in '%s'", text);
        return QD_EXIT_USAGE;
    }
    memcpy(name, text + s, e - s);
    name[e - s] = '\0';
    size_t la = (size_t)(colon - eq - 1);
    char *lo = malloc(la + 1);
    if (!lo)
        return QD_EXIT_FAIL;
    memcpy(lo, eq + 1, la);
    lo[la] = '\0';
    const qd_expr *x;
    int rc = cli_state_number(ctx, "--scan", lo, &x, a);
    if (rc == QD_EXIT_OK)
        rc = cli_state_number(ctx, "--scan", colon + 1, &x, b);
    free(lo);
    return rc;
}

/* The index in e->q of the coordinate called name; e->n when none. */
static size_t coord_index(const cli_lin_run *r, const char *name) {
    size_t j = 0;
    while (j < r->e->n && strcmp(qd_expr_name(r->e->q[j]), name))
        j++;
    return j;
}

static bool is_model_coord(const cli_lin_run *r, const char *name) {
    for (size_t i = 0; i < qd_model_ncoords(r->mf.model); i++)
        if (!strcmp(qd_expr_name(qd_model_coord(r->mf.model, i)), name))
            return true;
    return false;
}

/* The value of one coordinate: an expression in the parameters only. */
static int about_value(cli_lin_run *r, const char *name, const char *text, const qd_expr **out) {
    qd_diag err;
    const qd_read_opts opts = {.new_symbols = false};
    const qd_expr *x = qd_read(r->ctx, text, &opts, &err);
    if (!x) {
        cli_diag_read("--about", text, &err);
        return QD_EXIT_USAGE;
    }
    size_t nq = qd_model_ncoords(r->mf.model), off = 2 * nq + 1;
    double v;
    if (qd_eval(r->ctx, x, r->st.n - off, r->st.syms + off, r->st.vals + off, &v) != QD_OK ||
        !isfinite(v)) {
        qd_ctx_clear_error(r->ctx);
        cli_diag_error("--about %s: '%s' is not a number or an expression in the parameters",
                      name, text);
        return QD_EXIT_USAGE;
    }
    *out = x;
    return QD_EXIT_OK;
}

/* One NAME = EXPR item of --about. */
static int about_item(cli_lin_run *r, const char *item, const qd_expr **about, bool *seen) {
    const char *eq = strchr(item, '=');
    char name[128];
    size_t s = 0, e = eq ? (size_t)(eq - item) : 0;
    while (s < e && isspace((unsigned char)item[s]))
        s++;
    while (e > s && isspace((unsigned char)item[e - 1]))
        e--;
    if (!eq || e == s || e - s >= sizeof name) {
        cli_diag_error("--about: expected NAME=VALUE, not '%s'", item);
        return QD_EXIT_USAGE;
    }
    memcpy(name, item + s, e - s);
    name[e - s] = '\0';
    size_t j = coord_index(r, name);
    if (j == r->e->n) {
        cli_diag_error(is_model_coord(r, name)
                           ? "--about: %s is not an independent coordinate here (a constraint "
                             "eliminates it)"
                           : "--about: '%s' is not a coordinate", name);
        return QD_EXIT_USAGE;
    }
    if (seen[j]) {
        cli_diag_error("--about: %s is given twice", name);
        return QD_EXIT_USAGE;
    }
    seen[j] = true;
    return about_value(r, name, eq + 1, &about[j]);
}

int cli_scan_about(cli_lin_run *r, const char *text, const qd_expr **about) {
    size_t n = r->e->n;
    bool *seen = calloc(n + 1, sizeof *seen);
    char *item = malloc(strlen(text) + 1);
    int rc = seen && item ? QD_EXIT_OK : QD_EXIT_FAIL;
    for (size_t j = 0; j < n; j++)
        about[j] = qd_int(r->ctx, 0);
    for (size_t i = 0; rc == QD_EXIT_OK && text[i];) {
        size_t end = qd_state_item_end(text, i);
        memcpy(item, text + i, end - i);
        item[end - i] = '\0';
        if (strspn(item, " \t") < strlen(item))
            rc = about_item(r, item, about, seen);
        i = text[end] ? end + 1 : end;
    }
    free(seen);
    free(item);
    return rc;
}

/* ---- text ---------------------------------------------------------------------- */

/* x as cli_state_put_result writes it, right-aligned in w columns. */
static void put_cell(qd_buf *b, double x, int w) {
    qd_buf cell = QD_BUF_INIT;
    cli_state_put_result(&cell, x);
    qd_buf_printf(b, " %*s", w, qd_buf_str(&cell));
    b->failed = b->failed || cell.failed;
    qd_buf_free(&cell);
}

static bool all_conservative(const qd_scan *sc) {
    for (size_t k = 0; k < sc->count; k++)
        if (!sc->conservative[k])
            return false;
    return true;
}

static void put_text(const cli_scan_view *v, const qd_scan *sc, qd_buf *b) {
    size_t n = sc->n;
    bool cons = all_conservative(sc);
    qd_buf_printf(b, "scan of %s from ", v->param);
    cli_state_put_result(b, sc->value[0]);
    qd_buf_puts(b, " to ");
    cli_state_put_result(b, sc->value[sc->count - 1]);
    qd_buf_printf(b, " in %zu steps, following %s\n", sc->count - 1, v->followed);
    qd_buf_printf(b, " %14s", v->param);
    for (size_t j = 0; j < n; j++)
        qd_buf_printf(b, " %14s", v->names[j]);
    qd_buf_printf(b, " %14s  verdict\n", cons ? "min w^2" : "max Re s");
    for (size_t k = 0; k < sc->count; k++) {
        put_cell(b, sc->value[k], 14);
        for (size_t j = 0; j < n; j++)
            put_cell(b, sc->q[k * n + j], 14);
        put_cell(b, sc->margin[k], 14);
        qd_buf_printf(b, "  %s\n", verdict_name(sc->stable[k]));
    }
    if (!sc->ntrans)
        qd_buf_puts(b, "no change of stability\n");
    for (size_t t = 0; t < sc->ntrans; t++) {
        const qd_scan_transition *tr = &sc->trans[t];
        qd_buf_printf(b, "transition: %s = %.10g, %s -> %s\n", v->param, tr->value,
                      verdict_name(tr->from), verdict_name(tr->to));
    }
}

/* ---- json ---------------------------------------------------------------------- */

static void json_verdict(qd_json *j, int s) {
    qd_json_key(j, "stable");
    if (s == -1)
        qd_json_null(j);
    else
        qd_json_bool(j, s == 1);
    qd_json_key(j, "verdict");
    qd_json_string(j, verdict_name(s));
}

static void json_samples(const cli_scan_view *v, const qd_scan *sc, qd_json *j) {
    qd_json_key(j, "samples");
    qd_json_begin_array(j);
    for (size_t k = 0; k < sc->count; k++) {
        qd_json_begin_object(j);
        qd_json_key(j, v->param);
        qd_json_number(j, sc->value[k]);
        qd_json_key(j, v->key);
        qd_json_begin_object(j);
        for (size_t i = 0; i < sc->n; i++) {
            qd_json_key(j, v->names[i]);
            qd_json_number(j, sc->q[k * sc->n + i]);
        }
        qd_json_end_object(j);
        qd_json_key(j, sc->conservative[k] ? "min_omega2" : "max_re_s");
        qd_json_number(j, sc->margin[k]);
        json_verdict(j, sc->stable[k]);
        qd_json_end_object(j);
    }
    qd_json_end_array(j);
}

static void put_json(const cli_scan_view *v, const qd_scan *sc, qd_buf *b) {
    const char *name = v->param;
    qd_json j;
    qd_json_init(&j, b);
    qd_json_begin_object(&j);
    qd_json_key(&j, "parameter");
    qd_json_string(&j, name);
    qd_json_key(&j, "range");
    qd_json_begin_array(&j);
    qd_json_number(&j, sc->value[0]);
    qd_json_number(&j, sc->value[sc->count - 1]);
    qd_json_end_array(&j);
    qd_json_key(&j, "steps");
    qd_json_number(&j, (double)(sc->count - 1));
    json_samples(v, sc, &j);
    qd_json_key(&j, "transitions");
    qd_json_begin_array(&j);
    for (size_t t = 0; t < sc->ntrans; t++) {
        const qd_scan_transition *tr = &sc->trans[t];
        qd_json_begin_object(&j);
        qd_json_key(&j, name);
        qd_json_number(&j, tr->value);
        qd_json_key(&j, "from");
        qd_json_string(&j, verdict_name(tr->from));
        qd_json_key(&j, "to");
        qd_json_string(&j, verdict_name(tr->to));
        qd_json_key(&j, "bracket");
        qd_json_begin_array(&j);
        qd_json_number(&j, tr->lo);
        qd_json_number(&j, tr->hi);
        qd_json_end_array(&j);
        qd_json_end_object(&j);
    }
    qd_json_end_array(&j);
    qd_json_end_object(&j);
    qd_buf_puts(b, "\n");
    b->failed = b->failed || !qd_json_ok(&j);
}

/* ---- the command ------------------------------------------------------------------- */

int cli_scan_emit(const cli_scan_view *v, const qd_scan *sc, bool json) {
    qd_buf out = QD_BUF_INIT;
    if (json)
        put_json(v, sc, &out);
    else
        put_text(v, sc, &out);
    return cli_emit(&out, "scan");
}

int cli_scan_modes(cli_lin_run *r, const char *range, const char *about, size_t steps, bool json) {
    char name[128];
    double a, b;
    int rc = cli_scan_range(r->ctx, range, name, sizeof name, &a, &b);
    const qd_expr **ab = NULL;
    const char **names = calloc(r->e->n + 1, sizeof *names);
    if (!names)
        rc = QD_EXIT_FAIL;
    if (rc == QD_EXIT_OK && about) {
        ab = calloc(r->e->n + 1, sizeof *ab);
        rc = ab ? cli_scan_about(r, about, ab) : QD_EXIT_FAIL;
    }
    qd_scan_opts o = {.steps = steps, .about = ab};
    qd_scan sc = {0};
    if (rc == QD_EXIT_OK && qd_modes_scan(r->ctx, r->e, r->mf.model, name, a, b, &o, &sc) != QD_OK) {
        rc = qd_ctx_status(r->ctx) == QD_ERR_ARG ? QD_EXIT_USAGE : QD_EXIT_FAIL;
        cli_diag_error("--scan: %s", qd_ctx_message(r->ctx));
    } else if (rc == QD_EXIT_OK) {
        char followed[1024];
        snprintf(followed, sizeof followed, about ? "the equilibrium from %s" : "%s",
                 about ? about : "the equilibrium chosen at the start (as `qdot modes` does)");
        for (size_t j = 0; j < r->e->n; j++)
            names[j] = qd_expr_name(r->e->q[j]);
        cli_scan_view v = {name, names, followed, "equilibrium"};
        rc = cli_scan_emit(&v, &sc, json);
    }
    qd_scan_free(&sc);
    free(ab);
    free(names);
    return rc;
}

/*
 * cli/lqr_model.c - an LQR design on a model: the operating point of
 * --about read against the model, the model linearized there, and the
 * weights of --lqr solved for the gain (`qdot linearize --lqr`, and
 * `qdot simulate --input "F = lqr"`).
 */
#include "cli.h"
#include "lqr_cli.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int cli_lqr_read_error(const char *opt, const char *text, const char *msg, size_t where) {
    qd_diag d = {.status = QD_ERR_PARSE, .located = true, .line = 1, .col = where + 1,
                 .offset = where, .length = 1};
    snprintf(d.message, sizeof d.message, "%s", msg);
    cli_diag_show(opt, text, &d);
    return QD_EXIT_USAGE;
}

/* ---- --about --------------------------------------------------------------- */

static int about_item(qd_ctx *ctx, const char *item, cli_point *pt) {
    const char *eq = strchr(item, '=');
    if (!eq) {
        cli_diag_error("--about: expected NAME=VALUE, not '%s'", item);
        return QD_EXIT_USAGE;
    }
    char name[128];
    size_t len = (size_t)(eq - item);
    if (len >= sizeof name) {
        cli_diag_error("--about: the name in '%s' is too long", item);
        return QD_EXIT_USAGE;
    }
    memcpy(name, item, len);
    name[len] = '\0';
    qd_diag err;
    const qd_read_opts opts = {.new_symbols = false};
    const qd_expr *sym = qd_read(ctx, name, &opts, &err);
    if (!sym || qd_expr_kind(sym) != QD_SYMBOL) {
        qd_ctx_clear_error(ctx);
        cli_diag_error("--about: '%s' is not a coordinate, velocity or input of the model", name);
        return QD_EXIT_USAGE;
    }
    const qd_expr *val = qd_read(ctx, eq + 1, &opts, &err);
    if (!val) {
        cli_diag_read("--about", eq + 1, &err);
        return QD_EXIT_USAGE;
    }
    for (size_t i = 0; i < pt->n; i++)
        if (pt->syms[i] == sym) {
            cli_diag_error("--about: %s is given twice", qd_expr_name(sym));
            return QD_EXIT_USAGE;
        }
    pt->syms[pt->n] = sym;
    pt->vals[pt->n++] = val;
    return QD_EXIT_OK;
}

/* "NAME=EXPR, ...", split at the commas outside brackets. */
int cli_point_read(qd_ctx *ctx, const char *text, cli_point *pt) {
    size_t len = strlen(text);
    char *item = malloc(len + 1);
    pt->cap = len / 2 + 2;
    pt->syms = calloc(2 * pt->cap, sizeof *pt->syms);
    if (!item || !pt->syms) {
        free(item);
        cli_diag_error("out of memory");
        return QD_EXIT_FAIL;
    }
    pt->vals = pt->syms + pt->cap;
    int rc = QD_EXIT_OK;
    for (size_t i = 0; rc == QD_EXIT_OK && i < len;) {
        size_t end = cli_item_end(text, i);
        memcpy(item, text + i, end - i);
        item[end - i] = '\0';
        if (strspn(item, " \t") < strlen(item))
            rc = about_item(ctx, item, pt);
        i = text[end] ? end + 1 : end;
    }
    free(item);
    return rc;
}

void cli_point_free(cli_point *pt) {
    free(pt->syms); /* vals live in the same block */
    pt->syms = pt->vals = NULL;
    pt->n = pt->cap = 0;
}

const qd_expr *cli_point_value(qd_ctx *ctx, const cli_point *pt, const qd_expr *sym) {
    for (size_t i = 0; i < pt->n; i++)
        if (pt->syms[i] == sym)
            return pt->vals[i];
    return qd_int(ctx, 0); /* qd_linearize's default for a symbol not given */
}

/* ---- the design ------------------------------------------------------------ */

static const char **names_of(const qd_statespace *s) {
    const char **names = malloc((s->nx + s->nu + 1) * sizeof *names);
    for (size_t k = 0; names && k < s->nx + s->nu; k++)
        names[k] = qd_expr_name(k < s->nx ? s->states[k] : s->inputs[k - s->nx]);
    return names;
}

int cli_lqr_design(qd_ctx *ctx, const qd_statespace *s, const char *weights,
                   qd_care_result *out) {
    if (s->nu == 0) {
        cli_diag_error("--lqr: the model has no inputs to feed back (declare `inputs F, ...`)");
        return QD_EXIT_USAGE;
    }
    char err[200];
    size_t where;
    double *Q = malloc(s->nx * s->nx * sizeof *Q), *R = malloc(s->nu * s->nu * sizeof *R);
    int rc = QD_EXIT_OK;
    if (!Q || !R) {
        cli_diag_error("out of memory");
        rc = QD_EXIT_FAIL;
    } else if (!cli_lqr_parse(weights, s->nx, s->nu, Q, R, err, sizeof err, &where)) {
        rc = cli_lqr_read_error("--lqr", weights, err, where);
    } else if (qd_care_solve(ctx, s->nx, s->nu, s->A, s->B, Q, R, out) != QD_OK) {
        rc = cli_diag_ctx(ctx);
    }
    free(Q);
    free(R);
    return rc;
}

int cli_lqr_print_design(FILE *out, const qd_statespace *s, const qd_care_result *r,
                         cli_lqr_format fmt) {
    const char **names = names_of(s);
    bool ok = names && cli_lqr_print(out, r, names, names + s->nx, fmt);
    free(names);
    if (ok)
        return QD_EXIT_OK;
    cli_diag_error("out of memory, or a number that is not finite, printing the design");
    return QD_EXIT_FAIL;
}

int cli_lqr_json_design(qd_json *j, const qd_statespace *s, const qd_care_result *r) {
    const char **names = names_of(s);
    if (!names) {
        cli_diag_error("out of memory");
        return QD_EXIT_FAIL;
    }
    cli_lqr_json(j, r, names, names + s->nx);
    free(names);
    return QD_EXIT_OK;
}

/*
 * cli/lqr_model.c - the LQR options on a model: the operating point of
 * --about read against the model, and the library's design (qd_lqr_design)
 * and printer (qd_lqr_print) with the errors shown (`qdot linearize --lqr`,
 * `qdot simulate --input "F = lqr"`, `qdot lqr`).
 */
#include "cli.h"
#include "lqr_cli.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int cli_lqr_error(const qd_ctx *ctx, const char *opt, const char *text) {
    if (qd_ctx_status(ctx) != QD_ERR_PARSE || !qd_ctx_diag(ctx)->located)
        return cli_diag_ctx(ctx);
    cli_diag_show(opt, text, qd_ctx_diag(ctx));
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
        size_t end = qd_state_item_end(text, i);
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

/* ---- the design ------------------------------------------------------------ */

int cli_lqr_design(qd_ctx *ctx, const qd_statespace *s, const char *weights,
                   qd_care_result *out) {
    return qd_lqr_design(ctx, s, weights, out) == QD_OK ? QD_EXIT_OK
                                                        : cli_lqr_error(ctx, "--lqr", weights);
}

int cli_lqr_print_design(FILE *out, const qd_statespace *s, const qd_care_result *r,
                         cli_lqr_format fmt) {
    qd_buf b = QD_BUF_INIT;
    qd_status st = qd_lqr_print(s, r, (qd_lqr_format)fmt, &b);
    if (st == QD_OK)
        fputs(qd_buf_str(&b), out);
    else
        cli_diag_error("%s printing the design", st == QD_ERR_NOMEM ? "out of memory"
                                                                    : "a number that is not finite");
    qd_buf_free(&b);
    return st == QD_OK ? QD_EXIT_OK : QD_EXIT_FAIL;
}

int cli_lqr_json_design(qd_json *j, const qd_statespace *s, const qd_care_result *r) {
    qd_lqr_json(j, s, r);
    return QD_EXIT_OK;
}

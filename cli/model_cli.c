/*
 * cli/model_cli.c - option helpers, --set, derivation errors and statements
 * from the command line (model_cli.h).
 */
#include "model_cli.h"

#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "eom_out.h"
#include "qdot/read.h"
#include "qdot/routh.h"
#include "state.h"

typedef int (*file_loader)(qd_ctx *, const char *, const qd_model_opts *, cli_model_file *);

static int load_with(qd_ctx *ctx, const char *file, size_t nsets, const char *const *sets,
                     const char *derivation, cli_model_file *mf, file_loader load) {
    char names[QD_CLI_MAX_LIST][128];
    qd_param_value given[QD_CLI_MAX_LIST];
    *mf = (cli_model_file){0};
    if (nsets > QD_CLI_MAX_LIST)
        return cli_usage_error("at most %d parameters can be set", QD_CLI_MAX_LIST);
    for (size_t i = 0; i < nsets; i++) {
        int rc = cli_state_read_set(ctx, sets[i], names[i], sizeof names[i], &given[i].value);
        if (rc != QD_EXIT_OK)
            return rc;
        for (size_t k = 0; k < i; k++)
            if (!strcmp(names[k], names[i])) {
                cli_diag_error("--set: %s is given twice ('%s', then '%s'); give it once",
                               names[i], sets[k], sets[i]);
                return QD_EXIT_USAGE;
            }
        given[i].name = names[i];
    }
    qd_model_opts opts = {.params = given, .nparams = nsets};
    if (qd_model_opts_for(&opts, derivation) != QD_OK) /* a command missing from the rule */
        return cli_usage_error("internal: no parameter rule for '%s'", derivation);
    return load(ctx, file, &opts, mf);
}

int cli_load(qd_ctx *ctx, const char *file, size_t nsets, const char *const *sets,
             const char *derivation, cli_model_file *mf) {
    return load_with(ctx, file, nsets, sets, derivation, mf, cli_model_file_load_opts);
}

int cli_load_field(qd_ctx *ctx, const char *file, size_t nsets, const char *const *sets,
                   cli_model_file *mf) {
    return load_with(ctx, file, nsets, sets, "field", mf, cli_field_file_load);
}

int cli_load_derive(qd_ctx *ctx, const char *file, size_t nsets, const char *const *sets,
                    const char *derivation, const qd_eom_opts *opts, cli_model_file *mf,
                    qd_eom **e) {
    *e = NULL;
    int rc = cli_load(ctx, file, nsets, sets, derivation, mf);
    if (rc == QD_EXIT_OK && !(*e = qd_eom_derive_opts(ctx, mf->model, opts)))
        rc = cli_eom_derive_error(ctx, mf);
    return rc;
}

int cli_emit(qd_buf *b, const char *what) {
    bool ok = !b->failed;
    if (ok)
        fputs(qd_buf_str(b), stdout);
    else
        cli_diag_error("cannot print the %s", what);
    qd_buf_free(b);
    return ok ? QD_EXIT_OK : QD_EXIT_FAIL;
}

/* A diagnostic of the combined text shown against the option's text when it
 * lies there (else at the start of it: the keyword the CLI added). */
static void statement_diag(const qd_diag *d, const char *opt, const char *text, size_t base) {
    qd_read_error err;
    memset(&err, 0, sizeof err);
    size_t len = strlen(text);
    err.offset = d->offset >= base ? d->offset - base : 0;
    if (err.offset > len)
        err.offset = len;
    err.length = d->offset >= base ? d->length : 1;
    /* the parser's messages are short: cut at the reader's size */
    memcpy(err.message, d->message, sizeof err.message - 1);
    memcpy(err.hint, d->hint, sizeof err.hint - 1);
    cli_diag_read(opt, text, &err);
}

/* The text starts with a label "NAME:". */
static bool has_label(const char *s) {
    while (isspace((unsigned char)*s))
        s++;
    if (!isalpha((unsigned char)*s) && *s != '_')
        return false;
    while (isalnum((unsigned char)*s) || *s == '_')
        s++;
    while (isspace((unsigned char)*s))
        s++;
    return *s == ':';
}

/* "KEYWORD [LABEL: ]TEXT" added to the model as one more statement. */
static int add_statement(cli_model_file *mf, const char *opt, const char *keyword,
                         const char *label, const char *text) {
    if (strchr(text, '\n') || strchr(text, '#'))
        return cli_usage_error("%s takes one statement on one line, without comments", opt);
    char lab[80] = "";
    if (!has_label(text))
        snprintf(lab, sizeof lab, "%s: ", label);
    qd_buf stmt = QD_BUF_INIT;
    qd_buf_printf(&stmt, "%s %s", keyword, lab);
    size_t base = stmt.len;
    qd_buf_puts(&stmt, text);
    qd_diag d;
    memset(&d, 0, sizeof d);
    qd_status st = stmt.failed ? QD_ERR_NOMEM : qd_model_add_statement(mf->model, qd_buf_str(&stmt), &d);
    qd_buf_free(&stmt);
    if (st == QD_OK)
        return QD_EXIT_OK;
    if (st == QD_ERR_NOMEM)
        return cli_out_of_memory();
    statement_diag(&d, opt, text, base);
    return QD_EXIT_USAGE;
}

int cli_symmetry(cli_model_file *mf, const char *opt, const char *text,
                 const char *label) {
    return add_statement(mf, opt, "symmetry", label, text);
}

int cli_integral(cli_model_file *mf, const char *opt, const char *text,
                 const char *label) {
    return add_statement(mf, opt, "integral", label, text);
}

/* ---- --ignore ----------------------------------------------------------------- */

static int ignore_item(qd_ctx *ctx, const qd_model *m, const char *list, const char *s,
                       size_t len, const qd_expr **ign, size_t cap, size_t *n) {
    char name[128];
    while (len && (*s == ' ' || s[len - 1] == ' '))
        s += *s == ' ', len -= 1;
    if (!len || len >= sizeof name || *n == cap)
        return cli_usage_error("--ignore takes a comma-separated list of coordinates, not '%s'",
                               list);
    memcpy(name, s, len);
    name[len] = '\0';
    const qd_expr *c = qd_routh_lookup(ctx, m, name);
    if (!c)
        return cli_usage_error("--ignore: %s", qd_ctx_message(ctx));
    for (size_t k = 0; k < *n; k++)
        if (ign[k] == c)
            return cli_usage_error("--ignore: %s is listed twice", name);
    ign[(*n)++] = c;
    return QD_EXIT_OK;
}

int cli_ignore_parse(qd_ctx *ctx, const qd_model *m, const char *list, const qd_expr **ign,
                     size_t cap, size_t *n) {
    const char *s = list;
    int rc = QD_EXIT_OK;
    *n = 0;
    while (rc == QD_EXIT_OK) {
        const char *comma = strchr(s, ',');
        rc = ignore_item(ctx, m, list, s, comma ? (size_t)(comma - s) : strlen(s), ign, cap, n);
        if (!comma)
            break;
        s = comma + 1;
    }
    return rc;
}

int cli_ignore_check(qd_ctx *ctx, const cli_model_file *mf, const qd_eom *e,
                     const qd_expr *const *ign, size_t n) {
    for (size_t i = 0; i < n; i++)
        for (size_t j = 0; j < e->n; j++) {
            const char *why = NULL, *where = NULL;
            if (e->q[j] != ign[i] || !(where = qd_routh_not_cyclic(ctx, mf->model, e, j, &why)))
                continue;
            char msg[512];
            snprintf(msg, sizeof msg, "%s cannot be ignored: %s", qd_expr_name(ign[i]), why);
            cli_model_file_error(mf, where, msg,
                                 "only cyclic coordinates can be ignored: absent from L, with no "
                                 "generalized force and no dissipation");
            return QD_EXIT_USAGE;
        }
    return QD_EXIT_OK;
}

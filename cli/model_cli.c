/*
 * cli/model_cli.c - option helpers, --set, derivation errors and statements
 * from the command line (model_cli.h).
 */
#include "model_cli.h"

#include <ctype.h>
#include <stdlib.h>
#include <string.h>
#include "eom_out.h"
#include "qdot/read.h"
#include "state.h"

int cli_once(const char *opt, const char **slot, const char *value) {
    if (*slot) {
        cli_diag_error("%s is given twice; give it once", opt);
        return QD_EXIT_USAGE;
    }
    *slot = value;
    return QD_EXIT_OK;
}

int cli_push(const char *opt, const char **list, size_t *n, size_t cap, const char *value) {
    if (*n >= cap) {
        cli_diag_error("at most %zu %s options", cap, opt);
        return QD_EXIT_USAGE;
    }
    list[(*n)++] = value;
    return QD_EXIT_OK;
}

int cli_choice(const char *opt, const char *value, const char *const *names, int *out) {
    size_t k = 0;
    for (; names[k]; k++)
        if (!strcmp(value, names[k])) {
            *out = (int)k;
            return QD_EXIT_OK;
        }
    char list[256];
    size_t used = 0;
    list[0] = '\0';
    for (size_t i = 0; i < k && used < sizeof list; i++)
        used += (size_t)snprintf(list + used, sizeof list - used, "%s%s",
                                 i == 0 ? "" : i + 1 == k ? " or " : ", ", names[i]);
    cli_diag_error("%s takes %s, not '%s'", opt, list, value);
    return QD_EXIT_USAGE;
}

int cli_bad_option(const char *arg, const char *usage) {
    cli_diag_error("unknown option or missing value: '%s'\n%s", arg, usage);
    return QD_EXIT_USAGE;
}

int cli_apply_sets(qd_ctx *ctx, qd_model *m, size_t nsets, const char *const *sets,
                      cli_subs *subs) {
    for (size_t i = 0; i < nsets; i++) {
        const qd_expr *p, *v;
        int rc = cli_state_set(ctx, m, sets[i], &p, &v);
        if (rc != QD_EXIT_OK)
            return rc;
        if (!subs)
            continue;
        size_t k = 0;
        while (k < subs->n && subs->from[k] != p)
            k++;
        if (k == QD_CLI_MAX_LIST) {
            cli_diag_error("at most %d parameters can be set", QD_CLI_MAX_LIST);
            return QD_EXIT_USAGE;
        }
        subs->from[k] = p;
        subs->to[k] = v;
        subs->n += k == subs->n;
    }
    return QD_EXIT_OK;
}

int cli_load_derive(qd_ctx *ctx, const char *file, size_t nsets, const char *const *sets,
                       cli_subs *subs, const qd_eom_opts *opts, cli_model_file *mf,
                       qd_eom **e) {
    *e = NULL;
    int rc = cli_model_file_load(ctx, file, mf);
    if (rc == QD_EXIT_OK)
        rc = cli_apply_sets(ctx, mf->model, nsets, sets, subs);
    if (rc == QD_EXIT_OK && !(*e = qd_eom_derive_opts(ctx, mf->model, opts)))
        rc = cli_eom_derive_error(ctx, mf);
    return rc;
}

const qd_expr *cli_subst(qd_ctx *ctx, const cli_subs *subs, const qd_expr *x) {
    if (!x || !subs->n)
        return x;
    const qd_expr *y = qd_subs(ctx, x, subs->n, subs->from, subs->to);
    return y == x ? x : qd_simplify(ctx, y);
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

/* "KEYWORD [LABEL: ]TEXT" appended to the file's text and parsed again; the
 * model (and *all, the text it points into) for the caller to free. */
static int reparse(qd_ctx *ctx, const cli_model_file *mf, const char *opt, const char *keyword,
                   const char *label, const char *text, qd_model **out, char **all) {
    *out = NULL;
    if (strchr(text, '\n') || strchr(text, '#')) {
        cli_diag_error("%s takes one statement on one line, without comments", opt);
        return QD_EXIT_USAGE;
    }
    char lab[80] = "";
    if (!has_label(text))
        snprintf(lab, sizeof lab, "%s: ", label);
    size_t cap = strlen(mf->text) + strlen(keyword) + strlen(lab) + strlen(text) + 4;
    if (!(*all = malloc(cap))) {
        cli_diag_error("out of memory");
        return QD_EXIT_FAIL;
    }
    int base = snprintf(*all, cap, "%s\n%s %s", mf->text, keyword, lab);
    snprintf(*all + base, cap - (size_t)base, "%s\n", text);
    qd_diag d;
    memset(&d, 0, sizeof d);
    *out = qd_model_parse(ctx, *all, &d);
    if (*out)
        return QD_EXIT_OK;
    if (qd_ctx_status(ctx) == QD_ERR_NOMEM) {
        cli_diag_error("out of memory");
        return QD_EXIT_FAIL;
    }
    statement_diag(&d, opt, text, (size_t)base);
    return QD_EXIT_USAGE;
}

int cli_symmetry(qd_ctx *ctx, const cli_model_file *mf, const char *opt, const char *text,
                    const char *label, char *name, size_t cap, const qd_expr **xi) {
    qd_model *m;
    char *all = NULL;
    int rc = reparse(ctx, mf, opt, "symmetry", label, text, &m, &all);
    if (rc == QD_EXIT_OK) {
        size_t k = qd_model_nsymmetries(m) - 1;
        snprintf(name, cap, "%s", qd_model_symmetry_name(m, k));
        for (size_t j = 0; j < qd_model_ncoords(m); j++)
            xi[j] = qd_model_symmetry_field(m, k, j);
        qd_model_free(m);
    }
    free(all);
    return rc;
}

int cli_integral(qd_ctx *ctx, const cli_model_file *mf, const char *opt, const char *text,
                    const char *label, char *name, size_t cap, const qd_expr **expr) {
    qd_model *m;
    char *all = NULL;
    int rc = reparse(ctx, mf, opt, "integral", label, text, &m, &all);
    if (rc == QD_EXIT_OK) {
        size_t k = qd_model_nintegrals(m) - 1;
        snprintf(name, cap, "%s", qd_model_integral_name(m, k));
        *expr = qd_model_integral(m, k);
        qd_model_free(m);
    }
    free(all);
    return rc;
}

/*
 * cli/model_cli.c - option helpers, --set, derivation errors and statements
 * from the command line (model_cli.h).
 */
#include "model_cli.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "eom_out.h"
#include "qdot/json.h"
#include "qdot/routh.h"
#include "state.h"

typedef int (*file_loader)(qd_ctx *, const char *, const qd_model_opts *, cli_model_file *);

static const char *loaded; /* the model file this run read: its JSON's "model" (cli_emit) */

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
    int rc = load(ctx, file, &opts, mf);
    loaded = rc == QD_EXIT_OK ? mf->path : loaded;
    return rc;
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
    if (loaded && qd_buf_str(b)[0] == '{') /* a JSON document: its model first */
        qd_json_add_model(b, loaded);
    bool ok = !b->failed;
    if (ok)
        fputs(qd_buf_str(b), stdout);
    else
        cli_diag_error("cannot print the %s", what);
    qd_buf_free(b);
    return ok ? QD_EXIT_OK : QD_EXIT_FAIL;
}

int cli_model_add_given(cli_model_file *mf, const char *opt, const char *keyword,
                        const char *label, const char *text) {
    qd_diag d;
    qd_status st = qd_model_add_given(mf->model, keyword, label, text, &d);
    if (st == QD_ERR_NOMEM)
        return cli_out_of_memory();
    if (st != QD_OK)
        cli_diag_read(opt, text, &d);
    return st == QD_OK ? QD_EXIT_OK : QD_EXIT_USAGE;
}

int cli_ignore(qd_ctx *ctx, const cli_model_file *mf, const qd_eom *e, const char *list,
               const qd_expr **ign, size_t cap, size_t *n) {
    const char *where;
    qd_status st = qd_routh_ignore_read(ctx, mf->model, e, list, ign, cap, n, &where);
    if (st == QD_OK || st != QD_ERR_ARG)
        return st == QD_OK ? QD_EXIT_OK : cli_diag_ctx(ctx);
    if (!where)
        return cli_usage_error("--ignore: %s", qd_ctx_message(ctx));
    cli_model_file_error(mf, where, qd_ctx_message(ctx), "only cyclic coordinates can be "
                         "ignored: absent from L, with no generalized force and no dissipation");
    return QD_EXIT_USAGE;
}

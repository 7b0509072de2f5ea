/*
 * cli/cmd_action.c - `qdot action FILE --at STATE`: the action-angle
 * variables of a separable bounded motion (libqdot's qd_action_at): the
 * actions J_k = oint p_k dq_k at the state, the frequencies
 * omega_k = 2 pi dH/dJ_k, the angles, the commensurate frequencies, and H(J) where it is
 * recognised.  The state starts from the model's `initial` values; a
 * model given by H may take its momenta in --at.  The library writes the
 * result (qd_action_print).
 */
#include "driver.h"

#include <stdlib.h>
#include <string.h>
#include "qdot/action.h"
#include "qdot/routh.h"
#include "state.h"

typedef struct act_args {
    const char *at, *angle, *format;
    cli_list sets;
} act_args;

typedef struct act_run {
    cli_run c;
    act_args a;
} act_run;

static const cli_opt opts[] = {
    {"--at", NULL, CLI_TEXT, offsetof(act_args, at), "\"q=V, q'=V (or p=V), ...\"",
     "the state of the motion (over the model's initial values)", NULL, NULL},
    CLI_OPT_SET(act_args, sets),
    {"--angle", NULL, CLI_TEXT, offsetof(act_args, angle), "q[,q...]",
     "the coordinates whose angle variables to print", NULL, NULL},
    CLI_OPT_FORMAT(act_args, format),
    {NULL, NULL, CLI_FLAG, 0, NULL, NULL, NULL, NULL},
};

static const cli_spec spec = {
    "action", "FILE [options]",
    "The action-angle variables of a separable bounded motion: the actions J_k, the "
    "frequencies, the angles, commensurability and H(J).",
    opts, NULL, 1, 1, "FILE", false};

/* ---- the command ------------------------------------------------------------------ */

enum { MAX_ANGLES = 16 };

/* --angle q[,q...]: coordinates the model does not show to be angles. */
static int angles_parse(qd_ctx *ctx, const qd_model *m, const char *list, const qd_expr **out,
                        size_t *n) {
    *n = 0;
    for (const char *s = list;; s++) {
        size_t len = strcspn(s, ",");
        char name[128];
        while (len && *s == ' ')
            s++, len--;
        while (len && s[len - 1] == ' ')
            len--;
        if (!len || len >= sizeof name || *n == MAX_ANGLES)
            return cli_usage_error("--angle takes a comma-separated list of coordinates, not '%s'",
                                   list);
        memcpy(name, s, len);
        name[len] = '\0';
        if (!(out[(*n)++] = qd_routh_lookup(ctx, m, name)))
            return cli_usage_error("--angle: %s", qd_ctx_message(ctx));
        s += strcspn(s, ",");
        if (!*s)
            break;
    }
    return QD_EXIT_OK;
}

static int run(cli_run *c) {
    const act_args *a = &((act_run *)c)->a;
    qd_ctx *ctx = c->ctx;
    cli_model_file *mf = &c->mf;
    int rc = cli_load(ctx, c->file, a->sets.n, a->sets.items, "action", mf);
    if (rc != QD_EXIT_OK)
        return rc;
    cli_state st = {0};
    if (qd_action_state_read(ctx, mf->model, a->at, &st) != QD_OK)
        rc = a->at && qd_ctx_diag(ctx)->located ? cli_state_diag(ctx, "--at", a->at)
                                                : cli_diag_ctx(ctx);
    qd_action act = {0};
    const qd_expr *angles[MAX_ANGLES];
    qd_action_opts opts = {.angles = angles};
    if (rc == QD_EXIT_OK && a->angle)
        rc = angles_parse(ctx, mf->model, a->angle, angles, &opts.nangles);
    if (rc == QD_EXIT_OK &&
        qd_action_at(ctx, mf->model, st.n, st.syms, st.vals, &opts, &act) != QD_OK)
        rc = cli_diag_model(ctx, mf->path, mf->text, mf->model);
    if (rc == QD_EXIT_OK) {
        qd_buf b = QD_BUF_INIT;
        b.failed = qd_action_print(ctx, &act, cli_json(a->format), &b) != QD_OK;
        rc = cli_emit(&b, "actions");
    }
    qd_action_free(&act);
    cli_state_free(&st);
    return rc;
}

CLI_COMMAND(action, act_run, &spec, offsetof(act_run, a), 0, NULL, run, NULL)

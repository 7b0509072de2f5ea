/*
 * cli/eom_out.h - a failed derivation shown at the model statement to
 * blame.  The renderings of `qdot eom` are the library's (qdot/render.h).
 */
#ifndef QDOT_CLI_EOM_OUT_H
#define QDOT_CLI_EOM_OUT_H

#include "qdot/mech.h"
#include "cli.h"
#include "model_file.h"
#include "state.h"

/* Print why qd_eom_derive (or another derivation from mf) failed, at the
 * statement the error is about (a constraint the message names, or T/L for
 * a singular mass matrix), with its hint; returns the exit status. */
static inline int cli_eom_derive_error(const qd_ctx *ctx, const cli_model_file *mf) {
    return cli_diag_model(ctx, mf->path, mf->text, mf->model);
}

#endif

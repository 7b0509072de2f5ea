/*
 * cli/opt_diag.h - a library error about one of a command's options shown
 * against that option's text: the library names the field ("frame",
 * "t_end"), the option table knows which option holds it and its value.
 */
#ifndef QDOT_CLI_OPT_DIAG_H
#define QDOT_CLI_OPT_DIAG_H

#include "cli.h"

/* The context's error: a record about a field of spec's table (subject
 * QD_SUBJECT_NONE or TEXT, name "t_end" for --t-end) located in the option's text
 * is shown as "--t-end:1:5: error: ..." with that text and a caret (a list
 * option: the item the record's index names); any other as cli_diag_ctx.
 * args is the struct the table fills.  Returns the exit status. */
int cli_diag_opts(const qd_ctx *ctx, const cli_spec *spec, const void *args);

#endif

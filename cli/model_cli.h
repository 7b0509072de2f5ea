/*
 * cli/model_cli.h - what the commands on a model file share beyond the
 * argument loop of args.c: options given once or repeated, a --format chosen
 * from a list, the model read with the --set list as its parameter values,
 * the errors of deriving the equations, and extra
 * statements given on the command line (--symmetry, --integral) read by the
 * model language's own parser.  Every function prints its diagnostics and
 * returns an exit status (QD_EXIT_OK to go on).
 */
#ifndef QDOT_CLI_MODEL_CLI_H
#define QDOT_CLI_MODEL_CLI_H

#include "cli.h"
#include "model_file.h"

#define QD_CLI_MAX_LIST 64

/* FILE read and parsed with the --set list as parameter values (qd_model_opts:
 * parameters defined from a set one follow it), fixed into the formulas or
 * kept symbols by the library's rule for the command named derivation
 * (qd_model_opts_for). */
int cli_load(qd_ctx *ctx, const char *file, size_t nsets, const char *const *sets,
             const char *derivation, cli_model_file *mf);

/* What most commands start with: cli_load, then the equations derived
 * with opts (NULL: the defaults).  mf and *e belong to the caller, also on
 * error. */
int cli_load_derive(qd_ctx *ctx, const char *file, size_t nsets, const char *const *sets,
                    const char *derivation, const qd_eom_opts *opts, cli_model_file *mf,
                    qd_eom **e);

/* Print b on standard output, or, when building it failed, "cannot print
 * the WHAT"; b is freed. */
int cli_emit(qd_buf *b, const char *what);

/* cli_load for a field model (mf->field; parameters fixed). */
int cli_load_field(qd_ctx *ctx, const char *file, size_t nsets, const char *const *sets,
                   cli_model_file *mf);
/* cmd_field.c: `qdot eom` and `qdot modes` on a field model (qdot/field.h),
 * read into mf (the caller's, as ctx, also on error). */
int cli_field_eom(qd_ctx *ctx, cli_model_file *mf, const char *file, size_t nsets,
                  const char *const *sets, bool json);
int cli_field_modes(qd_ctx *ctx, cli_model_file *mf, const char *file, size_t nsets,
                    const char *const *sets, size_t count, double tol, bool json);

/* --ignore LIST (routh, orbit): the comma-separated coordinates into ign
 * (at most cap), each once; prints its own errors. */
int cli_ignore_parse(qd_ctx *ctx, const qd_model *m, const char *list, const qd_expr **ign,
                     size_t cap, size_t *n);
/* Every coordinate of ign is cyclic in e; else the error at the statement
 * that makes it not, and QD_EXIT_USAGE. */
int cli_ignore_check(qd_ctx *ctx, const cli_model_file *mf, const qd_eom *e,
                     const qd_expr *const *ign, size_t n);

/* A symmetry or an integral given on the command line (--symmetry, --integral:
 * what follows the keyword of the statement), added to the model as the
 * statement "KEYWORD [label: ]TEXT" (qd_model_add_statement), so the model
 * language's own parser checks it as it would in the file; errors point into
 * text under the option's name opt.  label names it when text has no
 * "NAME:" of its own.  It is then the model's last symmetry or integral. */
int cli_symmetry(cli_model_file *mf, const char *opt, const char *text,
                 const char *label);
int cli_integral(cli_model_file *mf, const char *opt, const char *text,
                 const char *label);


#endif

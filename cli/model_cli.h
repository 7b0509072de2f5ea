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
 * the WHAT"; b is freed.  A JSON document (b starts with '{') of a run that
 * read a model (cli_load) gets "model" first (qd_json_add_model). */
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

/* --ignore LIST (routh, orbit; qd_routh_ignore_read): the coordinates into
 * ign (at most cap), each once, and each cyclic in e when e is given; a
 * coordinate that is not is shown at the statement that makes it not. */
int cli_ignore(qd_ctx *ctx, const cli_model_file *mf, const qd_eom *e, const char *list,
               const qd_expr **ign, size_t cap, size_t *n);

/* text given with the option opt added to the model as statements KEYWORD
 * (qd_model_add_given: label, for --symmetry and --integral, names it when
 * text has no "NAME:"; NULL: an item each, --prescribe); an error is shown
 * in text under opt. */
int cli_model_add_given(cli_model_file *mf, const char *opt, const char *keyword,
                        const char *label, const char *text);

#endif

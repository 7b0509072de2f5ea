/*
 * cli/model_cli.h - what the commands on a model file share beyond the
 * argument loop of args.c: options given once or repeated, a --format chosen
 * from a list, the --set list applied to the model (and kept as
 * substitutions), the errors of deriving the equations, and extra
 * statements given on the command line (--symmetry, --integral) read by the
 * model language's own parser.  Every function prints its diagnostics and
 * returns an exit status (QD_EXIT_OK to go on).
 */
#ifndef QDOT_CLI_MODEL_CLI_H
#define QDOT_CLI_MODEL_CLI_H

#include "cli.h"
#include "model_file.h"

#define QD_CLI_MAX_LIST 64

/* An option that takes one value: an error when it is given twice. */
int cli_once(const char *opt, const char **slot, const char *value);
/* A repeatable option: value appended to list[*n] (at most cap). */
int cli_push(const char *opt, const char **list, size_t *n, size_t cap, const char *value);
/* value among names (NULL-terminated): *out its index; else an error listing
 * them ("--format takes text or json, not 'c'"). */
int cli_choice(const char *opt, const char *value, const char *const *names, int *out);
/* The error for argv[i], an unknown option or one without its value. */
int cli_bad_option(const char *arg, const char *usage);

/* --set substitutions: each parameter once, with the value of its last --set. */
typedef struct cli_subs {
    size_t n;
    const qd_expr *from[QD_CLI_MAX_LIST], *to[QD_CLI_MAX_LIST];
} cli_subs;

/* Apply the --set list to m in order; subs (may be NULL) receives them. */
int cli_apply_sets(qd_ctx *ctx, qd_model *m, size_t nsets, const char *const *sets,
                      cli_subs *subs);

/* What most commands start with: FILE read and parsed, the --set list
 * applied (subs may be NULL), the equations derived with opts (NULL: the
 * defaults).  mf and *e belong to the caller, also on error. */
int cli_load_derive(qd_ctx *ctx, const char *file, size_t nsets, const char *const *sets,
                       cli_subs *subs, const qd_eom_opts *opts, cli_model_file *mf,
                       qd_eom **e);

/* x with the substitutions made and simplified (x itself when none applies). */
const qd_expr *cli_subst(qd_ctx *ctx, const cli_subs *subs, const qd_expr *x);

/* Print b on standard output, or, when building it failed, "cannot print
 * the WHAT"; b is freed. */
int cli_emit(qd_buf *b, const char *what);


/* A symmetry or an integral given on the command line (--symmetry, --integral:
 * what follows the keyword of the statement): the text is appended to the
 * file's as "KEYWORD [label: ]TEXT" and the whole parsed again, so the model
 * language's own parser checks it as it would in the file; errors point into
 * text under the option's name opt.  label names it when text has no
 * "NAME:" of its own; name receives the name.  xi gets one component per
 * coordinate (0 for those not moved). */
int cli_symmetry(qd_ctx *ctx, const cli_model_file *mf, const char *opt, const char *text,
                    const char *label, char *name, size_t cap, const qd_expr **xi);
int cli_integral(qd_ctx *ctx, const cli_model_file *mf, const char *opt, const char *text,
                    const char *label, char *name, size_t cap, const qd_expr **expr);

#endif

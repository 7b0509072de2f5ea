/*
 * cli/model_file.h - a model file read into memory and parsed, for the
 * commands that take FILE (eom, check).
 */
#ifndef QDOT_CLI_MODEL_FILE_H
#define QDOT_CLI_MODEL_FILE_H

#include <stdio.h>

#include "qdot/model.h"
#include "qdot/field.h"

typedef struct cli_model_file {
    const char *path;  /* as given; "<stdin>" for "-" */
    char *text;        /* the whole file, NUL-terminated; the model points into it */
    size_t len;
    qd_model *model;
    qd_field *field;   /* cli_field_file_load: the field model instead */
} cli_model_file;

/* The text of path ("-" is standard input) whole, NUL-terminated, into
 * *text (malloc'd) and *len; what names the kind of file in the messages
 * ("a model file").  A file that cannot be read, longer than
 * QD_MODEL_MAX_BYTES or holding a NUL byte (shown with a caret: a reader
 * would stop there silently) is printed and QD_EXIT_USAGE; no memory,
 * QD_EXIT_FAIL. */
int cli_read_text(const char *path, const char *what, char **text, size_t *len);

/* Read and parse path ("-" is standard input).  Prints the diagnostics and
 * returns the exit status: QD_EXIT_USAGE for a file that cannot be read or a
 * model with an error, QD_EXIT_OK with mf->model set otherwise. */
int cli_model_file_load(qd_ctx *ctx, const char *path, cli_model_file *mf);
/* The same, read with the parameter values of opts (the --set list; an
 * unknown name is reported as --set's error). */
int cli_model_file_load_opts(qd_ctx *ctx, const char *path, const qd_model_opts *opts,
                             cli_model_file *mf);
void cli_model_file_free(cli_model_file *mf);

/* Does the file at path declare a field (qd_field_declared)?  false for
 * standard input and a file that cannot be read (the model's loader then
 * reports why). */
bool cli_model_file_is_field(const char *path);
/* Read and parse path as a field model (qd_field_parse) into mf->field. */
int cli_field_file_load(qd_ctx *ctx, const char *path, const qd_model_opts *opts,
                        cli_model_file *mf);

/* An error found after parsing (a singular mass matrix), shown at the
 * statement `what` of the model (see qd_model_where) with a caret, or as a
 * plain "FILE: error: ..." line when the model has no such statement. */
void cli_model_file_error(const cli_model_file *mf, const char *what, const char *message,
                         const char *hint);

#endif

/*
 * cli/model_file.h - a model file read into memory and parsed, for the
 * commands that take FILE (eom, check).
 */
#ifndef QDOT_CLI_MODEL_FILE_H
#define QDOT_CLI_MODEL_FILE_H

#include "qdot/model.h"

typedef struct qd_model_file {
    const char *path;  /* as given; "<stdin>" for "-" */
    char *text;        /* the whole file, NUL-terminated; the model points into it */
    size_t len;
    qd_model *model;
} qd_model_file;

/* Read and parse path ("-" is standard input).  Prints the diagnostics and
 * returns the exit status: QD_EXIT_USAGE for a file that cannot be read or a
 * model with an error, QD_EXIT_OK with mf->model set otherwise. */
int qd_model_file_load(qd_ctx *ctx, const char *path, qd_model_file *mf);
void qd_model_file_free(qd_model_file *mf);

/* An error found after parsing (a singular mass matrix), shown at the
 * statement `what` of the model (see qd_model_where) with a caret, or as a
 * plain "FILE: error: ..." line when the model has no such statement. */
void qd_model_file_error(const qd_model_file *mf, const char *what, const char *message,
                         const char *hint);

#endif

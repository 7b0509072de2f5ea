/*
 * qdot/read.h - reading an expression from text in the model language's
 * expression syntax (what QD_FMT_TEXT prints).
 *
 * Names resolve against the context's symbols: a declared coordinate q
 * makes q' and q'' its velocity and acceleration; t is the time; pi and e are
 * the constants; the built-in functions are known by name.  An unknown name
 * becomes a plain symbol when the options allow it, and is an error otherwise.
 */
#ifndef QDOT_READ_H
#define QDOT_READ_H

#include <stddef.h>
#include "expr.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct qd_read_error {
    size_t offset;      /* byte offset of the offending spot in the text */
    size_t length;      /* bytes it spans (at least 1 unless at the end) */
    char message[160];  /* what is wrong */
    char hint[160];     /* what to do, or "" */
} qd_read_error;

typedef struct qd_read_opts {
    bool new_symbols;   /* unknown names become plain symbols (else an error) */
} qd_read_opts;

/* Read text into an expression; NULL with *err filled on failure (err may be
 * NULL).  opts may be NULL: unknown names then become plain symbols. */
QD_API const qd_expr *qd_read(qd_ctx *ctx, const char *text, const qd_read_opts *opts,
                       qd_read_error *err);

#ifdef __cplusplus
}
#endif
#endif

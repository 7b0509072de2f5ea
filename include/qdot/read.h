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
#include "print.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The reader's errors are error records (status.h) located in the text;
 * the old name stays for callers written against it. */
typedef qd_diag qd_read_error;

typedef struct qd_read_opts {
    bool new_symbols;   /* unknown names become plain symbols (else an error) */
} qd_read_opts;

/* Read text into an expression; NULL on failure, with the context's error
 * record located in text (subject QD_SUBJECT_TEXT) and a copy in *err (err
 * may be NULL).  opts may be NULL: unknown names then become plain symbols. */
QD_API const qd_expr *qd_read(qd_ctx *ctx, const char *text, const qd_read_opts *opts,
                       qd_read_error *err);

/* A variable of the expression within read from text, as a derivative is
 * taken by it: a name or a rate ("r", "r'", "theta''"), read against the
 * context's symbols (no new ones), which must be a symbol that occurs in
 * within.  NULL on failure, with QD_ERR_ARG ("'zz' does not occur in the
 * expression": also for text that does not read, or reads as no symbol)
 * in the context's error record located in text, the whole of it, and a
 * copy in *err (err may be NULL); QD_ERR_NOMEM. */
QD_API const qd_expr *qd_read_variable(qd_ctx *ctx, const char *text, const qd_expr *within,
                                       qd_read_error *err);

/* The one renderer of error records, for every kind of input (a model
 * file, a state string, an expression on the command line):
 *
 *   FILE:LINE:COL: error: MESSAGE
 *     the source line
 *     ^~~~ under the byte range
 *     hint: HINT
 *
 * appended to out.  file names the input ("model.qd", "--at"); text is the
 * input the range points into.  A record that is not located (or text NULL)
 * gives "FILE: error: MESSAGE" and the hint.  Line and column are counted
 * from text, so a record may be shown against a part of what was parsed. */
QD_API void qd_diag_format(const qd_diag *d, const char *file, const char *text, qd_buf *out);

#ifdef __cplusplus
}
#endif

/* NULL (issue 30): a function of this header given NULL for a pointer it
 * needs does nothing and returns QD_ERR_ARG (recorded in ctx when ctx is
 * given), NULL, 0, false or NaN, as its return type has it; a void function
 * returns, and every _free accepts NULL. NULL is an accepted value, as
 * documented at the function, for: qd_read (err, opts); qd_read_variable (err); qd_diag_format
 * (file, text). An array whose count is 0 may be NULL. */
#endif

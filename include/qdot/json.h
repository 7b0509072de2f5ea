/*
 * qdot/json.h - a small JSON writer over qd_buf: the one writer of every
 * JSON document qdot produces (the program's --format json, Python's data).
 *
 * The writer keeps the commas and the indentation: objects put one member on
 * a line, arrays stay on one line.  Strings are escaped (quotes, backslashes,
 * control characters); numbers are written with %.17g so that they read back
 * to the same double.  JSON has no NaN or infinity, so a non-finite number is
 * refused: the writer then marks itself failed and the caller must not print
 * the document (qd_json_ok).
 */
#ifndef QDOT_JSON_H
#define QDOT_JSON_H

#include <stdbool.h>
#include <stdint.h>
#include "print.h"

#ifdef __cplusplus
extern "C" {
#endif

#define QD_JSON_MAX_DEPTH 32

typedef struct qd_json {
    qd_buf *out;
    unsigned depth;
    uint32_t has_items;  /* bit d: the container at depth d has a value already */
    uint32_t is_object;  /* bit d: the container at depth d is an object */
    bool after_key;      /* the next value completes a member */
    bool failed;         /* a non-finite number or nesting beyond QD_JSON_MAX_DEPTH */
    bool nonfinite;      /* ... because of a non-finite number */
    bool nomem;          /* an expression could not be printed for want of memory */
} qd_json;

QD_API void qd_json_init(qd_json *j, qd_buf *out);
QD_API void qd_json_begin_object(qd_json *j);
QD_API void qd_json_end_object(qd_json *j);
QD_API void qd_json_begin_array(qd_json *j);
QD_API void qd_json_end_array(qd_json *j);
QD_API void qd_json_key(qd_json *j, const char *key);
QD_API void qd_json_string(qd_json *j, const char *s); /* null for NULL */
QD_API bool qd_json_number(qd_json *j, double v); /* false for NaN and infinities */
/* v, or null where v is not finite (NaN: none, as a measure with no value). */
QD_API void qd_json_number_or_null(qd_json *j, double v);
QD_API void qd_json_bool(qd_json *j, bool v);
QD_API void qd_json_null(qd_json *j);
/* An expression as a string in the text format; null for NULL. */
QD_API void qd_json_expr(qd_json *j, qd_ctx *ctx, const qd_expr *x);
/* "key": [[x[0], ..., x[cols-1]], ...]: the rows x 'cols' matrix x stored by
 * rows (key NULL: the value alone, inside an array).  false if an entry was
 * refused (not finite). */
QD_API bool qd_json_matrix(qd_json *j, const char *key, size_t rows, size_t cols,
                           const double *x);
/* "key": [x[0], ..., x[n-1]] (key NULL: the array alone).  false if an entry
 * was refused (not finite). */
QD_API bool qd_json_vector(qd_json *j, const char *key, size_t n, const double *x);
/* A mode's "omega2", "omega" and "period" keys for the squared frequency w2:
 * omega null where w2 < 0 (no frequency: the mode grows), period null where
 * w2 <= 0. */
QD_API void qd_json_frequency(qd_json *j, double w2);
/* The result e of an operation on one expression (`qdot diff`, `expand`,
 * `simplify`, `print` --format json; src/json/expr_result.c) as one object
 * and a newline appended to out: "operation" (its name), "input" (the
 * expression as given), "variables" (diff's, as given; [] for the others),
 * and e as "result" (the text format, which reads back), "latex", "c" and
 * "sympy".  QD_OK; QD_ERR_NOMEM (recorded in ctx), out then untouched. */
QD_API qd_status qd_json_expr_result(qd_ctx *ctx, const char *operation, const char *input,
                                     size_t nvars, const char *const *vars,
                                     const qd_expr *e, qd_buf *out);
/* "model": model (the model file's name as the caller has it; NULL: null)
 * put first into the JSON object doc holds, a document of this writer's
 * layout ("{" first, a member on a line): the one key every command's JSON
 * that reads a model starts with (src/json/model_key.c).  A document whose
 * first member is "model" already is left as it is.  QD_OK; QD_ERR_ARG when
 * doc does not hold an object; QD_ERR_NOMEM with doc failed (a document is
 * not printed without its model). */
QD_API qd_status qd_json_add_model(qd_buf *doc, const char *model);
/* The document is complete, nothing was refused and no memory ran out. */
QD_API bool qd_json_ok(const qd_json *j);
/* Why the document is not ok: "out of memory", "a non-finite number (JSON
 * cannot hold it)" or "an unfinished or too deeply nested document". */
QD_API const char *qd_json_why(const qd_json *j);

/* The end of a printer that writes into a scratch buffer b first (so that
 * a failure leaves out untouched): b's text appended to out when b did
 * not fail and j (NULL for a text printer) is ok, then b freed.  QD_OK;
 * QD_ERR_NUMERIC "cannot write the JSON: <qd_json_why>" for a document
 * refused (a non-finite number); QD_ERR_NOMEM when b, j or out ran out;
 * the error recorded in ctx. */
QD_API qd_status qd_json_commit(qd_ctx *ctx, qd_buf *b, const qd_json *j, qd_buf *out);

#ifdef __cplusplus
}
#endif

/* NULL (issue 30): a function of this header given NULL for a pointer it
 * needs does nothing and returns false or NULL, as its return type has it; a
 * void function returns.  NULL is an accepted value, as documented at the
 * function, for: qd_json_string (s, written as null), qd_json_expr (x). */
#endif

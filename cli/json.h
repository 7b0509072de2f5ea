/*
 * cli/json.h - a small JSON writer over qd_buf.
 *
 * The writer keeps the commas and the indentation: objects put one member on
 * a line, arrays stay on one line.  Strings are escaped (quotes, backslashes,
 * control characters); numbers are written with %.17g so that they read back
 * to the same double.  JSON has no NaN or infinity, so a non-finite number is
 * refused: the writer then marks itself failed and the caller must not print
 * the document (cli_json_ok).
 */
#ifndef QDOT_CLI_JSON_H
#define QDOT_CLI_JSON_H

#include <stdbool.h>
#include <stdint.h>
#include "qdot/print.h"

#define QD_JSON_MAX_DEPTH 32

typedef struct cli_json {
    qd_buf *out;
    unsigned depth;
    uint32_t has_items;  /* bit d: the container at depth d has a value already */
    uint32_t is_object;  /* bit d: the container at depth d is an object */
    bool after_key;      /* the next value completes a member */
    bool failed;         /* a non-finite number or nesting beyond QD_JSON_MAX_DEPTH */
    bool nonfinite;      /* ... because of a non-finite number */
    bool nomem;          /* an expression could not be printed for want of memory */
} cli_json;

void cli_json_init(cli_json *j, qd_buf *out);
void cli_json_begin_object(cli_json *j);
void cli_json_end_object(cli_json *j);
void cli_json_begin_array(cli_json *j);
void cli_json_end_array(cli_json *j);
void cli_json_key(cli_json *j, const char *key);
void cli_json_string(cli_json *j, const char *s);
bool cli_json_number(cli_json *j, double v); /* false for NaN and infinities */
void cli_json_bool(cli_json *j, bool v);
void cli_json_null(cli_json *j);
/* An expression as a string in the text format; null for NULL. */
void cli_json_expr(cli_json *j, qd_ctx *ctx, const qd_expr *x);
/* The document is complete, nothing was refused and no memory ran out. */
bool cli_json_ok(const cli_json *j);
/* Why the document is not ok: "out of memory", "a non-finite number (JSON
 * cannot hold it)" or "an unfinished or too deeply nested document". */
const char *cli_json_why(const cli_json *j);

#endif

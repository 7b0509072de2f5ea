/*
 * cli/diag.c - error messages: one line "where: error: what", then the
 * source line with a caret under the spot and a hint, the way compilers do.
 */
#include "cli.h"

#include <stdarg.h>
#include <string.h>

void cli_diag_error(const char *fmt, ...) {
    va_list ap;
    va_start(ap, fmt);
    fputs("qdot: error: ", stderr);
    vfprintf(stderr, fmt, ap);
    fputc('\n', stderr);
    va_end(ap);
}

/* Line and column (1-based, in bytes) of an offset into text. */
static void locate(const char *text, size_t off, size_t *line, size_t *col, const char **start) {
    *line = 1;
    *start = text;
    for (size_t i = 0; i < off && text[i]; i++)
        if (text[i] == '\n') {
            (*line)++;
            *start = text + i + 1;
        }
    *col = (size_t)(text + off - *start) + 1;
}

void cli_diag_read(const char *file, const char *text, const qd_read_error *err) {
    size_t line, col;
    const char *start;
    size_t len = strlen(text), off = err->offset <= len ? err->offset : len;
    locate(text, off, &line, &col, &start);
    fprintf(stderr, "%s:%zu:%zu: error: %s\n", file, line, col, err->message);
    size_t n = strcspn(start, "\n");
    fprintf(stderr, "  %.*s\n  ", (int)n, start);
    for (size_t i = 1; i < col; i++)
        fputc(start[i - 1] == '\t' ? '\t' : ' ', stderr);
    size_t w = err->length ? err->length : 1;
    for (size_t i = 0; i < w && col - 1 + i <= n; i++)
        fputc(i ? '~' : '^', stderr);
    fputc('\n', stderr);
    if (err->hint[0])
        fprintf(stderr, "  hint: %s\n", err->hint);
}

int cli_diag_ctx(const qd_ctx *ctx) {
    qd_status st = qd_ctx_status(ctx);
    cli_diag_error("%s", qd_ctx_message(ctx)[0] ? qd_ctx_message(ctx) : qd_status_str(st));
    /* a bad argument or an exact division by zero is the input's fault */
    return st == QD_ERR_ARG || st == QD_ERR_DIVZERO || st == QD_ERR_PARSE ||
                   st == QD_ERR_UNBOUND || st == QD_ERR_NONLINEAR
               ? QD_EXIT_USAGE
               : QD_EXIT_FAIL;
}

bool cli_format(const char *name, qd_format *out) {
    static const struct { const char *name; qd_format f; } fmts[] = {
        {"text", QD_FMT_TEXT}, {"latex", QD_FMT_LATEX}, {"c", QD_FMT_C}, {"sympy", QD_FMT_SYMPY},
    };
    for (size_t i = 0; i < sizeof fmts / sizeof fmts[0]; i++)
        if (strcmp(name, fmts[i].name) == 0) {
            *out = fmts[i].f;
            return true;
        }
    return false;
}

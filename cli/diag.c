/*
 * cli/diag.c - error messages: one line "where: error: what", then the
 * source line with a caret under the spot and a hint, the way compilers do.
 */
#include "cli.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

static void verror(const char *fmt, va_list ap) {
    fputs("qdot: error: ", stderr);
    vfprintf(stderr, fmt, ap);
    fputc('\n', stderr);
}

void cli_diag_error(const char *fmt, ...) {
    va_list ap;
    va_start(ap, fmt);
    verror(fmt, ap);
    va_end(ap);
}

int cli_out_of_memory(void) {
    cli_diag_error("out of memory");
    return QD_EXIT_FAIL;
}

int cli_usage_error(const char *fmt, ...) {
    va_list ap;
    va_start(ap, fmt);
    verror(fmt, ap);
    va_end(ap);
    return QD_EXIT_USAGE;
}

/* The library's renderer (qd_diag_format) for every kind of input. */
void cli_diag_show(const char *file, const char *text, const qd_diag *d) {
    qd_buf b = QD_BUF_INIT;
    qd_diag_format(d, file, text, &b);
    fputs(b.failed ? d->message : qd_buf_str(&b), stderr);
    qd_buf_free(&b);
}

void cli_diag_read(const char *file, const char *text, const qd_diag *err) {
    qd_diag d = *err;
    d.located = true; /* a reader's record always points into its text */
    cli_diag_show(file, text, &d);
}

/* a bad argument or an exact division by zero is the input's fault */
int cli_exit(qd_status st) {
    if (st == QD_OK)
        return QD_EXIT_OK;
    return st == QD_ERR_ARG || st == QD_ERR_DIVZERO || st == QD_ERR_PARSE ||
                   st == QD_ERR_UNBOUND || st == QD_ERR_NONLINEAR
               ? QD_EXIT_USAGE
               : QD_EXIT_FAIL;
}

int cli_diag_ctx(const qd_ctx *ctx) {
    qd_diag d = *qd_ctx_diag(ctx);
    if (d.subject == QD_SUBJECT_NONE && d.name[0]) { /* an option's field (qdot/sim.h) */
        size_t n = strlen(d.message);
        char opt[64];
        snprintf(opt, sizeof opt, "%s", d.name);
        for (char *c = opt; *c; c++)
            *c = *c == '_' ? '-' : *c;
        snprintf(d.message + n, sizeof d.message - n, " (--%s)", opt);
    }
    cli_diag_show("qdot", NULL, &d);
    return cli_exit(qd_ctx_status(ctx));
}

int cli_diag_model(const qd_ctx *ctx, const char *file, const char *text, const qd_model *m) {
    qd_diag d = *qd_ctx_diag(ctx);
    if (d.subject == QD_SUBJECT_NONE || d.subject == QD_SUBJECT_TEXT)
        return cli_diag_ctx(ctx);
    qd_model_locate(m, &d); /* else shown without a caret */
    cli_diag_show(file, text, &d);
    return QD_EXIT_USAGE;
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

qd_render_format cli_render_format(const char *name) {
    qd_render_format f = QD_RENDER_TEXT;
    if (name)
        qd_render_format_parse(name, &f);
    return f;
}

qd_format cli_format_or_text(const char *name) {
    qd_format f = QD_FMT_TEXT;
    if (name)
        cli_format(name, &f);
    return f;
}

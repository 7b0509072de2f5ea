/*
 * cli/state.c - --set and --at: the library's state reader (qdot/state.h),
 * its errors shown against the option's text.
 */
#include "state.h"

#include <ctype.h>
#include <math.h>
#include <string.h>
#include "cli.h"

int cli_state_diag(const qd_ctx *ctx, const char *what, const char *text) {
    const qd_diag *d = qd_ctx_diag(ctx);
    if (!d->located)
        return cli_diag_ctx(ctx); /* out of memory: nothing to point at */
    cli_diag_show(what, text, d);
    return cli_exit(qd_ctx_status(ctx));
}

int cli_state_init(qd_ctx *ctx, const qd_model *m, cli_state *st) {
    return qd_state_init(ctx, m, st) == QD_OK ? QD_EXIT_OK : cli_diag_ctx(ctx);
}

void cli_state_free(cli_state *st) { qd_state_free(st); }

int cli_state_read(qd_ctx *ctx, const qd_model *m, const char *what, const char *text,
                   cli_state *st, const qd_state_read_opts *opts) {
    if (qd_state_read(ctx, m, st, text, opts) != QD_OK)
        return cli_state_diag(ctx, what, text);
    return QD_EXIT_OK;
}

int cli_state_parse(qd_ctx *ctx, const qd_model *m, const char *text, cli_state *st) {
    return cli_state_read(ctx, m, "--at", text, st, NULL);
}

int cli_state_parse_as(qd_ctx *ctx, const qd_model *m, const char *what, const char *text,
                      cli_state *st) {
    return cli_state_read(ctx, m, what, text, st, NULL);
}

/* text[start, start + len) of the option what: exact (a number) and val. */
static int read_number(qd_ctx *ctx, const char *what, const char *text, size_t start,
                       size_t len, const qd_expr **exact, double *val) {
    if (qd_state_value(ctx, NULL, text, start, len, exact, val) != QD_OK)
        return cli_state_diag(ctx, what, text);
    if (!qd_is_number(*exact) && !(*exact = qd_float(ctx, *val)))
        return cli_diag_ctx(ctx);
    return QD_EXIT_OK;
}

int cli_state_number(qd_ctx *ctx, const char *what, const char *text, const qd_expr **exact,
                    double *val) {
    return read_number(ctx, what, text, 0, strlen(text), exact, val);
}

int cli_state_read_set(qd_ctx *ctx, const char *arg, char *name, size_t cap,
                       const qd_expr **value) {
    const char *eq = strchr(arg, '=');
    if (!eq || eq == arg)
        return cli_usage_error("--set takes NAME=VALUE, not '%s'", arg);
    size_t n = (size_t)(eq - arg);
    while (n && isspace((unsigned char)arg[n - 1]))
        n--;
    if (n >= cap)
        return cli_usage_error("--set: the name in '%s' is too long", arg);
    memcpy(name, arg, n);
    name[n] = '\0';
    double v;
    size_t start = (size_t)(eq + 1 - arg);
    return read_number(ctx, "--set", arg, start, strlen(arg) - start, value, &v);
}

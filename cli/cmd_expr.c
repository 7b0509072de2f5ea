/*
 * cli/cmd_expr.c - the kernel on the command line: diff, expand, simplify,
 * print.  Each reads one expression (unknown names become plain symbols, or
 * coordinates when written with a prime: r' is then a symbol of its own),
 * applies one libqdot operation and prints the result.
 */
#include "cli.h"

#include <string.h>

typedef struct expr_args {
    const char *text;
    const char *vars[16];
    size_t nvars;
    qd_format fmt;
} expr_args;

/* EXPR [VAR...] [--format F]; returns an exit status, QD_EXIT_OK to go on. */
static int parse_args(int argc, char **argv, expr_args *a, size_t min_vars, const char *cmd) {
    a->text = NULL;
    a->nvars = 0;
    a->fmt = QD_FMT_TEXT;
    bool has_format = false;
    for (int i = 0; i < argc; i++) {
        if (!strcmp(argv[i], "--format")) {
            if (has_format) {
                cli_diag_error("--format is given twice; give it once");
                return QD_EXIT_USAGE;
            }
            has_format = true;
            if (i + 1 >= argc || !cli_format(argv[i + 1], &a->fmt)) {
                cli_diag_error("--format takes text, latex, c or sympy");
                return QD_EXIT_USAGE;
            }
            i++;
        } else if (!a->text) {
            a->text = argv[i];
        } else if (a->nvars < 16) {
            a->vars[a->nvars++] = argv[i];
        } else {
            cli_diag_error("too many arguments to '%s'", cmd);
            return QD_EXIT_USAGE;
        }
    }
    if (!a->text || a->nvars < min_vars) {
        cli_diag_error("usage: qdot %s EXPR%s [--format F]", cmd, min_vars ? " VAR [VAR...]" : "");
        return QD_EXIT_USAGE;
    }
    if (!min_vars && a->nvars) {
        cli_diag_error("'%s' takes one expression; unexpected '%s'", cmd, a->vars[0]);
        return QD_EXIT_USAGE;
    }
    return QD_EXIT_OK;
}

static int emit(qd_ctx *ctx, const qd_expr *e, qd_format fmt) {
    if (!e)
        return cli_diag_ctx(ctx);
    qd_buf b = QD_BUF_INIT;
    qd_status st = qd_print(ctx, e, fmt, &b);
    if (st == QD_OK)
        printf("%s\n", qd_buf_str(&b));
    else
        cli_diag_error("cannot print: %s", qd_status_str(st));
    qd_buf_free(&b);
    return st == QD_OK ? QD_EXIT_OK : QD_EXIT_FAIL;
}

typedef const qd_expr *(*unary_op)(qd_ctx *, const qd_expr *);

static int run(int argc, char **argv, const char *cmd, size_t min_vars, unary_op op) {
    expr_args a;
    int rc = parse_args(argc, argv, &a, min_vars, cmd);
    if (rc != QD_EXIT_OK)
        return rc;
    qd_ctx *ctx = qd_ctx_new();
    if (!ctx) {
        cli_diag_error("out of memory");
        return QD_EXIT_FAIL;
    }
    qd_diag err;
    const qd_expr *e = qd_read(ctx, a.text, NULL, &err);
    if (!e) {
        cli_diag_read("<expression>", a.text, &err);
        qd_ctx_free(ctx);
        return QD_EXIT_USAGE;
    }
    const qd_expr *e0 = e;
    for (size_t i = 0; i < a.nvars && e; i++) {
        /* a name or a rate: r, r', theta'' (read against the expression's symbols) */
        qd_read_opts known = {.new_symbols = false};
        const qd_expr *v = qd_read(ctx, a.vars[i], &known, NULL);
        if (!v || qd_expr_kind(v) != QD_SYMBOL || !qd_has(e0, v)) {
            qd_ctx_clear_error(ctx);
            cli_diag_error("'%s' does not occur in the expression", a.vars[i]);
            qd_ctx_free(ctx);
            return QD_EXIT_USAGE;
        }
        e = qd_diff(ctx, e, v);
    }
    if (op)
        e = op(ctx, e);
    rc = emit(ctx, e, a.fmt);
    qd_ctx_free(ctx);
    return rc;
}

int cli_cmd_diff(int argc, char **argv) { return run(argc, argv, "diff", 1, NULL); }
int cli_cmd_expand(int argc, char **argv) { return run(argc, argv, "expand", 0, qd_expand); }
int cli_cmd_simplify(int argc, char **argv) { return run(argc, argv, "simplify", 0, qd_simplify); }
int cli_cmd_print(int argc, char **argv) { return run(argc, argv, "print", 0, NULL); }

/*
 * cli/cmd_expr.c - the kernel on the command line: diff, expand, simplify,
 * print.  Each reads one expression (unknown names become plain symbols, or
 * coordinates when written with a prime: r' is then a symbol of its own),
 * applies one libqdot operation and prints the result (--format json: the
 * library's qd_json_expr_result); the variables of diff are read by
 * qd_read_variable (qdot/read.h).
 */
#include "driver.h"

#include <string.h>

#include "qdot/json.h"

#define MAX_VARS 16

typedef const qd_expr *(*unary_op)(qd_ctx *, const qd_expr *);

typedef struct expr_args {
    cli_run c; /* the options follow */
    const char *format;
    const char *pos[1 + MAX_VARS]; /* EXPR, then the VARs of diff */
    unary_op op;                   /* applied after diff; may be NULL */
    const char *name;              /* the command's */
} expr_args;

static const char *const formats[] = {"text", "latex", "c", "sympy", "json", NULL};

static const cli_opt expr_opts[] = {
    CLI_OPT_FORMATS(expr_args, format, formats),
    {0},
};

#define SPEC(name, syn, summary, maxpos) \
    {name, syn, summary, expr_opts, NULL, maxpos > 1 ? 2 : 1, maxpos, "EXPR", true}
static const cli_spec specs[] = {
    SPEC("diff", "EXPR VAR [VAR...] [--format F]",
         "partial derivative of EXPR (repeated for each VAR: a name or a rate r')", 1 + MAX_VARS),
    SPEC("expand", "EXPR [--format F]", "distribute products and powers of sums", 1),
    SPEC("simplify", "EXPR [--format F]", "expand, trigonometric identities, cancel, factor", 1),
    SPEC("print", "EXPR [--format F]", "print an expression in canonical form", 1),
};

static int emit(qd_ctx *ctx, const qd_expr *e, const expr_args *a, size_t nvars) {
    if (!e)
        return cli_diag_ctx(ctx);
    qd_buf b = QD_BUF_INIT;
    qd_status st = cli_json(a->format)
                       ? qd_json_expr_result(ctx, a->name, a->pos[0], nvars, a->pos + 1, e, &b)
                       : qd_print(ctx, e, cli_format_or_text(a->format), &b);
    if (st == QD_OK)
        printf("%s%s", qd_buf_str(&b), cli_json(a->format) ? "" : "\n"); /* JSON has it */
    else
        cli_diag_error("cannot print: %s", qd_status_str(st));
    qd_buf_free(&b);
    return st == QD_OK ? QD_EXIT_OK : QD_EXIT_FAIL;
}

static int run(cli_run *c) {
    const expr_args *a = (expr_args *)c;
    qd_ctx *ctx = c->ctx;
    const char *text = a->pos[0];
    size_t nvars = 0;
    while (nvars < MAX_VARS && a->pos[1 + nvars])
        nvars++;
    qd_diag err;
    const qd_expr *e = qd_read(ctx, text, NULL, &err);
    if (!e) {
        cli_diag_read("<expression>", text, &err);
        return QD_EXIT_USAGE;
    }
    const qd_expr *e0 = e;
    for (size_t i = 0; i < nvars && e; i++) {
        /* a name or a rate: r, r', theta'' (one of the expression's symbols) */
        const qd_expr *v = qd_read_variable(ctx, a->pos[1 + i], e0, &err);
        if (!v) {
            cli_diag_read("<variable>", a->pos[1 + i], &err);
            return cli_exit(err.status);
        }
        e = qd_diff(ctx, e, v);
    }
    if (a->op)
        e = a->op(ctx, e);
    /* expand only: simplify factors on purpose, (x + y)^2 */
    const qd_expr *kept = e && a->op == qd_expand ? qd_expand_kept(ctx, e) : NULL;
    if (kept) { /* said, not handed back as if expanded */
        qd_buf k = QD_BUF_INIT;
        if (qd_print(ctx, kept, QD_FMT_TEXT, &k) == QD_OK)
            fprintf(stderr, "qdot: note: %.*s%s is kept as a power: its expansion would exceed "
                            "64 MiB (docs/cli.md, qdot expand)\n",
                    k.len > 80 ? 77 : (int)k.len, qd_buf_str(&k), k.len > 80 ? "..." : "");
        qd_buf_free(&k);
    }
    return emit(ctx, e, a, nvars);
}

static int drive(int argc, char **argv, const cli_spec *spec, unary_op op) {
    const cli_driver d = {spec, 0, offsetof(expr_args, pos), NULL, run, NULL};
    expr_args a = {.op = op, .name = spec->name};
    return cli_drive(&d, &a.c, argc, argv);
}

int cli_cmd_diff(int argc, char **argv) { return drive(argc, argv, &specs[0], NULL); }
int cli_cmd_expand(int argc, char **argv) { return drive(argc, argv, &specs[1], qd_expand); }
int cli_cmd_simplify(int argc, char **argv) { return drive(argc, argv, &specs[2], qd_simplify); }
int cli_cmd_print(int argc, char **argv) { return drive(argc, argv, &specs[3], NULL); }

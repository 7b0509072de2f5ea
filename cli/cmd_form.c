/*
 * cli/cmd_form.c - `qdot form "EXPR" --vars "x, y"`: a quadratic form's
 * matrix, Lagrange's reduction to a sum of squares and its inertia
 * (qd_qform_reduce; Desloge App. 24-27).
 */
#include "cli.h"

#include <stddef.h>
#include <stdlib.h>
#include <string.h>
#include "qdot/json.h"

typedef struct form_args {
    const char *format, *vars, *text;
} form_args;

static const char *const formats[] = {"text", "json", NULL};

static const cli_opt form_opts[] = {
    {"--vars", NULL, CLI_TEXT, offsetof(form_args, vars), "\"x, y, ...\"",
     "the variables of the form (required)", NULL, NULL},
    {"--format", NULL, CLI_CHOICE, offsetof(form_args, format), "F", "the output format",
     formats, NULL},
    {0},
};

static const cli_spec form_spec = {
    "form", "EXPR --vars \"x, y, ...\" [--format F]",
    "a quadratic form: its matrix, Lagrange's reduction to a sum of squares, its inertia",
    form_opts, NULL, 1, 1, "EXPR", true,
};

/* The names of --vars as symbols (at most cap). */
static int read_vars(qd_ctx *ctx, const char *list, const qd_expr **x, size_t cap, size_t *n) {
    *n = 0;
    for (size_t i = 0; list[i];) {
        while (list[i] == ' ' || list[i] == ',')
            i++;
        size_t j = i;
        while (list[j] && list[j] != ',' && list[j] != ' ')
            j++;
        if (j == i)
            break;
        char name[128];
        if (j - i >= sizeof name || *n == cap) {
            cli_diag_error("--vars: too many variables or a name too long");
            return QD_EXIT_USAGE;
        }
        memcpy(name, list + i, j - i);
        name[j - i] = '\0';
        const qd_expr *s = qd_lookup(ctx, name);
        if (!s)
            s = qd_symbol(ctx, name);
        if (!s || qd_expr_kind(s) != QD_SYMBOL) {
            cli_diag_error("--vars: '%s' is not a variable name", name);
            return QD_EXIT_USAGE;
        }
        x[(*n)++] = s;
        i = j;
    }
    if (*n == 0) {
        cli_diag_error("--vars names no variable");
        return QD_EXIT_USAGE;
    }
    return QD_EXIT_OK;
}

static void put(qd_ctx *ctx, qd_buf *b, const qd_expr *x) {
    qd_print(ctx, x, QD_FMT_TEXT, b);
}

/* sum c_k y_k^2, as written (not expanded). */
static const qd_expr *squares(qd_ctx *ctx, const qd_qform *f) {
    const qd_expr *s = qd_int(ctx, 0);
    for (size_t k = 0; k < f->nsq; k++)
        s = qd_add(ctx, s, qd_mul(ctx, f->coef[k], qd_powi(ctx, f->lin[k], 2)));
    return s;
}

static void write_text(qd_ctx *ctx, qd_buf *b, const qd_expr *phi, const qd_qform *f) {
    size_t n = f->n;
    qd_buf_puts(b, "quadratic form in ");
    for (size_t i = 0; i < n; i++)
        qd_buf_printf(b, "%s%s", i ? ", " : "", qd_expr_name(f->x[i]));
    qd_buf_puts(b, "\n  phi = ");
    put(ctx, b, phi);
    qd_buf_puts(b, "\nmatrix (phi = x^T a x, a symmetric)\n");
    for (size_t i = 0; i < n; i++) {
        qd_buf_puts(b, "  [");
        for (size_t j = 0; j < n; j++) {
            qd_buf_puts(b, j ? ", " : "");
            put(ctx, b, f->a[i * n + j]);
        }
        qd_buf_puts(b, "]\n");
    }
    qd_buf_printf(b, "Lagrange's reduction (completing squares%s)\n",
                  f->paired ? "; the pair x_i = u + v, x_j = u - v where no square was left" : "");
    qd_buf_puts(b, "  phi = ");
    put(ctx, b, squares(ctx, f));
    qd_buf_puts(b, "\n");
    for (size_t k = 0; k < f->nsq; k++) {
        qd_buf_printf(b, "  c%zu = ", k + 1);
        put(ctx, b, f->coef[k]);
        qd_buf_printf(b, ", y%zu = ", k + 1);
        put(ctx, b, f->lin[k]);
        qd_buf_puts(b, "\n");
    }
    qd_buf_printf(b, "rank %zu\n", f->nsq);
    if (f->decided)
        qd_buf_printf(b, "inertia (Sylvester): n+ = %zu, n- = %zu, n0 = %zu (%s)\n", f->npos,
                      f->nneg, f->nzero, f->kind);
    else
        qd_buf_printf(b, "inertia: undecided (a coefficient of unknown sign); n0 = %zu\n",
                      f->nzero);
}

static void write_json(qd_ctx *ctx, qd_json *j, const qd_expr *phi, const qd_qform *f) {
    size_t n = f->n;
    qd_json_begin_object(j);
    qd_json_key(j, "variables");
    qd_json_begin_array(j);
    for (size_t i = 0; i < n; i++)
        qd_json_string(j, qd_expr_name(f->x[i]));
    qd_json_end_array(j);
    qd_json_key(j, "form");
    qd_json_expr(j, ctx, phi);
    qd_json_key(j, "matrix");
    qd_json_begin_array(j);
    for (size_t i = 0; i < n; i++) {
        qd_json_begin_array(j);
        for (size_t k = 0; k < n; k++)
            qd_json_expr(j, ctx, f->a[i * n + k]);
        qd_json_end_array(j);
    }
    qd_json_end_array(j);
    qd_json_key(j, "coefficients");
    qd_json_begin_array(j);
    for (size_t k = 0; k < f->nsq; k++)
        qd_json_expr(j, ctx, f->coef[k]);
    qd_json_end_array(j);
    qd_json_key(j, "linear_forms");
    qd_json_begin_array(j);
    for (size_t k = 0; k < f->nsq; k++)
        qd_json_expr(j, ctx, f->lin[k]);
    qd_json_end_array(j);
    qd_json_key(j, "sum_of_squares");
    qd_json_expr(j, ctx, squares(ctx, f));
    qd_json_key(j, "paired");
    qd_json_bool(j, f->paired);
    qd_json_key(j, "rank");
    qd_json_number(j, (double)f->nsq);
    qd_json_key(j, "inertia");
    if (f->decided) {
        qd_json_begin_object(j);
        qd_json_key(j, "positive");
        qd_json_number(j, (double)f->npos);
        qd_json_key(j, "negative");
        qd_json_number(j, (double)f->nneg);
        qd_json_key(j, "zero");
        qd_json_number(j, (double)f->nzero);
        qd_json_end_object(j);
    } else {
        qd_json_null(j);
    }
    qd_json_key(j, "kind");
    if (f->kind)
        qd_json_string(j, f->kind);
    else
        qd_json_null(j);
    qd_json_end_object(j);
}

int cli_cmd_form(int argc, char **argv) {
    form_args a = {0};
    int rc = cli_parse(&form_spec, argc, argv, &a, &a.text);
    if (rc != QD_EXIT_OK)
        return rc;
    if (!a.vars) {
        cli_diag_error("--vars is missing (usage: qdot form %s)", form_spec.synopsis);
        return QD_EXIT_USAGE;
    }
    bool json = a.format && !strcmp(a.format, "json");
    qd_ctx *ctx = qd_ctx_new();
    if (!ctx) {
        cli_diag_error("out of memory");
        return QD_EXIT_FAIL;
    }
    qd_diag err;
    const qd_expr *phi = qd_read(ctx, a.text, NULL, &err), *x[64];
    size_t n = 0;
    qd_qform *f = NULL;
    if (!phi) {
        cli_diag_read("<form>", a.text, &err);
        rc = QD_EXIT_USAGE;
    } else if ((rc = read_vars(ctx, a.vars, x, 64, &n)) == QD_EXIT_OK &&
               !(f = qd_qform_reduce(ctx, phi, n, x))) {
        rc = cli_diag_ctx(ctx);
    }
    if (f) {
        qd_buf b = QD_BUF_INIT;
        qd_json j;
        if (json) {
            qd_json_init(&j, &b);
            write_json(ctx, &j, phi, f);
            qd_buf_puts(&b, "\n");
        } else {
            write_text(ctx, &b, phi, f);
        }
        bool ok = !b.failed && (!json || qd_json_ok(&j));
        if (ok)
            fputs(qd_buf_str(&b), stdout);
        else
            cli_diag_error("cannot print the result");
        rc = ok ? QD_EXIT_OK : QD_EXIT_FAIL;
        qd_buf_free(&b);
    }
    qd_qform_free(f);
    qd_ctx_free(ctx);
    return rc;
}

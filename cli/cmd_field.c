/*
 * cli/cmd_field.c - `qdot eom` and `qdot modes` on a field model
 * (`field y(x, t) on x = A .. B`, qdot/field.h): the field equation of the
 * Lagrangian density, and the normal modes (closed form for constant
 * coefficients, else finite elements with the error estimate).
 */
#include "cli.h"

#include <math.h>
#include <stdio.h>
#include "qdot/json.h"
#include "model_cli.h"

static const char *end_name(qd_field_end e) { return e == QD_FIELD_FREE ? "free" : "fixed"; }

static void put_expr(qd_ctx *ctx, qd_buf *b, const qd_expr *x) { qd_print(ctx, x, QD_FMT_TEXT, b); }

/* "field y(x, t) on x = 0 .. 1: fixed at x = 0, free at x = 1" */
static void put_head(const qd_field *f, qd_buf *b) {
    double a, c;
    qd_field_interval(f, &a, &c);
    const char *x = qd_field_space(f);
    qd_buf_printf(b, "field %s(%s, t) on %s = ", qd_field_name(f), x, x);
    qd_buf_put_double(b, a);
    qd_buf_puts(b, " .. ");
    qd_buf_put_double(b, c);
    qd_buf_printf(b, ": %s at %s = ", end_name(qd_field_boundary(f, 0)), x);
    qd_buf_put_double(b, a);
    qd_buf_printf(b, ", %s at %s = ", end_name(qd_field_boundary(f, 1)), x);
    qd_buf_put_double(b, c);
    qd_buf_puts(b, "\n");
}

static void json_head(qd_ctx *ctx, const qd_field *f, qd_json *j) {
    double a, c;
    qd_field_interval(f, &a, &c);
    qd_json_key(j, "field");
    qd_json_string(j, qd_field_name(f));
    qd_json_key(j, "space");
    qd_json_string(j, qd_field_space(f));
    qd_json_key(j, "interval");
    qd_json_begin_array(j);
    qd_json_number(j, a);
    qd_json_number(j, c);
    qd_json_end_array(j);
    qd_json_key(j, "boundary");
    qd_json_begin_array(j);
    qd_json_string(j, end_name(qd_field_boundary(f, 0)));
    qd_json_string(j, end_name(qd_field_boundary(f, 1)));
    qd_json_end_array(j);
    qd_json_key(j, "density");
    qd_json_expr(j, ctx, qd_field_density(f));
}

static int emit(qd_buf *b, const qd_json *j, bool json, const char *what) {
    if (json && !qd_json_ok(j)) {
        cli_diag_error("cannot print the %s: %s", what, qd_json_why(j));
        qd_buf_free(b);
        return QD_EXIT_FAIL;
    }
    return cli_emit(b, what);
}

int cli_field_eom(const char *file, size_t nsets, const char *const *sets, bool json) {
    qd_ctx *ctx = qd_ctx_new();
    if (!ctx) {
        cli_diag_error("out of memory");
        return QD_EXIT_FAIL;
    }
    cli_model_file mf;
    int rc = cli_load_field(ctx, file, nsets, sets, &mf);
    const qd_expr *e = rc == QD_EXIT_OK ? qd_field_equation(ctx, mf.field) : NULL;
    if (rc == QD_EXIT_OK && !e)
        rc = cli_diag_ctx(ctx);
    if (e) {
        qd_buf b = QD_BUF_INIT;
        qd_json j;
        if (json) {
            qd_json_init(&j, &b);
            qd_json_begin_object(&j);
            json_head(ctx, mf.field, &j);
            qd_json_key(&j, "equation");
            qd_json_expr(&j, ctx, e);
            qd_json_end_object(&j);
            qd_buf_puts(&b, "\n");
        } else {
            put_head(mf.field, &b);
            qd_buf_puts(&b, "field equation (d/dt dL/dy_t + d/dx dL/dy_x - dL/dy = 0):\n  ");
            put_expr(ctx, &b, e);
            qd_buf_puts(&b, " = 0\n");
        }
        rc = emit(&b, &j, json, "field equation");
    }
    cli_model_file_free(&mf);
    qd_ctx_free(ctx);
    return rc;
}

/* "sin(3.14159*x)" or "cos(1.5708*(x - 1))" */
static void put_shape(qd_buf *b, const qd_field *f, const qd_field_mode *md) {
    double a, c;
    qd_field_interval(f, &a, &c);
    if (md->shape == QD_FIELD_SHAPE_NONE)
        return;
    if (md->k == 0) {
        qd_buf_puts(b, "1");
        return;
    }
    qd_buf_puts(b, md->shape == QD_FIELD_SHAPE_SIN ? "sin(" : "cos(");
    qd_buf_put_double(b, md->k); /* an expression one may evaluate: every digit */
    if (a == 0)
        qd_buf_printf(b, "*%s)", qd_field_space(f));
    else {
        qd_buf_printf(b, "*(%s %s ", qd_field_space(f), a > 0 ? "-" : "+");
        qd_buf_put_double(b, fabs(a));
        qd_buf_puts(b, "))");
    }
}

static void modes_text(qd_ctx *ctx, const qd_field *f, const qd_field_modes *r, double tol,
                       qd_buf *b) {
    put_head(f, b);
    qd_buf_puts(b, "rho = ");
    put_expr(ctx, b, r->rho);
    qd_buf_puts(b, ", tau = ");
    put_expr(ctx, b, r->tau);
    qd_buf_puts(b, ", kappa = ");
    put_expr(ctx, b, r->kappa);
    if (r->exact)
        qd_buf_puts(b, ": constant coefficients, the modes are exact\n");
    else
        qd_buf_printf(b, ": by linear finite elements on %zu elements with Richardson's "
                      "extrapolation; %s\n", r->elements,
                      r->converged ? "every error estimate is below the tolerance"
                                   : "NOT CONVERGED: the estimates exceed the tolerance");
    qd_buf_puts(b, r->exact ? "mode  omega  omega^2  shape\n" : "mode  omega  omega^2  error\n");
    /* computed results: the digit rule of qd_result_format, each column
     * against its largest entry (an error against the frequencies) */
    double w = 0, w2 = 0;
    for (size_t i = 0; i < r->n; i++) {
        w = fmax(w, r->mode[i].omega2 >= 0 ? r->mode[i].omega : 0);
        w2 = fmax(w2, fabs(r->mode[i].omega2));
    }
    for (size_t i = 0; i < r->n; i++) {
        const qd_field_mode *md = &r->mode[i];
        qd_buf_printf(b, "%zu  ", i + 1);
        if (md->omega2 >= 0)
            qd_buf_put_result(b, md->omega, w);
        else
            qd_buf_puts(b, "unstable");
        qd_buf_puts(b, "  ");
        qd_buf_put_result(b, md->omega2, w2);
        qd_buf_puts(b, "  ");
        if (r->exact)
            put_shape(b, f, md);
        else
            qd_buf_put_result(b, md->error, w);
        qd_buf_puts(b, "\n");
    }
    (void)tol;
}

static void modes_json(qd_ctx *ctx, const qd_field *f, const qd_field_modes *r, double tol,
                       qd_json *j) {
    qd_json_begin_object(j);
    json_head(ctx, f, j);
    qd_json_key(j, "rho");
    qd_json_expr(j, ctx, r->rho);
    qd_json_key(j, "tau");
    qd_json_expr(j, ctx, r->tau);
    qd_json_key(j, "kappa");
    qd_json_expr(j, ctx, r->kappa);
    qd_json_key(j, "method");
    qd_json_string(j, r->exact ? "exact" : "finite elements");
    qd_json_key(j, "converged");
    qd_json_bool(j, r->converged);
    qd_json_key(j, "elements");
    if (r->exact)
        qd_json_null(j);
    else
        qd_json_number(j, (double)r->elements);
    qd_json_key(j, "tolerance");
    qd_json_number(j, tol);
    qd_json_key(j, "modes");
    qd_json_begin_array(j);
    for (size_t i = 0; i < r->n; i++) {
        const qd_field_mode *md = &r->mode[i];
        qd_json_begin_object(j);
        qd_json_key(j, "omega");
        if (md->omega2 >= 0)
            qd_json_number(j, md->omega);
        else
            qd_json_null(j);
        qd_json_key(j, "omega2");
        qd_json_number(j, md->omega2);
        qd_json_key(j, "error");
        if (isfinite(md->error))
            qd_json_number(j, md->error);
        else
            qd_json_null(j);
        qd_json_key(j, "shape");
        if (md->shape == QD_FIELD_SHAPE_NONE)
            qd_json_null(j);
        else {
            qd_buf s = QD_BUF_INIT;
            put_shape(&s, f, md);
            qd_json_string(j, qd_buf_str(&s));
            qd_buf_free(&s);
        }
        qd_json_key(j, "k");
        if (md->shape == QD_FIELD_SHAPE_NONE)
            qd_json_null(j);
        else
            qd_json_number(j, md->k);
        qd_json_end_object(j);
    }
    qd_json_end_array(j);
    qd_json_end_object(j);
}

/* The library's reason, shown at the Ldensity statement (a bad input: 2). */
static int density_error(qd_ctx *ctx, const cli_model_file *mf) {
    if (qd_ctx_status(ctx) != QD_ERR_ARG)
        return cli_diag_ctx(ctx);
    qd_diag d;
    if (!qd_model_where(qd_field_model(mf->field), "Ldensity", &d))
        return cli_diag_ctx(ctx);
    snprintf(d.message, sizeof d.message, "%s", qd_ctx_message(ctx));
    snprintf(d.hint, sizeof d.hint, "the modes need Ldensity = rho/2*y_t^2 - tau/2*y_x^2 "
             "- kappa/2*y^2 with rho, tau, kappa functions of the space variable");
    cli_diag_show(mf->path, mf->text, &d);
    return QD_EXIT_USAGE;
}

int cli_field_modes(const char *file, size_t nsets, const char *const *sets, size_t count,
                    double tol, bool json) {
    qd_ctx *ctx = qd_ctx_new();
    if (!ctx) {
        cli_diag_error("out of memory");
        return QD_EXIT_FAIL;
    }
    cli_model_file mf;
    qd_field_modes r = {0};
    int rc = cli_load_field(ctx, file, nsets, sets, &mf);
    qd_field_modes_opts o = {.count = count, .tol = tol};
    if (rc == QD_EXIT_OK && qd_field_modes_compute(ctx, mf.field, &o, &r) != QD_OK)
        rc = density_error(ctx, &mf);
    if (rc == QD_EXIT_OK) {
        qd_buf b = QD_BUF_INIT;
        qd_json j;
        double t = tol > 0 ? tol : 1e-6;
        if (json) {
            qd_json_init(&j, &b);
            modes_json(ctx, mf.field, &r, t, &j);
            qd_buf_puts(&b, "\n");
        } else
            modes_text(ctx, mf.field, &r, t, &b);
        rc = emit(&b, &j, json, "modes");
        if (rc == QD_EXIT_OK && !r.converged) {
            cli_diag_error("the modes did not converge to --tol on %zu elements: the estimates "
                           "are printed; ask for fewer modes or a larger tolerance", r.elements);
            rc = QD_EXIT_FAIL;
        }
    }
    qd_field_modes_free(&r);
    cli_model_file_free(&mf);
    qd_ctx_free(ctx);
    return rc;
}

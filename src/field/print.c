/*
 * src/field/print.c - a field model's equation and normal modes written
 * for a reader (text) or a program (JSON), qdot/field.h.  One writer for
 * `qdot eom`/`qdot modes` on a field and any other caller.
 */
#include "qdot/field.h"

#include <math.h>

#include "qdot/json.h"
#include "../base/args.h"

static const char *end_name(qd_field_end e) { return e == QD_FIELD_FREE ? "free" : "fixed"; }

/* Written, or why not, recorded in ctx. */
static qd_status done(qd_ctx *ctx, const qd_buf *out, const qd_json *j) {
    if (out->failed || (j && !qd_json_ok(j))) {
        qd_status st = out->failed ? QD_ERR_NOMEM : QD_ERR_ARG;
        qd_ctx_error(ctx, st, "%s", out->failed ? "out of memory" : qd_json_why(j));
        return st;
    }
    return QD_OK;
}

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
    double ends[2];
    qd_field_interval(f, &ends[0], &ends[1]);
    qd_json_key(j, "field");
    qd_json_string(j, qd_field_name(f));
    qd_json_key(j, "space");
    qd_json_string(j, qd_field_space(f));
    qd_json_vector(j, "interval", 2, ends);
    qd_json_key(j, "boundary");
    qd_json_begin_array(j);
    qd_json_string(j, end_name(qd_field_boundary(f, 0)));
    qd_json_string(j, end_name(qd_field_boundary(f, 1)));
    qd_json_end_array(j);
    qd_json_key(j, "density");
    qd_json_expr(j, ctx, qd_field_density(f));
}

qd_status qd_field_equation_print(qd_ctx *ctx, const qd_field *f, const qd_expr *E, qd_buf *out) {
    QD_ARGS_CTX(ctx, ctx && f && E && out);
    put_head(f, out);
    qd_buf_puts(out, "field equation (d/dt dL/dy_t + d/dx dL/dy_x - dL/dy = 0):\n  ");
    qd_print(ctx, E, QD_FMT_TEXT, out);
    qd_buf_puts(out, " = 0\n");
    return done(ctx, out, NULL);
}

qd_status qd_field_equation_json(qd_ctx *ctx, const qd_field *f, const qd_expr *E, qd_buf *out) {
    QD_ARGS_CTX(ctx, ctx && f && E && out);
    qd_json j;
    qd_json_init(&j, out);
    qd_json_begin_object(&j);
    json_head(ctx, f, &j);
    qd_json_key(&j, "equation");
    qd_json_expr(&j, ctx, E);
    qd_json_end_object(&j);
    qd_buf_puts(out, "\n");
    return done(ctx, out, &j);
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

qd_status qd_field_modes_print(qd_ctx *ctx, const qd_field *f, const qd_field_modes *r,
                               qd_buf *b) {
    QD_ARGS_CTX(ctx, ctx && f && r && b && (r->mode || !r->n));
    put_head(f, b);
    qd_buf_puts(b, "rho = ");
    qd_print(ctx, r->rho, QD_FMT_TEXT, b);
    qd_buf_puts(b, ", tau = ");
    qd_print(ctx, r->tau, QD_FMT_TEXT, b);
    qd_buf_puts(b, ", kappa = ");
    qd_print(ctx, r->kappa, QD_FMT_TEXT, b);
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
    return done(ctx, b, NULL);
}

/* A number, or null where there is none. */
static void number_or_null(qd_json *j, bool has, double x) {
    qd_json_number_or_null(j, has ? x : NAN);
}

qd_status qd_field_modes_json(qd_ctx *ctx, const qd_field *f, const qd_field_modes *r,
                              qd_buf *out) {
    QD_ARGS_CTX(ctx, ctx && f && r && out && (r->mode || !r->n));
    qd_json j;
    qd_json_init(&j, out);
    qd_json_begin_object(&j);
    json_head(ctx, f, &j);
    qd_json_key(&j, "rho");
    qd_json_expr(&j, ctx, r->rho);
    qd_json_key(&j, "tau");
    qd_json_expr(&j, ctx, r->tau);
    qd_json_key(&j, "kappa");
    qd_json_expr(&j, ctx, r->kappa);
    qd_json_key(&j, "method");
    qd_json_string(&j, r->exact ? "exact" : "finite elements");
    qd_json_key(&j, "converged");
    qd_json_bool(&j, r->converged);
    qd_json_key(&j, "elements");
    number_or_null(&j, !r->exact, (double)r->elements);
    qd_json_key(&j, "tolerance");
    qd_json_number(&j, r->tol);
    qd_json_key(&j, "modes");
    qd_json_begin_array(&j);
    for (size_t i = 0; i < r->n; i++) {
        const qd_field_mode *md = &r->mode[i];
        bool shaped = md->shape != QD_FIELD_SHAPE_NONE;
        qd_json_begin_object(&j);
        qd_json_key(&j, "omega");
        number_or_null(&j, md->omega2 >= 0, md->omega);
        qd_json_key(&j, "omega2");
        qd_json_number(&j, md->omega2);
        qd_json_key(&j, "error");
        number_or_null(&j, isfinite(md->error), md->error);
        qd_json_key(&j, "shape");
        if (shaped) {
            qd_buf s = QD_BUF_INIT;
            put_shape(&s, f, md);
            qd_json_string(&j, s.failed ? NULL : qd_buf_str(&s));
            qd_buf_free(&s);
        } else
            qd_json_null(&j);
        qd_json_key(&j, "k");
        number_or_null(&j, shaped, md->k);
        qd_json_end_object(&j);
    }
    qd_json_end_array(&j);
    qd_json_end_object(&j);
    qd_buf_puts(out, "\n");
    return done(ctx, out, &j);
}

/*
 * src/render/qform.c - a quadratic form's reduction printed (qd_render_qform,
 * qdot/render.h): its matrix, Lagrange's sum of squares and Sylvester's
 * inertia, as `qdot form` and Python's QuadraticForm show them.
 */
#include "render.h"

#include "qdot/json.h"
#include "../base/args.h"

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

qd_status qd_render_qform(qd_ctx *ctx, const qd_expr *phi, const qd_qform *f,
                          qd_render_format fmt, qd_buf *out) {
    QD_ARGS_CTX(ctx, ctx && phi && f && out);
    qd_status st = qd__render_text_or_json(ctx, fmt, "a quadratic form");
    if (st != QD_OK)
        return st;
    if (fmt == QD_RENDER_JSON) {
        qd_json j;
        qd_json_init(&j, out);
        write_json(ctx, &j, phi, f);
        qd_buf_puts(out, "\n");
        st = qd__render_json_status(&j, out, QD_OK);
    } else {
        write_text(ctx, out, phi, f);
    }
    return qd__render_finish(ctx, out, st, "the quadratic form");
}

/* ---- homogeneity (qd_homogeneity, Desloge App. 20) ------------------------ */

static void homog_text(qd_ctx *ctx, qd_buf *b, const qd_homog *h, size_t n,
                       const qd_expr *const *x) {
    qd_buf_puts(b, "homogeneity in ");
    for (size_t i = 0; i < n; i++)
        qd_buf_printf(b, "%s%s", i ? ", " : "", qd_expr_name(x[i]));
    qd_buf_puts(b, " (Desloge App. 20: f(lambda x) = lambda^n f(x) for every lambda > 0)\n  f = ");
    put(ctx, b, h->f);
    qd_buf_puts(b, "\n  sum x_i df/dx_i = ");
    put(ctx, b, h->euler);
    qd_buf_puts(b, "\n");
    switch (h->verdict) {
    case QD_HOMOG_YES:
        qd_buf_puts(b, "homogeneous of degree ");
        put(ctx, b, h->degree);
        qd_buf_puts(b, ": sum x_i df/dx_i = (");
        put(ctx, b, h->degree);
        qd_buf_puts(b, ") f (Euler's theorem and its converse)");
        qd_zero_result_note(b, &h->test);
        qd_buf_puts(b, "\n");
        break;
    case QD_HOMOG_EVERY:
        qd_buf_puts(b, "f is 0: homogeneous of every degree\n");
        break;
    case QD_HOMOG_NO:
        qd_buf_puts(b, "not homogeneous: f(x) f(4 x) - f(2 x)^2 is not 0, as it would be if "
                       "f(lambda x) = lambda^n f(x)\n");
        qd_zero_result_print(b, &h->test);
        break;
    case QD_HOMOG_UNDECIDED:
        qd_buf_puts(b, "could not decide: (sum x_i df/dx_i)/f is not shown free of the variables, "
                       "and no point shows f(x) f(4 x) != f(2 x)^2\n");
        break;
    }
}

static void homog_json(qd_ctx *ctx, qd_json *j, const qd_homog *h, size_t n,
                       const qd_expr *const *x) {
    qd_json_begin_object(j);
    qd_json_key(j, "variables");
    qd_json_begin_array(j);
    for (size_t i = 0; i < n; i++)
        qd_json_string(j, qd_expr_name(x[i]));
    qd_json_end_array(j);
    qd_json_key(j, "f");
    qd_json_expr(j, ctx, h->f);
    qd_json_key(j, "euler");
    qd_json_expr(j, ctx, h->euler);
    qd_json_key(j, "verdict");
    qd_json_string(j, qd_homog_verdict_name(h->verdict));
    qd_json_key(j, "homogeneous");
    if (h->verdict == QD_HOMOG_UNDECIDED)
        qd_json_null(j);
    else
        qd_json_bool(j, h->verdict != QD_HOMOG_NO);
    qd_json_key(j, "degree");
    qd_json_expr(j, ctx, h->degree);
    qd_zero_result_json(j, &h->test);
    qd_json_end_object(j);
}

qd_status qd_render_homog(qd_ctx *ctx, const qd_homog *h, size_t n, const qd_expr *const *x,
                          qd_render_format fmt, qd_buf *out) {
    QD_ARGS_CTX(ctx, ctx && h && h->f && h->euler && (x || !n) && out);
    qd_status st = qd__render_text_or_json(ctx, fmt, "a homogeneity");
    if (st != QD_OK)
        return st;
    if (fmt == QD_RENDER_JSON) {
        qd_json j;
        qd_json_init(&j, out);
        homog_json(ctx, &j, h, n, x);
        qd_buf_puts(out, "\n");
        st = qd__render_json_status(&j, out, QD_OK);
    } else {
        homog_text(ctx, out, h, n, x);
    }
    return qd__render_finish(ctx, out, st, "the homogeneity");
}

/* ---- a fundamental period system (qd_periods_reduce, Desloge App. 31) ----- */

static void vec(qd_ctx *ctx, qd_buf *b, const qd_expr *const *v, size_t n) {
    qd_buf_puts(b, "(");
    for (size_t i = 0; i < n; i++) {
        qd_buf_puts(b, i ? ", " : "");
        put(ctx, b, v[i]);
    }
    qd_buf_puts(b, ")");
}

/* "e1 - 2 e2" for the integer coordinates c (k of them). */
static void combination(qd_buf *b, const long *c, size_t k) {
    bool any = false;
    for (size_t i = 0; i < k; i++) {
        if (!c[i])
            continue;
        long a = c[i] < 0 ? -c[i] : c[i];
        qd_buf_puts(b, any ? (c[i] < 0 ? " - " : " + ") : (c[i] < 0 ? "-" : ""));
        if (a != 1)
            qd_buf_printf(b, "%ld ", a);
        qd_buf_printf(b, "e%zu", i + 1);
        any = true;
    }
    if (!any)
        qd_buf_puts(b, "0");
}

static void periods_text(qd_ctx *ctx, qd_buf *b, const qd_expr *f, const qd_periods *p,
                         const qd_expr *const *x, const qd_expr *const *w) {
    qd_buf_puts(b, "periods in ");
    for (size_t i = 0; i < p->r; i++)
        qd_buf_printf(b, "%s%s", i ? ", " : "", qd_expr_name(x[i]));
    qd_buf_puts(b, " (Desloge App. 31: f(x + w) = f(x) for every x)\n");
    if (f) {
        qd_buf_puts(b, "  f = ");
        put(ctx, b, f);
        qd_buf_puts(b, "\n");
    }
    for (size_t j = 0; j < p->g; j++) {
        qd_buf_printf(b, "  w%zu = ", j + 1);
        vec(ctx, b, w + j * p->r, p->r);
        if (p->tested) {
            qd_zero_kind k = p->test[j].kind;
            qd_buf_puts(b, k == QD_ZERO_PROVEN || k == QD_ZERO_NUMERIC ? ": a period of f"
                           : k == QD_ZERO_NONZERO                      ? ": not a period of f"
                                                                      : ": could not decide");
            qd_zero_result_note(b, &p->test[j]);
        }
        qd_buf_puts(b, "\n");
        if (p->tested)
            qd_zero_result_print(b, &p->test[j]);
    }
    qd_buf_printf(b, "fundamental system of their integer combinations (Thm 4): %zu period%s\n",
                  p->rank, p->rank == 1 ? "" : "s");
    for (size_t k = 0; k < p->rank; k++) {
        qd_buf_printf(b, "  e%zu = ", k + 1);
        vec(ctx, b, p->basis + k * p->r, p->r);
        qd_buf_puts(b, "\n");
    }
    qd_buf_puts(b, "the given vectors in it (eq. 3)\n");
    for (size_t j = 0; j < p->g; j++) {
        qd_buf_printf(b, "  w%zu = ", j + 1);
        combination(b, p->coords + j * p->rank, p->rank);
        qd_buf_puts(b, "\n");
    }
}

static void json_vecs(qd_ctx *ctx, qd_json *j, const char *key, const qd_expr *const *v, size_t m,
                      size_t n) {
    qd_json_key(j, key);
    qd_json_begin_array(j);
    for (size_t k = 0; k < m; k++) {
        qd_json_begin_array(j);
        for (size_t i = 0; i < n; i++)
            qd_json_expr(j, ctx, v[k * n + i]);
        qd_json_end_array(j);
    }
    qd_json_end_array(j);
}

static void periods_json(qd_ctx *ctx, qd_json *j, const qd_expr *f, const qd_periods *p,
                         const qd_expr *const *x, const qd_expr *const *w) {
    qd_json_begin_object(j);
    qd_json_key(j, "variables");
    qd_json_begin_array(j);
    for (size_t i = 0; i < p->r; i++)
        qd_json_string(j, qd_expr_name(x[i]));
    qd_json_end_array(j);
    qd_json_key(j, "f");
    qd_json_expr(j, ctx, f);
    json_vecs(ctx, j, "periods", w, p->g, p->r);
    qd_json_key(j, "tests");
    qd_json_begin_array(j);
    for (size_t k = 0; p->tested && k < p->g; k++) {
        qd_json_begin_object(j);
        qd_json_key(j, "is_period");
        qd_zero_kind z = p->test[k].kind;
        if (z == QD_ZERO_UNKNOWN)
            qd_json_null(j);
        else
            qd_json_bool(j, z != QD_ZERO_NONZERO);
        qd_zero_result_json(j, &p->test[k]);
        qd_json_end_object(j);
    }
    qd_json_end_array(j);
    qd_json_key(j, "unit");
    qd_json_expr(j, ctx, p->unit);
    qd_json_key(j, "rank");
    qd_json_number(j, (double)p->rank);
    json_vecs(ctx, j, "fundamental", p->basis, p->rank, p->r);
    qd_json_key(j, "coordinates");
    qd_json_begin_array(j);
    for (size_t k = 0; k < p->g; k++) {
        qd_json_begin_array(j);
        for (size_t i = 0; i < p->rank; i++)
            qd_json_number(j, (double)p->coords[k * p->rank + i]);
        qd_json_end_array(j);
    }
    qd_json_end_array(j);
    qd_json_end_object(j);
}

qd_status qd_render_periods(qd_ctx *ctx, const qd_expr *f, const qd_periods *p,
                            const qd_expr *const *x, const qd_expr *const *w,
                            qd_render_format fmt, qd_buf *out) {
    QD_ARGS_CTX(ctx, ctx && p && x && w && out);
    qd_status st = qd__render_text_or_json(ctx, fmt, "a set of periods");
    if (st != QD_OK)
        return st;
    if (fmt == QD_RENDER_JSON) {
        qd_json j;
        qd_json_init(&j, out);
        periods_json(ctx, &j, f, p, x, w);
        qd_buf_puts(out, "\n");
        st = qd__render_json_status(&j, out, QD_OK);
    } else {
        periods_text(ctx, out, f, p, x, w);
    }
    return qd__render_finish(ctx, out, st, "the periods");
}

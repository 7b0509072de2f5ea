/*
 * src/linear/zvc_out.c - the zero-velocity picture of qdot/zvc.h: the
 * curves at a level, the equilibria in the box with the level of the curve
 * through each, and the picture written as text, CSV or JSON (the one
 * rendering the program and Python share).
 */
#include <math.h>
#include <string.h>
#include "base/args.h"
#include "base/mem.h"
#include "qdot/json.h"
#include "qdot/zvc.h"

/* W at configuration q (e->n values), the other inputs from syms/vals. */
static double zv_W_at(qd_ctx *ctx, const qd_eom *e, const qd_expr *W, const double *q,
                      size_t nvals, const qd_expr *const *syms, const double *vals) {
    size_t n = e->n, k = n;
    const qd_expr **s = qd__malloc(ctx, (n + nvals + 1) * sizeof *s);
    double *v = qd__malloc(ctx, (n + nvals + 1) * sizeof *v), w = NAN;
    if (s && v) {
        memcpy(s, e->q, n * sizeof *s);
        memcpy(v, q, n * sizeof *v);
        for (size_t i = 0; i < nvals; i++) {
            bool coord = false;
            for (size_t j = 0; j < n; j++)
                coord |= syms[i] == e->q[j];
            if (!coord) {
                s[k] = syms[i];
                v[k++] = vals[i];
            }
        }
        if (qd_eval(ctx, W, k, s, v, &w) != QD_OK) { /* a pole: no value, not a failure */
            qd_ctx_clear_error(ctx);
            w = NAN;
        }
    }
    qd__free(s);
    qd__free(v);
    return w;
}

/* The equilibria in the box: the box's two coordinates over its ranges,
 * the others over their default box (qd_equilibria_default_box). */
static qd_status zv_equilibria(qd_ctx *ctx, const qd_model *m, const qd_eom *e,
                               size_t nvals, const qd_expr *const *syms, const double *vals,
                               qd_zvc_picture *p) {
    size_t n = e->n;
    double *lo = qd__malloc(ctx, (n + 1) * sizeof *lo), *hi = qd__malloc(ctx, (n + 1) * sizeof *hi);
    bool *angle = qd__malloc(ctx, (n + 1) * sizeof *angle);
    qd_status st = lo && hi && angle ? qd_equilibria_default_box(ctx, e, m, angle, lo, hi)
                                     : QD_ERR_NOMEM;
    if (st == QD_OK) {
        lo[p->box.ix] = p->box.lo[0];
        hi[p->box.ix] = p->box.hi[0];
        lo[p->box.iy] = p->box.lo[1];
        hi[p->box.iy] = p->box.hi[1];
        qd_equilibria_opts o = {.lo = lo, .hi = hi, .numeric_only = true};
        st = qd_equilibria_find(ctx, e, m, nvals, syms, vals, &o, &p->eq);
    }
    if (st == QD_OK && !(p->eq_W = qd__calloc(ctx, p->eq.count + 1, sizeof *p->eq_W)))
        st = QD_ERR_NOMEM;
    for (size_t k = 0; st == QD_OK && k < p->eq.count; k++)
        p->eq_W[k] = zv_W_at(ctx, e, p->z.W, p->eq.pts[k].q, nvals, syms, vals);
    qd__free(lo);
    qd__free(hi);
    qd__free(angle);
    return st;
}

qd_status qd_zvc_picture_make(qd_ctx *ctx, const qd_model *m, const qd_eom *e, const qd_zvc *z,
                              const qd_zvc_box *box, size_t nvals, const qd_expr *const *syms,
                              const double *vals, double level, bool equilibria,
                              qd_zvc_picture *out) {
    QD_ARGS_CTX(ctx, ctx && m && e && z && box && out);
    *out = (qd_zvc_picture){.z = *z, .box = *box, .level = level};
    qd_status st = qd_zvc_curves(ctx, e, z, box, nvals, syms, vals, level, &out->curves);
    if (st == QD_OK && equilibria)
        st = zv_equilibria(ctx, m, e, nvals, syms, vals, out);
    return st;
}

void qd_zvc_picture_free(qd_zvc_picture *p) {
    if (!p)
        return;
    qd_contour_free(&p->curves);
    qd_equilibria_free(&p->eq);
    qd__free(p->eq_W);
    *p = (qd_zvc_picture){0};
}

/* ---- written out ---------------------------------------------------------- */

/* A computed number for a reader: the one digit rule (qd_buf_put_result). */
static void zv_put(qd_buf *b, double x) { qd_buf_put_result(b, x, 1); }

static qd_status zv_done(qd_ctx *ctx, const qd_buf *b) {
    if (!b->failed)
        return QD_OK;
    qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory writing the zero-velocity curves");
    return QD_ERR_NOMEM;
}

/* The picture's box is in e's coordinates. */
static qd_status zv_check(qd_ctx *ctx, const qd_eom *e, const qd_zvc_picture *p) {
    if (p->box.ix < e->n && p->box.iy < e->n)
        return QD_OK;
    qd_ctx_error(ctx, QD_ERR_ARG, "zero-velocity curves: the box names a coordinate the "
                                  "equations do not have");
    return QD_ERR_ARG;
}

qd_status qd_zvc_print(qd_ctx *ctx, const qd_eom *e, const qd_zvc_picture *p, qd_buf *b) {
    QD_ARGS_CTX(ctx, ctx && e && p && b);
    if (zv_check(ctx, e, p) != QD_OK)
        return QD_ERR_ARG;
    const char *x = qd_expr_name(e->q[p->box.ix]), *y = qd_expr_name(e->q[p->box.iy]);
    qd_buf_puts(b, "Jacobi's integral: h = ");
    qd_print(ctx, p->z.h, QD_FMT_TEXT, b);
    qd_buf_puts(b, "\nat rest: W = ");
    qd_print(ctx, p->z.W, QD_FMT_TEXT, b);
    qd_buf_puts(b, "\nlevel: h = ");
    zv_put(b, p->level);
    qd_buf_puts(b, " (zero-velocity curves W = h; the motion stays where W <= h)\n");
    qd_buf_printf(b, "equilibria in the box (h at rest there):\n");
    for (size_t k = 0; k < p->eq.count; k++) {
        qd_buf_puts(b, "  ");
        for (size_t j = 0; j < e->n; j++) {
            qd_buf_printf(b, "%s%s = ", j ? ", " : "", qd_expr_name(e->q[j]));
            zv_put(b, p->eq.pts[k].q[j]);
        }
        qd_buf_printf(b, " (%s): h = ", qd_eq_kind_name(p->eq.pts[k].kind));
        zv_put(b, p->eq_W[k]);
        qd_buf_puts(b, "\n");
    }
    qd_buf_printf(b, "%zu curve%s on a %zu x %zu grid:\n", p->curves.count,
                  p->curves.count == 1 ? "" : "s", p->box.nx, p->box.ny);
    for (size_t k = 0; k < p->curves.count; k++) {
        const qd_polyline *c = &p->curves.lines[k];
        double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
        for (size_t i = 0; i < c->count; i++) {
            x0 = fmin(x0, c->x[i]);
            x1 = fmax(x1, c->x[i]);
            y0 = fmin(y0, c->y[i]);
            y1 = fmax(y1, c->y[i]);
        }
        qd_buf_printf(b, "  curve %zu: %s, %zu points, %s in [%.4g, %.4g], %s in [%.4g, %.4g]\n",
                      k + 1, c->closed ? "closed" : "open", c->count, x, x0, x1, y, y0, y1);
    }
    return zv_done(ctx, b);
}

qd_status qd_zvc_csv(qd_ctx *ctx, const qd_eom *e, const qd_zvc_picture *p, qd_buf *b) {
    QD_ARGS_CTX(ctx, ctx && e && p && b);
    if (zv_check(ctx, e, p) != QD_OK)
        return QD_ERR_ARG;
    qd_buf_printf(b, "curve,%s,%s\n", qd_expr_name(e->q[p->box.ix]),
                  qd_expr_name(e->q[p->box.iy]));
    for (size_t k = 0; k < p->curves.count; k++)
        for (size_t i = 0; i < p->curves.lines[k].count; i++) {
            qd_buf_printf(b, "%zu,", k + 1);
            qd_buf_put_double(b, p->curves.lines[k].x[i] == 0 ? 0.0 : p->curves.lines[k].x[i]);
            qd_buf_puts(b, ",");
            qd_buf_put_double(b, p->curves.lines[k].y[i] == 0 ? 0.0 : p->curves.lines[k].y[i]);
            qd_buf_puts(b, "\n");
        }
    return zv_done(ctx, b);
}

static void zv_json_equilibria(const qd_eom *e, const qd_zvc_picture *p, qd_json *j) {
    qd_json_key(j, "equilibria");
    qd_json_begin_array(j);
    for (size_t k = 0; k < p->eq.count; k++) {
        qd_json_begin_object(j);
        for (size_t i = 0; i < e->n; i++) {
            qd_json_key(j, qd_expr_name(e->q[i]));
            qd_json_number(j, p->eq.pts[k].q[i]);
        }
        qd_json_key(j, "kind");
        qd_json_string(j, qd_eq_kind_name(p->eq.pts[k].kind));
        qd_json_key(j, "h");
        qd_json_number(j, p->eq_W[k]);
        qd_json_end_object(j);
    }
    qd_json_end_array(j);
}

static void zv_json_curves(const qd_eom *e, const qd_zvc_picture *p, qd_json *j) {
    qd_json_key(j, "curves");
    qd_json_begin_array(j);
    for (size_t k = 0; k < p->curves.count; k++) {
        const qd_polyline *c = &p->curves.lines[k];
        qd_json_begin_object(j);
        qd_json_key(j, "closed");
        qd_json_bool(j, c->closed);
        for (int axis = 0; axis < 2; axis++) {
            qd_json_key(j, qd_expr_name(e->q[axis ? p->box.iy : p->box.ix]));
            qd_json_begin_array(j);
            for (size_t i = 0; i < c->count; i++)
                qd_json_number(j, axis ? c->y[i] : c->x[i]);
            qd_json_end_array(j);
        }
        qd_json_end_object(j);
    }
    qd_json_end_array(j);
}

qd_status qd_zvc_json(qd_ctx *ctx, const qd_eom *e, const qd_zvc_picture *p, qd_buf *b) {
    QD_ARGS_CTX(ctx, ctx && e && p && b);
    if (zv_check(ctx, e, p) != QD_OK)
        return QD_ERR_ARG;
    qd_json j;
    qd_json_init(&j, b);
    qd_json_begin_object(&j);
    qd_json_key(&j, "h");
    qd_json_expr(&j, ctx, p->z.h);
    qd_json_key(&j, "W");
    qd_json_expr(&j, ctx, p->z.W);
    qd_json_key(&j, "level");
    qd_json_number(&j, p->level);
    qd_json_key(&j, "grid");
    qd_json_begin_array(&j);
    qd_json_number(&j, (double)p->box.nx);
    qd_json_number(&j, (double)p->box.ny);
    qd_json_end_array(&j);
    zv_json_equilibria(e, p, &j);
    zv_json_curves(e, p, &j);
    qd_json_end_object(&j);
    qd_buf_puts(b, "\n");
    if (!qd_json_ok(&j) && !b->failed) {
        qd_ctx_error(ctx, QD_ERR_NUMERIC, "zero-velocity curves: %s", qd_json_why(&j));
        return QD_ERR_NUMERIC;
    }
    return zv_done(ctx, b);
}

/*
 * src/field/modes.c - the field equation and the normal modes of a field
 * y(x, t) on an interval (qdot/field.h; Desloge ch. 83, Problem 4).
 *
 * The equation is the Euler-Lagrange equation of the density with total
 * derivatives in t and x.  The modes solve -(tau Y')' + kappa Y = w^2 rho Y:
 * in closed form for constant coefficients, else by linear finite elements
 * and Richardson's extrapolation in h^2 (the header gives the details).
 */
#include "../model/model_export.h"
#include "qdot/field.h"
#include "../base/mem.h"
#include "../base/args.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

extern void dsbgv_(const char *jobz, const char *uplo, const int *n, const int *ka,
                   const int *kb, double *ab, const int *ldab, double *bb, const int *ldbb,
                   double *w, double *z, const int *ldz, double *work, int *info);

/* NAME_tt, NAME_xt, NAME_xx for the field NAME in the space variable x:
 * which counts the x's (0, 1, 2). */
static const qd_expr *jet(qd_ctx *ctx, const qd__field *f, int which) {
    char name[3 * QD_MDL_NAME_MAX + 8];
    if (which == 0)
        snprintf(name, sizeof name, "%s_tt", f->name);
    else if (which == 1)
        snprintf(name, sizeof name, "%s_%st", f->name, f->space);
    else
        snprintf(name, sizeof name, "%s_%s%s", f->name, f->space, f->space);
    return qd_symbol(ctx, name);
}

/* d/dt or d/dx (along = 't' or 'x') of g(x, t, y, y_t, y_x). */
static const qd_expr *total(qd_ctx *ctx, const qd__field *f, const qd_expr *g, char along) {
    const qd_expr *ytt = jet(ctx, f, 0), *yxt = jet(ctx, f, 1), *yxx = jet(ctx, f, 2);
    bool t = along == 't';
    const qd_expr *terms[4] = {
        qd_diff(ctx, g, t ? qd_time(ctx) : f->x),
        qd_mul(ctx, qd_diff(ctx, g, f->y), t ? f->yt : f->yx),
        qd_mul(ctx, qd_diff(ctx, g, f->yt), t ? ytt : yxt),
        qd_mul(ctx, qd_diff(ctx, g, f->yx), t ? yxt : yxx),
    };
    return qd_add_n(ctx, 4, terms);
}

const qd_expr *qd_field_equation(qd_ctx *ctx, const qd_field *fld) {
    QD_ARGS(NULL, ctx && fld);
    const qd__field *f = qd__mdl_field_data(fld);
    const qd_expr *L = f->density;
    const qd_expr *e = qd_add(ctx, total(ctx, f, qd_diff(ctx, L, f->yt), 't'),
                              total(ctx, f, qd_diff(ctx, L, f->yx), 'x'));
    e = qd_sub(ctx, e, qd_diff(ctx, L, f->y));
    return e ? qd_expand(ctx, e) : NULL;
}

/* ---- the coefficients ---------------------------------------------------- */

static const qd_expr *d2(qd_ctx *ctx, const qd_expr *L, const qd_expr *a, const qd_expr *b) {
    return qd_simplify(ctx, qd_expand(ctx, qd_diff(ctx, qd_diff(ctx, L, a), b)));
}

/* rho, tau, kappa from L = rho/2 y_t^2 - tau/2 y_x^2 - kappa/2 y^2 + (linear). */
static qd_status coefficients(qd_ctx *ctx, const qd__field *f, qd_field_modes *r) {
    const qd_expr *L = f->density_num;
    r->rho = d2(ctx, L, f->yt, f->yt);
    r->tau = qd_neg(ctx, d2(ctx, L, f->yx, f->yx));
    r->kappa = qd_neg(ctx, d2(ctx, L, f->y, f->y));
    const qd_expr *cross[3] = {d2(ctx, L, f->yt, f->yx), d2(ctx, L, f->y, f->yt),
                               d2(ctx, L, f->y, f->yx)};
    if (!r->rho || !r->tau || !r->kappa || !cross[0] || !cross[1] || !cross[2])
        return qd_ctx_status(ctx) ? qd_ctx_status(ctx) : QD_ERR_NOMEM;
    r->tau = qd_simplify(ctx, r->tau);
    r->kappa = qd_simplify(ctx, r->kappa);
    const qd_expr *all[6] = {r->rho, r->tau, r->kappa, cross[0], cross[1], cross[2]};
    const qd_expr *vars[4] = {f->y, f->yt, f->yx, qd_time(ctx)};
    for (size_t i = 0; i < 6; i++)
        for (size_t v = 0; v < 4; v++)
            if (qd_has(all[i], vars[v])) {
                qd_ctx_error(ctx, QD_ERR_ARG,
                             "the density is not quadratic in %s, %s_t, %s_x with coefficients "
                             "in %s: its modes are not those of a linear field",
                             f->name, f->name, f->name, f->space);
                return QD_ERR_ARG;
            }
    for (size_t i = 3; i < 6; i++)
        if (!qd_is_zero(all[i])) {
            qd_ctx_error(ctx, QD_ERR_ARG,
                         "the density has a product of two of %s, %s_t, %s_x: only "
                         "rho/2*%s_t^2 - tau/2*%s_x^2 - kappa/2*%s^2 is handled",
                         f->name, f->name, f->name, f->name, f->name, f->name);
            return QD_ERR_ARG;
        }
    return QD_OK;
}

/* ---- constant coefficients: closed form ---------------------------------- */

static qd_status exact(qd_ctx *ctx, const qd__field *f, qd_field_modes *r) {
    double rho = qd_number_value(r->rho), tau = qd_number_value(r->tau);
    double kappa = qd_number_value(r->kappa);
    if (!(rho > 0) || !(tau > 0)) {
        qd_ctx_error(ctx, QD_ERR_ARG, "the density needs rho > 0 and tau > 0 (rho = %g, tau = %g)",
                     rho, tau);
        return QD_ERR_ARG;
    }
    double l = qd_number_value(f->ends[1]) - qd_number_value(f->ends[0]);
    bool free0 = f->bc[0] == QD_FIELD_FREE, free1 = f->bc[1] == QD_FIELD_FREE;
    for (size_t i = 0; i < r->n; i++) {
        qd_field_mode *md = &r->mode[i];
        double n = (double)i + 1;
        if (free0 == free1) /* n pi / l: from n = 1 fixed-fixed, n = 0 free-free */
            md->k = (free0 ? n - 1 : n) * M_PI / l;
        else
            md->k = (n - 0.5) * M_PI / l;
        md->shape = free0 ? QD_FIELD_SHAPE_COS : QD_FIELD_SHAPE_SIN;
        md->omega2 = (tau * md->k * md->k + kappa) / rho;
        md->omega = md->omega2 >= 0 ? sqrt(md->omega2) : NAN;
        md->error = 0;
    }
    r->exact = r->converged = true;
    return QD_OK;
}

/* ---- variable coefficients: finite elements ------------------------------ */

static qd_status coef_at(qd_ctx *ctx, const qd__field *f, const qd_expr *c, double x, double *v) {
    qd_status st = qd_eval(ctx, c, 1, &f->x, &x, v);
    if (st == QD_OK && !isfinite(*v)) {
        qd_ctx_error(ctx, QD_ERR_NUMERIC, "a coefficient of the density is not finite at %s = %g",
                     f->space, x);
        return QD_ERR_NUMERIC;
    }
    return st;
}

/* The lowest nw eigenvalues of K Y = lam M Y on ne elements. */
static qd_status fe_level(qd_ctx *ctx, const qd__field *f, const qd_field_modes *r, size_t ne,
                          size_t nw, double *lam, double *lam_max) {
    static const double gs[3] = {-0.7745966692414834, 0, 0.7745966692414834};
    static const double gw[3] = {5.0 / 9, 8.0 / 9, 5.0 / 9};
    double a = qd_number_value(f->ends[0]), h = (qd_number_value(f->ends[1]) - a) / (double)ne;
    size_t nn = ne + 1;
    double *buf = qd__calloc(ctx, 9 * nn + 4, sizeof *buf);
    if (!buf)
        return QD_ERR_NOMEM;
    double *kd = buf, *ko = buf + nn, *md = buf + 2 * nn, *mo = buf + 3 * nn;
    qd_status st = QD_OK;
    for (size_t e = 0; e < ne && st == QD_OK; e++)
        for (int g = 0; g < 3 && st == QD_OK; g++) {
            double s = gs[g], x = a + h * ((double)e + (1 + s) / 2), w = gw[g] * h / 2;
            double rho, tau, kap;
            if ((st = coef_at(ctx, f, r->rho, x, &rho)) || (st = coef_at(ctx, f, r->tau, x, &tau)) ||
                (st = coef_at(ctx, f, r->kappa, x, &kap)))
                break;
            if (!(rho > 0) || tau < 0) {
                qd_ctx_error(ctx, QD_ERR_ARG,
                             "the density needs rho > 0 and tau >= 0: rho = %g, tau = %g at %s = %g",
                             rho, tau, f->space, x);
                st = QD_ERR_ARG;
                break;
            }
            double p0 = (1 - s) / 2, p1 = (1 + s) / 2, d = 1 / (h * h);
            kd[e] += w * (tau * d + kap * p0 * p0);
            kd[e + 1] += w * (tau * d + kap * p1 * p1);
            ko[e] += w * (-tau * d + kap * p0 * p1);
            md[e] += w * rho * p0 * p0;
            md[e + 1] += w * rho * p1 * p1;
            mo[e] += w * rho * p0 * p1;
        }
    size_t i0 = f->bc[0] == QD_FIELD_FIXED, i1 = nn - (f->bc[1] == QD_FIELD_FIXED);
    int n = (int)(i1 - i0), ka = 1, ld = 2, info = 0;
    double *ab = buf + 4 * nn, *bb = ab + 2 * (size_t)n, *w = bb + 2 * (size_t)n;
    double *work = qd__calloc(ctx, 3 * (size_t)n + 1, sizeof *work);
    if (st == QD_OK && !work)
        st = QD_ERR_NOMEM;
    if (st == QD_OK) {
        *lam_max = 0; /* about the largest eigenvalue: 4 max K_ii/M_ii (12/h^2 c^2 uniform) */
        for (size_t g = 0; g < nn; g++)
            *lam_max = fmax(*lam_max, 4 * fabs(kd[g]) / md[g]);
        for (int j = 0; j < n; j++) {
            size_t g = i0 + (size_t)j;
            ab[2 * j + 1] = kd[g];
            bb[2 * j + 1] = md[g];
            ab[2 * j] = j ? ko[g - 1] : 0;
            bb[2 * j] = j ? mo[g - 1] : 0;
        }
        dsbgv_("N", "U", &n, &ka, &ka, ab, &ld, bb, &ld, w, NULL, &ld, work, &info);
        if (info != 0) {
            qd_ctx_error(ctx, QD_ERR_NUMERIC, "the discretized modes: LAPACK dsbgv failed (%d)", info);
            st = QD_ERR_NUMERIC;
        } else
            memcpy(lam, w, nw * sizeof *lam);
    }
    qd__free(work);
    qd__free(buf);
    return st;
}

static double root(double lam) { return lam >= 0 ? sqrt(lam) : -sqrt(-lam); }

/* The worst error estimate relative to its omega (modes near 0 against the
 * largest one). */
static double worst(const qd_field_modes *r) {
    double scale = fabs(r->mode[r->n - 1].omega), q = 0;
    for (size_t i = 0; i < r->n; i++) {
        const qd_field_mode *md = &r->mode[i];
        q = fmax(q, md->error / fmax(fabs(md->omega), 1e-6 * scale));
    }
    return isnan(q) ? INFINITY : q;
}

/* N, 2N, 4N, ... elements until the estimates are below tol; when refining
 * makes them worse (rounding has taken over), the best level is kept. */
static qd_status discretized(qd_ctx *ctx, const qd__field *f, const qd_field_modes_opts *o,
                             qd_field_modes *r) {
    size_t nw = r->n, ne = 8 * nw > 32 ? 8 * nw : 32;
    double *lam = qd__calloc(ctx, 4 * nw, sizeof *lam);
    qd_field_mode *best = qd__calloc(ctx, nw, sizeof *best);
    if (!lam || !best) {
        qd__free(lam);
        qd__free(best);
        return QD_ERR_NOMEM;
    }
    double *prev = lam + nw, *cur = lam + 2 * nw, *rprev = lam + 3 * nw;
    double best_q = INFINITY;
    size_t best_ne = 0;
    qd_status st = QD_OK;
    for (int level = 0; st == QD_OK && ne <= o->max_elements; level++, ne *= 2) {
        double lam_max;
        if ((st = fe_level(ctx, f, r, ne, nw, cur, &lam_max)) != QD_OK)
            break;
        /* rounding: dsbgv's eigenvalues are good to about eps ||K|| ~ eps lam_max,
         * which grows as 1/h^2 while the truncation falls as h^4 */
        double dlam = DBL_EPSILON * lam_max;
        for (size_t i = 0; i < nw; i++) {
            double rich = level ? (4 * cur[i] - prev[i]) / 3 : cur[i];
            qd_field_mode *md = &r->mode[i];
            md->omega2 = rich;
            md->omega = rich >= 0 ? sqrt(rich) : NAN;
            double w = fabs(root(rich));
            double round = w > 0 ? fmin(dlam / (2 * w), sqrt(dlam)) : sqrt(dlam);
            md->error = level >= 2 ? fabs(root(rich) - root(rprev[i])) + round : INFINITY;
            md->shape = QD_FIELD_SHAPE_NONE;
            rprev[i] = rich;
            prev[i] = cur[i];
        }
        if (level < 2)
            continue;
        double q = worst(r);
        if (q < best_q) {
            best_q = q;
            best_ne = ne;
            memcpy(best, r->mode, nw * sizeof *best);
        }
        if (q <= o->tol || q > 4 * best_q)
            break;
    }
    if (st == QD_OK && best_ne) {
        memcpy(r->mode, best, nw * sizeof *best);
        r->elements = best_ne;
        r->converged = best_q <= o->tol;
    } else if (st == QD_OK) {
        qd_ctx_error(ctx, QD_ERR_ARG, "the largest mesh allowed (%zu elements) is too small for "
                     "an error estimate", o->max_elements);
        st = QD_ERR_ARG;
    }
    qd__free(best);
    qd__free(lam);
    return st;
}

qd_status qd_field_modes_compute(qd_ctx *ctx, const qd_field *fld, const qd_field_modes_opts *opts,
                                 qd_field_modes *out) {
    QD_ARGS_CTX(ctx, ctx && fld && out);
    memset(out, 0, sizeof *out);
    qd_field_modes_opts o = opts ? *opts : (qd_field_modes_opts){0};
    if (!o.count)
        o.count = 5;
    if (!(o.tol > 0))
        o.tol = 1e-6;
    if (!o.max_elements)
        o.max_elements = 16384;
    if (o.count > 1000) {
        qd_ctx_error(ctx, QD_ERR_ARG, "at most 1000 modes, not %zu", o.count);
        return QD_ERR_ARG;
    }
    const qd__field *f = qd__mdl_field_data(fld);
    qd_status st = coefficients(ctx, f, out);
    if (st != QD_OK)
        return st;
    out->tol = o.tol;
    out->mode = qd__calloc(ctx, o.count, sizeof *out->mode);
    if (!out->mode)
        return QD_ERR_NOMEM;
    out->n = o.count;
    bool constant = qd_is_number(out->rho) && qd_is_number(out->tau) && qd_is_number(out->kappa);
    st = constant ? exact(ctx, f, out) : discretized(ctx, f, &o, out);
    if (st != QD_OK)
        qd_field_modes_free(out);
    return st;
}

void qd_field_modes_free(qd_field_modes *r) {
    if (!r)
        return;
    qd__free(r->mode);
    r->mode = NULL;
    r->n = 0;
}

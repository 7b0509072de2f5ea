/*
 * src/model/audit.c - the numbers of a model that its text does not show
 * wrong: a mass matrix that is not positive definite at the parameters'
 * values (m = 0, a negative inertia), a constraint with no real solution
 * (x^2 + y^2 = -1), an initial state off the constraints.  See qd_eom_audit
 * in qdot/mech.h.
 */
#include "base/args.h"
#include "qdot/mech.h"
#include "qdot/model.h"
#include "base/mem.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

typedef struct point {
    size_t nsym;
    const qd_expr **sym; /* coordinates, parameters, t */
    double *val;
} point;

static qd_status eval(qd_ctx *ctx, const point *pt, const qd_expr *e, double *x) {
    qd_status st = qd_eval(ctx, e, pt->nsym, pt->sym, pt->val, x);
    if (st == QD_OK && !isfinite(*x))
        *x = NAN;
    if (st != QD_OK && st != QD_ERR_NOMEM) {
        qd_ctx_clear_error(ctx);
        *x = NAN; /* outside the domain here: not a verdict */
        st = QD_OK;
    }
    return st;
}

/* Cholesky of M at pt: the first pivot <= 0 (index, value), or n. */
static qd_status pivot(qd_ctx *ctx, const qd_eom *e, const point *pt, double *a, size_t *k,
                       double *value) {
    size_t n = e->n;
    for (size_t i = 0; i < n * n; i++) {
        qd_status st = eval(ctx, pt, e->M[i], &a[i]);
        if (st != QD_OK)
            return st;
    }
    *k = n;
    for (size_t j = 0; j < n; j++) {
        double d = a[j * n + j];
        for (size_t p = 0; p < j; p++)
            d -= a[j * n + p] * a[j * n + p];
        if (!(d > 1e-300) || isnan(d)) {
            if (isnan(d))
                return QD_OK; /* not evaluable here: no verdict */
            *k = j;
            *value = d;
            return QD_OK;
        }
        double r = sqrt(d);
        a[j * n + j] = r;
        for (size_t i = j + 1; i < n; i++) {
            double s = a[i * n + j];
            for (size_t p = 0; p < j; p++)
                s -= a[i * n + p] * a[j * n + p];
            a[i * n + j] = s / r;
        }
    }
    return QD_OK;
}

qd_status qd_eom_audit(qd_ctx *ctx, const qd_model *m, const qd_eom *e, qd_audit *out) {
    QD_ARGS_CTX(ctx, ctx && m && e && out);
    memset(out, 0, sizeof *out);
    out->mass_ok = out->con_ok = true;
    size_t nq = qd_model_ncoords(m), np = qd_model_nparams(m), n = e->n;
    point pt = {nq + np + 1, NULL, NULL};
    pt.sym = qd__malloc(ctx, pt.nsym * sizeof *pt.sym);
    pt.val = qd__malloc(ctx, pt.nsym * sizeof *pt.val);
    double *a = qd__malloc(ctx, (n * n + 2 * nq + 1) * sizeof *a);
    qd_status st = pt.sym && pt.val && a ? QD_OK : QD_ERR_NOMEM;
    for (size_t i = 0; st == QD_OK && i < np; i++) {
        pt.sym[nq + i] = qd_model_param(m, i);
        if (qd_model_param_number(m, i, &pt.val[nq + i]) != QD_OK)
            st = QD_ERR_UNBOUND;
    }
    if (st == QD_OK) {
        for (size_t j = 0; j < nq; j++)
            pt.sym[j] = qd_model_coord(m, j);
        pt.sym[nq + np] = qd_time(ctx);
        pt.val[nq + np] = 0;
    }
    /* the mass matrix at two generic configurations: both must fail */
    size_t k[2] = {n, n};
    double v[2] = {0, 0};
    for (int g = 0; st == QD_OK && g < 2 && n && n == nq; g++) {
        for (size_t j = 0; j < nq; j++) {
            const qd_expr *q0 = qd_model_initial(m, j, 0);
            double x = 0.5 + 0.1 * (double)j;
            if (q0 && qd_eval(ctx, q0, 0, NULL, NULL, &x) != QD_OK) {
                qd_ctx_clear_error(ctx);
                x = 0.5 + 0.1 * (double)j;
            }
            pt.val[j] = g ? x + 0.25 + 0.1 * (double)j : x;
        }
        st = pivot(ctx, e, &pt, a, &k[g], &v[g]);
    }
    if (st == QD_OK && k[0] < n && k[1] < n) {
        out->mass_ok = false;
        out->mass_coord = k[0];
        out->mass_pivot = v[0];
    }
    /* the holonomic constraints from the initial state */
    for (size_t c = 0; st == QD_OK && c < e->ncon; c++) {
        const qd_con *con = &e->con[c];
        if (con->kind != QD_CON_HOLONOMIC || n != nq)
            continue;
        for (size_t j = 0; j < nq; j++) {
            const qd_expr *q0 = qd_model_initial(m, j, 0);
            double x = 0;
            if (q0 && qd_eval(ctx, q0, 0, NULL, NULL, &x) != QD_OK) {
                qd_ctx_clear_error(ctx);
                x = 0;
            }
            pt.val[j] = x;
        }
        double phi;
        if ((st = eval(ctx, &pt, con->expr, &phi)) != QD_OK)
            break;
        if (isfinite(phi) && fabs(phi) > out->residual) {
            out->residual = fabs(phi);
            out->residual_con = c;
        }
        /* Gauss-Newton on this constraint alone: q -= phi grad / |grad|^2 */
        double best = fabs(phi);
        for (int it = 0; st == QD_OK && it < 60 && isfinite(phi) && fabs(phi) > 1e-9; it++) {
            double g2 = 0;
            for (size_t j = 0; st == QD_OK && j < nq; j++) {
                const qd_expr *d = qd_diff(ctx, con->expr, pt.sym[j]);
                if (!d) {
                    st = qd_ctx_status(ctx);
                    break;
                }
                st = eval(ctx, &pt, d, &a[j]);
                g2 += isfinite(a[j]) ? a[j] * a[j] : 0;
            }
            if (st != QD_OK || !(g2 > 1e-300))
                break; /* a stationary point of phi with phi != 0 */
            double step = phi / g2;
            /* halve the step until |phi| decreases */
            double trial = phi;
            for (int h = 0; h < 30; h++) {
                for (size_t j = 0; j < nq; j++)
                    a[nq + j] = pt.val[j], pt.val[j] -= step * a[j];
                if ((st = eval(ctx, &pt, con->expr, &trial)) != QD_OK)
                    break;
                if (isfinite(trial) && fabs(trial) < fabs(phi))
                    break;
                for (size_t j = 0; j < nq; j++)
                    pt.val[j] = a[nq + j];
                step /= 2;
                trial = phi;
            }
            if (!(fabs(trial) < fabs(phi)))
                break;
            phi = trial;
            best = fmin(best, fabs(phi));
        }
        if (st == QD_OK && isfinite(best) && best > 1e-6 && out->con_ok) {
            out->con_ok = false;
            out->con = c;
            out->con_min = best;
        }
    }
    qd__free(pt.sym);
    qd__free(pt.val);
    qd__free(a);
    if (st == QD_ERR_NOMEM)
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory");
    return st;
}

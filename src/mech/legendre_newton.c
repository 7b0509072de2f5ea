/*
 * src/mech/legendre_newton.c - the numeric Legendre transform: q' from
 * p = dL/dq'(q, q', t) by Newton's method at one point (Desloge Appendix 22;
 * seed-desloge-D.md C2: "otherwise numerically with Newton's method at each
 * evaluation point").
 *
 * The Jacobian is the Hessian d^2L/dq'dq', differentiated symbolically once
 * per call; n is the number of coordinates, a handful, so the n x n solve is
 * plain elimination with partial pivoting.
 */
#include "legendre.h"
#include "../base/mem.h"
#include "../base/args.h"

#include <math.h>
#include <string.h>

#define NEWTON_MAX 60
#define NEWTON_TOL 1e-14

typedef struct newton {
    size_t n, nsyms;
    const qd_expr **syms; /* the caller's symbols, then the velocities */
    double *vals;
    const qd_expr **jac;  /* d pdef_i / d q'_k */
    double *r, *J, *dx;
} newton;

/* J dx = r in place (partial pivoting); false when J is singular. */
static bool dense_solve(size_t n, double *J, double *r, double *dx) {
    for (size_t k = 0; k < n; k++) {
        size_t piv = k;
        for (size_t i = k + 1; i < n; i++)
            if (fabs(J[i * n + k]) > fabs(J[piv * n + k]))
                piv = i;
        if (!(fabs(J[piv * n + k]) > 0))
            return false;
        for (size_t c = 0; piv != k && c < n; c++) {
            double t = J[k * n + c];
            J[k * n + c] = J[piv * n + c];
            J[piv * n + c] = t;
        }
        double t = r[k];
        r[k] = r[piv];
        r[piv] = t;
        for (size_t i = k + 1; i < n; i++) {
            double f = J[i * n + k] / J[k * n + k];
            for (size_t c = k; c < n; c++)
                J[i * n + c] -= f * J[k * n + c];
            r[i] -= f * r[k];
        }
    }
    for (size_t k = n; k-- > 0;) {
        double s = r[k];
        for (size_t c = k + 1; c < n; c++)
            s -= J[k * n + c] * dx[c];
        dx[k] = s / J[k * n + k];
    }
    return true;
}

static qd_status eval(qd_ctx *ctx, const newton *w, const qd_expr *x, double *out) {
    qd_status st = qd_eval(ctx, x, w->nsyms, w->syms, w->vals, out);
    if (st == QD_OK && !isfinite(*out))
        st = QD_ERR_NUMERIC;
    return st;
}

/* r = p - dL/dq' and J = d^2L/dq'dq' at the current velocities. */
static qd_status residual(qd_ctx *ctx, const qd_ham *h, const double *p, newton *w, double *norm) {
    size_t n = w->n;
    qd_status st = QD_OK;
    *norm = 0;
    for (size_t i = 0; st == QD_OK && i < n; i++) {
        double v = 0;
        st = eval(ctx, w, h->pdef[i], &v);
        w->r[i] = p[i] - v;
        *norm += fabs(w->r[i]) / (1 + fabs(p[i]));
        for (size_t k = 0; st == QD_OK && k < n; k++)
            st = eval(ctx, w, w->jac[i * n + k], &w->J[i * n + k]);
    }
    return st;
}

/* A step that leaves L's domain (|v| > c) is halved until it stays in. */
static qd_status step(qd_ctx *ctx, const qd_ham *h, const double *p, newton *w, double *norm) {
    size_t n = w->n, base = w->nsyms - n;
    double scale = 1;
    for (int k = 0; k < 40; k++, scale /= 2) {
        for (size_t i = 0; i < n; i++)
            w->vals[base + i] += scale * w->dx[i];
        qd_status st = residual(ctx, h, p, w, norm);
        if (st == QD_OK || st == QD_ERR_NOMEM)
            return st;
        if (!qd__ctx_recover(ctx))
            return QD_ERR_NOMEM;
        for (size_t i = 0; i < n; i++)
            w->vals[base + i] -= scale * w->dx[i];
    }
    return QD_ERR_NUMERIC;
}

/* The last step was tiny next to the velocities: near a point where the
 * Hessian is small (y'^4/4 at small y') a small residual alone is not yet
 * an accurate q'. */
static bool settled(const newton *w) {
    size_t base = w->nsyms - w->n;
    for (size_t i = 0; i < w->n; i++)
        if (!(fabs(w->dx[i]) <= 1e-13 * fabs(w->vals[base + i]) + 1e-300))
            return false;
    return true;
}

static qd_status iterate(qd_ctx *ctx, const qd_ham *h, const double *p, newton *w) {
    double norm = 0;
    int nudges = 0;
    bool moved = false;
    qd_status st = residual(ctx, h, p, w, &norm);
    for (int it = 0; st == QD_OK && it < NEWTON_MAX; it++) {
        if (norm == 0 || (norm < NEWTON_TOL * (double)w->n && moved && settled(w)))
            return QD_OK;
        if (!dense_solve(w->n, w->J, w->r, w->dx)) {
            /* a Hessian singular only at a point (y'^4: at y' = 0) is
             * stepped off; a few tries, then it is singular for real */
            if (++nudges > 3)
                return QD_ERR_SINGULAR;
            for (size_t i = 0; i < w->n; i++)
                w->vals[w->nsyms - w->n + i] += 0.1 * nudges;
            st = residual(ctx, h, p, w, &norm);
            moved = false;
            continue;
        }
        st = step(ctx, h, p, w, &norm);
        moved = true;
    }
    /* round-off can keep the residual just above the goal: accept near misses */
    if (st == QD_OK && norm < 1e3 * NEWTON_TOL * (double)w->n)
        return QD_OK;
    return st == QD_OK ? QD_ERR_NUMERIC : st;
}

static qd_status newton_init(qd_ctx *ctx, const qd_ham *h, size_t nsyms,
                             const qd_expr *const *syms, const double *vals, newton *w) {
    size_t n = h->n;
    w->n = n;
    w->nsyms = nsyms + n;
    w->syms = qd__calloc(ctx, w->nsyms, sizeof *w->syms);
    w->jac = qd__calloc(ctx, n * n + 1, sizeof *w->jac);
    w->vals = qd__calloc(ctx, w->nsyms, sizeof *w->vals);
    w->r = qd__calloc(ctx, 2 * n + n * n + 1, sizeof *w->r);
    if (!w->syms || !w->jac || !w->vals || !w->r)
        return QD_ERR_NOMEM;
    w->J = w->r + n;
    w->dx = w->J + n * n;
    /* the velocities last, so they shadow any value the caller gave them */
    memcpy(w->syms, syms, nsyms * sizeof *syms);
    memcpy(w->vals, vals, nsyms * sizeof *vals);
    for (size_t i = 0; i < n; i++) {
        w->syms[nsyms + i] = h->qd[i];
        for (size_t k = 0; k < n; k++)
            if (!(w->jac[i * n + k] = qd_diff(ctx, h->pdef[i], h->qd[k])))
                return qd_ctx_status(ctx);
    }
    return QD_OK;
}

static void newton_free(newton *w) {
    qd__free(w->syms);
    qd__free(w->jac);
    qd__free(w->vals);
    qd__free(w->r);
}

/* A value the caller gave a velocity is the first guess; 0 otherwise. */
static void first_guess(const qd_ham *h, size_t nsyms, const qd_expr *const *syms,
                        const double *vals, newton *w) {
    for (size_t k = 0; k < h->n; k++)
        for (size_t i = 0; i < nsyms; i++)
            if (syms[i] == h->qd[k])
                w->vals[nsyms + k] = vals[i];
}

qd_status qd_ham_velocities_at(qd_ctx *ctx, const qd_ham *h, size_t nsyms,
                               const qd_expr *const *syms, const double *vals, double *qd_out) {
    QD_ARGS_CTX(ctx, ctx && h && (nsyms == 0 || syms) && (nsyms == 0 || vals) && qd_out);
    if (!ctx || !h || !qd_out || (nsyms && (!syms || !vals)))
        return QD_ERR_ARG;
    newton w = {0};
    double *p = qd__calloc(ctx, h->n + 1, sizeof *p);
    qd_status st = p ? newton_init(ctx, h, nsyms, syms, vals, &w) : QD_ERR_NOMEM;
    for (size_t j = 0; st == QD_OK && j < h->n; j++)
        st = qd_eval(ctx, h->p[j], w.nsyms - h->n, w.syms, w.vals, &p[j]);
    if (st == QD_OK) {
        first_guess(h, nsyms, syms, vals, &w);
        st = iterate(ctx, h, p, &w);
    }
    for (size_t k = 0; st == QD_OK && k < h->n; k++)
        qd_out[k] = w.vals[w.nsyms - h->n + k];
    if (st != QD_OK && qd_ctx_status(ctx) == QD_OK)
        qd_ctx_error(ctx, st, "Newton's method on p = dL/dq' did not converge here (%s)",
                     st == QD_ERR_SINGULAR ? "the Hessian d^2L/dq'dq' is singular"
                     : st == QD_ERR_NOMEM ? "out of memory"
                                          : "no root within 60 steps, or L undefined on the way");
    newton_free(&w);
    qd__free(p);
    return st;
}

qd_status qd_ham_require_closed(qd_ctx *ctx, const qd_ham *h, const char *what) {
    QD_ARGS_CTX(ctx, ctx && h && what);
    if (!h->implicit)
        return QD_OK;
    qd_ctx_error(ctx, QD_ERR_NONLINEAR, "%s needs H in closed form, but L is not quadratic in "
                 "the velocities and p = dL/dq' has no closed-form solution for q' here (H is "
                 "defined implicitly: it can be evaluated at a state, numerically)", what);
    return QD_ERR_NONLINEAR;
}

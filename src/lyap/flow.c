/*
 * src/lyap/flow.c - the flow Jacobian d y(t)/d y(t0), its symplecticity in
 * canonical coordinates, and the Floquet multipliers (qdot/lyapunov.h).
 *
 * The state and 2n tangent vectors started at the identity are integrated
 * by the simulation's Runge-Kutta pairs through the tangent system of
 * variational.c (the qd_sim's ext_rhs), step control over all components,
 * and never renormalized: the vectors are the columns of Phi.  The run's
 * z component (the integral of tr J) gives Liouville's det Phi =
 * exp(z) as an independent check of the computed determinant.
 * Britannica 1911 "Dynamics" sec. 9 (seed 004): Lagrange's bilinear
 * invariant d/dt sum (dp Dq - Dp dq) = 0 is Phi_c^T J Phi_c = J.
 */
#include "lyap.h"

#include <math.h>
#include <string.h>

#include "base/args.h"
#include "base/mem.h"

extern void dgetrf_(const int *m, const int *n, double *a, const int *lda, int *ipiv, int *info);
extern void dgetrs_(const char *trans, const int *n, const int *nrhs, const double *a,
                    const int *lda, const int *ipiv, double *b, const int *ldb, int *info);
extern void dgeev_(const char *jobvl, const char *jobvr, const int *n, double *a, const int *lda,
                   double *wr, double *wi, double *vl, const int *ldvl, double *vr,
                   const int *ldvr, double *work, const int *lwork, int *info);

typedef struct flow_run {
    qd__lyap_tangent t;     /* the state and d tangent vectors (tangent.c) */
    const qd_sim_opts *o;
    const qd_flow_opts *fo;
    size_t d;
    double *phi;           /* d*d row-major scratch for the sink */
} flow_run;

void qd_flow_free(qd_flow *f) {
    if (!f)
        return;
    qd__free(f->y);
    f->y = f->phi = f->phi_c = f->mult_re = f->mult_im = NULL;
}

/* Phi row-major from the tangent vectors (column j at y + d + d j). */
static void read_phi(const flow_run *r, double *phi) {
    const double *W = r->t.it.y + r->d;
    for (size_t i = 0; i < r->d; i++)
        for (size_t j = 0; j < r->d; j++)
            phi[i * r->d + j] = W[j * r->d + i];
}

static qd_status advance(flow_run *r, double tb) { return qd__lyap_tangent_advance(&r->t, tb); }

static qd_status integrate(flow_run *r) {
    const qd_sim_opts *o = r->o;
    double every = r->fo && r->fo->every > 0 ? r->fo->every : o->t_end - o->t0;
    for (size_t i = 1; r->t.it.t < o->t_end; i++) {
        double tb = fmin(o->t0 + (double)i * every, o->t_end);
        qd_status st = advance(r, tb);
        if (st != QD_OK)
            return st;
        if (r->fo && r->fo->sink) {
            read_phi(r, r->phi);
            if (r->fo->sink(r->fo->data, r->t.it.t, r->t.it.y, r->phi)) {
                qd_ctx_error(r->t.ws.w.ctx, QD_ERR_ARG, "stopped");
                return QD_ERR_ARG;
            }
        }
    }
    return QD_OK;
}

/* det of the d*d row-major a (destroyed) by LU. */
static double det_lu(double *a, int d, int *ipiv) {
    int info = 0;
    dgetrf_(&d, &d, a, &d, ipiv, &info);
    if (info < 0)
        return NAN;
    double det = 1;
    for (int i = 0; i < d; i++)
        det *= a[i * d + i] * (ipiv[i] != i + 1 ? -1 : 1);
    return det;
}

/* Lambda = d(q, p)/d(q, q') at (t, y) into lam (d*d row-major). */
static void legendre_jacobian(flow_run *r, const qd_prog *P, double *pw, double *pout,
                              double t, const double *y, double *lam) {
    size_t n = r->d / 2, d = r->d;
    qd_sim *s = &r->t.ws.w;
    memcpy(s->in, y, d * sizeof *y);
    s->in[d] = t;
    qd_prog_eval(P, pw, s->in, pout);
    memset(lam, 0, d * d * sizeof *lam);
    for (size_t i = 0; i < n; i++) {
        lam[i * d + i] = 1;
        for (size_t k = 0; k < d; k++)
            lam[(n + i) * d + k] = pout[i * d + k];
    }
}

/* Phi_c = Lambda(end) Phi Lambda(0)^-1 and max |Phi_c^T J Phi_c - J|. */
static qd_status canonical(flow_run *r, qd_ctx *ctx, const double *y0, qd_flow *f) {
    size_t n = r->d / 2, d = r->d;
    const qd_eom *e = r->t.ws.l->sim->e;
    const qd_expr **outs = qd__malloc(ctx, (n * d + 1) * sizeof *outs);
    if (!outs)
        return QD_ERR_NOMEM;
    for (size_t i = 0; i < n; i++) {
        const qd_expr *p = qd_diff(ctx, e->L, e->qd[i]);
        for (size_t k = 0; k < d; k++)
            outs[i * d + k] = qd_diff(ctx, p, k < n ? e->q[k] : e->qd[k - n]);
    }
    qd_prog *P = qd_ctx_status(ctx) == QD_OK
                     ? qd_prog_new(ctx, r->t.ws.w.nin, r->t.ws.w.in_syms, n * d, outs) : NULL;
    qd__free(outs);
    if (!P)
        return qd_ctx_status(ctx) != QD_OK ? qd_ctx_status(ctx) : QD_ERR_NOMEM;
    double *pw = qd__malloc(ctx, (qd_prog_work_size(P) + n * d + 3 * d * d + 1) * sizeof *pw);
    int *ipiv = qd__malloc(ctx, (d + 1) * sizeof *ipiv);
    qd_status st = pw && ipiv ? QD_OK : QD_ERR_NOMEM;
    if (st == QD_OK) {
        qd_prog_work_init(P, pw);
        double *pout = pw + qd_prog_work_size(P), *l0 = pout + n * d, *l1 = l0 + d * d,
               *A = l1 + d * d;
        legendre_jacobian(r, P, pw, pout, r->o->t0, y0, l0);
        legendre_jacobian(r, P, pw, pout, r->t.it.t, f->y, l1);
        for (size_t i = 0; i < d; i++)           /* A = Lambda(end) Phi */
            for (size_t j = 0; j < d; j++) {
                double s = 0;
                for (size_t k = 0; k < d; k++)
                    s += l1[i * d + k] * f->phi[k * d + j];
                A[i * d + j] = s;
            }
        /* row-major l0 is Lambda0^T to LAPACK; Lambda0^T X = A^T gives X = Phi_c^T,
         * whose column-major storage is Phi_c row-major */
        int dd = (int)d, info = 0;
        dgetrf_(&dd, &dd, l0, &dd, ipiv, &info);
        if (info == 0)
            dgetrs_("N", &dd, &dd, l0, &dd, ipiv, A, &dd, &info);
        if (info != 0) {
            qd_ctx_error(ctx, QD_ERR_SINGULAR, "the Legendre map is singular at the start "
                         "(det d^2L/dq'dq' = 0): no canonical coordinates");
            st = QD_ERR_SINGULAR;
        } else {
            memcpy(f->phi_c, A, d * d * sizeof *A);
            double err = 0;
            for (size_t i = 0; i < d; i++)
                for (size_t j = 0; j < d; j++) {
                    double s = 0;  /* (Phi^T J Phi)_ij = sum_k Phi_ki (J Phi)_kj */
                    for (size_t k = 0; k < n; k++)
                        s += A[k * d + i] * A[(n + k) * d + j] - A[(n + k) * d + i] * A[k * d + j];
                    double Jij = (j == i + n) ? 1 : (i == j + n) ? -1 : 0;
                    err = fmax(err, fabs(s - Jij));
                }
            f->symplectic_error = err;
        }
    }
    qd__free(pw);
    qd__free(ipiv);
    qd_prog_free(P);
    return st;
}

static qd_status multipliers(qd_ctx *ctx, const qd_flow *f) {
    int d = (int)f->d, lwork = 8 * d + 16, info = 0, one = 1;
    double *a = qd__malloc(ctx, ((size_t)(d * d + lwork) + 1) * sizeof *a), dummy;
    if (!a)
        return QD_ERR_NOMEM;
    for (int i = 0; i < d; i++)   /* column-major */
        for (int j = 0; j < d; j++)
            a[j * d + i] = f->phi[i * d + j];
    dgeev_("N", "N", &d, a, &d, f->mult_re, f->mult_im, &dummy, &one, &dummy, &one, a + d * d,
           &lwork, &info);
    qd__free(a);
    if (info != 0) {
        qd_ctx_error(ctx, QD_ERR_NUMERIC, "the eigenvalues of the flow Jacobian did not "
                     "converge (LAPACK dgeev info %d)", info);
        return QD_ERR_NUMERIC;
    }
    return QD_OK;
}

static qd_status results(flow_run *r, qd_ctx *ctx, qd_flow *f) {
    size_t d = r->d;
    double y0[2 * 64], *y0p = d <= 128 ? y0 : qd__malloc(ctx, d * sizeof *y0p);
    if (!y0p)
        return QD_ERR_NOMEM;
    for (size_t i = 0; i < d / 2; i++) {
        y0p[i] = r->o->q0[i];
        y0p[d / 2 + i] = r->o->qd0[i];
    }
    memcpy(f->y, r->t.it.y, d * sizeof *f->y);
    read_phi(r, f->phi);
    f->closure = 0;
    for (size_t i = 0; i < d; i++)
        f->closure = fmax(f->closure, fabs(f->y[i] - y0p[i]));
    f->trace_integral = r->t.it.y[d + d * d];
    memcpy(r->phi, f->phi, d * d * sizeof *f->phi);
    int *ipiv = qd__malloc(ctx, (d + 1) * sizeof *ipiv);
    f->det = ipiv ? det_lu(r->phi, (int)d, ipiv) : NAN;
    qd__free(ipiv);
    qd_status st = ipiv ? multipliers(ctx, f) : QD_ERR_NOMEM;
    f->hamiltonian = qd_sim_conservative(r->t.ws.l->sim);
    if (st == QD_OK && f->hamiltonian)
        st = canonical(r, ctx, y0p, f);
    if (!f->hamiltonian)
        f->phi_c = NULL;
    if (y0p != y0)
        qd__free(y0p);
    return st;
}

static qd_status run(flow_run *r, qd_ctx *ctx, const qd_lyap *l, qd_flow *f) {
    size_t d = r->d;
    /* Phi's scratch after the state (r->phi) */
    qd_status st = qd__lyap_tangent_start(&r->t, ctx, l, r->o, d, d * d, "the flow Jacobian");
    /* the flow's arrays in one block: y, phi, phi_c, mult_re, mult_im */
    f->y = st == QD_OK ? qd__calloc(ctx, d + 2 * d * d + 2 * d, sizeof *f->y) : NULL;
    if (st != QD_OK || !f->y) {
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory starting the flow Jacobian");
        return st != QD_OK ? st : QD_ERR_NOMEM;
    }
    f->phi = f->y + d;
    f->phi_c = f->phi + d * d;
    f->mult_re = f->phi_c + d * d;
    f->mult_im = f->mult_re + d;
    r->phi = r->t.extra;
    st = integrate(r);
    if (st == QD_OK)
        st = results(r, ctx, f);
    return st;
}

qd_status qd_flow_run(qd_ctx *ctx, const qd_lyap *l, const qd_sim_opts *o,
                      const qd_flow_opts *fo, qd_flow *out) {
    QD_ARGS_CTX(ctx, ctx && l && o && out);
    *out = (qd_flow){.d = 2 * l->n, .symplectic_error = NAN, .det = NAN, .closure = NAN};
    qd_status st = qd__lyap_check_opts(ctx, o, "the flow Jacobian is");
    if (st != QD_OK)
        return st;
    flow_run r = {.o = o, .fo = fo, .d = 2 * l->n};
    st = run(&r, ctx, l, out);
    out->steps = r.t.it.steps;
    out->evals = r.t.ws.w.evals;
    out->rejected = r.t.it.rejected;
    if (st != QD_OK && qd_ctx_status(ctx) == QD_OK)
        qd_ctx_error(ctx, st, "the flow Jacobian run failed: %s", qd_status_str(st));
    qd__lyap_tangent_free(&r.t);
    return st;
}

/*
 * src/lyap/benettin.c - Lyapunov exponents by renormalization and QR.
 *
 * The state and k tangent vectors are integrated together by the
 * simulation's Runge-Kutta pairs (the qd_sim's ext_rhs hook).  Every
 * `renorm` time units the tangent vectors W (2n x k) are factored W = QR
 * (LAPACK dgeqrf, dorgqr) and replaced by Q: log |R_jj| is the growth of
 * the j-dimensional volume beyond the (j-1)-dimensional one, and its time
 * average is lambda_j (Benettin, Galgani, Giorgilli & Strelcyn, Meccanica
 * 15 (1980) 9 and 21; Skokos, Lect. Notes Phys. 790 (2010) 63, sec. 4).
 * For k = 1 this is Benettin's renormalization of one deviation vector
 * (Benettin, Galgani & Strelcyn, Phys. Rev. A 14 (1976) 2338).  QR rather
 * than classical Gram-Schmidt: Householder reflections keep Q orthogonal
 * to round-off even when the vectors have nearly collapsed onto the most
 * unstable direction.
 */
#include "lyap.h"

#include <math.h>
#include <string.h>

#include "base/mem.h"
#include "../base/args.h"

extern void dgeqrf_(const int *m, const int *n, double *a, const int *lda, double *tau,
                    double *work, const int *lwork, int *info);
extern void dorgqr_(const int *m, const int *n, const int *k, double *a, const int *lda,
                    const double *tau, double *work, const int *lwork, int *info);

/* A run: the integrator over the augmented state, the sums of log |R_jj|
 * and the running averages kept for the error estimate. */
typedef struct bench {
    qd__lyap_tangent r;     /* the state and k tangent vectors (tangent.c) */
    const qd_sim_opts *o;
    const qd_lyap_opts *lo; /* its progress hook */
    size_t k, d;
    double renorm, ta, T;   /* renormalization period; averaging from ta for T */
    double *sum;            /* k */
    double *hist;           /* running averages in the last half: nh rows of k */
    size_t nh, caph, renorms;
    double *tau, *work;
    int lwork;
} bench;

static qd_status check_opts(qd_ctx *ctx, const qd_lyap *l, const qd_sim_opts *o,
                            const qd_lyap_opts *lo) {
    qd_status st = qd__lyap_check_opts(ctx, o, "Lyapunov exponents are");
    if (st != QD_OK)
        return st;
    if (lo->nexp < 1 || lo->nexp > 2 * l->n) {
        qd_ctx_error(ctx, QD_ERR_ARG, "the number of exponents must be 1 to %zu (twice the "
                     "degrees of freedom), not %zu", 2 * l->n, lo->nexp);
        return QD_ERR_ARG;
    }
    if (!(lo->renorm >= 0) || !isfinite(lo->renorm)) {
        qd_ctx_error(ctx, QD_ERR_ARG, "the renormalization time must be positive");
        return QD_ERR_ARG;
    }
    if (!(lo->transient >= 0) || !(lo->transient < o->t_end - o->t0)) {
        qd_ctx_error(ctx, QD_ERR_ARG, "the transient must be at least 0 and shorter than "
                     "the run (t_end - t0 = %.17g)", o->t_end - o->t0);
        return QD_ERR_ARG;
    }
    return QD_OK;
}

/* The sums, the running averages kept and QR's workspace. */
static qd_status bench_alloc(bench *b, qd_ctx *ctx) {
    b->sum = qd__calloc(ctx, b->k, sizeof *b->sum);
    /* the renormalizations in the last half, and one more for the end */
    b->caph = (size_t)ceil(b->T / 2 / b->renorm) + 2;
    b->hist = qd__malloc(ctx, b->caph * b->k * sizeof *b->hist);
    b->lwork = (int)(64 * b->d);
    b->tau = qd__malloc(ctx, (b->k + (size_t)b->lwork) * sizeof *b->tau);
    if (!b->sum || !b->hist || !b->tau) {
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory starting the Lyapunov run");
        return QD_ERR_NOMEM;
    }
    b->work = b->tau + b->k;
    return QD_OK;
}

static void bench_free(bench *b) {
    qd__free(b->sum);
    qd__free(b->hist);
    qd__free(b->tau);
    qd__lyap_tangent_free(&b->r);
}

static qd_status advance(bench *b, double tb) { return qd__lyap_tangent_advance(&b->r, tb); }

/* W = QR; W <- Q; log |R_jj| added to the sums when counted. */
static qd_status renormalize(bench *b, bool counted) {
    int m = (int)b->d, k = (int)b->k, info = 0;
    double *W = b->r.it.y + b->d;
    dgeqrf_(&m, &k, W, &m, b->tau, b->work, &b->lwork, &info);
    for (size_t j = 0; info == 0 && j < b->k; j++) {
        double r = fabs(W[j * b->d + j]);
        if (!(r > 0) || !isfinite(r)) {
            qd_ctx_error(b->r.ws.w.ctx, QD_ERR_NUMERIC, "the tangent vectors collapsed or "
                         "overflowed at t = %.17g: shorten the renormalization time",
                         b->r.it.t);
            return QD_ERR_NUMERIC;
        }
        if (counted)
            b->sum[j] += log(r);
    }
    if (info == 0)
        dorgqr_(&m, &k, &k, W, &m, b->tau, b->work, &b->lwork, &info);
    if (info != 0) {
        qd_ctx_error(b->r.ws.w.ctx, QD_ERR_NUMERIC, "QR factorization failed (LAPACK info %d)",
                     info);
        return QD_ERR_NUMERIC;
    }
    b->r.it.y_changed = true;
    return QD_OK;
}

/* The caller's hook after a renormalization: nonzero stops the run. */
static qd_status report(bench *b) {
    if (!b->lo->progress)
        return QD_OK;
    double span = b->o->t_end - b->o->t0, t = b->r.it.t;
    if (b->lo->progress(b->lo->data, span > 0 ? (t - b->o->t0) / span : 1, t) == 0)
        return QD_OK;
    qd_ctx_error(b->r.ws.w.ctx, QD_ERR_ARG, "stopped at t = %.17g", t);
    return QD_ERR_ARG;
}

/* The running averages at a renormalization in the last half. */
static void record(bench *b) {
    double t = b->r.it.t - b->ta;
    if (t < b->T / 2 * (1 - 1e-12) || b->nh >= b->caph)
        return;
    for (size_t j = 0; j < b->k; j++)
        b->hist[b->nh * b->k + j] = b->sum[j] / t;
    b->nh++;
}

/* Through the transient (renormalized, not counted) to ta, z reset there. */
static qd_status transient(bench *b) {
    for (size_t i = 1; b->r.it.t < b->ta; i++) {
        double tb = fmin(b->o->t0 + (double)i * b->renorm, b->ta);
        qd_status st = advance(b, tb);
        if (st == QD_OK)
            st = renormalize(b, false);
        if (st == QD_OK)
            st = report(b);
        if (st != QD_OK)
            return st;
    }
    b->r.it.y[b->d + b->d * b->k] = 0;
    b->r.it.y_changed = true;
    return QD_OK;
}

static qd_status average(bench *b) {
    for (size_t i = 1; b->r.it.t < b->o->t_end; i++) {
        double tb = fmin(b->ta + (double)i * b->renorm, b->o->t_end);
        qd_status st = advance(b, tb);
        if (st == QD_OK)
            st = renormalize(b, true);
        if (st != QD_OK)
            return st;
        b->renorms++;
        record(b);
        if ((st = report(b)) != QD_OK)
            return st;
    }
    return QD_OK;
}

/* The exponents, descending, and twice the largest deviation of each
 * running average from its final value over the last half (NaN with fewer
 * than two renormalizations there).  The errors go through tau, free now. */
static void results(const bench *b, double *exps, double *err) {
    double *e = b->tau;
    for (size_t j = 0; j < b->k; j++) {
        double final = b->sum[j] / b->T, dev = 0;
        for (size_t h = 0; h < b->nh; h++)
            dev = fmax(dev, fabs(b->hist[h * b->k + j] - final));
        exps[j] = final;
        e[j] = b->nh >= 2 ? 2 * dev : NAN;
    }
    /* QR gives them nearly sorted already: insertion sort */
    for (size_t j = 1; j < b->k; j++)
        for (size_t i = j; i > 0 && exps[i] > exps[i - 1]; i--) {
            double x = exps[i], y = e[i];
            exps[i] = exps[i - 1];
            e[i] = e[i - 1];
            exps[i - 1] = x;
            e[i - 1] = y;
        }
    for (size_t j = 0; err && j < b->k; j++)
        err[j] = e[j];
}

static qd_status run(bench *b, qd_ctx *ctx, const qd_lyap *l, const qd_sim_opts *o) {
    qd_status st = qd__lyap_tangent_start(&b->r, ctx, l, o, b->k, 0, "the Lyapunov run");
    if (st == QD_OK)
        st = bench_alloc(b, ctx);
    if (st == QD_OK)
        st = transient(b);
    if (st == QD_OK)
        st = average(b);
    return st;
}

qd_status qd_lyap_run_stats(qd_ctx *ctx, const qd_lyap *l, const qd_sim_opts *o,
                            const qd_lyap_opts *lo, double *exps, double *err,
                            qd_lyap_stats *stats) {
    QD_ARGS_CTX(ctx, ctx && l && o && lo && exps);
    if (stats)
        *stats = (qd_lyap_stats){0};
    qd_status st = check_opts(ctx, l, o, lo);
    if (st != QD_OK)
        return st;
    bench b = {.o = o, .lo = lo, .k = lo->nexp, .d = 2 * l->n,
               .renorm = lo->renorm > 0 ? lo->renorm : 1,
               .ta = o->t0 + lo->transient, .T = o->t_end - o->t0 - lo->transient};
    st = run(&b, ctx, l, o);
    if (st == QD_OK)
        results(&b, exps, err);
    if (stats) {
        stats->t_avg = b.T;
        stats->renorms = b.renorms;
        stats->trace_mean = st == QD_OK ? b.r.it.y[b.d + b.d * b.k] / b.T : NAN;
        stats->steps = b.r.it.steps;
        stats->evals = b.r.ws.w.evals;
        stats->rejected = b.r.it.rejected;
    }
    if (st != QD_OK && qd_ctx_status(ctx) == QD_OK)
        qd_ctx_error(ctx, st, "the Lyapunov run failed: %s", qd_status_str(st));
    bench_free(&b);
    return st;
}

qd_status qd_lyap_run(qd_ctx *ctx, const qd_lyap *l, const qd_sim_opts *opts,
                      const qd_lyap_opts *lo, double *exps, double *err) {
    QD_ARGS_CTX(ctx, ctx && l && opts && lo && exps);
    return qd_lyap_run_stats(ctx, l, opts, lo, exps, err, NULL);
}

/*
 * src/sim/taylor.c - the Taylor integrator (issue 22): the solution's
 * Taylor series at the start of each step by automatic differentiation of
 * the compiled equations (src/sym/taylor_prog.c), summed at the step.
 *
 * Method: Jorba and Zou, "A software package for the numerical integration
 * of ODEs by means of high-order Taylor methods", Exp. Math. 14 (2005),
 * sec. 3.2, their step-size and order control: with the tolerances
 * eps_a, eps_r and ||.|| the max norm over the state,
 *     eps = eps_a, m = 1        when eps_r ||y_0|| <= eps_a (absolute),
 *     eps = eps_r, m = ||y_0||  otherwise (relative);
 *     order p = ceil(-ln(eps) / 2 + 1),
 *     rho_j = (m / ||y_j||)^(1/j),  h = min(rho_{p-1}, rho_p) / e^2,
 * the last two coefficients estimating the series' radius of convergence,
 * so that the truncation term ||y_p|| h^p ~ m e^(-2p) ~ eps; heyoka (Biscani
 * and Izzo 2021, MNRAS 504) multiplies h by exp(-0.7 / (p - 1)) as a safety
 * factor, which we keep.  There is no rejected step.
 *
 * Forms: (q, q') with M q'' = f (constraints: the saddle system with A and
 * b, then the driver's projection), (q, p) of a system made from H
 * (q' = dH/dp and p' from two programs), and (q, u) in generalized speeds.
 * Dense output is the step's Taylor polynomial, so the events' roots are
 * found on the polynomial itself.  --precision 80|128 keeps the state, the
 * time and every coefficient in long double or __float128 (taylor_core.h is
 * written once over the type).
 */
#include "taylor_native.h"
#include "base/mem.h"

#include <math.h>
#include <string.h>
#ifdef QD_HAVE_QUADMATH
#include <quadmath.h>
#endif

typedef struct tay tay;

/* The type-specific half (taylor_core.h). */
typedef struct tay_ops {
    qd_status (*series)(tay *T, size_t p);
    double (*norm)(tay *T, size_t j);
    void (*dense)(tay *T, double theta, double *y);
    void (*load)(tay *T, double t, const double *y);
    void (*flat_inputs)(tay *T, const double *in);
    double (*advance)(tay *T, double h, double tend, double *y); /* the new t */
    void (*commit)(tay *T);
    size_t size;
} tay_ops;

struct tay {
    const tay_ops *ops;
    qd__tay *tp;
    size_t dim, nin, tin, pmax, p;
    size_t *in_of;               /* dim: the input holding state component i */
    size_t *src_in, *src_out, *src_x; /* dim: where y_i' comes from: a state
                                    component, an output, or an unknown of the
                                    solve (SIZE_MAX: not that one) */
    bool *var;                   /* nin: the inputs that vary in a step */
    size_t nb, m, N, M_at, A_at; /* the solve: N unknowns, M nb*nb at M_at */
    size_t *r_at, *piv;          /* N */
    double *rs;                  /* N: each row's largest |K_0| entry (the pivot test's scale) */
    void *K, *X, *ynew, *t, *tnext; /* typed: N*N, (pmax+1)*N, dim, 1, 1 */
    void *ylo;                   /* typed, 2 dim: the state's rounding error, the next */
    void *dF;                    /* typed, dim: the derivative's change along ylo */
    /* the coefficient arrays, found once: the state's (dim), the sources of
     * its derivatives (dim, NULL: from the solve), K's entries (N*N, NULL
     * for 0; kneg: -A^T; kflat: constant), r's (N) */
    void **yc, **srcc, **kc, **rc;
    bool *kneg, *kflat;
};

#define TAY_T double
#define TAY_S(name) name##_d
#define TAY_M(fn) fn
#include "taylor_core.h"
#undef TAY_T
#undef TAY_S
#undef TAY_M

#define TAY_T long double
#define TAY_S(name) name##_l
#define TAY_M(fn) fn##l
#include "taylor_core.h"
#undef TAY_T
#undef TAY_S
#undef TAY_M

#ifdef QD_HAVE_QUADMATH
#define TAY_T qd__f128
#define TAY_S(name) name##_q
#define TAY_M(fn) fn##q
#include "taylor_core.h"
#undef TAY_T
#undef TAY_S
#undef TAY_M
#endif

/* Jorba and Zou's order for a tolerance. */
static size_t jz_order(double eps) {
    double p = ceil(-log(eps) / 2 + 1);
    return p < 2 ? 2 : (size_t)p;
}

static qd_status refuse(qd_sim *s, const char *why) {
    qd_ctx_error(s->ctx, QD_ERR_ARG, "taylor cannot integrate %s", why);
    return QD_ERR_ARG;
}

/* The solve's layout and the sources of the derivatives, per form. */
static void layout(tay *T, const qd__sim_integ *it) {
    const qd_sim *s = it->s;
    size_t n = s->n;
    for (size_t i = 0; i < T->dim; i++) {
        T->in_of[i] = i;
        T->src_in[i] = T->src_out[i] = T->src_x[i] = SIZE_MAX;
    }
    if (it->form == QD__LAG) {
        T->nb = n;
        T->m = s->m;
        T->M_at = 0;
        T->A_at = n * n + n;
        for (size_t j = 0; j < n; j++) {
            T->src_in[j] = n + j;
            T->src_x[n + j] = j;
            T->r_at[j] = n * n + j;
        }
        for (size_t c = 0; c < s->m; c++)
            T->r_at[n + c] = n * n + n + s->m * n + c;
    } else if (it->form == QD__SPD) {
        T->nb = s->nu;
        T->M_at = n;
        for (size_t r = 0; r < s->nu; r++) {
            T->in_of[n + r] = 2 * n + 1 + s->np + r;
            T->src_x[n + r] = r;
            T->r_at[r] = n + s->nu * s->nu + r;
        }
        for (size_t j = 0; j < n; j++)
            T->src_out[j] = j;
    } else {
        for (size_t i = 0; i < 2 * n; i++)
            T->src_out[i] = i; /* mom's q' then force's p' */
    }
    T->N = T->nb + T->m;
}

static const tay_ops *ops_for(int precision) {
#ifdef QD_HAVE_QUADMATH
    if (precision == 128)
        return &ops_q;
#endif
    return precision == 80 ? &ops_l : &ops_d;
}

static qd__tay_prec prec_of(int precision) {
    return precision == 128 ? QD__TAY_QUAD : precision == 80 ? QD__TAY_LONG : QD__TAY_DOUBLE;
}

static qd_status check(qd__sim_integ *it) {
    qd_sim *s = it->s;
    if (s->nuin)
        return refuse(s, "a model with inputs (a table or a callback has no Taylor series): "
                         "use dop853");
    if (it->precision && it->precision != 64 && it->precision != 80 && it->precision != 128) {
        qd_ctx_error(s->ctx, QD_ERR_ARG, "the precision is 64, 80 or 128 (bits of the "
                     "significand's type: double, long double, __float128)");
        return QD_ERR_ARG;
    }
#ifndef QD_HAVE_QUADMATH
    if (it->precision == 128) {
        qd_ctx_error(s->ctx, QD_ERR_UNSUPPORTED, "precision 128 needs libquadmath, which "
                     "this build lacks");
        return QD_ERR_UNSUPPORTED;
    }
#endif
    return QD_OK;
}

static qd_status alloc(tay *T, qd__sim_integ *it) {
    qd_ctx *ctx = it->s->ctx;
    size_t d = T->dim, N = it->s->n + it->s->m + it->s->nu, sz = T->ops->size;
    T->in_of = qd__malloc(ctx, (4 * d + 2 * N + 1) * sizeof *T->in_of);
    T->var = qd__calloc(ctx, T->nin + 2 * N * N + 1, sizeof *T->var);
    T->K = qd__calloc(ctx, N * N + (T->pmax + 2) * N + 4 * d + 3, sz);
    T->yc = qd__calloc(ctx, 2 * d + N * N + N + 1, sizeof *T->yc);
    T->rs = qd__malloc(ctx, (N + 1) * sizeof *T->rs);
    if (!T->in_of || !T->var || !T->K || !T->yc || !T->rs)
        return QD_ERR_NOMEM;
    T->srcc = T->yc + d;
    T->kc = T->srcc + d;
    T->rc = T->kc + N * N;
    T->kneg = T->var + T->nin;
    T->kflat = T->kneg + N * N;
    T->src_in = T->in_of + d;
    T->src_out = T->src_in + d;
    T->src_x = T->src_out + d;
    T->r_at = T->src_x + d;
    T->piv = T->r_at + N;
    T->X = (char *)T->K + N * N * sz;
    T->ynew = (char *)T->X + (T->pmax + 2) * N * sz;
    T->t = (char *)T->ynew + d * sz;
    T->tnext = (char *)T->t + sz;
    T->ylo = (char *)T->tnext + sz;
    T->dF = (char *)T->ylo + 2 * d * sz;
    return QD_OK;
}

/* The Taylor mode of the form's programs, the state and time varying. */
static qd_status make_tay(tay *T, qd__sim_integ *it) {
    qd_sim *s = it->s;
    const qd_prog *progs[2];
    size_t np;
    qd__sim_taylor_inputs(s, progs, &np, T->var);
    T->tp = qd__tay_new(s->ctx, np, progs, T->var, T->pmax, prec_of(it->precision));
    if (!T->tp)
        return qd_ctx_status(s->ctx) != QD_OK ? qd_ctx_status(s->ctx) : QD_ERR_NOMEM;
    if (!it->precision || it->precision == 64)
        qd__tay_set_native(T->tp, qd__sim_taylor_native_for(s, T->tp));
    size_t sz = T->ops->size;
    /* t = t0 + 1 (t - t0): coefficient 1 is 1, the rest 0 */
    char *tc = qd__tay_in(T->tp, T->tin);
    if (sz == sizeof(double))
        ((double *)tc)[1] = 1;
    else if (T->ops == &ops_l)
        ((long double *)tc)[1] = 1;
#ifdef QD_HAVE_QUADMATH
    else
        ((qd__f128 *)tc)[1] = 1;
#endif
    return QD_OK;
}

/* K's entry (i, l) of the saddle matrix: M, -A^T, A or 0. */
static void K_entry(tay *T, size_t i, size_t l) {
    size_t n = T->nb, e = i * T->N + l, out = SIZE_MAX;
    if (i < n && l < n)
        out = T->M_at + i * n + l;
    else if (i < n)
        out = T->A_at + (l - n) * n + i;
    else if (l < n)
        out = T->A_at + (i - n) * n + l;
    T->kneg[e] = i < n && l >= n;
    T->kc[e] = out == SIZE_MAX ? NULL : qd__tay_out(T->tp, out);
    T->kflat[e] = out == SIZE_MAX || qd__tay_out_flat(T->tp, out);
}

/* The coefficient arrays the step reads, found once. */
static void tables(tay *T) {
    for (size_t i = 0; i < T->dim; i++)
        T->yc[i] = qd__tay_in(T->tp, T->in_of[i]);
    for (size_t i = 0; i < T->dim; i++)
        T->srcc[i] = T->src_out[i] != SIZE_MAX ? qd__tay_out(T->tp, T->src_out[i])
                     : T->src_in[i] != SIZE_MAX ? T->yc[T->src_in[i]] : NULL;
    for (size_t i = 0; i < T->N; i++) {
        T->rc[i] = qd__tay_out(T->tp, T->r_at[i]);
        for (size_t l = 0; l < T->N; l++)
            K_entry(T, i, l);
    }
}

static qd_status taylor_init(qd__sim_integ *it) {
    qd_sim *s = it->s;
    qd_status st = check(it);
    if (st != QD_OK)
        return st;
    tay *T = qd__calloc(s->ctx, 1, sizeof *T);
    if (!T)
        return QD_ERR_NOMEM;
    it->priv = T;
    T->ops = ops_for(it->precision);
    T->dim = it->dim;
    T->nin = s->nin;
    T->tin = 2 * s->n;
    T->pmax = jz_order(fmin(it->rtol, it->atol));
    st = alloc(T, it);
    if (st == QD_OK) {
        layout(T, it);
        st = make_tay(T, it);
    }
    if (st == QD_OK)
        tables(T);
    if (st != QD_OK)
        return st;
    T->ops->load(T, it->t, it->y);
    it->y_changed = false;
    if (!(it->h > 0))
        it->h = INFINITY; /* the series choose the step (it->h only caps it) */
    return QD_OK;
}

/* Jorba and Zou's order and the tolerance's scale m from ||y_0||. */
static size_t step_order(const qd__sim_integ *it, tay *T, double *m) {
    double y0 = T->ops->norm(T, 0);
    bool absolute = it->rtol * y0 <= it->atol;
    *m = absolute ? 1 : y0;
    size_t p = jz_order(absolute ? it->atol : it->rtol);
    return p > T->pmax ? T->pmax : p;
}

/* h = min_j rho_j / e^2 * exp(-0.7 / (p - 1)) (the header), over the last
 * four coefficients where Jorba and Zou take two: a start from rest gives
 * series with every other pair of coefficients 0 (theta even in t, theta'
 * odd: y_3, y_4, y_7, y_8, ... vanish), and at p = 20 the last two are
 * such a pair: their rho is the radius of nothing, and the step 40 times
 * too long (measured: the double pendulum's energy off by 2e-3 after one
 * step). */
static double jz_step(tay *T, size_t p, double m) {
    double rho = INFINITY;
    for (size_t j = p > 4 ? p - 3 : 1; j <= p; j++)
        rho = fmin(rho, pow(m / T->ops->norm(T, j), 1.0 / (double)j));
    return rho * exp(-2.0 - 0.7 / (double)(p - 1));
}

static qd_status taylor_step(qd__sim_integ *it) {
    tay *T = it->priv;
    qd_sim *s = it->s;
    if (it->y_changed)
        T->ops->load(T, it->t, it->y);
    else if (T->p)
        T->ops->commit(T);
    it->y_changed = false;
    double m;
    size_t p = step_order(it, T, &m);
    T->ops->flat_inputs(T, s->in);
    qd_status st = T->ops->series(T, p);
    s->evals += p;
    if (st == QD_ERR_SINGULAR) {
        qd_ctx_error(s->ctx, QD_ERR_SINGULAR, "singular mass matrix at t = %.17g: the "
                     "accelerations are not determined there", it->t);
        return st;
    }
    T->p = p;
    double h = it->fixed ? it->h : fmin(it->h, jz_step(T, p, m));
    if (!(h > 0) || !isfinite(h))
        return qd__sim_not_finite(s, it->t, "the Taylor series of the solution is");
    if (h <= 1e-14 * fabs(it->t))
        return qd__sim_underflow(it, h);
    memcpy(it->yold, it->y, it->dim * sizeof *it->y);
    /* the driver cut the step to end at t_end */
    bool to_end = !it->fixed && h == it->h && it->t + h >= it->tend;
    double tnew = T->ops->advance(T, h, to_end ? it->tend : NAN, it->y);
    for (size_t i = 0; i < it->dim; i++)
        if (!isfinite(it->y[i]))
            return qd__sim_not_finite(s, it->t, "the Taylor series of the solution is");
    it->told = it->t;
    it->t = it->fixed ? it->told + h : tnew;
    /* the next step chooses its own size from its own series */
    if (!it->fixed)
        it->h = INFINITY;
    return QD_OK;
}

static void taylor_dense(qd__sim_integ *it, double t, double *y) {
    tay *T = it->priv;
    T->ops->dense(T, t - it->told, y);
}

static void taylor_free(qd__sim_integ *it) {
    tay *T = it->priv;
    if (!T)
        return;
    qd__tay_free(T->tp);
    qd__free(T->in_of);
    qd__free(T->rs);
    qd__free(T->var);
    qd__free(T->K);
    qd__free(T->yc);
    qd__free(T);
    it->priv = NULL;
}

const qd__sim_method qd__sim_taylor = {taylor_init, taylor_step, taylor_dense, NULL, taylor_free};

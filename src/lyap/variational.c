/*
 * src/lyap/variational.c - the variational equations of a model's motion,
 * built on the symbolic Jacobian and compiled once.
 *
 * Differentiating M(q, q', t) q'' = f(q, q', t) along a tangent vector
 * (dq, dv) of the state (q, q') gives
 *
 *     M dq'' = (df/dq - dM/dq q'') dq + (df/dq' - dM/dq' q'') dv,
 *
 * so the tangent map needs df/dq, df/dq' and the derivatives of M, which
 * are compiled into one program over the qd_sim's inputs (q, q', t,
 * parameters); q'' comes from the same solve as the state's right-hand
 * side, so no symbolic inverse of M is formed.  Finite differences would
 * lose half the digits of every exponent; these derivatives are exact.
 */
#include "lyap.h"

#include <math.h>
#include <string.h>

#include "base/mem.h"
#include "num/num.h"
#include "../base/args.h"

extern void dgetrf_(const int *m, const int *n, double *a, const int *lda, int *ipiv, int *info);
extern void dgetrs_(const char *trans, const int *n, const int *nrhs, const double *a,
                    const int *lda, const int *ipiv, double *b, const int *ldb, int *info);

/* ---- building --------------------------------------------------------------- */

/* Why a model cannot have a tangent system here; NULL when it can. */
static const char *refusal(const qd_model *m, const qd_eom *e) {
    if (e->ncon)
        return "Lyapunov exponents need an unconstrained model (constraints are not "
               "linearized here)";
    if (qd_model_nimpacts(m))
        return "Lyapunov exponents need a smooth motion: the model has impacts";
    if (qd_model_ninputs(m))
        return "Lyapunov exponents need an autonomous model of its own: the model has inputs";
    return NULL;
}

/* Append the n*n derivatives of M by x to outs at *k; the block's offset,
 * or 0 when every entry is zero (then nothing is appended). */
static size_t dm_block(qd_ctx *ctx, const qd_eom *e, const qd_expr *x, const qd_expr **outs,
                       size_t *k) {
    size_t n = e->n, at = *k;
    bool zero = true;
    for (size_t i = 0; i < n * n; i++) {
        outs[at + i] = qd_diff(ctx, e->M[i], x);
        zero = zero && outs[at + i] && qd_is_zero(outs[at + i]);
    }
    if (zero)
        return 0;
    *k += n * n;
    return at;
}

static qd_status compile_jacobian(qd_ctx *ctx, qd_lyap *l, const qd_eom *e) {
    size_t n = e->n, k = 0;
    const qd_expr **outs = qd__malloc(ctx, (4 * n * n * n + 2 * n * n + 1) * sizeof *outs);
    l->dmq = qd__calloc(ctx, 2 * n + 1, sizeof *l->dmq);
    if (!outs || !l->dmq) {
        qd__free(outs);
        return QD_ERR_NOMEM;
    }
    l->dmv = l->dmq + n;
    for (size_t i = 0; i < n; i++)
        for (size_t j = 0; j < n; j++) {
            outs[k + i * n + j] = qd_diff(ctx, e->f[i], e->q[j]);
            outs[k + n * n + i * n + j] = qd_diff(ctx, e->f[i], e->qd[j]);
        }
    k += 2 * n * n;
    for (size_t j = 0; j < n; j++) {
        l->dmq[j] = dm_block(ctx, e, e->q[j], outs, &k);
        l->dmv[j] = dm_block(ctx, e, e->qd[j], outs, &k);
    }
    if (qd_ctx_status(ctx) == QD_OK)
        l->jac = qd__sim_prog(l->sim, k, outs, &l->jac_n);
    qd__free(outs);
    return l->jac ? QD_OK : qd_ctx_status(ctx);
}

qd_lyap *qd_lyap_new(qd_ctx *ctx, const qd_model *m, const qd_eom *e) {
    QD_ARGS(NULL, ctx && m && e);
    const char *why = refusal(m, e);
    if (why) {
        qd_ctx_error(ctx, QD_ERR_ARG, "%s", why);
        return NULL;
    }
    qd_lyap *l = qd__calloc(ctx, 1, sizeof *l);
    if (!l) {
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory");
        return NULL;
    }
    l->n = e->n;
    l->sim = qd_sim_new(ctx, m, e);
    qd_status st = l->sim ? qd_sim_compile(l->sim) : qd_ctx_status(ctx);
    if (st == QD_OK)
        st = compile_jacobian(ctx, l, e);
    if (st != QD_OK) {
        if (qd_ctx_status(ctx) == QD_OK)
            qd_ctx_error(ctx, st, "cannot compile the variational equations");
        qd_lyap_free(l);
        return NULL;
    }
    return l;
}

void qd_lyap_free(qd_lyap *l) {
    if (!l)
        return;
    qd_prog_free(l->jac);
    qd_sim_free(l->sim);
    qd__free(l->dmq);
    qd__free(l);
}

size_t qd_lyap_ndof(const qd_lyap *l) { QD_ARGS(0, l); return l->n; }

/* ---- a run's workspace ------------------------------------------------------ */

qd_status qd__lyap_ws_init(qd__lyap_ws *ws, qd_ctx *ctx, const qd_lyap *l, size_t k,
                           const double *par) {
    size_t n = l->n;
    *ws = (qd__lyap_ws){.l = l, .w = *l->sim, .k = k};
    qd_status st = qd__sim_ws_alloc(&ws->w, ctx);
    ws->jout = qd__malloc(ctx, (l->jac_n + 1) * sizeof *ws->jout);
    ws->jwork = qd__malloc(ctx, (qd_prog_work_size(l->jac) + 1) * sizeof *ws->jwork);
    ws->A = qd__malloc(ctx, (3 * n * n + n * (k + n) + n) * sizeof *ws->A);
    ws->ipiv = qd__malloc(ctx, (n + 1) * sizeof *ws->ipiv);
    if (st != QD_OK || !ws->jout || !ws->jwork || !ws->A || !ws->ipiv) {
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory starting the Lyapunov run");
        return QD_ERR_NOMEM;
    }
    qd_prog_work_init(l->jac, ws->jwork);
    ws->B = ws->A + n * n;
    ws->LU = ws->B + n * n;
    ws->X = ws->LU + n * n;
    ws->qdd = ws->X + n * (k + n);
    /* the run's parameters, where every program reads them */
    for (size_t i = 0; par && i < ws->w.np; i++)
        ws->w.in[2 * n + 1 + i] = par[i];
    return QD_OK;
}

void qd__lyap_ws_free(qd__lyap_ws *ws) {
    qd__sim_ws_free(&ws->w);
    qd__free(ws->jout);
    qd__free(ws->jwork);
    qd__free(ws->A);
    qd__free(ws->ipiv);
}

/* ---- evaluation ------------------------------------------------------------- */

static bool finite_all(const double *x, size_t n) {
    for (size_t i = 0; i < n; i++)
        if (!isfinite(x[i]))
            return false;
    return true;
}

static qd_status singular_mass(qd_sim *s, double t) {
    qd_ctx_error(s->ctx, QD_ERR_SINGULAR,
                 "singular mass matrix at t = %.17g: the accelerations and the tangent "
                 "map are not determined there", t);
    return QD_ERR_SINGULAR;
}

/* M and f at (t, x) into acc_out, M factored into LU (column-major: the
 * factors of M^T, solved with 'T'), q'' into ws->qdd. */
static qd_status accelerations(qd__lyap_ws *ws, double t, const double *x) {
    qd_sim *s = &ws->w;
    int n = (int)s->n, info = 0;
    for (int i = 0; i < 2 * n; i++)
        s->in[i] = x[i];
    s->in[2 * n] = t;
    qd_prog_eval(s->acc, s->acc_w, s->in, s->acc_out);
    const double *M = s->acc_out, *f = M + n * n;
    if (!finite_all(M, (size_t)(n * n)))
        return qd__sim_not_finite(s, t, "the mass matrix is");
    /* the simulation's own test of a singular M, so both agree where it is */
    memcpy(ws->LU, M, (size_t)(n * n) * sizeof *M);
    memcpy(ws->qdd, f, (size_t)n * sizeof *f);
    if (!qd__num_solve((size_t)n, ws->LU, ws->qdd, 1e-13 * n))
        return singular_mass(s, t);
    memcpy(ws->LU, M, (size_t)(n * n) * sizeof *M);
    dgetrf_(&n, &n, ws->LU, &n, ws->ipiv, &info);
    return info == 0 ? QD_OK : singular_mass(s, t);
}

/* A = df/dq - sum_k dM/dq_k q'' e_k^T, B likewise with q' (row-major). */
static void tangent_blocks(qd__lyap_ws *ws) {
    const qd_lyap *l = ws->l;
    size_t n = l->n;
    qd_prog_eval(l->jac, ws->jwork, ws->w.in, ws->jout);
    memcpy(ws->A, ws->jout, 2 * n * n * sizeof *ws->A);
    for (size_t c = 0; c < n; c++) {
        const double *dq = l->dmq[c] ? ws->jout + l->dmq[c] : NULL;
        const double *dv = l->dmv[c] ? ws->jout + l->dmv[c] : NULL;
        for (size_t i = 0; (dq || dv) && i < n; i++)
            for (size_t j = 0; j < n; j++) {
                if (dq)
                    ws->A[i * n + c] -= dq[i * n + j] * ws->qdd[j];
                if (dv)
                    ws->B[i * n + c] -= dv[i * n + j] * ws->qdd[j];
            }
    }
}

/* The right-hand sides of M dq'' for the k tangent vectors at w, then the
 * n columns of B (for tr M^-1 B), solved in place in ws->X. */
static qd_status solve_tangent(qd__lyap_ws *ws, const double *w) {
    size_t n = ws->l->n, d = 2 * n;
    for (size_t j = 0; j < ws->k; j++) {
        const double *dq = w + j * d, *dv = dq + n;
        double *r = ws->X + j * n;
        for (size_t i = 0; i < n; i++) {
            double sum = 0;
            for (size_t c = 0; c < n; c++)
                sum += ws->A[i * n + c] * dq[c] + ws->B[i * n + c] * dv[c];
            r[i] = sum;
        }
    }
    for (size_t c = 0; c < n; c++)
        for (size_t i = 0; i < n; i++)
            ws->X[(ws->k + c) * n + i] = ws->B[i * n + c];
    int in = (int)n, nrhs = (int)(ws->k + n), info = 0;
    dgetrs_("T", &in, &nrhs, ws->LU, &in, ws->ipiv, ws->X, &in, &info);
    return info == 0 ? QD_OK : QD_ERR_NUMERIC;
}

qd_status qd__lyap_rhs(void *data, double t, const double *y, double *dy) {
    qd__lyap_ws *ws = data;
    size_t n = ws->l->n, d = 2 * n;
    qd_status st = accelerations(ws, t, y);
    if (st != QD_OK)
        return st;
    tangent_blocks(ws);
    if ((st = solve_tangent(ws, y + d)) != QD_OK)
        return st;
    for (size_t i = 0; i < n; i++) {
        dy[i] = y[n + i];
        dy[n + i] = ws->qdd[i];
    }
    for (size_t j = 0; j < ws->k; j++) {
        const double *w = y + d + j * d;
        double *dw = dy + d + j * d;
        for (size_t i = 0; i < n; i++) {
            dw[i] = w[n + i];
            dw[n + i] = ws->X[j * n + i];
        }
    }
    /* tr J = tr M^-1 B: the upper-left block of J is zero */
    double tr = 0;
    for (size_t i = 0; i < n; i++)
        tr += ws->X[(ws->k + i) * n + i];
    dy[d + ws->k * d] = tr;
    return QD_OK;
}

qd_status qd__lyap_jacobian(qd_ctx *ctx, const qd_lyap *l, const double *par, double t,
                            const double *x, double *F, double *J) {
    size_t n = l->n, d = 2 * n;
    qd__lyap_ws ws;
    qd_status st = qd__lyap_ws_init(&ws, ctx, l, d, par);
    double *y = st == QD_OK ? qd__calloc(ctx, 2 * (d + d * d + 1), sizeof *y) : NULL;
    if (st == QD_OK && !y)
        st = QD_ERR_NOMEM;
    if (st == QD_OK) {
        double *dy = y + d + d * d + 1;
        memcpy(y, x, d * sizeof *y);
        for (size_t j = 0; j < d; j++)
            y[d + j * d + j] = 1;   /* w_j = e_j: J w_j is J's column j */
        st = qd__lyap_rhs(&ws, t, y, dy);
        for (size_t i = 0; st == QD_OK && i < d; i++) {
            F[i] = dy[i];
            for (size_t j = 0; j < d; j++)
                J[i * d + j] = dy[d + j * d + i];
        }
    }
    qd__free(y);
    qd__lyap_ws_free(&ws);
    return st;
}

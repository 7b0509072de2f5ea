/*
 * src/linear/conlin.c - linearization of constrained systems on their
 * state manifold (qdot/conlin.h): the states chosen, the dependent ones
 * solved by Newton, and A = P (dF/dz) T, B = P dF/du from the forward-mode
 * Jacobians (qdot/tangent.h) of the compiled M, f, A, b and of the
 * constraint functions C(z).
 */
#include "ss.h"
#include "qdot/conlin.h"
#include "qdot/state.h"
#include "qdot/tangent.h"
#include "base/mem.h"

#include <math.h>
#include <stdio.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

extern void dgesv_(const int *n, const int *nrhs, double *a, const int *lda, int *ipiv, double *b,
                   const int *ldb, int *info);

#define NEWTON_ITERS 60

static const qd_expr *speed_velocity(const qd_model *m, size_t i);
#define IGNORABLE_TOL 1e-13

/* What one linearization works with.  The tangents' inputs are
 * in = (q, q', u, the rest of the model's state), the first 2n + nu varying. */
typedef struct cl_work {
    qd_ctx *ctx;
    const qd_eom *e;
    const qd_model *m;
    size_t n, nu, nc, nh, d;     /* d = nh + nc constraint functions */
    size_t nin;
    const qd_expr **in;
    double *val;                 /* nin */
    size_t *hol;                 /* nh: the holonomic constraints' indices */
    qd_tangent *dyn, *con, *out; /* (M, f, A, b), C and the outputs h (NULL: none) */
    double *C, *Cz;              /* d, d * (2n + nu) */
} cl_work;

static void work_free(cl_work *w) {
    qd_tangent_free(w->dyn);
    qd_tangent_free(w->con);
    qd_tangent_free(w->out);
    qd__free(w->in);
    qd__free(w->val);
    qd__free(w->hol);
    qd__free(w->C);
    qd__free(w->Cz);
}

static bool in_list(const qd_expr *x, const qd_expr *const *list, size_t n) {
    for (size_t i = 0; i < n; i++)
        if (list[i] == x)
            return true;
    return false;
}

/* The inputs: q, q', u, then the state's other slots (t, parameters, ...). */
static qd_status make_inputs(cl_work *w, const qd_model *m, const qd_state *st) {
    size_t n = w->n, k = 0;
    w->in = qd__calloc(w->ctx, 2 * n + w->nu + st->n + 1, sizeof *w->in);
    w->val = qd__calloc(w->ctx, 2 * n + w->nu + st->n + 1, sizeof *w->val);
    if (!w->in || !w->val)
        return QD_ERR_NOMEM;
    for (size_t j = 0; j < n; j++)
        w->in[k++] = w->e->q[j];
    for (size_t j = 0; j < n; j++)
        w->in[k++] = w->e->qd[j];
    for (size_t j = 0; j < w->nu; j++)
        w->in[k++] = qd_model_input(m, j);
    size_t head = k;
    for (size_t i = 0; i < st->n; i++)
        if (!in_list(st->syms[i], w->in, head)) {
            w->val[k] = st->vals[i];
            w->in[k++] = st->syms[i];
        }
    for (size_t i = 0; i < head; i++) {
        size_t s = qd_state_find(st, w->in[i]);
        w->val[i] = s < st->n ? st->vals[s] : 0;
    }
    w->nin = k;
    return QD_OK;
}

/* C = (phi_k holonomic; sum_j A_kj q'_j + a0_k every k) and (M, f, A, b). */
static qd_status make_tangents(cl_work *w) {
    const qd_eom *e = w->e;
    size_t n = w->n, nc = w->nc, nv = 2 * n + w->nu;
    const qd_expr **out = qd__calloc(w->ctx, n * n + n + nc * n + nc + w->d + 1, sizeof *out);
    const qd_expr **terms = qd__calloc(w->ctx, n + 2, sizeof *terms);
    bool *vary = qd__calloc(w->ctx, w->nin + 1, sizeof *vary);
    qd_status st = out && terms && vary ? QD_OK : QD_ERR_NOMEM;
    for (size_t i = 0; i < nv && st == QD_OK; i++)
        vary[i] = true;
    size_t k = 0;
    for (size_t h = 0; h < w->nh && st == QD_OK; h++)
        out[k++] = e->con[w->hol[h]].expr;
    for (size_t c = 0; c < nc && st == QD_OK; c++) {
        for (size_t j = 0; j < n; j++)
            terms[j] = qd_mul(w->ctx, e->A[c * n + j], e->qd[j]);
        terms[n] = e->con[c].a0 ? e->con[c].a0 : qd_int(w->ctx, 0);
        if (!(out[k++] = qd_add_n(w->ctx, n + 1, terms)))
            st = qd_ctx_status(w->ctx);
    }
    if (st == QD_OK && !(w->con = qd_tangent_new(w->ctx, w->nin, w->in, vary, w->d, out)))
        st = qd_ctx_status(w->ctx);
    k = 0;
    for (size_t i = 0; i < n * n && st == QD_OK; i++)
        out[k++] = e->M[i];
    for (size_t i = 0; i < n && st == QD_OK; i++)
        out[k++] = e->f[i];
    for (size_t i = 0; i < nc * n && st == QD_OK; i++)
        out[k++] = e->A[i];
    for (size_t i = 0; i < nc && st == QD_OK; i++)
        out[k++] = e->b[i];
    if (st == QD_OK && !(w->dyn = qd_tangent_new(w->ctx, w->nin, w->in, vary, k, out)))
        st = qd_ctx_status(w->ctx);
    size_t ny = qd_model_noutputs(w->m);
    const qd_expr **h = ny && st == QD_OK ? qd__calloc(w->ctx, ny + 1, sizeof *h) : NULL;
    for (size_t i = 0; h && i < ny; i++)
        h[i] = qd_model_output(w->m, i);
    if (ny && st == QD_OK && (!h || !(w->out = qd_tangent_new(w->ctx, w->nin, w->in, vary, ny, h))))
        st = h ? qd_ctx_status(w->ctx) : QD_ERR_NOMEM;
    qd__free(h);
    w->C = qd__calloc(w->ctx, w->d + 1, sizeof *w->C);
    w->Cz = qd__calloc(w->ctx, w->d * nv + 1, sizeof *w->Cz);
    if (st == QD_OK && (!w->C || !w->Cz))
        st = QD_ERR_NOMEM;
    qd__free(out);
    qd__free(terms);
    qd__free(vary);
    return st;
}

static qd_status con_eval(cl_work *w) {
    return qd_tangent_jacobian(w->ctx, w->con, w->val, w->C, w->Cz);
}

/* ---- the choice of states ---------------------------------------------------- */

/* Column-pivoted Gram-Schmidt on the columns cols[0..nc) of the rows
 * rows[0..nr) of Cz: the pivots taken, the columns of class 0 before those
 * of class 1 (cls NULL: one class), into dep (appended at *nd).  Returns
 * the rank reached.  forced: columns taken first whatever their size. */
/* pivots' scratch: a flag per column, a vector per row, the basis Q. */
typedef struct piv_scratch {
    bool *used;
    double *v, *Q;
} piv_scratch;

static size_t pivots(const cl_work *w, const size_t *rows, size_t nr, const size_t *cols,
                     size_t ncols, const int *cls, size_t *dep, size_t *nd,
                     const piv_scratch *sc) {
    double *Q = sc->Q;
    size_t nv = 2 * w->n + w->nu, rank = 0;
    double scale = 0;
    for (size_t r = 0; r < nr; r++)
        for (size_t c = 0; c < ncols; c++)
            scale = fmax(scale, fabs(w->Cz[rows[r] * nv + cols[c]]));
    bool *used = sc->used;
    double *v = sc->v;
    memset(used, 0, ncols * sizeof *used);
    if (scale == 0)
        return 0;
    for (int pass = 0; pass < 4 && rank < nr; pass++)
        for (; rank < nr;) {
            size_t best = SIZE_MAX;
            double bn = 1e-10 * scale;
            for (size_t c = 0; c < ncols; c++) {
                if (used[c] || (cls ? cls[c] != pass : pass != 0))
                    continue;
                for (size_t r = 0; r < nr; r++)
                    v[r] = w->Cz[rows[r] * nv + cols[c]];
                for (size_t k = 0; k < rank; k++) {
                    double dot = 0;
                    for (size_t r = 0; r < nr; r++)
                        dot += Q[k * nr + r] * v[r];
                    for (size_t r = 0; r < nr; r++)
                        v[r] -= dot * Q[k * nr + r];
                }
                double nrm = 0;
                for (size_t r = 0; r < nr; r++)
                    nrm += v[r] * v[r];
                nrm = sqrt(nrm);
                if (nrm > bn) {
                    bn = nrm;
                    best = c;
                }
            }
            if (best == SIZE_MAX)
                break;
            used[best] = true;
            dep[(*nd)++] = cols[best];
            for (size_t r = 0; r < nr; r++)
                v[r] = w->Cz[rows[r] * nv + cols[best]];
            for (size_t k = 0; k < rank; k++) {
                double dot = 0;
                for (size_t r = 0; r < nr; r++)
                    dot += Q[k * nr + r] * v[r];
                for (size_t r = 0; r < nr; r++)
                    v[r] -= dot * Q[k * nr + r];
            }
            for (size_t r = 0; r < nr; r++)
                Q[rank * nr + r] = v[r] / bn;
            rank++;
        }
    return rank;
}

static bool occurs(const qd_eom *e, const qd_expr *q) {
    for (size_t i = 0; i < e->n * e->n; i++)
        if (qd_has(e->M[i], q))
            return true;
    for (size_t i = 0; i < e->n; i++)
        if (qd_has(e->f[i], q))
            return true;
    return false;
}

static int cmp_size(const void *a, const void *b) {
    size_t x = *(const size_t *)a, y = *(const size_t *)b;
    return x < y ? -1 : x > y;
}

/* The dependent states at the point: coordinates from d phi/dq, velocities
 * from A: those of the dependent coordinates first, then those of the
 * coordinates M and f do not involve, then the others, and last the
 * velocities the point gives a value other than 0 (the rolling disc's spin:
 * what the caller set stays set). */
static qd_status choose(cl_work *w, size_t *dep, bool coords_given) {
    size_t n = w->n, nd = coords_given ? w->nh : 0, d = w->d;
    size_t *rows = qd__calloc(w->ctx, d + 2 * n + 2, sizeof *rows), *cols = rows + d + 1;
    int *cls = qd__calloc(w->ctx, 2 * n + 1, sizeof *cls);
    double *Q = qd__calloc(w->ctx, d * (d + 1) + d + 1, sizeof *Q);
    bool *used = qd__calloc(w->ctx, 2 * n + 1, sizeof *used);
    piv_scratch sc = {used, Q ? Q + d * (d + 1) : NULL, Q};
    qd_status st = rows && cls && Q && used ? QD_OK : QD_ERR_NOMEM;
    if (st == QD_OK) {
        for (size_t r = 0; r < w->nh; r++)
            rows[r] = r;
        for (size_t j = 0; j < n; j++)
            cols[j] = j;
        if (w->nh && !coords_given &&
            pivots(w, rows, w->nh, cols, n, NULL, dep, &nd, &sc) < w->nh) {
            qd_ctx_error(w->ctx, QD_ERR_ARG, "the holonomic constraints are not independent at "
                         "the point (d phi/dq has rank below %zu): give another point", w->nh);
            st = QD_ERR_ARG;
        }
    }
    if (st == QD_OK) {
        for (size_t r = 0; r < w->nc; r++)
            rows[r] = w->nh + r;
        for (size_t j = 0; j < n; j++) {
            bool depq = false;
            for (size_t k = 0; k < w->nh; k++)
                depq = depq || dep[k] == j;
            cols[j] = n + j;
            bool speed = false;
            for (size_t i = 0; i < qd_model_nspeeds(w->m); i++)
                speed = speed || speed_velocity(w->m, i) == w->e->qd[j];
            cls[j] = depq ? 0 : w->val[n + j] != 0 || speed ? 3 : occurs(w->e, w->e->q[j]) ? 2 : 1;
        }
        if (pivots(w, rows, w->nc, cols, n, cls, dep, &nd, &sc) < w->nc) {
            qd_ctx_error(w->ctx, QD_ERR_ARG, "the velocity constraints are not independent at "
                         "the point (their coefficients have rank below %zu)", w->nc);
            st = QD_ERR_ARG;
        }
    }
    if (st == QD_OK)
        qsort(dep, d, sizeof *dep, cmp_size);
    qd__free(rows);
    qd__free(cls);
    qd__free(Q);
    qd__free(used);
    return st;
}

/* "x, q2, q5'": the independent states named, as the complement into dep. */
static qd_status read_indep(cl_work *w, const char *text, size_t *dep, bool *coords_only) {
    size_t n = w->n, nq = 0, nv = 0;
    bool *named = qd__calloc(w->ctx, 2 * n + 1, sizeof *named);
    if (!named)
        return QD_ERR_NOMEM;
    qd_status st = QD_OK;
    size_t i = 0, len = strlen(text);
    while (st == QD_OK && i < len) {
        while (i < len && (text[i] == ',' || text[i] == ' ' || text[i] == '\t'))
            i++;
        size_t s = i;
        while (i < len && text[i] != ',' && text[i] != ' ' && text[i] != '\t')
            i++;
        if (i == s)
            break;
        size_t l = i - s, primes = 0;
        while (primes < l && text[i - 1 - primes] == '\'')
            primes++;
        size_t found = SIZE_MAX;
        for (size_t j = 0; j < n && primes <= 1; j++) {
            const char *nm = qd_expr_name(w->e->q[j]);
            if (strlen(nm) == l - primes && !strncmp(nm, text + s, l - primes))
                found = primes ? n + j : j;
        }
        if (found == SIZE_MAX || named[found]) {
            qd_ctx_error(w->ctx, QD_ERR_ARG, found == SIZE_MAX
                         ? "'%.*s' is no coordinate or velocity of the equations"
                         : "'%.*s' is named twice", (int)l, text + s);
            qd_ctx_error_at(w->ctx, text, s, l);
            st = QD_ERR_ARG;
        } else {
            named[found] = true;
            if (found < n)
                nq++;
            else
                nv++;
        }
    }
    *coords_only = st == QD_OK && nv == 0 && nq == n - w->nh;
    if (st == QD_OK && !*coords_only && (nq != n - w->nh || nv != n - w->nc)) {
        qd_ctx_error(w->ctx, QD_ERR_ARG, "the independent states are %zu coordinates and %zu "
                     "velocities, or the coordinates alone (%zu coordinates, %zu holonomic "
                     "constraints, %zu in all), not %zu and %zu", n - w->nh, n - w->nc, n,
                     w->nh, w->nc, nq, nv);
        qd_ctx_error_at(w->ctx, text, 0, len);
        st = QD_ERR_ARG;
    }
    for (size_t k = 0, nd = 0; st == QD_OK && k < (*coords_only ? n : 2 * n); k++)
        if (!named[k])
            dep[nd++] = k; /* coordinates alone: their velocities are chosen (choose) */
    qd__free(named);
    return st;
}

/* ---- the point on the manifold -------------------------------------------------- */

/* C_D, the constraint functions' Jacobian in the dependent states (d*d,
 * column-major for LAPACK). */
static void dep_block(const cl_work *w, const size_t *dep, double *K) {
    size_t nv = 2 * w->n + w->nu, d = w->d;
    for (size_t r = 0; r < d; r++)
        for (size_t c = 0; c < d; c++)
            K[r + c * d] = w->Cz[r * nv + dep[c]];
}

static const char *state_name(const cl_work *w, size_t k, char *buf, size_t cap) {
    snprintf(buf, cap, "%s%s", qd_expr_name(w->e->q[k % w->n]), k >= w->n ? "'" : "");
    return buf;
}

/* Newton on C(z) = 0 moving the dependent states only. */
static qd_status newton(cl_work *w, const size_t *dep, double *moved, double *residual) {
    size_t d = w->d;
    int di = (int)d, one = 1, info = 0;
    double *K = qd__calloc(w->ctx, d * d + d + 1, sizeof *K), *r = K ? K + d * d : NULL;
    int *piv = qd__calloc(w->ctx, d + 1, sizeof *piv);
    double *z0 = qd__calloc(w->ctx, d + 1, sizeof *z0);
    qd_status st = K && piv && z0 ? QD_OK : QD_ERR_NOMEM;
    for (size_t c = 0; c < d && st == QD_OK; c++)
        z0[c] = w->val[dep[c]];
    double res = INFINITY, scale = 1;
    for (size_t c = 0; c < d && st == QD_OK; c++)
        scale = fmax(scale, fabs(z0[c]));
    for (int it = 0; st == QD_OK && it < NEWTON_ITERS; it++) {
        st = con_eval(w);
        if (st != QD_OK)
            break;
        res = 0;
        for (size_t c = 0; c < d; c++)
            res = fmax(res, fabs(w->C[c]));
        if (res <= 1e-14 * scale && it > 0)
            break;
        dep_block(w, dep, K);
        memcpy(r, w->C, d * sizeof *r);
        dgesv_(&di, &one, K, &di, piv, r, &di, &info);
        if (info != 0) {
            char nm[160];
            qd_ctx_error(w->ctx, QD_ERR_ARG, "the dependent states do not follow from the "
                         "constraints at the point (their Jacobian is singular at %s): name "
                         "others with --independent", state_name(w, dep[info - 1], nm, sizeof nm));
            st = QD_ERR_ARG;
            break;
        }
        for (size_t c = 0; c < d; c++)
            w->val[dep[c]] -= r[c];
    }
    if (st == QD_OK && !(res <= 1e-10 * scale)) {
        qd_ctx_error(w->ctx, QD_ERR_ARG, "Newton did not reach the constraint manifold from the "
                     "point (residual %.3g after %d steps): give a point nearer it",
                     res, NEWTON_ITERS);
        st = QD_ERR_ARG;
    }
    *moved = 0;
    for (size_t c = 0; c < d && st == QD_OK; c++)
        *moved = fmax(*moved, fabs(w->val[dep[c]] - z0[c]));
    *residual = res;
    qd__free(K);
    qd__free(piv);
    qd__free(z0);
    return st;
}

/* The caller's choice failed at the point: the error says which states
 * the library would take there ("e.g. independent x, x'"), from the
 * point as given. */
static void suggest(cl_work *w, const double *given) {
    size_t d = w->d, n = w->n;
    size_t *dep = qd__calloc(w->ctx, d + 1, sizeof *dep);
    char why[512];
    snprintf(why, sizeof why, "%s", qd_ctx_message(w->ctx));
    memcpy(w->val, given, 2 * n * sizeof *w->val);
    qd_status st = dep ? con_eval(w) : QD_ERR_NOMEM;
    qd_ctx_clear_error(w->ctx);
    if (st == QD_OK && choose(w, dep, false) == QD_OK) {
        qd_buf b = QD_BUF_INIT;
        char nm[160];
        for (size_t k = 0, dd = 0, i = 0; k < 2 * n; k++) {
            if (dd < d && dep[dd] == k)
                dd++;
            else
                qd_buf_printf(&b, "%s%s", i++ ? ", " : "", state_name(w, k, nm, sizeof nm));
        }
        qd_ctx_clear_error(w->ctx);
        qd_ctx_error(w->ctx, QD_ERR_ARG, "%s; e.g. --independent \"%s\"", why,
                     b.failed ? "..." : qd_buf_str(&b));
        qd_buf_free(&b);
    } else {
        qd_ctx_clear_error(w->ctx);
        qd_ctx_error(w->ctx, QD_ERR_ARG, "%s", why);
    }
    qd__free(dep);
}

/* ---- the Jacobians ------------------------------------------------------------- */

/* dF/d(z, u) (2n rows, nv = 2n + nu columns) at the point, and q'' there. */
static qd_status flow_jacobian(cl_work *w, double *dF, double *g, double *lambda) {
    size_t n = w->n, nc = w->nc, nv = 2 * n + w->nu, s = n + nc;
    size_t nout = qd_tangent_nout(w->dyn);
    double *y = qd__calloc(w->ctx, nout + nout * nv + s * s + s * (nv + 1) + 1, sizeof *y);
    int *piv = qd__calloc(w->ctx, s + 1, sizeof *piv);
    if (!y || !piv) {
        qd__free(y);
        qd__free(piv);
        return QD_ERR_NOMEM;
    }
    double *J = y + nout, *K = J + nout * nv, *X = K + s * s; /* X: s x (1 + nv), col-major */
    const double *M = y, *f = y + n * n, *A = f + n, *b = A + nc * n;
    qd_status st = qd_tangent_jacobian(w->ctx, w->dyn, w->val, y, J);
    for (size_t i = 0; st == QD_OK && i < n; i++) {
        for (size_t j = 0; j < n; j++)
            K[i + j * s] = M[i * n + j];
        for (size_t c = 0; c < nc; c++) {
            K[i + (n + c) * s] = -A[c * n + i];
            K[n + c + i * s] = A[c * n + i];
        }
        X[i] = f[i];
    }
    for (size_t c = 0; st == QD_OK && c < nc; c++)
        X[n + c] = b[c];
    int si = (int)s, one = 1, nrhs = (int)nv, info = 0;
    if (st == QD_OK) {
        double *Kc = qd__malloc(w->ctx, (s * s + 1) * sizeof *Kc);
        if (!Kc)
            st = QD_ERR_NOMEM;
        else {
            memcpy(Kc, K, s * s * sizeof *Kc);
            dgesv_(&si, &one, Kc, &si, piv, X, &si, &info);
            qd__free(Kc);
        }
        if (st == QD_OK && info != 0) {
            qd_ctx_error(w->ctx, QD_ERR_SINGULAR, "the saddle-point matrix [M -A^T; A 0] is "
                         "singular at the point (the constraints are redundant there, or M is "
                         "singular)");
            st = QD_ERR_SINGULAR;
        }
    }
    /* the right-hand sides: d[f; b] - dK (q'', lambda) */
    double *R = X + s;
    for (size_t k = 0; st == QD_OK && k < nv; k++) {
        const double *dM = J + k, *df = J + n * n * nv + k;
        const double *dA = df + n * nv, *db = dA + nc * n * nv;
        for (size_t i = 0; i < n; i++) {
            double r = df[i * nv];
            for (size_t j = 0; j < n; j++)
                r -= dM[(i * n + j) * nv] * X[j];
            for (size_t c = 0; c < nc; c++)
                r += dA[(c * n + i) * nv] * X[n + c];
            R[k * s + i] = r;
        }
        for (size_t c = 0; c < nc; c++) {
            double r = db[c * nv];
            for (size_t j = 0; j < n; j++)
                r -= dA[(c * n + j) * nv] * X[j];
            R[k * s + n + c] = r;
        }
    }
    if (st == QD_OK)
        dgesv_(&si, &nrhs, K, &si, piv, R, &si, &info);
    for (size_t c = 0; st == QD_OK && c < nc; c++)
        lambda[c] = X[n + c];
    for (size_t i = 0; st == QD_OK && i < n; i++) {
        g[i] = X[i];
        for (size_t k = 0; k < nv; k++) {
            dF[i * nv + k] = k == n + i ? 1 : 0;
            dF[(n + i) * nv + k] = R[k * s + i];
        }
    }
    qd__free(y);
    qd__free(piv);
    return st;
}

/* T = dz/dx (2n * nx): the identity in the independent rows, -C_D^-1 C_I in
 * the dependent ones. */
static qd_status tangent_basis(cl_work *w, const size_t *indep, size_t nx, const size_t *dep,
                               double *T) {
    size_t d = w->d, nv = 2 * w->n + w->nu;
    int di = (int)d, nr = (int)nx, info = 0;
    double *K = qd__calloc(w->ctx, d * d + d * nx + 1, sizeof *K), *X = K ? K + d * d : NULL;
    int *piv = qd__calloc(w->ctx, d + 1, sizeof *piv);
    qd_status st = K && piv ? con_eval(w) : QD_ERR_NOMEM;
    if (st == QD_OK) {
        dep_block(w, dep, K);
        for (size_t r = 0; r < d; r++)
            for (size_t c = 0; c < nx; c++)
                X[r + c * d] = w->Cz[r * nv + indep[c]];
        if (d)
            dgesv_(&di, &nr, K, &di, piv, X, &di, &info);
        if (info != 0) {
            qd_ctx_error(w->ctx, QD_ERR_ARG, "the dependent states do not follow from the "
                         "constraints at the point: name others with --independent");
            st = QD_ERR_ARG;
        }
    }
    for (size_t c = 0; st == QD_OK && c < nx; c++) {
        T[indep[c] * nx + c] = 1;
        for (size_t r = 0; r < d; r++)
            T[dep[r] * nx + c] = -X[r + c * d];
    }
    qd__free(K);
    qd__free(piv);
    return st;
}

/* ---- ignorable states and the core --------------------------------------------- */

static void mark_ignorable(qd_conlin *c) {
    size_t nx = c->nx;
    double *A = c->ss.A;
    double big = 0;
    for (size_t i = 0; i < nx * nx; i++)
        big = fmax(big, fabs(A[i]));
    for (bool grew = true; grew;) {
        grew = false;
        for (size_t k = 0; k < nx; k++) {
            if (c->ignorable[k])
                continue;
            double col = 0;
            for (size_t i = 0; i < nx; i++)
                if (!c->ignorable[i])
                    col = fmax(col, fabs(A[i * nx + k]));
            if (col <= IGNORABLE_TOL * big) { /* rounding of an exact 0: made one */
                c->ignorable[k] = grew = true;
                for (size_t i = 0; i < nx; i++)
                    if (!c->ignorable[i])
                        A[i * nx + k] = 0;
            }
        }
    }
    c->ncore = 0;
    for (size_t k = 0; k < nx; k++)
        c->ncore += !c->ignorable[k];
}

extern void dgeev_(const char *jobvl, const char *jobvr, const int *n, double *a, const int *lda,
                   double *wr, double *wi, double *vl, const int *ldvl, double *vr,
                   const int *ldvr, double *work, const int *lwork, int *info);

static int by_re(const void *pa, const void *pb) {
    const double *a = pa, *b = pb;
    return a[0] > b[0] ? -1 : a[0] < b[0] ? 1 : a[1] > b[1] ? -1 : a[1] < b[1];
}

static qd_status core_eigen(qd_ctx *ctx, qd_conlin *c) {
    size_t m = c->ncore, nx = c->nx;
    if (!m)
        return QD_OK;
    int mi = (int)m, info = 0, lwork = (int)(8 * m + 16), one = 1;
    double *a = qd__calloc(ctx, m * m + 2 * m + (size_t)lwork + 2 * m + 1, sizeof *a);
    c->core_re = qd__calloc(ctx, 2 * m + 1, sizeof *c->core_re);
    if (!a || !c->core_re) {
        qd__free(a);
        return QD_ERR_NOMEM;
    }
    c->core_im = c->core_re + m;
    double *wr = a + m * m, *wi = wr + m, *work = wi + m;
    size_t r = 0;
    for (size_t i = 0; i < nx; i++) {
        if (c->ignorable[i])
            continue;
        size_t k = 0;
        for (size_t j = 0; j < nx; j++)
            if (!c->ignorable[j])
                a[r + (k++) * m] = c->ss.A[i * nx + j];
        r++;
    }
    double vdummy = 0;
    dgeev_("N", "N", &mi, a, &mi, wr, wi, &vdummy, &one, &vdummy, &one, work, &lwork, &info);
    if (info != 0) {
        qd__free(a);
        qd_ctx_error(ctx, QD_ERR_NUMERIC, "the eigen-solver (dgeev) failed: info %d", info);
        return QD_ERR_NUMERIC;
    }
    double *pr = qd__calloc(ctx, 2 * m + 1, sizeof *pr);
    if (!pr) {
        qd__free(a);
        return QD_ERR_NOMEM;
    }
    for (size_t k = 0; k < m; k++) {
        pr[2 * k] = wr[k];
        pr[2 * k + 1] = wi[k];
    }
    qsort(pr, m, 2 * sizeof *pr, by_re);
    for (size_t k = 0; k < m; k++) {
        c->core_re[k] = pr[2 * k];
        c->core_im[k] = pr[2 * k + 1];
    }
    qd__free(pr);
    qd__free(a);
    return QD_OK;
}

/* The eigenvalues of the ignorable states are exactly 0: dgeev's nearest
 * ones (within 1e-8 of the spectrum's scale: rounding) are set to 0. */
static void zero_ignorable(qd_conlin *c) {
    qd_statespace *s = &c->ss;
    double big = 1;
    for (size_t j = 0; j < s->nx; j++)
        big = fmax(big, hypot(s->eig_re[j], s->eig_im[j]));
    size_t left = c->nx - c->ncore;
    for (size_t j = 0; j < s->nx && left; j++)
        left -= s->eig_re[j] == 0 && s->eig_im[j] == 0;
    for (; left; left--) {
        size_t best = SIZE_MAX;
        double bv = 1e-8 * big;
        for (size_t j = 0; j < s->nx; j++) {
            double a = hypot(s->eig_re[j], s->eig_im[j]);
            if (a != 0 && a <= bv) {
                bv = a;
                best = j;
            }
        }
        if (best == SIZE_MAX)
            break;
        s->eig_re[best] = s->eig_im[best] = 0;
    }
}

/* ---- the linearization ------------------------------------------------------- */

void qd_conlin_free(qd_conlin *c) {
    if (!c)
        return;
    qd__free(c->indep);
    qd__free(c->z);
    qd__free(c->zsym);
    qd__free(c->ignorable);
    qd__free(c->core_re);
    qd__free(c->lambda);
    qd__free(c->lambda_sym);
    qd_statespace_free(&c->ss);
    memset(c, 0, sizeof *c);
}

static qd_status setup(cl_work *w, const qd_eom *e, const qd_model *m, const qd_linpoint *pt,
                       qd_conlin *c) {
    size_t n = e->n;
    w->e = e;
    w->m = m;
    w->n = n;
    w->nc = e->ncon;
    w->nu = qd_model_ninputs(m);
    w->hol = qd__calloc(w->ctx, e->ncon + 1, sizeof *w->hol);
    if (!w->hol)
        return QD_ERR_NOMEM;
    for (size_t k = 0; k < e->ncon; k++)
        if (e->con[k].kind == QD_CON_HOLONOMIC)
            w->hol[w->nh++] = k;
    w->d = w->nh + w->nc;
    if (2 * n < w->d) {
        qd_ctx_error(w->ctx, QD_ERR_ARG, "more constraints than states");
        return QD_ERR_ARG;
    }
    *c = (qd_conlin){.n = n, .nhol = w->nh, .ncon = w->nc, .nx = 2 * n - w->d};
    c->indep = qd__calloc(w->ctx, 2 * n + 1, sizeof *c->indep);
    c->z = qd__calloc(w->ctx, 4 * n + 1, sizeof *c->z);
    c->ignorable = qd__calloc(w->ctx, c->nx + 1, sizeof *c->ignorable);
    c->zsym = qd__calloc(w->ctx, 2 * n + 1, sizeof *c->zsym);
    c->lambda = qd__calloc(w->ctx, w->nc + 1, sizeof *c->lambda);
    c->lambda_sym = qd__calloc(w->ctx, w->nc + 1, sizeof *c->lambda_sym);
    if (!c->indep || !c->z || !c->ignorable || !c->zsym || !c->lambda || !c->lambda_sym)
        return QD_ERR_NOMEM;
    for (size_t k = 0; k < w->nc; k++)
        c->lambda_sym[k] = e->con[k].lambda;
    for (size_t j = 0; j < n; j++) {
        c->zsym[j] = e->q[j];
        c->zsym[n + j] = e->qd[j];
    }
    c->dep = c->indep + c->nx;
    c->given = c->z + 2 * n;
    qd_status st = make_inputs(w, m, &pt->st);
    return st == QD_OK ? make_tangents(w) : st;
}

/* The outputs' rows: C = (dh/dz) T, D = dh/du and y at the point. */
static qd_status fill_outputs(cl_work *w, qd_statespace *s, const double *T) {
    size_t n = w->n, nx = s->nx, nu = w->nu, ny = s->ny, nv = 2 * n + nu;
    if (!ny)
        return QD_OK;
    double *J = qd__calloc(w->ctx, ny * nv + 1, sizeof *J);
    qd_status st = J ? qd_tangent_jacobian(w->ctx, w->out, w->val, s->y0, J) : QD_ERR_NOMEM;
    for (size_t i = 0; st == QD_OK && i < ny; i++) {
        for (size_t j = 0; j < nx; j++) {
            double a = 0;
            for (size_t r = 0; r < 2 * n; r++)
                a += J[i * nv + r] * T[r * nx + j];
            s->C[i * nx + j] = a;
        }
        for (size_t u = 0; u < nu; u++)
            s->D[i * nu + u] = J[i * nv + 2 * n + u];
    }
    qd__free(J);
    return st;
}

/* The states' symbols and the numbers of A, B, C, D, x' and y into c->ss
 * (one block, as qd_statespace_free frees it). */
static qd_status fill_ss(cl_work *w, const qd_model *m, qd_conlin *c, const double *dF,
                         const double *g, const double *T) {
    size_t n = w->n, nx = c->nx, nu = w->nu, nv = 2 * n + nu, ny = qd_model_noutputs(m);
    qd_statespace *s = &c->ss;
    s->nx = nx;
    s->nu = nu;
    s->ny = ny;
    s->states = qd__calloc(w->ctx, nx + nu + 1, sizeof *s->states);
    s->outputs = qd__calloc(w->ctx, ny + 1, sizeof *s->outputs);
    s->A = qd__calloc(w->ctx, nx * nx + nx * nu + ny * (nx + nu) + nx + ny + 1, sizeof *s->A);
    if (!s->states || !s->outputs || !s->A)
        return QD_ERR_NOMEM;
    s->inputs = s->states + nx;
    s->B = s->A + nx * nx;
    s->C = s->B + nx * nu;
    s->D = s->C + ny * nx;
    s->xdot0 = s->D + ny * nu;
    s->y0 = s->xdot0 + nx;
    for (size_t i = 0; i < nx; i++) {
        size_t k = c->indep[i];
        s->states[i] = k < n ? w->e->q[k] : w->e->qd[k - n];
        s->n += k < n;
        s->xdot0[i] = k < n ? w->val[n + k] : g[k - n];
        for (size_t j = 0; j < nx; j++) {
            double a = 0;
            for (size_t r = 0; r < 2 * n; r++)
                a += dF[k * nv + r] * T[r * nx + j];
            s->A[i * nx + j] = a;
        }
        for (size_t u = 0; u < nu; u++)
            s->B[i * nu + u] = dF[k * nv + 2 * n + u];
    }
    for (size_t u = 0; u < nu; u++)
        s->inputs[u] = qd_model_input(m, u);
    for (size_t i = 0; i < ny; i++)
        s->outputs[i] = qd_model_output_name(m, i);
    return fill_outputs(w, s, T);
}

/* The verdict from the core: unstable above the tolerance (qdot/conlin.h). */
static void judge(qd_conlin *c) {
    double big = 1;
    for (size_t k = 0; k < c->ncore; k++)
        big = fmax(big, hypot(c->core_re[k], c->core_im[k]));
    c->tol = QD_CONLIN_MARGIN_TOL * big;
    c->margin = c->ncore ? c->core_re[0] : -INFINITY;
    double scale = 1, moving = 0;
    for (size_t k = 0; k < 2 * c->n; k++)
        scale = fmax(scale, fabs(c->z[k]));
    for (size_t i = 0; i < c->nx; i++)
        if (!c->ignorable[i])
            moving = fmax(moving, fabs(c->ss.xdot0[i]));
    c->steady = moving <= 1e-9 * scale;
    c->stable = c->steady && c->margin <= c->tol;
    c->marginal = c->stable && c->margin >= -c->tol;
}

qd_status qd_conlin_about(qd_ctx *ctx, const qd_eom *e, const qd_model *m, const qd_linpoint *pt,
                          const char *independent, qd_conlin *out) {
    if (!ctx || !e || !m || !pt || !out) {
        if (ctx)
            qd_ctx_error(ctx, QD_ERR_ARG, "qd_conlin_about: the equations, model, point and "
                         "result are needed");
        return QD_ERR_ARG;
    }
    *out = (qd_conlin){0};
    if (!e->ncon) {
        qd_ctx_error(ctx, QD_ERR_UNSUPPORTED, "the equations keep no constraints: linearize "
                     "them as they are (qd_linearize)");
        return QD_ERR_UNSUPPORTED;
    }
    cl_work w = {.ctx = ctx};
    qd_status st = setup(&w, e, m, pt, out);
    size_t n = e->n, nx = out->nx, nv = 2 * n + w.nu;
    double *dF = NULL, *g = NULL, *T = NULL;
    bool coords_only = false;
    if (st == QD_OK)
        st = independent ? read_indep(&w, independent, out->dep, &coords_only) : QD_OK;
    if (st == QD_OK && (!independent || coords_only))
        st = con_eval(&w);
    if (st == QD_OK && (!independent || coords_only))
        st = choose(&w, out->dep, coords_only);
    for (size_t k = 0; st == QD_OK && k < 2 * n; k++)
        out->given[k] = w.val[k];
    if (st == QD_OK)
        st = newton(&w, out->dep, &out->moved, &out->residual);
    if (st == QD_ERR_ARG && independent)
        suggest(&w, out->given);
    for (size_t k = 0, i = 0, dd = 0; st == QD_OK && k < 2 * n; k++) {
        if (dd < w.d && out->dep[dd] == k)
            dd++;
        else
            out->indep[i++] = k;
    }
    if (st == QD_OK) {
        dF = qd__calloc(ctx, 2 * n * nv + n + 2 * n * nx + 1, sizeof *dF);
        st = dF ? flow_jacobian(&w, dF, g = dF + 2 * n * nv, out->lambda) : QD_ERR_NOMEM;
        T = dF ? g + n : NULL;
    }
    if (st == QD_OK)
        st = tangent_basis(&w, out->indep, nx, out->dep, T);
    if (st == QD_OK)
        st = fill_ss(&w, m, out, dF, g, T);
    for (size_t k = 0; st == QD_OK && k < 2 * n; k++)
        out->z[k] = w.val[k];
    if (st == QD_OK) {
        mark_ignorable(out);
        st = qd__lin_ss_analyse(ctx, &out->ss);
    }
    if (st == QD_OK)
        st = core_eigen(ctx, out);
    if (st == QD_OK) {
        zero_ignorable(out);
        judge(out);
    }
    if (st == QD_ERR_NOMEM && qd_ctx_status(ctx) == QD_OK)
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory linearizing on the constraint manifold");
    qd__free(dF);
    work_free(&w);
    return st;
}

/* A speed defined as one velocity (u2 = q2'): that velocity, else NULL. */
static const qd_expr *speed_velocity(const qd_model *m, size_t i) {
    const qd_expr *d = qd_model_speed_definition(m, i);
    return d && qd_expr_kind(d) == QD_SYMBOL && qd_symbol_order(d) == 1 ? d : NULL;
}

/* The speeds' initial values (`initial u3 = v/rr`) into their velocities. */
static qd_status speeds_initial(qd_ctx *ctx, const qd_model *m, qd_state *st, bool about) {
    for (size_t i = 0; i < qd_model_nspeeds(m); i++) {
        const qd_expr *u0 = qd_model_speed_initial(m, i), *v = speed_velocity(m, i);
        size_t k = v ? qd_state_find(st, v) : st->n;
        if (u0 && k < st->n)
            st->vals[k] = qd_number_value(u0);
        else if (u0 && !about) {
            qd_ctx_error(ctx, QD_ERR_UNSUPPORTED, "the speed %s is not one velocity, so its "
                         "initial value does not give the point: give the velocities with "
                         "--about", qd_expr_name(qd_model_speed(m, i)));
            return QD_ERR_UNSUPPORTED;
        }
    }
    return QD_OK;
}

qd_status qd_conlin_point(qd_ctx *ctx, const qd_model *m, qd_linpoint *pt, const char *about) {
    if (!ctx || !m || !pt)
        return QD_ERR_ARG;
    qd_status st = qd_state_initial(ctx, m, &pt->st);
    if (st == QD_OK)
        st = speeds_initial(ctx, m, &pt->st, about != NULL);
    qd_state_read_opts o = {.refuse = QD_STATE_TIME | QD_STATE_PARAMS | QD_STATE_EXTRA};
    if (st == QD_OK && about)
        st = qd_state_read(ctx, m, &pt->st, about, &o);
    return st;
}

qd_status qd_conlin_keep_core(qd_ctx *ctx, qd_conlin *c) {
    if (!ctx || !c || !c->ss.A)
        return QD_ERR_ARG;
    const qd_statespace *o = &c->ss;
    size_t m = c->ncore, nu = o->nu, nx = o->nx, ny = o->ny;
    qd_statespace s = {.nx = m, .nu = nu, .ny = ny};
    s.states = qd__calloc(ctx, m + nu + 1, sizeof *s.states);
    s.outputs = qd__calloc(ctx, ny + 1, sizeof *s.outputs);
    s.A = qd__calloc(ctx, m * m + m * nu + ny * (m + nu) + m + ny + 1, sizeof *s.A);
    if (!s.states || !s.outputs || !s.A) {
        qd_statespace_free(&s);
        return QD_ERR_NOMEM;
    }
    s.inputs = s.states + m;
    s.B = s.A + m * m;
    s.C = s.B + m * nu;
    s.D = s.C + ny * m;
    s.xdot0 = s.D + ny * nu;
    s.y0 = s.xdot0 + m;
    for (size_t i = 0; i < ny; i++) { /* the ignorable states' columns of C left out */
        s.outputs[i] = o->outputs[i];
        s.y0[i] = o->y0[i];
        for (size_t j = 0, k = 0; j < nx; j++)
            if (!c->ignorable[j])
                s.C[i * m + k++] = o->C[i * nx + j];
        for (size_t u = 0; u < nu; u++)
            s.D[i * nu + u] = o->D[i * nu + u];
    }
    for (size_t i = 0, r = 0; i < nx; i++) {
        if (c->ignorable[i])
            continue;
        s.states[r] = o->states[i];
        s.n += c->indep[i] < c->n;
        s.xdot0[r] = o->xdot0[i];
        for (size_t j = 0, k = 0; j < nx; j++)
            if (!c->ignorable[j])
                s.A[r * m + k++] = o->A[i * nx + j];
        for (size_t u = 0; u < nu; u++)
            s.B[r * nu + u] = o->B[i * nu + u];
        r++;
    }
    for (size_t u = 0; u < nu; u++)
        s.inputs[u] = o->inputs[u];
    qd_status st = qd__lin_ss_analyse(ctx, &s);
    if (st != QD_OK) {
        qd_statespace_free(&s);
        return st;
    }
    qd_statespace_free(&c->ss);
    c->ss = s;
    return QD_OK;
}

/*
 * src/linear/statespace.c - x' = A x + B u, y = C x + D u about an
 * operating point (qdot/statespace.h).
 *
 * Differentiating M q'' = f with q'' held at its value at the point,
 *     M dq'' + (dM/dz) q''0 = df/dz   =>   dq''/dz = M^-1 (df/dz - dM/dz q''0),
 * z running over the coordinates, the velocities and the inputs (the same
 * Jacobian as SymPy's KanesMethod.linearize gives from its linearizer).
 * The partial derivatives are taken on the symbolic M and f, and the point
 * is put in exactly before anything is solved, so that the numbers (dgesv)
 * and the expressions (fraction-free elimination) come from the same
 * entries.  The eigen-analysis and the rank tests are in kalman.c.
 */
#include "linear.h"
#include "ss.h"

#include "base/mem.h"
#include "mech/mech_export.h"
#include "num/num.h"
#include "../base/args.h"

#include <math.h>
#include <string.h>

/* LAPACK, column-major */
extern void dgesv_(const int *n, const int *nrhs, double *a, const int *lda, int *ipiv,
                   double *b, const int *ldb, int *info);

/* The entries at the point, before any solve (z = q, q', u: nz of them). */
typedef struct entries {
    size_t n, nz, ny;
    const qd_expr **M0, **f0;  /* n*n, n */
    const qd_expr **Fz;        /* n*nz: df_j/dz */
    const qd_expr **Mz;        /* n*n*nz: dM_jl/dz at [(j*n + l)*nz + z] */
    const qd_expr **Yz, **y0;  /* ny*nz, ny */
    size_t count;              /* all of them, one block */
    const qd_expr **all;
} entries;

static void entries_free(entries *E) { qd__free(E->all); }

static qd_status entries_alloc(qd_ctx *ctx, entries *E, size_t n, size_t nz, size_t ny) {
    E->n = n;
    E->nz = nz;
    E->ny = ny;
    E->count = n * n + n + n * nz + n * n * nz + ny * nz + ny;
    E->all = qd__calloc(ctx, E->count + 1, sizeof *E->all);
    if (!E->all)
        return QD_ERR_NOMEM;
    E->M0 = E->all;
    E->f0 = E->M0 + n * n;
    E->Fz = E->f0 + n;
    E->Mz = E->Fz + n * nz;
    E->Yz = E->Mz + n * n * nz;
    E->y0 = E->Yz + ny * nz;
    return QD_OK;
}

/* The symbol z_k: q_k, q'_k, then the inputs. */
static const qd_expr *zsym(const qd_statespace *s, size_t k) {
    return k < s->nx ? s->states[k] : s->inputs[k - s->nx];
}

static const qd_expr *at(qd_ctx *ctx, const qd_expr *x, const qd__point *pt) {
    return qd_simplify(ctx, qd_subs(ctx, x, pt->n, pt->from, pt->to));
}

static qd_status build_entries(qd_ctx *ctx, const qd_eom *e, const qd_model *m,
                               const qd_statespace *s, const qd__point *pt, entries *E) {
    size_t n = e->n, nz = s->nx + s->nu;
    for (size_t j = 0; j < n; j++) {
        E->f0[j] = at(ctx, e->f[j], pt);
        for (size_t l = 0; l < n; l++)
            E->M0[j * n + l] = at(ctx, e->M[j * n + l], pt);
        for (size_t k = 0; k < nz; k++) {
            E->Fz[j * nz + k] = at(ctx, qd_diff(ctx, e->f[j], zsym(s, k)), pt);
            for (size_t l = 0; l < n; l++)
                E->Mz[(j * n + l) * nz + k] = at(ctx, qd_diff(ctx, e->M[j * n + l], zsym(s, k)), pt);
        }
    }
    for (size_t i = 0; i < s->ny; i++) {
        const qd_expr *y = qd_model_output(m, i);
        E->y0[i] = at(ctx, y, pt);
        for (size_t k = 0; k < nz; k++)
            E->Yz[i * nz + k] = at(ctx, qd_diff(ctx, y, zsym(s, k)), pt);
    }
    return qd_ctx_status(ctx);
}

/* ---- numbers --------------------------------------------------------------- */

/* Every entry at the parameters' values; a free symbol that is not a
 * parameter (the point left it out: a coordinate's value is its own) is an
 * error naming it. */
static qd_status eval_entries(qd_ctx *ctx, const qd_model *m, const entries *E, double *out) {
    size_t nin = 0;
    const qd_expr **ins = qd__num_inputs(ctx, E->count, E->all, &nin);
    if (!ins)
        return qd_ctx_status(ctx) ? qd_ctx_status(ctx) : QD_ERR_NOMEM;
    double *in = qd__calloc(ctx, nin + 1, sizeof *in);
    qd_status st = in ? QD_OK : QD_ERR_NOMEM;
    for (size_t i = 0; st == QD_OK && i < nin; i++) {
        size_t p = 0, np = qd_model_nparams(m);
        while (p < np && qd_model_param(m, p) != ins[i])
            p++;
        if (p == np) {
            qd_ctx_error(ctx, QD_ERR_ARG, "'%s' has no value at the operating point",
                         qd_expr_name(ins[i]));
            st = QD_ERR_ARG;
            break;
        }
        st = qd_model_param_number(m, p, &in[i]);
    }
    qd_prog *prog = st == QD_OK ? qd_prog_new(ctx, nin, ins, E->count, E->all) : NULL;
    if (st == QD_OK && !prog)
        st = qd_ctx_status(ctx) ? qd_ctx_status(ctx) : QD_ERR_NOMEM;
    if (prog)
        qd_prog_run(prog, in, out);
    for (size_t i = 0; st == QD_OK && i < E->count; i++)
        if (!isfinite(out[i])) {
            qd_ctx_error(ctx, QD_ERR_NUMERIC, "the equations are not finite at the operating "
                         "point (a singularity of the model)");
            st = QD_ERR_NUMERIC;
        }
    qd_prog_free(prog);
    qd__free(in);
    qd__free(ins);
    return st;
}

/* X = M^-1 R (M n*n, R n*k, both row-major; X may be R). */
static qd_status num_solve(qd_ctx *ctx, size_t n, const double *M, size_t k, const double *R,
                           double *X) {
    int ni = (int)n, ki = (int)k, info = 0;
    double *a = qd__malloc(ctx, (n * n + n * k + 1) * sizeof *a), *b = a ? a + n * n : NULL;
    int *piv = qd__malloc(ctx, (n + 1) * sizeof *piv);
    qd_status st = a && piv ? QD_OK : QD_ERR_NOMEM;
    if (st == QD_OK) {
        for (size_t i = 0; i < n; i++) {
            for (size_t j = 0; j < n; j++)
                a[i + j * n] = M[i * n + j];
            for (size_t j = 0; j < k; j++)
                b[i + j * n] = R[i * k + j];
        }
        if (k)
            dgesv_(&ni, &ki, a, &ni, piv, b, &ni, &info);
        if (info != 0) {
            qd_ctx_error(ctx, QD_ERR_SINGULAR, "the mass matrix is singular at the operating "
                         "point");
            st = QD_ERR_SINGULAR;
        }
        for (size_t i = 0; st == QD_OK && i < n; i++)
            for (size_t j = 0; j < k; j++)
                X[i * k + j] = b[i + j * n];
    }
    qd__free(a);
    qd__free(piv);
    return st;
}

/* The numeric A, B, C, D, xdot0, y0 from the entries' values v. */
static qd_status numbers(qd_ctx *ctx, qd_statespace *s, const entries *E, const double *v,
                         const double *qd0) {
    size_t n = s->n, nz = E->nz, nx = s->nx;
    const double *M0 = v, *f0 = v + n * n, *Fz = f0 + n, *Mz = Fz + n * nz, *Yz = Mz + n * n * nz,
                 *y0 = Yz + s->ny * nz;
    double *acc = qd__malloc(ctx, (n + n * nz + 1) * sizeof *acc), *R = acc ? acc + n : NULL;
    qd_status st = acc ? num_solve(ctx, n, M0, 1, f0, acc) : QD_ERR_NOMEM;
    for (size_t j = 0; st == QD_OK && j < n; j++)
        for (size_t k = 0; k < nz; k++) {
            double r = Fz[j * nz + k];
            for (size_t l = 0; l < n; l++)
                r -= Mz[(j * n + l) * nz + k] * acc[l];
            R[j * nz + k] = r;
        }
    if (st == QD_OK)
        st = num_solve(ctx, n, M0, nz, R, R);
    for (size_t j = 0; st == QD_OK && j < n; j++) {
        s->A[j * nx + n + j] = 1;
        s->xdot0[j] = qd0[j];
        s->xdot0[n + j] = acc[j];
        for (size_t k = 0; k < nx; k++)
            s->A[(n + j) * nx + k] = R[j * nz + k];
        for (size_t k = 0; k < s->nu; k++)
            s->B[(n + j) * s->nu + k] = R[j * nz + nx + k];
    }
    for (size_t i = 0; st == QD_OK && i < s->ny; i++) {
        s->y0[i] = y0[i];
        for (size_t k = 0; k < nx; k++)
            s->C[i * nx + k] = Yz[i * nz + k];
        for (size_t k = 0; k < s->nu; k++)
            s->D[i * s->nu + k] = Yz[i * nz + nx + k];
    }
    qd__free(acc);
    return st;
}

/* ---- expressions ------------------------------------------------------------ */

static bool all_zero(size_t n, const qd_expr *const *x) {
    for (size_t i = 0; i < n; i++)
        if (!qd_is_zero(x[i]))
            return false;
    return true;
}

/* A failed symbolic solve: too large or singular is no error (the numbers
 * stand alone, Asym NULL); anything else (out of memory) is. */
static qd_status solve_status(qd_ctx *ctx, qd_status st, bool *ok) {
    if (st == QD_OK)
        return qd_ctx_status(ctx);
    *ok = false;
    if (st == QD_ERR_TOOBIG || st == QD_ERR_SINGULAR)
        return qd_ctx_status(ctx);
    return qd_ctx_status(ctx) ? qd_ctx_status(ctx) : st;
}

/* The symbolic dq''/dz by fraction-free elimination into the *sym arrays,
 * which are dropped (NULL) when it grows too large. */
static qd_status expressions(qd_ctx *ctx, qd_statespace *s, const entries *E) {
    size_t n = s->n, nz = E->nz, nx = s->nx;
    const qd_expr **acc = qd__calloc(ctx, n + 2 * n * nz + 1, sizeof *acc);
    if (!acc)
        return QD_ERR_NOMEM;
    const qd_expr **R = acc + n, **X = R + n * nz;
    bool ok = true;
    qd_status st = QD_OK;
    if (all_zero(n, E->f0))
        for (size_t j = 0; j < n; j++)
            acc[j] = qd_int(ctx, 0);
    else
        st = solve_status(ctx, qd__mech_solve_cols(ctx, n, E->M0, 1, E->f0, acc, QD_SS_MAX_OPS),
                          &ok);
    for (size_t j = 0; st == QD_OK && ok && j < n; j++)
        for (size_t k = 0; k < nz; k++) {
            const qd_expr *r = E->Fz[j * nz + k];
            for (size_t l = 0; l < n; l++)
                r = qd_sub(ctx, r, qd_mul(ctx, E->Mz[(j * n + l) * nz + k], acc[l]));
            R[j * nz + k] = qd_simplify(ctx, r);
        }
    if (st == QD_OK && ok)
        st = solve_status(ctx, qd__mech_solve_cols(ctx, n, E->M0, nz, R, X, QD_SS_MAX_OPS), &ok);
    for (size_t i = 0; st == QD_OK && ok && i < nx; i++)
        for (size_t k = 0; k < nx + s->nu; k++) {
            const qd_expr *x = i < n ? qd_int(ctx, k == n + i ? 1 : 0) : X[(i - n) * nz + k];
            if (k < nx)
                s->Asym[i * nx + k] = x;
            else
                s->Bsym[i * s->nu + k - nx] = x;
        }
    for (size_t i = 0; st == QD_OK && ok && i < s->ny; i++)
        for (size_t k = 0; k < nz; k++) {
            if (k < nx)
                s->Csym[i * nx + k] = E->Yz[i * nz + k];
            else
                s->Dsym[i * s->nu + k - nx] = E->Yz[i * nz + k];
        }
    qd__free(acc);
    if (st == QD_OK)
        st = qd_ctx_status(ctx);
    if (st != QD_OK || !ok) {
        qd__free(s->Asym);
        s->Asym = s->Bsym = s->Csym = s->Dsym = NULL;
    }
    return st;
}

/* ---- the whole ------------------------------------------------------------- */

static qd_status alloc_out(qd_ctx *ctx, const qd_eom *e, const qd_model *m, qd_statespace *s) {
    size_t n = e->n, nx = 2 * n, nu = qd_model_ninputs(m), ny = qd_model_noutputs(m);
    s->n = n;
    s->nx = nx;
    s->nu = nu;
    s->ny = ny;
    size_t nnum = nx * nx + nx * nu + ny * nx + ny * nu + nx + ny;
    s->states = qd__calloc(ctx, nx + nu + 1, sizeof *s->states);
    s->outputs = qd__calloc(ctx, ny + 1, sizeof *s->outputs);
    s->A = qd__calloc(ctx, nnum + 1, sizeof *s->A);
    s->Asym = qd__calloc(ctx, nnum + 1, sizeof *s->Asym);
    if (!s->states || !s->outputs || !s->A || !s->Asym)
        return QD_ERR_NOMEM;
    s->inputs = s->states + nx;
    s->B = s->A + nx * nx;
    s->C = s->B + nx * nu;
    s->D = s->C + ny * nx;
    s->xdot0 = s->D + ny * nu;
    s->y0 = s->xdot0 + nx;
    s->Bsym = s->Asym + nx * nx;
    s->Csym = s->Bsym + nx * nu;
    s->Dsym = s->Csym + ny * nx;
    for (size_t j = 0; j < n; j++) {
        s->states[j] = e->q[j];
        s->states[n + j] = e->qd[j];
    }
    for (size_t k = 0; k < nu; k++)
        s->inputs[k] = qd_model_input(m, k);
    for (size_t i = 0; i < ny; i++)
        s->outputs[i] = qd_model_output_name(m, i);
    return QD_OK;
}

static qd_status derive(qd_ctx *ctx, const qd_eom *e, const qd_model *m, const qd__point *pt,
                        qd_statespace *s) {
    entries E = {0};
    double *v = NULL, *qd0 = NULL;
    qd_status st = alloc_out(ctx, e, m, s);
    if (st == QD_OK)
        st = entries_alloc(ctx, &E, e->n, s->nx + s->nu, s->ny);
    if (st == QD_OK)
        st = build_entries(ctx, e, m, s, pt, &E);
    v = st == QD_OK ? qd__malloc(ctx, (E.count + e->n + 1) * sizeof *v) : NULL;
    if (st == QD_OK && !v)
        st = QD_ERR_NOMEM;
    if (st == QD_OK) {
        qd0 = v + E.count;
        st = qd__lin_point_numbers(ctx, m, pt, e->n, e->qd, qd0);
    }
    if (st == QD_OK)
        st = eval_entries(ctx, m, &E, v);
    if (st == QD_OK)
        st = numbers(ctx, s, &E, v, qd0);
    if (st == QD_OK)
        st = expressions(ctx, s, &E);
    qd__free(v);
    entries_free(&E);
    return st;
}

qd_status qd_linearize(qd_ctx *ctx, const qd_eom *e, const qd_model *m, size_t npt,
                       const qd_expr *const *syms, const qd_expr *const *vals,
                       qd_statespace *out) {
    QD_ARGS_CTX(ctx, ctx && e && m && out);
    memset(out, 0, sizeof *out);
    if (!ctx || !e || !m)
        return QD_ERR_ARG;
    if (e->ncon) {
        qd_ctx_error(ctx, QD_ERR_ARG, "the equations keep %zu constraint%s with multipliers: "
                     "linearize in independent coordinates (derive with the constraints "
                     "eliminated, or choose coordinates that satisfy them)",
                     e->ncon, e->ncon == 1 ? "" : "s");
        return QD_ERR_ARG;
    }
    qd__point pt = {0};
    qd_status st = qd__lin_point_make(ctx, e, m, npt, syms, vals, &pt);
    if (st == QD_OK)
        st = derive(ctx, e, m, &pt, out);
    if (st == QD_OK)
        st = qd__lin_ss_analyse(ctx, out);
    qd__lin_point_free(&pt);
    if (st == QD_ERR_NOMEM && qd_ctx_status(ctx) == QD_OK)
        qd_ctx_error(ctx, st, "out of memory linearizing");
    return st;
}

void qd_statespace_free(qd_statespace *s) {
    if (!s)
        return;
    qd__free(s->states);
    qd__free((void *)s->outputs);
    qd__free(s->A);
    qd__free(s->Asym);
    qd__free(s->eig_re);
    qd__free(s->uncontrollable);
    memset(s, 0, sizeof *s);
}

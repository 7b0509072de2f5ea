/*
 * src/linear/speeds_lin.c - the first-order system of a model in
 * generalized speeds (qdot/speeds.h), y = (q, u),
 *
 *     q' = kin(q, u, t),      M_u(q, t) u' = f_u(q, u, t),
 *
 * linearized about a state, with the ignorable coordinates dropped.
 *
 * A coordinate is kept when f_u or M_u involves it, or the kinematic row
 * of a kept coordinate does (the closure of that); the others (the contact
 * point and the heading of a rolling disk) do not act back on the kept
 * ones, so the kept coordinates and the speeds form a closed system, the
 * reduced one, and a steady motion of the full system (the disk rolling
 * upright along a line) is a stationary point of it (Neimark and Fufaev,
 * Dynamics of Nonholonomic Systems, ch. III: the reduction by the
 * ignorable coordinates of a Chaplygin-type system).
 *
 * The Jacobian is exact: every derivative of kin, f_u and M_u is symbolic,
 * and  d u'/dy_k = M_u^-1 (df_u/dy_k - (dM_u/dy_k) u'),  evaluated at the
 * state in one compiled program.
 */
#include "linear.h"
#include "qdot/speeds.h"
#include "base/mem.h"
#include "num/num.h"
#include "../base/args.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

extern void dgeev_(const char *jobvl, const char *jobvr, const int *n, double *a, const int *lda,
                   double *wr, double *wi, double *vl, const int *ldvl, double *vr,
                   const int *ldvr, double *work, const int *lwork, int *info);

void qd_speeds_linear_free(qd_speeds_linear *l) {
    if (!l)
        return;
    qd__free(l->kept);
    qd__free(l->ignorable);
    qd__free(l->A);
    qd__free(l->rate);
    memset(l, 0, sizeof *l);
}

static bool has_coord(const qd_expr *x, const qd_expr *q) { return qd_has(x, q); }

/* kept[j]: q_j enters f_u or M_u, or the kinematic row of a kept
 * coordinate other than its own. */
void qd__lin_speeds_kept(const qd_speeds_eom *e, bool *kept) {
    size_t n = e->n, m = e->m;
    for (size_t j = 0; j < n; j++) {
        kept[j] = false;
        for (size_t r = 0; r < m && !kept[j]; r++)
            kept[j] = has_coord(e->f[r], e->q[j]);
        for (size_t i = 0; i < m * m && !kept[j]; i++)
            kept[j] = has_coord(e->M[i], e->q[j]);
    }
    for (bool grew = true; grew;) {
        grew = false;
        for (size_t j = 0; j < n; j++)
            for (size_t i = 0; i < n && !kept[j]; i++)
                if (i != j && kept[i] && has_coord(e->kin[i], e->q[j]))
                    kept[j] = grew = true;
    }
}

/* The symbolic pieces, in one array:
 *   kin of the kept (nk), d kin/dy (nk*d), f_u (m), M_u (m*m),
 *   df_u/dy (m*d), dM_u/dy (m*m*d),   y = (kept q, u), d = nk + m. */
typedef struct sparts {
    size_t nk, m, d, nout;
    const qd_expr **y;
    const qd_expr **out;
} sparts;

static size_t off_dkin(const sparts *p) { return p->nk; }
static size_t off_f(const sparts *p) { return p->nk + p->nk * p->d; }
static size_t off_M(const sparts *p) { return off_f(p) + p->m; }
static size_t off_df(const sparts *p) { return off_M(p) + p->m * p->m; }
static size_t off_dM(const sparts *p) { return off_df(p) + p->m * p->d; }

static qd_status parts(qd_ctx *ctx, const qd_speeds_eom *e, const qd_speeds_linear *l,
                       sparts *p) {
    size_t nk = l->nkept, m = e->m, d = nk + m;
    *p = (sparts){nk, m, d, 0, NULL, NULL};
    p->nout = nk + nk * d + m + m * m + m * d + m * m * d;
    p->y = qd__malloc(ctx, (d + 1) * sizeof *p->y);
    p->out = qd__malloc(ctx, (p->nout + 1) * sizeof *p->out);
    if (!p->y || !p->out)
        return QD_ERR_NOMEM;
    for (size_t i = 0; i < nk; i++)
        p->y[i] = e->q[l->kept[i]];
    for (size_t r = 0; r < m; r++)
        p->y[nk + r] = e->u[r];
    for (size_t i = 0; i < nk; i++) {
        const qd_expr *k = e->kin[l->kept[i]];
        p->out[i] = k;
        for (size_t c = 0; c < d; c++)
            p->out[off_dkin(p) + i * d + c] = qd_diff(ctx, k, p->y[c]);
    }
    for (size_t r = 0; r < m; r++) {
        p->out[off_f(p) + r] = e->f[r];
        for (size_t c = 0; c < d; c++)
            p->out[off_df(p) + r * d + c] = qd_diff(ctx, e->f[r], p->y[c]);
    }
    for (size_t i = 0; i < m * m; i++) {
        p->out[off_M(p) + i] = e->M[i];
        for (size_t c = 0; c < d; c++)
            p->out[off_dM(p) + i * d + c] = qd_diff(ctx, e->M[i], p->y[c]);
    }
    return qd_ctx_status(ctx);
}

/* The symbolic parts compiled once, evaluated at many states (a scan). */
typedef struct slin {
    qd_ctx *ctx;
    sparts p;
    size_t nin;
    const qd_expr **in;
    qd_prog *prog;
    double *x, *v;   /* nin inputs, p.nout outputs */
} slin;

static void slin_free(slin *s) {
    qd__free(s->p.y);
    qd__free(s->p.out);
    qd__free(s->in);
    qd_prog_free(s->prog);
    qd__free(s->x);
    qd__free(s->v);
    memset(s, 0, sizeof *s);
}

static qd_status slin_init(qd_ctx *ctx, const qd_speeds_eom *e, const qd_speeds_linear *l,
                           slin *s) {
    memset(s, 0, sizeof *s);
    s->ctx = ctx;
    qd_status st = parts(ctx, e, l, &s->p);
    if (st == QD_OK && !(s->in = qd__num_inputs(ctx, s->p.nout, s->p.out, &s->nin)))
        st = QD_ERR_NOMEM;
    if (st == QD_OK && !(s->prog = qd_prog_new(ctx, s->nin, s->in, s->p.nout, s->p.out)))
        st = QD_ERR_NOMEM;
    if (st == QD_OK) {
        s->x = qd__calloc(ctx, s->nin + 1, sizeof *s->x);
        s->v = qd__calloc(ctx, s->p.nout + 1, sizeof *s->v);
        st = s->x && s->v ? QD_OK : QD_ERR_NOMEM;
    }
    if (st != QD_OK && qd_ctx_status(ctx) != QD_OK)
        st = qd_ctx_status(ctx);
    return st;
}

/* Every output at syms/vals (symbols not given are 0) into s->v. */
static void slin_run(slin *s, size_t nvals, const qd_expr *const *syms, const double *vals) {
    for (size_t i = 0; i < s->nin; i++) {
        s->x[i] = 0;
        for (size_t k = 0; k < nvals; k++)
            if (syms[k] == s->in[i]) {
                s->x[i] = vals[k];
                break;
            }
    }
    qd_prog_run(s->prog, s->x, s->v);
}

/* x = M^-1 b (m), M copied into work (m*m). */
static bool solve_m(size_t m, const double *M, double *work, double *b) {
    memcpy(work, M, m * m * sizeof *work);
    return qd__num_solve(m, work, b, 1e-13);
}

/* A and rate from the numbers v (the layout of sparts). */
static qd_status assemble(qd_ctx *ctx, const sparts *p, const double *v, qd_speeds_linear *l) {
    size_t nk = p->nk, m = p->m, d = p->d;
    double *work = qd__malloc(ctx, (m * m + 1) * sizeof *work);
    double *ud = qd__malloc(ctx, (m + 1) * sizeof *ud), *col = qd__malloc(ctx, (m + 1) * sizeof *col);
    qd_status st = work && ud && col ? QD_OK : QD_ERR_NOMEM;
    const double *M = v + off_M(p);
    if (st == QD_OK) {
        memcpy(ud, v + off_f(p), m * sizeof *ud);
        if (!solve_m(m, M, work, ud)) {
            qd_ctx_error(ctx, QD_ERR_SINGULAR, "the mass matrix M_u is singular at this state");
            st = QD_ERR_SINGULAR;
        }
    }
    for (size_t i = 0; st == QD_OK && i < nk; i++) {
        l->rate[i] = v[i];
        for (size_t c = 0; c < d; c++)
            l->A[i * d + c] = v[off_dkin(p) + i * d + c];
    }
    for (size_t c = 0; st == QD_OK && c < d; c++) {
        for (size_t r = 0; r < m; r++) {
            col[r] = v[off_df(p) + r * d + c];
            for (size_t s = 0; s < m; s++)
                col[r] -= v[off_dM(p) + (r * m + s) * d + c] * ud[s];
        }
        solve_m(m, M, work, col);
        for (size_t r = 0; r < m; r++)
            l->A[(nk + r) * d + c] = col[r];
    }
    for (size_t r = 0; st == QD_OK && r < m; r++)
        l->rate[nk + r] = ud[r];
    qd__free(work);
    qd__free(ud);
    qd__free(col);
    return st;
}

static qd_status alloc_linear(qd_ctx *ctx, const qd_speeds_eom *e, qd_speeds_linear *l) {
    size_t n = e->n;
    l->n = n;
    l->m = e->m;
    l->ignorable = qd__calloc(ctx, n + 1, sizeof *l->ignorable);
    l->kept = qd__calloc(ctx, n + 1, sizeof *l->kept);
    if (!l->ignorable || !l->kept)
        return QD_ERR_NOMEM;
    qd__lin_speeds_kept(e, l->ignorable);  /* kept for now; inverted below */
    for (size_t j = 0; j < n; j++) {
        if (l->ignorable[j])
            l->kept[l->nkept++] = j;
        l->ignorable[j] = !l->ignorable[j];
    }
    l->dim = l->nkept + e->m;
    l->A = qd__calloc(ctx, l->dim * l->dim + 1, sizeof *l->A);
    l->rate = qd__calloc(ctx, l->dim + 1, sizeof *l->rate);
    return l->A && l->rate ? QD_OK : QD_ERR_NOMEM;
}

qd_status qd_speeds_linear_about(qd_ctx *ctx, const qd_speeds_eom *e, size_t nvals,
                                 const qd_expr *const *syms, const double *vals,
                                 qd_speeds_linear *out) {
    QD_ARGS_CTX(ctx, ctx && e && (nvals == 0 || syms) && (nvals == 0 || vals) && out);
    memset(out, 0, sizeof *out);
    if (!ctx || !e || (nvals && (!syms || !vals)))
        return QD_ERR_ARG;
    slin s = {0};
    qd_status st = alloc_linear(ctx, e, out);
    if (st == QD_OK)
        st = slin_init(ctx, e, out, &s);
    if (st == QD_OK) {
        slin_run(&s, nvals, syms, vals);
        st = assemble(ctx, &s.p, s.v, out);
    }
    slin_free(&s);
    if (st != QD_OK) {
        if (qd_ctx_status(ctx) == QD_OK)
            qd_ctx_error(ctx, st, "cannot linearize the equations in speeds");
        qd_speeds_linear_free(out);
    }
    return st;
}

/* ---- the eigenvalues --------------------------------------------------------- */

typedef struct scplx {
    double re, im;
} scplx;

static int by_re_desc(const void *pa, const void *pb) {
    const scplx *a = pa, *b = pb;
    if (a->re != b->re)
        return a->re < b->re ? 1 : -1;
    return a->im < b->im ? 1 : a->im > b->im ? -1 : 0;
}

static bool eigenvalues(qd_ctx *ctx, size_t d, const double *A, double *re, double *im) {
    int di = (int)d, info = 0, lwork = -1, one = 1;
    double *a = qd__malloc(ctx, (d * d + 1) * sizeof *a), q = 0, dummy = 0;
    if (!a)
        return false;
    for (size_t i = 0; i < d; i++)
        for (size_t j = 0; j < d; j++)
            a[i + j * d] = A[i * d + j];
    dgeev_("N", "N", &di, a, &di, re, im, &dummy, &one, &dummy, &one, &q, &lwork, &info);
    lwork = info == 0 ? (int)q : 0;
    double *work = lwork > 0 ? qd__malloc(ctx, (size_t)lwork * sizeof *work) : NULL;
    if (work)
        dgeev_("N", "N", &di, a, &di, re, im, &dummy, &one, &dummy, &one, work, &lwork, &info);
    qd__free(work);
    qd__free(a);
    if (work && info != 0)
        qd_ctx_error(ctx, QD_ERR_NUMERIC, "the eigen-solver (dgeev) failed: info %d", info);
    return work && info == 0;
}

/* How many independent null vectors A has (the geometric multiplicity of
 * the eigenvalue 0), at the relative tolerance of the zero eigenvalues;
 * SIZE_MAX when out of memory. */
static size_t nullity(qd_ctx *ctx, size_t d, const double *A) {
    double *a = qd__malloc(ctx, (d * d + 1) * sizeof *a);
    size_t *pc = qd__malloc(ctx, (d + 1) * sizeof *pc);
    size_t null = SIZE_MAX;
    if (a && pc) {
        memcpy(a, A, d * d * sizeof *a);
        null = d - qd__num_rank(d, a, NULL, QD_MODES_ZERO_TOL, pc, NULL, NULL);
    }
    qd__free(a);
    qd__free(pc);
    return null;
}

/* 0 when some Re s > 0; else 1 when the zero eigenvalues are semisimple
 * (as many null vectors as zeros: the neighbouring steady motions, which
 * do not drift apart linearly) and no imaginary pair repeats; -1 borderline;
 * -2 out of memory. */
static int verdict(qd_ctx *ctx, const qd_modes_result *r, const double *A) {
    double big = 0;
    for (size_t i = 0; i < r->neig; i++)
        big = fmax(big, hypot(r->eig_re[i], r->eig_im[i]));
    double tol = QD_MODES_ZERO_TOL * big;
    size_t zeros = 0;
    int v = 1;
    for (size_t i = 0; i < r->neig; i++) {
        double re = r->eig_re[i], im = r->eig_im[i];
        if (re > tol)
            return 0;
        if (re < -tol)
            continue;
        if (fabs(im) <= tol) {
            zeros++;
            continue;
        }
        for (size_t k = 0; k < r->neig; k++)
            if (k != i && fabs(r->eig_re[k]) <= tol && fabs(r->eig_im[k] - im) <= 1e3 * tol)
                v = -1;
    }
    if (big == 0)
        return -1;
    size_t null = zeros ? nullity(ctx, r->neig, A) : 0;
    if (null == SIZE_MAX)
        return -2;
    return null < zeros ? -1 : v;
}

qd_status qd_speeds_modes_solve(qd_ctx *ctx, const qd_speeds_linear *lin, qd_modes_result *out) {
    QD_ARGS_CTX(ctx, ctx && lin && out);
    memset(out, 0, sizeof *out);
    size_t d = lin->dim;
    out->n = d;
    out->neig = d;
    out->eig_re = qd__calloc(ctx, d + 1, sizeof *out->eig_re);
    out->eig_im = qd__calloc(ctx, d + 1, sizeof *out->eig_im);
    scplx *c = qd__malloc(ctx, (d + 1) * sizeof *c);
    qd_status st = out->eig_re && out->eig_im && c ? QD_OK : QD_ERR_NOMEM;
    if (st == QD_OK && !eigenvalues(ctx, d, lin->A, out->eig_re, out->eig_im))
        st = qd_ctx_status(ctx) ? qd_ctx_status(ctx) : QD_ERR_NOMEM;
    if (st == QD_OK) {
        for (size_t i = 0; i < d; i++)
            c[i] = (scplx){out->eig_re[i], out->eig_im[i]};
        qsort(c, d, sizeof *c, by_re_desc);
        for (size_t i = 0; i < d; i++) {
            out->eig_re[i] = c[i].re;
            out->eig_im[i] = c[i].im;
        }
        out->stable = verdict(ctx, out, lin->A);
        st = out->stable == -2 ? QD_ERR_NOMEM : QD_OK;
    }
    qd__free(c);
    if (st != QD_OK) {
        if (qd_ctx_status(ctx) == QD_OK)
            qd_ctx_error(ctx, st, "out of memory in the eigen-analysis");
        qd_modes_result_free(out);
    }
    return st;
}

/* ---- a scan along one value of the state --------------------------------------- */

typedef struct sscan {
    qd_ctx *ctx;
    slin s;
    qd_speeds_linear lin;
    size_t nvals, slot;          /* the value varied: vals[slot] */
    const qd_expr *const *syms;
    double *vals;
} sscan;

/* The verdict and the largest Re s at value x. */
static qd_status sscan_at(sscan *c, double x, int *verdict, double *margin) {
    qd_modes_result r;
    c->vals[c->slot] = x;
    slin_run(&c->s, c->nvals, c->syms, c->vals);
    qd_status st = assemble(c->ctx, &c->s.p, c->s.v, &c->lin);
    if (st == QD_OK)
        st = qd_speeds_modes_solve(c->ctx, &c->lin, &r);
    if (st != QD_OK)
        return st;
    *verdict = r.stable;
    *margin = r.neig ? r.eig_re[0] : 0;
    qd_modes_result_free(&r);
    return QD_OK;
}

static qd_status scan_alloc(qd_ctx *ctx, size_t count, qd_scan *out) {
    out->count = count;
    out->value = qd__calloc(ctx, count, sizeof *out->value);
    out->q = qd__calloc(ctx, 1, sizeof *out->q);
    out->stable = qd__calloc(ctx, count, sizeof *out->stable);
    out->margin = qd__calloc(ctx, count, sizeof *out->margin);
    out->conservative = qd__calloc(ctx, count, sizeof *out->conservative);
    out->trans = qd__calloc(ctx, count, sizeof *out->trans);
    return out->value && out->q && out->stable && out->margin && out->conservative &&
                   out->trans
               ? QD_OK
               : QD_ERR_NOMEM;
}

/* Bisect on the verdict between samples k - 1 and k. */
static qd_status bisect(sscan *c, qd_scan *out, size_t k, double tol) {
    double lo = out->value[k - 1], hi = out->value[k], margin;
    int from = out->stable[k - 1], v = from;
    qd_status st = QD_OK;
    while (st == QD_OK && hi - lo > tol) {
        double mid = lo + (hi - lo) / 2;
        if (mid <= lo || mid >= hi)
            break;
        if ((st = sscan_at(c, mid, &v, &margin)) == QD_OK)
            *(v == from ? &lo : &hi) = mid;
    }
    out->trans[out->ntrans++] = (qd_scan_transition){lo + (hi - lo) / 2, lo, hi, from,
                                                     out->stable[k]};
    return st;
}

static qd_status scan_run(sscan *c, double a, double b, const qd_scan_opts *o, qd_scan *out) {
    size_t steps = o && o->steps ? o->steps : 200;
    double tol = o && o->tol > 0 ? o->tol : 1e-13 * fmax(1, fmax(fabs(a), fabs(b)));
    qd_status st = scan_alloc(c->ctx, steps + 1, out);
    for (size_t k = 0; st == QD_OK && k <= steps; k++) {
        out->value[k] = k == steps ? b : a + (b - a) * (double)k / (double)steps;
        st = sscan_at(c, out->value[k], &out->stable[k], &out->margin[k]);
    }
    for (size_t k = 1; st == QD_OK && k <= steps; k++)
        if (out->stable[k] != out->stable[k - 1])
            st = bisect(c, out, k, tol);
    return st;
}

qd_status qd_speeds_modes_scan(qd_ctx *ctx, const qd_speeds_eom *e, size_t nvals,
                               const qd_expr *const *syms, const double *vals,
                               const qd_expr *what, double a, double b,
                               const qd_scan_opts *opts, qd_scan *out) {
    QD_ARGS_CTX(ctx, ctx && e && (nvals == 0 || syms) && (nvals == 0 || vals) && what && out);
    memset(out, 0, sizeof *out);
    if (!ctx || !e || !what || (nvals && (!syms || !vals)))
        return QD_ERR_ARG;
    sscan c = {.ctx = ctx, .nvals = nvals, .slot = SIZE_MAX, .syms = syms};
    for (size_t k = 0; k < nvals; k++)
        if (syms[k] == what)
            c.slot = k;
    if (c.slot == SIZE_MAX || !(a < b)) {
        qd_ctx_error(ctx, QD_ERR_ARG, c.slot == SIZE_MAX
                                          ? "'%s' is not a value of the state given"
                                          : "the range of %s must have A < B",
                     qd_expr_name(what));
        return QD_ERR_ARG;
    }
    c.vals = qd__malloc(ctx, (nvals + 1) * sizeof *c.vals);
    qd_status st = c.vals ? alloc_linear(ctx, e, &c.lin) : QD_ERR_NOMEM;
    if (st == QD_OK) {
        memcpy(c.vals, vals, nvals * sizeof *c.vals);
        st = slin_init(ctx, e, &c.lin, &c.s);
    }
    if (st == QD_OK)
        st = scan_run(&c, a, b, opts, out);
    slin_free(&c.s);
    qd_speeds_linear_free(&c.lin);
    qd__free(c.vals);
    if (st != QD_OK && qd_ctx_status(ctx) == QD_OK)
        qd_ctx_error(ctx, st, "the scan of the equations in speeds failed");
    return st;
}

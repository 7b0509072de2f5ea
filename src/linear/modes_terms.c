/*
 * src/linear/modes_terms.c - the part of V that the mode picture's springs
 * make (modes_links.c): V's terms less those linear in the particles'
 * positions.
 *
 * K0 holds gravity's share as well: m g y pulls a pendulum's bob back as a
 * spring to a wall would, but nothing joins the bob to anything, so a
 * picture read off K0 drew springs to walls on every pendulum.  V is split
 * into its terms (a sum, a factor free of the coordinates carried into a
 * sum it multiplies), and a term is a field (gravity, a uniform force) when
 * c + sum f_ik r_ik(q), the particles' positions r_ik, fits it at sample
 * points around the equilibrium (each coordinate moving the particles by up
 * to 5% of the configuration's size) to 1e-7 of its spread: least squares by
 * modified Gram-Schmidt, twice for round-off.  A term is central, a spring
 * to the origin on particle a, when its gradient is parallel to that of
 * |r_a| at every sample (to 1e-4: central differences): the spring of a
 * spring pendulum, k/2 (r - l0)^2.  What is kept is each other term's
 * Hessian at q0, exact (qd_diff twice).
 */
#include "linear.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#define MAXTERMS 256

typedef struct terms_ctx {
    qd_ctx *ctx;
    const qd_eom *e;
    size_t nvals, np, nt;
    const qd_expr *const *syms;
    double *w; /* nvals: the values with the coordinates put in */
} terms_ctx;

static bool has_coords(const qd_eom *e, const qd_expr *x) {
    for (size_t j = 0; j < e->n; j++)
        if (qd_has(x, e->q[j]))
            return true;
    return false;
}

/* The terms of x times factor into out (at most MAXTERMS; false beyond). */
static bool split(terms_ctx *t, const qd_expr *x, const qd_expr *factor, const qd_expr **out) {
    qd_kind k = qd_expr_kind(x);
    if (!has_coords(t->e, x))
        return true; /* a constant: no share in K0 */
    if (k == QD_ADD) {
        for (size_t i = 0; i < qd_expr_nargs(x); i++)
            if (!split(t, qd_expr_arg(x, i), factor, out))
                return false;
        return true;
    }
    if (k == QD_MUL) { /* one factor with the coordinates, a sum: distributed */
        size_t with = SIZE_MAX, nargs = qd_expr_nargs(x);
        for (size_t i = 0; i < nargs; i++)
            if (has_coords(t->e, qd_expr_arg(x, i)))
                with = with == SIZE_MAX ? i : SIZE_MAX - 1;
        if (with < nargs && qd_expr_kind(qd_expr_arg(x, with)) == QD_ADD) {
            const qd_expr *f = factor;
            for (size_t i = 0; i < nargs && f; i++)
                if (i != with)
                    f = qd_mul(t->ctx, f, qd_expr_arg(x, i));
            return f && split(t, qd_expr_arg(x, with), f, out);
        }
    }
    if (t->nt == MAXTERMS)
        return false;
    out[t->nt] = qd_mul(t->ctx, factor, x);
    return out[t->nt++] != NULL;
}

/* A small deterministic generator of steps in [-1, 1]. */
static double step_unit(uint64_t *s) {
    *s = *s * 6364136223846793005u + 1442695040888963407u;
    return (double)(*s >> 11) / (double)(UINT64_C(1) << 52) - 1;
}

/* Evaluate prog at q (velocities 0). */
static void run_at(terms_ctx *t, qd_prog *prog, const double *q, double *out) {
    for (size_t k = 0; k < t->nvals; k++)
        for (size_t j = 0; j < t->e->n; j++) {
            if (t->syms[k] == t->e->q[j])
                t->w[k] = q[j];
            else if (t->syms[k] == t->e->qd[j])
                t->w[k] = 0;
        }
    qd_prog_run(prog, t->w, out);
}

/* v less its projections on the ns orthonormal columns of basis (length m). */
static void project_out(double *v, const double *basis, size_t ns, size_t m) {
    for (unsigned pass = 0; pass < 2; pass++)
        for (size_t c = 0; c < ns; c++) {
            double d = 0;
            for (size_t s = 0; s < m; s++)
                d += basis[c * m + s] * v[s];
            for (size_t s = 0; s < m; s++)
                v[s] -= d * basis[c * m + s];
        }
}

static double norm(const double *v, size_t m) {
    double s = 0;
    for (size_t i = 0; i < m; i++)
        s += v[i] * v[i];
    return sqrt(s);
}

/* An orthonormal basis of the constant and the position components over
 * the m samples (pos: m rows of 3 np); its size. */
static size_t field_basis(const double *pos, size_t m, size_t np, double *basis, double *col) {
    size_t ns = 0;
    for (size_t c = 0; c <= 3 * np; c++) {
        for (size_t s = 0; s < m; s++)
            col[s] = c == 0 ? 1 : pos[s * 3 * np + c - 1];
        double before = norm(col, m);
        project_out(col, basis, ns, m);
        double after = norm(col, m);
        if (!(after > 1e-9 * before))
            continue; /* constant, or a combination of the others */
        for (size_t s = 0; s < m; s++)
            basis[ns * m + s] = col[s] / after;
        ns++;
    }
    return ns;
}

/* Term values (vt: m rows of nt) fit by the basis: a field. */
static bool is_field(const double *vt, size_t m, size_t nt, size_t k, const double *basis,
                     size_t ns, double *col) {
    double lo = INFINITY, hi = -INFINITY;
    for (size_t s = 0; s < m; s++) {
        col[s] = vt[s * nt + k];
        if (!isfinite(col[s]))
            return false;
        lo = fmin(lo, col[s]);
        hi = fmax(hi, col[s]);
    }
    project_out(col, basis, ns, m);
    return norm(col, m) <= 1e-7 * (hi - lo) * sqrt((double)m);
}

/* The gradients at sample q (central differences, steps h): of each term
 * (gt, n rows of nt) and of each |r_a| (gd, n rows of np). */
static void gradients(terms_ctx *t, qd_prog *prog, const double *q, const double *h,
                      double *qs, double *buf, double *gt, double *gd) {
    size_t n = t->e->n, nt = t->nt, np = t->np, nout = 3 * np + nt;
    for (size_t j = 0; j < n; j++) {
        for (int sgn = 0; sgn < 2; sgn++) {
            memcpy(qs, q, n * sizeof *qs);
            qs[j] += sgn ? -h[j] : h[j];
            run_at(t, prog, qs, buf + sgn * nout);
        }
        for (size_t k = 0; k < nt; k++)
            gt[j * nt + k] = (buf[3 * np + k] - buf[nout + 3 * np + k]) / (2 * h[j]);
        for (size_t a = 0; a < np; a++) {
            double r[2];
            for (int sgn = 0; sgn < 2; sgn++) {
                const double *p = buf + sgn * nout + 3 * a;
                r[sgn] = sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
            }
            gd[j * np + a] = (r[0] - r[1]) / (2 * h[j]);
        }
    }
}

/* Whether column k of g (n rows of cols g) is parallel to column a of d. */
static bool parallel(const double *g, size_t gc, size_t k, const double *d, size_t dc, size_t a,
                     size_t n) {
    double gg = 0, dd = 0, gd = 0;
    for (size_t j = 0; j < n; j++) {
        gg += g[j * gc + k] * g[j * gc + k];
        dd += d[j * dc + a] * d[j * dc + a];
        gd += g[j * gc + k] * d[j * dc + a];
    }
    if (!(dd > 0) || !isfinite(gg))
        return false;
    return gg - gd * gd / dd <= 1e-8 * gg; /* sin^2 of the angle */
}

typedef struct samples {
    size_t m;
    double *q, *pos, *vt; /* m rows of n, 3 np, nt */
} samples;

/* m sample points about q0, coordinate j stepped by up to scale[j]. */
static void take_samples(terms_ctx *t, qd_prog *prog, const double *q0, const double *scale,
                         samples *S, double *buf) {
    size_t n = t->e->n, np = t->np, nt = t->nt;
    uint64_t seed = 0x9e3779b97f4a7c15u;
    for (size_t s = 0; s < S->m; s++) {
        double *q = S->q + s * n;
        for (size_t j = 0; j < n; j++)
            q[j] = q0[j] + scale[j] * step_unit(&seed);
        run_at(t, prog, q, buf);
        memcpy(S->pos + s * 3 * np, buf, 3 * np * sizeof *buf);
        memcpy(S->vt + s * nt, buf + 3 * np, nt * sizeof *buf);
    }
}

/* Each term's particle it holds to the origin (central), else SIZE_MAX. */
static void find_centres(terms_ctx *t, qd_prog *prog, const samples *S, const double *scale,
                         const bool *field, double *work, size_t *centre) {
    size_t n = t->e->n, nt = t->nt, np = t->np;
    double *h = work, *qs = h + n, *buf = qs + n, *gt = buf + 2 * (3 * np + nt),
           *gd = gt + n * nt;
    for (size_t j = 0; j < n; j++)
        h[j] = 1e-5 * scale[j];
    bool *ok = calloc(nt * np + 1, sizeof *ok);
    if (!ok)
        return;
    for (size_t k = 0; k < nt * np; k++)
        ok[k] = !field[k / np];
    for (size_t s = 0; s < S->m && s < 8; s++) {
        gradients(t, prog, S->q + s * n, h, qs, buf, gt, gd);
        for (size_t k = 0; k < nt; k++)
            for (size_t a = 0; a < np; a++)
                ok[k * np + a] = ok[k * np + a] && parallel(gt, nt, k, gd, np, a, n);
    }
    for (size_t k = 0; k < nt; k++)
        for (size_t a = np; a-- > 0;)
            if (ok[k * np + a])
                centre[k] = a;
    free(ok);
}

/* The Hessian at q0 of each term that is not a field, into out->K. */
static qd_status hessians(terms_ctx *t, const qd_expr **terms, const bool *field,
                          const double *q0, qd__lin_springs *out) {
    size_t n = t->e->n, nt = t->nt, nk = 0;
    const qd_expr **outs = malloc((nt * n * n + 1) * sizeof *outs);
    if (!outs)
        return QD_ERR_NOMEM;
    for (size_t k = 0; k < nt; k++) {
        if (field[k])
            continue;
        for (size_t u = 0; u < n; u++) {
            const qd_expr *du = qd_diff(t->ctx, terms[k], t->e->q[u]);
            for (size_t v = 0; v < n; v++)
                outs[nk++] = du ? qd_diff(t->ctx, du, t->e->q[v]) : NULL;
        }
    }
    qd_status st = qd_ctx_status(t->ctx);
    qd_prog *p = st == QD_OK ? qd_prog_new(t->ctx, t->nvals, t->syms, nk, outs) : NULL;
    free(outs);
    if (!p)
        return st != QD_OK ? st : qd_ctx_status(t->ctx) ? qd_ctx_status(t->ctx) : QD_ERR_NOMEM;
    run_at(t, p, q0, out->K);
    qd_prog_free(p);
    return QD_OK;
}

/* The terms and the sample program: positions, then each term. */
static qd_prog *terms_prog(terms_ctx *t, const qd_model *m, const qd_expr **terms) {
    const qd_expr *V = qd_model_potential(m);
    if (!V || qd_model_lagrangian_given(m) || !split(t, V, qd_int(t->ctx, 1), terms))
        return NULL;
    const qd_expr *outs[3 * QD_MODES_PLOT_MAXP + MAXTERMS];
    for (size_t i = 0; i < t->np; i++)
        for (unsigned k = 0; k < 3; k++) {
            const qd_expr *x = qd_model_particle_position(m, i, k);
            outs[3 * i + k] = x ? x : qd_int(t->ctx, 0);
        }
    for (size_t k = 0; k < t->nt; k++)
        outs[3 * t->np + k] = terms[k];
    return qd_prog_new(t->ctx, t->nvals, t->syms, 3 * t->np + t->nt, outs);
}

static qd_status classify(terms_ctx *t, qd_prog *prog, const qd_expr **terms, const double *q0,
                          const double *scale, qd__lin_springs *out) {
    size_t n = t->e->n, np = t->np, nt = t->nt, m = 3 * np + 9;
    samples S = {m, NULL, NULL, NULL};
    size_t nbuf = 2 * (3 * np + nt) + 2 * n + n * nt + n * np;
    double *mem = malloc((m * (n + 3 * np + nt) + m * (3 * np + 2) + nbuf + 1) * sizeof *mem);
    bool *field = calloc(nt + 1, sizeof *field);
    out->K = malloc((nt * n * n + 1) * sizeof *out->K);
    out->centre = malloc((nt + 1) * sizeof *out->centre);
    if (!mem || !field || !out->K || !out->centre) {
        free(mem);
        free(field);
        return QD_ERR_NOMEM;
    }
    S.q = mem, S.pos = S.q + m * n, S.vt = S.pos + m * 3 * np;
    double *basis = S.vt + m * nt, *col = basis + m * (3 * np + 1), *work = col + m;
    take_samples(t, prog, q0, scale, &S, work);
    size_t ns = field_basis(S.pos, m, np, basis, col);
    for (size_t k = 0; k < nt; k++)
        field[k] = is_field(S.vt, m, nt, k, basis, ns, col);
    for (size_t k = 0; k < nt; k++)
        out->centre[k] = SIZE_MAX;
    find_centres(t, prog, &S, scale, field, work, out->centre);
    qd_status st = hessians(t, terms, field, q0, out);
    size_t kept = 0;
    for (size_t k = 0; k < nt; k++)
        if (!field[k])
            out->centre[kept++] = out->centre[k];
    out->nt = kept;
    free(mem);
    free(field);
    return st;
}

qd_status qd__lin_springs_find(qd_ctx *ctx, const qd_eom *e, const qd_model *m, size_t nvals,
                               const qd_expr *const *syms, const double *vals, const double *q0,
                               const double *jac, size_t np, double size,
                               qd__lin_springs *out) {
    memset(out, 0, sizeof *out);
    size_t n = e->n;
    terms_ctx t = {ctx, e, nvals, np, 0, syms, malloc((nvals + 1) * sizeof(double))};
    const qd_expr **terms = malloc(MAXTERMS * sizeof *terms);
    double *scale = malloc((n + 1) * sizeof *scale);
    qd_status st = t.w && terms && scale ? QD_OK : QD_ERR_NOMEM;
    qd_prog *prog = st == QD_OK ? terms_prog(&t, m, terms) : NULL;
    if (st == QD_OK && !prog)
        st = qd_ctx_status(ctx) ? qd_ctx_status(ctx) : QD_ERR_ARG; /* no V, or too many terms */
    if (st == QD_OK) {
        if (nvals)
            memcpy(t.w, vals, nvals * sizeof *t.w);
        for (size_t j = 0; j < n; j++) { /* a step moving the particles 5% of the size */
            double big = 0;
            for (size_t k = 0; k < 3 * np; k++)
                big = fmax(big, fabs(jac[j * 3 * np + k]));
            scale[j] = big > 0 ? 0.05 * size / big : 0.05;
        }
        st = classify(&t, prog, terms, q0, scale, out);
    }
    qd_prog_free(prog);
    free(t.w);
    free(terms);
    free(scale);
    if (st != QD_OK)
        qd__lin_springs_free(out);
    return st;
}

void qd__lin_springs_free(qd__lin_springs *s) {
    free(s->K);
    free(s->centre);
    memset(s, 0, sizeof *s);
}

/*
 * src/linear/speeds_eq.c - the equilibria of a model in generalized speeds.
 *
 * At rest q' = 0 and u' = 0.  The speeds are independent (W has full column
 * rank), so with a scleronomic speed map (w = 0) q' = W u is 0 exactly when
 * u = 0, and u' = 0 when f_u(q, 0) = 0: m equations in the n coordinates,
 * with the holonomic constraints phi(q) = 0, which the speeds keep only
 * differentiated (a Pfaffian constraint, integrable or not, fixes no
 * configuration: its constant is the motion's).
 * With nonholonomic constraints m < n, and the equilibria come in families:
 * the rolling disk stands upright anywhere, with any heading.  The
 * coordinates that no equation at rest involves are free (any value); the
 * others are solved for by qd_equilibria_find on the equations at rest,
 * dressed as a qd_eom of those coordinates (M = I: only f at rest and its
 * Jacobian are used there).  f_u(q, 0) = W^T f(q, 0) (the velocity terms
 * vanish at rest), so for a holonomic model (W invertible) the equilibria
 * are those of Lagrange's equations.
 *
 * More equations than solved coordinates: their zeros are zeros of the
 * gradient of |F|^2 / 2, sum_r F_r dF_r/dq_j, which is square; the
 * gradient's other zeros (minima of |F| above 0) are then dropped by the
 * residual of F itself.
 */
#include "linear.h"
#include "qdot/equilibria.h"
#include "qdot/speeds.h"
#include "base/mem.h"
#include "num/num.h"
#include "../base/args.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

void qd_speeds_equilibria_free(qd_speeds_equilibria *r) {
    if (!r)
        return;
    qd_equilibria_free(&r->eq);
    qd__free(r->solved);
    qd__free(r->free_coord);
    memset(r, 0, sizeof *r);
}

/* x with every speed 0, simplified. */
static const qd_expr *at_rest(qd_ctx *ctx, const qd_speeds_eom *e, const qd_expr *x,
                              const qd_expr **zeros) {
    return qd_simplify(ctx, qd_subs(ctx, x, e->m, e->u, zeros));
}

/* Rest is u = 0 only when the kinematics have no term free of the speeds. */
static qd_status check_scleronomic(qd_ctx *ctx, const qd_speeds_eom *e, const qd_expr **zeros) {
    for (size_t j = 0; j < e->n; j++) {
        const qd_expr *w = at_rest(ctx, e, e->kin[j], zeros);
        if (qd_ctx_status(ctx) != QD_OK)
            return qd_ctx_status(ctx);
        if (!qd_is_zero(w)) {
            qd_ctx_error(ctx, QD_ERR_UNSUPPORTED,
                         "the kinematics of %s have a term free of the speeds (w = b or a "
                         "moving constraint): rest is not u = 0, equilibria of such a model "
                         "are not supported", qd_expr_name(e->q[j]));
            return QD_ERR_UNSUPPORTED;
        }
    }
    return QD_OK;
}

/* The equations at rest that are not identically 0 (F, nz of them), and the
 * coordinates they involve (solved; the others free). */
static qd_status rest_equations(qd_ctx *ctx, const qd_speeds_eom *e, const qd_expr **F,
                                size_t *nz, qd_speeds_equilibria *out) {
    const qd_expr **zeros = qd__malloc(ctx, (e->m + 1) * sizeof *zeros);
    if (!zeros)
        return QD_ERR_NOMEM;
    for (size_t r = 0; r < e->m; r++)
        zeros[r] = qd_int(ctx, 0);
    qd_status st = check_scleronomic(ctx, e, zeros);
    *nz = 0;
    for (size_t r = 0; st == QD_OK && r < e->m; r++) {
        const qd_expr *f = at_rest(ctx, e, e->f[r], zeros);
        if (f && !qd_is_zero(f))
            F[(*nz)++] = f;
    }
    /* the speeds keep the holonomic constraints only differentiated: the
       configuration must still meet them */
    for (size_t k = 0; st == QD_OK && k < e->ncon; k++)
        if (e->con[k].kind == QD_CON_HOLONOMIC) {
            const qd_expr *phi = qd_simplify(ctx, e->con[k].expr);
            if (phi && !qd_is_zero(phi))
                F[(*nz)++] = phi;
        }
    qd__free(zeros);
    if (st != QD_OK || qd_ctx_status(ctx) != QD_OK)
        return st != QD_OK ? st : qd_ctx_status(ctx);
    for (size_t j = 0; j < e->n; j++) {
        bool used = false;
        for (size_t r = 0; r < *nz && !used; r++)
            used = qd_has(F[r], e->q[j]);
        out->free_coord[j] = !used;
        if (used)
            out->solved[out->nsolved++] = j;
    }
    return QD_OK;
}

/* k square equations G in the k solved coordinates from the nz rows F. */
static const qd_expr **square(qd_ctx *ctx, const qd_speeds_eom *e,
                              const qd_speeds_equilibria *s, const qd_expr *const *F, size_t nz) {
    size_t k = s->nsolved;
    const qd_expr **G = qd__malloc(ctx, (k + 1) * sizeof *G);
    if (!G)
        return NULL;
    for (size_t j = 0; j < k; j++) {
        if (nz <= k) {
            G[j] = j < nz ? F[j] : qd_int(ctx, 0);
            continue;
        }
        const qd_expr *g = qd_int(ctx, 0);
        for (size_t r = 0; r < nz; r++)
            g = qd_add(ctx, g, qd_mul(ctx, F[r], qd_diff(ctx, F[r], e->q[s->solved[j]])));
        G[j] = qd_simplify(ctx, g);
    }
    return G;
}

/* A qd_eom of the solved coordinates whose f at rest is G and M = I: what
 * qd_equilibria_find reads (n, q, qd, M, f, L). */
typedef struct fake {
    qd_eom e;
    const qd_expr **arr;
} fake;

static qd_status dress(qd_ctx *ctx, const qd_speeds_eom *se, const qd_speeds_equilibria *s,
                       const qd_expr **G, fake *fk) {
    size_t k = s->nsolved;
    memset(fk, 0, sizeof *fk);
    fk->arr = qd__malloc(ctx, (3 * k + k * k + 1) * sizeof *fk->arr);
    if (!fk->arr)
        return QD_ERR_NOMEM;
    qd_eom *e = &fk->e;
    e->n = k;
    e->q = fk->arr;
    e->qd = fk->arr + k;
    e->qdd = fk->arr + 2 * k;
    e->M = fk->arr + 3 * k;
    e->f = G;
    e->L = qd_int(ctx, 0);
    for (size_t j = 0; j < k; j++) {
        e->q[j] = se->q[s->solved[j]];
        e->qd[j] = qd_jet(ctx, e->q[j], 1);
        e->qdd[j] = qd_jet(ctx, e->q[j], 2);
        for (size_t i = 0; i < k; i++)
            e->M[j * k + i] = qd_int(ctx, i == j);
    }
    return qd_ctx_status(ctx);
}

/* max_r |F_r| at the point p of the solved coordinates. */
static double rest_residual(const qd_speeds_equilibria *s, const qd_expr *const *in, size_t nin,
                            qd_prog *prog, const double *x0, double *x, double *v, size_t nz,
                            const qd_equilibrium *p, const qd_speeds_eom *e) {
    memcpy(x, x0, (nin + 1) * sizeof *x);
    for (size_t a = 0; a < nin; a++)
        for (size_t j = 0; j < s->nsolved; j++)
            if (in[a] == e->q[s->solved[j]])
                x[a] = p->q[j];
    qd_prog_run(prog, x, v);
    double r = 0;
    for (size_t i = 0; i < nz; i++)
        r = fmax(r, fabs(v[i]));
    return r;
}

/* Keep the points where every row of F is 0 (the gradient form has others,
 * minima of |F| above 0), judged against the size of the values given. */
static qd_status keep_roots(qd_ctx *ctx, const qd_speeds_eom *e, const qd_speeds_equilibria *s,
                            const qd_expr *const *F, size_t nz, size_t nvals,
                            const qd_expr *const *syms, const double *vals, qd_equilibria *eq) {
    size_t nin = 0;
    const qd_expr **in = qd__num_inputs(ctx, nz, F, &nin);
    qd_prog *prog = in ? qd_prog_new(ctx, nin, in, nz, F) : NULL;
    double *x0 = prog ? qd__calloc(ctx, 2 * nin + 2, sizeof *x0) : NULL;
    double *v = x0 ? qd__calloc(ctx, nz + 1, sizeof *v) : NULL;
    qd_status st = v ? QD_OK : qd_ctx_status(ctx) ? qd_ctx_status(ctx) : QD_ERR_NOMEM;
    double scale = 1;
    for (size_t b = 0; b < nvals; b++)
        scale = fmax(scale, fabs(vals[b]));
    for (size_t a = 0; st == QD_OK && a < nin; a++)
        for (size_t b = 0; b < nvals; b++)
            if (syms[b] == in[a])
                x0[a] = vals[b];
    size_t kept = 0;
    for (size_t i = 0; st == QD_OK && i < eq->count; i++) {
        qd_equilibrium *p = &eq->pts[i];
        double r = rest_residual(s, in, nin, prog, x0, x0 + nin + 1, v, nz, p, e);
        if (r <= 1e-8 * scale) {
            p->residual = fmax(p->residual, r);
            eq->pts[kept++] = *p;
        } else {
            qd__free(p->q);
            qd__free(p->exact);
        }
    }
    if (st == QD_OK)
        eq->count = kept;
    qd__free(v);
    qd__free(x0);
    qd_prog_free(prog);
    qd__free(in);
    return st;
}

/* No coordinate in the equations at rest: every configuration is at rest
 * (none of them is 0 identically: no rows), or none is. */
static qd_status no_unknowns(qd_ctx *ctx, qd_speeds_equilibria *out, size_t nz) {
    qd_equilibria *eq = &out->eq;
    eq->method = "exact";
    eq->exact = true;
    if (nz)
        return QD_OK;
    eq->pts = qd__calloc(ctx, 2, sizeof *eq->pts);
    if (!eq->pts || !(eq->pts[0].q = qd__calloc(ctx, 1, sizeof *eq->pts[0].q)))
        return QD_ERR_NOMEM;
    eq->pts[0].exact = qd__calloc(ctx, 1, sizeof *eq->pts[0].exact);
    if (!eq->pts[0].exact)
        return QD_ERR_NOMEM;
    eq->count = 1;
    eq->pts[0].kind = QD_EQ_DEGENERATE;
    eq->pts[0].symmetric = true;
    eq->continuum = out->n > 0;
    return QD_OK;
}

/* opts' arrays (n, over e->q) cut down to the solved coordinates. */
static qd_status sub_opts(qd_ctx *ctx, const qd_speeds_equilibria *s,
                          const qd_equilibria_opts *opts, qd_equilibria_opts *o, double **buf) {
    size_t k = s->nsolved;
    *o = opts ? *opts : (qd_equilibria_opts){0};
    o->near = o->lo = o->hi = NULL;
    if (!opts || (!opts->near && !(opts->lo && opts->hi)))
        return QD_OK;
    *buf = qd__malloc(ctx, (3 * k + 1) * sizeof **buf);
    if (!*buf)
        return QD_ERR_NOMEM;
    double *near = *buf, *lo = near + k, *hi = lo + k;
    for (size_t j = 0; j < k; j++) {
        size_t c = s->solved[j];
        if (opts->near)
            near[j] = opts->near[c];
        if (opts->lo && opts->hi) {
            lo[j] = opts->lo[c];
            hi[j] = opts->hi[c];
        }
    }
    o->near = opts->near ? near : NULL;
    if (opts->lo && opts->hi) {
        o->lo = lo;
        o->hi = hi;
    }
    return QD_OK;
}

qd_status qd_speeds_equilibria_find(qd_ctx *ctx, const struct qd_speeds_eom *e,
                                    const qd_model *m, size_t nvals,
                                    const qd_expr *const *syms, const double *vals,
                                    const qd_equilibria_opts *opts, qd_speeds_equilibria *out) {
    QD_ARGS_CTX(ctx, ctx && e && m && out);
    memset(out, 0, sizeof *out);
    if (!ctx || !e || !m)
        return QD_ERR_ARG;
    size_t n = e->n, nz = 0;
    out->n = n;
    out->solved = qd__calloc(ctx, n + 1, sizeof *out->solved);
    out->free_coord = qd__calloc(ctx, n + 1, sizeof *out->free_coord);
    const qd_expr **F = qd__malloc(ctx, (e->m + e->ncon + 1) * sizeof *F), **G = NULL;
    fake fk = {0};
    qd_status st = out->solved && out->free_coord && F ? QD_OK : QD_ERR_NOMEM;
    if (st == QD_OK)
        st = rest_equations(ctx, e, F, &nz, out);
    out->nrows = nz;
    if (st == QD_OK && out->nsolved == 0) {
        st = no_unknowns(ctx, out, nz);
        goto done;
    }
    if (st == QD_OK)
        st = (G = square(ctx, e, out, F, nz)) ? QD_OK : QD_ERR_NOMEM;
    if (st == QD_OK)
        st = dress(ctx, e, out, G, &fk);
    qd_equilibria_opts o = {0};
    double *buf = NULL;
    if (st == QD_OK)
        st = sub_opts(ctx, out, opts, &o, &buf);
    if (st == QD_OK)
        st = qd_equilibria_find(ctx, &fk.e, m, nvals, syms, vals, &o, &out->eq);
    if (st == QD_OK && nz > out->nsolved)
        st = keep_roots(ctx, e, out, F, nz, nvals, syms, vals, &out->eq);
    qd__free(buf);
done:
    qd__free(fk.arr);
    qd__free(F);
    qd__free(G);
    if (st != QD_OK) {
        if (qd_ctx_status(ctx) == QD_OK)
            qd_ctx_error(ctx, st, "finding the equilibria of the equations in speeds failed");
        qd_speeds_equilibria_free(out);
    }
    return st;
}

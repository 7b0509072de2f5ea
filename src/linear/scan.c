/*
 * src/linear/scan.c - an equilibrium (qd_modes_scan, qdot/modes.h) or a
 * steady motion (qd_stability_scan, qdot/stability.h) followed along a
 * parameter, and the values where its stability changes.
 *
 * Natural-parameter continuation: at each sample the point of the previous
 * one (moved by the change of `about`, when given) starts damped Newton
 * (qd__lin_lm_solve; qd_steady_find for steady motions, the given values held).
 * The verdict is the one qd_modes_solve / qd_stability_analyze gives, so a
 * scan agrees with `qdot modes` and `qdot stability` at every value it
 * lists.  A change between two samples is bisected: on the sign of the
 * margin (the smallest w^2, the largest Re s) when it crosses zero clear of
 * round-off, else on the verdict itself, which is in effect the sign of the
 * discriminant in s^2 where two frequencies collide (L4).  Near such a
 * collision the eigenvalues are computed to sqrt(eps) only, but the split
 * grows as sqrt(|mu - mu_c|), so the verdict stays right to
 * |mu - mu_c| ~ eps (Desloge ch. 62; seed-desloge-B.md C6, pitfall 3).
 */
#include "linear.h"

#include "qdot/equilibria.h"
#include "qdot/stability.h"
#include "base/mem.h"
#include "../base/args.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The parameters at one value of the scanned one: each other parameter
 * follows its definition in the earlier ones. */
typedef struct scan_params {
    const qd_model *m;
    size_t np, idx;          /* idx: the scanned parameter */
    const qd_expr **syms;
    double *vals;
} scan_params;

/* What a scan keeps while it runs.  The point followed is a vector u of nu
 * numbers: an equilibrium's coordinates, or a steady motion's kept
 * coordinates, rates and momenta; the two kinds differ only in solve (u at
 * the parameters set, from u) and verdict. */
typedef struct scan_run scan_run;
struct scan_run {
    qd_ctx *ctx;
    scan_params P;
    const char *name;            /* the parameter */
    const char *what;            /* "equilibrium", "steady motion" */
    size_t nu;
    qd_status (*solve)(scan_run *r, double *u);
    qd_status (*verdict)(scan_run *r, const double *u, int *stable, double *margin,
                         bool *conservative);
    qd_status (*first)(scan_run *r, const qd_scan_opts *o, double a, double *u);
    /* equilibria */
    const qd_eom *e;
    qd__lin L;
    qd_linear lin;               /* about the current point */
    const qd_expr *const *about;
    double *ab_prev, *ab_next;   /* about at the last point reached and at the next */
    /* steady motions */
    const qd_steady *s;
    const bool *xfix, *wfix, *pfix, *pguess;
    const qd_steady_point *start;
    const qd_expr *const *given; /* nu: held values as expressions (NULL: a number) */
    qd_steady_point pt;          /* scratch: u unpacked */
    bool damped;                 /* some verdict was the damped one */
};

/* ---- the parameters ---------------------------------------------------------- */

static qd_status params_at(qd_ctx *ctx, scan_params *P, double v) {
    for (size_t i = 0; i < P->np; i++) {
        if (i == P->idx) {
            P->vals[i] = v;
            continue;
        }
        if (qd_eval(ctx, qd_model_param_definition(P->m, i), i, P->syms, P->vals,
                    &P->vals[i]) != QD_OK || !isfinite(P->vals[i])) {
            if (!qd__ctx_recover(ctx))
                return QD_ERR_NOMEM;
            qd_ctx_error(ctx, QD_ERR_ARG, "parameter %s has no finite value at %s = %.12g",
                         qd_expr_name(P->syms[i]), qd_expr_name(P->syms[P->idx]), v);
            return QD_ERR_ARG;
        }
    }
    return QD_OK;
}

/* The scanned parameter's index, refusing what cannot be scanned. */
static qd_status param_find(qd_ctx *ctx, const qd_model *m, const char *name, double a, double b,
                            size_t *idx) {
    size_t np = qd_model_nparams(m), i = 0;
    while (i < np && strcmp(qd_expr_name(qd_model_param(m, i)), name))
        i++;
    if (i == np) {
        qd_ctx_error(ctx, QD_ERR_ARG, "'%s' is not a parameter of the model%s", name,
                     np ? "" : " (it has none)");
        return QD_ERR_ARG;
    }
    const qd_expr *sym = qd_model_param(m, i);
    double v;
    if (qd_model_param_fixed(m, i)) {
        qd_ctx_error(ctx, QD_ERR_ARG, "parameter %s is fixed (its number is written into the "
                     "equations): it cannot be scanned", name);
        return QD_ERR_ARG;
    }
    if (qd_eval(ctx, qd_model_param_definition(m, i), 0, NULL, NULL, &v) != QD_OK) {
        if (!qd__ctx_recover(ctx))
            return QD_ERR_NOMEM;
        qd_ctx_error(ctx, QD_ERR_ARG, "parameter %s is defined from other parameters: scan "
                     "one of those", name);
        return QD_ERR_ARG;
    }
    if (!(a < b) || !isfinite(a) || !isfinite(b)) {
        qd_ctx_error(ctx, QD_ERR_ARG, "the range of %s is empty: give A < B (%.12g:%.12g)",
                     name, a, b);
        return QD_ERR_ARG;
    }
    if (qd_symbol_is_positive(sym) && !(a > 0)) {
        qd_ctx_error(ctx, QD_ERR_ARG, "parameter %s is assumed positive (its value was "
                     "positive when the model was read): the range must stay above 0", name);
        return QD_ERR_ARG;
    }
    *idx = i;
    return QD_OK;
}

static qd_status params_init(qd_ctx *ctx, const qd_model *m, size_t idx, scan_params *P) {
    P->m = m;
    P->np = qd_model_nparams(m);
    P->idx = idx;
    P->syms = qd__malloc(ctx, (P->np + 2) * sizeof *P->syms);
    P->vals = qd__malloc(ctx, (P->np + 2) * sizeof *P->vals);
    if (!P->syms || !P->vals)
        return QD_ERR_NOMEM;
    for (size_t i = 0; i < P->np; i++)
        P->syms[i] = qd_model_param(m, i);
    P->syms[P->np] = qd_time(ctx);   /* t = 0: a steady motion's equations ask for it */
    P->vals[P->np] = 0;
    return P->syms[P->np] ? QD_OK : QD_ERR_NOMEM;
}

/* ---- one point ------------------------------------------------------------------ */

/* `about` at the current parameters into out (n). */
static qd_status about_at(scan_run *r, double *out) {
    for (size_t j = 0; r->about && j < r->L.n; j++)
        if (qd_eval(r->ctx, r->about[j], r->P.np, r->P.syms, r->P.vals, &out[j]) != QD_OK ||
            !isfinite(out[j])) {
            if (!qd__ctx_recover(r->ctx))
                return QD_ERR_NOMEM;
            qd_ctx_error(r->ctx, QD_ERR_ARG, "the point given for %s is not a finite number "
                         "of the parameters", qd_expr_name(r->L.q[j]));
            return QD_ERR_ARG;
        }
    return QD_OK;
}

/* The equilibrium from q, in place: damped Newton. */
static qd_status modes_solve(scan_run *r, double *q) {
    qd__lin_bind(&r->L, r->P.np, r->P.syms, r->P.vals);
    double res, ftol = 1e-11 * qd__lin_scale(&r->L, q);
    if (!isfinite(ftol) || !qd__lin_lm_solve(&r->L, q, ftol, 200, &res))
        return qd__ctx_nomem(r->ctx) ? QD_ERR_NOMEM : QD_ERR_NUMERIC;
    /* a few more steps to round-off: the verdict near a collision of
     * eigenvalues is as sensitive to the point as to the parameter */
    qd__lin_lm_solve(&r->L, q, 0, 4, &res);
    return qd__ctx_nomem(r->ctx) ? QD_ERR_NOMEM : QD_OK;
}

/* Set the parameters to v and solve for the point from u (in place), moved
 * first by the change of `about` since the last point reached. */
static qd_status solve_at(scan_run *r, double v, double *u) {
    qd_status st = params_at(r->ctx, &r->P, v);
    if (st == QD_OK && r->about && (st = about_at(r, r->ab_next)) == QD_OK)
        for (size_t j = 0; j < r->nu; j++)
            u[j] += r->ab_next[j] - r->ab_prev[j];
    return st == QD_OK ? r->solve(r, u) : st;
}

/* Accept a point reached: `about` there is the base of the next step. */
static void reached(scan_run *r) {
    if (r->about)
        memcpy(r->ab_prev, r->ab_next, r->nu * sizeof *r->ab_prev);
}

/* The verdict at q (parameters as set by solve_at) and its margin. */
static qd_status modes_verdict(scan_run *r, const double *q, int *stable, double *margin,
                            bool *conservative) {
    size_t n = r->L.n;
    qd__lin_run(&r->L, q);
    const double *J = qd__lin_J(&r->L), *B = qd__lin_B(&r->L), *M = qd__lin_M(&r->L);
    for (size_t j = 0; j < n; j++)
        for (size_t k = 0; k < n; k++) {
            r->lin.M[j * n + k] = M[j * n + k];
            r->lin.K[j * n + k] = -J[j * n + k];
            r->lin.C[j * n + k] = -(B[j * n + k] + B[k * n + j]) / 2;
            r->lin.G[j * n + k] = -(B[j * n + k] - B[k * n + j]) / 2;
        }
    qd_modes_result res;
    qd_status st = qd_modes_solve(r->ctx, &r->lin, &res);
    if (st == QD_OK) {
        *stable = res.stable;
        *conservative = res.conservative;
        *margin = res.conservative ? res.omega2[0] : res.eig_re[0];
    }
    qd_modes_result_free(&res);
    return st;
}

/* ---- continuation ------------------------------------------------------------------ */

/* From (v0, q) to v1, halving the step while Newton fails. */
static qd_status advance(scan_run *r, double v0, double v1, double *q, double *work) {
    size_t n = r->nu;
    double v = v0, h = v1 - v0, hmin = 1e-6 * fabs(v1 - v0);
    while (v != v1) {
        double to = fabs(h) >= fabs(v1 - v) ? v1 : v + h;
        memcpy(work, q, n * sizeof *work);
        qd_status st = solve_at(r, to, work);
        if (st == QD_OK) {
            memcpy(q, work, n * sizeof *q);
            reached(r);
            v = to;
            continue;
        }
        if (st != QD_ERR_NUMERIC)
            return st;
        h /= 2;
        if (fabs(h) < hmin) {
            qd_ctx_error(r->ctx, QD_ERR_NUMERIC, "the %s is lost at %s = %.12g: "
                         "Newton's method from its value at %s = %.12g does not converge",
                         r->what, r->name, to, r->name, v);
            return QD_ERR_NUMERIC;
        }
    }
    return QD_OK;
}

/* The equilibrium at a: about(a), the caller's start, or libqdot's choice. */
static qd_status modes_first(scan_run *r, const qd_scan_opts *o, double a, double *q) {
    size_t n = r->nu;
    qd_status st = params_at(r->ctx, &r->P, a);
    if (st != QD_OK)
        return st;
    if (r->about) {
        if ((st = about_at(r, r->ab_prev)) != QD_OK)
            return st;
        memcpy(q, r->ab_prev, n * sizeof *q);
        memcpy(r->ab_next, r->ab_prev, n * sizeof *q);
    } else if (o->start) {
        memcpy(q, o->start, n * sizeof *q);
    } else {
        qd_equilibrium_choice ch;
        st = qd_equilibria_choose(r->ctx, r->e, r->P.m, r->P.np, r->P.syms, r->P.vals, &ch);
        if (st == QD_OK && !ch.pt) {
            qd_ctx_error(r->ctx, QD_ERR_NUMERIC, "no equilibrium found at %s = %.12g: give "
                         "a point", r->name, a);
            st = QD_ERR_NUMERIC;
        }
        if (st == QD_OK)
            memcpy(q, ch.pt->q, n * sizeof *q);
        qd_equilibrium_choice_free(&ch);
        if (st != QD_OK)
            return st;
    }
    if ((st = solve_at(r, a, q)) == QD_ERR_NUMERIC)
        qd_ctx_error(r->ctx, QD_ERR_NUMERIC, "no equilibrium near the point given at %s = "
                     "%.12g: Newton's method does not converge", r->name, a);
    return st;
}

/* Return to the point at lo: its parameters and `about` there. */
static qd_status back_to(scan_run *r, double lo, const double *qlo, double *q) {
    memcpy(q, qlo, r->nu * sizeof *q);
    qd_status st = params_at(r->ctx, &r->P, lo);
    if (st == QD_OK && r->about)
        st = about_at(r, r->ab_prev);
    return st;
}

/* Does the margin itself cross zero between samples k and k + 1, clear of
 * round-off at both ends?  Then its sign is the quantity to bisect: a w^2
 * through zero, a pair of damped roots through the imaginary axis.  Not at
 * a collision of frequencies (L4 at Routh's value), where the margin is
 * round-off on the stable side and the verdict is bisected instead. */
static bool margin_crosses(const qd_scan *out, size_t k) {
    double m0 = out->margin[k], m1 = out->margin[k + 1];
    double big = fmax(fabs(m0), fabs(m1));
    return out->conservative[k] == out->conservative[k + 1] && m0 * m1 < 0 &&
           fmin(fabs(m0), fabs(m1)) > 1e-9 * big;
}

/* Bisect the change between samples k and k + 1 of out; qlo: room for n.
 * The predicate is "the margin still has sample k's sign" when the margin
 * crosses zero (margin_crosses): exact, whatever the tolerances of the
 * verdict (a damped root with Re s < 1e-9 |s| counts as on the axis, which
 * would put the bowl's threshold 4e-8 late).  Otherwise it is "the verdict
 * is still sample k's": a midpoint in the thin borderline band where two
 * frequencies meet (within QD_MODES_ZERO_TOL's reach of the collision)
 * counts with the far side, whose verdict the transition reports. */
static qd_status bisect(scan_run *r, qd_scan *out, size_t k, double tol, double *q, double *qlo,
                        double *work) {
    size_t n = r->nu;
    double lo = out->value[k], hi = out->value[k + 1], margin, m0 = out->margin[k];
    int from = out->stable[k], to = out->stable[k + 1], v;
    bool cons, by_margin = margin_crosses(out, k);
    memcpy(qlo, out->q + k * n, n * sizeof *qlo);
    qd_status st = back_to(r, lo, qlo, q);
    while (st == QD_OK && hi - lo > tol) {
        double mid = lo + (hi - lo) / 2;
        if (mid <= lo || mid >= hi)
            break;
        if ((st = advance(r, lo, mid, q, work)) != QD_OK ||
            (st = r->verdict(r, q, &v, &margin, &cons)) != QD_OK)
            break;
        if (by_margin ? (margin > 0) == (m0 > 0) : v == from) {
            lo = mid;
            memcpy(qlo, q, n * sizeof *qlo);
        } else {
            hi = mid;
            st = back_to(r, lo, qlo, q);
        }
    }
    if (st != QD_OK)
        return st;
    out->trans[out->ntrans++] = (qd_scan_transition){lo + (hi - lo) / 2, lo, hi, from, to};
    return QD_OK;
}

/* ---- the scan ------------------------------------------------------------------------ */

static qd_status alloc_out(qd_ctx *ctx, size_t n, size_t count, qd_scan *out) {
    out->n = n;
    out->value = qd__calloc(ctx, count, sizeof *out->value);
    out->q = qd__calloc(ctx, count * n + 1, sizeof *out->q);
    out->stable = qd__calloc(ctx, count, sizeof *out->stable);
    out->margin = qd__calloc(ctx, count, sizeof *out->margin);
    out->conservative = qd__calloc(ctx, count, sizeof *out->conservative);
    out->trans = qd__calloc(ctx, count, sizeof *out->trans);
    return out->value && out->q && out->stable && out->margin && out->conservative && out->trans
               ? QD_OK : QD_ERR_NOMEM;
}

static qd_status alloc_run(qd_ctx *ctx, size_t n, scan_run *r) {
    size_t nn = n * n;
    r->ab_prev = qd__calloc(ctx, n + 1, sizeof *r->ab_prev);
    r->ab_next = qd__calloc(ctx, n + 1, sizeof *r->ab_next);
    r->lin.n = n;
    r->lin.M = qd__malloc(ctx, (nn + 1) * sizeof *r->lin.M);
    r->lin.C = qd__malloc(ctx, (nn + 1) * sizeof *r->lin.C);
    r->lin.G = qd__malloc(ctx, (nn + 1) * sizeof *r->lin.G);
    r->lin.K = qd__malloc(ctx, (nn + 1) * sizeof *r->lin.K);
    return r->ab_prev && r->ab_next && r->lin.M && r->lin.C && r->lin.G && r->lin.K
               ? QD_OK : QD_ERR_NOMEM;
}

/* A sample that lands on the change itself is borderline there: a w^2 or
 * a root within QD_MODES_ZERO_TOL of zero (a band of width ~1e-10 round
 * n = -3 for power-law orbits).  unstable -> borderline -> stable across a
 * band narrower than the spacing of the samples is one transition,
 * unstable -> stable, at the middle of the band. */
static void merge_borderline(qd_scan *out, double spacing) {
    size_t k = 0;
    for (size_t i = 0; i < out->ntrans; i++) {
        qd_scan_transition *t = &out->trans[i], *u = i + 1 < out->ntrans ? t + 1 : NULL;
        if (u && t->to == -1 && u->from == -1 && t->from != u->to &&
            u->value - t->value < spacing) {
            double mid = t->value + (u->value - t->value) / 2;
            out->trans[k++] = (qd_scan_transition){mid, t->lo, u->hi, t->from, u->to};
            i++;
        } else {
            out->trans[k++] = *t;
        }
    }
    out->ntrans = k;
}

/* Every sample, then every change of verdict between neighbours. */
static qd_status run_scan(scan_run *r, const qd_scan_opts *o, double a, double b,
                          qd_scan *out) {
    size_t n = r->nu, steps = o->steps ? o->steps : 200;
    double tol = o->tol > 0 ? o->tol : 1e-13 * fmax(1, fmax(fabs(a), fabs(b)));
    double *q = qd__calloc(r->ctx, 3 * n + 1, sizeof *q), *work = q ? q + n : NULL;
    qd_status st = q ? alloc_out(r->ctx, n, steps + 1, out) : QD_ERR_NOMEM;
    if (st == QD_OK)
        st = r->first(r, o, a, q);
    for (size_t k = 0; st == QD_OK && k <= steps; k++) {
        double v = k == steps ? b : a + (b - a) * (double)k / (double)steps;
        if (k)
            st = advance(r, out->value[k - 1], v, q, work);
        if (st == QD_OK)
            st = r->verdict(r, q, &out->stable[k], &out->margin[k], &out->conservative[k]);
        out->value[k] = v;
        memcpy(out->q + k * n, q, n * sizeof *q);
        out->count = k + 1;
    }
    for (size_t k = 0; st == QD_OK && k + 1 < out->count; k++)
        if (out->stable[k] != out->stable[k + 1])
            st = bisect(r, out, k, tol, q, work + n, work);
    if (st == QD_OK)
        merge_borderline(out, (b - a) / (double)steps);
    qd__free(q);
    return st;
}

qd_status qd_modes_scan(qd_ctx *ctx, const qd_eom *e, const qd_model *m, const char *param,
                        double a, double b, const qd_scan_opts *opts, qd_scan *out) {
    QD_ARGS_CTX(ctx, ctx && e && m && param && out);
    memset(out, 0, sizeof *out);
    if (!ctx || !e || !m || !param)
        return QD_ERR_ARG;
    qd_scan_opts o = opts ? *opts : (qd_scan_opts){0};
    scan_run r = {.ctx = ctx, .about = o.about, .name = param, .what = "equilibrium",
                  .nu = e->n, .e = e, .solve = modes_solve, .verdict = modes_verdict,
                  .first = modes_first};
    size_t idx;
    qd_status st = param_find(ctx, m, param, a, b, &idx);
    if (st == QD_OK)
        st = params_init(ctx, m, idx, &r.P);
    if (st == QD_OK)
        st = qd__lin_init(ctx, e, &r.L);
    if (st == QD_OK) {
        if ((st = alloc_run(ctx, e->n, &r)) == QD_OK)
            st = run_scan(&r, &o, a, b, out);
        qd__lin_free(&r.L);
    }
    if (st == QD_ERR_NOMEM && qd_ctx_status(ctx) == QD_OK)
        qd_ctx_error(ctx, st, "out of memory in the scan");
    qd__free(r.P.syms);
    qd__free(r.P.vals);
    qd__free(r.ab_prev);
    qd__free(r.ab_next);
    qd_linear_free(&r.lin);
    return st;
}

/* ---- steady motions (qdot/stability.h) ------------------------------------------- */

/* u = (x, w, p) into r->pt and back. */
static void unpack(scan_run *r, const double *u) {
    size_t nk = r->s->nkeep, nc = r->s->ncyc;
    memcpy(r->pt.x, u, nk * sizeof *u);
    memcpy(r->pt.w, u + nk, nc * sizeof *u);
    memcpy(r->pt.p, u + nk + nc, nc * sizeof *u);
}

static void pack(const scan_run *r, const qd_steady_point *pt, double *u) {
    size_t nk = r->s->nkeep, nc = r->s->ncyc;
    memcpy(u, pt->x, nk * sizeof *u);
    memcpy(u + nk, pt->w, nc * sizeof *u);
    memcpy(u + nk + nc, pt->p, nc * sizeof *u);
}

/* The steady motion from u: the given values held, the rest found by
 * qd_steady_find.  No motion there (or a singular point) is a failed step:
 * its message is dropped, the continuation halves the step. */
/* The held values of u that are expressions (r->given), at the parameters
 * set. */
static qd_status held_values(scan_run *r, double *u) {
    size_t nk = r->s->nkeep, nc = r->s->ncyc;
    for (size_t i = 0; r->given && i < r->nu; i++) {
        bool held = i < nk ? r->xfix[i] : i < nk + nc ? r->wfix[i - nk] : r->pfix[i - nk - nc];
        if (!held || !r->given[i])
            continue;
        if (qd_eval(r->ctx, r->given[i], r->P.np + 1, r->P.syms, r->P.vals, &u[i]) != QD_OK ||
            !isfinite(u[i])) {
            if (!qd__ctx_recover(r->ctx))
                return QD_ERR_NOMEM;
            qd_ctx_error(r->ctx, QD_ERR_ARG, "a value given is not a finite number of the "
                         "parameters at %s = %.12g", r->name, r->P.vals[r->P.idx]);
            return QD_ERR_ARG;
        }
    }
    return QD_OK;
}

static qd_status steady_solve(scan_run *r, double *u) {
    double res;
    qd_status st0 = held_values(r, u);
    if (st0 != QD_OK)
        return st0;
    unpack(r, u);
    qd_status st = qd_steady_find(r->ctx, r->s, r->P.np + 1, r->P.syms, r->P.vals, r->xfix,
                                  r->wfix, r->pfix, &r->pt, &res);
    if (st == QD_ERR_NUMERIC || st == QD_ERR_SINGULAR)
        return qd__ctx_recover(r->ctx) ? QD_ERR_NUMERIC : QD_ERR_NOMEM;
    if (st == QD_OK)
        pack(r, &r->pt, u);
    return st;
}

/* The verdict of qd_stability_analyze for the motion with the model's own
 * damping: ordinary without dissipation, the damped roots with it. */
static qd_status steady_verdict(scan_run *r, const double *u, int *stable, double *margin,
                                bool *conservative) {
    qd_stability an;
    unpack(r, u);
    qd_status st = qd_stability_analyze(r->ctx, r->s, r->P.np + 1, r->P.syms, r->P.vals, &r->pt,
                                        &an);
    if (st != QD_OK && qd__ctx_nomem(r->ctx))
        st = QD_ERR_NOMEM; /* the analysis may report what the failure left (SINGULAR) */
    if (st == QD_OK) {
        const qd_modes_result *o = an.dissipative ? &an.damped : &an.ordinary;
        r->damped = r->damped || an.dissipative;
        *stable = an.dissipative ? an.damped_stable : an.ordinary_stable;
        *conservative = o->conservative;
        *margin = o->conservative ? o->omega2[0] : o->eig_re[0];
        qd_stability_free(&an);
    }
    return st;
}

/* The first steady motion at a: the one qd_steady_find_all lists first
 * (nearest the start). */
static qd_status steady_first(scan_run *r, const qd_scan_opts *o, double a, double *u) {
    (void)o;
    qd_steady_set set;
    qd_status st = params_at(r->ctx, &r->P, a);
    if (st != QD_OK)
        return st;
    double *u0 = qd__calloc(r->ctx, r->nu + 1, sizeof *u0);
    if (!u0)
        return QD_ERR_NOMEM;
    pack(r, r->start, u0);
    if ((st = held_values(r, u0)) == QD_OK) {
        unpack(r, u0);
        st = qd_steady_find_all(r->ctx, r->s, r->P.np + 1, r->P.syms, r->P.vals, r->xfix,
                                r->wfix, r->pfix, r->pguess, &r->pt, &set);
        if (st != QD_OK && qd__ctx_nomem(r->ctx))
            st = QD_ERR_NOMEM; /* the search may report what the failure left (SINGULAR) */
    }
    qd__free(u0);
    if (st == QD_OK && set.count == 0) {
        qd_ctx_error(r->ctx, QD_ERR_NUMERIC, "no steady motion found at %s = %.12g", r->name, a);
        st = QD_ERR_NUMERIC;
    }
    if (st == QD_OK)
        pack(r, &set.pts[0], u);
    qd_steady_set_free(&set);
    return st;
}

static qd_status alloc_pt(qd_ctx *ctx, const qd_steady *s, qd_steady_point *pt) {
    pt->x = qd__calloc(ctx, s->nkeep + 1, sizeof *pt->x);
    pt->w = qd__calloc(ctx, s->ncyc + 1, sizeof *pt->w);
    pt->p = qd__calloc(ctx, s->ncyc + 1, sizeof *pt->p);
    return pt->x && pt->w && pt->p ? QD_OK : QD_ERR_NOMEM;
}

qd_status qd_stability_scan(qd_ctx *ctx, const qd_steady *s, const qd_model *m,
                            const char *param, double a, double b, const bool *xfix,
                            const bool *wfix, const bool *pfix, const bool *pguess,
                            const qd_steady_point *start, const qd_scan_opts *opts,
                            qd_scan *out) {
    QD_ARGS_CTX(ctx, ctx && s && m && param && xfix && wfix && pfix && start && out);
    memset(out, 0, sizeof *out);
    if (!ctx || !s || !m || !param || !start)
        return QD_ERR_ARG;
    qd_scan_opts o = opts ? *opts : (qd_scan_opts){0};
    scan_run r = {.ctx = ctx, .name = param, .what = "steady motion", .given = o.about,
                  .nu = s->nkeep + 2 * s->ncyc, .s = s, .xfix = xfix, .wfix = wfix,
                  .pfix = pfix, .pguess = pguess, .start = start, .solve = steady_solve,
                  .verdict = steady_verdict, .first = steady_first};
    size_t idx;
    qd_status st = param_find(ctx, m, param, a, b, &idx);
    if (st == QD_OK)
        st = params_init(ctx, m, idx, &r.P);
    if (st == QD_OK)
        st = alloc_pt(ctx, s, &r.pt);
    o.about = NULL;   /* the held values, not a predictor */
    if (st == QD_OK)
        st = run_scan(&r, &o, a, b, out);
    if (st == QD_OK && qd__ctx_nomem(ctx))
        st = QD_ERR_NOMEM; /* a search inside took a fallback for want of memory */
    out->damped = r.damped;
    if (st == QD_ERR_NOMEM && qd_ctx_status(ctx) == QD_OK)
        qd_ctx_error(ctx, st, "out of memory in the scan");
    qd__free(r.P.syms);
    qd__free(r.P.vals);
    qd__free(r.pt.x);
    qd__free(r.pt.w);
    qd__free(r.pt.p);
    return st;
}

void qd_scan_free(qd_scan *s) {
    if (!s)
        return;
    qd__free(s->value);
    qd__free(s->q);
    qd__free(s->stable);
    qd__free(s->margin);
    qd__free(s->conservative);
    qd__free(s->trans);
    memset(s, 0, sizeof *s);
}

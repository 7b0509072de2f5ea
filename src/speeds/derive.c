/*
 * src/speeds/derive.c - the equations in speeds: the velocity map P = [A; C]
 * from the speeds' definitions and the constraints' rows, its inverse
 * [W | Wc] and the kinematics q' = W u + w, then one of the methods
 * (kane.c, appell.c, hamel.c) for M_u u' = f_u.
 *
 * P is not inverted: P q' = (u - b, s - c0) is solved once with the speeds
 * (and the constraints' symbols s, when wanted) in the right-hand side, and
 * W, Wc, w are read off as coefficients (velocity_map).  P is sparse in
 * practice (a speed is a few velocities, a rolling constraint three): the
 * rows and columns with one entry are solved directly and only the rest by
 * fraction-free elimination (qd__mech_solve_sparse), so the solution stays short
 * and costs little (the rolling disk's map is triangular).  A singular P is reported at the row that depends on those
 * before it, found numerically at a random state.
 */
#include "spd.h"

#include "../base/mem.h"
#include "../num/num.h"
#include "../base/args.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char *const METHOD_NAMES[QD_SPEEDS_METHOD_COUNT] = {"kane", "appell", "hamel"};

const char *qd_speeds_method_name(qd_speeds_method m) {
    return (unsigned)m < QD_SPEEDS_METHOD_COUNT ? METHOD_NAMES[m] : NULL;
}

bool qd_speeds_method_from_name(const char *name, qd_speeds_method *m) {
    QD_ARGS(false, name && m);
    for (unsigned i = 0; name && i < QD_SPEEDS_METHOD_COUNT; i++)
        if (!strcmp(name, METHOD_NAMES[i])) {
            if (m)
                *m = (qd_speeds_method)i;
            return true;
        }
    return false;
}

void qd_speeds_eom_free(qd_speeds_eom *e) {
    if (!e)
        return;
    qd__spd_priv *pv = e->priv;
    if (pv) {
        qd_eom_free(pv->shell);
        qd_prog_free(pv->prog);
        qd__free(pv->in);
        qd__free(pv->work);
        qd__free(pv);
    }
    /* one block holds every array but mult (alloc below) */
    qd__free(e->q);
    qd__free(e->mult);
    qd__free(e->acc);
    qd__free(e);
}

/* Every array of e in one block: q, qd (n), u, ud, def (m), W (n*m), w, kin
 * (n), M (m*m), f (m). */
static qd_speeds_eom *alloc(qd_ctx *ctx, size_t n, size_t m, size_t nc) {
    qd_speeds_eom *e = qd__calloc(ctx, 1, sizeof *e);
    size_t total = 4 * n + 4 * m + n * m + m * m + 1;
    const qd_expr **b = e ? qd__calloc(ctx, total, sizeof *b) : NULL;
    qd__spd_priv *pv = b ? qd__calloc(ctx, 1, sizeof *pv) : NULL;
    if (!pv) {
        qd__free(b);
        qd__free(e);
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory deriving the equations in speeds");
        return NULL;
    }
    *e = (qd_speeds_eom){.n = n, .m = m, .ncon = nc, .priv = pv};
    e->q = b, b += n;
    e->qd = b, b += n;
    e->u = b, b += m;
    e->ud = b, b += m;
    e->def = b, b += m;
    e->W = b, b += n * m;
    e->w = b, b += n;
    e->kin = b, b += n;
    e->M = b, b += m * m;
    e->f = b, b += m;
    (void)b;
    return e;
}

static qd_status nomem(qd_ctx *ctx) {
    if (qd_ctx_status(ctx) == QD_OK)
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory deriving the equations in speeds");
    return qd_ctx_status(ctx);
}

/* ---- the velocity map ----------------------------------------------------- */

/* Row r of P from speed r's definition: u_r = A_r q' + b_r. */
static qd_status speed_row(qd__spd *d, size_t r) {
    qd_ctx *ctx = d->ctx;
    qd_speeds_eom *e = d->e;
    const qd_expr *rest = NULL;
    qd_status st = qd_linear_coeffs(ctx, e->def[r], d->n, e->qd, d->P + r * d->n, &rest);
    if (st == QD_ERR_NONLINEAR) {
        qd__ctx_recover(ctx);
        qd_ctx_error(ctx, QD_ERR_ARG, "speed %s is not linear in the velocities",
                     qd_expr_name(e->u[r]));
        qd_ctx_error_about(ctx, QD_SUBJECT_SPEED, r, qd_expr_name(e->u[r]), QD_REASON_NONE,
                           "a speed is linear in the velocities: u = a(q, t) q' + b(q, t)");
        return QD_ERR_ARG;
    }
    if (st != QD_OK)
        return qd_ctx_status(ctx) != QD_OK ? qd_ctx_status(ctx) : st;
    for (size_t j = 0; j < d->n; j++)
        if (!(d->P[r * d->n + j] = qd_simplify(ctx, d->P[r * d->n + j])))
            return nomem(ctx);
    d->p0[r] = qd_simplify(ctx, rest);
    return d->p0[r] ? QD_OK : nomem(ctx);
}

/* The first row of P (in its order: speeds, then constraints) that depends
 * on the rows before it, at a random state; n when none is found there. */
static size_t dependent_row(qd__spd *d) {
    size_t n = d->n, ns = 0;
    const qd_expr *syms[64];
    double vals[64], *R = qd__malloc(d->ctx, (n * n + 1) * sizeof *R);
    size_t found = n;
    if (!R)
        return n;
    for (size_t i = 0; i < n * n; i++) {
        const qd_expr *buf[64];
        size_t k = qd_free_symbols(d->ctx, d->P[i], buf, 64);
        for (size_t a = 0; a < k && a < 64; a++) {
            bool have = false;
            for (size_t b = 0; b < ns; b++)
                have = have || syms[b] == buf[a];
            if (!have && ns < 64) {
                syms[ns] = buf[a];
                vals[ns] = 0.31 + 0.57 * (double)((ns * 7919 + 17) % 97) / 97.0;
                ns++;
            }
        }
    }
    for (size_t i = 0; i < n * n; i++)
        if (qd_eval(d->ctx, d->P[i], ns, syms, vals, &R[i]) != QD_OK) {
            qd__ctx_recover(d->ctx);
            R[i] = NAN;
        }
    /* Gram-Schmidt on the rows in order: the first with nothing left */
    double scale = 1e-300;
    for (size_t i = 0; i < n * n; i++)
        scale = fabs(R[i]) > scale ? fabs(R[i]) : scale;
    for (size_t r = 0; r < n && found == n; r++) {
        double *x = R + r * n;
        for (size_t s = 0; s < r; s++) {
            const double *y = R + s * n;
            double dot = 0, yy = 0;
            for (size_t j = 0; j < n; j++)
                dot += x[j] * y[j], yy += y[j] * y[j];
            for (size_t j = 0; yy > 0 && j < n; j++)
                x[j] -= dot / yy * y[j];
        }
        double norm = 0;
        for (size_t j = 0; j < n; j++)
            norm += x[j] * x[j];
        if (!(sqrt(norm) > 1e-9 * scale))
            found = r;
    }
    qd__free(R);
    return found;
}

static qd_status singular_map(qd__spd *d) {
    qd_ctx *ctx = d->ctx;
    qd_speeds_eom *e = d->e;
    size_t r = dependent_row(d);
    const char *hint = "the speeds and the constraints together must fix every velocity: "
                       "n of them, independent";
    if (r >= d->m && r < d->n) {
        const char *name = e->con[r - d->m].name;
        qd_ctx_error(ctx, QD_ERR_SINGULAR,
                     "the speeds repeat constraint %s: with the constraints they do not "
                     "determine the velocities", name);
        qd_ctx_error_about(ctx, QD_SUBJECT_CONSTRAINT, r - d->m, name,
                           QD_REASON_DEPENDENT_SPEEDS, hint);
        return QD_ERR_SINGULAR;
    }
    if (r == d->n)
        r = d->m ? d->m - 1 : 0;
    qd_ctx_error(ctx, QD_ERR_SINGULAR,
                 "speed %s depends on the speeds and constraints before it: the speeds do not "
                 "determine the velocities (the map u = A q' + b is singular)",
                 qd_expr_name(e->u[r]));
    qd_ctx_error_about(ctx, QD_SUBJECT_SPEED, r, qd_expr_name(e->u[r]),
                       QD_REASON_DEPENDENT_SPEEDS, hint);
    return QD_ERR_SINGULAR;
}

static qd_status count_error(qd__spd *d) {
    qd_ctx *ctx = d->ctx;
    size_t r = d->m - 1;
    bool few = d->m + d->nc < d->n;
    qd_ctx_error(ctx, QD_ERR_SINGULAR,
                 "%zu speeds and %zu constraints for %zu coordinates: %s (speeds + constraints "
                 "must equal the coordinates)",
                 d->m, d->nc, d->n,
                 few ? "too few to determine the velocities" : "too many: some repeat others");
    qd_ctx_error_about(ctx, QD_SUBJECT_SPEED, r, qd_expr_name(d->e->u[r]),
                       QD_REASON_DEPENDENT_SPEEDS,
                       few ? "declare one speed per degree of freedom left by the constraints"
                           : "remove the speeds that the constraints already fix");
    return QD_ERR_SINGULAR;
}

/* A velocity solved for, linear in the symbols of the right-hand side:
 * each coefficient simplified on its own, which is all qd_simplify would do
 * to it and costs much less than simplifying the whole sum.  The
 * coefficients of X_j are kept (coef, n per unknown, and rest; done[j]), so
 * that velocity_map need not read them off again. */
typedef struct linear_form {
    qd_ctx *ctx;
    size_t n;
    const qd_expr *const *sym;
    const qd_expr **coef, **rest;
    bool *done;
} linear_form;

static const qd_expr *tidy_linear(void *arg, size_t j, size_t col, const qd_expr *x) {
    (void)col; /* one column */
    linear_form *f = arg;
    const qd_expr **c = f->coef + j * f->n;
    qd_status st = qd_linear_coeffs(f->ctx, x, f->n, f->sym, c, &f->rest[j]);
    if (st == QD_ERR_NONLINEAR) {
        qd__ctx_recover(f->ctx);
        return qd_simplify(f->ctx, x);
    }
    const qd_expr *sum = st == QD_OK ? (f->rest[j] = qd_simplify(f->ctx, f->rest[j])) : NULL;
    for (size_t r = 0; sum && r < f->n; r++) {
        c[r] = qd_simplify(f->ctx, c[r]);
        sum = c[r] ? qd_add(f->ctx, sum, qd_mul(f->ctx, c[r], f->sym[r])) : NULL;
    }
    f->done[j] = sum != NULL;
    return sum;
}

/* Whether an entry of P has more than QD__SPD_EXACT_MAX nodes: then its
 * exact solve swells (measured: the examples' maps have entries of at most
 * 6 nodes and solve exactly in microseconds; the Whipple bicycle's front
 * contact has 57 and its 2x2 core exceeds the expansion limit after
 * seconds of cancellation), and the map is solved on the DAG instead. */
static bool big_rows(const qd__spd *d) {
    for (size_t i = 0; i < d->n * d->n; i++)
        if (qd_dag_size(d->ctx, d->P[i]) > QD__SPD_EXACT_MAX)
            return true;
    return false;
}

/* The velocities as linear expressions: P q' = (u - b, s - c0) solved
 * with the speeds u (and, when need_wc, one symbol s_k per constraint) in
 * the right-hand side, one column: carrying u through the elimination
 * costs less than the n + 1 columns of P^-1 [I | -p0].  Then W_jr, Wc_jk
 * and w_j are the coefficients of u_r, s_k and the rest of q'_j, and the
 * kinematics q'_j at s = 0. */
static qd_status velocity_map(qd__spd *d) {
    qd_ctx *ctx = d->ctx;
    qd_speeds_eom *e = d->e;
    size_t n = d->n, m = d->m, nx = d->need_wc ? n : m;
    if (m + d->nc != n)
        return count_error(d);
    for (size_t r = 0; r < m; r++) {
        qd_status st = speed_row(d, r);
        if (st != QD_OK)
            return st;
    }
    for (size_t k = 0; k < d->nc; k++) {
        for (size_t j = 0; j < n; j++)
            d->P[(m + k) * n + j] = e->con[k].a[j];
        d->p0[m + k] = e->con[k].a0;
    }
    /* B, X, the rests (n each), the unknowns' symbols (nx: u, then s),
     * the coefficients (n nx) */
    const qd_expr **B = qd__calloc(ctx, 3 * n + nx + n * nx + 1, sizeof *B);
    bool *done = qd__calloc(ctx, n + 1, sizeof *done);
    if (!B || !done) {
        qd__free(B);
        qd__free(done);
        return nomem(ctx);
    }
    const qd_expr **X = B + n, **rest = X + n, **sym = rest + n, **coef = sym + nx;
    linear_form form = {ctx, nx, sym, coef, rest, done};
    for (size_t r = 0; r < nx; r++) {
        char name[48];
        if (r >= m)
            snprintf(name, sizeof name, "_hamel_s%zu", r - m);
        sym[r] = r < m ? e->u[r] : qd_symbol(ctx, name);
    }
    for (size_t i = 0; i < n; i++) {
        B[i] = qd_neg(ctx, d->p0[i]);
        if (i < nx)
            B[i] = qd_add(ctx, sym[i], B[i]);
    }
    qd_status st = big_rows(d) ? QD_ERR_TOOBIG
                               : qd__mech_solve_sparse(ctx, n, d->P, 1, B, X, 0, tidy_linear, &form);
    if (st == QD_ERR_SINGULAR)
        st = singular_map(d);
    if (st == QD_ERR_TOOBIG && qd__ctx_recover(ctx)) { /* the exact solve swells: on the DAG */
        qd__free(B);
        qd__free(done);
        st = qd__spd_big_map(d);
        return st == QD_ERR_SINGULAR ? singular_map(d) : st;
    }
    for (size_t j = 0; st == QD_OK && j < n; j++) {
        const qd_expr **c = coef + j * nx;
        if (!done[j]) { /* from the elimination of the core: read off and tidied here */
            st = qd_linear_coeffs(ctx, X[j], nx, sym, c, &rest[j]);
            for (size_t r = 0; st == QD_OK && r < nx; r++)
                c[r] = qd_simplify(ctx, c[r]);
            if (st == QD_OK)
                rest[j] = qd_simplify(ctx, rest[j]);
        }
        for (size_t r = 0; st == QD_OK && r < nx; r++) {
            const qd_expr *x = c[r];
            if (!x)
                st = nomem(ctx);
            else if (r < m)
                e->W[j * m + r] = x;
            else
                d->Pinv[j * n + r] = x;
        }
        if (st == QD_OK && !(e->w[j] = rest[j]))
            st = nomem(ctx);
        /* q'_j = sum_r W_jr u_r + w_j from the parts simplified one by one:
         * the s_k drop out, and simplifying the sum again would only regroup
         * it (its common factors are taken out) */
        const qd_expr *kin = st == QD_OK ? e->w[j] : NULL;
        for (size_t r = 0; kin && r < m; r++)
            kin = qd_add(ctx, qd_mul(ctx, e->W[j * m + r], e->u[r]), kin);
        if (st == QD_OK && !(e->kin[j] = qd_factor_terms(ctx, kin)))
            st = nomem(ctx);
    }
    for (size_t j = 0; st == QD_OK && j < n; j++)
        for (size_t r = 0; r < m; r++)
            d->Pinv[j * n + r] = e->W[j * m + r];
    qd__free(B);
    qd__free(done);
    return st;
}

/* q''_j: the kinematics differentiated along the motion. */
static qd_status accelerations(qd__spd *d) {
    const qd_expr **acc = qd__calloc(d->ctx, d->n + 1, sizeof *acc);
    for (size_t j = 0; acc && j < d->n; j++)
        if (!(acc[j] = qd__spd_dt(d, d->e->kin[j]))) {
            qd__free(acc);
            acc = NULL;
        }
    d->acc = acc;
    return acc ? QD_OK : nomem(d->ctx);
}

/* ---- shared pieces --------------------------------------------------------- */

const qd_expr *qd__spd_on_motion(qd__spd *d, const qd_expr *x) {
    qd_speeds_eom *e = d->e;
    if (d->acc && x) {
        const qd_expr **qdd = qd__malloc(d->ctx, (d->n + 1) * sizeof *qdd);
        if (!qdd)
            return NULL;
        for (size_t j = 0; j < d->n; j++)
            qdd[j] = d->shell->qdd[j];
        x = qd_subs(d->ctx, x, d->n, qdd, d->acc);
        qd__free(qdd);
    }
    return x ? qd_subs(d->ctx, x, d->n, e->qd, e->kin) : NULL;
}

const qd_expr *qd__spd_dt(qd__spd *d, const qd_expr *x) {
    qd_speeds_eom *e = d->e;
    return x ? qd_subs(d->ctx, qd_dt(d->ctx, x), d->n, e->qd, e->kin) : NULL;
}

/* Walks x as a tree, spending one of *budget per node; false when it runs
 * out (so the walk costs at most the budget, however much x shares). */
static bool tree_within(const qd_expr *x, size_t *budget) {
    if (*budget == 0)
        return false;
    --*budget;
    for (size_t i = 0; i < qd_expr_nargs(x); i++)
        if (!tree_within(qd_expr_arg(x, i), budget))
            return false;
    return true;
}

bool qd__spd_small(qd__spd *d, const qd_expr *x) {
    size_t budget = QD__SPD_TIDY_MAX_TREE;
    return x && qd_dag_size(d->ctx, x) <= QD__SPD_TIDY_MAX && tree_within(x, &budget);
}

const qd_expr *qd__spd_simplify(qd__spd *d, const qd_expr *x) {
    if (!x || !qd__spd_small(d, x))
        return x;
    const qd_expr *y = qd_simplify(d->ctx, x);
    if (!y && qd_ctx_status(d->ctx) == QD_ERR_TOOBIG && qd__ctx_recover(d->ctx))
        return x; /* a small DAG whose expansion is large: kept */
    return y;
}

const qd_expr *qd__spd_tidy(qd__spd *d, const qd_expr *x) {
    qd__vsum v;
    if (!x || !qd__spd_small(d, x))
        return x;
    qd_status st = qd__mech_by_velocity(d->ctx, x, d->m, d->e->u, &v);
    /* too large to expand (the estimate comes before the work): kept as it is */
    if (st == QD_ERR_TOOBIG && qd__ctx_recover(d->ctx))
        return x;
    if (st != QD_OK && st != QD_ERR_NONLINEAR)
        return NULL;
    return st == QD_OK ? v.all : qd__spd_simplify(d, x);
}

/* The coefficients of u' in a large row and its rest, on the DAG: d row/du'_s
 * and the row at u' = 0 (qd_linear_coeffs would expand it).  The rows are
 * linear in u' by construction (dS/du' of S quadratic in u', Hamel's
 * M_u u' + ...), which qd_linear_coeffs checks on the small ones. */
static qd_status big_coeffs(qd__spd *d, const qd_expr *row, const qd_expr **c,
                            const qd_expr **rest) {
    qd_ctx *ctx = d->ctx;
    size_t m = d->m;
    const qd_expr **zero = qd__malloc(ctx, (m + 1) * sizeof *zero);
    if (!zero)
        return nomem(ctx);
    for (size_t s = 0; s < m; s++) {
        zero[s] = qd_int(ctx, 0);
        c[s] = qd_subs(ctx, qd_diff(ctx, row, d->e->ud[s]), m, d->e->ud, zero);
    }
    *rest = qd_subs(ctx, row, m, d->e->ud, zero);
    qd__free(zero);
    for (size_t s = 0; s < m; s++)
        if (!c[s])
            return nomem(ctx);
    return *rest ? QD_OK : nomem(ctx);
}

qd_status qd__spd_rows(qd__spd *d, const qd_expr *const *rows) {
    qd_ctx *ctx = d->ctx;
    qd_speeds_eom *e = d->e;
    size_t m = d->m;
    const qd_expr **c = qd__malloc(ctx, (m + 1) * sizeof *c);
    if (!c)
        return nomem(ctx);
    qd_status st = QD_OK;
    for (size_t r = 0; st == QD_OK && r < m; r++) {
        const qd_expr *rest = NULL;
        st = qd__spd_small(d, rows[r]) ? qd_linear_coeffs(ctx, rows[r], m, e->ud, c, &rest)
                                       : big_coeffs(d, rows[r], c, &rest);
        if (st == QD_ERR_NONLINEAR) {
            qd__ctx_recover(ctx);
            qd_ctx_error(ctx, st, "the equation of speed %s is not linear in the speeds' rates",
                         qd_expr_name(e->u[r]));
            qd_ctx_error_about(ctx, QD_SUBJECT_SPEED, r, qd_expr_name(e->u[r]), QD_REASON_NONE,
                               NULL);
        }
        for (size_t s = 0; st == QD_OK && s < m; s++)
            if (!(e->M[r * m + s] = qd__spd_simplify(d, c[s])))
                st = nomem(ctx);
        if (st == QD_OK && !(e->f[r] = qd__spd_tidy(d, qd_neg(ctx, rest))))
            st = nomem(ctx);
    }
    qd__free(c);
    return st;
}

static const qd_expr *zero_or(qd_ctx *ctx, const qd_expr *x) { return x ? x : qd_int(ctx, 0); }

const qd_expr *qd__spd_force(qd__spd *d, size_t j) {
    qd_ctx *ctx = d->ctx;
    const qd__sys *s = &d->sys;
    const qd_expr *q = d->shell->q[j], *qd = d->shell->qd[j];
    const qd_expr *G = zero_or(ctx, s->Q[j]);
    if (s->D)
        G = qd_sub(ctx, G, qd_diff(ctx, s->D, qd));
    if (!s->L_given) {
        const qd_expr *VU = qd_add(ctx, zero_or(ctx, s->V), zero_or(ctx, s->U));
        G = qd_add(ctx, G, qd_sub(ctx, qd_dt(ctx, qd_diff(ctx, VU, qd)), qd_diff(ctx, VU, q)));
    }
    return qd__spd_on_motion(d, G);
}

const qd_expr *qd__spd_residual(qd__spd *d, size_t j) {
    qd_ctx *ctx = d->ctx;
    const qd__sys *s = &d->sys;
    const qd_expr *q = d->shell->q[j], *qd = d->shell->qd[j];
    const qd_expr *E = qd_sub(ctx, qd_dt(ctx, qd_diff(ctx, d->L, qd)), qd_diff(ctx, d->L, q));
    if (s->D)
        E = qd_add(ctx, E, qd_diff(ctx, s->D, qd));
    E = qd_sub(ctx, E, zero_or(ctx, s->Q[j]));
    return qd__spd_on_motion(d, E);
}

/* ---- the derivation --------------------------------------------------------- */

static qd_status check_model(qd_ctx *ctx, const qd_model *m) {
    if (!qd_model_nspeeds(m)) {
        qd_ctx_error(ctx, QD_ERR_ARG, "the model declares no speeds (a `speeds u1 = ...` line)");
        return QD_ERR_ARG;
    }
    if (qd_model_hamiltonian_given(m)) {
        qd_ctx_error(ctx, QD_ERR_ARG, "speeds need a model given by T or L, not by H");
        qd_ctx_error_about(ctx, QD_SUBJECT_STATEMENT, 0, "H", QD_REASON_NONE, NULL);
        return QD_ERR_ARG;
    }
    return QD_OK;
}

static bool all_zero(size_t n, const qd_expr *const *x) {
    for (size_t i = 0; i < n; i++)
        if (!qd_is_zero(x[i]))
            return false;
    return true;
}

/* Is T* = 1/2 u.M_u u?  When T is T2 alone, q' = W u (w = 0) and M is
 * T2's Hessian (L = T - V: no U, no acceleration in a force). */
static bool homogeneous(const qd__spd *d) {
    const qd_eom *sh = d->shell;
    if (d->sys.U || !all_zero(d->n, d->e->w) || (sh->T1 && !qd_is_zero(sh->T1)) ||
        (sh->T0 && !qd_is_zero(sh->T0)))
        return false;
    for (size_t j = 0; j < d->n; j++)
        for (size_t k = 0; d->sys.Q[j] && k < d->n; k++)
            if (qd_has(d->sys.Q[j], sh->qdd[k]))
                return false;
    return true;
}

/* The kinetic energy in speeds, T*(q, u, t): from M_u, simplified already,
 * when it is homogeneous; else T with the kinematics, simplified. */
static qd_status kinetic(qd__spd *d) {
    qd_ctx *ctx = d->ctx;
    qd_speeds_eom *e = d->e;
    size_t m = d->m;
    if (!d->sys.T || d->sys.L_given)
        return QD_OK;
    if (!homogeneous(d)) {
        e->T = qd__spd_tidy(d, qd__spd_on_motion(d, d->sys.T));
        return e->T ? QD_OK : nomem(ctx);
    }
    const qd_expr *T = qd_int(ctx, 0), *half = qd_rat(ctx, 1, 2);
    for (size_t r = 0; r < m; r++)
        for (size_t s = r; s < m; s++) {
            const qd_expr *c = e->M[r * m + s];
            if (!qd_is_zero(c))
                T = qd_add(ctx, T, qd_mul(ctx, r == s ? qd_mul(ctx, half, c) : c,
                                          qd_mul(ctx, e->u[r], e->u[s])));
        }
    e->T = T;
    return T ? QD_OK : nomem(ctx);
}

/* M_u must be invertible somewhere: a numeric look at two states. */
static qd_status check_mass(qd__spd *d) {
    qd_speeds_eom *e = d->e;
    size_t m = d->m;
    const qd_expr *syms[96];
    double vals[96], *K = qd__malloc(d->ctx, (m * m + m + 1) * sizeof *K);
    if (!K)
        return nomem(d->ctx);
    bool regular = false;
    for (unsigned trial = 0; trial < 2 && !regular; trial++) {
        size_t ns = 0;
        for (size_t i = 0; i < m * m; i++) {
            const qd_expr *buf[96];
            size_t k = qd_free_symbols(d->ctx, e->M[i], buf, 96);
            for (size_t a = 0; a < k && a < 96; a++) {
                bool have = false;
                for (size_t b = 0; b < ns; b++)
                    have = have || syms[b] == buf[a];
                if (!have && ns < 96)
                    syms[ns++] = buf[a];
            }
        }
        for (size_t i = 0; i < ns; i++)
            vals[i] = 0.23 + 0.71 * (double)((i * 7919 + 31 * trial + 5) % 89) / 89.0;
        bool ok = true;
        for (size_t i = 0; i < m * m && ok; i++)
            if (qd_eval(d->ctx, e->M[i], ns, syms, vals, &K[i]) != QD_OK) {
                qd__ctx_recover(d->ctx);
                ok = false;
            }
        for (size_t i = 0; i < m; i++)
            K[m * m + i] = 1;
        regular = ok && qd__num_solve(m, K, K + m * m, 1e-12 * (double)m);
        if (!ok) /* not evaluable (user functions): no verdict */
            regular = true;
    }
    qd__free(K);
    if (regular)
        return QD_OK;
    qd_ctx_error(d->ctx, QD_ERR_SINGULAR,
                 "the mass matrix of the speeds W^T M W is singular: a speed moves nothing "
                 "with inertia");
    qd_ctx_error_about(d->ctx, QD_SUBJECT_STATEMENT, 0, d->sys.L_given ? "L" : "T",
                       QD_REASON_SINGULAR_MASS, NULL);
    return QD_ERR_SINGULAR;
}

static qd_status setup(qd__spd *d, const qd_speeds_opts *opts) {
    qd_ctx *ctx = d->ctx;
    qd_status st = qd__mech_sys_from_model(ctx, d->model, &d->sys);
    if (st != QD_OK)
        return st;
    d->n = d->sys.n;
    d->m = qd_model_nspeeds(d->model);
    d->nc = d->sys.ncon;
    d->shell = qd__mech_eom_shell(ctx, &d->sys);
    if (!d->shell)
        return qd_ctx_status(ctx);
    d->L = qd__mech_sys_lagrangian(ctx, d->shell, &d->sys);
    if (!d->L)
        return qd_ctx_status(ctx) != QD_OK ? qd_ctx_status(ctx) : nomem(ctx);
    d->e = alloc(ctx, d->n, d->m, d->nc);
    if (!d->e)
        return QD_ERR_NOMEM;
    qd_speeds_eom *e = d->e;
    qd_eom *sh = d->shell;
    ((qd__spd_priv *)e->priv)->shell = sh; /* e owns it from here */
    e->method = opts ? opts->method : QD_SPEEDS_KANE;
    e->con = sh->con;
    for (size_t j = 0; j < d->n; j++) {
        e->q[j] = sh->q[j];
        e->qd[j] = sh->qd[j];
    }
    for (size_t r = 0; r < d->m; r++) {
        e->u[r] = qd_model_speed(d->model, r);
        e->ud[r] = qd_jet(ctx, e->u[r], 1);
        e->def[r] = qd_model_speed_definition(d->model, r);
        if (!e->ud[r] || !e->def[r])
            return nomem(ctx);
    }
    size_t n = d->n;
    d->P = qd__calloc(ctx, n * n + 1, sizeof *d->P);
    d->Pinv = qd__calloc(ctx, n * n + 1, sizeof *d->Pinv);
    d->p0 = qd__calloc(ctx, n + 1, sizeof *d->p0);
    return d->P && d->Pinv && d->p0 ? QD_OK : nomem(ctx);
}

static qd_status run(qd__spd *d, const qd_speeds_opts *opts) {
    qd_status st = setup(d, opts);
    d->need_wc = d->e && (d->e->method == QD_SPEEDS_HAMEL || (opts && opts->multipliers));
    if (st == QD_OK)
        st = velocity_map(d);
    if (st == QD_OK)
        st = accelerations(d);
    if (st != QD_OK)
        return st;
    switch (d->e->method) {
    case QD_SPEEDS_APPELL: st = qd__spd_appell(d, true); break;
    case QD_SPEEDS_HAMEL: st = qd__spd_hamel(d); break;
    default: st = qd__spd_kane(d); break;
    }
    if (st == QD_OK)
        st = kinetic(d);
    if (st == QD_OK && opts && opts->appell && !d->e->S)
        st = qd__spd_appell(d, false);
    if (st == QD_OK && opts && opts->multipliers && d->nc)
        st = qd__spd_multipliers(d);
    if (st == QD_OK)
        st = check_mass(d);
    return st;
}

qd_speeds_eom *qd_speeds_derive(qd_ctx *ctx, const qd_model *m, const qd_speeds_opts *opts) {
    QD_ARGS(NULL, ctx && m);
    if (!ctx || !m)
        return NULL;
    if (opts && (unsigned)opts->method >= QD_SPEEDS_METHOD_COUNT) {
        qd_ctx_error(ctx, QD_ERR_ARG, "unknown method for the equations in speeds");
        return NULL;
    }
    if (check_model(ctx, m) != QD_OK)
        return NULL;
    qd__spd d = {.ctx = ctx, .model = m};
    qd_status st = run(&d, opts);
    qd__mech_sys_free(&d.sys);
    qd__free(d.P);
    qd__free(d.Pinv);
    qd__free(d.p0);
    qd__free(d.acc);
    if (st != QD_OK) {
        if (!d.e) /* the shell is not yet e's */
            qd_eom_free(d.shell);
        if (qd_ctx_status(ctx) == QD_OK)
            qd_ctx_error(ctx, st, "deriving the equations in speeds failed");
        qd_speeds_eom_free(d.e);
        return NULL;
    }
    return d.e;
}

qd_status qd_speeds_solve(qd_ctx *ctx, qd_speeds_eom *e, size_t max_ops) {
    QD_ARGS_CTX(ctx, ctx && e);
    if (!ctx || !e)
        return QD_ERR_ARG;
    size_t m = e->m;
    const qd_expr **acc = qd__calloc(ctx, m + 1, sizeof *acc);
    if (!acc)
        return nomem(ctx);
    qd_status st = qd__mech_solve_cols(ctx, m, e->M, 1, e->f, acc, max_ops);
    if (st != QD_OK) {
        qd__free(acc);
        if (qd_ctx_status(ctx) == QD_OK && st == QD_ERR_TOOBIG)
            qd_ctx_error(ctx, st, "the explicit rates of the speeds exceed %zu operations; keep "
                                  "M_u u' = f_u", max_ops);
        else if (qd_ctx_status(ctx) == QD_OK && st == QD_ERR_SINGULAR)
            qd_ctx_error(ctx, st, "the mass matrix of the speeds is singular for every state");
        return st;
    }
    qd__free(e->acc);
    e->acc = acc;
    return QD_OK;
}

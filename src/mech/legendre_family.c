/*
 * src/mech/legendre_family.c - the Legendre transform of a Lagrangian that
 * is not quadratic in the velocities (Desloge ch. 93, Appendix 22;
 * seed-desloge-D.md C2, C5, P13).
 *
 * The family solved in closed form:
 *
 *     L = F(s) + a(q,t).q' + L0(q,t),   s = q'^T G(q,t) q'
 *
 * G is read off the Hessian at q' = 0 (G = (1/2) d^2L/dq'dq' there, so that
 * F'(0) = 1), F along one axis of G, and the split is kept only when
 * L - L0 - a.q' - F(q'^T G q') simplifies to 0.  Then p - a = 2 F'(s) G q',
 * so P = (p - a)^T G^-1 (p - a) = 4 F'(s)^2 s =: g(s).  When g is rational in s
 * with a numerator linear in s (the relativistic particle: F(s) = m c^2 (1 -
 * sqrt(1 - 2 s/(m c^2))) gives g = 4 s/(1 - 2 s/(m c^2))), g(s) = P is solved
 * for s, and q' = G^-1 (p - a)/(2 F'(s)) follows; H = p.q' - L comes from
 * hamilton.c as for a quadratic L.
 *
 * Anything else keeps the velocities implicit: vel_j is q'_j itself, defined
 * by p = dL/dq', so H = p.q' - L and Hamilton's equations dq/dt = q',
 * dp/dt = dL/dq hold as written and are evaluated by Newton's method on
 * p = dL/dq' (qd_ham_velocities_at).  A Hessian that is singular for a
 * reason we can name (L linear in a velocity, L - L0 - a.q' homogeneous of
 * degree 1 so that H = -L0 whatever p is) is an error naming the coordinate.
 */
#include "legendre.h"
#include "../base/mem.h"
#include "qdot/print.h"
#include "../base/args.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct family {
    size_t n;
    const qd_expr **qd, **zero;
    const qd_expr **a;    /* dL/dq' at q' = 0 */
    const qd_expr **G;    /* n x n, row-major */
    const qd_expr **Gi;   /* its inverse */
    const qd_expr *L0, *K; /* L at q' = 0; K = L - L0 - a.q' */
    const qd_expr *s, *F; /* the symbol s and F(s) - F(0) */
} family;

static const qd_expr **arr(qd_ctx *ctx, size_t n) {
    return qd__calloc(ctx, n ? n : 1, sizeof(const qd_expr *));
}

static void family_free(family *f) {
    qd__free(f->zero);
    qd__free(f->a);
    qd__free(f->G);
    qd__free(f->Gi);
}

static const qd_expr *at_rest(qd_ctx *ctx, const family *f, const qd_expr *x) {
    return qd_simplify(ctx, qd_subs(ctx, x, f->n, f->qd, f->zero));
}

/* L0, a and K: the parts of L free of and linear in the velocities. */
static qd_status split_linear(qd_ctx *ctx, const qd_expr *L, family *f) {
    f->L0 = at_rest(ctx, f, L);
    const qd_expr *K = qd_sub(ctx, L, f->L0);
    for (size_t j = 0; j < f->n; j++) {
        f->a[j] = at_rest(ctx, f, qd_diff(ctx, L, f->qd[j]));
        K = qd_sub(ctx, K, qd_mul(ctx, f->a[j], f->qd[j]));
    }
    f->K = K;
    return K ? QD_OK : qd_ctx_status(ctx);
}

/* G = (1/2) d^2K/dq'dq' at rest and its inverse (one column at a time). */
static qd_status metric(qd_ctx *ctx, family *f) {
    size_t n = f->n, bad = 0;
    for (size_t i = 0; i < n; i++)
        for (size_t j = 0; j < n; j++) {
            const qd_expr *d = qd_diff(ctx, qd_diff(ctx, f->K, f->qd[i]), f->qd[j]);
            f->G[i * n + j] = at_rest(ctx, f, qd_mul(ctx, qd_rat(ctx, 1, 2), d));
            if (!f->G[i * n + j])
                return qd_ctx_status(ctx);
        }
    const qd_expr **A = arr(ctx, n * (n + 1)), **x = arr(ctx, n);
    qd_status st = A && x ? QD_OK : QD_ERR_NOMEM;
    for (size_t c = 0; st == QD_OK && c < n; c++) {
        for (size_t i = 0; i < n; i++) {
            memcpy(A + i * (n + 1), f->G + i * n, n * sizeof *A);
            A[i * (n + 1) + n] = qd_int(ctx, i == c);
        }
        st = qd__mech_gauss_solve(ctx, n, A, x, &bad);
        for (size_t i = 0; st == QD_OK && i < n; i++)
            f->Gi[i * n + c] = x[i];
    }
    qd__free(A);
    qd__free(x);
    return st;
}

static const qd_expr *quad_form(qd_ctx *ctx, size_t n, const qd_expr *const *M,
                                const qd_expr *const *u) {
    const qd_expr *s = qd_int(ctx, 0);
    for (size_t i = 0; i < n; i++)
        for (size_t j = 0; j < n; j++)
            s = qd_add(ctx, s, qd_mul(ctx, M[i * n + j], qd_mul(ctx, u[i], u[j])));
    return s;
}

/* F along the first axis with G_jj != 0, then the exact test that K is
 * F(q'^T G q') everywhere. */
static qd_status profile(qd_ctx *ctx, family *f) {
    size_t n = f->n, j = 0;
    while (j < n && qd_is_zero(f->G[j * n + j]))
        j++;
    if (j == n)
        return QD_ERR_NONLINEAR;
    const qd_expr **ray = arr(ctx, n);
    if (!ray)
        return QD_ERR_NOMEM;
    for (size_t i = 0; i < n; i++)
        ray[i] = i == j ? qd_sqrt(ctx, qd_div(ctx, f->s, f->G[j * n + j])) : qd_int(ctx, 0);
    f->F = qd_simplify(ctx, qd_subs(ctx, f->K, n, f->qd, ray));
    qd__free(ray);
    if (!f->F)
        return qd_ctx_status(ctx);
    for (size_t i = 0; i < n; i++)
        if (qd_has(f->F, f->qd[i]))
            return QD_ERR_NONLINEAR;
    const qd_expr *sG = quad_form(ctx, n, f->G, f->qd);
    const qd_expr *r = qd_simplify(ctx, qd_sub(ctx, f->K, qd_subs(ctx, f->F, 1, &f->s, &sG)));
    if (!r)
        return qd_ctx_status(ctx);
    return qd_is_zero(r) ? QD_OK : QD_ERR_NONLINEAR;
}

/* The numerator of a canceled quotient: its factors with no negative power. */
static const qd_expr *numerator(qd_ctx *ctx, const qd_expr *x) {
    if (!x)
        return NULL;
    if (qd_expr_kind(x) == QD_POW && qd_is_number(qd_expr_arg(x, 1)) &&
        qd_number_sign(qd_expr_arg(x, 1)) < 0)
        return qd_int(ctx, 1);
    if (qd_expr_kind(x) != QD_MUL)
        return x;
    const qd_expr *num = qd_int(ctx, 1);
    for (size_t i = 0; i < qd_expr_nargs(x); i++)
        num = qd_mul(ctx, num, numerator(ctx, qd_expr_arg(x, i)));
    return num;
}

/* s from g(s) = P when the numerator of g - P is linear in s. */
static const qd_expr *solve_s(qd_ctx *ctx, const family *f, const qd_expr *P) {
    const qd_expr *Fp = qd_diff(ctx, f->F, f->s);
    const qd_expr *g = qd_mul(ctx, qd_int(ctx, 4), qd_mul(ctx, qd_powi(ctx, Fp, 2), f->s));
    const qd_expr *N = qd_expand(ctx, numerator(ctx, qd_cancel(ctx, qd_sub(ctx, g, P))));
    const qd_expr *c0 = qd_coeff(ctx, N, f->s, 0), *c1 = qd_coeff(ctx, N, f->s, 1);
    if (!N || !c0 || !c1)
        return NULL;
    const qd_expr *rest = qd_simplify(ctx, qd_sub(ctx, N, qd_add(ctx, c0, qd_mul(ctx, c1, f->s))));
    c1 = qd_simplify(ctx, c1);
    if (!rest || !c1 || !qd_is_zero(rest) || qd_is_zero(c1) || qd_has(c0, f->s) ||
        qd_has(c1, f->s))
        return NULL;
    return qd_simplify(ctx, qd_neg(ctx, qd_div(ctx, c0, c1)));
}

/* F(s) = A + B sqrt(C + D s), A, B, C, D free of s: the relativistic
 * profile (B = -m c^2, C = 1, D = -2/(m c^2) with G = m/2).  Then
 * C + D s = C B^2 D/(B^2 D - P), and with k = B^2 - P/D:
 *     H + L0 = B sqrt(C) - sign(B) sqrt(C k)
 *     q' = sign(B) sqrt(C/k) G^-1 (p - a)/D
 * (for the particle C k = m^2 c^4 + c^2 (p - e A)^2). */
typedef struct sqrt_form {
    const qd_expr *B, *C, *D;
} sqrt_form;

static bool sqrt_term(qd_ctx *ctx, const family *f, const qd_expr *term, sqrt_form *r) {
    const qd_expr *root = NULL, *B = qd_int(ctx, 1);
    size_t nf = qd_expr_kind(term) == QD_MUL ? qd_expr_nargs(term) : 1;
    for (size_t i = 0; i < nf; i++) {
        const qd_expr *x = nf == 1 ? term : qd_expr_arg(term, i);
        if (!qd_has(x, f->s))
            B = qd_mul(ctx, B, x);
        else if (!root && qd_expr_kind(x) == QD_POW && qd_expr_arg(x, 1) == qd_rat(ctx, 1, 2))
            root = qd_expr_arg(x, 0);
        else
            return false;
    }
    const qd_expr *D = NULL, *C = NULL;
    if (!root || qd_linear_coeffs(ctx, root, 1, &f->s, &D, &C) != QD_OK)
        return qd__ctx_recover(ctx) && false;
    r->B = B;
    r->C = C;
    r->D = D;
    return B && !qd_is_zero(D);
}

static bool sqrt_profile(qd_ctx *ctx, const family *f, sqrt_form *r) {
    const qd_expr *F = qd_expand(ctx, f->F); /* c m (c - sqrt(c^2 - 2 s/m)) to terms */
    if (!F)
        return false;
    size_t nt = qd_expr_kind(F) == QD_ADD ? qd_expr_nargs(F) : 1;
    bool found = false;
    for (size_t i = 0; i < nt; i++) {
        const qd_expr *t = nt == 1 ? F : qd_expr_arg(F, i);
        if (!qd_has(t, f->s))
            continue;
        if (found || !sqrt_term(ctx, f, t, r))
            return false;
        found = true;
    }
    return found;
}

/* The sign of x when its factors say it (numbers, positive parameters,
 * powers of them); 0 when they do not. */
static int known_sign(const qd_expr *x) {
    if (qd_is_number(x))
        return qd_number_sign(x);
    if (qd_expr_kind(x) == QD_SYMBOL)
        return qd_symbol_is_positive(x) ? 1 : 0;
    if (qd_expr_kind(x) == QD_POW)
        return known_sign(qd_expr_arg(x, 0)) > 0 ? 1 : 0;
    if (qd_expr_kind(x) != QD_MUL)
        return 0;
    int sg = 1;
    for (size_t i = 0; sg && i < qd_expr_nargs(x); i++)
        sg *= known_sign(qd_expr_arg(x, i));
    return sg;
}

static qd_status sqrt_closed_form(qd_ctx *ctx, const family *f, const sqrt_form *r,
                                  const qd_expr *const *pi, const qd_expr **vel,
                                  const qd_expr **H) {
    size_t n = f->n;
    const qd_expr *P = qd_factor_terms(ctx, quad_form(ctx, n, f->Gi, pi));
    const qd_expr *k = qd_sub(ctx, qd_powi(ctx, r->B, 2), qd_div(ctx, P, r->D));
    int known = known_sign(r->B);
    const qd_expr *sg = known ? qd_int(ctx, known) : qd_fn(ctx, QD_SIGN, r->B);
    const qd_expr *Ck = qd_simplify(ctx, qd_mul(ctx, r->C, k));
    *H = qd_sub(ctx, qd_sub(ctx, qd_mul(ctx, r->B, qd_sqrt(ctx, r->C)),
                            qd_mul(ctx, sg, qd_sqrt(ctx, Ck))), f->L0);
    const qd_expr *scale = qd_div(ctx, qd_mul(ctx, sg, qd_sqrt(ctx, qd_simplify(ctx, qd_div(ctx, r->C, k)))),
                                  r->D);
    for (size_t i = 0; i < n; i++) {
        const qd_expr *v = qd_int(ctx, 0);
        for (size_t j = 0; j < n; j++)
            v = qd_add(ctx, v, qd_mul(ctx, f->Gi[i * n + j], pi[j]));
        vel[i] = qd_mul(ctx, qd_factor_terms(ctx, v), scale);
    }
    return qd_ctx_status(ctx);
}

/* q' = G^-1 (p - a)/(2 F'(s)) and H = 2 s F'(s) - F(s) - L0 with s solved;
 * both are simplified as functions of the one symbol P before P =
 * (p - a)^T G^-1 (p - a) goes in, so that (p - e A)^2 stays whole.
 * QD_ERR_NONLINEAR when g(s) = P has no closed form here. */
static qd_status closed_form(qd_ctx *ctx, const family *f, const qd_expr *const *p,
                             const qd_expr **vel, const qd_expr **H) {
    size_t n = f->n;
    const qd_expr **pi = arr(ctx, n);
    if (!pi)
        return QD_ERR_NOMEM;
    for (size_t j = 0; j < n; j++)
        pi[j] = qd_sub(ctx, p[j], f->a[j]);
    sqrt_form r;
    if (sqrt_profile(ctx, f, &r)) {
        qd_status st = sqrt_closed_form(ctx, f, &r, pi, vel, H);
        qd__free(pi);
        return st;
    }
    const qd_expr *Psym = qd_symbol(ctx, "P#"), *s = solve_s(ctx, f, Psym);
    const qd_expr *P = qd_factor_terms(ctx, quad_form(ctx, n, f->Gi, pi));
    qd_status st = qd_ctx_status(ctx);
    if (st == QD_OK && !s)
        st = QD_ERR_NONLINEAR;
    if (st == QD_OK) {
        const qd_expr *w = qd_subs(ctx, qd_diff(ctx, f->F, f->s), 1, &f->s, &s);
        w = qd_simplify(ctx, qd_mul(ctx, qd_int(ctx, 2), w));
        const qd_expr *h = qd_sub(ctx, qd_mul(ctx, s, w), qd_subs(ctx, f->F, 1, &f->s, &s));
        h = qd_simplify(ctx, h);
        *H = qd_sub(ctx, qd_subs(ctx, h, 1, &Psym, &P), f->L0);
        w = qd_subs(ctx, w, 1, &Psym, &P);
        for (size_t i = 0; w && i < n; i++) {
            const qd_expr *v = qd_int(ctx, 0);
            for (size_t j = 0; j < n; j++)
                v = qd_add(ctx, v, qd_mul(ctx, f->Gi[i * n + j], pi[j]));
            vel[i] = qd_div(ctx, qd_factor_terms(ctx, v), w);
        }
        st = qd_ctx_status(ctx);
    }
    qd__free(pi);
    return st;
}

static qd_status family_split(qd_ctx *ctx, const qd_expr *L, family *f) {
    qd_status st = split_linear(ctx, L, f);
    if (st == QD_OK)
        st = metric(ctx, f);
    if (st == QD_OK)
        st = profile(ctx, f);
    return st;
}

static qd_status family_init(qd_ctx *ctx, size_t n, const qd_expr *const *qd, family *f) {
    f->n = n;
    f->qd = (const qd_expr **)qd;
    f->zero = arr(ctx, n);
    f->a = arr(ctx, n);
    f->G = arr(ctx, n * n);
    f->Gi = arr(ctx, n * n);
    f->s = qd_symbol(ctx, "s#");
    if (!f->zero || !f->a || !f->G || !f->Gi || !f->s)
        return QD_ERR_NOMEM;
    for (size_t j = 0; j < n; j++)
        f->zero[j] = qd_int(ctx, 0);
    return QD_OK;
}

/* Errors the kernel raised while trying the family only mean "not this
 * family" (0/0 at q' = 0 for a homogeneous L, say); out of memory stays. */
static qd_status not_family(qd_ctx *ctx, qd_status st) {
    if (st == QD_OK)
        return st;
    return qd__ctx_recover(ctx) ? QD_ERR_NONLINEAR : QD_ERR_NOMEM;
}

qd_status qd__mech_legendre_family(qd_ctx *ctx, const qd_expr *L, size_t n,
                                   const qd_expr *const *qd, const qd_expr *const *p,
                                   const qd_expr **vel, const qd_expr **H) {
    family f = {0};
    qd_status st = family_init(ctx, n, qd, &f);
    if (st == QD_OK)
        st = not_family(ctx, family_split(ctx, L, &f));
    if (st == QD_OK)
        st = not_family(ctx, closed_form(ctx, &f, p, vel, H));
    family_free(&f);
    return st;
}

/* ---- singular Hessians ------------------------------------------------------ */

/* The velocity L is linear in: dL/dq'_j holds no velocity.  n when none. */
static size_t linear_velocity(const qd_expr *const *pdef, size_t n, const qd_expr *const *qd) {
    for (size_t j = 0; j < n; j++) {
        bool any = false;
        for (size_t k = 0; k < n; k++)
            any = any || qd_has(pdef[j], qd[k]);
        if (!any)
            return j;
    }
    return n;
}

/* Euler's theorem (Appendix 20): L - L0 - a.q' homogeneous of degree 1 has
 * sum_k q'_k d^2L/dq'_j dq'_k = 0 for every j. */
static bool homogeneous_1(qd_ctx *ctx, const qd_expr *const *pdef, size_t n,
                          const qd_expr *const *qd) {
    for (size_t j = 0; j < n; j++) {
        const qd_expr *r = qd_int(ctx, 0);
        for (size_t k = 0; k < n; k++)
            r = qd_add(ctx, r, qd_mul(ctx, qd[k], qd_diff(ctx, pdef[j], qd[k])));
        r = qd_simplify(ctx, r);
        if (!r || !qd_is_zero(r))
            return false;
    }
    return true;
}

qd_status qd__mech_legendre_singular(qd_ctx *ctx, const qd_expr *const *pdef, size_t n,
                                const qd_expr *const *q, const qd_expr *const *qd,
                                const char *stmt) {
    char hint[512];
    size_t j = linear_velocity(pdef, n, qd);
    if (j < n) {
        const char *name = qd_expr_name(qd[j]);
        char pj[256];
        qd_buf b = QD_BUF_WITH(qd__ctx_allocator(ctx));
        qd_print(ctx, pdef[j], QD_FMT_TEXT, &b);
        snprintf(pj, sizeof pj, "%s", qd_buf_str(&b));
        qd_buf_free(&b);
        qd_ctx_error(ctx, QD_ERR_SINGULAR, "%s is linear in %s: its Hessian in the velocities is "
                     "singular, so there is no Hamiltonian (p_%s = %s does not depend on %s)",
                     stmt, name, qd_expr_name(q[j]), pj, name);
        snprintf(hint, sizeof hint, "a Hamiltonian needs d^2%s/dq'dq' invertible; %s enters %s "
                 "at most linearly", stmt, name, stmt);
        qd_ctx_error_about(ctx, QD_SUBJECT_COORD, j, qd_expr_name(q[j]), QD_REASON_SINGULAR_MASS,
                           hint);
        return QD_ERR_SINGULAR;
    }
    if (homogeneous_1(ctx, pdef, n, qd)) {
        qd_ctx_error(ctx, QD_ERR_SINGULAR, "%s is homogeneous of degree 1 in the velocities "
                     "(beyond its terms linear in them): its Hessian in the velocities is "
                     "singular (Euler's theorem: H = sum p q' - %s does not depend on p), so "
                     "there is no Hamiltonian", stmt, stmt);
        snprintf(hint, sizeof hint, "the momenta are homogeneous of degree 0 in the velocities: "
                 "they fix the direction of %s' but not its size", qd_expr_name(q[0]));
        qd_ctx_error_about(ctx, QD_SUBJECT_STATEMENT, 0, stmt, QD_REASON_SINGULAR_MASS, hint);
        return QD_ERR_SINGULAR;
    }
    return qd_ctx_status(ctx);
}

/* L quadratic in the velocities: every dL/dq'_j linear in them. */
static bool quadratic(qd_ctx *ctx, const qd_expr *const *pdef, size_t n, const qd_expr *const *qd,
                      const qd_expr **coeffs) {
    for (size_t j = 0; j < n; j++) {
        const qd_expr *rest = NULL;
        if (qd_linear_coeffs(ctx, pdef[j], n, qd, coeffs, &rest) != QD_OK) {
            qd__ctx_recover(ctx);
            return false;
        }
    }
    return true;
}

static qd_status regular(qd_ctx *ctx, const qd_model *m, const qd_expr **q, const qd_expr **qd,
                         const qd_expr **pdef, const qd_expr **coeffs) {
    size_t n = qd_model_ncoords(m);
    const qd_expr *L = qd_model_lagrangian(m);
    if (!L)
        return QD_OK;
    for (size_t j = 0; j < n; j++) {
        q[j] = qd_model_coord(m, j);
        qd[j] = qd_jet(ctx, q[j], 1);
        pdef[j] = qd_simplify(ctx, qd_diff(ctx, L, qd[j]));
        if (!pdef[j])
            return qd_ctx_status(ctx);
    }
    if (quadratic(ctx, pdef, n, qd, coeffs))
        return qd_ctx_status(ctx);
    return qd__mech_legendre_singular(ctx, pdef, n, q, qd,
                                      qd_model_lagrangian_given(m) ? "L" : "T");
}

qd_status qd_ham_regular(qd_ctx *ctx, const qd_model *m) {
    QD_ARGS_CTX(ctx, ctx && m);
    if (!ctx || !m)
        return QD_ERR_ARG;
    if (qd_model_hamiltonian_given(m))
        return QD_OK;
    size_t n = qd_model_ncoords(m);
    const qd_expr **q = arr(ctx, n), **qd = arr(ctx, n), **pdef = arr(ctx, n);
    const qd_expr **coeffs = arr(ctx, n);
    qd_status st = q && qd && pdef && coeffs ? regular(ctx, m, q, qd, pdef, coeffs) : QD_ERR_NOMEM;
    if (st == QD_ERR_NOMEM && qd_ctx_status(ctx) == QD_OK)
        qd_ctx_error(ctx, st, "out of memory");
    qd__free(q);
    qd__free(qd);
    qd__free(pdef);
    qd__free(coeffs);
    return st;
}

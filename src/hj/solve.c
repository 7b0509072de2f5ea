/*
 * src/hj/solve.c - the motion from dW/dalpha = beta where the quadratures
 * close and can be inverted (Desloge ch. 78: the oscillator, the projectile;
 * ch. 79 and Goldstein 10.8: Kepler's orbit equation).
 *
 * dW/dalpha = beta is, coordinate by coordinate, tau = int w(q) dq with
 * tau = t - beta (w = 1/(dH/dp_k)) or, for an orbit, tau = q_j - beta
 * (w = (dH/dp_j)/(dH/dp_k), q_j cyclic).  With P = p2 = a + b q + c q^2:
 *
 *     w = kappa/sqrt(P), c < 0:  kappa asin((2 g q - b)/sqrt(D))/sqrt(g) = tau,
 *                                g = -c, D = b^2 + 4 a g
 *                                q = (b + sqrt(D) sin(sqrt(g) tau/kappa))/(2 g)
 *     w = kappa/sqrt(P), c = 0:  2 kappa sqrt(a + b q)/b = tau
 *                                q = ((b tau/(2 kappa))^2 - a)/b
 *     w = kappa/(q^2 sqrt(P(1/q))): u = 1/q turns it into -kappa/sqrt(P(u));
 *     w = kappa/(sin(q)^2 sqrt(P)), P quadratic in u = cot(q): likewise.
 *
 * beta_<q> is the constant of integration (the time or the angle of the
 * reference point): the betas of the textbook, dW/dalpha_k, differ from it by
 * a factor and a constant, which is why they are named for the coordinate.
 */
#include "hj_priv.h"

#include <stdio.h>
#include "base/mem.h"
#include "../base/args.h"

/* P = a + b x + c x^2 exactly, with a, b, c free of x; false otherwise. */
static bool quadratic(qd_ctx *ctx, const qd_expr *P, const qd_expr *x, const qd_expr **abc) {
    const qd_expr *X = qd_expand(ctx, P), *sum = qd_int(ctx, 0);
    for (long k = 0; X && k <= 2; k++) {
        abc[k] = qd_coeff(ctx, X, x, k);
        if (!abc[k] || qd_has(abc[k], x))
            return false;
        sum = qd_add(ctx, sum, qd_mul(ctx, abc[k], qd_powi(ctx, x, k)));
    }
    const qd_expr *d = X ? qd_expand(ctx, qd_sub(ctx, X, sum)) : NULL;
    return d && qd_is_zero(d);
}

/* x from tau = int kappa dx/sqrt(a + b x + c x^2); NULL when not closed. */
static const qd_expr *invert(qd_ctx *ctx, const qd_expr *const *abc, const qd_expr *kappa,
                             const qd_expr *tau) {
    const qd_expr *a = abc[0], *b = abc[1], *c = abc[2], *two = qd_int(ctx, 2);
    if (qd_is_zero(c)) {
        if (qd_is_zero(b))
            return NULL;
        const qd_expr *s = qd_div(ctx, qd_mul(ctx, b, tau), qd_mul(ctx, two, kappa));
        return qd_div(ctx, qd_sub(ctx, qd_powi(ctx, s, 2), a), b);
    }
    if (qd__hj_sign(c) >= 0)
        return NULL;
    const qd_expr *g = qd_neg(ctx, c);
    const qd_expr *D = qd_add(ctx, qd_powi(ctx, b, 2), qd_mul(ctx, qd_int(ctx, 4), qd_mul(ctx, a, g)));
    const qd_expr *phase = qd_div(ctx, qd_mul(ctx, qd_sqrt(ctx, g), tau), kappa);
    return qd_div(ctx, qd_add(ctx, b, qd_mul(ctx, qd_sqrt(ctx, D), qd_fn(ctx, QD_SIN, phase))),
                  qd_mul(ctx, two, g));
}

/* dH/dp_j on the separated motion: every p_i = sqrt(p2_i) (cyclic: alpha_i). */
static const qd_expr *velocity(qd_ctx *ctx, const qd_hj *h, size_t j) {
    const qd_expr *v = qd_diff(ctx, h->H, h->sep[j].p);
    for (size_t i = 0; v && i < h->n; i++) {
        const qd_hj_sep *s = &h->sep[i];
        if (s->qk)
            continue; /* the momentum representation: p_k stays */
        const qd_expr *to = s->cyclic && s->constant != h->energy ? s->constant
                            : s->pk ? s->pk : qd_sqrt(ctx, s->p2);
        v = qd_subs(ctx, v, 1, &s->p, &to);
    }
    return v;
}

/* Does e contain a coordinate other than q_k? */
static bool on_others(const qd_hj *h, const qd_expr *e, size_t k) {
    for (size_t i = 0; i < h->n; i++)
        if (i != k && qd_has(e, h->sep[i].q))
            return true;
    return false;
}

/* tau = int w dq through u = 1/q: w = kappa/(q^2 sqrt(P(u))) (Kepler's orbit). */
static const qd_expr *closed_inverse(qd_ctx *ctx, const qd_hj_sep *s, const qd_expr *w,
                                     const qd_expr *tau) {
    const qd_expr *q = s->q, *abc[3];
    const qd_expr *kappa = qd_simplify(ctx, qd_mul(ctx, qd_mul(ctx, w, qd_sqrt(ctx, s->p2)),
                                                   qd_powi(ctx, q, 2)));
    const qd_expr *u = qd_symbol(ctx, "hj_u"), *inv = qd_powi(ctx, u, -1);
    if (!kappa || qd_has(kappa, q) || !quadratic(ctx, qd_subs(ctx, s->p2, 1, &q, &inv), u, abc))
        return NULL;
    const qd_expr *uq = invert(ctx, abc, qd_neg(ctx, kappa), tau);
    return uq ? qd_powi(ctx, uq, -1) : NULL;
}

/* tau = int w dq through u = cot(q), sin(q)^2 = 1/(1 + u^2):
 * w = kappa/(sin(q)^2 sqrt(P(u))) (the plane of a central orbit in
 * spherical coordinates, Desloge ch. 78 eq. 59); q = acot(u) = pi/2 - atan(u),
 * in (0, pi). */
static const qd_expr *closed_cot(qd_ctx *ctx, const qd_hj_sep *s, const qd_expr *w,
                                 const qd_expr *tau) {
    const qd_expr *q = s->q, *sq = qd_fn(ctx, QD_SIN, q), *abc[3];
    const qd_expr *kappa = qd_simplify(ctx, qd_mul(ctx, qd_mul(ctx, w, qd_sqrt(ctx, s->p2)),
                                                   qd_powi(ctx, sq, 2)));
    const qd_expr *u = qd_symbol(ctx, "hj_u");
    const qd_expr *to = qd_pow(ctx, qd_add(ctx, qd_int(ctx, 1), qd_powi(ctx, u, 2)), qd_rat(ctx, -1, 2));
    const qd_expr *P = qd_subs(ctx, s->p2, 1, &sq, &to);
    if (!kappa || qd_has(kappa, q) || !P || qd_has(P, q) || !quadratic(ctx, P, u, abc))
        return NULL;
    const qd_expr *uq = invert(ctx, abc, qd_neg(ctx, kappa), tau);
    return uq ? qd_sub(ctx, qd_div(ctx, qd_const(ctx, QD_PI), qd_int(ctx, 2)), qd_fn(ctx, QD_ATAN, uq))
              : NULL;
}

/* q_k from tau = int w dq_k in one of the closed forms, else NULL. */
static const qd_expr *closed(qd_ctx *ctx, const qd_hj_sep *s, const qd_expr *w, const qd_expr *tau) {
    const qd_expr *abc[3];
    const qd_expr *kappa = qd_simplify(ctx, qd_mul(ctx, w, qd_sqrt(ctx, s->p2)));
    if (kappa && !qd_has(kappa, s->q) && quadratic(ctx, s->p2, s->q, abc))
        return invert(ctx, abc, kappa, tau);
    const qd_expr *r = closed_inverse(ctx, s, w, tau);
    return r ? r : closed_cot(ctx, s, w, tau);
}

static const qd_expr *beta_symbol(qd_ctx *ctx, const qd_expr *q) {
    char name[128];
    snprintf(name, sizeof name, "beta_%s", qd_expr_name(q));
    return qd_symbol(ctx, name);
}

/* The momentum representation, one coordinate: p' = -dH/dq at q = qk(p);
 * when that is a constant f, p = f (t - beta) and q = qk(p) (H = p + sin p
 * + q: p = -(t - beta), q = E + t - beta + sin(t - beta)). */
static void solve_momentum(qd_ctx *ctx, qd_hj *h, size_t k) {
    qd_hj_sep *s = &h->sep[k];
    if (h->n != 1)
        return;
    const qd_expr *f = qd_simplify(ctx, qd_subs(ctx, qd_neg(ctx, qd_diff(ctx, h->H, s->q)), 1,
                                                &s->q, &s->qk));
    const qd_expr *beta = beta_symbol(ctx, s->q), *t = qd_time(ctx);
    if (!f || !beta || qd_has(f, s->p) || qd_has(f, s->q) || qd_is_zero(f))
        return;
    const qd_expr *pt = qd_mul(ctx, f, qd_sub(ctx, t, beta));
    s->motion = qd_simplify(ctx, qd_subs(ctx, s->qk, 1, &s->p, &pt));
    s->clock = t;
    s->beta = s->motion ? beta : NULL;
}

/* The motion of q_k against the time, else against a cyclic coordinate. */
static void solve_one(qd_ctx *ctx, qd_hj *h, size_t k) {
    qd_hj_sep *s = &h->sep[k];
    if (s->qk) {
        solve_momentum(ctx, h, k);
        return;
    }
    const qd_expr *vk = velocity(ctx, h, k), *beta = beta_symbol(ctx, s->q), *t = qd_time(ctx);
    if (!vk || !beta || qd_is_zero(vk))
        return;
    if (on_others(h, vk, k)) {
        /* no clock of its own: only an orbit against a cyclic coordinate */
    } else if (!qd_has(vk, s->q)) {                /* uniform motion */
        s->motion = qd_mul(ctx, vk, qd_sub(ctx, t, beta));
        s->clock = t;
    } else if ((s->motion = closed(ctx, s, qd_div(ctx, qd_int(ctx, 1), vk), qd_sub(ctx, t, beta)))) {
        s->clock = t;
    }
    for (size_t j = 0; !s->motion && j < h->n; j++) {
        const qd_hj_sep *c = &h->sep[j];
        if (j == k || !c->cyclic || c->constant == h->energy)
            continue;
        const qd_expr *w = qd_div(ctx, velocity(ctx, h, j), vk);
        if (w && !on_others(h, w, k) &&
            (s->motion = closed(ctx, s, w, qd_sub(ctx, c->q, beta))))
            s->clock = c->q;
    }
    if (s->motion) {
        s->motion = qd_simplify(ctx, s->motion);
        s->beta = beta;
    }
}

qd_status qd_hj_solve(qd_ctx *ctx, qd_hj *h) {
    QD_ARGS_CTX(ctx, ctx && h);
    if (!ctx || !h || !h->separable) {
        if (ctx)
            qd_ctx_error(ctx, QD_ERR_ARG, "the motion needs a separated Hamilton-Jacobi equation");
        return QD_ERR_ARG;
    }
    if (h->time_part) /* an explicit t (time_part.c) */
        return qd__hj_time_solve(ctx, h);
    for (size_t k = 0; k < h->n; k++) {
        solve_one(ctx, h, k);
        if (!qd__ctx_recover(ctx))
            return QD_ERR_NOMEM;
    }
    h->solved = true;
    return QD_OK;
}

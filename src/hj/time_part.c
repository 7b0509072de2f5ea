/*
 * src/hj/time_part.c - the Hamilton-Jacobi equation with an explicit t,
 * separated when every coordinate is cyclic (Desloge ch. 78; seed-desloge-
 * C.md T51, the particle on the moving wire y = x + a t^2/2): p_k = alpha_k
 * and S = sum_k alpha_k q_k + f(t) with f'(t) = -H(alpha, t), so
 * f = -int_0^t H(alpha, t') dt'; the motion from dS/dalpha_k = beta_k is
 * q_k = beta_k - df/dalpha_k.  A t-dependent H in which some coordinate
 * appears is left unseparated (qd_hj.why says so).
 */
#include "hj_priv.h"

#include <stdio.h>
#include <string.h>

/* alpha_<q>, with underscores added while the name is taken by something
 * that is not a plain symbol (as separate.c names its constants). */
static const qd_expr *tp_constant(qd_ctx *ctx, const char *q) {
    char name[128];
    snprintf(name, sizeof name, "alpha_%s", q);
    for (;;) {
        const qd_expr *old = qd_lookup(ctx, name);
        if (!old || qd_symbol_role(old) == QD_ROLE_PLAIN)
            return qd_symbol(ctx, name);
        if (strlen(name) + 2 >= sizeof name)
            return NULL;
        strcat(name, "_");
    }
}

qd_status qd__hj_time_part(qd_ctx *ctx, qd_hj *h, const qd_expr *const *q,
                           const qd_expr *const *p) {
    for (size_t k = 0; k < h->n; k++)
        if (qd_has(h->H, q[k]))
            return QD_OK; /* not all cyclic: why keeps "H depends on t explicitly" */
    const qd_expr *Ha = h->H, *W = qd_int(ctx, 0), *t = qd_time(ctx);
    for (size_t k = 0; k < h->n; k++) {
        const qd_expr *a = tp_constant(ctx, qd_expr_name(q[k]));
        if (!a)
            return QD_ERR_NOMEM;
        h->sep[k] = (qd_hj_sep){.q = q[k], .p = p[k], .constant = a,
                                .equation = qd_sub(ctx, p[k], a), .p2 = qd_powi(ctx, a, 2),
                                .cyclic = true, .integral = p[k]};
        h->constants[k] = a;
        Ha = qd_subs(ctx, Ha, 1, &p[k], &a);
        W = qd_add(ctx, W, qd_mul(ctx, a, q[k]));
    }
    /* f(0) = 0: int_0^t, the antiderivative less its value at 0 */
    const qd_expr *F = Ha ? qd_integrate(ctx, Ha, t) : NULL, *zero = qd_int(ctx, 0);
    if (!F)
        qd_ctx_clear_error(ctx);
    const qd_expr *f = F ? qd_neg(ctx, qd_sub(ctx, F, qd_subs(ctx, F, 1, &t, &zero)))
                         : qd_neg(ctx, qd__hj_integral(ctx, Ha, t));
    if (!(h->W = qd_simplify(ctx, W)) || !(h->time_part = qd_simplify(ctx, f)))
        return qd_ctx_status(ctx) != QD_OK ? qd_ctx_status(ctx) : QD_ERR_NOMEM;
    h->nconst = h->n;
    h->separable = true;
    h->form = "cyclic, explicit t";
    snprintf(h->why, sizeof h->why, "every coordinate is cyclic: S = sum alpha_k q_k + f(t), "
             "f'(t) = -H(alpha, t)");
    return QD_OK;
}

qd_status qd__hj_time_solve(qd_ctx *ctx, qd_hj *h) {
    for (size_t k = 0; k < h->n; k++) {
        qd_hj_sep *s = &h->sep[k];
        char name[160];
        snprintf(name, sizeof name, "beta_%s", qd_expr_name(s->q));
        const qd_expr *beta = qd_symbol(ctx, name);
        const qd_expr *df = qd_diff(ctx, h->time_part, s->constant);
        s->motion = beta && df ? qd_simplify(ctx, qd_sub(ctx, beta, df)) : NULL;
        s->clock = qd_time(ctx);
        s->beta = beta;
        if (!s->motion)
            return qd_ctx_status(ctx) != QD_OK ? qd_ctx_status(ctx) : QD_ERR_NOMEM;
    }
    h->solved = true;
    return QD_OK;
}

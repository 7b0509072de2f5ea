/*
 * src/linear/stability_problem.c - a steady-motion problem stated by name,
 * solved and scanned (qd_stability_problem, qdot/stability.h): the steps
 * `qdot stability` takes, one call each, so that every caller says the same.
 */
#include "qdot/stability.h"

#include <string.h>

#include "../base/args.h"
#include "../base/mem.h"

/* "a, b, c" of the driven items: one list for qd_steady_derive_named. */
static char *join(qd_ctx *ctx, const char *const *items, size_t n) {
    size_t len = 1;
    for (size_t i = 0; i < n; i++)
        len += strlen(items[i]) + 2;
    char *s = qd__malloc(ctx, len);
    if (!s)
        return NULL;
    s[0] = '\0';
    for (size_t i = 0; i < n; i++) {
        strcat(s, i ? ", " : "");
        strcat(s, items[i]);
    }
    return s;
}

qd_status qd_stability_problem_read(qd_ctx *ctx, const qd_model *m, const qd_eom *e,
                                    const qd_stability_spec *spec, qd_stability_problem *out) {
    QD_ARGS_CTX(ctx, ctx && m && e && spec && out && (!spec->ndriven || spec->driven));
    memset(out, 0, sizeof *out);
    bool driven = spec->ndriven > 0;
    if (!spec->ignore == !driven || (driven && (spec->momentum || spec->omega))) {
        qd_ctx_error(ctx, QD_ERR_ARG, "give the cyclic coordinates either ignored (free momenta, "
                                      "with momenta or rates held) or driven (maintained rates)");
        return QD_ERR_ARG;
    }
    if (driven && !(out->driven = join(ctx, spec->driven, spec->ndriven)))
        return QD_ERR_NOMEM;
    out->s = qd_steady_derive_named(ctx, m, e, driven ? "driven" : "ignore",
                                    driven ? out->driven : spec->ignore, driven);
    if (!out->s)
        return qd_ctx_status(ctx) != QD_OK ? qd_ctx_status(ctx) : QD_ERR_ARG;
    qd_steady_spec ss = {.rates = driven ? out->driven : spec->omega,
                         .rates_field = driven ? "driven" : "omega",
                         .momenta = spec->momentum, .guess = spec->guess, .at = spec->at};
    return qd_steady_given_read(ctx, out->s, m, &ss, &out->given);
}

/* The library has left out the motions where the coordinates are singular
 * (counted in set.nsingular). */
qd_status qd_stability_problem_solve(qd_ctx *ctx, qd_stability_problem *p) {
    QD_ARGS_CTX(ctx, ctx && p && p->s && !p->an);
    const qd_steady_given *g = &p->given;
    qd_status st = qd_steady_find_all(ctx, p->s, g->nvals, g->syms, g->vals, g->xfix, g->wfix,
                                      g->pfix, g->pguess, &g->start, &p->set);
    if (st != QD_OK)
        return st;
    if (!(p->an = qd__calloc(ctx, p->set.count + 1, sizeof *p->an)))
        return QD_ERR_NOMEM;
    for (size_t k = 0; st == QD_OK && k < p->set.count; k++)
        st = qd_stability_analyze(ctx, p->s, g->nvals, g->syms, g->vals, &p->set.pts[k],
                                  &p->an[k]);
    return st;
}

qd_status qd_stability_problem_scan(qd_ctx *ctx, const qd_stability_problem *p,
                                    const qd_model *m, const char *param, double a, double b,
                                    size_t steps, qd_scan *out) {
    QD_ARGS_CTX(ctx, ctx && p && p->s && m && param && out);
    const qd_steady_given *g = &p->given;
    qd_scan_opts o = {.steps = steps, .about = g->held};
    return qd_stability_scan(ctx, p->s, m, param, a, b, g->xfix, g->wfix, g->pfix, g->pguess,
                             &g->start, &o, out);
}

void qd_stability_problem_free(qd_stability_problem *p) {
    if (!p)
        return;
    for (size_t k = 0; p->an && k < p->set.count; k++)
        qd_stability_free(&p->an[k]);
    qd__free(p->an);
    qd_steady_set_free(&p->set);
    qd_steady_given_free(&p->given);
    qd_steady_free(p->s);
    qd__free(p->driven);
    memset(p, 0, sizeof *p);
}

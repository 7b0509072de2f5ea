/*
 * src/lyap/setup.c - the exponents of a run set up as `qdot lyapunov`
 * takes it (qd_lyap_setup_run): the variational equations of the set-up's
 * Lagrange equations, the count of exponents checked against 2n, the
 * arrays, the run and the report the printers read; and the flow Jacobian
 * of such a run as `qdot simulate --variational` takes it (qd_flow_setup_run).
 */
#include "lyap.h"

#include "base/mem.h"
#include "qdot/simsetup.h"
#include "../base/args.h"

/* The error just recorded is about the option field name. */
static qd_status field(qd_ctx *ctx, const char *name) {
    qd_ctx_error_about(ctx, QD_SUBJECT_NONE, 0, name, QD_REASON_NONE, NULL);
    return QD_ERR_ARG;
}

/* set's Lagrange equations, or the refusal of what (what) is refused on
 * another form: H, or (with speeds) the speeds a set integrates in. */
static const qd_eom *lagrange(qd_ctx *ctx, const qd_sim_setup *set, const char *what,
                              bool speeds) {
    const qd_eom *e = qd_sim_setup_eom(set);
    if (!e || (speeds && qd_sim_setup_speeds_eom(set))) {
        qd_ctx_error(ctx, QD_ERR_ARG, "%s take a model given by T and V or L (its equations M "
                     "q'' = f), not one given by H or in speeds", what);
        field(ctx, "no_speeds");
        return NULL;
    }
    return e;
}

qd_status qd_flow_setup_run(qd_ctx *ctx, const qd_sim_setup *set, const qd_model *m,
                            const qd_sim_opts *opts, qd_sim_write_fn write, void *data,
                            qd_sim_opts *used, qd_flow *f) {
    if (f)
        *f = (qd_flow){0};
    QD_ARGS_CTX(ctx, ctx && set && m && opts && used && f);
    const qd_eom *e = lagrange(ctx, set, "the flow Jacobian and the monodromy matrix", true);
    qd_lyap *l = e ? qd_lyap_new(ctx, m, e) : NULL;
    if (!l)
        return qd_ctx_status(ctx);
    qd_flow_sim_opts(opts, used);
    qd_status st = write ? qd_flow_run_csv(ctx, l, e, used, 0, write, data, f)
                         : qd_flow_run(ctx, l, used, NULL, f);
    qd_lyap_free(l);
    return st;
}

qd_status qd_lyap_setup_run(qd_ctx *ctx, const qd_sim_setup *set, const qd_model *m,
                            const qd_sim_opts *opts, const qd_lyap_opts *lo, qd_lyap_result *r) {
    if (r)
        *r = (qd_lyap_result){.opts = lo ? *lo : (qd_lyap_opts){0}};
    QD_ARGS_CTX(ctx, ctx && set && m && opts && r);
    const qd_eom *e = lagrange(ctx, set, "Lyapunov exponents", false);
    if (!e)
        return QD_ERR_ARG;
    if (!r->opts.nexp)
        r->opts.nexp = 1;
    if (r->opts.nexp > 2 * e->n) {
        qd_ctx_error(ctx, QD_ERR_ARG, "the model has %zu exponents (twice its %zu degrees of "
                     "freedom), not %zu", 2 * e->n, e->n, r->opts.nexp);
        return field(ctx, "exponents");
    }
    qd_lyap *l = qd_lyap_new(ctx, m, e);
    r->exps = l ? qd__calloc(ctx, 2 * r->opts.nexp, sizeof *r->exps) : NULL;
    if (!r->exps) {
        qd_lyap_free(l);
        return qd_ctx_status(ctx);
    }
    r->err = r->exps + r->opts.nexp;
    qd_status st = qd_lyap_run_stats(ctx, l, opts, &r->opts, r->exps, r->err, &r->stats);
    qd_lyap_free(l);
    r->report = (qd_lyap_report){.opts = &r->opts, .ndof = e->n, .exps = r->exps,
                                 .err = r->err, .stats = &r->stats, .method = opts->method,
                                 .conservative = qd_sim_conservative(qd_sim_setup_sim(set))};
    return st;
}

void qd_lyap_result_free(qd_lyap_result *r) {
    if (!r)
        return;
    qd__free(r->exps);
    r->exps = r->err = NULL;
}

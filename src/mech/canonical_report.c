/*
 * src/mech/canonical_report.c - the question `qdot canonical` asks of a map
 * (qd_canonical_examine, qdot/canonical.h): the verdict, and as asked the
 * Lagrange brackets and the transformed Hamiltonian, each computed only
 * when the ones before it succeeded.
 */
#include "qdot/canonical.h"
#include "base/args.h"

const char *qd_canon_kind_name(qd_canon_kind k) {
    static const char *const name[] = {"canonical", "scaled", "not canonical", "undecided"};
    return (unsigned)k < sizeof name / sizeof name[0] ? name[k] : NULL;
}

qd_status qd_canonical_examine(qd_ctx *ctx, qd_phase *ph, const qd_expr *const *Q,
                               const qd_expr *const *P, bool lagrange, bool newham,
                               qd_canon_report *out) {
    QD_ARGS_CTX(ctx, ctx && ph && Q && P && out);
    *out = (qd_canon_report){.lagrange = lagrange, .newham = newham};
    const qd_expr *t = qd_time(ctx);
    qd_status st = qd_canonical_check(ctx, ph->n, ph->q, ph->p, Q, P, t, &out->v);
    if (st == QD_OK && newham)
        st = qd_phase_ham(ctx, ph, true);
    if (st == QD_OK && (lagrange || newham))
        st = qd_phase_new_vars(ctx, ph);
    if (st == QD_OK && lagrange)
        st = qd_lagrange_brackets(ctx, ph->n, ph->q, ph->p, Q, P, &out->lb);
    bool answered = out->v.kind == QD_CANON_YES || out->v.kind == QD_CANON_SCALED;
    if (st == QD_OK && newham && answered)
        st = qd_transformed_hamiltonian(ctx, ph->n, ph->q, ph->p, Q, P, ph->Q, ph->P, t,
                                        ph->h->H, &out->nh);
    if (st == QD_OK && !ph->Q) /* the names of a failing bracket */
        st = qd_phase_new_vars(ctx, ph);
    if (st != QD_OK)
        qd_canon_report_free(out);
    return st;
}

void qd_canon_report_free(qd_canon_report *r) {
    if (!r)
        return;
    qd_lagrange_result_free(&r->lb);
    qd_newham_free(&r->nh);
}

/*
 * src/sweep/setup.c - a whole sweep set up from its texts, as `qdot sweep`
 * takes it (qd_sweep_setup_new): the measures' needs checked and added to
 * the run, the run compiled, the runs, the measures, the section and the
 * variational equations of the Lyapunov measures.  One place decides what
 * a sweep needs, so every caller refuses the same sweeps the same way.
 */
#include "sweep_int.h"

#include "qdot/simsetup.h"
#include "../base/args.h"

/* The error just recorded is about the option field name. */
static qd_status field(qd_ctx *ctx, const char *name) {
    qd_ctx_error_about(ctx, QD_SUBJECT_NONE, 0, name, QD_REASON_NONE, NULL);
    return QD_ERR_ARG;
}

/* What the measures need that the run lacks, before anything is built. */
static qd_status refuse(qd_ctx *ctx, const qd_sim_setup *set, const qd_sweep_spec *sp) {
    unsigned flags;
    qd_sweep_needs(NULL, sp->measures, NULL, 0, &flags);
    if ((sp->grid != NULL) + (sp->random != NULL) + (sp->list_csv != NULL) != 1) {
        qd_ctx_error(ctx, QD_ERR_ARG, "a sweep takes its runs from one of a grid, a random "
                     "draw and a list");
        return field(ctx, "grid");
    }
    if ((flags & QD_SWEEP_NEEDS_EVENT) && !sp->nevents) {
        qd_ctx_error(ctx, QD_ERR_ARG, "the measure event needs an event of the run (its first "
                     "is the one)");
        return field(ctx, "event");
    }
    if ((flags & QD_SWEEP_NEEDS_SECTION) && !sp->section) {
        qd_ctx_error(ctx, QD_ERR_ARG, "the measure poincare-count needs a section");
        return field(ctx, "section");
    }
    if ((flags & QD_SWEEP_NEEDS_LYAP) && !qd_sim_setup_eom(set)) {
        qd_ctx_error(ctx, QD_ERR_ARG, "the lyapunov measures take a model in the multiplier "
                     "form (not given by H, not in speeds)");
        return field(ctx, "no_speeds");
    }
    return QD_OK;
}

/* The runs of sp; *where names the text an error is located in. */
static qd_status runs(qd_sweep *w, const qd_sweep_spec *sp, const char **where) {
    *where = sp->grid ? "grid" : sp->random ? "random" : "list_csv";
    if (sp->grid)
        return qd_sweep_grid(w, sp->grid);
    if (sp->random)
        return qd_sweep_random(w, sp->random, sp->n, sp->seed);
    return qd_sweep_list_csv(w, sp->list_csv);
}

/* The Lyapunov measures' variational equations, owned by w. */
static qd_status lyap(qd_sweep *w, const qd_sim_setup *set, const qd_sweep_spec *sp) {
    unsigned flags;
    qd_sweep_needs(NULL, sp->measures, NULL, 0, &flags);
    if (!(flags & QD_SWEEP_NEEDS_LYAP))
        return QD_OK;
    w->own_lyap = qd_lyap_new(w->ctx, w->m, qd_sim_setup_eom(set));
    qd_lyap_opts lo = {.renorm = sp->renorm, .transient = sp->transient};
    return w->own_lyap ? qd_sweep_set_lyap(w, w->own_lyap, &lo) : qd_ctx_status(w->ctx);
}

qd_sweep *qd_sweep_setup_new(qd_ctx *ctx, qd_sim_setup *set, const qd_model *m,
                             const qd_sweep_spec *sp, const char **where) {
    QD_ARGS(NULL, ctx && set && m && sp && sp->measures);
    const char *none;
    if (!where)
        where = &none;
    *where = NULL;
    if (refuse(ctx, set, sp) != QD_OK)
        return NULL;
    *where = "measures";
    if (qd_sweep_setup_measures(ctx, set, sp->measures) != QD_OK)
        return NULL;
    *where = NULL;
    qd_sim *s = qd_sim_setup_sim(set);
    qd_sweep *w = qd_sim_compile(s) == QD_OK ? qd_sweep_new(ctx, s, m) : NULL;
    qd_status st = w ? runs(w, sp, where) : qd_ctx_status(ctx);
    if (st == QD_OK) {
        *where = "measures";
        st = qd_sweep_measures(w, sp->measures);
    }
    if (st == QD_OK)
        *where = NULL;
    if (st == QD_OK && sp->section)
        st = qd_sweep_set_section(w, sp->nevents);
    if (st == QD_OK)
        st = lyap(w, set, sp);
    if (st != QD_OK) {
        qd_sweep_free(w);
        return NULL;
    }
    return w;
}

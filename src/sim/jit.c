/*
 * src/sim/jit.c - qd_sim_jit: every compiled program of a system turned
 * into machine code (qd_prog_jit), so that each method's evaluations run
 * at native speed with the interpreter's numbers.
 */
#include "simint.h"
#include "setup.h"
#include "qdot/simsetup.h"

#include <stdio.h>
#include "../base/args.h"

/* Every program of a system, so that a tier-up covers the events and
 * outputs a step samples as well as the right-hand side. */
static size_t programs(const qd_sim *s, qd_prog **progs) {
    qd_prog *all[] = {s->acc, s->con, s->mom, s->force, s->aux, s->en, s->evp,
                      s->kin, s->udef, s->imp, s->uprog, s->fprog};
    size_t n = 0;
    for (size_t k = 0; k < sizeof all / sizeof *all; k++)
        if (all[k])
            progs[n++] = all[k];
    return n;
}

/* The instructions one evaluation of the right-hand side runs. */
static double rhs_work(const qd_sim *s) {
    return (double)(qd_prog_ninstr(s->acc) + qd_prog_ninstr(s->mom) +
                    qd_prog_ninstr(s->force) + qd_prog_ninstr(s->kin));
}

void qd__sim_jit_tier(qd_sim *s, bool now) {
    if (s->jit_tried || (!now && (double)s->evals * rhs_work(s) < QD_SIM_JIT_WORK))
        return;
    s->jit_tried = true;
    /* the JIT's failures (no module) are not the run's: a context of its own */
    qd_ctx *ctx = qd_ctx_new();
    qd_prog *progs[12];
    size_t n = ctx ? programs(s, progs) : 0;
    for (size_t k = 0; k < n && qd_prog_jit(ctx, progs[k]) == QD_OK; k++)
        ;
    qd_ctx_free(ctx);
}

qd_status qd_sim_jit(qd_sim *s) {
    QD_ARGS(QD_ERR_ARG, s);
    qd_status st = qd_sim_compile(s); /* aux holds the outputs and events */
    if (st != QD_OK)
        return st;
    qd_prog *progs[12];
    size_t n = programs(s, progs);
    for (size_t k = 0; st == QD_OK && k < n; k++)
        st = qd_prog_jit(s->ctx, progs[k]);
    return st;
}

qd_status qd_sim_setup_jit(qd_sim_setup *s, char *note, size_t cap) {
    QD_ARGS(QD_ERR_ARG, s);
    if (note && cap)
        note[0] = '\0';
    qd_status st = qd_sim_jit(s->sim);
    if (st == QD_ERR_UNSUPPORTED) { /* still runs, interpreted */
        if (note && cap)
            snprintf(note, cap, "jit unavailable (%s); using the interpreter",
                     qd_ctx_message(s->ctx));
        qd_ctx_clear_error(s->ctx);
        return QD_OK;
    }
    return st;
}

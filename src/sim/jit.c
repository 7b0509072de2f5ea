/*
 * src/sim/jit.c - qd_sim_jit: every compiled program of a system turned
 * into machine code (qd_prog_jit), so that each method's evaluations run
 * at native speed with the interpreter's numbers.
 */
#include "simint.h"
#include "setup.h"
#include "qdot/simsetup.h"

#include <math.h>
#include <stdio.h>
#include "../base/args.h"
#include "sym/sym_export.h"

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

/* An unconstrained system of (q, q') (not made from H, not in speeds):
 * acc is M and f and nothing else, which lag_rhs solves: jitted with that
 * solve. */
static bool fused(const qd_sim *s) {
    return s->acc && !s->hamilton && !s->se && s->m == 0 && s->acc_n == s->n * s->n + s->n;
}

/* The interpreter's work in one evaluation of the right-hand side, in
 * instructions: its programs, and the copies and the Cholesky solve that
 * the fused function (fused) does in registers. */
static double rhs_work(const qd_sim *s) {
    double n = (double)s->n, solve = fused(s) ? n * n * n / 3 + 3 * n * n + 8 * n : 0;
    return (double)(qd_prog_ninstr(s->acc) + qd_prog_ninstr(s->mom) +
                    qd_prog_ninstr(s->force) + qd_prog_ninstr(s->kin)) + solve;
}

/* The evaluations of the whole run, from those done by t: the rate so
 * far over the span to t_end (the done ones when the span is unknown). */
static double predicted_evals(const qd_sim *s, double t) {
    double done = (double)s->evals, span = s->jit_t1 - s->jit_t0, far = t - s->jit_t0;
    if (!isfinite(span) || !isfinite(far) || !(fabs(far) > 0) || !(span / far >= 1))
        return done;
    return done * (span / far);
}

/* Every program as machine code, acc (when fused) only with its solve:
 * lag_rhs calls nothing else of it, and compiling it twice doubled a
 * 20-link pendulum's compile time. */
static qd_status jit_all(qd_ctx *ctx, qd_sim *s) {
    qd_prog *progs[12];
    size_t n = programs(s, progs);
    bool fuse = fused(s);
    qd_status st = QD_OK;
    for (size_t k = 0; st == QD_OK && k < n; k++)
        if (!(fuse && progs[k] == s->acc))
            st = qd_prog_jit(ctx, progs[k]);
    if (st == QD_OK && fuse)
        st = qd__prog_jit_spd(ctx, s->acc, s->n, QD__SIM_SPD_TOL);
    return st;
}

void qd__sim_jit_tier(qd_sim *s, bool now, double t) {
    if (s->jit_tried || (!now && predicted_evals(s, t) * rhs_work(s) < QD_SIM_JIT_WORK))
        return;
    s->jit_tried = true;
    /* the JIT's failures (no module) are not the run's: a context of its own */
    qd_ctx *ctx = qd_ctx_new();
    if (ctx)
        jit_all(ctx, s);
    qd_ctx_free(ctx);
}

qd_status qd_sim_jit(qd_sim *s) {
    QD_ARGS(QD_ERR_ARG, s);
    qd_status st = qd_sim_compile(s); /* aux holds the outputs and events */
    return st == QD_OK ? jit_all(s->ctx, s) : st;
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

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

qd_status qd_sim_jit(qd_sim *s) {
    QD_ARGS(QD_ERR_ARG, s);
    qd_status st = qd_sim_compile(s); /* aux holds the outputs and events */
    if (st != QD_OK)
        return st;
    qd_prog *progs[] = {s->acc, s->con, s->mom, s->force, s->aux, s->en, s->evp,
                        s->kin, s->udef, s->imp, s->uprog, s->fprog};
    for (size_t k = 0; st == QD_OK && k < sizeof progs / sizeof *progs; k++)
        if (progs[k])
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

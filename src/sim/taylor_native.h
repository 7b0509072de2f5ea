/*
 * src/sim/taylor_native.h - what the Taylor integrator (taylor.c) and its
 * native loader (taylor_native.c) share: which programs the method
 * differentiates and which of their inputs vary, so that the generated
 * recurrences are those of the qd__tay every run builds.
 */
#ifndef QD_SIM_TAYLOR_NATIVE_H
#define QD_SIM_TAYLOR_NATIVE_H

#include "simint.h"
#include "sym/sym_export.h"

/* The programs (*np of them, at most 2) and var[0..s->nin): the state's
 * inputs in the method's form, and t. */
void qd__sim_taylor_inputs(const qd_sim *s, const qd_prog *progs[2], size_t *np, bool *var);

/* s's generated recurrences, when loaded and made for tp; else NULL. */
qd__tay_native qd__sim_taylor_native_for(const qd_sim *s, const qd__tay *tp);

void qd__sim_taylor_native_free(qd_sim *s);

#endif

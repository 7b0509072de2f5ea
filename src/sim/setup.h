/*
 * src/sim/setup.h - the set-up of a simulation (qdot/simsetup.h), shared by
 * setup.c (equations, initial state, options) and names.c (expressions in
 * the model's names: outputs, events, inputs).  Private to src/sim.
 */
#ifndef QD_SIM_SETUP_H
#define QD_SIM_SETUP_H

#include "qdot/codegen.h"
#include "qdot/simsetup.h"

struct qd_sim_setup {
    qd_ctx *ctx;
    const qd_model *m;
    qd_sim_form form;
    qd_eom *e;            /* Lagrange's form, else NULL */
    qd_speeds_eom *se;    /* the speeds form, else NULL */
    qd_sim *sim;
    /* the initial state: q, q', t, parameters, then momenta (H) or speeds */
    size_t n, nq, extra;  /* extra: the momenta or speeds at the end */
    const qd_expr **syms;
    double *vals;
    double *vals0;        /* the model's own initial state (qd_sim_setup_restart) */
    bool initial_given;
    bool *given;          /* n: the state's slots given by qd_sim_setup_initial */
    bool *qd0_given;      /* nq: the velocities given, in the equations' order */
    double *q0, *qd0, *p0, *u0; /* the run's initial values (qd_sim_setup_options) */
    qd_native *native;
    double period;        /* qd_sim_setup_options' period, else NaN */
    bool *input_given;    /* per model input: named by qd_sim_setup_input_text */
};

#endif

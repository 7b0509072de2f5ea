/*
 * cli/speeds_out.h - `qdot eom` output for a model with generalized speeds:
 * the kinematics q' = W u + w, the dynamic equations M_u u' = f_u
 * (qdot/speeds.h) and, when asked, the Gibbs-Appell function S and the
 * constraints' multipliers, in the five formats of eom_out.h.
 */
#ifndef QDOT_CLI_SPEEDS_OUT_H
#define QDOT_CLI_SPEEDS_OUT_H

#include "qdot/speeds.h"
#include "eom_out.h"

typedef struct cli_speeds_view {
    qd_ctx *ctx;
    const cli_model_file *mf;
    const qd_speeds_eom *e;   /* e->S and e->mult are printed when not NULL */
    bool multipliers;         /* asked for: said so also when there are none */
    /* --at: the numbers at one state instead (text and JSON only): st the
     * state (q, q', t, the parameters, then u), qd the velocities from the
     * kinematics (n), ud the speeds' rates (m), lambda the multipliers
     * (ncon) or NULL. */
    const cli_state *st;
    const double *qd, *ud, *lambda;
} cli_speeds_view;

/* Append the view to out; QD_OK, or the status of a printer that failed. */
qd_status cli_speeds_write(const cli_speeds_view *v, cli_eom_format fmt, qd_buf *out);

#endif

/*
 * src/sim/sim_export.h - sim's interface to the modules above it
 * (docs/design.md, "Architecture"): the compiled system's layout and the
 * explicit Runge-Kutta pairs, on which src/lyap integrates the state with
 * its tangent vectors (a run copy of the qd_sim with its own right-hand
 * side, ext_rhs).  Internal (prefix qd__sim_), not public: a C user runs
 * a qd_sim through qdot/sim.h; this is the layout the methods work on.
 */
#ifndef QD_SIM_SIM_EXPORT_H
#define QD_SIM_SIM_EXPORT_H

#include "qdot/eval.h"
#include "qdot/sim.h"
#include "qdot/speeds.h"

/* The state a method integrates: (q, q'), (q, p), or (q, u) in speeds. */
typedef enum qd__sim_form { QD__LAG, QD__HAM, QD__SPD } qd__sim_form;

typedef struct qd__sim_event {
    bool stop;
    size_t nguard;
} qd__sim_event;

/* Inputs of every program: q (n), q' (n), t, parameters (np), and, in the
 * (q, q') system, the constraints' multipliers (m) and the accelerations q''
 * (n), which only outputs and events read: they are solved for at the state
 * when one of those uses them (aux_lambda, aux_acc).
 *
 * Two parts.  The compiled system (programs, expressions, names, flags) is
 * immutable once qd_sim_compile has run: concurrent runs share it.  A run
 * works on a copy of the struct whose workspace part (qd__sim_ws_alloc:
 * inputs, outputs and workspaces of the programs, solver scratch, counters,
 * the context for messages) is its own. */
struct qd_sim {
    /* ---- compiled ---- */
    const qd_model *model;
    const qd_eom *e;
    size_t n, m, np, nin;
    const qd_expr **in_syms;
    double *par;    /* np parameter values */
    qd_prog *acc;   /* M (n*n), f (n), A (m*n), b (m) */
    qd_prog *con;   /* A (m*n), a0 (m), g (m) */
    qd_prog *mom;   /* canonical: M (n*n), b (n) = dL/dq' at q' = 0 */
    qd_prog *force; /* canonical: dL/dq + Q - dD/dq' (n) */
    qd_prog *aux;   /* h, T, g (m), outputs, events, guards */
    qd_prog *en;    /* h, T alone (the per-step energy measure), when aux has more */
    qd_prog *evp;   /* the events and the gaps alone (aux's, the same doubles): what
                       a step's sampling evaluates, many times per step */
    size_t acc_n, con_n, mom_n, force_n, aux_n, en_n, evp_n; /* output counts */
    bool canonical, separable, conservative, has_T;
    bool hamilton;  /* made from H (hamilton.c): e is NULL, the inputs' second
                       block holds the momenta, mom gives q' = dH/dp, acc
                       dH/dp and d^2H/dp^2 (initial momenta from velocities) */
    const qd_expr *h_expr, *T_expr;
    const qd_expr **b_expr, **force_expr;
    bool *holonomic;  /* m */
    const qd_con *cons; /* m: the constraints (e's, or se's in speeds) */
    /* generalized speeds (speeds.c): se the equations, y = (q, u); the
     * inputs' last block holds the nu speeds where the multipliers stand
     * otherwise; acc gives q' (n), M_u (nu*nu), f_u (nu), kin q' alone,
     * udef the speeds from (q, q', t) */
    const qd_speeds_eom *se;
    size_t nu;
    qd_prog *kin, *udef;
    size_t kin_n, udef_n;
    /* outputs and events, compiled into aux by qd_sim_compile */
    size_t nout, nev, nguard, cap_out, cap_ev, cap_guard;
    char **out_name;
    const qd_expr **out_expr, **ev_expr, **guard_expr;
    qd__sim_event *ev;
    bool aux_ready, aux_lambda, aux_acc;
    bool ev_lambda, ev_acc; /* evp reads the multipliers, the accelerations */
    /* column names of the fixed part: t, q, q', p_q, energy, res_c */
    char **names;
    size_t nnames;
    qd_sim_native_rhs native;
    /* the taylor method's generated recurrences (taylor_native.c) */
    void *tay_handle;
    void (*tay_native)(double *c, size_t stride, size_t k);
    unsigned long tay_nreg, tay_nlive;
    double *con_err_last; /* m: qd_sim_run's last per-constraint residuals */
    bool *solved;         /* n: the velocities the start solved (qd_sim_initial_solved) */
    bool *solved_last;    /* n: the same, kept after qd_sim_run */
    /* unilateral contacts (impact.c): their gaps are events nev.. of aux;
     * imp gives each one's gradient dGAP/dq (n) and dGAP/dt */
    size_t nimp, imp_n;
    const char **imp_name;
    const qd_expr **imp_gap;
    double *imp_E;  /* nimp restitutions, in [0, 1] */
    qd_prog *imp;
    /* the model's inputs (input.c): values in the slots uin_off.. of the
     * programs' inputs, filled from their sources before every evaluation;
     * uprog computes the expression sources (0 for the others) */
    size_t nuin, uin_off;
    struct qd__sim_input *uin;
    qd_prog *uprog;
    bool uin_ready;
    /* a run's first callback input that returned a non-finite value: its
     * index + 1 (0: none), t and value; the run ends at the next check */
    size_t uin_bad;
    double uin_bad_t, uin_bad_v;
    /* Coulomb friction (friction.c): nfc contacts; fprog gives for each
     * mu_s, mu_k, N (an expression's value; for a multiplier |N|/|lambda_N|), its
     * slip velocities s1, s2 (QD__FSTRIDE numbers per contact) */
    size_t nfc, fprog_n;
    struct qd__sim_fcon *fc;
    qd_prog *fprog;
    struct qd__sim_fric_last *flast; /* qd_sim_run's transitions (qd_sim_transitions) */
    bool rheo;      /* with friction: some constraint has a0 != 0 (a moving surface),
                       so the surfaces' work is one more state, y[2n + 1] */
    /* ---- a run's own ---- */
    qd_ctx *ctx;
    qd_sim_stop stop; /* the first failure's code, time and quantity (qd__sim_stop) */
    double *in;
    double *acc_out, *con_out, *mom_out, *force_out, *aux_out, *en_out;
    double *acc_w, *con_w, *mom_w, *force_w, *aux_w, *en_w;
    double *imp_out, *imp_w;
    double *evp_out, *evp_w;
    double *kin_out, *kin_w, *udef_out, *udef_w;
    double *uprog_out, *uprog_w;
    /* scratch for the linear solves */
    double *K, *rhs, *tmp;
    size_t *pc;
    size_t evals;
    /* the JIT (jit.c): qd_sim_opts.jit of the run, and whether it has
     * compiled (or tried to) */
    int jit_mode;
    bool jit_tried;
    double jit_t0, jit_t1; /* the run's span, to predict its length */
    double *con_err;  /* m: the worst residual of each constraint in this run */
    double tnow;  /* for messages */
    /* A run's own right-hand side in place of the form's, for a caller that
     * integrates more than the state with these methods (src/lyap: the
     * state and its tangent vectors); NULL: the form's. */
    qd_status (*ext_rhs)(void *data, double t, const double *y, double *dy);
    void *ext_data;
    double *fprog_out, *fprog_w;
    struct qd__sim_fric_run *fr; /* the contacts' modes in this run (friction.c) */
};

/* Compile outs into a program over s's inputs (angle sums expanded as the
 * generated C does); *count = nout.  NULL on failure, reason in ctx. */
qd_prog *qd__sim_prog(qd_sim *s, size_t nout, const qd_expr *const *outs, size_t *count);

/* Give the run copy w (a struct copy of a compiled system) its own
 * workspace, messages going to ctx; QD_ERR_NOMEM (nothing recorded). */
qd_status qd__sim_ws_alloc(qd_sim *w, qd_ctx *ctx);
void qd__sim_ws_free(qd_sim *w);

/* Records "WHAT not finite at t: CAUSE" (QD_ERR_NUMERIC) for the state
 * last set in s->in (qd__sim_not_finite_at with no values). */
qd_status qd__sim_not_finite(qd_sim *s, double t, const char *what);

/* ---- integrators ----------------------------------------------------------- */

typedef struct qd__sim_integ qd__sim_integ;

typedef struct qd__sim_method {
    qd_status (*init)(qd__sim_integ *it);
    /* One accepted step from (t, y) with it->h (the driver caps it at the
     * end); sets told, yold and t, y, and (adaptive) the next it->h. */
    qd_status (*step)(qd__sim_integ *it);
    /* y at t in [told, t]; NULL: cubic Hermite from the derivatives. */
    void (*dense)(qd__sim_integ *it, double t, double *y);
    /* One step of size h from (told, yold) into y (events); NULL: none. */
    qd_status (*redo)(qd__sim_integ *it, double h, double *y);
    void (*free)(qd__sim_integ *it);
} qd__sim_method;

struct qd__sim_integ {
    qd_sim *s;
    const qd__sim_method *ops;
    qd_sim_method method;
    qd__sim_form form;  /* LAG, or HAM for the symplectic methods when canonical */
    size_t dim;
    double t, told, h, tend, rtol, atol; /* h > 0 at init: the first step */
    double *y, *yold;
    bool fixed, y_changed; /* y_changed: the driver projected y after the step */
    size_t steps, rejected;
    void *priv;
    int precision; /* the Taylor method's type: 64, 80, 128 bits (0: 64) */
};

/* Dormand and Prince's pairs of order 5(4) and 8(5,3) (dopri5.c, dop853.c). */
extern const qd__sim_method qd__sim_dopri5, qd__sim_dop853;

#endif

/*
 * src/sim/simint.h - what the simulation files share beyond sim_export.h
 * (the compiled system and the integrator interface, which lyap uses too):
 * the system's set-up and evaluation (system.c), runs and events, the
 * methods' tables, contacts, friction, the projection (project.c).
 */
#ifndef QD_SIM_SIMINT_H
#define QD_SIM_SIMINT_H

#include "qdot/eval.h"
#include "qdot/sim.h"
#include "qdot/speeds.h"
#include "sim_export.h"

/* The state's second half as the programs take it: the momenta (y + n)
 * for a system made from H, the velocities qd otherwise. */
static inline const double *qd__sim_second(const qd_sim *s, const double *y, const double *qd) {
    return s->hamilton ? y + s->n : qd;
}

/* The speeds' block of the inputs (a system in speeds). */
static inline double *qd__sim_in_speeds(qd_sim *s) { return s->in + 2 * s->n + 1 + s->np; }

/* Record why the run stops (the first record wins, as the context's first
 * error does); called next to the qd_ctx_error that words it. */
void qd__sim_stop(qd_sim *s, qd_stop_code code, double t, double value);

/* ---- the model's inputs (input.c) ---------------------------------------- */

/* The input slots: nuin from the model, their symbols at in_syms[uin_off..)
 * (in_syms must have room); QD_ERR_ARG for a system in speeds or from H. */
qd_status qd__sim_uin_init(qd_sim *s);
void qd__sim_uin_free(qd_sim *s);
/* Compile the expression sources (qd_sim_compile). */
qd_status qd__sim_uin_compile(qd_sim *s);
/* Before a run from t0 to t1: every input the equations use has a source,
 * and every table covers [t0, t1]; QD_ERR_ARG naming the input. */
qd_status qd__sim_uin_check(qd_sim *s, double t0, double t1);
/* The inputs' values at t and the state already in s->in.  A callback
 * value that is not finite is kept (s->uin_bad) and ends the run. */
void qd__sim_uin_eval(qd_sim *s, double t);
/* Records "input F is not finite at t" for s->uin_bad (QD_ERR_NUMERIC). */
qd_status qd__sim_uin_failed(qd_sim *s);

/* The same over the concatenation of nparts arrays, parts[i] of size[i]
 * outputs; *count their total. */
qd_prog *qd__sim_prog_of(qd_sim *s, size_t nparts, const qd_expr *const *const *parts,
                         const size_t *size, size_t *count);
/* A system being made: a copy of *init allocated in ctx, or NULL (out of
 * memory, recorded). */
qd_sim *qd__sim_alloc(qd_ctx *ctx, const qd_sim *init);
/* s when st is QD_OK; else NULL with s freed and the error in ctx (what,
 * when nothing more precise was recorded). */
qd_sim *qd__sim_made(qd_sim *s, qd_status st, const char *what);
/* The programs' inputs: q, qd (n each), t, the parameters (their values
 * into s->par) and ntail more that the caller fills (the multipliers, or
 * the speeds). */
qd_status qd__sim_inputs(qd_sim *s, const qd_expr *const *q, const qd_expr *const *qd,
                         size_t ntail);
/* The column names and the per-constraint arrays. */
qd_status qd__sim_names(qd_sim *s);
/* A system made from H: the velocities in x[0..n) replaced by dH/dp, so
 * that outputs and events may use them. */
void qd__sim_hamilton_velocities(qd_sim *s, size_t n, const qd_expr **x);
/* A system made from H: p at t0 from the velocities qd (Newton on
 * dH/dp = qd); QD_ERR_SINGULAR when d^2H/dp^2 is singular there. */
qd_status qd__sim_hamilton_momenta(qd_sim *s, double t, const double *q, const double *qd,
                               double *p);

/* The constraints' program con: A (m*n), a0 (m), phi (m). */
qd_status qd__sim_con_prog(qd_sim *s);

/* ---- generalized speeds (speeds.c) ----------------------------------------- */

/* The speeds replaced by their definitions in x[0..n), so that outputs
 * and events may name them and still be read at (q, q', t). */
void qd__sim_speeds_defs(qd_sim *s, size_t n, const qd_expr **x);
/* (q', u') at (q, u, t): the kinematics, and M_u u' = f_u solved. */
qd_status qd__sim_speeds_rhs(qd_sim *s, double t, const double *y, double *dy);
/* q' = kin(q, u, t) at y = (q, u). */
void qd__sim_speeds_velocity(qd_sim *s, double t, const double *y, double *qd);
/* u from (q, q', t) by the definitions. */
void qd__sim_speeds_from(qd_sim *s, double t, const double *q, const double *qd, double *u);

/* Offsets in aux_out: h, T, the constraints, the outputs, the events
 * (the user's, then the impacts' gaps), the user events' guards. */
static inline size_t qd__sim_aux_out(const qd_sim *s) { return 2 + s->m; }
static inline size_t qd__sim_aux_ev(const qd_sim *s) { return 2 + s->m + s->nout; }
static inline size_t qd__sim_aux_guard(const qd_sim *s) {
    return 2 + s->m + s->nout + s->nev + s->nimp;
}
/* Event functions located in a step: the user's events, the gaps and two
 * per friction contact (its mode's switch, its normal force's sign). */
static inline size_t qd__sim_nev_all(const qd_sim *s) { return s->nev + s->nimp + 2 * s->nfc; }
/* The first friction event's index. */
static inline size_t qd__sim_fev0(const qd_sim *s) { return s->nev + s->nimp; }

/* y' = F(t, y) in either form; QD_ERR_SINGULAR (message with the time)
 * when M or the saddle matrix is singular. */
qd_status qd__sim_rhs(qd_sim *s, qd__sim_form form, double t, const double *y, double *dy);
/* The run's programs as machine code (jit.c): at once when now, else once
 * its evaluations, those done and those predicted to t_end from the time t
 * reached, come to QD_SIM_JIT_WORK instructions' worth of interpreting;
 * tried once per run, a failure leaving them interpreted. */
void qd__sim_jit_tier(qd_sim *s, bool now, double t);
/* qd__num_solve_spd's tolerance in the mass matrix's solve (system.c and
 * its jitted twin, jit.c). */
#define QD__SIM_SPD_TOL 1e-10
/* q' from (q, p) at t (canonical form). */
qd_status qd__sim_velocity(qd_sim *s, double t, const double *q, const double *p, double *qd);
/* p from (q, q'). */
void qd__sim_momentum(qd_sim *s, double t, const double *q, const double *qd, double *p);
/* The force dL/dq + Q - dD/dq' at (q, q', t) (canonical form). */
void qd__sim_force(qd_sim *s, double t, const double *q, const double *qd, double *F);
/* q' = M^-1 p for a separable system (constant M). */
qd_status qd__sim_drift_velocity(qd_sim *s, const double *p, double *qd);
/* Compile the outputs and events (once). */
qd_status qd__sim_aux_compile(qd_sim *s);
/* Evaluate aux at (q, q', t) into s->aux_out. */
void qd__sim_aux_eval(qd_sim *s, double t, const double *q, const double *qd);
/* The event functions at (q, q', t): the user's events, then the gaps (as
 * in aux_out from qd__sim_aux_ev, and the same doubles), without the rest
 * of aux. */
const double *qd__sim_ev_eval(qd_sim *s, double t, const double *q, const double *qd);
/* h and T at (q, q', t): the first two entries of the result. */
const double *qd__sim_energy_eval(qd_sim *s, double t, const double *q, const double *qd);
/* Records "WHAT not finite at t: CAUSE" (QD_ERR_NUMERIC), CAUSE from the
 * state last set in s->in and the values x[0..nx) found not finite (x may
 * be NULL): an overflow of the state, a division by zero (infinities at a
 * finite state), or a state outside the domain of the model's expressions
 * (NaN: |v| > c under sqrt(1 - v^2/c^2), ...). */
qd_status qd__sim_not_finite_at(qd_sim *s, double t, const char *what, const double *x,
                                size_t nx);
const char *qd__sim_nonfinite_cause(const qd_sim *s, const double *x, size_t nx);
/* Run p (compiled over s's inputs, work its workspace) at (q, q', t). */
void qd__sim_prog_at(qd_sim *s, const qd_prog *p, double *work, double t, const double *q,
                 const double *qd, double *out);
/* Evaluate con at (q, q', t) into s->con_out. */
void qd__sim_con_eval(qd_sim *s, double t, const double *q, const double *qd);

/* ---- integrators ----------------------------------------------------------- */

extern const qd__sim_method qd__sim_gauss2, qd__sim_gauss4, qd__sim_gauss6, qd__sim_verlet,
    qd__sim_yoshida4, qd__sim_yoshida6, qd__sim_yoshida8, qd__sim_bdf;
extern const qd__sim_method qd__sim_taylor; /* taylor.c */

/* An explicit Runge-Kutta pair (erk.c runs it): the step rk (num's tables
 * and stage loop) of rk->stages stages, the derivative at t + h the first
 * stage of the next step (FSAL); err is the error norm of the step (1 = the
 * tolerance), dense_prep the interpolant's coefficients from the stages of
 * the last step (nextra more of them), in ndense rows. */
typedef struct qd__sim_erk {
    const struct qd__num_rk *rk;
    int order, nextra, ndense;
    /* step size control of Hairer's dopri5.f/dop853.f: h_new = h / fac with
     * fac = err^expo / facold^beta / safe kept in [1/fac2, 1/fac1], facold
     * the error of the last accepted step (Lund stabilization, beta > 0) */
    double fac1, fac2, safe, beta, expo;
    double (*err)(const qd__sim_integ *it, const double *const *K, double h, const double *ynew);
    qd_status (*dense_prep)(qd__sim_integ *it, double **K, double *coef);
    void (*dense_eval)(const qd__sim_integ *it, const double *coef, double x, double *y);
} qd__sim_erk;
qd_status qd__sim_erk_init(qd__sim_integ *it, const qd__sim_erk *tab);
qd_status qd__sim_erk_step(qd__sim_integ *it);
void qd__sim_erk_dense(qd__sim_integ *it, double t, double *y);
qd_status qd__sim_erk_redo(qd__sim_integ *it, double h, double *y);
void qd__sim_erk_free(qd__sim_integ *it);
/* sqrt(mean((e_i / (atol + rtol max(|y_i|, |ynew_i|)))^2)) */
double qd__sim_err_rms(const qd__sim_integ *it, const double *err, const double *ynew);
qd_status qd__sim_underflow(qd__sim_integ *it, double h);

/* ---- a run (run.c) and its events (events.c) ------------------------------- */

typedef struct qd__sim_run {
    qd_sim *s;
    qd__sim_integ *it;
    double *row, *qd, *ytmp, *fa, *fb; /* row; q' scratch; state scratch; Hermite slopes */
    double *gold, *gnew;               /* event functions at told and t */
    double *ev_t, *ev_y;               /* located events of a step: nev times, nev*dim */
    bool *ev_hit, *ev_ok;
    bool slopes;                       /* fa, fb valid for this step */
    /* fb at (fb_t, fb_y) when fb_valid: the next step's fa if it starts there
     * (restart() clears it: an impact or a mode switch changes the rhs) */
    double *fb_y, fb_t;
    bool fb_valid;
    double *smp;                       /* the event functions at the step's samples */
    size_t nsmp;                       /* sample intervals of the step */
    double *ev_after;                  /* nev: the far side of each located crossing */
    /* steps whose event functions turned faster than NSAMPLE_MAX samples
     * resolve: their count, the first one's time and event, the widest
     * sample spacing among them */
    size_t fast_steps, fast_event;
    double fast_t, fast_spacing;
    struct qd__sim_impacts *imp;           /* the contacts' history (impact.c), or NULL */
    struct qd__sim_measure *meas;          /* the error measures (run.c), or NULL */
} qd__sim_run;

/* One contact's history in a run: what the chattering test reads. */
typedef struct qd__sim_contact {
    size_t count;     /* impacts so far */
    double t[3];      /* the last three impact times, t[2] the latest */
    double vout[3];   /* the rebound rates E |dGAP/dt-| after them */
    double vmax;      /* the fastest approach */
} qd__sim_contact;

typedef struct qd__sim_impacts {
    qd__sim_contact *c;   /* nimp */
    double *K, *rhs, *A, *b, *zero; /* Newton's law: the saddle system, m + 1 rows */
    bool *fresh;      /* nimp: struck at the start of the next step */
    bool *set;        /* nimp: the contacts struck together */
    double *g;        /* the event functions at the impact (nev + nimp) */
    size_t unresolved;/* a contact whose landing the step missed, or nimp */
    double t_after, *y_after; /* the state just after the last impact (retries) */
    double *ylag, *dy;        /* (q, q') and its derivative: the gap's acceleration */
    int retries;
} qd__sim_impacts;

/* q' of state y (q, q' or q, p) at t into r->qd. */
qd_status qd__sim_run_velocity(qd__sim_run *r, double t, const double *y);
/* The state at t in [told, t] (dense output or cubic Hermite). */
qd_status qd__sim_run_dense(qd__sim_run *r, double t, double *y);
/* Event functions at (t, y) into g (nev, may be NULL); ok[k] (may be NULL):
 * every guard of event k is > 0. */
qd_status qd__sim_run_events_at(qd__sim_run *r, double t, const double *y, double *g, bool *ok);
/* Locate the events that changed sign in the last step: r->ev_hit[k],
 * r->ev_t[k], r->ev_y + k*dim for each that happened (guards true). */
qd_status qd__sim_events_locate(qd__sim_run *r);
/* The next crossing of user event k in the step after the one just
 * located (r->ev_after[k]); r->ev_hit[k] when there is one. */
qd_status qd__sim_events_next(qd__sim_run *r, size_t k);
/* The most sample intervals the event search uses in a step. */
#define QD__EV_SAMPLES_MAX 64

/* ---- unilateral contacts (impact.c) --------------------------------------- */

/* The model's `impact NAME: GAP >= 0 restitution E`: the gaps (no
 * velocities), E in [0, 1], the gradients compiled (qd_sim_new). */
qd_status qd__sim_impact_setup(qd_sim *s);
void qd__sim_impact_free(qd_sim *s);
/* A run's contact history; NULL and QD_OK without impacts. */
qd_status qd__sim_impacts_new(qd__sim_run *r);
void qd__sim_impacts_free(qd__sim_run *r);
/* The gaps at the start: QD_ERR_ARG when one is negative. */
qd_status qd__sim_impact_check_start(qd__sim_run *r, double t, const double *y);
/* The rate dGAP/dt = a . q' + a0 of contact i at (t, y), q' in r->qd. */
double qd__sim_impact_rate(qd__sim_run *r, size_t i, double t, const double *y);

/* What an impact did, for the driver (run.c). */
typedef struct qd__sim_impact_result {
    double lost;      /* h before - h after */
    size_t count;     /* the contacts struck together (1 or more) */
    bool contact;     /* the run ends: in contact */
    bool at_rest;     /* ... with nothing moving (T after <= rtol T before) */
    bool zeno;        /* the bounces' times were summed (chattering) */
    double t_rest;    /* from when (the accumulation time of the impacts) */
} qd__sim_impact_result;
/* Newton's law for contact i at (t, y) (velocities just before), the
 * ordinary constraints held: y gets the velocities (momenta) after.  At
 * rest (chattering, or a rebound too small to resolve) the impact is
 * plastic, y is moved to res->t_rest and res->contact is set. */
qd_status qd__sim_impact_apply(qd__sim_run *r, size_t i, double t, double *y, qd__sim_impact_result *res);
/* Contact i's rebound could not be resolved from the state after its
 * impact (t, y): end in contact there (plastic impact, as above). */
qd_status qd__sim_impact_rest(qd__sim_run *r, size_t i, double t, double *y, qd__sim_impact_result *res);

/* ---- Coulomb friction (friction.c, friction_lcp.c) --------------------------- */

#define QD__FSTRIDE 5   /* fprog's numbers per contact: mu_s, mu_k, N, s1, s2 */
#define QD__FMAX 12     /* contacts: the mode choice tries up to 5^k sets */

/* A contact as compiled: its constraints (indices into s->cons) and the
 * constraint whose multiplier is the normal force (or (size_t)-1). */
typedef struct qd__sim_fcon {
    const char *name;
    size_t con[2], ncon, normal;
} qd__sim_fcon;

/* A contact's mode in a run.  slip: its rows are replaced by the kinetic
 * force -mu_k |N| u, u the unit slip direction (1-D: dir[0] = +-1; 2-D:
 * v/|v|, or dir while v = 0); sn: the sign assumed for the normal
 * multiplier, |N| = sn lambda_N. */
typedef struct qd__sim_fmode {
    bool slip;
    double dir[2];
    double sn;
} qd__sim_fmode;

typedef struct qd__sim_fric_run {
    qd__sim_fmode *mode;           /* nfc */
    bool *on;                  /* m: false for the rows of slipping contacts */
    qd_sim_transition *tr;     /* the switches so far */
    size_t ntr, cap;
    qd__sim_fmode *trial, *best;   /* nfc each: the mode choice's scratch */
    bool *fresh;               /* nfc: entered slip from rest at the last switch */
} qd__sim_fric_run;

/* The contacts of s's model compiled (qd_sim_new); QD_OK without any. */
qd_status qd__sim_fric_setup(qd_sim *s);
void qd__sim_fric_free(qd_sim *s);
/* QD_ERR_ARG naming what when the model has friction (the forms that
 * cannot take it: speeds, H). */
qd_status qd__sim_fric_refuse(qd_ctx *ctx, const qd_model *m, const char *what);
/* A run's modes; NULL and QD_OK without friction. */
qd_status qd__sim_fric_run_new(qd_sim *s);
void qd__sim_fric_run_free(qd_sim *s);
/* The saddle system K r = rhs ((n+m)^2, assembled at the state in s->in)
 * with the slipping contacts' rows replaced by their kinetic forces. */
void qd__sim_fric_saddle(qd_sim *s, double *K, double *rhs);
/* The power the slipping contacts dissipate, -sum lambda s, after the
 * saddle solve at the state (lambda in s->rhs + n). */
double qd__sim_fric_power(const qd_sim *s);
/* The power the surfaces' own motion puts into the system, -sum_c
 * lambda_c a0_c over every constraint (sticking or slipping), after the
 * saddle solve at the state in s->in. */
double qd__sim_fric_surface_power(qd_sim *s);
/* The extra states a friction run integrates after (q, q'): dissipated,
 * and surface_work when the surfaces move. */
size_t qd__sim_fric_nextra(const qd_sim *s);
/* Friction event k (0 .. 2 nfc) at (t, y). */
qd_status qd__sim_fric_event(qd__sim_run *r, size_t k, double t, const double *y, double *g);
/* Does friction event k switch when it leaves ga (sticking: rising from
 * below 0; else falling from above)? */
bool qd__sim_fric_crossing(const qd_sim *s, size_t k, double ga);
/* Choose the contacts' modes at (t, y): at the start (ev = (size_t)-1) or
 * after friction event ev; records the switches.  QD_ERR_NUMERIC
 * (Painleve's paradox) when no set of modes, or several, is consistent. */
qd_status qd__sim_fric_select(qd__sim_run *r, double t, const double *y, size_t ev);
/* The saddle solve at (t, y) with the current modes (system.c); false when
 * singular.  lambda in s->rhs + n, q'' in s->rhs. */
bool qd__sim_saddle(qd_sim *s, double t, const double *y);
/* |N| and the friction force's size |lambda| of contact c after a saddle
 * solve. */
double qd__sim_fric_normal(const qd_sim *s, size_t c);
double qd__sim_fric_force(const qd_sim *s, size_t c);
/* After a run: its switches kept in orig for qd_sim_transitions. */
void qd__sim_fric_keep(qd_sim *orig, qd_sim *run);
/* A contact's slip speed for the row: s (1-D) or |v| (2-D), at the state
 * last given to fprog. */
double qd__sim_fric_slip(const qd_sim *s, size_t c);

/* ---- constraints (project.c) ----------------------------------------------- */

/* Move q onto the holonomic constraints phi(q, t) = 0 (Gauss-Newton with the
 * constraint Jacobian) and q' onto A q' + a0 = 0.  QD_ERR_NUMERIC naming the
 * constraint when positions cannot be brought to it. */
qd_status qd__sim_project(qd_sim *s, double t, double *q, double *qd);
/* The start's projection: as qd__sim_project, the velocities given
 * (given[j], may be NULL) kept and the others solved (s->solved marks
 * those that changed); QD_ERR_ARG when a constraint only given velocities
 * enter is violated by them. */
qd_status qd__sim_project_start(qd_sim *s, double t, double *q, double *qd, const bool *given);

#endif

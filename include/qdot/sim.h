/*
 * qdot/sim.h - numerical integration of a model's equations of motion.
 *
 * A qd_sim is a model compiled into a first-order system (qd_prog programs,
 * no tree walking per step, no allocation per step):
 *
 *   Lagrangian form  y = (q, q'),  M(q, q', t) q'' = f(q, q', t)
 *                    (with constraints the saddle-point system of qdot/mech.h)
 *   canonical form   y = (q, p),   p = M q' + b,  q' = M^-1 (p - b),
 *                    dp/dt = dL/dq + Q - dD/dq'   (= -dH/dq + extra; used by
 *                    the Gauss-Legendre and splitting methods, so that they
 *                    are symplectic also for a non-separable H)
 *   speeds form      y = (q, u),   q' = W u + w,  M_u u' = f_u  (qdot/speeds.h:
 *                    the constraints eliminated, no multipliers)
 *
 * The methods: explicit Runge-Kutta pairs with step control and dense output
 * (Dormand-Prince 5(4), DOP853 8(5,3)), implicit Gauss-Legendre collocation
 * with s = 1, 2, 3 stages (orders 2, 4, 6; symplectic), Stormer-Verlet and
 * Yoshida's compositions of it (orders 4, 6, 8; only for H = T(p) + V(q)), and
 * BDF (SUNDIALS CVODE) for stiff systems.  docs/design.md (simulation) has
 * the details.
 */
#ifndef QDOT_SIM_H
#define QDOT_SIM_H

#include <stdbool.h>
#include <stddef.h>
#include "expr.h"
#include "json.h"
#include "mech.h"
#include "model.h"
#include "speeds.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum qd_sim_method {
    QD_SIM_DOPRI5,
    QD_SIM_DOP853,
    QD_SIM_GL2,       /* Gauss-Legendre, 1 stage (implicit midpoint), order 2 */
    QD_SIM_GL4,       /* 2 stages, order 4 */
    QD_SIM_GL6,       /* 3 stages, order 6 */
    QD_SIM_VERLET,    /* Stormer-Verlet, order 2 */
    QD_SIM_YOSHIDA4,  /* Yoshida compositions of Verlet, orders 4, 6, 8 */
    QD_SIM_YOSHIDA6,
    QD_SIM_YOSHIDA8,
    QD_SIM_BDF,       /* CVODE, variable-order BDF */
    QD_SIM_TAYLOR,    /* Taylor series by automatic differentiation, order from the
                         tolerance (Jorba and Zou 2005): docs/design.md */
    QD_SIM_METHOD_COUNT
} qd_sim_method;

QD_API const char *qd_sim_method_name(qd_sim_method m);            /* "dop853" */
QD_API bool qd_sim_method_from_name(const char *name, qd_sim_method *m);
QD_API int qd_sim_method_order(qd_sim_method m);                   /* nominal order (BDF: 5) */
QD_API bool qd_sim_method_adaptive(qd_sim_method m);               /* step size control */

typedef struct qd_sim qd_sim;

/* Thread safety.  Building a qd_sim (qd_sim_new, qd_sim_add_output,
 * qd_sim_add_event, qd_sim_set_native) and qd_sim_compile happen on one
 * thread.  After qd_sim_compile the qd_sim is immutable: any number of
 * threads may run it at once with qd_sim_run_with, each passing its own
 * context (messages) and getting its own workspace; the model, e and the
 * context the qd_sim was made with are only read.  qd_sim_run is the
 * one-thread convenience: it compiles when needed and records the
 * per-constraint residuals in s (qd_sim_constraint_error). */

/* Compile the equations e of model m (e from qd_eom_derive, without
 * eliminated coordinates; parameters at the model's values, so apply --set
 * to the model first).  e and m must outlive the qd_sim.  NULL on failure,
 * reason in ctx.
 *
 * The model's unilateral contacts (`impact NAME: GAP >= 0 restitution E`)
 * become internal events on GAP(q, t): when GAP reaches 0 while decreasing
 * (located as the events are), Newton's law of restitution is applied with
 * the ordinary constraints held (Desloge ch. 57, ch. 61; Byerly ch. III):
 * M (q'+ - q'-) = A^T Lambda, A q'+ + a0 = 0, dGAP/dt after = -E dGAP/dt
 * before; every method then restarts from the new velocities.  A
 * restitution outside [0, 1], a gap with velocities or one that does not
 * depend on the coordinates is QD_ERR_ARG here; a gap negative at t0 is
 * QD_ERR_ARG from qd_sim_run.  docs/design.md, "Impacts in simulation". */
QD_API qd_sim *qd_sim_new(qd_ctx *ctx, const qd_model *m, const qd_eom *e);

/* Compile the Hamilton's equations of a model given by H (`momenta`,
 * `H = ...`) directly, y = (q, p):
 *
 *     q' = dH/dp,   p' = -dH/dq + Q - dD/dq'  (D at q' = dH/dp),
 *
 * which need no Lagrangian, so H need not be regular (d^2H/dp^2 may be
 * singular: H = p x, H = c |p|).  Every method integrates (q, p); the
 * columns are those of qd_sim_columns, the momenta under their names in
 * `momenta`, the energy H.  Outputs and events are expressions in q, the
 * momenta, the velocities (replaced by dH/dp), t and the parameters.  m
 * must outlive the qd_sim; NULL on failure (a model not given by H,
 * constraints), reason in ctx. */
QD_API qd_sim *qd_sim_new_hamilton(qd_ctx *ctx, const qd_model *m);
/* (A model given by H with `impact`s is refused: the impact law needs M.) */

/* Compile a model's equations in generalized speeds e (qd_speeds_derive),
 * y = (q, u), n + m numbers:
 *
 *     q' = kin(q, u, t) = W u + w,     M_u u' = f_u,
 *
 * the constraints eliminated (every Pfaffian row holds for every u, so the
 * motion keeps it to round-off; a holonomic one is kept in its velocity
 * form and the positions are projected back onto phi = 0 after each step
 * unless opts.no_project).  Methods: dopri5, dop853, gl2, gl4, gl6 (the
 * collocation is not symplectic here: (q, u) are not canonical) and bdf;
 * verlet and yoshida* are QD_ERR_ARG from qd_sim_run.  The columns are t,
 * the coordinates, the speeds under their names, the velocities q' (name',
 * from the kinematics), energy (h from the model's Lagrangian at those q'),
 * res_NAME per constraint, then the outputs.  Outputs and events are
 * expressions in q, q', t and the parameters (a speed stands for its
 * definition).  Initial values: opts.q0 and opts.u0, or (u0 NULL) the
 * speeds of opts.qd0 by their definitions.  Multipliers are not computed:
 * an output using one fails to compile.  A model with `impact`s is
 * QD_ERR_ARG.  e and m must outlive the qd_sim; NULL on failure, reason in
 * ctx. */
QD_API qd_sim *qd_sim_new_speeds(qd_ctx *ctx, const qd_model *m, const qd_speeds_eom *e);
QD_API void qd_sim_free(qd_sim *s);

/* Extra output columns: an expression in the coordinates, velocities, t and
 * the parameters, under the column name `name` (copied).  Before the first
 * qd_sim_run. */
QD_API qd_status qd_sim_add_output(qd_sim *s, const char *name, const qd_expr *x);

/* Inputs (`inputs F, ...` in the model; Lagrangian form only: a model in
 * speeds or given by H with inputs is refused by its qd_sim_new_*).  Each
 * input the equations (or an output) use needs one source before the
 * first qd_sim_run, else the run is QD_ERR_ARG ("input F is used but not
 * supplied"); giving another replaces it.  QD_ERR_ARG for a name that is
 * not an input of the model, or after qd_sim_compile.
 *
 *   expression  u = x(q, q', t, parameters): a feedback law or a signal
 *               (x may not use the inputs); compiled with the system.
 *   table       n >= 2 samples (t[i], v[i]), t strictly increasing,
 *               interpolated linearly between them (copied).  The run's
 *               [t0, t_end] must lie inside [t[0], t[n-1]]: QD_ERR_ARG
 *               otherwise, from qd_sim_run.
 *   callback    fn(data, t, x) with x = (q, q') (2n numbers, the
 *               coordinates then the velocities, in the equations' order);
 *               called at every evaluation of the right-hand side (so it
 *               must be a function of its arguments, and thread-safe when
 *               runs share the qd_sim).  A value that is not finite (NaN,
 *               an infinity) is the callback's failure: the run calls it
 *               no more and ends with QD_ERR_NUMERIC ("input F is not
 *               finite at t = ..."). */
typedef double (*qd_sim_input_fn)(void *data, double t, const double *x);
/* The check qd_sim_run makes before a run from t0 to t_end: every input
 * used has a source and every table covers the span; QD_ERR_ARG naming the
 * input otherwise (recorded in s's context). */
QD_API qd_status qd_sim_inputs_ready(qd_sim *s, double t0, double t_end);
QD_API qd_status qd_sim_input_expr(qd_sim *s, const char *name, const qd_expr *x);
QD_API qd_status qd_sim_input_table(qd_sim *s, const char *name, size_t n, const double *t,
                                    const double *v);
/* Input name's table read from text[0, len), the text of a CSV file: rows
 * "t,value" (blanks around the numbers and a CR before the newline taken;
 * blank lines skipped; a first line that is not two numbers is a header),
 * then qd_sim_input_table (times increasing, two rows at least, linear
 * interpolation).  *bad_line the 1-based line that is not a row, else 0.
 * QD_ERR_ARG ("line N: expected \"t,value\"", or qd_sim_input_table's
 * error), QD_ERR_NOMEM. */
QD_API qd_status qd_sim_input_table_read(qd_sim *s, const char *name, const char *text,
                                         size_t len, size_t *bad_line);
QD_API qd_status qd_sim_input_callback(qd_sim *s, const char *name, qd_sim_input_fn fn,
                                       void *data);

/* An event: the times where g(q, q', t) crosses zero (in either direction)
 * and every guard expression is > 0 there, located to round-off (dense
 * output, then the method's own step to the root).  stop: end the run at
 * the first such time.  Before the first qd_sim_run. */
QD_API qd_status qd_sim_add_event(qd_sim *s, const qd_expr *g, size_t nguard,
                           const qd_expr *const *guard, bool stop);

/* A compiled right-hand side for the Lagrangian form, y = (q, q'),
 * dydt = (q', q''), par the parameters in model order, nonzero when M is
 * singular there (qdot/codegen.h's P_rhs, loaded with qd_native_load).
 * Used instead of the qd_prog programs by the methods that integrate
 * (q, q'); NULL returns to them. */
typedef int (*qd_sim_native_rhs)(double t, const double *y, const double *par, double *dydt);
QD_API void qd_sim_set_native(qd_sim *s, qd_sim_native_rhs rhs);

/* The taylor method's recurrences (the Taylor mode of the compiled
 * programs, orders >= 1, in double) as generated C, compiled with $CC (else
 * cc) into cache_dir (NULL: qd_native_load's default) or reused from
 * there, dlopened, and used by every later QD_SIM_TAYLOR run at precision
 * 64 (80 and 128 stay interpreted).  The same operations in the same order
 * as the interpreter: the same results to the bit.  The object is the
 * qd_sim's (closed by qd_sim_free) and serves every tolerance.  *cached (may
 * be NULL): the object was already in the cache.  QD_ERR_UNSUPPORTED
 * (reason recorded) when no compiler runs, compilation fails or the cache
 * is not the user's alone (qdot/codegen.h); the runs
 * then stay interpreted.  Before qd_sim_compile. */
QD_API qd_status qd_sim_load_native_taylor(qd_sim *s, const char *cache_dir, bool *cached);

/* What the system is (known after qd_sim_new). */
QD_API size_t qd_sim_ndof(const qd_sim *s);
QD_API size_t qd_sim_ncon(const qd_sim *s);
QD_API size_t qd_sim_nspeeds(const qd_sim *s);   /* m of qd_sim_new_speeds, else 0 */
/* The events added by qd_sim_add_event (their indices 0 .. nevents-1 in a
 * sink's rows); the contacts' impacts and friction switches not counted. */
QD_API size_t qd_sim_nevents(const qd_sim *s);
QD_API bool qd_sim_canonical(const qd_sim *s);   /* (q, p) form available */
QD_API bool qd_sim_separable(const qd_sim *s);   /* H = T(p) + V(q), p-free forces */
QD_API bool qd_sim_conservative(const qd_sim *s);/* no t in L, no forces, no dissipation */
/* dop853 for tolerance runs; gl4 with a fixed step for unconstrained
 * conservative systems, dop853 otherwise. */
QD_API qd_sim_method qd_sim_default_method(const qd_sim *s, bool fixed_step);

#define QD_SIM_MAX_STEPS ((size_t)100000000) /* 1e8: the default of max_steps */

/* An option refused (dt, max_steps) is recorded with subject
 * QD_SUBJECT_NONE and name the field's name ("dt"): the message does not
 * spell the option, so each caller adds its own (the CLI's --dt, Python's
 * argument dt). */
typedef struct qd_sim_opts {
    qd_sim_method method;
    double t0, t_end;
    /* Fixed-step methods: the step (required).  Adaptive methods: the output
     * grid (0: a row at every accepted step), unless fixed is set. */
    double dt;
    bool fixed;          /* dopri5/dop853 with the constant step dt, no control */
    double rtol, atol;   /* adaptive methods; 0 gives 1e-10, 1e-12 */
    bool no_project;     /* constrained systems: skip the projection */
    /* The most steps a run may take, 0 for QD_SIM_MAX_STEPS.  A fixed step
     * that needs more steps from t0 to t_end (or an output grid dt with
     * more rows) is refused before the run (QD_ERR_ARG, naming the count);
     * an adaptive run that reaches it stops with QD_ERR_NUMERIC. */
    size_t max_steps;
    const double *q0, *qd0; /* n initial coordinates and velocities */
    /* n flags (may be NULL): the velocities of qd0 the caller gave (the
     * CLI's --initial), which the start of a constrained run keeps: the
     * others are solved from the velocity constraints A q' + a0 = 0 (the
     * least change of them; which ones changed: stats.initial_solved and
     * qd_sim_initial_solved), and a constraint that only given velocities
     * enter and that they violate is refused (QD_ERR_ARG, naming it and
     * its residual; subject name "initial").  NULL or none set: every
     * velocity is moved the least (the projection of qd0). */
    const bool *qd0_given;
    /* A system made from H (qd_sim_new_hamilton): n initial momenta, or
     * NULL to find them from qd0 (dH/dp = q', solved by Newton's method:
     * QD_ERR_SINGULAR when d^2H/dp^2 is singular, as for H = p x). */
    const double *p0;
    /* A system in speeds (qd_sim_new_speeds): m initial speeds, or NULL
     * for the speeds of qd0 (u = A qd0 + b, after qd0 is projected onto
     * the constraints). */
    const double *u0;
    /* Values of the model's parameters in model order; NULL: the model's
     * own.  Every method and the native right-hand side use them, so one
     * compiled qd_sim serves runs with different parameters (qdot/sweep.h);
     * the restitutions of `impact`s keep the values the qd_sim was made
     * with (they are numbers fixed at qd_sim_new). */
    const double *par;
    /* The Taylor method's arithmetic: 0 or 64 double, 80 long double, 128
     * __float128 (state, time and coefficients; issue 22). */
    int precision;
    /* The output spacing, for every method (issue 33): rows at t0 + k every
     * (and t0, the events, the end) from the dense output (the method's
     * own, else cubic Hermite), whatever the steps are; 0: as dt says
     * (an adaptive method's dt is its output grid, a fixed step's rows are
     * its steps).  A grid with more rows than max_steps is refused. */
    double every;
    /* Machine code for the compiled programs (qd_prog_jit): QD_SIM_JIT_AUTO
     * (0) once the run has interpreted about as much work as compiling
     * costs (QD_SIM_JIT_WORK instruction evaluations: short runs never
     * compile), QD_SIM_JIT_ON from the start, QD_SIM_JIT_OFF never.  The
     * numbers are the same bit for bit; without the JIT module (a build
     * without LLVM) the run is interpreted. */
    int jit;
    /* Called after every step with its time (may be NULL): a progress bar,
     * ^C.  A nonzero return stops the run there as the row callback's does
     * (QD_STOP_CALLBACK): the rows written are whole.  A run whose rows are
     * sparse (an output grid --dt, a crawl near a singular point) is then
     * still seen and stopped between its rows. */
    int (*progress)(void *data, double t);
    void *progress_data;
} qd_sim_opts;

enum { QD_SIM_JIT_AUTO = 0, QD_SIM_JIT_ON = 1, QD_SIM_JIT_OFF = 2 };
/* Instructions evaluated before AUTO compiles: about the 0.1 s that LLVM
 * takes to load and compile a 20-link pendulum's programs, interpreted. */
#define QD_SIM_JIT_WORK 50000000.0

/* Why a run stopped, as data (issue 31): the code, the time and the
 * quantity that decided it; qd_stop_str renders the code in English, and
 * the context's message says the rest (the cause, what to change).
 * value: the step h for QD_STOP_STEP_UNDERFLOW, QD_STOP_STEP_COLLAPSE and
 * QD_STOP_NO_CONVERGENCE,
 * the residual for QD_STOP_PROJECTION, the offending number (inf, NaN or the
 * energy) for QD_STOP_NONFINITE, the step limit for QD_STOP_STEP_LIMIT, the
 * event's index (in the order added) for QD_STOP_EVENT, the impact's for
 * QD_STOP_CONTACT; NaN where none. */
typedef enum qd_stop_code {
    QD_STOP_NONE = 0,        /* not run */
    QD_STOP_END,             /* reached t_end */
    QD_STOP_EVENT,           /* a terminal event (qd_sim_add_event stop) */
    QD_STOP_CONTACT,         /* ended in contact (qd_sim_stats in_contact) */
    QD_STOP_CALLBACK,        /* the row callback returned nonzero */
    QD_STOP_REFUSED,         /* refused before the first step (options, initial state) */
    QD_STOP_STEP_UNDERFLOW,  /* the adaptive step fell below round-off */
    QD_STOP_NO_CONVERGENCE,  /* an implicit stage's Newton iteration, or the initial momenta */
    QD_STOP_SOLVER_FAILURE,  /* CVODE failed otherwise */
    QD_STOP_STEP_LIMIT,      /* more steps than opts.max_steps */
    QD_STOP_SINGULAR,        /* a singular mass matrix or constrained/impact system */
    QD_STOP_PROJECTION,      /* the projection onto the constraints failed */
    QD_STOP_NONFINITE,       /* a state, energy, input or output not finite */
    QD_STOP_PAINLEVE,        /* friction: no or several consistent stick/slip modes */
    QD_STOP_STEP_COLLAPSE,   /* the adaptive step shrank so far that max_steps cannot reach
                              * t_end at its pace (a singular point: it crawls, not underflows) */
    QD_STOP_FAILURE          /* another failure: the status and message say which */
} qd_stop_code;

typedef struct qd_sim_stop {
    qd_stop_code code;
    double t;     /* when (NaN for QD_STOP_NONE and QD_STOP_REFUSED) */
    double value; /* the quantity above, or NaN */
} qd_sim_stop;

/* "reached the end time", "step size underflow", ...; "unknown" outside the enum. */
QD_API const char *qd_stop_str(qd_stop_code code);
/* A run that stopped for code ended as asked (END, EVENT, CONTACT), not by failing. */
QD_API bool qd_stop_ok(qd_stop_code code);

typedef struct qd_sim_stats {
    size_t steps, evals, rejected;
    /* max |E(t) - E(0)| / max(|E(0)|, max T) over the rows the run made
     * (passed to the sink, or not: at t0, the output grid or every step,
     * the events, the end), so over what a caller gets: a grid row between
     * steps carries the dense output's error too.  energy_error_steps (at
     * the end of the struct) is the same at the integrator's accepted steps. */
    double energy_error_max;
    double constraint_error_max; /* max |residual| of every constraint (and of
                                    the holonomic ones differentiated) */
    double E0;                   /* the Jacobi integral h = sum q' dL/dq' - L at t0 */
    size_t events;
    double t;                    /* where the run ended */
    /* Unilateral contacts (the model's `impact NAME: GAP >= 0 restitution
     * E`): the impacts applied and the energy h they took (E < 1), which
     * energy_error_max does not count (it measures |E(t) - (E(0) - lost)|).
     * in_contact: the run ended in contact with impact `contact` (its index
     * in the model's impacts) at t, before t_end: its rebounds fell below
     * what the tolerance resolves (rate below sqrt(rtol) times its fastest
     * approach, E = 0 included, with the motion pressing the gap shut
     * after a plastic impact; or a landing inside the first step after the
     * rebound that a step 16^6 times shorter still misses).  The impact is
     * then plastic: the gap's rate is 0 after it.  at_rest: nothing moves
     * after it (T after <= rtol T before; the ball on the floor); else the
     * bodies would move on in sustained contact (a rod pivoting on a
     * ledge, a ball sliding along the floor), which is not simulated.
     * chattering: the flight
     * times were shrinking geometrically (infinitely many impacts in a
     * finite time, the bouncing ball with E < 1), and t is the sum of the
     * series, the accumulation time; else t is the last impact's time. */
    size_t impacts;
    double impact_energy_lost;
    bool in_contact, at_rest, chattering;
    size_t contact;
    /* Coulomb friction (the model's contacts, qdot/model.h): the stick/slip
     * switches, the energy friction dissipated (integrated with the state:
     * the power mu_k |N| |v_slip| of each slipping contact), and
     * max_t |E(t) + dissipated(t) - surface_work(t) - E(0)| / max(|E(0)|,
     * max T), which energy_error_max then equals.  surface_work (at the
     * end of the run) is the work the constraints' own motion did on the
     * system, the integral of -sum_c lambda_c a0_c over every constraint
     * A q' + a0 = 0 (a belt under a sticking block, the part of a slipping
     * one's slip velocity that is not from q'); 0 when no constraint has
     * an a0.  The balance holds to the tolerance for L without explicit t
     * and without forces or a dissipation function. */
    size_t transitions;
    double friction_dissipated;
    double energy_balance_error;
    double surface_work;
    /* A constrained system: how far the start's projection onto the
     * constraints moved the initial state given, |q - q0| and |q' - q'0|
     * (Euclidean; the velocities 0 for a system in speeds), so that a
     * caller can say so when it is not small (the CLI prints a note). */
    double initial_moved_q, initial_moved_qd;
    /* With qd0_given: how many velocities not given were solved from the
     * constraints (changed by the start); which: qd_sim_initial_solved. */
    size_t initial_solved;
    /* Event functions that oscillate faster than the event search resolves
     * (docs/design.md, "Events"): the steps where one turned at consecutive
     * samples of the finest sampling (64 per step), the first such step's
     * start time and event index (in the order added; then the impacts',
     * then friction's), and the widest sample spacing among those steps:
     * crossings closer together than it may have been missed there.  0
     * when every step was resolved. */
    size_t events_unresolved;
    double events_unresolved_t, events_unresolved_spacing;
    size_t events_unresolved_event;
    double energy_error_steps;   /* energy_error_max at the accepted steps */
    bool jit;                    /* the run ended on machine code (qd_sim_opts.jit) */
    qd_sim_stop stop;            /* why the run ended: filled by every run, failed or not */
} qd_sim_stats;

/* The worst residual of constraint c (in the model's order of the
 * constraints kept by the equations) over the last run: |phi| for a
 * holonomic one and its velocity form, |A q' + a0| for a Pfaffian one; 0 for
 * c out of range.  stats.constraint_error_max is the largest of these. */
QD_API double qd_sim_constraint_error(const qd_sim *s, size_t c);
/* Whether velocity j (the equations' order) was solved from the velocity
 * constraints at the start of the last run, which kept the velocities
 * given (qd_sim_opts.qd0_given); false for j out of range. */
QD_API bool qd_sim_initial_solved(const qd_sim *s, size_t j);

/* The columns of a run with method: t, the coordinates, the speeds (a
 * system in speeds), the velocities (name'), the momenta (p_name,
 * canonical-form methods only), energy (the Jacobi integral h, = T + V for
 * natural systems), one residual per constraint (res_NAME), then the
 * outputs.  names may be NULL; returns the
 * count; names[i] are owned by s. */
QD_API size_t qd_sim_columns(const qd_sim *s, qd_sim_method method, const char **names, size_t cap);

/* QD_OK when opts are valid on their own: method, times, the step, the
 * step count against max_steps, tolerances (t0, t_end and dt finite,
 * t_end > t0, dt >= 0); else QD_ERR_ARG with the
 * reason in ctx.  qd_sim_run checks the same, then whether the method can
 * take the system, before it starts. */
QD_API qd_status qd_sim_check_opts(qd_ctx *ctx, const qd_sim_opts *opts);

/* Compile the outputs and events (after the last add): from here on s is
 * immutable.  Idempotent.  A failure is recorded in s's context. */
QD_API qd_status qd_sim_compile(qd_sim *s);

/* qd_sim_compile, then every compiled program of s as machine code in this
 * process (qd_prog_jit, LLVM's ORC JIT): the runs give the interpreter's
 * numbers bit for bit, faster.  QD_ERR_UNSUPPORTED, saying why in s's
 * context, when the JIT module is missing or fails: the programs not
 * compiled stay interpreted, and s still runs. */
QD_API qd_status qd_sim_jit(qd_sim *s);
QD_API bool qd_sim_compiled(const qd_sim *s);

/* Receives every row (event -1: a sample; else the index of the event in
 * the order added).  Returning a positive value ends the run early
 * (QD_OK); a negative one is the sink's failure (it could not keep the
 * row: a write error, an exception in a binding): the run ends there with
 * QD_ERR_ARG ("the row callback reported a failure at t = ...").  An
 * impact of the model's contact i gives two rows with event nev + i (nev
 * the events added): the state just before it and the state just after
 * (ending in contact: the state at the run's end time).  Contacts whose
 * gaps close at the same instant (to round-off) are struck together, in
 * one law: one pair of rows, under the index of the one located first. */
typedef int (*qd_sim_sink)(void *data, int event, const double *row);

/* Integrate from opts->t0 to opts->t_end.  Rows at t0, at the output grid
 * (or every step) and at the end, and at every event.  final (may be NULL)
 * receives the last row.  Failures (QD_ERR_NUMERIC, QD_ERR_SINGULAR, with
 * the time in the message): step size underflow, no convergence of the
 * Gauss-Legendre iteration, a mass matrix singular at a state, a constraint
 * that projection cannot satisfy, and, for every method, a state (or its
 * energy) that is not finite: "non-finite state at t = ..." with the cause
 * (an overflow, a division by zero, NaN from the right-hand side), so no
 * row of inf or NaN is ever passed on.  A non-separable H for
 * verlet/yoshida, a missing step, a time or step that is not finite, an
 * initial state that is not finite or a method that cannot take the
 * system is QD_ERR_ARG. */
QD_API qd_status qd_sim_run(qd_sim *s, const qd_sim_opts *opts, qd_sim_sink sink, void *data,
                     qd_sim_stats *stats, double *final);

/* qd_sim_run on a compiled s (QD_ERR_ARG if not compiled) that other
 * threads may be running at the same time; failures are recorded in ctx,
 * which is this thread's own.  The sink runs on the calling thread. */
QD_API qd_status qd_sim_run_with(qd_ctx *ctx, const qd_sim *s, const qd_sim_opts *opts,
                                 qd_sim_sink sink, void *data, qd_sim_stats *stats,
                                 double *final);

/* ---- Coulomb friction (issue 18) -------------------------------------------
 *
 * A model with friction contacts (`constraint ... friction MU normal N`,
 * `rolls ... friction MU`) is integrated as a hybrid system: each contact
 * sticks (its constraints hold, their multipliers the friction force) or
 * slips (its constraints dropped, the force -mu_k |N| v/|v| against the slip
 * velocity v).  A sticking contact slips when |lambda| - mu_s |N| rises
 * through 0; a slipping one stops when v . v_entry falls through 0, and
 * sticks there if the static law holds (else it slips the other way).  The
 * switches are events located to round-off; at each the modes of every
 * contact are chosen again so that each one's law holds (stick: |lambda| <=
 * mu_s |N|; slip from rest: accelerating the way it slips; a normal
 * multiplier of the sign assumed), preferring sticking; when no choice, or
 * more than one, is consistent the run stops with QD_ERR_NUMERIC
 * ("Painleve paradox at t = ...").  Adaptive methods (dopri5, dop853, bdf)
 * only: QD_ERR_ARG for the fixed-step symplectic ones, a model in speeds or
 * given by H, or one with impacts.  The columns gain slip_NAME (the slip
 * velocity; its norm for two directions) and mode_NAME (0 stick, 1 slip)
 * per contact, then dissipated, before the outputs.  A switch gives a row
 * (after it) with event index nev + nimp + contact (nev the events added,
 * nimp the model's impacts). */
typedef enum qd_contact_mode { QD_CONTACT_STICK, QD_CONTACT_SLIP } qd_contact_mode;

typedef struct qd_sim_transition {
    double t;
    size_t contact;            /* the model's contact index */
    qd_contact_mode from, to;
} qd_sim_transition;

QD_API size_t qd_sim_ncontacts(const qd_sim *s);
/* The switches of the last qd_sim_run on s (not qd_sim_run_with, whose
 * switches reach its sink as rows), in time order; *n their count.  Owned
 * by s, valid until its next run. */
QD_API const qd_sim_transition *qd_sim_transitions(const qd_sim *s, size_t *n);

/* ---- the summary of a run (src/sim/summary.c) ------------------------------
 *
 * What `qdot simulate` reports after a run, for any caller: the library's
 * words and numbers, printed from plain data.  r->s is the system after its
 * qd_sim_run (the per-constraint residuals and the friction switches are
 * that run's), r->opts the options it ran with (method, t0), r->stats its
 * statistics, r->final its last row (qd_sim_columns(s, opts->method)
 * numbers; NULL: no "final" in JSON) and r->wall the seconds it took,
 * measured by the caller. */
typedef struct qd_sim_report {
    const qd_sim *s;
    const qd_sim_opts *opts;
    const qd_sim_stats *stats;
    const double *final;
    double wall;
} qd_sim_report;

/* The machine name of a stop code, for programs: "none", "end", "event",
 * "contact", "callback", "refused", "step_underflow", "no_convergence",
 * "solver_failure", "step_limit", "singular", "projection", "nonfinite",
 * "painleve", "step_collapse", "failure" (the QD_STOP_ names in lower case); "unknown"
 * outside the enum.  qd_stop_str is the English for a reader. */
QD_API const char *qd_stop_name(qd_stop_code code);
/* The stop record as one JSON object (the value of a "stop" key, or an
 * array's element): {"code": qd_stop_name, "reason": qd_stop_str, "ok":
 * qd_stop_ok, "t", "value"}, null where a number is not finite.  The one
 * shape of `simulate`'s and `sweep`'s records and Python's Result.stop. */
QD_API void qd_sim_stop_json(qd_json *j, const qd_sim_stop *stop);

/* The note on the initial state's projection (stats initial_moved_q,
 * initial_moved_qd) is printed when either moved by more than this: far
 * off the constraints, not rounding. */
#define QD_SIM_MOVED_NOTE 1e-4

/* The summary of r as text appended to out, every line started by prefix
 * (NULL: none; the CLI's "qdot: simulate: "):
 *
 *   METHOD, t = T0..T: N steps, N evaluations, N rejected, W s; energy error E
 *     over the rows written (E at the steps), constraint error C[ (not
 *     conserved: forces, damping or t in L)]
 *   stopped early: REASON at t = T       a run that did not end as asked
 *                                        (qd_stop_ok false; qd_stop_str)
 *   N events                             when there were any
 *   note: event K oscillates faster ...  events_unresolved (docs/design.md)
 *   note: the initial state was off the constraints ... (QD_SIM_MOVED_NOTE)
 *   N impacts, energy lost E             a model with impacts, and where the
 *   impact 'NAME': ... the run ends there  run ended in contact
 *   N stick/slip transitions, energy dissipated by friction D[, work done
 *     by moving surfaces W], energy balance error B   a model with friction
 *
 * times with %g (the end of a stop line with every digit), errors with
 * %.3g, energies with %.6g.  QD_ERR_NOMEM when out ran out. */
QD_API qd_status qd_sim_summary_print(const qd_sim_report *r, const char *prefix, qd_buf *out);

/* The summary of r as members of the JSON object open in j (the caller's
 * document): "method", "speeds" (integrated in the model's speeds),
 * "steps", "evaluations", "rejected", "wall_s", "energy_error_max" (over
 * the rows), "energy_error_steps", "constraint_error_max",
 * "constraint_errors" (constraint name to its worst residual), "events";
 * "events_unresolved" ({"steps", "event" (1-based), "t", "spacing"}) when
 * some were; "stop" ({"code": qd_stop_name, "reason": qd_stop_str, "ok":
 * qd_stop_ok, "t", "value": stats.stop's, null where not finite}) unless
 * the run reached t_end; with impacts "impacts", "impact_energy_lost" and
 * "contact" (null, or {"impact", "t", "chattering", "at_rest"}); with
 * friction "friction_dissipated", "energy_balance_error", "surface_work"
 * and "transitions" ([{"t", "contact", "from", "to"}], "stick"/"slip");
 * "final" (column name to the last row's value) when r->final is given.
 * QD_ERR_NUMERIC when a number was not finite (j is then failed:
 * qd_json_ok), QD_ERR_NOMEM when memory ran out. */
QD_API qd_status qd_sim_summary_json(qd_json *j, const qd_sim_report *r);

/* ---- the rows as `qdot simulate` writes them (src/sim/rows.c) ----------- */

/* Whether a run of s gives its rows an event column (the sink's event >= 0
 * for some rows): s has events (qd_sim_add_event, stops included), its
 * model impacts, or friction contacts.  Written as event + 1, 0 for a row
 * of the grid. */
QD_API bool qd_sim_event_column(const qd_sim *s);
/* "columns": the names qd_sim_columns gives for method, and "event" after
 * them when qd_sim_event_column: the key and array into j's open object.
 * QD_ERR_NOMEM when memory ran out (j's buffer failed), QD_ERR_NUMERIC
 * when j refused a number, QD_ERR_ARG when j was already too deep. */
QD_API qd_status qd_sim_columns_json(qd_json *j, const qd_sim *s, qd_sim_method method);
/* A run drawn and not written: an adaptive method's rows are its steps,
 * which can span a swing, so unless o has an output grid (dt > 0) or a
 * fixed step its dense output is sampled at rows points, dt = (t_end -
 * t0) / rows.  Other options are left as they are. */
QD_API void qd_sim_opts_sample(qd_sim_opts *o, size_t rows);
/* "plot": the picture of a run (qd_plot_run) written to file: {"file",
 * "panels": [{"x0", "x1", "y0", "y1"}, ...]}, each panel's axis ranges
 * (range[4 g + 0..3], npanels panels, as qd_plot_ranges gives them), so a
 * caller can place more on the picture (a range not finite: QD_ERR_NUMERIC,
 * j failed).  QD_ERR_NOMEM and QD_ERR_ARG as above. */
QD_API qd_status qd_sim_plot_json(qd_json *j, const char *file, size_t npanels,
                                  const double *range);

/* ---- the rows written (src/sim/writer.c) -----------------------------------
 *
 * The CSV of a run as `qdot simulate` writes it: a header of the names
 * qd_sim_columns gives for the method, then ",event" when
 * qd_sim_event_column; a line a row, its numbers in qd_double_format
 * (shortest round trip), then event + 1 (0 for a row of the grid).  In
 * JSON a row is an array of the same numbers. */
QD_API qd_status qd_sim_csv_header(const qd_sim *s, qd_sim_method method, qd_buf *out);
/* Row (ncols numbers) as one CSV line appended to out, with the event
 * column when event_column.  QD_ERR_NOMEM when out ran out. */
QD_API qd_status qd_sim_csv_row(size_t ncols, const double *row, bool event_column, int event,
                                qd_buf *out);
/* Row as a JSON array, an element of the array open in j. */
QD_API qd_status qd_sim_json_row(qd_json *j, size_t ncols, const double *row, bool event_column,
                                 int event);

/* Bytes handed on by a writer: 0 when they were kept, nonzero when they
 * are lost (a full disk, a closed pipe). */
typedef int (*qd_sim_write_fn)(void *data, const char *bytes, size_t len);

/* A run's rows written as they come: qd_sim_run(s, opts,
 * qd_sim_writer_sink, &w, ...).  The caller fills the first fields, then
 * qd_sim_writer_init the rest.  The CSV header goes out with the first
 * row, so a run refused before it writes nothing.  A write that fails
 * ends the run as a sink's failure (qd_sim_run's QD_ERR_ARG) with failed
 * set; nothing more is written. */
typedef struct qd_sim_writer {
    qd_sim_write_fn write; /* CSV lines to write(data, ...), or NULL */
    void *data;
    qd_json *json;         /* else rows into the array open in json, or NULL: none */
    qd_sim_sink tap;       /* called with each row once written (a plot, a progress
                            * bar), its return the sink's; may be NULL */
    void *tap_data;
    /* the writer's (qd_sim_writer_init; read them, do not set them): */
    const qd_sim *s;
    qd_sim_method method;
    size_t ncols, rows;    /* the row's numbers; the rows written */
    bool event_column, header, failed;
    double last_t;         /* the time of the last row written (NaN before one) */
    qd_buf line;
} qd_sim_writer;

/* w's own fields for runs of s with method; the caller's are kept.  s
 * must outlive w.  QD_ERR_ARG for NULL. */
QD_API qd_status qd_sim_writer_init(qd_sim_writer *w, const qd_sim *s, qd_sim_method method);
/* The qd_sim_sink of w (data): the row written, then w->tap.  -1 (the
 * sink's failure) when w is NULL or the row could not be written. */
QD_API int qd_sim_writer_sink(void *w, int event, const double *row);
QD_API void qd_sim_writer_free(qd_sim_writer *w); /* its memory, not w; NULL is fine */

#ifdef __cplusplus
}
#endif

/* NULL (issue 30): a function of this header given NULL for a pointer it
 * needs does nothing and returns QD_ERR_ARG (recorded in ctx when ctx is
 * given), NULL, 0, false or NaN, as its return type has it; a void function
 * returns, and every _free accepts NULL. NULL is an accepted value, as
 * documented at the function, for: qd_sim_input_callback (data);
 * qd_sim_add_event (guard); qd_sim_load_native_taylor (cache_dir, cached);
 * qd_sim_columns (names); qd_sim_run (data, final, sink, stats);
 * qd_sim_run_with (data, final, sink, stats); qd_sim_summary_print
 * (prefix). An array whose count is 0 may be NULL. */
#endif

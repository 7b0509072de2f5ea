/*
 * qdot/lyapunov.h - Lyapunov characteristic exponents of a model's motion.
 *
 * The first-order system y' = F(t, y), y = (q, q'), with M(q, q', t) q'' =
 * f(q, q', t), is integrated together with k tangent vectors w_j of the
 * variational equations w' = J(t, y) w.  J is built from the SYMBOLIC
 * derivatives of the equations of motion, compiled once:
 *
 *     J = [ 0                          I                          ]
 *         [ M^-1 (df/dq - dM/dq q'')   M^-1 (df/dq' - dM/dq' q'') ]
 *
 * where (dM/dq q'') has column k dM/dq_k q''.  Every `renorm` time units
 * the tangent vectors are orthonormalized by a QR factorization (one vector:
 * Benettin's renormalization; k vectors: the Gram-Schmidt / QR method of
 * Benettin, Galgani, Giorgilli & Strelcyn 1980, Shimada & Nagashima 1979),
 * and lambda_j = (1/T) sum log |R_jj| over the averaging time T (after the
 * transient).  docs/design.md, "Lyapunov exponents".
 *
 * Thread safety: qd_lyap_new on one thread; afterwards a qd_lyap is
 * immutable and any number of threads may call qd_lyap_run on it at once,
 * each with its own context (as qd_sim_run_with).
 */
#ifndef QDOT_LYAPUNOV_H
#define QDOT_LYAPUNOV_H

#include <stddef.h>
#include "json.h"
#include "mech.h"
#include "model.h"
#include "sim.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct qd_lyap qd_lyap;

/* Build and compile the variational equations of the equations e of model
 * m (Lagrangian form, as qd_sim_new takes them: parameters at the model's
 * values unless a run gives opts->par).  e and m must outlive the qd_lyap.
 * NULL on failure, reason in ctx: constraints, `impact`s and `inputs` are
 * QD_ERR_ARG (the tangent map of a constrained or driven-from-outside
 * motion is not built). */
QD_API qd_lyap *qd_lyap_new(qd_ctx *ctx, const qd_model *m, const qd_eom *e);
QD_API void qd_lyap_free(qd_lyap *l);
/* n: degrees of freedom (the state has 2n numbers, so 1 <= nexp <= 2n). */
QD_API size_t qd_lyap_ndof(const qd_lyap *l);

typedef struct qd_lyap_opts {
    size_t nexp;          /* exponents wanted: 1 (largest, Benettin) .. 2n (spectrum by QR) */
    double renorm;        /* time between renormalizations (0: 1) */
    double transient;     /* time integrated before averaging starts (>= 0) */
    /* May be NULL: after each renormalization, done in [0, 1] (the time
     * integrated, of t_end - t0) and the time t; nonzero stops the run
     * (QD_ERR_ARG, "stopped at t = T"): a progress bar, or ^C from Python. */
    int (*progress)(void *data, double done, double t);
    void *data;           /* progress' */
} qd_lyap_opts;

/* What a run measured besides the exponents (qd_lyap_run_stats). */
typedef struct qd_lyap_stats {
    double t_avg;         /* the averaging time T = t_end - t0 - transient */
    size_t renorms;       /* renormalizations in the averaging time */
    /* The time average of tr J over the averaging time: the sum of all 2n
     * exponents (Liouville: phase volume grows as exp(integral of tr J)).
     * 0 for a Hamiltonian system, -c/m for a damped oscillator. */
    double trace_mean;
    size_t steps, evals, rejected;
} qd_lyap_stats;

/* Integrate from opts->t0 (opts->q0, opts->qd0, opts->par) to opts->t_end
 * with opts->method (dopri5 or dop853; dop853 is the default method of the
 * CLI), rtol and atol (0: 1e-10, 1e-12), fixed/dt as in a simulation;
 * exps receives lo->nexp exponents in descending order and err (may be
 * NULL) an error estimate for each: twice the largest deviation of the
 * running average from its final value over the last half of the
 * averaging time (for lambda(t) = lambda + c/t the deviation at T/2 is the
 * bias c/T itself; docs/design.md).  Failures: QD_ERR_ARG for bad options
 * (nexp out of range, renorm < 0, transient outside [0, t_end - t0),
 * a method other than dopri5/dop853), QD_ERR_NUMERIC (step size
 * underflow, a state outside the model's domain) and QD_ERR_SINGULAR (a
 * singular mass matrix), with the time in the message, in ctx. */
QD_API qd_status qd_lyap_run(qd_ctx *ctx, const qd_lyap *l, const qd_sim_opts *opts,
                             const qd_lyap_opts *lo, double *exps, double *err);
/* qd_lyap_run that also fills stats (may be NULL). */
QD_API qd_status qd_lyap_run_stats(qd_ctx *ctx, const qd_lyap *l, const qd_sim_opts *opts,
                                   const qd_lyap_opts *lo, double *exps, double *err,
                                   qd_lyap_stats *stats);

/* ---- the flow and its Jacobian ------------------------------------------------
 *
 * The same tangent system with 2n tangent vectors started at the identity and
 * never renormalized: at time t they are the columns of the flow Jacobian
 * Phi(t) = d y(t) / d y(t0), y = (q, q') (the state-transition matrix of the
 * variational equations; Britannica 1911 "Dynamics" sec. 9, seed 004: the
 * tangent flow behind Lagrange's bilinear invariant and Helmholtz's
 * reciprocal theorems).
 *
 * For a Hamiltonian system (no dissipation, no forces besides those of V and
 * U: qd_sim_conservative) Phi is carried to the canonical coordinates (q, p)
 * with the Jacobian of the Legendre map, Lambda = d(q, p)/d(q, q') =
 * [I 0; d^2L/dq'dq  d^2L/dq'dq'] (symbolic, compiled): Phi_c =
 * Lambda(y(t)) Phi Lambda(y(t0))^-1, which is symplectic, Phi_c^T J Phi_c = J
 * with J = [0 I; -I 0]; symplectic_error is max |Phi_c^T J Phi_c - J|.
 * det Phi = exp(integral of tr J dt) (Liouville): exp(-b t/m) for a damped
 * oscillator; in (q, q') it is det M(t0)/det M(t) for a conservative one.
 *
 * The multipliers are the eigenvalues of Phi (those of Phi_c are the same):
 * when t_end - t0 is a period of the orbit, Phi is the monodromy matrix and
 * they are its Floquet multipliers; an autonomous conservative system has
 * two equal to 1 (the flow direction and the energy), in a Jordan block when
 * the period changes with the energy.  closure is max |y(t_end) - y(t0)|:
 * how closely the run returned to its start.
 */
typedef struct qd_flow {
    size_t d;                 /* 2n */
    double *y;                /* d: the state at t_end */
    double *phi;              /* d*d row-major: d y(t_end) / d y(t0) in (q, q') */
    double det;               /* det phi */
    bool hamiltonian;         /* phi_c and symplectic_error were computed */
    double *phi_c;            /* d*d: in (q, p); NULL unless hamiltonian */
    double symplectic_error;  /* NaN unless hamiltonian */
    double *mult_re, *mult_im;/* d eigenvalues of phi */
    double closure;
    double trace_integral;    /* integral of tr J over the run (log det phi) */
    size_t steps, evals, rejected;
} qd_flow;

/* Called at every multiple of `every` after t0 and at t_end with the state
 * (d) and phi (d*d row-major); nonzero stops the run (QD_ERR_ARG, "stopped"). */
typedef int (*qd_flow_sink)(void *data, double t, const double *y, const double *phi);

typedef struct qd_flow_opts {
    double every;             /* > 0: sink at t0 + k every (and at t_end); 0: at t_end only */
    qd_flow_sink sink;        /* may be NULL */
    void *data;
} qd_flow_opts;

/* Integrate the state and its flow Jacobian from opts->t0 to opts->t_end
 * with dopri5 or dop853 (rtol, atol as qd_lyap_run; fixed/dt as in a
 * simulation); fo may be NULL.  *out is filled (qd_flow_free frees its
 * arrays, also after a failure).  Failures as qd_lyap_run's. */
QD_API qd_status qd_flow_run(qd_ctx *ctx, const qd_lyap *l, const qd_sim_opts *opts,
                             const qd_flow_opts *fo, qd_flow *out);
QD_API void qd_flow_free(qd_flow *f);

/* ---- the flow printed (src/lyap/render.c) -------------------------------- */

/* closure (max |y(t_end) - y(t0)|) above which a run over a period given
 * did not return to its start: the orbit is not periodic with that period
 * (qd_flow_print says so). */
#define QD_FLOW_CLOSURE_TOL 1e-6

/* The options of a flow run for a simulation's in: the same, with dop853
 * (and no fixed step) where in's method is not dopri5 or dop853, the two
 * pairs the tangent system runs with.  *out written; QD_ERR_ARG for NULL. */
QD_API qd_status qd_flow_sim_opts(const qd_sim_opts *in, qd_sim_opts *out);

/* The name of entry i of the flow's state y = (q, q') of e appended to out:
 * the coordinate's name for i < n, the velocity's (name') for n <= i < 2n.
 * QD_ERR_ARG for i >= 2n, QD_ERR_NOMEM when out ran out. */
QD_API qd_status qd_flow_state_name(const qd_eom *e, size_t i, qd_buf *out);

/* The name of column k of the flow's rows (qd_flow_sink's t, y, phi as one
 * row) appended to out: "t" (k = 0), the state's names (1 <= k <= d,
 * qd_flow_state_name), then the entries of phi column by column,
 * k = 1 + d + j d + i for d y_i/d y_j(t0), named "dYi/dYj0" ("dx/dx'0").
 * d = 2n; QD_ERR_ARG for k >= 1 + d + d^2, QD_ERR_NOMEM when out ran out. */
QD_API qd_status qd_flow_column_name(const qd_eom *e, size_t k, qd_buf *out);

/* The flow's rows as CSV (src/lyap/flow_rows.c; `qdot simulate
 * --variational columns`): the header of qd_flow_column_name's names,
 * then the row at t0 (the initial state, phi = I) and a row at every
 * t0 + k every and t_end (qd_flow_opts every), each t, y, then phi column
 * by column in qd_double_format, handed to write(data, ...).  every <= 0:
 * opts' own spacing (every, else dt), else 100 rows.  A flow run of l with opts as given (qd_flow_sim_opts
 * first); *out as qd_flow_run fills it.  A write that fails ends the run:
 * QD_ERR_IO, recorded in ctx; nothing more is written. */
QD_API qd_status qd_flow_run_csv(qd_ctx *ctx, const qd_lyap *l, const qd_eom *e,
                                 const qd_sim_opts *opts, double every, qd_sim_write_fn write,
                                 void *data, qd_flow *out);

/* f as text appended to out, every line started by prefix (NULL: none):
 *
 *   flow Jacobian d(q, q')(t_end)/d(q, q')(t0), det D (Liouville exp(int tr
 *     J) L)[, symplectic error in (q, p) S]
 *   one line of phi per row ("% .10g" each)
 *   Floquet multipliers: a+bi ...    (period > 0: phi is the monodromy matrix)
 *   eigenvalues: a+bi ... (give the period T for a periodic orbit)   (else)
 *   closure max |y(t0 + T) - y(t0)| = C[: the orbit is not periodic with
 *     this T]                        (period > 0; above QD_FLOW_CLOSURE_TOL)
 *
 * with 10 significant digits, S and C with 3.  period is t_end - t0 when the
 * run was over a period, else 0.  QD_ERR_ARG for a flow without its arrays,
 * QD_ERR_NOMEM when out ran out. */
QD_API qd_status qd_flow_print(const qd_flow *f, double period, const char *prefix,
                               qd_buf *out);

/* f as members of the JSON object open in j (the caller's document), the
 * flow run of equations e with method: "variational" ({"method", "state":
 * the state's names}), "flow_jacobian" (phi, rows), "flow_det",
 * "liouville_det" (exp of the integral of tr J), "hamiltonian",
 * "flow_jacobian_canonical" (phi_c, when hamiltonian), "symplectic_error"
 * (null unless hamiltonian), "multipliers" ([re, im] pairs), "period"
 * (null unless period > 0), "closure", and "monodromy" (phi, when period >
 * 0).  QD_ERR_ARG for a flow without its arrays or whose d is not 2 e->n,
 * QD_ERR_NUMERIC when a number was not finite (j is then failed),
 * QD_ERR_NOMEM when memory ran out. */
QD_API qd_status qd_flow_json(qd_json *j, const qd_flow *f, const qd_eom *e,
                              qd_sim_method method, double period);

/* ---- the exponents printed (src/lyap/print.c) ---------------------------- */

/* What a qd_lyap_run_stats measured, with the options it ran with, for
 * qd_lyap_print and qd_lyap_json. */
typedef struct qd_lyap_report {
    const qd_lyap_opts *opts;    /* the options used: nexp exponents, renorm, transient */
    size_t ndof;                 /* n (qd_lyap_ndof): the state has 2n numbers */
    const double *exps;          /* opts->nexp exponents, descending */
    const double *err;           /* opts->nexp error estimates (NaN: none), or NULL: none */
    const qd_lyap_stats *stats;  /* the run's averaging time, renormalizations, mean tr J */
    bool conservative;           /* the system is conservative (qd_sim_conservative) */
    qd_sim_method method;        /* the integrator used */
} qd_lyap_report;

/* exps[0] + ... + exps[k-1]: with all k = 2n exponents, the time average of
 * tr J (Liouville), 0 for a conservative system.  NaN for NULL exps with
 * k > 0. */
QD_API double qd_lyap_sum(size_t k, const double *exps);

/* r as text appended to out, one line per exponent, "lambda_J = % .6f" (a
 * value below 5e-7 in size as 0) followed by "  +- E" (E with 2
 * significant digits) or "  (no error estimate: fewer than 2
 * renormalizations in the last half)"; then "mean tr J = % .6f  (the sum of
 * all D exponents, Liouville[; -> 0 as T grows for a conservative
 * system])"; with all D = 2n exponents "sum       = % .6f" (qd_lyap_sum),
 * and for a conservative system "conservative: the exponents pair,
 * lambda_i + lambda_{D+1}-i = P1, P2, ..." (lambda_i + lambda_{D+1-i} for
 * i <= n, six decimals).  QD_ERR_ARG for a report without opts, stats or
 * exps, with ndof 0 or opts->nexp outside 1..2n; QD_ERR_NOMEM when out
 * ran out. */
QD_API qd_status qd_lyap_print(const qd_lyap_report *r, qd_buf *out);

/* r as one JSON object and a newline appended to out: "method" (its name),
 * "t_avg", "transient", "renorm" (1 where opts->renorm is 0: the time used),
 * "renormalizations", "exponents" (the array), "errors" (the array, null
 * where there is no estimate), "trace_mean", "sum" (only with all 2n
 * exponents) and "conservative".  Errors as qd_lyap_print's, and
 * QD_ERR_NUMERIC (nothing appended) when a number other than an error
 * estimate is not finite. */
QD_API qd_status qd_lyap_json(const qd_lyap_report *r, qd_buf *out);

/* ---- a Poincare surface of section (src/lyap/section.c) ---------------- */

typedef struct qd_poincare_opts {
    int event;     /* the section: this event of the run (qd_sim_add_event's order) */
    size_t want;   /* the run ends at the want-th crossing (> 0) */
    /* Every row of the run, crossing true at a crossing of the section
     * (else a sample or another event's row); nonzero ends the run (a
     * crossing's row still counted). */
    int (*sink)(void *data, const double *row, bool crossing);
    /* May be NULL: after each row, done in [0, 1] the larger of the
     * crossings found (of want) and the time used (of t_end - t0). */
    void (*progress)(void *data, double done, double t);
    void *data;    /* sink's and progress' */
} qd_poincare_opts;

typedef struct qd_poincare_result {
    size_t got;          /* the crossings counted */
    double last_t;       /* the time of the last one (t0: none yet) */
    qd_sim_stats stats;  /* the run's */
} qd_poincare_result;

/* Run s from opts (qd_sim_run), the rows given to o->sink, until o->want
 * crossings of the section, t_end, or the sink says stop (the caller
 * compares r->got with o->want: fewer crossings than wanted by t_end is
 * no failure).  The run's failures are qd_sim_run's; QD_ERR_ARG for want
 * 0 or a NULL sink. */
QD_API qd_status qd_poincare_run(qd_sim *s, const qd_sim_opts *opts, const qd_poincare_opts *o,
                                 qd_poincare_result *r);

/* `qdot poincare --format json`, the shape of simulate's document: begin
 * opens the object in j with "model" (the model file, NULL: null) and, when
 * rows, "columns" (names[0..ncols)) and an open "rows" array, to which the
 * caller adds each crossing's row (qd_json_vector, key NULL); end closes
 * the rows (when rows), writes the run's summary (qd_sim_summary_json's
 * keys, no "final"; a run that found o->want crossings has the "stop" of a
 * terminal event of the section, {"code": "event", "t": the last
 * crossing's time, "value": o->event}), "crossings" (r->got) and "wanted"
 * (o->want), and closes the object.  Without rows (the rows written as CSV
 * elsewhere) the document is the summary alone.  QD_ERR_NUMERIC when a
 * number was not finite (j failed: qd_json_ok), QD_ERR_NOMEM when memory
 * ran out. */
QD_API qd_status qd_poincare_json_begin(qd_json *j, const char *model, size_t ncols,
                                        const char *const *names, bool rows);
QD_API qd_status qd_poincare_json_end(qd_json *j, const qd_sim *s, const qd_sim_opts *opts,
                                      const qd_poincare_opts *o, const qd_poincare_result *r,
                                      double wall, bool rows);

/* ---- several orbits through one section (src/lyap/orbits.c) ------------ */

#define QD_POINCARE_MAX_ORBITS 16

typedef struct qd_poincare_orbits {
    size_t n;                   /* orbits, 1 .. QD_POINCARE_MAX_ORBITS */
    const char *const *initial; /* n initial states, each "q=VALUE, q'=VALUE, ..." onto the
                                 * model's own (qd_sim_setup_initial); an entry NULL: the
                                 * model's own */
    /* May be NULL: called with the sink's data before orbit k's first row
     * (k from 0). */
    void (*start)(void *data, size_t k);
} qd_poincare_orbits;

struct qd_sim_setup;
/* Every initial state of orbits read (qd_sim_setup_restart on set, opts
 * from qd_sim_setup_options; their values are the last orbit's after), so
 * a mistake is told before any run.  QD_ERR_ARG for 0 or more than
 * QD_POINCARE_MAX_ORBITS orbits; else qd_sim_setup_restart's errors, *at
 * the orbit (its initial state's error located in orbits->initial[*at]). */
QD_API qd_status qd_poincare_orbits_check(qd_ctx *ctx, struct qd_sim_setup *set,
                                          qd_sim_opts *opts, const qd_poincare_orbits *orbits,
                                          size_t *at);
/* The orbits of orbits through one section: each from its initial state
 * (qd_sim_setup_restart on set; opts from qd_sim_setup_options, its initial
 * values replaced) run as qd_poincare_run runs it (o: the section's event,
 * the crossings wanted of each orbit, the sink and progress), one after
 * another, the rows to o->sink, orbit k's result into r[k] (orbits->n of
 * them).  Every initial state is read first (qd_poincare_orbits_check).  o->progress'
 * done is over all orbits.  When the sink says stop, the orbits after it
 * are not run (their r[k].got 0) and *at is the orbit it stopped in.  On failure *at is the orbit the error
 * concerns (an initial state's error is located in orbits->initial[*at]),
 * the orbits before it done.  QD_ERR_ARG for want 0 or a NULL sink; else
 * the errors of qd_poincare_orbits_check and qd_poincare_run. */
QD_API qd_status qd_poincare_orbits_run(qd_ctx *ctx, struct qd_sim_setup *set,
                                        qd_sim_opts *opts, const qd_poincare_opts *o,
                                        const qd_poincare_orbits *orbits,
                                        qd_poincare_result *r, size_t *at);

/* A line of a section's CSV (qdot poincare) appended to out: row NULL,
 * the header names[0, ncols) (names is needed either way); else row's ncols numbers (qd_buf_put_double:
 * the fewest digits that read back).  With norbits > 1 an orbit column
 * first: "orbit" in the header, orbit + 1 in a row.  QD_ERR_NOMEM when out
 * ran out of memory. */
QD_API qd_status qd_poincare_csv(size_t ncols, const char *const *names, const double *row,
                                 size_t norbits, size_t orbit, qd_buf *out);

/* The end of a section's run, a line an orbit appended to out, each
 * starting with prefix ("qdot: poincare: "), "orbit K: " after it when
 * norbits > 1: "dop853, 200 crossings by t = 1480.3: 9120 steps, 109450
 * evaluations, 12 rejected; energy error 3.1e-12 over the steps and
 * crossings" (the method, r[k]'s counts and its largest energy error),
 * and a line "note: only N of want crossings before t = T (raise
 * t_end_name)" for an orbit that found fewer.  QD_ERR_NOMEM when out ran
 * out of memory. */
QD_API qd_status qd_poincare_print(const qd_poincare_result *r, size_t norbits,
                                   qd_sim_method method, size_t want, const char *prefix,
                                   const char *t_end_name, qd_buf *out);

/* ---- a run set up as qdot lyapunov takes it (src/lyap/setup.c) ---------- */

/* The exponents of one run, with what the printers read of it. */
typedef struct qd_lyap_result {
    qd_lyap_opts opts;      /* as run (nexp 0 asked: 1) */
    double *exps, *err;     /* opts.nexp each, descending (qd_lyap_run's) */
    qd_lyap_stats stats;
    qd_lyap_report report;  /* points into this struct: keep it where it was filled */
} qd_lyap_result;

/* The lo->nexp (lo NULL or nexp 0: 1) largest exponents of set's run from
 * opts (qd_sim_setup_options'), by the variational equations of set's
 * Lagrange equations (m the model set was made from), into r, report
 * included.  QD_ERR_ARG refusing the run, the reason in ctx naming the
 * field in qd_diag.name: "no_speeds" (set is not in Lagrange's form: a
 * model given by H, or in speeds) or "exponents" (nexp above 2n); else the
 * errors of qd_lyap_new and qd_lyap_run.  Free r with qd_lyap_result_free,
 * also after a failure. */
QD_API qd_status qd_lyap_setup_run(qd_ctx *ctx, const struct qd_sim_setup *set,
                                   const qd_model *m, const qd_sim_opts *opts,
                                   const qd_lyap_opts *lo, qd_lyap_result *r);
QD_API void qd_lyap_result_free(qd_lyap_result *r); /* NULL is fine */

/* The flow Jacobian of set's run from opts (qd_sim_setup_options'), as
 * `qdot simulate --variational` takes it: the variational equations of
 * set's Lagrange equations (m the model set was made from) run with
 * qd_flow_sim_opts(opts), written to *used (for qd_flow_json); with write
 * given, the rows as CSV too (qd_flow_run_csv at opts' spacing).  *f filled
 * (qd_flow_free, also after a failure).  QD_ERR_ARG naming the field
 * "no_speeds" (qd_diag.name) for a set not in Lagrange's form (a model
 * given by H, or in speeds); else the errors of qd_lyap_new and
 * qd_flow_run or qd_flow_run_csv. */
QD_API qd_status qd_flow_setup_run(qd_ctx *ctx, const struct qd_sim_setup *set,
                                   const qd_model *m, const qd_sim_opts *opts,
                                   qd_sim_write_fn write, void *data, qd_sim_opts *used,
                                   qd_flow *f);

#ifdef __cplusplus
}
#endif

/* NULL (issue 30): a function of this header given NULL for a pointer it
 * needs does nothing and returns QD_ERR_ARG (recorded in ctx when ctx is
 * given), NULL, 0, false or NaN, as its return type has it; a void function
 * returns, and every _free accepts NULL. NULL is an accepted value, as
 * documented at the function, for: qd_lyap_run (err); qd_lyap_run_stats
 * (err, stats); qd_flow_run (fo); qd_flow_print (prefix); qd_lyap_print,
 * qd_lyap_json (r->err); qd_lyap_setup_run (lo); lo->progress and lo->data;
 * qd_flow_setup_run (write, data); qd_poincare_run's and
 * qd_poincare_orbits_run's o->progress and o->data; orbits->start and an
 * entry of orbits->initial; qd_poincare_csv (row: the header);
 * qd_poincare_json_begin (model; names when !rows). An array whose count is 0 may be NULL. */
#endif

/*
 * qdot/simsetup.h - a simulation set up from a model as `qdot simulate`
 * (and Python's Model.simulate) take it: which equations, the initial
 * state, outputs, events and inputs read in the model's names, the method
 * and its options from text.  Every decision of the set-up lives here, so
 * that the command line and Python make the same run, and the same mistake
 * gets the same message from both.
 *
 * Which equations (qd_sim_form_of):
 *   a model given by H (`momenta`, `H = ...`)  Hamilton's, y = (q, p)
 *   a model with `speeds` (unless no_speeds)    the speeds form, y = (q, u)
 *   otherwise                                   Lagrange's, y = (q, q')
 *
 * The namespace of outputs, events and inputs (qd_sim_setup_read): the
 * coordinates, velocities q', t, the parameters, the model's definitions
 * (`x2 = x1 + l*sin(theta)`, replaced by their values; NAME' is a
 * definition's time derivative), a speed's name (its definition), the
 * multipliers lambda_NAME of the constraints (Lagrange's form), the
 * momenta (a model given by H) and the model's inputs.  Any other name is
 * QD_ERR_ARG "unknown name 'NAME'", located in the text.
 *
 * Errors are recorded in the context: a text's error with its place in
 * that text (qd_diag offset, length), an option's with qd_diag.name its
 * field's name ("t_end", "dt", ...) and subject QD_SUBJECT_NONE, so that
 * each caller names it in its own terms (--t-end, t_end=).
 */
#ifndef QDOT_SIMSETUP_H
#define QDOT_SIMSETUP_H

#include <stdbool.h>
#include <stddef.h>
#include "control.h"
#include "sim.h"
#include "statespace.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum qd_sim_form {
    QD_SIM_FORM_LAGRANGE, /* M q'' = f, with multipliers for the constraints */
    QD_SIM_FORM_HAMILTON, /* the model's H */
    QD_SIM_FORM_SPEEDS    /* the model's speeds, the constraints eliminated */
} qd_sim_form;

/* The equations a model is simulated in (see above). */
QD_API qd_sim_form qd_sim_form_of(const qd_model *m, bool no_speeds);

typedef struct qd_sim_setup qd_sim_setup;

/* The model's equations derived (qd_eom_derive or qd_speeds_derive) and
 * compiled (qd_sim_new*), the model's `outputs` added as columns, and the
 * initial state at the model's `initial` values (coordinates and
 * velocities not named are 0, t = 0, the speeds from the velocities).  m
 * (with --set applied) must outlive the set-up.  NULL on failure, the
 * reason in ctx (a derivation's error: qd_model_locate finds its place). */
QD_API qd_sim_setup *qd_sim_setup_new(qd_ctx *ctx, const qd_model *m, bool no_speeds);
QD_API void qd_sim_setup_free(qd_sim_setup *s);

QD_API qd_sim *qd_sim_setup_sim(const qd_sim_setup *s);
QD_API qd_sim_form qd_sim_setup_form(const qd_sim_setup *s);
/* The equations: Lagrange's form (else NULL), the speeds form (else NULL). */
QD_API const qd_eom *qd_sim_setup_eom(const qd_sim_setup *s);
QD_API const qd_speeds_eom *qd_sim_setup_speeds_eom(const qd_sim_setup *s);
/* The constraints kept by the equations (either form), and constraint k. */
QD_API size_t qd_sim_setup_ncon(const qd_sim_setup *s);
QD_API const qd_con *qd_sim_setup_con(const qd_sim_setup *s, size_t k);

/* The initial state: the symbols and their values, n of them: the
 * coordinates, velocities, t, the parameters (model order), then the
 * momenta of a model given by H or the speeds of a model with speeds.
 * Owned by s; the values change with qd_sim_setup_initial. */
QD_API size_t qd_sim_setup_state(const qd_sim_setup *s, const qd_expr *const **syms,
                                 const double **vals);

/* "NAME=VALUE, ..." onto the initial state: NAME a coordinate, a velocity
 * NAME', t (the `independent` variable's name), a momentum or a speed;
 * VALUE a constant expression in the parameters ("pi/2", "r0").  When it
 * names a velocity, the model's initial speeds it does not name give way
 * (they follow from the velocities); momenta not named are 0.  An unknown
 * name (with "did you mean" the nearest), a parameter (its value is the
 * model's, or --set's: a run never changes it), a name given twice, an
 * item that is not NAME=VALUE or a value that does not evaluate is
 * QD_ERR_ARG located in text.  Once, before qd_sim_setup_options. */
QD_API qd_status qd_sim_setup_initial(qd_sim_setup *s, const char *text);

/* The run again from another initial state (several orbits through one
 * section, qd_poincare_orbits_run): the model's own initial state (as
 * qd_sim_setup_new made it, the earlier qd_sim_setup_initial undone), then
 * initial onto it as qd_sim_setup_initial reads it (NULL: none), and out's
 * t0 and initial values (q0, qd0, p0, u0) replaced; its other options (an
 * earlier qd_sim_setup_options') stay, t_end included.  After
 * qd_sim_setup_options; the values out points to change at the next
 * restart.  Errors as qd_sim_setup_initial's (out untouched), and
 * QD_ERR_ARG (field "t_end") when t_end is not after the new t0, or for
 * an impact's gap negative at t0. */
QD_API qd_status qd_sim_setup_restart(qd_sim_setup *s, const char *initial, qd_sim_opts *out);

/* text[a, b) (surrounding blanks skipped) read in the model's names (see
 * above): the expression, or NULL with the error located in text. */
QD_API const qd_expr *qd_sim_setup_read(qd_sim_setup *s, const char *text, size_t a, size_t b);

/* Output columns "EXPR, ..." (the items at top-level commas), each named by
 * its text; errors located in text. */
QD_API qd_status qd_sim_setup_outputs(qd_sim_setup *s, const char *text);
/* One output column under name, the expression text[a, b). */
QD_API qd_status qd_sim_setup_output(qd_sim_setup *s, const char *name, const char *text,
                                     size_t a, size_t b);

/* An event in the grammar "EXPR = EXPR[, EXPR > EXPR | EXPR < EXPR]...":
 * the crossing first (g = lhs - rhs), then guards (a > b: a - b > 0).
 * stop: the run ends at its first time.  Errors located in text. */
QD_API qd_status qd_sim_setup_event(qd_sim_setup *s, const char *text, bool stop);
/* An event where text[a0, a1) crosses text[b0, b1) (no guards, not
 * stopping): a sweep's escape measure. */
QD_API qd_status qd_sim_setup_crossing(qd_sim_setup *s, const char *text, size_t a0, size_t a1,
                                       size_t b0, size_t b1);

/* Input name's source: the expression text[a, b) (read in the model's
 * names; qd_sim_input_expr). */
QD_API qd_status qd_sim_setup_input(qd_sim_setup *s, const char *name, const char *text,
                                    size_t a, size_t b);

/* An input's source as one text says it (`qdot simulate --input`):
 *   "NAME = EXPR"   QD_SIM_INPUT_EXPR: the expression, given to the run
 *                   (qd_sim_setup_input)
 *   NAME=FILE.csv   QD_SIM_INPUT_TABLE (a value ending in .csv): the
 *                   caller reads the file (qd_sim_input_table_read)
 *   "NAME = lqr"    QD_SIM_INPUT_LQR: the caller sets the feedback up
 *                   (qd_sim_setup_lqr)
 * *kind says which, name (cap bytes) holds NAME and [*a, *b) is the
 * value's place in text, blanks trimmed.  A text without "NAME =", or a
 * NAME an earlier call gave, is QD_ERR_ARG (not located); an expression's
 * error is located in text. */
typedef enum qd_sim_input_kind {
    QD_SIM_INPUT_EXPR,
    QD_SIM_INPUT_TABLE,
    QD_SIM_INPUT_LQR
} qd_sim_input_kind;
QD_API qd_status qd_sim_setup_input_text(qd_sim_setup *s, const char *text,
                                         qd_sim_input_kind *kind, char *name, size_t cap,
                                         size_t *a, size_t *b);

/* The run's options as given: each number as text (NULL when not given),
 * an expression in the parameters. */
typedef struct qd_sim_setup_opts {
    const char *t_end;     /* required, unless period */
    const char *period;    /* instead of t_end: one period T, t_end = t0 + T
                            * (qd_sim_setup_period; then qd_sim_setup_period_of) */
    const char *dt;        /* > 0: the output spacing, for every method (dense output) */
    const char *step;      /* > 0: the step of a fixed-step method (or of fixed) */
    const char *rtol, *atol; /* > 0 */
    const char *every;     /* dt's older name; with dt and no step, dt is the step */
    const char *max_steps; /* a whole number > 0 */
    const char *method;    /* a name (qd_sim_method_from_name), or NULL for the default */
    int precision;         /* 0, 64, 80 or 128 (taylor only beyond 64) */
    bool no_project;
    bool fixed;            /* dopri5/dop853 take the constant step (step, else dt) */
} qd_sim_setup_opts;

/* The options of the run into *out, with the initial state (issue 33: dt
 * is the output spacing of every method, step the step of a fixed one).
 * The method: given, else qd_sim_default_method, a fixed-step default
 * only when step is given (rows asked for with dt and no step: an
 * adaptive method, whatever rtol).  A fixed-step method (or fixed) takes
 * step, else dt as its step; with both, rows every dt from the dense
 * output (out->every).  Refused before any output: step with rtol but no
 * method (ambiguous), step with an adaptive method without fixed, a
 * fixed-step method with neither, precision beyond 64 without taylor,
 * t_end not after t0, the options qd_sim_check_opts refuses, an impact's
 * gap negative at t0, an input without a source.  QD_ERR_ARG with the
 * field's name in qd_diag.name (a number's text error also located in
 * that text). */
QD_API qd_status qd_sim_setup_options(qd_sim_setup *s, const qd_sim_setup_opts *o,
                                      qd_sim_opts *out);

/* The period of the last qd_sim_setup_options given one, else NaN. */
QD_API double qd_sim_setup_period_of(const qd_sim_setup *s);

/* A run over one period: T read from text (a constant expression in pi, e
 * and the parameters, "2*pi*sqrt(l/g)"), positive, into *period, and
 * out->t_end = out->t0 + T.  After qd_sim_setup_options (which gives t0 from the state; its
 * t_end is then replaced).  QD_ERR_ARG (or the reader's QD_ERR_PARSE) with
 * the error located in text; out untouched. */
QD_API qd_status qd_sim_setup_period(qd_sim_setup *s, const char *text, qd_sim_opts *out,
                                     double *period);

/* --native: the compiled right-hand side of opts' method loaded when it can
 * take it (Lagrange's form, an adaptive method; the taylor recurrences in
 * double), else the compiled programs stay.  QD_OK either way unless out
 * of memory; note (cap bytes, may be NULL) says why it fell back, "" when
 * it did not.  After qd_sim_setup_options. */
QD_API qd_status qd_sim_setup_native(qd_sim_setup *s, const qd_sim_opts *opts, char *note,
                                     size_t cap);

/* --jit: the set-up's compiled programs as machine code (qd_sim_jit, LLVM's
 * ORC JIT in this process, no compiler run): the interpreter's numbers bit
 * for bit.  When the JIT cannot (the module missing, LLVM failing), note
 * (cap bytes, may be NULL) says why and the run stays interpreted: QD_OK.
 * Other failures (no memory) are the status.  After the options, events
 * and outputs are set. */
QD_API qd_status qd_sim_setup_jit(qd_sim_setup *s, char *note, size_t cap);

/* ---- an input fed back by LQR (src/sim/lqr.c) ------------------------------ */

/* An LQR feedback set up on a simulation's input (qd_sim_setup_lqr). */
typedef struct qd_sim_lqr {
    qd_statespace ss;          /* the model linearized about the point */
    qd_care_result r;          /* the design on ss (K: nu x nx, eig_re sorted) */
    size_t input;              /* the input's index in ss.inputs (its row of K) */
    const qd_expr *u;          /* u0 - K (x - x0): what the run takes for the input */
    size_t npt;                /* the operating point as read: syms = exact vals */
    const qd_expr **syms, **vals;
    const char *part;          /* on failure, what the error is about: "about" (the
                                * point's text, located in it), "point" (the
                                * linearization there), "weights" (located in that
                                * text), "name" (not an input; not Lagrange's form) */
} qd_sim_lqr;

/* Input name of s's run fed back by LQR (issue 31, "LQR on a model"): the
 * operating point about, "q=VALUE, q'=VALUE, F=VALUE, ..." (coordinates,
 * velocities and inputs of the model; each VALUE a constant expression in
 * pi, e and the parameters, kept exact; a name not given is 0), the model
 * linearized there (qd_linearize), the CARE solved for weights "Q = ...,
 * R = ..." (qd_lqr_design), and the input set to
 *     u = u0 - K (x - x0)          (qd_lqr_feedback, qd_sim_input_expr)
 * with K's row of that input.  Lagrange's form only (not H, not speeds).
 * *out is overwritten; qd_sim_lqr_free it, also after a failure.  Errors
 * (in the context): QD_ERR_ARG, QD_ERR_PARSE (a value misread),
 * QD_ERR_SINGULAR, QD_ERR_NUMERIC, QD_ERR_NOMEM, with out->part saying which
 * argument the error is about. */
QD_API qd_status qd_sim_setup_lqr(qd_sim_setup *s, const char *name, const char *about,
                                  const char *weights, qd_sim_lqr *out);
/* What the run's controller is, appended to out (each line starts with
 * prefix): "NAME = lqr: K = k1 (x1) k2 (x2) ...; closed-loop eigenvalues,
 * largest real part a" (6 digits), and a note when the operating point is
 * not an equilibrium (its first nonzero x' there).  QD_ERR_NOMEM when out
 * failed; QD_ERR_ARG for a feedback not set up. */
QD_API qd_status qd_sim_lqr_note(const qd_sim_lqr *l, const char *prefix, qd_buf *out);
QD_API void qd_sim_lqr_free(qd_sim_lqr *l); /* NULL is fine */

#ifdef __cplusplus
}
#endif

/* NULL (issue 30): a function of this header given NULL for a pointer it
 * needs does nothing and returns QD_ERR_ARG (recorded in ctx when ctx is
 * given), NULL, 0, false or NaN, as its return type has it; a void function
 * returns, and every _free accepts NULL. NULL is an accepted value, as
 * documented at the function, for: qd_sim_setup_state (syms, vals);
 * qd_sim_setup_native (note); qd_sim_setup_jit (note). An array whose count is 0 may be NULL. */
#endif

/*
 * qdot/model.h - the model language: a system described as on a textbook page.
 *
 *   coordinates theta1, theta2
 *   parameters m1 = 1, l1 = 1, g = 9.81
 *   x1 = l1*sin(theta1)
 *   T = m1/2*(x1'^2 + y1'^2)
 *   V = m1*g*y1
 *
 * qd_model_parse reads such a text (docs/language.md has the whole language)
 * into a qd_model: the coordinates and parameters as kernel symbols, and the
 * mechanical content (T, V, U, L, the dissipation function, the generalized
 * forces) as kernel expressions in the caller's context.  The model is owned
 * by the caller (qd_model_free); its expressions belong to the context.
 */
#ifndef QDOT_MODEL_H
#define QDOT_MODEL_H

#include <stddef.h>
#include "expr.h"
#include "print.h"
#include "read.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Errors in a model file are error records (qd_diag, status.h), shown with
 * qd_diag_format (read.h). */

typedef struct qd_model qd_model;

/* The longest model text read, in bytes (64 MiB): a longer one is refused
 * (QD_ERR_TOOBIG), and the CLI stops reading a file there. */
#define QD_MODEL_MAX_BYTES ((size_t)64 << 20)

/* Parse a model.  NULL on error, with the context's error record located in
 * text and a copy in *diag (diag may be NULL).  The text must be UTF-8 of
 * at most QD_MODEL_MAX_BYTES; lines end in \n, \r\n or \r.  A model
 * that parses is complete and consistent (T, L or momenta and H given, every
 * name known, every parameter valued).  text must stay alive while the model
 * is used. */
QD_API qd_model *qd_model_parse(qd_ctx *ctx, const char *text, qd_diag *diag);

/* A parameter's value given from outside the text (the command line's
 * --set NAME=VALUE). */
typedef struct qd_param_value {
    const char *name;
    const qd_expr *value;         /* a number */
} qd_param_value;

/* How to read a model.  Parameter values given here are input to the
 * parse: the text is read as if `parameters NAME = VALUE` stood in it, so a
 * parameter defined from NAME (m = 2*k), an initial value and everything
 * derived later follow.  Of two values for one name the last wins. */
typedef struct qd_model_opts {
    const qd_param_value *params;
    size_t nparams;
    /* true: each parameter given here, and each defined from one, is a
     * constant of this model, its number written into every expression in
     * place of its name (equations print with the value; qd_model_set_param
     * refuses it); false: it stays a symbol with this value (generated code
     * keeps it adjustable). */
    bool fix_params;
} qd_model_opts;

/* qd_model_parse with options (opts may be NULL).  A name in opts that no
 * parameter has is an error not in the text: NULL, QD_ERR_ARG in the
 * context, and diag->line == 0 with "unknown parameter 'kk'; did you mean
 * 'k'?" in diag->message. */
QD_API qd_model *qd_model_parse_opts(qd_ctx *ctx, const char *text, const qd_model_opts *opts,
                                     qd_diag *diag);

/* The rule of which derivations show the values of opts->params in their
 * formulas (docs/design.md, "Parameters given from outside"), shared by the
 * program and the Python package: derivation is a command's name; "eom",
 * "hamiltonian", "routh", "integrals", "hj", "metric", "bracket",
 * "canonical", "scatter" and "field" (formulas to read) set
 * opts->fix_params; "simulate", "poincare", "sweep", "lyapunov", "animate",
 * "modes", "equilibria", "stability", "linearize", "lqr", "zvc", "orbit",
 * "path", "action", "action_of", "impulse", "check" and "codegen" (numbers,
 * or code whose parameters stay adjustable) clear it.  QD_OK; QD_ERR_ARG,
 * opts unchanged, for NULL or a name not in the rule. */
QD_API qd_status qd_model_opts_for(qd_model_opts *opts, const char *derivation);

/* Add one statement (a line of the language, without comments) to a parsed
 * model as if it ended the text: a `symmetry`, an `integral`, a constraint,
 * a definition ...; not `coordinates` or `momenta`, which would change the
 * model's shape.  The model keeps a copy of text.  QD_OK; else QD_ERR_PARSE
 * with *diag located in text (line 1 is its first line) and the model as it
 * was, or QD_ERR_NOMEM. */
QD_API qd_status qd_model_add_statement(qd_model *m, const char *text, qd_diag *diag);
/* Add text given apart from the model's text (a command-line option, a
 * Python argument) as statements of the language: with label non-NULL one
 * statement "KEYWORD LABEL: TEXT", or "KEYWORD TEXT" when text starts with
 * its own "NAME:" (`symmetry`, `integral`); with label NULL a statement
 * "KEYWORD ITEM" for each item of the comma-separated text, commas inside
 * brackets not splitting (`prescribe`).  text is one line without comments.
 * QD_OK; else *diag (may be NULL) is located in text itself, not in the
 * statement built around it: QD_ERR_PARSE for what the language refuses,
 * QD_ERR_ARG for a second line, a comment or an empty item; QD_ERR_NOMEM.
 * The items before a failing one stay added. */
QD_API qd_status qd_model_add_given(qd_model *m, const char *keyword, const char *label,
                                    const char *text, qd_diag *diag);
QD_API void qd_model_free(qd_model *m);
/* The context m was read in, where its expressions live (m's, not the
 * caller's to free); NULL for NULL. */
QD_API qd_ctx *qd_model_ctx(const qd_model *m);

QD_API size_t qd_model_ncoords(const qd_model *m);
QD_API const qd_expr *qd_model_coord(const qd_model *m, size_t i);   /* in declaration order */
/* Coordinate i's unit where the model states it through its geometry:
 * "rad" when the particles' positions and V (each as a function of the
 * coordinates, parameters and t) repeat when it grows by 2 pi, and change
 * when it grows by 1: an angle.  NULL otherwise (a length, a charge, or not
 * said: the model writes no units), and for i out of range; a V that
 * cannot be evaluated without velocities gives NULL, nothing recorded in
 * ctx.  The string is static. */
QD_API const char *qd_model_coord_unit(qd_ctx *ctx, const qd_model *m, size_t i);
/* The unit of a run's column named name: "s" for t, a coordinate's unit
 * (qd_model_coord_unit) for its name, and per second for its velocity
 * NAME' ("rad/s"); NULL for any other column or an unknown unit. */
QD_API const char *qd_model_column_unit(qd_ctx *ctx, const qd_model *m, const char *name);
QD_API size_t qd_model_nparams(const qd_model *m);
/* The user functions the model declares (`functions W, h`), in order. */
QD_API size_t qd_model_nfunctions(const qd_model *m);
QD_API const char *qd_model_function_name(const qd_model *m, size_t i); /* NULL out of range */
QD_API const qd_expr *qd_model_param(const qd_model *m, size_t i);
/* Its value: the definition with the earlier parameters' values put in, a
 * constant expression, exact (2, 9.81, pi/6, sqrt(2)/2: not always a number
 * node; qd_eval gives the double). */
QD_API const qd_expr *qd_model_param_value(const qd_model *m, size_t i);
/* That value as the nearest double (an exact rational p/q that fits is
 * (double)p/q, correctly rounded: 9.81 stays 9.81).  QD_ERR_ARG, *x NaN and
 * nothing recorded, when i is out of range or the value is not a finite
 * number (the caller says so in its own words); QD_ERR_NOMEM, recorded in
 * the model's context, when evaluating it ran out of memory. */
QD_API qd_status qd_model_param_number(const qd_model *m, size_t i, double *x);
/* The parameter as written: an expression of the earlier parameters
 * (`m = 2*k` gives 2*k), or the number that replaced it. */
QD_API const qd_expr *qd_model_param_definition(const qd_model *m, size_t i);
/* Fixed by qd_model_opts (given with fix_params, or defined from a fixed
 * one): its number, not its symbol, stands in the model's expressions. */
QD_API bool qd_model_param_fixed(const qd_model *m, size_t i);
/* Give a parameter another value after parsing; the parameters defined from
 * it and the initial values follow.  QD_ERR_ARG for an unknown name (with
 * the nearest known name in the context's message), a value that is not a
 * number, a parameter fixed by qd_model_opts, or a value that would make a
 * parameter assumed positive zero or negative.  A parameter whose value is
 * positive when the model is read is assumed positive (sqrt(g^2) is g), so
 * a change of sign must be given as input to the parse (qd_model_opts). */
QD_API qd_status qd_model_set_param(qd_ctx *ctx, qd_model *m, const char *name, const qd_expr *value);

/* The mechanical content; NULL where the model gives none.  lagrangian is
 * L as given, or T - V - U; NULL for a model given by H (its L is the
 * mechanics layer's inverse Legendre transform, qd_legendre_inverse). */
QD_API const qd_expr *qd_model_kinetic(const qd_model *m);      /* T (particles, bodies and T = ...) */
QD_API const qd_expr *qd_model_potential(const qd_model *m);    /* V */
QD_API const qd_expr *qd_model_gen_potential(const qd_model *m);/* U, velocity-dependent */
QD_API const qd_expr *qd_model_lagrangian(const qd_model *m);   /* L */
QD_API bool qd_model_lagrangian_given(const qd_model *m);       /* L = ... in the text */
QD_API const qd_expr *qd_model_dissipation(const qd_model *m);  /* Rayleigh's D */
QD_API const qd_expr *qd_model_force(const qd_model *m, size_t i); /* Q_i (never NULL: 0 when none) */

/* Constraints (`constraint NAME: lhs = rhs`), in the order given: the
 * expression lhs - rhs, which the motion keeps at zero, and the name (given,
 * or "c1", "c2", ... for unnamed ones).  They may contain velocities. */
QD_API size_t qd_model_nconstraints(const qd_model *m);
QD_API const char *qd_model_constraint_name(const qd_model *m, size_t i);
QD_API const qd_expr *qd_model_constraint(const qd_model *m, size_t i);

/* The calculus of variations (docs/language.md): `independent x` names the
 * independent variable x, which is the time symbol t in every expression
 * (NULL when the model does not rename it); `constraint NAME: integral(G) = l`
 * is an isoperimetric condition, integral G dt = l, whose multiplier
 * lambda_NAME (a constant symbol, or the parameter of that name when the
 * model declares one, its number when that is fixed) stands in L as
 * -lambda_NAME*G.  NULL for an index out of range. */
QD_API const char *qd_model_independent(const qd_model *m);
QD_API size_t qd_model_nisoperimetric(const qd_model *m);
QD_API const char *qd_model_isoperimetric_name(const qd_model *m, size_t i);
QD_API const qd_expr *qd_model_isoperimetric(const qd_model *m, size_t i);       /* G */
QD_API const qd_expr *qd_model_isoperimetric_value(const qd_model *m, size_t i); /* l */
QD_API const qd_expr *qd_model_isoperimetric_multiplier(const qd_model *m, size_t i);

/* Reactions (`reaction [LABEL:] CON on r`), in the order given: the
 * Cartesian force that constraint CON exerts at the point r (a position,
 * free of velocities) is wanted; qd_eom_reaction computes it.  The name is
 * the label, or the constraint's name when there is none; NULL / 0 for an
 * index (or component k > 2) out of range. */
QD_API size_t qd_model_nreactions(const qd_model *m);
QD_API const char *qd_model_reaction_name(const qd_model *m, size_t i);
QD_API const char *qd_model_reaction_constraint(const qd_model *m, size_t i);
QD_API const qd_expr *qd_model_reaction_point(const qd_model *m, size_t i, unsigned k);

/* Rigid bodies (`body NAME mass M inertia I at r orientation R`), in the
 * order given.  Components are indexed 0..2 (x, y, z); matrices by row and
 * column 0..2.  The inertia tensor is about the centre of mass in body axes;
 * the rotation maps body components to space components (identity when no
 * orientation is given); the angular velocity w is in body axes (from
 * R^T R') and omega_space = R w, both simplified.  Every getter returns NULL
 * for an index out of range. */
QD_API size_t qd_model_nbodies(const qd_model *m);
QD_API const char *qd_model_body_name(const qd_model *m, size_t i);
QD_API const qd_expr *qd_model_body_mass(const qd_model *m, size_t i);
QD_API const qd_expr *qd_model_body_inertia(const qd_model *m, size_t i, unsigned row, unsigned col);
QD_API const qd_expr *qd_model_body_position(const qd_model *m, size_t i, unsigned k);
QD_API const qd_expr *qd_model_body_rotation(const qd_model *m, size_t i, unsigned row, unsigned col);
QD_API const qd_expr *qd_model_body_omega(const qd_model *m, size_t i, unsigned k);
QD_API const qd_expr *qd_model_body_omega_space(const qd_model *m, size_t i, unsigned k);

/* What a picture draws a body as (`shape BODY as ...`, docs/language.md). */
typedef enum qd_body_shape {
    QD_SHAPE_NONE, QD_SHAPE_ROD, QD_SHAPE_DISK, QD_SHAPE_RING, QD_SHAPE_SPHERE, QD_SHAPE_BOX
} qd_body_shape;
/* Body i's `shape` statement: its kind (QD_SHAPE_NONE when it has none or
 * i is out of range); into size[0..2] (may be NULL) its sizes, expressions
 * in the parameters owned by the model (a rod's length; a disk's, ring's
 * or sphere's radius; a box's edges along body x, y, z; NULL when unused);
 * into *axis (may be NULL) the body axis, 0 x, 1 y, 2 z, of a rod or of a
 * disk's or ring's normal (2 for the others). */
QD_API qd_body_shape qd_model_body_shape(const qd_model *m, size_t i, const qd_expr *size[3],
                                         int *axis);
/* The fixed plane body i's first `rolls BODY on plane(n, r0)` names (not a
 * moving one: its picture's ground), n into n[0..2] and r0 into r0[0..2],
 * owned by the model; false (n, r0 untouched) when it has none. */
QD_API bool qd_model_body_ground(const qd_model *m, size_t i, const qd_expr *n[3],
                                 const qd_expr *r0[3]);

/* Hamiltonian models (`momenta p_r, ...` and `H = ...`).  The momenta are
 * plain symbols; `momenta` with T or L (no H) only names them. */
QD_API bool qd_model_hamiltonian_given(const qd_model *m);
QD_API const qd_expr *qd_model_hamiltonian(const qd_model *m);       /* H as given, or NULL */
QD_API const qd_expr *qd_model_momentum(const qd_model *m, size_t i); /* the symbol named in `momenta`
                                                                   for coordinate i, or NULL */
/* Symmetries (`symmetry [NAME:] ...`): q_j -> q_j + eps xi_j, xi in q and t
 * (from a finite form: d/deps at eps = 0, simplified).  Unnamed: s1, s2, ... */
QD_API size_t qd_model_nsymmetries(const qd_model *m);
QD_API const char *qd_model_symmetry_name(const qd_model *m, size_t i);
QD_API const qd_expr *qd_model_symmetry_field(const qd_model *m, size_t i, size_t coord); /* xi_j (0 when
                                                                   not moved); NULL out of range */
/* Proposed integrals (`integral [NAME:] expr`): in q, q', t (in q, the
 * momenta, t for a model given by H).  Unnamed: I1, I2, ... */
QD_API size_t qd_model_nintegrals(const qd_model *m);
QD_API const char *qd_model_integral_name(const qd_model *m, size_t i);
QD_API const qd_expr *qd_model_integral(const qd_model *m, size_t i);

/* Particles (`particle MASS at r`), in the order given; NULL / 0 out of
 * range.  A particle has no name; its index is its name in messages. */
QD_API size_t qd_model_nparticles(const qd_model *m);
QD_API const qd_expr *qd_model_particle_mass(const qd_model *m, size_t i);
QD_API const qd_expr *qd_model_particle_position(const qd_model *m, size_t i, unsigned k);

/* Impulsive motion (Desloge ch. 57, Byerly ch. III).  The configuration is
 * frozen across an impulse; only the velocities jump.
 *
 * Blows, in the order given: `impulse J at r` (generalized impulse
 * Qhat_j = J . dr/dq_j, the virtual work of J at frozen time), `impulse G on
 * BODY` (an impulsive couple: Qhat_j = G . d(omega_space)/dq'_j) and
 * `Qhat[q] = X` (given directly).  qd_model_blow is blow i's generalized
 * impulse on coordinate j (0 where it does not act); its label is the
 * statement's text ("impulse (0, -J, 0) at P").  qd_model_impulse is the
 * sum over blows on coordinate j (never NULL: 0 without blows).  A blow
 * whose generalized impulse is identically zero (its point does not move
 * with the coordinates) is a parse error. */
QD_API size_t qd_model_nblows(const qd_model *m);
QD_API const char *qd_model_blow_label(const qd_model *m, size_t i);
QD_API const qd_expr *qd_model_blow(const qd_model *m, size_t i, size_t coord);
QD_API const qd_expr *qd_model_impulse(const qd_model *m, size_t coord);

/* Sudden constraints (`impact constraint NAME: lhs = rhs [restitution E]`),
 * in the order given: lhs - rhs, holonomic or linear in the velocities,
 * and E (a number or an expression in the parameters; 0 when not given).
 * After the impact its velocity form c(q') = A q' + a0 takes the value
 * -E c(q'-) (Newton's law; E = 0: it holds).  The multiplier is
 * Lambda_NAME.  Unnamed ones are k1, k2, ...  They do not take part in
 * qd_eom_derive. */
QD_API size_t qd_model_nimpact_constraints(const qd_model *m);
QD_API const char *qd_model_impact_constraint_name(const qd_model *m, size_t i);
QD_API const qd_expr *qd_model_impact_constraint(const qd_model *m, size_t i);
QD_API const qd_expr *qd_model_impact_constraint_restitution(const qd_model *m, size_t i);

/* Unilateral contacts (`impact NAME: GAP >= 0 restitution E`), in the order
 * given: GAP in q and t (no velocities), and E.  qd_sim applies Newton's
 * impact law when GAP reaches 0 while decreasing. */
QD_API size_t qd_model_nimpacts(const qd_model *m);
QD_API const char *qd_model_impact_name(const qd_model *m, size_t i);
QD_API const qd_expr *qd_model_impact_gap(const qd_model *m, size_t i);
QD_API const qd_expr *qd_model_impact_restitution(const qd_model *m, size_t i);

/* Prescribed velocities (`prescribe [NAME:] lhs = rhs, ...`, Thomson's
 * problem): lhs - rhs, linear in the velocities, to hold just after the
 * impulse.  Unnamed ones are v1, v2, ...; the impulse each needs is its
 * multiplier Lambda_NAME. */
QD_API size_t qd_model_nprescribed(const qd_model *m);
QD_API const char *qd_model_prescribed_name(const qd_model *m, size_t i);
QD_API const qd_expr *qd_model_prescribed(const qd_model *m, size_t i);

/* Generalized speeds (`speeds u1 = EXPR, u2 = EXPR, ...`; qdot/speeds.h), in
 * the order declared.  qd_model_speed is the speed's own symbol, a function
 * of t like a coordinate (made with qd_coord, so that qd_jet(u, 1) is u');
 * it is not among the coordinates.  Its definition is an expression in the
 * coordinates, velocities, t and the parameters, linear in the velocities
 * (checked when parsed: a located error otherwise).  Elsewhere in the model
 * (T, V, forces, constraints, outputs) a speed's name stands for its
 * definition, like a definition `NAME = EXPR`.  qd_model_speed_initial is
 * the value given by `initial u1 = 0.3` (a finite number, as for the
 * coordinates), or NULL; qd_model_speed_initial_definition the same as
 * written (in the parameters). */
QD_API size_t qd_model_nspeeds(const qd_model *m);
QD_API const qd_expr *qd_model_speed(const qd_model *m, size_t i);
QD_API const qd_expr *qd_model_speed_definition(const qd_model *m, size_t i);
QD_API const qd_expr *qd_model_speed_initial(const qd_model *m, size_t i);
QD_API const qd_expr *qd_model_speed_initial_definition(const qd_model *m, size_t i);

/* Inputs (`inputs F, tau`), in the order declared: plain symbols named as
 * written, kept by name in every derivation and given a value only by the
 * numbers (qd_sim's input sources, qd_linearize's operating point).  They
 * may stand in forces, torques, Q[q], V, the dissipation function and the
 * velocity-free part of L; in the velocity-dependent part of L (where
 * d/dt(dL/dq') would need their rate) or in a constraint they are a parse
 * error.  NULL out of range. */
QD_API size_t qd_model_ninputs(const qd_model *m);
QD_API const qd_expr *qd_model_input(const qd_model *m, size_t i);
/* Outputs (`outputs y1 = EXPR, ...`), in the order given: expressions in
 * q, q', t, the parameters and the inputs.  NULL out of range. */
QD_API size_t qd_model_noutputs(const qd_model *m);
QD_API const char *qd_model_output_name(const qd_model *m, size_t i);
QD_API const qd_expr *qd_model_output(const qd_model *m, size_t i);

/* Initial values: the value of a coordinate (order 0) or velocity (order 1)
 * named in `initial`, or NULL. */
QD_API const qd_expr *qd_model_initial(const qd_model *m, size_t coord, unsigned order);
/* The same as written, an expression in the parameters (al, v/2, pi/6),
 * or NULL. */
QD_API const qd_expr *qd_model_initial_definition(const qd_model *m, size_t coord, unsigned order);

/* A named definition (`x1 = ...`): its scalar value, or NULL when the name
 * is not defined or is a vector. */
QD_API const qd_expr *qd_model_definition(const qd_model *m, const char *name);
/* Every named definition, in the order written (`x1 = ...`, `P1 = [..]`,
 * `R = rot_z(th)`): their number; the i-th one's name (owned by m; NULL
 * when i is out of range); its size, 1 for a scalar, 3 for a vector, 9 for
 * a 3x3 matrix (0 out of range); and its component k < size (a matrix by
 * rows; NULL out of range). */
QD_API size_t qd_model_ndefinitions(const qd_model *m);
QD_API const char *qd_model_definition_name(const qd_model *m, size_t i);
QD_API size_t qd_model_definition_size(const qd_model *m, size_t i);
QD_API const qd_expr *qd_model_definition_component(const qd_model *m, size_t i, size_t k);
/* text[a, b) read as the model language reads an expression after m's
 * statements: coordinates, velocities, t, parameters, inputs, the
 * definitions with their rates, vectors and components (P.x, P'.x,
 * dot(r', r')), position(BODY), omega(BODY), rotations; the momenta when m
 * is given by H.  The value must be a scalar.  NULL with the error record
 * located in text (a vector where a scalar is needed, an unknown name). */
QD_API const qd_expr *qd_model_read_expr(qd_ctx *ctx, const qd_model *m, const char *text,
                                         size_t a, size_t b);

/* Where a statement of the model stands, for errors found after parsing
 * ("the mass matrix is singular" points at the T line).  what: "T", "V", "L",
 * "U", "H", "dissipation", "coordinates", "momenta", a coordinate's name,
 * "constraint:NAME", "body:NAME" (the body's name on its line),
 * "symmetry:NAME" or "integral:NAME" (the label, or the statement's first
 * item when unnamed), "speed:NAME" (the speed's name in `speeds`).  false
 * when the model has no such statement.  For a
 * statement added by qd_model_add_statement the place is in its text. */
QD_API bool qd_model_where(const qd_model *m, const char *what, qd_diag *where);

/* Locate an error record found after parsing (a derivation's) in the model
 * text: the statement, constraint, coordinate or parameter it is about.
 * false when it has no such subject or the model no such statement; d is
 * then unchanged. */
QD_API bool qd_model_locate(const qd_model *m, qd_diag *d);

/* ---- Coulomb friction (issue 18) -------------------------------------------
 *
 * A contact with dry friction: `constraint NAME: LHS = RHS friction MU
 * normal N` (one slip direction, the constraint's; LHS - RHS is the slip
 * velocity of the contact point), `rolls BODY ... friction MU` (two: the
 * rolling constraints BODY_roll1, BODY_roll2 together).  It sticks (its
 * constraints hold) while the friction force, the multipliers' norm, is at
 * most MU_S |N|; else it slips under a force MU_K |N| against the slip
 * velocity.  docs/language.md, "Friction". */
typedef enum qd_contact_kind {
    QD_CONTACT_CONSTRAINT,   /* `constraint ... friction`: one direction */
    QD_CONTACT_ROLLING,      /* `rolls ... friction`: two directions */
    QD_CONTACT_POINT         /* `friction MU on POINT against CONSTRAINT`: two */
} qd_contact_kind;

QD_API size_t qd_model_ncontacts(const qd_model *m);
/* The constraint's name (QD_CONTACT_CONSTRAINT) or the body's; NULL out of
 * range. */
QD_API const char *qd_model_contact_name(const qd_model *m, size_t i);
QD_API qd_contact_kind qd_model_contact_kind(const qd_model *m, size_t i);
/* The constraints (indices into qd_model_constraint) whose multipliers are
 * the friction force: 1 or 2, written into con[0..); 0 out of range. */
QD_API size_t qd_model_contact_constraints(const qd_model *m, size_t i, size_t con[2]);
/* The static and kinetic coefficients as written (equal for `friction
 * MU`): expressions in the parameters, >= 0 when read. */
QD_API const qd_expr *qd_model_contact_mu(const qd_model *m, size_t i, bool kinetic);
/* The normal force: an expression in q, q', t and the parameters, or NULL
 * when it is a constraint's multiplier (then that constraint's name from
 * qd_model_contact_normal_constraint, else NULL). */
QD_API const qd_expr *qd_model_contact_normal(const qd_model *m, size_t i);
QD_API const char *qd_model_contact_normal_constraint(const qd_model *m, size_t i);
/* With N a multiplier: |N| = scale |lambda_N|, scale the size of the
 * surface's gradient in space (`friction MU on POINT against CONSTRAINT`,
 * whose constraint need not be written with a unit gradient), else 1. */
QD_API const qd_expr *qd_model_contact_normal_scale(const qd_model *m, size_t i);

/* ---- numbers in the parameters (issue 30) -----------------------------------
 *
 * text, a constant expression in pi, e and m's parameters ("2*pi/w"), read
 * and evaluated at the parameters' values into *out.  A name that is not a
 * parameter (a coordinate, t, an unknown one: "did you mean" the nearest),
 * text that does not read, or a value that is not finite is QD_ERR_ARG
 * with the error record located in text.  ctx NULL: QD_ERR_ARG and
 * nothing recorded; m, text or out NULL: QD_ERR_ARG. */
QD_API qd_status qd_model_number(qd_ctx *ctx, const qd_model *m, const char *text, double *out);
/* The same for the value text[start, start + len) of an option's field
 * (qd_diag.name = field, subject QD_SUBJECT_NONE, hint kept), its error
 * located in the whole of text: what a reader of "m1, m2" or "p_x=VALUE"
 * calls for each part, so a caret stands under the part at fault. */
QD_API qd_status qd_model_number_field(qd_ctx *ctx, const qd_model *m, const char *field,
                                       const char *text, size_t start, size_t len, double *out);

#ifdef __cplusplus
}
#endif

/* NULL (issue 30): a function of this header given NULL for a pointer it
 * needs does nothing and returns QD_ERR_ARG (recorded in ctx when ctx is
 * given), NULL, 0, false or NaN, as its return type has it; a void function
 * returns, and every _free accepts NULL. NULL is an accepted value, as
 * documented at the function, for: qd_model_parse (diag);
 * qd_model_parse_opts (diag, opts); qd_model_add_statement (diag);
 * qd_model_add_given (label, diag); qd_model_where (where). An array whose count is 0 may be NULL. */
#endif

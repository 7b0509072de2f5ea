/*
 * src/model/parser.h - the model and the parser's shared state.
 *
 * The parser reads statements one line at a time and lowers every
 * expression straight into kernel nodes: a name must be defined before it is
 * used, so one pass suffices, and the model it fills holds only kernel
 * expressions (data flows one way: text -> symbols).
 */
#ifndef QD_MODEL_PARSER_H
#define QD_MODEL_PARSER_H

#include "qdot/model.h"
#include "model_export.h"
#include "lex.h"
#include "base/diag.h" /* qd__diag_nearest: "did you mean" */

/* A value of the language: a scalar, a vector of three components, or a
 * 3x3 matrix (a rotation, an inertia tensor), stored by rows. */
typedef enum vkind { VK_SCALAR, VK_VECTOR, VK_MATRIX } vkind;

typedef struct value {
    vkind kind;
    const qd_expr *c[9];   /* c[0] alone for a scalar, c[0..2] for a vector */
    size_t off, len;       /* the source span it came from */
} value;

/* A rigid body (`body NAME mass M inertia I at r orientation R`): every
 * part in space components except I and w, which are in body axes. */
typedef struct body {
    const char *name;      /* owned copy */
    const qd_expr *mass;
    const qd_expr *I[9];   /* inertia tensor about the centre of mass, body axes */
    const qd_expr *r[3];   /* centre of mass */
    const qd_expr *R[9];   /* body components -> space components */
    const qd_expr *w[3];   /* angular velocity, body axes (simplified) */
    const qd_expr *ws[3];  /* angular velocity, space axes: R w (simplified) */
    int shape;             /* qd_body_shape: `shape BODY as ...` (shape.c), else NONE */
    const qd_expr *size[3]; /* its sizes (qd_model_body_shape) */
    int axis;              /* a rod's axis, a disk's or ring's normal: 0 x, 1 y, 2 z */
    const qd_expr *ground[6]; /* the fixed plane its first `rolls` names: n, r0; else NULL */
} body;

/* `reaction [LABEL:] CON on r`: the force of constraint con at the point r
 * (reaction.c). */
typedef struct reaction {
    const char *name;      /* owned copy: the label, or the constraint's name */
    size_t con;            /* index into the model's constraints (or its sudden ones) */
    bool sudden;           /* con indexes the `impact constraint`s */
    const qd_expr *r[3];
} reaction;

/* `symmetry [NAME:] ...`: the vector field xi_j, one per coordinate
 * (symmetry.c). */
typedef struct symmetry {
    const char *name;      /* owned copy */
    const qd_expr **xi;    /* ncoords entries, 0 where the coordinate is not moved */
} symmetry;

/* `integral [NAME:] expr` (symmetry.c). */
typedef struct integral {
    const char *name;      /* owned copy */
    const qd_expr *expr;
} integral;

/* A blow (`impulse J at r`, `impulse G on BODY`, `Qhat[q] = X`):
 * its generalized impulse on each coordinate declared before it
 * (impulse.c). */
typedef struct blow {
    const char *label;     /* owned copy of the statement's text */
    const qd_expr **w;     /* nw entries */
    size_t nw;
} blow;

/* A relation that acts only at an impulse: a sudden constraint, a
 * unilateral contact's gap or a prescription (impulse.c). */
typedef struct sudden {
    const char *name;      /* owned copy */
    const qd_expr *expr;   /* lhs - rhs, or the gap */
    const qd_expr *E;      /* the restitution (0 for a prescription) */
} sudden;

/* `speeds NAME = EXPR, ...` (speeds.c): the speed's own symbol (made with
 * qd_coord, named NAME), its definition in q, q', t, and `initial NAME = X`. */
typedef struct speed {
    const qd_expr *sym;
    const qd_expr *def;        /* linear in the velocities */
    const qd_expr *init;       /* the number, or NULL */
    const qd_expr *init_def;   /* as written, in the parameters */
} speed;

/* `constraint NAME: integral(EXPR) = VALUE` (variational.c): the
 * isoperimetric condition that the functional integral EXPR dt (t the
 * independent variable) takes VALUE; its multiplier lambda_NAME is a constant,
 * and -lambda_NAME*EXPR is added to L. */
typedef struct isoper {
    const char *name;          /* owned copy */
    const qd_expr *expr;
    const qd_expr *value;      /* the number */
    const qd_expr *value_def;  /* as written, in the parameters */
    const qd_expr *lambda;
} isoper;

typedef struct particle {
    const qd_expr *mass;
    const qd_expr *r[3];
} particle;

typedef struct def {
    const char *name;      /* interned by the kernel */
    value v;
    size_t off, len;
} def;

typedef struct where {
    char what[160];            /* "speed:" and a name of up to 127 bytes */
    const char *src;       /* the text off counts in: the model's, or an added statement's */
    size_t off, len;
} where;

struct qd_model {
    qd_ctx *ctx;
    const char *text;
    const qd_expr **coords;
    size_t ncoords;
    /* A parameter is an expression of the earlier ones, as written (pdefs:
     * m = 2*k), or the number given in its place (qd_model_opts); pvals
     * holds the numbers, every pdefs[i] evaluated with the pvals before it,
     * so a parameter follows those it is defined from. */
    const qd_expr **params, **pdefs, **pvals;
    bool *pfixed;              /* its number stands in the expressions, not its symbol */
    size_t nparams;
    const char **funcs;        /* declared user functions */
    size_t nfuncs;
    def *defs;
    size_t ndefs;
    const qd_expr *T, *V, *U, *L, *D;
    const qd_expr **Q;         /* per coordinate */
    const qd_expr **init;      /* per coordinate: [2*i] value, [2*i+1] velocity */
    const qd_expr **init_defs; /* the same as written, in the parameters */
    where *wheres;
    size_t nwheres;
    const char **con_names;    /* owned copies */
    const qd_expr **cons;      /* lhs - rhs */
    size_t ncons;
    body *bodies;
    size_t nbodies;
    reaction *reactions;
    size_t nreactions;
    const qd_expr *H;          /* `H = ...`, in q, the momenta, t */
    const qd_expr **mom;       /* `momenta ...`: per coordinate, NULL when not given */
    symmetry *syms;
    size_t nsyms;
    integral *ints;
    size_t nints;
    particle *parts;
    size_t nparts;
    blow *blows;
    size_t nblows;
    const qd_expr **Qhat;      /* per coordinate: the sum of the blows */
    sudden *sudden;            /* `impact constraint` */
    size_t nsudden;
    sudden *impacts;           /* `impact NAME: GAP >= 0` */
    size_t nimpacts;
    sudden *prescribed;        /* `prescribe` */
    size_t nprescribed;
    speed *speeds;             /* `speeds` */
    size_t nspeeds;
    const char *src;           /* the text being read (the model's or an added statement) */
    char **added;              /* owned copies of the statements added after the parse */
    size_t nadded;
    char *indep;               /* `independent x`: the name the time symbol goes by, or NULL */
    const qd_expr **inputs;    /* `inputs F, ...`: plain symbols (io.c) */
    size_t ninputs;
    const char **out_names;    /* `outputs y = EXPR, ...`: owned copies (io.c) */
    const qd_expr **outs;
    size_t nouts;
    isoper *isos;              /* isoperimetric constraints (variational.c) */
    size_t nisos;
    size_t nisos_applied;      /* how many of them L already holds */
    /* Coulomb friction (friction.c): the contacts, in the order given */
    struct fcontact *contacts;
    size_t ncontacts;
    qd__field *field;          /* `field ...` (field.c), or NULL */
    /* the name table (names.c) */
    struct qd__name_entry *names;
    size_t names_cap, names_used;
};

typedef struct parser {
    qd_ctx *ctx;
    lexer lx;
    qd_model *m;
    qd_diag *diag;
    bool failed;
    const char *defining;      /* the name whose definition is being read */
    bool momenta_ok;           /* the momenta may be used (H, integral) */
    bool eps_ok;               /* eps may be used (a symmetry's finite form) */
    int nest;                  /* open brackets and signs: at most QD_MAX_NEST */
    const qd_model_opts *opts; /* parameter values given from outside, or NULL */
    bool *set_used;            /* per opts->params entry: a parameter took it */
    bool met_fixed;            /* a fixed parameter was written in as its number */
    bool field_ok;             /* qd_field_parse: a field model is wanted */
    bool no_dot;               /* '.' ends the expression (A .. B), not a component */
} parser;

/* expr.c */
bool qd__mdl_parse_expr(parser *p, value *out);
bool qd__mdl_parse_scalar(parser *p, const qd_expr **out, const char *what);
bool qd__mdl_parse_vector(parser *p, value *v, const char *what);  /* what: "a position" */
bool qd__mdl_parse_matrix_value(parser *p, value *v, const char *what);
/* v must be of kind want; else "a vector where a scalar is needed WHERE". */
bool qd__mdl_need_kind(parser *p, const value *v, vkind want, const char *where);
int qd__mdl_value_ncomp(const value *v);           /* 1, 3 or 9 */
const char *qd__mdl_vkind_name(vkind k);           /* "scalar", "vector", "matrix" */
/* Every component built (no NULL from the kernel); else the context's error. */
bool qd__mdl_kernel_ok(parser *p, const value *v);
/* The ')' closing the '(' at open (a missing one is reported at the '('). */
bool qd__mdl_expect_close(parser *p, size_t open);
/* "NAME takes WANT arguments, not GOT" at the call when got != want. */
bool qd__mdl_check_arity(parser *p, const char *name, size_t got, size_t want, size_t off, size_t len);

/* rot.c: 3x3 matrices by rows, rotation matrices, and their calls. */
void qd__mdl_mat_identity(qd_ctx *ctx, const qd_expr *out[9]);
void qd__mdl_mat_mul(qd_ctx *ctx, const qd_expr *const a[9], const qd_expr *const b[9],
             const qd_expr *out[9]);
void qd__mdl_mat_vec(qd_ctx *ctx, const qd_expr *const a[9], const qd_expr *const v[3],
             const qd_expr *out[3]);
void qd__mdl_mat_transpose(const qd_expr *const a[9], const qd_expr *out[9]);
bool qd__mdl_is_rot_call(const char *name);        /* rot_x ... tait_bryan, transpose */
bool qd__mdl_rot_call(parser *p, const char *name, const value *a, size_t n, value *out, size_t off,
              size_t len);

/* inertia.c: principal moments of common solids, as vectors. */
bool qd__mdl_is_inertia_call(const char *name);
bool qd__mdl_inertia_call(parser *p, const char *name, const value *a, size_t n, value *out, size_t off,
                  size_t len);

/* body.c */
bool qd__mdl_stmt_body(parser *p);
bool qd__mdl_stmt_torque(parser *p);
const body *qd__mdl_find_body(const qd_model *m, const char *name, size_t n);
bool qd__mdl_is_body_call(const char *name);       /* omega, omega_space, point, rotation, position */
/* The call's '(' is the current token; the first argument names a body. */
bool qd__mdl_body_call_ahead(const parser *p);
bool qd__mdl_body_call(parser *p, const char *name, size_t off, value *out);

/* hamstmt.c: `momenta ...` and `H = ...` */
bool qd__mdl_stmt_momenta(parser *p);
bool qd__mdl_stmt_hamiltonian(parser *p);
/* An energy statement (T, V, U, L, particle, body) after H: an error at
 * off..off+len when the model already gives H. */
bool qd__mdl_no_hamiltonian_yet(parser *p, const char *what, size_t off, size_t len);
/* The momentum named at src[off..off+n), or NULL. */
const qd_expr *qd__mdl_find_momentum(const qd_model *m, const char *name, size_t n);

/* symmetry.c */
bool qd__mdl_stmt_symmetry(parser *p);
bool qd__mdl_stmt_integral(parser *p);
const qd_expr *qd__mdl_eps_symbol(qd_ctx *ctx);
bool qd__mdl_check_integrals(parser *p);   /* after the last line */

/* impulse.c: `impulse`, `Qhat[q] = X`, `impact`, `prescribe` */
bool qd__mdl_stmt_impulse(parser *p);
bool qd__mdl_stmt_qhat(parser *p);
bool qd__mdl_stmt_impact(parser *p);
bool qd__mdl_stmt_prescribe(parser *p);
/* The sudden constraint named src[off..off+n), or -1. */
long qd__mdl_find_sudden(const qd_model *m, const char *src, size_t off, size_t n);
void qd__mdl_free_sudden(sudden *s, size_t from, size_t n);
void qd__mdl_free_blows(blow *b, size_t from, size_t n);

/* io.c: `inputs NAME, ...` and `outputs NAME = EXPR, ...` */
bool qd__mdl_stmt_inputs(parser *p);
bool qd__mdl_stmt_outputs(parser *p);
const qd_expr *qd__mdl_find_input(const qd_model *m, const char *name, size_t n);
bool qd__mdl_check_inputs(parser *p);      /* after the last line */
void qd__mdl_free_io(qd_model *m);

/* speeds.c: `speeds NAME = EXPR, ...` */
bool qd__mdl_stmt_speeds(parser *p);
/* The speed named src[off..off+n) (name points at it), or -1. */
long qd__mdl_find_speed(const qd_model *m, const char *name, size_t n);
/* A statement (H) that a model with speeds cannot have: an error at
 * off..off+len when it has some. */
bool qd__mdl_no_speeds_yet(parser *p, const char *what, size_t off, size_t len);

/* variational.c: `independent x`, `constraint NAME: integral(EXPR) = VALUE` */
bool qd__mdl_stmt_independent(parser *p);
/* The integral(...) of an isoperimetric constraint named name, at the token
 * `integral`; at: where the statement is, for qd_model_where. */
bool qd__mdl_isoperimetric(parser *p, const char *name, size_t at_off, size_t at_len);
/* Is the token `integral` followed by '('? */
bool qd__mdl_integral_ahead(const parser *p);
/* Add -lambda*EXPR to L for the conditions not yet in it (after L is made). */
bool qd__mdl_apply_isoperimetric(parser *p);
bool qd__mdl_isoperimetric_named(const qd_model *m, const char *name);
void qd__mdl_free_isoperimetric(qd_model *m); /* and the independent variable's name */

/* friction.c: a contact with Coulomb friction on 1 or 2 velocity
 * constraints (qdot/model.h, "Coulomb friction"). */
typedef struct fcontact {
    char *name;                /* owned copy */
    qd_contact_kind kind;
    size_t con[2], ncon;       /* indices into the model's constraints */
    const qd_expr *mu_s, *mu_k;/* as written, in the parameters */
    const qd_expr *normal;     /* N as an expression, or NULL */
    char *normal_con;          /* owned: the constraint whose multiplier is N */
    size_t normal_off, normal_len; /* where that name is written (forward use) */
    const qd_expr *normal_scale;   /* |N| = scale |lambda|, NULL for 1 */
} fcontact;

/* The clause `friction (MU | static MU_S kinetic MU_K) [normal N]` as read,
 * before its constraints exist. */
typedef struct fclause {
    size_t off, len;           /* the word `friction` */
    const qd_expr *mu_s, *mu_k;
    const qd_expr *normal;
    char normal_con[QD_MDL_NAME_MAX];       /* "" when N is an expression or not given */
    size_t normal_off, normal_len;
} fclause;

bool qd__mdl_friction_ahead(const parser *p);
/* `friction MU on POINT against CONSTRAINT` (friction_point.c) */
bool qd__mdl_stmt_friction(parser *p);
/* Read the clause at the token `friction`. */
bool qd__mdl_friction_parse(parser *p, fclause *fc);
/* Attach a read clause to constraints con[0..ncon) of the model under name;
 * a velocity-free one is an error at the clause.  need_normal: an error
 * when no N is given and none is implied. */
bool qd__mdl_friction_add(parser *p, const fclause *fc, const char *name, qd_contact_kind kind,
                          const size_t *con, size_t ncon);
/* After the last line: every normal named by a constraint exists. */
bool qd__mdl_friction_finish(parser *p);
void qd__mdl_free_friction(qd_model *m);

/* circuit.c: `inductance`, `capacitance`, `resistance`, `source` */
bool qd__mdl_stmt_inductance(parser *p);
bool qd__mdl_stmt_capacitance(parser *p);
bool qd__mdl_stmt_resistance(parser *p);
bool qd__mdl_stmt_source(parser *p);

/* field.c: `field`, `Ldensity = ...`, `boundary ...`; the checks after the
 * last line of a field model */
bool qd__mdl_stmt_field(parser *p);
bool qd__mdl_stmt_ldensity(parser *p);
bool qd__mdl_stmt_boundary(parser *p);
bool qd__mdl_field_finish(parser *p);
void qd__mdl_free_field(qd_model *m);
/* parse.c: the text read as a field model (p.field_ok) */
qd_model *qd__mdl_parse_field(qd_ctx *ctx, const char *text, const qd_model_opts *opts,
                              qd_diag *diag);

/* stmt.c: a constant (numbers and parameters) as written (*def) and its number (*out) */
bool qd__mdl_parse_constant(parser *p, const qd_expr **def, const qd_expr **out, const char *what);

/* reaction.c */
bool qd__mdl_stmt_rolls(parser *p);     /* roll.c */
bool qd__mdl_stmt_shape(parser *p);     /* shape.c */
bool qd__mdl_stmt_reaction(parser *p);

/* The body the current token names (consumed), or NULL after an error
 * naming the nearest body; what: the statement, for the message. */
const body *qd__mdl_expect_body(parser *p, const char *what);

/* stmt.c: shared by the statements in body.c and impulse.c */
bool qd__mdl_expect_at(parser *p, const char *stmt);  /* stmt: the usage, for the hint */
bool qd__mdl_constraint_named(const qd_model *m, const char *name);
/* Append constraint c = 0 named name (copied), its place in the text at
 * (off, len); an error there when out of memory. */
bool qd__mdl_push_constraint(parser *p, const char *name, const qd_expr *c, size_t off,
                             size_t len);
/* NAME '[' COORD ']' '=' from NAME: the coordinate's index, with the '='
 * consumed; -1 after an error (usage is the hint). */
int qd__mdl_coord_subscript(parser *p, const char *usage);
bool qd__mdl_end_of_statement(parser *p);
bool qd__mdl_fresh_name(parser *p, const char *what);
bool qd__mdl_named_definition(parser *p, const char *noun, const char *usage,
                              bool (*fresh)(parser *p, const char *name, token at),
                              char name[QD_MDL_NAME_MAX], token *at, value *v);

/* error.c: record the first error at a span. */
bool qd__mdl_perr(parser *p, size_t off, size_t len, const char *hint, const char *fmt, ...)
#ifdef __GNUC__
    __attribute__((format(printf, 5, 6)))
#endif
    ;
/* The same with a reason code (qd_diag.reason) for callers that branch on it. */
bool qd__mdl_perr_why(parser *p, qd_reason why, size_t off, size_t len, const char *hint,
                      const char *fmt, ...)
#ifdef __GNUC__
    __attribute__((format(printf, 6, 7)))
#endif
    ;
bool qd__mdl_perr_tok(parser *p, const char *hint, const char *fmt, ...)
#ifdef __GNUC__
    __attribute__((format(printf, 3, 4)))
#endif
    ;
/* Every name usable in an expression (for suggestions); caller frees. */
const char **qd__mdl_known_names(const parser *p, size_t *count);

/* stmt.c: one statement at the lexer's token; the checks after the last line */
bool qd__mdl_statement(parser *p);
bool qd__mdl_finish(parser *p);

/* model.c */
/* Every parameter's and initial value's number from the definitions:
 * pvals[i] = pdefs[i] with the earlier values put in. */
bool qd__mdl_eval_params(qd_model *m);
/* QD_ERR_ARG with "unknown parameter 'NAME'; did you mean ...?" in the context. */
qd_status qd__mdl_unknown_param(qd_ctx *ctx, const qd_model *m, const char *name);
const def *qd__mdl_find_def(const qd_model *m, const char *name, size_t n);
bool qd__mdl_add_def(qd_model *m, const char *name, value v, size_t off, size_t len);
bool qd__mdl_add_where(qd_model *m, const char *what, size_t off, size_t len);
int qd__mdl_coord_index(const qd_model *m, const qd_expr *sym);
bool qd__mdl_push(qd_ctx *ctx, void **arr, size_t *n, size_t size, const void *item);

/* names.c: the hashed name table.  find: the index of the name src[0..n)
 * of that kind, or -1; add: enter the list's entry at index (false when out
 * of memory). */
enum { QD_MDL_NAME_COORD = 1, QD_MDL_NAME_PARAM, QD_MDL_NAME_DEF, QD_MDL_NAME_FUNC,
       QD_MDL_NAME_WHERE };
long qd__mdl_names_find(const qd_model *m, unsigned kind, const char *s, size_t n);
bool qd__mdl_names_add(qd_model *m, unsigned kind, size_t index);
void qd__mdl_names_free(qd_model *m);
extern unsigned long qd__mdl_name_probes; /* slots looked at, for the tests */
/* x with the values of the parameters of index < n put in (pvals): only the
 * parameters x contains are looked at. */
const qd_expr *qd__mdl_subs_params(const qd_model *m, const qd_expr *x, size_t n);

/* Is the name at src[off..off+n) equal to word? */
bool qd__mdl_name_is(const char *src, size_t off, size_t n, const char *word);

#endif

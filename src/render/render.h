/*
 * src/render/render.h - what the renderers of whole systems share (eom.c,
 * eom_at.c, speeds.c): the names of a script's results, the SymPy lines
 * that bind a model's names, the C and SymPy results as parts, and a
 * number in the digit rule of print.h.
 */
#ifndef QD_RENDER_RENDER_H
#define QD_RENDER_RENDER_H

#include "qdot/render.h"

/* A name a SymPy or C rendering gives one of its results: base with a _
 * appended while it clashes with a coordinate, parameter, function or t of
 * m, or with one of the n symbols avoid (the speeds). */
typedef struct qd__render_name { char s[32]; } qd__render_name;
qd__render_name qd__render_name_pick(const qd_model *m, const char *base, size_t n,
                                     const qd_expr *const *avoid);

/* "name = Function('name')" (fn) or "name = Symbol('name')" for sym, when
 * the SymPy printer prints it by its bare name (one that would shadow
 * Python or SymPy is printed self-contained instead and needs no line). */
void qd__render_sympy_bind(qd_ctx *ctx, qd_buf *b, const qd_expr *sym, bool fn);
/* NAME = Matrix([...]) of the rows x cols expressions x (a column when cols
 * is 1). */
qd_status qd__render_sympy_matrix(qd_ctx *ctx, qd_buf *b, const char *name,
                                  const qd_expr *const *x, size_t rows, size_t cols);

/* One result of a rendering (outputs.c): rank 0 the scalar x[0] ("name"),
 * 1 the vector x[0..rows) ("name[i]"), 2 the rows x cols row-major matrix
 * ("name[i][j]"); x NULL: none (skipped). */
typedef struct qd__render_part {
    const char *name;
    const qd_expr *const *x;
    size_t rows, cols;
    int rank;
} qd__render_part;
/* One qd_print_c_block assigning every entry of the parts, in order, so
 * that their common subexpressions are shared. */
qd_status qd__render_c_block(qd_ctx *ctx, qd_buf *b, size_t nparts,
                             const qd__render_part *parts);
/* The line "inputs (doubles in scope): ..." as a C comment: the C names of the groups'
 * symbols, t and the parameters of m. */
void qd__render_c_inputs(qd_buf *b, const qd_model *m, size_t ngroups,
                         const qd__render_part *groups);
/* NAME = Function('NAME') for the user functions in the parts' entries. */
qd_status qd__render_sympy_functions(qd_ctx *ctx, qd_buf *b, size_t nparts,
                                     const qd__render_part *parts);

/* A value evaluated at a state, in the digits of qd_double_format; -0 as 0. */
void qd__render_number(qd_buf *b, double x);
/* "NAME = VALUE, ..." of the parameters of m ("none" without any). */
void qd__render_params(qd_buf *b, const qd_model *m);
/* The parameters as a JSON object under key "parameters". */
struct qd_json;
void qd__render_json_params(struct qd_json *j, const qd_model *m);

/* *full: o with each parameter of m that o's state does not name added at
 * the model's value (qd_eval needs them all); its arrays are allocated
 * (qd__render_state_free). */
qd_status qd__render_state(qd_ctx *ctx, const qd_model *m, const qd_render_opts *o,
                           qd_render_opts *full);
void qd__render_state_free(qd_render_opts *full);

/* The value of sym in a state (o->syms, o->vals); NaN when it is absent. */
double qd__render_value(const qd_render_opts *o, const qd_expr *sym);

/* x as a JSON string in the text syntax (printed through tmp). */
qd_status qd__render_json_expr(qd_ctx *ctx, struct qd_json *j, const qd_expr *x, qd_buf *tmp);
/* key: [the names of x[0..n)]. */
void qd__render_json_names(struct qd_json *j, const char *key, const qd_expr *const *x, size_t n);
/* st, or QD_ERR_NOMEM (recorded) when out ran out while printing the
 * equations. */
qd_status qd__render_done(qd_ctx *ctx, const qd_buf *out, qd_status st);

/* One result that prints as text or JSON (a quadratic form, periods, a
 * Fourier series, ...): QD_OK for those formats, else QD_ERR_ARG recorded
 * as "WHAT prints as text or json". */
qd_status qd__render_text_or_json(qd_ctx *ctx, qd_render_format fmt, const char *what);
/* After such a rendering: st, QD_ERR_NOMEM when out ran out, and a failure
 * recorded as "cannot print NAME: reason". */
qd_status qd__render_finish(qd_ctx *ctx, const qd_buf *out, qd_status st, const char *name);

/* The status after a JSON rendering into b: QD_ERR_NOMEM when b ran out,
 * QD_ERR_NUMERIC for a number JSON cannot hold. */
qd_status qd__render_json_status(const struct qd_json *j, const qd_buf *b, qd_status st);

/* What qd_render_eom prints: e's expressions, or at a state number nodes
 * in their place (eom_at.c). */
typedef struct qd__eom_view {
    qd_ctx *ctx;
    const qd_model *m;
    const char *source;
    const qd_eom *e;                /* n, q, qd, qdd */
    const qd_expr **M, **f;         /* n*n row-major, n */
    const qd_expr **acc;            /* n, or NULL when not solved */
    const qd_expr **A, **b;         /* ncon*n row-major, ncon: A q'' = b */
    const qd_expr **lambda;         /* ncon multipliers, or NULL */
    const qd_expr **R;              /* n constraint forces A^T lambda (at a state), or NULL */
    const qd_expr *T[3];            /* T2, T1, T0; NULL when L was given without T */
    bool split;                     /* T1 or T0 is not identically zero */
    const qd_render_opts *at;       /* at a state (&full), else NULL */
    qd_render_opts full;            /* the state with every parameter */
    /* At a state: the model's `reaction` statements that could be computed
     * (qd_eom_reaction), 3 components each, and the relative residual of each. */
    size_t nreact;
    const char **react_name;
    const qd_expr **react;
    double *react_res;
    const qd_expr **numbers;        /* the storage of M..R at a state */
} qd__eom_view;

/* Fill v with the numbers of e at the state o (QD_OK, or the error recorded
 * in ctx); qd__render_eom_view_free releases them. */
qd_status qd__render_eom_numbers(qd__eom_view *v, const qd_render_opts *o);
void qd__render_eom_view_free(qd__eom_view *v);

#endif

/*
 * qdot/state.h - a point of a model's state space, and its reader (issue 31).
 *
 * Every numeric evaluation in libqdot takes a list of symbols and their
 * values (qd_eval's syms/vals).  A qd_state is that list for a model, in the
 * one layout the library uses everywhere:
 *
 *   q_0 .. q_{n-1}, q'_0 .. q'_{n-1}, t, the parameters p_0 .. p_{np-1},
 *
 * then whatever a caller appends (the momenta of a model given by H, its
 * inputs, its generalized speeds).  The qd_slot_* functions name the slots,
 * so that no caller writes `2*n + 1 + i`.
 *
 * qd_state_read reads a state as the command line and Python give it,
 * "theta1=0.3, theta1'=-0.1, t=0, r=r0": a comma-separated list of
 * NAME=VALUE (a comma inside brackets separates nothing: f(1, 2)).  NAME
 * is a coordinate, a velocity (the coordinate with a prime), t (or the
 * model's `independent` name) or the name of any other slot (a parameter, a
 * momentum, an input, a speed).  VALUE is a constant expression in pi, e and
 * the parameters ("2*pi", "r0/2"), evaluated at the parameters' values.
 * Every error is an error record located in the text (offset and length:
 * a caret under the name or the value), and a misspelt name gets "did you
 * mean" the nearest one, as in a model file.
 */
#ifndef QDOT_STATE_H
#define QDOT_STATE_H

#include <stdbool.h>
#include <stddef.h>
#include "model.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- the layout -------------------------------------------------------------
 * nq is the number of coordinates of the state (a model's, or fewer when a
 * constraint eliminated some), np the number of parameters. */
static inline size_t qd_slot_coord(size_t nq, size_t j) { (void)nq; return j; }
static inline size_t qd_slot_velocity(size_t nq, size_t j) { return nq + j; }
static inline size_t qd_slot_time(size_t nq) { return 2 * nq; }
static inline size_t qd_slot_param(size_t nq, size_t i) { return 2 * nq + 1 + i; }
/* The slots of the layout itself: what a caller appends starts here. */
static inline size_t qd_slot_count(size_t nq, size_t np) { return 2 * nq + 1 + np; }

/* A model's state: n symbols and their values, the model's coordinates at
 * the front in the layout above.  The arrays come from the C library's
 * malloc (a caller may grow them with realloc and raise n, as
 * qd_state_append does, and free them with free). */
typedef struct qd_state {
    size_t n;
    const qd_expr **syms;
    double *vals;
} qd_state;

/* The layout's symbols into syms[0 .. qd_slot_count(n, np)): q[j], their
 * velocities (qd_jet(q[j], 1)), t and m's parameters, and the parameters'
 * values into vals at their slots (vals' other slots are not touched).  q
 * NULL: m's coordinates (n is then qd_model_ncoords(m)).  QD_ERR_ARG for a
 * parameter with no finite value, QD_ERR_NOMEM. */
QD_API qd_status qd_state_layout(qd_ctx *ctx, const qd_model *m, size_t n,
                                 const qd_expr *const *q, const qd_expr **syms, double *vals);

/* m's state: every coordinate, velocity and t at 0, every parameter at its
 * value.  *st is overwritten (free it with qd_state_free, also after a
 * failure). */
QD_API qd_status qd_state_init(qd_ctx *ctx, const qd_model *m, qd_state *st);
/* count more slots: syms[0 .. count), with vals (NULL: 0). */
QD_API qd_status qd_state_append(qd_ctx *ctx, qd_state *st, size_t count,
                                 const qd_expr *const *syms, const double *vals);
/* The coordinates' and velocities' values from m's `initial` (those it
 * does not give keep theirs), and a speed's for every slot that is one of
 * m's speeds. */
QD_API qd_status qd_state_initial(qd_ctx *ctx, const qd_model *m, qd_state *st);
/* The slot of sym, or st->n when it has none. */
QD_API size_t qd_state_find(const qd_state *st, const qd_expr *sym);
QD_API void qd_state_free(qd_state *st);

/* ---- reading -------------------------------------------------------------- */

/* What a state's reader takes (qd_state_read_opts.refuse, or'ed): a name of
 * a kind refused is an error that says what it is. */
enum {
    QD_STATE_VELOCITIES = 1u << 0, /* the point is at rest: coordinates only */
    QD_STATE_TIME = 1u << 1,
    QD_STATE_PARAMS = 1u << 2,     /* the parameters keep the model's values */
    QD_STATE_EXTRA = 1u << 3       /* the slots after the parameters */
};

typedef struct qd_state_read_opts {
    unsigned refuse;             /* kinds not taken (0: every slot) */
    /* The coordinates that are independent here (the equations' coordinates
     * when constraints eliminated others), or NULL: all.  A coordinate not
     * among them, or its velocity, is an error naming them. */
    const qd_expr *const *independent;
    size_t nindependent;
    /* Out, each n entries or NULL: given[i] true for each slot the text
     * names (the rest untouched); exact[i] the value as read, an exact
     * expression in the parameters (pi/6 stays pi/6). */
    bool *given;
    const qd_expr **exact;
} qd_state_read_opts;

/* Read text (above) into st->vals: the slots named take their values, the
 * others keep theirs.  Empty items ("a=1,") are allowed; a slot named twice
 * is an error.  QD_OK; else QD_ERR_ARG (or the reader's QD_ERR_PARSE, an
 * evaluation's QD_ERR_DIVZERO) with the context's error record located in
 * text, and st->vals partly written; QD_ERR_NOMEM.  opts may be NULL. */
QD_API qd_status qd_state_read(qd_ctx *ctx, const qd_model *m, qd_state *st, const char *text,
                               const qd_state_read_opts *opts);

/* The same list with a range for each value, "x=-1:1, theta=-pi:pi" (a
 * search box): the names resolved as qd_state_read resolves them (opts'
 * refusals and independent coordinates, "did you mean"), each range read by
 * qd_state_range into lo[slot] and hi[slot] (st->n entries each; the slots
 * not named untouched; opts->given marks the named ones, opts->exact is not
 * written).  An empty range (A >= B) or one wider than a double holds is an
 * error; every error is located in text.  st is only looked up. */
QD_API qd_status qd_state_read_ranges(qd_ctx *ctx, const qd_model *m, const qd_state *st,
                                      const char *text, const qd_state_read_opts *opts,
                                      double *lo, double *hi);

/* One value, text[start, start + len): a constant expression in pi, e and
 * m's parameters (m NULL: in pi and e alone), as qd_state_read reads a
 * VALUE, with errors located in text.  *exact the expression as read (a
 * number, or an expression in the parameters), *val its value at the
 * parameters' values: a number that has no finite double (1e400) is an
 * error, and so is a value that is not finite. */
QD_API qd_status qd_state_value(qd_ctx *ctx, const qd_model *m, const char *text, size_t start,
                                size_t len, const qd_expr **exact, double *val);

/* A range "A:B", text[start, start + len): A and B read as qd_state_value
 * reads a value (constant expressions in pi, e and m's parameters) into *a
 * and *b (the older "A..B" is read the same).  No colon outside brackets is
 * an error located at the span, as
 * every error of the values is located in text.  The order of A and B is
 * the caller's to check. */
QD_API qd_status qd_state_range(qd_ctx *ctx, const qd_model *m, const char *text, size_t start,
                                size_t len, double *a, double *b);

/* "NAME=A:B" (a scan's parameter and its range: qdot modes --scan): NAME,
 * blanks trimmed, into name (cap bytes, NUL-ended), the range after '='
 * read by qd_state_range into *a and *b.  No '=', an empty NAME or one of
 * cap bytes or more is QD_ERR_ARG located in text; the range's errors are
 * qd_state_range's.  NAME is not looked up: the caller knows what it may
 * be. */
QD_API qd_status qd_state_named_range(qd_ctx *ctx, const qd_model *m, const char *text,
                                      char *name, size_t cap, double *a, double *b);

/* A point "q = EXPR, ..." of the coordinates q[0, n) (a scan's --about:
 * the equations' coordinates, eliminated ones refused), read as
 * qd_state_read reads it on a copy of st's values (st unchanged), with
 * velocities, t, parameters and extra slots refused: at[j] the exact
 * expression read for q[j] (kept in the parameters: a scan evaluates it
 * at each value), 0 for a coordinate not named.  Errors as qd_state_read's,
 * located in text. */
QD_API qd_status qd_state_read_point(qd_ctx *ctx, const qd_model *m, const qd_state *st,
                                     const char *text, size_t n, const qd_expr *const *q,
                                     const qd_expr **at);

/* The end of the item that starts at text[i] of a comma-separated list:
 * the next comma outside brackets, or the end of text. */
QD_API size_t qd_state_item_end(const char *text, size_t i);

#ifdef __cplusplus
}
#endif

/* NULL (issue 30): a function of this header given NULL for a pointer it
 * needs does nothing and returns QD_ERR_ARG (recorded in ctx when ctx is
 * given), NULL, 0, false or NaN, as its return type has it; a void function
 * returns, and every _free accepts NULL. NULL is an accepted value, as
 * documented at the function, for: qd_state_layout (q); qd_state_append
 * (vals); qd_state_read (opts); qd_state_value (m); qd_state_named_range
 * (m). An array whose count is 0 may be NULL. */
#endif

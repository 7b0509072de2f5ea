/*
 * qdot/print.h - expressions as text, LaTeX, C and SymPy.
 *
 * Printers append to a qd_buf, a growable string the caller owns and may
 * reuse; qd_buf_free releases it.  A printer fails only when memory runs out.
 */
#ifndef QDOT_PRINT_H
#define QDOT_PRINT_H

#include <stddef.h>
#include "expr.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct qd_buf {
    char *s;      /* NUL-terminated; NULL until something is appended */
    size_t len;
    size_t cap;
    bool failed;  /* sticky: an append ran out of memory */
    const qd_allocator *alloc; /* NULL: the C library's (set before the first append) */
} qd_buf;

#define QD_BUF_INIT {NULL, 0, 0, false, NULL}
#define QD_BUF_WITH(a) {NULL, 0, 0, false, (a)}  /* memory from the allocator a */

QD_API void qd_buf_free(qd_buf *b);
QD_API void qd_buf_clear(qd_buf *b);          /* empties it, keeps the memory */
QD_API void qd_buf_puts(qd_buf *b, const char *s);
QD_API void qd_buf_putn(qd_buf *b, const char *s, size_t n);
QD_API void qd_buf_printf(qd_buf *b, const char *fmt, ...)
#ifdef __GNUC__
    __attribute__((format(printf, 2, 3)))
#endif
    ;
QD_API const char *qd_buf_str(const qd_buf *b); /* "" when empty */

/* x in the fewest significant digits that read back to the same double
 * (9.81, not 9.8100000000000005; 0.1 + 0.2 is 0.30000000000000004): the
 * shortest of %.15g, %.16g, %.17g (for a subnormal of any %.Ng), into
 * out (QD_DOUBLE_MAX bytes with the NUL); returns the length.  -0 is "-0",
 * infinities and NaN as printf writes them.  Pure: any thread may call it. */
#define QD_DOUBLE_MAX 40
QD_API size_t qd_double_format(char *out, double x);
/* The same appended to b. */
QD_API void qd_buf_put_double(qd_buf *b, double x);

/* The one digit rule for printing numbers (docs/design.md, "printed
 * numbers"; issue 31).  A number a program may read back (JSON, CSV, a value
 * the user gave, an expression evaluated at a state) keeps every digit:
 * qd_double_format.  A computed result shown to a reader (a root, an
 * eigenvalue or frequency, an iterated or extrapolated value) is printed by
 * qd_result_format: QD_RESULT_DIGITS significant digits (%.12g), and 0 when
 * |x| <= QD_RESULT_ZERO * scale, that is below the last digit shown of the
 * largest number printed with it, where only round-off lives (an eigenvalue
 * whose real part is 1e-17 against an imaginary part of 3 is on the axis).
 * scale is the magnitude of the numbers printed together (max |s| for the
 * parts of eigenvalues, max |q| for the coordinates of a point); scale <= 0
 * or NaN is 1, for a number of order one on its own.  -0 prints as 0,
 * infinities and NaN as printf writes them.  Returns the length written to
 * out (QD_DOUBLE_MAX bytes with the NUL).  Pure: any thread may call it. */
#define QD_RESULT_DIGITS 12
#define QD_RESULT_ZERO 1e-12
QD_API size_t qd_result_format(char *out, double x, double scale);
/* The same appended to b. */
QD_API void qd_buf_put_result(qd_buf *b, double x, double scale);

typedef enum qd_format {
    QD_FMT_TEXT,  /* the model language's syntax; qd_parse reads it back to the same node */
    QD_FMT_LATEX, /* q' as \dot{q}, q'' as \ddot{q} */
    QD_FMT_C,     /* a C99 expression over doubles (math.h) */
    QD_FMT_SYMPY  /* Python for SymPy; coordinates as functions of t */
} qd_format;

/* Append e in the given format. */
QD_API qd_status qd_print(qd_ctx *ctx, const qd_expr *e, qd_format fmt, qd_buf *out);

/* The name the time symbol t prints as in ctx from now on, for a model
 * whose independent variable is not time (`independent x`: x, Byerly ch.
 * IV): text and SymPy write x, y(x) and y(x).diff(x); LaTeX writes x and
 * primes, y' and y'', since dots would say d/dt.  The C printer keeps t:
 * generated functions take the independent variable as their argument t.
 * NULL or "t" restores t.  QD_ERR_ARG unless name is an identifier. */
QD_API qd_status qd_print_set_time_name(qd_ctx *ctx, const char *name);
/* That name: "t" unless set. */
QD_API const char *qd_print_time_name(const qd_ctx *ctx);

/* The lines a SymPy script needs before expressions printed with
 * QD_FMT_SYMPY that call user-named functions: `V = Function('V')` once per
 * name found in the n expressions (NULL entries are skipped), in name order.
 * A name the printer spells self-contained (Function('E')) needs none.
 * Symbols are the caller's to bind: it knows the coordinates and parameters. */
QD_API qd_status qd_print_sympy_functions(qd_ctx *ctx, size_t n, const qd_expr *const *exprs,
                                          qd_buf *out);

/* C for a block of n expressions: every subexpression used more than once is
 * hoisted into a `const double qd_tK = ...;` temporary (the prefix keeps them
 * apart from the model's names), then each output is assigned as
 * `<lhs[i]> = ...;`.  Symbols are printed by their names with
 * primes spelled _d, _dd (theta'' becomes theta_dd). */
QD_API qd_status qd_print_c_block(qd_ctx *ctx, size_t n, const qd_expr *const *exprs,
                           const char *const *lhs, qd_buf *out);

/* `qdot tour`: a one-minute tour of the kernel on the double pendulum
 * (positions read from text, velocities by d/dt, T expanded and simplified,
 * the mass matrix m2 l1 l2 cos(theta1 - theta2) by differentiation, its
 * LaTeX, SymPy and C forms, its value from a compiled program), appended to
 * out; it makes its symbols in ctx (coordinates theta1, theta2, parameters
 * m1, m2, l1, l2, g).  QD_OK, or the kernel's error recorded in ctx
 * (QD_ERR_NOMEM). src/sym/tour.c. */
QD_API qd_status qd_tour_print(qd_ctx *ctx, qd_buf *out);

/* The C identifier qdot uses for a symbol (theta' -> theta_d). */
QD_API qd_status qd_c_name(const qd_expr *sym, qd_buf *out);

#ifdef __cplusplus
}
#endif

/* NULL (issue 30): a function of this header given NULL for a pointer it
 * needs does nothing and returns QD_ERR_ARG (recorded in ctx when ctx is
 * given), NULL, 0, false or NaN, as its return type has it; a void function
 * returns, and every _free accepts NULL. NULL is an accepted value, as
 * documented at the function, for: qd_print (e). An array whose count is 0
 * may be NULL. Exception: qd_buf_str(NULL) is "". */
#endif

/*
 * qdot/certify.h - certified zero tests (issue 33): the one function every
 * yes/no verdict of qdot (canonical, bracket, integrals, hj, ...) asks
 * whether an expression that should vanish does.
 *
 * qd_zero_test first simplifies.  When the simplifier does not reduce the
 * expression to 0 it is evaluated in ball arithmetic (FLINT's Arb, 128 bits,
 * raised to 512 where a ball is too wide) at exact dyadic points: every
 * symbol gets a value k/16 with 3 <= k <= 29 (a positive symbol positive,
 * the others of either sign), chosen by a fixed pseudo-random sequence.  A
 * point where the expression is undefined (log or sqrt of a negative, a
 * division by a ball containing 0, asin outside [-1, 1]) is skipped, and so
 * is one outside the domain of e as given, where only its simplified form
 * is defined (sqrt(a) sqrt(b) simplified to sqrt(a b), at a, b < 0): a
 * witness's value is that of e.  The
 * result is tri-state:
 *   QD_ZERO_PROVEN   the simplifier reduced it to 0;
 *   QD_ZERO_NONZERO  a witness: at the point, the value's ball (midpoint
 *                    value, radius bound) excludes 0, so it is certainly not 0;
 *   QD_ZERO_NUMERIC  no witness: at each of `points` points the ball contains
 *                    0 with radius below 2^-(bits/2) (verified numerically,
 *                    not proved);
 *   QD_ZERO_UNKNOWN  could not decide: user functions with no definition,
 *                    more than QD_WITNESS_MAX symbols, or too few points
 *                    where the expression is defined.
 */
#ifndef QDOT_CERTIFY_H
#define QDOT_CERTIFY_H

#include <stddef.h>
#include "expr.h"
#include "json.h"

#ifdef __cplusplus
extern "C" {
#endif

#define QD_WITNESS_MAX 16     /* symbols a witness point can bind */
#define QD_ZERO_POINTS 12     /* points a QD_ZERO_NUMERIC verdict is checked at */

typedef enum qd_zero_kind {
    QD_ZERO_PROVEN,
    QD_ZERO_NONZERO,
    QD_ZERO_NUMERIC,
    QD_ZERO_UNKNOWN
} qd_zero_kind;

typedef struct qd_witness {
    size_t n;                          /* symbols bound */
    const qd_expr *sym[QD_WITNESS_MAX];
    double at[QD_WITNESS_MAX];         /* exact (dyadic) values */
    double value;                      /* the ball's midpoint, rounded to double */
    double radius;                     /* an upper bound of the ball's radius */
} qd_witness;

typedef struct qd_zero_result {
    qd_zero_kind kind;
    const qd_expr *simplified;  /* the expression after qd_simplify */
    qd_witness witness;         /* NONZERO: the point; else n = 0 */
    unsigned points;            /* NUMERIC: points checked (QD_ZERO_POINTS) */
    unsigned bits;              /* the precision used (bits of the midpoints) */
} qd_zero_result;

/* Is e zero wherever it is defined?  Writes the verdict to *out and returns
 * QD_OK; an error (reason in ctx) only when simplification fails. */
QD_API qd_status qd_zero_test(qd_ctx *ctx, const qd_expr *e, qd_zero_result *out);

/* Is e - target zero?  qd_zero_test of the difference; the witness value is
 * that of e - target. */
QD_API qd_status qd_equal_test(qd_ctx *ctx, const qd_expr *e, const qd_expr *target,
                               qd_zero_result *out);

/* "proven", "nonzero", "numeric" or "unknown": the JSON names of the kinds. */
QD_API const char *qd_zero_kind_name(qd_zero_kind k);

/* ---- a verdict's zero test written out (src/mech/certify_out.c) ---------- */

/* The witness of a QD_ZERO_NONZERO result z as one text line appended to
 * out, the point's values and the difference to 17 digits:
 *     "  witness: at q = 0.8125 the difference is 0.625 +- 0 (certified,
 *      128-bit ball arithmetic)\n"
 * ("at ..." left out when the point binds no symbol); nothing for the
 * other kinds. */
QD_API void qd_zero_result_print(qd_buf *out, const qd_zero_result *z);
/* How a QD_ZERO_NUMERIC result z is known, appended to out to end a
 * verdict's sentence: " (verified numerically at 12 points, 128 bits)";
 * nothing for the other kinds. */
QD_API void qd_zero_result_note(qd_buf *out, const qd_zero_result *z);
/* z as members of the JSON object j is writing: "certainty" (the kind's
 * name, qd_zero_kind_name), "witness" ({"point": {symbol: value, ...},
 * "value", "radius"} for NONZERO, else null), "points" (NUMERIC, else
 * null) and "bits".  A non-finite number marks j failed (qd_json_ok). */
QD_API void qd_zero_result_json(qd_json *j, const qd_zero_result *z);

#ifdef __cplusplus
}
#endif

/* NULL (issue 30): a function of this header given NULL for a pointer it
 * needs does nothing and returns QD_ERR_ARG (recorded in ctx when ctx is
 * given), NULL, 0, false or NaN, as its return type has it; a void function
 * returns, and every _free accepts NULL. NULL is an accepted value, as
 * documented at the function, for: none. An array whose count is 0 may be NULL. */
#endif

/*
 * tests/util/check.h - the assertions the model-level tests share: a model
 * that must parse, an expression that must equal a textbook formula, two
 * expressions equal at random points.
 */
#ifndef QT_CHECK_H
#define QT_CHECK_H

#include <stdbool.h>
#include "qdot/qdot.h"

/* Parse text; on failure the test fails with the located message. */
qd_model *qt_parse_ok(qd_ctx *ctx, const char *text);

/* e - want simplifies to 0 (want read with unknown names as new symbols);
 * else the test fails printing e. */
void qt_assert_is(qd_ctx *ctx, const qd_expr *e, const char *want);

/* a and b agree at npoints random values of their free symbols (each in
 * [lo, hi]) to rel relative to 1 + |a| + |b|; used where the simplifier may
 * write the same function two ways. */
bool qt_same_numeric(qd_ctx *ctx, const qd_expr *a, const qd_expr *b, double lo, double hi,
                     int npoints, double rel);

#endif

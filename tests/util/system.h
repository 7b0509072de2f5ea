/*
 * tests/util/system.h - a mechanical system for tests: a model text parsed
 * and its equations derived in a fresh context, kept in cmocka's state and
 * freed by qt_system_teardown.  A parse or derivation failure fails the test
 * with the diagnostic.
 */
#ifndef QT_SYSTEM_H
#define QT_SYSTEM_H

#include <stdbool.h>
#include "qdot/qdot.h"

typedef struct qt_system {
    qd_ctx *ctx;
    qd_model *model;
    qd_eom *eom;   /* NULL until derived */
} qt_system;

qt_system *qt_system_parse(void **state, const char *text);
qt_system *qt_system_derive(void **state, const char *text, bool eliminate);
int qt_system_teardown(void **state);
/* The symbol of that name (coordinate, velocity "q'", parameter, multiplier). */
const qd_expr *qt_symbol(const qt_system *s, const char *name);

#endif

/*
 * src/base/version.c - the loaded library's version (qdot/version.h).
 */
#include "qdot/version.h"

const char *qd_version(void) {
    return QDOT_VERSION;
}

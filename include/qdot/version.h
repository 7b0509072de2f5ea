/*
 * qdot/version.h - the version of libqdot.
 *
 * QDOT_VERSION is the version this header belongs to; qd_version() is the
 * version of the library actually loaded, so a program (or the Python
 * package, at import) can tell a header from one release used with the
 * library of another.  The shared library's soname is libqdot.so.0 while the
 * major version is 0.  This header is the one place the version is written:
 * CMakeLists.txt and setup.py read it from here.
 */
#ifndef QDOT_VERSION_H
#define QDOT_VERSION_H

#include "status.h" /* QD_API */

#define QDOT_VERSION "0.1.0"

#ifdef __cplusplus
extern "C" {
#endif

/* "0.1.0": QDOT_VERSION of the headers the library was built with. */
QD_API const char *qd_version(void);

#ifdef __cplusplus
}
#endif

/* NULL (issue 30): no function of this header takes a pointer. */
#endif

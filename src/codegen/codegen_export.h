/*
 * src/codegen/codegen_export.h - codegen's interface to the modules above
 * it (docs/design.md, "Architecture"), used by src/sim: the rewrite both
 * apply before compiling, so the generated C and the compiled programs
 * compute the same formulas, and the native compile-and-load step the
 * Taylor method's generated recurrences go through.  Internal (prefix
 * qd__cg_), not public: compiling arbitrary C text is not an API we offer
 * (qdot/codegen.h loads only what qdot generates).
 */
#ifndef QD_CODEGEN_CODEGEN_EXPORT_H
#define QD_CODEGEN_CODEGEN_EXPORT_H

#include <stdbool.h>
#include "qdot/expr.h"

/* Rewrite sin/cos of a difference or sum of two coordinates,
 * sin(a - b) = sin a cos b - cos a sin b, over the outputs exprs[0..n) in
 * place, when that leaves fewer sine and cosine calls in the whole set (the
 * n-link pendulum: n(n-1) calls become 2n).  *applied says whether it did. */
qd_status qd__cg_angle_sums(qd_ctx *ctx, size_t n, const qd_expr **exprs, bool *applied);

/* Compile text (one C file) into cache (NULL: qd_native_load's default)
 * unless its object is there, and dlopen it.  generator names the text's
 * kind and version (part of the hash).  path: the object's name; cached:
 * it was there.  QD_ERR_UNSUPPORTED when no compiler runs or it fails, or
 * the cache is not the user's alone (see native.c). */
qd_status qd__cg_native_object(qd_ctx *ctx, const char *text, const char *generator,
                            const char *cache, char path[4096], bool *cached, void **handle);

#endif

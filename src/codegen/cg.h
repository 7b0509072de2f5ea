/*
 * src/codegen/cg.h - what the code generator's files share.
 */
#ifndef QD_CODEGEN_CG_H
#define QD_CODEGEN_CG_H

#include "angles.h"
#include "qdot/codegen.h"

/* The C of e's equations.  embed: one self-contained file (the header's
 * declarations inlined, no #include "prefix.h"), as native loading compiles
 * it; otherwise c includes "<prefix>.h" and h (not NULL) receives it. */
qd_status qd__cg_emit(qd_ctx *ctx, const qd_model *m, const qd_eom *e, const char *prefix,
                      bool embed, qd_buf *c, qd_buf *h);

/* The generated file's dense solvers (LU with partial pivoting, Cholesky
 * with an LU fallback), for nk unknowns; appended to out. */
void qd__cg_solvers(qd_buf *out, size_t nk, bool cholesky);

/* The tables every generated file has for the model's parameters:
 * <P>_param_names (NULL-terminated) and <P>_par_default, the values; QD_ERR_ARG
 * (recorded) when a parameter has no value. */
qd_status qd__cg_param_tables(qd_ctx *ctx, const qd_model *m, const char *P, qd_buf *c);

/* Compile text (one C file) into cache (NULL: qd_native_load's default)
 * unless its object is there, and dlopen it.  generator names the text's
 * kind and version (part of the hash).  path: the object's name; cached:
 * it was there.  QD_ERR_UNSUPPORTED when no compiler runs or it fails, or
 * the cache is not the user's alone (see native.c). */
qd_status qd__native_object(qd_ctx *ctx, const char *text, const char *generator,
                            const char *cache, char path[4096], bool *cached, void **handle);

#endif

/*
 * src/model/model_export.h - model's interface to the modules above it
 * (docs/design.md, "Architecture"), used by src/field: the `field`
 * statement as the parser read it.  The parser reads the field's
 * statements with the rest of the language (one reader, one set of
 * messages); src/field derives the field equations and modes from them
 * and offers them publicly (qdot/field.h).  Internal (prefix qd__mdl_),
 * not public: the field's public face is qdot/field.h.
 */
#ifndef QD_MODEL_MODEL_EXPORT_H
#define QD_MODEL_MODEL_EXPORT_H

#include "qdot/expr.h"

/* A name is at most QD_MDL_NAME_MAX - 1 bytes (a longer one is refused
 * where it is read, parse.c), so a buffer of QD_MDL_NAME_MAX holds it whole. */
#define QD_MDL_NAME_MAX 128

/* `field y(x, t) on x = A .. B` with `Ldensity` and `boundary` (field.c):
 * a continuous system, read only by qd_field_parse (qdot/field.h). */
typedef struct qd__field {
    char *name, *space;        /* owned copies: y, x */
    const qd_expr *y, *yt, *yx, *x;  /* the symbols the density is written in */
    const qd_expr *ends[2];    /* the interval's ends, numbers */
    const qd_expr *density;    /* NULL until `Ldensity = ...`; as written */
    const qd_expr *density_num;/* the same with the parameters' values put in */
    int bc[2];                 /* -1 not given, else a qd_field_end */
} qd__field;

/* The field statement read into f (a field model, qd_field_parse). */
struct qd_field;
const qd__field *qd__mdl_field_data(const struct qd_field *f);

#endif

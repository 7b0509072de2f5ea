/*
 * src/model/parser.h - the model and the parser's shared state.
 *
 * The parser reads statements one line at a time and lowers every
 * expression straight into kernel nodes: a name must be defined before it is
 * used, so one pass suffices, and the model it fills holds only kernel
 * expressions (data flows one way: text -> symbols).
 */
#ifndef QD_MODEL_PARSER_H
#define QD_MODEL_PARSER_H

#include "qdot/model.h"
#include "lex.h"

/* A value of the language: a scalar, or a vector of three components. */
typedef struct value {
    bool vec;
    const qd_expr *c[3];   /* c[0] alone for a scalar */
    size_t off, len;       /* the source span it came from */
} value;

typedef struct def {
    const char *name;      /* interned by the kernel */
    value v;
    size_t off, len;
} def;

typedef struct where {
    char what[64];
    size_t off, len;
} where;

struct qd_model {
    qd_ctx *ctx;
    const char *text;
    const qd_expr **coords;
    size_t ncoords;
    const qd_expr **params, **pvals;
    size_t nparams;
    const char **funcs;        /* declared user functions */
    size_t nfuncs;
    def *defs;
    size_t ndefs;
    const qd_expr *T, *V, *U, *L, *D;
    const qd_expr **Q;         /* per coordinate */
    const qd_expr **init;      /* per coordinate: [2*i] value, [2*i+1] velocity */
    where *wheres;
    size_t nwheres;
    const char **con_names;    /* owned copies */
    const qd_expr **cons;      /* lhs - rhs */
    size_t ncons;
};

typedef struct parser {
    qd_ctx *ctx;
    lexer lx;
    qd_model *m;
    qd_diag *diag;
    bool failed;
    const char *defining;      /* the name whose definition is being read */
} parser;

/* expr.c */
bool parse_expr(parser *p, value *out);
bool parse_scalar(parser *p, const qd_expr **out, const char *what);

/* error.c: record the first error at a span. */
bool perr(parser *p, size_t off, size_t len, const char *hint, const char *fmt, ...)
#ifdef __GNUC__
    __attribute__((format(printf, 5, 6)))
#endif
    ;
bool perr_tok(parser *p, const char *hint, const char *fmt, ...)
#ifdef __GNUC__
    __attribute__((format(printf, 3, 4)))
#endif
    ;
/* The known name nearest to word (edit distance), or NULL if none is close. */
const char *nearest(const char *word, size_t n, const char *const *names, size_t count);
/* Every name usable in an expression (for suggestions); caller frees. */
const char **known_names(const parser *p, size_t *count);

/* model.c */
const def *model_find_def(const qd_model *m, const char *name, size_t n);
bool model_add_def(qd_model *m, const char *name, value v, size_t off, size_t len);
bool model_add_where(qd_model *m, const char *what, size_t off, size_t len);
int model_coord_index(const qd_model *m, const qd_expr *sym);
bool model_push(void **arr, size_t *n, size_t size, const void *item);

/* Is the name at src[off..off+n) equal to word? */
bool name_is(const char *src, size_t off, size_t n, const char *word);

#endif

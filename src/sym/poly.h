/*
 * src/sym/poly.h - sparse Laurent polynomials over generators, and the
 * expansion session built on them.
 *
 * A generator is a maximal non-polynomial subexpression (a symbol, a call,
 * a power with a non-integer exponent, the inverse of a sum, pi, ...),
 * known by its index in the session.  A polynomial is a list of terms; a
 * term is a numeric coefficient and a monomial, the (generator, exponent)
 * pairs sorted by generator with nonzero signed exponents, so x * x^-1
 * cancels like any other exponent.
 *
 * Coefficients are int64 while they fit, GMP rationals after an overflow or
 * a division, and doubles as soon as a float takes part (a float coefficient
 * makes its term float, as in the constructors).
 *
 * Errors (out of memory, an exponent or a size beyond the limits) are
 * recorded in the context and reported as a NULL polynomial.
 */
#ifndef QD_SYM_POLY_H
#define QD_SYM_POLY_H

#include "node.h"

enum { QD_COEF_INT, QD_COEF_BIG, QD_COEF_FLT };

/* A polynomial may not grow beyond this many terms (QD_ERR_TOOBIG). */
#define QD_POLY_MAX_TERMS 20000000u

/* A product or power is multiplied out only when a bound on its size
 * (terms x (term record + monomial + coefficient bytes)) stays within this
 * (QD_ERR_TOOBIG "expression too large"; expand.c keeps such a power of a
 * sum as it is).  docs/language.md, "expand". */
#define QD_EXPAND_MAX_BYTES (64 << 20)

typedef struct qd__coef {
    uint32_t kind;
    union {
        int64_t i;
        double f;
        uint32_t big; /* index into the owning polynomial's bigs */
    } v;
} qd__coef;

typedef struct qd__pvar {
    uint32_t var;
    int32_t exp;
} qd__pvar;

typedef struct qd__pterm {
    uint64_t hash;     /* of the monomial alone */
    uint32_t off, len; /* the monomial: pool[off .. off+len) */
    qd__coef c;
} qd__pterm;

typedef struct qd__poly {
    qd__pterm *terms;
    size_t n, cap;
    qd__pvar *pool;
    size_t plen, pcap;
    mpq_ptr *bigs;
    size_t nbig, bigcap;
} qd__poly;

void qd__poly_free(qd__poly *p);
qd__poly *qd__poly_zero(qd_ctx *ctx);
qd__poly *qd__poly_number(qd_ctx *ctx, const qd_expr *num); /* a rational or float node */
qd__poly *qd__poly_var(qd_ctx *ctx, uint32_t var, int32_t exp);
qd__poly *qd__poly_add_n(qd_ctx *ctx, size_t n, const qd__poly *const *ps);
qd__poly *qd__poly_mul(qd_ctx *ctx, const qd__poly *a, const qd__poly *b);
/* Bounds on the bytes x*y and a^n take (-1 when out of memory, recorded);
 * qd__poly_fits says whether a bound is within QD_EXPAND_MAX_BYTES, else
 * records QD_ERR_TOOBIG. */
double qd__poly_mul_bytes(qd_ctx *ctx, const qd__poly *x, const qd__poly *y);
double qd__poly_pow_bytes(qd_ctx *ctx, const qd__poly *a, long n);
bool qd__poly_fits(qd_ctx *ctx, double bytes);
/* a^n for n >= 0; negative n only for a single term (its inverse). */
qd__poly *qd__poly_pow(qd_ctx *ctx, const qd__poly *a, long n);
/* The terms of p in which var has exponent exp, with var removed. */
qd__poly *qd__poly_slice(qd_ctx *ctx, const qd__poly *p, uint32_t var, int32_t exp);
/* Append term t of src to dst, leaving out var (UINT32_MAX for none); the
 * caller keeps monomials distinct. */
bool qd__poly_append(qd_ctx *ctx, qd__poly *dst, const qd__poly *src, size_t t, uint32_t var);
/* Append a term with an integer coefficient; m sorted, its exponents nonzero,
 * and distinct from the monomials already in p. */
bool qd__poly_push_int(qd_ctx *ctx, qd__poly *p, const qd__pvar *m, uint32_t len, int64_t c);
/* The same with a rational coefficient (stored as an int64 when it is one). */
bool qd__poly_push_mpq(qd_ctx *ctx, qd__poly *p, const qd__pvar *m, uint32_t len, mpq_srcptr c);
/* x*y by FLINT (poly_flint.c) when that is the faster way; *done false when
 * it is not (nothing recorded, NULL), else the result (NULL on error). */
qd__poly *qd__poly_mul_flint(qd_ctx *ctx, const qd__poly *x, const qd__poly *y, bool *done);
/* a^n (n >= 2) the same way. */
qd__poly *qd__poly_pow_flint(qd_ctx *ctx, const qd__poly *a, long n, bool *done);
/* x*y by packed monomials (poly_pack.c), for the sizes between the general
 * loop and FLINT, when both fit; *done as above. */
qd__poly *qd__poly_mul_packed(qd_ctx *ctx, const qd__poly *x, const qd__poly *y, bool *done);
/* a^n (n >= 2) the same way. */
qd__poly *qd__poly_pow_packed(qd_ctx *ctx, const qd__poly *a, long n, bool *done);
/* The exponent of var in term t of p (0 when absent). */
int32_t qd__poly_exp(const qd__poly *p, size_t t, uint32_t var);
/* The coefficient of term t as a number node. */
const qd_expr *qd__poly_coef_node(qd_ctx *ctx, const qd__poly *p, size_t t);
bool qd__poly_coef_is_one(const qd__poly *p, size_t t);
bool qd__poly_coef_is_zero(const qd__poly *p, size_t t);

/* ---- expand.c: the expansion session ------------------------------------ */

typedef struct qd__xsess {
    qd_ctx *ctx;
    qd__ptrmap polys;    /* node -> its qd__poly (owned) */
    qd__ptrmap exprs;    /* node -> its expansion */
    qd__ptrmap genix;    /* generator node -> index + 1 */
    const qd_expr **gens;
    size_t ngens, gcap;
    qd__poly **owned;
    size_t nowned, ocap;
    struct qd__powslot *pows; /* cache of generator^k nodes */
    size_t powcap, powlen;
} qd__xsess;

void qd__xs_init(qd__xsess *s, qd_ctx *ctx);
void qd__xs_free(qd__xsess *s);
/* The polynomial of e (owned by the session), NULL on error. */
const qd__poly *qd__xs_poly(qd__xsess *s, const qd_expr *e);
/* The canonical node of p, itself fully expanded. */
const qd_expr *qd__xs_expr(qd__xsess *s, const qd__poly *p);
/* Keep p alive until the session ends (and free it then). */
bool qd__xs_own(qd__xsess *s, qd__poly *p);
/* The index of generator g, adding it when new; -1 on error. */
long qd__xs_gen(qd__xsess *s, const qd_expr *g);
/* The expansion of e. */
const qd_expr *qd__xs_expand(qd__xsess *s, const qd_expr *e);

#endif

/*
 * qdot/form.h - real quadratic forms: Lagrange's reduction to a sum of
 * squares and Sylvester's law of inertia (Desloge, Classical Mechanics,
 * App. 24-27); below them, any function's degree of homogeneity (App. 20)
 * and periods (App. 31).
 *
 * phi(x) = sum_ij a_ij x_i x_j with a symmetric (App. 27 eqs. 1-3).
 * Lagrange's reduction (App. 27 Thm 3) completes the square on a nonzero
 * diagonal element a_kk,
 *
 *     phi = a_kk (x_k + sum_{j != k} a_kj/a_kk x_j)^2 + phi',
 *
 * phi' free of x_k (a'_ij = a_ij - a_ik a_kj/a_kk), and when every
 * remaining diagonal element is 0 but a_ij is not, substitutes the pair
 * x_i = u + v, x_j = u - v (the book's y1 = x1 + x2, y2 = x1 - x2), which
 * makes the squares 2 a_ij (u^2 - v^2).  The result is exact:
 *
 *     phi = sum_k c_k y_k^2,     y_k linear forms in x, independent,
 *
 * with rational (or symbolic) c_k.  The c_k are not unique; by Sylvester's
 * law (App. 27 Thm 4) the numbers n+, n-, n0 of positive, negative and
 * zero coefficients are (n0 = n - rank).  A symbolic c_k whose sign is not
 * known leaves the inertia undecided (decided = false) rather than guessed;
 * a symbolic pivot is taken as nonzero unless it simplifies to 0 (the
 * reduction is then the generic one, and pivots lists the assumptions).
 */
#ifndef QDOT_FORM_H
#define QDOT_FORM_H

#include <stdbool.h>
#include <stddef.h>
#include "expr.h"
#include "certify.h"
#include "metric.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct qd_qform {
    size_t n;                 /* variables */
    const qd_expr **x;        /* n: the variables (the caller's symbols) */
    const qd_expr **a;        /* n*n, row-major, symmetric: phi = x^T a x */
    size_t nsq;               /* squares: the rank (generically, see pivots) */
    const qd_expr **coef;     /* nsq coefficients c_k */
    const qd_expr **lin;      /* nsq linear forms y_k in x (coefficient of the
                                 variable completed on: 1, or 1/2 after a pair) */
    size_t npos, nneg, nzero; /* inertia (n+, n-, n0), when decided */
    bool decided;             /* every c_k of known sign */
    const char *kind;         /* "positive definite", "negative definite",
                                 "positive semidefinite", "negative semidefinite",
                                 "indefinite", "zero"; NULL when undecided */
    bool paired;              /* the pair substitution was needed (App. 27 P16) */
} qd_qform;

/* Reduce phi, a homogeneous quadratic in the n variables x (symbols; no
 * linear or constant term, coefficients free of x): QD_ERR_ARG with a
 * message naming the offending term otherwise.  The reduction is checked:
 * phi - sum c_k y_k^2 must expand to 0 (QD_ERR_NUMERIC if not, which would
 * be a bug).  NULL on failure, reason in ctx; free with qd_qform_free. */
QD_API qd_qform *qd_qform_reduce(qd_ctx *ctx, const qd_expr *phi, size_t n,
                                 const qd_expr *const *x);

/* The same from the symmetric matrix a (n*n, row-major; QD_ERR_ARG when
 * not symmetric) with the names x for the variables. */
QD_API qd_qform *qd_qform_reduce_matrix(qd_ctx *ctx, size_t n, const qd_expr *const *a,
                                        const qd_expr *const *x);

QD_API void qd_qform_free(qd_qform *f);

/* The variables of a form read from text, "x, y, z" (names separated by
 * commas or spaces), as qd_qform_reduce takes them: each name is the
 * context's symbol of that name (made when new), in order, into
 * x[0 .. *n), at most cap.  On failure the context's error record is
 * located in text (qd_ctx_diag, a caret under the name): QD_ERR_ARG for a
 * name that is no symbol (a constant such as pi), one given twice, more
 * than cap, or none at all (the whole text); QD_ERR_NOMEM.  *n is 0 on
 * entry and counts the variables read. */
QD_API qd_status qd_qform_vars_read(qd_ctx *ctx, const char *text, const qd_expr **x,
                                    size_t cap, size_t *n);

/* ---- homogeneity (Desloge App. 20) ----------------------------------------
 * f(x_1..x_r, y) is homogeneous of degree n in x when f(lambda x, y) =
 * lambda^n f(x, y) for every lambda > 0 (App. 20 eq. 1; the other symbols y
 * are passive).  Euler's theorem (eq. 2) and its converse: that holds iff
 * sum_i x_i df/dx_i = n f identically (d/dlambda of lambda^-n f(lambda x)
 * is lambda^(-n-1) (sum x_i df/dx_i - n f)(lambda x)).  So the degree is
 * (sum x_i df/dx_i) / f when that is free of x, confirmed by the zero test
 * (qd_equal_test, qdot/certify.h); when it is not, any homogeneous f has
 * f(x) f(4x) = f(2x)^2 (both 4^n f(x)^2), and a point where they certainly
 * differ (f, f(2x) and f(4x) each defined there and evaluated in ball
 * arithmetic at the points qd_zero_test would pick) is the witness that f is
 * not homogeneous.  When neither holds the
 * degree is estimated as log2(f(2x)/f(x)) at a point, rounded to p/q
 * (q <= 12) and confirmed the same way, or the verdict is undecided. */
typedef enum qd_homog_verdict {
    QD_HOMOG_YES,       /* homogeneous of degree `degree` */
    QD_HOMOG_EVERY,     /* f is 0: homogeneous of every degree */
    QD_HOMOG_NO,        /* not homogeneous: test.witness the point where
                           f(x) f(4x) - f(2x)^2 (probe) is certainly not 0 */
    QD_HOMOG_UNDECIDED  /* neither: a ratio that does not simplify, no witness */
} qd_homog_verdict;

typedef struct qd_homog {
    qd_homog_verdict verdict;
    const qd_expr *f;      /* f simplified */
    const qd_expr *euler;  /* sum_i x_i df/dx_i, simplified */
    const qd_expr *degree; /* YES: n, free of x (a number, or in the passive
                              symbols: x^a has degree a); else NULL */
    const qd_expr *probe;  /* f(x) f(4x) - f(2x)^2 when it was tested, else NULL */
    qd_zero_result test;   /* YES: the test of euler - n f (proven or numeric);
                              NO: of probe, with its witness; UNDECIDED: the
                              last test made (kind UNKNOWN when none) */
} qd_homog;

/* The homogeneity of f in the n variables x (symbols, none twice) into *out,
 * as above; the other symbols of f are passive.  QD_ERR_ARG for no
 * variables or one that is not a symbol; errors of simplification.  *out
 * holds expressions of ctx only (nothing to free). */
QD_API qd_status qd_homogeneity(qd_ctx *ctx, const qd_expr *f, size_t n,
                                const qd_expr *const *x, qd_homog *out);

/* "homogeneous", "every degree", "not homogeneous", "undecided": the
 * verdict in words (JSON "verdict"). */
QD_API const char *qd_homog_verdict_name(qd_homog_verdict v);

/* ---- multiply periodic functions (Desloge App. 31) ------------------------
 * f(x, y) is periodic in x with the period w when f(x + w, y) = f(x, y) for
 * every x (eq. 1).  Integer combinations of periods are periods (Thms 1-3),
 * and the periods have a fundamental system w(1..k), k <= r, of which every
 * period is an integer combination (Thm 4, eq. 3).  For g given vectors w_j
 * whose components are all rational multiples of one constant (the unit:
 * 2 pi, pi, 1, ...), qd_periods_reduce finds that system for the lattice
 * they generate: a basis by integer row reduction (Hermite's normal form of
 * the integer matrix w L / unit), and each w_j's integer coordinates in it.
 * With f given, each w_j is also tested as a period of f (qd_zero_test of
 * f(x + w_j) - f(x)). */
typedef struct qd_periods {
    size_t g, r;              /* vectors given, variables */
    const qd_expr *unit;      /* every component is a rational multiple of it */
    size_t rank;              /* the fundamental system's size k <= min(g, r) */
    const qd_expr **basis;    /* rank * r, row-major, in Hermite's normal form
                                 (the first nonzero component of each positive) */
    long *coords;             /* g * rank: w_j = sum_k coords[j rank + k] basis_k */
    bool tested;              /* f was given */
    qd_zero_result *test;     /* g: f(x + w_j) - f(x) zero-tested, when tested */
} qd_periods;

/* The fundamental system of the n-vectors w (g of them, row-major g * n:
 * w[j n + i] the shift of x_i) and, when f is not NULL, the test of each as
 * a period of f in the variables x.  QD_ERR_ARG for a component that is not
 * a rational multiple of the unit (the first nonzero component), naming
 * both; QD_ERR_TOOBIG when the integers outgrow a long.  NULL on failure,
 * reason in ctx; free with qd_periods_free. */
QD_API qd_periods *qd_periods_reduce(qd_ctx *ctx, const qd_expr *f, size_t n,
                                     const qd_expr *const *x, size_t g,
                                     const qd_expr *const *w);
QD_API void qd_periods_free(qd_periods *p);

/* Vectors of n components from text: "2*pi, 0; 0, 2*pi" (vectors separated
 * by ';', components by ','), each component an expression, into a new
 * array of *g * n expressions (*out; the caller frees it with
 * qd_periods_vectors_free).  QD_ERR_PARSE or QD_ERR_ARG (a vector of
 * another length, none given) located in text (qd_ctx_diag). */
QD_API qd_status qd_periods_vectors_read(qd_ctx *ctx, const char *text, size_t n, size_t *g,
                                         const qd_expr ***out);
QD_API void qd_periods_vectors_free(const qd_expr **w);

/* ---- Gram-Schmidt orthogonalization (Desloge App. 21) ---------------------
 * s linearly independent vectors a(1..s) of n components, and a symmetric
 * n x n matrix T (NULL: the identity), give
 *
 *     b(1) = a(1),   b(r) = a(r) - sum_{j<r} [a(r)^T T b(j) / b(j)^T T b(j)] b(j)
 *
 * (Thm 2, eqs. 3a-3b; with T the identity Thm 1, eqs. 1a-1b), vectors that
 * span the same space with b(i)^T T b(j) = 0 for i != j (eq. 4).  Exact in
 * rational or symbolic entries; eq. 4 is checked afterwards by the zero
 * test (qdot/certify.h).  The kinetic metric as T orthogonalizes the
 * coordinate tangents (`qdot metric --gram-schmidt`); the mass matrix, the
 * modal vectors of a repeated frequency (Desloge ch. 65). */
typedef struct qd_gram {
    size_t n, s;              /* components, vectors */
    bool euclidean;           /* T was NULL or the identity (Thm 1) */
    const qd_expr **a;        /* s * n: the given vectors, simplified */
    const qd_expr **b;        /* s * n: the orthogonal ones, row-major */
    const qd_expr **norm;     /* s: b(r)^T T b(r) */
    const qd_expr **coef;     /* s * s: coef[r s + j] = a(r)^T T b(j) / b(j)^T T b(j)
                                 for j < r, 0 for j >= r: a(r) = b(r) + sum_j coef b(j) */
    qd_zero_kind check;       /* eq. 4's zero tests: QD_ZERO_PROVEN for all, or
                                 QD_ZERO_NUMERIC when one was verified numerically */
} qd_gram;

/* The orthogonalization above of the s vectors a (row-major s * n) under T
 * (n * n, row-major, or NULL).  NULL on failure, reason in ctx: QD_ERR_ARG
 * for no vectors, more than n, an asymmetric T, or an a(r) that is a
 * linear combination of those before it (b(r) = 0, named); QD_ERR_SINGULAR
 * for a b(r) != 0 with b(r)^T T b(r) = 0 (T not definite: the process
 * divides by it).  Free with qd_gram_free. */
QD_API qd_gram *qd_gram_schmidt(qd_ctx *ctx, size_t n, const qd_expr *const *T, size_t s,
                                const qd_expr *const *a);
QD_API void qd_gram_free(qd_gram *g);

/* ---- the Fourier series of a trigonometric polynomial (App. 31, ch. 79) ---
 * A multiply periodic function of angles x (App. 31; the angle variables of
 * ch. 79) written as a sum of harmonics,
 *
 *     f = sum_k a_k cos(k.x) + b_k sin(k.x),
 *
 * exactly, when f is a polynomial in cos and sin of linear combinations of
 * the x with coefficients free of them: products and powers are linearized
 * (cos a cos b = [cos(a - b) + cos(a + b)]/2, ...) and phases moved into the
 * coefficients; k and -k are one harmonic, the constant term has k = 0 and
 * b = 0.  The sum is checked against f by the zero test.  Any other f (a
 * ratio of trigonometric functions, a power series) is refused: its series
 * is infinite, and no numeric series is computed. */
typedef struct qd_fourier_term {
    const qd_expr *arg;       /* k.x */
    const qd_expr **k;        /* n: the wave vector, d(arg)/dx_i */
    const qd_expr *a, *b;     /* a cos(arg) + b sin(arg) */
} qd_fourier_term;

typedef struct qd_fourier {
    size_t n, nterms;
    qd_fourier_term *terms;   /* nterms, in the order they were made */
    const qd_expr **k;        /* the terms' wave vectors' storage */
    qd_zero_kind check;       /* the sum against f: QD_ZERO_PROVEN or QD_ZERO_NUMERIC */
} qd_fourier;

/* The series of f in the n variables x.  NULL on failure, reason in ctx:
 * QD_ERR_ARG for a variable that is not a symbol or an f that is not a
 * trigonometric polynomial in them (a power above 64 included), QD_ERR_TOOBIG
 * for more than 4096 harmonics.  Free with qd_fourier_free. */
QD_API qd_fourier *qd_fourier_series(qd_ctx *ctx, const qd_expr *f, size_t n,
                                     const qd_expr *const *x);
QD_API void qd_fourier_free(qd_fourier *f);

/* ---- change of variables in an integral (Desloge App. 19) -----------------
 * The n old variables x given in terms of n new ones y, x = x(y), have the
 * Jacobian matrix dx_i/dy_j and determinant J(x/y), with J(y/x) = 1/J(x/y)
 * (App. 18), and where J does not vanish
 *
 *     int_R f(x) dx = int_R' f(x(y)) |J(x/y)| dy        (App. 19 eq. 1),
 *
 * the limits chosen so that both volumes are positive.  Where J vanishes
 * the map is not invertible and J may change sign, and the region must be
 * split there (p. 913): the zero set of J, factor by factor, as the
 * metric's chart has it (r = 0; theta = 0 + k pi).  |J| is J or -J when
 * J's form shows its sign (positive symbols, even powers: qd_symbol_positive
 * makes a new variable or a parameter positive), else abs(J).  Desloge ch. 60
 * eq. 6 (s = s(theta), psi = phi: sigma = s/sin(theta) |ds/dtheta|) is such
 * a change. */
typedef struct qd_change {
    size_t n;
    const qd_expr **x, **y, **map;  /* n each: old and new variables, x_i(y) simplified */
    const qd_expr **jac;            /* n*n row-major: dx_i/dy_j */
    const qd_expr *det, *inverse;   /* J(x/y) and J(y/x) = 1/J(x/y) */
    int sign;                       /* 1: J >= 0 by its form, -1: J <= 0, 0: not known */
    const qd_expr *absdet;          /* |J|: J, -J, or abs(J) when the sign is not known */
    const qd_expr *f, *integrand;   /* f(x) and f(x(y)) |J| (NULL when no f was given) */
    size_t nsing;                   /* the zero set of J, in the new variables */
    qd_metric_singular *sing;
} qd_change;

/* The change x = map(y) (n each; map free of x) with f (NULL: none) into a
 * new qd_change.  NULL on failure, reason in ctx: QD_ERR_ARG for a variable
 * that is not a symbol or is given twice, or a map that depends on an old
 * variable; QD_ERR_SINGULAR when J is identically 0.  Free with
 * qd_change_free. */
QD_API qd_change *qd_change_vars(qd_ctx *ctx, const qd_expr *f, size_t n,
                                 const qd_expr *const *x, const qd_expr *const *y,
                                 const qd_expr *const *map);
QD_API void qd_change_free(qd_change *c);

/* The map read from text, "x = r*cos(th), y = r*sin(th)" (items split at
 * the commas outside brackets, qd_state_item_end; a trailing comma ends the
 * list): map[i] is the expression given for x[i] (unknown names become
 * plain symbols, so the new variables are made here unless made before).
 * On failure the context's error record is located in text (qd_ctx_diag):
 * QD_ERR_ARG for an item without '=', a name that is not among x or is given
 * twice (a caret under it), an x not given (the whole text); the reader's
 * status for an expression. */
QD_API qd_status qd_change_read(qd_ctx *ctx, const char *text, size_t n,
                                const qd_expr *const *x, const qd_expr **map);

/* Names read as qd_qform_vars_read reads them, each made a symbol assumed
 * positive (qd_symbol_positive: abs(r) is r) unless it is one already:
 * `qdot form --positive "r, b"`.  QD_ERR_ARG located at a name that is
 * already a symbol of either sign (its sign is fixed when it is made) or
 * is not a name. */
QD_API qd_status qd_qform_positive_read(qd_ctx *ctx, const char *text, const qd_expr **x,
                                        size_t cap, size_t *n);

#ifdef __cplusplus
}
#endif

/* NULL (issue 30): a function of this header given NULL for a pointer it
 * needs does nothing and returns QD_ERR_ARG (recorded in ctx when ctx is
 * given), NULL, 0, false or NaN, as its return type has it; a void function
 * returns, and every _free accepts NULL. NULL is an accepted value, as
 * documented at the function, for: qd_periods_reduce (f), qd_gram_schmidt (T), qd_change_vars (f). An array whose
 * count is 0 may be NULL. */
#endif

/*
 * qdot/expr.h - the symbolic kernel: contexts and expressions.
 *
 * Ownership in one sentence: a qd_ctx owns every expression made in it, an
 * expression lives until its context is freed, and nothing else is ever freed
 * one by one.
 *
 * Expressions are immutable nodes of a DAG and are hash-consed: two
 * structurally equal expressions made in one context are the same node, so
 * equality is pointer equality (a == b) and a shared subexpression is stored
 * once.  Every constructor returns the canonical form (flattened, sorted,
 * like terms and factors combined, numbers folded; docs/design.md lists the
 * rules), so x + y and y + x are one node.
 *
 * Errors: constructors return NULL when they fail (out of memory, an exact
 * division by zero) and record the reason in the context; a NULL argument
 * gives a NULL result, so a chain of calls needs one check at the end.
 */
#ifndef QDOT_EXPR_H
#define QDOT_EXPR_H

#include <stddef.h>
#include <stdint.h>
#include <stdbool.h>
#include "status.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct qd_ctx qd_ctx;
typedef struct qd_expr qd_expr; /* always handled as const qd_expr * */

/* ---- contexts ---------------------------------------------------------- */

QD_API qd_ctx *qd_ctx_new(void);                /* NULL when out of memory */
QD_API void qd_ctx_free(qd_ctx *ctx);           /* frees every expression; NULL is fine */

/* The memory a context and everything made in it come from (SQLite's
 * sqlite3_mem_methods, but per context: no global state).  The library's
 * allocations go through these three functions (docs/design.md lists the few
 * that cannot reach a context); one that fails makes the
 * call in progress return QD_ERR_NOMEM, with nothing leaked.  realloc_fn and
 * free_fn are never given NULL.  The allocator must outlive the context and
 * every object made with it (results are freed through it, after the context
 * if need be); what malloc_fn and realloc_fn return must be aligned as
 * malloc's.  GMP's and FLINT's large requests (1024 bytes or more) in
 * expansion, cancelling, factoring and number folding are asked of this
 * allocator first, and a refusal gives QD_ERR_NOMEM; their memory itself
 * and LAPACK's come from elsewhere (docs/design.md, "Allocation and
 * out-of-memory"). */
typedef struct qd_allocator {
    void *(*malloc_fn)(void *user, size_t size);
    void *(*realloc_fn)(void *user, void *p, size_t size);
    void (*free_fn)(void *user, void *p);
    void *user;
} qd_allocator;

QD_API qd_ctx *qd_ctx_new_with(const qd_allocator *a); /* a NULL: the C library's */

QD_API qd_status qd_ctx_status(const qd_ctx *ctx);     /* first error since the last clear */
QD_API const char *qd_ctx_message(const qd_ctx *ctx);  /* its message, "" when none */
QD_API const qd_diag *qd_ctx_diag(const qd_ctx *ctx);  /* its whole record (status.h) */
QD_API void qd_ctx_clear_error(qd_ctx *ctx);
/* Record an error (used by the library's own modules; first error wins). */
QD_API void qd_ctx_error(qd_ctx *ctx, qd_status st, const char *fmt, ...)
#ifdef __GNUC__
    __attribute__((format(printf, 3, 4)))
#endif
    ;
/* Say what the error just recorded is about, and what to do (hint may be
 * NULL); name may be NULL.  Only the first error's first subject is kept. */
QD_API void qd_ctx_error_about(qd_ctx *ctx, qd_subject subject, size_t index, const char *name,
                               qd_reason why, const char *hint);
/* Locate the error just recorded at text[offset, offset + length), when it is
 * not located yet. */
QD_API void qd_ctx_error_at(qd_ctx *ctx, const char *text, size_t offset, size_t length);
QD_API size_t qd_ctx_node_count(const qd_ctx *ctx);    /* distinct nodes made so far */

/* The progress of a long computation that has no parameter of its own for
 * it (today the multistart search for equilibria, qdot/equilibria.h, which
 * `qdot modes` and `qdot stability` run when no point is given): fn(data,
 * what, done, total) is called on the computing thread with what is being
 * done ("equilibria: multistart"), done of total steps, once a step; a
 * nonzero return stops the computation, which fails with QD_ERR_ARG
 * ("stopped").  One per context, as SQLite's sqlite3_progress_handler is
 * one per connection; fn NULL turns it off.  The library never prints: a
 * program draws the bar (the CLI on a terminal only, past one second). */
typedef int (*qd_progress_fn)(void *data, const char *what, size_t done, size_t total);
QD_API void qd_ctx_set_progress(qd_ctx *ctx, qd_progress_fn fn, void *data);

/* ---- node kinds --------------------------------------------------------- */

typedef enum qd_kind {
    QD_RATIONAL, /* exact rational of any size */
    QD_FLOAT,    /* inexact double */
    QD_CONSTANT, /* pi or e */
    QD_SYMBOL,   /* t, a coordinate or one of its time derivatives, a parameter, a plain symbol */
    QD_FUNC,     /* a built-in function of one or two arguments */
    QD_UFUNC,    /* a user-named function V(r, ...) */
    QD_UDERIV,   /* a partial derivative of a user-named function, V'(r) */
    QD_POW,      /* base^exponent: args[0]^args[1] */
    QD_MUL,      /* product: optional numeric coefficient first, then factors */
    QD_ADD       /* sum: optional numeric constant first, then terms */
} qd_kind;

typedef enum qd_func {
    QD_SIN, QD_COS, QD_TAN, QD_ASIN, QD_ACOS, QD_ATAN, QD_ATAN2,
    QD_SINH, QD_COSH, QD_TANH, QD_EXP, QD_LOG, QD_ABS, QD_SIGN,
    QD_STEP,     /* Heaviside's step: 0 for x < 0, 1/2 at 0 (as SymPy's Heaviside), 1 for x > 0 */
    QD_FUNC_COUNT
} qd_func;

typedef enum qd_constant { QD_PI, QD_E } qd_constant;

typedef enum qd_role {
    QD_ROLE_PLAIN, /* a symbol with no meaning to mechanics */
    QD_ROLE_TIME,  /* the time t */
    QD_ROLE_COORD, /* a generalized coordinate q (order 0) or its derivative q', q'', ... */
    QD_ROLE_PARAM  /* a named constant */
} qd_role;

/* ---- numbers and constants --------------------------------------------- */

QD_API const qd_expr *qd_int(qd_ctx *ctx, long v);
QD_API const qd_expr *qd_rat(qd_ctx *ctx, long num, long den);  /* den == 0: QD_ERR_DIVZERO */
/* An exact number from text: "12", "-3/4", "2.5" (= 5/2), "1e-3" (= 1/1000). */
QD_API const qd_expr *qd_rat_str(qd_ctx *ctx, const char *text);
QD_API const qd_expr *qd_float(qd_ctx *ctx, double v);          /* NaN and infinities refused */
QD_API const qd_expr *qd_const(qd_ctx *ctx, qd_constant c);

/* ---- symbols -------------------------------------------------------------
 * A name belongs to one symbol per context: asking again for the same name
 * and role returns the same node; asking with another role is QD_ERR_ARG.
 * Coordinates are functions of the time; their derivatives are symbols of
 * their own (the jet), named with primes: qd_jet(ctx, q, 2) is "q''".
 */
QD_API const qd_expr *qd_symbol(qd_ctx *ctx, const char *name);
QD_API const qd_expr *qd_param(qd_ctx *ctx, const char *name);
/* A plain symbol (role QD_ROLE_PLAIN) or parameter (QD_ROLE_PARAM) assumed
 * positive: abs(m) is m, sqrt(m^2) is m.  Symbols are otherwise real of either
 * sign.  The assumption is fixed when the symbol is made: asking for it later
 * by name with qd_symbol or qd_param finds it, while assuming positive a
 * symbol already made without it is QD_ERR_ARG. */
QD_API const qd_expr *qd_symbol_positive(qd_ctx *ctx, const char *name, qd_role role);
QD_API bool qd_symbol_is_positive(const qd_expr *e);
QD_API const qd_expr *qd_time(qd_ctx *ctx);                         /* the symbol "t" */
QD_API const qd_expr *qd_coord(qd_ctx *ctx, const char *name);
QD_API const qd_expr *qd_jet(qd_ctx *ctx, const qd_expr *coord, unsigned order);
QD_API const qd_expr *qd_lookup(const qd_ctx *ctx, const char *name); /* NULL when unknown */

/* ---- arithmetic (all return canonical forms) ---------------------------- */

QD_API const qd_expr *qd_add(qd_ctx *ctx, const qd_expr *a, const qd_expr *b);
QD_API const qd_expr *qd_sub(qd_ctx *ctx, const qd_expr *a, const qd_expr *b);
QD_API const qd_expr *qd_mul(qd_ctx *ctx, const qd_expr *a, const qd_expr *b);
QD_API const qd_expr *qd_div(qd_ctx *ctx, const qd_expr *a, const qd_expr *b);
QD_API const qd_expr *qd_neg(qd_ctx *ctx, const qd_expr *a);
QD_API const qd_expr *qd_pow(qd_ctx *ctx, const qd_expr *base, const qd_expr *exponent);
QD_API const qd_expr *qd_powi(qd_ctx *ctx, const qd_expr *base, long exponent);
QD_API const qd_expr *qd_sqrt(qd_ctx *ctx, const qd_expr *a);   /* a^(1/2) */
QD_API const qd_expr *qd_add_n(qd_ctx *ctx, size_t n, const qd_expr *const *terms);
QD_API const qd_expr *qd_mul_n(qd_ctx *ctx, size_t n, const qd_expr *const *factors);

/* Built-in functions: one argument, or two for QD_ATAN2 (y, x). */
QD_API const qd_expr *qd_fn(qd_ctx *ctx, qd_func f, const qd_expr *a);
QD_API const qd_expr *qd_fn2(qd_ctx *ctx, qd_func f, const qd_expr *a, const qd_expr *b);
QD_API const char *qd_func_name(qd_func f);                 /* "sin", "atan2", ... */
QD_API bool qd_func_from_name(const char *name, qd_func *out); /* also accepts nothing else */

/* A user-named function f(args...): an unknown function of its arguments. */
QD_API const qd_expr *qd_ufunc(qd_ctx *ctx, const char *name, size_t n, const qd_expr *const *args);
/* The partial derivative of f with respect to argument slots (0-based, sorted
 * on construction; nslots >= 1), evaluated at args: d^k f / d x_s1 ... d x_sk. */
QD_API const qd_expr *qd_uderiv(qd_ctx *ctx, const char *name, size_t nslots, const unsigned *slots,
                         size_t n, const qd_expr *const *args);

/* ---- inspection ---------------------------------------------------------- */

QD_API qd_kind qd_expr_kind(const qd_expr *e);
QD_API size_t qd_expr_nargs(const qd_expr *e);
QD_API const qd_expr *qd_expr_arg(const qd_expr *e, size_t i);
QD_API uint64_t qd_expr_hash(const qd_expr *e);  /* deterministic: the same in every run */
/* The canonical total order (<0, 0, >0); 0 only for the same node. */
QD_API int qd_expr_cmp(const qd_expr *a, const qd_expr *b);

QD_API const char *qd_expr_name(const qd_expr *e);  /* symbol, user function or derivative name */
QD_API qd_role qd_symbol_role(const qd_expr *e);
QD_API unsigned qd_symbol_order(const qd_expr *e);           /* 0 for q, 1 for q', ... */
QD_API const qd_expr *qd_symbol_coord(const qd_expr *e);     /* q for q'' (coordinates only) */
QD_API qd_func qd_expr_func(const qd_expr *e);
QD_API qd_constant qd_expr_constant(const qd_expr *e);
QD_API size_t qd_uderiv_nslots(const qd_expr *e);
QD_API unsigned qd_uderiv_slot(const qd_expr *e, size_t i);

QD_API bool qd_is_number(const qd_expr *e);        /* rational or float */
QD_API bool qd_is_zero(const qd_expr *e);          /* exact 0 or 0.0 */
QD_API bool qd_is_one(const qd_expr *e);           /* exact 1 */
QD_API bool qd_is_integer(const qd_expr *e);       /* exact integer */
QD_API int qd_number_sign(const qd_expr *e);       /* -1, 0, 1 for numbers */
QD_API double qd_number_value(const qd_expr *e);   /* numbers only */
/* An exact rational that fits: num/den in lowest terms, den > 0. */
QD_API bool qd_rational_get(const qd_expr *e, long *num, long *den);
/* Decimal text of a rational, "p" or "p/q", in a string owned by the context. */
QD_API const char *qd_rational_str(qd_ctx *ctx, const qd_expr *e);

/* Does e contain the node x anywhere? */
QD_API bool qd_has(const qd_expr *e, const qd_expr *x);
/* The symbols in e, in canonical order, written to out (at most cap); returns
 * how many there are (which may exceed cap); 0 with QD_ERR_NOMEM in the
 * context when out of memory. */
QD_API size_t qd_free_symbols(qd_ctx *ctx, const qd_expr *e, const qd_expr **out, size_t cap);

/* ---- operations ----------------------------------------------------------- */

/* Partial derivative with respect to a symbol of any role. */
QD_API const qd_expr *qd_diff(qd_ctx *ctx, const qd_expr *e, const qd_expr *sym);
QD_API const qd_expr *qd_diff_n(qd_ctx *ctx, const qd_expr *e, const qd_expr *sym, unsigned n);
/* Total time derivative over the jet: d/dt = d/dt|explicit + sum q' d/dq + q'' d/dq' + ... */
QD_API const qd_expr *qd_dt(qd_ctx *ctx, const qd_expr *e);

/* Simultaneous substitution of n nodes (usually symbols) by expressions. */
QD_API const qd_expr *qd_subs(qd_ctx *ctx, const qd_expr *e, size_t n,
                       const qd_expr *const *from, const qd_expr *const *to);

/* Distribute products over sums and expand integer powers of sums, also
 * inside function arguments. */
QD_API const qd_expr *qd_expand(qd_ctx *ctx, const qd_expr *e);
/* What qd_expand left as it was in its result e, so that a caller can say
 * so instead of handing back an expression that looks unexpanded: the
 * first positive integer power of a sum in e (one whose expansion would
 * exceed 64 MiB, or whose exponent is past 2^24: docs/cli.md,
 * "qdot expand"), or NULL when there is none.  NULL also when ctx runs out of
 * memory (recorded). */
QD_API const qd_expr *qd_expand_kept(qd_ctx *ctx, const qd_expr *e);

/* For e linear in the n symbols xs: e = sum_i coeffs[i]*xs[i] + *rest, with no
 * xs left in coeffs or rest.  QD_ERR_NONLINEAR (and NULLs) otherwise.  This is
 * how a mass matrix is read off the accelerations. */
QD_API qd_status qd_linear_coeffs(qd_ctx *ctx, const qd_expr *e, size_t n, const qd_expr *const *xs,
                           const qd_expr **coeffs, const qd_expr **rest);
/* The coefficient of x^k in the expansion of e (k may be 0). */
QD_API const qd_expr *qd_coeff(qd_ctx *ctx, const qd_expr *e, const qd_expr *x, long k);
/* e written as a polynomial in x: sum_k c_k x^k with each c_k gathered. */
QD_API const qd_expr *qd_collect(qd_ctx *ctx, const qd_expr *e, const qd_expr *x);

/* The simplifier: expansion, trigonometric identities (sin^2 + cos^2 = 1,
 * products of sines and cosines to sines and cosines of sums and differences
 * where that is shorter), common factors pulled out of sums, common
 * polynomial factors cancelled in quotients, and sums (or the groups of their
 * terms over one denominator) factored over the integers where that is
 * shorter.  Keeps the value everywhere the input is defined. */
QD_API const qd_expr *qd_simplify(qd_ctx *ctx, const qd_expr *e);
QD_API const qd_expr *qd_trigsimp(qd_ctx *ctx, const qd_expr *e);
/* Put a rational expression over a common denominator and cancel the
 * greatest common divisor of numerator and denominator. */
QD_API const qd_expr *qd_cancel(qd_ctx *ctx, const qd_expr *e);
/* Pull the common numeric and symbolic factors out of a sum. */
QD_API const qd_expr *qd_factor_terms(qd_ctx *ctx, const qd_expr *e);

/* Number of operations (additions, multiplications, powers, function calls)
 * in the tree, counted the way SymPy's count_ops(visual=False) does. */
QD_API size_t qd_count_ops(const qd_expr *e);
/* Number of distinct nodes of the DAG under e. */
QD_API size_t qd_dag_size(qd_ctx *ctx, const qd_expr *e);

/* An antiderivative of e with respect to the symbol x (no constant added).
 * Integrates sums term by term and products of factors free of x with one
 * of: x^n and (a x + b)^n for a number n (n = -1 gives log(a x + b)/a, a
 * logarithm of the argument, not of its absolute value), c^(a x + b) with c
 * free of x, and sin, cos, exp, sinh, cosh of (a x + b); a and b free of x.
 * An input that fits only once expanded (x (x + 1)) is expanded.  Anything
 * else returns NULL with QD_ERR_ARG. */
QD_API const qd_expr *qd_integrate(qd_ctx *ctx, const qd_expr *e, const qd_expr *x);

/* ---- simple numeric evaluation ---------------------------------------------
 * Evaluates e with the n symbols syms[i] set to vals[i], walking the DAG once
 * (each shared node once).  QD_ERR_UNBOUND when a symbol has no value.  For
 * repeated evaluation compile a qd_prog (qdot/eval.h), which is much faster.
 */
QD_API qd_status qd_eval(qd_ctx *ctx, const qd_expr *e, size_t n, const qd_expr *const *syms,
                  const double *vals, double *out);

#ifdef __cplusplus
}
#endif

/* NULL (issue 30): a function of this header given NULL for a pointer it
 * needs does nothing and returns QD_ERR_ARG (recorded in ctx when ctx is
 * given), NULL, 0, false or NaN, as its return type has it; a void function
 * returns, and every _free accepts NULL. NULL is an accepted value, as
 * documented at the function, for: qd_ctx_new_with (a); qd_ctx_error_about
 * (hint, name); qd_ctx_set_progress (fn, data); qd_ufunc (args); qd_free_symbols (out); qd_eval (syms,
 * vals). An array whose count is 0 may be NULL.
 * Exception: qd_ctx_message(NULL) is "". */
#endif

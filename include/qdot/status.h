/*
 * qdot/status.h - the status codes every fallible libqdot call returns, and
 * the error record that says what an error is about.
 *
 * The library never prints and never exits: a call that fails returns one of
 * these codes (or NULL), and the context keeps an error record (qd_ctx_diag):
 * the status, a message, what the error is about (a statement, a constraint,
 * a coordinate ... by index and name), the byte range in the text read when
 * it is known, and a hint.  A caller shows it with qd_diag_format; it never
 * has to search the message.  Errors are sticky: once a context holds an
 * error, every constructor that is handed the resulting NULL returns NULL
 * too, so a long chain of calls needs a single check at its end.
 */
#ifndef QDOT_STATUS_H
#define QDOT_STATUS_H

/* QD_API marks what libqdot exports: the shared library is built with
 * -fvisibility=hidden, so a function without it stays internal. */
#if defined(QDOT_BUILD) && defined(__GNUC__)
#define QD_API __attribute__((visibility("default")))
#else
#define QD_API
#endif

#include <stdbool.h>
#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef enum qd_status {
    QD_OK = 0,
    QD_ERR_NOMEM,      /* an allocation failed */
    QD_ERR_DIVZERO,    /* an exact division by zero, e.g. 0^-1 */
    QD_ERR_ARG,        /* an argument outside what the call accepts */
    QD_ERR_PARSE,      /* text that does not read as an expression */
    QD_ERR_NONLINEAR,  /* an expression that had to be linear (or polynomial) is not */
    QD_ERR_UNBOUND,    /* numeric evaluation met a symbol with no value */
    QD_ERR_SINGULAR,   /* a singular matrix */
    QD_ERR_NUMERIC,    /* numerical failure: overflow, step size underflow, no convergence */
    QD_ERR_TOOBIG,     /* a result would exceed a documented size limit */
    QD_ERR_UNSUPPORTED, /* the platform lacks something needed (no C compiler for native code) */
    QD_ERR_IO          /* a file could not be written (a full disk): errno's reason in the message */
} qd_status;

/* What an error is about.  index counts from 0 in the model's order (its
 * coordinates, its constraints, its parameters); name is the subject's own
 * name ("T", "roll1", "theta"), so a caller can find it without the index. */
typedef enum qd_subject {
    QD_SUBJECT_NONE,       /* nothing in particular (out of memory, a bad argument) */
    QD_SUBJECT_TEXT,       /* a spot in text being read: see offset and length */
    QD_SUBJECT_STATEMENT,  /* a statement of the model: name is "T", "V", "L", "H", ... */
    QD_SUBJECT_CONSTRAINT, /* constraint number index */
    QD_SUBJECT_COORD,      /* coordinate number index (its velocity, its equation) */
    QD_SUBJECT_PARAM,      /* parameter number index */
    QD_SUBJECT_SPEED       /* generalized speed number index (`speeds`) */
} qd_subject;

/* Why, when the subject alone does not say it: lets a caller (or a test)
 * tell an inconsistent constraint set from a redundant one without reading
 * English. */
typedef enum qd_reason {
    QD_REASON_NONE,
    QD_REASON_INCONSISTENT,  /* constraints no motion satisfies together */
    QD_REASON_REDUNDANT,     /* constraints that repeat others: multipliers not unique */
    QD_REASON_DEGENERATE,    /* a constraint whose coefficients all vanish */
    QD_REASON_NOT_PFAFFIAN,  /* a constraint not linear in the velocities, or with none */
    QD_REASON_NOT_QUADRATIC, /* a velocity (momentum) enters T, L (H) beyond the square */
    QD_REASON_SINGULAR_MASS, /* the mass matrix is singular */
    QD_REASON_TOO_DEEP,      /* text nested beyond the readers' limit (QD_MAX_NEST) */
    QD_REASON_BAD_BYTE,      /* a byte or character the language does not allow there */
    QD_REASON_DEPENDENT_SPEEDS, /* speeds (with the constraints) that do not determine q' */
    QD_REASON_WRONG_KIND     /* a vector or matrix where a scalar is needed, or the reverse */
} qd_reason;

/* Brackets and signs nest at most this deep in any text libqdot reads, so a
 * hostile input cannot exhaust the stack. */
#define QD_MAX_NEST 256

/* An error record.  line and col (1-based, col in bytes) and offset/length
 * (bytes) locate the error in the text read when located is true. */
typedef struct qd_diag {
    qd_status status;
    qd_subject subject;
    size_t index;          /* which constraint, coordinate, parameter; for a
                            * statement, the coordinate it concerns (whose
                            * velocity enters L beyond the square), else 0 */
    char name[64];         /* the subject's name, "" when none */
    qd_reason reason;
    bool located;
    size_t line, col;
    size_t offset;         /* byte offset in the text */
    size_t length;         /* bytes the caret spans (>= 1 when located) */
    char message[256];
    char hint[256];        /* what to do, "" when there is nothing to add */
} qd_diag;

/* A short English name of the status ("division by zero"); never NULL. */
QD_API const char *qd_status_str(qd_status st);

/* "Did you mean": the name of names[0..count) nearest word[0..n) (a few
 * edits, scaled to its length), or NULL when none is close; the one rule
 * of every suggestion qdot makes (model files, option names, states). */
QD_API const char *qd_nearest_name(const char *word, size_t n, const char *const *names,
                                   size_t count);

#ifdef __cplusplus
}
#endif

/* NULL (issue 30): a function of this header given NULL for a pointer it
 * needs does nothing and returns QD_ERR_ARG (recorded in ctx when ctx is
 * given), NULL, 0, false or NaN, as its return type has it; a void function
 * returns, and every _free accepts NULL. No pointer argument here accepts
 * NULL otherwise. An array whose count is 0 may be NULL. */
#endif

/*
 * qdot/status.h - the status codes every fallible libqdot call returns.
 *
 * The library never prints and never exits: a call that fails returns one of
 * these codes (or NULL), and the context keeps a message the caller can show
 * (qd_ctx_message).  Errors are sticky: once a context holds an error, every
 * constructor that is handed the resulting NULL returns NULL too, so a long
 * chain of calls needs a single check at its end.
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
    QD_ERR_UNSUPPORTED /* the platform lacks something needed (no C compiler for native code) */
} qd_status;

/* A short English name of the status ("division by zero"); never NULL. */
QD_API const char *qd_status_str(qd_status st);

#ifdef __cplusplus
}
#endif
#endif

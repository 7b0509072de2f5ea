/*
 * cli/lqr_cli.h - the weights of an LQR design as the command line gives
 * them: --lqr "Q = diag(1, 1, 10, 1), R = 0.1".
 */
#ifndef QDOT_LQR_CLI_H
#define QDOT_LQR_CLI_H

#include <stdbool.h>
#include <stddef.h>

/* Read text into Q (n*n) and R (m*m), row-major arrays the caller owns.
 * text is "Q = W, R = W" in either order, each given once, where W is
 *   a number c              c times the identity,
 *   diag(d1, ..., dk)       k = the size,
 *   [[a11, a12, ...], ...]  the full matrix, row by row.
 * On an error: false, the message in err (errlen bytes) and its byte offset
 * in text at *where.  Symmetry and definiteness are left to qd_care_solve,
 * which names what is wrong with them. */
bool cli_lqr_parse(const char *text, size_t n, size_t m, double *Q, double *R, char *err,
                   size_t errlen, size_t *where);

#endif

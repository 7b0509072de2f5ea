/*
 * src/base/diag.h - what the two readers share to report a bad byte.
 */
#ifndef QD_BASE_DIAG_H
#define QD_BASE_DIAG_H

#include "qdot/read.h"

/* The byte (or UTF-8 character) at s, which a reader does not accept, named
 * in plain words in msg: "unexpected byte 0xff (not UTF-8 text)", "'θ'
 * (U+03B8) cannot be used in a name; ...".  *hint gets what to do.  Returns
 * the bytes it spans (a whole character when it is well-formed UTF-8). */
size_t qd__diag_bad_char(const char *s, char *msg, size_t cap, const char **hint);

/* The hint of "expression nested too deeply", the same in both readers. */
#define QD_NEST_HINT "brackets and signs nest at most 256 deep; name a part with a definition"

/* The name in names[0..count) nearest to word[0..n) by edit distance, when
 * it is close (1 edit for short words, up to 3 for long ones), else NULL:
 * the "did you mean" of every unknown-name error. */
const char *qd__diag_nearest(const char *word, size_t n, const char *const *names, size_t count);

#endif

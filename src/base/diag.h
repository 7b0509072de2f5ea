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

/* Line (from 1) and column (from 1, in bytes) of byte off of text, and the
 * offset of its line's first byte: a line ends at "\n", "\r\n" or a lone
 * "\r" (old Mac files).  start may be NULL. */
void qd__diag_line_col(const char *text, size_t off, size_t *line, size_t *col, size_t *start);
/* The bytes of the line starting at s, up to its end ("\n", "\r" or NUL). */
size_t qd__diag_line_len(const char *s);
/* The first byte of text[0..n) that does not start well-formed UTF-8
 * (an overlong form, a stray continuation byte, a cut or surrogate
 * character), or n when every byte is valid. */
size_t qd__diag_utf8_check(const char *text, size_t n);

/* A malloc'd copy of text with every byte outside [start, end) a blank
 * and the line breaks kept, or NULL: what a reader reads so that its errors
 * carry the offsets, lines and columns of the caller's whole text. */
char *qd__diag_blanked(const char *text, size_t start, size_t end);

/* The hint of "expression nested too deeply", the same in both readers. */
#define QD_NEST_HINT "brackets and signs nest at most 256 deep; name a part with a definition"

/* The name in names[0..count) nearest to word[0..n) by edit distance, when
 * it is close (1 edit for short words, up to 3 for long ones), else NULL:
 * the "did you mean" of every unknown-name error. */
const char *qd__diag_nearest(const char *word, size_t n, const char *const *names, size_t count);

#endif

/*
 * src/num/result.c - the digit rule of a computed result shown to a
 * reader (qd_result_format, qdot/print.h): 12 significant digits, and 0
 * below the last digit the largest number printed with it shows.
 *
 * Why 12 and 1e-12 together: a result found by iteration or elimination
 * carries round-off of some 1e-15 to 1e-13 relative to the numbers it came
 * from; 12 digits hide it (0.49, not 0.48999999999999927), and a number
 * below 1e-12 of its companions is that round-off, not a value, so the
 * threshold is where the digits stop.  Relative, not absolute: a system
 * in small units (lengths in km for a molecule) must not print all zeros.
 */
#include "qdot/print.h"

#include <math.h>
#include <stdio.h>
#include <string.h>
#include "../base/args.h"

size_t qd_result_format(char *out, double x, double scale) {
    QD_ARGS(0, out);
    if (!(scale > 0) || !isfinite(scale)) /* no common scale: a number of order one */
        scale = 1;
    if (isfinite(x) && fabs(x) <= QD_RESULT_ZERO * scale)
        x = 0;
    if (x == 0)
        x = 0.0; /* -0 reads 0 */
    snprintf(out, QD_DOUBLE_MAX, "%.*g", QD_RESULT_DIGITS, x);
    return strlen(out);
}

void qd_buf_put_result(qd_buf *b, double x, double scale) {
    QD_ARGS(, b);
    char s[QD_DOUBLE_MAX];
    qd_buf_putn(b, s, qd_result_format(s, x, scale));
}

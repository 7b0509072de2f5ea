/*
 * src/num/shortest.c - a double in the fewest significant digits that read
 * back to it: the shortest of %.15g, %.16g, %.17g (the same digits as the
 * shortest %.Ng of any N, since every decimal of at most 15 digits reads
 * back to the double nearest it; %g's style is the one of 15 digits, so
 * 1e13 is 10000000000000).  A subnormal has fewer digits: the shortest
 * %.Ng of any N (5e-324).  A row per step of a long simulation
 * makes this a hot spot (about 65% of qdot simulate's time when it was
 * snprintf and strtod three times a number): exact 128-bit integer digits
 * for 1e-12 <= |x| < 1e15, snprintf and strtod outside, identical output on
 * 2e7 random doubles (bench/README.md, "Simulation against GSL, CVODE and SciPy").
 */
#include "qdot/print.h"
#include "../base/args.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

__extension__ typedef unsigned __int128 u128;

static const uint64_t POW5[28] = {
    UINT64_C(1), UINT64_C(5), UINT64_C(25), UINT64_C(125), UINT64_C(625), UINT64_C(3125),
    UINT64_C(15625), UINT64_C(78125), UINT64_C(390625), UINT64_C(1953125),
    UINT64_C(9765625), UINT64_C(48828125), UINT64_C(244140625), UINT64_C(1220703125),
    UINT64_C(6103515625), UINT64_C(30517578125), UINT64_C(152587890625),
    UINT64_C(762939453125), UINT64_C(3814697265625), UINT64_C(19073486328125),
    UINT64_C(95367431640625), UINT64_C(476837158203125), UINT64_C(2384185791015625),
    UINT64_C(11920928955078125), UINT64_C(59604644775390625),
    UINT64_C(298023223876953125), UINT64_C(1490116119384765625),
    UINT64_C(7450580596923828125)};

/* The digits of |x| = m 2^-s rounded to p = k + 1 + e10 significant digits
 * into *D: 1 when lo <= D < hi and D reads back to x, -1 when D >= hi (the
 * decimal exponent is one more), 0 otherwise.  With 10^k = 5^k 2^k, D is
 * m 5^k / 2^(s - k) rounded (ties to even, as printf), and it reads back
 * when |D 10^-k - x| < ulp/2, i.e. |2 D 2^(s-k) - 2 m 5^k| < 5^k: all in
 * exact 128-bit integers while k <= 31 and s - k <= 69. */
static int digits_roundtrip(uint64_t m, int s, int k, uint64_t lo, uint64_t hi, uint64_t *D) {
    int sh = s - k;
    if (k < 0 || k > 31 || sh < 1 || sh > 69)
        return 0;
    /* 5^k: 5^27 is the largest that fits 64 bits; constant, so the printer
     * shares no mutable table between threads */
    u128 p5 = POW5[k < 27 ? k : 27];
    for (int i = 27; i < k; i++)
        p5 *= 5;
    u128 N = (u128)m * p5, half = (u128)1 << (sh - 1), rem = N & (((u128)1 << sh) - 1);
    u128 d = N >> sh;
    d += rem > half || (rem == half && (d & 1));
    if (d >= hi)
        return -1;
    if (d < lo)
        return 0;
    u128 a = d << (sh + 1), b = N << 1;
    u128 diff = a > b ? a - b : b - a;
    *D = (uint64_t)d;
    return diff < p5;
}

/* |x| in [1e-12, 1e15) as %.pg prints it with the shortest p of 15, 16, 17
 * that reads back; 0 outside that range or when unsure. */
static size_t fast_number(char *out, double x) {
    static const uint64_t pow10[18] = {
        UINT64_C(1), UINT64_C(10), UINT64_C(100), UINT64_C(1000), UINT64_C(10000),
        UINT64_C(100000), UINT64_C(1000000), UINT64_C(10000000), UINT64_C(100000000),
        UINT64_C(1000000000), UINT64_C(10000000000), UINT64_C(100000000000),
        UINT64_C(1000000000000), UINT64_C(10000000000000), UINT64_C(100000000000000),
        UINT64_C(1000000000000000), UINT64_C(10000000000000000),
        UINT64_C(100000000000000000)};
    double ax = fabs(x);
    if (!(ax >= 1e-12 && ax < 1e15))
        return 0;
    uint64_t bits;
    memcpy(&bits, &ax, sizeof bits);
    uint64_t frac = bits & ((UINT64_C(1) << 52) - 1);
    int be = (int)(bits >> 52);            /* normal here: ax = m 2^-s */
    if (frac == 0)                         /* a power of 2: the gap below is half */
        return 0;
    uint64_t m = frac | (UINT64_C(1) << 52);
    int s = 1075 - be;
    /* 2^(e2-1) <= ax < 2^e2: floor(log10 ax) is this or one more */
    int est = (int)floor((double)(be - 1023) * 0.30102999566398120);
    for (int p = 15; p <= 17; p++) {
        uint64_t D = 0;
        int e10 = est;
        int r = digits_roundtrip(m, s, p - 1 - e10, pow10[p - 1], pow10[p], &D);
        if (r < 0) {
            e10++;
            r = digits_roundtrip(m, s, p - 1 - e10, pow10[p - 1], pow10[p], &D);
        }
        if (r < 0 || e10 < -12 || e10 > 14)
            return 0;
        if (!r)
            continue;
        char dig[20];
        for (int i = p - 1; i >= 0; i--, D /= 10)
            dig[i] = (char)('0' + D % 10);
        int nd = p;
        while (nd > 1 && dig[nd - 1] == '0')
            nd--;
        size_t n = 0;
        if (x < 0)
            out[n++] = '-';
        if (e10 < -4) {                    /* d.ddde-XX */
            out[n++] = dig[0];
            if (nd > 1)
                out[n++] = '.';
            for (int i = 1; i < nd; i++)
                out[n++] = dig[i];
            out[n++] = 'e';
            out[n++] = '-';
            out[n++] = (char)('0' + -e10 / 10);
            out[n++] = (char)('0' + -e10 % 10);
        } else if (e10 >= 0) {
            for (int i = 0; i <= e10; i++)
                out[n++] = i < nd ? dig[i] : '0';
            if (nd > e10 + 1) {
                out[n++] = '.';
                for (int i = e10 + 1; i < nd; i++)
                    out[n++] = dig[i];
            }
        } else {
            out[n++] = '0';
            out[n++] = '.';
            for (int i = 0; i < -e10 - 1; i++)
                out[n++] = '0';
            for (int i = 0; i < nd; i++)
                out[n++] = dig[i];
        }
        out[n] = '\0';
        return n;
    }
    return 0;
}

size_t qd_double_format(char *out, double x) {
    QD_ARGS(0, out);
    size_t n = fast_number(out, x);
    if (n)
        return n;
    /* a subnormal has fewer than 15 significant digits: 5e-324 */
    for (int p = fabs(x) < 0x1p-1022 && x != 0 ? 1 : 15; p <= 17; p++) {
        snprintf(out, QD_DOUBLE_MAX, "%.*g", p, x);
        if (p == 17 || strtod(out, NULL) == x)
            break;
    }
    return strlen(out);
}

void qd_buf_put_double(qd_buf *b, double x) {
    QD_ARGS(, b);
    char s[QD_DOUBLE_MAX];
    qd_buf_putn(b, s, qd_double_format(s, x));
}

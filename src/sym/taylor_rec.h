/*
 * src/sym/taylor_rec.h - the Taylor-mode recurrences, written once over a
 * floating type: taylor_prog.c includes this once per type with
 *   TAY_T          the type,
 *   TAY_S(name)    name with the type's suffix,
 *   TAY_M(fn)      the type's maths function fn (sin -> sinl, sinq),
 *   TAY_POWV(b, e) b^e as qd_prog computes it.
 *
 * x, y: the operands' coefficient arrays, d the result's, u its auxiliary
 * series; coefficient k >= 1 from orders < k of d and u and orders <= k of
 * x and y (Jorba and Zou 2005, sec. 2.1; Griewank and Walther 2008,
 * table 13.2).  With x' the derivative, each follows from an identity
 * that holds order by order:
 *   d = x / y      y d = x
 *   d = x^e        x d' = e x' d        (e constant)
 *   d = sqrt(x)    d d = x
 *   sin, cos       s' = c x', c' = -s x'  (computed together)
 *   d = exp(x)     d' = x' d
 *   d = log(x)     x d' = x'
 *   d = tan(x)     d' = u x', u = 1 + d^2       (tanh: u = 1 - d^2)
 *   d = asin(x)    u d' = x', u = sqrt(1 - x^2) (acos: u d' = -x')
 *   d = atan(x)    u d' = x', u = 1 + x^2
 *   atan2(x, y)    u d' = y x' - x y', u = x^2 + y^2
 */

/* sum_{j=lo..hi} x_j y_{k-j}, in two interleaved sums (two independent
 * chains of additions keep the FPU's pipeline busy: the recurrences are
 * most of a Taylor step) */
static inline __attribute__((always_inline)) TAY_T TAY_S(conv)(const TAY_T *x, const TAY_T *y, size_t lo, size_t hi, size_t k) {
    TAY_T s0 = 0, s1 = 0;
    size_t j = lo;
    for (; j + 1 <= hi; j += 2) {
        s0 += x[j] * y[k - j];
        s1 += x[j + 1] * y[k - j - 1];
    }
    if (j == hi)
        s0 += x[j] * y[k - j];
    return s0 + s1;
}

/* sum_{j=lo..hi} j x_j y_{k-j} */
static TAY_T TAY_S(wconv)(const TAY_T *x, const TAY_T *y, size_t lo, size_t hi, size_t k) {
    TAY_T s = 0;
    for (size_t j = lo; j <= hi; j++)
        s += (TAY_T)j * x[j] * y[k - j];
    return s;
}

/* sum_{j=1..k-1} d_j d_{k-j}, by its symmetry */
static TAY_T TAY_S(square_mid)(const TAY_T *d, size_t k) {
    TAY_T s = 0;
    for (size_t j = 1; 2 * j < k; j++)
        s += d[j] * d[k - j];
    s += s;
    if (k % 2 == 0)
        s += d[k / 2] * d[k / 2];
    return s;
}

static TAY_T TAY_S(step)(TAY_T x) { return x > 0 ? 1 : x < 0 ? 0 : x == 0 ? (TAY_T)0.5 : x; }

/* Order 0: the values, as the program computes them. */
static void TAY_S(order0)(const qd__tay *tp, TAY_T *c) {
    for (size_t i = 0; i < tp->nins; i++) {
        const tcode *in = &tp->code[i];
        TAY_T *d = c + in->d, *u = c + in->u, x = c[in->a], y = c[in->b];
        c[in->w] = 0;
        switch ((top)in->op) {
        case T_ADD: d[0] = x + y; break;
        case T_SUB: d[0] = x - y; break;
        case T_MUL: case T_MULC: d[0] = x * y; break;
        case T_DIV: case T_DIVC: d[0] = x / y; break;
        case T_NEG: d[0] = -x; break;
        case T_RECIP: d[0] = 1 / x; break;
        case T_SQRT: d[0] = TAY_M(sqrt)(x); break;
        case T_POWC: d[0] = TAY_POWV(x, y); break;
        case T_SINCOS: d[0] = TAY_M(sin)(x); u[0] = TAY_M(cos)(x); break;
        case T_SINHCOSH: d[0] = TAY_M(sinh)(x); u[0] = TAY_M(cosh)(x); break;
        case T_TAN: d[0] = TAY_M(tan)(x); u[0] = 1 + d[0] * d[0]; break;
        case T_TANH: d[0] = TAY_M(tanh)(x); u[0] = 1 - d[0] * d[0]; break;
        case T_ASIN: d[0] = TAY_M(asin)(x); u[0] = TAY_M(sqrt)(1 - x * x); break;
        case T_ACOS: d[0] = TAY_M(acos)(x); u[0] = TAY_M(sqrt)(1 - x * x); break;
        case T_ATAN: d[0] = TAY_M(atan)(x); u[0] = 1 + x * x; break;
        case T_ATAN2: d[0] = TAY_M(atan2)(x, y); u[0] = x * x + y * y; break;
        case T_EXP: d[0] = TAY_M(exp)(x); break;
        case T_LOG: d[0] = TAY_M(log)(x); break;
        case T_ABS: d[0] = TAY_M(fabs)(x); break;
        case T_SIGN: d[0] = (TAY_T)((x > 0) - (x < 0)); break;
        case T_STEP: d[0] = TAY_S(step)(x); break;
        }
    }
}

/* asin, acos: u = sqrt(1 - x^2), then u d' = +-x'. */
static void TAY_S(arcsin)(TAY_T *d, TAY_T *u, const TAY_T *x, size_t k, TAY_T sign) {
    TAY_T w = -TAY_S(conv)(x, x, 0, k, k);
    u[k] = (w - TAY_S(square_mid)(u, k)) / (2 * u[0]);
    d[k] = (sign * x[k] - TAY_S(wconv)(d, u, 1, k - 1, k) / (TAY_T)k) / u[0];
}

static void TAY_S(orderk)(const qd__tay *tp, TAY_T *c, size_t k) {
    TAY_T kk = (TAY_T)k;
    for (size_t l = 0; l < tp->nlive; l++) {
        const tcode *in = &tp->code[tp->live[l]];
        TAY_T *d = c + in->d, *u = c + in->u, *w = c + in->w;
        const TAY_T *x = c + in->a, *y = c + in->b;
        switch ((top)in->op) {
        case T_ADD: d[k] = x[k] + y[k]; break;
        case T_SUB: d[k] = x[k] - y[k]; break;
        case T_NEG: d[k] = -x[k]; break;
        case T_MULC: d[k] = x[0] * y[k]; break;
        case T_MUL: d[k] = TAY_S(conv)(x, y, 0, k, k); break;
        case T_DIVC: d[k] = x[k] / y[0]; break;
        case T_DIV: d[k] = (x[k] - TAY_S(conv)(y, d, 1, k, k)) / y[0]; break;
        case T_RECIP: d[k] = -TAY_S(conv)(x, d, 1, k, k) / x[0]; break;
        case T_SQRT: d[k] = (x[k] - TAY_S(square_mid)(d, k)) / (2 * d[0]); break;
        case T_POWC: {
            TAY_T s = 0, e = y[0];
            for (size_t j = 1; j <= k; j++)
                s += (e * (TAY_T)j - (TAY_T)(k - j)) * x[j] * d[k - j];
            d[k] = s / (kk * x[0]);
            break;
        }
        case T_SINCOS:
            w[k] = kk * x[k]; /* (x')_(k-1) = k x_k, shared by both: see has_weight */
            d[k] = TAY_S(conv)(w, u, 1, k, k) / kk;
            u[k] = -TAY_S(conv)(w, d, 1, k, k) / kk;
            break;
        case T_SINHCOSH:
            w[k] = kk * x[k];
            d[k] = TAY_S(conv)(w, u, 1, k, k) / kk;
            u[k] = TAY_S(conv)(w, d, 1, k, k) / kk;
            break;
        case T_TAN:
            w[k] = kk * x[k];
            d[k] = TAY_S(conv)(w, u, 1, k, k) / kk;
            u[k] = TAY_S(conv)(d, d, 0, k, k);
            break;
        case T_TANH:
            w[k] = kk * x[k];
            d[k] = TAY_S(conv)(w, u, 1, k, k) / kk;
            u[k] = -TAY_S(conv)(d, d, 0, k, k);
            break;
        case T_ASIN: TAY_S(arcsin)(d, u, x, k, 1); break;
        case T_ACOS: TAY_S(arcsin)(d, u, x, k, -1); break;
        case T_ATAN:
            u[k] = TAY_S(conv)(x, x, 0, k, k);
            d[k] = (x[k] - TAY_S(wconv)(d, u, 1, k - 1, k) / kk) / u[0];
            break;
        case T_ATAN2: {
            TAY_T v = (TAY_S(wconv)(x, y, 1, k, k) - TAY_S(wconv)(y, x, 1, k, k)) / kk;
            u[k] = TAY_S(conv)(x, x, 0, k, k) + TAY_S(conv)(y, y, 0, k, k);
            d[k] = (v - TAY_S(wconv)(d, u, 1, k - 1, k) / kk) / u[0];
            break;
        }
        case T_EXP:
            w[k] = kk * x[k];
            d[k] = TAY_S(conv)(w, d, 1, k, k) / kk;
            break;
        case T_LOG: d[k] = (x[k] - TAY_S(wconv)(d, x, 1, k - 1, k) / kk) / x[0]; break;
        case T_ABS: d[k] = x[0] < 0 ? -x[k] : x[k]; break;
        case T_SIGN: case T_STEP: break; /* piecewise constant: flat, never live */
        }
    }
}

static void TAY_S(run)(qd__tay *tp, size_t k) {
    TAY_T *c = tp->work;
    if (k == 0)
        TAY_S(order0)(tp, c);
    else
        TAY_S(orderk)(tp, c, k);
}

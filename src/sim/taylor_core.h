/*
 * src/sim/taylor_core.h - the Taylor integrator's arithmetic over one
 * floating type: the state's series order by order, the linear solve for
 * the accelerations' series, the polynomial's value.  taylor.c includes it
 * once per type with TAY_T, TAY_S(name) and TAY_M(fn) (as taylor_rec.h).
 *
 * The series of the unknowns x = (q'', lambda) of K(t) x(t) = r(t), with
 * K = [M -A^T; A 0] and r = (f, b) (M u' = f in speeds), order by order
 * with the one factorization of K_0 = K(t0) per step:
 *     K_0 x_k = r_k - sum_{j=1..k} K_j x_{k-j}.
 */

static TAY_T *TAY_S(state)(tay *T, size_t i) { return T->yc[i]; }

/* LU with scaled partial pivoting of K (N*N) in place (Golub & Van Loan
 * sec. 3.5.2): each row judged against its own largest entry rs (scratch,
 * N), so the test is invariant under row scaling, as qd__num_solve's
 * equilibration: M = diag(1, r^2) at r = 6.7e6 is regular.  false when a
 * row is zero or no pivot is above 1e-13 N of its row's scale. */
static bool TAY_S(lu)(TAY_T *K, size_t N, size_t *piv, double *rs) {
    for (size_t i = 0; i < N; i++) {
        double m = 0;
        for (size_t j = 0; j < N; j++)
            m = fmax(m, (double)TAY_M(fabs)(K[i * N + j]));
        if (!(m > 0) || !isfinite(m))
            return false;
        rs[i] = m;
    }
    double tol = 1e-13 * (double)N;
    for (size_t c = 0; c < N; c++) {
        size_t p = c;
        for (size_t i = c + 1; i < N; i++)
            if ((double)TAY_M(fabs)(K[i * N + c]) / rs[i] > (double)TAY_M(fabs)(K[p * N + c]) / rs[p])
                p = i;
        if (!((double)TAY_M(fabs)(K[p * N + c]) / rs[p] > tol))
            return false;
        piv[c] = p;
        double rc = rs[c];
        rs[c] = rs[p];
        rs[p] = rc;
        for (size_t j = 0; p != c && j < N; j++) {
            TAY_T t = K[c * N + j];
            K[c * N + j] = K[p * N + j];
            K[p * N + j] = t;
        }
        for (size_t i = c + 1; i < N; i++) {
            TAY_T l = K[i * N + c] /= K[c * N + c];
            for (size_t j = c + 1; j < N; j++)
                K[i * N + j] -= l * K[c * N + j];
        }
    }
    return true;
}

/* The row swaps first: lu swapped whole rows, so L is in the final order. */
static void TAY_S(lu_solve)(const TAY_T *K, size_t N, const size_t *piv, TAY_T *x) {
    for (size_t c = 0; c < N; c++) {
        TAY_T t = x[piv[c]];
        x[piv[c]] = x[c];
        x[c] = t;
    }
    for (size_t c = 0; c < N; c++)
        for (size_t i = c + 1; i < N; i++)
            x[i] -= K[i * N + c] * x[c];
    for (size_t i = N; i-- > 0;) {
        for (size_t j = i + 1; j < N; j++)
            x[i] -= K[i * N + j] * x[j];
        x[i] /= K[i * N + i];
    }
}

/* Order j of K's entry e (T->kc: its series, NULL for 0; T->kneg: -A^T). */
static TAY_T TAY_S(K_at)(const tay *T, size_t e, size_t j) {
    const TAY_T *c = T->kc[e];
    return !c ? 0 : T->kneg[e] ? -c[j] : c[j];
}

/* r_k - sum_{j=1..k} K_j x_{k-j} into x_k, then solved with K_0. */
static bool TAY_S(solve_order)(tay *T, size_t k) {
    size_t N = T->N;
    TAY_T *K = T->K, *X = T->X, *x = X + k * N;
    for (size_t i = 0; i < N; i++)
        x[i] = ((const TAY_T *)T->rc[i])[k];
    for (size_t i = 0; i < N; i++) {
        TAY_T s = 0;
        for (size_t l = 0; l < N; l++) {
            const TAY_T *c = T->kc[i * N + l];
            if (!c || T->kflat[i * N + l])
                continue;
            TAY_T v = 0;
            for (size_t j = 1; j <= k; j++)
                v += c[j] * X[(k - j) * N + l];
            s += T->kneg[i * N + l] ? -v : v;
        }
        x[i] -= s;
    }
    if (k == 0) {
        for (size_t e = 0; e < N * N; e++)
            K[e] = TAY_S(K_at)(T, e, 0);
        if (!TAY_S(lu)(K, N, T->piv, T->rs))
            return false;
    }
    TAY_S(lu_solve)(K, N, T->piv, x);
    return true;
}

/* The derivative's change dF = F'(y) ylo for the rounding error ylo of the
 * state (its exact value is y + ylo): the order-1 pass of the program along
 * ylo at fixed t, after order 0.  The derivatives are evaluated at the
 * rounded state, and a coordinate far from 0 (an angle wound up to 100
 * rad: ulp 1.4e-14) gives accelerations off by ~1e-13 at every step; dF
 * added to the step's increment (advance) removes that to first order,
 * for one more pass of the 20 a step takes (the double pendulum's energy
 * error over 1000 s: 1.5e-13 without, measured). */
static void TAY_S(direction)(tay *T) {
    TAY_T *tc = qd__tay_in(T->tp, T->tin), *lo = T->ylo, *dF = T->dF;
    tc[1] = 0;
    for (size_t i = 0; i < T->dim; i++)
        TAY_S(state)(T, i)[1] = lo[i];
    qd__tay_run(T->tp, 1);
    if (T->N)
        TAY_S(solve_order)(T, 1);
    for (size_t i = 0; i < T->dim; i++) {
        const TAY_T *src = T->srcc[i];
        dF[i] = src ? src[1] : ((TAY_T *)T->X)[T->N + T->src_x[i]];
    }
    tc[1] = 1;
}

/* The state's coefficients 1..p from coefficient 0 (already set). */
static qd_status TAY_S(series)(tay *T, size_t p) {
    TAY_T tm = *(TAY_T *)T->t;
    ((TAY_T *)qd__tay_in(T->tp, T->tin))[0] = tm;
    for (size_t k = 0; k < p; k++) {
        qd__tay_run(T->tp, k);
        if (T->N && !TAY_S(solve_order)(T, k))
            return QD_ERR_SINGULAR;
        if (k == 0)
            TAY_S(direction)(T);
        TAY_T inv = 1 / (TAY_T)(k + 1);
        for (size_t i = 0; i < T->dim; i++) {
            const TAY_T *src = T->srcc[i];
            TAY_T v = src ? src[k] : ((TAY_T *)T->X)[k * T->N + T->src_x[i]];
            TAY_S(state)(T, i)[k + 1] = v * inv;
        }
    }
    return QD_OK;
}

static double TAY_S(norm)(tay *T, size_t j) {
    TAY_T m = 0;
    for (size_t i = 0; i < T->dim; i++) {
        TAY_T a = TAY_M(fabs)(TAY_S(state)(T, i)[j]);
        m = a > m || a != a ? a : m;
    }
    return (double)m;
}

/* The polynomial of order p at theta (Horner). */
static TAY_T TAY_S(horner)(const TAY_T *c, size_t p, TAY_T theta) {
    TAY_T v = c[p];
    for (size_t k = p; k-- > 0;)
        v = v * theta + c[k];
    return v;
}

static void TAY_S(dense)(tay *T, double theta, double *y) {
    for (size_t i = 0; i < T->dim; i++)
        y[i] = (double)TAY_S(horner)(TAY_S(state)(T, i), T->p, (TAY_T)theta);
}

/* The state and time from the driver's doubles (a projection, an impact). */
static void TAY_S(load)(tay *T, double t, const double *y) {
    TAY_T *lo = T->ylo;
    *(TAY_T *)T->t = t;
    for (size_t i = 0; i < T->dim; i++) {
        TAY_S(state)(T, i)[0] = y[i];
        lo[i] = 0;
    }
}

/* Coefficient 0 of the flat inputs (the parameters) from the system. */
static void TAY_S(flat_inputs)(tay *T, const double *in) {
    for (size_t i = 0; i < T->nin; i++)
        if (!T->var[i])
            ((TAY_T *)qd__tay_in(T->tp, i))[0] = in[i];
}

/* Advance by h: the new state (and t) in the type, rounded into y; the
 * coefficients of the step stay for dense output.  The increment is added
 * by compensated summation (Kahan 1965; Knuth's TwoSum): the state carries
 * its rounding error ylo from step to step, so that tens of thousands of
 * steps do not add half an ulp each to y (the double pendulum's energy
 * error over 1000 s: 5.6e-13 without, measured). */
static double TAY_S(advance)(tay *T, double h, double tend, double *y) {
    TAY_T *t = T->t, *ynew = T->ynew, *lo = T->ylo, *lonew = lo + T->dim, *dF = T->dF;
    /* a step to the end: its length from the time in the type, so that an
     * extended state does not inherit the drift of the driver's double t */
    TAY_T th = tend == tend ? (TAY_T)tend - *t : (TAY_T)h;
    for (size_t i = 0; i < T->dim; i++) {
        const TAY_T *c = TAY_S(state)(T, i);
        TAY_T a = c[0], b = (TAY_S(horner)(c + 1, T->p - 1, th) * th) + (lo[i] + th * dF[i]);
        TAY_T s = a + b, bb = s - a;
        ynew[i] = s;
        lonew[i] = (a - (s - bb)) + (b - bb);
    }
    for (size_t i = 0; i < T->dim; i++)
        y[i] = (double)ynew[i];
    *(TAY_T *)T->tnext = tend == tend ? (TAY_T)tend : *t + th;
    return (double)*(TAY_T *)T->tnext;
}

/* The step's end becomes the next step's start. */
static void TAY_S(commit)(tay *T) {
    const TAY_T *ynew = T->ynew;
    TAY_T *lo = T->ylo;
    for (size_t i = 0; i < T->dim; i++) {
        TAY_S(state)(T, i)[0] = ynew[i];
        lo[i] = lo[T->dim + i];
    }
    *(TAY_T *)T->t = *(TAY_T *)T->tnext;
}

static const tay_ops TAY_S(ops) = {TAY_S(series), TAY_S(norm), TAY_S(dense), TAY_S(load),
                                   TAY_S(flat_inputs), TAY_S(advance), TAY_S(commit),
                                   sizeof(TAY_T)};

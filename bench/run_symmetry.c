/*
 * bench/run_symmetry.c - the cyclic fast path of symmetry-adapted modes
 * against the full eigenproblem (issue 19; `make bench` runs it).
 *
 * The ring of N equal masses m joined by springs k (M0 = m I, K0
 * circulant), for several N: qd_modes_solve (dsygvd on the n*n pencil,
 * n^3 work) and qd_cyclic_solve (one pencil per harmonic, n^2 work to form
 * them) timed in the same run, so the ratio does not depend on the load of
 * the machine; each repeated until it has run 0.2 s, the best time kept.
 * Both are checked against w_j^2 = (4k/m) sin^2(pi j/N).
 *
 * Prints one tab-separated line per N:  N  full_s  fast_s  ratio  max_err
 */
#define _POSIX_C_SOURCE 199309L
#include <qdot/qdot.h>
#include <qdot/modes.h>
#include <qdot/symmetry.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

static const double PI = 3.14159265358979323846;

static double now(void) {
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static int ring(size_t N, qd_linear *lin) {
    size_t nn = N * N;
    lin->n = N;
    lin->M = calloc(nn, sizeof *lin->M);
    lin->K = calloc(nn, sizeof *lin->K);
    lin->C = calloc(nn, sizeof *lin->C);
    lin->G = calloc(nn, sizeof *lin->G);
    if (!lin->M || !lin->K || !lin->C || !lin->G)
        return -1;
    for (size_t i = 0; i < N; i++) {
        lin->M[i * N + i] = 1;
        lin->K[i * N + i] = 2;
        lin->K[i * N + (i + 1) % N] -= 1;
        lin->K[i * N + (i + N - 1) % N] -= 1;
    }
    return 0;
}

static void ring_free(qd_linear *lin) {
    free(lin->M);
    free(lin->K);
    free(lin->C);
    free(lin->G);
}

static int cmp(const void *a, const void *b) {
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* The largest error of w (ascending, N values) against the closed form. */
static double error(size_t N, const double *w) {
    double *want = malloc(N * sizeof *want), e = 0;
    if (!want)
        return INFINITY;
    for (size_t j = 0; j < N; j++)
        want[j] = 4 * pow(sin(PI * (double)j / (double)N), 2);
    qsort(want, N, sizeof *want, cmp);
    for (size_t j = 0; j < N; j++)
        e = fmax(e, fabs(w[j] - want[j]));
    free(want);
    return e;
}

/* Best time of the full solve (which 0) or the fast path (1). */
static double best(qd_ctx *ctx, const qd_linear *lin, int which, double *err) {
    double bestt = INFINITY, spent = 0;
    for (int reps = 0; spent < 0.2 || reps < 1; reps++) {
        qd_modes_result r;
        qd_cyclic_modes c;
        double t0 = now();
        qd_status st = which ? qd_cyclic_solve(ctx, lin, 1, &c) : qd_modes_solve(ctx, lin, &r);
        double t = now() - t0;
        if (st != QD_OK)
            return NAN;
        *err = error(lin->n, which ? c.omega2 : r.omega2);
        if (which)
            qd_cyclic_modes_free(&c);
        else
            qd_modes_result_free(&r);
        bestt = fmin(bestt, t);
        spent += t;
    }
    return bestt;
}

int main(void) {
    const size_t sizes[] = {100, 250, 500, 1000};
    qd_ctx *ctx = qd_ctx_new();
    if (!ctx)
        return 1;
    printf("N\tfull_s\tfast_s\tratio\tmax_err\n");
    for (size_t i = 0; i < sizeof sizes / sizeof sizes[0]; i++) {
        qd_linear lin;
        double e1 = 0, e2 = 0;
        if (ring(sizes[i], &lin) != 0)
            return 1;
        double full = best(ctx, &lin, 0, &e1), fast = best(ctx, &lin, 1, &e2);
        printf("%zu\t%.4g\t%.4g\t%.0f\t%.2g\n", sizes[i], full, fast, full / fast, fmax(e1, e2));
        ring_free(&lin);
    }
    qd_ctx_free(ctx);
    return 0;
}

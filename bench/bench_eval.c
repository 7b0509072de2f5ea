/*
 * bench/bench_eval.c - how fast does a compiled qd_prog run a real workload?
 *
 *   cc -O2 -Iinclude bench/bench_eval.c bench/eval_ref.c build/libqdot.a -lflint -lgmp -lm
 *   ./a.out [n] [runs]          (defaults: n = 8, runs = 700000)
 *
 * The workload: the planar n-pendulum's mass matrix M_jk = d^2 T / dq_j' dq_k'
 * and the potential gradient dV/dq_j, built with the kernel alone (qd_dt,
 * qd_diff; no model or mechanics modules), compiled into one program with
 * n^2 + n outputs.  The baseline, bench/eval_ref.c, computes the same numbers
 * by hand in plain C.  Both run over the same rotating set of input points;
 * the outputs are compared before timing.  Times are the best of 7 batches.
 */
#define _POSIX_C_SOURCE 199309L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "qdot/qdot.h"

#define NMAX 32
#define NPTS 64

void ref_eval(int n, const double *in, double *out); /* bench/eval_ref.c */

static const qd_expr *named(qd_ctx *ctx, const char *fmt, int i, bool param) {
    char name[32];
    snprintf(name, sizeof name, fmt, i + 1);
    return param ? qd_param(ctx, name) : qd_coord(ctx, name);
}

/* Inputs: q[n], q'[n], l[n], m[n], g.  Outputs: M row by row, then dV/dq. */
static void pendulum(qd_ctx *ctx, int n, const qd_expr **in, const qd_expr **out) {
    const qd_expr **q = in, **qd = in + n, **l = in + 2 * n, **m = in + 3 * n;
    const qd_expr *g = in[4 * n] = qd_param(ctx, "g");
    for (int i = 0; i < n; i++) {
        q[i] = named(ctx, "q%d", i, false);
        qd[i] = qd_jet(ctx, q[i], 1);
        l[i] = named(ctx, "l%d", i, true);
        m[i] = named(ctx, "m%d", i, true);
    }
    const qd_expr *x = qd_int(ctx, 0), *y = x, *T = x, *V = x, *half = qd_rat(ctx, 1, 2);
    for (int i = 0; i < n; i++) {
        x = qd_add(ctx, x, qd_mul(ctx, l[i], qd_fn(ctx, QD_SIN, q[i])));
        y = qd_sub(ctx, y, qd_mul(ctx, l[i], qd_fn(ctx, QD_COS, q[i])));
        const qd_expr *v2 = qd_add(ctx, qd_powi(ctx, qd_dt(ctx, x), 2),
                                   qd_powi(ctx, qd_dt(ctx, y), 2));
        T = qd_add(ctx, T, qd_mul(ctx, qd_mul(ctx, half, m[i]), v2));
        V = qd_add(ctx, V, qd_mul(ctx, qd_mul(ctx, m[i], g), y));
    }
    for (int j = 0; j < n; j++) {
        const qd_expr *dT = qd_diff(ctx, T, qd[j]);
        for (int k = 0; k < n; k++)
            out[j * n + k] = qd_diff(ctx, dT, qd[k]);
        out[n * n + j] = qd_diff(ctx, V, q[j]);
    }
}

static double now(void) {
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

static double max_rel_diff(const double *a, const double *b, int n) {
    double worst = 0;
    for (int i = 0; i < n; i++)
        worst = fmax(worst, fabs(a[i] - b[i]) / fmax(1, fabs(b[i])));
    return worst;
}

/* The machine is shared and noisy: the best of BATCHES batches. */
#define BATCHES 7

static double time_prog(qd_prog *p, double pts[][4 * NMAX + 1], double *out, long runs) {
    double best = INFINITY, sink = 0;
    for (int b = 0; b < BATCHES; b++) {
        double t0 = now();
        for (long r = 0; r < runs / BATCHES; r++) {
            qd_prog_run(p, pts[r % NPTS], out);
            sink += out[0];
        }
        best = fmin(best, now() - t0);
    }
    if (sink == 42) /* keep the loop */
        puts("");
    return best / (runs / BATCHES);
}

static double time_ref(int n, double pts[][4 * NMAX + 1], double *out, long runs) {
    double best = INFINITY, sink = 0;
    for (int b = 0; b < BATCHES; b++) {
        double t0 = now();
        for (long r = 0; r < runs / BATCHES; r++) {
            ref_eval(n, pts[r % NPTS], out);
            sink += out[0];
        }
        best = fmin(best, now() - t0);
    }
    if (sink == 42)
        puts("");
    return best / (runs / BATCHES);
}

int main(int argc, char **argv) {
    int n = argc > 1 ? atoi(argv[1]) : 8;
    long runs = argc > 2 ? atol(argv[2]) : 700000;
    if (n < 1 || n > NMAX || runs < BATCHES)
        return fprintf(stderr, "usage: %s [n <= %d] [runs]\n", argv[0], NMAX), 2;
    int nin = 4 * n + 1, nout = n * n + n;
    qd_ctx *ctx = qd_ctx_new();
    const qd_expr *in[4 * NMAX + 1], **out = malloc(nout * sizeof *out);
    double t0 = now();
    pendulum(ctx, n, in, out);
    double t_build = now() - t0;
    t0 = now();
    qd_prog *p = qd_prog_new(ctx, nin, in, nout, out);
    double t_compile = now() - t0;
    if (!p)
        return fprintf(stderr, "compile failed: %s\n", qd_ctx_message(ctx)), 1;
    size_t dag = 0;
    for (int i = 0; i < nout; i++)
        dag += qd_dag_size(ctx, out[i]);

    static double pts[NPTS][4 * NMAX + 1];
    srand(1);
    for (int k = 0; k < NPTS; k++)
        for (int i = 0; i < nin; i++)
            pts[k][i] = i < 2 * n ? 2.0 * rand() / RAND_MAX - 1 : 0.5 + 1.0 * rand() / RAND_MAX;
    double *a = malloc(nout * sizeof *a), *b = malloc(nout * sizeof *b), worst = 0;
    for (int k = 0; k < NPTS; k++) {
        qd_prog_run(p, pts[k], a);
        ref_eval(n, pts[k], b);
        worst = fmax(worst, max_rel_diff(a, b, nout));
    }

    double tp = time_prog(p, pts, a, runs), tr = time_ref(n, pts, b, runs);
    printf("n-pendulum, n = %d: %d outputs, %zu instructions "
           "(sum of output DAG sizes %zu, %zu nodes in the context)\n",
           n, nout, qd_prog_ninstr(p), dag, qd_ctx_node_count(ctx));
    printf("build %.1f ms, compile %.2f ms, max relative difference %.1e\n",
           1e3 * t_build, 1e3 * t_compile, worst);
    printf("qd_prog_run  %8.1f ns/eval (%.2f ns/instruction)\n", 1e9 * tp,
           1e9 * tp / qd_prog_ninstr(p));
    printf("hand-written %8.1f ns/eval\nratio        %8.2f\n", 1e9 * tr, tp / tr);
    qd_prog_free(p);
    qd_ctx_free(ctx);
    free(out), free(a), free(b);
    return worst < 1e-12 ? 0 : 1;
}

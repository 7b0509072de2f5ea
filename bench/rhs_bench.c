/*
 * bench/rhs_bench.c - one right-hand side of the planar n-link pendulum,
 * five ways (bench/run_rhs.py drives it; bench/README-rhs in
 * docs/parts/codegen-design.md):
 *
 *   eom_eval   qd_eom_eval: the library's compiled program for M and f
 *              plus its dense solver, as `qdot simulate` without --native
 *   prog       qd_prog_run on M and f with the inputs in a flat array, then
 *              the same Cholesky as the hand-written code: the interpreter
 *              alone
 *   native     qd_native_load's generated, compiled and loaded rhs
 *   textbook   bench/rhs_hand.c, sin and cos of every angle difference
 *   sincos     bench/rhs_hand.c, addition theorems on per-angle sin, cos
 *
 * Usage: rhs_bench N CACHE_DIR [seconds]
 * The results of all five are compared at NPTS random states first (they
 * must agree to 1e-9 relative); then each is timed over the same rotating
 * states, best of BATCHES batches, wall clock.  Output: tab-separated lines
 * `time NAME N NS_PER_CALL` and `info KEY VALUE`.
 */
#define _POSIX_C_SOURCE 199309L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "qdot/qdot.h"
#include "qdot/codegen.h"

#define NMAX 64
#define NPTS 64
#define BATCHES 7

int hand_rhs_textbook(int n, const double *y, const double *par, double *dydt);
int hand_rhs_sincos(int n, const double *y, const double *par, double *dydt);
int hand_cholesky(int n, double *M, double *x);

static double now(void) {
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static void model_text(qd_buf *b, int n) {
    qd_buf_printf(b, "# planar %d-link pendulum (bench/rhs_bench.c)\ncoordinates ", n);
    for (int i = 1; i <= n; i++)
        qd_buf_printf(b, "%stheta%d", i > 1 ? ", " : "", i);
    qd_buf_puts(b, "\nparameters ");
    for (int i = 1; i <= n; i++)
        qd_buf_printf(b, "m%d = %g, ", i, 1 + 0.1 * (i % 3));
    for (int i = 1; i <= n; i++)
        qd_buf_printf(b, "l%d = %g, ", i, 1 - 0.01 * i);
    qd_buf_puts(b, "g = 9.81\n\nx1 = l1*sin(theta1)\ny1 = -l1*cos(theta1)\n");
    for (int i = 2; i <= n; i++)
        qd_buf_printf(b, "x%d = x%d + l%d*sin(theta%d)\ny%d = y%d - l%d*cos(theta%d)\n", i,
                      i - 1, i, i, i, i - 1, i, i);
    qd_buf_puts(b, "\nT =");
    for (int i = 1; i <= n; i++)
        qd_buf_printf(b, "%s m%d/2*(x%d'^2 + y%d'^2)", i > 1 ? " +" : "", i, i, i);
    qd_buf_puts(b, "\nV =");
    for (int i = 1; i <= n; i++)
        qd_buf_printf(b, "%s m%d*g*y%d", i > 1 ? " +" : "", i, i);
    qd_buf_puts(b, "\n");
}

typedef struct bench {
    int n, np;
    qd_ctx *ctx;
    qd_eom *e;
    qd_native nat;
    qd_prog *prog;
    const qd_expr *syms[4 * NMAX + 2];   /* q, q', t, params (eom_eval) */
    double y[NPTS][2 * NMAX], par[2 * NMAX + 1];
    double vals[NPTS][4 * NMAX + 2];     /* eom_eval inputs */
    double pin[NPTS][4 * NMAX + 1];      /* prog inputs: q, q', params */
    double scratch[NMAX * NMAX + NMAX];
} bench;

enum { EOM_EVAL, PROG, NATIVE, TEXTBOOK, SINCOS, NMETHODS };
static const char *const names[] = {"eom_eval", "prog", "native", "textbook", "sincos"};

static int call(bench *b, int method, int k, double *dydt) {
    int n = b->n;
    switch (method) {
    case EOM_EVAL:
        memcpy(dydt, b->y[k] + n, n * sizeof *dydt);
        return qd_eom_eval(b->ctx, b->e, 2 * n + 1 + b->np, b->syms, b->vals[k], NULL, NULL,
                           dydt + n, NULL, NULL) != QD_OK;
    case PROG:
        qd_prog_run(b->prog, b->pin[k], b->scratch);
        memcpy(dydt, b->y[k] + n, n * sizeof *dydt);
        memcpy(dydt + n, b->scratch + n * n, n * sizeof *dydt);
        return hand_cholesky(n, b->scratch, dydt + n);
    case NATIVE: return b->nat.rhs(0.0, b->y[k], b->par, dydt);
    case TEXTBOOK: return hand_rhs_textbook(n, b->y[k], b->par, dydt);
    default: return hand_rhs_sincos(n, b->y[k], b->par, dydt);
    }
}

static double time_method(bench *b, int method, double seconds) {
    double dydt[2 * NMAX], sink = 0;
    long reps = 16;
    /* grow the batch until it takes a 50th of the budget */
    for (;;) {
        double t0 = now();
        for (long r = 0; r < reps; r++)
            call(b, method, (int)(r % NPTS), dydt);
        if (now() - t0 > seconds / 50 || reps > (1L << 30))
            break;
        reps *= 2;
    }
    double best = INFINITY;
    for (int k = 0; k < BATCHES; k++) {
        double t0 = now();
        for (long r = 0; r < reps; r++) {
            call(b, method, (int)(r % NPTS), dydt);
            sink += dydt[b->n];
        }
        best = fmin(best, now() - t0);
    }
    if (sink == 42.0)
        puts("");
    return best / (double)reps;
}

static int setup(bench *b, const char *cache) {
    int n = b->n;
    qd_buf text = QD_BUF_INIT;
    model_text(&text, n);
    qd_diag d;
    b->ctx = qd_ctx_new();
    double t0 = now();
    qd_model *m = qd_model_parse(b->ctx, qd_buf_str(&text), &d);
    if (!m)
        return fprintf(stderr, "rhs_bench: %s\n", d.message), 1;
    b->e = qd_eom_derive(b->ctx, m);
    if (!b->e)
        return fprintf(stderr, "rhs_bench: %s\n", qd_ctx_message(b->ctx)), 1;
    printf("info\tderive_s\t%.4f\n", now() - t0);
    qd_buf c = QD_BUF_INIT;
    t0 = now();
    if (qd_codegen_c(b->ctx, m, b->e, "bench", &c, NULL) != QD_OK)
        return fprintf(stderr, "rhs_bench: %s\n", qd_ctx_message(b->ctx)), 1;
    printf("info\tcodegen_s\t%.4f\ninfo\tcodegen_bytes\t%zu\n", now() - t0, c.len);
    qd_buf_free(&c);
    t0 = now();
    if (qd_native_load(b->ctx, m, b->e, cache, &b->nat) != QD_OK)
        return fprintf(stderr, "rhs_bench: %s\n", qd_ctx_message(b->ctx)), 1;
    printf("info\tnative_load_s\t%.4f\ninfo\tnative_cached\t%d\n", now() - t0, b->nat.cached);
    b->np = (int)qd_model_nparams(m);
    memcpy(b->par, b->nat.par_default, b->np * sizeof *b->par);
    /* inputs */
    const qd_expr *pin[4 * NMAX + 1], *out[NMAX * NMAX + NMAX];
    for (int j = 0; j < n; j++) {
        b->syms[j] = pin[j] = b->e->q[j];
        b->syms[n + j] = pin[n + j] = b->e->qd[j];
    }
    b->syms[2 * n] = qd_time(b->ctx);
    for (int i = 0; i < b->np; i++)
        b->syms[2 * n + 1 + i] = pin[2 * n + i] = qd_model_param(m, (size_t)i);
    for (int i = 0; i < n * n + n; i++)
        out[i] = i < n * n ? b->e->M[i] : b->e->f[i - n * n];
    b->prog = qd_prog_new(b->ctx, (size_t)(2 * n + b->np), pin, (size_t)(n * n + n), out);
    if (!b->prog)
        return fprintf(stderr, "rhs_bench: %s\n", qd_ctx_message(b->ctx)), 1;
    printf("info\tprog_instructions\t%zu\n", qd_prog_ninstr(b->prog));
    srand(7);
    for (int k = 0; k < NPTS; k++) {
        for (int j = 0; j < 2 * n; j++)
            b->y[k][j] = 2.0 * rand() / RAND_MAX - 1;
        memcpy(b->vals[k], b->y[k], 2 * n * sizeof(double));
        b->vals[k][2 * n] = 0;
        memcpy(b->vals[k] + 2 * n + 1, b->par, b->np * sizeof(double));
        memcpy(b->pin[k], b->y[k], 2 * n * sizeof(double));
        memcpy(b->pin[k] + 2 * n, b->par, b->np * sizeof(double));
    }
    qd_buf_free(&text);
    qd_model_free(m); /* the equations keep what they need in the context */
    return 0;
}

static double check(bench *b) {
    double worst = 0, ref[2 * NMAX], got[2 * NMAX];
    for (int k = 0; k < NPTS; k++) {
        if (call(b, TEXTBOOK, k, ref))
            return INFINITY;
        for (int m = 0; m < NMETHODS; m++) {
            if (call(b, m, k, got))
                return INFINITY;
            for (int i = 0; i < 2 * b->n; i++)
                worst = fmax(worst, fabs(got[i] - ref[i]) / fmax(1, fabs(ref[i])));
        }
    }
    return worst;
}

int main(int argc, char **argv) {
    static bench b;
    b.n = argc > 2 ? atoi(argv[1]) : 0;
    double seconds = argc > 3 ? atof(argv[3]) : 2.0;
    if (b.n < 1 || b.n > NMAX)
        return fprintf(stderr, "usage: rhs_bench N CACHE_DIR [seconds]\n"), 2;
    if (setup(&b, argv[2]))
        return 1;
    double worst = check(&b);
    printf("info\tmax_rel_diff\t%.3g\n", worst);
    if (!(worst < 1e-9))
        return fprintf(stderr, "rhs_bench: the right-hand sides disagree (%.3g)\n", worst), 1;
    for (int m = 0; m < NMETHODS; m++)
        printf("time\t%s\t%d\t%.2f\n", names[m], b.n, 1e9 * time_method(&b, m, seconds));
    qd_prog_free(b.prog);
    qd_native_unload(&b.nat);
    qd_eom_free(b.e);
    qd_ctx_free(b.ctx);
    return 0;
}

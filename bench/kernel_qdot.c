/*
 * qdot side of the kernel benchmark (see bench/README.md).
 *
 * Prints one line per benchmark, tab-separated, the same protocol as
 * kernel_ginac and kernel_sympy.py:  name reps median_s min_s size value
 * A repetition is timed from qd_ctx_new to qd_ctx_free: it makes its own
 * symbols and expressions, so nothing is reused from an earlier one.  Only
 * the public API is used.
 */
#define _POSIX_C_SOURCE 199309L
#include <qdot/qdot.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

typedef struct opts {
    double budget;  /* seconds of timed runs per benchmark */
    int min_reps;
    int max_reps;
} opts;

enum { MAXOUT = 2 };

/* What a benchmark computed: its outputs and the symbols of the point. */
typedef struct result {
    size_t nout;
    const qd_expr *out[MAXOUT];
    const qd_expr *sym[4];
} result;

/* The evaluation point, the same in all three programs. */
static const double POINT[4] = {0.125, 0.25, 0.375, 0.5};

static void symbols(qd_ctx *ctx, result *r) {
    static const char *const names[4] = {"x", "y", "z", "w"};
    for (int i = 0; i < 4; i++)
        r->sym[i] = qd_symbol(ctx, names[i]);
    r->nout = 1;
}

static void expand1(qd_ctx *ctx, result *r) {
    symbols(ctx, r);
    const qd_expr *const t[4] = {qd_int(ctx, 1), r->sym[0], r->sym[1], r->sym[2]};
    r->out[0] = qd_expand(ctx, qd_powi(ctx, qd_add_n(ctx, 4, t), 20));
}

static void expand2(qd_ctx *ctx, result *r) {
    symbols(ctx, r);
    const qd_expr *e = qd_expand(ctx, qd_powi(ctx, qd_add_n(ctx, 4, r->sym), 15));
    r->out[0] = qd_expand(ctx, qd_mul(ctx, e, qd_diff(ctx, e, r->sym[0])));
}

static void diff10(qd_ctx *ctx, result *r) {
    symbols(ctx, r);
    const qd_expr *x = r->sym[0];
    const qd_expr *f = qd_mul(ctx, qd_powi(ctx, qd_fn(ctx, QD_SIN, x), 4),
                              qd_mul(ctx, qd_fn(ctx, QD_COS, x), qd_fn(ctx, QD_EXP, x)));
    r->out[0] = qd_diff_n(ctx, f, x, 10);
}

static void trig200(qd_ctx *ctx, result *r) {
    symbols(ctx, r);
    const qd_expr *x = r->sym[0], *y = r->sym[1], *s = qd_int(ctx, 0);
    for (long k = 1; k <= 200; k++) {
        const qd_expr *kk = qd_int(ctx, k);
        const qd_expr *sk = qd_fn(ctx, QD_SIN, qd_mul(ctx, kk, x));
        const qd_expr *ck = qd_fn(ctx, QD_COS, qd_mul(ctx, kk, y));
        s = qd_add(ctx, s, qd_mul(ctx, kk, qd_mul(ctx, sk, ck)));
    }
    r->nout = 2;
    r->out[0] = qd_diff(ctx, s, x);
    r->out[1] = qd_diff(ctx, s, y);
}

typedef struct bench {
    const char *name;
    void (*fn)(qd_ctx *, result *);
} bench;

static const bench BENCHES[] = {
    {"expand1", expand1}, {"expand2", expand2}, {"diff10", diff10}, {"trig200", trig200}};

/* Processor time of this process: the machine may be shared, and waiting for
 * a processor is not the kernel's cost. */
static double now(void) {
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static size_t nterms(const qd_expr *e) {
    return qd_expr_kind(e) == QD_ADD ? qd_expr_nargs(e) : 1;
}

/* Untimed: the result's size (top-level terms, summed over the outputs) and
 * its value at the point, to show the three systems computed the same thing. */
static int check(const bench *b, size_t *size, double *value) {
    qd_ctx *ctx = qd_ctx_new();
    result r = {0};
    b->fn(ctx, &r);
    *size = 0;
    *value = 0.0;
    for (size_t i = 0; i < r.nout; i++) {
        double v = 0.0;
        if (!r.out[i] || qd_eval(ctx, r.out[i], 4, r.sym, POINT, &v) != QD_OK) {
            fprintf(stderr, "kernel_qdot: %s failed: %s\n", b->name, qd_ctx_message(ctx));
            qd_ctx_free(ctx);
            return -1;
        }
        *size += nterms(r.out[i]);
        *value += v;
    }
    qd_ctx_free(ctx);
    return 0;
}

static double one_run(const bench *b) {
    double t0 = now();
    qd_ctx *ctx = qd_ctx_new();
    result r = {0};
    b->fn(ctx, &r);
    if (!r.out[0])
        abort(); /* check() already succeeded on the same input */
    qd_ctx_free(ctx);
    return now() - t0;
}

static int cmp_double(const void *a, const void *b) {
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static int run(const bench *b, const opts *o, double *t) {
    size_t size;
    double value, total = 0.0;
    if (check(b, &size, &value) != 0) /* also the warm-up */
        return -1;
    int n = 0;
    while (n < o->max_reps && (n < o->min_reps || total < o->budget)) {
        t[n] = one_run(b);
        total += t[n++];
    }
    qsort(t, (size_t)n, sizeof *t, cmp_double);
    double med = n % 2 ? t[n / 2] : 0.5 * (t[n / 2 - 1] + t[n / 2]);
    printf("%s\t%d\t%.6e\t%.6e\t%zu\t%.15g\n", b->name, n, med, t[0], size, value);
    fflush(stdout);
    return 0;
}

static int wanted(const char *name, int argc, char **argv, int first) {
    if (first >= argc)
        return 1;
    for (int i = first; i < argc; i++)
        if (strcmp(argv[i], name) == 0)
            return 1;
    return 0;
}

static int parse_opts(int argc, char **argv, opts *o) {
    int i = 1;
    for (; i + 1 < argc && strncmp(argv[i], "--", 2) == 0; i += 2) {
        if (!strcmp(argv[i], "--budget"))
            o->budget = atof(argv[i + 1]);
        else if (!strcmp(argv[i], "--min-reps"))
            o->min_reps = atoi(argv[i + 1]);
        else if (!strcmp(argv[i], "--max-reps"))
            o->max_reps = atoi(argv[i + 1]);
        else {
            fprintf(stderr, "kernel_qdot: unknown option %s\n", argv[i]);
            return -1;
        }
    }
    if (o->max_reps < 1 || o->min_reps > o->max_reps) {
        fprintf(stderr, "kernel_qdot: need 1 <= min-reps <= max-reps\n");
        return -1;
    }
    return i;
}

/* Usage: kernel_qdot [--budget S] [--min-reps N] [--max-reps N] [names...] */
int main(int argc, char **argv) {
    opts o = {1.0, 5, 1000};
    int first = parse_opts(argc, argv, &o);
    if (first < 0)
        return 2;
    double *t = malloc((size_t)o.max_reps * sizeof *t);
    if (!t)
        return 1;
    int rc = 0;
    for (size_t i = 0; i < sizeof BENCHES / sizeof BENCHES[0]; i++)
        if (wanted(BENCHES[i].name, argc, argv, first) && run(&BENCHES[i], &o, t) != 0)
            rc = 1;
    free(t);
    return rc;
}

/*
 * qdot side of the n-link pendulum benchmark (see bench/README.md).
 *
 * The planar n-link pendulum: point masses m_i on massless rods l_i, angles
 * theta_i from the downward vertical, gravity g, all symbolic.  The model
 * text is generated in memory, the way a user would write it (x_i, y_i
 * defined link by link, T and V as sums).  A repetition is timed from
 * qd_ctx_new to qd_ctx_free: parse the text, derive Lagrange's equations
 * (every entry of M and f simplified), free everything.
 *
 * Prints one tab-separated line per n:  n reps median_s min_s ops
 * where ops is qd_count_ops summed over the n*n entries of M and the n of f.
 * `--emit N` prints the model text for N instead (the driver feeds it to
 * `qdot eom`, so both time the same model).
 */
#define _POSIX_C_SOURCE 199309L
#include <qdot/mech.h>
#include <qdot/model.h>
#include <qdot/qdot.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

typedef struct opts {
    double budget; /* seconds of timed runs per n */
    int min_reps;
    int max_reps;
} opts;

/* "theta1, theta2, ..., thetaN" for fmt "theta%d". */
static void list(qd_buf *b, const char *fmt, int n) {
    for (int i = 1; i <= n; i++) {
        if (i > 1)
            qd_buf_puts(b, ", ");
        qd_buf_printf(b, fmt, i);
    }
}

static void model_text(qd_buf *b, int n) {
    qd_buf_printf(b, "# planar %d-link pendulum (bench/pendulum_qdot.c)\ncoordinates ", n);
    list(b, "theta%d", n);
    qd_buf_puts(b, "\nparameters ");
    list(b, "m%d = 1", n);
    qd_buf_puts(b, ", ");
    list(b, "l%d = 1", n);
    qd_buf_puts(b, ", g = 9.81\n\nx1 = l1*sin(theta1)\ny1 = -l1*cos(theta1)\n");
    for (int i = 2; i <= n; i++)
        qd_buf_printf(b, "x%d = x%d + l%d*sin(theta%d)\ny%d = y%d - l%d*cos(theta%d)\n",
                      i, i - 1, i, i, i, i - 1, i, i);
    qd_buf_puts(b, "\nT =");
    for (int i = 1; i <= n; i++)
        qd_buf_printf(b, "%s m%d/2*(x%d'^2 + y%d'^2)", i > 1 ? " +" : "", i, i, i);
    qd_buf_puts(b, "\nV =");
    for (int i = 1; i <= n; i++)
        qd_buf_printf(b, "%s m%d*g*y%d", i > 1 ? " +" : "", i, i);
    qd_buf_puts(b, "\n");
}

/* Processor time of this process, as in kernel_qdot.c. */
static double now(void) {
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* One repetition: parse + derive in a fresh context.  When ops is not NULL
 * (the untimed check run) also the size of M and f.  -1 on failure. */
static int derive(const char *text, size_t *ops) {
    qd_ctx *ctx = qd_ctx_new();
    qd_diag d;
    qd_model *m = ctx ? qd_model_parse(ctx, text, &d) : NULL;
    qd_eom *e = m ? qd_eom_derive(ctx, m) : NULL;
    if (!e) {
        fprintf(stderr, "pendulum_qdot: %s\n",
                m ? qd_ctx_message(ctx) : ctx ? d.message : "out of memory");
    } else if (ops) {
        *ops = 0;
        for (size_t i = 0; i < e->n * e->n; i++)
            *ops += qd_count_ops(e->M[i]);
        for (size_t i = 0; i < e->n; i++)
            *ops += qd_count_ops(e->f[i]);
    }
    int rc = e ? 0 : -1;
    qd_eom_free(e);
    qd_model_free(m);
    qd_ctx_free(ctx);
    return rc;
}

static int cmp_double(const void *a, const void *b) {
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static int run(int n, const opts *o, double *t) {
    qd_buf b = QD_BUF_INIT;
    model_text(&b, n);
    size_t ops = 0;
    if (derive(qd_buf_str(&b), &ops) != 0) { /* also the warm-up */
        qd_buf_free(&b);
        return -1;
    }
    int k = 0;
    double total = 0.0;
    while (k < o->max_reps && (k < o->min_reps || total < o->budget)) {
        double t0 = now();
        if (derive(qd_buf_str(&b), NULL) != 0)
            abort(); /* the same text just succeeded */
        t[k] = now() - t0;
        total += t[k++];
    }
    qd_buf_free(&b);
    qsort(t, (size_t)k, sizeof *t, cmp_double);
    double med = k % 2 ? t[k / 2] : 0.5 * (t[k / 2 - 1] + t[k / 2]);
    printf("%d\t%d\t%.6e\t%.6e\t%zu\n", n, k, med, t[0], ops);
    fflush(stdout);
    return 0;
}

static int emit(int n) {
    qd_buf b = QD_BUF_INIT;
    model_text(&b, n);
    fputs(qd_buf_str(&b), stdout);
    qd_buf_free(&b);
    return 0;
}

static int parse_opts(int argc, char **argv, opts *o, int *emit_n) {
    int i = 1;
    for (; i + 1 < argc && strncmp(argv[i], "--", 2) == 0; i += 2) {
        if (!strcmp(argv[i], "--budget"))
            o->budget = atof(argv[i + 1]);
        else if (!strcmp(argv[i], "--min-reps"))
            o->min_reps = atoi(argv[i + 1]);
        else if (!strcmp(argv[i], "--max-reps"))
            o->max_reps = atoi(argv[i + 1]);
        else if (!strcmp(argv[i], "--emit"))
            *emit_n = atoi(argv[i + 1]);
        else {
            fprintf(stderr, "pendulum_qdot: unknown option %s\n", argv[i]);
            return -1;
        }
    }
    if (o->max_reps < 1 || o->min_reps > o->max_reps) {
        fprintf(stderr, "pendulum_qdot: need 1 <= min-reps <= max-reps\n");
        return -1;
    }
    return i;
}

/* Usage: pendulum_qdot [--budget S] [--min-reps N] [--max-reps N] [n...]
 *        pendulum_qdot --emit N */
int main(int argc, char **argv) {
    opts o = {1.0, 5, 1000};
    int emit_n = 0;
    int first = parse_opts(argc, argv, &o, &emit_n);
    if (first < 0)
        return 2;
    if (emit_n > 0)
        return emit(emit_n);
    static const int DEFAULT_N[] = {2, 4, 8, 16, 32};
    double *t = malloc((size_t)o.max_reps * sizeof *t);
    if (!t)
        return 1;
    int rc = 0;
    if (first >= argc) {
        for (size_t i = 0; i < sizeof DEFAULT_N / sizeof DEFAULT_N[0]; i++)
            rc |= run(DEFAULT_N[i], &o, t) != 0;
    }
    for (int i = first; i < argc; i++) {
        int n = atoi(argv[i]);
        rc |= (n < 1 || run(n, &o, t) != 0);
    }
    free(t);
    return rc;
}

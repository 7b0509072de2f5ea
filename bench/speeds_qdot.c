/*
 * bench/speeds_qdot.c - qdot side of the generalized-speeds benchmark
 * (bench/run_speeds.py drives it; see bench/README.md).
 *
 * For a model with `speeds` and nonholonomic constraints, times in the same
 * run (so the ratio is not at the mercy of the machine's load):
 *   speeds:<method>  parse + qd_speeds_derive by Kane, Gibbs-Appell or
 *                    Boltzmann-Hamel: M_u u' = f_u, m equations;
 *   multipliers      parse + qd_eom_derive of the same text without its
 *                    `speeds` line: M q'' = f + A^T lambda, A q'' = b, the
 *                    formulation qdot had before speeds;
 *   multipliers+solve  the same, then qd_eom_solve: q'' and lambda
 *                    explicit, the reduced equations' counterpart.
 * A repetition runs from qd_ctx_new to qd_ctx_free (fresh context: nothing
 * is remembered from the previous one); processor time of this process.
 *
 * Prints one tab-separated line per variant:
 *   model variant reps median_s min_s ops
 * ops: qd_count_ops summed over M_u and f_u (speeds), M, f, A, b
 * (multipliers) or q'' and lambda (multipliers+solve).  `--print FILE` prints instead, in SymPy syntax, the Kane
 * equations (lines "M r s EXPR", "f r EXPR", "kin j EXPR") for the driver's
 * agreement check, and the multiplier formulation ("EM j k", "Ef j",
 * "EA k j", "Eb k") for its sizes.
 * `--count VARIANT N FILE` derives that variant N times and prints nothing:
 * the driver runs it under callgrind with N = 1 and N = 3, and half the
 * difference is the instructions of one derivation, free of start-up and
 * of the machine's load (processor time on a shared machine varies by tens
 * of percent between runs; instruction counts do not).
 * Usage: speeds_qdot [--budget S] [--min-reps N] FILE.qd ...
 *        speeds_qdot --print FILE.qd
 *        speeds_qdot --count speeds:kane|speeds:appell|speeds:hamel|multipliers N FILE.qd
 */
#define _POSIX_C_SOURCE 199309L
#include <qdot/qdot.h>
#include <qdot/speeds.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define MAX_REPS 2000
#define MULTIPLIERS (-1)
#define SOLVED (-2)

typedef struct opts {
    double budget; /* seconds of timed runs per variant */
    int min_reps;
} opts;

/* strdup is POSIX, not C11. */
static char *copy(const char *s) {
    size_t n = strlen(s) + 1;
    char *c = malloc(n);
    return c ? memcpy(c, s, n) : NULL;
}

static char *slurp(const char *path) {
    FILE *fp = fopen(path, "rb");
    if (!fp)
        return NULL;
    qd_buf b = QD_BUF_INIT;
    char chunk[4096];
    size_t k;
    while ((k = fread(chunk, 1, sizeof chunk, fp)) > 0)
        qd_buf_putn(&b, chunk, k);
    fclose(fp);
    char *text = copy(qd_buf_str(&b));
    qd_buf_free(&b);
    return text;
}

/* Does the line at s start the statement kw? */
static int starts(const char *s, const char *kw) {
    size_t n = strlen(kw);
    return strncmp(s, kw, n) == 0 && (s[n] == ' ' || s[n] == '\t');
}

/* The model text without its `speeds` statement (one line), for the
 * multiplier formulation of the same system; `initial` lines go too (they
 * may name speeds, and deriving does not need them). */
static char *without_speeds(const char *text) {
    char *out = copy(text);
    if (!out)
        return NULL;
    char *p = out;
    while (p && *p) {
        char *eol = strchr(p, '\n');
        const char *s = p + strspn(p, " \t");
        if (starts(s, "speeds") || starts(s, "initial")) {
            size_t rest = eol ? strlen(eol) : 0;
            memmove(p, eol ? eol : p + strlen(p), rest + 1);
            continue;
        }
        p = eol ? eol + 1 : NULL;
    }
    return out;
}

static double now(void) {
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static size_t sum_ops(size_t n, const qd_expr *const *e) {
    size_t ops = 0;
    for (size_t i = 0; i < n; i++)
        ops += qd_count_ops(e[i]);
    return ops;
}

static size_t speeds_ops(const qd_speeds_eom *e) {
    return sum_ops(e->m * e->m, e->M) + sum_ops(e->m, e->f);
}

static size_t eom_ops(const qd_eom *e) {
    return sum_ops(e->n * e->n, e->M) + sum_ops(e->n, e->f) + sum_ops(e->ncon * e->n, e->A) +
           sum_ops(e->ncon, e->b);
}

/* q'' and lambda solved symbolically (qd_eom_solve) */
static size_t solved_ops(const qd_eom *e) {
    return sum_ops(e->n, e->acc) + sum_ops(e->ncon, e->mult);
}

/* One repetition in a fresh context: method >= 0 derives in speeds by that
 * method, MULTIPLIERS with multipliers, SOLVED with multipliers and then
 * q'' and lambda solved for; the size when ops is not NULL. */
static int derive(const char *text, int method, size_t *ops) {
    qd_ctx *ctx = qd_ctx_new();
    qd_diag d;
    qd_model *m = ctx ? qd_model_parse(ctx, text, &d) : NULL;
    int rc = -1;
    if (m && method >= 0) {
        qd_speeds_opts o = {.method = (qd_speeds_method)method};
        qd_speeds_eom *e = qd_speeds_derive(ctx, m, &o);
        if (e && ops)
            *ops = speeds_ops(e);
        rc = e ? 0 : -1;
        qd_speeds_eom_free(e);
    } else if (m) {
        qd_eom *e = qd_eom_derive(ctx, m);
        if (e && method == SOLVED && qd_eom_solve(ctx, e, (size_t)-1) != QD_OK) {
            qd_eom_free(e);
            e = NULL;
        }
        if (e && ops)
            *ops = method == SOLVED ? solved_ops(e) : eom_ops(e);
        rc = e ? 0 : -1;
        qd_eom_free(e);
    }
    if (rc != 0)
        fprintf(stderr, "speeds_qdot: %s\n",
                m ? qd_ctx_message(ctx) : ctx ? d.message : "out of memory");
    qd_model_free(m);
    qd_ctx_free(ctx);
    return rc;
}

static int cmp_double(const void *a, const void *b) {
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static int run(const char *model, const char *variant, const char *text, int method,
               const opts *o) {
    static double t[MAX_REPS];
    size_t ops = 0;
    if (derive(text, method, &ops) != 0) /* also the warm-up */
        return -1;
    int k = 0;
    double total = 0.0;
    while (k < MAX_REPS && (k < o->min_reps || total < o->budget)) {
        double t0 = now();
        if (derive(text, method, NULL) != 0)
            abort(); /* the same text just succeeded */
        t[k] = now() - t0;
        total += t[k++];
    }
    qsort(t, (size_t)k, sizeof *t, cmp_double);
    double med = k % 2 ? t[k / 2] : 0.5 * (t[k / 2 - 1] + t[k / 2]);
    printf("%s\t%s\t%d\t%.6e\t%.6e\t%zu\n", model, variant, k, med, t[0], ops);
    fflush(stdout);
    return 0;
}

static const char *model_name(const char *path, char *buf, size_t len) {
    const char *base = strrchr(path, '/');
    snprintf(buf, len, "%s", base ? base + 1 : path);
    char *dot = strrchr(buf, '.');
    if (dot)
        *dot = '\0';
    return buf;
}

/* Every variant of one model, one after the other; the driver runs this
 * several rounds and keeps each variant's best median. */
static int bench_file(const char *path, const opts *o) {
    char *text = slurp(path);
    char *plain = text ? without_speeds(text) : NULL;
    char name[128];
    int rc = text && plain ? 0 : -1;
    model_name(path, name, sizeof name);
    for (int k = 0; rc == 0 && k < QD_SPEEDS_METHOD_COUNT; k++) {
        char variant[32];
        snprintf(variant, sizeof variant, "speeds:%s", qd_speeds_method_name((qd_speeds_method)k));
        rc |= run(name, variant, text, k, o);
    }
    if (rc == 0)
        rc |= run(name, "multipliers", plain, MULTIPLIERS, o);
    /* qd_eom_solve may refuse (QD_ERR_TOOBIG): reported, not an error */
    if (rc == 0 && run(name, "multipliers+solve", plain, SOLVED, o) != 0)
        printf("%s\tmultipliers+solve\tfailed\n", name);
    if (!text)
        fprintf(stderr, "speeds_qdot: cannot read %s\n", path);
    free(plain);
    free(text);
    return rc;
}

static int item(qd_ctx *ctx, const char *tag, const qd_expr *e) {
    qd_buf b = QD_BUF_INIT;
    int bad = qd_print(ctx, e, QD_FMT_SYMPY, &b) != QD_OK;
    if (!bad)
        printf("%s %s\n", tag, qd_buf_str(&b));
    qd_buf_free(&b);
    return bad;
}

/* The multiplier formulation of the same text: "EM j k", "Ef j", "EA k j",
 * "Eb k" lines (M, f, A, b of qd_eom). */
static int print_multipliers(const char *text) {
    char *plain = without_speeds(text);
    qd_ctx *ctx = qd_ctx_new();
    qd_diag d;
    qd_model *m = plain && ctx ? qd_model_parse(ctx, plain, &d) : NULL;
    qd_eom *e = m ? qd_eom_derive(ctx, m) : NULL;
    int bad = !e;
    char tag[48];
    for (size_t j = 0; e && j < e->n; j++) {
        for (size_t k = 0; k < e->n; k++) {
            snprintf(tag, sizeof tag, "EM %zu %zu", j, k);
            bad |= item(ctx, tag, e->M[j * e->n + k]);
        }
        snprintf(tag, sizeof tag, "Ef %zu", j);
        bad |= item(ctx, tag, e->f[j]);
    }
    for (size_t k = 0; e && k < e->ncon; k++) {
        for (size_t j = 0; j < e->n; j++) {
            snprintf(tag, sizeof tag, "EA %zu %zu", k, j);
            bad |= item(ctx, tag, e->A[k * e->n + j]);
        }
        snprintf(tag, sizeof tag, "Eb %zu", k);
        bad |= item(ctx, tag, e->b[k]);
    }
    if (bad)
        fprintf(stderr, "speeds_qdot: multipliers: %s\n", m ? qd_ctx_message(ctx) : d.message);
    qd_eom_free(e);
    qd_model_free(m);
    qd_ctx_free(ctx);
    free(plain);
    return bad;
}

static int print_file(const char *path) {
    char *text = slurp(path);
    qd_ctx *ctx = qd_ctx_new();
    qd_diag d;
    qd_model *m = text && ctx ? qd_model_parse(ctx, text, &d) : NULL;
    qd_speeds_eom *e = m ? qd_speeds_derive(ctx, m, NULL) : NULL;
    int bad = !e;
    char tag[48];
    for (size_t r = 0; e && r < e->m; r++) {
        for (size_t s = 0; s < e->m; s++) {
            snprintf(tag, sizeof tag, "M %zu %zu", r, s);
            bad |= item(ctx, tag, e->M[r * e->m + s]);
        }
        snprintf(tag, sizeof tag, "f %zu", r);
        bad |= item(ctx, tag, e->f[r]);
    }
    for (size_t j = 0; e && j < e->n; j++) {
        snprintf(tag, sizeof tag, "kin %zu", j);
        bad |= item(ctx, tag, e->kin[j]);
    }
    if (bad)
        fprintf(stderr, "speeds_qdot: %s: %s\n", path,
                !m ? (text ? d.message : "cannot read") : qd_ctx_message(ctx));
    qd_speeds_eom_free(e);
    qd_model_free(m);
    qd_ctx_free(ctx);
    if (!bad)
        bad = print_multipliers(text);
    free(text);
    return bad;
}

/* --count: `reps` derivations of one variant, untimed. */
static int count(const char *variant, int reps, const char *path) {
    int method = MULTIPLIERS;
    if (strncmp(variant, "speeds:", 7) == 0) {
        qd_speeds_method k;
        if (!qd_speeds_method_from_name(variant + 7, &k))
            return 2;
        method = (int)k;
    } else if (strcmp(variant, "multipliers") != 0) {
        return 2;
    }
    char *text = slurp(path);
    char *use = text && method == MULTIPLIERS ? without_speeds(text) : text;
    int rc = use ? 0 : 1;
    for (int r = 0; rc == 0 && r < reps; r++)
        rc = derive(use, method, NULL) != 0;
    if (use != text)
        free(use);
    free(text);
    return rc;
}

int main(int argc, char **argv) {
    if (argc == 5 && !strcmp(argv[1], "--count"))
        return count(argv[2], atoi(argv[3]), argv[4]);
    opts o = {1.0, 5};
    int i = 1;
    for (; i + 1 < argc && strncmp(argv[i], "--", 2) == 0; i += 2) {
        if (!strcmp(argv[i], "--budget"))
            o.budget = atof(argv[i + 1]);
        else if (!strcmp(argv[i], "--min-reps"))
            o.min_reps = atoi(argv[i + 1]);
        else if (!strcmp(argv[i], "--print"))
            return print_file(argv[i + 1]);
        else {
            fprintf(stderr, "speeds_qdot: unknown option %s\n", argv[i]);
            return 2;
        }
    }
    if (i >= argc || o.min_reps < 1 || o.min_reps > MAX_REPS) {
        fprintf(stderr, "usage: speeds_qdot [--budget S] [--min-reps N] FILE.qd ...\n");
        return 2;
    }
    int rc = 0;
    for (; i < argc; i++)
        rc |= bench_file(argv[i], &o) != 0;
    return rc;
}

/*
 * cli/cmd_lyapunov.c - `qdot lyapunov FILE --t-end T [--exponents K] [--renorm DT]
 * [--transient T0] [simulate options] [--format text|json]`: the K largest
 * Lyapunov exponents of the motion from the model's initial state
 * (qdot/lyapunov.h), their error estimates, and the check their sum
 * allows: with all 2n of them, the sum equals the time average of tr J
 * (Liouville), 0 for a conservative system, whose exponents also pair,
 * lambda_i + lambda_{2n+1-i} = 0.
 */
#include "cli.h"

#include <stddef.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "qdot/json.h"
#include "sim_cli.h"

typedef struct ly_args {
    cli_sim_args a;
    size_t n;
    const char *renorm_text, *transient_text, *format;
    double renorm, transient;
} ly_args;

static const char *const formats[] = {"text", "json", NULL};

static const cli_opt opts[] = {
    {"--exponents", NULL, CLI_COUNT, offsetof(ly_args, n), "K", "the K largest exponents (1)", NULL,
     NULL},
    {"--renorm", NULL, CLI_TEXT, offsetof(ly_args, renorm_text), "DT",
     "the time between renormalizations (1)", NULL, NULL},
    {"--transient", NULL, CLI_TEXT, offsetof(ly_args, transient_text), "T0",
     "the time run before the averaging starts (0)", NULL, NULL},
    {"--format", NULL, CLI_CHOICE, offsetof(ly_args, format), "F", "how the result is printed",
     formats, NULL},
    {NULL, NULL, CLI_FLAG, 0, NULL, NULL, NULL, NULL},
};

static const cli_group groups[] = {
    CLI_SIM_GROUP(ly_args, a),
    {NULL, 0},
};

static const cli_spec spec = {
    "lyapunov", "FILE --t-end T [options]",
    "the largest Lyapunov exponents of the motion from the initial state, with error estimates",
    opts, groups, 1, 1, "FILE", false,
};

/* A time >= 0, or an exit status. */
static int number(const char *opt, const char *v, double *out) {
    char *end;
    double x = v ? strtod(v, &end) : 0;
    if (v && (end == v || *end || !isfinite(x) || x < 0)) {
        cli_diag_error("%s takes a number >= 0, not '%s'", opt, v);
        return QD_EXIT_USAGE;
    }
    *out = x;
    return QD_EXIT_OK;
}

/* What was measured, for either format. */
typedef struct ly_result {
    size_t k, d;           /* exponents computed; 2n */
    double *ex, *err;
    qd_lyap_stats st;
    bool conservative;
} ly_result;

static double sum_of(const ly_result *r) {
    double s = 0;
    for (size_t j = 0; j < r->k; j++)
        s += r->ex[j];
    return s;
}

/* Round-off's -0.000000 printed as 0. */
static double clean(double x) { return fabs(x) < 5e-7 ? 0.0 : x; }

/* Six decimals, the digits the estimates have. */
static void fixed(const char *before, double x) { printf("%s% .6f", before, clean(x)); }

static void print_text(const ly_result *r) {
    for (size_t j = 0; j < r->k; j++) {
        printf("lambda_%zu", j + 1);
        fixed(" = ", r->ex[j]);
        if (isnan(r->err[j]))
            printf("  (no error estimate: fewer than 2 renormalizations in the last half)\n");
        else
            printf("  +- %.2g\n", r->err[j]);
    }
    fixed("mean tr J = ", r->st.trace_mean);
    printf("  (the sum of all %zu exponents, Liouville%s)\n", r->d,
           r->conservative ? "; -> 0 as T grows for a conservative system" : "");
    if (r->k == r->d)
        fixed("sum       = ", sum_of(r));
    if (r->k == r->d)
        printf("\n");
    if (r->k == r->d && r->conservative) {
        printf("conservative: the exponents pair, lambda_i + lambda_%zu-i =", r->d + 1);
        for (size_t j = 0; j < r->d / 2; j++)
            printf("%s%.6f", j ? ", " : " ", clean(r->ex[j] + r->ex[r->d - 1 - j]));
        printf("\n");
    }
}

static void json_numbers(qd_json *j, const char *key, const double *x, size_t n) {
    qd_json_key(j, key);
    qd_json_begin_array(j);
    for (size_t i = 0; i < n; i++)
        if (isnan(x[i]))
            qd_json_null(j);
        else
            qd_json_number(j, x[i]);
    qd_json_end_array(j);
}

static int print_json(const ly_result *r, const cli_sim *c, const ly_args *p) {
    qd_buf b = QD_BUF_INIT;
    qd_json j;
    qd_json_init(&j, &b);
    qd_json_begin_object(&j);
    qd_json_key(&j, "method");
    qd_json_string(&j, qd_sim_method_name(c->opts.method));
    qd_json_key(&j, "t_avg");
    qd_json_number(&j, r->st.t_avg);
    qd_json_key(&j, "transient");
    qd_json_number(&j, p->transient);
    qd_json_key(&j, "renorm");
    qd_json_number(&j, p->renorm > 0 ? p->renorm : 1);
    qd_json_key(&j, "renormalizations");
    qd_json_number(&j, (double)r->st.renorms);
    json_numbers(&j, "exponents", r->ex, r->k);
    json_numbers(&j, "errors", r->err, r->k);
    qd_json_key(&j, "trace_mean");
    qd_json_number(&j, r->st.trace_mean);
    if (r->k == r->d) {
        qd_json_key(&j, "sum");
        qd_json_number(&j, sum_of(r));
    }
    qd_json_key(&j, "conservative");
    qd_json_bool(&j, r->conservative);
    qd_json_end_object(&j);
    bool ok = qd_json_ok(&j);
    if (ok)
        printf("%s\n", qd_buf_str(&b));
    qd_buf_free(&b);
    return ok ? QD_EXIT_OK : QD_EXIT_FAIL;
}

/* The model made into the tangent system and run; prints the result. */
static int run(cli_sim *c, const ly_args *p) {
    if (!c->e) {
        cli_diag_error("lyapunov takes a model given by T and V or L (its equations M q'' = "
                       "f), not one given by H or in speeds (try --no-speeds)");
        return QD_EXIT_USAGE;
    }
    size_t d = 2 * c->e->n;
    if (p->n > d) {
        cli_diag_error("--exponents: the model has %zu exponents (twice its %zu degrees of freedom), "
                       "not %zu", d, c->e->n, p->n);
        return QD_EXIT_USAGE;
    }
    qd_lyap *l = qd_lyap_new(c->ctx, c->mf.model, c->e);
    if (!l)
        return cli_diag_ctx(c->ctx);
    ly_result r = {.k = p->n, .d = d,
                   .conservative = qd_sim_conservative(c->s)};
    r.ex = calloc(2 * r.k, sizeof *r.ex);
    r.err = r.ex + r.k;
    qd_lyap_opts lo = {.nexp = r.k, .renorm = p->renorm, .transient = p->transient};
    qd_status st = r.ex ? qd_lyap_run_stats(c->ctx, l, &c->opts, &lo, r.ex, r.err, &r.st)
                        : QD_ERR_NOMEM;
    int rc;
    if (st == QD_ERR_ARG) {
        rc = cli_diag_ctx(c->ctx);
    } else if (st != QD_OK) {
        rc = cli_sim_fail(c, st);
    } else {
        fprintf(stderr, "qdot: lyapunov: %s, averaged over T = %g after a transient of %g, "
                        "%zu renormalizations: %zu steps, %zu evaluations, %zu rejected\n",
                qd_sim_method_name(c->opts.method), r.st.t_avg, p->transient, r.st.renorms,
                r.st.steps, r.st.evals, r.st.rejected);
        rc = QD_EXIT_OK;
        if (p->a.json)
            rc = print_json(&r, c, p);
        else
            print_text(&r);
    }
    free(r.ex);
    qd_lyap_free(l);
    return rc;
}

int cli_cmd_lyapunov(int argc, char **argv) {
    ly_args p = {.n = 1};
    int rc = cli_parse(&spec, argc, argv, &p, &p.a.file);
    p.a.json = p.format && !strcmp(p.format, "json");
    if (rc == QD_EXIT_OK)
        rc = number("--renorm", p.renorm_text, &p.renorm);
    if (rc == QD_EXIT_OK)
        rc = number("--transient", p.transient_text, &p.transient);
    if (rc == QD_EXIT_OK && !p.a.t_end) {
        cli_diag_error("--t-end is missing (qdot lyapunov --help)");
        rc = QD_EXIT_USAGE;
    }
    if (rc != QD_EXIT_OK)
        return rc;
    /* Runge-Kutta: dop853 unless named; --dt makes its step fixed */
    if (!p.a.method)
        p.a.method = "dop853";
    p.a.fixed = true; /* with --dt */
    cli_sim c = {0};
    rc = cli_sim_setup(&c, &p.a);
    if (rc == QD_EXIT_OK)
        rc = run(&c, &p);
    cli_sim_free(&c);
    return rc;
}

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

#include <stdio.h>
#include <stdlib.h>

#include "out.h"
#include "progress.h"
#include "qdot/lyapunov.h"
#include "model_cli.h"
#include "sim_cli.h"

typedef struct ly_args {
    cli_sim_args a;
    size_t n;
    const char *format;
    double renorm, transient;
} ly_args;

static const cli_opt opts[] = {
    {"--exponents", NULL, CLI_COUNT, offsetof(ly_args, n), "K", "the K largest exponents (1)", NULL,
     NULL},
    {"--renorm", NULL, CLI_NONNEG, offsetof(ly_args, renorm), "DT",
     "the time between renormalizations (1)", NULL, NULL},
    {"--transient", NULL, CLI_NONNEG, offsetof(ly_args, transient), "T0",
     "the time run before the averaging starts (0)", NULL, NULL},
    CLI_OPT_FORMAT(ly_args, format),
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

/* The result in the format asked for, written to standard output. */
static int emit(const qd_lyap_report *r, bool json) {
    qd_buf b = QD_BUF_INIT;
    b.failed |= (json ? qd_lyap_json(r, &b) : qd_lyap_print(r, &b)) != QD_OK;
    return cli_emit(&b, "exponents"); /* JSON: "model" first */
}

static int progress(void *data, double done, double t) {
    cli_progress_update(data, done, t);
    return 0;
}

/* The run and its exponents (qd_lyap_setup_run), with a bar on a terminal;
 * prints the result. */
static int run(cli_sim *c, const ly_args *p) {
    cli_progress bar;
    cli_progress_start(&bar, "lyapunov");
    qd_lyap_opts lo = {.nexp = p->n, .renorm = p->renorm, .transient = p->transient,
                       .progress = progress, .data = &bar};
    qd_lyap_result r;
    qd_status st = qd_lyap_setup_run(c->ctx, c->set, c->mf.model, &c->opts, &lo, &r);
    cli_progress_end(&bar);
    int rc = st == QD_OK ? QD_EXIT_OK : st == QD_ERR_ARG ? cli_diag_ctx(c->ctx)
                                                         : cli_sim_fail(c, st);
    if (rc == QD_EXIT_OK) {
        fprintf(stderr, "qdot: lyapunov: %s, averaged over T = %g after a transient of %g, "
                        "%zu renormalizations: %zu steps, %zu evaluations, %zu rejected\n",
                qd_sim_method_name(c->opts.method), r.stats.t_avg, p->transient,
                r.stats.renorms, r.stats.steps, r.stats.evals, r.stats.rejected);
        rc = emit(&r.report, p->a.json);
    }
    qd_lyap_result_free(&r);
    return rc;
}

int cli_cmd_lyapunov(int argc, char **argv) {
    ly_args p = {.n = 1};
    int rc = cli_parse(&spec, argc, argv, &p, &p.a.file);
    p.a.json = cli_json(p.format);
    if (rc == QD_EXIT_OK && !p.a.t_end)
        rc = cli_usage_error("--t-end is missing (qdot lyapunov --help)");
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

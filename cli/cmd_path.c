/*
 * cli/cmd_path.c - `qdot path FILE --from "q=..., t=t0" --to "q=..., t=t1"`:
 * the stationary paths of the action between two configurations
 * (qd_path_find; --energy E: Maupertuis' paths of energy E, qd_path_find_energy),
 * each with its action, initial velocities, samples, kinetic foci and
 * whether it is a minimum.
 */
#include "cli.h"

#include <ctype.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "json.h"
#include "model_cli.h"
#include "model_file.h"
#include "qdot/path.h"
#include "state.h"

#define MAX_GUESS 16

typedef struct path_args {
    const char *file, *from, *to, *energy, *segments, *guess[MAX_GUESS], *sets[QD_CLI_MAX_LIST];
    size_t nguess, nsets;
    bool json, all;
} path_args;

static const char usage_text[] =
    "usage: qdot path FILE --from \"q=VALUE, ..., t=T0\" --to \"q=VALUE, ..., t=T1\" [--all] "
    "[--guess \"q'=VALUE, ...\"]... [--energy E] [--segments N] [--format text|json] "
    "[--set NAME=VALUE]...";

static const char *const formats[] = {"text", "json", NULL};

static int parse_option(int argc, char **argv, int *i, void *data) {
    path_args *a = data;
    const char *v;
    int f;
    if ((v = cli_value(argc, argv, i, "--format"))) {
        int rc = cli_choice("--format", v, formats, &f);
        a->json = f == 1;
        return rc;
    }
    if ((v = cli_value(argc, argv, i, "--set")))
        return cli_push("--set", a->sets, &a->nsets, QD_CLI_MAX_LIST, v);
    if ((v = cli_value(argc, argv, i, "--guess")))
        return cli_push("--guess", a->guess, &a->nguess, MAX_GUESS, v);
    if ((v = cli_value(argc, argv, i, "--from")))
        return cli_once("--from", &a->from, v);
    if ((v = cli_value(argc, argv, i, "--to")))
        return cli_once("--to", &a->to, v);
    if ((v = cli_value(argc, argv, i, "--energy")))
        return cli_once("--energy", &a->energy, v);
    if ((v = cli_value(argc, argv, i, "--segments")))
        return cli_once("--segments", &a->segments, v);
    if (!strcmp(argv[*i], "--all")) {
        a->all = true;
        return QD_EXIT_OK;
    }
    return cli_bad_option(argv[*i], usage_text);
}

/* Does the state text give t ("t = 2" among its items)? */
static bool gives_t(const char *s) {
    for (const char *p = s; *p; p++) {
        if (*p != 't' || (p > s && (isalnum((unsigned char)p[-1]) || p[-1] == '_')))
            continue;
        const char *q = p + 1;
        while (*q == ' ')
            q++;
        if (*q == '=')
            return true;
    }
    return false;
}

static int parse_args(int argc, char **argv, path_args *a) {
    int rc = cli_file_args(argc, argv, "path", usage_text, &a->file, parse_option, a);
    if (rc != QD_EXIT_OK)
        return rc;
    if (!a->from || !a->to) {
        cli_diag_error("path needs --from and --to\n%s", usage_text);
        return QD_EXIT_USAGE;
    }
    if (!a->energy && !gives_t(a->to)) {
        cli_diag_error("path: --to needs the end time t=T1 (or give --energy E)\n%s", usage_text);
        return QD_EXIT_USAGE;
    }
    return QD_EXIT_OK;
}

typedef struct path_run {
    qd_ctx *ctx;
    cli_model_file mf;
    qd_eom *e;
    cli_state from, to, g;
    double *q0, *q1, *guess;
    qd_path_set ps;
    bool energy;
} path_run;

static int read_number(const char *what, const char *text, double lo, double *x) {
    char *end;
    *x = strtod(text, &end);
    if (end == text || *end || !isfinite(*x) || *x < lo) {
        cli_diag_error("%s takes a number%s, not '%s'", what, lo > 0 ? " >= 1" : "", text);
        return QD_EXIT_USAGE;
    }
    return QD_EXIT_OK;
}

static int read_ends(path_run *r, const path_args *a, qd_path_opts *o) {
    const qd_model *m = r->mf.model;
    size_t n = r->e->n;
    int rc = cli_state_init(r->ctx, m, &r->from);
    if (rc == QD_EXIT_OK)
        rc = cli_state_parse_as(r->ctx, m, "--from", a->from, &r->from);
    if (rc == QD_EXIT_OK)
        rc = cli_state_init(r->ctx, m, &r->to);
    if (rc == QD_EXIT_OK)
        rc = cli_state_parse_as(r->ctx, m, "--to", a->to, &r->to);
    r->guess = calloc(a->nguess * n + 1, sizeof *r->guess);
    if (rc == QD_EXIT_OK && !r->guess) {
        cli_diag_error("out of memory");
        return QD_EXIT_FAIL;
    }
    for (size_t k = 0; rc == QD_EXIT_OK && k < a->nguess; k++) {
        cli_state_free(&r->g);
        rc = cli_state_init(r->ctx, m, &r->g);
        if (rc == QD_EXIT_OK)
            rc = cli_state_parse_as(r->ctx, m, "--guess", a->guess[k], &r->g);
        if (rc == QD_EXIT_OK)
            memcpy(r->guess + k * n, r->g.vals + n, n * sizeof *r->guess);
    }
    if (rc != QD_EXIT_OK)
        return rc;
    o->q0 = r->from.vals;
    o->q1 = r->to.vals;
    o->t0 = r->from.vals[2 * n];
    o->t1 = r->to.vals[2 * n];
    o->nguess = a->nguess;
    o->guess = a->nguess ? r->guess : NULL;
    o->all = a->all;
    if (!r->energy && !(o->t1 > o->t0)) {
        cli_diag_error("path: the end time %g is not after the start time %g", o->t1, o->t0);
        return QD_EXIT_USAGE;
    }
    return QD_EXIT_OK;
}

static void put(qd_buf *b, double x) {
    cli_state_put_result(b, x);
}

static void write_text(const path_run *r, qd_buf *b) {
    size_t n = r->e->n;
    qd_buf_printf(b, "paths: %zu\n", r->ps.count);
    for (size_t i = 0; i < r->ps.count; i++) {
        const qd_path *p = &r->ps.paths[i];
        qd_buf_printf(b, "path %zu:\n  action: ", i + 1);
        put(b, p->action);
        qd_buf_puts(b, "\n  initial velocities: ");
        for (size_t j = 0; j < n; j++) {
            qd_buf_printf(b, "%s%s' = ", j ? ", " : "", qd_expr_name(r->e->q[j]));
            put(b, p->v0[j]);
        }
        if (r->energy) {
            qd_buf_puts(b, "\n  time: ");
            put(b, p->t[p->nsamples - 1] - p->t[0]);
        }
        qd_buf_puts(b, "\n  kinetic foci:");
        for (size_t k = 0; k < p->nfoci; k++) {
            qd_buf_puts(b, k ? ", " : " ");
            put(b, p->foci[k]);
            if (p->foci_mult && p->foci_mult[k] > 1) /* det J touches 0 there (foci.c) */
                qd_buf_printf(b, " (multiplicity %zu)", p->foci_mult[k]);
        }
        qd_buf_printf(b, "%s\n  minimum: %s\n  samples (%s", p->nfoci ? "" : " none",
                      p->minimum ? "yes" : "no", qd_print_time_name(r->ctx));
        for (size_t j = 0; j < n; j++)
            qd_buf_printf(b, ", %s", qd_expr_name(r->e->q[j]));
        size_t step = p->nsamples > 11 ? (p->nsamples - 1) / 10 : 1;
        qd_buf_printf(b, "; every %zu of %zu, --format json for all):\n", step, p->nsamples);
        for (size_t k = 0; k < p->nsamples; k += step) {
            qd_buf_puts(b, "   ");
            for (size_t j = 0; j <= n; j++) {
                qd_buf_puts(b, " ");
                double x = j ? p->q[k * n + j - 1] : p->t[k];
                put(b, fabs(x) < 1e-10 ? 0 : x);  /* an end reached to the tolerance */
            }
            qd_buf_puts(b, "\n");
        }
    }
}

static void write_json(const path_run *r, qd_buf *b) {
    size_t n = r->e->n;
    cli_json j;
    cli_json_init(&j, b);
    cli_json_begin_object(&j);
    cli_json_key(&j, "count");
    cli_json_number(&j, (double)r->ps.count);
    cli_json_key(&j, "paths");
    cli_json_begin_array(&j);
    for (size_t i = 0; i < r->ps.count; i++) {
        const qd_path *p = &r->ps.paths[i];
        cli_json_begin_object(&j);
        cli_json_key(&j, "action");
        cli_json_number(&j, p->action);
        cli_json_key(&j, "initial_velocities");
        cli_json_begin_object(&j);
        for (size_t k = 0; k < n; k++) {
            char name[160];
            snprintf(name, sizeof name, "%s'", qd_expr_name(r->e->q[k]));
            cli_json_key(&j, name);
            cli_json_number(&j, p->v0[k]);
        }
        cli_json_end_object(&j);
        cli_json_key(&j, "residual");
        cli_json_number(&j, p->residual);
        cli_json_key(&j, "samples");
        cli_json_begin_array(&j);
        for (size_t s = 0; s < p->nsamples; s++) {
            cli_json_begin_array(&j);
            cli_json_number(&j, p->t[s]);
            for (size_t k = 0; k < n; k++)
                cli_json_number(&j, p->q[s * n + k]);
            cli_json_end_array(&j);
        }
        cli_json_end_array(&j);
        cli_json_key(&j, "kinetic_foci");
        cli_json_begin_array(&j);
        for (size_t k = 0; k < p->nfoci; k++)
            cli_json_number(&j, p->foci[k]);
        cli_json_end_array(&j);
        cli_json_key(&j, "minimum");
        cli_json_bool(&j, p->minimum);
        cli_json_end_object(&j);
    }
    cli_json_end_array(&j);
    cli_json_end_object(&j);
    qd_buf_puts(b, "\n");
}

static int run(path_run *r, const path_args *a) {
    int rc = cli_load_derive(r->ctx, a->file, a->nsets, a->sets, false, NULL, &r->mf, &r->e);
    qd_path_opts o = {0};
    double E = 0, nseg = 0;
    r->energy = a->energy != NULL;
    if (rc == QD_EXIT_OK && a->energy)
        rc = read_number("--energy", a->energy, -INFINITY, &E);
    if (rc == QD_EXIT_OK && a->segments)
        rc = read_number("--segments", a->segments, 1, &nseg);
    if (rc == QD_EXIT_OK)
        rc = read_ends(r, a, &o);
    if (rc != QD_EXIT_OK)
        return rc;
    o.segments = (size_t)nseg;
    qd_status st = r->energy ? qd_path_find_energy(r->ctx, r->mf.model, r->e, E, &o, &r->ps)
                             : qd_path_find(r->ctx, r->mf.model, r->e, &o, &r->ps);
    if (st != QD_OK)
        return cli_diag_ctx(r->ctx);
    qd_buf b = QD_BUF_INIT;
    if (a->json)
        write_json(r, &b);
    else
        write_text(r, &b);
    return cli_emit(&b, "paths");
}

int cli_cmd_path(int argc, char **argv) {
    path_args a = {0};
    int rc = parse_args(argc, argv, &a);
    if (rc != QD_EXIT_OK)
        return rc;
    path_run r = {.ctx = qd_ctx_new()};
    if (!r.ctx) {
        cli_diag_error("out of memory");
        return QD_EXIT_FAIL;
    }
    rc = run(&r, &a);
    qd_path_set_free(&r.ps);
    cli_state_free(&r.from);
    cli_state_free(&r.to);
    cli_state_free(&r.g);
    free(r.guess);
    if (r.e)
        qd_eom_free(r.e);
    cli_model_file_free(&r.mf);
    qd_ctx_free(r.ctx);
    return rc;
}

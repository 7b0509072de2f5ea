/*
 * cli/cmd_integrals.c - `qdot integrals FILE`: cyclic coordinates, Jacobi's
 * integral and the energy, the energy balance, symmetries found by
 * coordinate names, Noether's integrals of the model's `symmetry`
 * statements and of --symmetry, and the check of the model's `integral`
 * statements and of --integral (qdot/integrals.h does the work).
 *
 * --symmetry and --integral take what the statements take, after the
 * keyword: "[NAME:] x -> x + eps, y -> y" or "[NAME:] delta x = -y,
 * delta y = x", and "[NAME:] EXPR".
 */
#include "cli.h"

#include <stdlib.h>
#include <string.h>
#include "qdot/json.h"
#include "model_cli.h"
#include "model_file.h"
#include "state.h"
#include "qdot/integrals.h"

#define MAX_OPT QD_CLI_MAX_LIST

typedef struct int_run {
    qd_ctx *ctx;
    cli_model_file mf;
    qd_eom *e;
    qd_integrals *I;
    bool json, search;
    const char *file, *sets[MAX_OPT], *syms[MAX_OPT], *ints[MAX_OPT];
    size_t nsets, nsymopt, nintopt;
    size_t nnoether, nproposed;
    qd_noether *noether;
    qd_int_proposed *proposed;
} int_run;

static const char usage_text[] =
    "usage: qdot integrals FILE [--format text|json] [--set NAME=VALUE]... "
    "[--symmetry \"[NAME:] x -> x + eps, ...\" | \"[NAME:] delta x = -y, ...\"]... "
    "[--integral \"[NAME:] EXPR\"]... [--no-search]";

static const char *const formats[] = {"text", "json", NULL};

static int parse_option(int argc, char **argv, int *i, void *data) {
    int_run *r = data;
    const char *v;
    int f;
    if ((v = cli_value(argc, argv, i, "--format"))) {
        int rc = cli_choice("--format", v, formats, &f);
        r->json = f == 1;
        return rc;
    }
    if (!strcmp(argv[*i], "--no-search")) {
        r->search = false;
        return QD_EXIT_OK;
    }
    if ((v = cli_value(argc, argv, i, "--set")))
        return cli_push("--set", r->sets, &r->nsets, MAX_OPT, v);
    if ((v = cli_value(argc, argv, i, "--symmetry")))
        return cli_push("--symmetry", r->syms, &r->nsymopt, MAX_OPT, v);
    if ((v = cli_value(argc, argv, i, "--integral")))
        return cli_push("--integral", r->ints, &r->nintopt, MAX_OPT, v);
    return cli_bad_option(argv[*i], usage_text);
}

/* ---- --symmetry and --integral ------------------------------------------- */

/* Added to the model as its own `symmetry` and `integral` statements (after
 * the file's); unnamed ones are S1, S2, ... and J1, J2, ... */
static int parse_given(int_run *r) {
    int rc = QD_EXIT_OK;
    char label[32];
    for (size_t k = 0; rc == QD_EXIT_OK && k < r->nsymopt; k++) {
        snprintf(label, sizeof label, "S%zu", k + 1);
        rc = cli_symmetry(&r->mf, "--symmetry", r->syms[k], label);
    }
    for (size_t k = 0; rc == QD_EXIT_OK && k < r->nintopt; k++) {
        snprintf(label, sizeof label, "J%zu", k + 1);
        rc = cli_integral(&r->mf, "--integral", r->ints[k], label);
    }
    return rc;
}

/* ---- the analysis ------------------------------------------------------------ */

static int failed(int_run *r) {
    if (qd_ctx_status(r->ctx) == QD_ERR_ARG) {
        cli_diag_error("%s", qd_ctx_message(r->ctx));
        return QD_EXIT_USAGE;
    }
    return cli_diag_ctx(r->ctx);
}

static int noether_all(int_run *r) {
    const qd_model *m = r->mf.model;
    size_t nm = qd_model_nsymmetries(m), n = r->e->n;
    r->noether = calloc(nm + 1, sizeof *r->noether);
    const qd_expr **xi = calloc(n ? n : 1, sizeof *xi);
    if (!r->noether || !xi) {
        free(xi);
        return QD_EXIT_FAIL;
    }
    int rc = QD_EXIT_OK;
    for (size_t i = 0; rc == QD_EXIT_OK && i < nm; i++) {
        const char *name = qd_model_symmetry_name(m, i);
        for (size_t j = 0; j < n; j++)
            xi[j] = qd_model_symmetry_field(m, i, j);
        if (qd_integrals_noether(r->ctx, r->I, name, xi, &r->noether[i]) != QD_OK)
            rc = failed(r);
        r->nnoether = i + 1;
    }
    free(xi);
    return rc;
}

static int proposed_all(int_run *r) {
    const qd_model *m = r->mf.model;
    size_t nm = qd_model_nintegrals(m);
    r->proposed = calloc(nm + 1, sizeof *r->proposed);
    if (!r->proposed)
        return QD_EXIT_FAIL;
    for (size_t i = 0; i < nm; i++) {
        const char *name = qd_model_integral_name(m, i);
        const qd_expr *x = qd_model_integral(m, i);
        if (qd_integrals_check(r->ctx, r->I, name, x, &r->proposed[i]) != QD_OK)
            return failed(r);
        r->nproposed = i + 1;
    }
    return QD_EXIT_OK;
}

/* ---- text ---------------------------------------------------------------------- */

static void put(const int_run *r, qd_buf *b, const qd_expr *x) {
    qd_print(r->ctx, x, QD_FMT_TEXT, b);
}

static const char *qname(const int_run *r, size_t j) { return qd_expr_name(r->e->q[j]); }

static void put_field(const int_run *r, qd_buf *b, const qd_noether *nt) {
    bool any = false;
    for (size_t j = 0; j < r->e->n; j++) {
        if (qd_is_zero(nt->xi[j]))
            continue;
        qd_buf_printf(b, "%sdelta %s = ", any ? ", " : "", qname(r, j));
        put(r, b, nt->xi[j]);
        any = true;
    }
    if (!any)
        qd_buf_puts(b, "the zero field");
}

static const char *numerically(bool numeric) {
    return numeric ? " (numerically, at random states: the simplifier did not reach 0)" : "";
}

static const char *undecided(bool numeric) {
    return numeric ? " (undecided: no counterexample, but too few random states where it is "
                     "defined)"
                   : "";
}

static void text_noether(const int_run *r, qd_buf *b, const qd_noether *nt, bool found) {
    qd_buf_printf(b, "  %s: ", nt->name);
    put_field(r, b, nt);
    qd_buf_puts(b, "\n");
    if (!nt->invariant) {
        qd_buf_puts(b, "    not a symmetry: dL/deps = ");
        put(r, b, nt->dL);
        qd_buf_puts(b, found ? "\n" : " (not 0, nor found as dF/dt of some F(q, t))\n");
        return;
    }
    if (nt->F) {
        qd_buf_puts(b, "    dL/deps = dF/dt with F = ");
        put(r, b, nt->F);
        qd_buf_puts(b, " (a symmetry up to a total derivative)\n");
    } else {
        qd_buf_puts(b, "    dL/deps = 0: a symmetry of L\n");
    }
    qd_buf_puts(b, "    I = ");
    put(r, b, nt->integral);
    if (nt->conserved) {
        qd_buf_printf(b, " is conserved%s\n", numerically(nt->numeric));
    } else {
        qd_buf_puts(b, " is not conserved: the forces work along the field, dI/dt = ");
        put(r, b, nt->remainder);
        qd_buf_puts(b, "\n");
    }
}

static void text_cyclic(const int_run *r, qd_buf *b) {
    const qd_integrals *I = r->I;
    qd_buf_puts(b, "cyclic coordinates");
    qd_buf_puts(b, I->ncyclic ? "\n" : ": none\n");
    for (size_t i = 0; i < I->ncyclic; i++) {
        const qd_int_cyclic *c = &I->cyclic[i];
        qd_buf_printf(b, "  %s: p_%s = ", qname(r, c->coord), qname(r, c->coord));
        put(r, b, c->momentum);
        if (c->conserved)
            qd_buf_puts(b, " is conserved\n");
        else
            qd_buf_printf(b, " is not conserved: %s\n", c->obstruction);
    }
}

static void text_jacobi(const int_run *r, qd_buf *b) {
    const qd_int_jacobi *J = &r->I->jacobi;
    qd_buf_puts(b, "Jacobi's integral h = sum_j q'_j dL/dq'_j - L\n  h = ");
    put(r, b, J->h);
    if (J->conserved)
        qd_buf_printf(b, "\n  conserved: yes%s\n", numerically(J->numeric));
    else
        qd_buf_printf(b, "\n  conserved: no (%s)%s\n", J->not_conserved, undecided(J->numeric));
    if (J->energy) {
        qd_buf_puts(b, "  energy E = T + V + U0 = ");
        put(r, b, J->energy);
        qd_buf_puts(b, "\n");
    }
    if (J->equals_energy == 1) {
        qd_buf_printf(b, "  h = E: yes (%s)\n", J->reason);
    } else if (J->equals_energy == 0) {
        qd_buf_puts(b, "  h = E: no, h - E = ");
        put(r, b, J->h_minus_E);
        qd_buf_printf(b, " (%s)\n", J->reason);
    } else {
        qd_buf_printf(b, "  h = E: unknown (%s)\n", J->reason);
    }
}

static void text_balance(const int_run *r, qd_buf *b) {
    const qd_int_balance *B = &r->I->balance;
    const char *t = qd_print_time_name(r->ctx); /* x for `independent x` */
    qd_buf_printf(b, "energy balance along the motion\n  dh/d%s = ", t);
    put(r, b, B->dhdt);
    qd_buf_printf(b, "\n  expected %s = ", B->formula);
    put(r, b, B->expected);
    if (B->verified) {
        qd_buf_printf(b, ": verified%s\n", numerically(B->numeric));
    } else {
        qd_buf_printf(b, ": NOT verified, dh/d%s - expected = ", t);
        put(r, b, B->remainder);
        qd_buf_puts(b, "\n");
    }
    if (r->I->balance.D_quadratic)
        qd_buf_puts(b, "  D is homogeneous quadratic in the velocities: it dissipates at the "
                       "rate 2D\n");
}

static void text_found(const int_run *r, qd_buf *b) {
    const qd_integrals *I = r->I;
    if (!r->search)
        return;
    qd_buf_puts(b, "symmetries found by coordinate names (x*, y*, z*)");
    if (r->e->ncon) {
        qd_buf_puts(b, ": not searched (the model has constraints)\n");
        return;
    }
    if (!I->ntested) {
        qd_buf_puts(b, ": no candidates (no coordinate is named x, y or z, with or "
                       "without a numeric suffix)\n");
        return;
    }
    qd_buf_puts(b, I->nfound ? "\n" : ": none\n");
    for (size_t i = 0; i < I->nfound; i++)
        text_noether(r, b, &I->found[i], true);
    bool any = false;
    for (size_t i = 0; i < I->ntested; i++) {
        bool hit = false;
        for (size_t k = 0; k < I->nfound; k++)
            hit |= !strcmp(I->found[k].name, I->tested[i]);
        if (!hit)
            qd_buf_printf(b, "%s%s", any ? ", " : "  not symmetries: ", I->tested[i]);
        any |= !hit;
    }
    if (any)
        qd_buf_puts(b, "\n");
}

static void text_proposed(const int_run *r, qd_buf *b) {
    if (!r->nproposed)
        return;
    qd_buf_puts(b, "proposed integrals\n");
    for (size_t i = 0; i < r->nproposed; i++) {
        const qd_int_proposed *p = &r->proposed[i];
        qd_buf_printf(b, "  %s = ", p->name);
        put(r, b, p->expr);
        if (p->conserved) {
            qd_buf_printf(b, "\n    conserved: dI/dt = 0 along the motion%s\n",
                          numerically(p->numeric));
        } else {
            qd_buf_puts(b, "\n    not conserved: dI/dt = ");
            put(r, b, p->remainder);
            qd_buf_printf(b, " along the motion%s\n", undecided(p->numeric));
        }
    }
}

static void write_text(const int_run *r, qd_buf *b) {
    qd_buf_printf(b, "qdot integrals %s\n", r->mf.path);
    text_cyclic(r, b);
    text_jacobi(r, b);
    text_balance(r, b);
    text_found(r, b);
    if (r->nnoether) {
        qd_buf_puts(b, "Noether's integrals of the given symmetries\n");
        for (size_t i = 0; i < r->nnoether; i++)
            text_noether(r, b, &r->noether[i], false);
    }
    text_proposed(r, b);
}

/* ---- JSON ---------------------------------------------------------------------- */

static void jexpr(const int_run *r, qd_json *j, const char *key, const qd_expr *x) {
    qd_json_key(j, key);
    qd_json_expr(j, r->ctx, x);
}

static void jbool(qd_json *j, const char *key, bool v) {
    qd_json_key(j, key);
    qd_json_bool(j, v);
}

static void jstr(qd_json *j, const char *key, const char *v) {
    qd_json_key(j, key);
    if (v)
        qd_json_string(j, v);
    else
        qd_json_null(j);
}

static void json_noether(const int_run *r, qd_json *j, const qd_noether *nt) {
    qd_json_begin_object(j);
    jstr(j, "name", nt->name);
    qd_json_key(j, "field");
    qd_json_begin_object(j);
    for (size_t k = 0; k < r->e->n; k++)
        if (!qd_is_zero(nt->xi[k]))
            jexpr(r, j, qname(r, k), nt->xi[k]);
    qd_json_end_object(j);
    jbool(j, "invariant", nt->invariant);
    jexpr(r, j, "dL_deps", nt->dL);
    jexpr(r, j, "F", nt->F);
    jexpr(r, j, "remainder", nt->invariant ? qd_int(r->ctx, 0) : nt->dL);
    jexpr(r, j, "integral", nt->integral);
    jbool(j, "conserved", nt->conserved);
    jexpr(r, j, "dIdt", nt->remainder);
    jbool(j, "numeric", nt->numeric);
    qd_json_end_object(j);
}

static void json_cyclic(const int_run *r, qd_json *j) {
    qd_json_key(j, "cyclic");
    qd_json_begin_array(j);
    for (size_t i = 0; i < r->I->ncyclic; i++) {
        const qd_int_cyclic *c = &r->I->cyclic[i];
        qd_json_begin_object(j);
        jstr(j, "coordinate", qname(r, c->coord));
        jexpr(r, j, "momentum", c->momentum);
        jbool(j, "conserved", c->conserved);
        jstr(j, "obstruction", c->obstruction);
        qd_json_end_object(j);
    }
    qd_json_end_array(j);
}

static void json_jacobi(const int_run *r, qd_json *j) {
    const qd_int_jacobi *J = &r->I->jacobi;
    qd_json_key(j, "jacobi");
    qd_json_begin_object(j);
    jexpr(r, j, "h", J->h);
    jbool(j, "explicit_t", J->explicit_t);
    jbool(j, "conserved", J->conserved);
    jstr(j, "not_conserved", J->not_conserved);
    jexpr(r, j, "energy", J->energy);
    qd_json_key(j, "equals_energy");
    if (J->equals_energy < 0)
        qd_json_null(j);
    else
        qd_json_bool(j, J->equals_energy == 1);
    jexpr(r, j, "h_minus_energy", J->h_minus_E);
    jstr(j, "reason", J->reason);
    jbool(j, "numeric", J->numeric);
    qd_json_end_object(j);
}

static void json_balance(const int_run *r, qd_json *j) {
    const qd_int_balance *B = &r->I->balance;
    qd_json_key(j, "energy_balance");
    qd_json_begin_object(j);
    jexpr(r, j, "dhdt", B->dhdt);
    jstr(j, "formula", B->formula);
    jexpr(r, j, "expected", B->expected);
    jbool(j, "D_quadratic", B->D_quadratic);
    jbool(j, "verified", B->verified);
    jbool(j, "numeric", B->numeric);
    jexpr(r, j, "remainder", B->remainder);
    qd_json_end_object(j);
}

static void json_lists(const int_run *r, qd_json *j) {
    qd_json_key(j, "found");
    qd_json_begin_array(j);
    for (size_t i = 0; i < r->I->nfound; i++)
        json_noether(r, j, &r->I->found[i]);
    qd_json_end_array(j);
    qd_json_key(j, "tested");
    qd_json_begin_array(j);
    for (size_t i = 0; i < r->I->ntested; i++)
        qd_json_string(j, r->I->tested[i]);
    qd_json_end_array(j);
    qd_json_key(j, "noether");
    qd_json_begin_array(j);
    for (size_t i = 0; i < r->nnoether; i++)
        json_noether(r, j, &r->noether[i]);
    qd_json_end_array(j);
    qd_json_key(j, "proposed");
    qd_json_begin_array(j);
    for (size_t i = 0; i < r->nproposed; i++) {
        const qd_int_proposed *p = &r->proposed[i];
        qd_json_begin_object(j);
        jstr(j, "name", p->name);
        jexpr(r, j, "expr", p->expr);
        jbool(j, "conserved", p->conserved);
        jexpr(r, j, "remainder", p->remainder);
        jbool(j, "numeric", p->numeric);
        qd_json_end_object(j);
    }
    qd_json_end_array(j);
}

static void write_json(const int_run *r, qd_buf *b) {
    qd_json j;
    qd_json_init(&j, b);
    qd_json_begin_object(&j);
    jstr(&j, "file", r->mf.path);
    qd_json_key(&j, "coordinates");
    qd_json_begin_array(&j);
    for (size_t k = 0; k < r->e->n; k++)
        qd_json_string(&j, qname(r, k));
    qd_json_end_array(&j);
    jexpr(r, &j, "L", r->I->L);
    json_cyclic(r, &j);
    json_jacobi(r, &j);
    json_balance(r, &j);
    json_lists(r, &j);
    qd_json_end_object(&j);
    qd_buf_puts(b, "\n");
    b->failed = b->failed || !qd_json_ok(&j);
}

static int emit(int_run *r) {
    qd_buf b = QD_BUF_INIT;
    if (r->json)
        write_json(r, &b);
    else
        write_text(r, &b);
    return cli_emit(&b, "integrals");
}

static int run(int_run *r) {
    int rc = cli_load_derive(r->ctx, r->file, r->nsets, r->sets, true, NULL, &r->mf, &r->e);
    if (rc == QD_EXIT_OK)
        rc = parse_given(r);
    qd_integrals_opts o = {.search = r->search};
    if (rc == QD_EXIT_OK && !(r->I = qd_integrals_derive(r->ctx, r->mf.model, r->e, &o)))
        rc = failed(r);
    if (rc == QD_EXIT_OK)
        rc = noether_all(r);
    if (rc == QD_EXIT_OK)
        rc = proposed_all(r);
    return rc == QD_EXIT_OK ? emit(r) : rc;
}

int cli_cmd_integrals(int argc, char **argv) {
    int_run r = {.search = true};
    int rc = cli_file_args(argc, argv, "integrals", usage_text, &r.file, parse_option, &r);
    if (rc != QD_EXIT_OK)
        return rc;
    if (!(r.ctx = qd_ctx_new())) {
        cli_diag_error("out of memory");
        return QD_EXIT_FAIL;
    }
    rc = run(&r);
    for (size_t i = 0; i < r.nnoether; i++)
        qd_noether_clear(&r.noether[i]);
    free(r.noether);
    free(r.proposed);
    qd_integrals_free(r.I);
    qd_eom_free(r.e);
    cli_model_file_free(&r.mf);
    qd_ctx_free(r.ctx);
    return rc;
}

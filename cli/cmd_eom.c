/*
 * cli/cmd_eom.c - `qdot eom FILE`: Lagrange's equations of a model,
 *
 *     d/dt(dL/dq'_j) - dL/dq_j + dD/dq'_j = Q_j,   written   M q'' = f,
 *
 * derived by libqdot (qd_eom_derive) from the model read with the --set
 * values in place of its parameters', solved for q'' with --solve, or evaluated at a state with
 * --at.  Constraints add multipliers, M q'' = f + A^T lambda with A q'' = b;
 * --eliminate substitutes the holonomic ones that can be solved for a
 * coordinate instead.  With --at, the model's `reaction` statements give
 * the Cartesian force of a constraint at a point (qd_eom_reaction).  A model
 * that declares `speeds` gets its equations in the speeds instead,
 * q' = W u + w and M_u u' = f_u (qd_speeds_derive, by --method kane, appell
 * or hamel), with --appell the Gibbs-Appell function, with --multipliers
 * the constraint forces, and with --at the numbers at a state of q, u and t
 * (qd_speeds_eval).  The pipeline is here; the output formats are in
 * eom_out.c and speeds_out.c.
 */
#include "cli.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "eom_out.h"
#include "model_cli.h"
#include "speeds_out.h"
#include "qdot/json.h"

/* Symbolic accelerations larger than this (count_ops, per entry) are not
 * worth printing: M and f say the same in far less space. */
#define SOLVE_MAX_OPS 2000
#define MAX_SETS QD_CLI_MAX_LIST

typedef struct eom_args {
    const char *file;
    cli_eom_format fmt;
    bool solve, eliminate;
    bool appell, multipliers; /* speeds only */
    bool hamel_coef;          /* speeds only: --hamel-coefficients */
    const char *method;       /* speeds only: as given, NULL when not */
    qd_speeds_method smethod;
    const char *sets[MAX_SETS];
    size_t nsets;
    const char *at;
} eom_args;

typedef struct eom_run {
    qd_ctx *ctx;
    cli_model_file mf;
    qd_eom *e;
    cli_state st;
    const qd_expr **numbers;                      /* numeric mode: M, f, acc, A, b,
                                                     lambda, R as nodes */
    size_t nreact;                                /* numeric mode: reactions computed */
    const char **react_name;
    const qd_expr **react;                        /* 3 per reaction */
    double *react_res;
    cli_eom_view view;
} eom_run;

static const char usage_text[] =
    "usage: qdot eom FILE [--format text|latex|json|sympy|c] [--solve] [--eliminate] "
    "[--set NAME=VALUE]... [--at \"q=VALUE, q'=VALUE, t=VALUE\"] "
    "[--method kane|appell|hamel] [--appell] [--multipliers] [--hamel-coefficients]";

/* --method NAME: one of the library's names (qd_speeds_method_name). */
static int parse_method(const char *v, eom_args *a) {
    const char *names[QD_SPEEDS_METHOD_COUNT + 1];
    for (int k = 0; k < QD_SPEEDS_METHOD_COUNT; k++)
        names[k] = qd_speeds_method_name((qd_speeds_method)k);
    names[QD_SPEEDS_METHOD_COUNT] = NULL;
    int k = 0, rc = cli_once("--method", &a->method, v);
    if (rc == QD_EXIT_OK)
        rc = cli_choice("--method", v, names, &k);
    a->smethod = (qd_speeds_method)k;
    return rc;
}

static int parse_option(int argc, char **argv, int *i, void *data) {
    eom_args *a = data;
    const char *v;
    if (!strcmp(argv[*i], "--solve")) {
        a->solve = true;
    } else if (!strcmp(argv[*i], "--eliminate")) {
        a->eliminate = true;
    } else if (!strcmp(argv[*i], "--appell")) {
        a->appell = true;
    } else if (!strcmp(argv[*i], "--multipliers")) {
        a->multipliers = true;
    } else if (!strcmp(argv[*i], "--hamel-coefficients")) {
        a->hamel_coef = true;
    } else if ((v = cli_value(argc, argv, i, "--method"))) {
        return parse_method(v, a);
    } else if ((v = cli_value(argc, argv, i, "--format"))) {
        if (!cli_eom_format_from_name(v, &a->fmt)) {
            cli_diag_error("--format takes text, latex, json, sympy or c, not '%s'", v);
            return QD_EXIT_USAGE;
        }
    } else if ((v = cli_value(argc, argv, i, "--set"))) {
        if (a->nsets == MAX_SETS) {
            cli_diag_error("at most %d --set options", MAX_SETS);
            return QD_EXIT_USAGE;
        }
        a->sets[a->nsets++] = v;
    } else if ((v = cli_value(argc, argv, i, "--at"))) {
        if (a->at) {
            cli_diag_error("--at is given twice; name every value in one list");
            return QD_EXIT_USAGE;
        }
        a->at = v;
    } else {
        cli_diag_error("unknown option or missing value: '%s'\n%s", argv[*i], usage_text);
        return QD_EXIT_USAGE;
    }
    return QD_EXIT_OK;
}

static int parse_args(int argc, char **argv, eom_args *a) {
    *a = (eom_args){.fmt = QD_EOM_TEXT};
    return cli_file_args(argc, argv, "eom", usage_text, &a->file, parse_option, a);
}

static int solve(eom_run *r) {
    qd_status st = qd_eom_solve(r->ctx, r->e, SOLVE_MAX_OPS);
    if (st == QD_OK)
        return QD_EXIT_OK;
    if (st == QD_ERR_TOOBIG) {
        fprintf(stderr, "qdot: note: the solved accelerations exceed %d operations; "
                        "printing M and f instead (use --at for numbers)\n", SOLVE_MAX_OPS);
        qd_ctx_clear_error(r->ctx);
        return QD_EXIT_OK;
    }
    if (st == QD_ERR_SINGULAR) {
        cli_diag_error("cannot solve for the accelerations: %s", qd_ctx_message(r->ctx));
        return QD_EXIT_FAIL;
    }
    return cli_diag_ctx(r->ctx);
}

static void singular_at(const eom_run *r) {
    qd_buf b = QD_BUF_INIT;
    for (size_t i = 0; i < 2 * qd_model_ncoords(r->mf.model) + 1; i++) {
        qd_buf_puts(&b, i ? ", " : "");
        qd_print(r->ctx, r->st.syms[i], QD_FMT_TEXT, &b);
        qd_buf_printf(&b, "=%.17g", r->st.vals[i]);
    }
    if (r->e->ncon)
        cli_diag_error("at %s: %s", qd_buf_str(&b), qd_ctx_message(r->ctx));
    else
        cli_diag_error("the mass matrix is singular at %s: the accelerations are not determined "
                      "there", qd_buf_str(&b));
    qd_buf_free(&b);
}

/* x evaluated at the state, as a number node; NULL (and a message) on failure. */
static const qd_expr *at_state(eom_run *r, const qd_expr *x) {
    double v;
    if (!x || qd_eval(r->ctx, x, r->st.n, r->st.syms, r->st.vals, &v) != QD_OK)
        return NULL;
    return qd_float(r->ctx, v);
}

/* How many numbers --at computes: M, f, q'', A, b, lambda, R. */
static size_t count_numbers(const qd_eom *e) {
    size_t n = e->n, m = e->ncon;
    return n * n + 2 * n + m * n + 2 * m + n;
}

/* A and b at the state (the compiled program has them, but not as an
 * interface: qd_eval per entry is plenty for one state). */
static qd_status constraint_rows(eom_run *r, double *Ab) {
    const qd_eom *e = r->e;
    qd_status st = QD_OK;
    for (size_t i = 0; st == QD_OK && i < e->ncon * e->n + e->ncon; i++) {
        const qd_expr *x = i < e->ncon * e->n ? e->A[i] : e->b[i - e->ncon * e->n];
        st = qd_eval(r->ctx, x, r->st.n, r->st.syms, r->st.vals, &Ab[i]);
    }
    return st;
}

/* One `reaction` statement at the state: its force as three number nodes
 * appended to r->react.  A reaction that cannot be had (its constraint was
 * eliminated) is a note, not an error: the rest of the output stands. */
static qd_status reaction_at(eom_run *r, size_t i, const double *lambda) {
    const qd_model *m = r->mf.model;
    const qd_expr *pt[3];
    double F[3], res;
    for (unsigned k = 0; k < 3; k++)
        pt[k] = qd_model_reaction_point(m, i, k);
    qd_status st = qd_eom_reaction(r->ctx, r->e, qd_model_reaction_constraint(m, i), pt,
                                   r->st.n, r->st.syms, r->st.vals, lambda, F, &res);
    if (st == QD_ERR_ARG) {
        fprintf(stderr, "qdot: note: reaction %s: %s\n", qd_model_reaction_name(m, i),
                qd_ctx_message(r->ctx));
        qd_ctx_clear_error(r->ctx);
        return QD_OK;
    }
    size_t j = r->nreact;
    for (unsigned k = 0; st == QD_OK && k < 3; k++)
        if (!(r->react[3 * j + k] = qd_float(r->ctx, F[k])))
            st = QD_ERR_NUMERIC;
    if (st == QD_OK) {
        r->react_name[j] = qd_model_reaction_name(m, i);
        r->react_res[j] = res;
        r->nreact++;
    }
    return st;
}

/* Is reaction i on a sudden constraint (`impact constraint`)? */
static bool impulsive(const qd_model *m, size_t i) {
    const char *con = qd_model_reaction_constraint(m, i);
    for (size_t k = 0; k < qd_model_nimpact_constraints(m); k++)
        if (!strcmp(con, qd_model_impact_constraint_name(m, k)))
            return true;
    return false;
}

static qd_status reactions(eom_run *r, const double *lambda) {
    size_t nr = qd_model_nreactions(r->mf.model);
    if (!nr)
        return QD_OK;
    r->react_name = malloc(nr * sizeof *r->react_name);
    r->react = malloc(3 * nr * sizeof *r->react);
    r->react_res = malloc(nr * sizeof *r->react_res);
    if (!r->react_name || !r->react || !r->react_res)
        return QD_ERR_NOMEM;
    qd_status st = QD_OK;
    for (size_t i = 0; i < nr && st == QD_OK; i++)
        if (!impulsive(r->mf.model, i)) /* qdot impulse reports those */
            st = reaction_at(r, i, lambda);
    return st;
}

/* --at: M, f, q'', the multipliers and the constraint forces as numbers
 * (qd_eom_eval), kept as number nodes so that every format prints them. */
static int evaluate(eom_run *r, const char *at) {
    size_t n = r->e->n, m = r->e->ncon, total = count_numbers(r->e);
    int rc = cli_state_init(r->ctx, r->mf.model, &r->st);
    if (rc == QD_EXIT_OK)
        rc = cli_state_parse(r->ctx, r->mf.model, at, &r->st);
    if (rc != QD_EXIT_OK)
        return rc;
    double *num = calloc(total + 1, sizeof *num);
    r->numbers = malloc((total + 1) * sizeof *r->numbers);
    if (!num || !r->numbers) {
        free(num);
        return QD_EXIT_FAIL;
    }
    double *A = num + n * n + 2 * n, *lambda = A + m * n + m;
    qd_status st = qd_eom_eval(r->ctx, r->e, r->st.n, r->st.syms, r->st.vals, num, num + n * n,
                               num + n * n + n, lambda, lambda + m);
    if (st == QD_OK)
        st = constraint_rows(r, A);
    if (st == QD_OK)
        st = reactions(r, lambda);
    for (size_t i = 0; st == QD_OK && i < total; i++)
        if (!(r->numbers[i] = qd_float(r->ctx, num[i])))
            st = QD_ERR_NUMERIC;
    free(num);
    if (st == QD_ERR_SINGULAR) {
        singular_at(r);
        return QD_EXIT_FAIL;
    }
    if (st != QD_OK) {
        cli_diag_error("cannot evaluate the equations at this state: %s",
                      qd_ctx_message(r->ctx)[0] ? qd_ctx_message(r->ctx) : qd_status_str(st));
        return QD_EXIT_FAIL;
    }
    return QD_EXIT_OK;
}

static int make_view(eom_run *r) {
    cli_eom_view *v = &r->view;
    qd_eom *e = r->e;
    size_t n = e->n;
    *v = (cli_eom_view){.ctx = r->ctx, .mf = &r->mf, .e = e, .M = e->M, .f = e->f, .acc = e->acc,
                       .A = e->A, .b = e->b, .lambda = e->mult, .T = {e->T2, e->T1, e->T0}};
    v->split = e->T2 && e->T1 && e->T0 && (!qd_is_zero(e->T1) || !qd_is_zero(e->T0));
    if (!r->numbers)
        return QD_EXIT_OK;
    v->numeric = true;
    v->st = &r->st;
    v->M = r->numbers;
    v->f = r->numbers + n * n;
    v->acc = r->numbers + n * n + n;
    v->A = v->acc + n;
    v->b = v->A + e->ncon * n;
    v->lambda = v->b + e->ncon;
    v->R = v->lambda + e->ncon;
    v->nreact = r->nreact;
    v->react_name = r->react_name;
    v->react = r->react;
    v->react_res = r->react_res;
    for (size_t i = 0; i < 3 && v->T[0]; i++)
        if (!(v->T[i] = at_state(r, v->T[i])))
            return cli_diag_ctx(r->ctx);
    return QD_EXIT_OK;
}

static int emit(eom_run *r, cli_eom_format fmt) {
    int rc = make_view(r);
    if (rc != QD_EXIT_OK)
        return rc;
    qd_buf b = QD_BUF_INIT;
    qd_status st = cli_eom_write(&r->view, fmt, &b);
    if (st == QD_OK && !b.failed)
        fputs(qd_buf_str(&b), stdout);
    else
        cli_diag_error("cannot print the equations: %s",
                      qd_status_str(b.failed ? QD_ERR_NOMEM : st));
    qd_buf_free(&b);
    return st == QD_OK && !b.failed ? QD_EXIT_OK : QD_EXIT_FAIL;
}

/* An option of one kind of model given for the other: its name, or NULL. */
static const char *speeds_option(const eom_args *a) {
    return a->method ? "--method" : a->appell ? "--appell" : a->multipliers ? "--multipliers"
           : a->hamel_coef ? "--hamel-coefficients"
                                                                          : NULL;
}

static const char *coords_option(const eom_args *a) {
    return a->eliminate ? "--eliminate" : NULL;
}

/* Lagrange's equations in the coordinates: M q'' = f (+ A^T lambda). */
static int run_coords(eom_run *r, const eom_args *a) {
    const char *opt = speeds_option(a);
    if (opt) {
        cli_diag_error("%s is for a model with generalized speeds, and %s declares no speeds "
                       "(a `speeds` statement; without one, --solve gives the multipliers)",
                       opt, a->file);
        return QD_EXIT_USAGE;
    }
    qd_eom_opts opts = {.eliminate = a->eliminate};
    if (!(r->e = qd_eom_derive_opts(r->ctx, r->mf.model, &opts)))
        return cli_eom_derive_error(r->ctx, &r->mf);
    int rc = a->at ? evaluate(r, a->at) : a->solve ? solve(r) : QD_EXIT_OK;
    return rc == QD_EXIT_OK ? emit(r, a->fmt) : rc;
}

/* The --at state of a model with speeds: cli_state's (q, q', t, the
 * parameters) with the speeds appended, so that --at names them; the
 * velocities follow from the kinematics and must not be given. */
static int speeds_state(eom_run *r, const qd_speeds_eom *e, const char *at) {
    cli_state *st = &r->st;
    int rc = cli_state_init(r->ctx, r->mf.model, st);
    if (rc != QD_EXIT_OK)
        return rc;
    const qd_expr **syms = realloc(st->syms, (st->n + e->m) * sizeof *syms);
    if (syms)
        st->syms = syms;
    double *vals = syms ? realloc(st->vals, (st->n + e->m) * sizeof *vals) : NULL;
    if (!vals) {
        cli_diag_error("out of memory");
        return QD_EXIT_FAIL;
    }
    st->vals = vals;
    for (size_t i = 0; i < e->m; i++) {
        st->syms[st->n + i] = e->u[i];
        st->vals[st->n + i] = 0;
    }
    st->n += e->m;
    rc = cli_state_parse(r->ctx, r->mf.model, at, st);
    for (size_t j = 0; rc == QD_EXIT_OK && j < e->n; j++)
        if (st->vals[e->n + j] != 0) {
            cli_diag_error("--at: %s' is given, but with speeds the velocities follow from "
                           "them: give the speeds (%s, ...)", qd_expr_name(e->q[j]),
                           qd_expr_name(e->u[0]));
            rc = QD_EXIT_USAGE;
        }
    return rc;
}

/* Every number at the state is finite; else the error naming the first
 * that is not (1/sin(theta) at theta = 0: the speed map is singular there). */
static int finite_at(const qd_speeds_eom *e, const double *num) {
    size_t total = e->n + e->m + (e->mult ? e->ncon : 0);
    for (size_t i = 0; i < total; i++) {
        if (isfinite(num[i]))
            continue;
        const char *what = i < e->n ? qd_expr_name(e->q[i])
                         : i < e->n + e->m ? qd_expr_name(e->u[i - e->n])
                                           : qd_expr_name(e->con[i - e->n - e->m].lambda);
        cli_diag_error("at this state %s%s is not a finite number (the speeds may not determine "
                       "the velocities there)", what, i < e->n + e->m ? "'" : "");
        return QD_EXIT_FAIL;
    }
    return QD_EXIT_OK;
}

/* --at: q', u' and the multipliers at the state (qd_speeds_eval). */
static int speeds_at(eom_run *r, const qd_speeds_eom *e, const char *at, double *num,
                     cli_speeds_view *v) {
    int rc = speeds_state(r, e, at);
    if (rc != QD_EXIT_OK)
        return rc;
    v->st = &r->st;
    v->qd = num;
    v->ud = num + e->n;
    v->lambda = e->mult ? num + e->n + e->m : NULL;
    qd_status st = qd_speeds_eval(r->ctx, e, r->st.n, r->st.syms, r->st.vals, num,
                                  num + e->n, e->mult ? num + e->n + e->m : NULL);
    if (st == QD_OK)
        return finite_at(e, num);
    cli_diag_error("cannot evaluate the equations at this state: %s",
                   qd_ctx_message(r->ctx)[0] ? qd_ctx_message(r->ctx) : qd_status_str(st));
    return st == QD_ERR_NOMEM ? cli_diag_ctx(r->ctx) : QD_EXIT_FAIL;
}

static int speeds_emit(const cli_speeds_view *v, cli_eom_format fmt) {
    qd_buf b = QD_BUF_INIT;
    qd_status st = cli_speeds_write(v, fmt, &b);
    int rc = QD_EXIT_OK;
    if (st == QD_OK && !b.failed) {
        fputs(qd_buf_str(&b), stdout);
    } else {
        cli_diag_error("cannot print the equations: %s",
                       qd_status_str(b.failed ? QD_ERR_NOMEM : st));
        rc = QD_EXIT_FAIL;
    }
    qd_buf_free(&b);
    return rc;
}

/* --solve: u' = M_u^-1 f_u symbolically; M_u and f_u stay when too large. */
static int solve_speeds(eom_run *r, qd_speeds_eom *e) {
    qd_status st = qd_speeds_solve(r->ctx, e, SOLVE_MAX_OPS);
    if (st == QD_OK)
        return QD_EXIT_OK;
    if (st == QD_ERR_TOOBIG) {
        fprintf(stderr, "qdot: note: the solved rates exceed %d operations; "
                        "printing M and f instead (use --at for numbers)\n", SOLVE_MAX_OPS);
        qd_ctx_clear_error(r->ctx);
        return QD_EXIT_OK;
    }
    cli_diag_error("cannot solve for the speeds' rates: %s", qd_ctx_message(r->ctx));
    return QD_EXIT_FAIL;
}

/* The name of Hamel index i: a speed, then a constraint. */
static const char *hamel_index(const qd_speeds_eom *e, size_t i) {
    return i < e->m ? qd_expr_name(e->u[i]) : e->con[i - e->m].name ? e->con[i - e->m].name : "?";
}

/* --hamel-coefficients: gamma_ikm of the speeds (qd_speeds_hamel_coefficients),
 * the nonzero ones in text, all of them as [i][k][m] in JSON. */
static int hamel_coefficients(eom_run *r, const qd_speeds_eom *e, bool json) {
    size_t n = e->n;
    const qd_expr **g = calloc(n * n * n + 1, sizeof *g);
    if (!g) {
        cli_diag_error("out of memory");
        return QD_EXIT_FAIL;
    }
    if (qd_speeds_hamel_coefficients(r->ctx, e, g) != QD_OK) {
        free(g);
        return cli_diag_ctx(r->ctx);
    }
    qd_buf b = QD_BUF_INIT;
    qd_json j;
    if (json) {
        qd_json_init(&j, &b);
        qd_json_begin_object(&j);
        qd_json_key(&j, "indices");
        qd_json_begin_array(&j);
        for (size_t i = 0; i < n; i++)
            qd_json_string(&j, hamel_index(e, i));
        qd_json_end_array(&j);
        qd_json_key(&j, "gamma");
        qd_json_begin_array(&j);
        for (size_t i = 0; i < n; i++) {
            qd_json_begin_array(&j);
            for (size_t k = 0; k < n; k++) {
                qd_json_begin_array(&j);
                for (size_t m = 0; m < n; m++)
                    qd_json_expr(&j, r->ctx, g[(i * n + k) * n + m]);
                qd_json_end_array(&j);
            }
            qd_json_end_array(&j);
        }
        qd_json_end_array(&j);
        qd_json_end_object(&j);
        qd_buf_puts(&b, "\n");
        b.failed = b.failed || !qd_json_ok(&j);
    } else {
        qd_buf_puts(&b, "Hamel coefficients gamma[i,k,m] = sum_jl (da_kj/dq_l - da_kl/dq_j) "
                        "b_ji b_lm (Desloge ch. 68), indices ");
        for (size_t i = 0; i < n; i++)
            qd_buf_printf(&b, "%s%s", i ? ", " : "", hamel_index(e, i));
        qd_buf_puts(&b, "\n");
        size_t nz = 0;
        for (size_t i = 0; i < n; i++)
            for (size_t k = 0; k < n; k++)
                for (size_t m = 0; m < n; m++) {
                    const qd_expr *x = g[(i * n + k) * n + m];
                    if (qd_is_zero(x))
                        continue;
                    nz++;
                    qd_buf_printf(&b, "  gamma[%s,%s,%s] = ", hamel_index(e, i),
                                  hamel_index(e, k), hamel_index(e, m));
                    qd_print(r->ctx, x, QD_FMT_TEXT, &b);
                    qd_buf_puts(&b, "\n");
                }
        qd_buf_puts(&b, nz ? "  (the others are 0)\n" : "  all 0 (the quasi-velocities are "
                                                          "exact differentials)\n");
    }
    int rc = b.failed ? QD_EXIT_FAIL : QD_EXIT_OK;
    if (rc == QD_EXIT_OK)
        fputs(qd_buf_str(&b), stdout);
    else
        cli_diag_error("cannot print the result");
    qd_buf_free(&b);
    free(g);
    return rc;
}

/* The equations in the model's speeds: q' = W u + w, M_u u' = f_u. */
static int run_speeds(eom_run *r, const eom_args *a) {
    const char *opt = coords_option(a);
    if (opt) {
        cli_diag_error("%s is not available for a model with generalized speeds (%s declares "
                       "them): qdot eom prints M u' = f in the speeds", opt, a->file);
        return QD_EXIT_USAGE;
    }
    if (a->at && a->fmt != QD_EOM_TEXT && a->fmt != QD_EOM_JSON) {
        cli_diag_error("--at with speeds prints text or json");
        return QD_EXIT_USAGE;
    }
    qd_speeds_opts opts = {.method = a->smethod, .appell = a->appell,
                           .multipliers = a->multipliers};
    qd_speeds_eom *e = qd_speeds_derive(r->ctx, r->mf.model, &opts);
    if (!e)
        return cli_eom_derive_error(r->ctx, &r->mf);
    if (a->hamel_coef) {
        int hrc = hamel_coefficients(r, e, a->fmt == QD_EOM_JSON);
        qd_speeds_eom_free(e);
        return hrc;
    }
    cli_speeds_view v = {.ctx = r->ctx, .mf = &r->mf, .e = e, .multipliers = a->multipliers};
    if (a->solve && !a->at && solve_speeds(r, e) != QD_EXIT_OK) {
        qd_speeds_eom_free(e);
        return QD_EXIT_FAIL;
    }
    double *num = a->at ? calloc(e->n + e->m + e->ncon + 1, sizeof *num) : NULL;
    int rc = QD_EXIT_OK;
    if (a->at && !num) {
        cli_diag_error("out of memory");
        rc = QD_EXIT_FAIL;
    }
    if (rc == QD_EXIT_OK && a->at)
        rc = speeds_at(r, e, a->at, num, &v);
    if (rc == QD_EXIT_OK)
        rc = speeds_emit(&v, a->fmt);
    free(num);
    qd_speeds_eom_free(e);
    return rc;
}

int cli_cmd_eom(int argc, char **argv) {
    eom_args a;
    int rc = parse_args(argc, argv, &a);
    if (rc != QD_EXIT_OK)
        return rc;
    if (cli_model_file_is_field(a.file)) {
        if (a.solve || a.eliminate || a.appell || a.multipliers || a.hamel_coef || a.method || a.at ||
            (a.fmt != QD_EOM_TEXT && a.fmt != QD_EOM_JSON)) {
            cli_diag_error("a field model takes --set and --format text|json only");
            return QD_EXIT_USAGE;
        }
        return cli_field_eom(a.file, a.nsets, a.sets, a.fmt == QD_EOM_JSON);
    }
    eom_run r = {.ctx = qd_ctx_new()};
    if (!r.ctx) {
        cli_diag_error("out of memory");
        return QD_EXIT_FAIL;
    }
    rc = cli_load(r.ctx, a.file, a.nsets, a.sets, true, &r.mf);
    if (rc == QD_EXIT_OK)
        rc = qd_model_nspeeds(r.mf.model) ? run_speeds(&r, &a) : run_coords(&r, &a);
    free(r.numbers);
    free(r.react_name);
    free(r.react);
    free(r.react_res);
    cli_state_free(&r.st);
    if (r.e)
        qd_eom_free(r.e);
    cli_model_file_free(&r.mf);
    qd_ctx_free(r.ctx);
    return rc;
}

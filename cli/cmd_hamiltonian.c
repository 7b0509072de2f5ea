/*
 * cli/cmd_hamiltonian.c - `qdot hamiltonian FILE`: the momenta, H(q, p, t)
 * and Hamilton's equations of a model (qd_ham_derive), with the verdicts
 * H = T + V? and H conserved?  --set gives parameters values; --at evaluates H
 * and the equations at a point (q, p, t): momenta are named there as they
 * are printed (p_r=0.3), everything else goes to the state parser.
 * A model given by H (`momenta ...`, `H = ...`) skips Lagrange's equations:
 * its equations come from H, and the Lagrangian printed is the inverse
 * Legendre transform (or the reason there is none).
 */
#include "cli.h"

#include <stdlib.h>
#include <string.h>
#include "qdot/json.h"
#include "eom_out.h"
#include "model_cli.h"
#include "model_file.h"
#include "state.h"

typedef enum { FMT_TEXT, FMT_JSON, FMT_LATEX, FMT_SYMPY } ham_fmt;

typedef struct ham_run {
    qd_ctx *ctx;
    cli_model_file mf;
    qd_eom *e;
    qd_ham *h;
    ham_fmt fmt;
    const char *file, *at, *format;
    cli_list sets;
    cli_state st; /* q, q', t, the parameters, then the momenta */
} ham_run;

static const char *const formats[] = {"text", "json", "latex", "sympy", NULL};

static const cli_opt opts[] = {
    {"--at", NULL, CLI_TEXT, offsetof(ham_run, at), "\"q=V, p_q=V, t=V\"",
     "evaluate H and the equations at this point (momenta named as printed)", NULL, NULL},
    {"--set", NULL, CLI_LIST, offsetof(ham_run, sets), "NAME=VALUE",
     "give a parameter another value (fixed into the expressions)", NULL, NULL},
    {"--format", NULL, CLI_CHOICE, offsetof(ham_run, format), "F", "output format", formats,
     NULL},
    {NULL, NULL, CLI_FLAG, 0, NULL, NULL, NULL, NULL},
};

static const cli_spec spec = {
    "hamiltonian", "FILE [options]",
    "The momenta, H(q, p, t) and Hamilton's equations of a model, with the verdicts H = T + V? "
    "and H conserved?",
    opts, NULL, 1, 1, "FILE", false};

static int parse_args(int argc, char **argv, ham_run *r) {
    const char *pos[1];
    int rc = cli_parse(&spec, argc, argv, r, pos);
    r->file = pos[0];
    for (int k = 0; r->format && formats[k]; k++)
        if (!strcmp(formats[k], r->format))
            r->fmt = (ham_fmt)k;
    return rc;
}

/* ---- --at ------------------------------------------------------------------ */

/* The model's state with the momenta appended, named in --at as they are
 * printed (p_r=0.3). */
static int state_at(ham_run *r) {
    int rc = cli_state_init(r->ctx, r->mf.model, &r->st);
    if (rc == QD_EXIT_OK && qd_state_append(r->ctx, &r->st, r->h->n, r->h->p, NULL) != QD_OK)
        rc = cli_diag_ctx(r->ctx);
    return rc == QD_EXIT_OK ? cli_state_parse(r->ctx, r->mf.model, r->at, &r->st) : rc;
}

/* x at the --at point as a number node. */
static const qd_expr *number(ham_run *r, const qd_expr *x) {
    double v;
    if (qd_eval(r->ctx, x, r->st.n, r->st.syms, r->st.vals, &v) != QD_OK)
        return NULL;
    return qd_float(r->ctx, v);
}

/* An implicit H (L not quadratic in q', no closed form) needs q' at the
 * point: Newton's method on p = dL/dq', from the q' given (else 0). */
static int implicit_velocities(ham_run *r) {
    qd_ham *h = r->h;
    double *v = calloc(h->n ? h->n : 1, sizeof *v);
    if (!v)
        return QD_EXIT_FAIL;
    qd_status st = qd_ham_velocities_at(r->ctx, h, r->st.n, r->st.syms, r->st.vals, v);
    for (size_t j = 0; st == QD_OK && j < h->n; j++) {
        if (qd_state_find(&r->st, h->qd[j]) < r->st.n)
            r->st.vals[qd_state_find(&r->st, h->qd[j])] = v[j];
        h->vel[j] = qd_float(r->ctx, v[j]);
    }
    free(v);
    if (st != QD_OK) {
        cli_diag_error("cannot evaluate at this point: %s", qd_ctx_message(r->ctx));
        return QD_EXIT_FAIL;
    }
    return QD_EXIT_OK;
}

static int evaluate(ham_run *r) {
    qd_ham *h = r->h;
    int rc = state_at(r);
    if (rc == QD_EXIT_OK && h->implicit)
        rc = implicit_velocities(r);
    if (rc != QD_EXIT_OK)
        return rc;
    h->H = number(r, h->H);
    for (size_t j = 0; h->H && j < h->n; j++)
        if (!(h->dq[j] = number(r, h->dq[j])) || !(h->dp[j] = number(r, h->dp[j])))
            break;
    if (qd_ctx_status(r->ctx) != QD_OK) {
        cli_diag_error("cannot evaluate at this point: %s", qd_ctx_message(r->ctx));
        return QD_EXIT_FAIL;
    }
    return QD_EXIT_OK;
}

/* ---- output ---------------------------------------------------------------- */

static qd_format expr_format(ham_fmt f) {
    return f == FMT_LATEX ? QD_FMT_LATEX : f == FMT_SYMPY ? QD_FMT_SYMPY : QD_FMT_TEXT;
}

static void put(const ham_run *r, qd_buf *b, const qd_expr *x) {
    qd_print(r->ctx, x, expr_format(r->fmt), b);
}

/* "  lhs = rhs" (LaTeX rows end in \\). */
static void line(const ham_run *r, qd_buf *b, const qd_expr *lhs_x, const char *lhs,
                 const qd_expr *rhs) {
    qd_buf_puts(b, "  ");
    if (lhs_x)
        put(r, b, lhs_x);
    qd_buf_printf(b, "%s = ", lhs);
    put(r, b, rhs);
    qd_buf_puts(b, r->fmt == FMT_LATEX ? " \\\\\n" : "\n");
}

static void verdicts(const ham_run *r, qd_buf *b, const char *cmt) {
    const qd_ham *h = r->h;
    if (h->H_minus_E) {
        qd_buf_printf(b, "%sH = T + V: %s", cmt, h->is_energy ? "yes" : "no, H - (T + V) = ");
        if (!h->is_energy)
            qd_print(r->ctx, h->H_minus_E, QD_FMT_TEXT, b);
        qd_buf_puts(b, "\n");
    } else {
        qd_buf_printf(b, "%sH = T + V: unknown (the model gives %s, not T and V)\n", cmt,
                      h->H_given ? "H" : "L");
    }
    qd_buf_printf(b, "%sH conserved: %s\n", cmt,
                  h->conserved ? "yes" : "no (explicit t, generalized forces or dissipation)");
}

static void write_lines(const ham_run *r, qd_buf *b) {
    const qd_ham *h = r->h;
    const char *cmt = r->fmt == FMT_LATEX ? "% " : "";
    qd_buf_printf(b, "%sqdot hamiltonian %s\n%smomenta%s\n", cmt, r->mf.path, cmt,
                  h->implicit ? " (no closed form for the velocities: they solve these)"
                  : r->at     ? ""
                              : " and velocities");
    for (size_t j = 0; j < h->n; j++) {
        if (h->pdef[j])
            line(r, b, h->p[j], "", h->pdef[j]);
        if (!r->at && !h->implicit)
            line(r, b, h->qd[j], "", h->vel[j]);
    }
    if (h->implicit && r->at) {
        qd_buf_printf(b, "%svelocities at the point (Newton's method on the momenta)\n", cmt);
        for (size_t j = 0; j < h->n; j++)
            line(r, b, h->qd[j], "", h->vel[j]);
    }
    if (h->implicit && !r->at)
        qd_buf_printf(b, "%sHamiltonian (defined implicitly: sum p q' - L at those "
                         "velocities)\n", cmt);
    else
        qd_buf_printf(b, "%sHamiltonian%s\n", cmt, r->at ? " at the point" : "");
    line(r, b, NULL, "H", h->H);
    if (h->H_given && !r->at) {
        qd_buf_printf(b, "%sLagrangian (inverse Legendre transform)\n", cmt);
        if (h->L_from_H)
            line(r, b, NULL, "L", h->L_from_H);
        else
            qd_buf_printf(b, "%s  none: %s\n", cmt, h->L_why);
    }
    qd_buf_printf(b, "%sHamilton's equations\n", cmt);
    for (size_t j = 0; j < h->n; j++) {
        qd_buf_printf(b, "  d%s/dt = ", qd_expr_name(h->q[j]));
        put(r, b, h->dq[j]);
        qd_buf_printf(b, "%s  d%s/dt = ", r->fmt == FMT_LATEX ? " \\\\\n" : "\n",
                      qd_expr_name(h->p[j]));
        put(r, b, h->dp[j]);
        qd_buf_puts(b, r->fmt == FMT_LATEX ? " \\\\\n" : "\n");
    }
    verdicts(r, b, cmt);
}

static void sympy_list(const ham_run *r, qd_buf *b, const char *name, const qd_expr *const *x) {
    qd_buf_printf(b, "%s = [", cli_script_name(r->mf.model, name).s);
    for (size_t j = 0; j < r->h->n; j++) {
        qd_buf_puts(b, j ? ", " : "");
        put(r, b, x[j]);
    }
    qd_buf_puts(b, "]\n");
}

/* W = Function('W') for the user functions in H, L and the lists. */
static void sympy_functions(const ham_run *r, qd_buf *b) {
    const qd_ham *h = r->h;
    const qd_expr *const *lists[4] = {h->pdef, h->vel, h->dq, h->dp};
    const qd_expr **all = malloc((2 + 4 * h->n) * sizeof *all);
    if (!all) {
        b->failed = true;
        return;
    }
    size_t k = 0;
    all[k++] = h->H;
    all[k++] = h->L_from_H;
    for (size_t i = 0; i < 4; i++)
        for (size_t j = 0; j < h->n; j++)
            all[k++] = lists[i][j];
    qd_print_sympy_functions(r->ctx, k, all, b);
    free(all);
}

/* Python that defines momenta, pdef (dL/dq'), H, dq_dt and dp_dt (each with
 * underscores appended when the model uses the name: a length L); the
 * coordinates are functions of t as in `eom --format sympy`. */
static void write_sympy(const ham_run *r, qd_buf *b) {
    const qd_ham *h = r->h;
    const qd_model *m = r->mf.model;
    const char *t = qd_print_time_name(r->ctx); /* x for `independent x` */
    qd_buf_printf(b, "# qdot hamiltonian %s\nfrom sympy import *\n\n%s = Symbol('%s')\n", r->mf.path,
                  t, t);
    for (size_t j = 0; j < h->n; j++)
        qd_buf_printf(b, "%s = Function('%s')\n%s = Symbol('%s')\n", qd_expr_name(h->q[j]),
                      qd_expr_name(h->q[j]), qd_expr_name(h->p[j]), qd_expr_name(h->p[j]));
    for (size_t i = 0; i < qd_model_nparams(m); i++)
        qd_buf_printf(b, "%s = Symbol('%s')\n", qd_expr_name(qd_model_param(m, i)),
                      qd_expr_name(qd_model_param(m, i)));
    for (size_t i = 0; i < qd_model_ninputs(m); i++) /* inputs print by name */
        qd_buf_printf(b, "%s = Symbol('%s')\n", qd_expr_name(qd_model_input(m, i)),
                      qd_expr_name(qd_model_input(m, i)));
    sympy_functions(r, b);
    sympy_list(r, b, "momenta", h->p);
    if (h->pdef[0] || !h->n)
        sympy_list(r, b, "pdef", h->pdef);
    else
        qd_buf_printf(b, "%s = None\n", cli_script_name(m, "pdef").s);
    sympy_list(r, b, "velocities", h->vel);
    if (h->implicit) /* velocities are then the symbols q' themselves, tied to p by pdef */
        qd_buf_printf(b, "%s = True\n", cli_script_name(m, "implicit").s);
    qd_buf_printf(b, "%s = ", cli_script_name(m, "H").s);
    put(r, b, h->H);
    qd_buf_puts(b, "\n");
    if (h->H_given) {
        qd_buf_printf(b, "%s = ", cli_script_name(m, "L").s);
        if (h->L_from_H)
            put(r, b, h->L_from_H);
        else
            qd_buf_puts(b, "None");
        qd_buf_puts(b, "\n");
    }
    sympy_list(r, b, "dq_dt", h->dq);
    sympy_list(r, b, "dp_dt", h->dp);
    verdicts(r, b, "# ");
}

/* A string of x, or its number with --at. */
static void json_expr(const ham_run *r, qd_json *j, const qd_expr *x) {
    if (r->at && x && qd_is_number(x))
        qd_json_number(j, cli_state_value(x));
    else
        qd_json_expr(j, r->ctx, x);
}

static void json_list(const ham_run *r, qd_json *j, const char *key, const qd_expr *const *x) {
    qd_json_key(j, key);
    qd_json_begin_array(j);
    for (size_t k = 0; k < r->h->n; k++)
        if (x[k])
            json_expr(r, j, x[k]);
        else
            qd_json_null(j);
    qd_json_end_array(j);
}

static void json_point(const ham_run *r, qd_json *j) {
    qd_json_key(j, "at");
    qd_json_begin_object(j);
    const qd_model *m = r->mf.model;
    size_t nq = qd_model_ncoords(m), momenta = qd_slot_count(nq, qd_model_nparams(m));
    for (size_t i = 0; i < r->st.n; i++) /* q, t and p */
        if (i < nq || i == qd_slot_time(nq) || i >= momenta) {
            qd_json_key(j, qd_expr_name(r->st.syms[i]));
            qd_json_number(j, r->st.vals[i]);
        }
    qd_json_end_object(j);
}

static void write_json(const ham_run *r, qd_buf *b) {
    const qd_ham *h = r->h;
    qd_json j;
    qd_json_init(&j, b);
    qd_json_begin_object(&j);
    qd_json_key(&j, "model");
    qd_json_string(&j, r->mf.path);
    qd_json_key(&j, "coordinates");
    qd_json_begin_array(&j);
    for (size_t k = 0; k < h->n; k++)
        qd_json_string(&j, qd_expr_name(h->q[k]));
    qd_json_end_array(&j);
    qd_json_key(&j, "momenta");
    qd_json_begin_array(&j);
    for (size_t k = 0; k < h->n; k++)
        qd_json_string(&j, qd_expr_name(h->p[k]));
    qd_json_end_array(&j);
    json_list(r, &j, "definitions", h->pdef);
    json_list(r, &j, "velocities", h->vel);
    if (h->implicit) { /* only then, so the other models' output is unchanged */
        qd_json_key(&j, "implicit");
        qd_json_bool(&j, true);
    }
    if (r->at)
        json_point(r, &j);
    qd_json_key(&j, "H");
    json_expr(r, &j, h->H);
    json_list(r, &j, "dq_dt", h->dq);
    json_list(r, &j, "dp_dt", h->dp);
    qd_json_key(&j, "H_is_energy");
    if (h->H_minus_E)
        qd_json_bool(&j, h->is_energy);
    else
        qd_json_null(&j);
    qd_json_key(&j, "H_minus_energy");
    qd_json_expr(&j, r->ctx, h->H_minus_E);
    qd_json_key(&j, "conserved");
    qd_json_bool(&j, h->conserved);
    qd_json_key(&j, "H_given");
    qd_json_bool(&j, h->H_given);
    if (h->H_given && !r->at) { /* the inverse Legendre transform, or why there is none */
        qd_json_key(&j, "L");
        json_expr(r, &j, h->L_from_H);
        qd_json_key(&j, "L_error");
        if (h->L_from_H)
            qd_json_null(&j);
        else
            qd_json_string(&j, h->L_why);
    }
    qd_json_end_object(&j);
    qd_buf_puts(b, "\n");
    b->failed = b->failed || !qd_json_ok(&j);
}

static int emit(ham_run *r) {
    qd_buf b = QD_BUF_INIT;
    if (r->fmt == FMT_JSON)
        write_json(r, &b);
    else if (r->fmt == FMT_SYMPY)
        write_sympy(r, &b);
    else
        write_lines(r, &b);
    return cli_emit(&b, "Hamiltonian");
}

static int run(ham_run *r) {
    int rc = cli_load(r->ctx, r->file, r->sets.n, r->sets.items, true, &r->mf);
    bool given = rc == QD_EXIT_OK && qd_model_hamiltonian_given(r->mf.model);
    /* a singular Hessian named as the Legendre transform sees it, before
     * Lagrange's equations fail on the same matrix */
    if (rc == QD_EXIT_OK && !given && qd_ham_regular(r->ctx, r->mf.model) != QD_OK)
        rc = cli_eom_derive_error(r->ctx, &r->mf);
    if (rc == QD_EXIT_OK && !given && !(r->e = qd_eom_derive(r->ctx, r->mf.model)))
        rc = cli_eom_derive_error(r->ctx, &r->mf);
    if (rc == QD_EXIT_OK && !(r->h = qd_ham_derive(r->ctx, r->mf.model, r->e)))
        rc = cli_eom_derive_error(r->ctx, &r->mf);
    if (rc == QD_EXIT_OK && r->at)
        rc = evaluate(r);
    return rc == QD_EXIT_OK ? emit(r) : rc;
}

int cli_cmd_hamiltonian(int argc, char **argv) {
    ham_run r = {.fmt = FMT_TEXT};
    int rc = parse_args(argc, argv, &r);
    if (rc != QD_EXIT_OK)
        return rc;
    if (!(r.ctx = qd_ctx_new())) {
        cli_diag_error("out of memory");
        return QD_EXIT_FAIL;
    }
    rc = run(&r);
    cli_state_free(&r.st);
    qd_ham_free(r.h);
    qd_eom_free(r.e);
    cli_model_file_free(&r.mf);
    qd_ctx_free(r.ctx);
    return rc;
}

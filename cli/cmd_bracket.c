/*
 * cli/cmd_bracket.c - `qdot bracket FILE F G`: the Poisson bracket [F, G]
 * (qd_bracket) in the model's canonical variables, the coordinates q_j and
 * the momenta p_<q_j> named as hamilton.h names them; `--dt F` gives
 *
 *     dF/dt = [F, H] + dF/dt|explicit + sum_j dF/dp_j extra_j,
 *
 * the last sum being the generalized forces and dissipation that Hamilton's
 * equations carry beyond -dH/dq (zero for a conservative model); for an
 * implicit H (L not quadratic in q', no closed-form q'(p)) the result is in
 * q' too, which solves p = dL/dq'.  Also the
 * model-and-variables helpers (cli_phase) that `qdot canonical` shares.
 */
#include "cli.h"

#include <stdlib.h>
#include <string.h>
#include "eom_out.h"
#include "qdot/json.h"
#include "model_cli.h"
#include "model_file.h"

typedef enum { FMT_TEXT, FMT_JSON, FMT_LATEX } br_fmt;

static const char usage_text[] =
    "usage: qdot bracket FILE F G [--format text|json|latex]\n"
    "       qdot bracket FILE --dt F [--format text|json|latex]";

/* ---- the canonical variables ---------------------------------------------- */

static int momenta(cli_phase *ph) {
    const qd_model *m = ph->mf->model;
    ph->n = qd_model_ncoords(m);
    ph->q = calloc(ph->n + 1, sizeof *ph->q);
    ph->p = calloc(ph->n + 1, sizeof *ph->p);
    if (!ph->q || !ph->p) {
        cli_diag_error("out of memory");
        return QD_EXIT_FAIL;
    }
    for (size_t j = 0; j < ph->n; j++) {
        char name[256];
        ph->q[j] = qd_model_coord(m, j);
        snprintf(name, sizeof name, "p_%s", qd_expr_name(ph->q[j]));
        /* the model's own name (`momenta`), else p_<q>; a parameter already
         * named p_x cannot also be the momentum */
        const qd_expr *named = qd_model_momentum(m, j);
        if (!(ph->p[j] = named ? named : qd_symbol(ph->ctx, name)))
            return cli_diag_ctx(ph->ctx);
    }
    return QD_EXIT_OK;
}

int cli_phase_load(const char *file, size_t nsets, const char *const *sets, cli_phase *ph) {
    *ph = (cli_phase){.ctx = qd_ctx_new(), .mf = calloc(1, sizeof *ph->mf)};
    if (!ph->ctx || !ph->mf) {
        cli_diag_error("out of memory");
        return QD_EXIT_FAIL;
    }
    int rc = cli_load(ph->ctx, file, nsets, sets, true, ph->mf);
    return rc == QD_EXIT_OK ? momenta(ph) : rc;
}

/* Velocities have no place in a function on phase space. */
static int no_velocity(cli_phase *ph, const char *what, const qd_expr *x) {
    for (size_t j = 0; j < ph->n; j++)
        for (unsigned k = 1; k <= 2; k++) {
            const qd_expr *v = qd_jet(ph->ctx, ph->q[j], k);
            if (v && qd_has(x, v)) {
                cli_diag_error("%s contains the velocity %s: write functions of %s and p_%s",
                              what, qd_expr_name(v), qd_expr_name(ph->q[j]),
                              qd_expr_name(ph->q[j]));
                return QD_EXIT_USAGE;
            }
        }
    return QD_EXIT_OK;
}

/* A parameter the model was read with --set has its number in the model's
 * expressions: the same in what the user writes beside them. */
static const qd_expr *fixed_values(cli_phase *ph, const qd_expr *x) {
    const qd_model *m = ph->mf->model;
    for (size_t i = 0; x && i < qd_model_nparams(m); i++)
        if (qd_model_param_fixed(m, i)) {
            const qd_expr *p = qd_model_param(m, i), *v = qd_model_param_value(m, i);
            x = qd_subs(ph->ctx, x, 1, &p, &v);
        }
    return x;
}

int cli_phase_read(cli_phase *ph, const char *what, const char *text, const qd_expr **out) {
    qd_read_opts opts = {.new_symbols = false};
    qd_diag err;
    *out = qd_read(ph->ctx, text, &opts, &err);
    if (!*out) {
        cli_diag_read(what, text, &err);
        return QD_EXIT_USAGE;
    }
    *out = fixed_values(ph, *out);
    if (!*out)
        return cli_diag_ctx(ph->ctx);
    return no_velocity(ph, what, *out);
}

int cli_phase_ham(cli_phase *ph, bool closed) {
    /* a model given by H needs no equations of motion for its brackets */
    if (!qd_model_hamiltonian_given(ph->mf->model) &&
        !(ph->e = qd_eom_derive(ph->ctx, ph->mf->model)))
        return cli_eom_derive_error(ph->ctx, ph->mf);
    if (!(ph->h = qd_ham_derive(ph->ctx, ph->mf->model, ph->e)))
        return cli_eom_derive_error(ph->ctx, ph->mf);
    if (closed && ph->h->implicit) { /* K = H + dF/dt in new variables needs H itself */
        cli_diag_error("a generating function's new Hamiltonian needs H in closed form, but L is "
                       "not quadratic in the velocities and p = dL/dq' has no closed-form "
                       "solution for q' here (H is defined implicitly; `qdot hamiltonian --at` "
                       "evaluates it)");
        return QD_EXIT_FAIL;
    }
    for (size_t j = 0; j < ph->n; j++)
        if (ph->h->p[j] != ph->p[j]) {
            cli_diag_error("the Hamiltonian names its momentum %s, not %s",
                          qd_expr_name(ph->h->p[j]), qd_expr_name(ph->p[j]));
            return QD_EXIT_FAIL;
        }
    return QD_EXIT_OK;
}

void cli_phase_free(cli_phase *ph) {
    qd_ham_free(ph->h);
    if (ph->e)
        qd_eom_free(ph->e);
    if (ph->mf)
        cli_model_file_free(ph->mf);
    free(ph->mf);
    free(ph->q);
    free(ph->p);
    qd_ctx_free(ph->ctx);
    *ph = (cli_phase){0};
}

/* ---- the command ------------------------------------------------------------ */

typedef struct br_args {
    const char *file, *F, *G;
    bool dt;
    br_fmt fmt;
} br_args;

static int parse_format(const char *v, br_fmt *f) {
    static const char *const names[] = {"text", "json", "latex"};
    for (int i = 0; i < 3; i++)
        if (!strcmp(v, names[i])) {
            *f = (br_fmt)i;
            return QD_EXIT_OK;
        }
    cli_diag_error("--format takes text, json or latex, not '%s'", v);
    return QD_EXIT_USAGE;
}

static int positional(br_args *a, const char *s) {
    const char **slot = !a->file ? &a->file : !a->F ? &a->F : !a->G && !a->dt ? &a->G : NULL;
    if (!slot) {
        cli_diag_error("unexpected argument '%s'\n%s", s, usage_text);
        return QD_EXIT_USAGE;
    }
    *slot = s;
    return QD_EXIT_OK;
}

static int parse_args(int argc, char **argv, br_args *a) {
    *a = (br_args){.fmt = FMT_TEXT};
    int rc = QD_EXIT_OK;
    bool options = true; /* until "--": after it every argument is an expression */
    for (int i = 0; rc == QD_EXIT_OK && i < argc; i++) {
        if (options && !strcmp(argv[i], "--"))
            options = false;
        else if (!options || !cli_is_option(argv[i]))
            rc = positional(a, argv[i]); /* -x and -p_x are expressions */
        else if (!strcmp(argv[i], "--dt"))
            a->dt = true;
        else if (!strncmp(argv[i], "--format=", 9))
            rc = parse_format(argv[i] + 9, &a->fmt);
        else if (!strcmp(argv[i], "--format") && i + 1 < argc)
            rc = parse_format(argv[++i], &a->fmt);
        else {
            cli_diag_error("unknown option or missing value: '%s'\n%s", argv[i], usage_text);
            rc = QD_EXIT_USAGE;
        }
    }
    if (rc == QD_EXIT_OK && (!a->F || (!a->dt && !a->G) || (a->dt && a->G))) {
        cli_diag_error("%s", usage_text);
        rc = QD_EXIT_USAGE;
    }
    return rc;
}

/* dF/dt along the motion from Hamilton's equations as qd_ham_derive gives
 * them, dq_j/dt = dH/dp_j and dp_j/dt = -dH/dq_j + extra_j:
 *
 *     dF/dt = dF/dt|explicit + sum_j (dF/dq_j dq_j/dt + dF/dp_j dp_j/dt),
 *
 * i.e. [F, H] plus the forces' part.  Taking the equations rather than
 * differentiating H serves an implicit H too (its q' depends on q and p in
 * no closed form; there dq_j/dt = q'_j and dp_j/dt = dL/dq_j + extra_j,
 * exact, with q' the solution of p = dL/dq'). */
static const qd_expr *time_derivative(cli_phase *ph, const qd_expr *F) {
    qd_ctx *ctx = ph->ctx;
    const qd_ham *h = ph->h;
    const qd_expr *d = qd_diff(ctx, F, qd_time(ctx));
    for (size_t j = 0; j < ph->n; j++)
        d = qd_add(ctx, d, qd_add(ctx, qd_mul(ctx, qd_diff(ctx, F, ph->q[j]), h->dq[j]),
                                  qd_mul(ctx, qd_diff(ctx, F, ph->p[j]), h->dp[j])));
    return d ? qd_simplify(ctx, d) : NULL;
}

static void json_expr(qd_ctx *ctx, qd_json *j, const char *key, const qd_expr *x) {
    qd_buf s = QD_BUF_INIT;
    qd_print(ctx, x, QD_FMT_TEXT, &s);
    qd_json_key(j, key);
    qd_json_string(j, qd_buf_str(&s));
    qd_buf_free(&s);
}

static void write_json(cli_phase *ph, const br_args *a, const qd_expr *F, const qd_expr *G,
                       const qd_expr *r, qd_buf *b) {
    qd_json j;
    qd_json_init(&j, b);
    qd_json_begin_object(&j);
    qd_json_key(&j, "momenta");
    qd_json_begin_array(&j);
    for (size_t k = 0; k < ph->n; k++)
        qd_json_string(&j, qd_expr_name(ph->p[k]));
    qd_json_end_array(&j);
    json_expr(ph->ctx, &j, "F", F);
    if (a->dt) {
        json_expr(ph->ctx, &j, "H", ph->h->H);
        json_expr(ph->ctx, &j, "dF_dt", r);
        if (ph->h->implicit) { /* H and dF_dt are in q' too, defined by p = dL/dq' */
            qd_json_key(&j, "implicit");
            qd_json_bool(&j, true);
        }
    } else {
        json_expr(ph->ctx, &j, "G", G);
        json_expr(ph->ctx, &j, "bracket", r);
    }
    qd_json_end_object(&j);
    qd_buf_puts(b, "\n");
    b->failed = b->failed || !qd_json_ok(&j);
}

static void write_line(cli_phase *ph, const br_args *a, const qd_expr *F, const qd_expr *G,
                       const qd_expr *r, qd_buf *b) {
    qd_format f = a->fmt == FMT_LATEX ? QD_FMT_LATEX : QD_FMT_TEXT;
    bool tex = a->fmt == FMT_LATEX;
    if (a->dt) {
        qd_buf_puts(b, tex ? "\\frac{d}{dt}\\left(" : "d/dt(");
        qd_print(ph->ctx, F, f, b);
        qd_buf_puts(b, tex ? "\\right) = " : ") = ");
    } else {
        qd_buf_puts(b, tex ? "\\left\\{" : "[");
        qd_print(ph->ctx, F, f, b);
        qd_buf_puts(b, ", ");
        qd_print(ph->ctx, G, f, b);
        qd_buf_puts(b, tex ? "\\right\\} = " : "] = ");
    }
    qd_print(ph->ctx, r, f, b);
    qd_buf_puts(b, "\n");
    if (a->dt && ph->h->implicit)
        qd_buf_puts(b, tex ? "% q' solves p = dL/dq' (no closed form)\n"
                           : "  (q' solves p = dL/dq': no closed form)\n");
}

static int emit(cli_phase *ph, const br_args *a, const qd_expr *F, const qd_expr *G,
                const qd_expr *r) {
    qd_buf b = QD_BUF_INIT;
    if (a->fmt == FMT_JSON)
        write_json(ph, a, F, G, r, &b);
    else
        write_line(ph, a, F, G, r, &b);
    bool ok = !b.failed;
    if (ok)
        fputs(qd_buf_str(&b), stdout);
    else
        cli_diag_error("cannot print the bracket");
    qd_buf_free(&b);
    return ok ? QD_EXIT_OK : QD_EXIT_FAIL;
}

static int run(cli_phase *ph, const br_args *a) {
    const qd_expr *F, *G = NULL, *r;
    int rc = cli_phase_read(ph, "F", a->F, &F);
    if (rc == QD_EXIT_OK && !a->dt)
        rc = cli_phase_read(ph, "G", a->G, &G);
    if (rc == QD_EXIT_OK && a->dt)
        rc = cli_phase_ham(ph, false);
    if (rc != QD_EXIT_OK)
        return rc;
    r = a->dt ? time_derivative(ph, F) : qd_bracket(ph->ctx, ph->n, ph->q, ph->p, F, G);
    if (!r)
        return cli_diag_ctx(ph->ctx);
    return emit(ph, a, F, G, r);
}

int cli_cmd_bracket(int argc, char **argv) {
    br_args a;
    int rc = parse_args(argc, argv, &a);
    if (rc != QD_EXIT_OK)
        return rc;
    cli_phase ph;
    rc = cli_phase_load(a.file, 0, NULL, &ph);
    if (rc == QD_EXIT_OK)
        rc = run(&ph, &a);
    cli_phase_free(&ph);
    return rc;
}

/*
 * cli/cmd_modes.c - `qdot modes FILE`: small oscillations about an
 * equilibrium (or any point at rest given with --about).  libqdot
 * linearizes (qd_linear_about: M0 q'' + (C0 + G0) q' + K0 q = 0) and solves
 * the eigenproblem (qd_modes_solve: K0 a = w^2 M0 a, or the state-space
 * eigenvalues when there is damping or a gyroscopic term); with 1 or 2
 * degrees of freedom about an exact equilibrium, w^2 is also printed as an
 * expression of the parameters (or, when the equilibrium itself depends on
 * the parameters' values, as an exact number at those values).  --initial
 * gives the motion from initial values through the normal coordinates
 * Q = a^T M0 (q - q0).
 *
 * Without --about or --at-equilibrium libqdot chooses the equilibrium
 * (qd_equilibria_choose: a minimum of the potential nearest the model's
 * `initial` state, or of lowest V without one); this file says which and
 * how many others there are (stderr in text; JSON "choice").
 *
 * --symmetry (modes_symmetry.c): the symmetry group of the point, its
 * character table and the modes labelled by irreps, in place of the plain
 * conservative modes.
 */
#include "linear_cli.h"

#include <math.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>
#include "qdot/json.h"
#include "model_cli.h"
#include "modes_plot.h"
#include "modes_symmetry.h"
#include "plot_cli.h"

static const double PI = 3.14159265358979323846;

typedef struct modes_args {
    const char *file, *about, *initial, *scan, *format;
    const char *independent; /* --independent: a model that keeps constraints */
    size_t steps;   /* --steps: 0 the library's default */
    size_t at_eq;   /* 1-based; 0: the first minimum, else the first */
    cli_list sets;
    bool json;
    const char *plot;  /* --plot FILE: the mode shapes drawn */
    bool symmetry;     /* --symmetry */
    size_t count;      /* --count: a field model's number of modes */
    double tol;        /* --tol: a field model's relative tolerance */
} modes_args;

typedef struct modes_run {
    cli_lin_run lr;
    qd_equilibrium_choice ch;   /* found: the list (--at-equilibrium, automatic choice) */
    const qd_equilibrium *pt;   /* NULL with --about */
    const char *why;            /* how pt was chosen (automatic choice only) */
    bool sym_exact;             /* w2sym is in the parameters (else exact numbers) */
    double *q0;
    qd_linear lin;
    qd_modes_result res;
    const qd_expr *w2sym[2];
    bool have_sym;
    double residual;
    double *Q, *Qd;             /* --initial: normal coordinates at t = 0 */
    cli_sym_run sym;            /* --symmetry */
} modes_run;

static const char *const formats[] = {"text", "json", NULL};

static int tol_option(const char *v, void *args) {
    modes_args *a = args;
    char *end;
    a->tol = strtod(v, &end);
    if (*end || !(a->tol >= 1e-14 && a->tol <= 0.1)) {
        cli_diag_error("--tol takes a relative tolerance from 1e-14 to 0.1, not '%s'", v);
        return QD_EXIT_USAGE;
    }
    return QD_EXIT_OK;
}

#define OPT(...) CLI_OPT(modes_args, __VA_ARGS__)
static const cli_opt opts[] = {
    OPT("--at-equilibrium", CLI_COUNT, at_eq, "N", "about equilibrium N, as `qdot equilibria` "
        "lists them"),
    OPT("--about", CLI_TEXT, about, "\"q1=VALUE, ...\"", "about this point at rest"),
    OPT("--initial", CLI_TEXT, initial, "\"q1=VALUE, q1'=VALUE, ...\"", "the motion from these "
        "initial values, through the normal coordinates"),
    OPT("--scan", CLI_TEXT, scan, "NAME=A:B", "follow the point as the parameter goes from A to "
        "B, and where its stability changes"),
    OPT("--steps", CLI_COUNT, steps, "N", "steps of --scan (at most 100000)"),
    OPT("--symmetry", CLI_FLAG, symmetry, NULL, "the point's symmetry group and the modes "
        "labelled by irreps"),
    OPT("--independent", CLI_TEXT, independent, "\"q1, ...\"", "the independent coordinates "
        "of a model that keeps constraints"),
    OPT("--plot", CLI_TEXT, plot, "FILE.png|.svg|.pdf", "draw the mode shapes"),
    OPT("--count", CLI_COUNT, count, "N", "a field model: the number of modes (at most 1000)"),
    {"--tol", NULL, CLI_CALL, 0, "X", "a field model: the relative tolerance (1e-14 to 0.1)",
     NULL, tol_option},
    OPT("--set", CLI_LIST, sets, "NAME=VALUE", "a parameter's value"),
    {"--format", NULL, CLI_CHOICE, offsetof(modes_args, format), "NAME", "text or json", formats,
     NULL},
    {0},
};
#undef OPT

static const cli_spec spec = {
    "modes", "FILE [--at-equilibrium N | --about \"q1=VALUE, ...\"] [options]",
    "small oscillations about an equilibrium: frequencies and mode shapes (a field model: "
    "FIELDFILE [--count N] [--tol X])", opts, NULL, 1, 1, "FILE", false};

static int parse_args(int argc, char **argv, modes_args *a) {
    const char *pos[1];
    int rc = cli_parse(&spec, argc, argv, a, pos);
    a->file = pos[0];
    a->json = a->format && !strcmp(a->format, "json");
    if (rc == QD_EXIT_OK && a->steps > 100000) {
        cli_diag_error("--steps takes a number of steps from 1 to 100000, not %zu", a->steps);
        rc = QD_EXIT_USAGE;
    }
    if (rc == QD_EXIT_OK && a->count > 1000) {
        cli_diag_error("--count takes a number of modes from 1 to 1000, not %zu", a->count);
        rc = QD_EXIT_USAGE;
    }
    return rc;
}

/* What the library's automatic choice means, for the note and JSON. */
static const char *chosen_why(qd_eq_chosen c) {
    switch (c) {
    case QD_EQ_CHOSEN_NEAREST_MINIMUM:
        return "the minimum of the potential nearest the model's initial state";
    case QD_EQ_CHOSEN_LOWEST_MINIMUM:
        return "the minimum of the potential with the lowest V";
    case QD_EQ_CHOSEN_NEWTON_FROM_INITIAL:
        return "no minimum of the potential was found: the equilibrium reached by Newton's "
               "method from the model's initial state";
    default:
        return "no minimum of the potential was found: the first equilibrium listed";
    }
}

static int no_equilibrium(void) {
    cli_diag_error("no equilibrium found (qdot equilibria lists none): give a point with "
                  "--about");
    return QD_EXIT_FAIL;
}

static int choose_auto(modes_run *r) {
    cli_lin_run *lr = &r->lr;
    if (qd_equilibria_choose(lr->ctx, lr->e, lr->mf.model, lr->st.n, lr->st.syms, lr->st.vals,
                             &r->ch) != QD_OK) {
        cli_diag_error("%s", qd_ctx_message(lr->ctx));
        return QD_EXIT_FAIL;
    }
    if (!r->ch.pt)
        return no_equilibrium();
    r->pt = r->ch.pt;
    r->why = chosen_why(r->ch.reason);
    return QD_EXIT_OK;
}

static int choose_listed(modes_run *r, size_t k) {
    const qd_equilibria *eq = &r->ch.found;
    int rc = cli_lin_equilibria(&r->lr, NULL, NULL, &r->ch.found);
    if (rc != QD_EXIT_OK)
        return rc;
    if (eq->count == 0)
        return no_equilibrium();
    if (k > eq->count) {
        cli_diag_error("--at-equilibrium %zu: there %s %zu equilibri%s", k,
                      eq->count == 1 ? "is" : "are", eq->count, eq->count == 1 ? "um" : "a");
        return QD_EXIT_USAGE;
    }
    r->pt = &eq->pts[k - 1];
    return QD_EXIT_OK;
}

static int choose_point(modes_run *r, const modes_args *a) {
    size_t n = r->lr.e->n;
    r->q0 = calloc(n + 1, sizeof *r->q0);
    if (!r->q0)
        return QD_EXIT_FAIL;
    if (a->about)
        return cli_lin_coords(&r->lr, "--about", a->about, r->q0);
    int rc = a->at_eq ? choose_listed(r, a->at_eq) : choose_auto(r);
    if (rc == QD_EXIT_OK)
        memcpy(r->q0, r->pt->q, n * sizeof *r->q0);
    return rc;
}

/* The state at q0, at rest; the residual of the equations there. */
static int linearize(modes_run *r) {
    cli_lin_run *lr = &r->lr;
    size_t n = lr->e->n;
    cli_lin_set_state(lr, r->q0, NULL);
    if (qd_eom_rest_residual(lr->ctx, lr->e, lr->st.n, lr->st.syms, lr->st.vals,
                             &r->residual) != QD_OK)
        qd_ctx_clear_error(lr->ctx);
    if (qd_linear_about(lr->ctx, lr->e, lr->mf.model, lr->st.n, lr->st.syms, lr->st.vals,
                        &r->lin) != QD_OK ||
        qd_modes_solve(lr->ctx, &r->lin, &r->res) != QD_OK) {
        cli_diag_error("%s", qd_ctx_message(lr->ctx));
        return QD_EXIT_FAIL;
    }
    if (r->pt && r->pt->exact && n <= 2 && r->res.conservative) {
        r->have_sym = qd_modes_exact_omega2(lr->ctx, lr->e, lr->mf.model, lr->st.n, lr->st.syms,
                                            lr->st.vals, r->pt->exact, r->w2sym,
                                            &r->sym_exact) == QD_OK;
        qd_ctx_clear_error(lr->ctx);
    }
    return QD_EXIT_OK;
}

static int initial(modes_run *r, const char *text) {
    cli_lin_run *lr = &r->lr;
    size_t n = lr->e->n;
    if (!r->res.conservative) {
        cli_diag_error("--initial: the motion through normal coordinates needs a conservative "
                      "system without gyroscopic terms");
        return QD_EXIT_USAGE;
    }
    double *q = calloc(n + 1, sizeof *q), *qd = calloc(n + 1, sizeof *qd);
    r->Q = calloc(n + 1, sizeof *r->Q);
    r->Qd = calloc(n + 1, sizeof *r->Qd);
    int rc = q && qd && r->Q && r->Qd ? QD_EXIT_OK : QD_EXIT_FAIL;
    if (rc == QD_EXIT_OK) {
        memcpy(q, r->q0, n * sizeof *q);
        rc = cli_lin_point(lr, "--initial", text, q, qd);
    }
    if (rc == QD_EXIT_OK)
        qd_modes_normal_coords(&r->lin, &r->res, r->q0, q, qd, r->Q, r->Qd);
    free(q);
    free(qd);
    return rc;
}

/* ---- text ------------------------------------------------------------------ */

static void put_matrix(qd_buf *b, const char *name, size_t n, const double *A) {
    qd_buf_printf(b, "%s = [", name);
    for (size_t i = 0; i < n; i++) {
        qd_buf_puts(b, i ? ", [" : "[");
        for (size_t j = 0; j < n; j++) {
            qd_buf_puts(b, j ? ", " : "");
            cli_state_put_result(b, A[i * n + j]);
        }
        qd_buf_puts(b, "]");
    }
    qd_buf_puts(b, "]\n");
}

static bool all_zero(size_t nn, const double *A) {
    for (size_t i = 0; i < nn; i++)
        if (A[i] != 0)
            return false;
    return true;
}

static void put_point(modes_run *r, qd_buf *b) {
    const qd_eom *e = r->lr.e;
    qd_buf_puts(b, r->pt ? "equilibrium: " : "about: ");
    for (size_t j = 0; j < e->n; j++) {
        qd_buf_printf(b, "%s%s = ", j ? ", " : "", qd_expr_name(e->q[j]));
        if (r->pt)
            cli_lin_put_value(&r->lr, r->pt, j, b);
        else
            cli_state_put_result(b, r->q0[j]);
    }
    if (r->pt)
        qd_buf_printf(b, " (%s of the potential)", qd_eq_kind_name(r->pt->kind));
    qd_buf_printf(b, "\n");
    if (r->residual > 1e-8)
        qd_buf_printf(b, "note: not an equilibrium: the generalized forces at rest are %.3g "
                         "there; the linearization drops them\n", r->residual);
}

static void put_conservative(modes_run *r, qd_buf *b) {
    const qd_eom *e = r->lr.e;
    const qd_modes_result *res = &r->res;
    size_t n = res->n;
    qd_buf_puts(b, "conservative, no gyroscopic terms: K0 a = w^2 M0 a, a^T M0 a = 1\n");
    for (size_t j = 0; j < n; j++) {
        double w2 = res->omega2[j], w = sqrt(fabs(w2));
        qd_buf_printf(b, "mode %zu: w^2 = ", j + 1);
        cli_state_put_result(b, w2);
        if (w2 > 0)
            qd_buf_printf(b, ", w = %.10g rad/s, period = %.10g s", w, 2 * PI / w);
        else if (w2 == 0)
            qd_buf_puts(b, ", zero frequency (neutral: the normal coordinate drifts, Q(0) + "
                           "Q'(0) t)");
        else
            qd_buf_printf(b, ", unstable direction: growth rate %.10g 1/s", w);
        size_t mult = qd_modes_multiplicity(res, j);
        if (mult > 1)
            qd_buf_printf(b, " [repeated x%zu: the shapes are one M0-orthonormal basis of the "
                             "eigenspace]", mult);
        qd_buf_puts(b, "\n  shape: ");
        for (size_t i = 0; i < n; i++) {
            qd_buf_printf(b, "%s%s = ", i ? ", " : "", qd_expr_name(e->q[i]));
            double v = res->shapes[i * n + j];
            cli_state_put_result(b, v);
        }
        qd_buf_puts(b, "\n");
    }
    if (r->have_sym) {
        for (size_t j = 0; j < n; j++) {
            qd_buf_printf(b, r->sym_exact ? "w^2 (exact, mode %zu) = "
                                          : "w^2 (exact at these parameter values, mode %zu) = ",
                          j + 1);
            qd_print(r->lr.ctx, r->w2sym[j], QD_FMT_TEXT, b);
            qd_buf_puts(b, "\n");
        }
    }
    qd_buf_puts(b, "normal coordinates: Q_j = a_j^T M0 (q - q0), Q_j'' + w_j^2 Q_j = 0\n");
}

static void put_solution(modes_run *r, qd_buf *b) {
    const qd_eom *e = r->lr.e;
    size_t n = e->n;
    qd_buf_puts(b, "motion from the initial values: q(t) = q0 + sum_j a_j Q_j(t)\n");
    for (size_t j = 0; j < n; j++) {
        double w2 = r->res.omega2[j], w = sqrt(fabs(w2));
        qd_buf_printf(b, "  Q_%zu(t) = ", j + 1);
        if (w2 > 0)
            qd_buf_printf(b, "%.10g*cos(%.10g*t) + %.10g*sin(%.10g*t)\n", r->Q[j], w, r->Qd[j] / w,
                          w);
        else if (w2 == 0)
            qd_buf_printf(b, "%.10g + %.10g*t\n", r->Q[j], r->Qd[j]);
        else
            qd_buf_printf(b, "%.10g*cosh(%.10g*t) + %.10g*sinh(%.10g*t)\n", r->Q[j], w,
                          r->Qd[j] / w, w);
    }
}

static void put_state_space(modes_run *r, qd_buf *b) {
    const qd_modes_result *res = &r->res;
    qd_buf_puts(b, "damped or gyroscopic: state-space eigenvalues s of "
                   "det(s^2 M0 + s (C0 + G0) + K0) = 0\n");
    for (size_t i = 0; i < res->neig; i++) {
        double re = res->eig_re[i], im = res->eig_im[i], mod = hypot(re, im);
        if (fabs(re) <= 1e-12 * mod)
            re = 0; /* round-off off the imaginary axis: the verdict already knows */
        qd_buf_printf(b, "  s = %.10g %s %.10gi", re, im < 0 ? "-" : "+", fabs(im));
        if (mod > 0 && im > 0)
            qd_buf_printf(b, "  (frequency %.10g rad/s, damping ratio %.6g)", im, re == 0 ? 0 : -re / mod);
        qd_buf_puts(b, "\n");
    }
}

static const char *verdict(int s) {
    return s == 1 ? "stable" : s == 0 ? "unstable" : "borderline";
}

static void put_text(modes_run *r, qd_buf *b) {
    size_t n = r->lin.n;
    put_point(r, b);
    put_matrix(b, "M0", n, r->lin.M);
    if (!all_zero(n * n, r->lin.C))
        put_matrix(b, "C0", n, r->lin.C);
    if (!all_zero(n * n, r->lin.G))
        put_matrix(b, "G0", n, r->lin.G);
    put_matrix(b, "K0", n, r->lin.K);
    if (r->sym.active)
        cli_sym_put_text(&r->sym, r->lr.e, b);
    else if (r->res.conservative)
        put_conservative(r, b);
    else
        put_state_space(r, b);
    if (r->Q)
        put_solution(r, b);
    qd_buf_printf(b, "%s", verdict(r->res.stable));
    if (r->res.stable == -1)
        qd_buf_puts(b, r->res.conservative ? " (zero-frequency modes: the linear test is not "
                                             "decisive)" : " (roots on the imaginary axis that "
                                                           "are zero or repeated)");
    if (r->pt && r->pt->kind == QD_EQ_MAXIMUM && r->res.stable == 1)
        qd_buf_puts(b, " (a maximum of the potential, stabilized by the gyroscopic terms)");
    qd_buf_puts(b, "\n");
}

/* ---- json ------------------------------------------------------------------ */

static void json_matrix(qd_json *j, const char *key, size_t n, const double *A) {
    qd_json_key(j, key);
    qd_json_begin_array(j);
    for (size_t i = 0; i < n; i++) {
        qd_json_begin_array(j);
        for (size_t k = 0; k < n; k++)
            qd_json_number(j, A[i * n + k]);
        qd_json_end_array(j);
    }
    qd_json_end_array(j);
}

/* The frequencies: w of every mode (conservative; unstable ones left out),
 * or the positive imaginary parts of the state-space eigenvalues. */
static void json_frequencies(modes_run *r, qd_json *j) {
    const qd_modes_result *res = &r->res;
    qd_json_key(j, "frequencies");
    qd_json_begin_array(j);
    double *w = malloc((res->neig + 1) * sizeof *w);
    size_t nw = w ? qd_modes_frequencies(res, w) : 0;
    for (size_t k = 0; k < nw; k++)
        qd_json_number(j, w[k]);
    free(w);
    qd_json_end_array(j);
}

/* The conservative modes: w^2, w, period, multiplicity, shape, and the
 * exact w^2 and the initial normal coordinates when there are any. */
static void json_modes(modes_run *r, qd_json *j) {
    const qd_eom *e = r->lr.e;
    const qd_modes_result *res = &r->res;
    size_t n = e->n;
    qd_json_key(j, "modes");
    qd_json_begin_array(j);
    for (size_t k = 0; res->conservative && k < n; k++) {
        double w2 = res->omega2[k];
        qd_json_begin_object(j);
        qd_json_frequency(j, w2);
        qd_json_key(j, "multiplicity");
        qd_json_number(j, (double)qd_modes_multiplicity(res, k));
        qd_json_key(j, "shape");
        qd_json_begin_object(j);
        for (size_t i = 0; i < n; i++) {
            qd_json_key(j, qd_expr_name(e->q[i]));
            qd_json_number(j, res->shapes[i * n + k]);
        }
        qd_json_end_object(j);
        if (r->have_sym) {
            qd_json_key(j, "omega2_exact");
            qd_json_expr(j, r->lr.ctx, r->w2sym[k]);
            qd_json_key(j, "omega2_exact_in_parameters");
            qd_json_bool(j, r->sym_exact);
        }
        if (r->Q) {
            qd_json_key(j, "Q0");
            qd_json_number(j, r->Q[k]);
            qd_json_key(j, "Q0_dot");
            qd_json_number(j, r->Qd[k]);
        }
        qd_json_end_object(j);
    }
    qd_json_end_array(j);
}

static void put_json(modes_run *r, qd_buf *b) {
    const qd_eom *e = r->lr.e;
    const qd_modes_result *res = &r->res;
    size_t n = e->n;
    qd_json j;
    qd_json_init(&j, b);
    qd_json_begin_object(&j);
    qd_json_key(&j, "equilibrium");
    qd_json_begin_object(&j);
    for (size_t k = 0; k < n; k++) {
        qd_json_key(&j, qd_expr_name(e->q[k]));
        qd_json_number(&j, r->q0[k]);
    }
    qd_json_end_object(&j);
    qd_json_key(&j, "residual");
    qd_json_number(&j, r->residual);
    if (r->why) {
        qd_json_key(&j, "choice");
        qd_json_begin_object(&j);
        qd_json_key(&j, "reason");
        qd_json_string(&j, r->why);
        qd_json_key(&j, "others");
        qd_json_number(&j, (double)r->ch.others);
        qd_json_end_object(&j);
    }
    qd_json_key(&j, "conservative");
    qd_json_bool(&j, res->conservative);
    json_matrix(&j, "mass_matrix", n, r->lin.M);
    json_matrix(&j, "damping_matrix", n, r->lin.C);
    json_matrix(&j, "gyroscopic_matrix", n, r->lin.G);
    json_matrix(&j, "stiffness_matrix", n, r->lin.K);
    if (r->sym.active)
        cli_sym_put_json(&r->sym, e, &j);
    json_frequencies(r, &j);
    if (r->sym.active)
        cli_sym_json_modes(&r->sym, e, &j);
    else
        json_modes(r, &j);
    qd_json_key(&j, "eigenvalues");
    qd_json_begin_array(&j);
    for (size_t k = 0; k < res->neig; k++) {
        qd_json_begin_array(&j);
        qd_json_number(&j, res->eig_re[k]);
        qd_json_number(&j, res->eig_im[k]);
        qd_json_end_array(&j);
    }
    qd_json_end_array(&j);
    qd_json_key(&j, "stable");
    if (res->stable == -1)
        qd_json_null(&j);
    else
        qd_json_bool(&j, res->stable == 1);
    qd_json_key(&j, "verdict");
    qd_json_string(&j, verdict(res->stable));
    qd_json_end_object(&j);
    qd_buf_puts(b, "\n");
    b->failed = b->failed || !qd_json_ok(&j);
}

/* Which equilibrium was taken without --about, and that there are others. */
static void note_choice(const modes_run *r) {
    fprintf(stderr, "qdot: note: modes about ");
    for (size_t j = 0; j < r->lr.e->n; j++)
        fprintf(stderr, "%s%s = %.12g", j ? ", " : "", qd_expr_name(r->lr.e->q[j]), r->pt->q[j]);
    fprintf(stderr, ", %s", r->why);
    size_t others = r->ch.others;
    if (others)
        fprintf(stderr, "; %zu other equilibri%s found%s (qdot equilibria lists them; choose with "
                "--at-equilibrium N or --about)", others, others == 1 ? "um" : "a",
                r->ch.found.continuum ? ", not isolated" : "");
    fprintf(stderr, "\n");
}

int cli_cmd_modes(int argc, char **argv) {
    modes_args a = {0};
    int rc = parse_args(argc, argv, &a);
    if (rc != QD_EXIT_OK)
        return rc;
    if (cli_model_file_is_field(a.file)) {
        if (a.about || a.at_eq || a.initial || a.scan || a.plot || a.symmetry || a.steps) {
            cli_diag_error("a field model takes --count, --tol, --set and --format only");
            return QD_EXIT_USAGE;
        }
        return cli_field_modes(a.file, a.sets.n, a.sets.items, a.count, a.tol, a.json);
    }
    if (a.count || a.tol) {
        cli_diag_error("--count and --tol are for a field model (`field y(x, t) on ...`)");
        return QD_EXIT_USAGE;
    }
    if (a.about && a.at_eq) {
        cli_diag_error("give either --at-equilibrium or --about, not both");
        return QD_EXIT_USAGE;
    }
    if (a.scan && (a.at_eq || a.initial)) {
        cli_diag_error("--scan follows the point given with --about (or the equilibrium chosen "
                      "at the start of the range): give neither --at-equilibrium nor --initial");
        return QD_EXIT_USAGE;
    }
    if (a.plot && a.scan) {
        cli_diag_error("--plot draws the modes about one point: not with --scan");
        return QD_EXIT_USAGE;
    }
    if (a.plot && (rc = cli_plot_check(&(cli_plot_args){.file = a.plot}, "modes")))
        return rc;
    if (a.symmetry && a.scan) {
        cli_diag_error("--symmetry labels the modes about one point: not with --scan");
        return QD_EXIT_USAGE;
    }
    if (a.steps && !a.scan) {
        cli_diag_error("--steps is the number of steps of --scan: give --scan NAME=A:B");
        return QD_EXIT_USAGE;
    }
    modes_run r = {.lr = {.ctx = qd_ctx_new()}};
    if (!r.lr.ctx) {
        cli_diag_error("out of memory");
        return QD_EXIT_FAIL;
    }
    rc = cli_lin_load_model(&r.lr, a.file, a.sets.items, a.sets.n);
    if (rc == QD_EXIT_OK && a.plot && qd_model_nspeeds(r.lr.mf.model)) {
        cli_diag_error("--plot: the modes of a model in speeds are not drawn yet");
        rc = QD_EXIT_USAGE;
    }
    if (rc == QD_EXIT_OK && a.symmetry && qd_model_nspeeds(r.lr.mf.model)) {
        cli_diag_error("--symmetry: the modes of a model in speeds are not analysed by symmetry");
        rc = QD_EXIT_USAGE;
    }
    if (rc == QD_EXIT_OK && qd_model_nspeeds(r.lr.mf.model)) {
        rc = cli_speeds_modes(r.lr.ctx, &r.lr.mf, a.about, a.scan, a.steps, a.json,
                              a.at_eq ? "--at-equilibrium" : a.initial ? "--initial" : NULL);
        goto done;
    }
    if (rc == QD_EXIT_OK)
        rc = cli_lin_derive(&r.lr);
    if (rc == QD_EXIT_OK && (r.lr.e->ncon ? a.scan || a.symmetry || a.plot || a.initial
                                          : a.independent != NULL)) {
        cli_diag_error(r.lr.e->ncon ? "%s: not yet on the constraint manifold of a model that "
                                      "keeps constraints with multipliers"
                                    : "%s: the model keeps no constraints",
                       r.lr.e->ncon ? (a.scan ? "--scan" : a.symmetry ? "--symmetry"
                                               : a.plot ? "--plot" : "--initial")
                                    : "--independent");
        rc = QD_EXIT_USAGE;
    }
    if (rc == QD_EXIT_OK && a.scan) {
        rc = cli_scan_modes(&r.lr, a.scan, a.about, a.steps, a.json);
        goto done;
    }
    if (rc == QD_EXIT_OK)
        rc = choose_point(&r, &a);
    if (rc == QD_EXIT_OK && r.why && !a.json)
        note_choice(&r);
    if (rc == QD_EXIT_OK && r.lr.e->ncon) { /* on the manifold (constrained_cli.c) */
        rc = cli_con_modes(&r.lr, r.q0, a.independent, a.json);
        goto done;
    }
    if (rc == QD_EXIT_OK)
        rc = linearize(&r);
    if (rc == QD_EXIT_OK && a.symmetry)
        rc = cli_sym_compute(&r.lr, &r.lin, &r.sym);
    if (rc == QD_EXIT_OK && a.initial)
        rc = initial(&r, a.initial);
    if (rc == QD_EXIT_OK) {
        qd_buf b = QD_BUF_INIT;
        (a.json ? put_json : put_text)(&r, &b);
        rc = cli_emit(&b, "modes");
    }
    if (rc == QD_EXIT_OK && a.plot)
        rc = cli_modes_plot(&r.lr, r.q0, &r.res, a.plot, a.file);
done:
    free(r.q0);
    free(r.Q);
    free(r.Qd);
    qd_linear_free(&r.lin);
    qd_modes_result_free(&r.res);
    cli_sym_free(&r.sym);
    qd_equilibrium_choice_free(&r.ch);
    cli_lin_free(&r.lr);
    qd_ctx_free(r.lr.ctx);
    return rc;
}

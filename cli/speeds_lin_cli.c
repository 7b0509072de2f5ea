/*
 * cli/speeds_lin_cli.c - `qdot equilibria` and `qdot modes` on a model with
 * `speeds` (linear_cli.h): the state is (q, u).  Equilibria are u = 0 with
 * f_u(q, 0) = 0, the coordinates no equation at rest involves reported as
 * free (qd_speeds_equilibria_find); modes are the eigenvalues of the
 * reduced first-order system's Jacobian (qd_speeds_linear_about), about an
 * equilibrium or a state given with --about (a steady motion: the disk
 * rolling upright at spin u3 = 6).
 */
#include "linear_cli.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "eom_out.h"
#include "qdot/json.h"
#include "model_cli.h"
#include "qdot/speeds.h"

typedef struct sp_run {
    qd_ctx *ctx;
    cli_model_file *mf;   /* borrowed */
    qd_speeds_eom *e;
    cli_state st;         /* q, q', t, the parameters, then the speeds */
} sp_run;

static void sp_free(sp_run *r) {
    qd_speeds_eom_free(r->e);
    cli_state_free(&r->st);
}

/* Derive, and the state: coordinates, speeds, t at 0, parameters at their values. */
static int sp_load(sp_run *r, const char *refuse) {
    if (refuse) {
        cli_diag_error("%s is not available for a model with speeds (the state is q and u)",
                       refuse);
        return QD_EXIT_USAGE;
    }
    if (!(r->e = qd_speeds_derive(r->ctx, r->mf->model, NULL)))
        return cli_eom_derive_error(r->ctx, r->mf);
    int rc = cli_state_init(r->ctx, r->mf->model, &r->st);
    if (rc == QD_EXIT_OK && qd_state_append(r->ctx, &r->st, r->e->m, r->e->u, NULL) != QD_OK)
        rc = cli_diag_ctx(r->ctx);
    return rc;
}

/* The value of the state at x (a coordinate or speed of the equations). */
static double *value_of(const sp_run *r, const qd_expr *x) {
    size_t k = qd_state_find(&r->st, x);
    return k < r->st.n ? &r->st.vals[k] : NULL;
}

static void put_names(qd_buf *b, size_t n, const qd_expr *const *syms, const bool *pick) {
    bool first = true;
    for (size_t j = 0; j < n; j++)
        if (!pick || pick[j]) {
            qd_buf_printf(b, "%s%s", first ? "" : ", ", qd_expr_name(syms[j]));
            first = false;
        }
}

/* ---- equilibria --------------------------------------------------------------- */

static void eq_text(const sp_run *r, const qd_speeds_equilibria *s, qd_buf *b) {
    const qd_equilibria *eq = &s->eq;
    const qd_speeds_eom *e = r->e;
    qd_buf_printf(b, "%zu equilibri%s (%s%s) with every speed 0: ", eq->count,
                  eq->count == 1 ? "um" : "a", eq->method,
                  eq->exact ? ": the complete set, angles in (-pi, pi]" : "");
    put_names(b, e->m, e->u, NULL);
    qd_buf_puts(b, "\n");
    /* a family within the solved coordinates is sampled: a few samples say it */
    size_t shown = eq->continuum && eq->count > 10 ? 10 : eq->count;
    for (size_t i = 0; i < shown; i++) {
        const qd_equilibrium *p = &eq->pts[i];
        qd_buf_printf(b, "%3zu  ", i + 1);
        for (size_t j = 0; j < s->nsolved; j++) {
            qd_buf_printf(b, "%s%s = ", j ? ", " : "", qd_expr_name(e->q[s->solved[j]]));
            if (p->exact) {
                qd_print(r->ctx, p->exact[j], QD_FMT_TEXT, b);
                if (!qd_is_number(p->exact[j])) {
                    qd_buf_puts(b, " (");
                    cli_state_put_result(b, p->q[j]);
                    qd_buf_puts(b, ")");
                }
            } else {
                cli_state_put_result(b, p->q[j]);
            }
        }
        if (!s->nsolved)
            qd_buf_puts(b, "any configuration");
        qd_buf_puts(b, p->residual < 1e-14 ? ", residual < 1e-14\n" : "");
        if (p->residual >= 1e-14)
            qd_buf_printf(b, ", residual %.3g\n", p->residual);
    }
    if (shown < eq->count)
        qd_buf_printf(b, "  ... and %zu more samples (--format json lists them all)\n",
                      eq->count - shown);
    if (eq->continuum && s->nsolved)
        qd_buf_puts(b, "note: these equilibria are not isolated (a family along a null "
                       "direction of the equations at rest); the points listed are samples "
                       "of it\n");
    if (s->nsolved < e->n) {
        qd_buf_puts(b, "free (any value: no equation at rest involves them): ");
        put_names(b, e->n, e->q, s->free_coord);
        qd_buf_puts(b, "\n");
    }
    qd_buf_printf(b, "note: at rest u = 0 and f_u(q, 0) = 0: %zu equation%s not identically 0 "
                     "in %zu coordinate%s\n", s->nrows, s->nrows == 1 ? "" : "s", e->n,
                  e->n == 1 ? "" : "s");
}

static void eq_json(const sp_run *r, const qd_speeds_equilibria *s, qd_buf *b) {
    const qd_equilibria *eq = &s->eq;
    const qd_speeds_eom *e = r->e;
    qd_json j;
    qd_json_init(&j, b);
    qd_json_begin_object(&j);
    qd_json_key(&j, "method");
    qd_json_string(&j, eq->method);
    qd_json_key(&j, "exact");
    qd_json_bool(&j, eq->exact);
    qd_json_key(&j, "continuum");
    qd_json_bool(&j, eq->continuum);
    qd_json_key(&j, "speeds");
    qd_json_begin_array(&j);
    for (size_t k = 0; k < e->m; k++)
        qd_json_string(&j, qd_expr_name(e->u[k]));
    qd_json_end_array(&j);
    qd_json_key(&j, "free");
    qd_json_begin_array(&j);
    for (size_t k = 0; k < e->n; k++)
        if (s->free_coord[k])
            qd_json_string(&j, qd_expr_name(e->q[k]));
    qd_json_end_array(&j);
    qd_json_key(&j, "equilibria");
    qd_json_begin_array(&j);
    for (size_t i = 0; i < eq->count; i++) {
        const qd_equilibrium *p = &eq->pts[i];
        qd_json_begin_object(&j);
        qd_json_key(&j, "equilibrium");
        qd_json_begin_object(&j);
        for (size_t k = 0; k < s->nsolved; k++) {
            qd_json_key(&j, qd_expr_name(e->q[s->solved[k]]));
            qd_json_number(&j, p->q[k]);
        }
        qd_json_end_object(&j);
        if (p->exact) {
            qd_json_key(&j, "exact");
            qd_json_begin_object(&j);
            for (size_t k = 0; k < s->nsolved; k++) {
                qd_json_key(&j, qd_expr_name(e->q[s->solved[k]]));
                qd_json_expr(&j, r->ctx, p->exact[k]);
            }
            qd_json_end_object(&j);
        }
        qd_json_key(&j, "residual");
        qd_json_number(&j, p->residual);
        qd_json_end_object(&j);
    }
    qd_json_end_array(&j);
    qd_json_end_object(&j);
    qd_buf_puts(b, "\n");
    b->failed = b->failed || !qd_json_ok(&j);
}

int cli_speeds_equilibria(qd_ctx *ctx, cli_model_file *mf, bool json, const char *refuse) {
    sp_run r = {.ctx = ctx, .mf = mf};
    qd_speeds_equilibria s = {0};
    int rc = sp_load(&r, refuse);
    if (rc == QD_EXIT_OK &&
        qd_speeds_equilibria_find(ctx, r.e, r.mf->model, r.st.n, r.st.syms, r.st.vals, NULL, &s) !=
            QD_OK)
        rc = cli_diag_ctx(ctx);
    if (rc == QD_EXIT_OK) {
        qd_buf b = QD_BUF_INIT;
        (json ? eq_json : eq_text)(&r, &s, &b);
        rc = cli_emit(&b, "equilibria");
    }
    qd_speeds_equilibria_free(&s);
    sp_free(&r);
    return rc;
}

/* ---- modes ---------------------------------------------------------------------- */

/* "theta=pi/2, u3=6": coordinates and speeds (others keep their values). */
static int parse_about(sp_run *r, const char *text) {
    qd_state_read_opts o = {.refuse = QD_STATE_VELOCITIES | QD_STATE_TIME | QD_STATE_PARAMS};
    return cli_state_read(r->ctx, r->mf->model, "--about", text, &r->st, &o);
}

/* No --about: the first equilibrium listed, free coordinates and speeds 0. */
static int at_equilibrium(sp_run *r) {
    qd_speeds_equilibria s;
    if (qd_speeds_equilibria_find(r->ctx, r->e, r->mf->model, r->st.n, r->st.syms, r->st.vals, NULL,
                                  &s) != QD_OK)
        return cli_diag_ctx(r->ctx);
    int rc = QD_EXIT_OK;
    if (s.eq.count == 0) {
        cli_diag_error("no equilibrium found (qdot equilibria lists none): give a state with "
                       "--about");
        rc = QD_EXIT_FAIL;
    }
    for (size_t j = 0; rc == QD_EXIT_OK && j < s.nsolved; j++) {
        double *v = value_of(r, r->e->q[s.solved[j]]);
        if (v)
            *v = s.eq.pts[0].q[j];
    }
    qd_speeds_equilibria_free(&s);
    return rc;
}

static const char *verdict_text(int stable) {
    return stable == 1 ? "stable (every Re s <= 0; the zero roots semisimple: neighbouring "
                         "steady motions)"
         : stable == 0 ? "unstable"
                       : "borderline (zero or imaginary roots that repeat without as many "
                         "eigenvectors: the linear motion may drift)";
}

static void modes_text(const sp_run *r, const qd_speeds_linear *lin, const qd_modes_result *res,
                       qd_buf *b) {
    const qd_speeds_eom *e = r->e;
    qd_buf_puts(b, "state: ");
    for (size_t k = 0; k < e->n + e->m; k++) {
        const qd_expr *x = k < e->n ? e->q[k] : e->u[k - e->n];
        const double *v = value_of(r, x);
        qd_buf_printf(b, "%s%s = ", k ? ", " : "", qd_expr_name(x));
        cli_state_put_result(b, v ? *v : NAN);
    }
    qd_buf_puts(b, "\nreduced system: (");
    for (size_t i = 0; i < lin->nkept; i++)
        qd_buf_printf(b, "%s, ", qd_expr_name(e->q[lin->kept[i]]));
    put_names(b, e->m, e->u, NULL);
    qd_buf_puts(b, ")");
    if (lin->nkept < e->n) {
        qd_buf_puts(b, "; ignorable, dropped: ");
        put_names(b, e->n, e->q, lin->ignorable);
    }
    double rate = 0;
    for (size_t i = 0; i < lin->dim; i++)
        rate = fmax(rate, fabs(lin->rate[i]));
    qd_buf_puts(b, "\n");
    if (rate > 1e-8)
        qd_buf_printf(b, "note: not a stationary point of the reduced system: |y'| = %.3g "
                         "there; the linearization drops it\n", rate);
    qd_buf_printf(b, "eigenvalues s of its Jacobian (%zu):\n", res->neig);
    double big = 0;
    for (size_t i = 0; i < res->neig; i++)
        big = fmax(big, hypot(res->eig_re[i], res->eig_im[i]));
    for (size_t i = 0; i < res->neig; i++) {
        /* round-off about 0 is not printed: the verdict already judged it */
        double re = res->eig_re[i], im = res->eig_im[i];
        re = fabs(re) <= 1e-12 * big ? 0 : re;
        im = fabs(im) <= 1e-12 * big ? 0 : im;
        qd_buf_printf(b, "  s = %.10g %s %.10gi", re, im < 0 ? "-" : "+", fabs(im));
        if (im > 0)
            qd_buf_printf(b, "  (frequency %.10g rad/s)", im);
        qd_buf_puts(b, "\n");
    }
    qd_buf_printf(b, "%s\n", verdict_text(res->stable));
}

static void modes_json(const sp_run *r, const qd_speeds_linear *lin, const qd_modes_result *res,
                       qd_buf *b) {
    const qd_speeds_eom *e = r->e;
    qd_json j;
    qd_json_init(&j, b);
    qd_json_begin_object(&j);
    qd_json_key(&j, "state");
    qd_json_begin_object(&j);
    for (size_t k = 0; k < e->n + e->m; k++) {
        const qd_expr *x = k < e->n ? e->q[k] : e->u[k - e->n];
        const double *v = value_of(r, x);
        qd_json_key(&j, qd_expr_name(x));
        qd_json_number(&j, v ? *v : NAN);
    }
    qd_json_end_object(&j);
    qd_json_key(&j, "kept");
    qd_json_begin_array(&j);
    for (size_t i = 0; i < lin->nkept; i++)
        qd_json_string(&j, qd_expr_name(e->q[lin->kept[i]]));
    qd_json_end_array(&j);
    qd_json_key(&j, "ignorable");
    qd_json_begin_array(&j);
    for (size_t i = 0; i < e->n; i++)
        if (lin->ignorable[i])
            qd_json_string(&j, qd_expr_name(e->q[i]));
    qd_json_end_array(&j);
    qd_json_key(&j, "eigenvalues");
    qd_json_begin_array(&j);
    for (size_t i = 0; i < res->neig; i++) {
        qd_json_begin_array(&j);
        qd_json_number(&j, res->eig_re[i]);
        qd_json_number(&j, res->eig_im[i]);
        qd_json_end_array(&j);
    }
    qd_json_end_array(&j);
    qd_json_key(&j, "verdict");
    qd_json_string(&j, res->stable == 1 ? "stable" : res->stable == 0 ? "unstable"
                                                                         : "borderline");
    qd_json_key(&j, "stable");
    if (res->stable < 0)
        qd_json_null(&j);
    else
        qd_json_bool(&j, res->stable == 1);
    qd_json_end_object(&j);
    qd_buf_puts(b, "\n");
    b->failed = b->failed || !qd_json_ok(&j);
}

/* --scan NAME=A:B: the verdict at the state as NAME (a parameter, speed or
 * coordinate) goes from A to B. */
static int scan(sp_run *r, const char *range, const char *about, size_t steps, bool json) {
    char name[128];
    double a, b;
    int rc = cli_scan_range(r->ctx, range, name, sizeof name, &a, &b);
    const qd_expr *what = NULL;
    for (size_t k = 0; rc == QD_EXIT_OK && k < r->st.n; k++)
        if (r->st.syms[k] && !strcmp(qd_expr_name(r->st.syms[k]), name) &&
            qd_symbol_role(r->st.syms[k]) != QD_ROLE_TIME)
            what = r->st.syms[k];
    if (rc == QD_EXIT_OK && !what) {
        cli_diag_error("--scan: %s is not a parameter, coordinate or speed of the model", name);
        return QD_EXIT_USAGE;
    }
    qd_scan_opts o = {.steps = steps};
    qd_scan sc = {0};
    if (rc == QD_EXIT_OK && qd_speeds_modes_scan(r->ctx, r->e, r->st.n, r->st.syms, r->st.vals, what,
                                                 a, b, &o, &sc) != QD_OK) {
        rc = qd_ctx_status(r->ctx) == QD_ERR_ARG ? QD_EXIT_USAGE : QD_EXIT_FAIL;
        cli_diag_error("--scan: %s", qd_ctx_message(r->ctx));
    } else if (rc == QD_EXIT_OK) {
        char followed[1024];
        snprintf(followed, sizeof followed, "the state %s",
                 about ? about : "of the first equilibrium (every speed 0)");
        cli_scan_view v = {name, NULL, followed, "state"};
        rc = cli_scan_emit(&v, &sc, json);
    }
    qd_scan_free(&sc);
    return rc;
}

int cli_speeds_modes(qd_ctx *ctx, cli_model_file *mf, const char *about, const char *range,
                     size_t steps, bool json, const char *refuse) {
    sp_run r = {.ctx = ctx, .mf = mf};
    qd_speeds_linear lin = {0};
    qd_modes_result res = {0};
    int rc = sp_load(&r, refuse);
    if (rc == QD_EXIT_OK)
        rc = about ? parse_about(&r, about) : at_equilibrium(&r);
    if (rc == QD_EXIT_OK && range) {
        rc = scan(&r, range, about, steps, json);
        sp_free(&r);
        return rc;
    }
    if (rc == QD_EXIT_OK &&
        (qd_speeds_linear_about(ctx, r.e, r.st.n, r.st.syms, r.st.vals, &lin) != QD_OK ||
         qd_speeds_modes_solve(ctx, &lin, &res) != QD_OK))
        rc = cli_diag_ctx(ctx);
    if (rc == QD_EXIT_OK) {
        qd_buf b = QD_BUF_INIT;
        (json ? modes_json : modes_text)(&r, &lin, &res, &b);
        rc = cli_emit(&b, "modes");
    }
    qd_modes_result_free(&res);
    qd_speeds_linear_free(&lin);
    sp_free(&r);
    return rc;
}

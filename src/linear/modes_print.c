/*
 * src/linear/modes_print.c - the small oscillations about one point as text
 * or JSON (qd_modes_print, qdot/modes.h): the point, M0, C0, G0, K0, the
 * modes (or the state-space eigenvalues, or the symmetry's labelled modes),
 * the motion from initial values and the verdict.  What `qdot modes`
 * prints, for any caller.
 */
#include "qdot/modes.h"
#include "qdot/json.h"
#include "qdot/symmetry.h"
#include "../base/args.h"
#include "../base/mem.h"
#include "linear.h"

#include <math.h>

static const double PI = 3.14159265358979323846;

/* The largest |A[i][col]| of the n*n matrix A: the scale of a column that
 * is one vector (a mode shape, a symmetry coordinate), whose entries are
 * small together when M0 is large. */
static double column_scale(const double *A, size_t n, size_t col) {
    double s = 0;
    for (size_t i = 0; i < n; i++)
        s = fmax(s, fabs(A[i * n + col]));
    return s;
}

/* ---- text ------------------------------------------------------------------ */

bool qd_modes_rest_note(double residual, qd_buf *out) {
    if (!(residual > QD_MODES_REST_TOL))
        return false;
    if (out)
        qd_buf_printf(out, "not an equilibrium: the generalized forces at rest are %.3g there; "
                           "the linearization drops them", residual);
    return true;
}

static void put_matrix(qd_buf *b, const char *name, size_t n, const double *A) {
    qd_buf_printf(b, "%s = [", name);
    for (size_t i = 0; i < n; i++) {
        qd_buf_puts(b, i ? ", [" : "[");
        for (size_t j = 0; j < n; j++) {
            qd_buf_puts(b, j ? ", " : "");
            qd_buf_put_result(b, A[i * n + j], 1);
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

static void put_point(qd_ctx *ctx, const qd_modes_report *r, qd_buf *b) {
    const qd_eom *e = r->e;
    qd_buf_puts(b, r->pt ? "equilibrium: " : "about: ");
    for (size_t j = 0; j < e->n; j++) {
        qd_buf_printf(b, "%s%s = ", j ? ", " : "", qd_expr_name(e->q[j]));
        if (r->pt)
            qd_equilibrium_put_value(ctx, r->pt, j, b);
        else
            qd_buf_put_result(b, r->q0[j], 1);
    }
    if (r->pt)
        qd_buf_printf(b, " (%s of the potential)", qd_eq_kind_name(r->pt->kind));
    qd_buf_printf(b, "\n");
    if (qd_modes_rest_note(r->residual, NULL)) {
        qd_buf_puts(b, "note: ");
        qd_modes_rest_note(r->residual, b);
        qd_buf_puts(b, "\n");
    }
}

static void put_conservative(qd_ctx *ctx, const qd_modes_report *r, qd_buf *b) {
    const qd_eom *e = r->e;
    const qd_modes_result *res = r->res;
    size_t n = res->n;
    qd_buf_puts(b, "conservative, no gyroscopic terms: K0 a = w^2 M0 a, a^T M0 a = 1\n");
    for (size_t j = 0; j < n; j++) {
        double w2 = res->omega2[j], w = sqrt(fabs(w2));
        qd_buf_printf(b, "mode %zu: w^2 = ", j + 1);
        qd_buf_put_result(b, w2, 1);
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
        double scale = column_scale(res->shapes, n, j);
        for (size_t i = 0; i < n; i++) {
            qd_buf_printf(b, "%s%s = ", i ? ", " : "", qd_expr_name(e->q[i]));
            qd_buf_put_result(b, res->shapes[i * n + j], scale);
        }
        qd_buf_puts(b, "\n");
    }
    for (size_t j = 0; r->w2exact && j < n; j++) {
        qd_buf_printf(b, r->w2exact_in_params ? "w^2 (exact, mode %zu) = "
                                              : "w^2 (exact at these parameter values, mode "
                                                "%zu) = ", j + 1);
        qd_print(ctx, r->w2exact[j], QD_FMT_TEXT, b);
        qd_buf_puts(b, "\n");
    }
    qd_buf_puts(b, "normal coordinates: Q_j = a_j^T M0 (q - q0), Q_j'' + w_j^2 Q_j = 0\n");
}

static void put_solution(const qd_modes_report *r, qd_buf *b) {
    size_t n = r->e->n;
    qd_buf_puts(b, "motion from the initial values: q(t) = q0 + sum_j a_j Q_j(t)\n");
    for (size_t j = 0; j < n; j++) {
        double w2 = r->res->omega2[j], w = sqrt(fabs(w2));
        qd_buf_printf(b, "  Q_%zu(t) = ", j + 1);
        if (w2 > 0)
            qd_buf_printf(b, "%.10g*cos(%.10g*t) + %.10g*sin(%.10g*t)\n", r->Q[j], w,
                          r->Qd[j] / w, w);
        else if (w2 == 0)
            qd_buf_printf(b, "%.10g + %.10g*t\n", r->Q[j], r->Qd[j]);
        else
            qd_buf_printf(b, "%.10g*cosh(%.10g*t) + %.10g*sinh(%.10g*t)\n", r->Q[j], w,
                          r->Qd[j] / w, w);
    }
}

static void put_state_space(const qd_modes_result *res, qd_buf *b) {
    qd_buf_puts(b, "damped or gyroscopic: state-space eigenvalues s of "
                   "det(s^2 M0 + s (C0 + G0) + K0) = 0\n");
    for (size_t i = 0; i < res->neig; i++) {
        /* round-off against the largest root (or off the imaginary axis
         * against its own size): the verdict already knows */
        double re = qd__lin_root_shown(res, res->eig_re[i]);
        double im = qd__lin_root_shown(res, res->eig_im[i]), mod = hypot(re, im);
        if (fabs(re) <= 1e-12 * mod)
            re = 0;
        qd_buf_printf(b, "  s = %.10g %s %.10gi", re, im < 0 ? "-" : "+", fabs(im));
        if (mod > 0 && im > 0)
            qd_buf_printf(b, "  (frequency %.10g rad/s, damping ratio %.6g)", im,
                          re == 0 ? 0 : -re / mod);
        qd_buf_puts(b, "\n");
    }
}

static const char *verdict(int s) {
    return s == 1 ? "stable" : s == 0 ? "unstable" : "borderline";
}

static void put_text(qd_ctx *ctx, const qd_modes_report *r, qd_buf *b) {
    const qd_linear *lin = r->lin;
    const qd_modes_result *res = r->res;
    size_t n = lin->n;
    put_point(ctx, r, b);
    put_matrix(b, "M0", n, lin->M);
    if (!all_zero(n * n, lin->C))
        put_matrix(b, "C0", n, lin->C);
    if (!all_zero(n * n, lin->G))
        put_matrix(b, "G0", n, lin->G);
    put_matrix(b, "K0", n, lin->K);
    if (r->cyc)
        qd_cyclic_print(r->cyc, b);
    else if (r->sym)
        qd_symmetry_print(r->sym, r->e, b);
    else if (res->conservative)
        put_conservative(ctx, r, b);
    else
        put_state_space(res, b);
    if (r->Q)
        put_solution(r, b);
    qd_buf_printf(b, "%s", verdict(res->stable));
    if (res->stable == -1)
        qd_buf_puts(b, res->conservative ? " (zero-frequency modes: the linear test is not "
                                           "decisive)" : " (roots on the imaginary axis that "
                                                         "are zero or repeated)");
    if (r->pt && r->pt->kind == QD_EQ_MAXIMUM && res->stable == 1)
        qd_buf_puts(b, " (a maximum of the potential, stabilized by the gyroscopic terms)");
    qd_buf_puts(b, "\n");
}

/* ---- json ------------------------------------------------------------------ */

/* The frequencies: w of every mode (conservative; unstable ones left out),
 * or the positive imaginary parts of the state-space eigenvalues. */
static void json_frequencies(const qd_modes_result *res, qd_json *j) {
    qd_json_key(j, "frequencies");
    qd_json_begin_array(j);
    double *w = qd__mem_malloc(NULL, (res->neig + 1) * sizeof *w);
    size_t nw = w ? qd_modes_frequencies(res, w) : 0;
    if (!w)
        j->out->failed = true;
    for (size_t k = 0; k < nw; k++)
        qd_json_number(j, w[k]);
    qd__free(w);
    qd_json_end_array(j);
}

/* The conservative modes: w^2, w, period, multiplicity, shape, and the
 * exact w^2 and the initial normal coordinates when there are any. */
static void json_modes(qd_ctx *ctx, const qd_modes_report *r, qd_json *j) {
    const qd_eom *e = r->e;
    const qd_modes_result *res = r->res;
    size_t n = e->n;
    qd_json_key(j, "modes");
    qd_json_begin_array(j);
    for (size_t k = 0; res->conservative && k < n; k++) {
        qd_json_begin_object(j);
        qd_json_frequency(j, res->omega2[k]);
        qd_json_key(j, "multiplicity");
        qd_json_number(j, (double)qd_modes_multiplicity(res, k));
        qd_json_key(j, "shape");
        qd_json_begin_object(j);
        for (size_t i = 0; i < n; i++) {
            qd_json_key(j, qd_expr_name(e->q[i]));
            qd_json_number(j, res->shapes[i * n + k]);
        }
        qd_json_end_object(j);
        if (r->w2exact) {
            qd_json_key(j, "omega2_exact");
            qd_json_expr(j, ctx, r->w2exact[k]);
            qd_json_key(j, "omega2_exact_in_parameters");
            qd_json_bool(j, r->w2exact_in_params);
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

static void json_head(const qd_modes_report *r, qd_json *j) {
    const qd_eom *e = r->e;
    qd_json_key(j, "equilibrium");
    qd_json_begin_object(j);
    for (size_t k = 0; k < e->n; k++) {
        qd_json_key(j, qd_expr_name(e->q[k]));
        qd_json_number(j, r->q0[k]);
    }
    qd_json_end_object(j);
    qd_json_key(j, "residual");
    qd_json_number(j, r->residual);
    if (r->choice) {
        qd_json_key(j, "choice");
        qd_json_begin_object(j);
        qd_json_key(j, "code");
        qd_json_string(j, qd_eq_chosen_code(r->choice->reason));
        qd_json_key(j, "reason");
        qd_json_string(j, qd_eq_chosen_name(r->choice->reason));
        qd_json_key(j, "others");
        qd_json_number(j, (double)r->choice->others);
        qd_json_end_object(j);
    }
}

static bool put_json(qd_ctx *ctx, const qd_modes_report *r, qd_buf *b) {
    const qd_linear *lin = r->lin;
    const qd_modes_result *res = r->res;
    size_t n = lin->n;
    qd_json j;
    qd_json_init(&j, b);
    qd_json_begin_object(&j);
    json_head(r, &j);
    qd_json_key(&j, "conservative");
    qd_json_bool(&j, res->conservative);
    qd_json_matrix(&j, "mass_matrix", n, n, lin->M);
    qd_json_matrix(&j, "damping_matrix", n, n, lin->C);
    qd_json_matrix(&j, "gyroscopic_matrix", n, n, lin->G);
    qd_json_matrix(&j, "stiffness_matrix", n, n, lin->K);
    if (r->cyc)
        qd_cyclic_json(&j, r->cyc);
    else if (r->sym)
        qd_symmetry_json(&j, r->sym, r->e);
    json_frequencies(res, &j);
    if (r->cyc)
        qd_cyclic_json_modes(&j, r->cyc);
    else if (r->sym)
        qd_symmetry_json_modes(&j, r->sym, r->e);
    else
        json_modes(ctx, r, &j);
    qd_json_key(&j, "eigenvalues");
    qd_json_begin_array(&j);
    for (size_t k = 0; k < res->neig; k++) {
        qd_json_begin_array(&j);
        qd_json_number(&j, qd__lin_root_shown(res, res->eig_re[k]));
        qd_json_number(&j, qd__lin_root_shown(res, res->eig_im[k]));
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
    return qd_json_ok(&j) || b->failed; /* out of memory is said as such */
}

/* The fields every printer reads, and that they agree on n. */
static bool report_ok(const qd_modes_report *r) {
    if (!r->e || !r->q0 || !r->lin || !r->res)
        return false;
    size_t n = r->e->n;
    const qd_linear *lin = r->lin;
    const qd_modes_result *res = r->res;
    if (lin->n != n || res->n != n || !lin->M || !lin->C || !lin->G || !lin->K ||
        (res->neig && (!res->eig_re || !res->eig_im)))
        return false;
    if (res->conservative && n && (!res->omega2 || !res->shapes))
        return false;
    if ((r->Q && (!r->Qd || !res->conservative)) || (r->sym && r->sym->n != n) ||
        (r->cyc && r->cyc->n != n))
        return false;
    return !r->pt || r->pt->q;
}

qd_status qd_modes_print(qd_ctx *ctx, const qd_modes_report *r, bool json, qd_buf *out) {
    QD_ARGS_CTX(ctx, ctx && r && out);
    if (!report_ok(r)) {
        qd_ctx_error(ctx, QD_ERR_ARG, "qd_modes_print: the report is incomplete or its sizes "
                                      "disagree");
        return QD_ERR_ARG;
    }
    qd_buf b = QD_BUF_WITH(out->alloc);
    bool ok = true;
    if (json)
        ok = put_json(ctx, r, &b);
    else
        put_text(ctx, r, &b);
    bool nomem = b.failed;
    if (ok && !nomem)
        qd_buf_putn(out, qd_buf_str(&b), b.len);
    qd_buf_free(&b);
    if (nomem || out->failed) {
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory");
        return QD_ERR_NOMEM;
    }
    if (!ok) {
        qd_ctx_error(ctx, QD_ERR_NUMERIC, "a number of the modes is not finite");
        return QD_ERR_NUMERIC;
    }
    return QD_OK;
}

/*
 * src/linear/stability_print.c - steady motions and their stability as
 * text or JSON (qd_stability_print, qdot/stability.h): what `qdot
 * stability` prints, for any caller.
 */
#include "qdot/stability.h"
#include "qdot/json.h"
#include "../base/args.h"
#include "linear.h"

#include <math.h>
#include <stdio.h>

/* A computed result: the digit rule of qd_result_format (qdot/print.h). */
static void put_num(qd_buf *b, double x) { qd_buf_put_result(b, x, 1); }

static void put_matrix(qd_buf *b, const char *name, const double *A, size_t n) {
    qd_buf_printf(b, "  %s = [", name);
    for (size_t i = 0; i < n; i++) {
        qd_buf_puts(b, i ? "; " : "");
        for (size_t j = 0; j < n; j++) {
            qd_buf_puts(b, j ? ", " : "");
            put_num(b, A[i * n + j]);
        }
    }
    qd_buf_puts(b, "]\n");
}

static const char *tri(int v, const char *yes, const char *no, const char *border) {
    return v == 1 ? yes : v == 0 ? no : border;
}

static double max_re(const qd_modes_result *m) {
    double x = -INFINITY;
    for (size_t i = 0; i < m->neig; i++)
        x = fmax(x, m->eig_re[i]);
    return x;
}

/* Rounding noise (1e-16 against roots of order 1) printed as 0: the real
 * parts of undamped gyroscopic roots are 0 exactly. */
static double shown(const qd_modes_result *m, double x) { return qd__lin_root_shown(m, x); }

static void put_roots(qd_buf *b, const qd_modes_result *m) {
    for (size_t i = 0; i < m->neig; i++) {
        double im = shown(m, m->eig_im[i]);
        qd_buf_puts(b, i ? ", " : "");
        put_num(b, shown(m, m->eig_re[i]));
        qd_buf_puts(b, im < 0 ? " - " : " + ");
        put_num(b, fabs(im));
        qd_buf_puts(b, "i");
    }
}

/* How many motions, said once before them when there is more than one (or
 * some were left out). */
static void text_count(const qd_stability_report *r, qd_buf *b) {
    size_t n = r->set->count;
    if (n > 1)
        qd_buf_printf(b, "%zu steady motions for these values%s; the first is the one nearest "
                         "the starting values\n", n, r->set->complete ? "" : " (found from the "
                         "starting values: there may be others)");
    if (r->set->nsingular)
        qd_buf_printf(b, "(%zu more at singular points of the coordinates, left out)\n",
                      r->set->nsingular);
}

static void text_motion(qd_ctx *ctx, const qd_stability_report *r, qd_buf *b, size_t k) {
    const qd_steady *s = r->s;
    const qd_stability *an = &r->an[k];
    const qd_steady_point *pt = &r->set->pts[k];
    if (r->set->count > 1)
        qd_buf_printf(b, "steady motion %zu of %zu (%s):\n", k + 1, r->set->count,
                      s->driven ? "rates maintained: V_eff = V - T0"
                                : "momenta free: V_eff = V + K, Routhian");
    else
        qd_buf_printf(b, "steady motion (%s):\n", s->driven ? "rates maintained: V_eff = V - T0"
                                                            : "momenta free: V_eff = V + K, "
                                                              "Routhian");
    for (size_t j = 0; j < s->nkeep; j++) {
        qd_buf_printf(b, "  %s = ", qd_expr_name(s->keep[j]));
        put_num(b, pt->x[j]);
        qd_buf_puts(b, r->given->xfix[j] ? "  (given)\n" : "\n");
    }
    for (size_t c = 0; c < s->ncyc; c++) {
        qd_buf_printf(b, "  %s = ", qd_expr_name(s->cycd[c]));
        put_num(b, pt->w[c]);
        qd_buf_printf(b, "%s, p_%s = ", r->given->wfix[c] ? " (given)" : "", qd_expr_name(s->cyc[c]));
        put_num(b, pt->p[c]);
        qd_buf_puts(b, r->given->pfix[c] ? " (given)\n" : "\n");
    }
    qd_buf_puts(b, "effective potential: V_eff = ");
    qd_print(ctx, s->Veff, QD_FMT_TEXT, b);
    qd_buf_puts(b, "\nlinearized about it: M0 x'' + (C0 + G0) x' + K0 x = 0\n");
    put_matrix(b, "M0", an->lin.M, an->n);
    if (an->dissipative)
        put_matrix(b, "C0", an->lin.C, an->n);
    put_matrix(b, "G0", an->lin.G, an->n);
    put_matrix(b, "K0", an->lin.K, an->n);
    put_matrix(b, "Hessian of V_eff", an->hessian, an->n);
    qd_buf_puts(b, "frequencies:");
    for (size_t i = 0; i < an->nfreq; i++) {
        qd_buf_puts(b, " ");
        put_num(b, an->freq[i]);
    }
    qd_buf_puts(b, an->nfreq ? "\n" : " none\n");
    qd_buf_puts(b, "roots s (no dissipation): ");
    put_roots(b, &an->ordinary);
    qd_buf_printf(b, "\nordinary stability: %s\n",
                  tri(an->ordinary_stable, "stable", "unstable", "borderline"));
    qd_buf_printf(b, "secular stability: %s\n",
                  tri(an->secular_stable, "stable (V_eff is a minimum)",
                      "unstable (V_eff is not a minimum)",
                      "borderline (the Hessian of V_eff is singular)"));
    if (an->dissipative) {
        qd_buf_puts(b, "with the model's dissipation: roots ");
        put_roots(b, &an->damped);
        qd_buf_printf(b, "\n  %s (max Re s = ", tri(an->damped_stable, "stable", "unstable",
                                                    "borderline"));
        put_num(b, max_re(&an->damped));
        qd_buf_puts(b, ")\n");
    }
    qd_buf_printf(b, "verdict: %s\n", an->verdict);
}

static void text_out(qd_ctx *ctx, const qd_stability_report *r, qd_buf *b) {
    qd_buf_printf(b, "model: %s\n", r->model);
    text_count(r, b);
    for (size_t k = 0; k < r->set->count; k++) {
        qd_buf_puts(b, k ? "\n" : "");
        text_motion(ctx, r, b, k);
    }
}

static void json_tri(qd_json *j, int v) {
    if (v < 0)
        qd_json_null(j);
    else
        qd_json_bool(j, v == 1);
}

static void json_roots(qd_json *j, const char *key, const qd_modes_result *m) {
    qd_json_key(j, key);
    qd_json_begin_array(j);
    for (size_t i = 0; i < m->neig; i++) {
        qd_json_begin_array(j);
        qd_json_number(j, shown(m, m->eig_re[i]));
        qd_json_number(j, shown(m, m->eig_im[i]));
        qd_json_end_array(j);
    }
    qd_json_end_array(j);
}

static void json_steady(qd_json *j, const qd_steady *s, const qd_steady_point *pt) {
    qd_json_key(j, "steady");
    qd_json_begin_object(j);
    for (size_t k = 0; k < s->nkeep; k++) {
        qd_json_key(j, qd_expr_name(s->keep[k]));
        qd_json_number(j, pt->x[k]);
    }
    for (size_t c = 0; c < s->ncyc; c++) {
        qd_json_key(j, qd_expr_name(s->cycd[c]));
        qd_json_number(j, pt->w[c]);
        char name[160];
        snprintf(name, sizeof name, "p_%s", qd_expr_name(s->cyc[c]));
        qd_json_key(j, name);
        qd_json_number(j, pt->p[c]);
    }
    qd_json_end_object(j);
}

/* Every motion in short: where it is, its frequencies and verdicts. */
static void json_all(qd_json *j, const qd_stability_report *r) {
    qd_json_key(j, "steady_motions");
    qd_json_begin_array(j);
    for (size_t k = 0; k < r->set->count; k++) {
        const qd_stability *an = &r->an[k];
        qd_json_begin_object(j);
        json_steady(j, r->s, &r->set->pts[k]);
        qd_json_key(j, "residual");
        qd_json_number(j, r->set->residual[k]);
        qd_json_key(j, "frequencies");
        qd_json_begin_array(j);
        for (size_t i = 0; i < an->nfreq; i++)
            qd_json_number(j, an->freq[i]);
        qd_json_end_array(j);
        json_roots(j, "eigenvalues", &an->ordinary);
        qd_json_key(j, "stable");
        json_tri(j, an->ordinary_stable);
        qd_json_key(j, "secular");
        json_tri(j, an->secular_stable);
        qd_json_key(j, "verdict");
        qd_json_string(j, an->verdict);
        qd_json_end_object(j);
    }
    qd_json_end_array(j);
    qd_json_key(j, "complete");
    qd_json_bool(j, r->set->complete);
}

static bool json_out(qd_ctx *ctx, const qd_stability_report *r, qd_buf *b) {
    const qd_steady *s = r->s;
    const qd_stability *an = &r->an[0];
    qd_json j;
    qd_json_init(&j, b);
    qd_json_begin_object(&j);
    qd_json_key(&j, "model");
    qd_json_string(&j, r->model);
    qd_json_key(&j, "kind");
    qd_json_string(&j, s->driven ? "driven" : "free");
    json_steady(&j, s, &r->set->pts[0]);
    qd_json_key(&j, "residual");
    qd_json_number(&j, r->set->residual[0]);
    qd_json_key(&j, "Veff");
    qd_json_expr(&j, ctx, s->Veff);
    qd_json_matrix(&j, "mass_matrix", an->n, an->n, an->lin.M);
    qd_json_matrix(&j, "damping_matrix", an->n, an->n, an->lin.C);
    qd_json_matrix(&j, "gyroscopic_matrix", an->n, an->n, an->lin.G);
    qd_json_matrix(&j, "stiffness_matrix", an->n, an->n, an->lin.K);
    qd_json_matrix(&j, "hessian", an->n, an->n, an->hessian);
    qd_json_key(&j, "frequencies");
    qd_json_begin_array(&j);
    for (size_t i = 0; i < an->nfreq; i++)
        qd_json_number(&j, an->freq[i]);
    qd_json_end_array(&j);
    json_roots(&j, "eigenvalues", &an->ordinary);
    qd_json_key(&j, "stable");
    json_tri(&j, an->ordinary_stable);
    qd_json_key(&j, "secular");
    json_tri(&j, an->secular_stable);
    if (an->dissipative) {
        qd_json_key(&j, "dissipation");
        qd_json_begin_object(&j);
        json_roots(&j, "eigenvalues", &an->damped);
        qd_json_key(&j, "stable");
        json_tri(&j, an->damped_stable);
        qd_json_key(&j, "max_re");
        qd_json_number(&j, max_re(&an->damped));
        qd_json_end_object(&j);
    }
    qd_json_key(&j, "verdict");
    qd_json_string(&j, an->verdict);
    json_all(&j, r);
    qd_json_end_object(&j);
    qd_buf_puts(b, "\n");
    return qd_json_ok(&j);
}

qd_status qd_stability_print(qd_ctx *ctx, const qd_stability_report *r, bool json,
                             qd_buf *out) {
    QD_ARGS_CTX(ctx, ctx && r && r->s && r->given && r->set && r->model && out);
    if (r->set->count == 0 || !r->an) {
        qd_ctx_error(ctx, QD_ERR_ARG, "qd_stability_print: no steady motion to print");
        return QD_ERR_ARG;
    }
    qd_buf b = QD_BUF_WITH(out->alloc);
    bool ok = true;
    if (json)
        ok = json_out(ctx, r, &b);
    else
        text_out(ctx, r, &b);
    bool nomem = b.failed;
    if (ok && !nomem)
        qd_buf_putn(out, qd_buf_str(&b), b.len);
    qd_buf_free(&b);
    if (!ok) {
        qd_ctx_error(ctx, QD_ERR_NUMERIC, "a number of the steady motion is not finite");
        return QD_ERR_NUMERIC;
    }
    if (nomem || out->failed) {
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory");
        return QD_ERR_NOMEM;
    }
    return QD_OK;
}

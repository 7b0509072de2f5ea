/*
 * src/linear/conlin_scan.c - a constrained linearization (qdot/conlin.h)
 * along a parameter: at each sample the model's parameter is set (the
 * `initial` point follows it), the point solved onto the manifold again
 * and A's core eigenvalues taken; where the core's margin (its largest
 * Re s) crosses 0 between two samples (above 1e-10 of the core's largest
 * |s|: round-off puts a conservative core's imaginary pairs at +-1e-16),
 * bisection on that test finds the
 * value: a real eigenvalue through 0 or a complex pair through the
 * imaginary axis (the Whipple bicycle's capsize and weave speeds,
 * Meijaard et al. 2007, sec. 5).
 */
#include "qdot/conlin.h"
#include "qdot/state.h"
#include "base/mem.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define BISECT_TOL 1e-12
#define MAX_STEPS 100000
#define MARGIN_TOL 1e-10

typedef struct sc_run {
    qd_ctx *ctx;
    const qd_eom *e;
    qd_model *m;
    qd_linpoint *pt;
    const char *about, *indep, *name;
    double tol;  /* at the last point: MARGIN_TOL times the core's largest |s| */
} sc_run;

/* Unstable: a core eigenvalue with Re s above the tolerance (round-off puts
 * the imaginary pairs of a conservative core at +-1e-16). */
static bool unstable(const sc_run *r, double margin) { return margin > r->tol; }

/* The linearization at p: margin, the |Im s| of its eigenvalue, all eigenvalues (re, im may
 * be NULL). */
static qd_status at(sc_run *r, double p, double *margin, double *omega, double *re, double *im) {
    qd_status st = qd_model_set_param(r->ctx, r->m, r->name, qd_float(r->ctx, p));
    if (st == QD_OK)
        st = qd_state_layout(r->ctx, r->m, qd_model_ncoords(r->m), NULL, r->pt->st.syms,
                             r->pt->st.vals);
    if (st == QD_OK)
        st = qd_conlin_point(r->ctx, r->m, r->pt, r->about);
    qd_conlin c = {0};
    if (st == QD_OK)
        st = qd_conlin_about(r->ctx, r->e, r->m, r->pt, r->indep, &c);
    if (st == QD_OK) {
        double big = 1;
        for (size_t k = 0; k < c.ncore; k++)
            big = fmax(big, hypot(c.core_re[k], c.core_im[k]));
        r->tol = MARGIN_TOL * big;
        *margin = c.ncore ? c.core_re[0] : -INFINITY;
        *omega = c.ncore ? fabs(c.core_im[0]) : 0;
        for (size_t k = 0; re && k < c.nx; k++) {
            re[k] = c.ss.eig_re[k];
            im[k] = c.ss.eig_im[k];
        }
    }
    qd_conlin_free(&c);
    return st;
}

void qd_conlin_scan_free(qd_conlin_scan *s) {
    if (!s)
        return;
    qd__free(s->p);
    qd__free(s->cross);
    qd__free(s->unstable);
    memset(s, 0, sizeof *s);
}

/* The crossing between lo (unstable when ulo) and hi.  When the stable side
 * is inside (not marginal), on the sign of the margin itself, so the value
 * is not moved by the tolerance; else on the tolerance's test. */
static qd_status bisect(sc_run *r, double lo, bool ulo, double hi, qd_conlin_cross *x) {
    double tol = BISECT_TOL * fabs(hi - lo) * 1e2, mid = lo, mm = 0, om = 0, side = 0, os;
    qd_status st = at(r, ulo ? hi : lo, &side, &os, NULL, NULL);
    x->marginal = st == QD_OK && side >= -r->tol;
    for (int it = 0; it < 200 && hi - lo > fmax(tol, 4e-16 * fabs(lo)) && st == QD_OK; it++) {
        mid = 0.5 * (lo + hi);
        st = at(r, mid, &mm, &om, NULL, NULL);
        if (st != QD_OK)
            break;
        if ((x->marginal ? unstable(r, mm) : mm > 0) == ulo)
            lo = mid;
        else
            hi = mid;
    }
    if (st == QD_OK)
        st = at(r, 0.5 * (lo + hi), &mm, &om, NULL, NULL);
    x->at = 0.5 * (lo + hi);
    x->omega = om;
    x->to_stable = ulo;
    return st;
}

qd_status qd_conlin_scan_run(qd_ctx *ctx, const qd_eom *e, qd_model *m, qd_linpoint *pt,
                             const char *about, const char *independent, const char *name,
                             double a, double b, size_t steps, qd_conlin_scan *out) {
    if (!ctx || !e || !m || !pt || !name || !out)
        return QD_ERR_ARG;
    *out = (qd_conlin_scan){0};
    size_t ip = qd_model_nparams(m);
    for (size_t i = 0; i < qd_model_nparams(m); i++)
        if (!strcmp(qd_expr_name(qd_model_param(m, i)), name))
            ip = i;
    if (ip == qd_model_nparams(m) || !(a < b) || !steps || steps > MAX_STEPS) {
        qd_ctx_error(ctx, QD_ERR_ARG, ip == qd_model_nparams(m)
                     ? "'%s' is no parameter of the model" : "the scan of %s needs A < B and "
                     "1 to 100000 steps", name);
        return QD_ERR_ARG;
    }
    /* a parameter the model assumes positive (its value when read was) cannot be 0 */
    if (qd_symbol_is_positive(qd_model_param(m, ip)) && a < 0) {
        qd_ctx_error(ctx, QD_ERR_ARG, "%s is assumed positive (it was when the model was read): "
                     "scan it from 0 or above, or give a value <= 0 with --set", name);
        return QD_ERR_ARG;
    }
    out->nudged = qd_symbol_is_positive(qd_model_param(m, ip)) && a == 0;
    double keep = 0;
    if (qd_model_param_number(m, ip, &keep) != QD_OK)
        return qd_ctx_status(ctx);
    sc_run r = {ctx, e, m, pt, about, independent, name, 0};
    size_t ns = steps + 1, nx = 2 * e->n;
    out->p = qd__calloc(ctx, ns * (3 + 2 * nx) + 1, sizeof *out->p);
    out->cross = qd__calloc(ctx, ns + 1, sizeof *out->cross);
    out->unstable = qd__calloc(ctx, ns + 1, sizeof *out->unstable);
    if (!out->p || !out->cross || !out->unstable)
        return QD_ERR_NOMEM;
    out->re = out->p + ns;
    out->im = out->re + ns * nx;
    out->margin = out->im + ns * nx;
    out->nsamples = ns;
    qd_status st = QD_OK;
    for (size_t i = 0; i < ns && st == QD_OK; i++) {
        double p = a + (b - a) * (double)i / (double)steps, om;
        out->p[i] = p;
        if (i == 0 && out->nudged)
            out->p[0] = p = a + 1e-6 * (b - a);
        st = at(&r, p, &out->margin[i], &om, out->re + i * nx, out->im + i * nx);
        out->unstable[i] = st == QD_OK && unstable(&r, out->margin[i]);
        if (st != QD_OK) {
            char why[512];
            snprintf(why, sizeof why, "%s", qd_ctx_message(ctx));
            qd_ctx_clear_error(ctx);
            qd_ctx_error(ctx, st, "at %s = %.17g: %s", name, p, why);
        }
    }
    /* the independent states: 2n less the holonomic constraints and all constraints */
    size_t nh = 0;
    for (size_t k = 0; k < e->ncon; k++)
        nh += e->con[k].kind == QD_CON_HOLONOMIC;
    out->nx = 2 * e->n - nh - e->ncon;
    for (size_t i = 0; st == QD_OK && i < ns; i++) /* packed rows of nx */
        for (size_t k = 0; k < out->nx; k++) {
            out->re[i * out->nx + k] = out->re[i * nx + k];
            out->im[i * out->nx + k] = out->im[i * nx + k];
        }
    for (size_t i = 0; i + 1 < ns && st == QD_OK; i++) {
        if (out->unstable[i] != out->unstable[i + 1])
            st = bisect(&r, out->p[i], out->unstable[i], out->p[i + 1],
                        &out->cross[out->ncross++]);
    }
    qd_status back = qd_model_set_param(ctx, m, name, qd_float(ctx, keep));
    if (back == QD_OK)
        back = qd_state_layout(ctx, m, qd_model_ncoords(m), NULL, pt->st.syms, pt->st.vals);
    return st != QD_OK ? st : back;
}

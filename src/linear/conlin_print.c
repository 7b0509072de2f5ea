/*
 * src/linear/conlin_print.c - a constrained linearization and its scan
 * along a parameter, as text and JSON (qdot/conlin.h).
 */
#include "qdot/conlin.h"
#include "qdot/json.h"
#include "qdot/print.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* A state's name: the coordinate, or its velocity with a prime. */
static const char *zname(const qd_conlin *c, size_t k) { return qd_expr_name(c->zsym[k]); }

static void put_eig(qd_buf *b, double re, double im) {
    char r[QD_DOUBLE_MAX], m[QD_DOUBLE_MAX];
    qd_double_format(r, re == 0 ? 0 : re);
    qd_double_format(m, fabs(im));
    if (im == 0)
        qd_buf_puts(b, r);
    else
        qd_buf_printf(b, "%s %c %si", r, im < 0 ? '-' : '+', m);
}

static void names_text(qd_buf *b, const qd_conlin *c, const size_t *idx, size_t count) {
    for (size_t i = 0; i < count; i++)
        qd_buf_printf(b, "%s%s", i ? ", " : "", zname(c, idx[i]));
    if (!count)
        qd_buf_puts(b, "none");
}

static void text(qd_buf *b, const qd_conlin *c) {
    size_t d = c->nhol + c->ncon;
    qd_buf_printf(b, "on the constraint manifold (%zu coordinates, %zu constraint%s, %zu of "
                  "them holonomic): %zu independent states\nindependent: ",
                  c->n, c->ncon, c->ncon == 1 ? "" : "s", c->nhol, c->nx);
    names_text(b, c, c->indep, c->nx);
    qd_buf_puts(b, "\ndependent: ");
    names_text(b, c, c->dep, d);
    qd_buf_puts(b, "\npoint:");
    for (size_t k = 0; k < 2 * c->n; k++) {
        char v[QD_DOUBLE_MAX];
        qd_double_format(v, c->z[k] == 0 ? 0 : c->z[k]);
        qd_buf_printf(b, "%s %s = %s", k ? "," : "", zname(c, k), v);
    }
    size_t nm = 0;
    for (size_t i = 0; i < d; i++) {
        size_t k = c->dep[i];
        double was = c->given[k];
        if (fabs(c->z[k] - was) <= 1e-9 * fmax(1, fabs(was)))
            continue;
        char v[QD_DOUBLE_MAX], g[QD_DOUBLE_MAX];
        qd_double_format(v, c->z[k] == 0 ? 0 : c->z[k]);
        qd_double_format(g, was == 0 ? 0 : was);
        qd_buf_printf(b, "%s %s = %s (was %s)", nm++ ? "," : "\nsolved from the constraints:",
                      zname(c, k), v, g);
    }
    qd_buf_puts(b, "\nignorable (no state's rate depends on them; an eigenvalue 0 each): ");
    size_t ni = 0;
    for (size_t i = 0; i < c->nx; i++)
        if (c->ignorable[i])
            qd_buf_printf(b, "%s%s", ni++ ? ", " : "", zname(c, c->indep[i]));
    if (!ni)
        qd_buf_puts(b, "none");
    qd_buf_puts(b, "\neigenvalues of the core:");
    for (size_t k = 0; k < c->ncore; k++) {
        qd_buf_puts(b, k ? ", " : " ");
        put_eig(b, c->core_re[k], c->core_im[k]);
    }
    qd_buf_puts(b, c->ncore ? "\n" : " none\n");
    for (size_t k = 0; k < c->ncon; k++) {
        char v[QD_DOUBLE_MAX];
        qd_double_format(v, c->lambda[k] == 0 ? 0 : c->lambda[k]);
        qd_buf_printf(b, "%s%s = %s", k ? ", " : "multipliers: ", qd_expr_name(c->lambda_sym[k]),
                      v);
    }
    if (c->ncon)
        qd_buf_puts(b, "\n");
}

static const char *verdict(const qd_conlin *c) {
    return !c->steady ? "not steady" : !c->stable ? "unstable"
           : c->marginal ? "marginally stable" : "stable";
}

/* The verdict line of the text: the core decides (qdot/conlin.h). */
static void verdict_text(qd_buf *b, const qd_conlin *c) {
    char v[QD_DOUBLE_MAX];
    qd_double_format(v, c->margin == 0 ? 0 : c->margin);
    if (!c->steady)
        qd_buf_puts(b, "verdict: none (not a steady motion: the states not ignorable move, "
                       "x' != 0 there)\n");
    else if (!c->ncore)
        qd_buf_puts(b, "verdict: marginally stable (every state ignorable: only zero "
                       "eigenvalues)\n");
    else if (!c->stable)
        qd_buf_printf(b, "verdict: unstable (the core's largest Re s is %s)\n", v);
    else if (c->marginal)
        qd_buf_printf(b, "verdict: marginally stable (the core's largest Re s is 0 to %.3g: "
                      "eigenvalues on the imaginary axis, which the linearization does not "
                      "decide)\n", c->tol);
    else
        qd_buf_printf(b, "verdict: stable (the core's largest Re s is %s)\n", v);
}

static void names_json(qd_json *j, const char *key, const qd_conlin *c, const size_t *idx,
                       size_t count, const bool *only) {
    qd_json_key(j, key);
    qd_json_begin_array(j);
    for (size_t i = 0; i < count; i++)
        if (!only || only[i])
            qd_json_string(j, zname(c, idx[i]));
    qd_json_end_array(j);
}

/* The members, without braces: written into an object by the caller. */
static void json(qd_json *j, const qd_conlin *c) {
    names_json(j, "independent", c, c->indep, c->nx, NULL);
    names_json(j, "dependent", c, c->dep, c->nhol + c->ncon, NULL);
    names_json(j, "ignorable", c, c->indep, c->nx, c->ignorable);
    qd_json_key(j, "point");
    qd_json_begin_object(j);
    for (size_t k = 0; k < 2 * c->n; k++) {
        qd_json_key(j, zname(c, k));
        qd_json_number(j, c->z[k]);
    }
    qd_json_end_object(j);
    qd_json_key(j, "core_eigenvalues");
    qd_json_begin_array(j);
    for (size_t k = 0; k < c->ncore; k++) {
        qd_json_begin_array(j);
        qd_json_number(j, c->core_re[k]);
        qd_json_number(j, c->core_im[k]);
        qd_json_end_array(j);
    }
    qd_json_end_array(j);
    qd_json_key(j, "multipliers");
    qd_json_begin_object(j);
    for (size_t k = 0; k < c->ncon; k++) {
        qd_json_key(j, qd_expr_name(c->lambda_sym[k]));
        qd_json_number(j, c->lambda[k]);
    }
    qd_json_end_object(j);
    qd_json_key(j, "stable");
    if (c->steady)
        qd_json_bool(j, c->stable);
    else
        qd_json_null(j);
    qd_json_key(j, "marginal");
    qd_json_bool(j, c->marginal);
    qd_json_key(j, "verdict");
    qd_json_string(j, verdict(c));
}

qd_status qd_conlin_print(const qd_conlin *c, bool as_json, qd_buf *out) {
    if (!c || !out)
        return QD_ERR_ARG;
    qd_buf b = QD_BUF_INIT;
    if (as_json) {
        qd_json j;
        qd_json_init(&j, &b);
        qd_json_begin_object(&j);
        json(&j, c);
        qd_json_end_object(&j);
        if (!qd_json_ok(&j)) {
            qd_buf_free(&b);
            return QD_ERR_NUMERIC;
        }
    } else
        text(&b, c);
    if (b.failed) {
        qd_buf_free(&b);
        return QD_ERR_NOMEM;
    }
    qd_buf_puts(out, qd_buf_str(&b));
    qd_buf_free(&b);
    return out->failed ? QD_ERR_NOMEM : QD_OK;
}

/* ---- the scan ----------------------------------------------------------------- */

static void cross_text(qd_buf *b, const char *name, const qd_conlin_cross *x) {
    qd_buf_printf(b, "  %s = %.12g: %s above; ", name, x->at,
                  !x->to_stable ? "unstable" : x->marginal ? "marginally stable (Re s = 0)"
                                                            : "stable");
    if (x->omega > 0)
        qd_buf_printf(b, "a complex pair crosses the imaginary axis at s = +-%.10gi\n", x->omega);
    else if (x->marginal)
        qd_buf_puts(b, "a real pair meets at s = 0 and turns imaginary\n");
    else
        qd_buf_puts(b, "a real eigenvalue crosses 0\n");
}

qd_status qd_conlin_scan_print(const qd_conlin_scan *s, const char *name, bool as_json,
                               qd_buf *out) {
    if (!s || !name || !out)
        return QD_ERR_ARG;
    qd_buf b = QD_BUF_INIT;
    if (as_json) {
        qd_json j;
        qd_json_init(&j, &b);
        qd_json_begin_object(&j);
        qd_json_key(&j, "parameter");
        qd_json_string(&j, name);
        qd_json_key(&j, "starts_above_zero");
        qd_json_bool(&j, s->nudged);
        qd_json_key(&j, "samples");
        qd_json_begin_array(&j);
        for (size_t i = 0; i < s->nsamples; i++) {
            qd_json_begin_object(&j);
            qd_json_key(&j, "value");
            qd_json_number(&j, s->p[i]);
            qd_json_key(&j, "margin");
            qd_json_number(&j, s->margin[i]);
            qd_json_key(&j, "eigenvalues");
            qd_json_begin_array(&j);
            for (size_t k = 0; k < s->nx; k++) {
                qd_json_begin_array(&j);
                qd_json_number(&j, s->re[i * s->nx + k]);
                qd_json_number(&j, s->im[i * s->nx + k]);
                qd_json_end_array(&j);
            }
            qd_json_end_array(&j);
            qd_json_end_object(&j);
        }
        qd_json_end_array(&j);
        qd_json_key(&j, "crossings");
        qd_json_begin_array(&j);
        for (size_t i = 0; i < s->ncross; i++) {
            qd_json_begin_object(&j);
            qd_json_key(&j, "value");
            qd_json_number(&j, s->cross[i].at);
            qd_json_key(&j, "omega");
            qd_json_number(&j, s->cross[i].omega);
            qd_json_key(&j, "to_stable");
            qd_json_bool(&j, s->cross[i].to_stable);
            qd_json_key(&j, "marginal");
            qd_json_bool(&j, s->cross[i].marginal);
            qd_json_end_object(&j);
        }
        qd_json_end_array(&j);
        qd_json_end_object(&j);
        qd_buf_puts(&b, "\n");
        if (!qd_json_ok(&j)) {
            qd_buf_free(&b);
            return QD_ERR_NUMERIC;
        }
    } else {
        if (s->nudged)
            qd_buf_printf(&b, "(the model assumes %s > 0: the scan starts at %.6g, not 0)\n",
                          name, s->p[0]);
        qd_buf_printf(&b, "%12s  %-14s  %s\n", name, "max Re s", "eigenvalues (not ignorable)");
        for (size_t i = 0; i < s->nsamples; i++) {
            qd_buf_printf(&b, "%12.6g  %-14.8g ", s->p[i], s->margin[i]);
            for (size_t k = 0; k < s->nx; k++) {
                double re = s->re[i * s->nx + k], im = s->im[i * s->nx + k];
                if (re == 0 && im == 0)
                    continue;
                if (im < 0)
                    continue;
                qd_buf_printf(&b, im > 0 ? " %.6g+-%.6gi" : " %.6g", re, im);
            }
            qd_buf_puts(&b, "\n");
        }
        qd_buf_printf(&b, "stability changes (the largest Re s of the core through 0):%s\n",
                      s->ncross ? "" : " none");
        for (size_t i = 0; i < s->ncross; i++)
            cross_text(&b, name, &s->cross[i]);
    }
    if (b.failed) {
        qd_buf_free(&b);
        return QD_ERR_NOMEM;
    }
    qd_buf_puts(out, qd_buf_str(&b));
    qd_buf_free(&b);
    return out->failed ? QD_ERR_NOMEM : QD_OK;
}

/* ---- with the state-space form ------------------------------------------------ */

qd_status qd_conlin_render(qd_ctx *ctx, const qd_conlin *c, const struct qd_care_result *lqr,
                           qd_ss_format fmt, qd_buf *out) {
    if (!ctx || !c || !out)
        return QD_ERR_ARG;
    qd_buf notes = QD_BUF_INIT, form = QD_BUF_INIT;
    qd_status st = QD_OK;
    if (fmt == QD_SS_TEXT || fmt == QD_SS_JSON)
        st = qd_conlin_print(c, fmt == QD_SS_JSON, &notes);
    if (st == QD_OK)
        st = qd_statespace_render(ctx, &c->ss, lqr, fmt, &form);
    if (st == QD_OK) {
        const char *f = qd_buf_str(&form);
        if (fmt == QD_SS_JSON) { /* {notes} + {form} -> {notes, form} */
            const char *nb = qd_buf_str(&notes);
            size_t nl = strlen(nb);
            while (nl && nb[nl - 1] != '}')
                nl--;
            for (nl = nl ? nl - 1 : 0; nl && (nb[nl - 1] == '\n' || nb[nl - 1] == ' ');)
                nl--;
            qd_buf_putn(out, nb, nl);
            qd_buf_puts(out, ",");
            qd_buf_puts(out, f[0] == '{' ? f + 1 : f);
        } else {
            qd_buf_puts(out, qd_buf_str(&notes));
            qd_buf_puts(out, f);
            if (fmt == QD_SS_TEXT)
                verdict_text(out, c);
        }
        if (out->failed)
            st = QD_ERR_NOMEM;
    }
    if (st == QD_ERR_NOMEM && qd_ctx_status(ctx) == QD_OK)
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory printing the state-space form");
    qd_buf_free(&notes);
    qd_buf_free(&form);
    return st;
}

qd_status qd_conlin_modes_print(qd_ctx *ctx, const qd_conlin *c, bool as_json, qd_buf *out) {
    if (!ctx || !c || !out)
        return QD_ERR_ARG;
    qd_buf b = QD_BUF_INIT;
    const qd_statespace *s = &c->ss;
    bool ok = true;
    if (as_json) {
        qd_json j;
        qd_json_init(&j, &b);
        qd_json_begin_object(&j);
        json(&j, c);
        qd_json_key(&j, "states");
        qd_json_begin_array(&j);
        for (size_t i = 0; i < s->nx; i++)
            qd_json_string(&j, qd_expr_name(s->states[i]));
        qd_json_end_array(&j);
        qd_json_key(&j, "eigenvalues");
        qd_json_begin_array(&j);
        for (size_t k = 0; k < s->nx; k++) {
            qd_json_begin_array(&j);
            qd_json_number(&j, s->eig_re[k]);
            qd_json_number(&j, s->eig_im[k]);
            qd_json_end_array(&j);
        }
        qd_json_end_array(&j);
        qd_json_end_object(&j);
        qd_buf_puts(&b, "\n");
        ok = qd_json_ok(&j);
    } else {
        text(&b, c);
        qd_buf_puts(&b, "eigenvalues of A (every state):\n");
        for (size_t k = 0; k < s->nx; k++) {
            qd_buf_puts(&b, "  s = ");
            put_eig(&b, s->eig_re[k], s->eig_im[k]);
            if (s->eig_im[k] > 0)
                qd_buf_printf(&b, "  (w = %.10g rad/s)", s->eig_im[k]);
            qd_buf_puts(&b, "\n");
        }
        verdict_text(&b, c);
    }
    qd_status st = !ok ? QD_ERR_NUMERIC : b.failed ? QD_ERR_NOMEM : QD_OK;
    if (st == QD_OK)
        qd_buf_puts(out, qd_buf_str(&b));
    if (st == QD_OK && out->failed)
        st = QD_ERR_NOMEM;
    if (st != QD_OK)
        qd_ctx_error(ctx, st, st == QD_ERR_NOMEM ? "out of memory printing the modes"
                                                 : "a number of the modes JSON cannot hold");
    qd_buf_free(&b);
    return st;
}

bool qd_conlin_needed(const qd_eom *e) {
    for (size_t k = 0; e && k < e->ncon; k++)
        if (e->con[k].kind != QD_CON_HOLONOMIC)
            return true;
    return false;
}

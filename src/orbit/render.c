/*
 * src/orbit/render.c - an orbit analysis as text and JSON (qd_orbit_render,
 * orbit.h): the output of `qdot orbit`.  Text shows computed results by
 * the one digit rule (qd_result_format: 12 digits, 0 at or below 1e-12); JSON keeps
 * every digit and writes null for what the orbit does not have (a NaN) and
 * for an open end (JSON has no infinity).
 */
#include "base/args.h"
#include "orb.h"

#include <math.h>

#include "qdot/json.h"

/* A computed result: the one digit rule (qd_buf_put_result, scale 1;
 * an open end prints inf). */
static void num(qd_buf *b, double x) { qd_buf_put_result(b, x, 1); }

static void put(qd_buf *b, const char *before, double x, const char *after) {
    qd_buf_puts(b, before);
    num(b, x);
    qd_buf_puts(b, after);
}

static const char *name(const qd_expr *x) { return qd_expr_name(x); }

static void by_name(const qd_orbit *o, qd_buf *b, const char *what, const double *v) {
    const qd_routh *h = o->routh;
    qd_buf_printf(b, "%s:", what);
    for (size_t i = 0; i < h->nign; i++) {
        qd_buf_printf(b, "%s %s ", i ? "," : "", name(h->ign[i]));
        num(b, v[i]);
    }
    qd_buf_puts(b, "\n");
}

static void text_ends(const qd_orbit *o, const qd_orbit_result *r, qd_buf *b) {
    const char *x = name(o->x);
    if (r->nturn) {
        qd_buf_printf(b, "turning points: %s = ", x);
        for (size_t k = 0; k < r->nturn; k++)
            put(b, k ? ", " : "", r->turn[k], "");
        qd_buf_puts(b, "\n");
    }
    put(b, "motion: ", r->lo, "");
    qd_buf_printf(b, " <= %s <= ", x);
    put(b, "", r->hi, "\n");
}

static void text_kind(const qd_orbit *o, const qd_orbit_result *r, qd_buf *b) {
    qd_buf_printf(b, "kind: %s\n", qd_orbit_kind_name(r->kind));
    text_ends(o, r, b);
    if (r->kind == QD_ORBIT_UNBOUND) {
        qd_buf_puts(b, "radial period: none (unbound)\n");
        if (r->nign && isfinite(r->advance[0]))
            by_name(o, b, "turn from infinity and back", r->advance);
    }
    if (r->kind == QD_ORBIT_ASYMPTOTIC) {
        qd_buf_puts(b, "radial period: none (E is the top of V_eff: the motion creeps towards "
                       "the unstable circle at the end of its interval for ever)\n");
        by_name(o, b, "advance on the way", r->advance);
    }
    if (r->kind == QD_ORBIT_CAPTURE) {
        put(b, "falls into the singular point of V_eff after time ", r->fall_time, "\n");
        by_name(o, b, "advance until then", r->advance);
    }
    if (isfinite(r->period)) {
        put(b, "radial period: ", r->period,
            r->kind == QD_ORBIT_CIRCULAR ? " (small radial oscillations)\n" : "\n");
        by_name(o, b, "advance per period", r->advance);
        by_name(o, b, "apsidal angle", r->apsidal);
        by_name(o, b, "precession per period", r->precession);
    }
}

static void text_circle(const qd_orbit *o, const qd_orbit_result *r, const qd_orbit_circle *c,
                        qd_buf *b) {
    qd_buf_printf(b, "  %s = ", name(o->x));
    put(b, "", c->x, ": V_eff = ");
    put(b, "", c->energy, "");
    qd_buf_printf(b, ", %s", c->stable == 1 ? "stable" : c->stable == 0 ? "unstable"
                                                                       : "borderline");
    if (c->stable == 1) {
        put(b, ", omega = ", c->omega, "");
        for (size_t i = 0; i < r->nign; i++) {
            qd_buf_printf(b, ", apsidal angle (%s) ", name(o->routh->ign[i]));
            num(b, c->apsidal[i]);
        }
        if (isfinite(c->bertrand))
            put(b, " = pi/sqrt(3 + r f'/f) ", c->bertrand, "");
    }
    qd_buf_puts(b, "\n");
}

static void text_conic(const qd_orbit *o, const qd_orbit_result *r, qd_buf *b) {
    put(b, "conic: p = ", r->p, "");
    put(b, ", e = ", r->e, "");
    put(b, ", a = ", r->a, "");
    if (r->nu != 1)
        put(b, ", nu = ", r->nu, "");
    if (r->repulsive)
        qd_buf_puts(b, ", repulsive");
    if (isfinite(r->periapsis)) {
        qd_buf_printf(b, ", periapsis at %s = ", name(o->routh->ign[0]));
        num(b, r->periapsis);
    }
    qd_buf_puts(b, "\n");
}

/* The orbit equation: the conic with its numbers, else the quadrature. */
static qd_status put_equation(qd_ctx *ctx, const qd_orbit *o, const qd_orbit_result *r,
                              qd_buf *b) {
    const char *c = name(o->routh->ign[0]);
    if (r->conic) {
        double peri = isfinite(r->periapsis) ? r->periapsis : 0;
        bool group = r->nu != 1 && peri != 0;
        qd_buf_printf(b, "%s = ", name(o->x));
        put(b, "", r->p, r->repulsive ? "/(" : "/(1 + ");
        put(b, "", r->e, "*cos(");
        if (r->nu != 1)
            put(b, "", r->nu, group ? "*(" : "*");
        qd_buf_printf(b, "%s", c);
        if (peri != 0) {
            qd_buf_printf(b, " %s ", peri < 0 ? "+" : "-");
            num(b, fabs(peri));
        }
        qd_buf_puts(b, group ? "))" : ")");
        qd_buf_puts(b, r->repulsive ? " - 1)" : ")"); /* C3's p/(e cos - 1) */
        return QD_OK;
    }
    const qd_expr *lhs = NULL, *rhs = qd_orbit_equation(ctx, o, r, &lhs);
    if (!rhs || !lhs)
        return qd_ctx_status(ctx) ? qd_ctx_status(ctx) : QD_ERR_NOMEM;
    qd_status st = qd_print(ctx, lhs, QD_FMT_TEXT, b);
    qd_buf_puts(b, " = ");
    return st == QD_OK ? qd_print(ctx, rhs, QD_FMT_TEXT, b) : st;
}

static qd_status text(qd_ctx *ctx, const qd_orbit *o, const qd_orbit_result *r,
                      const char *model, bool equation, qd_buf *b) {
    const qd_routh *h = o->routh;
    qd_buf_printf(b, "model: %s\nignored: ", model);
    for (size_t i = 0; i < h->nign; i++) {
        qd_buf_printf(b, "%s%s (%s = ", i ? ", " : "", name(h->ign[i]), name(h->beta[i]));
        put(b, "", r->momenta[i], ")");
    }
    qd_buf_puts(b, "\neffective potential: V_eff = ");
    qd_status st = qd_print(ctx, o->Veff, QD_FMT_TEXT, b);
    put(b, "\nenergy: E = ", r->energy, "\n");
    text_kind(o, r, b);
    qd_buf_printf(b, "circular orbits at these momenta:%s\n", r->ncircle ? "" : " none");
    for (size_t k = 0; k < r->ncircle; k++)
        text_circle(o, r, &r->circle[k], b);
    if (r->conic)
        text_conic(o, r, b);
    if (st == QD_OK && equation) {
        qd_buf_puts(b, "orbit: ");
        st = put_equation(ctx, o, r, b);
        qd_buf_puts(b, "\n");
    }
    return st;
}

/* ---- JSON ---------------------------------------------------------------- */

static void jnum(qd_json *j, double x) {
    if (isfinite(x))
        qd_json_number(j, x);
    else
        qd_json_null(j);
}

static void jkey(qd_json *j, const char *key, double x) {
    qd_json_key(j, key);
    jnum(j, x);
}

static void json_by_name(const qd_orbit *o, qd_json *j, const char *key, const double *v) {
    const qd_routh *h = o->routh;
    qd_json_key(j, key);
    qd_json_begin_object(j);
    for (size_t i = 0; i < h->nign; i++)
        jkey(j, name(h->ign[i]), v[i]);
    qd_json_end_object(j);
}

static void json_circles(const qd_orbit *o, const qd_orbit_result *r, qd_json *j) {
    qd_json_key(j, "circular");
    qd_json_begin_array(j);
    for (size_t k = 0; k < r->ncircle; k++) {
        const qd_orbit_circle *c = &r->circle[k];
        qd_json_begin_object(j);
        jkey(j, name(o->x), c->x);
        jkey(j, "effective_potential", c->energy);
        qd_json_key(j, "stable");
        if (c->stable < 0)
            qd_json_null(j);
        else
            qd_json_bool(j, c->stable == 1);
        jkey(j, "omega", c->omega);
        json_by_name(o, j, "apsidal_angle", c->apsidal);
        jkey(j, "bertrand", c->bertrand);
        qd_json_end_object(j);
    }
    qd_json_end_array(j);
}

static void json_conic(const qd_orbit_result *r, qd_json *j) {
    qd_json_key(j, "conic");
    if (!r->conic) {
        qd_json_null(j);
        return;
    }
    qd_json_begin_object(j);
    jkey(j, "p", r->p);
    jkey(j, "e", r->e);
    jkey(j, "a", r->a);
    jkey(j, "nu", r->nu);
    jkey(j, "periapsis", r->periapsis);
    qd_json_key(j, "repulsive");
    qd_json_bool(j, r->repulsive);
    qd_json_end_object(j);
}

static void json_motion(const qd_orbit *o, const qd_orbit_result *r, qd_json *j) {
    qd_json_key(j, "kind");
    qd_json_string(j, qd_orbit_kind_name(r->kind));
    qd_json_key(j, "turning_points");
    qd_json_begin_array(j);
    for (size_t k = 0; k < r->nturn; k++)
        jnum(j, r->turn[k]);
    qd_json_end_array(j);
    qd_json_key(j, "interval");
    qd_json_begin_array(j);
    jnum(j, r->lo);
    jnum(j, r->hi);
    qd_json_end_array(j);
    jkey(j, "radial_period", r->period);
    json_by_name(o, j, "advance", r->advance);
    json_by_name(o, j, "apsidal_angle", r->apsidal);
    json_by_name(o, j, "precession_per_period", r->precession);
    jkey(j, "fall_time", r->fall_time);
    jkey(j, "quadrature_error", r->quad_error);
}

static qd_status json(qd_ctx *ctx, const qd_orbit *o, const qd_orbit_result *r,
                      const char *model, bool equation, qd_buf *b) {
    qd_json j;
    qd_json_init(&j, b);
    qd_json_begin_object(&j);
    qd_json_key(&j, "model");
    qd_json_string(&j, model);
    qd_json_key(&j, "coordinate");
    qd_json_string(&j, name(o->x));
    qd_json_key(&j, "effective_potential");
    qd_json_expr(&j, ctx, o->Veff);
    jkey(&j, "energy", r->energy);
    qd_json_key(&j, "momenta");
    qd_json_begin_object(&j);
    for (size_t i = 0; i < r->nign; i++)
        jkey(&j, name(o->routh->beta[i]), r->momenta[i]);
    qd_json_end_object(&j);
    json_motion(o, r, &j);
    json_circles(o, r, &j);
    json_conic(r, &j);
    qd_status st = QD_OK;
    if (equation) {
        qd_buf e = QD_BUF_INIT;
        st = put_equation(ctx, o, r, &e);
        qd_json_key(&j, "orbit");
        qd_json_string(&j, qd_buf_str(&e));
        qd_buf_free(&e);
    }
    qd_json_end_object(&j);
    qd_buf_puts(b, "\n");
    if (st == QD_OK && !qd_json_ok(&j)) {
        qd_ctx_error(ctx, j.nomem ? QD_ERR_NOMEM : QD_ERR_NUMERIC,
                     "the orbit cannot be written: %s", qd_json_why(&j));
        st = qd_ctx_status(ctx);
    }
    return st;
}

qd_status qd_orbit_render(qd_ctx *ctx, const qd_orbit *o, const qd_orbit_result *r,
                          const char *model, bool equation, bool as_json, qd_buf *b) {
    QD_ARGS_CTX(ctx, ctx && o && r && model && b);
    qd_status st = as_json ? json(ctx, o, r, model, equation, b)
                           : text(ctx, o, r, model, equation, b);
    if (st == QD_OK && b->failed) {
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory");
        st = QD_ERR_NOMEM;
    }
    return st;
}

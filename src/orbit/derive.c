/*
 * src/orbit/derive.c - the symbolic side of the orbit analysis: Routh's
 * reduction to one coordinate, V_eff's derivatives, the ignored rates at
 * x' = 0, the detection of central and Kepler-type reductions, and the
 * compiled program every numeric step evaluates.
 */
#include "orb.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "base/mem.h"
#include "num/num.h"
#include "../base/args.h"

static const qd_expr **arr(qd_ctx *ctx, size_t n) {
    return qd__calloc(ctx, n ? n : 1, sizeof(const qd_expr *));
}

void qd_orbit_free(qd_orbit *o) {
    if (!o)
        return;
    if (o->num) {
        qd_prog_free(o->num->prog);
        qd_prog_free(o->num->prog2);
        qd__free(o->num->ins);
        qd__free(o->num->ins2);
        qd__free(o->num);
    }
    qd__free(o->rate);
    qd_routh_free(o->routh);
    qd__free(o);
}

/* "r, z" into buf: the coordinates left by the reduction. */
static void kept_names(const qd_routh *r, char *buf, size_t cap) {
    size_t len = 0;
    buf[0] = '\0';
    for (size_t k = 0; k < r->nkeep && len + 1 < cap; k++)
        len += (size_t)snprintf(buf + len, cap - len, "%s%s", k ? ", " : "",
                                qd_expr_name(r->keep[k]));
}

static qd_status check_reduction(qd_ctx *ctx, const qd_routh *r) {
    char names[256];
    if (r->nkeep != 1) {
        kept_names(r, names, sizeof names);
        qd_ctx_error(ctx, QD_ERR_ARG,
                     "orbit reduces the motion to one coordinate, but %zu are left (%s): "
                     "ignore all but one", r->nkeep, names);
        return QD_ERR_ARG;
    }
    if (!r->conserved) {
        qd_ctx_error(ctx, QD_ERR_ARG,
                     "the reduced motion of %s does not conserve its energy (explicit t, a "
                     "generalized force or dissipation): it has no turning points to find",
                     qd_expr_name(r->keep[0]));
        return QD_ERR_ARG;
    }
    return QD_OK;
}

/* Central: c' x^2 and M free of x (one ignored angle, a particle in its
 * plane).  Kepler-type: besides, V_eff = c0 + c1/x + c2/x^2 exactly. */
static void detect_kepler(qd_ctx *ctx, qd_orbit *o) {
    const qd_expr *x = o->x;
    if (o->routh->nign != 1 || qd_has(o->mass, x))
        return;
    const qd_expr *h = qd_simplify(ctx, qd_mul(ctx, o->rate[0], qd_powi(ctx, x, 2)));
    if (!h || qd_has(h, x))
        return;
    o->central = true;
    const qd_expr *V = qd_expand(ctx, o->Veff);
    const qd_expr *c0 = qd_coeff(ctx, V, x, 0), *c1 = qd_coeff(ctx, V, x, -1),
                  *c2 = qd_coeff(ctx, V, x, -2);
    if (!c0 || !c1 || !c2 || qd_has(c0, x) || qd_has(c1, x) || qd_has(c2, x))
        return;
    const qd_expr *back = qd_add(ctx, qd_add(ctx, c0, qd_div(ctx, c1, x)),
                                 qd_div(ctx, c2, qd_powi(ctx, x, 2)));
    const qd_expr *rest = qd_expand(ctx, qd_sub(ctx, V, back));
    if (rest && qd_is_zero(rest) && !qd_is_zero(c1)) {
        o->kepler = true;
        o->k0 = c0;
        o->k1 = c1;
        o->k2 = c2;
    }
}

/* o->general: prog2, h and its slope in x' and the rates, all at (x, x'). */
static qd_status compile2(qd_ctx *ctx, qd_orbit *o) {
    const qd_routh *r = o->routh;
    size_t nout = QD__ORB_RATE2 + r->nign;
    const qd_expr **outs = arr(ctx, nout);
    if (!outs)
        return QD_ERR_NOMEM;
    outs[QD__ORB_H] = r->h;
    outs[QD__ORB_DH] = qd_diff(ctx, r->h, o->xd);
    for (size_t i = 0; i < r->nign; i++)
        outs[QD__ORB_RATE2 + i] = r->ignvel[i];
    struct qd__orb_num *num = o->num;
    if (outs[QD__ORB_DH] && (num->ins2 = qd__num_inputs(ctx, nout, outs, &num->nin2)))
        num->prog2 = qd_prog_new(ctx, num->nin2, num->ins2, nout, outs);
    qd__free(outs);
    return num->prog2 ? QD_OK : qd_ctx_status(ctx);
}

static qd_status compile(qd_ctx *ctx, qd_orbit *o) {
    size_t nign = o->routh->nign, nout = QD__ORB_RATE + nign + (o->kepler ? 3 : 0);
    size_t ih4 = nout;
    if (o->general)
        nout += 2;
    const qd_expr **outs = arr(ctx, nout);
    o->num = qd__calloc(ctx, 1, sizeof *o->num);
    if (!outs || !o->num) {
        qd__free(outs);
        return QD_ERR_NOMEM;
    }
    outs[QD__ORB_V] = o->Veff;
    for (int k = 0; k < 4; k++)
        outs[QD__ORB_V1 + k] = o->dV[k];
    outs[QD__ORB_M] = o->mass;
    for (size_t i = 0; i < nign; i++)
        outs[QD__ORB_RATE + i] = o->rate[i];
    if (o->kepler) {
        outs[QD__ORB_RATE + nign] = o->k0;
        outs[QD__ORB_RATE + nign + 1] = o->k1;
        outs[QD__ORB_RATE + nign + 2] = o->k2;
    }
    if (o->general) {
        /* h = h0 + M s/2 + h4 s^2/24 + h6 s^3/720 in s = x'^2 (h is even in x':
         * R1 does not enter it): the series that solves h = E for x' near a
         * turning point, where h - V_eff is a difference of nearly equal numbers */
        const qd_expr *d = o->routh->h, *zero = qd_int(ctx, 0);
        for (int k = 1; k <= 6 && d; k++) {
            d = qd_diff(ctx, d, o->xd);
            if (k == 4 || k == 6)
                outs[ih4 + (k == 6)] = d ? qd_subs(ctx, d, 1, &o->xd, &zero) : NULL;
        }
        if (!outs[ih4] || !outs[ih4 + 1]) {
            qd__free(outs);
            return qd_ctx_status(ctx) ? qd_ctx_status(ctx) : QD_ERR_NOMEM;
        }
        o->num->ih4 = ih4;
    }
    o->num->nout = nout;
    o->num->ins = qd__num_inputs(ctx, nout, outs, &o->num->nin);
    if (o->num->ins)
        o->num->prog = qd_prog_new(ctx, o->num->nin, o->num->ins, nout, outs);
    qd__free(outs);
    if (o->num->prog && o->general)
        return compile2(ctx, o);
    return o->num->prog ? QD_OK : qd_ctx_status(ctx);
}

static qd_status derive_parts(qd_ctx *ctx, qd_orbit *o) {
    qd_routh *r = o->routh;
    o->x = r->keep[0];
    o->xd = r->keepd[0];
    o->Veff = r->Veff;
    o->mass = r->M[0];
    const qd_expr *d = o->Veff;
    for (int k = 0; k < 4; k++)
        o->dV[k] = d = qd_diff(ctx, d, o->x);
    o->rate = arr(ctx, r->nign);
    if (!o->rate || !d)
        return qd_ctx_status(ctx) ? qd_ctx_status(ctx) : QD_ERR_NOMEM;
    const qd_expr *zero = qd_int(ctx, 0);
    /* E = M x'^2/2 + V_eff holds only when -R is quadratic in x'; a
     * relativistic L's M and rates depend on x' (m gamma^3): the general path */
    o->general = qd_has(o->mass, o->xd);
    for (size_t i = 0; i < r->nign; i++) {
        o->general = o->general || qd_has(r->ignvel[i], o->xd);
        if (!(o->rate[i] = qd_subs(ctx, r->ignvel[i], 1, &o->xd, &zero)))
            return qd_ctx_status(ctx);
    }
    if (o->general && !(o->mass = qd_subs(ctx, o->mass, 1, &o->xd, &zero)))
        return qd_ctx_status(ctx);
    if (!o->general) /* Bertrand's and Kepler's forms assume E = M x'^2/2 + V_eff */
        detect_kepler(ctx, o);
    if (qd__ctx_nomem(ctx)) /* the detection's NULLs were for want of memory, not a "no" */
        return QD_ERR_NOMEM;
    return compile(ctx, o);
}

qd_orbit *qd_orbit_derive(qd_ctx *ctx, const qd_model *m, const qd_eom *e, size_t nign,
                          const qd_expr *const *ign) {
    QD_ARGS(NULL, ctx && m && e);
    if (nign == 0) {
        qd_ctx_error(ctx, QD_ERR_ARG,
                     "orbit needs a cyclic coordinate to ignore (--ignore): with none the "
                     "motion does not reduce to one coordinate");
        return NULL;
    }
    qd_orbit *o = qd__calloc(ctx, 1, sizeof *o);
    if (!o)
        return NULL;
    o->routh = qd_routh_derive(ctx, m, e, nign, ign);
    qd_status st = o->routh ? check_reduction(ctx, o->routh) : qd_ctx_status(ctx);
    if (st == QD_OK)
        st = derive_parts(ctx, o);
    if (st != QD_OK) {
        if (qd_ctx_status(ctx) == QD_OK)
            qd_ctx_error(ctx, st, "cannot prepare the orbit analysis");
        qd_orbit_free(o);
        return NULL;
    }
    return o;
}

/* ---- evaluation environment ---------------------------------------------- */

static size_t slot(const qd_orbit *o, const qd_expr *s) {
    for (size_t i = 0; i < o->num->nin; i++)
        if (o->num->ins[i] == s)
            return i;
    return SIZE_MAX;
}

static qd_status bind_input(qd_ctx *ctx, const qd_expr *s, size_t n, const qd_expr *const *syms,
                            const double *vals, double *v) {
    for (size_t k = 0; k < n; k++)
        if (syms[k] == s) {
            *v = vals[k];
            return QD_OK;
        }
    qd_ctx_error(ctx, QD_ERR_UNBOUND, "%s has no value: give it one", qd_expr_name(s));
    return QD_ERR_UNBOUND;
}

qd_status qd__orb_env_init(qd_ctx *ctx, const qd_orbit *o, size_t n, const qd_expr *const *syms,
                           const double *vals, const double *beta, qd__orb_env *env) {
    const struct qd__orb_num *num = o->num;
    memset(env, 0, sizeof *env);
    env->o = o;
    env->work = qd__malloc(ctx, (qd_prog_work_size(num->prog) + 1) * sizeof(double));
    env->in = qd__calloc(ctx, num->nin + 1, sizeof(double));
    env->out = qd__calloc(ctx, num->nout, sizeof(double));
    if (!env->work || !env->in || !env->out) {
        qd__orb_env_free(env);
        return QD_ERR_NOMEM;
    }
    qd_prog_work_init(num->prog, env->work);
    env->ix = slot(o, o->x);
    if (num->prog2) {
        env->work2 = qd__malloc(ctx, (qd_prog_work_size(num->prog2) + 1) * sizeof(double));
        env->in2 = qd__calloc(ctx, num->nin2 + 1, sizeof(double));
        env->out2 = qd__calloc(ctx, QD__ORB_RATE2 + o->routh->nign, sizeof(double));
        if (!env->work2 || !env->in2 || !env->out2) {
            qd__orb_env_free(env);
            return QD_ERR_NOMEM;
        }
        qd_prog_work_init(num->prog2, env->work2);
        env->ix2 = env->ixd2 = SIZE_MAX;
        for (size_t i = 0; i < num->nin2; i++) {
            const qd_expr *s = num->ins2[i];
            size_t b = 0;
            while (b < o->routh->nign && o->routh->beta[b] != s)
                b++;
            if (s == o->x)
                env->ix2 = i;
            else if (s == o->xd)
                env->ixd2 = i;
            else if (b < o->routh->nign)
                env->in2[i] = beta[b];
            else if (bind_input(ctx, s, n, syms, vals, &env->in2[i]) != QD_OK) {
                qd__orb_env_free(env);
                return QD_ERR_UNBOUND;
            }
        }
    }
    for (size_t i = 0; i < num->nin; i++) {
        const qd_expr *s = num->ins[i];
        size_t b = 0;
        while (b < o->routh->nign && o->routh->beta[b] != s)
            b++;
        if (b < o->routh->nign)
            env->in[i] = beta[b];
        else if (i != env->ix && bind_input(ctx, s, n, syms, vals, &env->in[i]) != QD_OK) {
            qd__orb_env_free(env);
            return QD_ERR_UNBOUND;
        }
    }
    return QD_OK;
}

void qd__orb_env_free(qd__orb_env *env) {
    qd__free(env->work);
    qd__free(env->in);
    qd__free(env->out);
    qd__free(env->work2);
    qd__free(env->in2);
    qd__free(env->out2);
    env->work = env->in = env->out = env->work2 = env->in2 = env->out2 = NULL;
}

const double *qd__orb_at2(qd__orb_env *env, double x, double xd) {
    if (env->ix2 != SIZE_MAX)
        env->in2[env->ix2] = x;
    if (env->ixd2 != SIZE_MAX)
        env->in2[env->ixd2] = xd;
    qd_prog_eval(env->o->num->prog2, env->work2, env->in2, env->out2);
    return env->out2;
}

/* Below this share of |E| + |V_eff| the gap is left to the series in
 * s = x'^2: there h - V_eff would lose more digits to cancellation than the
 * series' first omitted term (h8 s^4) costs; 1e-4 gave the least error on
 * the relativistic Kepler orbits of tests/orbit (about 1e-12 in the
 * advance against Sommerfeld's closed form). */
#define SERIES_GAP 1e-4

double qd__orb_speed(qd__orb_env *env, double x, double gap) {
    const double *o = env->out;
    double M = o[QD__ORB_M], h4 = o[env->o->num->ih4], h6 = o[env->o->num->ih4 + 1];
    double V = o[QD__ORB_V], s = 2 * gap / M;
    if (!(s > 0) || !isfinite(s))
        return NAN;
    if (gap <= SERIES_GAP * (fabs(env->E) + fabs(V))) {
        /* M s/2 + h4 s^2/24 + h6 s^3/720 = gap, by Newton from s's leading term */
        for (int it = 0; it < 30; it++) {
            double f = s * (M / 2 + s * (h4 / 24 + s * h6 / 720)) - gap;
            double df = M / 2 + s * (h4 / 12 + s * h6 / 240), ds = f / df;
            s -= ds;
            if (!(s > 0) || !isfinite(s))
                return NAN;
            if (fabs(ds) <= 1e-15 * s)
                break;
        }
        return sqrt(s);
    }
    /* h(x, x') = E by Newton in x', a step that leaves h's domain halved
     * (the speed of light bounds a relativistic x') */
    double xd = sqrt(s);
    for (int it = 0; it < 60; it++) {
        const double *p = qd__orb_at2(env, x, xd);
        double f = p[QD__ORB_H] - env->E, df = p[QD__ORB_DH];
        if (!isfinite(f) || !(df > 0))
            return NAN;
        double step = f / df, next = xd - step;
        for (int k = 0; k < 60 && !(next > 0 && isfinite(qd__orb_at2(env, x, next)[QD__ORB_H])); k++)
            next = xd - (step /= 2);
        if (!(next > 0))
            return NAN;
        bool done = fabs(next - xd) <= 4e-16 * next;
        xd = next;
        if (done)
            break;
    }
    return xd;
}

const double *qd__orb_at(qd__orb_env *env, double x) {
    if (env->ix != SIZE_MAX)
        env->in[env->ix] = x;
    qd_prog_eval(env->o->num->prog, env->work, env->in, env->out);
    return env->out;
}

double qd__orb_gap(qd__orb_env *env, double x) { return env->E - qd__orb_at(env, x)[QD__ORB_V]; }

double qd__orb_slope(qd__orb_env *env, double x) { return qd__orb_at(env, x)[QD__ORB_V1]; }

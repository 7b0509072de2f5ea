/*
 * src/mech/constraints.c - the constraint rows of M q'' = f + A^T lambda,
 * A q'' = b.
 *
 * Each constraint of the model is split into its velocity coefficients,
 * sum_j a_j q'_j + a0 (Desloge ch. 49 eq. 15, ch. 52 thm 1): for a holonomic
 * phi(q, t) they are a_j = dphi/dq_j and a0 = dphi/dt, for a Pfaffian one
 * qd_linear_coeffs reads them off.  The row closing the system is the
 * constraint differentiated until the accelerations appear, phi'' (holonomic)
 * or (sum a_j q'_j + a0)' (Pfaffian); its acceleration coefficients are a_j
 * again and b = -(the rest), i.e. b = -(sum_j a_j' q'_j + a0').  Virtual
 * displacements are at frozen time, so dphi/dt enters b only, never A
 * (Desloge, pitfall 1: a moving smooth surface).
 */
#include "mech.h"

#include "qdot/print.h"
#include "../base/mem.h"

#include <stdio.h>
#include <stdlib.h>

static bool has_any(const qd_expr *x, size_t n, const qd_expr *const *syms) {
    for (size_t i = 0; x && i < n; i++)
        if (qd_has(x, syms[i]))
            return true;
    return false;
}

/* A velocity of x that is in it other than linearly, for the message. */
static const char *nonlinear_velocity(qd_ctx *ctx, const qd_eom *e, const qd_expr *x) {
    for (size_t j = 0; j < e->n; j++) {
        const qd_expr *d = qd_diff(ctx, x, e->qd[j]);
        if (d && has_any(d, e->n, e->qd))
            return qd_expr_name(e->qd[j]);
    }
    return "a velocity";
}

/* x grouped by velocity monomials and simplified. */
static const qd_expr *tidy(qd_ctx *ctx, const qd_eom *e, const qd_expr *x) {
    qd__vsum v;
    qd_status st = qd__mech_by_velocity(ctx, x, e->n, e->qd, &v);
    if (st != QD_OK && st != QD_ERR_NONLINEAR)
        return NULL;
    return qd_simplify(ctx, st == QD_OK ? v.all : x);
}

#define PFAFFIAN_HINT "write the constraint as sum_j a_j(q, t) q'_j + a0(q, t) = 0"

/* c->a, c->a0 and kind; the constraint differentiated once more than
 * needed for its velocity form goes to *closing, when closing is not NULL. */
static qd_status split(qd_ctx *ctx, const qd_eom *e, qd_con *c, const qd_expr **closing) {
    size_t n = e->n;
    if (has_any(c->expr, n, e->qdd)) {
        qd_ctx_error(ctx, QD_ERR_ARG,
                     "constraint %s contains accelerations: a constraint relates coordinates, "
                     "velocities and t", c->name);
        qd_ctx_error_about(ctx, QD_SUBJECT_CONSTRAINT, (size_t)(c - e->con), c->name,
                           QD_REASON_NOT_PFAFFIAN, PFAFFIAN_HINT);
        return QD_ERR_ARG;
    }
    if (!has_any(c->expr, n, e->qd)) {
        c->kind = QD_CON_HOLONOMIC;
        for (size_t j = 0; j < n; j++)
            c->a[j] = qd_diff(ctx, c->expr, e->q[j]);
        c->a0 = qd_diff(ctx, c->expr, qd_time(ctx));
        if (!closing)
            return c->a0 ? QD_OK : qd_ctx_status(ctx);
        *closing = qd_dt(ctx, qd_dt(ctx, c->expr));
        return *closing ? QD_OK : qd_ctx_status(ctx);
    }
    c->kind = QD_CON_NONHOLONOMIC;
    qd_status st = qd_linear_coeffs(ctx, c->expr, n, e->qd, c->a, &c->a0);
    if (st == QD_ERR_NONLINEAR) {
        qd__ctx_recover(ctx); /* the kernel's message does not name the constraint */
        qd_ctx_error(ctx, st,
                     "constraint %s is not linear in the velocities (%s enters nonlinearly): "
                     "qdot handles holonomic and Pfaffian constraints",
                     c->name, nonlinear_velocity(ctx, e, c->expr));
        qd_ctx_error_about(ctx, QD_SUBJECT_CONSTRAINT, (size_t)(c - e->con), c->name,
                           QD_REASON_NOT_PFAFFIAN, PFAFFIAN_HINT);
        return st;
    }
    if (!closing)
        return st == QD_OK ? QD_OK : qd_ctx_status(ctx);
    *closing = st == QD_OK ? qd_dt(ctx, c->expr) : NULL;
    return *closing ? QD_OK : qd_ctx_status(ctx);
}

/* The multiplier's symbol: lambda_<name>, with '_' appended while a
 * coordinate or parameter has that name. */
static const qd_expr *multiplier(qd_ctx *ctx, const char *name) {
    char buf[160];
    int len = snprintf(buf, sizeof buf, "lambda_%s", name);
    if (len < 0 || (size_t)len >= sizeof buf - 8) {
        qd_ctx_error(ctx, QD_ERR_ARG, "constraint name '%s' is too long", name);
        return NULL;
    }
    for (const qd_expr *s; (s = qd_lookup(ctx, buf)) && qd_symbol_role(s) != QD_ROLE_PLAIN;)
        buf[len++] = '_', buf[len] = '\0';
    return qd_symbol(ctx, buf);
}

static qd_status row(qd_ctx *ctx, qd_eom *e, size_t k, const qd_expr **scratch, bool with_b) {
    qd_con *c = &e->con[k];
    const qd_expr *closing = NULL, *rest = NULL;
    qd_status st = split(ctx, e, c, with_b ? &closing : NULL);
    if (st == QD_OK && with_b)
        st = qd_linear_coeffs(ctx, closing, e->n, e->qdd, scratch, &rest);
    if (st != QD_OK)
        return qd_ctx_status(ctx) != QD_OK ? qd_ctx_status(ctx) : st;
    for (size_t j = 0; j < e->n; j++)
        if (!(c->a[j] = qd_simplify(ctx, c->a[j])))
            return qd_ctx_status(ctx);
    c->a0 = qd_simplify(ctx, c->a0);
    if (with_b && !(e->b[k] = tidy(ctx, e, qd_neg(ctx, rest))))
        return qd_ctx_status(ctx);
    c->lambda = multiplier(ctx, c->name);
    return c->a0 && c->lambda ? QD_OK : qd_ctx_status(ctx);
}

/* ---- classification on the configuration manifold --------------------------
 *
 * A Pfaffian constraint lives on the manifold the holonomic ones cut out
 * (Desloge ch. 49): r theta' - b phi' = 0 is nonholonomic in (r, theta, phi)
 * but exact once the contact r = a + b holds.  So the Pfaffian constraints
 * are classified again where the holonomic ones can be solved for a
 * coordinate (the same solver as --eliminate): q_j = g, q'_j = g' are
 * substituted, which is the pull-back of the form to the manifold, and the
 * reduced form is classified in the remaining coordinates; its integral holds
 * on the manifold.  Where no holonomic constraint can be solved, the
 * differentials of the holonomic constraints join the Frobenius test:
 * w is integrable modulo them when dw ^ w ^ dphi_1 ^ ... ^ dphi_h = 0.  That
 * is decided off the manifold too (a sufficient condition), so a constraint
 * integrable only on it may still be called nonholonomic there: that keeps
 * a multiplier, never loses one.  Forms that are integrable one by one must
 * also be so together (the two no-slip conditions of a rolling disk); exact
 * forms (the dphi) never spoil that, so they are always included. */

/* A set of classified constraints over n coordinates. */
typedef struct conset {
    size_t n;
    const qd_expr *const *q;
    size_t m;
    qd_con *con;
} conset;

static size_t count_kind(const conset *cs, qd_con_kind kind) {
    size_t c = 0;
    for (size_t k = 0; k < cs->m; k++)
        c += cs->con[k].kind == kind;
    return c;
}

/* The holonomic constraints, the integrable ones when asked, and extra;
 * at most 16, into out. */
static size_t gather(const conset *cs, bool integrable, qd_con *extra, qd_con **out) {
    size_t m = 0;
    for (size_t k = 0; k < cs->m && m < 16; k++)
        if (cs->con[k].kind == QD_CON_HOLONOMIC)
            out[m++] = &cs->con[k];
    for (size_t k = 0; k < cs->m && m < 16; k++)
        if (integrable && cs->con[k].kind == QD_CON_INTEGRABLE && &cs->con[k] != extra)
            out[m++] = &cs->con[k];
    if (extra && m < 16)
        out[m++] = extra;
    return m;
}

/* Are the integrable Pfaffian constraints of cs integrable together? */
static qd_status together(qd_ctx *ctx, const conset *cs, bool *ok) {
    qd_con *group[16];
    *ok = true;
    if (count_kind(cs, QD_CON_INTEGRABLE) < 2)
        return QD_OK;
    size_t m = gather(cs, true, NULL, group);
    return qd__mech_con_frobenius(ctx, cs->n, cs->q, group, m, ok);
}

/* Each nonholonomic constraint of cs tested with the differentials of the
 * holonomic ones; integral not given. */
static qd_status modulo_holonomic(qd_ctx *ctx, conset *cs) {
    qd_con *group[16];
    for (size_t k = 0; k < cs->m; k++) {
        qd_con *c = &cs->con[k];
        bool ok;
        if (c->kind != QD_CON_NONHOLONOMIC)
            continue;
        size_t m = gather(cs, false, c, group);
        qd_status st = qd__mech_con_frobenius(ctx, cs->n, cs->q, group, m, &ok);
        if (st != QD_OK)
            return st;
        if (ok)
            *c = (qd_con){.name = c->name, .kind = QD_CON_INTEGRABLE, .expr = c->expr,
                          .a = c->a, .a0 = c->a0, .lambda = c->lambda};
    }
    return QD_OK;
}

static void demote(conset *cs) {
    for (size_t k = 0; k < cs->m; k++)
        if (cs->con[k].kind == QD_CON_INTEGRABLE) {
            cs->con[k].kind = QD_CON_NONHOLONOMIC;
            cs->con[k].integral = cs->con[k].factor = NULL;
        }
}

/* The model's constraints with the solvable holonomic ones substituted. */
typedef struct surface {
    qd__sys sys;
    qd_elim *elim;
    size_t nelim;
    qd_con *con;
    const qd_expr **a, **qd;
} surface;

static void surface_free(surface *sf) {
    qd__mech_sys_free(&sf->sys);
    qd__free(sf->elim);
    qd__free(sf->con);
    qd__free(sf->a);
    qd__free(sf->qd);
}

/* Constraint i of the reduced system: its coefficients and kind (a
 * Pfaffian one as nonholonomic, to be classified). */
static qd_status surface_row(qd_ctx *ctx, surface *sf, size_t i) {
    size_t n = sf->sys.n;
    qd_con *c = &sf->con[i];
    *c = (qd_con){.name = sf->sys.con_name[i], .expr = sf->sys.con_expr[i], .a = sf->a + i * n};
    if (!has_any(c->expr, n, sf->qd)) {
        c->kind = QD_CON_HOLONOMIC;
        for (size_t j = 0; j < n; j++)
            c->a[j] = qd_diff(ctx, c->expr, sf->sys.q[j]);
        c->a0 = qd_diff(ctx, c->expr, qd_time(ctx));
    } else {
        c->kind = QD_CON_NONHOLONOMIC;
        qd_status st = qd_linear_coeffs(ctx, c->expr, n, sf->qd, c->a, &c->a0);
        if (st != QD_OK)
            return st;
    }
    for (size_t j = 0; j < n; j++)
        c->a[j] = qd_simplify(ctx, c->a[j]);
    c->a0 = qd_simplify(ctx, c->a0);
    return qd_ctx_status(ctx);
}

static qd_status surface_copy(qd_ctx *ctx, const qd_eom *e, const qd__sys *s, surface *sf) {
    size_t n = e->n, m = s->ncon;
    sf->sys = (qd__sys){.n = n, .ncon = m};
    sf->sys.q = qd__malloc(ctx, (n + 1) * sizeof *sf->sys.q);
    sf->sys.Q = qd__malloc(ctx, (n + 1) * sizeof *sf->sys.Q);
    sf->sys.con_name = qd__malloc(ctx, (m + 1) * sizeof *sf->sys.con_name);
    sf->sys.con_expr = qd__malloc(ctx, (m + 1) * sizeof *sf->sys.con_expr);
    if (!sf->sys.q || !sf->sys.Q || !sf->sys.con_name || !sf->sys.con_expr)
        return QD_ERR_NOMEM;
    for (size_t j = 0; j < n; j++)
        sf->sys.q[j] = e->q[j];
    for (size_t k = 0; k < m; k++) {
        sf->sys.con_name[k] = s->con_name[k];
        sf->sys.con_expr[k] = s->con_expr[k];
    }
    return QD_OK;
}

/* *ok: some coordinate was eliminated and every reduced constraint is
 * known (a failure of the reduction is not an error of the model: the
 * classification then goes without it). */
static qd_status surface_init(qd_ctx *ctx, const qd_eom *e, const qd__sys *s, surface *sf,
                              bool *ok) {
    *sf = (surface){0};
    *ok = false;
    qd_status st = surface_copy(ctx, e, s, sf);
    for (size_t j = 0; st == QD_OK && j < e->n; j++)
        if (!(sf->sys.Q[j] = qd_int(ctx, 0)))
            st = qd_ctx_status(ctx);
    if (st == QD_OK)
        st = qd__mech_eliminate(ctx, &sf->sys, &sf->elim, &sf->nelim);
    if (st != QD_OK || sf->nelim == 0) {
        if (st == QD_ERR_NOMEM)
            return st;
        qd__ctx_recover(ctx);
        return QD_OK;
    }
    size_t n = sf->sys.n, m = sf->sys.ncon;
    sf->con = qd__calloc(ctx, m + 1, sizeof *sf->con);
    sf->a = qd__calloc(ctx, m * n + 1, sizeof *sf->a);
    sf->qd = qd__calloc(ctx, n + 1, sizeof *sf->qd);
    if (!sf->con || !sf->a || !sf->qd)
        return QD_ERR_NOMEM;
    for (size_t j = 0; j < n; j++)
        sf->qd[j] = qd_jet(ctx, sf->sys.q[j], 1);
    for (size_t i = 0; st == QD_OK && i < m; i++)
        st = surface_row(ctx, sf, i);
    if (st == QD_ERR_NOMEM)
        return st;
    qd__ctx_recover(ctx);
    *ok = st == QD_OK;
    return QD_OK;
}

static qd_con *surface_find(const surface *sf, const char *name) {
    for (size_t i = 0; i < sf->sys.ncon; i++)
        if (sf->con[i].name == name)
            return &sf->con[i];
    return NULL;
}

/* Classify e's nonholonomic constraints on the reduced system, and test the
 * integrable ones together there. */
static qd_status on_surface(qd_ctx *ctx, qd_eom *e, surface *sf) {
    conset rs = {sf->sys.n, sf->sys.q, sf->sys.ncon, sf->con};
    for (size_t k = 0; k < e->ncon; k++) {
        qd_con *c = &e->con[k], *r = surface_find(sf, c->name);
        if (c->kind == QD_CON_HOLONOMIC || !r || r->kind == QD_CON_HOLONOMIC)
            continue;
        if (c->kind == QD_CON_INTEGRABLE) {
            r->kind = QD_CON_INTEGRABLE;
            continue;
        }
        qd_status st = qd__mech_con_classify(ctx, rs.n, rs.q, r);
        if (st != QD_OK)
            return st;
    }
    qd_status st = modulo_holonomic(ctx, &rs);
    for (size_t k = 0; st == QD_OK && k < e->ncon; k++) {
        qd_con *c = &e->con[k], *r = surface_find(sf, c->name);
        if (c->kind == QD_CON_NONHOLONOMIC && r && r->kind == QD_CON_INTEGRABLE) {
            c->kind = QD_CON_INTEGRABLE;
            c->integral = r->integral;
            c->factor = r->factor;
        }
    }
    bool ok = true;
    if (st == QD_OK)
        st = together(ctx, &rs, &ok);
    if (st == QD_OK && !ok)
        demote(&(conset){e->n, e->q, e->ncon, e->con});
    return st;
}

/* After each Pfaffian constraint was classified alone. */
static qd_status classify_all(qd_ctx *ctx, qd_eom *e, const qd__sys *s) {
    conset cs = {e->n, e->q, e->ncon, e->con};
    bool ok = true;
    qd_status st = QD_OK;
    if (count_kind(&cs, QD_CON_HOLONOMIC) && count_kind(&cs, QD_CON_NONHOLONOMIC)) {
        surface sf;
        bool reduced;
        st = surface_init(ctx, e, s, &sf, &reduced);
        if (st == QD_OK && reduced)
            st = on_surface(ctx, e, &sf);
        surface_free(&sf);
        if (st != QD_OK || reduced)
            return st;
        st = modulo_holonomic(ctx, &cs);
    }
    if (st == QD_OK)
        st = together(ctx, &cs, &ok);
    if (st == QD_OK && !ok)
        demote(&cs);
    return st;
}

qd_status qd__mech_con_setup(qd_ctx *ctx, qd_eom *e, const qd__sys *s, bool with_b) {
    size_t n = e->n, m = s->ncon;
    e->ncon = m;
    e->con = qd__calloc(ctx, m ? m : 1, sizeof *e->con);
    e->A = qd__calloc(ctx, m * n + 1, sizeof *e->A);
    e->b = qd__calloc(ctx, m ? m : 1, sizeof *e->b);
    const qd_expr **scratch = qd__calloc(ctx, n ? n : 1, sizeof *scratch);
    qd_status st = e->con && e->A && e->b && scratch ? QD_OK : QD_ERR_NOMEM;
    for (size_t k = 0; st == QD_OK && k < m; k++) {
        e->con[k] = (qd_con){.name = s->con_name[k], .expr = s->con_expr[k], .a = e->A + k * n};
        st = row(ctx, e, k, scratch, with_b);
        if (st == QD_OK && e->con[k].kind != QD_CON_HOLONOMIC)
            st = qd__mech_con_classify(ctx, n, e->q, &e->con[k]);
    }
    if (st == QD_OK)
        st = classify_all(ctx, e, s);
    qd__free(scratch);
    if (st == QD_ERR_NOMEM && qd_ctx_status(ctx) == QD_OK)
        qd_ctx_error(ctx, st, "out of memory deriving the constraints");
    return st;
}

/*
 * src/model/speeds.c - generalized speeds (quasi-velocities), Desloge ch. 67-70.
 *
 *   speeds NAME = EXPR (',' NAME = EXPR)*
 *
 * Each EXPR is u = a(q, t) . q' + b(q, t): linear in the velocities, with at
 * least one of them, and no acceleration (qdot/speeds.h gives the equations
 * that use them).  A speed's name then stands for its definition, as a
 * definition's does, so T, forces and outputs may be written in the speeds;
 * its own symbol (a coordinate-like function of t, so that u' exists) is
 * what the equations in speeds are written in.  Several `speeds` statements
 * add up, in order: qd_model_add_statement adds speeds like any statement.
 */
#include "parser.h"
#include "../base/mem.h"
#include "../base/args.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define SPEED_HINT "a speed is linear in the velocities: u = a(q) q' + b(q, t)"
#define SPEED_USAGE "write: speeds u1 = EXPR, u2 = EXPR"
/* expr.c takes at most four primes in a row */
#define MAX_ORDER 4

static qd_ctx *C(parser *p) { return p->ctx; }

long qd__mdl_find_speed(const qd_model *m, const char *name, size_t n) {
    for (size_t i = 0; i < m->nspeeds; i++)
        if (qd__mdl_name_is(name, 0, n, qd_expr_name(m->speeds[i].sym)))
            return (long)i;
    return -1;
}

/* The first acceleration (or higher derivative) of a coordinate in e, or NULL. */
static const qd_expr *acceleration_in(parser *p, const qd_expr *e) {
    for (size_t j = 0; j < p->m->ncoords; j++)
        for (unsigned order = 2; order <= MAX_ORDER; order++) {
            const qd_expr *a = qd_jet(C(p), p->m->coords[j], order);
            if (a && qd_has(e, a))
                return a;
        }
    return NULL;
}

/* The velocity that enters e nonlinearly, for the message: one whose
 * partial derivative still has a velocity in it, else the first present. */
static const qd_expr *nonlinear_velocity(parser *p, const qd_expr *e, const qd_expr **qd, size_t n) {
    const qd_expr *first = NULL;
    for (size_t j = 0; j < n; j++) {
        if (!qd_has(e, qd[j]))
            continue;
        first = first ? first : qd[j];
        const qd_expr *d = qd_diff(C(p), e, qd[j]);
        for (size_t k = 0; d && k < n; k++)
            if (qd_has(d, qd[k]))
                return qd[j];
    }
    return first;
}

/* Is some coefficient a_j of u = a . q' + b nonzero? */
static bool has_velocity(parser *p, const qd_expr **a, size_t n) {
    for (size_t j = 0; j < n; j++) {
        const qd_expr *s = qd_simplify(C(p), a[j]);
        if (s && !qd_is_zero(s))
            return true;
    }
    return false;
}

/* 1: linear with a velocity, 0: not, -1: out of memory.  The velocity at
 * fault in *bad (NULL when there is none at all). */
static int split_linear(parser *p, const qd_expr *e, const qd_expr **bad) {
    size_t n = p->m->ncoords;
    const qd_expr **qd = qd__malloc(C(p), (2 * n + 1) * sizeof *qd), *rest;
    if (!qd)
        return -1;
    const qd_expr **a = qd + n;
    int r = -1;
    for (size_t j = 0; j < n; j++)
        if (!(qd[j] = qd_jet(C(p), p->m->coords[j], 1)))
            goto done;
    qd_status st = qd_linear_coeffs(C(p), e, n, qd, a, &rest);
    *bad = NULL;
    if (st == QD_ERR_NONLINEAR && qd__ctx_recover(C(p))) {
        *bad = nonlinear_velocity(p, e, qd, n);
        r = 0;
    } else if (st == QD_OK) {
        r = has_velocity(p, a, n) ? 1 : 0;
    }
    if (qd__ctx_nomem(C(p)))
        r = -1;
done:
    qd__free(qd);
    return r;
}

/* The definition is a speed: scalar, no accelerations, linear in the
 * velocities with at least one (Desloge ch. 67: d gamma = a . dq + a0 dt). */
static bool check_definition(parser *p, const value *v) {
    if (!qd__mdl_need_kind(p, v, VK_SCALAR, "for a speed"))
        return false;
    const qd_expr *acc = acceleration_in(p, v->c[0]), *bad = NULL;
    if (acc)
        return qd__mdl_perr(p, v->off, v->len, SPEED_HINT,
                            "a speed cannot depend on an acceleration (%s)", qd_expr_name(acc));
    int r = split_linear(p, v->c[0], &bad);
    if (r < 0)
        return qd__mdl_perr(p, v->off, v->len, NULL, "out of memory");
    if (r == 0 && bad)
        return qd__mdl_perr(p, v->off, v->len, SPEED_HINT,
                            "a speed must be linear in the velocities, but %s enters nonlinearly",
                            qd_expr_name(bad));
    if (r == 0)
        return qd__mdl_perr(p, v->off, v->len, SPEED_HINT,
                            "a speed must contain a velocity, but this is a function of the "
                            "coordinates and t only");
    return true;
}

static bool add_speed(parser *p, const char *name, token at, const qd_expr *def) {
    qd_model *m = p->m;
    const qd_expr *sym = qd_coord(C(p), name);
    if (!sym)
        return qd__mdl_perr(p, at.off, at.len, "choose another name for the speed", "%s",
                            qd_ctx_message(C(p)));
    speed s = {sym, def, NULL, NULL};
    char what[160];
    snprintf(what, sizeof what, "speed:%s", name);
    size_t n = m->nspeeds;
    if (!qd__mdl_push(m->ctx, (void **)&m->speeds, &n, sizeof s, &s))
        return qd__mdl_perr(p, at.off, at.len, NULL, "out of memory");
    m->nspeeds = n;
    if (!qd__mdl_add_where(m, what, at.off, at.len))
        return qd__mdl_perr(p, at.off, at.len, NULL, "out of memory");
    return true;
}

/* NAME '=' EXPR */
static bool one_speed(parser *p) {
    char name[QD_MDL_NAME_MAX];
    token at;
    value v;
    return qd__mdl_named_definition(p, "speed", SPEED_USAGE, NULL, name, &at, &v) &&
           check_definition(p, &v) && add_speed(p, name, at, v.c[0]);
}

/* speeds NAME '=' EXPR (',' NAME '=' EXPR)* */
bool qd__mdl_stmt_speeds(parser *p) {
    token kw = p->lx.tok;
    if (p->m->H) {
        qd_diag h;
        qd_model_where(p->m, "H", &h);
        return qd__mdl_perr(p, kw.off, kw.len, "speeds are for a model given by its energies T "
                            "and V (or L)", "speeds cannot be given with H (line %zu)", h.line);
    }
    do
        if (!one_speed(p))
            return false;
    while (p->lx.tok.kind == TK_COMMA);
    return qd__mdl_end_of_statement(p);
}

bool qd__mdl_no_speeds_yet(parser *p, const char *what, size_t off, size_t len) {
    if (p->m->nspeeds == 0)
        return true;
    qd_diag s;
    char key[160];
    snprintf(key, sizeof key, "speed:%.120s", qd_expr_name(p->m->speeds[0].sym));
    qd_model_where(p->m, key, &s);
    return qd__mdl_perr(p, off, len, "speeds are for a model given by its energies T and V (or L)",
                        "%s cannot be given with speeds (line %zu)", what, s.line);
}

/* ---- accessors ----------------------------------------------------------- */

static const speed *speed_at(const qd_model *m, size_t i) {
    return i < m->nspeeds ? &m->speeds[i] : NULL;
}

size_t qd_model_nspeeds(const qd_model *m) { QD_ARGS(0, m); return m->nspeeds; }

const qd_expr *qd_model_speed(const qd_model *m, size_t i) {
    QD_ARGS(NULL, m);
    const speed *s = speed_at(m, i);
    return s ? s->sym : NULL;
}

const qd_expr *qd_model_speed_definition(const qd_model *m, size_t i) {
    QD_ARGS(NULL, m);
    const speed *s = speed_at(m, i);
    return s ? s->def : NULL;
}

const qd_expr *qd_model_speed_initial(const qd_model *m, size_t i) {
    QD_ARGS(NULL, m);
    const speed *s = speed_at(m, i);
    return s ? s->init : NULL;
}

const qd_expr *qd_model_speed_initial_definition(const qd_model *m, size_t i) {
    QD_ARGS(NULL, m);
    const speed *s = speed_at(m, i);
    return s ? s->init_def : NULL;
}

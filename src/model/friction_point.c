/*
 * src/model/friction_point.c - `friction MU on POINT against CONSTRAINT`:
 * a point sliding on a rough surface (issue 18).
 *
 * CONSTRAINT, phi(q) = 0, keeps the point r(q) (a position defined as
 * NAME = (x, y, z)) on a fixed surface S(r) = 0, phi = S(r(q)).  Its
 * multiplier gives the Cartesian force lambda grad S, so the normal force
 * is |lambda| |grad S|, and grad S solves J^T grad S = grad_q phi, J the
 * Jacobian dr/dq restricted to the coordinates that move the point (2 or 3
 * of them, a square block: Cramer's rule).  The slip velocity is the
 * point's velocity r', tangent to the surface; the contact's velocity
 * constraints are its components on a unit tangent basis
 *
 *   in a plane (2 coordinates):  t = (-n2, n1)/|n|, one direction;
 *   in space:                    t1 = n x e / |n x e|, t2 = n x t1 / |n|,
 *
 * e the axis of a component of n that is identically 0, else x (so the
 * basis degenerates where the normal is along x: give such a surface a
 * normal with a zero component, or turn the axes).  They are added as the
 * constraints POINT_slip1 (and POINT_slip2), and the contact is the 2-D
 * (or 1-D) friction contact of src/model/friction.c.
 */
#include "parser.h"
#include "../base/mem.h"

#include <stdio.h>
#include <string.h>

typedef const qd_expr *E;

static const char *const usage = "write: friction MU on POINT against CONSTRAINT";

static qd_ctx *C(parser *p) { return p->ctx; }

/* The identifier at the token as a C string (consumed). */
static bool take_name(parser *p, char *buf, size_t cap, token *at, const char *what) {
    *at = p->lx.tok; /* set on every path: the caller's token is never left unset */
    if (p->lx.tok.kind != TK_IDENT)
        return qd__mdl_perr_tok(p, usage, "expected %s, found %s", what,
                                qd__mdl_lex_tk_name(p->lx.tok.kind));
    snprintf(buf, cap, "%.*s", (int)(at->len < cap - 1 ? at->len : cap - 1), p->lx.src + at->off);
    qd__mdl_lex_next(&p->lx);
    return true;
}

static bool keyword(parser *p, const char *word) {
    if (!qd__mdl_lex_is(&p->lx, word))
        return qd__mdl_perr_tok(p, usage, "expected '%s'", word);
    qd__mdl_lex_next(&p->lx);
    return true;
}

static long find_constraint(const qd_model *m, const char *name) {
    for (size_t i = 0; i < m->ncons; i++)
        if (!strcmp(m->con_names[i], name))
            return (long)i;
    return -1;
}

static E det2(qd_ctx *c, E a, E b, E d, E e) { return qd_sub(c, qd_mul(c, a, e), qd_mul(c, b, d)); }

/* Row-major 2x2 or 3x3 determinant. */
static E det(qd_ctx *c, size_t k, E *a) {
    if (k == 2)
        return det2(c, a[0], a[1], a[2], a[3]);
    E m0 = det2(c, a[4], a[5], a[7], a[8]), m1 = det2(c, a[3], a[5], a[6], a[8]);
    E m2 = det2(c, a[3], a[4], a[6], a[7]);
    return qd_add(c, qd_sub(c, qd_mul(c, a[0], m0), qd_mul(c, a[1], m1)), qd_mul(c, a[2], m2));
}

/* The point's geometry: the coordinates that move it (cols), the space
 * axes it moves along (rows), k of each. */
typedef struct geom {
    size_t cols[3], rows[3], k;
    E r[3], n[3];          /* n = grad S on the rows' axes, 0 elsewhere */
} geom;

static bool find_block(parser *p, geom *g, E phi, token at) {
    const qd_model *m = p->m;
    size_t nrows = 0;
    g->k = 0;
    for (size_t j = 0; j < m->ncoords; j++) {
        bool moves = qd_has(g->r[0], m->coords[j]) || qd_has(g->r[1], m->coords[j]) ||
                     qd_has(g->r[2], m->coords[j]);
        if (moves && g->k == 3)
            return qd__mdl_perr(p, at.off, at.len, "place the point with 2 or 3 coordinates",
                                "the point moves with more than 3 coordinates");
        if (moves)
            g->cols[g->k++] = j;
        else if (qd_has(phi, m->coords[j]))
            return qd__mdl_perr(p, at.off, at.len, "the surface is fixed: write it in the "
                                "point's coordinates", "the surface depends on '%s', which "
                                "does not move the point", qd_expr_name(m->coords[j]));
    }
    for (size_t i = 0; i < 3; i++)
        if (!qd_is_number(g->r[i]))
            g->rows[nrows++] = i;
    if (g->k < 2 || nrows != g->k)
        return qd__mdl_perr(p, at.off, at.len, "a point on a surface in space takes 3 "
                            "coordinates, on a curve in a plane 2",
                            "the point moves along %zu axes with %zu coordinates", nrows, g->k);
    return true;
}

/* n = grad S from J^T n = grad_q phi (Cramer), on the rows' axes. */
static void normal(qd_ctx *c, geom *g, E phi, const qd_model *m) {
    size_t k = g->k;
    E Jt[9], rhs[3];
    for (size_t a = 0; a < k; a++) {
        rhs[a] = qd_diff(c, phi, m->coords[g->cols[a]]);
        for (size_t b = 0; b < k; b++)
            Jt[a * k + b] = qd_diff(c, g->r[g->rows[b]], m->coords[g->cols[a]]);
    }
    E D = det(c, k, Jt);
    for (size_t i = 0; i < 3; i++)
        g->n[i] = qd_int(c, 0);
    for (size_t b = 0; b < k; b++) {
        E A[9];
        memcpy(A, Jt, sizeof A);
        for (size_t a = 0; a < k; a++)
            A[a * k + b] = rhs[a];
        g->n[g->rows[b]] = qd_simplify(c, qd_div(c, det(c, k, A), D));
    }
}

static E dot3(qd_ctx *c, const E *a, const E *b) {
    return qd_add(c, qd_add(c, qd_mul(c, a[0], b[0]), qd_mul(c, a[1], b[1])),
                  qd_mul(c, a[2], b[2]));
}

static void cross3(qd_ctx *c, const E *a, const E *b, E *out) {
    out[0] = qd_sub(c, qd_mul(c, a[1], b[2]), qd_mul(c, a[2], b[1]));
    out[1] = qd_sub(c, qd_mul(c, a[2], b[0]), qd_mul(c, a[0], b[2]));
    out[2] = qd_sub(c, qd_mul(c, a[0], b[1]), qd_mul(c, a[1], b[0]));
}

/* The slip velocities t . r' (1 or 2 of them) into s. */
static size_t slips(qd_ctx *c, const geom *g, E *s) {
    E v[3], t1[3], t2[3], e[3];
    for (size_t i = 0; i < 3; i++)
        v[i] = qd_dt(c, g->r[i]);
    E nn = qd_sqrt(c, dot3(c, g->n, g->n));
    if (g->k == 2) {
        size_t a = g->rows[0], b = g->rows[1];
        s[0] = qd_div(c, qd_sub(c, qd_mul(c, g->n[a], v[b]), qd_mul(c, g->n[b], v[a])), nn);
        return 1;
    }
    size_t axis = 0;
    for (size_t i = 3; i-- > 0;)
        if (qd_is_zero(g->n[i]))
            axis = i;
    for (size_t i = 0; i < 3; i++)
        e[i] = qd_int(c, i == axis);
    cross3(c, g->n, e, t1);
    E l1 = qd_sqrt(c, dot3(c, t1, t1));
    cross3(c, g->n, t1, t2);
    s[0] = qd_div(c, dot3(c, t1, v), l1);
    s[1] = qd_div(c, dot3(c, t2, v), qd_mul(c, l1, nn));
    return 2;
}

static bool add_slip_constraint(parser *p, const char *point, size_t i, E e, token at) {
    char name[96];
    snprintf(name, sizeof name, "%.60s_slip%zu", point, i + 1);
    if (qd__mdl_constraint_named(p->m, name))
        return qd__mdl_perr(p, at.off, at.len, "one friction statement per point",
                            "constraint '%s' exists already", name);
    return qd__mdl_push_constraint(p, name, e, at.off, at.len);
}

/* The contact of point (r) on constraint ci. */
static bool point_contact(parser *p, fclause *fc, const char *point, const E *r, size_t ci,
                          token at) {
    qd_model *m = p->m;
    qd_ctx *c = C(p);
    geom g = {.r = {r[0], r[1], r[2]}};
    E phi = m->cons[ci], s[2];
    for (size_t j = 0; j < m->ncoords; j++)
        if (qd_has(phi, qd_jet(c, m->coords[j], 1)))
            return qd__mdl_perr(p, at.off, at.len, "name the constraint that holds the point "
                                "on the surface, a relation of the positions",
                                "'%s' is not a surface: it has velocities", m->con_names[ci]);
    if (!find_block(p, &g, phi, at))
        return false;
    normal(c, &g, phi, m);
    size_t ns = slips(c, &g, s), con[2];
    for (size_t i = 0; i < ns; i++) {
        s[i] = s[i] ? qd_simplify(c, s[i]) : NULL;
        if (!s[i])
            return qd__mdl_perr(p, at.off, at.len, NULL, "%s", qd_ctx_message(c));
        if (!add_slip_constraint(p, point, i, s[i], at))
            return false;
        con[i] = m->ncons - 1;
    }
    snprintf(fc->normal_con, sizeof fc->normal_con, "%s", m->con_names[ci]);
    fc->normal_off = at.off;
    fc->normal_len = at.len;
    if (!qd__mdl_friction_add(p, fc, point, QD_CONTACT_POINT, con, ns))
        return false;
    m->contacts[m->ncontacts - 1].normal_scale =
        qd_simplify(c, qd_sqrt(c, dot3(c, g.n, g.n)));
    return true;
}

bool qd__mdl_stmt_friction(parser *p) {
    fclause fc;
    if (!qd__mdl_friction_parse(p, &fc))
        return false;
    if (fc.normal || fc.normal_con[0])
        return qd__mdl_perr(p, fc.off, fc.len, "the surface's constraint gives the normal "
                            "force: drop 'normal N'", "a point's normal force is given twice");
    char point[64], con[64];
    token pat, cat;
    if (!keyword(p, "on") || !take_name(p, point, sizeof point, &pat, "a point's name"))
        return false;
    const def *d = qd__mdl_find_def(p->m, point, strlen(point));
    if (!d || d->v.kind != VK_VECTOR)
        return qd__mdl_perr(p, pat.off, pat.len, "define it first: P = (x, y, z)",
                            "'%s' is not a point (a position defined as a vector)", point);
    if (!keyword(p, "against") || !take_name(p, con, sizeof con, &cat, "a constraint's name"))
        return false;
    long ci = find_constraint(p->m, con);
    if (ci < 0)
        return qd__mdl_perr(p, cat.off, cat.len, "give the constraint that keeps the point "
                            "on the surface first: constraint NAME: ... = 0",
                            "no constraint named '%s'", con);
    if (!qd__mdl_end_of_statement(p))
        return false;
    return point_contact(p, &fc, point, d->v.c, (size_t)ci, pat);
}

/*
 * src/model/roll.c - rolling without slipping: the rolls statement.
 *
 *   rolls BODY on plane(n, r0) [moving V | turning W] as SHAPE
 *   rolls BODY (on | inside) cylinder(R, P0, d) [moving V | turning W] as SHAPE
 *   SHAPE := sphere(a) | disk(a) | cylinder(a)
 *
 * A body touching a surface at the point p rolls without slipping when the
 * material point of the body at p moves with the surface there:
 *
 *   v_c + w x (p - c) = v_surface(p)          (Desloge ch. 64 Ex. 2, C11;
 *                                               Byerly Art. 10a, TC: "contact
 *                                               point velocity = 0")
 *
 * with c the centre of mass and w = omega_space(BODY).  Its two components
 * along the surface are Pfaffian constraints (BODY_roll1, BODY_roll2); the
 * normal component is the time derivative of the holonomic contact
 * condition (BODY_contact: the gap between body and surface, 0 at contact),
 * which is kept in its integrated form.  A generated constraint that
 * simplifies to 0 (the user's coordinates already satisfy it) is left out.
 *
 * The contact point, with m the unit normal of the surface at the contact
 * (pointing to the body's side) and k = R e_z the body's symmetry axis:
 *   sphere:   p = c - a m
 *   cylinder: p = c - a m        (lying on its side: k perpendicular to m)
 *   disk:     p = c - a u,  u = (m - (m.k) k)/|m - (m.k) k|, the rim point
 *             lowest along m (a thin disk, or a cylinder's rim edge)
 * On a plane m = n/|n|; on a cylinder of axis P0 + s d, m = +-rho/|rho| with
 * rho the part of c - P0 across the axis (+ on it, - inside it), and the
 * disk or cylinder rolling there must have its axis along d.
 *
 * Square roots of squares are taken positive: |m - (m.k) k| for
 * euler(phi, theta, psi) on a horizontal plane is sin(theta) (the disk
 * leans, 0 < theta < pi), and |rho| for a centre at r (sin q, cos q) is r.
 */
#include "parser.h"
#include "../base/mem.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef const qd_expr *E;

typedef enum surface { ON_PLANE, ON_CYLINDER, IN_CYLINDER } surface;
typedef enum shape { SPHERE, DISK, CYLINDER, NSHAPES } shape;

static const char *const shape_names[NSHAPES] = {"sphere", "disk", "cylinder"};

/* What one rolls statement says. */
typedef struct rolling {
    const body *b;
    token name;
    surface surf;
    E n[3];            /* plane: its normal; cylinder: its axis direction d */
    E r0[3];           /* a point of the plane, or of the axis */
    E radius;          /* the fixed cylinder's */
    E vs[3];           /* moving V: the surface's velocity */
    E rate;            /* turning W: about the normal through r0, or the axis */
    bool moving, turning, has_shape;
    shape sh;
    E a;
    value shape_at;    /* the span of SHAPE(a), for its errors */
} rolling;

/* The contact: the point, the gap (0 at contact) and two tangents. */
typedef struct contact {
    E p[3];
    E gap;
    E t1[3], t2[3];
} contact;

static const char *usage = "write: rolls BODY on plane((0, 0, 1), (0, 0, 0)) as sphere(a)";

static qd_ctx *C(parser *p) { return p->ctx; }

/* ---- vectors ----------------------------------------------------------------- */

static E dot(qd_ctx *c, E const a[3], E const b[3]) {
    return qd_add_n(c, 3, (E[]){qd_mul(c, a[0], b[0]), qd_mul(c, a[1], b[1]),
                                qd_mul(c, a[2], b[2])});
}

static void cross(qd_ctx *c, E const a[3], E const b[3], E out[3]) {
    E r[3];
    for (int i = 0; i < 3; i++) {
        int j = (i + 1) % 3, k = (i + 2) % 3;
        r[i] = qd_sub(c, qd_mul(c, a[j], b[k]), qd_mul(c, a[k], b[j]));
    }
    memcpy(out, r, sizeof r);
}

/* out = a + s b */
static void axpy(qd_ctx *c, E const a[3], E s, E const b[3], E out[3]) {
    for (int i = 0; i < 3; i++)
        out[i] = qd_add(c, a[i], qd_mul(c, s, b[i]));
}

static void scale(qd_ctx *c, E s, E const a[3], E out[3]) {
    for (int i = 0; i < 3; i++)
        out[i] = qd_simplify(c, qd_mul(c, s, a[i]));
}

static bool is_zero_vec(qd_ctx *c, E const a[3]) {
    for (int i = 0; i < 3; i++)
        if (!qd_is_zero(qd_simplify(c, a[i])))
            return false;
    return true;
}

/* ---- square roots of squares ----------------------------------------------- */

static bool square_root_num(qd_ctx *c, E x, E *out) {
    long num, den;
    if (!qd_rational_get(x, &num, &den) || num < 0)
        return false;
    long rn = 0, rd = 0;
    while (rn * rn < num)
        rn++;
    while (rd * rd < den)
        rd++;
    if (rn * rn != num || rd * rd != den)
        return false;
    *out = qd_rat(c, rn, rd);
    return true;
}

/* X^(2k) -> X^k; a rational square -> its root; else false. */
static bool square_root_factor(qd_ctx *c, E x, E *out) {
    if (qd_is_number(x))
        return square_root_num(c, x, out);
    long num, den;
    if (qd_expr_kind(x) != QD_POW || !qd_rational_get(qd_expr_arg(x, 1), &num, &den) ||
        den != 1 || num % 2 != 0)
        return false;
    *out = qd_powi(c, qd_expr_arg(x, 0), num / 2);
    return true;
}

/* sqrt(x), with sqrt(X^2) = X (X > 0 on the motion: see the head comment). */
static E root(qd_ctx *c, E x) {
    x = qd_simplify(c, x);
    E r;
    if (!x || square_root_factor(c, x, &r))
        return x ? r : NULL;
    if (qd_expr_kind(x) == QD_MUL) {
        size_t n = qd_expr_nargs(x);
        E f[16];
        bool all = n <= 16;
        for (size_t i = 0; all && i < n; i++)
            all = square_root_factor(c, qd_expr_arg(x, i), &f[i]);
        if (all)
            return qd_mul_n(c, n, f);
    }
    return qd_sqrt(c, x);
}

/* v/|v| */
static void unit(qd_ctx *c, E const v[3], E out[3]) {
    E len = root(c, dot(c, v, v));
    scale(c, qd_pow(c, len, qd_int(c, -1)), v, out);
}

/* ---- geometry ----------------------------------------------------------------- */

static void body_axis(const body *b, E k[3]) {
    k[0] = b->R[2];
    k[1] = b->R[5];
    k[2] = b->R[8];
}

/* p = c - a u for the body's shape, m the surface's unit normal at the
 * contact (toward the body); *reach = p's distance from c along m. */
static bool contact_point(parser *p, const rolling *r, E const m[3], contact *ct, E *reach) {
    qd_ctx *c = C(p);
    E u[3], k[3];
    memcpy(u, m, sizeof u);
    *reach = r->a;
    body_axis(r->b, k);
    E mk = qd_simplify(c, dot(c, m, k));
    if (r->sh == DISK && !qd_is_zero(mk)) {
        E w[3], w2 = qd_simplify(c, qd_sub(c, qd_int(c, 1), qd_powi(c, mk, 2)));
        if (qd_is_zero(w2))
            return qd__mdl_perr(p, r->shape_at.off, r->shape_at.len, "a disk rolls on its rim: tilt it",
                        "the disk lies flat on the surface (its axis is along the normal)");
        axpy(c, m, qd_neg(c, mk), k, w);
        E len = root(c, w2);
        scale(c, qd_pow(c, len, qd_int(c, -1)), w, u);
        *reach = qd_mul(c, r->a, len);
    } else if (r->sh == CYLINDER && !qd_is_zero(mk)) {
        return qd__mdl_perr(p, r->shape_at.off, r->shape_at.len,
                    "a cylinder rolls on its side, body z along the surface; for a tilted one "
                    "touching on its rim edge write: as disk(a)",
                    "the cylinder's axis (body z) is not parallel to the surface");
    }
    axpy(c, r->b->r, qd_neg(c, r->a), u, ct->p);
    return true;
}

static bool plane_contact(parser *p, const rolling *r, contact *ct) {
    qd_ctx *c = C(p);
    E n[3], rel[3], reach;
    unit(c, r->n, n);
    if (!contact_point(p, r, n, ct, &reach))
        return false;
    axpy(c, r->b->r, qd_int(c, -1), r->r0, rel);
    ct->gap = qd_sub(c, dot(c, rel, n), reach);
    /* t1 = e_y x n (e_x x n when n is along y): e_x, e_y for n = e_z */
    E zero = qd_int(c, 0), one = qd_int(c, 1);
    E ey[3] = {zero, one, zero}, ex[3] = {one, zero, zero}, t[3];
    cross(c, ey, n, t);
    if (is_zero_vec(c, t))
        cross(c, ex, n, t);
    unit(c, t, ct->t1);
    cross(c, n, ct->t1, ct->t2);
    return true;
}

static bool parallel_axis(parser *p, const rolling *r, E const d[3]) {
    E k[3], x[3];
    body_axis(r->b, k);
    cross(C(p), k, d, x);
    if (r->sh == SPHERE || is_zero_vec(C(p), x))
        return true;
    return qd__mdl_perr(p, r->shape_at.off, r->shape_at.len,
                "on a cylinder the rolling disk or cylinder turns about an axis parallel to "
                "the fixed one",
                "the %s's axis (body z) is not parallel to the cylinder's axis",
                shape_names[r->sh]);
}

static bool cylinder_contact(parser *p, const rolling *r, contact *ct) {
    qd_ctx *c = C(p);
    E d[3], rel[3], rho[3], e[3], m[3], reach;
    unit(c, r->n, d);
    if (!parallel_axis(p, r, d))
        return false;
    axpy(c, r->b->r, qd_int(c, -1), r->r0, rel);
    axpy(c, rel, qd_neg(c, dot(c, rel, d)), d, rho);
    E dist = root(c, dot(c, rho, rho));
    if (qd_is_zero(dist))
        return qd__mdl_perr(p, r->name.off, r->name.len, NULL,
                    "the body's centre is on the cylinder's axis: it cannot touch the surface");
    scale(c, qd_pow(c, dist, qd_int(c, -1)), rho, e);
    bool inside = r->surf == IN_CYLINDER;
    scale(c, qd_int(c, inside ? -1 : 1), e, m);
    if (!contact_point(p, r, m, ct, &reach))
        return false;
    ct->gap = inside ? qd_sub(c, qd_sub(c, r->radius, dist), reach)
                     : qd_sub(c, qd_sub(c, dist, r->radius), reach);
    cross(c, d, e, ct->t1);
    memcpy(ct->t2, d, sizeof ct->t2);
    return true;
}

/* v_c + w x (p - c) - v_surface(p) */
static void slip_velocity(qd_ctx *c, const rolling *r, const contact *ct, E out[3]) {
    E arm[3], spin[3], vs[3];
    axpy(c, ct->p, qd_int(c, -1), r->b->r, arm);
    cross(c, r->b->ws, arm, spin);
    for (int i = 0; i < 3; i++)
        vs[i] = r->moving ? r->vs[i] : qd_int(c, 0);
    if (r->turning) {
        E axis[3], from[3];
        unit(c, r->n, axis);
        axpy(c, ct->p, qd_int(c, -1), r->r0, from);
        cross(c, axis, from, vs);
        for (int i = 0; i < 3; i++)
            vs[i] = qd_mul(c, r->rate, vs[i]);
    }
    for (int i = 0; i < 3; i++)
        out[i] = qd_sub(c, qd_add(c, qd_dt(c, r->b->r[i]), spin[i]), vs[i]);
}

/* ---- adding the constraints ------------------------------------------------- */

static bool constraint_named(const qd_model *m, const char *name) {
    for (size_t i = 0; i < m->ncons; i++)
        if (!strcmp(m->con_names[i], name))
            return true;
    return false;
}

/* BODY_roll1, BODY_roll2, BODY_contact; a second rolls line for the same
 * body goes on with BODY_roll3, BODY_roll4, BODY_contact2. */
static void constraint_names(const qd_model *m, const char *body, char names[3][80]) {
    for (int k = 1;; k++) {
        snprintf(names[0], 80, "%.60s_roll%d", body, 2 * k - 1);
        snprintf(names[1], 80, "%.60s_roll%d", body, 2 * k);
        if (k == 1)
            snprintf(names[2], 80, "%.60s_contact", body);
        else
            snprintf(names[2], 80, "%.60s_contact%d", body, k);
        if (!constraint_named(m, names[0]) && !constraint_named(m, names[1]) &&
            !constraint_named(m, names[2]))
            return;
    }
}

/* idx[i]: the model's index of constraint i (slip 1, slip 2, gap), or
 * (size_t)-1 where it vanishes identically and is not added. */
static bool generate(parser *p, const rolling *r, size_t idx[3]) {
    qd_ctx *c = C(p);
    contact ct;
    bool ok = r->surf == ON_PLANE ? plane_contact(p, r, &ct) : cylinder_contact(p, r, &ct);
    if (!ok)
        return false;
    E slip[3], e[3];
    slip_velocity(c, r, &ct, slip);
    e[0] = qd_simplify(c, dot(c, ct.t1, slip));
    e[1] = qd_simplify(c, dot(c, ct.t2, slip));
    e[2] = qd_simplify(c, ct.gap);
    for (int i = 0; i < 3; i++)
        if (!e[i])
            return qd__mdl_perr(p, r->name.off, r->name.len, NULL, "%s", qd_ctx_message(c));
    char names[3][80];
    constraint_names(p->m, r->b->name, names);
    for (int i = 0; i < 3; i++) {
        idx[i] = (size_t)-1;
        if (qd_is_zero(e[i]))
            continue;
        if (qd_is_number(e[i]))
            return qd__mdl_perr(p, r->name.off, r->name.len, "check the surface and the body's position",
                        "the body can never touch the surface: the gap is %g",
                        qd_number_value(e[i]));
        if (!qd__mdl_push_constraint(p, names[i], e[i], r->name.off, r->name.len))
            return false;
        idx[i] = p->m->ncons - 1;
    }
    return true;
}

/* `friction ...` after a rolls statement: the two slip components are one
 * contact, its normal force the gap constraint's multiplier unless given. */
static bool add_friction(parser *p, const rolling *r, fclause *fc, const size_t idx[3]) {
    size_t con[2], ncon = 0;
    for (int i = 0; i < 2; i++)
        if (idx[i] != (size_t)-1)
            con[ncon++] = idx[i];
    if (!ncon)
        return qd__mdl_perr(p, fc->off, fc->len, "the body cannot slip on this surface",
                            "rolling without slip velocity: friction has nothing to act on");
    if (!fc->normal && !fc->normal_con[0] && idx[2] != (size_t)-1) {
        snprintf(fc->normal_con, sizeof fc->normal_con, "%s", p->m->con_names[idx[2]]);
        fc->normal_off = r->name.off;
        fc->normal_len = r->name.len;
    }
    return qd__mdl_friction_add(p, fc, r->b->name, QD_CONTACT_ROLLING, con, ncon);
}

/* ---- parsing ------------------------------------------------------------------ */

static bool expect_comma(parser *p, const char *hint) {
    if (p->lx.tok.kind == TK_COMMA) {
        qd__mdl_lex_next(&p->lx);
        return true;
    }
    return qd__mdl_perr_tok(p, hint, "expected ',', found %s", qd__mdl_lex_tk_name(p->lx.tok.kind));
}

/* An optional label before an argument: plane(normal n, through r0). */
static void skip_label(parser *p, const char *word) {
    if (!qd__mdl_lex_is(&p->lx, word))
        return;
    lexer ahead = p->lx;
    qd__mdl_lex_next(&ahead);
    tk_kind k = ahead.tok.kind;
    if (k == TK_LPAREN || k == TK_IDENT || k == TK_NUMBER || k == TK_MINUS)
        p->lx = ahead;
}

/* plane '(' [normal] n ',' [through] r0 ')' */
static bool parse_plane(parser *p, rolling *r) {
    static const char *hint = "write: plane((0, 0, 1), (0, 0, 0)), the normal and a point";
    size_t open = p->lx.tok.off;
    if (p->lx.tok.kind != TK_LPAREN)
        return qd__mdl_perr_tok(p, hint, "expected '(' after 'plane'");
    qd__mdl_lex_next(&p->lx);
    value n, r0;
    skip_label(p, "normal");
    if (!qd__mdl_parse_vector(p, &n, "a plane's normal") || !expect_comma(p, hint))
        return false;
    skip_label(p, "through");
    if (!qd__mdl_parse_vector(p, &r0, "a point of the plane") || !qd__mdl_expect_close(p, open))
        return false;
    if (is_zero_vec(C(p), n.c))
        return qd__mdl_perr(p, n.off, n.len, hint, "the plane's normal is zero");
    memcpy(r->n, n.c, sizeof r->n);
    memcpy(r->r0, r0.c, sizeof r->r0);
    return true;
}

/* cylinder '(' R ',' P0 ',' d ')' */
static bool parse_cylinder(parser *p, rolling *r) {
    static const char *hint = "write: cylinder(R, (0, 0, 0), (0, 0, 1)): the radius, a point "
                              "of the axis and its direction";
    size_t open = p->lx.tok.off;
    if (p->lx.tok.kind != TK_LPAREN)
        return qd__mdl_perr_tok(p, hint, "expected '(' after 'cylinder'");
    qd__mdl_lex_next(&p->lx);
    value P0, d;
    if (!qd__mdl_parse_scalar(p, &r->radius, "a radius") || !expect_comma(p, hint) ||
        !qd__mdl_parse_vector(p, &P0, "a point of the axis") || !expect_comma(p, hint) ||
        !qd__mdl_parse_vector(p, &d, "the axis direction") || !qd__mdl_expect_close(p, open))
        return false;
    if (is_zero_vec(C(p), d.c))
        return qd__mdl_perr(p, d.off, d.len, hint, "the cylinder's axis direction is zero");
    memcpy(r->n, d.c, sizeof r->n);
    memcpy(r->r0, P0.c, sizeof r->r0);
    return true;
}

/* (on | inside) (plane | cylinder) '(' ... ')' */
static bool parse_surface(parser *p, rolling *r) {
    bool inside = qd__mdl_lex_is(&p->lx, "inside");
    if (!inside && !qd__mdl_lex_is(&p->lx, "on"))
        return qd__mdl_perr_tok(p, usage, "expected 'on' or 'inside', found %s",
                                qd__mdl_lex_tk_name(p->lx.tok.kind));
    qd__mdl_lex_next(&p->lx);
    if (qd__mdl_lex_is(&p->lx, "plane") && !inside) {
        r->surf = ON_PLANE;
        qd__mdl_lex_next(&p->lx);
        return parse_plane(p, r);
    }
    if (qd__mdl_lex_is(&p->lx, "cylinder")) {
        r->surf = inside ? IN_CYLINDER : ON_CYLINDER;
        qd__mdl_lex_next(&p->lx);
        return parse_cylinder(p, r);
    }
    if (qd__mdl_lex_is(&p->lx, "plane"))
        return qd__mdl_perr_tok(p, "a body rolls on a plane, not inside it: rolls BODY on plane(n, r0)",
                        "'inside' a plane");
    return qd__mdl_perr_tok(p, "the surfaces are plane(n, r0) and cylinder(R, P0, d)",
                    "unknown surface: expected 'plane' or 'cylinder'");
}

static int shape_index(const parser *p) {
    for (int i = 0; i < NSHAPES; i++)
        if (qd__mdl_lex_is(&p->lx, shape_names[i]))
            return i;
    return -1;
}

static bool unknown_shape(parser *p) {
    char word[64], hint[160];
    size_t n = p->lx.tok.len < 63 ? p->lx.tok.len : 63;
    snprintf(word, sizeof word, "%.*s", (int)n, p->lx.src + p->lx.tok.off);
    const char *near = qd__diag_nearest(word, n, shape_names, NSHAPES);
    if (!strcmp(word, "ring") || !strcmp(word, "hoop"))
        near = "disk";
    else if (!strcmp(word, "shell") || !strcmp(word, "ball"))
        near = "sphere";
    if (near)
        snprintf(hint, sizeof hint, "did you mean '%s'? (it touches as %s(a) does)", near, near);
    else
        snprintf(hint, sizeof hint, "the shapes are sphere(a), disk(a) and cylinder(a)");
    return qd__mdl_perr_tok(p, hint, "unknown rolling shape '%s'", word);
}

/* as (sphere | disk | cylinder) '(' a ')' */
static bool parse_shape(parser *p, rolling *r) {
    int k = p->lx.tok.kind == TK_IDENT ? shape_index(p) : -1;
    if (k < 0)
        return p->lx.tok.kind == TK_IDENT ? unknown_shape(p)
                                          : qd__mdl_perr_tok(p, usage, "expected a shape, found %s",
                                                     qd__mdl_lex_tk_name(p->lx.tok.kind));
    size_t off = p->lx.tok.off;
    qd__mdl_lex_next(&p->lx);
    size_t open = p->lx.tok.off;
    if (p->lx.tok.kind != TK_LPAREN)
        return qd__mdl_perr_tok(p, "give its radius: sphere(a)", "expected '(' after '%s'",
                        shape_names[k]);
    qd__mdl_lex_next(&p->lx);
    if (!qd__mdl_parse_scalar(p, &r->a, "a radius") || !qd__mdl_expect_close(p, open))
        return false;
    r->sh = (shape)k;
    r->has_shape = true;
    r->shape_at.off = off;
    r->shape_at.len = p->lx.tok.off - off;
    return true;
}

/* (moving V | turning W | as SHAPE)*, each once */
static bool parse_clauses(parser *p, rolling *r) {
    while (p->lx.tok.kind == TK_IDENT && !qd__mdl_friction_ahead(p)) {
        bool moving = qd__mdl_lex_is(&p->lx, "moving"), turning = qd__mdl_lex_is(&p->lx, "turning");
        bool as = qd__mdl_lex_is(&p->lx, "as");
        if (!moving && !turning && !as)
            return qd__mdl_perr_tok(p, "after the surface: as SHAPE, moving (vx, vy, vz) or turning W",
                            "expected 'as', 'moving' or 'turning'");
        if ((moving || turning) && (r->moving || r->turning))
            return qd__mdl_perr_tok(p, "give the surface's motion once: moving V or turning W",
                            "the surface's motion is given twice");
        if (as && r->has_shape)
            return qd__mdl_perr_tok(p, usage, "the shape is given twice");
        qd__mdl_lex_next(&p->lx);
        value v;
        bool ok = moving  ? qd__mdl_parse_vector(p, &v, "the surface's velocity")
                : turning ? qd__mdl_parse_scalar(p, &r->rate, "a rate of turn")
                          : parse_shape(p, r);
        if (!ok)
            return false;
        if (moving)
            memcpy(r->vs, v.c, sizeof r->vs);
        r->moving |= moving;
        r->turning |= turning;
    }
    return true;
}

/* The rolling body: declared, and turning. */
static bool parse_body(parser *p, rolling *r) {
    qd_model *m = p->m;
    if (p->lx.tok.kind != TK_IDENT)
        return qd__mdl_perr_tok(p, usage, "expected a body's name, found %s",
                                qd__mdl_lex_tk_name(p->lx.tok.kind));
    r->name = p->lx.tok;
    r->b = qd__mdl_find_body(m, p->lx.src + r->name.off, r->name.len);
    char word[64], hint[160];
    size_t n = r->name.len < 63 ? r->name.len : 63;
    snprintf(word, sizeof word, "%.*s", (int)n, p->lx.src + r->name.off);
    if (!r->b) {
        const char **names = qd__malloc(p->ctx, (m->nbodies + 1) * sizeof *names);
        for (size_t i = 0; names && i < m->nbodies; i++)
            names[i] = m->bodies[i].name;
        const char *near = names ? qd__diag_nearest(word, n, names, m->nbodies) : NULL;
        snprintf(hint, sizeof hint, near ? "did you mean '%s'?" : "%s",
                 near ? near : "declare it first: body NAME mass M inertia I at r orientation R");
        qd__free(names);
        return qd__mdl_perr_tok(p, hint, "'%s' is not a body", word);
    }
    if (is_zero_vec(C(p), r->b->ws))
        return qd__mdl_perr_tok(p, "give it an orientation that turns: orientation euler(phi, theta, psi)",
                        "body '%s' has no orientation (it cannot turn), so it cannot roll", word);
    qd__mdl_lex_next(&p->lx);
    return true;
}

bool qd__mdl_stmt_rolls(parser *p) {
    qd__mdl_lex_next(&p->lx);
    rolling r;
    memset(&r, 0, sizeof r);
    if (!parse_body(p, &r) || !parse_surface(p, &r) || !parse_clauses(p, &r))
        return false;
    if (!r.has_shape)
        return qd__mdl_perr(p, r.name.off, r.name.len,
                    "add the body's shape: as sphere(a), as disk(a) or as cylinder(a)",
                    "rolls needs the shape that touches the surface");
    fclause fc;
    bool friction = qd__mdl_friction_ahead(p);
    if (friction && !qd__mdl_friction_parse(p, &fc))
        return false;
    if (!qd__mdl_end_of_statement(p))
        return false;
    size_t idx[3];
    if (!generate(p, &r, idx))
        return false;
    body *b = (body *)(size_t)r.b; /* the model's own: the plane kept for pictures */
    if (r.surf == ON_PLANE && !r.moving && !b->ground[0]) {
        memcpy(b->ground, r.n, sizeof r.n);
        memcpy(b->ground + 3, r.r0, sizeof r.r0);
    }
    return !friction || add_friction(p, &r, &fc, idx);
}

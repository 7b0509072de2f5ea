/*
 * src/model/body.c - rigid bodies: the body and torque statements, and the
 * calls that reach into a body from an expression.
 *
 *   body NAME mass M inertia I at r [orientation R]
 *   torque G on NAME
 *
 * I is the inertia tensor about the centre of mass in body axes: principal
 * moments (A, B, C), or a symmetric 3x3 matrix.  R (default: the identity,
 * a body that only translates) maps body components to space components.
 * The body adds to T
 *
 *   M/2 |r'|^2 + 1/2 w . I w,   with [w]x = R^T R',  w = (W32, W13, W21),
 *
 * w in body axes (Goldstein 3rd ed. eq. 4.87 for Euler angles; Desloge
 * ch. 63 eq. 11).  A torque G (space components) does the virtual work
 * G . delta(theta); the angular velocity is linear in the velocities, so
 * Q_j = G . d(omega_space)/dq'_j (Desloge ch. 64 eqs. 18-20).
 */
#include "parser.h"
#include "../base/mem.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static qd_ctx *C(parser *p) { return p->ctx; }

const body *qd__mdl_find_body(const qd_model *m, const char *name, size_t n) {
    for (size_t i = 0; i < m->nbodies; i++)
        if (strlen(m->bodies[i].name) == n && memcmp(m->bodies[i].name, name, n) == 0)
            return &m->bodies[i];
    return NULL;
}

/* ---- checks -------------------------------------------------------------- */

static bool check_symmetric(parser *p, const value *I) {
    for (int i = 0; i < 3; i++)
        for (int j = i + 1; j < 3; j++) {
            const qd_expr *a = I->c[3 * i + j], *b = I->c[3 * j + i];
            if (a == b || qd_is_zero(qd_simplify(C(p), qd_sub(C(p), a, b))))
                continue;
            return qd__mdl_perr(p, I->off, I->len, "an inertia tensor is symmetric: I_ij = I_ji",
                        "the inertia tensor is not symmetric: row %d, column %d differs from "
                        "row %d, column %d", i + 1, j + 1, j + 1, i + 1);
        }
    return true;
}

#define MAX_SYMS 64

/* Is R^T R = 1 and det R = +1 at two arbitrary states (parameters at their
 * values)?  true also when R cannot be evaluated (user functions). */
static bool numerically_rotation(parser *p, const qd_expr *const R[9]) {
    qd_ctx *ctx = C(p);
    const qd_model *m = p->m;
    const qd_expr *e[9], *syms[MAX_SYMS];
    size_t ns = 0;
    for (int i = 0; i < 9; i++) {
        e[i] = qd_subs(ctx, R[i], m->nparams, m->params, m->pvals);
        const qd_expr *s[MAX_SYMS];
        size_t k = qd_free_symbols(ctx, e[i], s, MAX_SYMS);
        if (!e[i] || qd__ctx_nomem(ctx))
            return true; /* no verdict; the caller sees the error */
        for (size_t a = 0; a < k && a < MAX_SYMS; a++) {
            size_t b = 0;
            while (b < ns && syms[b] != s[a])
                b++;
            if (b == ns && ns < MAX_SYMS)
                syms[ns++] = s[a];
        }
    }
    for (int trial = 0; trial < 2; trial++) {
        double v[MAX_SYMS], r[9];
        for (size_t i = 0; i < ns; i++)
            v[i] = 0.3 + 0.77 * (double)((i * 7919 + 13 * (size_t)trial + 5) % 101) / 101.0;
        for (int i = 0; i < 9; i++)
            if (qd_eval(ctx, e[i], ns, syms, v, &r[i]) != QD_OK || !isfinite(r[i])) {
                qd__ctx_recover(ctx);
                return true; /* outside its domain here: no verdict */
            }
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++) {
                double d = r[i] * r[j] + r[3 + i] * r[3 + j] + r[6 + i] * r[6 + j];
                if (!(fabs(d - (i == j)) < 1e-9))
                    return false;
            }
        double det = r[0] * (r[4] * r[8] - r[5] * r[7]) - r[1] * (r[3] * r[8] - r[5] * r[6]) +
                     r[2] * (r[3] * r[7] - r[4] * r[6]);
        if (det < 0)
            return false;
    }
    return true;
}

/* ---- kinematics ------------------------------------------------------------ */

/* w from [w]x = R^T R', and R w; each component simplified as it is built,
 * so that what T and the torques inherit is short. */
static void angular_velocity(qd_ctx *ctx, body *b) {
    const qd_expr *Rt[9], *Rd[9], *W[9];
    for (int i = 0; i < 9; i++)
        Rd[i] = qd_dt(ctx, b->R[i]);
    qd__mdl_mat_transpose(b->R, Rt);
    qd__mdl_mat_mul(ctx, Rt, Rd, W);
    b->w[0] = qd_simplify(ctx, W[7]);
    b->w[1] = qd_simplify(ctx, W[2]);
    b->w[2] = qd_simplify(ctx, W[3]);
    qd__mdl_mat_vec(ctx, b->R, b->w, b->ws);
    for (int i = 0; i < 3; i++)
        b->ws[i] = qd_simplify(ctx, b->ws[i]);
}

/* M/2 |r'|^2 + 1/2 w . I w */
static const qd_expr *body_kinetic(qd_ctx *ctx, const body *b) {
    const qd_expr *v2 = qd_int(ctx, 0), *rot = qd_int(ctx, 0);
    for (int i = 0; i < 3; i++)
        v2 = qd_add(ctx, v2, qd_powi(ctx, qd_dt(ctx, b->r[i]), 2));
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            rot = qd_add(ctx, rot, qd_mul_n(ctx, 3, (const qd_expr *[]){b->I[3 * i + j],
                                                                       b->w[i], b->w[j]}));
    return qd_mul(ctx, qd_rat(ctx, 1, 2), qd_add(ctx, qd_mul(ctx, b->mass, v2), rot));
}

/* ---- body NAME clause* ------------------------------------------------------ */

static const char *const clauses[] = {"mass", "inertia", "at", "orientation"};
#define NCLAUSES 4

static int clause_index(const parser *p) {
    for (int i = 0; i < NCLAUSES; i++)
        if (qd__mdl_lex_is(&p->lx, clauses[i]))
            return i;
    return -1;
}

static const char *body_usage =
    "write: body NAME mass M inertia (A, B, C) at (x, y, z) orientation R";

static bool unknown_clause(parser *p) {
    char word[64], hint[128];
    size_t n = p->lx.tok.len < 63 ? p->lx.tok.len : 63;
    snprintf(word, sizeof word, "%.*s", (int)n, p->lx.src + p->lx.tok.off);
    const char *near = p->lx.tok.kind == TK_IDENT ? qd__diag_nearest(word, n, clauses, NCLAUSES) : NULL;
    if (near)
        snprintf(hint, sizeof hint, "did you mean '%s'?", near);
    return qd__mdl_perr_tok(p, near ? hint : body_usage,
                    "expected 'mass', 'inertia', 'at' or 'orientation', found %s",
                    p->lx.tok.kind == TK_IDENT ? word : qd__mdl_lex_tk_name(p->lx.tok.kind));
}

/* The clauses in any order, each once; v[k] is clause k's value. */
static bool body_clauses(parser *p, value v[NCLAUSES], bool seen[NCLAUSES]) {
    while (p->lx.tok.kind == TK_IDENT) {
        int k = clause_index(p);
        if (k < 0)
            return unknown_clause(p);
        if (seen[k])
            return qd__mdl_perr_tok(p, body_usage, "'%s' is given twice", clauses[k]);
        seen[k] = true;
        qd__mdl_lex_next(&p->lx);
        bool ok = k == 0 ? qd__mdl_parse_expr(p, &v[k]) && qd__mdl_need_kind(p, &v[k], VK_SCALAR, "as a mass")
                : k == 1 ? qd__mdl_parse_expr(p, &v[k])
                : k == 2 ? qd__mdl_parse_vector(p, &v[k], "a position")
                         : qd__mdl_parse_matrix_value(p, &v[k], "an orientation");
        if (!ok)
            return false;
        if (k == 1 && v[k].kind == VK_SCALAR)
            return qd__mdl_perr_why(p, QD_REASON_WRONG_KIND, v[k].off, v[k].len,
                        "give the principal moments (A, B, C) or the tensor [[..], [..], [..]]",
                        "a scalar where a vector or matrix is needed: an inertia is three "
                        "moments or a tensor");
    }
    return p->lx.tok.kind == TK_NEWLINE || p->lx.tok.kind == TK_EOF ||
           (p->lx.tok.kind == TK_NUMBER ? unknown_clause(p) : qd__mdl_end_of_statement(p));
}

/* Fill b from the clauses' values; the rotation is checked numerically. */
static bool body_build(parser *p, body *b, value v[NCLAUSES], bool has_R) {
    qd_ctx *ctx = C(p);
    b->mass = v[0].c[0];
    if (v[1].kind == VK_MATRIX) {
        if (!check_symmetric(p, &v[1]))
            return false;
        memcpy(b->I, v[1].c, sizeof b->I);
    } else {
        for (int i = 0; i < 9; i++)
            b->I[i] = i % 4 == 0 ? v[1].c[i / 4] : qd_int(ctx, 0);
    }
    memcpy(b->r, v[2].c, sizeof b->r);
    if (has_R)
        memcpy(b->R, v[3].c, sizeof b->R);
    else
        qd__mdl_mat_identity(ctx, b->R);
    bool rotation = !has_R || numerically_rotation(p, b->R);
    if (qd__ctx_nomem(ctx)) /* the check's own failure is no verdict */
        return qd__mdl_perr(p, v[3].off, v[3].len, NULL, "%s", qd_ctx_message(ctx));
    if (!rotation)
        return qd__mdl_perr(p, v[3].off, v[3].len, "use rot_x, rot_y, rot_z, euler(phi, theta, psi) "
                    "or their products", "the orientation is not a rotation "
                    "(R^T R = 1 and det R = 1 fail)");
    angular_velocity(ctx, b);
    for (int i = 0; i < 3; i++)
        if (!b->w[i] || !b->ws[i])
            return qd__mdl_perr(p, v[3].off, v[3].len, NULL, "%s", qd_ctx_message(ctx));
    return true;
}

bool qd__mdl_stmt_body(parser *p) {
    if (!qd__mdl_no_hamiltonian_yet(p, "a body", p->lx.tok.off, p->lx.tok.len))
        return false;
    qd__mdl_lex_next(&p->lx);
    if (p->lx.tok.kind != TK_IDENT)
        return qd__mdl_perr_tok(p, body_usage, "expected a body name, found %s",
                                qd__mdl_lex_tk_name(p->lx.tok.kind));
    token at = p->lx.tok;
    if (!qd__mdl_fresh_name(p, "body"))
        return false;
    qd__mdl_lex_next(&p->lx);
    value v[NCLAUSES];
    bool seen[NCLAUSES] = {false};
    body b;
    memset(&b, 0, sizeof b);
    if (!body_clauses(p, v, seen))
        return false;
    for (int k = 0; k < 3; k++)
        if (!seen[k])
            return qd__mdl_perr(p, at.off, at.len, body_usage, "body '%.*s' has no %s", (int)at.len,
                        p->lx.src + at.off, k == 2 ? "position ('at')" : clauses[k]);
    if (!body_build(p, &b, v, seen[3]))
        return false;
    qd_model *m = p->m;
    const qd_expr *T = body_kinetic(C(p), &b);
    m->T = m->T ? qd_add(C(p), m->T, T) : T;
    if (!m->T)
        return qd__mdl_perr(p, at.off, at.len, NULL, "%s", qd_ctx_message(C(p)));
    char *name = qd__malloc(p->ctx, at.len + 1), what[80];
    if (name)
        snprintf(name, at.len + 1, "%.*s", (int)at.len, p->lx.src + at.off);
    b.name = name;
    snprintf(what, sizeof what, "body:%.70s", name ? name : "");
    if (!name || !qd__mdl_push(m->ctx, (void **)&m->bodies, &m->nbodies, sizeof b, &b)) {
        qd__free(name);
        return qd__mdl_perr(p, at.off, at.len, NULL, "out of memory");
    }
    if (!qd__mdl_add_where(m, what, at.off, at.len))
        return qd__mdl_perr(p, at.off, at.len, NULL, "out of memory");
    return qd__mdl_end_of_statement(p);
}

/* ---- body names in calls and torques ---------------------------------------- */

/* The body named by the current token, or NULL after an error naming the
 * nearest body. */
const body *qd__mdl_expect_body(parser *p, const char *what) {
    const qd_model *m = p->m;
    if (p->lx.tok.kind != TK_IDENT) {
        qd__mdl_perr_tok(p, body_usage, "%s needs a body's name, found %s", what,
                         qd__mdl_lex_tk_name(p->lx.tok.kind));
        return NULL;
    }
    const body *b = qd__mdl_find_body(m, p->lx.src + p->lx.tok.off, p->lx.tok.len);
    if (b) {
        qd__mdl_lex_next(&p->lx);
        return b;
    }
    char word[64], hint[128];
    size_t n = p->lx.tok.len < 63 ? p->lx.tok.len : 63;
    snprintf(word, sizeof word, "%.*s", (int)n, p->lx.src + p->lx.tok.off);
    const char **names = qd__malloc(p->ctx, (m->nbodies + 1) * sizeof *names);
    for (size_t i = 0; names && i < m->nbodies; i++)
        names[i] = m->bodies[i].name;
    const char *near = names ? qd__diag_nearest(word, n, names, m->nbodies) : NULL;
    snprintf(hint, sizeof hint, near ? "did you mean '%s'?" : "%s", near ? near : body_usage);
    qd__free(names);
    qd__mdl_perr_tok(p, hint, "'%s' is not a body", word);
    return NULL;
}

static const char *const body_calls[] = {"omega", "omega_space", "point", "rotation", "position"};

bool qd__mdl_is_body_call(const char *name) {
    for (size_t i = 0; i < sizeof body_calls / sizeof body_calls[0]; i++)
        if (!strcmp(name, body_calls[i]))
            return true;
    return false;
}

bool qd__mdl_body_call_ahead(const parser *p) {
    lexer lx = p->lx;
    qd__mdl_lex_next(&lx);
    return lx.tok.kind == TK_IDENT && qd__mdl_find_body(p->m, lx.src + lx.tok.off, lx.tok.len);
}

/* point(NAME, a) = r + R a: the body-fixed point a (body axes) in space. */
static bool body_point(parser *p, const body *b, value *out) {
    if (p->lx.tok.kind != TK_COMMA)
        return qd__mdl_perr_tok(p, "write point(body, (x, y, z)) with (x, y, z) in body axes",
                        "point takes 2 arguments: a body and a point in body axes");
    qd__mdl_lex_next(&p->lx);
    value a;
    if (!qd__mdl_parse_expr(p, &a) || !qd__mdl_need_kind(p, &a, VK_VECTOR, "as a point in body axes"))
        return false;
    out->kind = VK_VECTOR;
    qd__mdl_mat_vec(C(p), b->R, a.c, out->c);
    for (int i = 0; i < 3; i++)
        out->c[i] = qd_add(C(p), b->r[i], out->c[i]);
    return true;
}

/* omega(NAME), omega_space(NAME), rotation(NAME), position(NAME),
 * point(NAME, (x, y, z)); the current token is the '('. */
bool qd__mdl_body_call(parser *p, const char *name, size_t off, value *out) {
    size_t open = p->lx.tok.off;
    qd__mdl_lex_next(&p->lx);
    const body *b = qd__mdl_expect_body(p, name);
    if (!b)
        return false;
    value r = {VK_VECTOR, {NULL}, off, 0};
    if (!strcmp(name, "point")) {
        if (!body_point(p, b, &r))
            return false;
    } else if (p->lx.tok.kind == TK_COMMA) {
        return qd__mdl_perr_tok(p, NULL, "%s takes 1 argument, a body's name", name);
    } else if (!strcmp(name, "rotation")) {
        r.kind = VK_MATRIX;
        memcpy(r.c, b->R, sizeof b->R);
    } else {
        const qd_expr *const *src = !strcmp(name, "omega")         ? b->w
                                    : !strcmp(name, "omega_space") ? b->ws
                                                                   : b->r;
        memcpy(r.c, src, 3 * sizeof *src);
    }
    if (!qd__mdl_expect_close(p, open))
        return false;
    r.len = p->lx.tok.off - off;
    *out = r;
    return qd__mdl_kernel_ok(p, out);
}

/* torque G on NAME: Q_j += G . d(omega_space)/dq'_j */
bool qd__mdl_stmt_torque(parser *p) {
    qd__mdl_lex_next(&p->lx);
    value G;
    if (!qd__mdl_parse_vector(p, &G, "a torque"))
        return false;
    if (!qd__mdl_lex_is(&p->lx, "on"))
        return qd__mdl_perr_tok(p, "write: torque (Gx, Gy, Gz) on BODY", "expected 'on', found %s",
                        qd__mdl_lex_tk_name(p->lx.tok.kind));
    qd__mdl_lex_next(&p->lx);
    const body *b = qd__mdl_expect_body(p, "torque");
    if (!b)
        return false;
    qd_ctx *ctx = C(p);
    qd_model *m = p->m;
    for (size_t j = 0; j < m->ncoords; j++) {
        const qd_expr *qd = qd_jet(ctx, m->coords[j], 1), *w = qd_int(ctx, 0);
        for (int i = 0; i < 3; i++)
            w = qd_add(ctx, w, qd_mul(ctx, G.c[i], qd_diff(ctx, b->ws[i], qd)));
        m->Q[j] = qd_add(ctx, m->Q[j], w);
        if (!m->Q[j])
            return qd__mdl_perr(p, G.off, G.len, NULL, "%s", qd_ctx_message(ctx));
    }
    return qd__mdl_end_of_statement(p);
}

/*
 * src/model/impulse.c - the statements of impulsive motion (Desloge ch. 57,
 * Byerly ch. III): what acts only at an instant.
 *
 *   impulse J at r                      a blow: Qhat_j += J . dr/dq_j
 *   impulse G on BODY                   an impulsive couple: Qhat_j += G . dw/dq'_j
 *   Qhat[q] = X                         a generalized impulse given directly
 *   impact constraint [NAME:] LHS [= RHS] [restitution E]
 *                                       a constraint that takes hold at the impact
 *   impact [NAME:] LHS >= RHS [restitution E]   (or <=)
 *                                       a unilateral contact, for simulate
 *   prescribe [NAME:] LHS = RHS, ...    velocities given just after (Thomson)
 *
 * The model only records them; src/impulse solves the impulse equations and
 * src/sim applies the contacts' impact law.  A blow is checked here to do
 * virtual work at all: an impulse at a point that does not move with the
 * coordinates would silently do nothing.
 */
#include "parser.h"
#include "../base/mem.h"
#include "../base/args.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static qd_ctx *C(parser *p) { return p->ctx; }

static char *copy_span(parser *p, size_t off, size_t len) {
    char *s = qd__malloc(C(p), len + 1);
    if (s) {
        memcpy(s, p->lx.src + off, len);
        s[len] = '\0';
    }
    return s;
}

/* ---- blows ------------------------------------------------------------------ */

/* Record a blow with generalized impulse w (ncoords entries, simplified),
 * labelled by the statement's text src[off..end). */
static bool add_blow(parser *p, const qd_expr **w, size_t off, size_t end, const value *at) {
    qd_model *m = p->m;
    bool any = false;
    for (size_t j = 0; j < m->ncoords; j++) {
        if (!(w[j] = qd_simplify(C(p), w[j])))
            return qd__mdl_perr(p, at->off, at->len, NULL, "%s", qd_ctx_message(C(p)));
        any = any || !qd_is_zero(w[j]);
    }
    if (!any)
        return qd__mdl_perr(p, at->off, at->len,
                            "an impulse acts through its point's motion: the point must move "
                            "with the coordinates, along the impulse",
                            "this impulse does no virtual work: its point does not move with "
                            "the coordinates (or only across the impulse)");
    blow b = {copy_span(p, off, end - off), NULL, m->ncoords};
    b.w = qd__malloc(C(p), (m->ncoords + 1) * sizeof *b.w);
    if (!b.label || !b.w || !qd__mdl_push(C(p), (void **)&m->blows, &m->nblows, sizeof b, &b)) {
        qd__free((char *)b.label);
        qd__free(b.w);
        return qd__mdl_perr(p, off, 1, NULL, "out of memory");
    }
    memcpy(b.w, w, m->ncoords * sizeof *w);
    for (size_t j = 0; j < m->ncoords; j++)
        if (!(m->Qhat[j] = qd_add(C(p), m->Qhat[j], w[j])))
            return qd__mdl_perr(p, off, 1, NULL, "%s", qd_ctx_message(C(p)));
    return true;
}

/* An impulse acts at an instant: what it is may depend on where the system
 * is, not on how it moves (the velocities jump across it). */
static bool velocity_free(parser *p, const value *v, const char *what) {
    for (size_t j = 0; j < p->m->ncoords; j++)
        for (unsigned order = 1; order <= 2; order++) {
            const qd_expr *qd = qd_jet(C(p), p->m->coords[j], order);
            for (int i = 0; i < qd__mdl_value_ncomp(v); i++)
                if (qd && qd_has(v->c[i], qd))
                    return qd__mdl_perr(p, v->off, v->len,
                                        "the velocities jump across an impulse: give it in "
                                        "the coordinates, t and the parameters",
                                        "%s depends on %s%s", what,
                                        qd_expr_name(p->m->coords[j]), order == 1 ? "'" : "''");
        }
    return true;
}

/* impulse VECTOR (at POSITION | on BODY) */
bool qd__mdl_stmt_impulse(parser *p) {
    qd_model *m = p->m;
    size_t start = p->lx.tok.off;
    qd__mdl_lex_next(&p->lx);
    value J;
    if (!qd__mdl_parse_vector(p, &J, "an impulse") || !velocity_free(p, &J, "an impulse"))
        return false;
    const qd_expr **w = qd__calloc(C(p), m->ncoords + 1, sizeof *w);
    if (!w)
        return qd__mdl_perr(p, start, 1, NULL, "out of memory");
    bool ok;
    size_t end;
    value at;
    if (qd__mdl_lex_is(&p->lx, "on")) {
        /* a couple does the virtual work G . delta(theta), and the angular
         * velocity is linear in the velocities (body.c, torque) */
        qd__mdl_lex_next(&p->lx);
        token bt = p->lx.tok;
        const body *b = qd__mdl_expect_body(p, "impulse");
        ok = b != NULL;
        for (size_t j = 0; ok && j < m->ncoords; j++) {
            const qd_expr *qd = qd_jet(C(p), m->coords[j], 1);
            w[j] = qd_int(C(p), 0);
            for (int i = 0; i < 3; i++)
                w[j] = qd_add(C(p), w[j], qd_mul(C(p), J.c[i], qd_diff(C(p), b->ws[i], qd)));
        }
        end = bt.off + bt.len;
        at = (value){VK_VECTOR, {0}, bt.off, bt.len};
    } else {
        value r;
        ok = qd__mdl_expect_at(p, "impulse (Jx, Jy, Jz) at (x, y, z), or impulse G on BODY") &&
             qd__mdl_parse_vector(p, &r, "a position") && velocity_free(p, &r, "the point of an impulse");
        for (size_t j = 0; ok && j < m->ncoords; j++) {
            w[j] = qd_int(C(p), 0);
            for (int i = 0; i < 3; i++)
                w[j] = qd_add(C(p), w[j], qd_mul(C(p), J.c[i], qd_diff(C(p), r.c[i], m->coords[j])));
        }
        end = ok ? r.off + r.len : start;
        at = r;
    }
    ok = ok && add_blow(p, w, start, end, &at);
    qd__free(w);
    return ok && qd__mdl_end_of_statement(p);
}

/* Qhat '[' COORD ']' '=' EXPR */
bool qd__mdl_stmt_qhat(parser *p) {
    qd_model *m = p->m;
    size_t start = p->lx.tok.off;
    int j = qd__mdl_coord_subscript(p, "write Qhat[coordinate] = expression");
    if (j < 0)
        return false;
    value x;
    if (!qd__mdl_parse_expr(p, &x) || !qd__mdl_need_kind(p, &x, VK_SCALAR, "in Qhat[...]") ||
        !velocity_free(p, &x, "a generalized impulse"))
        return false;
    const qd_expr **w = qd__calloc(C(p), m->ncoords + 1, sizeof *w);
    if (!w)
        return qd__mdl_perr(p, start, 1, NULL, "out of memory");
    for (size_t k = 0; k < m->ncoords; k++)
        w[k] = k == (size_t)j ? x.c[0] : qd_int(C(p), 0);
    bool ok = add_blow(p, w, start, x.off + x.len, &x);
    qd__free(w);
    return ok && qd__mdl_end_of_statement(p);
}

/* ---- sudden constraints, contacts, prescriptions ----------------------------- */

long qd__mdl_find_sudden(const qd_model *m, const char *src, size_t off, size_t n) {
    for (size_t k = 0; k < m->nsudden; k++)
        if (qd__mdl_name_is(src, off, n, m->sudden[k].name))
            return (long)k;
    return -1;
}

void qd__mdl_free_sudden(sudden *s, size_t from, size_t n) {
    for (size_t i = from; i < n; i++)
        qd__free((char *)s[i].name);
}

void qd__mdl_free_blows(blow *b, size_t from, size_t n) {
    for (size_t i = from; i < n; i++) {
        qd__free((char *)b[i].label);
        qd__free(b[i].w);
    }
}

/* [NAME ':'] into name, or a fresh prefix%zu; *at the name's token (or the
 * statement's first). */
static bool label(parser *p, const char *prefix, char *name, size_t cap, token *at) {
    lexer save = p->lx;
    *at = p->lx.tok;
    qd__mdl_lex_next(&p->lx);
    if (at->kind == TK_IDENT && p->lx.tok.kind == TK_COLON) {
        snprintf(name, cap, "%.*s", (int)(at->len < cap - 1 ? at->len : cap - 1), p->lx.src + at->off);
        if (qd__mdl_constraint_named(p->m, name))
            return qd__mdl_perr(p, at->off, at->len, "give each constraint its own name",
                                "a constraint named '%s' is already given", name);
        qd__mdl_lex_next(&p->lx);
        return true;
    }
    p->lx = save;
    size_t k = 1;
    do
        snprintf(name, cap, "%s%zu", prefix, k++);
    while (qd__mdl_constraint_named(p->m, name));
    return true;
}

/* x is a relation among the coordinates and t, or linear in the velocities:
 * what a velocity form a . q' + a0 can be had from.  velocities: allowed. */
static bool check_relation(parser *p, const qd_expr *x, size_t off, size_t len, bool velocities,
                           const char *what) {
    const qd_model *m = p->m;
    if (qd_is_number(x))
        return qd__mdl_perr(p, off, len, "it relates the coordinates (or their velocities)",
                            qd_is_zero(x) ? "this %s always holds" : "this %s can never hold", what);
    bool coords = false;
    for (size_t j = 0; j < m->ncoords; j++) {
        const qd_expr *v = qd_jet(C(p), m->coords[j], 1), *a = qd_jet(C(p), m->coords[j], 2);
        coords = coords || qd_has(x, m->coords[j]) || qd_has(x, v);
        if (a && qd_has(x, a))
            return qd__mdl_perr(p, off, len, "give it in the coordinates and velocities",
                                "a %s cannot depend on accelerations (%s'')", what,
                                qd_expr_name(m->coords[j]));
        if (!v || !qd_has(x, v))
            continue;
        if (!velocities)
            return qd__mdl_perr(p, off, len, "a contact's gap is a distance: give it in the "
                                "coordinates and t", "a %s cannot depend on %s'", what,
                                qd_expr_name(m->coords[j]));
        const qd_expr *d = qd_diff(C(p), x, v);
        for (size_t k = 0; d && k < m->ncoords; k++) {
            const qd_expr *vk = qd_jet(C(p), m->coords[k], 1);
            if (vk && qd_has(d, vk))
                return qd__mdl_perr(p, off, len, "an impulse problem is linear in the velocities",
                                    "a %s must be linear in the velocities: %s' enters "
                                    "nonlinearly", what, qd_expr_name(m->coords[j]));
        }
    }
    if (!coords)
        return qd__mdl_perr(p, off, len, "it must involve the coordinates",
                            "this %s does not depend on the coordinates", what);
    return true;
}

/* ['restitution' E]: E a number or an expression in the parameters, in
 * [0, 1] at their values. */
static bool restitution(parser *p, const qd_expr **E) {
    *E = qd_int(C(p), 0);
    if (!qd__mdl_lex_is(&p->lx, "restitution"))
        return true;
    qd__mdl_lex_next(&p->lx);
    size_t off = p->lx.tok.off;
    if (!qd__mdl_parse_scalar(p, E, "a restitution coefficient"))
        return false;
    size_t len = p->lx.tok.off > off ? p->lx.tok.off - off : 1;
    const qd_model *m = p->m;
    const qd_expr *v = qd_subs(C(p), *E, m->nparams, m->params, m->pvals);
    double e = NAN;
    if (!v || qd_eval(C(p), v, 0, NULL, NULL, &e) != QD_OK) {
        qd__ctx_recover(C(p));
        return qd__mdl_perr(p, off, len, "a restitution is a number, or an expression in the "
                            "parameters", "a restitution coefficient cannot depend on the "
                            "coordinates, the velocities or t");
    }
    if (!(e >= 0 && e <= 1))
        return qd__mdl_perr(p, off, len, "0: the bodies stay together; 1: perfectly elastic",
                            "a restitution coefficient is between 0 and 1, not %g", e);
    return true;
}

static bool push_sudden(parser *p, sudden **list, size_t *n, const char *name, const qd_expr *x,
                        const qd_expr *E, const char *kind, token at) {
    char what[96];
    sudden s = {qd__malloc(C(p), strlen(name) + 1), x, E};
    if (s.name)
        strcpy((char *)s.name, name);
    snprintf(what, sizeof what, "%s:%s", kind, name);
    if (!s.name || !qd__mdl_push(C(p), (void **)list, n, sizeof s, &s)) {
        qd__free((char *)s.name);
        return qd__mdl_perr(p, at.off, at.len, NULL, "out of memory");
    }
    if (!qd__mdl_add_where(p->m, what, at.off, at.len))
        return qd__mdl_perr(p, at.off, at.len, NULL, "out of memory");
    return true;
}

/* impact constraint [NAME ':'] LHS ['=' RHS] [restitution E] */
static bool sudden_constraint(parser *p) {
    char name[QD_MDL_NAME_MAX];
    token at;
    qd__mdl_lex_next(&p->lx); /* constraint */
    if (!label(p, "k", name, sizeof name, &at))
        return false;
    size_t off = p->lx.tok.off;
    const qd_expr *lhs, *rhs = NULL, *E;
    if (!qd__mdl_parse_scalar(p, &lhs, "a constraint"))
        return false;
    if (p->lx.tok.kind == TK_EQ) {
        qd__mdl_lex_next(&p->lx);
        if (!qd__mdl_parse_scalar(p, &rhs, "a constraint"))
            return false;
    }
    size_t len = p->lx.tok.off > off ? p->lx.tok.off - off : 1;
    const qd_expr *x = rhs ? qd_sub(C(p), lhs, rhs) : lhs;
    if (!x)
        return qd__mdl_perr(p, off, 1, NULL, "%s", qd_ctx_message(C(p)));
    if (at.off == off)
        at = (token){TK_EOF, off, len};
    return check_relation(p, x, off, len, true, "sudden constraint") && restitution(p, &E) &&
           push_sudden(p, &p->m->sudden, &p->m->nsudden, name, x, E, "impact", at) &&
           qd__mdl_end_of_statement(p);
}

/* impact [NAME ':'] LHS ('>=' | '<=') RHS [restitution E] */
bool qd__mdl_stmt_impact(parser *p) {
    qd__mdl_lex_next(&p->lx);
    if (qd__mdl_lex_is(&p->lx, "constraint")) {
        lexer save = p->lx;
        qd__mdl_lex_next(&p->lx);
        bool named_constraint = p->lx.tok.kind == TK_COLON; /* `impact constraint: ...` */
        p->lx = save;
        if (!named_constraint)
            return sudden_constraint(p);
    }
    char name[QD_MDL_NAME_MAX];
    token at;
    if (!label(p, "contact", name, sizeof name, &at))
        return false;
    size_t off = p->lx.tok.off;
    const qd_expr *lhs, *rhs, *E;
    if (!qd__mdl_parse_scalar(p, &lhs, "a gap"))
        return false;
    tk_kind rel = p->lx.tok.kind;
    if (rel != TK_GE && rel != TK_LE)
        return qd__mdl_perr_tok(p, "write: impact floor: y >= 0 restitution 0.9 (or impact "
                                "constraint NAME: ... for a constraint that takes hold)",
                                "expected '>=' or '<=', found %s", qd__mdl_lex_tk_name(rel));
    qd__mdl_lex_next(&p->lx);
    if (!qd__mdl_parse_scalar(p, &rhs, "a gap"))
        return false;
    size_t len = p->lx.tok.off > off ? p->lx.tok.off - off : 1;
    /* the gap is what must stay >= 0 */
    const qd_expr *gap = rel == TK_GE ? qd_sub(C(p), lhs, rhs) : qd_sub(C(p), rhs, lhs);
    if (!gap)
        return qd__mdl_perr(p, off, 1, NULL, "%s", qd_ctx_message(C(p)));
    if (at.off == off)
        at = (token){TK_EOF, off, len};
    return check_relation(p, gap, off, len, false, "contact") && restitution(p, &E) &&
           push_sudden(p, &p->m->impacts, &p->m->nimpacts, name, gap, E, "impact", at) &&
           qd__mdl_end_of_statement(p);
}

/* prescribe [NAME ':'] LHS '=' RHS (',' [NAME ':'] LHS '=' RHS)* */
bool qd__mdl_stmt_prescribe(parser *p) {
    do {
        qd__mdl_lex_next(&p->lx);
        char name[QD_MDL_NAME_MAX];
        token at;
        if (!label(p, "v", name, sizeof name, &at))
            return false;
        size_t off = p->lx.tok.off;
        const qd_expr *lhs, *rhs;
        if (!qd__mdl_parse_scalar(p, &lhs, "a prescribed velocity"))
            return false;
        if (p->lx.tok.kind != TK_EQ)
            return qd__mdl_perr_tok(p, "write: prescribe P.y' = v", "expected '=', found %s",
                                    qd__mdl_lex_tk_name(p->lx.tok.kind));
        qd__mdl_lex_next(&p->lx);
        if (!qd__mdl_parse_scalar(p, &rhs, "a prescribed velocity"))
            return false;
        size_t len = p->lx.tok.off > off ? p->lx.tok.off - off : 1;
        const qd_expr *x = qd_sub(C(p), lhs, rhs);
        if (!x)
            return qd__mdl_perr(p, off, 1, NULL, "%s", qd_ctx_message(C(p)));
        bool any = false;
        for (size_t j = 0; j < p->m->ncoords; j++) {
            const qd_expr *v = qd_jet(C(p), p->m->coords[j], 1);
            any = any || (v && qd_has(x, v));
        }
        if (!any)
            return qd__mdl_perr(p, off, len, "prescribe a velocity: P.y' = v, x' = 2",
                                "a prescription gives velocities, but this has none");
        if (at.off == off)
            at = (token){TK_EOF, off, len};
        if (!check_relation(p, x, off, len, true, "prescription") ||
            !push_sudden(p, &p->m->prescribed, &p->m->nprescribed, name, x, qd_int(C(p), 0),
                         "prescribe", at))
            return false;
    } while (p->lx.tok.kind == TK_COMMA);
    return qd__mdl_end_of_statement(p);
}

/* ---- accessors ---------------------------------------------------------------- */

size_t qd_model_nparticles(const qd_model *m) { QD_ARGS(0, m); return m->nparts; }
const qd_expr *qd_model_particle_mass(const qd_model *m, size_t i) {
    QD_ARGS(NULL, m);
    return i < m->nparts ? m->parts[i].mass : NULL;
}
const qd_expr *qd_model_particle_position(const qd_model *m, size_t i, unsigned k) {
    QD_ARGS(NULL, m);
    return i < m->nparts && k < 3 ? m->parts[i].r[k] : NULL;
}

size_t qd_model_nblows(const qd_model *m) { QD_ARGS(0, m); return m->nblows; }
const char *qd_model_blow_label(const qd_model *m, size_t i) {
    QD_ARGS(NULL, m);
    return i < m->nblows ? m->blows[i].label : NULL;
}
const qd_expr *qd_model_blow(const qd_model *m, size_t i, size_t coord) {
    QD_ARGS(NULL, m);
    if (i >= m->nblows || coord >= m->ncoords)
        return NULL;
    /* a coordinate declared after the blow cannot appear in it */
    return coord < m->blows[i].nw ? m->blows[i].w[coord] : qd_int(m->ctx, 0);
}
const qd_expr *qd_model_impulse(const qd_model *m, size_t coord) {
    QD_ARGS(NULL, m);
    return coord < m->ncoords ? m->Qhat[coord] : NULL;
}

static const sudden *at_index(const sudden *s, size_t n, size_t i) { return i < n ? &s[i] : NULL; }

size_t qd_model_nimpact_constraints(const qd_model *m) { QD_ARGS(0, m); return m->nsudden; }
const char *qd_model_impact_constraint_name(const qd_model *m, size_t i) {
    QD_ARGS(NULL, m);
    const sudden *s = at_index(m->sudden, m->nsudden, i);
    return s ? s->name : NULL;
}
const qd_expr *qd_model_impact_constraint(const qd_model *m, size_t i) {
    QD_ARGS(NULL, m);
    const sudden *s = at_index(m->sudden, m->nsudden, i);
    return s ? s->expr : NULL;
}
const qd_expr *qd_model_impact_constraint_restitution(const qd_model *m, size_t i) {
    QD_ARGS(NULL, m);
    const sudden *s = at_index(m->sudden, m->nsudden, i);
    return s ? s->E : NULL;
}

size_t qd_model_nimpacts(const qd_model *m) { QD_ARGS(0, m); return m->nimpacts; }
const char *qd_model_impact_name(const qd_model *m, size_t i) {
    QD_ARGS(NULL, m);
    const sudden *s = at_index(m->impacts, m->nimpacts, i);
    return s ? s->name : NULL;
}
const qd_expr *qd_model_impact_gap(const qd_model *m, size_t i) {
    QD_ARGS(NULL, m);
    const sudden *s = at_index(m->impacts, m->nimpacts, i);
    return s ? s->expr : NULL;
}
const qd_expr *qd_model_impact_restitution(const qd_model *m, size_t i) {
    QD_ARGS(NULL, m);
    const sudden *s = at_index(m->impacts, m->nimpacts, i);
    return s ? s->E : NULL;
}

size_t qd_model_nprescribed(const qd_model *m) { QD_ARGS(0, m); return m->nprescribed; }
const char *qd_model_prescribed_name(const qd_model *m, size_t i) {
    QD_ARGS(NULL, m);
    const sudden *s = at_index(m->prescribed, m->nprescribed, i);
    return s ? s->name : NULL;
}
const qd_expr *qd_model_prescribed(const qd_model *m, size_t i) {
    QD_ARGS(NULL, m);
    const sudden *s = at_index(m->prescribed, m->nprescribed, i);
    return s ? s->expr : NULL;
}

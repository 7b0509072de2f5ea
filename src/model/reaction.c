/*
 * src/model/reaction.c - the reaction statement: which constraint force is
 * wanted, and at which point.
 *
 *   reaction [LABEL:] CON on r
 *
 * CON names a constraint declared above (or a sudden one, `impact
 * constraint`, whose reaction is an impulse), r is a position (coordinates,
 * parameters and t; no velocities).  The model only records the request;
 * the force itself needs the multiplier at a state (src/mech/reaction.c).
 * One constraint may act at several points (a rope on each of its masses):
 * the label tells the reports apart; without one the reaction is named after
 * the constraint.
 */
#include "parser.h"
#include "../base/mem.h"
#include "../base/args.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static qd_ctx *C(parser *p) { return p->ctx; }

static bool reaction_named(const qd_model *m, const char *name) {
    for (size_t i = 0; i < m->nreactions; i++)
        if (!strcmp(m->reactions[i].name, name))
            return true;
    return false;
}

/* The constraint the current token names; -1 (and an error) when none. */
static long expect_constraint(parser *p) {
    const qd_model *m = p->m;
    token at = p->lx.tok;
    if (at.kind != TK_IDENT) {
        qd__mdl_perr_tok(p, "write: reaction CONSTRAINT on (x, y, z)",
                 "expected a constraint's name, found %s", qd__mdl_lex_tk_name(at.kind));
        return -1;
    }
    for (size_t k = 0; k < m->ncons; k++)
        if (qd__mdl_name_is(p->lx.src, at.off, at.len, m->con_names[k])) {
            qd__mdl_lex_next(&p->lx);
            return (long)k;
        }
    long s = qd__mdl_find_sudden(m, p->lx.src, at.off, at.len);
    if (s >= 0) { /* an impulsive reaction: encoded past the ordinary ones */
        qd__mdl_lex_next(&p->lx);
        return (long)m->ncons + s;
    }
    char hint[160] = "declare the constraint (constraint NAME: ...) before its reaction";
    const char *near = qd__diag_nearest(p->lx.src + at.off, at.len, m->con_names, m->ncons);
    if (near)
        snprintf(hint, sizeof hint, "did you mean '%s'?", near);
    qd__mdl_perr_tok(p, hint, "'%.*s' is not a constraint", (int)(at.len < 64 ? at.len : 64),
             p->lx.src + at.off);
    return -1;
}

/* r must be a place, not a motion: dr/dq_j is what the force works through. */
static bool velocity_free(parser *p, const value *r) {
    qd_ctx *ctx = C(p);
    for (size_t j = 0; j < p->m->ncoords; j++)
        for (unsigned order = 1; order <= 2; order++) {
            const qd_expr *v = qd_jet(ctx, p->m->coords[j], order);
            for (int i = 0; i < 3; i++)
                if (v && qd_has(r->c[i], v))
                    return qd__mdl_perr(p, r->off, r->len, "give the point's position, e.g. (x, y, 0)",
                                "the point of a reaction depends on %s%s",
                                qd_expr_name(p->m->coords[j]), order == 1 ? "'" : "''");
        }
    return true;
}

/* [LABEL ':']: the label into name (cap bytes), or "" when there is none. */
static void label(parser *p, char *name, size_t cap, token *at) {
    lexer save = p->lx;
    *at = p->lx.tok;
    name[0] = '\0';
    qd__mdl_lex_next(&p->lx);
    if (at->kind != TK_IDENT || p->lx.tok.kind != TK_COLON) {
        p->lx = save;
        return;
    }
    snprintf(name, cap, "%.*s", (int)(at->len < cap - 1 ? at->len : cap - 1), p->lx.src + at->off);
    qd__mdl_lex_next(&p->lx);
}

static bool add(parser *p, const char *name, size_t con, bool sudden, const value *r, token at) {
    qd_model *m = p->m;
    char what[80];
    reaction x = {qd__malloc(p->ctx, strlen(name) + 1), con, sudden, {r->c[0], r->c[1], r->c[2]}};
    if (x.name)
        strcpy((char *)x.name, name);
    snprintf(what, sizeof what, "reaction:%s", name);
    if (!x.name || !qd__mdl_push(m->ctx, (void **)&m->reactions, &m->nreactions, sizeof x, &x)) {
        qd__free((char *)x.name);
        return qd__mdl_perr(p, at.off, at.len, NULL, "out of memory");
    }
    if (!qd__mdl_add_where(m, what, at.off, at.len))
        return qd__mdl_perr(p, at.off, at.len, NULL, "out of memory");
    return true;
}

/* reaction [LABEL ':'] CON 'on' POSITION */
bool qd__mdl_stmt_reaction(parser *p) {
    char name[QD_MDL_NAME_MAX];
    token at;
    qd__mdl_lex_next(&p->lx);
    label(p, name, sizeof name, &at);
    token con_at = p->lx.tok;
    long k = expect_constraint(p);
    if (k < 0)
        return false;
    bool sudden = (size_t)k >= p->m->ncons;
    if (sudden)
        k -= (long)p->m->ncons;
    if (!name[0]) {
        snprintf(name, sizeof name, "%s", sudden ? p->m->sudden[k].name : p->m->con_names[k]);
        at = con_at;
    }
    if (reaction_named(p->m, name))
        return qd__mdl_perr(p, at.off, at.len, "label it: reaction NAME: CONSTRAINT on (x, y, z)",
                    "a reaction named '%s' is already given", name);
    if (!qd__mdl_lex_is(&p->lx, "on"))
        return qd__mdl_perr_tok(p, "write: reaction CONSTRAINT on (x, y, z)", "expected 'on', found %s",
                        qd__mdl_lex_tk_name(p->lx.tok.kind));
    qd__mdl_lex_next(&p->lx);
    value r;
    if (!qd__mdl_parse_vector(p, &r, "a position") || !velocity_free(p, &r) ||
        !add(p, name, (size_t)k, sudden, &r, at))
        return false;
    return qd__mdl_end_of_statement(p);
}

size_t qd_model_nreactions(const qd_model *m) { QD_ARGS(0, m); return m->nreactions; }

const char *qd_model_reaction_name(const qd_model *m, size_t i) {
    QD_ARGS(NULL, m);
    return i < m->nreactions ? m->reactions[i].name : NULL;
}

const char *qd_model_reaction_constraint(const qd_model *m, size_t i) {
    QD_ARGS(NULL, m);
    if (i >= m->nreactions)
        return NULL;
    const reaction *r = &m->reactions[i];
    return r->sudden ? m->sudden[r->con].name : m->con_names[r->con];
}

const qd_expr *qd_model_reaction_point(const qd_model *m, size_t i, unsigned k) {
    QD_ARGS(NULL, m);
    return i < m->nreactions && k < 3 ? m->reactions[i].r[k] : NULL;
}

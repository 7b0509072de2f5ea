/*
 * src/model/friction.c - Coulomb friction clauses (issue 18).
 *
 *   constraint NAME: LHS = RHS friction MU normal N
 *   constraint NAME: LHS = RHS friction static MU_S kinetic MU_K normal N
 *   rolls BODY on SURFACE as SHAPE friction MU [normal N]
 *
 * The clause turns the velocity constraints it follows into a contact that
 * may slip (src/sim/friction.c integrates it): LHS - RHS is the slip
 * velocity of the contact point, the constraint's multiplier the friction
 * force along it.  N is an expression, or the name of a constraint (earlier
 * or later in the file) whose multiplier is the normal force.
 */
#include "parser.h"
#include "../base/mem.h"
#include "../base/args.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char *const usage =
    "write: friction MU normal N, or friction static MU_S kinetic MU_K normal N";

bool qd__mdl_friction_ahead(const parser *p) {
    return p->lx.tok.kind == TK_IDENT && qd__mdl_lex_is(&p->lx, "friction");
}

/* A coefficient: a constant of the parameters, not negative when read. */
static bool parse_mu(parser *p, const qd_expr **def, const char *what) {
    size_t off = p->lx.tok.off;
    const qd_expr *num;
    if (!qd__mdl_parse_constant(p, def, &num, what))
        return false;
    size_t len = p->lx.tok.off > off ? p->lx.tok.off - off : 1;
    double x = 0;
    qd_eval(p->ctx, num, 0, NULL, NULL, &x);
    if (x < 0)
        return qd__mdl_perr(p, off, len,
                            "a friction coefficient is 0 or more (tan of the friction angle)",
                            "the friction coefficient is negative (%g)", x);
    return true;
}

static bool is_constraint(const qd_model *m, const char *name) {
    for (size_t i = 0; i < m->ncons; i++)
        if (!strcmp(m->con_names[i], name))
            return true;
    return false;
}

static bool known_name(const parser *p, const char *name) {
    size_t n;
    const char **names = qd__mdl_known_names(p, &n);
    bool found = false;
    for (size_t i = 0; names && i < n && !found; i++)
        found = !strcmp(names[i], name);
    qd__free(names);
    return found;
}

/* 'normal' (CONSTRAINT | EXPR): a lone name that is no name of an
 * expression is a constraint's, checked at the end of the file. */
static bool parse_normal(parser *p, fclause *fc) {
    qd__mdl_lex_next(&p->lx);
    token at = p->lx.tok;
    if (at.kind == TK_IDENT) {
        lexer ahead = p->lx;
        qd__mdl_lex_next(&ahead);
        char name[QD_MDL_NAME_MAX];
        snprintf(name, sizeof name, "%.*s", (int)at.len, p->lx.src + at.off); /* at most 127 */
        bool alone = ahead.tok.kind == TK_NEWLINE || ahead.tok.kind == TK_EOF;
        if (alone && (is_constraint(p->m, name) || !known_name(p, name))) {
            strcpy(fc->normal_con, name);
            fc->normal_off = at.off;
            fc->normal_len = at.len;
            p->lx = ahead;
            return true;
        }
    }
    return qd__mdl_parse_scalar(p, &fc->normal, "a normal force");
}

/* 'friction' (MU | 'static' MU_S 'kinetic' MU_K) ['normal' N] */
bool qd__mdl_friction_parse(parser *p, fclause *fc) {
    memset(fc, 0, sizeof *fc);
    fc->off = p->lx.tok.off;
    fc->len = p->lx.tok.len;
    qd__mdl_lex_next(&p->lx);
    if (qd__mdl_lex_is(&p->lx, "static")) {
        qd__mdl_lex_next(&p->lx);
        if (!parse_mu(p, &fc->mu_s, "a static friction coefficient"))
            return false;
        if (!qd__mdl_lex_is(&p->lx, "kinetic"))
            return qd__mdl_perr_tok(p, usage, "expected 'kinetic' after the static coefficient");
        qd__mdl_lex_next(&p->lx);
        if (!parse_mu(p, &fc->mu_k, "a kinetic friction coefficient"))
            return false;
    } else {
        if (!parse_mu(p, &fc->mu_s, "a friction coefficient"))
            return false;
        fc->mu_k = fc->mu_s;
    }
    if (qd__mdl_lex_is(&p->lx, "normal"))
        return parse_normal(p, fc);
    return true;
}

static bool has_velocity(const parser *p, const qd_expr *c) {
    const qd_model *m = p->m;
    for (size_t j = 0; j < m->ncoords; j++)
        if (qd_has(c, qd_jet(p->ctx, m->coords[j], 1)))
            return true;
    return false;
}

static char *copy_of(qd_ctx *ctx, const char *s) {
    char *c = qd__malloc(ctx, strlen(s) + 1);
    if (c)
        strcpy(c, s);
    return c;
}

bool qd__mdl_friction_add(parser *p, const fclause *fc, const char *name, qd_contact_kind kind,
                          const size_t *con, size_t ncon) {
    qd_model *m = p->m;
    for (size_t i = 0; i < ncon; i++)
        if (!has_velocity(p, m->cons[con[i]]))
            return qd__mdl_perr(p, fc->off, fc->len,
                                "friction acts along a velocity constraint: write the slip "
                                "velocity of the contact point, e.g. x' - a*phi' = 0",
                                "friction needs a velocity constraint");
    if (!fc->normal && !fc->normal_con[0])
        return qd__mdl_perr(p, fc->off, fc->len,
                            "add the normal force: normal N (an expression, or the name of the "
                            "constraint whose multiplier it is)",
                            "friction needs the normal force");
    fcontact c = {.kind = kind, .ncon = ncon, .mu_s = fc->mu_s, .mu_k = fc->mu_k,
                  .normal = fc->normal, .normal_off = fc->normal_off,
                  .normal_len = fc->normal_len};
    for (size_t i = 0; i < ncon; i++)
        c.con[i] = con[i];
    c.name = copy_of(p->ctx, name);
    c.normal_con = fc->normal_con[0] ? copy_of(p->ctx, fc->normal_con) : NULL;
    bool ok = c.name && (c.normal_con || !fc->normal_con[0]) &&
              qd__mdl_push(m->ctx, (void **)&m->contacts, &m->ncontacts, sizeof c, &c);
    if (!ok) {
        qd__free(c.name);
        qd__free(c.normal_con);
        return qd__mdl_perr(p, fc->off, fc->len, NULL, "out of memory");
    }
    return true;
}

/* "no constraint named 'Nc'" with the nearest constraint's name. */
static bool unknown_normal(parser *p, const fcontact *c) {
    const qd_model *m = p->m;
    char hint[160];
    const char *near = qd__diag_nearest(c->normal_con, strlen(c->normal_con),
                                        (const char *const *)m->con_names, m->ncons);
    if (near)
        snprintf(hint, sizeof hint, "did you mean '%s'?", near);
    else
        snprintf(hint, sizeof hint, "name the constraint that holds the body on the surface, "
                                    "or give N as an expression");
    return qd__mdl_perr(p, c->normal_off, c->normal_len, hint,
                        "no constraint named '%s' gives the normal force", c->normal_con);
}

bool qd__mdl_friction_finish(parser *p) {
    qd_model *m = p->m;
    for (size_t i = 0; i < m->ncontacts; i++) {
        const fcontact *c = &m->contacts[i];
        if (c->normal_con && !is_constraint(m, c->normal_con))
            return unknown_normal(p, c);
        for (size_t k = 0; c->normal_con && k < c->ncon; k++)
            if (!strcmp(m->con_names[c->con[k]], c->normal_con))
                return qd__mdl_perr(p, c->normal_off, c->normal_len,
                                    "the normal force comes from the constraint that holds the "
                                    "body on the surface",
                                    "a contact's normal force cannot be its own friction force");
    }
    return true;
}

void qd__mdl_free_friction(qd_model *m) {
    for (size_t i = 0; i < m->ncontacts; i++) {
        qd__free(m->contacts[i].name);
        qd__free(m->contacts[i].normal_con);
    }
    qd__free(m->contacts);
}

/* ---- the public queries ------------------------------------------------------ */

static const fcontact *contact_at(const qd_model *m, size_t i) {
    return i < m->ncontacts ? &m->contacts[i] : NULL;
}

size_t qd_model_ncontacts(const qd_model *m) { QD_ARGS(0, m); return m->ncontacts; }

const char *qd_model_contact_name(const qd_model *m, size_t i) {
    QD_ARGS(NULL, m);
    const fcontact *c = contact_at(m, i);
    return c ? c->name : NULL;
}

qd_contact_kind qd_model_contact_kind(const qd_model *m, size_t i) {
    QD_ARGS((qd_contact_kind)0, m);
    const fcontact *c = contact_at(m, i);
    return c ? c->kind : QD_CONTACT_CONSTRAINT;
}

size_t qd_model_contact_constraints(const qd_model *m, size_t i, size_t con[2]) {
    QD_ARGS(0, m && con);
    const fcontact *c = contact_at(m, i);
    for (size_t k = 0; c && k < c->ncon; k++)
        con[k] = c->con[k];
    return c ? c->ncon : 0;
}

const qd_expr *qd_model_contact_mu(const qd_model *m, size_t i, bool kinetic) {
    QD_ARGS(NULL, m);
    const fcontact *c = contact_at(m, i);
    return c ? (kinetic ? c->mu_k : c->mu_s) : NULL;
}

const qd_expr *qd_model_contact_normal(const qd_model *m, size_t i) {
    QD_ARGS(NULL, m);
    const fcontact *c = contact_at(m, i);
    return c ? c->normal : NULL;
}

const qd_expr *qd_model_contact_normal_scale(const qd_model *m, size_t i) {
    QD_ARGS(NULL, m);
    const fcontact *c = contact_at(m, i);
    return c ? (c->normal_scale ? c->normal_scale : qd_int(m->ctx, 1)) : NULL;
}

const char *qd_model_contact_normal_constraint(const qd_model *m, size_t i) {
    QD_ARGS(NULL, m);
    const fcontact *c = contact_at(m, i);
    return c ? c->normal_con : NULL;
}

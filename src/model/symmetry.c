/*
 * src/model/symmetry.c - proposed symmetries and integrals of motion.
 *
 *   symmetry [NAME:] q1 -> EXPR, q2 -> EXPR, ...     finite, in the parameter eps
 *   symmetry [NAME:] delta q1 = EXPR, delta q2 = EXPR  the vector field itself
 *   integral [NAME:] EXPR
 *
 * A symmetry is a point transformation q_j -> q_j + eps xi_j(q, t) + O(eps^2);
 * the model keeps only the field xi (what Noether's theorem uses): from the
 * finite form, xi_j = d(rhs_j)/d eps at eps = 0, simplified.  The finite form
 * must be the identity at eps = 0, or it is not a one-parameter family
 * through the identity and xi means nothing.  The model records the
 * proposals; checking them is the mechanics layer's job.
 */
#include "parser.h"
#include "../base/mem.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static qd_ctx *C(parser *p) { return p->ctx; }

const qd_expr *qd__mdl_eps_symbol(qd_ctx *ctx) { return qd_symbol(ctx, "eps"); }

/* [NAME ':'] after the keyword: the label's token (kind TK_EOF when none). */
static token label(parser *p) {
    qd__mdl_lex_next(&p->lx);
    token at = p->lx.tok;
    lexer save = p->lx;
    qd__mdl_lex_next(&p->lx);
    if (at.kind == TK_IDENT && p->lx.tok.kind == TK_COLON) {
        qd__mdl_lex_next(&p->lx);
        return at;
    }
    p->lx = save;
    return (token){TK_EOF, at.off, at.len ? at.len : 1};
}

static bool taken(const parser *p, bool sym, const char *name) {
    const qd_model *m = p->m;
    size_t n = sym ? m->nsyms : m->nints;
    for (size_t i = 0; i < n; i++)
        if (!strcmp(sym ? m->syms[i].name : m->ints[i].name, name))
            return true;
    return false;
}

/* The name of the statement: its label, or s1, s2, ... / I1, I2, ... */
static bool name_of(parser *p, bool sym, token lab, char *name, size_t cap) {
    const char *what = sym ? "symmetry" : "integral";
    if (lab.kind == TK_IDENT) {
        snprintf(name, cap, "%.*s", (int)(lab.len < cap - 1 ? lab.len : cap - 1),
                 p->lx.src + lab.off);
        if (taken(p, sym, name)) {
            char hint[96];
            snprintf(hint, sizeof hint, "give each %s its own name", what);
            return qd__mdl_perr(p, lab.off, lab.len, hint, "%s '%s' is named twice", what, name);
        }
        return true;
    }
    size_t k = (sym ? p->m->nsyms : p->m->nints) + 1;
    do
        snprintf(name, cap, "%s%zu", sym ? "s" : "I", k++);
    while (taken(p, sym, name));
    return true;
}

static bool add_where(qd_model *m, const char *kind, const char *name, token at) {
    char what[80];
    snprintf(what, sizeof what, "%s:%s", kind, name);
    return qd__mdl_add_where(m, what, at.off, at.len);
}

static char *copy_of(qd_ctx *ctx, const char *s) {
    char *c = qd__malloc(ctx, strlen(s) + 1);
    if (c)
        strcpy(c, s);
    return c;
}

/* A velocity or acceleration in x, or NULL. */
static const qd_expr *motion_in(parser *p, const qd_expr *x, unsigned from) {
    for (size_t j = 0; j < p->m->ncoords; j++)
        for (unsigned order = from; order <= 2; order++) {
            const qd_expr *v = qd_jet(C(p), p->m->coords[j], order);
            if (v && qd_has(x, v))
                return v;
        }
    return NULL;
}

static int coord_at(const parser *p, token t) {
    for (size_t i = 0; t.kind == TK_IDENT && i < p->m->ncoords; i++)
        if (qd__mdl_name_is(p->lx.src, t.off, t.len, qd_expr_name(p->m->coords[i])))
            return (int)i;
    return -1;
}

static bool not_a_coordinate(parser *p) {
    token t = p->lx.tok;
    if (t.kind != TK_IDENT)
        return qd__mdl_perr_tok(p, "write: symmetry x -> x + eps, or symmetry delta x = 1",
                        "expected a coordinate, found %s", qd__mdl_lex_tk_name(t.kind));
    const char **names = qd__malloc(p->ctx, (p->m->ncoords + 1) * sizeof *names);
    for (size_t i = 0; names && i < p->m->ncoords; i++)
        names[i] = qd_expr_name(p->m->coords[i]);
    const char *near = names ? qd__diag_nearest(p->lx.src + t.off, t.len, names, p->m->ncoords) : NULL;
    char hint[160] = "a symmetry moves the coordinates";
    if (near)
        snprintf(hint, sizeof hint, "did you mean '%s'?", near);
    qd__free(names);
    return qd__mdl_perr_tok(p, hint, "'%.*s' is not a coordinate", (int)(t.len < 64 ? t.len : 64),
                    p->lx.src + t.off);
}

/* Is the current token '-' directly followed by '>'? Then step over "->". */
static bool arrow(parser *p) {
    token t = p->lx.tok;
    if (t.kind != TK_MINUS || p->lx.src[t.off + 1] != '>')
        return false;
    p->lx.pos = t.off + 2;
    qd__mdl_lex_next(&p->lx);
    return true;
}

/* eps is the finite form's own parameter: a model name eps would be hidden. */
static bool eps_free(parser *p, token kw) {
    const qd_model *m = p->m;
    const char *kind = qd__mdl_find_def(m, "eps", 3) ? "definition" : NULL;
    for (size_t i = 0; i < m->ncoords && !kind; i++)
        if (!strcmp(qd_expr_name(m->coords[i]), "eps"))
            kind = "coordinate";
    for (size_t i = 0; i < m->nparams && !kind; i++)
        if (!strcmp(qd_expr_name(m->params[i]), "eps"))
            kind = "parameter";
    if (!kind && !qd__mdl_find_momentum(m, "eps", 3))
        return true;
    return qd__mdl_perr(p, kw.off, kw.len, "rename it, or give the field: symmetry delta q = ...",
                "'eps' is the symmetry's parameter, but the model has a %s named eps",
                kind ? kind : "momentum");
}

/* One item "q -> EXPR" (finite) or "delta q = EXPR", into xi[j]. */
static bool item(parser *p, bool finite, const qd_expr **xi) {
    qd_ctx *ctx = C(p);
    if (!finite) {
        if (!qd__mdl_lex_is(&p->lx, "delta"))
            return qd__mdl_perr_tok(p, "write every item as delta q = ...",
                                    p->lx.tok.kind == TK_IDENT
                                        ? "one symmetry mixes 'delta q = ...' with 'q -> ...'"
                                        : "expected 'delta q = ...', found %s",
                                    qd__mdl_lex_tk_name(p->lx.tok.kind));
        qd__mdl_lex_next(&p->lx);
    }
    int j = coord_at(p, p->lx.tok);
    if (j < 0)
        return not_a_coordinate(p);
    if (xi[j])
        return qd__mdl_perr_tok(p, "list each coordinate once", "'%s' is moved twice",
                        qd_expr_name(p->m->coords[j]));
    qd__mdl_lex_next(&p->lx);
    if (finite && !arrow(p))
        return qd__mdl_perr_tok(p, p->lx.tok.kind == TK_EQ
                               ? "the field form starts with delta: symmetry delta x = 1"
                               : "write: symmetry x -> x + eps",
                        "expected '->', found %s", qd__mdl_lex_tk_name(p->lx.tok.kind));
    if (!finite) {
        if (p->lx.tok.kind != TK_EQ)
            return qd__mdl_perr_tok(p, "write: symmetry delta x = -y, delta y = x",
                            "expected '=', found %s", qd__mdl_lex_tk_name(p->lx.tok.kind));
        qd__mdl_lex_next(&p->lx);
    }
    size_t off = p->lx.tok.off;
    const qd_expr *rhs;
    p->eps_ok = finite;
    bool ok = qd__mdl_parse_scalar(p, &rhs, "a transformed coordinate");
    p->eps_ok = false;
    if (!ok)
        return false;
    size_t len = p->lx.tok.off - off;
    const qd_expr *v = motion_in(p, rhs, 1);
    if (v)
        return qd__mdl_perr(p, off, len, "a symmetry is a point transformation: q and t only",
                    "a symmetry depends on the velocity %s", qd_expr_name(v));
    const qd_expr *q = p->m->coords[j];
    if (finite) {
        const qd_expr *eps = qd__mdl_eps_symbol(ctx), *zero = qd_int(ctx, 0);
        const qd_expr *at0 = qd_simplify(ctx, qd_subs(ctx, rhs, 1, &eps, &zero));
        if (at0 && !qd_is_zero(qd_simplify(ctx, qd_sub(ctx, at0, q)))) {
            char hint[160];
            snprintf(hint, sizeof hint, "at eps = 0 the transformation is the identity: "
                     "%s -> %s + eps*(...)", qd_expr_name(q), qd_expr_name(q));
            return qd__mdl_perr(p, off, len, hint, "at eps = 0 this is not %s", qd_expr_name(q));
        }
        rhs = qd_simplify(ctx, qd_subs(ctx, qd_diff(ctx, rhs, eps), 1, &eps, &zero));
    } else {
        rhs = qd_simplify(ctx, rhs);
    }
    if (!rhs)
        return qd__mdl_perr(p, off, len ? len : 1, NULL, "%s", qd_ctx_message(ctx));
    xi[j] = rhs;
    return true;
}

/* symmetry [NAME ':'] ITEM (',' ITEM)* */
bool qd__mdl_stmt_symmetry(parser *p) {
    qd_model *m = p->m;
    token kw = p->lx.tok;
    if (m->ncoords == 0)
        return qd__mdl_perr(p, kw.off, kw.len, "declare the coordinates first", "a symmetry before any "
                    "coordinates");
    token lab = label(p);
    char name[QD_MDL_NAME_MAX];
    if (!name_of(p, true, lab, name, sizeof name))
        return false;
    token first = p->lx.tok;
    lexer save = p->lx;
    qd__mdl_lex_next(&p->lx);
    bool finite = !(qd__mdl_lex_is(&save, "delta") && p->lx.tok.kind == TK_IDENT);
    p->lx = save;
    if (finite && !eps_free(p, kw))
        return false;
    const qd_expr **xi = qd__calloc(p->ctx, m->ncoords, sizeof *xi);
    if (!xi)
        return qd__mdl_perr(p, kw.off, kw.len, NULL, "out of memory");
    bool ok = true;
    for (;;) {
        if (!(ok = item(p, finite, xi)) || p->lx.tok.kind != TK_COMMA)
            break;
        qd__mdl_lex_next(&p->lx);
    }
    bool moves = false;
    for (size_t j = 0; ok && j < m->ncoords; j++) {
        if (!xi[j])
            xi[j] = qd_int(C(p), 0);
        moves = moves || !qd_is_zero(xi[j]);
    }
    if (ok && !moves)
        ok = qd__mdl_perr(p, kw.off, kw.len, finite ? "the coordinates must depend on eps: x -> x + eps"
                                            : "give a field that is not zero: delta x = 1",
                  "this symmetry moves nothing");
    symmetry s = {NULL, xi};
    if (ok && !(s.name = copy_of(p->ctx, name)))
        ok = qd__mdl_perr(p, kw.off, kw.len, NULL, "out of memory");
    if (ok && !qd__mdl_push(m->ctx, (void **)&m->syms, &m->nsyms, sizeof s, &s)) {
        qd__free((char *)s.name);
        ok = qd__mdl_perr(p, kw.off, kw.len, NULL, "out of memory");
    }
    if (!ok) {
        qd__free(xi);
        return false;
    }
    if (!add_where(m, "symmetry", name, lab.kind == TK_IDENT ? lab : first))
        return qd__mdl_perr(p, kw.off, kw.len, NULL, "out of memory");
    return qd__mdl_end_of_statement(p);
}

/* integral [NAME ':'] EXPR */
bool qd__mdl_stmt_integral(parser *p) {
    qd_model *m = p->m;
    token kw = p->lx.tok;
    token lab = label(p);
    char name[QD_MDL_NAME_MAX];
    if (!name_of(p, false, lab, name, sizeof name))
        return false;
    size_t off = p->lx.tok.off;
    const qd_expr *I;
    p->momenta_ok = true;
    bool ok = qd__mdl_parse_scalar(p, &I, "an integral");
    p->momenta_ok = false;
    if (!ok)
        return false;
    size_t len = p->lx.tok.off - off;
    const qd_expr *a = motion_in(p, I, 2);
    if (a)
        return qd__mdl_perr(p, off, len, "an integral of motion is a function of q, q' (or p) and t",
                    "an integral depends on the acceleration %s", qd_expr_name(a));
    if (qd_is_number(I))
        return qd__mdl_perr(p, off, len, "propose a function of the coordinates and velocities",
                    "this integral is a constant");
    integral in = {copy_of(p->ctx, name), I};
    if (!in.name || !qd__mdl_push(m->ctx, (void **)&m->ints, &m->nints, sizeof in, &in)) {
        qd__free((char *)in.name);
        return qd__mdl_perr(p, kw.off, kw.len, NULL, "out of memory");
    }
    if (!add_where(m, "integral", name, lab.kind == TK_IDENT ? lab : (token){TK_EOF, off, len}))
        return qd__mdl_perr(p, kw.off, kw.len, NULL, "out of memory");
    return qd__mdl_end_of_statement(p);
}

/* After the last line: an integral speaks the model's language, velocities
 * for a Lagrangian model and momenta for a Hamiltonian one. */
bool qd__mdl_check_integrals(parser *p) {
    qd_model *m = p->m;
    for (size_t i = 0; i < m->nints; i++) {
        const qd_expr *I = m->ints[i].expr, *v = motion_in(p, I, 1), *mom = NULL;
        for (size_t j = 0; m->mom && j < m->ncoords && !mom; j++)
            if (qd_has(I, m->mom[j]))
                mom = m->mom[j];
        const char *bad = m->H && v ? qd_expr_name(v) : !m->H && mom ? qd_expr_name(mom) : NULL;
        if (!bad)
            continue;
        char what[80];
        snprintf(what, sizeof what, "integral:%s", m->ints[i].name);
        qd_diag w;
        qd_model_where(m, what, &w);
        return qd__mdl_perr(p, w.offset, w.length,
                    m->H ? "the model is given by H: write the integral in the coordinates and "
                           "momenta"
                         : "the model is given by T or L: write the integral in the coordinates "
                           "and velocities",
                    m->H ? "an integral of a Hamiltonian model depends on the velocity %s"
                         : "an integral depends on the momentum %s, but the model gives no H",
                    bad);
    }
    return true;
}

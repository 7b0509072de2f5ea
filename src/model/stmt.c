/*
 * src/model/stmt.c - statements of the model language, one per line.
 *
 *   coordinates NAME, ...
 *   parameters NAME = VALUE, ...
 *   functions NAME, ...                 user-named functions: V(r)
 *   NAME = EXPR                         a definition; T V L U dissipation are reserved
 *   particle MASS at POSITION           adds MASS/2 |POSITION'|^2 to T
 *   force F at POSITION                 adds Q_j = F . dPOSITION/dq_j
 *   Q[COORD] = EXPR                     adds to the generalized force on COORD
 *   initial NAME = VALUE, NAME' = VALUE, ...
 *   constraint [NAME:] LHS [= RHS]       kept at zero: LHS - RHS = 0
 *   body NAME mass M inertia I at r [orientation R]    (body.c)
 *   torque G on NAME                                    (body.c)
 *   rolls NAME on SURFACE as SHAPE                      (roll.c)
 *   momenta NAME, ...   and   H = EXPR                  (hamstmt.c)
 *   symmetry [NAME:] ...   and   integral [NAME:] EXPR  (symmetry.c)
 */
#include "parser.h"
#include "../base/mem.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char *const keywords[] = {
    "coordinates", "parameters", "functions", "particle", "force", "initial", "constraint",
    "reaction",
    "body", "torque", "rolls", "momenta", "symmetry", "integral",
};
#define NKEYWORDS (sizeof keywords / sizeof keywords[0])


static const char *const reserved[] = {"T", "V", "L", "U", "H", "dissipation"};

static qd_ctx *C(parser *p) { return p->ctx; }

static void tok_text(const parser *p, char *buf, size_t cap) {
    size_t n = p->lx.tok.len < cap - 1 ? p->lx.tok.len : cap - 1;
    memcpy(buf, p->lx.src + p->lx.tok.off, n);
    buf[n] = '\0';
}

bool qd__mdl_end_of_statement(parser *p) {
    tk_kind k = p->lx.tok.kind;
    if (k == TK_NEWLINE || k == TK_EOF)
        return true;
    if (k == TK_RPAREN || k == TK_RBRACK)
        return qd__mdl_perr_tok(p, "remove it, or add the '(' it should close", "unmatched %s",
                        qd__lex_tk_name(k));
    return qd__mdl_perr_tok(p, "one statement per line", "unexpected %s after the statement",
                    qd__lex_tk_name(k));
}

/* A name not yet used for anything else. */
bool qd__mdl_fresh_name(parser *p, const char *what) {
    char name[128];
    tok_text(p, name, sizeof name);
    const qd_model *m = p->m;
    const char *kind = NULL;
    for (size_t i = 0; i < m->ncoords && !kind; i++)
        if (!strcmp(name, qd_expr_name(m->coords[i])))
            kind = "coordinate";
    for (size_t i = 0; i < m->nparams && !kind; i++)
        if (!strcmp(name, qd_expr_name(m->params[i])))
            kind = "parameter";
    for (size_t i = 0; i < m->nfuncs && !kind; i++)
        if (!strcmp(name, m->funcs[i]))
            kind = "function";
    if (!kind && qd__mdl_find_def(m, name, strlen(name)))
        kind = "definition";
    if (!kind && qd__mdl_find_body(m, name, strlen(name)))
        kind = "body";
    if (!kind && qd__mdl_find_momentum(m, name, strlen(name)))
        kind = "momentum";
    qd_func f;
    if (!kind && (qd_func_from_name(name, &f) || !strcmp(name, "sqrt") || !strcmp(name, "t") ||
                  !strcmp(name, "pi")))
        kind = "built-in name";
    for (size_t i = 0; i < sizeof reserved / sizeof reserved[0] && !kind; i++)
        if (!strcmp(name, reserved[i]))
            kind = "reserved name";
    if (!kind)
        return true;
    char hint[128];
    snprintf(hint, sizeof hint, "choose another name for the %s", what);
    return qd__mdl_perr_tok(p, hint, "'%s' is already a %s", name, kind);
}

/* coordinates NAME (',' NAME)* */
static bool stmt_coordinates(parser *p) {
    if (p->m->mom)
        return qd__mdl_perr_tok(p, "declare every coordinate before the momenta",
                        "coordinates after the momenta");
    do {
        qd__lex_next(&p->lx);
        if (p->lx.tok.kind != TK_IDENT)
            return qd__mdl_perr_tok(p, NULL, "expected a coordinate name, found %s",
                            qd__lex_tk_name(p->lx.tok.kind));
        char name[128];
        tok_text(p, name, sizeof name);
        for (size_t i = 0; i < p->m->ncoords; i++)
            if (!strcmp(name, qd_expr_name(p->m->coords[i])))
                return qd__mdl_perr_tok(p, "each coordinate is declared once",
                                "coordinate '%s' is declared twice", name);
        if (!qd__mdl_fresh_name(p, "coordinate"))
            return false;
        const qd_expr *q = qd_coord(C(p), name);
        if (!q)
            return qd__mdl_perr_tok(p, NULL, "%s", qd_ctx_message(C(p)));
        /* the generalized force and initial values grow with the coordinates */
        qd_model *m = p->m;
        const qd_expr *zero = qd_int(C(p), 0), *none = NULL;
        size_t n = m->ncoords, nq = m->ncoords, ni = 2 * m->ncoords;
        if (!qd__mdl_push(m->ctx, (void **)&m->coords, &n, sizeof q, &q) ||
            !qd__mdl_push(m->ctx, (void **)&m->Q, &nq, sizeof zero, &zero) ||
            !qd__mdl_push(m->ctx, (void **)&m->init, &ni, sizeof none, &none) ||
            !qd__mdl_push(m->ctx, (void **)&m->init, &ni, sizeof none, &none) ||
            !qd__mdl_add_where(m, name, p->lx.tok.off, p->lx.tok.len))
            return qd__mdl_perr_tok(p, NULL, "out of memory");
        m->ncoords = n;
        qd__lex_next(&p->lx);
    } while (p->lx.tok.kind == TK_COMMA);
    return qd__mdl_end_of_statement(p);
}

/* A constant: an expression of numbers, constants and parameters, with the
 * parameters' values put in. */
static bool parse_constant(parser *p, const qd_expr **out, const char *what) {
    size_t off = p->lx.tok.off;
    if (!qd__mdl_parse_scalar(p, out, what))
        return false;
    const qd_model *m = p->m;
    *out = qd_subs(C(p), *out, m->nparams, m->params, m->pvals);
    const qd_expr *sym;
    if (*out && qd_free_symbols(C(p), *out, &sym, 1) > 0)
        return qd__mdl_perr(p, off, p->lx.tok.off - off, "a value is a number, e.g. 9.81 or pi/4",
                    "%s must be a number, but it depends on '%s'", what, qd_expr_name(sym));
    if (!*out)
        return qd__mdl_perr(p, off, 1, NULL, "%s", qd_ctx_message(C(p)));
    /* every command computes with it: 1e400 or sqrt(-1) would be inf or NaN there */
    double x;
    if (qd_eval(C(p), *out, 0, NULL, NULL, &x) != QD_OK || !isfinite(x)) {
        qd_ctx_clear_error(C(p));
        return qd__mdl_perr(p, off, p->lx.tok.off > off ? p->lx.tok.off - off : 1,
                    "give a real number within the range of a double",
                    "%s must be a finite real number", what);
    }
    return true;
}

/* parameters NAME '=' VALUE (',' NAME '=' VALUE)* */
static bool stmt_parameters(parser *p) {
    do {
        qd__lex_next(&p->lx);
        if (p->lx.tok.kind != TK_IDENT)
            return qd__mdl_perr_tok(p, NULL, "expected a parameter name, found %s",
                            qd__lex_tk_name(p->lx.tok.kind));
        char name[128], hint[192];
        tok_text(p, name, sizeof name);
        token at = p->lx.tok;
        if (!qd__mdl_fresh_name(p, "parameter"))
            return false;
        qd__lex_next(&p->lx);
        if (p->lx.tok.kind != TK_EQ) {
            snprintf(hint, sizeof hint, "give a default value: %.40s = 1 (--set %.40s=... overrides it)",
                     name, name);
            return qd__mdl_perr(p, at.off, at.len, hint, "parameter '%s' has no value", name);
        }
        qd__lex_next(&p->lx);
        const qd_expr *v, *sym;
        if (!parse_constant(p, &v, "a parameter's value"))
            return false;
        sym = qd_param(C(p), name);
        if (!sym)
            return qd__mdl_perr(p, at.off, at.len, NULL, "%s", qd_ctx_message(C(p)));
        size_t n = p->m->nparams;
        if (!qd__mdl_push(p->ctx, (void **)&p->m->params, &n, sizeof sym, &sym) ||
            !qd__mdl_push(p->ctx, (void **)&p->m->pvals, &p->m->nparams, sizeof v, &v))
            return qd__mdl_perr_tok(p, NULL, "out of memory");
    } while (p->lx.tok.kind == TK_COMMA);
    return qd__mdl_end_of_statement(p);
}

/* functions NAME (',' NAME)* */
static bool stmt_functions(parser *p) {
    do {
        qd__lex_next(&p->lx);
        if (p->lx.tok.kind != TK_IDENT)
            return qd__mdl_perr_tok(p, NULL, "expected a function name, found %s", qd__lex_tk_name(p->lx.tok.kind));
        char name[128];
        tok_text(p, name, sizeof name);
        if (!qd__mdl_fresh_name(p, "function"))
            return false;
        qd_func f;
        if (qd_func_from_name(name, &f))
            return qd__mdl_perr_tok(p, NULL, "'%s' is a built-in function", name);
        char *copy = qd__malloc(p->ctx, strlen(name) + 1);
        if (!copy || !qd__mdl_push(p->ctx, (void **)&p->m->funcs, &p->m->nfuncs, sizeof copy, &copy)) {
            qd__free(copy);
            return qd__mdl_perr_tok(p, NULL, "out of memory");
        }
        strcpy(copy, name);
        qd__lex_next(&p->lx);
    } while (p->lx.tok.kind == TK_COMMA);
    return qd__mdl_end_of_statement(p);
}

static bool expect_at(parser *p, const char *stmt) {
    if (qd__lex_is(&p->lx, "at")) {
        qd__lex_next(&p->lx);
        return true;
    }
    char hint[96];
    snprintf(hint, sizeof hint, "write: %s", stmt);
    return qd__mdl_perr_tok(p, hint, "expected 'at', found %s", qd__lex_tk_name(p->lx.tok.kind));
}

/* particle MASS at POSITION */
static bool stmt_particle(parser *p) {
    if (!qd__mdl_no_hamiltonian_yet(p, "a particle", p->lx.tok.off, p->lx.tok.len))
        return false;
    qd__lex_next(&p->lx);
    const qd_expr *mass;
    value r;
    if (!qd__mdl_parse_scalar(p, &mass, "a mass") || !expect_at(p, "particle m at (x, y, z)") ||
        !qd__mdl_parse_vector(p, &r, "a position"))
        return false;
    qd_ctx *ctx = C(p);
    const qd_expr *v2 = ctx ? qd_int(ctx, 0) : NULL;
    for (int i = 0; i < 3; i++)
        v2 = qd_add(ctx, v2, qd_powi(ctx, qd_dt(ctx, r.c[i]), 2));
    const qd_expr *t = qd_mul_n(ctx, 3, (const qd_expr *[]){qd_rat(ctx, 1, 2), mass, v2});
    p->m->T = p->m->T ? qd_add(ctx, p->m->T, t) : t;
    if (!p->m->T)
        return qd__mdl_perr(p, r.off, r.len, NULL, "%s", qd_ctx_message(ctx));
    return qd__mdl_end_of_statement(p);
}

/* force F at POSITION: Q_j += F . dr/dq_j (virtual work at frozen time) */
static bool stmt_force(parser *p) {
    qd__lex_next(&p->lx);
    value F, r;
    if (!qd__mdl_parse_vector(p, &F, "a force") || !expect_at(p, "force (Fx, Fy, Fz) at (x, y, z)") ||
        !qd__mdl_parse_vector(p, &r, "a position"))
        return false;
    qd_ctx *ctx = C(p);
    qd_model *m = p->m;
    for (size_t j = 0; j < m->ncoords; j++) {
        const qd_expr *w = qd_int(ctx, 0);
        for (int i = 0; i < 3; i++)
            w = qd_add(ctx, w, qd_mul(ctx, F.c[i], qd_diff(ctx, r.c[i], m->coords[j])));
        m->Q[j] = qd_add(ctx, m->Q[j], w);
        if (!m->Q[j])
            return qd__mdl_perr(p, F.off, F.len, NULL, "%s", qd_ctx_message(ctx));
    }
    return qd__mdl_end_of_statement(p);
}

static int coord_named(parser *p) {
    for (size_t i = 0; i < p->m->ncoords; i++)
        if (qd__mdl_name_is(p->lx.src, p->lx.tok.off, p->lx.tok.len, qd_expr_name(p->m->coords[i])))
            return (int)i;
    return -1;
}

static bool no_such_coordinate(parser *p) {
    char name[128], hint[192] = "";
    tok_text(p, name, sizeof name);
    const char **names = qd__malloc(p->ctx, (p->m->ncoords + 1) * sizeof *names);
    for (size_t i = 0; names && i < p->m->ncoords; i++)
        names[i] = qd_expr_name(p->m->coords[i]);
    const char *near = names ? qd__mdl_nearest(name, strlen(name), names, p->m->ncoords) : NULL;
    if (near)
        snprintf(hint, sizeof hint, "did you mean '%s'?", near);
    qd__free(names);
    return qd__mdl_perr_tok(p, hint, "'%s' is not a coordinate", name);
}

/* Q '[' COORD ']' '=' EXPR */
static bool stmt_genforce(parser *p) {
    qd__lex_next(&p->lx); /* Q */
    qd__lex_next(&p->lx); /* [ */
    int j = coord_named(p);
    if (p->lx.tok.kind != TK_IDENT || j < 0)
        return p->lx.tok.kind == TK_IDENT ? no_such_coordinate(p)
                                          : qd__mdl_perr_tok(p, NULL, "expected a coordinate name");
    qd__lex_next(&p->lx);
    if (p->lx.tok.kind != TK_RBRACK)
        return qd__mdl_perr_tok(p, "write Q[coordinate] = expression", "expected ']'");
    qd__lex_next(&p->lx);
    if (p->lx.tok.kind != TK_EQ)
        return qd__mdl_perr_tok(p, "write Q[coordinate] = expression", "expected '='");
    qd__lex_next(&p->lx);
    const qd_expr *q;
    if (!qd__mdl_parse_scalar(p, &q, "a generalized force"))
        return false;
    p->m->Q[j] = qd_add(C(p), p->m->Q[j], q);
    return qd__mdl_end_of_statement(p);
}

/* initial NAME ['] = VALUE (',' ...)* */
static bool stmt_initial(parser *p) {
    do {
        qd__lex_next(&p->lx);
        int j = coord_named(p);
        if (p->lx.tok.kind != TK_IDENT || j < 0)
            return p->lx.tok.kind == TK_IDENT ? no_such_coordinate(p)
                                              : qd__mdl_perr_tok(p, NULL, "expected a coordinate name");
        qd__lex_next(&p->lx);
        unsigned order = 0;
        for (; p->lx.tok.kind == TK_PRIME; qd__lex_next(&p->lx))
            order++;
        if (order > 1)
            return qd__mdl_perr_tok(p, "give positions and velocities: q = ..., q' = ...",
                            "an initial value is for a coordinate or its velocity");
        if (p->lx.tok.kind != TK_EQ)
            return qd__mdl_perr_tok(p, "write: initial q = 0.5, q' = 0", "expected '='");
        qd__lex_next(&p->lx);
        const qd_expr *v;
        if (!parse_constant(p, &v, "an initial value"))
            return false;
        p->m->init[2 * (size_t)j + order] = v;
    } while (p->lx.tok.kind == TK_COMMA);
    return qd__mdl_end_of_statement(p);
}

static bool constraint_named(const qd_model *m, const char *name) {
    for (size_t i = 0; i < m->ncons; i++)
        if (!strcmp(m->con_names[i], name))
            return true;
    return false;
}

static bool add_constraint_where(qd_model *m, const char *name, token at) {
    char what[80];
    snprintf(what, sizeof what, "constraint:%s", name);
    return qd__mdl_add_where(m, what, at.off, at.len);
}

/* constraint [NAME ':'] LHS ['=' RHS] */
static bool stmt_constraint(parser *p) {
    qd_model *m = p->m;
    qd__lex_next(&p->lx);
    char name[64];
    token at = p->lx.tok;
    lexer save = p->lx;
    qd__lex_next(&p->lx);
    bool named = at.kind == TK_IDENT && p->lx.tok.kind == TK_COLON;
    if (named) {
        snprintf(name, sizeof name, "%.*s", (int)(at.len < 63 ? at.len : 63), p->lx.src + at.off);
        if (constraint_named(m, name))
            return qd__mdl_perr(p, at.off, at.len, "give each constraint its own name",
                        "constraint '%s' is named twice", name);
        qd__lex_next(&p->lx);
    } else {
        p->lx = save;
        size_t k = m->ncons + 1;
        do
            snprintf(name, sizeof name, "c%zu", k++);
        while (constraint_named(m, name));
    }
    size_t off = p->lx.tok.off;
    const qd_expr *lhs, *rhs = NULL;
    if (!qd__mdl_parse_scalar(p, &lhs, "a constraint"))
        return false;
    if (p->lx.tok.kind == TK_EQ) {
        qd__lex_next(&p->lx);
        if (!qd__mdl_parse_scalar(p, &rhs, "a constraint"))
            return false;
    }
    const qd_expr *c = rhs ? qd_sub(C(p), lhs, rhs) : lhs;
    if (!c)
        return qd__mdl_perr(p, off, 1, NULL, "%s", qd_ctx_message(C(p)));
    if (qd_is_number(c))
        return qd__mdl_perr(p, off, p->lx.tok.off - off, "a constraint relates coordinates or velocities",
                    qd_is_zero(c) ? "this constraint always holds" : "this constraint can never hold");
    char *copy = qd__malloc(p->ctx, strlen(name) + 1);
    if (copy)
        strcpy(copy, name);
    size_t n = m->ncons;
    if (!copy || !qd__mdl_push(m->ctx, (void **)&m->con_names, &n, sizeof copy, &copy) ||
        !qd__mdl_push(m->ctx, (void **)&m->cons, &m->ncons, sizeof c, &c) ||
        !add_constraint_where(m, name, named ? at : (token){TK_EOF, off, 1})) {
        qd__free(copy);
        return qd__mdl_perr(p, off, 1, NULL, "out of memory");
    }
    return qd__mdl_end_of_statement(p);
}

static const qd_expr **reserved_slot(qd_model *m, const char *name) {
    if (!strcmp(name, "T")) return &m->T;
    if (!strcmp(name, "V")) return &m->V;
    if (!strcmp(name, "L")) return &m->L;
    if (!strcmp(name, "U")) return &m->U;
    if (!strcmp(name, "dissipation")) return &m->D;
    return NULL;
}

/* NAME '=' EXPR */
static bool stmt_definition(parser *p) {
    char name[128];
    tok_text(p, name, sizeof name);
    token at = p->lx.tok;
    const qd_expr **slot = reserved_slot(p->m, name);
    bool explicit_T = slot == &p->m->T;
    if (slot && slot != &p->m->D && !qd__mdl_no_hamiltonian_yet(p, name, at.off, at.len))
        return false;
    if (!slot && !qd__mdl_fresh_name(p, "definition"))
        return false;
    if (slot && (explicit_T ? qd_model_where(p->m, "T", NULL) : *slot != NULL)) {
        qd_diag first;
        qd_model_where(p->m, name, &first);
        return qd__mdl_perr(p, at.off, at.len, "give it once; add the parts in one expression",
                    "%s is given twice (first on line %zu)", name, first.line);
    }
    qd__lex_next(&p->lx); /* '=' */
    qd__lex_next(&p->lx);
    p->defining = name;
    value v;
    bool ok = qd__mdl_parse_expr(p, &v);
    p->defining = NULL;
    if (!ok)
        return false;
    if (slot) {
        if (v.kind != VK_SCALAR)
            return qd__mdl_perr(p, v.off, v.len, v.kind == VK_VECTOR
                            ? "an energy is a scalar: use dot(v, v) for |v|^2"
                            : "an energy is a scalar",
                        "a %s where a scalar is needed: %s is a scalar", qd__mdl_vkind_name(v.kind), name);
        /* particle lines and T = ... add up */
        *slot = explicit_T && *slot ? qd_add(C(p), *slot, v.c[0]) : v.c[0];
    } else if (!qd__mdl_add_def(p->m, name, v, at.off, at.len)) {
        return qd__mdl_perr(p, at.off, at.len, NULL, "out of memory");
    }
    if (!qd__mdl_add_where(p->m, name, at.off, at.len))
        return qd__mdl_perr(p, at.off, at.len, NULL, "out of memory");
    return qd__mdl_end_of_statement(p);
}

static bool unknown_statement(parser *p) {
    char word[128], hint[192] = "";
    tok_text(p, word, sizeof word);
    const char *near = qd__mdl_nearest(word, strlen(word), keywords, NKEYWORDS);
    if (near)
        snprintf(hint, sizeof hint, "did you mean '%s'?", near);
    else
        snprintf(hint, sizeof hint, "a statement starts with a keyword (coordinates, parameters, "
                 "particle, body, force, torque, initial, functions, constraint, momenta, "
                 "symmetry, integral) or is a definition NAME = ...");
    return qd__mdl_perr_tok(p, hint, "unknown statement '%s'", word);
}

static bool statement(parser *p) {
    lexer *lx = &p->lx;
    if (lx->tok.kind != TK_IDENT) {
        if (lx->tok.kind == TK_RPAREN || lx->tok.kind == TK_RBRACK)
            return qd__mdl_end_of_statement(p);
        return qd__mdl_perr_tok(p, NULL, "expected a statement, found %s", qd__lex_tk_name(lx->tok.kind));
    }
    if (qd__lex_is(lx, "coordinates"))
        return stmt_coordinates(p);
    if (qd__lex_is(lx, "parameters"))
        return stmt_parameters(p);
    if (qd__lex_is(lx, "functions"))
        return stmt_functions(p);
    if (qd__lex_is(lx, "particle"))
        return stmt_particle(p);
    if (qd__lex_is(lx, "force"))
        return stmt_force(p);
    if (qd__lex_is(lx, "initial"))
        return stmt_initial(p);
    if (qd__lex_is(lx, "constraint"))
        return stmt_constraint(p);
    /* NAME '=' or Q '[': look one token ahead without consuming */
    lexer save = *lx;
    qd__lex_next(lx);
    tk_kind next = lx->tok.kind;
    *lx = save;
    /* the newer keywords stay usable as names defined before they existed */
    if (qd__lex_is(lx, "body") && next != TK_EQ)
        return qd__mdl_stmt_body(p);
    if (qd__lex_is(lx, "torque") && next != TK_EQ)
        return qd__mdl_stmt_torque(p);
    if (qd__lex_is(lx, "rolls") && next != TK_EQ)
        return qd__mdl_stmt_rolls(p);
    if (qd__lex_is(lx, "reaction") && next != TK_EQ)
        return qd__mdl_stmt_reaction(p);
    if (qd__lex_is(lx, "momenta") && next != TK_EQ)
        return qd__mdl_stmt_momenta(p);
    if (qd__lex_is(lx, "symmetry") && next != TK_EQ)
        return qd__mdl_stmt_symmetry(p);
    if (qd__lex_is(lx, "integral") && next != TK_EQ)
        return qd__mdl_stmt_integral(p);
    if (qd__lex_is(lx, "H") && next == TK_EQ)
        return qd__mdl_stmt_hamiltonian(p);
    if (next == TK_EQ)
        return stmt_definition(p);
    if (next == TK_LBRACK && qd__lex_is(lx, "Q"))
        return stmt_genforce(p);
    return unknown_statement(p);
}

/* After the last line: the Lagrangian and the checks that need the whole file. */
static bool finish(parser *p) {
    qd_model *m = p->m;
    qd_ctx *ctx = C(p);
    if (m->ncoords == 0)
        return qd__mdl_perr(p, 0, 1, "declare them: coordinates q1, q2", "no coordinates are declared");
    if (!qd__mdl_check_integrals(p))
        return false;
    if (m->H)
        return true; /* the Lagrangian, if any, is the mechanics layer's inverse Legendre */
    if (!m->L && !m->T)
        return qd__mdl_perr(p, p->lx.tok.off, 1,
                    "give the kinetic energy T = ... (and V = ...), or particles, or L = ..., "
                    "or momenta and H = ...",
                    "neither T nor L is given");
    if (!m->L) {
        const qd_expr *zero = qd_int(ctx, 0);
        m->L = qd_sub(ctx, qd_sub(ctx, m->T, m->V ? m->V : zero), m->U ? m->U : zero);
    }
    if (!m->L)
        return qd__mdl_perr(p, 0, 1, NULL, "%s", qd_ctx_message(ctx));
    return true;
}

qd_model *qd_model_parse(qd_ctx *ctx, const char *text, qd_diag *diag) {
    qd_model *m = qd__calloc(ctx, 1, sizeof *m);
    if (!m) {
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory");
        return NULL;
    }
    m->ctx = ctx;
    m->text = text;
    parser p = {ctx, {0}, m, diag, false, NULL, false, false};
    qd__lex_init(&p.lx, text);
    while (!p.failed && p.lx.tok.kind != TK_EOF) {
        if (p.lx.tok.kind == TK_NEWLINE) {
            qd__lex_next(&p.lx);
            continue;
        }
        if (statement(&p) && p.lx.tok.kind == TK_NEWLINE)
            qd__lex_next(&p.lx);
    }
    if (!p.failed && p.lx.depth > 0) {
        size_t open = p.lx.open[p.lx.depth - 1 < LEX_MAX_DEPTH ? p.lx.depth - 1 : 0];
        qd__mdl_perr(&p, open, 1, "every bracket opened must be closed", "unclosed '%c'", text[open]);
    }
    if (!p.failed)
        finish(&p);
    if (p.failed) {
        qd_model_free(m);
        return NULL;
    }
    return m;
}

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
 *   impulse J at r, impulse G on BODY, Qhat[q] = X      (impulse.c)
 *   impact constraint NAME: ..., impact NAME: GAP >= 0, prescribe ...
 *   speeds NAME = EXPR, ...                             (speeds.c)
 *   inductance, capacitance, resistance, source ... on BRANCH  (circuit.c)
 *   friction MU on POINT against CONSTRAINT            (friction_point.c)
 */
#include "parser.h"
#include "../base/mem.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char *const reserved[] = {"T", "V", "L", "U", "H", "dissipation"};

static qd_ctx *C(parser *p) { return p->ctx; }
static bool no_acceleration(parser *p, const char *what, const qd_expr *e, size_t off,
                            size_t len);

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
                        qd__mdl_lex_tk_name(k));
    return qd__mdl_perr_tok(p, "one statement per line", "unexpected %s after the statement",
                    qd__mdl_lex_tk_name(k));
}

/* NAME '=' EXPR, one item of a statement that defines new names (outputs,
 * speeds): a name, fresh by fresh (NULL: qd__mdl_fresh_name), then its
 * definition, parsed with the name as the one being defined (a definition
 * that uses itself is an error).  noun words the messages, usage is the
 * hint. */
bool qd__mdl_named_definition(parser *p, const char *noun, const char *usage,
                              bool (*fresh)(parser *p, const char *name, token at),
                              char name[QD_MDL_NAME_MAX], token *at, value *v) {
    const char *a = strchr("aeiou", noun[0]) ? "an" : "a";
    qd__mdl_lex_next(&p->lx);
    *at = p->lx.tok;
    if (at->kind != TK_IDENT)
        return qd__mdl_perr_tok(p, usage, "expected %s %s's name, found %s", a, noun,
                                qd__mdl_lex_tk_name(at->kind));
    snprintf(name, QD_MDL_NAME_MAX, "%.*s",
             (int)(at->len < QD_MDL_NAME_MAX - 1 ? at->len : QD_MDL_NAME_MAX - 1),
             p->lx.src + at->off);
    if (!(fresh ? fresh(p, name, *at) : qd__mdl_fresh_name(p, noun)))
        return false;
    qd__mdl_lex_next(&p->lx);
    if (p->lx.tok.kind != TK_EQ) {
        char hint[256];
        snprintf(hint, sizeof hint, "%s %s is defined where it is named: %s", a, noun, usage);
        return qd__mdl_perr(p, at->off, at->len, hint, "%s '%s' has no definition", noun, name);
    }
    qd__mdl_lex_next(&p->lx);
    p->defining = name;
    bool ok = qd__mdl_parse_expr(p, v);
    p->defining = NULL;
    return ok;
}

/* A name not yet used for anything else. */
bool qd__mdl_fresh_name(parser *p, const char *what) {
    char name[128];
    tok_text(p, name, sizeof name);
    const qd_model *m = p->m;
    const char *kind = NULL;
    size_t n = strlen(name);
    if (qd__mdl_names_find(m, QD_MDL_NAME_COORD, name, n) >= 0)
        kind = "coordinate";
    else if (qd__mdl_names_find(m, QD_MDL_NAME_PARAM, name, n) >= 0)
        kind = "parameter";
    else if (qd__mdl_names_find(m, QD_MDL_NAME_FUNC, name, n) >= 0)
        kind = "function";
    if (!kind && qd__mdl_find_def(m, name, strlen(name)))
        kind = "definition";
    if (!kind && qd__mdl_find_body(m, name, strlen(name)))
        kind = "body";
    if (!kind && qd__mdl_find_momentum(m, name, strlen(name)))
        kind = "momentum";
    if (!kind && qd__mdl_find_speed(m, name, strlen(name)) >= 0)
        kind = "speed";
    if (!kind && qd__mdl_find_input(m, name, strlen(name)))
        kind = "input";
    if (!kind && m->indep && !strcmp(name, m->indep))
        kind = "independent variable";
    qd_func f;
    if (!kind && (qd_func_from_name(name, &f) || !strcmp(name, "sqrt") || !strcmp(name, "t") ||
                  !strcmp(name, "pi")))
        kind = "built-in name";
    /* `L = ...` always gives the Lagrangian and a name in an expression is
     * never an energy, so a parameter L or a function V (V = V(r)) is told
     * apart by the grammar; a coordinate is not, as it names a statement's
     * place (qd_model_where) */
    bool value_name = !strcmp(what, "parameter") || !strcmp(what, "function");
    for (size_t i = 0; i < sizeof reserved / sizeof reserved[0] && !kind && !value_name; i++)
        if (!strcmp(name, reserved[i]))
            kind = "reserved name";
    if (!kind)
        return true;
    char hint[128];
    snprintf(hint, sizeof hint, "choose another name for the %s", what);
    return qd__mdl_perr_tok(p, hint, "'%s' is already %s %s", name,
                            strchr("aeiou", kind[0]) ? "an" : "a", kind);
}

/* coordinates NAME (',' NAME)* */
static bool stmt_coordinates(parser *p) {
    if (p->m->mom)
        return qd__mdl_perr_tok(p, "declare every coordinate before the momenta",
                        "coordinates after the momenta");
    do {
        qd__mdl_lex_next(&p->lx);
        if (p->lx.tok.kind != TK_IDENT)
            return qd__mdl_perr_tok(p, NULL, "expected a coordinate name, found %s",
                            qd__mdl_lex_tk_name(p->lx.tok.kind));
        char name[128];
        tok_text(p, name, sizeof name);
        if (qd__mdl_names_find(p->m, QD_MDL_NAME_COORD, name, strlen(name)) >= 0)
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
        size_t n = m->ncoords, nq = m->ncoords, ni = 2 * m->ncoords, nd = 2 * m->ncoords;
        size_t nh = m->ncoords;
        if (!qd__mdl_push(m->ctx, (void **)&m->coords, &n, sizeof q, &q) ||
            !qd__mdl_push(m->ctx, (void **)&m->Q, &nq, sizeof zero, &zero) ||
            !qd__mdl_push(m->ctx, (void **)&m->Qhat, &nh, sizeof zero, &zero) ||
            !qd__mdl_push(m->ctx, (void **)&m->init, &ni, sizeof none, &none) ||
            !qd__mdl_push(m->ctx, (void **)&m->init, &ni, sizeof none, &none) ||
            !qd__mdl_push(m->ctx, (void **)&m->init_defs, &nd, sizeof none, &none) ||
            !qd__mdl_push(m->ctx, (void **)&m->init_defs, &nd, sizeof none, &none) ||
            !qd__mdl_add_where(m, name, p->lx.tok.off, p->lx.tok.len))
            return qd__mdl_perr_tok(p, NULL, "out of memory");
        m->ncoords = n;
        if (!qd__mdl_names_add(m, QD_MDL_NAME_COORD, n - 1))
            return qd__mdl_perr_tok(p, NULL, "out of memory");
        qd__mdl_lex_next(&p->lx);
    } while (p->lx.tok.kind == TK_COMMA);
    return qd__mdl_end_of_statement(p);
}

/* The value given from outside for the parameter name (the last of its
 * name wins), or NULL. */
static const qd_expr *given_value(parser *p, const char *name) {
    const qd_model_opts *o = p->opts;
    for (size_t k = o ? o->nparams : 0; k-- > 0;)
        if (o->params[k].name && !strcmp(o->params[k].name, name)) {
            for (size_t j = 0; j < o->nparams; j++)
                if (o->params[j].name && !strcmp(o->params[j].name, name))
                    p->set_used[j] = true;
            return o->params[k].value;
        }
    return NULL;
}

/* A constant: an expression of numbers, constants and parameters.  *def is
 * it as written (or given, when given is not NULL), *out its number with the
 * parameters' values put in. */
static bool parse_constant(parser *p, const qd_expr *given, const qd_expr **def,
                           const qd_expr **out, const char *what);

bool qd__mdl_parse_constant(parser *p, const qd_expr **def, const qd_expr **out,
                            const char *what) {
    return parse_constant(p, NULL, def, out, what);
}

static bool parse_constant(parser *p, const qd_expr *given, const qd_expr **def,
                           const qd_expr **out, const char *what) {
    size_t off = p->lx.tok.off;
    if (!qd__mdl_parse_scalar(p, def, what))
        return false;
    size_t len = p->lx.tok.off > off ? p->lx.tok.off - off : 1;
    if (given)
        *def = given;
    const qd_model *m = p->m;
    *out = qd__mdl_subs_params(m, *def, m->nparams);
    const qd_expr *sym;
    size_t nsym = *out ? qd_free_symbols(C(p), *out, &sym, 1) : 0;
    if (qd__ctx_nomem(C(p))) /* 0 symbols may mean out of memory */
        return qd__mdl_perr(p, off, 1, NULL, "%s", qd_ctx_message(C(p)));
    if (nsym > 0)
        return qd__mdl_perr(p, off, len, "a value is a number, e.g. 9.81 or pi/4",
                    "%s must be a number, but it depends on '%s'", what, qd_expr_name(sym));
    if (!*out)
        return qd__mdl_perr(p, off, 1, NULL, "%s", qd_ctx_message(C(p)));
    /* every command computes with it: 1e400 or sqrt(-1) would be inf or NaN there */
    double x;
    if (qd_eval(C(p), *out, 0, NULL, NULL, &x) != QD_OK || !isfinite(x)) {
        qd__ctx_recover(C(p));
        return qd__mdl_perr(p, off, len, "give a real number within the range of a double",
                    "%s must be a finite real number", what);
    }
    return true;
}

static bool push_param(parser *p, const qd_expr *sym, const qd_expr *def, const qd_expr *v,
                       bool fixed) {
    qd_model *m = p->m;
    size_t n1 = m->nparams, n2 = m->nparams, n3 = m->nparams;
    return qd__mdl_push(m->ctx, (void **)&m->params, &n1, sizeof sym, &sym) &&
           qd__mdl_push(m->ctx, (void **)&m->pdefs, &n2, sizeof def, &def) &&
           qd__mdl_push(m->ctx, (void **)&m->pfixed, &n3, sizeof fixed, &fixed) &&
           qd__mdl_push(m->ctx, (void **)&m->pvals, &m->nparams, sizeof v, &v) &&
           qd__mdl_names_add(m, QD_MDL_NAME_PARAM, m->nparams - 1);
}

/* parameters NAME '=' VALUE (',' NAME '=' VALUE)* */
/* A parameter whose value is positive (after --set) is assumed positive, so
 * that sqrt(g^2*l^2) is g*l, as a physicist writes it; qd_model_set_param
 * later refuses to make it zero or negative.  A context keeps one symbol
 * per name: a name assumed positive by an earlier model cannot take a value
 * <= 0 here (the earlier simplifications would be wrong for it). */
static const qd_expr *param_symbol(parser *p, const char *name, const qd_expr *v, token at) {
    double x = 0;
    if (qd_eval(C(p), v, 0, NULL, NULL, &x) != QD_OK)
        return NULL;
    const qd_expr *old = qd_lookup(C(p), name);
    if (x > 0 && (!old || qd_symbol_is_positive(old)))
        return qd_symbol_positive(C(p), name, QD_ROLE_PARAM);
    if (x <= 0 && old && qd_symbol_is_positive(old)) {
        qd__mdl_perr(p, at.off, at.len, "read this model in a context of its own",
                     "'%s' was assumed positive by a model read earlier in this context, "
                     "but its value here is %g", name, x);
        return NULL;
    }
    return qd_param(C(p), name);
}

static bool stmt_parameters(parser *p) {
    do {
        qd__mdl_lex_next(&p->lx);
        if (p->lx.tok.kind != TK_IDENT)
            return qd__mdl_perr_tok(p, NULL, "expected a parameter name, found %s",
                            qd__mdl_lex_tk_name(p->lx.tok.kind));
        char name[128], hint[192];
        tok_text(p, name, sizeof name);
        token at = p->lx.tok;
        if (!qd__mdl_fresh_name(p, "parameter"))
            return false;
        qd__mdl_lex_next(&p->lx);
        if (p->lx.tok.kind != TK_EQ) {
            snprintf(hint, sizeof hint, "give a default value: %.40s = 1 (--set %.40s=... overrides it)",
                     name, name);
            return qd__mdl_perr(p, at.off, at.len, hint, "parameter '%s' has no value", name);
        }
        qd__mdl_lex_next(&p->lx);
        const qd_expr *given = given_value(p, name), *def, *v, *sym;
        p->met_fixed = false;
        if (!parse_constant(p, given, &def, &v, "a parameter's value"))
            return false;
        /* defined from a fixed parameter: a number of this model too */
        bool fixed = (given && p->opts->fix_params) || (!given && p->met_fixed);
        sym = param_symbol(p, name, v, at);
        if (!sym && p->failed)
            return false;
        if (!sym)
            return qd__mdl_perr(p, at.off, at.len, NULL, "%s", qd_ctx_message(C(p)));
        if (!push_param(p, sym, def, v, fixed))
            return qd__mdl_perr_tok(p, NULL, "out of memory");
    } while (p->lx.tok.kind == TK_COMMA);
    return qd__mdl_end_of_statement(p);
}

/* functions NAME (',' NAME)* */
static bool stmt_functions(parser *p) {
    do {
        qd__mdl_lex_next(&p->lx);
        if (p->lx.tok.kind != TK_IDENT)
            return qd__mdl_perr_tok(p, NULL, "expected a function name, found %s",
                                    qd__mdl_lex_tk_name(p->lx.tok.kind));
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
        if (!qd__mdl_names_add(p->m, QD_MDL_NAME_FUNC, p->m->nfuncs - 1))
            return qd__mdl_perr_tok(p, NULL, "out of memory");
        qd__mdl_lex_next(&p->lx);
    } while (p->lx.tok.kind == TK_COMMA);
    return qd__mdl_end_of_statement(p);
}

bool qd__mdl_expect_at(parser *p, const char *stmt) {
    if (qd__mdl_lex_is(&p->lx, "at")) {
        qd__mdl_lex_next(&p->lx);
        return true;
    }
    char hint[96];
    snprintf(hint, sizeof hint, "write: %s", stmt);
    return qd__mdl_perr_tok(p, hint, "expected 'at', found %s",
                            qd__mdl_lex_tk_name(p->lx.tok.kind));
}

/* particle MASS at POSITION */
static bool stmt_particle(parser *p) {
    if (!qd__mdl_no_hamiltonian_yet(p, "a particle", p->lx.tok.off, p->lx.tok.len))
        return false;
    qd__mdl_lex_next(&p->lx);
    const qd_expr *mass;
    value r;
    if (!qd__mdl_parse_scalar(p, &mass, "a mass") || !qd__mdl_expect_at(p, "particle m at (x, y, z)") ||
        !qd__mdl_parse_vector(p, &r, "a position"))
        return false;
    for (int i = 0; i < 3; i++)
        if (!no_acceleration(p, "a particle's position", r.c[i], r.off, r.len))
            return false;
    qd_ctx *ctx = C(p);
    const qd_expr *v2 = ctx ? qd_int(ctx, 0) : NULL;
    for (int i = 0; i < 3; i++)
        v2 = qd_add(ctx, v2, qd_powi(ctx, qd_dt(ctx, r.c[i]), 2));
    const qd_expr *t = qd_mul_n(ctx, 3, (const qd_expr *[]){qd_rat(ctx, 1, 2), mass, v2});
    p->m->T = p->m->T ? qd_add(ctx, p->m->T, t) : t;
    if (!p->m->T)
        return qd__mdl_perr(p, r.off, r.len, NULL, "%s", qd_ctx_message(ctx));
    /* kept for what needs the particles themselves: a collision's lab and
     * centre-of-mass frames */
    particle pt = {mass, {r.c[0], r.c[1], r.c[2]}};
    if (!qd__mdl_push(ctx, (void **)&p->m->parts, &p->m->nparts, sizeof pt, &pt))
        return qd__mdl_perr(p, r.off, r.len, NULL, "out of memory");
    return qd__mdl_end_of_statement(p);
}

/* force F at POSITION: Q_j += F . dr/dq_j (virtual work at frozen time) */
static bool stmt_force(parser *p) {
    qd__mdl_lex_next(&p->lx);
    value F, r;
    if (!qd__mdl_parse_vector(p, &F, "a force") || !qd__mdl_expect_at(p, "force (Fx, Fy, Fz) at (x, y, z)") ||
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
    if (p->lx.tok.kind != TK_IDENT)
        return -1;
    return (int)qd__mdl_names_find(p->m, QD_MDL_NAME_COORD, p->lx.src + p->lx.tok.off,
                                   p->lx.tok.len);
}

/* The name at the token is none of the coordinates (nor, with speeds, of
 * the speeds): say so with the nearest of them. */
static bool not_among(parser *p, bool speeds) {
    char name[128], hint[192] = "";
    tok_text(p, name, sizeof name);
    const qd_model *m = p->m;
    size_t ns = speeds ? m->nspeeds : 0, n = 0;
    const char **names = qd__malloc(p->ctx, (m->ncoords + ns + 1) * sizeof *names);
    for (size_t i = 0; names && i < m->ncoords; i++)
        names[n++] = qd_expr_name(m->coords[i]);
    for (size_t i = 0; names && i < ns; i++)
        names[n++] = qd_expr_name(m->speeds[i].sym);
    const char *near = names ? qd__diag_nearest(name, strlen(name), names, n) : NULL;
    if (near)
        snprintf(hint, sizeof hint, "did you mean '%s'?", near);
    qd__free(names);
    return qd__mdl_perr_tok(p, hint, ns ? "'%s' is not a coordinate or a speed"
                                        : "'%s' is not a coordinate", name);
}

static bool no_such_coordinate(parser *p) { return not_among(p, false); }

int qd__mdl_coord_subscript(parser *p, const char *usage) {
    qd__mdl_lex_next(&p->lx); /* the name */
    qd__mdl_lex_next(&p->lx); /* [ */
    int j = coord_named(p);
    if (p->lx.tok.kind != TK_IDENT || j < 0) {
        if (p->lx.tok.kind == TK_IDENT)
            no_such_coordinate(p);
        else
            qd__mdl_perr_tok(p, NULL, "expected a coordinate name");
        return -1;
    }
    qd__mdl_lex_next(&p->lx);
    if (p->lx.tok.kind != TK_RBRACK)
        return qd__mdl_perr_tok(p, usage, "expected ']'"), -1;
    qd__mdl_lex_next(&p->lx);
    if (p->lx.tok.kind != TK_EQ)
        return qd__mdl_perr_tok(p, usage, "expected '='"), -1;
    qd__mdl_lex_next(&p->lx);
    return j;
}

/* Q '[' COORD ']' '=' EXPR */
static bool stmt_genforce(parser *p) {
    int j = qd__mdl_coord_subscript(p, "write Q[coordinate] = expression");
    if (j < 0)
        return false;
    const qd_expr *q;
    if (!qd__mdl_parse_scalar(p, &q, "a generalized force"))
        return false;
    p->m->Q[j] = qd_add(C(p), p->m->Q[j], q);
    return qd__mdl_end_of_statement(p);
}

/* The initial value named name (with its prime, "q'") is given once in the
 * text being read: else an error at off..off+len naming the first place.
 * A statement added to a model later (qd_model_add_statement) may replace
 * a value of the model's text. */
static bool initial_once(parser *p, const char *name, size_t off, size_t len) {
    qd_model *m = p->m;
    char key[QD_MDL_NAME_MAX + 16];
    snprintf(key, sizeof key, "initial:%s", name);
    long i = qd__mdl_names_find(m, QD_MDL_NAME_WHERE, key, strlen(key));
    if (i >= 0 && m->wheres[i].src == m->src) {
        size_t line, col;
        qd__diag_line_col(m->src, m->wheres[i].off, &line, &col, NULL);
        char hint[QD_MDL_NAME_MAX + 96];
        snprintf(hint, sizeof hint, "the first is at line %zu, column %zu; give each initial value once",
                 line, col);
        return qd__mdl_perr(p, off, len, hint, "the initial value of %s is given twice (first on "
                            "line %zu)", name, line);
    }
    return qd__mdl_add_where(m, key, off, len) || qd__mdl_perr(p, off, len, NULL, "out of memory");
}

/* initial SPEED = VALUE: the speed itself, not its rate (a speed is
 * already a velocity). */
static bool initial_speed(parser *p, speed *s) {
    if (!initial_once(p, qd_expr_name(s->sym), p->lx.tok.off, p->lx.tok.len))
        return false;
    qd__mdl_lex_next(&p->lx);
    if (p->lx.tok.kind == TK_PRIME)
        return qd__mdl_perr_tok(p, "give the speed's own value: initial u1 = 0.3",
                                "an initial value is for a speed, not its rate");
    if (p->lx.tok.kind != TK_EQ)
        return qd__mdl_perr_tok(p, "write: initial u1 = 0.3", "expected '='");
    qd__mdl_lex_next(&p->lx);
    const qd_expr *def, *v;
    if (!parse_constant(p, NULL, &def, &v, "an initial value"))
        return false;
    s->init_def = def;
    s->init = v;
    return true;
}

/* initial NAME ['] = VALUE (',' ...)*, NAME a coordinate or a speed */
static bool stmt_initial(parser *p) {
    do {
        qd__mdl_lex_next(&p->lx);
        long k = p->lx.tok.kind == TK_IDENT
                     ? qd__mdl_find_speed(p->m, p->lx.src + p->lx.tok.off, p->lx.tok.len) : -1;
        if (k >= 0) {
            if (!initial_speed(p, &p->m->speeds[k]))
                return false;
            continue;
        }
        int j = coord_named(p);
        if (p->lx.tok.kind != TK_IDENT || j < 0)
            return p->lx.tok.kind == TK_IDENT ? not_among(p, true)
                                              : qd__mdl_perr_tok(p, NULL, "expected a coordinate name");
        token at = p->lx.tok;
        qd__mdl_lex_next(&p->lx);
        unsigned order = 0;
        for (; p->lx.tok.kind == TK_PRIME; qd__mdl_lex_next(&p->lx))
            order++;
        if (order > 1)
            return qd__mdl_perr_tok(p, "give positions and velocities: q = ..., q' = ...",
                            "an initial value is for a coordinate or its velocity");
        char name[QD_MDL_NAME_MAX + 1];
        snprintf(name, sizeof name, "%s%s", qd_expr_name(p->m->coords[j]), order ? "'" : "");
        if (!initial_once(p, name, at.off, at.len + order))
            return false;
        if (p->lx.tok.kind != TK_EQ)
            return qd__mdl_perr_tok(p, "write: initial q = 0.5, q' = 0", "expected '='");
        qd__mdl_lex_next(&p->lx);
        const qd_expr *def, *v;
        if (!parse_constant(p, NULL, &def, &v, "an initial value"))
            return false;
        p->m->init_defs[2 * (size_t)j + order] = def;
        p->m->init[2 * (size_t)j + order] = v;
    } while (p->lx.tok.kind == TK_COMMA);
    return qd__mdl_end_of_statement(p);
}

static bool in_list(const sudden *s, size_t n, const char *name) {
    for (size_t i = 0; i < n; i++)
        if (!strcmp(s[i].name, name))
            return true;
    return false;
}

/* One namespace for every relation with a multiplier: a reaction names its
 * constraint, and lambda_NAME and Lambda_NAME must not read alike. */
static bool constraint_named(const qd_model *m, const char *name) {
    for (size_t i = 0; i < m->ncons; i++)
        if (!strcmp(m->con_names[i], name))
            return true;
    return in_list(m->sudden, m->nsudden, name) || in_list(m->impacts, m->nimpacts, name) ||
           in_list(m->prescribed, m->nprescribed, name) || qd__mdl_isoperimetric_named(m, name);
}

bool qd__mdl_push_constraint(parser *p, const char *name, const qd_expr *c, size_t off,
                             size_t len) {
    qd_model *m = p->m;
    char *copy = qd__malloc(p->ctx, strlen(name) + 1);
    if (copy)
        strcpy(copy, name);
    size_t n = m->ncons;
    if (!copy || !qd__mdl_push(m->ctx, (void **)&m->con_names, &n, sizeof copy, &copy)) {
        qd__free(copy);
        return qd__mdl_perr(p, off, len, NULL, "out of memory");
    }
    if (!qd__mdl_push(m->ctx, (void **)&m->cons, &m->ncons, sizeof c, &c)) {
        m->con_names[n - 1] = NULL; /* not counted by ncons: the model does not free it */
        qd__free(copy);
        return qd__mdl_perr(p, off, len, NULL, "out of memory");
    }
    /* from here the model owns the name (ncons counts it) */
    char what[160];
    snprintf(what, sizeof what, "constraint:%s", name);
    return qd__mdl_add_where(m, what, off, len) ||
           qd__mdl_perr(p, off, len, NULL, "out of memory");
}

bool qd__mdl_constraint_named(const qd_model *m, const char *name) {
    return constraint_named(m, name);
}

/* constraint [NAME ':'] LHS ['=' RHS] */
static bool stmt_constraint(parser *p) {
    qd_model *m = p->m;
    qd__mdl_lex_next(&p->lx);
    char name[QD_MDL_NAME_MAX];
    token at = p->lx.tok;
    lexer save = p->lx;
    qd__mdl_lex_next(&p->lx);
    bool named = at.kind == TK_IDENT && p->lx.tok.kind == TK_COLON;
    if (named) {
        snprintf(name, sizeof name, "%.*s", (int)at.len, p->lx.src + at.off); /* at most 127 */
        if (constraint_named(m, name))
            return qd__mdl_perr(p, at.off, at.len, "give each constraint its own name",
                        "constraint '%s' is named twice", name);
        qd__mdl_lex_next(&p->lx);
    } else {
        p->lx = save;
        size_t k = m->ncons + 1;
        do
            snprintf(name, sizeof name, "c%zu", k++);
        while (constraint_named(m, name));
    }
    if (qd__mdl_integral_ahead(p))
        return named ? qd__mdl_isoperimetric(p, name, at.off, at.len)
                     : qd__mdl_isoperimetric(p, name, p->lx.tok.off, p->lx.tok.len);
    size_t off = p->lx.tok.off;
    const qd_expr *lhs, *rhs = NULL;
    if (!qd__mdl_parse_scalar(p, &lhs, "a constraint"))
        return false;
    if (p->lx.tok.kind == TK_EQ) {
        qd__mdl_lex_next(&p->lx);
        if (!qd__mdl_parse_scalar(p, &rhs, "a constraint"))
            return false;
    }
    const qd_expr *c = rhs ? qd_sub(C(p), lhs, rhs) : lhs;
    if (!c)
        return qd__mdl_perr(p, off, 1, NULL, "%s", qd_ctx_message(C(p)));
    if (qd_is_number(c))
        return qd__mdl_perr(p, off, p->lx.tok.off - off, "a constraint relates coordinates or velocities",
                    qd_is_zero(c) ? "this constraint always holds" : "this constraint can never hold");
    fclause fc;
    bool friction = qd__mdl_friction_ahead(p);
    if (friction && !qd__mdl_friction_parse(p, &fc))
        return false;
    if (!qd__mdl_push_constraint(p, name, c, named ? at.off : off, named ? at.len : 1))
        return false;
    size_t ci = m->ncons - 1;
    if (friction && !qd__mdl_friction_add(p, &fc, name, QD_CONTACT_CONSTRAINT, &ci, 1))
        return false;
    return qd__mdl_end_of_statement(p);
}

/* An acceleration (q'', or a higher derivative) in e, or NULL; *nomem when
 * the symbols could not be listed. */
static const qd_expr *acceleration(parser *p, const qd_expr *e, bool *nomem) {
    const qd_expr *few[16], **sym = few;
    *nomem = false;
    size_t n = e ? qd_free_symbols(C(p), e, few, 16) : 0;
    if (n == 0) {
        *nomem = e && qd__ctx_nomem(C(p));
        return NULL;
    }
    if (n > 16) {
        if (!(sym = qd__malloc(C(p), n * sizeof *sym))) {
            *nomem = true;
            return NULL;
        }
        qd_free_symbols(C(p), e, sym, n);
    }
    const qd_expr *a = NULL;
    for (size_t i = 0; i < n && !a; i++) {
        const char *name = qd_expr_name(sym[i]);
        if (name && strstr(name, "''"))
            a = sym[i];
    }
    if (sym != few)
        qd__free(sym);
    return a;
}

#define ACCEL_HINT "Lagrange's equations need L(q, q', t); an acceleration would change " \
                   "their order and is not handled: write the energy in the velocities"

/* The energy what (T, V, L, U, dissipation, a particle's position) at
 * off..off+len has no acceleration in it: else an error there. */
static bool no_acceleration(parser *p, const char *what, const qd_expr *e, size_t off,
                            size_t len) {
    bool nomem;
    const qd_expr *a = acceleration(p, e, &nomem);
    if (nomem)
        return qd__mdl_perr(p, off, len, NULL, "out of memory");
    if (a)
        return qd__mdl_perr(p, off, len, ACCEL_HINT, "%s depends on the acceleration %s",
                            what, qd_expr_name(a));
    return true;
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
    /* circuit elements (circuit.c) add to V and D as particles do to T */
    bool adds = explicit_T || slot == &p->m->V || slot == &p->m->D;
    if (slot && slot != &p->m->D && !qd__mdl_no_hamiltonian_yet(p, name, at.off, at.len))
        return false;
    if (!slot && !qd__mdl_fresh_name(p, "definition"))
        return false;
    /* T adds to the particles'; L is made from T - V - U when not given */
    bool twice = adds              ? qd_model_where(p->m, name, NULL)
                 : slot == &p->m->L ? qd_model_lagrangian_given(p->m)
                                    : slot && *slot;
    if (slot && twice) {
        qd_diag first;
        qd_model_where(p->m, name, &first);
        return qd__mdl_perr(p, at.off, at.len, "give it once; add the parts in one expression",
                    "%s is given twice (first on line %zu)", name, first.line);
    }
    qd__mdl_lex_next(&p->lx); /* '=' */
    qd__mdl_lex_next(&p->lx);
    p->defining = name;
    value v;
    bool ok = qd__mdl_parse_expr(p, &v);
    p->defining = NULL;
    if (!ok)
        return false;
    if (slot) {
        if (v.kind != VK_SCALAR)
            return qd__mdl_perr_why(p, QD_REASON_WRONG_KIND, v.off, v.len, v.kind == VK_VECTOR
                            ? "an energy is a scalar: use dot(v, v) for |v|^2"
                            : "an energy is a scalar",
                        "a %s where a scalar is needed: %s is a scalar", qd__mdl_vkind_name(v.kind), name);
        if (!no_acceleration(p, name, v.c[0], v.off, v.len))
            return false;
        /* particle lines and T = ... add up (and circuit elements with V, D) */
        *slot = adds && *slot ? qd_add(C(p), *slot, v.c[0]) : v.c[0];
    } else if (!qd__mdl_add_def(p->m, name, v, at.off, at.len)) {
        return qd__mdl_perr(p, at.off, at.len, NULL, "out of memory");
    }
    if (!qd__mdl_add_where(p->m, name, at.off, at.len))
        return qd__mdl_perr(p, at.off, at.len, NULL, "out of memory");
    return qd__mdl_end_of_statement(p);
}

/* The statements that open with a keyword, in the order the hint lists
 * them.  A newer one stays usable as a name defined before it existed
 * (`body = 2` is a definition), so it is a statement only when no '='
 * follows. */
static const struct stmt_kw {
    const char *word;
    bool (*parse)(parser *p);
    bool newer;
} statements[] = {
    {"coordinates", stmt_coordinates, false},   {"parameters", stmt_parameters, false},
    {"functions", stmt_functions, false},       {"particle", stmt_particle, false},
    {"force", stmt_force, false},               {"initial", stmt_initial, false},
    {"constraint", stmt_constraint, false},     {"body", qd__mdl_stmt_body, true},
    {"torque", qd__mdl_stmt_torque, true},      {"rolls", qd__mdl_stmt_rolls, true},
    {"reaction", qd__mdl_stmt_reaction, true},  {"momenta", qd__mdl_stmt_momenta, true},
    {"symmetry", qd__mdl_stmt_symmetry, true},  {"integral", qd__mdl_stmt_integral, true},
    {"impulse", qd__mdl_stmt_impulse, true},    {"impact", qd__mdl_stmt_impact, true},
    {"prescribe", qd__mdl_stmt_prescribe, true}, {"speeds", qd__mdl_stmt_speeds, true},
    {"independent", qd__mdl_stmt_independent, true},
    {"field", qd__mdl_stmt_field, true},        {"boundary", qd__mdl_stmt_boundary, true},
    {"inputs", qd__mdl_stmt_inputs, true},      {"outputs", qd__mdl_stmt_outputs, true},
    {"inductance", qd__mdl_stmt_inductance, true}, {"capacitance", qd__mdl_stmt_capacitance, true},
    {"resistance", qd__mdl_stmt_resistance, true}, {"source", qd__mdl_stmt_source, true},
    {"friction", qd__mdl_stmt_friction, true},  {"shape", qd__mdl_stmt_shape, true},
};
#define NSTATEMENTS (sizeof statements / sizeof statements[0])

static bool unknown_statement(parser *p) {
    char word[128], hint[256];
    const char *words[NSTATEMENTS];
    tok_text(p, word, sizeof word);
    for (size_t i = 0; i < NSTATEMENTS; i++)
        words[i] = statements[i].word;
    const char *near = qd__diag_nearest(word, strlen(word), words, NSTATEMENTS);
    if (near)
        snprintf(hint, sizeof hint, "did you mean '%s'?", near);
    else {
        /* spaces, not commas: with the circuit statements the whole list
         * fills the 255 bytes of a diagnostic's hint, so inputs, outputs,
         * friction, field, boundary and shape are left to "did you mean" above */
        size_t n = (size_t)snprintf(hint, sizeof hint, "a statement starts with a keyword (");
        for (size_t i = 0; i < NSTATEMENTS && n < sizeof hint; i++)
            if (statements[i].parse != qd__mdl_stmt_inputs &&
                statements[i].parse != qd__mdl_stmt_outputs &&
                statements[i].parse != qd__mdl_stmt_friction &&
                statements[i].parse != qd__mdl_stmt_field &&
                statements[i].parse != qd__mdl_stmt_boundary &&
                statements[i].parse != qd__mdl_stmt_shape)
                n += (size_t)snprintf(hint + n, sizeof hint - n, "%s%s", i ? " " : "", words[i]);
        if (n < sizeof hint)
            snprintf(hint + n, sizeof hint - n, ") or NAME = ...");
    }
    return qd__mdl_perr_tok(p, hint, "unknown statement '%s'", word);
}

static const struct stmt_kw *keyword_statement(const lexer *lx, bool newer) {
    for (size_t i = 0; i < NSTATEMENTS; i++)
        if (statements[i].newer == newer && qd__mdl_lex_is(lx, statements[i].word))
            return &statements[i];
    return NULL;
}

bool qd__mdl_statement(parser *p) {
    lexer *lx = &p->lx;
    if (lx->tok.kind != TK_IDENT) {
        if (lx->tok.kind == TK_RPAREN || lx->tok.kind == TK_RBRACK)
            return qd__mdl_end_of_statement(p);
        return qd__mdl_perr_tok(p, NULL, "expected a statement, found %s",
                                qd__mdl_lex_tk_name(lx->tok.kind));
    }
    const struct stmt_kw *kw = keyword_statement(lx, false);
    if (kw)
        return kw->parse(p);
    /* NAME '=' or Q '[': look one token ahead without consuming */
    lexer save = *lx;
    qd__mdl_lex_next(lx);
    tk_kind next = lx->tok.kind;
    *lx = save;
    if (next != TK_EQ && (kw = keyword_statement(lx, true)))
        return kw->parse(p);
    if (qd__mdl_lex_is(lx, "H") && next == TK_EQ)
        return qd__mdl_stmt_hamiltonian(p);
    if (qd__mdl_lex_is(lx, "Ldensity") && next == TK_EQ && p->m->field)
        return qd__mdl_stmt_ldensity(p);
    if (next == TK_EQ)
        return stmt_definition(p);
    if (next == TK_LBRACK && qd__mdl_lex_is(lx, "Q"))
        return stmt_genforce(p);
    if (next == TK_LBRACK && qd__mdl_lex_is(lx, "Qhat"))
        return qd__mdl_stmt_qhat(p);
    return unknown_statement(p);
}

/* After the last line: the Lagrangian and the checks that need the whole file. */
bool qd__mdl_finish(parser *p) {
    qd_model *m = p->m;
    qd_ctx *ctx = C(p);
    if (m->field || p->field_ok)
        return qd__mdl_field_finish(p);
    if (m->ncoords == 0)
        return qd__mdl_perr(p, 0, 1, "declare them: coordinates q1, q2", "no coordinates are declared");
    if (!qd__mdl_check_integrals(p) || !qd__mdl_friction_finish(p))
        return false;
    if (m->H && m->nisos) {
        qd_diag at;
        qd_model_where(m, "H", &at);
        return qd__mdl_perr(p, at.offset, at.length, "write the integrand as L = ... in the velocities",
                            "an isoperimetric constraint needs a Lagrangian, not H");
    }
    if (m->H)
        return true; /* the Lagrangian, if any, is the mechanics layer's inverse Legendre */
    if (!m->L && !m->T)
        return qd__mdl_perr(p, p->lx.tok.off, 1,
                    "give the kinetic energy T = ... (and V = ...), or particles, or L = ..., "
                    "or momenta and H = ...",
                    "neither T nor L is given");
    if (!qd_model_lagrangian_given(m)) {
        const qd_expr *zero = qd_int(ctx, 0);
        m->L = qd_sub(ctx, qd_sub(ctx, m->T, m->V ? m->V : zero), m->U ? m->U : zero);
        m->nisos_applied = 0; /* a new L: every isoperimetric term again */
    }
    if (!m->L)
        return qd__mdl_perr(p, 0, 1, NULL, "%s", qd_ctx_message(ctx));
    /* what the statements above did not see: a body's position or rotation,
     * a circuit element, a definition added in pieces */
    static const char *const energy[] = {"L", "T", "V", "U", "dissipation"};
    const qd_expr *const parts[] = {m->L, m->T, m->V, m->U, m->D};
    for (size_t i = 0; i < 5; i++) {
        qd_diag at;
        bool placed = qd_model_where(m, energy[i], &at);
        if (!no_acceleration(p, energy[i], parts[i], placed ? at.offset : 0,
                             placed ? at.length : 1))
            return false;
    }
    return qd__mdl_apply_isoperimetric(p) && qd__mdl_check_inputs(p);
}


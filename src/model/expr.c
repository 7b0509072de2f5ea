/*
 * src/model/expr.c - expressions of the model language, lowered to kernel
 * nodes as they are read.
 *
 *   sum      := ('-' | '+')? product (('+' | '-') product)*
 *   product  := factor (('*' | '/') factor)*   a leading sign covers the product
 *   factor   := ('-' | '+') factor | power
 *   power    := postfix ('^' factor)?           right-associative: -x^2 = -(x^2)
 *   postfix  := primary ("'" | '.' ('x' | 'y' | 'z'))*
 *   primary  := number | name | name '(' args ')' | '(' sum (',' sum){0,2} ')'
 *             | '[' row ',' row ',' row ']'       row := '[' sum ',' sum ',' sum ']'
 *
 * Values are scalars, 3-vectors ((x, y) is (x, y, 0)) or 3x3 matrices; '+'
 * and '-' need two of a kind; in a product the scalars commute and the rest
 * multiply left to right (matrix*matrix, matrix*vector, at most one vector,
 * last); '/' needs a scalar divisor.  Functions other than dot, cross, norm
 * and the matrix, body and inertia calls (rot.c, body.c, inertia.c) take
 * scalars.
 */
#include "parser.h"
#include "base/diag.h"
#include "base/mem.h"
#include "sym/sym_export.h"

#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static bool parse_sum(parser *p, value *out);
static bool parse_factor(parser *p, value *out);
static bool parse_signed(parser *p, value *out);

static qd_ctx *C(parser *p) { return p->ctx; }

static void span(value *v, const value *a, const value *b) {
    v->off = a->off;
    v->len = b->off + b->len - a->off;
}

static value scalar(const qd_expr *e, size_t off, size_t len) {
    value v = {VK_SCALAR, {e}, off, len};
    return v;
}

int qd__mdl_value_ncomp(const value *v) { return v->kind == VK_MATRIX ? 9 : v->kind == VK_VECTOR ? 3 : 1; }

const char *qd__mdl_vkind_name(vkind k) {
    return k == VK_MATRIX ? "matrix" : k == VK_VECTOR ? "vector" : "scalar";
}

static const char *kind_hint(vkind have, vkind want) {
    if (want == VK_SCALAR)
        return have == VK_VECTOR ? "take a component (r.x), norm(r) or dot(a, b)"
                                 : "a matrix acts on a vector: R*(x, y, z)";
    if (want == VK_VECTOR)
        return have == VK_SCALAR ? "write a vector as (x, y, z) or (x, y)"
                                 : "multiply the matrix by a vector: R*(x, y, z)";
    return "write a matrix as [[a, b, c], [d, e, f], [g, h, i]], or use rot_z(a), "
           "euler(phi, theta, psi)";
}

bool qd__mdl_need_kind(parser *p, const value *v, vkind want, const char *where) {
    if (v->kind == want)
        return true;
    return qd__mdl_perr_why(p, QD_REASON_WRONG_KIND, v->off, v->len, kind_hint(v->kind, want),
                            "a %s where a %s is needed%s%s",
                qd__mdl_vkind_name(v->kind), qd__mdl_vkind_name(want), where ? " " : "", where ? where : "");
}

static bool need_scalar(parser *p, const value *v, const char *where) {
    return qd__mdl_need_kind(p, v, VK_SCALAR, where);
}

bool qd__mdl_kernel_ok(parser *p, const value *v) {
    int n = qd__mdl_value_ncomp(v);
    for (int i = 0; i < n; i++)
        if (!v->c[i])
            return qd__mdl_perr(p, v->off, v->len, NULL, "%s", qd_ctx_message(p->ctx)[0]
                                                             ? qd_ctx_message(p->ctx)
                                                             : "this expression cannot be built");
    return true;
}

/* The ')' or ']' closing the bracket at open.  Newlines do not end a
 * statement inside brackets, so a missing ')' is found late: point at the
 * '(' instead. */
static bool expect_closing(parser *p, size_t open, tk_kind close) {
    if (p->lx.tok.kind == close) {
        qd__mdl_lex_next(&p->lx);
        return true;
    }
    const char *s = p->lx.src;
    size_t line, col;
    qd__diag_line_col(s, p->lx.tok.off, &line, &col, NULL);
    char hint[160];
    char c = close == TK_RPAREN ? ')' : ']';
    snprintf(hint, sizeof hint, "a '%c' is missing: found %s on line %zu", c,
             qd__mdl_lex_tk_name(p->lx.tok.kind), line);
    return qd__mdl_perr(p, open, 1, hint, "unclosed '%c'", s[open]);
}

bool qd__mdl_expect_close(parser *p, size_t open) { return expect_closing(p, open, TK_RPAREN); }

/* ---- operators ------------------------------------------------------------ */

static bool add_values(parser *p, value *a, const value *b, bool minus) {
    if (a->kind != b->kind)
        return qd__mdl_perr(p, b->off, b->len,
                    "both sides of + and - must be of one kind: scalars, vectors or matrices",
                    "cannot add a %s to a %s", qd__mdl_vkind_name(b->kind), qd__mdl_vkind_name(a->kind));
    for (int i = 0; i < qd__mdl_value_ncomp(a); i++)
        a->c[i] = minus ? qd_sub(C(p), a->c[i], b->c[i]) : qd_add(C(p), a->c[i], b->c[i]);
    span(a, a, b);
    return qd__mdl_kernel_ok(p, a);
}

static void dt_value(parser *p, value *v) {
    for (int i = 0; i < qd__mdl_value_ncomp(v); i++)
        v->c[i] = qd_dt(C(p), v->c[i]);
}

/* ---- names ------------------------------------------------------------------- */

static bool is_name_char(char c) { return isalnum((unsigned char)c) || c == '_'; }

/* Does "name =" (not "==") start at s + j? */
static bool names_at(const char *s, size_t j, const char *name, size_t n) {
    if (strncmp(s + j, name, n) != 0 || is_name_char(s[j + n]))
        return false;
    size_t k = j + n;
    while (s[k] == ' ' || s[k] == '\t')
        k++;
    return s[k] == '=' && s[k + 1] != '=';
}

/* Does the `speeds` line at j declare name (right after the keyword or a
 * comma)? */
static bool speeds_line_names(const char *s, size_t j, const char *name, size_t n) {
    if (strncmp(s + j, "speeds", 6) != 0 || (s[j + 6] != ' ' && s[j + 6] != '\t'))
        return false;
    for (size_t k = j + 6; s[k] && s[k] != '\n' && s[k] != '\r'; k++) {
        if (s[k] != ',' && k != j + 6)
            continue;
        size_t a = k + 1;
        while (s[a] == ' ' || s[a] == '\t')
            a++;
        if (names_at(s, a, name, n))
            return true;
    }
    return false;
}

/* Offset of a later line "name = ..." (or a `speeds` line naming it), or -1. */
static long defined_later(parser *p, const char *name, size_t n, size_t from) {
    const char *s = p->lx.src;
    for (size_t i = from; s[i]; i++) {
        if (s[i] != '\n' && s[i] != '\r')
            continue;
        size_t j = i + 1;
        while (s[j] == ' ' || s[j] == '\t')
            j++;
        if (names_at(s, j, name, n) || speeds_line_names(s, j, name, n))
            return (long)j;
    }
    return -1;
}

/* Does the definition line at off mention word? (for circular definitions) */
static bool line_mentions(const char *s, size_t off, const char *word) {
    size_t n = strlen(word), end = off + strcspn(s + off, "\r\n");
    const char *eq = memchr(s + off, '=', end - off);
    for (const char *q = eq ? eq + 1 : s + end; q + n <= s + end; q++) {
        bool left = q == s || !is_name_char(q[-1]);
        bool right = !is_name_char(q[n]);
        if (left && right && strncmp(q, word, n) == 0)
            return true;
    }
    return false;
}

static size_t line_of(const char *s, size_t off) {
    size_t line, col;
    qd__diag_line_col(s, off, &line, &col, NULL);
    return line;
}

static bool unknown_name(parser *p, size_t off, size_t n, bool call) {
    const char *s = p->lx.src;
    char name[128];
    snprintf(name, sizeof name, "%.*s", (int)(n < 127 ? n : 127), s + off);
    long later = call ? -1 : defined_later(p, name, strlen(name), off);
    char hint[256];
    if (later >= 0) {
        size_t line = line_of(s, (size_t)later);
        if (p->defining && line_mentions(s, (size_t)later, p->defining))
            return qd__mdl_perr(p, off, n, "define each name from names defined before it",
                        "circular definition: '%s' uses '%s', which is defined on line %zu "
                        "in terms of '%s'", p->defining, name, line, p->defining);
        snprintf(hint, sizeof hint, "move the definition of '%s' (line %zu) above this line",
                 name, line);
        return qd__mdl_perr(p, off, n, hint, "'%s' is used before it is defined", name);
    }
    size_t count;
    const char **names = qd__mdl_known_names(p, &count);
    const char *near = names ? qd__diag_nearest(name, strlen(name), names, count) : NULL;
    if (near)
        snprintf(hint, sizeof hint, "did you mean '%s'?", near);
    else if (call)
        snprintf(hint, sizeof hint, "declare it with 'functions %s' if it is an unknown function",
                 name);
    else
        snprintf(hint, sizeof hint, "declare it under 'coordinates' or 'parameters', or define "
                 "it with '%s = ...'", name);
    qd__free(names);
    return qd__mdl_perr(p, off, n, hint, call ? "unknown function '%s'" : "unknown name '%s'", name);
}

static bool lookup_name(parser *p, size_t off, size_t n, value *out) {
    const char *s = p->lx.src;
    qd_model *m = p->m;
    const def *d = qd__mdl_find_def(m, s + off, n);
    if (d) {
        *out = d->v;
        out->off = off;
        out->len = n;
        return true;
    }
    long u = qd__mdl_find_speed(m, s + off, n);
    if (u >= 0) { /* a speed's name stands for its definition */
        *out = scalar(m->speeds[u].def, off, n);
        return true;
    }
    long i = qd__mdl_names_find(m, QD_MDL_NAME_COORD, s + off, n);
    if (i >= 0) {
        *out = scalar(m->coords[i], off, n);
        return true;
    }
    i = qd__mdl_names_find(m, QD_MDL_NAME_PARAM, s + off, n);
    if (i >= 0) {
        /* a parameter fixed from outside is its number (qd_model_opts) */
        *out = scalar(m->pfixed[i] ? m->pvals[i] : m->params[i], off, n);
        p->met_fixed = p->met_fixed || m->pfixed[i];
        return true;
    }
    const qd_expr *in = qd__mdl_find_input(m, s + off, n);
    if (in) {
        *out = scalar(in, off, n);
        return true;
    }
    const qd_expr *mom = qd__mdl_find_momentum(m, s + off, n);
    if (mom && !p->momenta_ok)
        return qd__mdl_perr(p, off, n, "use the momenta in H = ... or in an integral; elsewhere write "
                    "the velocities", "'%s' is a momentum, which means nothing here",
                    qd_expr_name(mom));
    if (mom) {
        *out = scalar(mom, off, n);
        return true;
    }
    const qd_expr *k = NULL;
    if (p->eps_ok && qd__mdl_name_is(s, off, n, "eps"))
        k = qd__mdl_eps_symbol(C(p));
    else if (qd__mdl_name_is(s, off, n, "t") || (m->indep && qd__mdl_name_is(s, off, n, m->indep)))
        k = qd_time(C(p)); /* `independent x`: x is the time symbol by another name */
    else if (qd__mdl_name_is(s, off, n, "pi"))
        k = qd_const(C(p), QD_PI);
    else if (qd__mdl_name_is(s, off, n, "e"))
        k = qd_const(C(p), QD_E); /* unless a parameter named e, found above */
    if (k) {
        *out = scalar(k, off, n);
        return true;
    }
    const body *b = qd__mdl_find_body(m, s + off, n);
    if (b)
        return qd__mdl_perr(p, off, n, "use position(b), rotation(b), omega(b) or point(b, (x, y, z))",
                    "'%s' is a body, not a value", b->name);
    return unknown_name(p, off, n, false);
}

/* ---- calls ---------------------------------------------------------------------- */

#define MAX_ARGS 16

/* The arguments of a call; *end is just past its ')', so that the call's
 * span stops there and not at the next token. */
static bool parse_args(parser *p, value *args, size_t *nargs, size_t *end) {
    *nargs = 0;
    size_t open = p->lx.tok.off;
    qd__mdl_lex_next(&p->lx); /* '(' */
    if (p->lx.tok.kind == TK_RPAREN) {
        *end = p->lx.tok.off + p->lx.tok.len;
        qd__mdl_lex_next(&p->lx);
        return true;
    }
    for (;;) {
        if (*nargs == MAX_ARGS)
            return qd__mdl_perr_tok(p, NULL, "too many arguments (at most %d)", MAX_ARGS);
        if (!parse_sum(p, &args[(*nargs)++]))
            return false;
        if (p->lx.tok.kind == TK_COMMA) {
            qd__mdl_lex_next(&p->lx);
            continue;
        }
        *end = p->lx.tok.off + p->lx.tok.len;
        return qd__mdl_expect_close(p, open);
    }
}

bool qd__mdl_check_arity(parser *p, const char *name, size_t got, size_t want, size_t off, size_t len) {
    if (got == want)
        return true;
    return qd__mdl_perr(p, off, len, NULL, "%s takes %zu argument%s, not %zu", name, want,
                want == 1 ? "" : "s", got);
}

static bool vector_call(parser *p, const char *name, value *a, size_t n, value *out, size_t off,
                        size_t len) {
    qd_ctx *ctx = C(p);
    bool two = strcmp(name, "norm") != 0;
    if (!qd__mdl_check_arity(p, name, n, two ? 2 : 1, off, len))
        return false;
    for (size_t i = 0; i < n; i++)
        if (a[i].kind != VK_VECTOR)
            return qd__mdl_perr(p, a[i].off, a[i].len, kind_hint(a[i].kind, VK_VECTOR),
                        "%s needs vectors; this is a %s", name, qd__mdl_vkind_name(a[i].kind));
    value r = scalar(NULL, off, len);
    if (!strcmp(name, "cross")) {
        r.kind = VK_VECTOR;
        for (int i = 0; i < 3; i++) {
            int j = (i + 1) % 3, k = (i + 2) % 3;
            r.c[i] = qd_sub(ctx, qd_mul(ctx, a[0].c[j], a[1].c[k]), qd_mul(ctx, a[0].c[k], a[1].c[j]));
        }
    } else {
        const value *b = two ? &a[1] : &a[0];
        r.c[0] = qd_add_n(ctx, 3, (const qd_expr *[]){qd_mul(ctx, a[0].c[0], b->c[0]),
            qd_mul(ctx, a[0].c[1], b->c[1]), qd_mul(ctx, a[0].c[2], b->c[2])});
        if (!two)
            r.c[0] = qd_sqrt(ctx, r.c[0]);
    }
    *out = r;
    return qd__mdl_kernel_ok(p, out);
}

static const char *user_function(parser *p, size_t off, size_t n) {
    long i = qd__mdl_names_find(p->m, QD_MDL_NAME_FUNC, p->lx.src + off, n);
    return i >= 0 ? p->m->funcs[i] : NULL;
}

/* Is the name a coordinate, parameter or definition (which a body call such
 * as omega(...) must not hide when its argument is not a body)? */
static bool names_a_value(parser *p, const char *name) {
    qd_model *m = p->m;
    size_t n = strlen(name);
    return qd__mdl_find_def(m, name, n) || qd__mdl_names_find(m, QD_MDL_NAME_COORD, name, n) >= 0 ||
           qd__mdl_names_find(m, QD_MDL_NAME_PARAM, name, n) >= 0;
}

static bool parse_call(parser *p, size_t off, size_t n, value *out) {
    char name[64];
    snprintf(name, sizeof name, "%.*s", (int)(n < 63 ? n : 63), p->lx.src + off);
    const char *uf = user_function(p, off, n);
    if (!uf && qd__mdl_is_body_call(name) && (qd__mdl_body_call_ahead(p) || !names_a_value(p, name)))
        return qd__mdl_body_call(p, name, off, out);
    if (!uf && !strcmp(name, "integral"))
        return qd__mdl_perr(p, off, n, "write it as an isoperimetric constraint: "
                            "constraint length: integral(sqrt(1 + y'^2)) = l",
                            "integral() is only meaningful in a constraint");
    value a[MAX_ARGS];
    size_t na, end = off;
    if (!parse_args(p, a, &na, &end))
        return false;
    size_t len = end - off;
    if (!strcmp(name, "dot") || !strcmp(name, "cross") || !strcmp(name, "norm"))
        return vector_call(p, name, a, na, out, off, len);
    if (!uf && qd__mdl_is_rot_call(name))
        return qd__mdl_rot_call(p, name, a, na, out, off, len);
    if (!uf && qd__mdl_is_inertia_call(name))
        return qd__mdl_inertia_call(p, name, a, na, out, off, len);
    const qd_expr *args[MAX_ARGS];
    for (size_t i = 0; i < na; i++) {
        if (!need_scalar(p, &a[i], "as a function argument"))
            return false;
        args[i] = a[i].c[0];
    }
    qd_func f;
    const qd_expr *e;
    if (uf) {
        e = qd_ufunc(C(p), uf, na, args);
    } else if (!strcmp(name, "sqrt")) {
        if (!qd__mdl_check_arity(p, name, na, 1, off, len))
            return false;
        e = qd_sqrt(C(p), args[0]);
    } else if (qd_func_from_name(name, &f)) {
        if (!qd__mdl_check_arity(p, name, na, f == QD_ATAN2 ? 2 : 1, off, len))
            return false;
        e = f == QD_ATAN2 ? qd__atan2_written(C(p), args[0], args[1]) : qd_fn(C(p), f, args[0]);
    } else {
        value dummy;
        if (lookup_name(p, off, n, &dummy))
            return qd__mdl_perr(p, off, n, "write a product with '*': m*(a + b)", "'%s' is not a function",
                        name);
        p->failed = false; /* replace the lookup's message with the call's */
        return unknown_name(p, off, n, true);
    }
    *out = scalar(e, off, len);
    return qd__mdl_kernel_ok(p, out);
}

/* ---- grammar ------------------------------------------------------------------- */

/* '(' sum (',' sum){0,2} ')': a parenthesized scalar or a vector */
static bool parse_paren(parser *p, value *out) {
    size_t off = p->lx.tok.off;
    qd__mdl_lex_next(&p->lx);
    value c[3];
    size_t n = 0;
    for (;;) {
        if (!parse_sum(p, &c[n]))
            return false;
        n++;
        if (p->lx.tok.kind != TK_COMMA)
            break;
        if (n == 3)
            return qd__mdl_perr_tok(p, NULL, "a vector has at most three components");
        qd__mdl_lex_next(&p->lx);
    }
    for (size_t i = 0; n > 1 && i < n; i++)
        if (!need_scalar(p, &c[i], "as a vector component"))
            return false;
    size_t end = p->lx.tok.off + p->lx.tok.len;
    if (!qd__mdl_expect_close(p, off))
        return false;
    if (n == 1) {
        *out = c[0];
        out->off = off;
        out->len = end - off;
        return true;
    }
    value v = {VK_VECTOR, {c[0].c[0], c[1].c[0], n == 3 ? c[2].c[0] : qd_int(C(p), 0)}, off,
               end - off};
    *out = v;
    return true;
}

/* '[' sum ',' sum ',' sum ']': one row of a matrix literal, into c[0..2] */
static bool parse_row(parser *p, const qd_expr **c) {
    size_t off = p->lx.tok.off;
    if (p->lx.tok.kind != TK_LBRACK)
        return qd__mdl_perr_tok(p, "write a matrix as [[a, b, c], [d, e, f], [g, h, i]]",
                                "expected a row '[a, b, c]', found %s",
                                qd__mdl_lex_tk_name(p->lx.tok.kind));
    qd__mdl_lex_next(&p->lx);
    for (int i = 0; i < 3; i++) {
        value v;
        if (i > 0 && p->lx.tok.kind != TK_COMMA)
            return qd__mdl_perr_tok(p, NULL, "a row of a matrix has three entries; found %s after %d",
                            qd__mdl_lex_tk_name(p->lx.tok.kind), i);
        if (i > 0)
            qd__mdl_lex_next(&p->lx);
        if (!parse_sum(p, &v) || !need_scalar(p, &v, "as a matrix entry"))
            return false;
        c[i] = v.c[0];
    }
    if (p->lx.tok.kind == TK_COMMA)
        return qd__mdl_perr_tok(p, NULL, "a row of a matrix has three entries, not more");
    return expect_closing(p, off, TK_RBRACK);
}

/* '[' row ',' row ',' row ']' */
static bool parse_matrix(parser *p, value *out) {
    size_t off = p->lx.tok.off;
    qd__mdl_lex_next(&p->lx);
    value v = {VK_MATRIX, {NULL}, off, 0};
    for (int i = 0; i < 3; i++) {
        if (i > 0 && p->lx.tok.kind != TK_COMMA)
            return qd__mdl_perr_tok(p, "write a matrix as [[a, b, c], [d, e, f], [g, h, i]]",
                                    "a matrix has three rows; found %s after %d",
                                    qd__mdl_lex_tk_name(p->lx.tok.kind), i);
        if (i > 0)
            qd__mdl_lex_next(&p->lx);
        if (!parse_row(p, &v.c[3 * i]))
            return false;
    }
    if (p->lx.tok.kind == TK_COMMA)
        return qd__mdl_perr_tok(p, NULL, "a matrix has three rows, not more");
    size_t end = p->lx.tok.off + p->lx.tok.len;
    if (!expect_closing(p, off, TK_RBRACK))
        return false;
    v.len = end - off;
    *out = v;
    return true;
}

/* primary := number | name | name '(' args ')' | '(' ... ')' */
static bool parse_primary(parser *p, value *out) {
    token t = p->lx.tok;
    switch (t.kind) {
    case TK_NUMBER: {
        char buf[128];
        if (t.len >= sizeof buf)
            return qd__mdl_perr_tok(p, NULL, "number too long");
        memcpy(buf, p->lx.src + t.off, t.len);
        buf[t.len] = '\0';
        const qd_expr *e = qd_rat_str(C(p), buf);
        if (!e)
            return qd__mdl_perr_tok(p, "write numbers as 12, 0.5, 3/4 or 1e-3", "'%s' is not a number", buf);
        qd__mdl_lex_next(&p->lx);
        *out = scalar(e, t.off, t.len);
        return true;
    }
    case TK_IDENT:
        qd__mdl_lex_next(&p->lx);
        if (p->lx.tok.kind == TK_LPAREN)
            return parse_call(p, t.off, t.len, out);
        return lookup_name(p, t.off, t.len, out);
    case TK_LPAREN:
        return parse_paren(p, out);
    case TK_LBRACK:
        return parse_matrix(p, out);
    default:
        return qd__mdl_perr_tok(p, NULL, "expected an expression, found %s",
                                qd__mdl_lex_tk_name(t.kind));
    }
}

/* Each prime differentiates the whole expression again, and the size of
 * d^n/dt^n of a composite grows fast with n: a mechanical model needs q''
 * at most, so a long run of primes is a typo (or a fuzzer), not physics. */
#define MAX_PRIMES 4

/* postfix := primary ("'" | '.' component)* */
static bool parse_postfix(parser *p, value *out) {
    if (!parse_primary(p, out))
        return false;
    int primes = 0;
    for (;;) {
        if (p->lx.tok.kind == TK_PRIME) {
            if (++primes > MAX_PRIMES)
                return qd__mdl_perr_tok(p, "Lagrange's equations need velocities and accelerations only",
                                "a time derivative of order above %d", MAX_PRIMES);
            dt_value(p, out);
            out->len = p->lx.tok.off + 1 - out->off;
            qd__mdl_lex_next(&p->lx);
            if (!qd__mdl_kernel_ok(p, out))
                return false;
        } else if (p->lx.tok.kind == TK_DOT && !p->no_dot) {
            qd__mdl_lex_next(&p->lx);
            int k = qd__mdl_lex_is(&p->lx, "x")   ? 0
                    : qd__mdl_lex_is(&p->lx, "y") ? 1
                    : qd__mdl_lex_is(&p->lx, "z") ? 2
                                                  : -1;
            if (k < 0)
                return qd__mdl_perr_tok(p, "components are .x, .y and .z", "expected a component name");
            if (out->kind != VK_VECTOR)
                return qd__mdl_perr_why(p, QD_REASON_WRONG_KIND, out->off, out->len,
                            out->kind == VK_SCALAR ? "only a vector has components"
                                                   : "R*(1, 0, 0) is the first column of R",
                            "a %s where a vector is needed", qd__mdl_vkind_name(out->kind));
            *out = scalar(out->c[k], out->off, p->lx.tok.off + 1 - out->off);
            qd__mdl_lex_next(&p->lx);
        } else {
            return true;
        }
    }
}

/* power := postfix ('^' factor)? */
static bool parse_power(parser *p, value *out) {
    if (!parse_postfix(p, out))
        return false;
    if (p->lx.tok.kind != TK_CARET)
        return true;
    qd__mdl_lex_next(&p->lx);
    value e;
    if (!parse_factor(p, &e))
        return false;
    const char *base = out->kind == VK_VECTOR ? "as a base; |r|^2 is dot(r, r)" : "as a base";
    if (!need_scalar(p, out, base) || !need_scalar(p, &e, "as an exponent"))
        return false;
    out->c[0] = qd__pow_written(C(p), out->c[0], e.c[0]);
    span(out, out, &e);
    return qd__mdl_kernel_ok(p, out);
}

static void negate(parser *p, value *v) {
    for (int i = 0; i < qd__mdl_value_ncomp(v); i++)
        v->c[i] = qd_neg(C(p), v->c[i]);
}

/* factor := ('-' | '+') factor | power
 * Every bracket, sign and exponent nests one factor inside another: the
 * count bounds the recursion (and the stack) as the kernel's reader does. */
static bool parse_factor(parser *p, value *out) {
    if (p->nest >= QD_MAX_NEST) {
        p->nest++; /* tells the error record why */
        return qd__mdl_perr_tok(p, QD_NEST_HINT, "expression nested too deeply");
    }
    p->nest++;
    bool ok = parse_signed(p, out);
    p->nest--;
    return ok;
}

static bool parse_signed(parser *p, value *out) {
    if (p->lx.tok.kind != TK_MINUS && p->lx.tok.kind != TK_PLUS)
        return parse_power(p, out);
    bool neg = p->lx.tok.kind == TK_MINUS;
    size_t off = p->lx.tok.off;
    qd__mdl_lex_next(&p->lx);
    if (!parse_factor(p, out))
        return false;
    if (neg)
        negate(p, out);
    out->len += out->off - off;
    out->off = off;
    return qd__mdl_kernel_ok(p, out);
}

#define MAX_FACTORS 64

/* acc * b for two values that are not scalars: matrix*matrix is a matrix,
 * matrix*vector a vector; a vector can only come last. */
static bool mul_nonscalar(parser *p, value *acc, const value *b) {
    if (acc->kind == VK_VECTOR && b->kind == VK_VECTOR)
        return qd__mdl_perr_why(p, QD_REASON_WRONG_KIND, b->off, b->len, "use dot(a, b) or cross(a, b)",
                    "a vector where a scalar is needed: cannot multiply two vectors");
    if (acc->kind == VK_VECTOR)
        return qd__mdl_perr(p, b->off, b->len, "write transpose(R)*v for the row vector v^T R",
                    "a matrix cannot multiply a vector from the right");
    const qd_expr *c[9];
    if (b->kind == VK_MATRIX)
        qd__mdl_mat_mul(C(p), acc->c, b->c, c);
    else
        qd__mdl_mat_vec(C(p), acc->c, b->c, c);
    acc->kind = b->kind;
    memcpy(acc->c, c, sizeof c);
    return true;
}

/* product := factor (('*' | '/') factor)*
 * The scalar factors are multiplied in one call, as the kernel's reader does,
 * so that 2*(a + b)*x is one product and reads back to the node it printed
 * from (pairwise, 2*(a + b) would be distributed first).  Scalars commute,
 * so the vectors and matrices are multiplied apart from them, in order. */
static bool parse_product(parser *p, value *out) {
    if (!parse_factor(p, out))
        return false;
    const qd_expr *fs[MAX_FACTORS] = {NULL};
    size_t n = 0;
    value acc = *out, first = *out; /* acc: the product of the non-scalars */
    bool have = out->kind != VK_SCALAR;
    if (!have)
        fs[n++] = out->c[0];
    while (p->lx.tok.kind == TK_STAR || p->lx.tok.kind == TK_SLASH) {
        bool divide = p->lx.tok.kind == TK_SLASH;
        qd__mdl_lex_next(&p->lx);
        value b;
        if (!parse_factor(p, &b))
            return false;
        if (divide && !need_scalar(p, &b, "as a divisor"))
            return false;
        if (b.kind != VK_SCALAR) {
            if (have && !mul_nonscalar(p, &acc, &b))
                return false;
            if (!have)
                acc = b;
            have = true;
        } else {
            if (n == MAX_FACTORS) {
                fs[0] = qd_mul_n(C(p), n, fs); /* fold, and go on */
                n = 1;
            }
            fs[n++] = divide ? qd_pow(C(p), b.c[0], qd_int(C(p), -1)) : b.c[0];
        }
        span(out, &first, &b);
    }
    const qd_expr *s = qd_mul_n(C(p), n, fs);
    value r = have ? acc : *out;
    for (int i = 0; i < qd__mdl_value_ncomp(&r); i++)
        r.c[i] = have ? (n ? qd_mul(C(p), s, acc.c[i]) : acc.c[i]) : s;
    r.off = out->off;
    r.len = out->len;
    *out = r;
    return qd__mdl_kernel_ok(p, out);
}

/* sum := ('-' | '+')? product (('+' | '-') product)*
 * A leading sign applies to the whole product: -x^2*y is -(x^2*y). */
static bool parse_sum(parser *p, value *out) {
    bool neg = false;
    size_t off = p->lx.tok.off;
    if (p->lx.tok.kind == TK_MINUS || p->lx.tok.kind == TK_PLUS) {
        neg = p->lx.tok.kind == TK_MINUS;
        qd__mdl_lex_next(&p->lx);
    }
    if (!parse_product(p, out))
        return false;
    if (neg)
        negate(p, out);
    out->len += out->off - off;
    out->off = off;
    while (p->lx.tok.kind == TK_PLUS || p->lx.tok.kind == TK_MINUS) {
        bool minus = p->lx.tok.kind == TK_MINUS;
        qd__mdl_lex_next(&p->lx);
        value b;
        if (!parse_product(p, &b) || !add_values(p, out, &b, minus))
            return false;
    }
    return true;
}

bool qd__mdl_parse_expr(parser *p, value *out) {
    if (p->lx.too_deep)
        return qd__mdl_perr_tok(p, QD_NEST_HINT, "expression nested too deeply");
    return parse_sum(p, out);
}

static bool parse_kind(parser *p, value *v, vkind want, const char *what) {
    if (!qd__mdl_parse_expr(p, v))
        return false;
    if (v->kind == want)
        return true;
    return qd__mdl_perr_why(p, QD_REASON_WRONG_KIND, v->off, v->len, kind_hint(v->kind, want),
                            "a %s where a %s is needed: %s is a %s",
                qd__mdl_vkind_name(v->kind), qd__mdl_vkind_name(want), what, qd__mdl_vkind_name(want));
}

bool qd__mdl_parse_scalar(parser *p, const qd_expr **out, const char *what) {
    value v;
    if (!parse_kind(p, &v, VK_SCALAR, what))
        return false;
    *out = v.c[0];
    return true;
}

bool qd__mdl_parse_vector(parser *p, value *v, const char *what) {
    return parse_kind(p, v, VK_VECTOR, what);
}

bool qd__mdl_parse_matrix_value(parser *p, value *v, const char *what) {
    return parse_kind(p, v, VK_MATRIX, what);
}

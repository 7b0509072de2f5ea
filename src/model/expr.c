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
 *
 * Values are scalars or 3-vectors ((x, y) is (x, y, 0)); '+' and '-' need two
 * of a kind, '*' at most one vector, '/' a scalar divisor, and functions
 * other than dot, cross and norm take scalars.
 */
#include "parser.h"

#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static bool parse_sum(parser *p, value *out);
static bool parse_factor(parser *p, value *out);

static qd_ctx *C(parser *p) { return p->ctx; }

static void span(value *v, const value *a, const value *b) {
    v->off = a->off;
    v->len = b->off + b->len - a->off;
}

static value scalar(const qd_expr *e, size_t off, size_t len) {
    value v = {false, {e, NULL, NULL}, off, len};
    return v;
}

static bool need_scalar(parser *p, const value *v, const char *where) {
    if (!v->vec)
        return true;
    return perr(p, v->off, v->len, "take a component (r.x), norm(r) or dot(a, b)",
                "a vector where a scalar is needed%s%s", where ? " " : "", where ? where : "");
}

static bool kernel_ok(parser *p, const value *v) {
    int n = v->vec ? 3 : 1;
    for (int i = 0; i < n; i++)
        if (!v->c[i])
            return perr(p, v->off, v->len, NULL, "%s", qd_ctx_message(p->ctx)[0]
                                                             ? qd_ctx_message(p->ctx)
                                                             : "this expression cannot be built");
    return true;
}

/* The ')' closing the '(' at open.  Newlines do not end a statement inside
 * brackets, so a missing ')' is found late: point at the '(' instead. */
static bool expect_close(parser *p, size_t open) {
    if (p->lx.tok.kind == TK_RPAREN) {
        lex_next(&p->lx);
        return true;
    }
    const char *s = p->lx.src;
    size_t line = 1;
    for (size_t i = 0; i < p->lx.tok.off; i++)
        line += s[i] == '\n';
    char hint[160];
    snprintf(hint, sizeof hint, "a ')' is missing: found %s on line %zu",
             tk_name(p->lx.tok.kind), line);
    return perr(p, open, 1, hint, "unclosed '('");
}

/* ---- operators ------------------------------------------------------------ */

static bool add_values(parser *p, value *a, const value *b, bool minus) {
    if (a->vec != b->vec)
        return perr(p, b->off, b->len, "both sides of + and - must be scalars, or both vectors",
                    "cannot add a %s to a %s", b->vec ? "vector" : "scalar",
                    a->vec ? "vector" : "scalar");
    for (int i = 0; i < (a->vec ? 3 : 1); i++)
        a->c[i] = minus ? qd_sub(C(p), a->c[i], b->c[i]) : qd_add(C(p), a->c[i], b->c[i]);
    span(a, a, b);
    return kernel_ok(p, a);
}

static void dt_value(parser *p, value *v) {
    for (int i = 0; i < (v->vec ? 3 : 1); i++)
        v->c[i] = qd_dt(C(p), v->c[i]);
}

/* ---- names ------------------------------------------------------------------- */

static bool is_name_char(char c) { return isalnum((unsigned char)c) || c == '_'; }

/* Offset of a later line "name = ...", or -1. */
static long defined_later(parser *p, const char *name, size_t n, size_t from) {
    const char *s = p->lx.src;
    for (size_t i = from; s[i]; i++) {
        if (s[i] != '\n')
            continue;
        size_t j = i + 1;
        while (s[j] == ' ' || s[j] == '\t')
            j++;
        if (strncmp(s + j, name, n) == 0) {
            size_t k = j + n;
            if (is_name_char(s[k]))
                continue;
            while (s[k] == ' ' || s[k] == '\t')
                k++;
            if (s[k] == '=' && s[k + 1] != '=')
                return (long)j;
        }
    }
    return -1;
}

/* Does the definition line at off mention word? (for circular definitions) */
static bool line_mentions(const char *s, size_t off, const char *word) {
    size_t n = strlen(word), end = off + strcspn(s + off, "\n");
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
    size_t line = 1;
    for (size_t i = 0; i < off; i++)
        line += s[i] == '\n';
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
            return perr(p, off, n, "define each name from names defined before it",
                        "circular definition: '%s' uses '%s', which is defined on line %zu "
                        "in terms of '%s'", p->defining, name, line, p->defining);
        snprintf(hint, sizeof hint, "move the definition of '%s' (line %zu) above this line",
                 name, line);
        return perr(p, off, n, hint, "'%s' is used before it is defined", name);
    }
    size_t count;
    const char **names = known_names(p, &count);
    const char *near = names ? nearest(name, strlen(name), names, count) : NULL;
    if (near)
        snprintf(hint, sizeof hint, "did you mean '%s'?", near);
    else if (call)
        snprintf(hint, sizeof hint, "declare it with 'functions %s' if it is an unknown function",
                 name);
    else
        snprintf(hint, sizeof hint, "declare it under 'coordinates' or 'parameters', or define "
                 "it with '%s = ...'", name);
    free(names);
    return perr(p, off, n, hint, call ? "unknown function '%s'" : "unknown name '%s'", name);
}

static bool lookup_name(parser *p, size_t off, size_t n, value *out) {
    const char *s = p->lx.src;
    qd_model *m = p->m;
    const def *d = model_find_def(m, s + off, n);
    if (d) {
        *out = d->v;
        out->off = off;
        out->len = n;
        return true;
    }
    for (size_t i = 0; i < m->ncoords; i++)
        if (name_is(s, off, n, qd_expr_name(m->coords[i]))) {
            *out = scalar(m->coords[i], off, n);
            return true;
        }
    for (size_t i = 0; i < m->nparams; i++)
        if (name_is(s, off, n, qd_expr_name(m->params[i]))) {
            *out = scalar(m->params[i], off, n);
            return true;
        }
    const qd_expr *k = NULL;
    if (name_is(s, off, n, "t"))
        k = qd_time(C(p));
    else if (name_is(s, off, n, "pi"))
        k = qd_const(C(p), QD_PI);
    else if (name_is(s, off, n, "e"))
        k = qd_const(C(p), QD_E); /* unless a parameter named e, found above */
    if (k) {
        *out = scalar(k, off, n);
        return true;
    }
    return unknown_name(p, off, n, false);
}

/* ---- calls ---------------------------------------------------------------------- */

#define MAX_ARGS 16

static bool parse_args(parser *p, value *args, size_t *nargs) {
    *nargs = 0;
    size_t open = p->lx.tok.off;
    lex_next(&p->lx); /* '(' */
    if (p->lx.tok.kind == TK_RPAREN) {
        lex_next(&p->lx);
        return true;
    }
    for (;;) {
        if (*nargs == MAX_ARGS)
            return perr_tok(p, NULL, "too many arguments (at most %d)", MAX_ARGS);
        if (!parse_sum(p, &args[(*nargs)++]))
            return false;
        if (p->lx.tok.kind == TK_COMMA) {
            lex_next(&p->lx);
            continue;
        }
        return expect_close(p, open);
    }
}

static bool arity(parser *p, const char *name, size_t got, size_t want, size_t off, size_t len) {
    if (got == want)
        return true;
    return perr(p, off, len, NULL, "%s takes %zu argument%s, not %zu", name, want,
                want == 1 ? "" : "s", got);
}

static bool vector_call(parser *p, const char *name, value *a, size_t n, value *out, size_t off,
                        size_t len) {
    qd_ctx *ctx = C(p);
    bool two = strcmp(name, "norm") != 0;
    if (!arity(p, name, n, two ? 2 : 1, off, len))
        return false;
    for (size_t i = 0; i < n; i++)
        if (!a[i].vec)
            return perr(p, a[i].off, a[i].len, "write a vector as (x, y, z) or (x, y)",
                        "%s needs vectors; this is a scalar", name);
    value r = scalar(NULL, off, len);
    if (!strcmp(name, "cross")) {
        r.vec = true;
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
    return kernel_ok(p, out);
}

static const char *user_function(parser *p, size_t off, size_t n) {
    for (size_t i = 0; i < p->m->nfuncs; i++)
        if (name_is(p->lx.src, off, n, p->m->funcs[i]))
            return p->m->funcs[i];
    return NULL;
}

static bool parse_call(parser *p, size_t off, size_t n, value *out) {
    char name[64];
    snprintf(name, sizeof name, "%.*s", (int)(n < 63 ? n : 63), p->lx.src + off);
    value a[MAX_ARGS];
    size_t na;
    if (!parse_args(p, a, &na))
        return false;
    size_t len = p->lx.tok.off - off;
    if (!strcmp(name, "dot") || !strcmp(name, "cross") || !strcmp(name, "norm"))
        return vector_call(p, name, a, na, out, off, len);
    const qd_expr *args[MAX_ARGS];
    for (size_t i = 0; i < na; i++) {
        if (!need_scalar(p, &a[i], "as a function argument"))
            return false;
        args[i] = a[i].c[0];
    }
    qd_func f;
    const char *uf = user_function(p, off, n);
    const qd_expr *e;
    if (uf) {
        e = qd_ufunc(C(p), uf, na, args);
    } else if (!strcmp(name, "sqrt")) {
        if (!arity(p, name, na, 1, off, len))
            return false;
        e = qd_sqrt(C(p), args[0]);
    } else if (qd_func_from_name(name, &f)) {
        if (!arity(p, name, na, f == QD_ATAN2 ? 2 : 1, off, len))
            return false;
        e = f == QD_ATAN2 ? qd_fn2(C(p), f, args[0], args[1]) : qd_fn(C(p), f, args[0]);
    } else {
        value dummy;
        if (lookup_name(p, off, n, &dummy))
            return perr(p, off, n, "write a product with '*': m*(a + b)", "'%s' is not a function",
                        name);
        p->failed = false; /* replace the lookup's message with the call's */
        return unknown_name(p, off, n, true);
    }
    *out = scalar(e, off, len);
    return kernel_ok(p, out);
}

/* ---- grammar ------------------------------------------------------------------- */

/* '(' sum (',' sum){0,2} ')': a parenthesized scalar or a vector */
static bool parse_paren(parser *p, value *out) {
    size_t off = p->lx.tok.off;
    lex_next(&p->lx);
    value c[3];
    size_t n = 0;
    for (;;) {
        if (!parse_sum(p, &c[n]))
            return false;
        n++;
        if (p->lx.tok.kind != TK_COMMA)
            break;
        if (n == 3)
            return perr_tok(p, NULL, "a vector has at most three components");
        lex_next(&p->lx);
    }
    for (size_t i = 0; n > 1 && i < n; i++)
        if (!need_scalar(p, &c[i], "as a vector component"))
            return false;
    size_t end = p->lx.tok.off + p->lx.tok.len;
    if (!expect_close(p, off))
        return false;
    if (n == 1) {
        *out = c[0];
        out->off = off;
        out->len = end - off;
        return true;
    }
    value v = {true, {c[0].c[0], c[1].c[0], n == 3 ? c[2].c[0] : qd_int(C(p), 0)}, off, end - off};
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
            return perr_tok(p, NULL, "number too long");
        memcpy(buf, p->lx.src + t.off, t.len);
        buf[t.len] = '\0';
        const qd_expr *e = qd_rat_str(C(p), buf);
        if (!e)
            return perr_tok(p, "write numbers as 12, 0.5, 3/4 or 1e-3", "'%s' is not a number", buf);
        lex_next(&p->lx);
        *out = scalar(e, t.off, t.len);
        return true;
    }
    case TK_IDENT:
        lex_next(&p->lx);
        if (p->lx.tok.kind == TK_LPAREN)
            return parse_call(p, t.off, t.len, out);
        return lookup_name(p, t.off, t.len, out);
    case TK_LPAREN:
        return parse_paren(p, out);
    default:
        return perr_tok(p, NULL, "expected an expression, found %s", tk_name(t.kind));
    }
}

/* postfix := primary ("'" | '.' component)* */
static bool parse_postfix(parser *p, value *out) {
    if (!parse_primary(p, out))
        return false;
    for (;;) {
        if (p->lx.tok.kind == TK_PRIME) {
            dt_value(p, out);
            out->len = p->lx.tok.off + 1 - out->off;
            lex_next(&p->lx);
            if (!kernel_ok(p, out))
                return false;
        } else if (p->lx.tok.kind == TK_DOT) {
            lex_next(&p->lx);
            int k = lex_is(&p->lx, "x") ? 0 : lex_is(&p->lx, "y") ? 1 : lex_is(&p->lx, "z") ? 2 : -1;
            if (k < 0)
                return perr_tok(p, "components are .x, .y and .z", "expected a component name");
            if (!out->vec)
                return perr(p, out->off, out->len, "only a vector has components",
                            "a scalar where a vector is needed");
            *out = scalar(out->c[k], out->off, p->lx.tok.off + 1 - out->off);
            lex_next(&p->lx);
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
    lex_next(&p->lx);
    value e;
    if (!parse_factor(p, &e))
        return false;
    if (!need_scalar(p, out, "as a base; |r|^2 is dot(r, r)") || !need_scalar(p, &e, "as an exponent"))
        return false;
    out->c[0] = qd_pow(C(p), out->c[0], e.c[0]);
    span(out, out, &e);
    return kernel_ok(p, out);
}

static void negate(parser *p, value *v) {
    for (int i = 0; i < (v->vec ? 3 : 1); i++)
        v->c[i] = qd_neg(C(p), v->c[i]);
}

/* factor := ('-' | '+') factor | power */
static bool parse_factor(parser *p, value *out) {
    if (p->lx.tok.kind != TK_MINUS && p->lx.tok.kind != TK_PLUS)
        return parse_power(p, out);
    bool neg = p->lx.tok.kind == TK_MINUS;
    size_t off = p->lx.tok.off;
    lex_next(&p->lx);
    if (!parse_factor(p, out))
        return false;
    if (neg)
        negate(p, out);
    out->len += out->off - off;
    out->off = off;
    return kernel_ok(p, out);
}

#define MAX_FACTORS 64

/* product := factor (('*' | '/') factor)*
 * The scalar factors are multiplied in one call, as the kernel's reader does,
 * so that 2*(a + b)*x is one product and reads back to the node it printed
 * from (pairwise, 2*(a + b) would be distributed first). */
static bool parse_product(parser *p, value *out) {
    if (!parse_factor(p, out))
        return false;
    const qd_expr *fs[MAX_FACTORS] = {NULL};
    size_t n = 0;
    value vec = *out, first = *out;
    bool have_vec = out->vec;
    if (!out->vec)
        fs[n++] = out->c[0];
    while (p->lx.tok.kind == TK_STAR || p->lx.tok.kind == TK_SLASH) {
        bool divide = p->lx.tok.kind == TK_SLASH;
        lex_next(&p->lx);
        value b;
        if (!parse_factor(p, &b))
            return false;
        if (divide && !need_scalar(p, &b, "as a divisor"))
            return false;
        if (b.vec && have_vec)
            return perr(p, b.off, b.len, "use dot(a, b) or cross(a, b)",
                        "a vector where a scalar is needed: cannot multiply two vectors");
        if (b.vec) {
            vec = b;
            have_vec = true;
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
    value r = have_vec ? vec : *out;
    r.vec = have_vec;
    for (int i = 0; i < (have_vec ? 3 : 1); i++)
        r.c[i] = have_vec ? qd_mul(C(p), s, vec.c[i]) : s;
    r.off = out->off;
    r.len = out->len;
    *out = r;
    return kernel_ok(p, out);
}

/* sum := ('-' | '+')? product (('+' | '-') product)*
 * A leading sign applies to the whole product: -x^2*y is -(x^2*y). */
static bool parse_sum(parser *p, value *out) {
    bool neg = false;
    size_t off = p->lx.tok.off;
    if (p->lx.tok.kind == TK_MINUS || p->lx.tok.kind == TK_PLUS) {
        neg = p->lx.tok.kind == TK_MINUS;
        lex_next(&p->lx);
    }
    if (!parse_product(p, out))
        return false;
    if (neg)
        negate(p, out);
    out->len += out->off - off;
    out->off = off;
    while (p->lx.tok.kind == TK_PLUS || p->lx.tok.kind == TK_MINUS) {
        bool minus = p->lx.tok.kind == TK_MINUS;
        lex_next(&p->lx);
        value b;
        if (!parse_product(p, &b) || !add_values(p, out, &b, minus))
            return false;
    }
    return true;
}

bool parse_expr(parser *p, value *out) {
    if (p->lx.too_deep)
        return perr_tok(p, NULL, "brackets nested too deeply");
    return parse_sum(p, out);
}

bool parse_scalar(parser *p, const qd_expr **out, const char *what) {
    value v;
    if (!parse_expr(p, &v))
        return false;
    if (v.vec)
        return perr(p, v.off, v.len, "take a component (r.x), norm(r) or dot(a, b)",
                    "a vector where a scalar is needed: %s is a scalar", what);
    *out = v.c[0];
    return true;
}

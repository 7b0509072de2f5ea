/*
 * src/sym/read.c - qd_read: text in the model language's expression syntax
 * to a canonical expression.  A recursive-descent parser, one function per
 * rule of the grammar below; each opens with the production it parses.
 *
 *   input    := sum EOF
 *   sum      := term { ('+' | '-') term }
 *   term     := ('+' | '-') term | product       -x*y is -(x*y)
 *   product  := power { ('*' | '/') operand }
 *   operand  := ('+' | '-') operand | power      x*-y
 *   power    := postfix [ '^' operand ]          right-associative, -x^2 is -(x^2)
 *   postfix  := primary { "'" }                  q' is the jet symbol, (e)' is d/dt e
 *   primary  := number | name | call | '(' sum ')'
 *   call     := name [ "'"... [ '[' slot { ',' slot } ']' ] ] '(' [ sum { ',' sum } ] ')'
 *
 * Numbers: 12, 2.5, 1e-3 and 1.5E+2 are exact rationals (2.5 is 5/2); a
 * number with the suffix f (2.5f, 3f, 1e-20f) is a float, the double nearest
 * to it.  That is how the text printer writes floats, so they read back.
 *
 * Names: [A-Za-z_][A-Za-z0-9_]*.  A name is, in this order, a symbol of the
 * context (so a symbol named e stays that symbol), pi, e, t (the time), or a
 * new plain symbol (an error when opts->new_symbols is false); before all
 * these, the name the time prints as (qd_print_set_time_name) is the time.
 * An unknown name that the text writes with a prime anywhere (r' or r'')
 * is made a coordinate, not a plain symbol, so that r' is a symbol of its own
 * (a plain symbol's rate would be 0: `m/2*r'^2` must not read as 0); a plain
 * symbol the context already has, written with a prime, is refused.  A name
 * followed by '(' is a built-in function, sqrt, or a user function; with
 * primes before the '(' it is a derivative of a user function: V'(r) and
 * V''(r) for one argument, V'[1,2](x, y) with 1-based argument slots.
 *
 * A factor chain a*b/c is multiplied in one qd_mul_n call and a sum in one
 * qd_add_n call, so 2*(a + b)*x stays a product (two factors at a time
 * would distribute 2 over the sum).  Whitespace may appear anywhere;
 * newlines only inside brackets.
 */
#include "qdot/read.h"
#include "node.h"
#include "sym_export.h"
#include "base/diag.h"
#include "../base/args.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAX_NEST QD_MAX_NEST  /* bounds the recursion on ((((...)))) and - - - x */
#define MAX_NAME 256

enum tok { T_EOF, T_NUM, T_NAME, T_PRIME, T_LPAR, T_RPAR, T_LBRK, T_RBRK, T_COMMA,
           T_PLUS, T_MINUS, T_STAR, T_SLASH, T_CARET, T_NEWLINE, T_BAD };

typedef struct rd {
    qd_ctx *ctx;
    const char *s;
    size_t pos;        /* scan position: just after the current token */
    enum tok tok;      /* the current token */
    size_t tpos, tlen; /* its bytes */
    int depth;         /* open brackets: newlines are blanks inside them */
    int nest;
    bool new_symbols;
    bool failed;
    const char *primed;  /* "\0"-separated names written as q' in the text, or NULL */
    const qd_expr **fresh; /* the plain symbols this text created (unknown names) */
    size_t nfresh, capfresh;
    qd_read_error *err;
} rd;

typedef struct vec {
    const qd_expr **v;
    size_t n, cap;
} vec;

static const qd_expr *sum(rd *p);
static const qd_expr *operand(rd *p);

/* ---- errors ------------------------------------------------------------- */

static const qd_expr *fail(rd *p, size_t off, size_t len, const char *hint, const char *fmt, ...)
#ifdef __GNUC__
    __attribute__((format(printf, 5, 6)))
#endif
    ;

static const qd_expr *fail(rd *p, size_t off, size_t len, const char *hint, const char *fmt, ...) {
    if (p->failed)
        return NULL;
    p->failed = true;
    char msg[256];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    qd_reason why = p->nest > MAX_NEST ? QD_REASON_TOO_DEEP : QD_REASON_NONE;
    unsigned char c = (unsigned char)p->s[off];
    if (p->tok == T_BAD && off == p->tpos && (c >= 0x7F || c < 0x20)) {
        len = qd__diag_bad_char(p->s + off, msg, sizeof msg, &hint);
        why = QD_REASON_BAD_BYTE;
    }
    /* a constructor's error (check) is reported at the reader's spot */
    qd_status st = p->ctx->status;
    qd__ctx_recover(p->ctx);
    qd_ctx_error(p->ctx, st != QD_OK ? st : QD_ERR_PARSE, "%s", msg);
    qd_ctx_error_about(p->ctx, QD_SUBJECT_TEXT, 0, NULL, why, hint);
    qd_ctx_error_at(p->ctx, p->s, off, len);
    if (p->err)
        *p->err = p->ctx->diag;
    return NULL;
}

/* A constructor returned NULL: report the kernel's reason at the spot. */
static const qd_expr *check(rd *p, const qd_expr *e, size_t off, size_t len) {
    if (!e && !p->failed) {
        const char *why = qd_ctx_message(p->ctx);
        fail(p, off, len, NULL, "%s", *why ? why : "cannot build this expression");
    }
    return e;
}

static size_t column(const rd *p, size_t off) {
    size_t c = 1;
    while (off > 0 && p->s[off - 1] != '\n') {
        off--;
        c++;
    }
    return c;
}

static bool push(rd *p, vec *v, const qd_expr *e) {
    if (v->n == v->cap) {
        size_t cap = v->cap ? 2 * v->cap : 8;
        const qd_expr **nv = qd__realloc(p->ctx, v->v, cap * sizeof *nv);
        if (!nv) {
            qd__oom(p->ctx);
            fail(p, p->tpos, p->tlen, NULL, "out of memory");
            return false;
        }
        v->v = nv;
        v->cap = cap;
    }
    v->v[v->n++] = e;
    return true;
}

/* ---- the scanner -------------------------------------------------------- */

static bool is_name_start(char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
}
static bool is_digit(char c) { return c >= '0' && c <= '9'; }
static bool is_name_char(char c) { return is_name_start(c) || is_digit(c); }

static size_t scan_number(const char *s) {
    size_t i = 0;
    while (is_digit(s[i]) || s[i] == '.')
        i++;
    if (s[i] == 'e' || s[i] == 'E') {
        size_t j = i + 1;
        if (s[j] == '+' || s[j] == '-')
            j++;
        if (is_digit(s[j])) {
            while (is_digit(s[j]))
                j++;
            i = j;
        }
    }
    if (s[i] == 'f' && !is_name_char(s[i + 1]))
        i++;
    return i;
}

static enum tok punct(char c) {
    switch (c) {
    case '\'': return T_PRIME;
    case '(': return T_LPAR;
    case ')': return T_RPAR;
    case '[': return T_LBRK;
    case ']': return T_RBRK;
    case ',': return T_COMMA;
    case '+': return T_PLUS;
    case '-': return T_MINUS;
    case '*': return T_STAR;
    case '/': return T_SLASH;
    case '^': return T_CARET;
    case '\n': return T_NEWLINE;
    default: return T_BAD;
    }
}

static void next(rd *p) {
    const char *s = p->s;
    size_t i = p->pos;
    while (s[i] == ' ' || s[i] == '\t' || s[i] == '\r' || (s[i] == '\n' && p->depth > 0))
        i++;
    p->tpos = i;
    if (!s[i]) {
        p->tok = T_EOF;
        p->tlen = 0;
    } else if (is_digit(s[i]) || (s[i] == '.' && is_digit(s[i + 1]))) {
        p->tok = T_NUM;
        p->tlen = scan_number(s + i);
    } else if (is_name_start(s[i])) {
        size_t j = i;
        while (is_name_char(s[j]))
            j++;
        p->tok = T_NAME;
        p->tlen = j - i;
    } else {
        p->tok = punct(s[i]);
        p->tlen = 1;
    }
    p->pos = i + p->tlen;
}

static const char *describe(const rd *p) {
    switch (p->tok) {
    case T_EOF: return "the end of the input";
    case T_NEWLINE: return "the end of the line";
    case T_NUM: return "a number";
    case T_NAME: return "a name";
    default: return NULL;
    }
}

/* "expected ..., found X" at the current token. */
static const qd_expr *unexpected(rd *p, const char *what, const char *hint) {
    const char *d = describe(p);
    if (d)
        return fail(p, p->tpos, p->tlen, hint, "expected %s, found %s", what, d);
    return fail(p, p->tpos, p->tlen, hint, "expected %s, found '%c'", what, p->s[p->tpos]);
}

/* Consume the closing bracket of one opened at off. */
static bool close(rd *p, enum tok t, char c, char open, size_t off) {
    p->depth--;
    if (p->tok == t) {
        next(p);
        return true;
    }
    char hint[64], msg[16];
    snprintf(hint, sizeof hint, "to close '%c' at column %zu", open, column(p, off));
    snprintf(msg, sizeof msg, "'%c'", c);
    fail(p, p->tpos, p->tlen, hint, "missing %s", msg);
    return false;
}

/* ---- numbers and names -------------------------------------------------- */

/* number := digits ['.' digits] [('e'|'E') ['+'|'-'] digits] ['f'] */
static const qd_expr *number(rd *p) {
    size_t off = p->tpos, len = p->tlen;
    char buf[128];
    bool is_float = p->s[off + len - 1] == 'f';
    size_t n = len - is_float;
    if (is_name_start(p->s[off + len]))
        return fail(p, off, len + 1, "write '*' to multiply, as in 2*x",
                    "a number cannot run into a name");
    size_t dots = 0;
    for (size_t i = 0; i < n; i++)
        dots += p->s[off + i] == '.';
    if (n >= sizeof buf || dots > 1)
        return fail(p, off, len, NULL, "bad number '%.*s'", (int)len, p->s + off);
    memcpy(buf, p->s + off, n);
    buf[n] = '\0';
    next(p);
    if (is_float)
        return check(p, qd_float(p->ctx, strtod(buf, NULL)), off, len);
    return check(p, qd_rat_str(p->ctx, buf), off, len);
}

/* Is name one of the names the text writes with a prime (prescan)? */
static bool is_primed(const rd *p, const char *name) {
    for (const char *q = p->primed; q && *q; q += strlen(q) + 1)
        if (!strcmp(q, name))
            return true;
    return false;
}

/* The names written q', q'', ... (not V'(r), a function's derivative), as
 * "\0"-separated strings ending in an empty one, in a buffer the caller
 * frees; NULL when there are none or out of memory (names then stay plain:
 * the reader refuses a plain symbol's prime below, so nothing reads as 0). */
static char *prescan_primed(qd_ctx *ctx, const char *text) {
    rd q = {.ctx = ctx, .s = text, .depth = 1};
    size_t n = 0, cap = 0;
    char *out = NULL;
    for (next(&q); q.tok != T_EOF && q.tok != T_BAD; next(&q)) {
        if (q.tok != T_NAME || text[q.pos] != '\'')
            continue;
        size_t off = q.tpos, len = q.tlen, after = q.pos;
        while (text[after] == '\'')
            after++;
        while (text[after] == ' ' || text[after] == '\t' || text[after] == '\r' || text[after] == '\n')
            after++;
        if (text[after] == '(' || text[after] == '[' || len >= MAX_NAME)
            continue;
        if (n + len + 2 > cap) {
            size_t ncap = 2 * (n + len + 2);
            char *b = qd__realloc(ctx, out, ncap);
            if (!b)
                break;
            out = b;
            cap = ncap;
        }
        memcpy(out + n, text + off, len);
        n += len;
        out[n++] = '\0';
        out[n] = '\0';
    }
    return out;
}

/* A name standing alone: a symbol, pi, e, t, or a new symbol.  The name t
 * prints as (qd_print_set_time_name: x for `independent x`) is t first,
 * so that what the text printer writes reads back. */
static const qd_expr *name_value(rd *p, const char *name, size_t off, size_t len) {
    if (p->ctx->sym->tname && !strcmp(name, p->ctx->sym->tname))
        return check(p, qd_time(p->ctx), off, len);
    const qd_expr *s = qd_lookup(p->ctx, name);
    if (s)
        return s;
    if (!strcmp(name, "pi"))
        return qd_const(p->ctx, QD_PI);
    if (!strcmp(name, "e"))
        return qd_const(p->ctx, QD_E);
    if (!strcmp(name, "t"))
        return check(p, qd_time(p->ctx), off, len);
    if (!p->new_symbols)
        return fail(p, off, len, NULL, "unknown name '%s'", name);
    if (is_primed(p, name))
        return check(p, qd_coord(p->ctx, name), off, len);
    const qd_expr *fresh = check(p, qd_symbol(p->ctx, name), off, len);
    if (fresh && p->nfresh == p->capfresh) {
        size_t ncap = p->capfresh ? 2 * p->capfresh : 8;
        const qd_expr **b = qd__realloc(p->ctx, p->fresh, ncap * sizeof *b);
        if (!b) {
            qd__oom(p->ctx);
            return fail(p, off, len, NULL, "out of memory");
        }
        p->fresh = b;
        p->capfresh = ncap;
    }
    if (fresh)
        p->fresh[p->nfresh++] = fresh;
    return fresh;
}

/* args := '(' [ sum { ',' sum } ] ')' */
static bool args(rd *p, vec *v) {
    size_t open = p->tpos;
    p->depth++;
    next(p);
    if (p->tok != T_RPAR) {
        for (;;) {
            const qd_expr *a = sum(p);
            if (!a || !push(p, v, a))
                return false;
            if (p->tok != T_COMMA)
                break;
            next(p);
        }
    }
    return close(p, T_RPAR, ')', '(', open);
}

static const qd_expr *builtin(rd *p, const char *name, size_t off, size_t len, const vec *v) {
    qd_func f = QD_SIN;
    bool sq = !strcmp(name, "sqrt");
    if (!sq)
        qd_func_from_name(name, &f);
    size_t want = f == QD_ATAN2 ? 2 : 1;
    if (v->n != want)
        return fail(p, off, len, NULL, "%s takes %zu argument%s, not %zu", name, want,
                    want == 1 ? "" : "s", v->n);
    if (sq)
        return check(p, qd_sqrt(p->ctx, v->v[0]), off, len);
    if (f == QD_ATAN2)
        return check(p, qd__atan2_written(p->ctx, v->v[0], v->v[1]), off, len);
    return check(p, qd_fn(p->ctx, f, v->v[0]), off, len);
}

/* A call of a function that is not built in: known name, or new_symbols. */
static bool user_ok(rd *p, const char *name, size_t off, size_t len) {
    if (qd_lookup(p->ctx, name)) {
        fail(p, off, len, "write '*' to multiply", "'%s' is a symbol, not a function", name);
        return false;
    }
    if (!p->new_symbols && !qd__find_name(p->ctx, name)) {
        fail(p, off, len, NULL, "unknown function '%s'", name);
        return false;
    }
    return true;
}

/* slots := '[' slot { ',' slot } ']'   (1-based argument numbers) */
static size_t slots(rd *p, unsigned *out, size_t cap) {
    size_t open = p->tpos, n = 0;
    p->depth++;
    next(p);
    for (;;) {
        if (p->tok != T_NUM || n == cap) {
            unexpected(p, "an argument number", "V'[1,2](x, y) is d2V/dx dy");
            return 0;
        }
        unsigned long k = strtoul(p->s + p->tpos, NULL, 10);
        if (k == 0 || k > 64 || p->tlen != strspn(p->s + p->tpos, "0123456789")) {
            fail(p, p->tpos, p->tlen, "arguments count from 1", "bad argument number");
            return 0;
        }
        out[n++] = (unsigned)(k - 1);
        next(p);
        if (p->tok != T_COMMA)
            break;
        next(p);
    }
    return close(p, T_RBRK, ']', '[', open) ? n : 0;
}

/* uderiv := name "'"... [ slots ] args   (p is at the first prime) */
static const qd_expr *uderiv(rd *p, const char *name, size_t off, size_t nprime) {
    unsigned sl[64];
    size_t ns = nprime;
    bool bracket = p->tok == T_LBRK;
    if (!user_ok(p, name, off, strlen(name)))
        return NULL;
    if (bracket) {
        if (nprime != 1)
            return fail(p, off, p->tpos - off, "write V'[1,1](x, y)",
                        "one prime before an argument list");
        if (!(ns = slots(p, sl, 64)))
            return NULL;
    } else if (nprime > 64) {
        return fail(p, off, p->tpos - off, NULL, "too many primes");
    } else {
        memset(sl, 0, sizeof sl);
    }
    vec v = {0};
    const qd_expr *r = NULL;
    if (args(p, &v)) {
        size_t len = p->tpos - off;
        if (!bracket && v.n != 1) {
            char hint[MAX_NAME + 40];
            snprintf(hint, sizeof hint, "say which argument: %s'[1](...)", name);
            fail(p, off, len, hint, "%s has %zu arguments", name, v.n);
        }
        for (size_t i = 0; i < ns && !p->failed; i++)
            if (sl[i] >= v.n)
                fail(p, off, len, NULL, "%s has no argument %u", name, sl[i] + 1);
        if (!p->failed)
            r = check(p, qd_uderiv(p->ctx, name, ns, sl, v.n, v.v), off, len);
    }
    qd__free(v.v);
    return r;
}

/* call := name args   (built-in, sqrt or user function) */
static const qd_expr *call(rd *p, const char *name, size_t off) {
    qd_func f;
    bool known = qd_func_from_name(name, &f) || !strcmp(name, "sqrt");
    if (!known && !user_ok(p, name, off, strlen(name)))
        return NULL;
    vec v = {0};
    const qd_expr *r = NULL;
    if (args(p, &v)) {
        size_t len = p->tpos - off;
        r = known ? builtin(p, name, off, len, &v)
                  : check(p, qd_ufunc(p->ctx, name, v.n, v.v), off, len);
    }
    qd__free(v.v);
    return r;
}

/* name-led primary := name | name args | name "'"... [ slots ] args */
static const qd_expr *named(rd *p) {
    char name[MAX_NAME];
    size_t off = p->tpos, len = p->tlen;
    if (len >= MAX_NAME)
        return fail(p, off, len, NULL, "name longer than %d bytes", MAX_NAME - 1);
    memcpy(name, p->s + off, len);
    name[len] = '\0';
    size_t after = p->pos, nprime = 0;
    while (p->s[after + nprime] == '\'')
        nprime++;
    next(p);
    if (p->tok == T_LPAR && !nprime)
        return call(p, name, off);
    if (nprime) {
        /* look past the primes: V'(r) and V'[1](x, y) are derivatives */
        p->pos = after + nprime;
        next(p);
        if (p->tok == T_LPAR || p->tok == T_LBRK)
            return uderiv(p, name, off, nprime);
        p->pos = after;
        next(p);
    }
    return name_value(p, name, off, len);
}

/* ---- expressions -------------------------------------------------------- */

/* primary := number | name | call | '(' sum ')' */
static const qd_expr *primary(rd *p) {
    switch (p->tok) {
    case T_NUM: return number(p);
    case T_NAME: return named(p);
    case T_LPAR: {
        size_t open = p->tpos;
        p->depth++;
        next(p);
        const qd_expr *e = sum(p);
        if (e && p->tok == T_COMMA) { /* (1, 2, 3) */
            p->depth--;
            return fail(p, p->tpos, 1, "write one expression, or each component on its own",
                        "a vector or tuple is not an expression here: ',' inside '(' at column %zu",
                        column(p, open));
        }
        if (!e || !close(p, T_RPAR, ')', '(', open))
            return NULL;
        return e;
    }
    case T_RPAR: return fail(p, p->tpos, 1, "remove it, or open it with '(' before",
                             "unmatched ')'");
    default: return unexpected(p, "an expression", NULL);
    }
}

/* Is s a plain symbol that this text created (an unknown name)? */
static bool is_fresh(const rd *p, const qd_expr *s) {
    for (size_t i = 0; i < p->nfresh; i++)
        if (p->fresh[i] == s)
            return true;
    return false;
}

/* The first plain symbol in e that the text created (an unknown name, not a
 * symbol the caller made), or NULL (none, or out of memory: the caller then
 * goes on, and a constructor's error is reported as usual). */
static const qd_expr *plain_symbol(rd *p, const qd_expr *e) {
    qd_ctx *ctx = p->ctx;
    if (!p->nfresh)
        return NULL;
    const qd_expr *buf[16];
    size_t n = qd_free_symbols(ctx, e, buf, 16);
    const qd_expr **all = buf;
    if (n > 16) {
        all = qd__malloc(ctx, n * sizeof *all);
        if (!all)
            return NULL;
        n = qd_free_symbols(ctx, e, all, n);
    }
    const qd_expr *found = NULL;
    for (size_t i = 0; i < n && !found; i++)
        if (all[i]->kind == QD_SYMBOL && all[i]->tag == QD_ROLE_PLAIN && is_fresh(p, all[i]))
            found = all[i];
    if (all != buf)
        qd__free(all);
    return found;
}

/* postfix := primary { "'" }   (a coordinate steps along its jet, else d/dt) */
static const qd_expr *postfix(rd *p) {
    size_t off = p->tpos;
    const qd_expr *e = primary(p);
    if (e && p->tok == T_PRIME && e->kind == QD_SYMBOL && e->tag == QD_ROLE_PLAIN)
        return fail(p, off, p->pos - off, "declare it a coordinate, or write it as a symbol of its own",
                    "'%s' is a plain symbol: its rate would be 0", e->u.sym.name);
    if (e && p->tok == T_PRIME && e->kind != QD_SYMBOL) {
        /* the rate of (r^2*th')' or sin(x)' would take each plain symbol in
         * it as constant (issue 33: (x*y)' read as 0): refused, naming it */
        const qd_expr *plain = plain_symbol(p, e);
        if (plain)
            return fail(p, off, p->pos - off,
                        "write its rate out, or write the name with a prime elsewhere in the text "
                        "(it is then a coordinate)",
                        "'%s' is a plain symbol: its rate in this derivative would be 0",
                        plain->u.sym.name);
    }
    while (e && p->tok == T_PRIME) {
        if (e->kind == QD_SYMBOL && e->tag == QD_ROLE_COORD)
            e = qd_jet(p->ctx, e, e->order + 1u);
        else
            e = qd_dt(p->ctx, e);
        e = check(p, e, off, p->pos - off);
        next(p);
    }
    return e;
}

/* power := postfix [ '^' operand ] */
static const qd_expr *power(rd *p) {
    size_t off = p->tpos;
    const qd_expr *b = postfix(p);
    if (!b || p->tok != T_CARET)
        return b;
    next(p);
    const qd_expr *x = operand(p);
    return x ? check(p, qd__pow_written(p->ctx, b, x), off, p->tpos - off) : NULL;
}

/* Unary signs before f, as in term and operand: '+'... '-'... f */
static const qd_expr *signed_(rd *p, const qd_expr *(*f)(rd *)) {
    if (p->tok != T_PLUS && p->tok != T_MINUS)
        return f(p);
    bool minus = p->tok == T_MINUS;
    size_t off = p->tpos;
    if (++p->nest > MAX_NEST)
        return fail(p, off, 1, QD_NEST_HINT, "expression nested too deeply");
    next(p);
    if (p->tok == T_EOF || p->tok == T_NEWLINE)
        return unexpected(p, "an operand", "the sign needs something after it");
    const qd_expr *e = signed_(p, f);
    p->nest--;
    return e && minus ? check(p, qd_neg(p->ctx, e), off, p->tpos - off) : e;
}

/* operand := ('+' | '-') operand | power */
static const qd_expr *operand(rd *p) { return signed_(p, power); }

/* product := power { ('*' | '/') operand } */
static const qd_expr *product(rd *p) {
    vec v = {0};
    const qd_expr *e = power(p), *r = NULL;
    bool ok = e && push(p, &v, e);
    while (ok && (p->tok == T_STAR || p->tok == T_SLASH)) {
        bool div = p->tok == T_SLASH;
        size_t op = p->tpos;
        next(p);
        if (p->tok == T_EOF || p->tok == T_NEWLINE) {
            unexpected(p, "an operand", div ? "'/' needs a divisor" : "'*' needs a factor");
            break;
        }
        size_t at = p->tpos;
        if (!(e = operand(p)))
            break;
        if (div && qd_is_zero(e) && e->kind == QD_RATIONAL) {
            fail(p, op, p->tpos - op, NULL, "division by zero");
            break;
        }
        if (div)
            e = check(p, qd_pow(p->ctx, e, qd_int(p->ctx, -1)), at, p->tpos - at);
        ok = e && push(p, &v, e);
    }
    if (ok && !p->failed)
        r = check(p, qd_mul_n(p->ctx, v.n, v.v), p->tpos, 0);
    qd__free(v.v);
    return r;
}

/* term := ('+' | '-') term | product */
static const qd_expr *term(rd *p) { return signed_(p, product); }

/* sum := term { ('+' | '-') term } */
static const qd_expr *sum(rd *p) {
    if (++p->nest > MAX_NEST)
        return fail(p, p->tpos, p->tlen, QD_NEST_HINT, "expression nested too deeply");
    vec v = {0};
    const qd_expr *e = term(p), *r = NULL;
    bool ok = e && push(p, &v, e);
    while (ok && (p->tok == T_PLUS || p->tok == T_MINUS)) {
        bool minus = p->tok == T_MINUS;
        size_t op = p->tpos;
        next(p);
        if (p->tok == T_EOF || p->tok == T_NEWLINE) {
            unexpected(p, "an operand", minus ? "'-' needs a right operand"
                                              : "'+' needs a right operand");
            break;
        }
        if (!(e = term(p)))
            break;
        if (minus)
            e = check(p, qd_neg(p->ctx, e), op, p->tpos - op);
        ok = e && push(p, &v, e);
    }
    if (ok && !p->failed)
        r = check(p, qd_add_n(p->ctx, v.n, v.v), p->tpos, 0);
    qd__free(v.v);
    p->nest--;
    return r;
}

/* input := sum EOF */
static const qd_expr *read_input(rd *p) {
    next(p);
    while (p->tok == T_NEWLINE)
        next(p);
    if (p->tok == T_EOF)
        return fail(p, p->tpos, 0, "write an expression such as x + 1", "empty expression");
    const qd_expr *e = sum(p);
    while (e && p->tok == T_NEWLINE)
        next(p);
    if (!e || p->tok == T_EOF)
        return e;
    if (p->tok == T_RPAR)
        return fail(p, p->tpos, 1, "remove it, or open it with '(' before", "unmatched ')'");
    if (p->tok == T_NUM || p->tok == T_NAME || p->tok == T_LPAR)
        return unexpected(p, "an operator", "write '*' to multiply");
    return unexpected(p, "an operator or the end of the input", NULL);
}

const qd_expr *qd_read(qd_ctx *ctx, const char *text, const qd_read_opts *opts,
                       qd_read_error *err) {
    QD_ARGS(NULL, ctx && text);
    if (err)
        memset(err, 0, sizeof *err);
    if (!ctx)
        return NULL;
    rd p = {.ctx = ctx, .s = text ? text : "", .new_symbols = !opts || opts->new_symbols,
            .err = err};
    char *primed = p.new_symbols ? prescan_primed(ctx, p.s) : NULL;
    p.primed = primed;
    const qd_expr *e = read_input(&p);
    qd__free(primed);
    qd__free(p.fresh);
    return e;
}

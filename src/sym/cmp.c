/*
 * src/sym/cmp.c - the canonical total order, and inspection of nodes.
 *
 * The order decides how sums and products are stored, hence printed.  It
 * depends only on structure (never on addresses), so output is the same in
 * every run.  Rules, in order:
 *   - numbers first, by value; then pi, e; then symbols by name in natural
 *     order (theta2 < theta10); then function calls; then the rest;
 *   - a power is compared by its base first, then its exponent, so that
 *     x < x^2 < x*y < y: factors of one base sit together;
 *   - calls by function, then arguments left to right; sums and products by
 *     their arguments left to right, a prefix before the longer sequence.
 */
#include "node.h"
#include "../base/args.h"

#include <ctype.h>
#include <stdlib.h>
#include <string.h>

/* isdigit is '0'..'9' in every locale (C11 7.4.1.5); the range test spares
 * the ctype table lookup per character of every comparison of two names. */
static bool digit(char c) { return c >= '0' && c <= '9'; }

int qd__name_cmp(const char *a, const char *b) {
    const char *a0 = a, *b0 = b;
    while (*a && *b) {
        if (digit(*a) && digit(*b)) {
            const char *ea = a, *eb = b;
            while (*a == '0')
                a++;
            while (*b == '0')
                b++;
            const char *sa = a, *sb = b;
            while (digit(*a))
                a++;
            while (digit(*b))
                b++;
            if (a - sa != b - sb)
                return (a - sa) < (b - sb) ? -1 : 1;
            int c = strncmp(sa, sb, (size_t)(a - sa));
            if (c)
                return c;
            (void)ea;
            (void)eb;
            continue;
        }
        if (*a != *b)
            return (unsigned char)*a < (unsigned char)*b ? -1 : 1;
        a++;
        b++;
    }
    if (*a || *b)
        return *a ? 1 : -1;
    return strcmp(a0, b0); /* "x01" and "x1": still a total order */
}

static int rank(const qd_expr *e) {
    switch ((qd_kind)e->kind) {
    case QD_RATIONAL:
    case QD_FLOAT: return 0;
    case QD_CONSTANT: return 1;
    case QD_SYMBOL: return 2;
    case QD_FUNC: return 3;
    case QD_UFUNC: return 4;
    case QD_UDERIV: return 5;
    case QD_POW: return 6;
    case QD_MUL: return 7;
    case QD_ADD: return 8;
    }
    return 9;
}

static int args_cmp(const qd_expr *a, const qd_expr *b) {
    return qd__seq_cmp(a->args, a->nargs, b->args, b->nargs);
}

int qd__seq_cmp(const qd_expr *const *a, size_t na, const qd_expr *const *b, size_t nb) {
    size_t n = na < nb ? na : nb;
    for (size_t i = 0; i < n; i++) {
        int c = qd_expr_cmp(a[i], b[i]);
        if (c)
            return c;
    }
    return (na > nb) - (na < nb);
}

/* Exponent of the base view: NULL stands for 1. */
static int exp_cmp(const qd_expr *x, const qd_expr *y) {
    if (x == y)
        return 0;
    if (!x || !y) {
        const qd_expr *e = x ? x : y;
        int sign = x ? 1 : -1;
        if (qd__is_num(e))
            return sign * (qd_number_value(e) < 1.0 ? -1 : 1);
        return -sign; /* 1 before a symbolic exponent */
    }
    return qd_expr_cmp(x, y);
}

static int same_rank_cmp(const qd_expr *a, const qd_expr *b) {
    int c;
    switch ((qd_kind)a->kind) {
    case QD_RATIONAL:
    case QD_FLOAT:
        return qd__number_cmp(a, b);
    case QD_CONSTANT:
        return (int)a->tag - (int)b->tag;
    case QD_SYMBOL:
        return qd__name_cmp(a->u.sym.name, b->u.sym.name);
    case QD_FUNC:
        if (a->tag != b->tag)
            return a->tag < b->tag ? -1 : 1;
        return args_cmp(a, b);
    case QD_UDERIV:
        c = strcmp(a->u.fn.name, b->u.fn.name);
        if (c)
            return c;
        for (uint32_t i = 0; i < a->u.fn.nslots && i < b->u.fn.nslots; i++)
            if (a->u.fn.slots[i] != b->u.fn.slots[i])
                return a->u.fn.slots[i] < b->u.fn.slots[i] ? -1 : 1;
        if (a->u.fn.nslots != b->u.fn.nslots)
            return a->u.fn.nslots < b->u.fn.nslots ? -1 : 1;
        return args_cmp(a, b);
    case QD_UFUNC:
        c = qd__name_cmp(a->u.fn.name, b->u.fn.name);
        return c ? c : args_cmp(a, b);
    case QD_POW:
    case QD_MUL:
    case QD_ADD:
        return args_cmp(a, b);
    }
    return 0;
}

int qd_expr_cmp(const qd_expr *a, const qd_expr *b) {
    QD_ARGS(0, a && b);
    if (a == b)
        return 0;
    const qd_expr *ba = a, *bb = b, *ea = NULL, *eb = NULL;
    if (a->kind == QD_POW) {
        ba = a->args[0];
        ea = a->args[1];
    }
    if (b->kind == QD_POW) {
        bb = b->args[0];
        eb = b->args[1];
    }
    if (ba != bb) {
        int ra = rank(ba), rb = rank(bb);
        if (ra != rb)
            return ra < rb ? -1 : 1;
        int c = same_rank_cmp(ba, bb);
        if (c)
            return c;
    }
    int c = exp_cmp(ea, eb);
    if (c)
        return c;
    /* Distinct nodes that tie above (a float and an equal rational base): */
    return a->hash < b->hash ? -1 : a->hash > b->hash;
}

/* ---- inspection --------------------------------------------------------- */

qd_kind qd_expr_kind(const qd_expr *e) { QD_ARGS((qd_kind)0, e); return (qd_kind)e->kind; }
size_t qd_expr_nargs(const qd_expr *e) { QD_ARGS(0, e); return e->nargs; }
const qd_expr *qd_expr_arg(const qd_expr *e, size_t i) { QD_ARGS(NULL, e); return i < e->nargs ? e->args[i] : NULL; }
uint64_t qd_expr_hash(const qd_expr *e) { QD_ARGS(0, e); return e->hash; }
qd_role qd_symbol_role(const qd_expr *e) { QD_ARGS((qd_role)0, e); return (qd_role)e->tag; }
unsigned qd_symbol_order(const qd_expr *e) { QD_ARGS(0, e); return e->order; }
qd_func qd_expr_func(const qd_expr *e) { QD_ARGS((qd_func)0, e); return (qd_func)e->tag; }
qd_constant qd_expr_constant(const qd_expr *e) { QD_ARGS((qd_constant)0, e); return (qd_constant)e->tag; }

const qd_expr *qd_symbol_coord(const qd_expr *e) {
    QD_ARGS(NULL, e);
    return e->kind == QD_SYMBOL && e->tag == QD_ROLE_COORD ? e->u.sym.coord : NULL;
}

const char *qd_expr_name(const qd_expr *e) {
    QD_ARGS(NULL, e);
    if (e->kind == QD_SYMBOL)
        return e->u.sym.name;
    if (e->kind == QD_UFUNC || e->kind == QD_UDERIV)
        return e->u.fn.name;
    if (e->kind == QD_FUNC)
        return qd_func_name((qd_func)e->tag);
    return NULL;
}

size_t qd_uderiv_nslots(const qd_expr *e) { QD_ARGS(0, e); return e->kind == QD_UDERIV ? e->u.fn.nslots : 0; }
unsigned qd_uderiv_slot(const qd_expr *e, size_t i) { QD_ARGS(0, e); return e->u.fn.slots[i]; }

static bool has_rec(const qd_expr *e, const qd_expr *x, qd__ptrmap *seen) {
    if (e == x)
        return true;
    if (!e->nargs)
        return false;
    /* a node over leaves only (sin(q), q'^2, a*b) is answered without the
     * memo: remembering it would cost an allocation and save nothing */
    bool leaves = true;
    for (uint32_t i = 0; leaves && i < e->nargs; i++)
        leaves = !e->args[i]->nargs;
    if (leaves) {
        for (uint32_t i = 0; i < e->nargs; i++)
            if (e->args[i] == x)
                return true;
        return false;
    }
    if (qd__ptrmap_has(seen, e))
        return false;
    for (uint32_t i = 0; i < e->nargs; i++)
        if (has_rec(e->args[i], x, seen))
            return true;
    qd__ptrmap_put(seen, e, (void *)e); /* on failure we only revisit */
    return false;
}

bool qd_has(const qd_expr *e, const qd_expr *x) {
    QD_ARGS(false, e && x);
    if (!e || !x)
        return false;
    qd__ptrmap seen = QD_PTRMAP_INIT;
    bool r = has_rec(e, x, &seen);
    qd__ptrmap_free(&seen);
    return r;
}

/* false when out of memory: a symbol may be missing from syms */
static bool symbols_rec(const qd_expr *e, qd__ptrmap *seen, qd__ptrmap *syms) {
    if (qd__ptrmap_has(seen, e))
        return true;
    bool ok = qd__ptrmap_put(seen, e, (void *)e);
    if (e->kind == QD_SYMBOL)
        ok = qd__ptrmap_put(syms, e, (void *)e) && ok;
    for (uint32_t i = 0; ok && i < e->nargs; i++)
        ok = symbols_rec(e->args[i], seen, syms);
    return ok;
}

static int cmp_ptr(const void *a, const void *b) {
    return qd_expr_cmp(*(const qd_expr *const *)a, *(const qd_expr *const *)b);
}

size_t qd_free_symbols(qd_ctx *ctx, const qd_expr *e, const qd_expr **out, size_t cap) {
    QD_ARGS(0, ctx && e);
    if (!e)
        return 0;
    qd__ptrmap seen = QD_PTRMAP_AL(qd__ctx_allocator(ctx)),
               syms = QD_PTRMAP_AL(qd__ctx_allocator(ctx));
    bool ok = symbols_rec(e, &seen, &syms);
    if (!ok)
        qd__oom(ctx);
    size_t n = 0;
    const qd_expr **all = ok && syms.len ? qd__alloc(ctx, syms.len * sizeof *all) : NULL;
    for (size_t i = 0; all && i < syms.cap; i++)
        if (syms.slots[i].key)
            all[n++] = syms.slots[i].key;
    if (n > 1)
        qsort(all, n, sizeof *all, cmp_ptr);
    for (size_t i = 0; i < n && i < cap; i++)
        out[i] = all[i];
    size_t total = all ? syms.len : 0; /* 0 and the error in ctx when out of memory */
    qd__ptrmap_free(&seen);
    qd__ptrmap_free(&syms);
    return total;
}

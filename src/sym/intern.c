/*
 * src/sym/intern.c - the context and its unique table (hash-consing).
 *
 * Every node goes through qd__intern: the node's hash is computed from its
 * kind, its payload and its arguments' hashes (never from addresses, so it is
 * the same in every run), the table is probed, and an existing equal node is
 * returned instead of a new one.  Arguments are already unique, so "equal"
 * compares argument pointers, not subtrees: interning costs O(nargs).
 */
#include "node.h"
#include "../base/args.h"
#include "../base/diag.h" /* qd__diag_line_col */

#include <assert.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

uint64_t qd__hash_mix(uint64_t h, uint64_t v) {
    h ^= v + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
    h ^= h >> 31;
    h *= 0xbf58476d1ce4e5b9ULL;
    h ^= h >> 29;
    return h;
}

static uint64_t hash_str(const char *s) {
    uint64_t h = 1469598103934665603ULL; /* FNV-1a */
    for (; *s; s++) {
        h ^= (unsigned char)*s;
        h *= 1099511628211ULL;
    }
    return h;
}

static uint64_t hash_mpz(uint64_t h, const mpz_t z) {
    size_t n = mpz_size(z);
    h = qd__hash_mix(h, (uint64_t)mpz_sgn(z) + 7);
    for (size_t i = 0; i < n; i++)
        h = qd__hash_mix(h, (uint64_t)mpz_getlimbn(z, (mp_size_t)i));
    return h;
}

static uint64_t node_hash(const qd_expr *p, size_t nargs, const qd_expr *const *args) {
    uint64_t h = qd__hash_mix((uint64_t)p->kind * 1000003u, (uint64_t)p->tag * 31u + p->order);
    switch ((qd_kind)p->kind) {
    case QD_RATIONAL:
        h = hash_mpz(h, mpq_numref(p->u.q));
        h = hash_mpz(h, mpq_denref(p->u.q));
        break;
    case QD_FLOAT: {
        uint64_t bits;
        memcpy(&bits, &p->u.f, sizeof bits);
        h = qd__hash_mix(h, bits);
        break;
    }
    case QD_SYMBOL:
        h = qd__hash_mix(h, hash_str(p->u.sym.name));
        break;
    case QD_UDERIV:
        for (uint32_t i = 0; i < p->u.fn.nslots; i++)
            h = qd__hash_mix(h, p->u.fn.slots[i] + 17u);
        /* fall through */
    case QD_UFUNC:
        h = qd__hash_mix(h, hash_str(p->u.fn.name));
        break;
    default:
        break;
    }
    for (size_t i = 0; i < nargs; i++)
        h = qd__hash_mix(h, args[i]->hash);
    return h;
}

static bool node_equal(const qd_expr *a, const qd_expr *p, uint64_t h, size_t nargs,
                       const qd_expr *const *args) {
    if (a->hash != h || a->kind != p->kind || a->tag != p->tag || a->order != p->order ||
        a->nargs != nargs)
        return false;
    switch ((qd_kind)p->kind) {
    case QD_RATIONAL:
        return mpq_equal(a->u.q, p->u.q) != 0;
    case QD_FLOAT:
        return memcmp(&a->u.f, &p->u.f, sizeof a->u.f) == 0;
    case QD_SYMBOL:
        return a->u.sym.name == p->u.sym.name;
    case QD_UDERIV:
        if (a->u.fn.nslots != p->u.fn.nslots ||
            memcmp(a->u.fn.slots, p->u.fn.slots, p->u.fn.nslots * sizeof(unsigned)) != 0)
            return false;
        /* fall through */
    case QD_UFUNC:
        if (a->u.fn.name != p->u.fn.name)
            return false;
        break;
    default:
        break;
    }
    for (size_t i = 0; i < nargs; i++)
        if (a->args[i] != args[i])
            return false;
    return true;
}

void qd__oom(qd_ctx *ctx) { qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory"); }

void *qd__alloc(qd_ctx *ctx, size_t size) {
    void *p = qd_arena_alloc(&ctx->arena, size);
    if (!p)
        qd__oom(ctx);
    return p;
}

static bool table_grow(qd_ctx *ctx) {
    size_t cap = ctx->table_cap ? ctx->table_cap * 2 : 4096;
    struct qd__slot *t = qd__mem_calloc(ctx->alloc, cap, sizeof *t);
    if (!t)
        return false;
    for (size_t i = 0; i < ctx->table_cap; i++) {
        struct qd__slot slot = ctx->table[i];
        if (!slot.e)
            continue;
        size_t j = (size_t)slot.hash & (cap - 1);
        while (t[j].e)
            j = (j + 1) & (cap - 1);
        t[j] = slot;
    }
    qd__free(ctx->table);
    ctx->table = t;
    ctx->table_cap = cap;
    return true;
}

static bool remember_rational(qd_ctx *ctx, qd_expr *e) {
    if (ctx->nrat == ctx->rat_cap) {
        size_t cap = ctx->rat_cap ? ctx->rat_cap * 2 : 256;
        qd_expr **r = qd__mem_realloc(ctx->alloc, ctx->rationals, cap * sizeof *r);
        if (!r)
            return false;
        ctx->rationals = r;
        ctx->rat_cap = cap;
    }
    ctx->rationals[ctx->nrat++] = e;
    return true;
}

const qd_expr *qd__intern(qd_ctx *ctx, const qd_expr *proto, size_t nargs,
                          const qd_expr *const *args) {
    for (size_t i = 0; i < nargs; i++)
        if (!args[i])
            return NULL;
    if ((ctx->table_len + 1) * 2 > ctx->table_cap && !table_grow(ctx)) {
        qd__oom(ctx);
        return NULL;
    }
    uint64_t h = node_hash(proto, nargs, args);
    size_t i = (size_t)h & (ctx->table_cap - 1);
    for (; ctx->table[i].e; i = (i + 1) & (ctx->table_cap - 1))
        if (ctx->table[i].hash == h && node_equal(ctx->table[i].e, proto, h, nargs, args))
            return ctx->table[i].e;
    assert(qd__is_canonical(proto, nargs, args));

    qd_expr *e = qd__alloc(ctx, sizeof *e + nargs * sizeof e->args[0]);
    if (!e)
        return NULL;
    memcpy(e, proto, sizeof *e);
    e->hash = h;
    e->nargs = (uint32_t)nargs;
    if (nargs)
        memcpy(e->args, args, nargs * sizeof args[0]);
    if (proto->kind == QD_RATIONAL) {
        if (!remember_rational(ctx, e)) {
            qd__oom(ctx);
            return NULL;
        }
        mpq_init(e->u.q);
        mpq_set(e->u.q, proto->u.q);
    } else if (proto->kind == QD_UDERIV) {
        unsigned *slots = qd__alloc(ctx, proto->u.fn.nslots * sizeof *slots);
        if (!slots)
            return NULL;
        memcpy(slots, proto->u.fn.slots, proto->u.fn.nslots * sizeof *slots);
        e->u.fn.slots = slots;
    }
    ctx->table[i] = (struct qd__slot){h, e};
    ctx->table_len++;
    return e;
}

/* Names are interned too, so symbols and functions compare names by pointer. */
const char *qd__intern_name(qd_ctx *ctx, const char *name) {
    if ((ctx->names_len + 1) * 2 > ctx->names_cap) {
        size_t cap = ctx->names_cap ? ctx->names_cap * 2 : 256;
        const char **t = qd__mem_calloc(ctx->alloc, cap, sizeof *t);
        if (!t) {
            qd__oom(ctx);
            return NULL;
        }
        for (size_t i = 0; i < ctx->names_cap; i++) {
            if (!ctx->names[i])
                continue;
            size_t j = (size_t)hash_str(ctx->names[i]) & (cap - 1);
            while (t[j])
                j = (j + 1) & (cap - 1);
            t[j] = ctx->names[i];
        }
        qd__free(ctx->names);
        ctx->names = t;
        ctx->names_cap = cap;
    }
    size_t i = (size_t)hash_str(name) & (ctx->names_cap - 1);
    for (; ctx->names[i]; i = (i + 1) & (ctx->names_cap - 1))
        if (strcmp(ctx->names[i], name) == 0)
            return ctx->names[i];
    size_t n = strlen(name) + 1;
    char *s = qd__alloc(ctx, n);
    if (!s)
        return NULL;
    memcpy(s, name, n);
    ctx->names[i] = s;
    ctx->names_len++;
    return s;
}

const char *qd__find_name(const qd_ctx *ctx, const char *name) {
    if (!ctx->names_cap)
        return NULL;
    size_t i = (size_t)hash_str(name) & (ctx->names_cap - 1);
    for (; ctx->names[i]; i = (i + 1) & (ctx->names_cap - 1))
        if (strcmp(ctx->names[i], name) == 0)
            return ctx->names[i];
    return NULL;
}

qd_ctx *qd_ctx_new(void) { return qd_ctx_new_with(NULL); }

qd_ctx *qd_ctx_new_with(const qd_allocator *a) {
    qd__gmp_install();
    qd_ctx *ctx = qd__mem_calloc(a, 1, sizeof *ctx);
    if (!ctx)
        return NULL;
    ctx->alloc = a;
    ctx->symtab.al = a;
    qd_arena_init(&ctx->arena, a);
    ctx->zero = qd_int(ctx, 0);
    ctx->one = qd_int(ctx, 1);
    ctx->minus_one = qd_int(ctx, -1);
    ctx->half = qd_rat(ctx, 1, 2);
    ctx->t = qd_time(ctx);
    if (!ctx->zero || !ctx->one || !ctx->minus_one || !ctx->half || !ctx->t) {
        qd_ctx_free(ctx);
        return NULL;
    }
    return ctx;
}

void qd_ctx_free(qd_ctx *ctx) {
    if (!ctx)
        return;
    for (size_t i = 0; i < ctx->nrat; i++)
        mpq_clear(ctx->rationals[i]->u.q);
    qd__free(ctx->rationals);
    qd__free(ctx->table);
    qd__free(ctx->names);
    qd_ptrmap_free(&ctx->symtab);
    qd_arena_free(&ctx->arena);
    qd__free(ctx);
}

/* ---- the context's allocation path (mem.h) ------------------------------ */

const qd_allocator *qd__ctx_allocator(const qd_ctx *ctx) { return ctx->alloc; }

void *qd__malloc(qd_ctx *ctx, size_t size) {
    void *p = qd__mem_malloc(ctx->alloc, size);
    if (!p)
        qd__oom(ctx);
    return p;
}

void *qd__calloc(qd_ctx *ctx, size_t n, size_t size) {
    void *p = qd__mem_calloc(ctx->alloc, n, size);
    if (!p)
        qd__oom(ctx);
    return p;
}

void *qd__realloc(qd_ctx *ctx, void *p, size_t size) {
    void *q = qd__mem_realloc(ctx->alloc, p, size);
    if (!q)
        qd__oom(ctx);
    return q;
}

char *qd__strdup(qd_ctx *ctx, const char *s) {
    size_t n = strlen(s) + 1;
    char *d = qd__malloc(ctx, n);
    if (d)
        memcpy(d, s, n);
    return d;
}

qd_status qd_ctx_status(const qd_ctx *ctx) { QD_ARGS(QD_ERR_ARG, ctx); return ctx->status; }
const char *qd_ctx_message(const qd_ctx *ctx) { QD_ARGS("", ctx); return ctx->diag.message; }
const qd_diag *qd_ctx_diag(const qd_ctx *ctx) { QD_ARGS(NULL, ctx); return &ctx->diag; }
size_t qd_ctx_node_count(const qd_ctx *ctx) { QD_ARGS(0, ctx); return ctx->table_len; }

void qd_ctx_clear_error(qd_ctx *ctx) {
    QD_ARGS(, ctx);
    ctx->status = QD_OK;
    memset(&ctx->diag, 0, sizeof ctx->diag);
}

bool qd__ctx_nomem(const qd_ctx *ctx) { return ctx->status == QD_ERR_NOMEM; }

bool qd__ctx_recover(qd_ctx *ctx) {
    if (ctx->status == QD_ERR_NOMEM)
        return false;
    qd_ctx_clear_error(ctx);
    return true;
}

void qd_ctx_error(qd_ctx *ctx, qd_status st, const char *fmt, ...) {
    QD_ARGS(, ctx && fmt);
    if (ctx->status != QD_OK)
        return; /* the first error is the one that explains the rest */
    ctx->status = st;
    memset(&ctx->diag, 0, sizeof ctx->diag);
    ctx->diag.status = st;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(ctx->diag.message, sizeof ctx->diag.message, fmt, ap);
    va_end(ap);
}

void qd_ctx_error_about(qd_ctx *ctx, qd_subject subject, size_t index, const char *name,
                        qd_reason why, const char *hint) {
    QD_ARGS(, ctx);
    qd_diag *d = &ctx->diag;
    if (ctx->status == QD_OK || (d->subject != QD_SUBJECT_NONE && d->subject != QD_SUBJECT_TEXT))
        return; /* no error to qualify, or it already says what it is about */
    d->subject = subject;
    d->index = index;
    snprintf(d->name, sizeof d->name, "%s", name ? name : "");
    d->reason = why;
    if (hint)
        snprintf(d->hint, sizeof d->hint, "%s", hint);
}

void qd_ctx_error_at(qd_ctx *ctx, const char *text, size_t offset, size_t length) {
    QD_ARGS(, ctx && text);
    qd_diag *d = &ctx->diag;
    if (ctx->status == QD_OK || d->located || !text)
        return;
    size_t n = strlen(text);
    d->located = true;
    d->offset = offset < n ? offset : n;
    d->length = length ? length : 1;
    qd__diag_line_col(text, d->offset, &d->line, &d->col, NULL); /* \n, \r\n or \r */
    if (d->subject == QD_SUBJECT_NONE)
        d->subject = QD_SUBJECT_TEXT;
}

const char *qd_status_str(qd_status st) {
    switch (st) {
    case QD_OK: return "ok";
    case QD_ERR_NOMEM: return "out of memory";
    case QD_ERR_DIVZERO: return "division by zero";
    case QD_ERR_ARG: return "invalid argument";
    case QD_ERR_PARSE: return "syntax error";
    case QD_ERR_NONLINEAR: return "not linear";
    case QD_ERR_UNBOUND: return "symbol without a value";
    case QD_ERR_SINGULAR: return "singular matrix";
    case QD_ERR_NUMERIC: return "numerical failure";
    case QD_ERR_TOOBIG: return "result too large";
    case QD_ERR_UNSUPPORTED: return "not supported here";
    case QD_ERR_IO: return "write error";
    }
    return "unknown status";
}

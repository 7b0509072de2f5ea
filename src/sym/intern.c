/*
 * src/sym/intern.c - the kernel's part of a context: its unique table
 * (hash-consing) and interned names, attached to base's context (base/ctx.h).
 *
 * Every node goes through qd__intern: the node's hash is computed from its
 * kind, its payload and its arguments' hashes (never from addresses, so it is
 * the same in every run), the table is probed, and an existing equal node is
 * returned instead of a new one.  Arguments are already unique, so "equal"
 * compares argument pointers, not subtrees: interning costs O(nargs).
 */
#include "node.h"
#include "../base/args.h"

#include <assert.h>
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

static bool table_grow(qd_ctx *ctx) {
    size_t cap = ctx->sym->table_cap ? ctx->sym->table_cap * 2 : 4096;
    struct qd__slot *t = qd__mem_calloc(ctx->alloc, cap, sizeof *t);
    if (!t)
        return false;
    for (size_t i = 0; i < ctx->sym->table_cap; i++) {
        struct qd__slot slot = ctx->sym->table[i];
        if (!slot.e)
            continue;
        size_t j = (size_t)slot.hash & (cap - 1);
        while (t[j].e)
            j = (j + 1) & (cap - 1);
        t[j] = slot;
    }
    qd__free(ctx->sym->table);
    ctx->sym->table = t;
    ctx->sym->table_cap = cap;
    return true;
}

static bool remember_rational(qd_ctx *ctx, qd_expr *e) {
    if (ctx->sym->nrat == ctx->sym->rat_cap) {
        size_t cap = ctx->sym->rat_cap ? ctx->sym->rat_cap * 2 : 256;
        qd_expr **r = qd__mem_realloc(ctx->alloc, ctx->sym->rationals, cap * sizeof *r);
        if (!r)
            return false;
        ctx->sym->rationals = r;
        ctx->sym->rat_cap = cap;
    }
    ctx->sym->rationals[ctx->sym->nrat++] = e;
    return true;
}

const qd_expr *qd__intern(qd_ctx *ctx, const qd_expr *proto, size_t nargs,
                          const qd_expr *const *args) {
    for (size_t i = 0; i < nargs; i++)
        if (!args[i])
            return NULL;
    if ((ctx->sym->table_len + 1) * 2 > ctx->sym->table_cap && !table_grow(ctx)) {
        qd__oom(ctx);
        return NULL;
    }
    uint64_t h = node_hash(proto, nargs, args);
    size_t i = (size_t)h & (ctx->sym->table_cap - 1);
    for (; ctx->sym->table[i].e; i = (i + 1) & (ctx->sym->table_cap - 1))
        if (ctx->sym->table[i].hash == h && node_equal(ctx->sym->table[i].e, proto, h, nargs, args))
            return ctx->sym->table[i].e;
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
    ctx->sym->table[i] = (struct qd__slot){h, e};
    ctx->sym->table_len++;
    return e;
}

/* Names are interned too, so symbols and functions compare names by pointer. */
const char *qd__intern_name(qd_ctx *ctx, const char *name) {
    if ((ctx->sym->names_len + 1) * 2 > ctx->sym->names_cap) {
        size_t cap = ctx->sym->names_cap ? ctx->sym->names_cap * 2 : 256;
        const char **t = qd__mem_calloc(ctx->alloc, cap, sizeof *t);
        if (!t) {
            qd__oom(ctx);
            return NULL;
        }
        for (size_t i = 0; i < ctx->sym->names_cap; i++) {
            if (!ctx->sym->names[i])
                continue;
            size_t j = (size_t)hash_str(ctx->sym->names[i]) & (cap - 1);
            while (t[j])
                j = (j + 1) & (cap - 1);
            t[j] = ctx->sym->names[i];
        }
        qd__free(ctx->sym->names);
        ctx->sym->names = t;
        ctx->sym->names_cap = cap;
    }
    size_t i = (size_t)hash_str(name) & (ctx->sym->names_cap - 1);
    for (; ctx->sym->names[i]; i = (i + 1) & (ctx->sym->names_cap - 1))
        if (strcmp(ctx->sym->names[i], name) == 0)
            return ctx->sym->names[i];
    size_t n = strlen(name) + 1;
    char *s = qd__alloc(ctx, n);
    if (!s)
        return NULL;
    memcpy(s, name, n);
    ctx->sym->names[i] = s;
    ctx->sym->names_len++;
    return s;
}

const char *qd__find_name(const qd_ctx *ctx, const char *name) {
    if (!ctx->sym->names_cap)
        return NULL;
    size_t i = (size_t)hash_str(name) & (ctx->sym->names_cap - 1);
    for (; ctx->sym->names[i]; i = (i + 1) & (ctx->sym->names_cap - 1))
        if (strcmp(ctx->sym->names[i], name) == 0)
            return ctx->sym->names[i];
    return NULL;
}

/* The kernel's state, released by qd_ctx_free (base/ctx.c) through the
 * context's detach hook. */
static void sym_detach(qd_ctx *ctx) {
    qd__sym_state *S = ctx->sym;
    if (!S)
        return;
    for (size_t i = 0; i < S->nrat; i++)
        mpq_clear(S->rationals[i]->u.q);
    qd__free(S->rationals);
    qd__free(S->table);
    qd__free(S->names);
    qd__ptrmap_free(&S->symtab);
    qd__free(S);
    ctx->sym = NULL;
}

qd_ctx *qd_ctx_new(void) { return qd_ctx_new_with(NULL); }

/* A bare context from base, with the unique table attached. */
qd_ctx *qd_ctx_new_with(const qd_allocator *a) {
    qd__gmp_install();
    qd_ctx *ctx = qd__ctx_create(a);
    if (!ctx)
        return NULL;
    qd__sym_state *S = qd__mem_calloc(a, 1, sizeof *S);
    if (!S) {
        qd_ctx_free(ctx);
        return NULL;
    }
    S->symtab.al = a;
    ctx->sym = S;
    ctx->detach = sym_detach;
    S->zero = qd_int(ctx, 0);
    S->one = qd_int(ctx, 1);
    S->minus_one = qd_int(ctx, -1);
    S->half = qd_rat(ctx, 1, 2);
    S->t = qd_time(ctx);
    if (!S->zero || !S->one || !S->minus_one || !S->half || !S->t) {
        qd_ctx_free(ctx);
        return NULL;
    }
    return ctx;
}

size_t qd_ctx_node_count(const qd_ctx *ctx) { QD_ARGS(0, ctx); return ctx->sym->table_len; }

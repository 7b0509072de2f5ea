/*
 * src/sym/trigsimp.c - trigonometric identities on the terms of a sum.
 *
 * A term of a canonical sum is c*F: a numeric coefficient and a factor list.
 * Two terms combine into one when their factor lists differ only in powers of
 * sin and cos (s = sin(u), k = cos(u); A is everything else):
 *   c A s^a k^b + c A s^(a-2) k^(b+2)  =  c A s^(a-2) k^b          sin^2 + cos^2 = 1
 *   c A s^a k^b - c A s^(a-2) k^b      = -c A s^(a-2) k^(b+2)      1 - sin^2 = cos^2
 *   c A s^a k^b - c A s^a k^(b-2)      = -c A s^(a+2) k^(b-2)      1 - cos^2 = sin^2
 *   c A cos u cos v +- c A sin u sin v =  c A cos(u -+ v)
 *   c A sin u cos v +- c A cos u sin v =  c A sin(u +- v)
 * Each rule turns two terms into one, so it always shortens the sum.  What
 * pairs cannot reach (sin^4 - cos^4, several angles at once) is left to the
 * reduction of even powers modulo sin^2 + cos^2 = 1 (trigeven.c), tried
 * when squares remain after the pairs.
 *
 * Finding partners without comparing all pairs: a term is indexed by a
 * commutative hash of its factor list (a sum of per-factor hashes of (base,
 * exponent)), so the hash of the partner a rule asks for is the term's hash
 * with a few factor hashes swapped.  It is looked up by binary search and
 * verified factor by factor.  Like terms are merged in a canonical sum, so a
 * factor list names at most one term.
 */
#include "node.h"
#include "../base/args.h"

#include <stdlib.h>

#define MAX_ANGLES 16
#define MAX_ROUNDS 64

typedef struct term {
    const qd_expr *coeff;
    const qd_expr *const *fs;
    size_t nf;
    uint64_t h;
    bool dead;
} term;

typedef struct entry {
    uint64_t h;
    size_t idx;
} entry;

/* One rewrite of a factor list: base goes from exponent `from` to `to` (0: absent). */
typedef struct change {
    const qd_expr *base;
    long from, to;
} change;

/* The powers of sin(u) and cos(u) in one term; blocked when either has an
 * exponent that is not an integer (the rules would drop it).  Negative
 * powers take part: s^a k^b + s^(a-2) k^(b+2) = s^(a-2) k^b for all
 * integers a, b, and the result is defined wherever both terms were. */
typedef struct angle {
    const qd_expr *u, *s, *c;
    long a, b;
    bool blocked;
} angle;

typedef struct pass {
    qd_ctx *ctx;
    term *t;
    size_t n;
    entry *index;
    const qd_expr **out; /* the new terms, at most one per combined pair */
    size_t nout;
} pass;

static bool int_exp(const qd_expr *e, long *k) {
    long den;
    return qd_rational_get(e, k, &den) && den == 1;
}

static uint64_t fh_int(const qd_expr *base, long k) {
    return qd__hash_mix(qd__hash_mix(0x51ed270bULL, base->hash), (uint64_t)k);
}

static uint64_t fh_node(const qd_expr *f) {
    long k;
    if (f->kind != QD_POW)
        return fh_int(f, 1);
    if (int_exp(f->args[1], &k))
        return fh_int(f->args[0], k);
    return qd__hash_mix(qd__hash_mix(0x2545f491ULL, f->args[0]->hash), f->args[1]->hash);
}

/* The base of a factor and its exponent when that is an integer (else 0). */
static const qd_expr *factor_base(const qd_expr *f, long *k) {
    *k = 1;
    if (f->kind != QD_POW)
        return f;
    if (!int_exp(f->args[1], k))
        *k = 0;
    return f->args[0];
}

static bool is_trig(const qd_expr *b) {
    return b->kind == QD_FUNC && (b->tag == QD_SIN || b->tag == QD_COS);
}

static int entry_cmp(const void *pa, const void *pb) {
    const entry *a = pa, *b = pb;
    if (a->h != b->h)
        return a->h < b->h ? -1 : 1;
    return (a->idx > b->idx) - (a->idx < b->idx);
}

/* ---- partners ------------------------------------------------------------ */

static const change *find_change(const change *ch, size_t nch, const qd_expr *base) {
    for (size_t i = 0; i < nch; i++)
        if (ch[i].base == base)
            return &ch[i];
    return NULL;
}

static bool in_list(const qd_expr *const *fs, size_t n, const qd_expr *f) {
    for (size_t i = 0; i < n; i++)
        if (fs[i] == f)
            return true;
    return false;
}

/* Is t2's factor list exactly t1's with the changes applied? */
static bool matches(const term *t1, const term *t2, const change *ch, size_t nch) {
    size_t expect = t1->nf;
    for (size_t i = 0; i < nch; i++)
        expect += (ch[i].to != 0) - (ch[i].from != 0);
    if (t2->nf != expect)
        return false;
    for (size_t i = 0; i < t2->nf; i++) {
        long k;
        const qd_expr *b = factor_base(t2->fs[i], &k);
        const change *c = find_change(ch, nch, b);
        if (c ? (k == 0 || k != c->to) : !in_list(t1->fs, t1->nf, t2->fs[i]))
            return false;
    }
    return true;
}

/* The live term whose factors are term i's with the changes applied, or -1. */
static long find_partner(const pass *p, size_t i, const change *ch, size_t nch) {
    uint64_t h = p->t[i].h;
    for (size_t k = 0; k < nch; k++) {
        if (ch[k].from)
            h -= fh_int(ch[k].base, ch[k].from);
        if (ch[k].to)
            h += fh_int(ch[k].base, ch[k].to);
    }
    size_t lo = 0, hi = p->n;
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        if (p->index[mid].h < h)
            lo = mid + 1;
        else
            hi = mid;
    }
    for (; lo < p->n && p->index[lo].h == h; lo++) {
        size_t j = p->index[lo].idx;
        if (j != i && !p->t[j].dead && matches(&p->t[i], &p->t[j], ch, nch))
            return (long)j;
    }
    return -1;
}

/* coeff * (term i's factors with the changes) * extra; kills terms i and j. */
static bool emit(pass *p, size_t i, size_t j, const qd_expr *coeff, const change *ch,
                 size_t nch, const qd_expr *extra) {
    const term *t = &p->t[i];
    const qd_expr **fs = qd__malloc(p->ctx, (t->nf + nch + 2) * sizeof *fs);
    if (!fs) {
        qd__oom(p->ctx);
        return false;
    }
    size_t m = 0;
    fs[m++] = coeff;
    for (size_t k = 0; k < t->nf; k++) {
        long e;
        if (!find_change(ch, nch, factor_base(t->fs[k], &e)))
            fs[m++] = t->fs[k];
    }
    for (size_t k = 0; k < nch; k++)
        if (ch[k].to)
            fs[m++] = qd_powi(p->ctx, ch[k].base, ch[k].to);
    if (extra)
        fs[m++] = extra;
    p->out[p->nout] = qd_mul_n(p->ctx, m, fs);
    qd__free(fs);
    p->t[i].dead = p->t[j].dead = true;
    return p->out[p->nout++] != NULL;
}

/* ---- the rules ----------------------------------------------------------- */

static bool same(const qd_expr *c1, const qd_expr *c2) { return c1 == c2; }

static bool opposite(qd_ctx *ctx, const qd_expr *c1, const qd_expr *c2) {
    return qd_neg(ctx, c1) == c2;
}

/* sin^2 + cos^2 = 1 and its two rearrangements, for one angle of term i. */
static int try_pyth(pass *p, size_t i, const angle *g) {
    const qd_expr *c1 = p->t[i].coeff;
    long a = g->a, b = g->b, j;
    if (a >= 2) {
        change pc[2] = {{g->s, a, a - 2}, {g->c, b, b + 2}};
        if ((j = find_partner(p, i, pc, 2)) >= 0 && same(c1, p->t[j].coeff))
            return emit(p, i, (size_t)j, c1, pc, 1, NULL) ? 1 : -1;
        if ((j = find_partner(p, i, pc, 1)) >= 0 && opposite(p->ctx, c1, p->t[j].coeff))
            return emit(p, i, (size_t)j, p->t[j].coeff, pc, 2, NULL) ? 1 : -1;
    }
    if (b >= 2) {
        change pc[2] = {{g->c, b, b - 2}, {g->s, a, a + 2}};
        if ((j = find_partner(p, i, pc, 1)) >= 0 && opposite(p->ctx, c1, p->t[j].coeff))
            return emit(p, i, (size_t)j, p->t[j].coeff, pc, 2, NULL) ? 1 : -1;
    }
    return 0;
}

/* cos x cos y +- sin x sin y and sin x cos y +- cos x sin y, for angles x != y. */
static int try_sum(pass *p, size_t i, const angle *x, const angle *y) {
    qd_ctx *ctx = p->ctx;
    const qd_expr *c1 = p->t[i].coeff, *extra = NULL;
    long j;
    if (x->b >= 1 && y->b >= 1 && qd_expr_cmp(x->u, y->u) < 0) {
        change pc[4] = {{x->c, x->b, x->b - 1}, {y->c, y->b, y->b - 1},
                        {x->s, x->a, x->a + 1}, {y->s, y->a, y->a + 1}};
        if ((j = find_partner(p, i, pc, 4)) >= 0) {
            if (same(c1, p->t[j].coeff))
                extra = qd_fn(ctx, QD_COS, qd_sub(ctx, x->u, y->u));
            else if (opposite(ctx, c1, p->t[j].coeff))
                extra = qd_fn(ctx, QD_COS, qd_add(ctx, x->u, y->u));
            if (extra)
                return emit(p, i, (size_t)j, c1, pc, 2, extra) ? 1 : -1;
        }
    }
    if (x->a >= 1 && y->b >= 1) {
        change pc[4] = {{x->s, x->a, x->a - 1}, {y->c, y->b, y->b - 1},
                        {x->c, x->b, x->b + 1}, {y->s, y->a, y->a + 1}};
        if ((j = find_partner(p, i, pc, 4)) >= 0) {
            if (same(c1, p->t[j].coeff))
                extra = qd_fn(ctx, QD_SIN, qd_add(ctx, x->u, y->u));
            else if (opposite(ctx, c1, p->t[j].coeff))
                extra = qd_fn(ctx, QD_SIN, qd_sub(ctx, x->u, y->u));
            if (extra)
                return emit(p, i, (size_t)j, c1, pc, 2, extra) ? 1 : -1;
        }
    }
    return 0;
}

/* The angles of a term, with both calls made (so their hashes are known). */
static size_t angles_of(qd_ctx *ctx, const term *t, angle *out) {
    size_t n = 0;
    for (size_t i = 0; i < t->nf; i++) {
        long k;
        const qd_expr *b = factor_base(t->fs[i], &k);
        if (!is_trig(b))
            continue;
        size_t j = 0;
        while (j < n && out[j].u != b->args[0])
            j++;
        if (j == n) {
            if (n == MAX_ANGLES)
                continue;
            const qd_expr *u = b->args[0];
            out[n++] = (angle){u, qd_fn(ctx, QD_SIN, u), qd_fn(ctx, QD_COS, u), 0, 0, false};
            if (!out[j].s || !out[j].c)
                return 0;
        }
        if (k == 0)
            out[j].blocked = true;
        else if (b->tag == QD_SIN && out[j].s == b)
            out[j].a = k;
        else if (b->tag == QD_COS && out[j].c == b)
            out[j].b = k;
    }
    return n;
}

static int try_term(pass *p, size_t i) {
    angle g[MAX_ANGLES];
    size_t n = angles_of(p->ctx, &p->t[i], g), m = 0;
    for (size_t x = 0; x < n; x++)
        if (!g[x].blocked)
            g[m++] = g[x];
    n = m;
    int r = 0;
    for (size_t x = 0; x < n && !r; x++)
        r = try_pyth(p, i, &g[x]);
    for (size_t x = 0; x < n && !r; x++)
        for (size_t y = 0; y < n && !r; y++)
            if (x != y)
                r = try_sum(p, i, &g[x], &g[y]);
    if (r == 0 && qd__ctx_nomem(p->ctx))
        r = -1; /* a rewrite not built for want of memory is no "nothing to rewrite" */
    return r;
}

/* ---- one pass over a sum ------------------------------------------------------ */

/* Every argument is a term, the constant too (no factors: 1 - sin^2 = cos^2). */
static bool load(pass *p, const qd_expr *s) {
    p->n = s->nargs;
    p->t = qd__calloc(p->ctx, p->n, sizeof *p->t);
    p->index = qd__malloc(p->ctx, p->n * sizeof *p->index);
    p->out = qd__malloc(p->ctx, (p->n + 1) * sizeof *p->out);
    if (!p->t || !p->index || !p->out)
        return false;
    for (size_t i = 0; i < p->n; i++) {
        term *t = &p->t[i];
        const qd_expr *x = s->args[i];
        if (qd__is_num(x)) {
            t->coeff = x;
        } else if (x->kind != QD_MUL) {
            t->coeff = p->ctx->sym->one;
            t->fs = &s->args[i];
            t->nf = 1;
        } else {
            size_t off = qd__is_num(x->args[0]) ? 1 : 0;
            t->coeff = off ? x->args[0] : p->ctx->sym->one;
            t->fs = x->args + off;
            t->nf = x->nargs - off;
        }
        for (size_t k = 0; k < t->nf; k++)
            t->h += fh_node(t->fs[k]);
        p->index[i] = (entry){t->h, i};
    }
    qsort(p->index, p->n, sizeof *p->index, entry_cmp);
    return true;
}

/* Combine what pairs one pass finds; *changed tells whether any did. */
static const qd_expr *one_pass(qd_ctx *ctx, const qd_expr *s, bool *changed) {
    pass p = {ctx, NULL, 0, NULL, NULL, 0};
    const qd_expr *r = NULL;
    *changed = false;
    if (!load(&p, s)) {
        qd__oom(ctx);
        goto done;
    }
    for (size_t i = 0; i < p.n; i++)
        if (!p.t[i].dead && try_term(&p, i) < 0)
            goto done;
    if (p.nout == 0) {
        r = s;
        goto done;
    }
    *changed = true;
    for (size_t i = 0; i < p.n; i++)
        if (!p.t[i].dead)
            p.out[p.nout++] = s->args[i];
    r = qd_add_n(ctx, p.nout, p.out);
done:
    qd__free(p.t);
    qd__free(p.index);
    qd__free(p.out);
    return r;
}

static const qd_expr *pair_rounds(qd_ctx *ctx, const qd_expr *s) {
    bool changed = true;
    for (int round = 0; round < MAX_ROUNDS && changed && s && s->kind == QD_ADD; round++)
        s = one_pass(ctx, s, &changed);
    return s;
}

/* Is there a sin^k or cos^k, k >= 2 even or odd, among the terms of s? */
static bool has_square(const qd_expr *s) {
    for (size_t i = 0; s->kind == QD_ADD && i < s->nargs; i++) {
        const qd_expr *t = s->args[i];
        size_t nf = t->kind == QD_MUL ? t->nargs : 1;
        for (size_t j = 0; j < nf; j++) {
            long k;
            if (is_trig(factor_base(t->kind == QD_MUL ? t->args[j] : t, &k)) && k >= 2)
                return true;
        }
    }
    return false;
}

/* The pair rules, and the reduction of even powers (trigeven.c) before them
 * or after: the angle-sum rules take away products that the reduction
 * needs, while the reduction can leave new pairs.  The shortest wins, the
 * pair rules alone on a tie.  When the pair rules leave no square, the
 * reduction is not tried: that keeps the common case (the pendulum's
 * sin^2 + cos^2 pairs) at the cost of the pair rules alone. */
static const qd_expr *simp_sum(qd_ctx *ctx, const qd_expr *s) {
    const qd_expr *best = pair_rounds(ctx, s), *from[2] = {s, best};
    if (!best || !has_square(best))
        return best;
    size_t ops = qd_count_ops(best);
    for (int k = 0; k < 2; k++) {
        if (k == 1 && from[1] == s)
            break;
        const qd_expr *x = qd__trig_even(ctx, from[k]);
        if (x && x != from[k])
            x = pair_rounds(ctx, x);
        if (!x)
            return NULL;
        size_t o = qd_count_ops(x);
        if (o < ops) {
            best = x;
            ops = o;
        }
    }
    return best;
}

/* ---- the walk ------------------------------------------------------------------ */

static const qd_expr *post_trig(qd_ctx *ctx, const qd_expr *e, void *data) {
    (void)data;
    return e->kind == QD_ADD ? simp_sum(ctx, e) : e;
}

const qd_expr *qd_trigsimp(qd_ctx *ctx, const qd_expr *e) {
    QD_ARGS(NULL, ctx && e);
    if (!e)
        return NULL;
    qd__ptrmap memo = QD_PTRMAP_AL(qd__ctx_allocator(ctx));
    const qd_expr *r = qd__map(ctx, e, &memo, post_trig, NULL);
    qd__ptrmap_free(&memo);
    return r;
}

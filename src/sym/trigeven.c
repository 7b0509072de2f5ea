/*
 * src/sym/trigeven.c - even powers of sin(u) and cos(u) reduced modulo
 * sin(u)^2 + cos(u)^2 = 1.
 *
 * For one angle u, a term of a sum is c*K*S^a*C^b with S = sin(u)^2,
 * C = cos(u)^2 and a key K that keeps sin(u) and cos(u) to the first power
 * at most.  The terms of one key make a polynomial P(S, C): with C = 1 - S
 * it is a polynomial in S alone, with S = 1 - C one in C alone.  Two groups
 * have different keys, so no term of one ever merges with a term of
 * another, before or after: each group takes the shortest of its three
 * forms on its own (SHORTEST), ties going to fewer subtractions.
 *
 * That greedy choice, angle by angle, misses identities in several angles
 * at once: the determinant of a product of rotations is 1, yet reducing any
 * one angle of its expansion makes it longer.  Reducing every angle the
 * same way (ELIM_COS for all, or ELIM_SIN for all) gives the normal form
 * modulo the ideal of the sin^2 + cos^2 - 1, which is unique: a polynomial
 * in sines and cosines equal to 1 comes out as 1.  Both normal forms are
 * candidates beside the input; the shortest then gets the greedy pass.
 */
#include "node.h"

#include <stdlib.h>

#define MAX_DEGREE 12 /* a group of higher degree in S and C is left alone */
#define MAX_GROWTH 8

/* A group as it is, or with cos^2 = 1 - sin^2 (ELIM_COS) or sin^2 = 1 - cos^2. */
typedef enum way { KEEP, ELIM_COS, ELIM_SIN } way;

/* A term split for one angle: c * key * sin(u)^(2 al) * cos(u)^(2 be). */
typedef struct eterm {
    const qd_expr *node, *coeff;
    const qd_expr *const *fs, *const *key; /* its factors, and with the squares out */
    size_t nf, nkey;
    const qd_expr **own; /* the key's storage when it is not fs */
    long al, be;
    bool used; /* rewritten with its group */
} eterm;

typedef struct vec {
    const qd_expr **v;
    size_t n, cap;
} vec;

typedef struct angle {
    const qd_expr *s, *c;
} angle;

static bool push(qd_ctx *ctx, vec *v, const qd_expr *e) {
    if (!e)
        return false;
    if (v->n == v->cap) {
        size_t cap = v->cap ? 2 * v->cap : 16;
        const qd_expr **nv = qd__realloc(ctx, v->v, cap * sizeof *nv);
        if (!nv)
            return false;
        v->v = nv;
        v->cap = cap;
    }
    v->v[v->n++] = e;
    return true;
}

/* A positive integer power of sin or cos: its base and exponent. */
static const qd_expr *trig_power(const qd_expr *f, long *k) {
    long den;
    *k = 1;
    if (f->kind == QD_POW) {
        if (!qd_rational_get(f->args[1], k, &den) || den != 1 || *k < 1)
            return NULL;
        f = f->args[0];
    }
    return f->kind == QD_FUNC && (f->tag == QD_SIN || f->tag == QD_COS) ? f : NULL;
}

/* The coefficient and factors of the term *slot (a factor list of one
 * points at the slot itself, which lives as long as the sum). */
static void factors(const qd_expr *const *slot, const qd_expr **coeff, const qd_expr *const **fs,
                    size_t *nf, const qd_expr *one) {
    const qd_expr *t = *slot;
    *coeff = one;
    if (qd__is_num(t)) {
        *coeff = t;
        *fs = NULL;
        *nf = 0;
    } else if (t->kind != QD_MUL) {
        *fs = slot;
        *nf = 1;
    } else {
        size_t off = qd__is_num(t->args[0]) ? 1 : 0;
        if (off)
            *coeff = t->args[0];
        *fs = t->args + off;
        *nf = t->nargs - off;
    }
}

/* The exponents of sin(u) and cos(u) in a factor list; false when one is not
 * a positive integer (the term is then left as it is). */
static bool exponents(const qd_expr *const *fs, size_t nf, const angle *g, long *a, long *b) {
    *a = *b = 0;
    for (size_t i = 0; i < nf; i++) {
        const qd_expr *base = fs[i]->kind == QD_POW ? fs[i]->args[0] : fs[i];
        if (base != g->s && base != g->c)
            continue;
        long k;
        if (!trig_power(fs[i], &k))
            return false;
        *(base == g->s ? a : b) = k;
    }
    return true;
}

static bool split(qd_ctx *ctx, const qd_expr *const *slot, const angle *g, eterm *et) {
    const qd_expr *const *fs;
    size_t nf;
    long a, b;
    *et = (eterm){*slot, NULL, NULL, NULL, 0, 0, NULL, 0, 0, false};
    factors(slot, &et->coeff, &fs, &nf, ctx->sym->one);
    et->key = et->fs = fs;
    et->nkey = et->nf = nf;
    if (!exponents(fs, nf, g, &a, &b) || (a < 2 && b < 2))
        return true;
    et->al = a / 2;
    et->be = b / 2;
    if (!(et->own = qd__malloc(ctx, nf * sizeof *et->own)))
        return false;
    size_t m = 0;
    for (size_t i = 0; i < nf; i++) {
        const qd_expr *base = fs[i]->kind == QD_POW ? fs[i]->args[0] : fs[i];
        long k = base == g->s ? a : base == g->c ? b : 0;
        if (k == 0)
            et->own[m++] = fs[i];
        else if (k % 2)
            et->own[m++] = base; /* the factor list stays sorted: one base, one place */
    }
    et->key = et->own;
    et->nkey = m;
    return true;
}

static int by_key(const void *pa, const void *pb) {
    const eterm *a = *(const eterm *const *)pa, *b = *(const eterm *const *)pb;
    int c = qd__seq_cmp(a->key, a->nkey, b->key, b->nkey);
    return c ? c : (a > b) - (a < b);
}

static long binom(long n, long k) {
    long r = 1;
    for (long i = 1; i <= k; i++)
        r = r * (n - k + i) / i;
    return r;
}

/* The group's polynomial with the other square eliminated, p[0..deg], in
 * S = sin^2 (in_sin) or in C = cos^2. */
static bool poly_form(qd_ctx *ctx, eterm *const *g, size_t n, bool in_sin, const qd_expr **p,
                      long deg) {
    for (long d = 0; d <= deg; d++)
        p[d] = ctx->sym->zero;
    for (size_t i = 0; i < n; i++) {
        long keep = in_sin ? g[i]->al : g[i]->be, drop = in_sin ? g[i]->be : g[i]->al;
        for (long j = 0; j <= drop; j++) {
            const qd_expr *c = qd_int(ctx, (j % 2 ? -1 : 1) * binom(drop, j));
            c = c ? qd__number_mul(ctx, g[i]->coeff, c) : NULL;
            if (!c || !(p[keep + j] = qd__number_add(ctx, p[keep + j], c)))
                return false;
        }
    }
    return true;
}

/* The terms of a group in one form (KEEP, ELIM_COS or ELIM_SIN) appended to out. */
static bool form_terms(qd_ctx *ctx, eterm *const *g, size_t n, way w, const angle *a,
                       long deg, vec *out) {
    if (w == KEEP) {
        for (size_t i = 0; i < n; i++)
            if (!push(ctx, out, g[i]->node))
                return false;
        return true;
    }
    const qd_expr *p[MAX_DEGREE + 1];
    const qd_expr **fs = qd__malloc(ctx, (g[0]->nkey + 2) * sizeof *fs);
    bool ok = fs && poly_form(ctx, g, n, w == ELIM_COS, p, deg);
    for (long d = 0; ok && d <= deg; d++) {
        if (qd_is_zero(p[d]))
            continue;
        fs[0] = p[d];
        for (size_t i = 0; i < g[0]->nkey; i++)
            fs[i + 1] = g[0]->key[i];
        fs[g[0]->nkey + 1] = qd_powi(ctx, w == ELIM_COS ? a->s : a->c, 2 * d);
        ok = fs[g[0]->nkey + 1] && push(ctx, out, qd_mul_n(ctx, g[0]->nkey + 2, fs));
    }
    qd__free(fs);
    return ok;
}

/* Shorter, and on a tie fewer subtractions: 1 + cos^2 rather than 2 - sin^2. */
typedef struct cost {
    size_t ops, neg;
} cost;

static cost cost_of(const qd_expr *e) {
    cost c = {qd_count_ops(e), 0};
    for (size_t i = 0; e->kind == QD_ADD && i < e->nargs; i++) {
        const qd_expr *t = e->args[i], *k = t->kind == QD_MUL ? t->args[0] : t;
        c.neg += qd__is_num(k) && qd_number_sign(k) < 0;
    }
    return c;
}

static bool cheaper(cost a, cost b) {
    return a.ops < b.ops || (a.ops == b.ops && a.neg < b.neg);
}

static cost form_cost(qd_ctx *ctx, eterm *const *g, size_t n, way w, const angle *a, long deg,
                      bool *ok) {
    vec v = {NULL, 0, 0};
    const qd_expr *s = NULL;
    if (form_terms(ctx, g, n, w, a, deg, &v))
        s = v.n ? qd_add_n(ctx, v.n, v.v) : ctx->sym->zero;
    qd__free(v.v);
    *ok = *ok && s;
    return s ? cost_of(s) : (cost){0, 0};
}

/* The shortest form of a group (KEEP on a tie with the terms as they are). */
static way choose(qd_ctx *ctx, eterm *const *g, size_t n, const angle *a, long deg, bool *ok) {
    if (n < 2 || deg > MAX_DEGREE)
        return KEEP; /* one term never gets shorter */
    cost o = form_cost(ctx, g, n, KEEP, a, deg, ok);
    cost os = form_cost(ctx, g, n, ELIM_COS, a, deg, ok);
    cost oc = form_cost(ctx, g, n, ELIM_SIN, a, deg, ok);
    if (cheaper(os, o) && !cheaper(oc, os))
        return ELIM_COS;
    return cheaper(oc, o) ? ELIM_SIN : KEEP;
}

static bool same_key(const eterm *a, const eterm *b) {
    return !qd__seq_cmp(a->key, a->nkey, b->key, b->nkey);
}

/* The term whose own factors are exactly e's key (no squares of the angle:
 * a = b = 0 in the group), by binary search: a canonical sum is sorted by
 * its terms' factor lists, the constant first. */
static eterm *find_plain(const qd_expr *sum, eterm *t, const eterm *e) {
    size_t lo = qd__is_num(sum->args[0]) ? 1 : 0, hi = sum->nargs;
    if (e->nkey == 0)
        return lo ? &t[0] : NULL;
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        int c = qd__seq_cmp(t[mid].fs, t[mid].nf, e->key, e->nkey);
        if (c == 0)
            return t[mid].al || t[mid].be ? NULL : &t[mid];
        if (c < 0)
            lo = mid + 1;
        else
            hi = mid;
    }
    return NULL;
}

/* The groups of the terms with squares, act[0..nact) sorted by key, each in
 * its shortest form, appended to out; their terms are marked used. */
static bool rewrite_groups(qd_ctx *ctx, const qd_expr *sum, eterm *t, eterm **act, size_t nact,
                           const angle *a, vec *out, bool *changed) {
    eterm **grp = qd__malloc(ctx, (nact + 1) * sizeof *grp);
    bool ok = grp != NULL;
    for (size_t i = 0, j; ok && i < nact; i = j) {
        long deg = 0;
        size_t m = 0;
        for (j = i; j < nact && same_key(act[i], act[j]); j++) {
            grp[m++] = act[j];
            if (act[j]->al + act[j]->be > deg)
                deg = act[j]->al + act[j]->be;
        }
        eterm *plain = find_plain(sum, t, act[i]);
        if (plain)
            grp[m++] = plain;
        way f = choose(ctx, grp, m, a, deg, &ok);
        if (!ok || f == KEEP)
            continue;
        *changed = true;
        for (size_t k = 0; k < m; k++)
            grp[k]->used = true;
        ok = form_terms(ctx, grp, m, f, a, deg, out);
    }
    qd__free(grp);
    return ok;
}

/* The sum with each group of angle a in its shortest form; the sum itself
 * when nothing changes, NULL on error. */
static const qd_expr *reduce_angle(qd_ctx *ctx, const qd_expr *sum, const angle *a) {
    if (sum->kind != QD_ADD)
        return sum;
    size_t n = sum->nargs, nact = 0;
    eterm *t = qd__calloc(ctx, n, sizeof *t);
    eterm **act = qd__malloc(ctx, n * sizeof *act);
    vec out = {NULL, 0, 0};
    bool ok = t && act, changed = false;
    for (size_t i = 0; ok && i < n; i++) {
        ok = split(ctx, &sum->args[i], a, &t[i]);
        if (t[i].al || t[i].be)
            act[nact++] = &t[i];
    }
    if (ok && nact) {
        qsort(act, nact, sizeof *act, by_key);
        ok = rewrite_groups(ctx, sum, t, act, nact, a, &out, &changed);
    }
    for (size_t i = 0; ok && changed && i < n; i++)
        if (!t[i].used)
            ok = push(ctx, &out, t[i].node);
    const qd_expr *r = !ok        ? NULL
                       : !changed ? sum
                       : out.n    ? qd_add_n(ctx, out.n, out.v)
                                  : ctx->sym->zero;
    if (!ok && ctx->status == QD_OK)
        qd__oom(ctx);
    for (size_t i = 0; t && i < n; i++)
        qd__free(t[i].own);
    qd__free(t);
    qd__free(act);
    qd__free(out.v);
    return r;
}

/* The angles with an even power of their sine or cosine somewhere in sum. */
static bool collect_angles(qd_ctx *ctx, const qd_expr *sum, angle **out, size_t *n) {
    size_t cap = 0;
    *out = NULL;
    *n = 0;
    for (size_t i = 0; i < sum->nargs; i++) {
        const qd_expr *t = sum->args[i];
        const qd_expr *const *fs = t->kind == QD_MUL ? t->args : &sum->args[i];
        size_t nf = t->kind == QD_MUL ? t->nargs : 1;
        for (size_t j = 0; j < nf; j++) {
            long k;
            const qd_expr *b = trig_power(fs[j], &k), *u = b ? b->args[0] : NULL;
            size_t m = 0;
            while (u && m < *n && (*out)[m].s->args[0] != u)
                m++;
            if (!u || k < 2 || m < *n)
                continue;
            if (*n == cap) {
                cap = cap ? 2 * cap : 4;
                angle *na = qd__realloc(ctx, *out, cap * sizeof *na);
                if (!na)
                    return false;
                *out = na;
            }
            (*out)[(*n)++] = (angle){qd_fn(ctx, QD_SIN, u), qd_fn(ctx, QD_COS, u)};
            if (!(*out)[*n - 1].s || !(*out)[*n - 1].c)
                return false;
        }
    }
    return true;
}

/* ---- normal forms ------------------------------------------------------------ */

/* One square to eliminate in a term: sin(u)^a cos(u)^b becomes
 * keep^(a or b) * (1 - other^2)^drop * other^(rest). */
typedef struct elim {
    const qd_expr *keep, *drop_base;
    long keep_exp, drop, rest;
} elim;

/* The squares term t has to lose (one elim per angle), at most nf of them. */
static size_t squares(const qd_expr *const *fs, size_t nf, const angle *g, size_t ng, way w,
                      elim *e) {
    size_t ne = 0;
    for (size_t i = 0; i < nf; i++) {
        const qd_expr *base = fs[i]->kind == QD_POW ? fs[i]->args[0] : fs[i];
        if (base->kind != QD_FUNC || (base->tag != QD_SIN && base->tag != QD_COS))
            continue;
        size_t j = 0;
        while (j < ng && g[j].s != base && g[j].c != base)
            j++;
        if (j == ng)
            continue; /* an angle with no square anywhere: g[j] would be past the end */
        size_t seen = 0;
        while (seen < ne && e[seen].keep != g[j].s && e[seen].keep != g[j].c)
            seen++;
        long a, b;
        if (seen == ne && exponents(fs, nf, &g[j], &a, &b) &&
            (w == ELIM_COS ? b : a) >= 2)
            e[ne++] = w == ELIM_COS ? (elim){g[j].s, g[j].c, a, b / 2, b % 2}
                                    : (elim){g[j].c, g[j].s, b, a / 2, a % 2};
    }
    return ne;
}

/* The term *slot with every square of one function eliminated, its terms
 * appended to out: the product over its angles of the binomial expansions. */
static bool nf_term(qd_ctx *ctx, const qd_expr *const *slot, const angle *g, size_t ng, way w,
                    vec *out) {
    const qd_expr *coeff, *const *fs;
    size_t nf, ne, combos = 1;
    factors(slot, &coeff, &fs, &nf, ctx->sym->one);
    elim *e = qd__malloc(ctx, (nf ? nf : 1) * sizeof *e);
    if (!e)
        return false;
    ne = squares(fs, nf, g, ng, w, e);
    for (size_t i = 0; i < ne; i++)
        combos *= (size_t)e[i].drop + 1;
    if (ne == 0 || combos > 4096) {
        qd__free(e);
        return push(ctx, out, *slot);
    }
    const qd_expr **buf = qd__malloc(ctx, (nf + 2 * ne + 1) * sizeof *buf);
    bool ok = buf != NULL;
    for (size_t k = 0; ok && k < combos; k++) {
        size_t m = 1, r = k;
        const qd_expr *c = coeff;
        for (size_t i = 0; i < nf; i++) {
            const qd_expr *base = fs[i]->kind == QD_POW ? fs[i]->args[0] : fs[i];
            size_t j = 0;
            while (j < ne && base != e[j].keep && base != e[j].drop_base)
                j++;
            if (j == ne)
                buf[m++] = fs[i];
        }
        for (size_t i = 0; ok && i < ne; r /= (size_t)e[i].drop + 1, i++) {
            long j = (long)(r % ((size_t)e[i].drop + 1));
            const qd_expr *bj = qd_int(ctx, (j % 2 ? -1 : 1) * binom(e[i].drop, j));
            c = bj ? qd__number_mul(ctx, c, bj) : NULL;
            buf[m++] = qd_powi(ctx, e[i].keep, e[i].keep_exp + 2 * j);
            buf[m++] = qd_powi(ctx, e[i].drop_base, e[i].rest);
            ok = c && buf[m - 1] && buf[m - 2];
        }
        buf[0] = c;
        ok = ok && push(ctx, out, qd_mul_n(ctx, m, buf));
    }
    qd__free(e);
    qd__free(buf);
    return ok;
}

/* The sum with every square of one function (w) eliminated in all angles:
 * the normal form, unique for the value.  The sum itself when that grows
 * past MAX_GROWTH times its terms (it is not going to be the shortest). */
static const qd_expr *normal_form(qd_ctx *ctx, const qd_expr *sum, const angle *g, size_t ng,
                                  way w) {
    vec out = {NULL, 0, 0};
    bool ok = true;
    for (size_t i = 0; ok && i < sum->nargs && out.n <= MAX_GROWTH * sum->nargs + 64; i++)
        ok = nf_term(ctx, &sum->args[i], g, ng, w, &out);
    const qd_expr *r = !ok                                  ? NULL
                       : out.n > MAX_GROWTH * sum->nargs + 64 ? sum
                                                              : qd_add_n(ctx, out.n, out.v);
    qd__free(out.v);
    return r;
}

/* x when it is cheaper than *best. */
static void keep_cheaper(const qd_expr *x, const qd_expr **best, cost *c) {
    cost cx = cost_of(x);
    if (cheaper(cx, *c)) {
        *best = x;
        *c = cx;
    }
}

const qd_expr *qd__trig_even(qd_ctx *ctx, const qd_expr *sum) {
    angle *g;
    size_t n;
    if (sum->kind != QD_ADD)
        return sum;
    if (!collect_angles(ctx, sum, &g, &n)) {
        qd__free(g);
        if (ctx->status == QD_OK)
            qd__oom(ctx);
        return NULL;
    }
    const qd_expr *best = sum;
    cost c = n ? cost_of(sum) : (cost){0, 0};
    for (way w = ELIM_COS; best && n && w <= ELIM_SIN; w++) {
        const qd_expr *x = normal_form(ctx, sum, g, n, w);
        if (!x)
            best = NULL;
        else if (x != sum)
            keep_cheaper(x, &best, &c);
    }
    for (size_t i = 0; best && i < n; i++) {
        const qd_expr *x = reduce_angle(ctx, best, &g[i]);
        if (!x)
            best = NULL;
        else if (x != best)
            keep_cheaper(x, &best, &c);
    }
    qd__free(g);
    return best;
}

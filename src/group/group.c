/* src/group/group.c - a finite group from its multiplication table: the
 * checks that make the table a group, inverses, generators and conjugacy
 * classes (Desloge App. 28; seed-desloge-D.md App. 28).
 *
 * Associativity is checked by Light's test: the elements g with
 * (x y) g = x (y g) for all x, y are closed under the product (if a and b
 * are, (x y)(a b) = ((x y) a) b = (x (y a)) b = x ((y a) b) = x (y (a b))),
 * so checking the generators alone checks the whole table.  A group of order
 * n has a generating set of at most log2 n elements (each one added outside
 * the subgroup so far at least doubles it), so the check costs O(n^2 log n)
 * instead of O(n^3): 4.4e7 products for the dihedral group of a ring of 1000
 * masses. */
#include "group.h"
#include "../base/mem.h"

#include <stdint.h>
#include <string.h>

void qd__group_free(qd__group *g) {
    if (!g)
        return;
    qd__free(g->mul);
    qd__free(g->inv);
    qd__free(g->class_of);
    qd__free(g->class_size);
    qd__free(g->class_rep);
    memset(g, 0, sizeof *g);
}

static size_t mul(const qd__group *g, size_t a, size_t b) {
    return g->mul[a * g->order + b];
}

static qd_status twice(qd_ctx *ctx, size_t elem, const char *where, size_t a) {
    qd_ctx_error(ctx, QD_ERR_ARG, "not a group: element %zu appears twice in the %s of %zu", elem, where, a);
    return QD_ERR_ARG;
}

/* Every row and every column a permutation of the elements: closure and
 * unique solutions of a x = b and x a = b.  The columns are checked while the
 * rows are read, in a bit per (column, element): walking the columns of the
 * table itself missed the cache on every entry. */
static qd_status check_latin(qd_ctx *ctx, const qd__group *g) {
    size_t n = g->order, words = (n * n + 63) / 64;
    for (size_t i = 0; i < n * n; i++)
        if (g->mul[i] >= n) {
            qd_ctx_error(ctx, QD_ERR_ARG, "not a group: %zu*%zu = %zu is outside the %zu elements",
                         i / n, i % n, g->mul[i], n);
            return QD_ERR_ARG;
        }
    size_t *row = qd__malloc(ctx, n * sizeof *row);
    uint64_t *col = qd__calloc(ctx, words, sizeof *col);
    qd_status st = row && col ? QD_OK : QD_ERR_NOMEM;
    for (size_t i = 0; i < n && st == QD_OK; i++)
        row[i] = SIZE_MAX;
    for (size_t a = 0; a < n && st == QD_OK; a++)
        for (size_t b = 0; b < n; b++) {
            size_t r = mul(g, a, b), bit = b * n + r;
            if (row[r] == a) {
                st = twice(ctx, r, "row", a);
                break;
            }
            if (col[bit / 64] >> (bit % 64) & 1) {
                st = twice(ctx, r, "column", b);
                break;
            }
            row[r] = a;
            col[bit / 64] |= (uint64_t)1 << (bit % 64);
        }
    qd__free(col);
    qd__free(row);
    return st;
}

/* In a Latin square an identity is e with e*b = b and b*e = b for all b;
 * row e fixes element 0 only if e is a left identity, so test that first. */
static qd_status find_identity(qd_ctx *ctx, qd__group *g) {
    size_t n = g->order;
    for (size_t e = 0; e < n; e++) {
        if (mul(g, e, 0) != 0)
            continue;
        bool ok = true;
        for (size_t b = 0; b < n && ok; b++)
            ok = mul(g, e, b) == b && mul(g, b, e) == b;
        if (ok) {
            g->identity = e;
            return QD_OK;
        }
    }
    qd_ctx_error(ctx, QD_ERR_ARG, "not a group: no element of the %zu-element table is an identity", n);
    return QD_ERR_ARG;
}

static qd_status find_inverses(qd_ctx *ctx, qd__group *g) {
    size_t n = g->order, e = g->identity;
    for (size_t a = 0; a < n; a++) {
        size_t b = 0;
        while (mul(g, a, b) != e)
            b++;  /* a Latin row holds e exactly once */
        if (mul(g, b, a) != e) {
            qd_ctx_error(ctx, QD_ERR_ARG, "not a group: %zu*%zu is the identity but %zu*%zu is not", a, b,
                         b, a);
            return QD_ERR_ARG;
        }
        g->inv[a] = b;
    }
    return QD_OK;
}

/* The elements reached from the identity by right products with gens[0..k):
 * reach[x] true, returns how many. queue holds n entries. */
static size_t span(const qd__group *g, const size_t *gens, size_t k, bool *reach, size_t *queue) {
    size_t n = g->order, head = 0, tail = 0;
    memset(reach, 0, n * sizeof *reach);
    reach[g->identity] = true;
    queue[tail++] = g->identity;
    while (head < tail) {
        size_t x = queue[head++];
        for (size_t i = 0; i < k; i++) {
            size_t y = mul(g, x, gens[i]);
            if (!reach[y]) {
                reach[y] = true;
                queue[tail++] = y;
            }
        }
    }
    return tail;
}

size_t qd__group_generators(qd_ctx *ctx, const qd__group *g, size_t *gens) {
    size_t n = g->order, k = 0;
    bool *reach = qd__malloc(ctx, n * sizeof *reach);
    size_t *queue = qd__malloc(ctx, n * sizeof *queue);
    if (!reach || !queue) {
        k = SIZE_MAX;
        goto free_scratch;
    }
    size_t got = span(g, gens, 0, reach, queue);
    for (size_t a = 0; a < n && got < n; a++)
        if (!reach[a]) {
            gens[k++] = a;
            got = span(g, gens, k, reach, queue);
        }
free_scratch:
    qd__free(queue);
    qd__free(reach);
    return k;
}

/* Light's test on the generators (see the head of the file).  With
 * col[y] = y c kept apart, both sides read one row and one small array: the
 * table itself is read row by row (a column walk missed the cache for each
 * of the 4e6 entries of D_1000's). */
static qd_status check_associative(qd_ctx *ctx, const qd__group *g, const size_t *gens, size_t k) {
    size_t n = g->order, *col = qd__malloc(ctx, n * sizeof *col);
    if (!col)
        return QD_ERR_NOMEM;
    qd_status st = QD_OK;
    for (size_t i = 0; i < k && st == QD_OK; i++) {
        size_t c = gens[i];
        for (size_t y = 0; y < n; y++)
            col[y] = mul(g, y, c);
        for (size_t x = 0; x < n && st == QD_OK; x++) {
            const size_t *row = g->mul + x * n;
            for (size_t y = 0; y < n; y++)
                if (col[row[y]] != row[col[y]]) {
                    qd_ctx_error(ctx, QD_ERR_ARG,
                                 "not a group: the table is not associative, (%zu*%zu)*%zu != %zu*(%zu*%zu)",
                                 x, y, c, x, y, c);
                    st = QD_ERR_ARG;
                    break;
                }
        }
    }
    qd__free(col);
    return st;
}

/* Conjugacy classes as orbits of x -> s x s^-1 over the generators s (an
 * orbit under the generators is one under the group); the identity's class
 * is found first, so it is class 0. */
static qd_status find_classes(qd_ctx *ctx, qd__group *g, const size_t *gens, size_t k) {
    size_t n = g->order, *queue = qd__malloc(ctx, n * sizeof *queue);
    if (!queue)
        return QD_ERR_NOMEM;
    for (size_t x = 0; x < n; x++)
        g->class_of[x] = SIZE_MAX;
    g->nclass = 0;
    for (size_t step = 0; step <= n; step++) {
        size_t x = step == 0 ? g->identity : step - 1;
        if (g->class_of[x] != SIZE_MAX)
            continue;
        size_t c = g->nclass++, head = 0, tail = 0;
        g->class_rep[c] = x;
        g->class_of[x] = c;
        queue[tail++] = x;
        while (head < tail) {
            size_t y = queue[head++];
            for (size_t i = 0; i < k; i++) {
                size_t z = mul(g, mul(g, gens[i], y), g->inv[gens[i]]);
                if (g->class_of[z] == SIZE_MAX) {
                    g->class_of[z] = c;
                    queue[tail++] = z;
                }
            }
        }
        g->class_size[c] = tail;
    }
    qd__free(queue);
    return QD_OK;
}

static qd_status alloc_group(qd_ctx *ctx, size_t order, qd__group *g) {
    g->order = order;
    g->mul = qd__malloc(ctx, order * order * sizeof *g->mul);
    g->inv = qd__malloc(ctx, order * sizeof *g->inv);
    g->class_of = qd__malloc(ctx, order * sizeof *g->class_of);
    g->class_size = qd__malloc(ctx, order * sizeof *g->class_size);
    g->class_rep = qd__malloc(ctx, order * sizeof *g->class_rep);
    if (!g->mul || !g->inv || !g->class_of || !g->class_size || !g->class_rep)
        return QD_ERR_NOMEM;
    return QD_OK;
}

qd_status qd__group_from_table(qd_ctx *ctx, size_t order, const size_t *table, qd__group *g) {
    if (!g)
        return QD_ERR_ARG;
    memset(g, 0, sizeof *g);
    if (order == 0 || !table) {
        qd_ctx_error(ctx, QD_ERR_ARG, "a group needs at least one element and a multiplication table");
        return QD_ERR_ARG;
    }
    if (order > QD__GROUP_MAX_ORDER) {
        qd_ctx_error(ctx, QD_ERR_TOOBIG, "a group of order %zu is above the limit of %d", order,
                     QD__GROUP_MAX_ORDER);
        return QD_ERR_TOOBIG;
    }
    size_t *scratch = NULL, k = 0;
    qd_status st = alloc_group(ctx, order, g);
    if (st == QD_OK) {
        memcpy(g->mul, table, order * order * sizeof *table);
        scratch = qd__malloc(ctx, order * sizeof *scratch);
        st = scratch ? check_latin(ctx, g) : QD_ERR_NOMEM;
    }
    if (st == QD_OK)
        st = find_identity(ctx, g);
    if (st == QD_OK)
        st = find_inverses(ctx, g);
    if (st == QD_OK) {
        k = qd__group_generators(ctx, g, scratch);
        st = k == SIZE_MAX ? QD_ERR_NOMEM : check_associative(ctx, g, scratch, k);
    }
    if (st == QD_OK)
        st = find_classes(ctx, g, scratch, k);
    qd__free(scratch);
    if (st != QD_OK)
        qd__group_free(g);
    return st;
}

/* src/group/product.c - the character table of G = H x C2 from that of H.
 *
 * When a central involution z lies outside a subgroup H of index 2, G is the
 * direct product H x {e, z} and its irreducible characters are those of H
 * times the two characters of C2: chi(h z^e) = chi_H(h) (+-1)^e.  H is the
 * kernel of a homomorphism phi: G -> {+1, -1} with phi(z) = -1; phi is tried
 * on every sign pattern of the generators (at most 2^10) and extended over
 * the group by phi(x s) = phi(x) phi(s), which fails on a contradiction.
 * This covers the axial point groups Burnside's method would find slow:
 * D_nh = D_n x {E, sigma_h} and C_nh = C_n x {E, sigma_h} for even n, D_nd
 * = D_n x {E, i} for odd n (a ring of 1000 masses moving in space is D1000h,
 * 1006 classes: H = D_1000 has the closed form).  H's table comes from
 * qd__group_characters itself, so H may split again (D2h -> D2 -> C2). */
#include "group.h"
#include "../base/mem.h"

#include <stdint.h>
#include <string.h>

enum { MAX_SIGN_GENERATORS = 10 };

/* phi from the signs of the generators (bit i of mask: gens[i] -> -1), or
 * false if they extend to no homomorphism. queue holds order entries. */
static bool sign_hom(const qd__group *g, const size_t *gens, size_t k, unsigned mask, signed char *phi,
                     size_t *queue) {
    size_t n = g->order, head = 0, tail = 0;
    memset(phi, 0, n * sizeof *phi);
    phi[g->identity] = 1;
    queue[tail++] = g->identity;
    while (head < tail) {
        size_t x = queue[head++];
        for (size_t i = 0; i < k; i++) {
            size_t y = g->mul[x * n + gens[i]];
            signed char v = (signed char)(mask >> i & 1 ? -phi[x] : phi[x]);
            if (!phi[y]) {
                phi[y] = v;
                queue[tail++] = y;
            } else if (phi[y] != v) {
                return false;
            }
        }
    }
    return true;
}

/* A central involution z with phi(z) = -1, SIZE_MAX if none. */
static size_t central_involution(const qd__group *g, const signed char *phi) {
    for (size_t c = 1; c < g->nclass; c++) {
        size_t z = g->class_rep[c];
        if (g->class_size[c] == 1 && g->mul[z * g->order + z] == g->identity && phi[z] < 0)
            return z;
    }
    return SIZE_MAX;
}

/* Finds phi and z; false when G is no such product (or has too many
 * generators to try). */
static bool find_factor(qd_ctx *ctx, const qd__group *g, signed char *phi, size_t *z, qd_status *st) {
    size_t n = g->order, *gens = qd__malloc(ctx, n * sizeof *gens), *queue = qd__malloc(ctx, n * sizeof *queue);
    size_t k = gens && queue ? qd__group_generators(ctx, g, gens) : SIZE_MAX;
    bool found = false;
    *st = k == SIZE_MAX ? QD_ERR_NOMEM : QD_OK;
    for (unsigned mask = 1; *st == QD_OK && k <= MAX_SIGN_GENERATORS && mask < 1u << k && !found; mask++)
        if (sign_hom(g, gens, k, mask, phi, queue)) {
            *z = central_involution(g, phi);
            found = *z != SIZE_MAX;
        }
    qd__free(queue);
    qd__free(gens);
    return found;
}

/* H = ker phi as a group of its own: elems[i] its elements, idx the inverse. */
static qd_status kernel_table(qd_ctx *ctx, const qd__group *g, const signed char *phi, size_t *elems,
                              size_t *idx, qd__group *h) {
    size_t n = g->order, m = 0;
    for (size_t x = 0; x < n; x++) {
        idx[x] = phi[x] > 0 ? m : SIZE_MAX;
        if (phi[x] > 0)
            elems[m++] = x;
    }
    size_t *mul = qd__malloc(ctx, m * m * sizeof *mul);
    if (!mul)
        return QD_ERR_NOMEM;
    for (size_t a = 0; a < m; a++)
        for (size_t b = 0; b < m; b++)
            mul[a * m + b] = idx[g->mul[elems[a] * n + elems[b]]];
    qd_status st = qd__group_from_table(ctx, m, mul, h);
    qd__free(mul);
    return st;
}

/* Rows 2i and 2i+1: H's row i times the even and the odd character of C2. */
static void combine(const qd__group *g, const signed char *phi, size_t z, const size_t *idx, const qd__group *h,
                    const qd__chartab *th, qd__chartab *t) {
    size_t nc = g->nclass, hn = th->n;
    for (size_t c = 0; c < nc; c++) {
        size_t x = g->class_rep[c];
        bool odd = phi[x] < 0;
        size_t hc = h->class_of[idx[odd ? g->mul[x * g->order + z] : x]];
        for (size_t i = 0; i < hn; i++)
            for (int s = 0; s < 2; s++) {
                double sign = odd && s ? -1 : 1;
                t->re[(2 * i + (size_t)s) * nc + c] = sign * th->re[i * hn + hc];
                t->im[(2 * i + (size_t)s) * nc + c] = sign * th->im[i * hn + hc];
                t->dim[2 * i + (size_t)s] = th->dim[i];
            }
    }
}

qd_status qd__group_product_table(qd_ctx *ctx, const qd__group *g, qd__chartab *t, bool *done) {
    size_t n = g->order, z = SIZE_MAX;
    *done = false;
    signed char *phi = qd__malloc(ctx, n * sizeof *phi);
    size_t *elems = qd__malloc(ctx, n * sizeof *elems), *idx = qd__malloc(ctx, n * sizeof *idx);
    qd__group h = {0};
    qd__chartab th = {0};
    qd_status st = phi && elems && idx ? QD_OK : QD_ERR_NOMEM;
    if (st == QD_OK && find_factor(ctx, g, phi, &z, &st)) {
        st = kernel_table(ctx, g, phi, elems, idx, &h);
        if (st == QD_OK)
            st = qd__group_characters(ctx, &h, &th);
        if (st == QD_OK && 2 * th.n == g->nclass) {  /* always, for a direct product */
            combine(g, phi, z, idx, &h, &th, t);
            *done = true;
        }
    }
    qd__group_chartab_free(&th);
    qd__group_free(&h);
    qd__free(idx);
    qd__free(elems);
    qd__free(phi);
    return st;
}

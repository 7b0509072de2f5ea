/* src/group/pointgroup.c - the Schoenflies name of a group of 3x3 orthogonal
 * matrices and the Mulliken labels of its irreducible representations.
 *
 * Each matrix is a rotation (det +1) or a rotation times -1 (det -1): the
 * angle and axis of the proper part classify it as the identity, a rotation
 * C_n, the inversion, a mirror (the proper part a half turn about the mirror's
 * normal) or an improper rotation S_n.  The name follows the usual flowchart:
 * two or more C3 axes make a cubic group (I with a C5, O with a C4, else T;
 * h with the inversion, Td with mirrors); otherwise n is the highest order of
 * a rotation, C2 axes perpendicular to the principal axis make D_n (h with a
 * mirror perpendicular to the axis, d with other mirrors), and without them
 * C_nh, C_nv, S_2n or C_n.
 *
 * Labels (F. A. Cotton, Chemical Applications of Group Theory, 3rd ed., ch. 4
 * and App. IIA): A or B by the character of the principal rotation (S_2n in
 * S_2n and D_nd for even n, as in Cotton's tables), E, T, G, H by dimension;
 * subscript 1 or 2 by the character of a C2 perpendicular to the axis (D
 * groups), of sigma_v (C_nv) or of sigma_d (Td), preferring the C2 along x and
 * the mirror containing x when a group has two such classes; in D2 and D2h
 * B1, B2, B3 name the C2 (along z, y, x) with character +1; E_k for principal
 * order 5 or more, from chi(C_n) = 2 cos(2 pi k / n); g/u by the inversion,
 * else ' / '' by sigma_h.  One-dimensional complex characters come in
 * conjugate pairs, labelled E..a and E..b (a: Im chi(C_n) > 0). */
#include "group.h"
#include "../base/mem.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

static const double PI = 3.14159265358979323846;
static const double TOL = 1e-6;

enum kind { IDENT, ROT, INV, MIRROR, IMPROPER };

typedef struct op {
    enum kind kind;
    double angle;    /* of the proper part about axis, in [0, pi] */
    double axis[3];  /* unit; zero for the identity and the inversion */
    size_t order;    /* in the group */
} op;

typedef struct pg {
    char name[16];
    bool cubic, d2;
    size_t n;            /* highest order of a proper rotation */
    double axis[3];      /* principal axis */
    size_t prin, np;     /* element deciding A/B and E_k, and its order; SIZE_MAX: none */
    size_t second;       /* C2', sigma_v or sigma_d: subscripts 1/2 */
    size_t inv, sigh;    /* inversion, sigma_h */
    size_t c2[3];        /* D2 and D2h: the C2 along z, y, x */
    size_t c3, c5;       /* cubic groups: a C3 and a C5 */
} pg;

static double dot(const double *a, const double *b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static bool parallel(const double *a, const double *b) {
    return fabs(fabs(dot(a, b)) - 1) < TOL;
}

static bool perpendicular(const double *a, const double *b) {
    return fabs(dot(a, b)) < TOL;
}

static double det3(const double *R) {
    return R[0] * (R[4] * R[8] - R[5] * R[7]) - R[1] * (R[3] * R[8] - R[5] * R[6]) +
           R[2] * (R[3] * R[7] - R[4] * R[6]);
}

/* Angle and axis of the rotation P: from the antisymmetric part, or near a
 * half turn from P + I = 2 a a^T (its largest column). */
static void rotation_axis(const double *P, op *o) {
    double c = fmax(-1, fmin(1, (P[0] + P[4] + P[8] - 1) / 2));
    o->angle = acos(c);
    memset(o->axis, 0, sizeof o->axis);
    if (o->angle < TOL)
        return;
    double a[3] = {P[7] - P[5], P[2] - P[6], P[3] - P[1]}, len = sqrt(dot(a, a));
    if (len < 1e-3) {
        int j = 0;
        for (int i = 1; i < 3; i++)
            j = P[4 * i] > P[4 * j] ? i : j;
        for (int i = 0; i < 3; i++)
            a[i] = (P[3 * i + j] + (i == j)) / 2;
        len = sqrt(dot(a, a));
    }
    for (int i = 0; i < 3; i++)
        o->axis[i] = a[i] / len;
}

static void classify(const double *R, op *o) {
    double s = det3(R) > 0 ? 1 : -1, P[9];
    for (int i = 0; i < 9; i++)
        P[i] = s * R[i];
    rotation_axis(P, o);
    if (s > 0)
        o->kind = o->angle < TOL ? IDENT : ROT;
    else
        o->kind = o->angle < TOL ? INV : PI - o->angle < TOL ? MIRROR : IMPROPER;
}

/* The turn of element o about the unit axis a, in (-pi, pi]: for an improper
 * element R = sigma_h C(phi) = -C(phi + pi), so phi is the proper part's
 * angle less pi. */
static double turn_about(const op *o, const double *a) {
    double t = dot(o->axis, a) < 0 ? -o->angle : o->angle;
    if (o->kind == IMPROPER || o->kind == MIRROR)
        t -= PI;
    while (t <= -PI)
        t += 2 * PI;
    while (t > PI)
        t -= 2 * PI;
    return t;
}

static size_t gcd(size_t a, size_t b) {
    while (b) {
        size_t r = a % b;
        a = b;
        b = r;
    }
    return a;
}

/* The orders of all elements: walking the powers of a (pw holds them) also
 * gives ord(a^j) = ord(a) / gcd(j, ord(a)), so each cyclic subgroup is
 * walked once (a ring of 1000 masses: O(n), not O(n^2)). */
static void element_orders(const qd__group *g, op *ops, size_t *pw) {
    size_t n = g->order;
    for (size_t a = 0; a < n; a++)
        ops[a].order = 0;
    for (size_t a = 0; a < n; a++) {
        if (ops[a].order)
            continue;
        size_t k = 0;
        for (size_t x = a; x != g->identity; x = g->mul[x * n + a])
            pw[k++] = x;
        pw[k] = g->identity;
        k++;
        for (size_t j = 1; j <= k; j++)
            if (!ops[pw[j - 1]].order)
                ops[pw[j - 1]].order = k / gcd(j, k);
    }
}

/* R orthogonal, a faithful representation: R_a R_s = R_(a s) for the
 * generators s (enough, as products of generators reach every element), and
 * only the identity mapped to I. */
static bool is_orthogonal(const double *R) {
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            if (fabs(R[3 * i] * R[3 * j] + R[3 * i + 1] * R[3 * j + 1] + R[3 * i + 2] * R[3 * j + 2] - (i == j)) >
                TOL)
                return false;
    return true;
}

static bool same_product(const double *A, const double *B, const double *C) {
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            if (fabs(A[3 * i] * B[j] + A[3 * i + 1] * B[3 + j] + A[3 * i + 2] * B[6 + j] - C[3 * i + j]) > TOL)
                return false;
    return true;
}

static qd_status represents(qd_ctx *ctx, const qd__group *g, const double *R, const op *ops, bool *ok) {
    size_t n = g->order, *gens = qd__malloc(ctx, n * sizeof *gens);
    if (!gens)
        return QD_ERR_NOMEM;
    size_t k = qd__group_generators(ctx, g, gens);
    *ok = k != SIZE_MAX;
    for (size_t a = 0; a < n && *ok; a++) {
        *ok = is_orthogonal(R + 9 * a) && (ops[a].kind == IDENT) == (a == g->identity);
        for (size_t i = 0; i < k && *ok; i++)
            *ok = same_product(R + 9 * a, R + 9 * gens[i], R + 9 * g->mul[a * n + gens[i]]);
    }
    qd__free(gens);
    return k == SIZE_MAX ? QD_ERR_NOMEM : QD_OK;
}

/* The first element of the given kind and order (0: any) whose axis is
 * parallel (par) or perpendicular (!par) to a; a NULL: any axis. */
static size_t find_op(const qd__group *g, const op *ops, enum kind kind, size_t order, const double *a,
                      bool par) {
    for (size_t e = 0; e < g->order; e++)
        if (ops[e].kind == kind && (!order || ops[e].order == order) &&
            (!a || (par ? parallel(ops[e].axis, a) : perpendicular(ops[e].axis, a))))
            return e;
    return SIZE_MAX;
}

/* The element about a turning by +2 pi / order (improper when improper). */
static size_t find_turn(const qd__group *g, const op *ops, const double *a, size_t order, bool improper) {
    for (size_t e = 0; e < g->order; e++)
        if (ops[e].kind == (improper ? IMPROPER : ROT) && ops[e].order == order && parallel(ops[e].axis, a) &&
            fabs(remainder(turn_about(&ops[e], a) - 2 * PI / (double)order, 2 * PI)) < TOL)  /* +-pi alike */
            return e;
    return SIZE_MAX;
}

static size_t count_ops(const qd__group *g, const op *ops, enum kind kind, size_t order) {
    size_t k = 0;
    for (size_t e = 0; e < g->order; e++)
        k += ops[e].kind == kind && (!order || ops[e].order == order);
    return k;
}

/* Preferred among several: the element whose axis (a mirror's normal) is
 * closest to the unit vector u, or for mirrors with want_perp the one whose
 * normal is perpendicular to u (the plane contains u). */
static size_t prefer(const qd__group *g, const op *ops, enum kind kind, size_t order, const double *axis,
                     const double *u, bool want_perp) {
    size_t best = SIZE_MAX;
    double score = -1;
    for (size_t e = 0; e < g->order; e++) {
        if (ops[e].kind != kind || (order && ops[e].order != order) ||
            (axis && !perpendicular(ops[e].axis, axis)))
            continue;
        double d = fabs(dot(ops[e].axis, u)), s = want_perp ? 1 - d : d;
        if (s > score + TOL) {
            score = s;
            best = e;
        }
    }
    return best;
}

/* Orders and counts are below QD__GROUP_MAX_ORDER: the mask only tells the
 * compiler so, for the fixed-size names and labels. */
static unsigned small(size_t k) {
    return (unsigned)(k & 0xFFFF);
}

static void orient(double *a) {
    int j = 0;
    for (int i = 1; i < 3; i++)
        j = fabs(a[i]) > fabs(a[j]) + TOL ? i : j;
    if (a[j] < 0)
        for (int i = 0; i < 3; i++)
            a[i] = -a[i];
}

static const double X[3] = {1, 0, 0}, Y[3] = {0, 1, 0}, Z[3] = {0, 0, 1};

static void cubic_group(const qd__group *g, const op *ops, pg *p) {
    bool inv = p->inv != SIZE_MAX;
    p->cubic = true;
    if (count_ops(g, ops, ROT, 5))
        snprintf(p->name, sizeof p->name, "%s", inv ? "Ih" : "I");
    else if (count_ops(g, ops, ROT, 4))
        snprintf(p->name, sizeof p->name, "%s", inv ? "Oh" : "O");
    else
        snprintf(p->name, sizeof p->name, "%s", inv ? "Th" : count_ops(g, ops, MIRROR, 0) ? "Td" : "T");
    p->c3 = find_op(g, ops, ROT, 3, NULL, true);
    for (size_t e = 0; e < g->order && p->c5 == SIZE_MAX; e++)
        if (ops[e].kind == ROT && fabs(ops[e].angle - 2 * PI / 5) < TOL)
            p->c5 = e;
    if (!strcmp(p->name, "Td"))
        p->second = find_op(g, ops, MIRROR, 0, NULL, true);
    for (size_t e = 0; e < g->order && p->name[0] == 'O' && p->second == SIZE_MAX; e++)
        if (ops[e].kind == ROT && ops[e].order == 2 && find_op(g, ops, ROT, 4, ops[e].axis, true) == SIZE_MAX)
            p->second = e;  /* a C2' of O: on no C4 axis */
}

/* The principal axis: the axis of a highest-order rotation; among the three
 * C2 of D2-like groups the one that is also an S4 axis (D2d), else the one
 * closest to z. */
static void principal_axis(const qd__group *g, const op *ops, pg *p) {
    size_t e = find_op(g, ops, ROT, p->n, NULL, true);
    if (p->n == 2 && count_ops(g, ops, ROT, 2) > 1) {
        size_t s4 = find_op(g, ops, IMPROPER, 4, NULL, true);
        e = s4 != SIZE_MAX ? find_op(g, ops, ROT, 2, ops[s4].axis, true) : prefer(g, ops, ROT, 2, NULL, Z, false);
    }
    memcpy(p->axis, ops[e].axis, sizeof p->axis);
    orient(p->axis);
}

static void d2_axes(const qd__group *g, const op *ops, pg *p) {
    p->c2[0] = find_op(g, ops, ROT, 2, p->axis, true);
    p->c2[1] = prefer(g, ops, ROT, 2, p->axis, Y, false);
    for (size_t e = 0; e < g->order; e++)
        if (ops[e].kind == ROT && e != p->c2[0] && e != p->c2[1])
            p->c2[2] = e;
}

static void axial_group(const qd__group *g, const op *ops, pg *p) {
    principal_axis(g, ops, p);
    size_t n = p->n, perp = 0;
    for (size_t e = 0; e < g->order; e++)
        perp += ops[e].kind == ROT && ops[e].order == 2 && perpendicular(ops[e].axis, p->axis);
    p->sigh = find_op(g, ops, MIRROR, 0, p->axis, true);
    bool sigv = find_op(g, ops, MIRROR, 0, p->axis, false) != SIZE_MAX;
    bool improper = count_ops(g, ops, IMPROPER, 0) + count_ops(g, ops, INV, 0) > 0;
    bool even_s = false;  /* A/B and E_k by S_2n: Cotton's S4, S8, D2d, D4d */
    if (perp) {
        const char *h = p->sigh != SIZE_MAX ? "h" : sigv ? "d" : "";
        snprintf(p->name, sizeof p->name, "D%u%s", small(n), h);
        p->second = prefer(g, ops, ROT, 2, p->axis, X, false);
        p->d2 = n == 2 && *h != 'd';
        even_s = *h == 'd' && n % 2 == 0;
        if (p->d2)
            d2_axes(g, ops, p);
    } else if (p->sigh != SIZE_MAX || sigv || !improper) {
        snprintf(p->name, sizeof p->name, "C%u%s", small(n), p->sigh != SIZE_MAX ? "h" : sigv ? "v" : "");
        if (p->sigh == SIZE_MAX && sigv)
            p->second = prefer(g, ops, MIRROR, 0, p->axis, X, true);
    } else {
        snprintf(p->name, sizeof p->name, "S%u", small(2 * n));
        even_s = n % 2 == 0;
    }
    p->np = even_s ? 2 * n : n;
    p->prin = find_turn(g, ops, p->axis, p->np, even_s);
}

/* C1, Cs and Ci: no rotation. */
static void small_group(const qd__group *g, const op *ops, pg *p) {
    p->sigh = find_op(g, ops, MIRROR, 0, NULL, true);
    snprintf(p->name, sizeof p->name, "%s", g->order == 1 ? "C1" : p->inv != SIZE_MAX ? "Ci" : "Cs");
}

static void analyze(const qd__group *g, const op *ops, pg *p) {
    memset(p, 0, sizeof *p);
    p->prin = p->second = p->inv = p->sigh = p->c3 = p->c5 = SIZE_MAX;
    p->c2[0] = p->c2[1] = p->c2[2] = SIZE_MAX;
    p->inv = find_op(g, ops, INV, 0, NULL, true);
    p->n = 1;
    for (size_t e = 0; e < g->order; e++)
        if (ops[e].kind == ROT && ops[e].order > p->n)
            p->n = ops[e].order;
    if (count_ops(g, ops, ROT, 3) >= 4)  /* two C3 axes, each with C3 and C3^2 */
        cubic_group(g, ops, p);
    else if (p->n > 1)
        axial_group(g, ops, p);
    else
        small_group(g, ops, p);
}

/* ops for every element, and whether R is a faithful orthogonal
 * representation of g at all. */
static qd_status describe(qd_ctx *ctx, const qd__group *g, const double *R, pg *p, bool *is_pg) {
    *is_pg = false;
    if (!g || !g->mul) {
        qd_ctx_error(ctx, QD_ERR_ARG, "point group: no group given");
        return QD_ERR_ARG;
    }
    if (!R)  /* an abstract group: not an error, just no geometry */
        return QD_OK;
    op *ops = qd__malloc(ctx, g->order * sizeof *ops);
    size_t *pw = qd__malloc(ctx, g->order * sizeof *pw);
    qd_status st = ops && pw ? QD_OK : QD_ERR_NOMEM;
    for (size_t e = 0; e < g->order && st == QD_OK; e++)
        classify(R + 9 * e, &ops[e]);
    if (st == QD_OK) {
        element_orders(g, ops, pw);
        st = represents(ctx, g, R, ops, is_pg);
    }
    if (st == QD_OK && *is_pg)
        analyze(g, ops, p);
    qd__free(pw);
    qd__free(ops);
    return st;
}

qd_status qd__group_pointgroup_name(qd_ctx *ctx, const qd__group *g, const double *R,
                                    char name[16]) {
    pg p;
    bool is_pg = false;
    name[0] = '\0';
    qd_status st = describe(ctx, g, R, &p, &is_pg);
    if (st == QD_OK && is_pg)
        memcpy(name, p.name, sizeof p.name);
    return st;
}

typedef struct row {
    const qd__group *g;
    const qd__chartab *t;
    size_t i;
} row;

static double re_at(const row *r, size_t e) {
    return r->t->re[r->i * r->t->n + r->g->class_of[e]];
}

static double im_at(const row *r, size_t e) {
    return r->t->im[r->i * r->t->n + r->g->class_of[e]];
}

static bool row_complex(const row *r) {
    for (size_t c = 0; c < r->t->n; c++)
        if (r->t->im[r->i * r->t->n + c] != 0)
            return true;
    return false;
}

/* k of E_k: chi(C_n) = exp(+-2 pi i k / n) (complex) or 2 cos(2 pi k / n). */
static size_t e_index(const row *r, const pg *p, bool cplx) {
    double a = cplx ? fabs(atan2(im_at(r, p->prin), re_at(r, p->prin)))
                    : acos(fmax(-1, fmin(1, re_at(r, p->prin) / 2)));
    return (size_t)lround(a * (double)p->np / (2 * PI));
}

/* The subscript: 1/2 (A, B; T by the opposite sign, as Cotton's T1 is odd
 * under C2' and sigma_d), 1/2/3 for B in D2, k for E when n >= 5. */
static void subscript(const row *r, const pg *p, char letter, bool cplx, char *out, size_t size) {
    out[0] = '\0';
    if ((letter == 'A' || letter == 'B') && p->d2) {
        for (int k = 0; k < 3 && letter == 'B'; k++)
            if (p->c2[k] != SIZE_MAX && re_at(r, p->c2[k]) > 0)
                snprintf(out, size, "%d", k + 1);
    } else if ((letter == 'A' || letter == 'B') && p->second != SIZE_MAX) {
        snprintf(out, size, "%d", re_at(r, p->second) > 0 ? 1 : 2);
    } else if (letter == 'T' && p->second != SIZE_MAX) {
        snprintf(out, size, "%d", re_at(r, p->second) < 0 ? 1 : 2);
    } else if (letter == 'T' && p->c5 != SIZE_MAX) {
        snprintf(out, size, "%d", re_at(r, p->c5) > 0 ? 1 : 2);
    } else if (letter == 'E' && !p->cubic && p->prin != SIZE_MAX && p->np >= 5) {
        snprintf(out, size, "%u", small(e_index(r, p, cplx)));
    }
}

static void mulliken(const row *r, const pg *p, char label[12]) {
    size_t d = r->t->dim[r->i];
    bool cplx = d == 1 && row_complex(r);
    char letter = d > 5 ? '?' : "?AETGH"[d], sub[8];
    if (d == 1)  /* a complex one-dimensional character is half of an E */
        letter = cplx ? 'E' : p->prin != SIZE_MAX && re_at(r, p->prin) < 0 ? 'B' : 'A';
    if (d == 1 && p->d2)  /* D2: B unless symmetric under all three C2 */
        for (int k = 0; k < 3; k++)
            letter = p->c2[k] != SIZE_MAX && re_at(r, p->c2[k]) < 0 ? 'B' : letter;
    subscript(r, p, letter, cplx, sub, sizeof sub);
    size_t ref = p->cubic ? p->c3 : p->prin;
    const char *ab = !cplx || ref == SIZE_MAX ? "" : im_at(r, ref) > 0 ? "a" : "b";
    const char *par = "";
    if (p->inv != SIZE_MAX)
        par = re_at(r, p->inv) > 0 ? "g" : "u";
    else if (p->sigh != SIZE_MAX)
        par = re_at(r, p->sigh) > 0 ? "'" : "''";
    snprintf(label, 12, "%c%s%s%s", letter, sub, ab, par);
}

static bool all_distinct(size_t n, char (*labels)[12]) {
    for (size_t i = 0; i < n; i++)
        for (size_t j = i + 1; j < n; j++)
            if (!strcmp(labels[i], labels[j]))
                return false;
    return true;
}

qd_status qd__group_irrep_labels(qd_ctx *ctx, const qd__group *g, const double *R,
                                 const qd__chartab *t, char (*labels)[12]) {
    if (!g || !t || !labels || t->n != g->nclass) {
        qd_ctx_error(ctx, QD_ERR_ARG, "irrep labels: a character table of the group is needed");
        return QD_ERR_ARG;
    }
    pg p;
    bool is_pg = false;
    qd_status st = describe(ctx, g, R, &p, &is_pg);
    if (st != QD_OK)
        return st;
    for (size_t i = 0; i < t->n && is_pg; i++) {
        row r = {g, t, i};
        mulliken(&r, &p, labels[i]);
    }
    /* An abstract group, or a table these rules do not name uniquely: Gamma_i. */
    if (!is_pg || !all_distinct(t->n, labels))
        for (size_t i = 0; i < t->n; i++)
            snprintf(labels[i], 12, "Gamma%u", small(i + 1));
    return QD_OK;
}

/*
 * src/linear/symmetry_group.c - from the operations S_g to a group: the
 * Cayley table (products matched by their action on one fixed vector),
 * classes, characters, Schoenflies name and Mulliken labels
 * (qd_group_characters, src/group/symmetry.c),
 * and the names of classes and blocks for printing.
 */
#include "symmetry.h"

#include "base/mem.h"
#include "../base/args.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

/* A fixed vector with no symmetry of its own: S_a S_b = S_g exactly when
 * they agree on it (distinct orthogonal-like S differ on almost every v). */
static void probe(size_t n, double *v) {
    for (size_t i = 0; i < n; i++)
        v[i] = sin(1.3 + 0.7 * (double)i) + 0.1 * (double)i + 1;
}

static void apply(size_t n, const double *S, const double *x, double *y) {
    for (size_t i = 0; i < n; i++) {
        double t = 0;
        for (size_t j = 0; j < n; j++)
            t += S[i * n + j] * x[j];
        y[i] = t;
    }
}

static size_t find_image(size_t order, size_t n, const double *w, const double *u, double tol) {
    for (size_t g = 0; g < order; g++) {
        size_t i = 0;
        while (i < n && fabs(w[g * n + i] - u[i]) <= tol)
            i++;
        if (i == n)
            return g;
    }
    return order;
}

/* table[a*order + b] = index of S_a S_b; false when not closed. */
static bool cayley(qd_ctx *ctx, qd_symmetry *s, bool *nomem) {
    size_t n = s->n, order = s->order;
    double *v = qd__malloc(ctx, (n + 1) * sizeof *v), *u = qd__malloc(ctx, (n + 1) * sizeof *u);
    double *w = qd__malloc(ctx, (order * n + 1) * sizeof *w);
    bool ok = v && u && w;
    *nomem = !ok;
    if (ok) {
        probe(n, v);
        for (size_t g = 0; g < order; g++)
            apply(n, s->S + g * n * n, v, w + g * n);
    }
    for (size_t a = 0; ok && a < order; a++)
        for (size_t b = 0; ok && b < order; b++) {
            apply(n, s->S + a * n * n, w + b * n, u);
            s->table[a * order + b] = find_image(order, n, w, u, 1e-7 * (double)n);
            ok = s->table[a * order + b] < order;
        }
    qd__free(v);
    qd__free(u);
    qd__free(w);
    return ok;
}

static bool is_identity(size_t n, const double *S) {
    for (size_t i = 0; i < n * n; i++)
        if (fabs(S[i] - (i % (n + 1) == 0)) > 1e-9)
            return false;
    return true;
}

/* The identity first: the group module's class 0 is {E}. */
static bool identity_first(qd_symmetry *s) {
    size_t nn = s->n * s->n, g = 0;
    while (g < s->order && !is_identity(s->n, s->S + g * nn))
        g++;
    if (g == s->order)
        return false;
    for (size_t i = 0; g && i < nn; i++) {
        double t = s->S[i];
        s->S[i] = s->S[g * nn + i];
        s->S[g * nn + i] = t;
    }
    for (size_t k = 0; g && s->R && k < 9; k++) {
        double t = s->R[k];
        s->R[k] = s->R[g * 9 + k];
        s->R[g * 9 + k] = t;
    }
    return true;
}

/* Everything after the operations are in s->S (and s->R). */
static qd_status build(qd_ctx *ctx, qd_symmetry *s) {
    bool nomem = false;
    s->table = qd__malloc(ctx, (s->order * s->order + 1) * sizeof *s->table);
    if (!s->table)
        return QD_ERR_NOMEM;
    if (!identity_first(s)) {
        qd_ctx_error(ctx, QD_ERR_ARG, "the operations do not include the identity");
        return QD_ERR_ARG;
    }
    if (!cayley(ctx, s, &nomem)) {
        if (nomem)
            return QD_ERR_NOMEM;
        qd_ctx_error(ctx, QD_ERR_ARG, "the %zu operations are not closed under products: not "
                     "a group", s->order);
        return QD_ERR_ARG;
    }
    qd_symmetry g;
    qd_status st = qd_group_characters(ctx, s->order, s->table, s->geometric ? s->R : NULL, &g);
    if (st != QD_OK)
        return st;
    /* s keeps its own table and R; the group's analysis moves over */
    qd__free(g.table);
    qd__free(g.R);
    memcpy(s->name, g.name, sizeof s->name);
    s->nclass = g.nclass;
    s->class_of = g.class_of;
    s->class_size = g.class_size;
    s->class_rep = g.class_rep;
    s->nirrep = g.nirrep;
    s->irrep_dim = g.irrep_dim;
    s->chi_re = g.chi_re;
    s->chi_im = g.chi_im;
    s->label = g.label;
    return QD_OK;
}

static qd_status take_ops(qd_ctx *ctx, qd_symmetry *s, size_t order, const double *S,
                          const double *R) {
    size_t nn = s->n * s->n;
    s->order = order;
    s->S = qd__malloc(ctx, (order * nn + 1) * sizeof *s->S);
    if (!s->S)
        return QD_ERR_NOMEM;
    memcpy(s->S, S, order * nn * sizeof *s->S);
    s->geometric = R != NULL;
    if (R) {
        s->R = qd__malloc(ctx, (order * 9 + 1) * sizeof *s->R);
        if (!s->R)
            return QD_ERR_NOMEM;
        memcpy(s->R, R, order * 9 * sizeof *s->R);
    }
    return QD_OK;
}

static bool conservative(const qd_linear *lin) {
    for (size_t i = 0; i < lin->n * lin->n; i++)
        if (lin->C[i] != 0 || lin->G[i] != 0)
            return false;
    return true;
}

qd_status qd_symmetry_from_ops(qd_ctx *ctx, const qd_linear *lin, size_t order,
                               const double *S, const double *R, qd_symmetry *out) {
    QD_ARGS_CTX(ctx, ctx && lin && (order == 0 || S) && out);
    memset(out, 0, sizeof *out);
    if (!ctx || !lin || !S || order == 0)
        return QD_ERR_ARG;
    size_t n = lin->n;
    out->n = n;
    for (size_t g = 0; g < order; g++)
        if (!qd__lin_symm_invariant(n, S + g * n * n, lin->M) ||
            !qd__lin_symm_invariant(n, S + g * n * n, lin->K)) {
            qd_ctx_error(ctx, QD_ERR_ARG, "operation %zu leaves M0 or K0 not invariant", g);
            return QD_ERR_ARG;
        }
    qd_status st = take_ops(ctx, out, order, S, R);
    return st == QD_OK ? build(ctx, out) : st;
}

static qd_status find_ops(qd_ctx *ctx, const qd_eom *e, const qd_model *m, size_t nvals,
                          const qd_expr *const *syms, const double *vals,
                          const qd_linear *lin, qd__symm_ops *ops, qd_symmetry *out) {
    bool found = false;
    qd_status st = QD_OK;
    if (m && e)
        st = qd__lin_symm_geometric(ctx, e, m, nvals, syms, vals, lin, ops, &out->rigid,
                                &out->nrigid, &out->rigid_kind, &found);
    if (st == QD_OK && !found)
        st = qd__lin_symm_permutations(ctx, lin, ops);
    out->geometric = found;
    if (st == QD_OK && ops->overflow) {
        qd_ctx_error(ctx, QD_ERR_TOOBIG, "the symmetry group has more than %d elements",
                     QD_SYMMETRY_MAX_ORDER);
        st = QD_ERR_TOOBIG;
    }
    return st;
}

qd_status qd_symmetry_find(qd_ctx *ctx, const qd_eom *e, const qd_model *m, size_t nvals,
                           const qd_expr *const *syms, const double *vals,
                           const qd_linear *lin, qd_symmetry *out) {
    QD_ARGS_CTX(ctx, ctx && e && m && (nvals == 0 || syms) && (nvals == 0 || vals) && lin && out);
    memset(out, 0, sizeof *out);
    if (!ctx || !lin)
        return QD_ERR_ARG;
    if (!conservative(lin)) {
        qd_ctx_error(ctx, QD_ERR_ARG, "symmetry-adapted modes need a conservative system "
                     "without damping or gyroscopic terms (C0 = G0 = 0)");
        return QD_ERR_ARG;
    }
    out->n = lin->n;
    qd__symm_ops ops = {.n = lin->n};
    qd_status st = find_ops(ctx, e, m, nvals, syms, vals, lin, &ops, out);
    bool geometric = out->geometric;
    if (st == QD_OK)
        st = take_ops(ctx, out, ops.count, ops.S, geometric ? ops.R : NULL);
    qd__lin_symm_ops_free(&ops);
    return st == QD_OK ? build(ctx, out) : st;
}

/* ---- names ------------------------------------------------------------------- */

/* theta = 2 pi k / n with the smallest n: "n" and k. */
static bool fraction_of_turn(double theta, int *n, int *k) {
    for (int d = 2; d <= 360; d++) {
        double kk = theta * d / (2 * 3.14159265358979323846);
        if (fabs(kk - round(kk)) < 1e-6 * d) {
            *n = d;
            *k = (int)round(kk);
            return true;
        }
    }
    return false;
}

/* E, Cn, Cn^k, sigma, i, Sn, Sn^k from the 3x3 map. */
static void operation_name(const double *R, char *buf, size_t cap) {
    double det = R[0] * (R[4] * R[8] - R[5] * R[7]) - R[1] * (R[3] * R[8] - R[5] * R[6]) +
                 R[2] * (R[3] * R[7] - R[4] * R[6]);
    double tr = R[0] + R[4] + R[8];
    double c = det > 0 ? (tr - 1) / 2 : (tr + 1) / 2;
    double theta = acos(fmax(-1, fmin(1, c)));
    int n = 0, k = 0;
    if (theta < 1e-6)
        snprintf(buf, cap, "%s", det > 0 ? "E" : "sigma");
    else if (det < 0 && fabs(theta - 3.14159265358979323846) < 1e-6)
        snprintf(buf, cap, "i");
    else if (!fraction_of_turn(theta, &n, &k))
        snprintf(buf, cap, "%s", det > 0 ? "C" : "S");
    else if (k == 1)
        snprintf(buf, cap, "%c%d", det > 0 ? 'C' : 'S', n);
    else
        snprintf(buf, cap, "%c%d^%d", det > 0 ? 'C' : 'S', n, k);
}

static size_t element_order(const qd_symmetry *s, size_t g) {
    size_t k = 1, x = g;
    while (x != 0 && k <= s->order) {
        x = s->table[x * s->order + g];
        k++;
    }
    return k;
}

static void class_base(const qd_symmetry *s, size_t c, char *buf, size_t cap) {
    char op[12];
    size_t g = s->class_rep[c];
    if (s->geometric)
        operation_name(s->R + 9 * g, op, sizeof op);
    else if (c == 0)
        snprintf(op, sizeof op, "E");
    else
        snprintf(op, sizeof op, "g%zu", element_order(s, g));
    if (s->class_size[c] > 1)
        snprintf(buf, cap, "%u%.11s", (unsigned)s->class_size[c] % 10000u, op);
    else
        snprintf(buf, cap, "%s", op);
}

void qd_symmetry_class_name(const qd_symmetry *sym, size_t c, char *buf, size_t cap) {
    QD_ARGS(, sym && buf);
    if (!sym || c >= sym->nclass || cap == 0) {
        if (cap)
            buf[0] = 0;
        return;
    }
    char mine[24], other[24];
    class_base(sym, c, mine, sizeof mine);
    size_t primes = 0;
    for (size_t d = 0; d < c; d++) {   /* C2 and C2' of D4h: one name, two classes */
        class_base(sym, d, other, sizeof other);
        primes += strcmp(mine, other) == 0;
    }
    snprintf(buf, cap, "%s%.*s", mine, (int)(primes < 3 ? primes : 3), "'''");
}

/* The one position where the labels of a complex pair differ, 'a' against
 * 'b' (E1a/E1b, Ea'/Eb', Eag/Ebg), or SIZE_MAX. */
static size_t pair_letter(const char *x, const char *y) {
    size_t lx = strlen(x), at = SIZE_MAX;
    if (lx != strlen(y))
        return SIZE_MAX;
    for (size_t i = 0; i < lx; i++)
        if (x[i] != y[i]) {
            if (at != SIZE_MAX || !strchr("ab", x[i]) || !strchr("ab", y[i]))
                return SIZE_MAX;
            at = i;
        }
    return at;
}

void qd_symmetry_block_label(const qd_symmetry *sym, size_t b, char *buf, size_t cap) {
    QD_ARGS(, sym && buf);
    if (!sym || b >= sym->nblock || cap == 0) {
        if (cap)
            buf[0] = 0;
        return;
    }
    const char *x = sym->label[sym->block_irrep[b]], *y = sym->label[sym->block_pair[b]];
    size_t at = pair_letter(x, y);
    if (strcmp(x, y) == 0)
        snprintf(buf, cap, "%s", x);
    else if (at != SIZE_MAX)
        snprintf(buf, cap, "%.*s%s", (int)at, x, x + at + 1);   /* E1a, E1b: E1 */
    else
        snprintf(buf, cap, "%s+%s", x, y);
}

void qd_symmetry_free(qd_symmetry *s) {
    if (!s)
        return;
    void *arrays[] = {s->S, s->R, s->table, s->class_of, s->class_size, s->class_rep,
                      s->irrep_dim, s->chi_re, s->chi_im, s->label, s->chi, s->mult,
                      s->block_irrep, s->block_pair, s->block_start, s->block_size, s->U,
                      s->Kb, s->omega2, s->shapes, s->mode_block, s->mode_degeneracy,
                      s->mode_kind, s->rigid, s->rigid_kind};
    for (size_t i = 0; i < sizeof arrays / sizeof arrays[0]; i++)
        qd__free(arrays[i]);
    memset(s, 0, sizeof *s);
}

/*
 * src/linear/symmetry_reduce.c - the displacement representation reduced
 * (Desloge ch. 66; App. 30 eq. 22): its character chi(g) = tr S_g, the
 * multiplicities n_i = (1/|G|) sum_c |c| conj(chi_i(c)) chi(c), the
 * projectors P_i = (d_i/|G|) sum_g conj(chi_i(g)) S_g (a complex-conjugate
 * pair of irreps as one real projector P_i + P_i*, seed-desloge-B.md
 * pitfall 14), an M0-orthonormal basis of each range (Gram-Schmidt in the
 * M0 metric, App. 21 Thm 2), K0 in that basis (block diagonal: checked),
 * and each block solved as a symmetric eigenproblem.  Zero modes are
 * matched with the rigid translations and rotations projected on their
 * block.
 */
#include "symmetry.h"
#include "linear.h"

#include "base/mem.h"
#include "../base/args.h"

#include <math.h>
#include <string.h>

static double max_abs(size_t len, const double *a) {
    double m = 0;
    for (size_t i = 0; i < len; i++)
        m = fmax(m, fabs(a[i]));
    return m;
}

static qd_status reducible(qd_ctx *ctx, qd_symmetry *s) {
    size_t n = s->n, nc = s->nclass, ni = s->nirrep;
    s->chi = qd__malloc(ctx, (nc + 1) * sizeof *s->chi);
    s->mult = qd__calloc(ctx, ni + 1, sizeof *s->mult);
    if (!s->chi || !s->mult)
        return QD_ERR_NOMEM;
    for (size_t c = 0; c < nc; c++) {
        const double *S = s->S + s->class_rep[c] * n * n;
        double t = 0;
        for (size_t i = 0; i < n; i++)
            t += S[i * n + i];
        s->chi[c] = t;
    }
    size_t total = 0;
    for (size_t i = 0; i < ni; i++) {
        double re = 0, im = 0;
        for (size_t c = 0; c < nc; c++) {
            re += (double)s->class_size[c] * s->chi_re[i * nc + c] * s->chi[c];
            im -= (double)s->class_size[c] * s->chi_im[i * nc + c] * s->chi[c];
        }
        re /= (double)s->order;
        im /= (double)s->order;
        if (fabs(re - round(re)) > 1e-6 || fabs(im) > 1e-6 || round(re) < 0) {
            qd_ctx_error(ctx, QD_ERR_NUMERIC, "the multiplicity of %s is %.6g, not a whole "
                         "number: the characters do not fit the operations", s->label[i], re);
            return QD_ERR_NUMERIC;
        }
        s->mult[i] = (size_t)round(re);
        total += s->mult[i] * s->irrep_dim[i];
    }
    if (total != n) {
        qd_ctx_error(ctx, QD_ERR_NUMERIC, "the irreps account for %zu of %zu coordinates", total,
                     n);
        return QD_ERR_NUMERIC;
    }
    return QD_OK;
}

static bool is_complex(const qd_symmetry *s, size_t i) {
    for (size_t c = 0; c < s->nclass; c++)
        if (fabs(s->chi_im[i * s->nclass + c]) > 1e-9)
            return true;
    return false;
}

/* The irrep whose characters are the conjugates of i's. */
static size_t conjugate(const qd_symmetry *s, size_t i) {
    size_t nc = s->nclass;
    for (size_t j = 0; j < s->nirrep; j++) {
        size_t c = 0;
        while (c < nc && fabs(s->chi_re[j * nc + c] - s->chi_re[i * nc + c]) < 1e-9 &&
               fabs(s->chi_im[j * nc + c] + s->chi_im[i * nc + c]) < 1e-9)
            c++;
        if (c == nc)
            return j;
    }
    return i;
}

/* The real blocks: each irrep with n_i > 0, a complex pair once. */
static qd_status blocks(qd_ctx *ctx, qd_symmetry *s) {
    size_t ni = s->nirrep;
    s->block_irrep = qd__malloc(ctx, (ni + 1) * sizeof *s->block_irrep);
    s->block_pair = qd__malloc(ctx, (ni + 1) * sizeof *s->block_pair);
    s->block_start = qd__malloc(ctx, (ni + 1) * sizeof *s->block_start);
    s->block_size = qd__malloc(ctx, (ni + 1) * sizeof *s->block_size);
    if (!s->block_irrep || !s->block_pair || !s->block_start || !s->block_size)
        return QD_ERR_NOMEM;
    size_t start = 0;
    s->nblock = 0;
    for (size_t i = 0; i < ni; i++) {
        size_t j = is_complex(s, i) ? conjugate(s, i) : i;
        if (j < i || s->mult[i] == 0)
            continue;   /* the pair's block is the first irrep's */
        size_t b = s->nblock++;
        s->block_irrep[b] = i;
        s->block_pair[b] = j;
        s->block_start[b] = start;
        s->block_size[b] = s->mult[i] * s->irrep_dim[i] * (j == i ? 1 : 2);
        start += s->block_size[b];
    }
    return QD_OK;
}

/* P = (d/|G|) sum_g w(g) S_g with w = Re chi_i (twice for a pair: P_i + P_i*). */
static void projector(const qd_symmetry *s, size_t b, double *P) {
    size_t n = s->n, nn = n * n, i = s->block_irrep[b], nc = s->nclass;
    double f = (double)s->irrep_dim[i] / (double)s->order * (s->block_pair[b] == i ? 1 : 2);
    memset(P, 0, nn * sizeof *P);
    for (size_t g = 0; g < s->order; g++) {
        double w = f * s->chi_re[i * nc + s->class_of[g]];
        if (w == 0)
            continue;
        const double *S = s->S + g * nn;
        for (size_t k = 0; k < nn; k++)
            P[k] += w * S[k];
    }
}

static double m_dot(size_t n, const double *M, const double *x, const double *y) {
    double t = 0;
    for (size_t i = 0; i < n; i++)
        for (size_t j = 0; j < n; j++)
            t += x[i] * M[i * n + j] * y[j];
    return t;
}

/* The columns of P, pivoted Gram-Schmidt in the M0 metric, into U's
 * columns start.. start+size; false when the range is smaller. */
static bool orthonormal_range(const qd_symmetry *s, const double *M, double *cols,
                              size_t start, size_t size, double *qv) {
    size_t n = s->n;
    double scale = 0;
    for (size_t c = 0; c < n; c++)
        scale = fmax(scale, m_dot(n, M, cols + c * n, cols + c * n));
    for (size_t k = 0; k < size; k++) {
        size_t best = n;
        double bn = 1e-16 * scale;
        for (size_t c = 0; c < n; c++) {
            double v = m_dot(n, M, cols + c * n, cols + c * n);
            if (v > bn) {
                bn = v;
                best = c;
            }
        }
        if (best == n || bn < 1e-12 * scale)
            return false;
        double *u = cols + best * n, norm = sqrt(bn);
        for (size_t i = 0; i < n; i++)
            s->U[i * n + start + k] = u[i] / norm;
        const double *q = s->U + start + k;   /* stride n */
        for (size_t i = 0; i < n; i++)
            qv[i] = q[i * n];
        for (size_t c = 0; c < n; c++) {   /* remove the new direction from every column */
            double *x = cols + c * n, d = m_dot(n, M, qv, x);
            for (size_t i = 0; i < n; i++)
                x[i] -= d * qv[i];
        }
    }
    return true;
}

static qd_status coordinates(qd_ctx *ctx, const qd_linear *lin, qd_symmetry *s) {
    size_t n = s->n, nn = n * n;
    double *P = qd__malloc(ctx, (nn + 1) * sizeof *P), *cols = qd__malloc(ctx, (nn + 1) * sizeof *cols);
    double *qv = qd__malloc(ctx, (n + 1) * sizeof *qv);
    s->U = qd__calloc(ctx, nn + 1, sizeof *s->U);
    qd_status st = P && cols && qv && s->U ? QD_OK : QD_ERR_NOMEM;
    for (size_t b = 0; st == QD_OK && b < s->nblock; b++) {
        projector(s, b, P);
        for (size_t c = 0; c < n; c++)   /* column c of P, contiguous */
            for (size_t i = 0; i < n; i++)
                cols[c * n + i] = P[i * n + c];
        if (!orthonormal_range(s, lin->M, cols, s->block_start[b], s->block_size[b], qv)) {
            char lab[32];
            qd_symmetry_block_label(s, b, lab, sizeof lab);
            qd_ctx_error(ctx, QD_ERR_NUMERIC, "the projector of %s has rank below n_i d_i = %zu",
                         lab, s->block_size[b]);
            st = QD_ERR_NUMERIC;
        }
    }
    qd__free(P);
    qd__free(cols);
    qd__free(qv);
    return st;
}

static size_t block_of(const qd_symmetry *s, size_t col) {
    size_t b = 0;
    while (b + 1 < s->nblock && col >= s->block_start[b + 1])
        b++;
    return b;
}

/* Kb = U^T K0 U and the largest entry off the blocks. */
static qd_status block_form(qd_ctx *ctx, const qd_linear *lin, qd_symmetry *s) {
    size_t n = s->n, nn = n * n;
    double *KU = qd__malloc(ctx, (nn + 1) * sizeof *KU), *Ut = qd__malloc(ctx, (nn + 1) * sizeof *Ut);
    s->Kb = qd__malloc(ctx, (nn + 1) * sizeof *s->Kb);
    if (!KU || !Ut || !s->Kb) {
        qd__free(KU);
        qd__free(Ut);
        return QD_ERR_NOMEM;
    }
    qd__lin_symm_matmul(n, lin->K, s->U, KU);
    for (size_t i = 0; i < n; i++)
        for (size_t j = 0; j < n; j++)
            Ut[i * n + j] = s->U[j * n + i];
    qd__lin_symm_matmul(n, Ut, KU, s->Kb);
    qd__free(KU);
    qd__free(Ut);
    double big = max_abs(nn, s->Kb), off = 0;
    for (size_t i = 0; i < n; i++)
        for (size_t j = 0; j < n; j++)
            if (block_of(s, i) != block_of(s, j))
                off = fmax(off, fabs(s->Kb[i * n + j]));
    s->offblock = big > 0 ? off / big : 0;
    if (s->offblock > 1e-8) {
        qd_ctx_error(ctx, QD_ERR_NUMERIC, "K0 in the symmetry coordinates is not block "
                     "diagonal (off-block %.3g relative)", s->offblock);
        return QD_ERR_NUMERIC;
    }
    return QD_OK;
}

/* ---- the block eigenproblems --------------------------------------------- */

typedef struct block_sol {
    size_t m;
    double *K, *w, *V;   /* m*m row-major block; m; m*m column-major vectors */
    double *tmp;         /* m*m + 2m scratch */
} block_sol;

/* x minus its components along the nb orthonormal vectors of length m
 * stored one after another at basis (Gram-Schmidt, one vector at a time). */
static void project_out(const double *basis, size_t nb, size_t m, double *x) {
    for (size_t b = 0; b < nb; b++) {
        const double *u = basis + b * m;
        double d = 0;
        for (size_t k = 0; k < m; k++)
            d += u[k] * x[k];
        for (size_t k = 0; k < m; k++)
            x[k] -= d * u[k];
    }
}

/* Replace the block's zero modes by the rigid motions projected on it,
 * where they lie in the zero eigenspace: translations first. */
static void rigid_zero_modes(const qd_linear *lin, qd_symmetry *s, size_t b, block_sol *bs,
                             size_t z0, size_t z, qd_mode_kind *kind) {
    size_t n = s->n, m = bs->m, got = 0, st = s->block_start[b];
    /* against all of K0: a block of zero modes has only round-off to scale by */
    double *c = bs->tmp, *x = bs->tmp + m, kmax = max_abs(n * n, s->Kb);
    double *orig = bs->tmp + 2 * m;   /* the solver's zero modes, before replacing */
    memcpy(orig, bs->V + z0 * m, z * m * sizeof *orig);
    for (size_t r = 0; r < s->nrigid && got < z; r++) {
        const double *v = s->rigid + r * n;
        double vn = sqrt(m_dot(n, lin->M, v, v)), cn = 0;
        for (size_t k = 0; k < m; k++) {   /* c = U_b^T M0 v */
            double t = 0;
            for (size_t i = 0; i < n; i++)
                for (size_t j = 0; j < n; j++)
                    t += s->U[i * n + st + k] * lin->M[i * n + j] * v[j];
            c[k] = t;
        }
        project_out(bs->V + z0 * m, got, m, c);
        for (size_t k = 0; k < m; k++)
            cn += c[k] * c[k];
        cn = sqrt(cn);
        if (cn <= 1e-6 * vn)
            continue;
        double kc = 0;
        for (size_t k = 0; k < m; k++) {
            double t = 0;
            for (size_t l = 0; l < m; l++)
                t += bs->K[k * m + l] * c[l];
            kc = fmax(kc, fabs(t));
        }
        if (kc > 1e-6 * fmax(kmax, 1e-300) * cn)
            continue;   /* not a zero mode of this system (held in place) */
        double *u = bs->V + (z0 + got) * m;
        for (size_t k = 0; k < m; k++)
            u[k] = c[k] / cn;
        kind[got++] = s->rigid_kind[r];
    }
    /* the block's other zero modes: orthogonal to the rigid ones */
    size_t next = got;
    for (size_t a = 0; a < z && next < z; a++) {
        double *u = bs->V + (z0 + next) * m, xn = 0;
        memcpy(x, orig + a * m, m * sizeof *x);
        project_out(bs->V + z0 * m, next, m, x);
        for (size_t k = 0; k < m; k++)
            xn += x[k] * x[k];
        if (sqrt(xn) < 1e-6)
            continue;
        for (size_t k = 0; k < m; k++)
            u[k] = x[k] / sqrt(xn);
        kind[next++] = QD_MODE_ZERO;
    }
}

static qd_status alloc_modes(qd_ctx *ctx, qd_symmetry *s) {
    size_t n = s->n;
    s->omega2 = qd__malloc(ctx, (n + 1) * sizeof *s->omega2);
    s->shapes = qd__malloc(ctx, (n * n + 1) * sizeof *s->shapes);
    s->mode_block = qd__malloc(ctx, (n + 1) * sizeof *s->mode_block);
    s->mode_degeneracy = qd__malloc(ctx, (n + 1) * sizeof *s->mode_degeneracy);
    s->mode_kind = qd__malloc(ctx, (n + 1) * sizeof *s->mode_kind);
    return s->omega2 && s->shapes && s->mode_block && s->mode_degeneracy && s->mode_kind
               ? QD_OK : QD_ERR_NOMEM;
}

/* Block b solved into the unsorted mode slots start.. (column start + k of
 * shapes is U_b v_k). */
static qd_status solve_block(qd_ctx *ctx, const qd_linear *lin, qd_symmetry *s, size_t b,
                             double zero) {
    size_t n = s->n, m = s->block_size[b], st = s->block_start[b];
    block_sol bs = {.m = m};
    bs.K = qd__malloc(ctx, (m * m + 1) * sizeof *bs.K);
    bs.w = qd__malloc(ctx, (m + 1) * sizeof *bs.w);
    bs.V = qd__malloc(ctx, (m * m + 1) * sizeof *bs.V);
    bs.tmp = qd__malloc(ctx, (m * m + 2 * m + 1) * sizeof *bs.tmp);
    qd_status ret = bs.K && bs.w && bs.V && bs.tmp ? QD_OK : QD_ERR_NOMEM;
    for (size_t i = 0; ret == QD_OK && i < m; i++)
        for (size_t j = 0; j < m; j++)
            bs.K[i * m + j] = s->Kb[(st + i) * n + st + j];
    if (ret == QD_OK && !qd__lin_sym_eig(ctx, m, bs.K, bs.w, bs.V)) {
        qd_ctx_error(ctx, QD_ERR_NUMERIC, "the eigen-solver (dsyev) failed on a block");
        ret = QD_ERR_NUMERIC;
    }
    size_t z0 = m, z = 0;
    for (size_t k = 0; ret == QD_OK && k < m; k++) {
        if (fabs(bs.w[k]) <= zero) {
            bs.w[k] = 0;
            z0 = z0 < k ? z0 : k;
            z++;
        }
        s->mode_kind[st + k] = QD_MODE_VIBRATION;
    }
    if (ret == QD_OK && z)
        rigid_zero_modes(lin, s, b, &bs, z0, z, s->mode_kind + st + z0);
    for (size_t k = 0; ret == QD_OK && k < m; k++) {
        s->omega2[st + k] = bs.w[k];
        s->mode_block[st + k] = b;
        s->mode_degeneracy[st + k] =
            s->irrep_dim[s->block_irrep[b]] * (s->block_pair[b] == s->block_irrep[b] ? 1 : 2);
        for (size_t i = 0; i < n; i++) {
            double t = 0;
            for (size_t l = 0; l < m; l++)
                t += s->U[i * n + st + l] * bs.V[k * m + l];
            s->shapes[i * n + st + k] = t;
        }
    }
    qd__free(bs.K);
    qd__free(bs.w);
    qd__free(bs.V);
    qd__free(bs.tmp);
    return ret;
}

/* Modes ascending in w^2, then by block; each shape's largest component
 * positive (as qd_modes_solve). */
static qd_status sort_modes(qd_ctx *ctx, qd_symmetry *s) {
    size_t n = s->n;
    size_t *idx = qd__malloc(ctx, (n + 1) * sizeof *idx);
    double *w = qd__malloc(ctx, (n + 1) * sizeof *w), *sh = qd__malloc(ctx, (n * n + 1) * sizeof *sh);
    size_t *mb = qd__malloc(ctx, (n + 1) * sizeof *mb), *md = qd__malloc(ctx, (n + 1) * sizeof *md);
    qd_mode_kind *mk = qd__malloc(ctx, (n + 1) * sizeof *mk);
    qd_status st = idx && w && sh && mb && md && mk ? QD_OK : QD_ERR_NOMEM;
    double tie = 1e-9 * fmax(max_abs(n, s->omega2), 1e-300);
    for (size_t k = 0; st == QD_OK && k < n; k++) {   /* insertion sort: stable */
        size_t j = k;
        while (j > 0 && s->omega2[idx[j - 1]] > s->omega2[k] + tie) {
            idx[j] = idx[j - 1];
            j--;
        }
        idx[j] = k;
    }
    for (size_t k = 0; st == QD_OK && k < n; k++) {
        size_t f = idx[k], big = 0;
        w[k] = s->omega2[f];
        mb[k] = s->mode_block[f];
        md[k] = s->mode_degeneracy[f];
        mk[k] = s->mode_kind[f];
        for (size_t i = 0; i < n; i++)
            if (fabs(s->shapes[i * n + f]) > fabs(s->shapes[big * n + f]) * (1 + 1e-9))
                big = i;
        double sg = s->shapes[big * n + f] < 0 ? -1 : 1;
        for (size_t i = 0; i < n; i++)
            sh[i * n + k] = sg * s->shapes[i * n + f];
    }
    if (st == QD_OK) {
        memcpy(s->omega2, w, n * sizeof *w);
        memcpy(s->shapes, sh, n * n * sizeof *sh);
        memcpy(s->mode_block, mb, n * sizeof *mb);
        memcpy(s->mode_degeneracy, md, n * sizeof *md);
        memcpy(s->mode_kind, mk, n * sizeof *mk);
    }
    qd__free(idx);
    qd__free(w);
    qd__free(sh);
    qd__free(mb);
    qd__free(md);
    qd__free(mk);
    return st;
}

static qd_status solve_blocks(qd_ctx *ctx, const qd_linear *lin, qd_symmetry *s) {
    qd_status st = alloc_modes(ctx, s);
    if (st != QD_OK)
        return st;
    /* zero: against the largest w^2, which the block diagonal bounds */
    double big = 0;
    for (size_t i = 0; i < s->n; i++)
        big = fmax(big, fabs(s->Kb[i * s->n + i]));
    double zero = QD_MODES_ZERO_TOL * big;
    for (size_t b = 0; st == QD_OK && b < s->nblock; b++)
        st = solve_block(ctx, lin, s, b, zero);
    return st == QD_OK ? sort_modes(ctx, s) : st;
}

qd_status qd_symmetry_reduce(qd_ctx *ctx, const qd_linear *lin, qd_symmetry *sym) {
    QD_ARGS_CTX(ctx, ctx && lin && sym);
    if (!ctx || !lin || !sym || !sym->order || lin->n != sym->n)
        return QD_ERR_ARG;
    qd_status st = reducible(ctx, sym);
    if (st == QD_OK)
        st = blocks(ctx, sym);
    if (st == QD_OK)
        st = coordinates(ctx, lin, sym);
    if (st == QD_OK)
        st = block_form(ctx, lin, sym);
    if (st == QD_OK)
        st = solve_blocks(ctx, lin, sym);
    return st;
}

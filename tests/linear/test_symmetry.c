/*
 * tests/linear/test_symmetry.c - symmetry-adapted small oscillations
 * (qdot/symmetry.h) against closed forms:
 *
 *   equilateral triangle of springs, free in its plane: C3v, chi = (6, 0, 0),
 *     Gamma = A1 + A2 + 2E; w^2 = 3k/m (A1), 3k/(2m) (E), translations E,
 *     rotation A2 (Desloge ch. 66 worked example, App. 30 eq. 22;
 *     seed-desloge-D.md T33); its rotations alone (C3): the complex pair
 *     merged into one real E block;
 *   linear symmetric triatomic along its axis: w^2 = k/m (symmetric
 *     stretch, even under the mirror) and (k/m)(1 + 2m/M) (odd, with the
 *     translation);
 *   square of side springs k and diagonal springs kd, in its plane: C4v,
 *     A1 + A2 + B1 + B2 + 2E; w^2 = 2(k + kd)/m (A1 breathing), 2kd/m,
 *     2k/m (a B and the E pair: accidental degeneracy), SymPy cross-check
 *     of the Hessian (three zeros, 2k/m x3, 2kd/m, 2(k + kd)/m);
 *   tetrahedral XY4 (centre M, bonds k, Y-Y springs kh): Td, A1 + E + T1 +
 *     3T2, A1 breathing w^2 = (k + 4kh)/m, translations T2, rotations T1;
 *     E and T2 against SymPy's eigenvalues of M^-1 K;
 *   ring of N masses on a circle (arc coordinates): C6v for N = 6 from the
 *     particles, the abstract dihedral group of order 12 from T and V alone,
 *     and the cyclic fast path for N = 1000: w_k = 2 sqrt(k/m) |sin(pi k/N)|;
 *   every character table by both orthogonality relations; a scalene
 *     triangle has no symmetry; operations that are not a group are refused.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "qdot/qdot.h"
#include "qdot/modes.h"
#include "qdot/symmetry.h"
#include "../util/system.h"

static const double PI = 3.14159265358979323846;

#define TRIANGLE                                                                               \
    "coordinates x1, y1, x2, y2, x3, y3\nparameters m = 2, k = 5, a = 1\n"                     \
    "d12 = sqrt((x1 - x2)^2 + (y1 - y2)^2)\nd23 = sqrt((x2 - x3)^2 + (y2 - y3)^2)\n"           \
    "d31 = sqrt((x3 - x1)^2 + (y3 - y1)^2)\n"                                                  \
    "particle m at (x1, y1)\nparticle m at (x2, y2)\nparticle m at (x3, y3)\n"                 \
    "V = k/2*((d12 - a)^2 + (d23 - a)^2 + (d31 - a)^2)\n"

#define TRIATOMIC                                                                              \
    "coordinates x1, x2, x3\nparameters m = 1, M = 3, k = 2, a = 1\n"                          \
    "particle m at (x1, 0)\nparticle M at (x2, 0)\nparticle m at (x3, 0)\n"                    \
    "V = k/2*((x2 - x1 - a)^2 + (x3 - x2 - a)^2)\n"

#define SQUARE                                                                                 \
    "coordinates x1, y1, x2, y2, x3, y3, x4, y4\nparameters m = 1.5, k = 2, kd = 3, a = 2\n"   \
    "r1 = (x1, y1)\nr2 = (x2, y2)\nr3 = (x3, y3)\nr4 = (x4, y4)\n"                             \
    "particle m at r1\nparticle m at r2\nparticle m at r3\nparticle m at r4\n"                 \
    "V = k/2*((norm(r1 - r2) - a)^2 + (norm(r2 - r3) - a)^2 + (norm(r3 - r4) - a)^2"           \
    " + (norm(r4 - r1) - a)^2) + kd/2*((norm(r1 - r3) - a*sqrt(2))^2"                          \
    " + (norm(r2 - r4) - a*sqrt(2))^2)\n"

#define TETRA                                                                                  \
    "coordinates x0, y0, z0, x1, y1, z1, x2, y2, z2, x3, y3, z3, x4, y4, z4\n"                 \
    "parameters m = 1, M = 3, k = 2, kh = 1/2, b = 1\n"                                        \
    "r0 = (x0, y0, z0)\nr1 = (x1, y1, z1)\nr2 = (x2, y2, z2)\nr3 = (x3, y3, z3)\n"             \
    "r4 = (x4, y4, z4)\n"                                                                      \
    "particle M at r0\nparticle m at r1\nparticle m at r2\nparticle m at r3\n"                 \
    "particle m at r4\nd = b*sqrt(8/3)\n"                                                      \
    "V = k/2*((norm(r1 - r0) - b)^2 + (norm(r2 - r0) - b)^2 + (norm(r3 - r0) - b)^2"           \
    " + (norm(r4 - r0) - b)^2) + kh/2*((norm(r1 - r2) - d)^2 + (norm(r1 - r3) - d)^2"          \
    " + (norm(r1 - r4) - d)^2 + (norm(r2 - r3) - d)^2 + (norm(r2 - r4) - d)^2"                 \
    " + (norm(r3 - r4) - d)^2)\n"

#define RING6_PARTICLES                                                                        \
    "coordinates s1, s2, s3, s4, s5, s6\nparameters m = 1, k = 1, R = 1\n"                     \
    "particle m at R*(cos(s1/R), sin(s1/R))\n"                                                 \
    "particle m at R*(cos(pi/3 + s2/R), sin(pi/3 + s2/R))\n"                                   \
    "particle m at R*(cos(2*pi/3 + s3/R), sin(2*pi/3 + s3/R))\n"                               \
    "particle m at R*(cos(pi + s4/R), sin(pi + s4/R))\n"                                       \
    "particle m at R*(cos(4*pi/3 + s5/R), sin(4*pi/3 + s5/R))\n"                               \
    "particle m at R*(cos(5*pi/3 + s6/R), sin(5*pi/3 + s6/R))\n"                               \
    "V = k/2*((s2 - s1)^2 + (s3 - s2)^2 + (s4 - s3)^2 + (s5 - s4)^2 + (s6 - s5)^2"             \
    " + (s1 - s6)^2)\n"

#define RING6_ABSTRACT                                                                         \
    "coordinates s1, s2, s3, s4, s5, s6\nparameters m = 1, k = 1\n"                            \
    "T = m/2*(s1'^2 + s2'^2 + s3'^2 + s4'^2 + s5'^2 + s6'^2)\n"                                \
    "V = k/2*((s2 - s1)^2 + (s3 - s2)^2 + (s4 - s3)^2 + (s5 - s4)^2 + (s6 - s5)^2"             \
    " + (s1 - s6)^2)\n"

#define SCALENE                                                                                \
    "coordinates x1, y1, x2, y2, x3, y3\nparameters m = 1, k = 1\n"                            \
    "d12 = sqrt((x1 - x2)^2 + (y1 - y2)^2)\nd23 = sqrt((x2 - x3)^2 + (y2 - y3)^2)\n"           \
    "d31 = sqrt((x3 - x1)^2 + (y3 - y1)^2)\n"                                                  \
    "particle m at (x1, y1)\nparticle m at (x2, y2)\nparticle m at (x3, y3)\n"                 \
    "V = k/2*((d12 - 1)^2 + (d23 - 1.2)^2 + (d31 - 1.5)^2)\n"

typedef struct point {
    size_t n;
    const qd_expr *syms[64];
    double vals[64];
} point;

static void at(const qt_system *s, const double *q, point *p) {
    size_t nq = qd_model_ncoords(s->model), np = qd_model_nparams(s->model);
    p->n = nq + np;
    for (size_t i = 0; i < nq; i++) {
        p->syms[i] = qd_model_coord(s->model, i);
        p->vals[i] = q ? q[i] : 0;
    }
    for (size_t i = 0; i < np; i++) {
        p->syms[nq + i] = qd_model_param(s->model, i);
        assert_int_equal(qd_eval(s->ctx, qd_model_param_value(s->model, i), 0, NULL, NULL,
                                 &p->vals[nq + i]), QD_OK);
    }
}

/* Linearize at q, find the group and reduce. */
static void analyse(const qt_system *s, const double *q, qd_linear *lin, qd_symmetry *sym) {
    point p;
    at(s, q, &p);
    assert_int_equal(qd_linear_about(s->ctx, s->eom, s->model, p.n, p.syms, p.vals, lin), QD_OK);
    qd_status st = qd_symmetry_find(s->ctx, s->eom, s->model, p.n, p.syms, p.vals, lin, sym);
    if (st != QD_OK)
        fail_msg("%s", qd_ctx_message(s->ctx));
    if (sym->order > 1 && qd_symmetry_reduce(s->ctx, lin, sym) != QD_OK)
        fail_msg("%s", qd_ctx_message(s->ctx));
}

/* Both orthogonality relations (Desloge App. 29): rows
 * sum_c |c| conj(chi_i) chi_j = |G| delta_ij, columns
 * sum_i conj(chi_i(c)) chi_i(c') = |G|/|c| delta_cc'; sum d_i^2 = |G|. */
static void check_orthogonality(const qd_symmetry *s) {
    size_t nc = s->nclass, g = s->order, d2 = 0;
    assert_int_equal(s->nirrep, nc);
    for (size_t i = 0; i < nc; i++) {
        d2 += s->irrep_dim[i] * s->irrep_dim[i];
        assert_true(fabs(s->chi_re[i * nc] - (double)s->irrep_dim[i]) < 1e-9);
        for (size_t j = 0; j < nc; j++) {
            double re = 0, im = 0;
            for (size_t c = 0; c < nc; c++) {
                double ar = s->chi_re[i * nc + c], ai = -s->chi_im[i * nc + c];
                double br = s->chi_re[j * nc + c], bi = s->chi_im[j * nc + c];
                re += (double)s->class_size[c] * (ar * br - ai * bi);
                im += (double)s->class_size[c] * (ar * bi + ai * br);
            }
            assert_true(fabs(re - (i == j ? (double)g : 0)) < 1e-8);
            assert_true(fabs(im) < 1e-8);
        }
    }
    assert_int_equal(d2, g);
    for (size_t c = 0; c < nc; c++)
        for (size_t e = 0; e < nc; e++) {
            double re = 0;
            for (size_t i = 0; i < nc; i++)
                re += s->chi_re[i * nc + c] * s->chi_re[i * nc + e] +
                      s->chi_im[i * nc + c] * s->chi_im[i * nc + e];
            assert_true(fabs(re - (c == e ? (double)g / (double)s->class_size[c] : 0)) < 1e-8);
        }
}

/* U^T M0 U = I and every mode a^T M0 a = 1, K0 a = w^2 M0 a. */
static void check_modes(const qd_linear *lin, const qd_symmetry *s) {
    size_t n = s->n;
    for (size_t a = 0; a < n; a++)
        for (size_t b = 0; b < n; b++) {
            double t = 0;
            for (size_t i = 0; i < n; i++)
                for (size_t j = 0; j < n; j++)
                    t += s->U[i * n + a] * lin->M[i * n + j] * s->U[j * n + b];
            assert_true(fabs(t - (a == b)) < 1e-10);
        }
    assert_true(s->offblock < 1e-10);
    double big = 0;
    for (size_t j = 0; j < n; j++)
        big = fmax(big, fabs(s->omega2[j]));
    for (size_t j = 0; j < n; j++)
        for (size_t i = 0; i < n; i++) {
            double ka = 0, ma = 0;
            for (size_t l = 0; l < n; l++) {
                ka += lin->K[i * n + l] * s->shapes[l * n + j];
                ma += lin->M[i * n + l] * s->shapes[l * n + j];
            }
            assert_true(fabs(ka - s->omega2[j] * ma) < 1e-9 * big);
        }
}

static size_t irrep_named(const qd_symmetry *s, const char *name) {
    for (size_t i = 0; i < s->nirrep; i++)
        if (strcmp(s->label[i], name) == 0)
            return i;
    fail_msg("no irrep %s", name);
    return 0;
}

static const char *mode_label(const qd_symmetry *s, size_t j) {
    return s->label[s->block_irrep[s->mode_block[j]]];
}

static size_t count_kind(const qd_symmetry *s, qd_mode_kind k) {
    size_t c = 0;
    for (size_t j = 0; j < s->n; j++)
        c += s->mode_kind[j] == k;
    return c;
}

static void test_triangle(void **state) {
    qt_system *s = qt_system_derive(state, TRIANGLE, false);
    double q[6] = {0, 0, 1, 0, 0.5, sqrt(3) / 2}, k = 5, m = 2;
    qd_linear lin;
    qd_symmetry sym;
    analyse(s, q, &lin, &sym);
    assert_true(sym.geometric);
    assert_int_equal(sym.order, 6);
    assert_int_equal(sym.nclass, 3);
    assert_string_equal(sym.name, "C3v");
    check_orthogonality(&sym);
    /* chi = (6, 0, 0): only E leaves every particle in place */
    for (size_t c = 0; c < 3; c++)
        assert_true(fabs(sym.chi[c] - (c == 0 ? 6 : 0)) < 1e-10);
    assert_int_equal(sym.mult[irrep_named(&sym, "A1")], 1);
    assert_int_equal(sym.mult[irrep_named(&sym, "A2")], 1);
    assert_int_equal(sym.mult[irrep_named(&sym, "E")], 2);
    check_modes(&lin, &sym);
    double want[6] = {0, 0, 0, 1.5 * k / m, 1.5 * k / m, 3 * k / m};
    for (size_t j = 0; j < 6; j++)
        assert_true(fabs(sym.omega2[j] - want[j]) < 1e-10 * k / m);
    assert_string_equal(mode_label(&sym, 3), "E");
    assert_string_equal(mode_label(&sym, 4), "E");
    assert_int_equal(sym.mode_degeneracy[3], 2);
    assert_string_equal(mode_label(&sym, 5), "A1");
    assert_int_equal(sym.mode_kind[5], QD_MODE_VIBRATION);
    /* the zero modes: two translations (E) and the rotation (A2) */
    assert_int_equal(count_kind(&sym, QD_MODE_TRANSLATION), 2);
    assert_int_equal(count_kind(&sym, QD_MODE_ROTATION), 1);
    for (size_t j = 0; j < 3; j++)
        assert_string_equal(mode_label(&sym, j),
                            sym.mode_kind[j] == QD_MODE_ROTATION ? "A2" : "E");
    qd_symmetry_free(&sym);
    qd_linear_free(&lin);
}

/* The rotations alone (C3, a subgroup of C3v): complex characters, the pair
 * Ea, Eb merged into one real block of degeneracy 2 (seed-desloge-B.md
 * pitfall 14); the rotation now shares A with the breathing mode. */
static void test_triangle_c3(void **state) {
    qt_system *s = qt_system_derive(state, TRIANGLE, false);
    double q[6] = {0, 0, 1, 0, 0.5, sqrt(3) / 2}, k = 5, m = 2;
    qd_linear lin;
    qd_symmetry sym, c3;
    analyse(s, q, &lin, &sym);
    double S[3 * 36], R[3 * 9];
    size_t got = 0;
    for (size_t g = 0; g < sym.order; g++) {
        const double *r = sym.R + 9 * g;
        double det = r[0] * (r[4] * r[8] - r[5] * r[7]) - r[1] * (r[3] * r[8] - r[5] * r[6]) +
                     r[2] * (r[3] * r[7] - r[4] * r[6]);
        if (det > 0) {
            assert_true(got < 3);
            memcpy(S + 36 * got, sym.S + 36 * g, 36 * sizeof *S);
            memcpy(R + 9 * got, r, 9 * sizeof *R);
            got++;
        }
    }
    assert_int_equal(got, 3);
    assert_int_equal(qd_symmetry_from_ops(s->ctx, &lin, 3, S, R, &c3), QD_OK);
    assert_string_equal(c3.name, "C3");
    check_orthogonality(&c3);
    assert_int_equal(qd_symmetry_reduce(s->ctx, &lin, &c3), QD_OK);
    check_modes(&lin, &c3);
    assert_int_equal(c3.nblock, 2);
    size_t pair = c3.block_size[0] == 4 ? 0 : 1;
    assert_int_equal(c3.block_size[pair], 4);
    assert_int_equal(c3.block_size[1 - pair], 2);
    assert_true(c3.block_pair[pair] != c3.block_irrep[pair]);
    char lab[32];
    qd_symmetry_block_label(&c3, pair, lab, sizeof lab);
    assert_string_equal(lab, "E");
    double want[6] = {0, 0, 0, 1.5 * k / m, 1.5 * k / m, 3 * k / m};
    for (size_t j = 0; j < 6; j++)
        assert_true(fabs(c3.omega2[j] - want[j]) < 1e-10 * k / m);
    assert_int_equal(c3.mode_degeneracy[3], 2);
    assert_int_equal(c3.mode_block[5], 1 - pair);
    qd_symmetry_free(&c3);
    qd_symmetry_free(&sym);
    qd_linear_free(&lin);
}

static void test_triatomic(void **state) {
    qt_system *s = qt_system_derive(state, TRIATOMIC, false);
    double q[3] = {-1, 0, 1}, m = 1, M = 3, k = 2;
    qd_linear lin;
    qd_symmetry sym;
    analyse(s, q, &lin, &sym);
    assert_int_equal(sym.order, 2);
    check_orthogonality(&sym);
    check_modes(&lin, &sym);
    /* the mirror exchanges the end masses: tr S = -1 */
    assert_true(fabs(sym.chi[1] + 1) < 1e-12);
    assert_true(fabs(sym.omega2[0]) < 1e-12);
    assert_int_equal(sym.mode_kind[0], QD_MODE_TRANSLATION);
    assert_true(fabs(sym.omega2[1] - k / m) < 1e-12);
    assert_true(fabs(sym.omega2[2] - k / m * (1 + 2 * m / M)) < 1e-12);
    /* the symmetric stretch is even under the mirror, the other two odd */
    size_t even = sym.block_irrep[sym.mode_block[1]];
    assert_true(sym.chi_re[even * 2 + 1] > 0);
    assert_true(sym.block_irrep[sym.mode_block[2]] != even);
    assert_true(sym.block_irrep[sym.mode_block[0]] != even);
    qd_symmetry_free(&sym);
    qd_linear_free(&lin);
}

static void test_square(void **state) {
    qt_system *s = qt_system_derive(state, SQUARE, false);
    double q[8] = {1, 1, -1, 1, -1, -1, 1, -1}, m = 1.5, k = 2, kd = 3;
    qd_linear lin;
    qd_symmetry sym;
    analyse(s, q, &lin, &sym);
    assert_int_equal(sym.order, 8);
    assert_int_equal(sym.nclass, 5);
    assert_string_equal(sym.name, "C4v");
    check_orthogonality(&sym);
    check_modes(&lin, &sym);
    const char *ones[] = {"A1", "A2", "B1", "B2"};
    for (size_t i = 0; i < 4; i++)
        assert_int_equal(sym.mult[irrep_named(&sym, ones[i])], 1);
    assert_int_equal(sym.mult[irrep_named(&sym, "E")], 2);
    double want[8] = {0, 0, 0, 2 * k / m, 2 * k / m, 2 * k / m, 2 * kd / m, 2 * (k + kd) / m};
    for (size_t j = 0; j < 8; j++)
        assert_true(fabs(sym.omega2[j] - want[j]) < 1e-10);
    assert_string_equal(mode_label(&sym, 7), "A1");
    /* 2k/m three times: the E pair and one B, an accidental degeneracy the
     * blocks separate */
    size_t e = 0, b = 0;
    for (size_t j = 3; j < 6; j++) {
        e += strcmp(mode_label(&sym, j), "E") == 0;
        b += mode_label(&sym, j)[0] == 'B';
    }
    assert_int_equal(e, 2);
    assert_int_equal(b, 1);
    assert_true(mode_label(&sym, 6)[0] == 'B');
    assert_int_equal(count_kind(&sym, QD_MODE_TRANSLATION), 2);
    assert_int_equal(count_kind(&sym, QD_MODE_ROTATION), 1);
    qd_symmetry_free(&sym);
    qd_linear_free(&lin);
}

static void test_tetrahedron(void **state) {
    qt_system *s = qt_system_derive(state, TETRA, false);
    double c = 1 / sqrt(3), m = 1, k = 2, kh = 0.5;
    double q[15] = {0, 0, 0, c, c, c, c, -c, -c, -c, c, -c, -c, -c, c};
    qd_linear lin;
    qd_symmetry sym;
    analyse(s, q, &lin, &sym);
    assert_int_equal(sym.order, 24);
    assert_int_equal(sym.nclass, 5);
    assert_string_equal(sym.name, "Td");
    check_orthogonality(&sym);
    check_modes(&lin, &sym);
    assert_int_equal(sym.mult[irrep_named(&sym, "A1")], 1);
    assert_int_equal(sym.mult[irrep_named(&sym, "A2")], 0);
    assert_int_equal(sym.mult[irrep_named(&sym, "E")], 1);
    assert_int_equal(sym.mult[irrep_named(&sym, "T1")], 1);
    assert_int_equal(sym.mult[irrep_named(&sym, "T2")], 3);
    assert_int_equal(count_kind(&sym, QD_MODE_TRANSLATION), 3);
    assert_int_equal(count_kind(&sym, QD_MODE_ROTATION), 3);
    for (size_t j = 0; j < 6; j++) {
        assert_true(fabs(sym.omega2[j]) < 1e-12);
        assert_string_equal(mode_label(&sym, j),
                            sym.mode_kind[j] == QD_MODE_ROTATION ? "T1" : "T2");
    }
    /* SymPy, M^-1 K of this model: 1/2 (x2), 35/18 -+ sqrt(721)/18 (x3 each), 4 */
    double tlo = (35 - sqrt(721)) / 18, thi = (35 + sqrt(721)) / 18;
    double want[9] = {tlo, tlo, tlo, 0.5, 0.5, thi, thi, thi, (k + 4 * kh) / m};
    const char *lab[9] = {"T2", "T2", "T2", "E", "E", "T2", "T2", "T2", "A1"};
    for (size_t j = 0; j < 9; j++) {
        assert_true(fabs(sym.omega2[6 + j] - want[j]) < 1e-10);
        assert_string_equal(mode_label(&sym, 6 + j), lab[j]);
        assert_int_equal(sym.mode_degeneracy[6 + j], lab[j][0] == 'T' ? 3 : lab[j][0] == 'E' ? 2 : 1);
    }
    qd_symmetry_free(&sym);
    qd_linear_free(&lin);
}

/* w_k^2 = (4k/m) sin^2(pi j/N), each 0 < j < N/2 twice. */
static void ring_omega2(size_t N, double k, double m, double *w) {
    size_t pos = 0;
    for (size_t j = 0; 2 * j <= N; j++) {
        double v = 4 * k / m * pow(sin(PI * (double)j / (double)N), 2);
        w[pos++] = v;
        if (j && 2 * j != N)
            w[pos++] = v;
    }
    for (size_t i = 1; i < N; i++)   /* ascending */
        for (size_t j = i; j > 0 && w[j - 1] > w[j]; j--) {
            double t = w[j];
            w[j] = w[j - 1];
            w[j - 1] = t;
        }
}

static void test_ring6(void **state) {
    double want[6];
    ring_omega2(6, 1, 1, want);
    for (int abstract = 0; abstract < 2; abstract++) {
        qt_system *s = qt_system_derive(state, abstract ? RING6_ABSTRACT : RING6_PARTICLES, false);
        qd_linear lin;
        qd_symmetry sym;
        analyse(s, NULL, &lin, &sym);
        assert_int_equal(sym.geometric, !abstract);
        assert_int_equal(sym.order, 12);   /* D6: six rotations, six mirrors */
        assert_int_equal(sym.nclass, 6);
        if (!abstract)
            assert_string_equal(sym.name, "C6v");
        else
            assert_string_equal(sym.name, "");
        check_orthogonality(&sym);
        check_modes(&lin, &sym);
        for (size_t j = 0; j < 6; j++)
            assert_true(fabs(sym.omega2[j] - want[j]) < 1e-12);
        assert_int_equal(sym.mode_degeneracy[1], 2);
        assert_int_equal(sym.mode_degeneracy[5], 1);
        if (!abstract)   /* the rotation of the ring about its axis */
            assert_int_equal(sym.mode_kind[0], QD_MODE_ROTATION);
        qd_symmetry_free(&sym);
        qd_linear_free(&lin);
        qt_system_teardown(state);
    }
}

/* The ring of N masses by its matrices (M = m I, K circulant). */
static void ring_linear(size_t N, double k, double m, qd_linear *lin) {
    size_t nn = N * N;
    lin->n = N;
    lin->M = calloc(nn, sizeof *lin->M);
    lin->K = calloc(nn, sizeof *lin->K);
    lin->C = calloc(nn, sizeof *lin->C);
    lin->G = calloc(nn, sizeof *lin->G);
    assert_non_null(lin->M);
    assert_non_null(lin->K);
    for (size_t i = 0; i < N; i++) {
        lin->M[i * N + i] = m;
        lin->K[i * N + i] = 2 * k;
        lin->K[i * N + (i + 1) % N] -= k;
        lin->K[i * N + (i + N - 1) % N] -= k;
    }
}

static void free_ring(qd_linear *lin) {
    free(lin->M);
    free(lin->K);
    free(lin->C);
    free(lin->G);
}

static void test_ring_fast(void **state) {
    (void)state;
    size_t N = 1000;
    double k = 3, m = 0.5;
    qd_ctx *ctx = qd_ctx_new();
    qd_linear lin;
    ring_linear(N, k, m, &lin);
    assert_int_equal(qd_cyclic_cell(&lin), 1);
    qd_cyclic_modes cm;
    assert_int_equal(qd_cyclic_solve(ctx, &lin, 1, &cm), QD_OK);
    double *want = malloc(N * sizeof *want);
    assert_non_null(want);
    ring_omega2(N, k, m, want);
    for (size_t j = 0; j < N; j++)
        assert_true(fabs(cm.omega2[j] - want[j]) < 1e-11 * 4 * k / m);
    assert_int_equal(cm.harmonic[0], 0);
    assert_int_equal(cm.harmonic[N - 1], N / 2);   /* the highest: neighbours opposite */
    assert_int_equal(cm.degeneracy[1], 2);
    qd_cyclic_modes_free(&cm);
    /* a shift that is not a symmetry is refused; a broken ring has none */
    assert_int_equal(qd_cyclic_solve(ctx, &lin, 3, &cm), QD_ERR_ARG);   /* 3 does not divide 1000 */
    qd_ctx_clear_error(ctx);
    lin.K[0] += 1;
    assert_int_equal(qd_cyclic_cell(&lin), 0);
    free(want);
    free_ring(&lin);
    qd_ctx_free(ctx);
}

/* Two coordinates per cell (a diatomic ring, masses m1, m2 alternating):
 * the fast path against the full generalized eigenproblem. */
static void test_ring_cells(void **state) {
    (void)state;
    size_t N = 40, n = 2 * N;
    qd_ctx *ctx = qd_ctx_new();
    qd_linear lin;
    ring_linear(n, 2, 1, &lin);
    for (size_t i = 1; i < n; i += 2)
        lin.M[i * n + i] = 3;
    assert_int_equal(qd_cyclic_cell(&lin), 2);
    qd_cyclic_modes cm;
    qd_modes_result full;
    assert_int_equal(qd_cyclic_solve(ctx, &lin, 2, &cm), QD_OK);
    assert_int_equal(qd_modes_solve(ctx, &lin, &full), QD_OK);
    for (size_t j = 0; j < n; j++)
        assert_true(fabs(cm.omega2[j] - full.omega2[j]) < 1e-10);
    qd_cyclic_modes_free(&cm);
    qd_modes_result_free(&full);
    free_ring(&lin);
    qd_ctx_free(ctx);
}

static void test_no_symmetry(void **state) {
    qt_system *s = qt_system_derive(state, SCALENE, false);
    /* a triangle of sides 1, 1.2, 1.5 at rest */
    double c = (1 + 1.5 * 1.5 - 1.2 * 1.2) / 2, q[6] = {0, 0, 1, 0, c, sqrt(1.5 * 1.5 - c * c)};
    qd_linear lin;
    qd_symmetry sym;
    analyse(s, q, &lin, &sym);
    assert_int_equal(sym.order, 1);
    qd_symmetry_free(&sym);
    qd_linear_free(&lin);
}

/* {E, C3} without C3^2 is not closed; a map that changes K0 is refused. */
static void test_not_a_group(void **state) {
    qt_system *s = qt_system_derive(state, RING6_ABSTRACT, false);
    qd_linear lin;
    point p;
    at(s, NULL, &p);
    assert_int_equal(qd_linear_about(s->ctx, s->eom, s->model, p.n, p.syms, p.vals, &lin), QD_OK);
    double S[2 * 36] = {0};
    for (size_t i = 0; i < 6; i++) {
        S[i * 6 + i] = 1;
        S[36 + ((i + 1) % 6) * 6 + i] = 1;   /* the shift by one */
    }
    qd_symmetry sym;
    assert_int_equal(qd_symmetry_from_ops(s->ctx, &lin, 2, S, NULL, &sym), QD_ERR_ARG);
    qd_symmetry_free(&sym);
    qd_ctx_clear_error(s->ctx);
    S[36 + 1 * 6 + 0] = 0;   /* s1 -> s3: not a symmetry of the ring */
    S[36 + 2 * 6 + 0] = 1;
    S[36 + 2 * 6 + 1] = 0;
    S[36 + 1 * 6 + 1] = 1;
    assert_int_equal(qd_symmetry_from_ops(s->ctx, &lin, 2, S, NULL, &sym), QD_ERR_ARG);
    qd_symmetry_free(&sym);
    qd_linear_free(&lin);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_teardown(test_triangle, qt_system_teardown),
        cmocka_unit_test_teardown(test_triangle_c3, qt_system_teardown),
        cmocka_unit_test_teardown(test_triatomic, qt_system_teardown),
        cmocka_unit_test_teardown(test_square, qt_system_teardown),
        cmocka_unit_test_teardown(test_tetrahedron, qt_system_teardown),
        cmocka_unit_test(test_ring6),
        cmocka_unit_test(test_ring_fast),
        cmocka_unit_test(test_ring_cells),
        cmocka_unit_test_teardown(test_no_symmetry, qt_system_teardown),
        cmocka_unit_test_teardown(test_not_a_group, qt_system_teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

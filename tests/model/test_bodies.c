/*
 * tests/model/test_bodies.c - rigid bodies in the model language: matrices,
 * rotations, angular velocity, kinetic energy, torques, inertia helpers.
 *
 * Expected values come from the textbooks (Goldstein 3rd ed. ch. 4; Desloge
 * ch. 63-64 and Byerly App. A, as re-derived in ../shared/reference/) or from
 * independent computation in the test (numeric integration of the moments
 * of inertia), never from the code under test.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "qdot/qdot.h"
#include "qdot/model.h"
#include "util/randexpr.h"

typedef const qd_expr *E;

static const double PI = 3.14159265358979323846;

static qd_model *parse(qd_ctx *ctx, const char *text) {
    qd_diag d;
    qd_model *m = qd_model_parse(ctx, text, &d);
    if (!m)
        fail_msg("%zu:%zu: %s [hint: %s]\n%s", d.line, d.col, d.message, d.hint, text);
    return m;
}

static E def(const qd_model *m, const char *name) {
    E e = qd_model_definition(m, name);
    if (!e)
        fail_msg("no scalar definition '%s'", name);
    return e;
}

static size_t add_syms(qd_ctx *ctx, E e, E *syms, size_t n) {
    E s[32];
    size_t k = qd_free_symbols(ctx, e, s, 32);
    assert_true(k <= 32);
    for (size_t i = 0; i < k; i++) {
        size_t j = 0;
        while (j < n && syms[j] != s[i])
            j++;
        if (j == n) {
            assert_true(n < 32);
            syms[n++] = s[i];
        }
    }
    return n;
}

/* a and b agree at 20 random points (every symbol in [0.2, 1.4]). */
static void same_value(qd_ctx *ctx, E a, E b, uint64_t seed) {
    assert_non_null(a);
    assert_non_null(b);
    E syms[32];
    size_t n = add_syms(ctx, b, syms, add_syms(ctx, a, syms, 0));
    qt_rng r = {seed};
    for (int k = 0; k < 20; k++) {
        double v[32], x, y;
        for (size_t i = 0; i < n; i++)
            v[i] = qt_uniform(&r, 0.2, 1.4);
        assert_int_equal(qd_eval(ctx, a, n, syms, v, &x), QD_OK);
        assert_int_equal(qd_eval(ctx, b, n, syms, v, &y), QD_OK);
        if (!(fabs(x - y) <= 1e-11 * (1 + fabs(x) + fabs(y))))
            fail_msg("seed %llu point %d: %.17g != %.17g", (unsigned long long)seed, k, x, y);
    }
}

static E S(qd_ctx *c, E a) { return qd_fn(c, QD_SIN, a); }
static E Co(qd_ctx *c, E a) { return qd_fn(c, QD_COS, a); }
static E mul3(qd_ctx *c, E a, E b, E d) { return qd_mul_n(c, 3, (E[]){a, b, d}); }
static E half(qd_ctx *c, E a) { return qd_mul(c, qd_rat(c, 1, 2), a); }

/* ---- the heavy symmetric top ------------------------------------------------- */

static const char *top_text =
    "coordinates phi, theta, psi\n"
    "parameters M = 3, A = 2, C = 5, h = 1/2, g = 9.81\n"
    "R = euler(phi, theta, psi)\n"
    "body top mass M inertia (A, A, C) at R*(0, 0, h) orientation R\n"
    "V = M*g*position(top).z\n"
    "w1 = omega(top).x\n"
    "w2 = omega(top).y\n"
    "w3 = omega(top).z\n"
    "s1 = omega_space(top).x\n"
    "s2 = omega_space(top).y\n"
    "s3 = omega_space(top).z\n";

/* w in body axes: Goldstein eq. 4.87, exactly (pointer equality). */
static void top_angular_velocity(void **state) {
    (void)state;
    qd_ctx *c = qd_ctx_new();
    qd_model *m = parse(c, top_text);
    E ph = qd_model_coord(m, 0), th = qd_model_coord(m, 1), ps = qd_model_coord(m, 2);
    E phd = qd_jet(c, ph, 1), thd = qd_jet(c, th, 1), psd = qd_jet(c, ps, 1);
    E w[3] = {
        qd_add(c, mul3(c, phd, S(c, th), S(c, ps)), qd_mul(c, thd, Co(c, ps))),
        qd_sub(c, mul3(c, phd, S(c, th), Co(c, ps)), qd_mul(c, thd, S(c, ps))),
        qd_add(c, qd_mul(c, phd, Co(c, th)), psd),
    };
    const char *names[3] = {"w1", "w2", "w3"};
    for (unsigned k = 0; k < 3; k++) {
        assert_ptr_equal(qd_model_body_omega(m, 0, k), qd_simplify(c, w[k]));
        assert_ptr_equal(def(m, names[k]), qd_model_body_omega(m, 0, k));
    }
    /* space axes: Desloge ch. 63 eq. 12 (seed-desloge-B.md, C8) */
    E s[3] = {
        qd_add(c, qd_mul(c, thd, Co(c, ph)), mul3(c, psd, S(c, ph), S(c, th))),
        qd_sub(c, qd_mul(c, thd, S(c, ph)), mul3(c, psd, Co(c, ph), S(c, th))),
        qd_add(c, phd, qd_mul(c, psd, Co(c, th))),
    };
    const char *snames[3] = {"s1", "s2", "s3"};
    for (unsigned k = 0; k < 3; k++) {
        assert_ptr_equal(def(m, snames[k]), qd_model_body_omega_space(m, 0, k));
        same_value(c, def(m, snames[k]), s[k], 100 + k);
    }
    assert_int_equal(qd_model_nbodies(m), 1);
    assert_string_equal(qd_model_body_name(m, 0), "top");
    assert_ptr_equal(qd_model_body_mass(m, 0), qd_lookup(c, "M"));
    assert_null(qd_model_body_omega(m, 1, 0));
    qd_diag d;
    assert_true(qd_model_where(m, "body:top", &d));
    assert_int_equal(d.line, 4);
    assert_int_equal(d.col, 6);
    qd_model_free(m);
    qd_ctx_free(c);
}

/* The heavy top, its centre of mass at h on the axis: T as in Goldstein
 * 3rd ed. sec. 5.7 and Desloge ch. 64 Ex. 1 (seed-desloge-B.md, C10) with the
 * moment about the fixed point A + M h^2 (parallel axes); V = M g h cos(theta). */
static void top_kinetic_energy(void **state) {
    (void)state;
    qd_ctx *c = qd_ctx_new();
    qd_model *m = parse(c, top_text);
    E th = qd_model_coord(m, 1);
    E phd = qd_jet(c, qd_model_coord(m, 0), 1), thd = qd_jet(c, th, 1);
    E psd = qd_jet(c, qd_model_coord(m, 2), 1);
    E M = qd_lookup(c, "M"), A = qd_lookup(c, "A"), C = qd_lookup(c, "C"), h = qd_lookup(c, "h");
    E A1 = qd_add(c, A, mul3(c, M, h, h));
    E T = qd_add(c, half(c, qd_mul(c, A1, qd_add(c, qd_powi(c, thd, 2),
                                                   qd_mul(c, qd_powi(c, phd, 2),
                                                          qd_powi(c, S(c, th), 2))))),
                 half(c, qd_mul(c, C, qd_powi(c, qd_add(c, psd, qd_mul(c, phd, Co(c, th))), 2))));
    same_value(c, qd_model_kinetic(m), T, 7);
    same_value(c, qd_model_potential(m), mul3(c, M, qd_lookup(c, "g"), qd_mul(c, h, Co(c, th))), 8);
    qd_model_free(m);
    /* about the centre of mass alone: T = A/2 (theta'^2 + phi'^2 sin^2) + C/2 (psi' + phi' cos)^2 */
    m = parse(c, "coordinates phi, theta, psi\nparameters A = 2, C = 5\n"
                 "body top mass 1 inertia (A, A, C) at (0, 0, 0) orientation euler(phi, theta, psi)\n");
    E T0 = qd_add(c, half(c, qd_mul(c, A, qd_add(c, qd_powi(c, thd, 2),
                                                  qd_mul(c, qd_powi(c, phd, 2),
                                                         qd_powi(c, S(c, th), 2))))),
                  half(c, qd_mul(c, C, qd_powi(c, qd_add(c, psd, qd_mul(c, phd, Co(c, th))), 2))));
    assert_ptr_equal(qd_expand(c, qd_simplify(c, qd_model_kinetic(m))),
                     qd_expand(c, qd_simplify(c, T0)));
    same_value(c, qd_model_kinetic(m), T0, 9);
    qd_model_free(m);
    qd_ctx_free(c);
}

/* Byerly App. A Sec. 8 (seed-byerly.md): z-y-z angles with psi the
 * precession, theta, phi the spin: R = Rz(psi) Ry(theta) Rz(phi), and
 * w1 = theta' sin(phi) - psi' sin(theta) cos(phi),
 * w2 = theta' cos(phi) + psi' sin(theta) sin(phi), w3 = psi' cos(theta) + phi'. */
static void byerly_zyz(void **state) {
    (void)state;
    qd_ctx *c = qd_ctx_new();
    qd_model *m = parse(c, "coordinates psi, theta, phi\n"
                           "body b mass 1 inertia (1, 2, 3) at (0, 0, 0) "
                           "orientation euler_zyz(psi, theta, phi)\n");
    E ps = qd_model_coord(m, 0), th = qd_model_coord(m, 1), ph = qd_model_coord(m, 2);
    E psd = qd_jet(c, ps, 1), thd = qd_jet(c, th, 1), phd = qd_jet(c, ph, 1);
    E w[3] = {
        qd_sub(c, qd_mul(c, thd, S(c, ph)), mul3(c, psd, S(c, th), Co(c, ph))),
        qd_add(c, qd_mul(c, thd, Co(c, ph)), mul3(c, psd, S(c, th), S(c, ph))),
        qd_add(c, qd_mul(c, psd, Co(c, th)), phd),
    };
    for (unsigned k = 0; k < 3; k++)
        assert_ptr_equal(qd_model_body_omega(m, 0, k), qd_simplify(c, w[k]));
    qd_model_free(m);
    qd_ctx_free(c);
}

/* ---- rotations ------------------------------------------------------------------ */

static void rotation_of(qd_ctx *c, const char *R, qd_model **m) {
    char text[512];
    snprintf(text, sizeof text, "coordinates a, b, g\nparameters k = 1\n"
             "body x mass 1 inertia (1, 1, 1) at (0, 0, 0) orientation %s\n", R);
    *m = parse(c, text);
}

/* Every rotation is orthogonal with determinant 1, exactly after simplify. */
static void rotations_orthogonal(void **state) {
    (void)state;
    const char *rs[] = {"rot_x(a)", "rot_y(a)", "rot_z(a)", "euler(a, b, g)", "euler_zyz(a, b, g)",
                        "tait_bryan(a, b, g)", "rot_x(a)*euler(b, g, a)*rot_y(2*t)",
                        "transpose(rot_z(k*t))*rot_y(b)"};
    for (size_t r = 0; r < sizeof rs / sizeof rs[0]; r++) {
        qd_ctx *c = qd_ctx_new();
        qd_model *m;
        rotation_of(c, rs[r], &m);
        E R[9];
        for (unsigned i = 0; i < 9; i++)
            R[i] = qd_model_body_rotation(m, 0, i / 3, i % 3);
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++) {
                E d = qd_add_n(c, 3, (E[]){qd_mul(c, R[i], R[j]), qd_mul(c, R[3 + i], R[3 + j]),
                                          qd_mul(c, R[6 + i], R[6 + j])});
                if (qd_simplify(c, d) != qd_int(c, i == j))
                    fail_msg("%s: (R^T R)[%d][%d] is not %d", rs[r], i, j, i == j);
            }
        E det = qd_add_n(c, 3, (E[]){
            mul3(c, R[0], qd_sub(c, qd_mul(c, R[4], R[8]), qd_mul(c, R[5], R[7])), qd_int(c, 1)),
            mul3(c, R[1], qd_sub(c, qd_mul(c, R[5], R[6]), qd_mul(c, R[3], R[8])), qd_int(c, 1)),
            mul3(c, R[2], qd_sub(c, qd_mul(c, R[3], R[7]), qd_mul(c, R[4], R[6])), qd_int(c, 1))});
        if (qd_simplify(c, det) != qd_int(c, 1))
            fail_msg("%s: det R is not 1", rs[r]);
        same_value(c, det, qd_int(c, 1), 40 + r);
        qd_model_free(m);
        qd_ctx_free(c);
    }
}

/* euler(phi, theta, psi) is rot_z rot_x rot_z and the transpose of
 * Goldstein's passive A = BCD (3rd ed. sec. 4.4, written out entry by entry). */
static void euler_is_goldstein_transpose(void **state) {
    (void)state;
    qd_ctx *c = qd_ctx_new();
    qd_model *m1, *m2;
    rotation_of(c, "euler(a, b, g)", &m1);
    rotation_of(c, "rot_z(a)*rot_x(b)*rot_z(g)", &m2);
    E ph = qd_lookup(c, "a"), th = qd_lookup(c, "b"), ps = qd_lookup(c, "g");
    E cf = Co(c, ph), sf = S(c, ph), ct = Co(c, th), st = S(c, th), cp = Co(c, ps), sp = S(c, ps);
    E A[9] = {
        qd_sub(c, qd_mul(c, cp, cf), mul3(c, ct, sf, sp)),
        qd_add(c, qd_mul(c, cp, sf), mul3(c, ct, cf, sp)),
        qd_mul(c, sp, st),
        qd_sub(c, qd_neg(c, qd_mul(c, sp, cf)), mul3(c, ct, sf, cp)),
        qd_add(c, qd_neg(c, qd_mul(c, sp, sf)), mul3(c, ct, cf, cp)),
        qd_mul(c, cp, st),
        qd_mul(c, st, sf),
        qd_neg(c, qd_mul(c, st, cf)),
        ct,
    };
    for (unsigned i = 0; i < 3; i++)
        for (unsigned j = 0; j < 3; j++) {
            E r1 = qd_expand(c, qd_model_body_rotation(m1, 0, i, j));
            assert_ptr_equal(r1, qd_expand(c, qd_model_body_rotation(m2, 0, i, j)));
            assert_ptr_equal(r1, qd_expand(c, A[3 * j + i]));
        }
    qd_model_free(m1);
    qd_model_free(m2);
    qd_ctx_free(c);
}

/* tait_bryan(yaw, pitch, roll) carries the body x axis (the heading) to
 * (cos yaw cos pitch, sin yaw cos pitch, -sin pitch). */
static void tait_bryan_heading(void **state) {
    (void)state;
    qd_ctx *c = qd_ctx_new();
    qd_model *m;
    rotation_of(c, "tait_bryan(a, b, g)", &m);
    E y = qd_lookup(c, "a"), p = qd_lookup(c, "b");
    E h[3] = {qd_mul(c, Co(c, y), Co(c, p)), qd_mul(c, S(c, y), Co(c, p)), qd_neg(c, S(c, p))};
    for (unsigned i = 0; i < 3; i++)
        assert_ptr_equal(qd_expand(c, qd_model_body_rotation(m, 0, i, 0)), h[i]);
    qd_model_free(m);
    qd_ctx_free(c);
}

/* Matrix arithmetic: literals, products, transpose, sums, scalars, derivatives. */
static void matrix_arithmetic(void **state) {
    (void)state;
    qd_ctx *c = qd_ctx_new();
    qd_model *m = parse(c,
        "coordinates q\n"
        "M = [[1, 2, 3],\n"
        "     [4, 5, 6],\n"
        "     [7, 8, 10]]\n"
        "v = M*(1, 1, 1)\n"
        "v1 = v.x\nv2 = v.y\nv3 = v.z\n"
        "u = transpose(M)*(1, 0, 0)\n"          /* first row of M */
        "u2 = u.y\n"
        "W = 2*M*M/4 - M*M/2 + [[0, 0, 0], [0, 0, 0], [0, 0, q]]\n"
        "w3 = (W*(0, 0, 1)).z\n"
        "P = rot_z(q)'\n"                        /* d/dt of a rotation */
        "p1 = (P*(1, 0, 0)).x\n"
        "n = -rot_z(q)*(1, 0, 0)\n"
        "n2 = n.y\n"
        "T = q'^2\n");
    E q = qd_model_coord(m, 0);
    assert_ptr_equal(def(m, "v1"), qd_int(c, 6));
    assert_ptr_equal(def(m, "v2"), qd_int(c, 15));
    assert_ptr_equal(def(m, "v3"), qd_int(c, 25));
    assert_ptr_equal(def(m, "u2"), qd_int(c, 2));
    assert_ptr_equal(def(m, "w3"), q);
    assert_ptr_equal(def(m, "p1"), qd_neg(c, qd_mul(c, qd_jet(c, q, 1), S(c, q))));
    assert_ptr_equal(def(m, "n2"), qd_neg(c, S(c, q)));
    assert_null(qd_model_definition(m, "M")); /* a matrix is not a scalar */
    qd_model_free(m);
    qd_ctx_free(c);
}

/* ---- bodies ----------------------------------------------------------------------- */

/* A rod of length l pivoted at one end, swinging in the xy plane:
 * T = (m l^2/3)/2 q'^2 (moment about the end), V = -m g l/2 cos q. */
static void compound_pendulum(void **state) {
    (void)state;
    const char *forms[] = {
        /* the rod along body z, turned into the plane */
        "body rod mass m inertia rod(m, l) at (l/2*sin(q), -l/2*cos(q)) "
        "orientation rot_z(q)*rot_x(pi/2)\n",
        /* the moments written out, axis of rotation z */
        "body rod mass m inertia (m*l^2/12, 0, m*l^2/12) at (l/2*sin(q), -l/2*cos(q)) "
        "orientation rot_z(q)\n",
        /* the full tensor, and the centre of mass as a body-fixed point */
        "body rod mass m inertia [[m*l^2/12, 0, 0], [0, 0, 0], [0, 0, m*l^2/12]] at (0, 0, 0) "
        "orientation rot_z(q)\n",
    };
    for (size_t f = 0; f < 3; f++) {
        qd_ctx *c = qd_ctx_new();
        char text[512];
        snprintf(text, sizeof text, "coordinates q\nparameters m = 2, l = 3, g = 9.81\n%s"
                 "V = m*g*position(rod).y\n", forms[f]);
        qd_model *m = parse(c, text);
        E q = qd_model_coord(m, 0), M = qd_lookup(c, "m"), l = qd_lookup(c, "l");
        E T = half(c, mul3(c, qd_rat(c, 1, 3), qd_mul(c, M, qd_powi(c, l, 2)),
                           qd_powi(c, qd_jet(c, q, 1), 2)));
        if (f < 2) {
            assert_ptr_equal(qd_simplify(c, qd_model_kinetic(m)), qd_simplify(c, T));
            same_value(c, qd_model_potential(m),
                       qd_neg(c, mul3(c, M, qd_lookup(c, "g"), qd_mul(c, half(c, l), Co(c, q)))),
                       3);
        } else {
            /* the centre of mass fixed: only T about it, m l^2/24 q'^2 = T/4 */
            assert_ptr_equal(qd_simplify(c, qd_model_kinetic(m)),
                             qd_simplify(c, qd_mul(c, qd_rat(c, 1, 4), T)));
        }
        qd_model_free(m);
        qd_ctx_free(c);
    }
}

/* point(b, a) = r + R a: a planar body at (x, y) turned by q. */
static void body_point(void **state) {
    (void)state;
    qd_ctx *c = qd_ctx_new();
    qd_model *m = parse(c, "coordinates x, y, q\nparameters a = 2, m = 1\n"
                           "body plate mass m inertia disk(m, a) at (x, y) orientation rot_z(q)\n"
                           "P = point(plate, (a, 0, 0))\n"
                           "px = P.x\npy = P.y\npz = P.z\n"
                           "Q2 = point(plate, (0, a, 1))\n"
                           "qx = Q2.x\nqz = Q2.z\n"
                           "rz = rotation(plate)*(0, 0, 1)\n"
                           "r3 = rz.z\n");
    E x = qd_model_coord(m, 0), y = qd_model_coord(m, 1), q = qd_model_coord(m, 2);
    E a = qd_lookup(c, "a");
    assert_ptr_equal(def(m, "px"), qd_add(c, x, qd_mul(c, a, Co(c, q))));
    assert_ptr_equal(def(m, "py"), qd_add(c, y, qd_mul(c, a, S(c, q))));
    assert_ptr_equal(def(m, "pz"), qd_int(c, 0));
    assert_ptr_equal(def(m, "qx"), qd_sub(c, x, qd_mul(c, a, S(c, q))));
    assert_ptr_equal(def(m, "qz"), qd_int(c, 1));
    assert_ptr_equal(def(m, "r3"), qd_int(c, 1));
    qd_model_free(m);
    qd_ctx_free(c);
}

/* Body without orientation: it only translates, T = M/2 |r'|^2. */
static void translating_body(void **state) {
    (void)state;
    qd_ctx *c = qd_ctx_new();
    qd_model *m = parse(c, "coordinates x, y\nparameters M = 2\n"
                           "body b mass M inertia sphere(M, 1) at (x, y, x*y)\n"
                           "particle M at (x, y, x*y)\n");
    E T = qd_model_kinetic(m);
    /* twice the particle's */
    same_value(c, T, qd_mul(c, qd_int(c, 2), half(c, qd_mul(c, qd_lookup(c, "M"), qd_add_n(c, 3,
        (E[]){qd_powi(c, qd_jet(c, qd_model_coord(m, 0), 1), 2),
              qd_powi(c, qd_jet(c, qd_model_coord(m, 1), 1), 2),
              qd_powi(c, qd_dt(c, qd_mul(c, qd_model_coord(m, 0), qd_model_coord(m, 1))), 2)})))),
               11);
    for (unsigned k = 0; k < 3; k++)
        assert_ptr_equal(qd_model_body_omega(m, 0, k), qd_int(c, 0));
    qd_model_free(m);
    qd_ctx_free(c);
}

/* A full tensor is a tensor: the body turned by Q with principal moments
 * equals the body with the tensor Q diag(A, B, C) Q^T in the unturned axes. */
static void tensor_rotates(void **state) {
    (void)state;
    qd_ctx *c = qd_ctx_new();
    const char *head = "coordinates a, b, g\nparameters A = 1, B = 2, C = 5/2, s = 1/3\n"
                       "Q = rot_x(s)*rot_y(2*s)\n"
                       "D = [[A, 0, 0], [0, B, 0], [0, 0, C]]\n";
    char t1[512], t2[512];
    snprintf(t1, sizeof t1, "%sbody x mass 1 inertia (A, B, C) at (0, 0, 0) "
             "orientation euler(a, b, g)*Q\n", head);
    snprintf(t2, sizeof t2, "%sbody x mass 1 inertia Q*D*transpose(Q) at (0, 0, 0) "
             "orientation euler(a, b, g)\n", head);
    qd_model *m1 = parse(c, t1), *m2 = parse(c, t2);
    same_value(c, qd_model_kinetic(m1), qd_model_kinetic(m2), 21);
    qd_model_free(m1);
    qd_model_free(m2);
    qd_ctx_free(c);
}

/* A torque on a rotor turning about z: Q_phi = G_z.  On the top
 * (Desloge ch. 64 eqs. 18-20): Q_theta = G . line of nodes (cos phi, sin phi, 0),
 * Q_phi = G_z, Q_psi = G . body axis 3 = G . R (0, 0, 1). */
static void torques(void **state) {
    (void)state;
    qd_ctx *c = qd_ctx_new();
    qd_model *m = parse(c, "coordinates phi\nparameters Gx = 1, Gy = 2, Gz = 3\n"
                           "body rotor mass 1 inertia (1, 1, 2) at (0, 0, 0) orientation rot_z(phi)\n"
                           "torque (Gx, Gy, Gz) on rotor\n");
    assert_ptr_equal(qd_model_force(m, 0), qd_lookup(c, "Gz"));
    qd_model_free(m);
    m = parse(c, "coordinates phi, theta, psi\nparameters Gx = 1, Gy = 2, Gz = 3\n"
                 "body top mass 1 inertia (1, 1, 2) at (0, 0, 0) orientation euler(phi, theta, psi)\n"
                 "torque (Gx, Gy, Gz) on top\n"
                 "torque (0, 0, t) on top\n");
    E ph = qd_model_coord(m, 0), th = qd_model_coord(m, 1);
    E Gx = qd_lookup(c, "Gx"), Gy = qd_lookup(c, "Gy"), Gz = qd_lookup(c, "Gz");
    E Gz2 = qd_add(c, Gz, qd_time(c));
    same_value(c, qd_model_force(m, 1), qd_add(c, qd_mul(c, Gx, Co(c, ph)), qd_mul(c, Gy, S(c, ph))),
               31);
    assert_ptr_equal(qd_model_force(m, 0), Gz2);
    E e3 = qd_add_n(c, 3, (E[]){mul3(c, Gx, S(c, th), S(c, ph)),
                               qd_neg(c, mul3(c, Gy, S(c, th), Co(c, ph))),
                               qd_mul(c, Gz2, Co(c, th))});
    same_value(c, qd_model_force(m, 2), e3, 32);
    qd_model_free(m);
    qd_ctx_free(c);
}

/* ---- inertia helpers against numeric integration ------------------------------------ */

/* A solid as a map from the unit cube (u, v, s) to a point, with the
 * density times the Jacobian as weight. */
typedef double (*solid_map)(double u, double v, double s, const double *dim, double p[3]);

static double map_rod(double u, double v, double s, const double *d, double p[3]) {
    (void)v, (void)s;
    p[0] = p[1] = 0, p[2] = (u - 0.5) * d[0];
    return d[0];
}
static double map_ring(double u, double v, double s, const double *d, double p[3]) {
    (void)v, (void)s;
    double f = 2 * PI * u;
    p[0] = d[0] * cos(f), p[1] = d[0] * sin(f), p[2] = 0;
    return 1;
}
static double map_disk(double u, double v, double s, const double *d, double p[3]) {
    (void)s;
    double r = d[0] * u, f = 2 * PI * v;
    p[0] = r * cos(f), p[1] = r * sin(f), p[2] = 0;
    return r;
}
static double map_ball(double u, double v, double s, const double *d, double p[3]) {
    double r = d[0] * u, th = PI * v, f = 2 * PI * s;
    p[0] = r * sin(th) * cos(f), p[1] = r * sin(th) * sin(f), p[2] = r * cos(th);
    return r * r * sin(th);
}
static double map_shell(double u, double v, double s, const double *d, double p[3]) {
    (void)s;
    double th = PI * u, f = 2 * PI * v;
    p[0] = d[0] * sin(th) * cos(f), p[1] = d[0] * sin(th) * sin(f), p[2] = d[0] * cos(th);
    return sin(th);
}
static double map_cylinder(double u, double v, double s, const double *d, double p[3]) {
    double r = d[0] * u, f = 2 * PI * v;
    p[0] = r * cos(f), p[1] = r * sin(f), p[2] = (s - 0.5) * d[1];
    return r;
}
static double map_cone(double u, double v, double s, const double *d, double p[3]) {
    double z = d[1] * s, R = d[0] * (1 - s), r = R * u, f = 2 * PI * v; /* base at z = 0 */
    p[0] = r * cos(f), p[1] = r * sin(f), p[2] = z;
    return r * R;
}
static double map_box(double u, double v, double s, const double *d, double p[3]) {
    p[0] = (u - 0.5) * d[0], p[1] = (v - 0.5) * d[1], p[2] = (s - 0.5) * d[2];
    return 1;
}

/* Principal moments about the centre of mass for mass 1, by the midpoint rule. */
static void integrate(solid_map f, const double *dim, double I[3]) {
    enum { N = 60 };
    double w = 0, c[3] = {0}, s2[3] = {0};
    for (int i = 0; i < N; i++)
        for (int j = 0; j < N; j++)
            for (int k = 0; k < N; k++) {
                double p[3];
                double dw = f((i + 0.5) / N, (j + 0.5) / N, (k + 0.5) / N, dim, p);
                w += dw;
                for (int a = 0; a < 3; a++) {
                    c[a] += dw * p[a];
                    s2[a] += dw * p[a] * p[a];
                }
            }
    for (int a = 0; a < 3; a++) {
        c[a] /= w;
        s2[a] = s2[a] / w - c[a] * c[a]; /* second moment about the centre */
    }
    for (int a = 0; a < 3; a++)
        I[a] = s2[(a + 1) % 3] + s2[(a + 2) % 3];
}

static void inertia_helpers(void **state) {
    (void)state;
    struct { const char *call; solid_map f; double dim[3]; } cases[] = {
        {"rod(m, 3/2)", map_rod, {1.5}},
        {"ring(m, 3/2)", map_ring, {1.5}},
        {"disk(m, 3/2)", map_disk, {1.5}},
        {"sphere(m, 3/2)", map_ball, {1.5}},
        {"shell(m, 3/2)", map_shell, {1.5}},
        {"cylinder(m, 3/2, 5/2)", map_cylinder, {1.5, 2.5}},
        {"cone(m, 3/2, 5/2)", map_cone, {1.5, 2.5}},
        {"box(m, 3/2, 5/2, 1/2)", map_box, {1.5, 2.5, 0.5}},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        qd_ctx *c = qd_ctx_new();
        char text[256];
        snprintf(text, sizeof text, "coordinates q\nparameters m = 1\nI = %s\n"
                 "I1 = I.x\nI2 = I.y\nI3 = I.z\nT = q'^2\n", cases[i].call);
        qd_model *m = parse(c, text);
        double I[3];
        integrate(cases[i].f, cases[i].dim, I);
        const char *names[3] = {"I1", "I2", "I3"};
        for (int a = 0; a < 3; a++) {
            double got;
            E mm = qd_lookup(c, "m");
            const double one = 1;
            assert_int_equal(qd_eval(c, def(m, names[a]), 1, &mm, &one, &got), QD_OK);
            if (!(fabs(got - I[a]) <= 2e-3 * (1 + fabs(I[a]))))
                fail_msg("%s: I%d = %g, by integration %g", cases[i].call, a + 1, got, I[a]);
        }
        qd_model_free(m);
        qd_ctx_free(c);
    }
}

/* Desloge ch. 63 Ex. 1 (T31): the cone's moment about a transverse axis
 * through the apex is 3/20 m h^2 (tan^2 alpha + 4) = 3/20 m (a^2 + 4 h^2);
 * the centre of mass is 3h/4 from the apex (parallel axes). */
static void cone_about_apex(void **state) {
    (void)state;
    qd_ctx *c = qd_ctx_new();
    qd_model *m = parse(c, "coordinates q\nparameters m = 1, a = 1, h = 2\n"
                           "I1 = cone(m, a, h).x\nI3 = cone(m, a, h).z\nT = q'^2\n");
    E M = qd_lookup(c, "m"), a = qd_lookup(c, "a"), h = qd_lookup(c, "h");
    E apex = qd_add(c, def(m, "I1"), mul3(c, M, qd_rat(c, 9, 16), qd_powi(c, h, 2)));
    E want = mul3(c, qd_rat(c, 3, 20), M,
                  qd_add(c, qd_powi(c, a, 2), qd_mul(c, qd_int(c, 4), qd_powi(c, h, 2))));
    assert_ptr_equal(qd_expand(c, apex), qd_expand(c, want));
    assert_ptr_equal(qd_expand(c, def(m, "I3")), mul3(c, qd_rat(c, 3, 10), M, qd_powi(c, a, 2)));
    qd_model_free(m);
    qd_ctx_free(c);
}

/* Names that were free before bodies existed still are. */
static void backward_compatible_names(void **state) {
    (void)state;
    qd_ctx *c = qd_ctx_new();
    qd_model *m = parse(c, "coordinates q\nparameters omega = 2, ring = 3\n"
                           "body = omega*q\ntorque = ring*q'\n"
                           "T = body'^2 + torque^2\nV = omega*(q + 1)\n");
    E q = qd_model_coord(m, 0);
    assert_ptr_equal(def(m, "body"), qd_mul(c, qd_lookup(c, "omega"), q));
    qd_model_free(m);
    qd_ctx_free(c);
}

typedef struct bad {
    const char *text;
    size_t line, col;
    const char *message;
    const char *hint;
} bad;

#define HEAD "coordinates q\nT = q'^2\n"
static const bad bad_models[] = {
    {HEAD "body b mass 1 inertia (1, 1, 1)\n", 3, 6, "body 'b' has no position ('at')", NULL},
    {HEAD "body b inertia (1, 1, 1) at (q, 0)\n", 3, 6, "body 'b' has no mass", NULL},
    {HEAD "body b mass 1 at (q, 0)\n", 3, 6, "body 'b' has no inertia", NULL},
    {HEAD "body b mass 1 inertia 2 at (q, 0)\n", 3, 23, "a scalar where a vector or matrix is needed",
     "principal moments"},
    {HEAD "body b mass 1 mass 2\n", 3, 15, "'mass' is given twice", NULL},
    {HEAD "body b mass 1 inertia (1, 1, 1) at (q, 0) orientaton rot_z(q)\n", 3, 43,
     "expected 'mass', 'inertia', 'at' or 'orientation', found orientaton",
     "did you mean 'orientation'?"},
    {HEAD "body b mass (1, 0) inertia (1, 1, 1) at (q, 0)\n", 3, 13,
     "a vector where a scalar is needed as a mass", NULL},
    {HEAD "body b mass 1 inertia (1, 1, 1) at rot_z(q)\n", 3, 36,
     "a matrix where a vector is needed: a position is a vector", "R*(x, y, z)"},
    {HEAD "body b mass 1 inertia (1, 1, 1) at (q, 0) orientation (0, 0, q)\n", 3, 55,
     "a vector where a matrix is needed: an orientation is a matrix", "rot_z(a)"},
    {HEAD "body b mass 1 inertia [[1, 2, 0], [0, 1, 0], [0, 0, 1]] at (q, 0)\n", 3, 23,
     "the inertia tensor is not symmetric: row 1, column 2", NULL},
    {HEAD "body b mass 1 inertia (1, 1, 1) at (q, 0) orientation [[1, 0, 0], [0, 1, 0], [0, 0, -1]]\n",
     3, 55, "the orientation is not a rotation", NULL},
    {HEAD "body b mass 1 inertia (1, 1, 1) at (q, 0) orientation 2*rot_z(q)\n", 3, 55,
     "the orientation is not a rotation", NULL},
    {HEAD "body q mass 1 inertia (1, 1, 1) at (q, 0)\n", 3, 6, "'q' is already a coordinate", NULL},
    {HEAD "body b mass 1 inertia (1, 1, 1) at (q, 0)\nbody b mass 1 inertia (1, 1, 1) at (q, 0)\n",
     4, 6, "'b' is already a body", NULL},
    {HEAD "body b mass 1 inertia (1, 1, 1) at (q, 0)\nV = b\n", 4, 5, "'b' is a body, not a value",
     "position(b)"},
    {HEAD "body ball mass 1 inertia (1, 1, 1) at (q, 0)\nV = omega(bal).z\n", 4, 11,
     "'bal' is not a body", "did you mean 'ball'?"},
    {HEAD "body b mass 1 inertia (1, 1, 1) at (q, 0)\nV = omega(b, q).z\n", 4, 12,
     "omega takes 1 argument", NULL},
    {HEAD "body b mass 1 inertia (1, 1, 1) at (q, 0)\nV = point(b).z\n", 4, 12,
     "point takes 2 arguments", NULL},
    {HEAD "body b mass 1 inertia (1, 1, 1) at (q, 0)\nV = point(b, 1).z\n", 4, 14,
     "a scalar where a vector is needed as a point in body axes", NULL},
    {HEAD "body b mass 1 inertia (1, 1, 1) at (q, 0)\ntorque (0, 0, 1) at b\n", 4, 18,
     "expected 'on'", NULL},
    {HEAD "body b mass 1 inertia (1, 1, 1) at (q, 0)\ntorque (0, 0, 1) on c\n", 4, 21,
     "'c' is not a body", NULL},
    {HEAD "body b mass 1 inertia (1, 1, 1) at (q, 0)\ntorque 1 on b\n", 4, 8,
     "a scalar where a vector is needed: a torque is a vector", NULL},
    {HEAD "R = rod(1)\n", 3, 5, "rod takes 2 arguments, not 1", NULL},
    {HEAD "R = sphere(1, (1, 2))\n", 3, 15, "a vector where a scalar is needed as a length", NULL},
};

static void diagnostics(void **state) {
    (void)state;
    for (size_t i = 0; i < sizeof bad_models / sizeof bad_models[0]; i++) {
        const bad *b = &bad_models[i];
        qd_ctx *ctx = qd_ctx_new();
        qd_diag d;
        memset(&d, 0, sizeof d);
        qd_model *m = qd_model_parse(ctx, b->text, &d);
        if (m)
            fail_msg("case %zu parsed but must fail: %s", i, b->text);
        if (d.line != b->line || d.col != b->col || strncmp(d.message, b->message, strlen(b->message)) ||
            (b->hint && !strstr(d.hint, b->hint)))
            fail_msg("case %zu: got %zu:%zu: %s [hint: %s]; want %zu:%zu: %s [hint: %s]", i, d.line,
                     d.col, d.message, d.hint, b->line, b->col, b->message, b->hint ? b->hint : "-");
        qd_ctx_free(ctx);
    }
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(top_angular_velocity),
        cmocka_unit_test(top_kinetic_energy),
        cmocka_unit_test(byerly_zyz),
        cmocka_unit_test(rotations_orthogonal),
        cmocka_unit_test(euler_is_goldstein_transpose),
        cmocka_unit_test(tait_bryan_heading),
        cmocka_unit_test(matrix_arithmetic),
        cmocka_unit_test(compound_pendulum),
        cmocka_unit_test(body_point),
        cmocka_unit_test(translating_body),
        cmocka_unit_test(tensor_rotates),
        cmocka_unit_test(torques),
        cmocka_unit_test(inertia_helpers),
        cmocka_unit_test(cone_about_apex),
        cmocka_unit_test(backward_compatible_names),
        cmocka_unit_test(diagnostics),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

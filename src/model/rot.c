/*
 * src/model/rot.c - 3x3 matrices and rotations of the model language.
 *
 * A rotation matrix R is active: it maps the components of a vector in the
 * body's axes to its components in space, r_space = R r_body.  The
 * elementary ones turn by a about a space axis:
 *
 *   rot_x(a) = [[1, 0, 0], [0, c, -s], [0, s, c]]
 *   rot_y(a) = [[c, 0, s], [0, 1, 0], [-s, 0, c]]
 *   rot_z(a) = [[c, -s, 0], [s, c, 0], [0, 0, 1]]        (c = cos a, s = sin a)
 *
 * and the three-angle families are their products (docs/language.md):
 *
 *   euler(phi, theta, psi)      = rot_z(phi) rot_x(theta) rot_z(psi)   z-x-z
 *   euler_zyz(phi, theta, psi)  = rot_z(phi) rot_y(theta) rot_z(psi)   z-y-z
 *   tait_bryan(yaw, pitch, roll) = rot_z(yaw) rot_y(pitch) rot_x(roll)
 *
 * Goldstein's A = B C D (3rd ed., eq. 4.46) is the passive matrix taking
 * space components to body components: A = euler(phi, theta, psi)^T.
 * Desloge ch. 63 writes R = Rz(phi) Rx(theta) Rz(psi) as here
 * (reference: seed-desloge-B.md, C8 and pitfall 4).
 */
#include "parser.h"

#include <string.h>

void qd__mdl_mat_identity(qd_ctx *ctx, const qd_expr *out[9]) {
    for (int i = 0; i < 9; i++)
        out[i] = qd_int(ctx, i % 4 == 0);
}

void qd__mdl_mat_mul(qd_ctx *ctx, const qd_expr *const a[9], const qd_expr *const b[9],
             const qd_expr *out[9]) {
    const qd_expr *r[9];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            r[3 * i + j] = qd_add_n(ctx, 3, (const qd_expr *[]){
                qd_mul(ctx, a[3 * i], b[j]), qd_mul(ctx, a[3 * i + 1], b[3 + j]),
                qd_mul(ctx, a[3 * i + 2], b[6 + j])});
    memcpy(out, r, sizeof r); /* out may be a or b */
}

void qd__mdl_mat_vec(qd_ctx *ctx, const qd_expr *const a[9], const qd_expr *const v[3],
             const qd_expr *out[3]) {
    const qd_expr *r[3];
    for (int i = 0; i < 3; i++)
        r[i] = qd_add_n(ctx, 3, (const qd_expr *[]){qd_mul(ctx, a[3 * i], v[0]),
            qd_mul(ctx, a[3 * i + 1], v[1]), qd_mul(ctx, a[3 * i + 2], v[2])});
    memcpy(out, r, sizeof r);
}

void qd__mdl_mat_transpose(const qd_expr *const a[9], const qd_expr *out[9]) {
    const qd_expr *r[9];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            r[3 * j + i] = a[3 * i + j];
    memcpy(out, r, sizeof r);
}

/* The rotation by a about axis k (0 = x, 1 = y, 2 = z): the identity in
 * row and column k, the plane rotation [[c, -s], [s, c]] in the other two,
 * taken in cyclic order (y, z), (z, x), (x, y). */
static void rot_axis(qd_ctx *ctx, int k, const qd_expr *a, const qd_expr *out[9]) {
    const qd_expr *c = qd_fn(ctx, QD_COS, a), *s = qd_fn(ctx, QD_SIN, a);
    int u = (k + 1) % 3, v = (k + 2) % 3;
    for (int i = 0; i < 9; i++)
        out[i] = qd_int(ctx, 0);
    out[4 * k] = qd_int(ctx, 1);
    out[4 * u] = c;
    out[4 * v] = c;
    out[3 * u + v] = qd_neg(ctx, s);
    out[3 * v + u] = s;
}

typedef struct rot_fn {
    const char *name;
    int axes[3];   /* the factors' axes, left to right; -1: fewer factors */
} rot_fn;

static const rot_fn rot_fns[] = {
    {"rot_x", {0, -1, -1}},
    {"rot_y", {1, -1, -1}},
    {"rot_z", {2, -1, -1}},
    {"euler", {2, 0, 2}},
    {"euler_zyz", {2, 1, 2}},
    {"tait_bryan", {2, 1, 0}},
};
#define NROT (sizeof rot_fns / sizeof rot_fns[0])

static const rot_fn *find_rot(const char *name) {
    for (size_t i = 0; i < NROT; i++)
        if (!strcmp(rot_fns[i].name, name))
            return &rot_fns[i];
    return NULL;
}

bool qd__mdl_is_rot_call(const char *name) { return find_rot(name) || !strcmp(name, "transpose"); }

static bool transpose_call(parser *p, const value *a, size_t n, value *out, size_t off,
                           size_t len) {
    if (!qd__mdl_check_arity(p, "transpose", n, 1, off, len) ||
        !qd__mdl_need_kind(p, &a[0], VK_MATRIX, "as the argument of transpose"))
        return false;
    value r = {VK_MATRIX, {NULL}, off, len};
    qd__mdl_mat_transpose(a[0].c, r.c);
    *out = r;
    return true;
}

bool qd__mdl_rot_call(parser *p, const char *name, const value *a, size_t n, value *out, size_t off,
              size_t len) {
    if (!strcmp(name, "transpose"))
        return transpose_call(p, a, n, out, off, len);
    const rot_fn *f = find_rot(name);
    size_t want = f->axes[1] < 0 ? 1 : 3;
    if (!qd__mdl_check_arity(p, name, n, want, off, len))
        return false;
    for (size_t i = 0; i < n; i++)
        if (!qd__mdl_need_kind(p, &a[i], VK_SCALAR, "as an angle"))
            return false;
    value r = {VK_MATRIX, {NULL}, off, len};
    rot_axis(p->ctx, f->axes[0], a[0].c[0], r.c);
    for (size_t i = 1; i < want; i++) {
        const qd_expr *m[9];
        rot_axis(p->ctx, f->axes[i], a[i].c[0], m);
        qd__mdl_mat_mul(p->ctx, r.c, m, r.c);
    }
    *out = r;
    return qd__mdl_kernel_ok(p, out);
}

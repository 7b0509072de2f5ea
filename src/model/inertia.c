/*
 * src/model/inertia.c - principal moments of inertia of uniform solids,
 * about the centre of mass, as the vector (I_x, I_y, I_z) of body axes with
 * the symmetry axis along z (docs/language.md lists them with sources):
 *
 *   rod(m, l)            thin rod of length l along z   (m l^2/12, m l^2/12, 0)
 *   ring(m, a)           thin hoop of radius a           (m a^2/2, m a^2/2, m a^2)
 *   disk(m, a)           thin disk of radius a           (m a^2/4, m a^2/4, m a^2/2)
 *   sphere(m, a)         solid ball                      2/5 m a^2 each
 *   shell(m, a)          thin spherical shell            2/3 m a^2 each
 *   cylinder(m, a, h)    solid, radius a, height h       (m(3a^2 + h^2)/12, same, m a^2/2)
 *   cone(m, a, h)        solid, base radius a, height h  (3m(4a^2 + h^2)/80, same, 3 m a^2/10)
 *   box(m, a, b, c)      solid, edges a, b, c along x, y, z
 *                                                        m/12 (b^2 + c^2, a^2 + c^2, a^2 + b^2)
 */
#include "parser.h"

#include <string.h>

typedef struct solid {
    const char *name;
    size_t nargs;   /* the mass first, then the lengths */
} solid;

static const solid solids[] = {
    {"rod", 2}, {"ring", 2}, {"disk", 2}, {"sphere", 2},
    {"shell", 2}, {"cylinder", 3}, {"cone", 3}, {"box", 4},
};
#define NSOLIDS (sizeof solids / sizeof solids[0])

static const solid *find_solid(const char *name) {
    for (size_t i = 0; i < NSOLIDS; i++)
        if (!strcmp(solids[i].name, name))
            return &solids[i];
    return NULL;
}

bool qd__mdl_is_inertia_call(const char *name) { return find_solid(name) != NULL; }

/* k m x^2 */
static const qd_expr *kmx2(qd_ctx *ctx, long num, long den, const qd_expr *m, const qd_expr *x) {
    return qd_mul_n(ctx, 3, (const qd_expr *[]){qd_rat(ctx, num, den), m, qd_powi(ctx, x, 2)});
}

/* The moments (transverse, transverse, axial) of the axially symmetric
 * solids, or the box's three. */
static void moments(qd_ctx *ctx, const char *name, const qd_expr *const *x, const qd_expr *I[3]) {
    const qd_expr *m = x[0], *a = x[1];
    if (!strcmp(name, "box")) {
        const qd_expr *sq[3] = {qd_powi(ctx, x[1], 2), qd_powi(ctx, x[2], 2), qd_powi(ctx, x[3], 2)};
        for (int i = 0; i < 3; i++)
            I[i] = qd_mul_n(ctx, 3, (const qd_expr *[]){qd_rat(ctx, 1, 12), m,
                qd_add(ctx, sq[(i + 1) % 3], sq[(i + 2) % 3])});
        return;
    }
    const qd_expr *side, *axial;
    if (!strcmp(name, "rod")) {
        side = kmx2(ctx, 1, 12, m, a);
        axial = qd_int(ctx, 0);
    } else if (!strcmp(name, "ring")) {
        side = kmx2(ctx, 1, 2, m, a);
        axial = kmx2(ctx, 1, 1, m, a);
    } else if (!strcmp(name, "disk")) {
        side = kmx2(ctx, 1, 4, m, a);
        axial = kmx2(ctx, 1, 2, m, a);
    } else if (!strcmp(name, "sphere")) {
        side = axial = kmx2(ctx, 2, 5, m, a);
    } else if (!strcmp(name, "shell")) {
        side = axial = kmx2(ctx, 2, 3, m, a);
    } else if (!strcmp(name, "cylinder")) {
        side = qd_add(ctx, kmx2(ctx, 1, 4, m, a), kmx2(ctx, 1, 12, m, x[2]));
        axial = kmx2(ctx, 1, 2, m, a);
    } else { /* cone, about its centre of mass, 3h/4 from the apex */
        side = qd_add(ctx, kmx2(ctx, 3, 20, m, a), kmx2(ctx, 3, 80, m, x[2]));
        axial = kmx2(ctx, 3, 10, m, a);
    }
    I[0] = I[1] = side;
    I[2] = axial;
}

bool qd__mdl_inertia_call(parser *p, const char *name, const value *a, size_t n, value *out, size_t off,
                  size_t len) {
    const solid *s = find_solid(name);
    if (!qd__mdl_check_arity(p, name, n, s->nargs, off, len))
        return false;
    const qd_expr *x[4];
    for (size_t i = 0; i < n; i++) {
        if (!qd__mdl_need_kind(p, &a[i], VK_SCALAR, i ? "as a length" : "as a mass"))
            return false;
        x[i] = a[i].c[0];
    }
    value r = {VK_VECTOR, {NULL}, off, len};
    moments(p->ctx, name, x, r.c);
    *out = r;
    return qd__mdl_kernel_ok(p, out);
}

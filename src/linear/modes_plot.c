/*
 * src/linear/modes_plot.c - the mode shapes drawn (qdot/modes.h):
 * qd_modes_picture_make (the particles at the equilibrium and moved along
 * each mode, and the plane they are drawn in) and qd_modes_plot (the
 * picture: a panel per mode, or the coordinates of each mode against the
 * coordinate number for a model without particles).  `qdot modes --plot`
 * writes it.
 *
 * A model with particles: each mode's panel has the particles at the
 * equilibrium and at q0 + s a_j (the shape scaled so the largest particle
 * displacement is a fifth of the configuration's size), in the plane where
 * they spread most.  Particles on one line (a chain of masses and springs)
 * move along it, so there each particle's displacement is drawn across the
 * line, against its place at rest: the textbook picture of a chain's modes.
 */
#include "linear.h"
#include "qdot/eval.h"
#include "qdot/plot.h"
#include "../base/args.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The value of each symbol of syms in a copy of vals, q set at the
 * coordinates of e and the velocities 0. */
static void put_state(const qd_eom *e, size_t nvals, const qd_expr *const *syms, double *vals,
                      const double *q) {
    for (size_t k = 0; k < nvals; k++)
        for (size_t j = 0; j < e->n; j++) {
            if (syms[k] == e->q[j])
                vals[k] = q[j];
            else if (syms[k] == e->qd[j])
                vals[k] = 0;
        }
}

static qd_prog *position_prog(qd_ctx *ctx, const qd_model *m, size_t np, size_t nvals,
                              const qd_expr *const *syms) {
    const qd_expr *outs[3 * QD_MODES_PLOT_MAXP];
    for (size_t i = 0; i < np; i++)
        for (unsigned k = 0; k < 3; k++) {
            const qd_expr *x = qd_model_particle_position(m, i, k);
            outs[3 * i + k] = x ? x : qd_int(ctx, 0);
        }
    return qd_prog_new(ctx, nvals, syms, 3 * np, outs);
}

static double spread(const double *p, size_t np, unsigned k) {
    double lo = INFINITY, hi = -INFINITY;
    for (size_t i = 0; i < np; i++) {
        lo = fmin(lo, p[3 * i + k]);
        hi = fmax(hi, p[3 * i + k]);
    }
    return hi - lo;
}

/* Positions at rest and moved along each mode; the scale makes the largest
 * displacement a fifth of the configuration's size (1 when it is a point).
 * w: nvals values to work in, q: n. */
static void move_along_modes(const qd_eom *e, size_t nvals, const qd_expr *const *syms,
                             qd_prog *prog, const double *q0, const qd_modes_result *res,
                             qd_modes_picture *pic, double *w, double *q) {
    size_t n = res->n, np = pic->np;
    put_state(e, nvals, syms, w, q0);
    qd_prog_run(prog, w, pic->rest);
    double size = fmax(fmax(spread(pic->rest, np, 0), spread(pic->rest, np, 1)),
                       spread(pic->rest, np, 2));
    if (!(size > 0))
        size = 1;
    for (size_t j = 0; j < n; j++) {
        double *mv = pic->moved + j * 3 * np, h = 1e-6 * size, big = 0;
        /* the linear displacement per unit s: a forward difference along a_j,
         * h small against the configuration (plotting needs 3 digits) */
        for (size_t i = 0; i < n; i++)
            q[i] = q0[i] + h * res->shapes[i * n + j];
        put_state(e, nvals, syms, w, q);
        qd_prog_run(prog, w, mv);
        for (size_t k = 0; k < 3 * np; k++) {
            mv[k] = (mv[k] - pic->rest[k]) / h;
            big = fmax(big, fabs(mv[k]));
        }
        double s = big > 0 ? 0.2 * size / big : 0;
        for (size_t k = 0; k < 3 * np; k++)
            mv[k] = pic->rest[k] + s * mv[k];
    }
}

/* The springs' stiffness: between particles (K) and to walls (Kw), the
 * Hessians of V's terms that are not linear in the positions
 * (modes_terms.c), a term that holds a particle to the origin by its
 * distance drawn as a spring from there instead of to a wall (in a plane:
 * k/2 x1^2 on a chain along x is |r1| - a too).  False
 * (nothing set) when V cannot be split so. */
static bool spring_terms(qd_ctx *ctx, const qd_eom *e, const qd_model *m, size_t nvals,
                         const qd_expr *const *syms, const double *vals, const double *q0,
                         const double *jac, double size, qd_modes_picture *pic, double *K,
                         double *Kw) {
    size_t n = e->n, np = pic->np;
    qd__lin_springs sp;
    if (qd__lin_springs_find(ctx, e, m, nvals, syms, vals, q0, jac, np, size, &sp) != QD_OK) {
        qd_ctx_clear_error(ctx);
        return false;
    }
    for (size_t k = 0; k < sp.nt; k++) {
        /* on a line (a chain) a spring along it is drawn to a wall beyond */
        size_t a = pic->ay == 3 ? SIZE_MAX : sp.centre[k];
        for (size_t u = 0; u < n * n; u++) {
            K[u] += sp.K[k * n * n + u];
            Kw[u] += a == SIZE_MAX ? sp.K[k * n * n + u] : 0;
        }
        for (size_t l = 0; a != SIZE_MAX && l < pic->nlinks; l++)
            if (pic->links[l].a == a && pic->links[l].b == np)
                a = SIZE_MAX; /* a second term of the same spring */
        if (a != SIZE_MAX && pic->nlinks < QD_MODES_PLOT_MAXLINKS) {
            pic->links[pic->nlinks++] = (qd_modes_link_of){a, np, QD_MODES_SPRING};
            pic->pivot = true;
        }
    }
    qd__lin_springs_free(&sp);
    return true;
}

/* What joins the particles: the positions' Jacobian along each coordinate
 * (forward differences, as the modes') and K0 (modes_links.c). */
static qd_status find_links(qd_ctx *ctx, const qd_eom *e, const qd_model *m, size_t nvals,
                            const qd_expr *const *syms, const double *vals, qd_prog *prog,
                            const double *q0, qd_modes_picture *pic, double *w, double *q) {
    size_t n = e->n, np = pic->np;
    double size = fmax(fmax(spread(pic->rest, np, 0), spread(pic->rest, np, 1)),
                       spread(pic->rest, np, 2));
    size = size > 0 ? size : 1;
    double *jac = malloc((12 * np * n + 1) * sizeof *jac), *far = jac ? jac + 3 * np * n : NULL;
    double h = 1e-6 * size;
    size_t *owner = malloc((n + 1) * sizeof *owner);
    qd_linear lin = {0};
    bool have_k = jac && owner &&
                  qd_linear_about(ctx, e, m, nvals, syms, vals, &lin) == QD_OK;
    if (!have_k)
        qd_ctx_clear_error(ctx); /* no springs drawn, the rest of the picture stands */
    for (size_t j = 0; jac && owner && j < n; j++) {
        memcpy(q, q0, n * sizeof *q);
        q[j] += h;
        put_state(e, nvals, syms, w, q);
        double *d = jac + j * 3 * np;
        qd_prog_run(prog, w, d);
        for (size_t k = 0; k < 3 * np; k++)
            d[k] = (d[k] - pic->rest[k]) / h;
        for (int f = 0; f < 3; f++) { /* a rod's length is kept at any step: */
            q[j] = q0[j] + (f == 1 ? -1e-3 : 1e-3 * (f + 1)) * size; /* +H, -H, +2H */
            put_state(e, nvals, syms, w, q);
            qd_prog_run(prog, w, far + ((size_t)f * n + j) * 3 * np);
        }
    }
    double *K = have_k ? calloc(2 * n * n, sizeof *K) : NULL, *Kw = K ? K + n * n : NULL;
    if (K && !spring_terms(ctx, e, m, nvals, syms, vals, q0, jac, size, pic, K, Kw)) {
        memcpy(K, lin.K, n * n * sizeof *K); /* no V of its own (L given): K0 */
        memcpy(Kw, lin.K, n * n * sizeof *K);
    }
    if (jac && owner)
        qd__lin_modes_links(pic, jac, far, n, K, Kw, size, owner);
    free(K);
    qd_linear_free(&lin);
    qd_status st = jac && owner ? QD_OK : QD_ERR_NOMEM;
    free(jac);
    free(owner);
    return st;
}

/* The two axes where the positions, at rest and moved, spread most
 * (taken all together: one particle moved along y spreads along y). */
static void choose_plane(qd_modes_picture *pic) {
    double sp[3];
    for (unsigned k = 0; k < 3; k++) {
        double lo = INFINITY, hi = -INFINITY;
        for (size_t i = 0; i < pic->np * (pic->nmode + 1); i++) {
            double v = i < pic->np ? pic->rest[3 * i + k] : pic->moved[3 * (i - pic->np) + k];
            lo = fmin(lo, v);
            hi = fmax(hi, v);
        }
        sp[k] = hi - lo;
    }
    unsigned a = sp[1] > sp[0] ? 1 : 0;
    a = sp[2] > sp[a] ? 2 : a;
    unsigned b = a == 0 ? 1 : 0;
    for (unsigned k = 0; k < 3; k++)
        if (k != a && sp[k] > sp[b])
            b = k;
    pic->ax = a < b ? a : b;
    pic->ay = a < b ? b : a;
    if (!(sp[b] > 1e-9 * sp[a])) { /* on one line */
        pic->ax = a;
        pic->ay = 3;
    }
}

void qd_modes_picture_free(qd_modes_picture *pic) {
    QD_ARGS(, pic);
    free(pic->rest);
    free(pic->moved);
    pic->rest = pic->moved = NULL;
    pic->np = pic->nmode = 0;
}

/* The particles drawn: none when there are more than QD_MODES_PLOT_MAXP, or
 * more modes than panels. */
static size_t particles_drawn(const qd_model *m, const qd_modes_result *res) {
    size_t np = qd_model_nparticles(m);
    if (np > QD_MODES_PLOT_MAXP || res->n > QD_MODES_PLOT_MAXPANELS)
        return 0;
    return np;
}

static qd_status shapes_check(qd_ctx *ctx, const qd_eom *e, const qd_modes_result *res) {
    if (!res->conservative || !res->shapes) {
        qd_ctx_error(ctx, QD_ERR_ARG, "a system with damping or gyroscopic terms has no mode "
                                      "shapes (its modes are complex)");
        return QD_ERR_ARG;
    }
    if (res->n != e->n) {
        qd_ctx_error(ctx, QD_ERR_ARG, "the modes have %zu coordinates, the equations %zu",
                     res->n, e->n);
        return QD_ERR_ARG;
    }
    return QD_OK;
}

qd_status qd_modes_picture_make(qd_ctx *ctx, const qd_eom *e, const qd_model *m, size_t nvals,
                                const qd_expr *const *syms, const double *vals,
                                const qd_modes_result *res, qd_modes_picture *out) {
    QD_ARGS_CTX(ctx, ctx && e && m && (nvals == 0 || syms) && (nvals == 0 || vals) && res &&
                         out);
    memset(out, 0, sizeof *out);
    qd_status st = shapes_check(ctx, e, res);
    if (st != QD_OK)
        return st;
    size_t n = res->n, np = particles_drawn(m, res);
    out->nmode = n;
    out->np = np;
    if (!np)
        return QD_OK;
    out->rest = calloc(3 * np, sizeof(double));
    out->moved = calloc(3 * np * n, sizeof(double));
    double *q0 = calloc(2 * n + 1, sizeof(double)), *q = q0 ? q0 + n : NULL;
    double *w = calloc(nvals + 1, sizeof(double));
    qd_prog *prog = out->rest && out->moved && q0 && w ? position_prog(ctx, m, np, nvals, syms)
                                                       : NULL;
    st = prog ? QD_OK : qd_ctx_status(ctx) ? qd_ctx_status(ctx) : QD_ERR_NOMEM;
    if (st == QD_OK) {
        if (nvals)
            memcpy(w, vals, nvals * sizeof *w);
        for (size_t k = 0; k < nvals; k++) /* the equilibrium's coordinates */
            for (size_t j = 0; j < n; j++)
                if (syms[k] == e->q[j])
                    q0[j] = vals[k];
        move_along_modes(e, nvals, syms, prog, q0, res, out, w, q);
        choose_plane(out);
        st = find_links(ctx, e, m, nvals, syms, vals, prog, q0, out, w, q);
    }
    qd_prog_free(prog);
    free(q0);
    free(w);
    if (st != QD_OK)
        qd_modes_picture_free(out);
    return st;
}

static const char *axis_name(unsigned k) {
    static const char *const names[] = {"x", "y", "z"};
    return names[k];
}

/* omega, drawn as the Greek letter (qd_plot_math_text) */
static void mode_label(const qd_modes_result *res, size_t j, char *buf, size_t cap) {
    double w2 = res->omega2[j];
    if (w2 >= 0)
        snprintf(buf, cap, "mode %zu: omega = %.4g rad/s", j + 1, sqrt(w2));
    else
        snprintf(buf, cap, "mode %zu: unstable, omega^2 = %.4g", j + 1, w2);
}

/* Particle i (np: the origin) at pos in the picture's axes: in the plane,
 * or on a line its place at rest across and its displacement up. */
static void pic_xy(const qd_modes_picture *pic, const double *pos, size_t i, double *x,
                   double *y) {
    unsigned ax = pic->ax, ay = pic->ay;
    if (i == pic->np) {
        *x = *y = 0;
        return;
    }
    *x = ay == 3 ? pic->rest[3 * i + ax] : pos[3 * i + ax];
    *y = ay == 3 ? pos[3 * i + ax] - pic->rest[3 * i + ax] : pos[3 * i + ay];
}

/* A spring to wall w (from particle a at pos): the spring and the wall,
 * which stays where it is; none for a wall across the axis out of the
 * picture's plane. */
static qd_status add_wall(qd_plot *p, const qd_modes_picture *pic, const double *pos, size_t a,
                          size_t w) {
    unsigned e = pic->wall_axis[w];
    const double *at = pic->wall + 3 * w;
    if (e == 3 && pic->ay != 3) { /* a pivot at a fixed point, a rod from it */
        double ax, ay;
        pic_xy(pic, pos, a, &ax, &ay);
        qd_status st = qd_plot_add_mark(p, QD_PLOT_ROD, ax, ay, at[pic->ax], at[pic->ay]);
        return st == QD_OK ? qd_plot_add_mark(p, QD_PLOT_PIVOT, at[pic->ax], at[pic->ay], 0, 0)
                           : st;
    }
    if (e != pic->ax && e != pic->ay)
        return QD_OK;
    double ax, ay, wx, wy, rx, ry;
    pic_xy(pic, pos, a, &ax, &ay);
    pic_xy(pic, pic->rest, a, &rx, &ry);
    /* the wall's point in the picture's axes: on a line, at rest across */
    wx = pic->ay == 3 ? at[pic->ax] : e == pic->ax ? at[e] : rx;
    wy = pic->ay == 3 ? 0 : e == pic->ay ? at[e] : ry;
    qd_status st = qd_plot_add_mark(p, QD_PLOT_SPRING, ax, ay, wx, wy);
    return st == QD_OK ? qd_plot_add_mark(p, QD_PLOT_WALL, wx, wy, rx, pic->ay == 3 ? 0 : ry)
                       : st;
}

/* Mode j's springs and rods (moved), its arrows from rest, the pivot. */
static qd_status add_marks(qd_plot *p, const qd_modes_picture *pic, size_t j) {
    const double *mv = pic->moved + j * 3 * pic->np;
    qd_status st = QD_OK;
    for (size_t l = 0; l < pic->nlinks && st == QD_OK; l++) {
        double ax, ay, bx, by;
        if (pic->links[l].b > pic->np) {
            st = add_wall(p, pic, mv, pic->links[l].a, pic->links[l].b - pic->np - 1);
            continue;
        }
        pic_xy(pic, mv, pic->links[l].a, &ax, &ay);
        pic_xy(pic, mv, pic->links[l].b, &bx, &by);
        st = qd_plot_add_mark(p, pic->links[l].kind == QD_MODES_SPRING ? QD_PLOT_SPRING
                                                                       : QD_PLOT_ROD,
                              ax, ay, bx, by);
    }
    for (size_t i = 0; i < pic->np && st == QD_OK; i++) {
        double ax, ay, bx, by;
        pic_xy(pic, pic->rest, i, &ax, &ay);
        pic_xy(pic, mv, i, &bx, &by);
        st = qd_plot_add_mark(p, QD_PLOT_ARROW, ax, ay, bx, by);
    }
    if (st == QD_OK && pic->pivot && pic->ay != 3)
        st = qd_plot_add_mark(p, QD_PLOT_PIVOT, 0, 0, 0, 0);
    return st;
}

static qd_status add_particles(qd_plot *p, const qd_modes_picture *pic, const double *pos,
                               const char *label, double *x, double *y) {
    for (size_t i = 0; i < pic->np; i++)
        pic_xy(pic, pos, i, &x[i], &y[i]);
    return qd_plot_add(p, label, QD_PLOT_DOTS, pic->np, x, y, NULL);
}

static qd_status draw_particles(qd_plot *p, const qd_modes_picture *pic,
                                const qd_modes_result *res) {
    unsigned ax = pic->ax, ay = pic->ay;
    double x[QD_MODES_PLOT_MAXP], y[QD_MODES_PLOT_MAXP];
    char label[96], yl[64];
    snprintf(yl, sizeof yl, ay == 3 ? "displacement along %s" : "%s", axis_name(ax));
    qd_status st = QD_OK;
    for (size_t j = 0; j < res->n && st == QD_OK; j++) {
        mode_label(res, j, label, sizeof label);
        st = qd_plot_select(p, j);
        if (st == QD_OK)
            st = qd_plot_set_heading(p, label);
        if (st == QD_OK)
            st = qd_plot_set_xlabel(p, axis_name(ax));
        if (st == QD_OK)
            st = qd_plot_set_ylabel(p, ay == 3 ? yl : axis_name(ay));
        if (st == QD_OK && ay != 3) /* positions in the plane: true shape */
            st = qd_plot_set_equal_axes(p, true);
        if (st == QD_OK)
            st = add_marks(p, pic, j);
        if (st == QD_OK)
            st = add_particles(p, pic, pic->moved + j * 3 * pic->np, "mode shape", x, y);
        if (st == QD_OK)
            st = add_particles(p, pic, pic->rest, "equilibrium", x, y);
    }
    return st;
}

/* A panel per mode, at most 3 to a row (2 x 2 for four), each about
 * 330 x 330. */
static qd_plot *new_grid(qd_ctx *ctx, size_t nmode) {
    size_t cols = nmode <= 3 ? nmode : nmode == 4 ? 2 : 3, rows = (nmode + cols - 1) / cols;
    qd_plot *p = qd_plot_new(ctx, cols == 1 ? 500 : 330 * (int)cols, 60 + 340 * (int)rows);
    if (p && (qd_plot_panels(p, rows, cols) != QD_OK || qd_plot_share_legend(p, true) != QD_OK)) {
        qd_plot_free(p);
        return NULL;
    }
    return p;
}

/* No particles: a_ij (each mode scaled to a largest entry of 1) against
 * the coordinate's number. */
static qd_status draw_coordinates(qd_plot *p, const qd_modes_result *res) {
    size_t n = res->n;
    double *x = malloc(n * sizeof *x), *y = malloc(n * sizeof *y);
    qd_status st = x && y ? qd_plot_set_xlabel(p, "coordinate number") : QD_ERR_NOMEM;
    if (st == QD_OK)
        st = qd_plot_set_ylabel(p, "mode shape (largest entry 1)");
    char label[96];
    for (size_t j = 0; j < n && st == QD_OK; j++) {
        double big = 0;
        for (size_t i = 0; i < n; i++)
            big = fmax(big, fabs(res->shapes[i * n + j]));
        for (size_t i = 0; i < n; i++) {
            x[i] = (double)(i + 1);
            y[i] = big > 0 ? res->shapes[i * n + j] / big : 0;
        }
        mode_label(res, j, label, sizeof label);
        st = qd_plot_add(p, label, QD_PLOT_LINE_POINTS, n, x, y, NULL);
    }
    free(x);
    free(y);
    return st;
}

qd_status qd_modes_plot(qd_ctx *ctx, const qd_eom *e, const qd_model *m, size_t nvals,
                        const qd_expr *const *syms, const double *vals,
                        const qd_modes_result *res, const char *title, qd_plot **out) {
    QD_ARGS_CTX(ctx, ctx && e && m && (nvals == 0 || syms) && (nvals == 0 || vals) && res &&
                         title && out);
    *out = NULL;
    qd_status st = shapes_check(ctx, e, res);
    if (st != QD_OK)
        return st;
    size_t np = particles_drawn(m, res);
    qd_plot *p = np ? new_grid(ctx, res->n) : qd_plot_new(ctx, 0, 0);
    st = p ? qd_plot_set_title(p, title) : QD_ERR_NOMEM;
    qd_modes_picture pic = {0};
    if (st == QD_OK && np)
        st = qd_modes_picture_make(ctx, e, m, nvals, syms, vals, res, &pic);
    if (st == QD_OK)
        st = np ? draw_particles(p, &pic, res) : draw_coordinates(p, res);
    qd_modes_picture_free(&pic);
    if (st != QD_OK) {
        qd_plot_free(p);
        return st;
    }
    *out = p;
    return QD_OK;
}

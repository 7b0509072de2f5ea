/*
 * cli/modes_plot.c - `qdot modes --plot FILE`: the mode shapes drawn.
 *
 * A model with particles: a panel per mode, each with the particles at the
 * equilibrium and at q0 + s a_j (the shape scaled so the largest particle
 * displacement is a fifth of the configuration's size), in the plane where
 * they spread most.
 * Particles on one line (a chain of masses and springs) move along it, so
 * there each particle's displacement is drawn across the line, against its
 * place at rest: the textbook picture of a chain's modes.  A model without
 * particles: one panel, each mode's coordinates a_ij against the
 * coordinate number.
 */
#include "modes_plot.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"

#define MAXP 64 /* particles drawn */

typedef struct shapes {
    size_t np;       /* particles */
    double *rest;    /* np x 3 at q0 */
    double *moved;   /* nmode x np x 3 at q0 + s a_j */
} shapes;

/* The particles' positions (x, y, z; 0 where a model gives fewer) at q. */
static void positions(cli_lin_run *lr, qd_prog *prog, const double *q, double *out) {
    cli_lin_set_state(lr, q, NULL);
    qd_prog_run(prog, lr->st.vals, out);
}

static qd_prog *position_prog(cli_lin_run *lr, size_t np) {
    const qd_expr *outs[3 * MAXP];
    const qd_model *m = lr->mf.model;
    for (size_t i = 0; i < np; i++)
        for (unsigned k = 0; k < 3; k++) {
            const qd_expr *x = qd_model_particle_position(m, i, k);
            outs[3 * i + k] = x ? x : qd_int(lr->ctx, 0);
        }
    return qd_prog_new(lr->ctx, lr->st.n, lr->st.syms, 3 * np, outs);
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
 * displacement a fifth of the configuration's size (1 when it is a point). */
static void move_along_modes(cli_lin_run *lr, qd_prog *prog, const double *q0,
                             const qd_modes_result *res, shapes *sh, double *q) {
    size_t n = res->n, np = sh->np;
    positions(lr, prog, q0, sh->rest);
    double size = fmax(fmax(spread(sh->rest, np, 0), spread(sh->rest, np, 1)),
                       spread(sh->rest, np, 2));
    if (!(size > 0))
        size = 1;
    for (size_t j = 0; j < n; j++) {
        double *mv = sh->moved + j * 3 * np, h = 1e-6 * size, big = 0;
        /* the linear displacement per unit s: a forward difference along a_j,
         * h small against the configuration (plotting needs 3 digits) */
        for (size_t i = 0; i < n; i++)
            q[i] = q0[i] + h * res->shapes[i * n + j];
        positions(lr, prog, q, mv);
        for (size_t k = 0; k < 3 * np; k++) {
            mv[k] = (mv[k] - sh->rest[k]) / h;
            big = fmax(big, fabs(mv[k]));
        }
        double s = big > 0 ? 0.2 * size / big : 0;
        for (size_t k = 0; k < 3 * np; k++)
            mv[k] = sh->rest[k] + s * mv[k];
    }
}

/* The two axes where the positions, at rest and moved, spread most
 * (taken all together: one particle moved along y spreads along y). */
static void choose_plane(const shapes *sh, size_t nmode, unsigned *ax, unsigned *ay) {
    double sp[3];
    for (unsigned k = 0; k < 3; k++) {
        double lo = INFINITY, hi = -INFINITY;
        for (size_t i = 0; i < sh->np * (nmode + 1); i++) {
            double v = i < sh->np ? sh->rest[3 * i + k] : sh->moved[3 * (i - sh->np) + k];
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
    *ax = a < b ? a : b;
    *ay = a < b ? b : a;
    if (!(sp[b] > 1e-9 * sp[a])) { /* on one line: a marks that case */
        *ax = a;
        *ay = 3;
    }
}

static const char *axis_name(unsigned k) {
    static const char *const names[] = {"x", "y", "z"};
    return names[k];
}

static void mode_label(const qd_modes_result *res, size_t j, char *buf, size_t cap) {
    double w2 = res->omega2[j];
    if (w2 >= 0)
        snprintf(buf, cap, "mode %zu: w = %.4g rad/s", j + 1, sqrt(w2));
    else
        snprintf(buf, cap, "mode %zu: unstable, w^2 = %.4g", j + 1, w2);
}

static qd_status add_particles(qd_plot *p, const shapes *sh, const double *pos, const double *rest,
                               unsigned ax, unsigned ay, const char *label, double *x,
                               double *y) {
    for (size_t i = 0; i < sh->np; i++) {
        x[i] = ay == 3 ? rest[3 * i + ax] : pos[3 * i + ax];
        y[i] = ay == 3 ? pos[3 * i + ax] - rest[3 * i + ax] : pos[3 * i + ay];
    }
    return qd_plot_add(p, label, QD_PLOT_LINE_POINTS, sh->np, x, y, NULL);
}

static qd_status draw_particles(qd_plot *p, const shapes *sh, const qd_modes_result *res) {
    unsigned ax, ay;
    choose_plane(sh, res->n, &ax, &ay);
    double x[MAXP], y[MAXP];
    char label[96], yl[64];
    snprintf(yl, sizeof yl, ay == 3 ? "displacement along %s" : "%s", axis_name(ax));
    qd_status st = QD_OK;
    for (size_t j = 0; j < res->n && st == QD_OK; j++) {
        mode_label(res, j, label, sizeof label);
        st = qd_plot_select(p, j);
        if (st == QD_OK)
            st = qd_plot_set_xlabel(p, axis_name(ax));
        if (st == QD_OK)
            st = qd_plot_set_ylabel(p, ay == 3 ? yl : axis_name(ay));
        if (st == QD_OK && ay != 3) /* positions in the plane: true shape */
            st = qd_plot_set_equal_axes(p, true);
        if (st == QD_OK)
            st = add_particles(p, sh, sh->rest, sh->rest, ax, ay, "equilibrium", x, y);
        if (st == QD_OK)
            st = add_particles(p, sh, sh->moved + j * 3 * sh->np, sh->rest, ax, ay, label, x, y);
    }
    return st;
}

/* A panel per mode, at most 3 to a row (2 x 2 for four), each about
 * 330 x 330. */
static qd_plot *new_grid(qd_ctx *ctx, size_t nmode) {
    size_t cols = nmode <= 3 ? nmode : nmode == 4 ? 2 : 3, rows = (nmode + cols - 1) / cols;
    qd_plot *p = qd_plot_new(ctx, cols == 1 ? 500 : 330 * (int)cols, 40 + 330 * (int)rows);
    if (p && qd_plot_panels(p, rows, cols) != QD_OK) {
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

static qd_status particle_plot(qd_plot *p, cli_lin_run *lr, const double *q0,
                               const qd_modes_result *res, size_t np) {
    shapes sh = {.np = np, .rest = calloc(3 * np, sizeof(double)),
                 .moved = calloc(3 * np * res->n, sizeof(double))};
    double *q = calloc(res->n, sizeof *q);
    qd_prog *prog = sh.rest && sh.moved && q ? position_prog(lr, np) : NULL;
    qd_status st = prog ? QD_OK : qd_ctx_status(lr->ctx) ? qd_ctx_status(lr->ctx) : QD_ERR_NOMEM;
    if (st == QD_OK) {
        move_along_modes(lr, prog, q0, res, &sh, q);
        cli_lin_set_state(lr, q0, NULL);
        st = draw_particles(p, &sh, res);
    }
    qd_prog_free(prog);
    free(sh.rest);
    free(sh.moved);
    free(q);
    return st;
}

int cli_modes_plot(cli_lin_run *lr, const double *q0, const qd_modes_result *res,
                   const char *file, const char *title) {
    if (!res->conservative || !res->shapes) {
        cli_diag_error("modes --plot draws mode shapes, which a system with damping or "
                       "gyroscopic terms does not have (its modes are complex)");
        return QD_EXIT_USAGE;
    }
    size_t np = qd_model_nparticles(lr->mf.model);
    if (np > MAXP)
        np = 0; /* too many to draw as particles: the coordinates instead */
    if (np && res->n > 8 * 3)
        np = 0; /* more modes than panels: the coordinates instead */
    qd_plot *p = np ? new_grid(lr->ctx, res->n) : qd_plot_new(lr->ctx, 0, 0);
    const char *slash = strrchr(title, '/');
    qd_status st = p ? qd_plot_set_title(p, slash ? slash + 1 : title) : QD_ERR_NOMEM;
    if (st == QD_OK)
        st = np ? particle_plot(p, lr, q0, res, np) : draw_coordinates(p, res);
    if (st == QD_OK)
        st = qd_plot_write(p, file);
    qd_plot_free(p);
    if (st == QD_OK)
        return QD_EXIT_OK;
    return qd_ctx_status(lr->ctx) != QD_OK ? cli_diag_ctx(lr->ctx) : QD_EXIT_FAIL;
}

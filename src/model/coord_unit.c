/*
 * src/model/coord_unit.c - a coordinate's unit as the model states it
 * through its geometry (qd_model_coord_unit, qdot/model.h): a coordinate
 * the particles' positions and V repeat in with period 2 pi, and that
 * moves them, is an angle (rad).  Plots label and group their panels by it
 * (a panel never mixes metres and radians).
 */
#include "qdot/model.h"
#include "qdot/eval.h"
#include "base/args.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define MAXOUT 200 /* positions of the first 64 particles and V */

static const double TWO_PI = 6.283185307179586;

/* outs at the point in, and the largest difference from there with input
 * j moved by d, relative to the values' size. */
static double moved(qd_prog *p, double *in, size_t j, double d, const double *base,
                    size_t nout) {
    double out[MAXOUT], diff = 0, size = 1e-300;
    double keep = in[j];
    in[j] = keep + d;
    qd_prog_run(p, in, out);
    in[j] = keep;
    for (size_t k = 0; k < nout; k++) {
        diff = fmax(diff, fabs(out[k] - base[k]));
        size = fmax(size, fabs(base[k]));
    }
    return diff / size;
}

const char *qd_model_coord_unit(qd_ctx *ctx, const qd_model *m, size_t i) {
    QD_ARGS(NULL, ctx && m);
    size_t nq = qd_model_ncoords(m), npar = qd_model_nparams(m);
    size_t np = qd_model_nparticles(m);
    if (i >= nq)
        return NULL;
    np = np > 64 ? 64 : np;
    const qd_expr *outs[MAXOUT], *V = qd_model_potential(m);
    size_t nout = 0;
    for (size_t a = 0; a < np; a++)
        for (unsigned k = 0; k < 3; k++) {
            const qd_expr *x = qd_model_particle_position(m, a, k);
            if (x)
                outs[nout++] = x;
        }
    if (V)
        outs[nout++] = V;
    size_t nin = nq + npar + 1;
    const qd_expr **syms = malloc(nin * sizeof *syms);
    double *in = malloc(nin * sizeof *in);
    qd_prog *p = NULL;
    if (syms && in && nout) {
        for (size_t k = 0; k < nq; k++) {
            syms[k] = qd_model_coord(m, k);
            in[k] = 0.3 + 0.17 * (double)k; /* a point of no symmetry */
        }
        for (size_t k = 0; k < npar; k++) {
            syms[nq + k] = qd_model_param(m, k);
            if (qd_model_param_number(m, k, &in[nq + k]) != QD_OK)
                in[nq + k] = 1.3;
        }
        syms[nin - 1] = qd_time(ctx);
        in[nin - 1] = 0.4;
        p = syms[nin - 1] ? qd_prog_new(ctx, nin, syms, nout, outs) : NULL;
    }
    const char *unit = NULL;
    if (p) {
        double base[MAXOUT];
        qd_prog_run(p, in, base);
        /* periodic in 2 pi to rounding, and moved by a unit step */
        if (moved(p, in, i, TWO_PI, base, nout) < 1e-9 && moved(p, in, i, 1, base, nout) > 1e-6)
            unit = "rad";
    } else if (qd_ctx_status(ctx) != QD_OK) {
        qd_ctx_clear_error(ctx); /* V of velocities or of an unknown: no unit said */
    }
    qd_prog_free(p);
    free(syms);
    free(in);
    return unit;
}

const char *qd_model_column_unit(qd_ctx *ctx, const qd_model *m, const char *name) {
    QD_ARGS(NULL, ctx && m && name);
    if (!strcmp(name, "t"))
        return "s";
    size_t len = strlen(name), base = len && name[len - 1] == '\'' ? len - 1 : len;
    for (size_t i = 0; i < qd_model_ncoords(m); i++) {
        const char *q = qd_expr_name(qd_model_coord(m, i));
        if (!q || strlen(q) != base || strncmp(q, name, base))
            continue;
        const char *u = qd_model_coord_unit(ctx, m, i);
        /* the only unit said is rad: its rate is rad/s */
        return base == len || !u ? u : "rad/s";
    }
    return NULL;
}

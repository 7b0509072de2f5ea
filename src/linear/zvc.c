/*
 * src/linear/zvc.c - Jacobi's integral at rest and its level curves, the
 * zero-velocity curves (qdot/zvc.h).
 *
 * h comes from qd_integrals_derive, which also says whether it is
 * conserved; W = h(q, q' = 0) = V - T0 (+ U0) is evaluated on the grid by
 * one compiled program and contoured by qd_contour_grid.
 */
#include "linear.h"

#include "qdot/integrals.h"
#include "qdot/zvc.h"
#include "num/num.h"
#include "base/mem.h"
#include "../base/args.h"

#include <math.h>
#include <stdint.h>
#include <string.h>

qd_status qd_zvc_derive(qd_ctx *ctx, const qd_model *m, qd_eom *e, qd_zvc *out) {
    QD_ARGS_CTX(ctx, ctx && m && e && out);
    memset(out, 0, sizeof *out);
    if (!ctx || !m || !e)
        return QD_ERR_ARG;
    if (e->ncon) {
        qd_ctx_error(ctx, QD_ERR_ARG, "the model keeps %zu constraint%s with multipliers: "
                     "zero-velocity curves need independent coordinates", e->ncon,
                     e->ncon == 1 ? "" : "s");
        return QD_ERR_ARG;
    }
    qd_integrals *I = qd_integrals_derive(ctx, m, e, NULL);
    if (!I)
        return qd_ctx_status(ctx);
    qd_status st = QD_OK;
    if (!I->jacobi.conserved) {
        qd_ctx_error(ctx, QD_ERR_ARG, "Jacobi's integral is not conserved: %s",
                     I->jacobi.not_conserved ? I->jacobi.not_conserved : "it changes along "
                     "the motion");
        st = QD_ERR_ARG;
    } else {
        const qd_expr **zeros = qd__malloc(ctx, (e->n + 1) * sizeof *zeros);
        if (!zeros) {
            st = QD_ERR_NOMEM;
        } else {
            for (size_t j = 0; j < e->n; j++)
                zeros[j] = qd_int(ctx, 0);
            out->h = I->jacobi.h;
            out->W = qd_simplify(ctx, qd_subs(ctx, out->h, e->n, e->qd, zeros));
            qd__free(zeros);
            st = out->W ? QD_OK : qd_ctx_status(ctx);
        }
    }
    qd_integrals_free(I);
    return st;
}

static bool box_ok(const qd_eom *e, const qd_zvc_box *b) {
    return b->ix < e->n && b->iy < e->n && b->ix != b->iy && b->nx > 0 && b->ny > 0 &&
           b->lo[0] < b->hi[0] && b->lo[1] < b->hi[1] && isfinite(b->hi[0] - b->lo[0]) &&
           isfinite(b->hi[1] - b->lo[1]);
}

/* W at every grid point into f ((nx + 1) (ny + 1), x fastest). */
static qd_status grid_values(qd_ctx *ctx, const qd_eom *e, const qd_expr *W,
                             const qd_zvc_box *b, size_t nvals, const qd_expr *const *syms,
                             const double *vals, double *f) {
    size_t nin = 0, sx = SIZE_MAX, sy = SIZE_MAX;
    const qd_expr **in = qd__num_inputs(ctx, 1, &W, &nin);
    qd_prog *p = in ? qd_prog_new(ctx, nin, in, 1, &W) : NULL;
    double *iv = p ? qd__calloc(ctx, nin + 1, sizeof *iv) : NULL;
    qd_status st = p && iv ? QD_OK : (qd_ctx_status(ctx) ? qd_ctx_status(ctx) : QD_ERR_NOMEM);
    for (size_t i = 0; st == QD_OK && i < nin; i++) {
        for (size_t k = 0; k < nvals; k++)
            if (syms[k] == in[i])
                iv[i] = vals[k];
        sx = in[i] == e->q[b->ix] ? i : sx;
        sy = in[i] == e->q[b->iy] ? i : sy;
    }
    for (size_t j = 0; st == QD_OK && j <= b->ny; j++)
        for (size_t i = 0; i <= b->nx; i++) {
            double x = b->lo[0] + (b->hi[0] - b->lo[0]) * (double)i / (double)b->nx;
            double y = b->lo[1] + (b->hi[1] - b->lo[1]) * (double)j / (double)b->ny;
            if (sx != SIZE_MAX)
                iv[sx] = x;
            if (sy != SIZE_MAX)
                iv[sy] = y;
            qd_prog_run(p, iv, &f[i + j * (b->nx + 1)]);
        }
    qd_prog_free(p);
    qd__free(in);
    qd__free(iv);
    return st;
}

qd_status qd_zvc_curves(qd_ctx *ctx, const qd_eom *e, const qd_zvc *z, const qd_zvc_box *box,
                        size_t nvals, const qd_expr *const *syms, const double *vals,
                        double level, qd_contour *out) {
    QD_ARGS_CTX(ctx, ctx && e && z && box && out);
    memset(out, 0, sizeof *out);
    if (!ctx || !e || !z || !z->W || !box)
        return QD_ERR_ARG;
    if (!box_ok(e, box)) {
        qd_ctx_error(ctx, QD_ERR_ARG, "zero-velocity curves: the box needs two different "
                     "coordinates, each with a range LOW < HIGH, and at least one cell");
        return QD_ERR_ARG;
    }
    size_t npts = (box->nx + 1) * (box->ny + 1);
    double *f = qd__malloc(ctx, npts * sizeof *f);
    qd_status st = f ? grid_values(ctx, e, z->W, box, nvals, syms, vals, f) : QD_ERR_NOMEM;
    if (st == QD_OK)
        st = qd_contour_grid(ctx, box->nx, box->ny, f, box->lo[0], box->hi[0], box->lo[1],
                             box->hi[1], level, out);
    if (st == QD_ERR_NOMEM && qd_ctx_status(ctx) == QD_OK)
        qd_ctx_error(ctx, st, "out of memory tracing zero-velocity curves");
    qd__free(f);
    return st;
}

/*
 * src/lyap/tangent.c - what the Lyapunov exponents (benettin.c) and the
 * flow Jacobian (flow.c) share: their options' common checks, the run of
 * the state with k tangent vectors started at e_1 .. e_k on the
 * simulation's Runge-Kutta pairs (the qd_sim's ext_rhs), the driver that
 * lands on a given time, and the release.
 */
#include "lyap.h"

#include <math.h>
#include <string.h>

#include "base/mem.h"

qd_status qd__lyap_check_opts(qd_ctx *ctx, const qd_sim_opts *o, const char *subject) {
    qd_status st = qd_sim_check_opts(ctx, o);
    if (st != QD_OK)
        return st;
    if (o->method != QD_SIM_DOP853 && o->method != QD_SIM_DOPRI5) {
        qd_ctx_error(ctx, QD_ERR_ARG, "%s integrated with dopri5 or dop853, not %s", subject,
                     qd_sim_method_name(o->method));
        return QD_ERR_ARG;
    }
    if (!o->q0 || !o->qd0) {
        qd_ctx_error(ctx, QD_ERR_ARG, "the initial coordinates and velocities are needed");
        return QD_ERR_ARG;
    }
    return QD_OK;
}

qd_status qd__lyap_tangent_start(qd__lyap_tangent *r, qd_ctx *ctx, const qd_lyap *l,
                                 const qd_sim_opts *o, size_t k, size_t extra,
                                 const char *what) {
    size_t d = 2 * l->n, dim = d + d * k + 1;
    *r = (qd__lyap_tangent){.o = o, .d = d, .k = k};
    r->it = (qd__sim_integ){.method = o->method,
                        .ops = o->method == QD_SIM_DOPRI5 ? &qd__sim_dopri5 : &qd__sim_dop853,
                        .form = QD__LAG, .t = o->t0, .tend = o->t_end,
                        .rtol = o->rtol > 0 ? o->rtol : 1e-10,
                        .atol = o->atol > 0 ? o->atol : 1e-12, .fixed = o->fixed,
                        .h = o->fixed ? o->dt : 0};
    qd_status st = qd__lyap_ws_init(&r->ws, ctx, l, k, o->par);
    r->it.s = &r->ws.w;
    r->it.y = qd__calloc(ctx, 2 * dim + extra, sizeof *r->it.y);
    if (st != QD_OK || !r->it.y) {
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory starting %s", what);
        return QD_ERR_NOMEM;
    }
    r->it.yold = r->it.y + dim;
    r->extra = r->it.yold + dim;
    r->it.dim = dim;
    double *y = r->it.y;
    for (size_t i = 0; i < d / 2; i++) {
        y[i] = o->q0[i];
        y[d / 2 + i] = o->qd0[i];
    }
    for (size_t j = 0; j < k; j++)
        y[d + j * d + j] = 1;
    r->ws.w.ext_rhs = qd__lyap_rhs;
    r->ws.w.ext_data = &r->ws;
    return r->it.ops->init(&r->it);
}

qd_status qd__lyap_tangent_advance(qd__lyap_tangent *r, double tb) {
    qd__sim_integ *it = &r->it;
    size_t max = r->o->max_steps ? r->o->max_steps : QD_SIM_MAX_STEPS;
    while (it->t < tb) {
        if (it->steps >= max) {
            qd_ctx_error(r->ws.w.ctx, QD_ERR_NUMERIC, "more than %zu steps before t = %.17g "
                         "(at t = %.17g)", max, r->o->t_end, it->t);
            return QD_ERR_NUMERIC;
        }
        double h = it->fixed ? r->o->dt : it->h;
        bool last = it->t + 1.01 * h >= tb;
        it->h = last ? tb - it->t : h;
        r->ws.w.tnow = it->t;
        qd_status st = it->ops->step(it);
        if (st != QD_OK)
            return st;
        it->steps++;
        if (last && fabs(it->t - tb) <= 4e-16 * fabs(tb) + 1e-300) {
            it->t = tb;
            /* the shortened step says nothing about the step the solution
             * allows: keep the controller's proposal from before it */
            if (!it->fixed && it->h < h)
                it->h = h;
        }
    }
    return QD_OK;
}

void qd__lyap_tangent_free(qd__lyap_tangent *r) {
    if (r->it.ops && r->it.priv)
        r->it.ops->free(&r->it);
    qd__free(r->it.y);
    r->it.y = NULL;
    qd__lyap_ws_free(&r->ws);
}

/*
 * src/sim/system.c - a model compiled into a first-order system.
 *
 * Every program takes the same input vector (q, q', t, parameters), kept in
 * the qd_sim, so a right-hand side is a copy of the state into it, one or two
 * qd_prog runs and a small dense solve in preallocated scratch: no tree
 * walking and no allocation per step.  The canonical form needs no symbolic
 * inverse of M: q' = M^-1 (p - b) is solved numerically, and
 * -dH/dq|_p = dL/dq|_q' (the Legendre transform's identity, Goldstein
 * sec. 8.1), so dp/dt = dL/dq + Q - dD/dq' at the solved q'.
 */
#include "simint.h"
#include "taylor_native.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "codegen/codegen_export.h"
#include "num/num.h"
#include "sym/sym_export.h"
#include "base/mem.h"
#include "../base/args.h"

static char *dup_printf(qd_ctx *ctx, const char *a, const char *b, const char *c) {
    size_t len = strlen(a) + strlen(b) + strlen(c) + 1;
    char *s = qd__malloc(ctx, len);
    if (s)
        snprintf(s, len, "%s%s%s", a, b, c);
    return s;
}

static bool has_any(const qd_expr *x, size_t n, const qd_expr *const *syms) {
    for (size_t i = 0; i < n; i++)
        if (qd_has(x, syms[i]))
            return true;
    return false;
}

/* The outputs compiled into one program.  Sines and cosines of angle sums
 * are expanded first when that saves calls to the maths library (the
 * pendulum chain's cos(theta_j - theta_k): see src/codegen/angles.c), the
 * rewrite the generated C uses, so both paths compute the same formulas. */
qd_prog *qd__sim_prog_of(qd_sim *s, size_t nparts, const qd_expr *const *const *parts,
                         const size_t *size, size_t *count) {
    size_t nout = 0, k = 0;
    for (size_t i = 0; i < nparts; i++)
        nout += size[i];
    const qd_expr **x = qd__malloc(s->ctx, (nout + 1) * sizeof *x);
    bool applied;
    qd_prog *p = NULL;
    if (x) {
        for (size_t i = 0; i < nparts; i++)
            for (size_t j = 0; j < size[i]; j++)
                x[k++] = parts[i][j];
        if (qd__cg_angle_sums(s->ctx, nout, x, &applied) == QD_OK)
            p = qd_prog_new(s->ctx, s->nin, s->in_syms, nout, x);
        qd__free(x);
    } else {
        qd_ctx_error(s->ctx, QD_ERR_NOMEM, "out of memory compiling the simulation");
    }
    *count = nout;
    return p;
}

qd_prog *qd__sim_prog(qd_sim *s, size_t nout, const qd_expr *const *outs, size_t *count) {
    return qd__sim_prog_of(s, 1, &outs, &nout, count);
}

qd_status qd__sim_inputs(qd_sim *s, const qd_expr *const *q, const qd_expr *const *qd,
                         size_t ntail) {
    size_t n = s->n;
    s->np = qd_model_nparams(s->model);
    s->nuin = qd_model_ninputs(s->model);
    s->uin_off = 2 * n + 1 + s->np + ntail;
    s->nin = s->uin_off + s->nuin;
    s->in_syms = qd__malloc(s->ctx, s->nin * sizeof *s->in_syms);
    s->par = qd__calloc(s->ctx, s->np + 1, sizeof *s->par);
    if (!s->in_syms || !s->par)
        return QD_ERR_NOMEM;
    for (size_t j = 0; j < n; j++) {
        s->in_syms[j] = q[j];
        s->in_syms[n + j] = qd[j];
    }
    s->in_syms[2 * n] = qd_time(s->ctx);
    for (size_t i = 0; i < s->np; i++) {
        s->in_syms[2 * n + 1 + i] = qd_model_param(s->model, i);
        qd_status st = qd_model_param_number(s->model, i, &s->par[i]);
        if (st != QD_OK) {
            if (st == QD_ERR_ARG)
                qd_ctx_error(s->ctx, QD_ERR_ARG, "parameter %s has no finite value",
                             qd_expr_name(s->in_syms[2 * n + 1 + i]));
            return st;
        }
    }
    return qd__sim_uin_init(s);
}

static qd_status setup_inputs(qd_sim *s) {
    const qd_eom *e = s->e;
    size_t n = s->n, m = s->m;
    qd_status st = qd__sim_inputs(s, e->q, e->qd, m + n);
    for (size_t k = 0; st == QD_OK && k < m; k++)
        s->in_syms[2 * n + 1 + s->np + k] = e->con[k].lambda;
    /* an output r'' or an event guard r'' > 0 (a perihelion) reads them */
    for (size_t j = 0; st == QD_OK && j < n; j++)
        s->in_syms[2 * n + 1 + s->np + m + j] = e->qdd[j];
    return st;
}

static qd_status compile_acc(qd_sim *s) {
    const qd_eom *e = s->e;
    size_t n = s->n, m = s->m;
    const qd_expr *const *parts[] = {e->M, e->f, e->A, e->b};
    const size_t size[] = {n * n, n, m * n, m};
    s->acc = qd__sim_prog_of(s, 4, parts, size, &s->acc_n);
    if (!s->acc)
        return qd_ctx_status(s->ctx);
    return qd__sim_con_prog(s);
}

qd_status qd__sim_con_prog(qd_sim *s) {
    size_t n = s->n, m = s->m, k = 0;
    if (!m)
        return QD_OK;
    const qd_expr **outs = qd__malloc(s->ctx, (m * (n + 2) + 1) * sizeof *outs);
    if (!outs)
        return QD_ERR_NOMEM;
    for (size_t i = 0; i < m; i++)
        for (size_t j = 0; j < n; j++)
            outs[k++] = s->cons[i].a[j];
    for (size_t i = 0; i < m; i++)
        outs[k++] = s->cons[i].a0;
    for (size_t i = 0; i < m; i++)
        outs[k++] = s->cons[i].expr;
    s->con = qd__sim_prog(s, k, outs, &s->con_n);
    qd__free(outs);
    return s->con ? QD_OK : qd_ctx_status(s->ctx);
}

static size_t model_index(const qd_sim *s, const qd_expr *q) {
    for (size_t i = 0; i < qd_model_ncoords(s->model); i++)
        if (qd_model_coord(s->model, i) == q)
            return i;
    return (size_t)-1;
}

/* A constraint that moves with t (phi(q, t) with dphi/dt = a0 != 0, or t in
 * its coefficients) does work on the system, so h is not conserved: a bead
 * on a wire turning at omega, written as th = omega t, changed its T + V by
 * 54% in a unit of time, and the summary called that an energy "error"
 * (issue 33). */
static bool moving_constraint(const qd_eom *e, const qd_expr *t) {
    for (size_t k = 0; k < e->ncon; k++) {
        const qd_con *c = &e->con[k];
        if (c->a0 && !qd_is_zero(c->a0))
            return true;
        for (size_t j = 0; j < e->n; j++)
            if (c->a[j] && qd_has(c->a[j], t))
                return true;
    }
    return false;
}

/* h = sum q' dL/dq' - L, T, the canonical pieces and what the system is. */
static qd_status analyse(qd_sim *s) {
    qd_ctx *ctx = s->ctx;
    const qd_eom *e = s->e;
    size_t n = s->n;
    const qd_expr *L = e->L, *D = qd_model_dissipation(s->model), *t = qd_time(ctx);
    const qd_expr **zeros = qd__malloc(ctx, (n + 1) * sizeof *zeros);
    s->b_expr = qd__calloc(ctx, n + 1, sizeof *s->b_expr);
    s->force_expr = qd__calloc(ctx, n + 1, sizeof *s->force_expr);
    if (!zeros || !s->b_expr || !s->force_expr) {
        qd__free(zeros);
        return QD_ERR_NOMEM;
    }
    for (size_t j = 0; j < n; j++)
        zeros[j] = qd_int(ctx, 0);
    const qd_expr *h = qd_neg(ctx, L);
    bool forces = false;
    /* an input is a force from outside: no canonical form, nothing conserved */
    s->canonical = s->m == 0 && e->nelim == 0 && s->nuin == 0;
    s->separable = s->canonical;
    for (size_t j = 0; j < n; j++) {
        const qd_expr *pdef = qd_diff(ctx, L, e->qd[j]);
        h = qd_add(ctx, h, qd_mul(ctx, e->qd[j], pdef));
        s->b_expr[j] = qd_simplify(ctx, qd_subs(ctx, pdef, n, e->qd, zeros));
        size_t mi = model_index(s, e->q[j]);
        const qd_expr *Q = mi != (size_t)-1 ? qd_model_force(s->model, mi) : qd_int(ctx, 0);
        forces = forces || (Q && !qd_is_zero(Q));
        const qd_expr *F = qd_add(ctx, qd_diff(ctx, L, e->q[j]), Q);
        if (D)
            F = qd_sub(ctx, F, qd_diff(ctx, D, e->qd[j]));
        s->force_expr[j] = F;
        if (!s->b_expr[j] || !F)
            break;
        s->separable = s->separable && qd_is_zero(s->b_expr[j]) && !has_any(F, n, e->qd) &&
                       !qd_has(F, t);
        for (size_t k = 0; k < n; k++) {
            const qd_expr *Mjk = e->M[j * n + k];
            s->canonical = s->canonical && !has_any(Mjk, n, e->qd);
            s->separable = s->separable && !has_any(Mjk, n, e->q) && !qd_has(Mjk, t);
        }
    }
    s->separable = s->separable && s->canonical;
    s->h_expr = qd_simplify(ctx, h);
    s->has_T = e->T2 != NULL;
    s->T_expr = s->has_T ? qd_add(ctx, qd_add(ctx, e->T2, e->T1), e->T0) : qd_int(ctx, 0);
    s->conservative = !qd_has(L, t) && !forces && !(D && !qd_is_zero(D)) && s->nuin == 0 &&
                      !moving_constraint(e, t);
    qd__free(zeros);
    return qd_ctx_status(ctx) == QD_OK && s->h_expr ? QD_OK : qd_ctx_status(ctx);
}

static qd_status compile_canonical(qd_sim *s) {
    size_t n = s->n;
    if (!s->canonical)
        return QD_OK;
    const qd_expr *const *parts[] = {s->e->M, s->b_expr};
    const size_t size[] = {n * n, n};
    s->mom = qd__sim_prog_of(s, 2, parts, size, &s->mom_n);
    if (s->mom)
        s->force = qd__sim_prog(s, n, s->force_expr, &s->force_n);
    return s->mom && s->force ? QD_OK : qd_ctx_status(s->ctx);
}

/* Coordinate j and its momentum's column name (p_q, or the name given in
 * `momenta` for a model given by H). */
static const qd_expr *coord(const qd_sim *s, size_t j) {
    return s->e ? s->e->q[j] : s->se ? s->se->q[j] : qd_model_coord(s->model, j);
}

static char *momentum_name(const qd_sim *s, size_t j) {
    if (s->hamilton)
        return dup_printf(s->ctx, qd_expr_name(qd_model_momentum(s->model, j)), "", "");
    return dup_printf(s->ctx, "p_", qd_expr_name(coord(s, j)), "");
}

/* The names of the state's second half: the momenta, or the speeds (a
 * system in speeds has no momenta column). */
static char *second_name(const qd_sim *s, size_t j) {
    if (s->se)
        return j < s->nu ? dup_printf(s->ctx, qd_expr_name(s->se->u[j]), "", "") : NULL;
    return momentum_name(s, j);
}

/* t, q, q', p (or, in speeds: t, q, u, q'), energy, res_c. */
qd_status qd__sim_names(qd_sim *s) {
    size_t n = s->n, k = 0, nsecond = s->se ? s->nu : n;
    s->nnames = 2 * n + nsecond + 2 + s->m + (s->nfc ? 2 * s->nfc + qd__sim_fric_nextra(s) : 0);
    s->names = qd__calloc(s->ctx, s->nnames, sizeof *s->names);
    s->holonomic = qd__calloc(s->ctx, s->m + 1, sizeof *s->holonomic);
    s->con_err_last = qd__calloc(s->ctx, s->m + 1, sizeof *s->con_err_last);
    s->solved_last = qd__calloc(s->ctx, n + 1, sizeof *s->solved_last);
    if (!s->names || !s->holonomic || !s->con_err_last || !s->solved_last)
        return QD_ERR_NOMEM;
    s->names[k++] = dup_printf(s->ctx, "t", "", "");
    for (size_t j = 0; j < n; j++)
        s->names[k++] = dup_printf(s->ctx, qd_expr_name(coord(s, j)), "", "");
    for (size_t j = 0; s->se && j < nsecond; j++)
        s->names[k++] = second_name(s, j);
    for (size_t j = 0; j < n; j++)
        s->names[k++] = dup_printf(s->ctx, qd_expr_name(coord(s, j)), "'", "");
    for (size_t j = 0; !s->se && j < nsecond; j++)
        s->names[k++] = second_name(s, j);
    s->names[k++] = dup_printf(s->ctx, "energy", "", "");
    for (size_t c = 0; c < s->m; c++) {
        s->names[k++] = dup_printf(s->ctx, "res_", s->cons[c].name, "");
        s->holonomic[c] = s->cons[c].kind == QD_CON_HOLONOMIC;
    }
    for (size_t c = 0; c < s->nfc; c++) {
        s->names[k++] = dup_printf(s->ctx, "slip_", s->fc[c].name, "");
        s->names[k++] = dup_printf(s->ctx, "mode_", s->fc[c].name, "");
    }
    if (s->nfc)
        s->names[k++] = dup_printf(s->ctx, "dissipated", "", "");
    if (s->nfc && s->rheo)
        s->names[k++] = dup_printf(s->ctx, "surface_work", "", "");
    for (size_t i = 0; i < k; i++)
        if (!s->names[i])
            return QD_ERR_NOMEM;
    return QD_OK;
}

qd_sim *qd__sim_alloc(qd_ctx *ctx, const qd_sim *init) {
    qd_sim *s = qd__calloc(ctx, 1, sizeof *s);
    if (!s)
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory");
    else
        *s = *init;
    return s;
}

qd_sim *qd__sim_made(qd_sim *s, qd_status st, const char *what) {
    if (st == QD_OK)
        return s;
    if (qd_ctx_status(s->ctx) == QD_OK)
        qd_ctx_error(s->ctx, st, "%s", what);
    qd_sim_free(s);
    return NULL;
}

qd_sim *qd_sim_new(qd_ctx *ctx, const qd_model *m, const qd_eom *e) {
    QD_ARGS(NULL, ctx && m && e);
    if (e->nelim) {
        qd_ctx_error(ctx, QD_ERR_ARG, "simulation needs the equations without eliminated "
                                      "coordinates");
        return NULL;
    }
    qd_sim *s = qd__sim_alloc(ctx, &(qd_sim){.ctx = ctx, .model = m, .e = e, .n = e->n,
                                            .m = e->ncon, .cons = e->con});
    if (!s)
        return NULL;
    qd_status st = setup_inputs(s);
    if (st == QD_OK)
        st = compile_acc(s);
    if (st == QD_OK)
        st = analyse(s);
    if (st == QD_OK)
        st = compile_canonical(s);
    if (st == QD_OK)
        st = qd__sim_fric_setup(s);
    if (st == QD_OK)
        st = qd__sim_names(s);
    if (st == QD_OK)
        st = qd__sim_impact_setup(s);
    return qd__sim_made(s, st, "cannot compile the equations for simulation");
}

void qd_sim_free(qd_sim *s) {
    if (!s)
        return;
    qd__free(s->con_err_last);
    qd__free(s->solved_last);
    qd__sim_impact_free(s);
    qd__sim_fric_free(s);
    qd__sim_taylor_native_free(s);
    qd_prog_free(s->acc);
    qd_prog_free(s->con);
    qd_prog_free(s->mom);
    qd_prog_free(s->force);
    qd_prog_free(s->aux);
    qd_prog_free(s->en);
    qd_prog_free(s->evp);
    qd_prog_free(s->kin);
    qd_prog_free(s->udef);
    qd__sim_uin_free(s);
    qd__free(s->in_syms);
    qd__free(s->par);
    qd__free(s->b_expr);
    qd__free(s->force_expr);
    qd__free(s->holonomic);
    for (size_t i = 0; s->names && i < s->nnames; i++)
        qd__free(s->names[i]);
    qd__free(s->names);
    for (size_t i = 0; i < s->nout; i++)
        qd__free(s->out_name[i]);
    qd__free(s->out_name);
    qd__free(s->out_expr);
    qd__free(s->ev_expr);
    qd__free(s->guard_expr);
    qd__free(s->ev);
    qd__free(s);
}

size_t qd_sim_ndof(const qd_sim *s) { QD_ARGS(0, s); return s->n; }
size_t qd_sim_ncon(const qd_sim *s) { QD_ARGS(0, s); return s->m; }
size_t qd_sim_nevents(const qd_sim *s) { QD_ARGS(0, s); return s->nev; }
bool qd_sim_canonical(const qd_sim *s) { QD_ARGS(false, s); return s->canonical; }
double qd_sim_constraint_error(const qd_sim *s, size_t c) {
    QD_ARGS(NAN, s);
    return c < s->m ? s->con_err_last[c] : 0;
}
bool qd_sim_initial_solved(const qd_sim *s, size_t j) {
    QD_ARGS(false, s);
    return j < s->n && s->solved_last && s->solved_last[j];
}
bool qd_sim_separable(const qd_sim *s) { QD_ARGS(false, s); return s->separable; }
bool qd_sim_conservative(const qd_sim *s) { QD_ARGS(false, s); return s->conservative; }

qd_sim_method qd_sim_default_method(const qd_sim *s, bool fixed_step) {
    QD_ARGS((qd_sim_method)0, s);
    return fixed_step && s->m == 0 && s->conservative ? QD_SIM_GL4 : QD_SIM_DOP853;
}

/* ---- outputs and events ---------------------------------------------------- */

static bool grow(qd_ctx *ctx, void **p, size_t *cap, size_t need, size_t size) {
    if (need <= *cap)
        return true;
    size_t c = *cap ? 2 * *cap : 8;
    while (c < need)
        c *= 2;
    void *q = qd__realloc(ctx, *p, c * size);
    if (!q)
        return false;
    *p = q;
    *cap = c;
    return true;
}

qd_status qd_sim_add_output(qd_sim *s, const char *name, const qd_expr *x) {
    QD_ARGS(QD_ERR_ARG, s && name && x);
    if (s->aux_ready || !x || !name) {
        qd_ctx_error(s->ctx, QD_ERR_ARG, "outputs are added before the first run");
        return QD_ERR_ARG;
    }
    size_t cap = s->cap_out;
    bool ok = grow(s->ctx, (void **)&s->out_expr, &cap, s->nout + 1, sizeof *s->out_expr);
    cap = s->cap_out;
    ok = ok && grow(s->ctx, (void **)&s->out_name, &cap, s->nout + 1, sizeof *s->out_name);
    s->cap_out = ok ? cap : s->cap_out;
    char *copy = ok ? dup_printf(s->ctx, name, "", "") : NULL;
    if (!copy) {
        qd_ctx_error(s->ctx, QD_ERR_NOMEM, "out of memory");
        return QD_ERR_NOMEM;
    }
    s->out_expr[s->nout] = x;
    s->out_name[s->nout++] = copy;
    return QD_OK;
}

qd_status qd_sim_add_event(qd_sim *s, const qd_expr *g, size_t nguard,
                           const qd_expr *const *guard, bool stop) {
    QD_ARGS(QD_ERR_ARG, s && g);
    if (s->aux_ready || !g) {
        qd_ctx_error(s->ctx, QD_ERR_ARG, "events are added before the first run");
        return QD_ERR_ARG;
    }
    size_t cap = s->cap_ev;
    bool ok = grow(s->ctx, (void **)&s->ev_expr, &cap, s->nev + 1, sizeof *s->ev_expr);
    cap = s->cap_ev;
    ok = ok && grow(s->ctx, (void **)&s->ev, &cap, s->nev + 1, sizeof *s->ev);
    s->cap_ev = ok ? cap : s->cap_ev;
    ok = ok && grow(s->ctx, (void **)&s->guard_expr, &s->cap_guard, s->nguard + nguard + 1,
                    sizeof *s->guard_expr);
    if (!ok) {
        qd_ctx_error(s->ctx, QD_ERR_NOMEM, "out of memory");
        return QD_ERR_NOMEM;
    }
    for (size_t i = 0; i < nguard; i++)
        s->guard_expr[s->nguard++] = guard[i];
    s->ev_expr[s->nev] = g;
    s->ev[s->nev++] = (qd__sim_event){.stop = stop, .nguard = nguard};
    return QD_OK;
}

/* aux over outs[0 .. k) and, when there are events (ne from e0), evp over
 * those alone.  A step's sampling evaluates the events several times per
 * step; aux would compute h, T, the constraints and the outputs each time
 * for nothing.  Both programs are compiled from the same expressions after
 * one angle-sum rewrite of the whole set (qd__sim_prog's, decided for the
 * set), so that evp gives the doubles aux gives: a sample and a row agree
 * on an event's sign. */
static qd_prog *aux_programs(qd_sim *s, size_t k, const qd_expr *const *outs, size_t e0,
                             size_t ne) {
    const qd_expr **x = qd__malloc(s->ctx, (k + 1) * sizeof *x);
    bool applied;
    qd_prog *p = NULL;
    s->aux_n = k;
    s->evp_n = ne;
    if (!x) {
        qd_ctx_error(s->ctx, QD_ERR_NOMEM, "out of memory compiling the simulation");
        return NULL;
    }
    memcpy(x, outs, k * sizeof *x);
    if (qd__cg_angle_sums(s->ctx, k, x, &applied) == QD_OK) {
        p = qd_prog_new(s->ctx, s->nin, s->in_syms, k, x);
        if (p && ne)
            s->evp = qd_prog_new(s->ctx, s->nin, s->in_syms, ne, x + e0);
    }
    qd__free(x);
    return p;
}

qd_status qd__sim_aux_compile(qd_sim *s) {
    if (s->aux_ready)
        return QD_OK;
    qd_prog_free(s->aux);
    qd_prog_free(s->en);
    qd_prog_free(s->evp);
    s->aux = s->en = s->evp = NULL;
    size_t total = qd__sim_aux_guard(s) + s->nguard, k = 0;
    const qd_expr **outs = qd__malloc(s->ctx, (total + 1) * sizeof *outs);
    if (!outs)
        return QD_ERR_NOMEM;
    outs[k++] = s->h_expr;
    outs[k++] = s->T_expr;
    for (size_t c = 0; c < s->m; c++)
        outs[k++] = s->cons[c].expr;
    for (size_t i = 0; i < s->nout; i++)
        outs[k++] = s->out_expr[i];
    for (size_t i = 0; i < s->nev; i++)
        outs[k++] = s->ev_expr[i];
    for (size_t i = 0; i < s->nimp; i++)
        outs[k++] = s->imp_gap[i];
    for (size_t i = 0; i < s->nguard; i++)
        outs[k++] = s->guard_expr[i];
    if (s->hamilton)
        qd__sim_hamilton_velocities(s, k - 2, outs + 2);
    if (s->se)
        qd__sim_speeds_defs(s, k - 2, outs + 2);
    size_t e0 = qd__sim_aux_ev(s), ne = s->nev + s->nimp;
    s->aux = aux_programs(s, k, outs, e0, ne);
    s->aux_lambda = s->aux_acc = s->ev_lambda = s->ev_acc = false;
    /* in speeds the multipliers are not inputs: compiling names them */
    for (size_t i = 2 + s->m; !s->se && i < k; i++)
        for (size_t c = 0; c < s->m; c++) {
            bool has = qd_has(outs[i], s->cons[c].lambda);
            s->aux_lambda = s->aux_lambda || has;
            s->ev_lambda = s->ev_lambda || (has && i >= e0 && i < e0 + ne);
        }
    /* nor, in speeds or an H model, the accelerations */
    for (size_t i = 2 + s->m; !s->se && !s->hamilton && i < k; i++) {
        bool has = has_any(outs[i], s->n, s->e->qdd);
        s->aux_acc = s->aux_acc || has;
        s->ev_acc = s->ev_acc || (has && i >= e0 && i < e0 + ne);
    }
    /* outputs and events are needed at rows and event checks only; the
     * energy measure at every step */
    if (s->aux && k > 2 + s->m)
        s->en = qd__sim_prog(s, 2, outs, &s->en_n);
    qd__free(outs);
    s->aux_ready = s->aux != NULL && (k == 2 + s->m || s->en != NULL) && (!ne || s->evp);
    return s->aux_ready ? QD_OK : qd_ctx_status(s->ctx);
}

qd_status qd_sim_compile(qd_sim *s) {
    QD_ARGS(QD_ERR_ARG, s);
    qd_status st = qd__sim_uin_compile(s);
    return st == QD_OK ? qd__sim_aux_compile(s) : st;
}

bool qd_sim_compiled(const qd_sim *s) { QD_ARGS(false, s); return s->aux_ready; }

/* ---- a run's workspace ------------------------------------------------------ */

/* One program's output buffer and workspace; *out and *work NULL when the
 * program is (the missing programs of a system without them). */
static bool prog_ws(qd_ctx *ctx, const qd_prog *p, size_t nout, double **out, double **work) {
    *out = *work = NULL;
    if (!p)
        return true;
    *out = qd__malloc(ctx, (nout + 1) * sizeof **out);
    *work = qd__malloc(ctx, qd_prog_work_size(p) * sizeof **work);
    if (*work)
        qd_prog_work_init(p, *work);
    return *out && *work;
}

qd_status qd__sim_ws_alloc(qd_sim *w, qd_ctx *ctx) {
    size_t n = w->n, N = n + w->m;
    w->ctx = ctx;
    w->in = qd__calloc(ctx, w->nin + 1, sizeof *w->in);
    /* K: the matrix, rhs (N), tmp (N + 4n), the right-hand side kept for
     * solve_mass's second try (n) */
    w->K = qd__malloc(ctx, (N * N + 2 * N + 5 * n + 1) * sizeof *w->K);
    w->pc = qd__malloc(ctx, (N + 1) * sizeof *w->pc);
    w->con_err = qd__calloc(ctx, w->m + 1, sizeof *w->con_err);
    w->solved = qd__calloc(ctx, n + 1, sizeof *w->solved);
    bool ok = prog_ws(ctx, w->acc, w->acc_n, &w->acc_out, &w->acc_w);
    ok = prog_ws(ctx, w->con, w->con_n, &w->con_out, &w->con_w) && ok;
    ok = prog_ws(ctx, w->mom, w->mom_n, &w->mom_out, &w->mom_w) && ok;
    ok = prog_ws(ctx, w->force, w->force_n, &w->force_out, &w->force_w) && ok;
    ok = prog_ws(ctx, w->aux, w->aux_n, &w->aux_out, &w->aux_w) && ok;
    ok = prog_ws(ctx, w->en, w->en_n, &w->en_out, &w->en_w) && ok;
    ok = prog_ws(ctx, w->imp, w->imp_n, &w->imp_out, &w->imp_w) && ok;
    ok = prog_ws(ctx, w->evp, w->evp_n, &w->evp_out, &w->evp_w) && ok;
    ok = prog_ws(ctx, w->kin, w->kin_n, &w->kin_out, &w->kin_w) && ok;
    ok = prog_ws(ctx, w->udef, w->udef_n, &w->udef_out, &w->udef_w) && ok;
    ok = prog_ws(ctx, w->uprog, w->nuin, &w->uprog_out, &w->uprog_w) && ok;
    if (!ok || !w->in || !w->K || !w->pc || !w->con_err || !w->solved)
        return QD_ERR_NOMEM;
    w->rhs = w->K + N * N;
    w->tmp = w->rhs + N;
    for (size_t i = 0; i < w->np; i++)
        w->in[2 * n + 1 + i] = w->par[i];
    w->evals = 0;
    return QD_OK;
}

void qd__sim_ws_free(qd_sim *w) {
    double *bufs[] = {w->in, w->K, w->con_err, w->acc_out, w->acc_w, w->con_out, w->con_w,
                      w->mom_out, w->mom_w, w->force_out, w->force_w, w->aux_out, w->aux_w,
                      w->en_out, w->en_w, w->imp_out, w->imp_w, w->evp_out, w->evp_w,
                      w->kin_out, w->kin_w,
                      w->udef_out, w->udef_w, w->uprog_out, w->uprog_w};
    for (size_t i = 0; i < sizeof bufs / sizeof *bufs; i++)
        qd__free(bufs[i]);
    qd__free(w->pc);
    qd__free(w->solved);
}

size_t qd_sim_columns(const qd_sim *s, qd_sim_method method, const char **names, size_t cap) {
    QD_ARGS(0, s);
    size_t n = s->n, k = 0;
    bool ham = s->hamilton || ((method >= QD_SIM_GL2 && method <= QD_SIM_YOSHIDA8) &&
                               s->canonical);
    for (size_t i = 0; i < s->nnames; i++) {
        if (!s->se && i >= 1 + 2 * n && i < 1 + 3 * n && !ham)
            continue;
        if (names && k < cap)
            names[k] = s->names[i];
        k++;
    }
    for (size_t i = 0; i < s->nout; i++, k++)
        if (names && k < cap)
            names[k] = s->out_name[i];
    return k;
}

/* ---- evaluation ------------------------------------------------------------ */

static void set_state(qd_sim *s, double t, const double *q, const double *qd) {
    size_t n = s->n;
    /* a few numbers: a loop, not a call to memcpy */
    for (size_t i = 0; i < n; i++)
        s->in[i] = q[i];
    for (size_t i = 0; qd && i < n; i++)
        s->in[n + i] = qd[i];
    s->in[2 * n] = t;
    if (s->nuin)
        qd__sim_uin_eval(s, t);
}

static bool saddle_solve(qd_sim *s, double t, const double *y);

void qd__sim_prog_at(qd_sim *s, const qd_prog *p, double *work, double t, const double *q,
                 const double *qd, double *out) {
    set_state(s, t, q, qd);
    qd_prog_eval(p, work, s->in, out);
}

/* The multipliers and accelerations at the state set: the saddle-point
 * solve of the right-hand side; NaN where it is singular. */
static void second_inputs(qd_sim *s, double t) {
    double *lambda = s->in + 2 * s->n + 1 + s->np, *qdd = lambda + s->m;
    bool ok = saddle_solve(s, t, NULL);
    for (size_t k = 0; k < s->m; k++)
        lambda[k] = ok ? s->rhs[s->n + k] : NAN;
    for (size_t j = 0; j < s->n; j++)
        qdd[j] = ok ? s->rhs[j] : NAN;
}

void qd__sim_aux_eval(qd_sim *s, double t, const double *q, const double *qd) {
    set_state(s, t, q, qd);
    if (s->aux_lambda || s->aux_acc)
        second_inputs(s, t);
    qd_prog_eval(s->aux, s->aux_w, s->in, s->aux_out);
}

const double *qd__sim_ev_eval(qd_sim *s, double t, const double *q, const double *qd) {
    if (!s->evp) {
        qd__sim_aux_eval(s, t, q, qd);
        return s->aux_out + qd__sim_aux_ev(s);
    }
    set_state(s, t, q, qd);
    if (s->ev_lambda || s->ev_acc)
        second_inputs(s, t);
    qd_prog_eval(s->evp, s->evp_w, s->in, s->evp_out);
    return s->evp_out;
}

const double *qd__sim_energy_eval(qd_sim *s, double t, const double *q, const double *qd) {
    set_state(s, t, q, qd);
    if (!s->en) {
        qd_prog_eval(s->aux, s->aux_w, s->in, s->aux_out);
        return s->aux_out;
    }
    qd_prog_eval(s->en, s->en_w, s->in, s->en_out);
    return s->en_out;
}

void qd__sim_con_eval(qd_sim *s, double t, const double *q, const double *qd) {
    set_state(s, t, q, qd);
    qd_prog_eval(s->con, s->con_w, s->in, s->con_out);
}

static qd_status singular(qd_sim *s, double t) {
    qd__sim_stop(s, QD_STOP_SINGULAR, t, NAN);
    if (s->m)
        qd_ctx_error(s->ctx, QD_ERR_SINGULAR,
                     "singular mass matrix at t = %.17g: the constrained equations "
                     "[M -A^T; A 0] cannot be solved for the accelerations there", t);
    else
        qd_ctx_error(s->ctx, QD_ERR_SINGULAR,
                     "singular mass matrix at t = %.17g: the accelerations are not "
                     "determined there", t);
    return QD_ERR_SINGULAR;
}

/* NaN or infinity in M is not a singular matrix, and not always a state
 * outside the domain of L: the message names what the numbers say (issue
 * 30).  The state in s->in (q, q', t as last set) not finite, or grown
 * past 1e100, is an overflow (a blow-up, or a step too long); else an
 * infinity at a finite state is a division by zero (a singular point of
 * the coordinates: gimbal lock where sin(theta) divides, 1/sqrt(1 -
 * v^2/c^2) at v = c); else a NaN is an expression outside its domain
 * (sqrt or log of a negative number, 0/0, sqrt(1 - v^2/c^2) at |v| > c).
 * Only the matrices stop the run here: a non-finite f gives non-finite
 * accelerations, which an adaptive method rejects (erk.c) and retries
 * with a smaller step; run.c checks every state the run reaches. */
static bool any_nan(const double *x, size_t n) {
    for (size_t i = 0; x && i < n; i++)
        if (isnan(x[i]))
            return true;
    return false;
}

const char *qd__sim_nonfinite_cause(const qd_sim *s, const double *x, size_t nx) {
    double big = 0;
    for (size_t i = 0; i < 2 * s->n + 1; i++)
        big = isnan(s->in[i]) ? INFINITY : fmax(big, fabs(s->in[i]));
    if (!(big <= 1e100))
        return "an overflow: the state has grown beyond what a double holds (a solution "
               "that blows up in finite time, or a step too long for it)";
    if (!any_nan(x, nx))
        return "a division by zero at a finite state: a point where the model's expressions "
               "are infinite (coordinates that degenerate there, such as Euler angles in "
               "gimbal lock, or 1/sqrt(1 - v^2/c^2) at a speed equal to c)";
    return "the state is outside the domain of the model's expressions (a square root or "
           "logarithm of a negative number, 0/0, or sqrt(1 - v^2/c^2) at a speed above c)";
}

qd_status qd__sim_not_finite_at(qd_sim *s, double t, const char *what, const double *x,
                                size_t nx) {
    qd__sim_stop(s, QD_STOP_NONFINITE, t, nx ? x[0] : NAN);
    qd_ctx_error(s->ctx, QD_ERR_NUMERIC, "%s not finite at t = %.17g: %s", what, t,
                 qd__sim_nonfinite_cause(s, x, nx));
    return QD_ERR_NUMERIC;
}

qd_status qd__sim_not_finite(qd_sim *s, double t, const char *what) {
    return qd__sim_not_finite_at(s, t, what, NULL, 0);
}

static bool all_finite(const double *x, size_t n) {
    for (size_t i = 0; i < n; i++)
        if (!isfinite(x[i]))
            return false;
    return true;
}

/* M and A of the last evaluation of the (q, q') system (acc_out: M, f, A, b). */
static bool matrices_finite(const qd_sim *s) {
    size_t n = s->n;
    return all_finite(s->acc_out, n * n) && all_finite(s->acc_out + n * n + n, s->m * n);
}

/* Solve the n*n matrix M x = r in scratch; x may alias r.  Cholesky
 * first (M is symmetric, and positive definite for a kinetic energy: half
 * the LU's work), the equilibrated LU when a pivot is not positive (an
 * indefinite velocity part of L) or small, which then decides singularity
 * as before; r is kept in K's spare room for that second try. */
static qd_status solve_mass(qd_sim *s, double t, const double *M, const double *r, double *x) {
    size_t n = s->n;
    if (!all_finite(M, n * n))
        return qd__sim_not_finite_at(s, t, "the mass matrix is", M, n * n);
    double *r0 = s->K + (n + s->m) * (n + s->m) + 2 * (n + s->m) + 4 * n; /* its own room */
    memcpy(s->K, M, n * n * sizeof *M);
    memcpy(r0, r, n * sizeof *r);
    memcpy(x, r0, n * sizeof *x);
    if (qd__num_solve_spd(n, s->K, x, QD__SIM_SPD_TOL))
        return QD_OK;
    memcpy(s->K, M, n * n * sizeof *M);
    memcpy(x, r0, n * sizeof *x);
    if (!qd__num_solve(n, s->K, x, 1e-13 * (double)n))
        return singular(s, t);
    return QD_OK;
}

void qd_sim_set_native(qd_sim *s, qd_sim_native_rhs rhs) { QD_ARGS(, s); s->native = rhs; }

/* [M -A^T; A 0] [q''; lambda] = [f; b] at the state in s->in (y, when not
 * NULL, is set first), solved into s->rhs; false when singular. */
static bool saddle_solve(qd_sim *s, double t, const double *y) {
    size_t n = s->n, m = s->m, N = n + m;
    if (y)
        set_state(s, t, y, y + n);
    qd_prog_eval(s->acc, s->acc_w, s->in, s->acc_out);
    const double *M = s->acc_out, *f = M + n * n;
    const double *A = f + n, *b = A + m * n;
    qd__num_saddle(n, m, M, f, A, b, s->K, s->rhs);
    if (s->fr)
        qd__sim_fric_saddle(s, s->K, s->rhs);
    return qd__num_solve(N, s->K, s->rhs, 1e-13 * (double)N);
}

bool qd__sim_saddle(qd_sim *s, double t, const double *y) { return saddle_solve(s, t, y); }

static qd_status lag_rhs(qd_sim *s, double t, const double *y, double *dy) {
    size_t n = s->n;
    /* the generated code knows nothing of friction's modes */
    if (s->native && !s->fr)
        return s->native(t, y, s->in + 2 * n + 1, dy) ? singular(s, t) : QD_OK;
    for (size_t i = 0; i < n; i++)
        dy[i] = y[n + i];
    if (s->m) {
        if (!saddle_solve(s, t, y)) {
            if (matrices_finite(s))
                return singular(s, t);
            /* the values not finite: M's, else A's */
            bool m_ok = all_finite(s->acc_out, n * n);
            return qd__sim_not_finite_at(s, t, m_ok ? "the constraint matrix is"
                                                    : "the mass matrix is",
                                         s->acc_out + (m_ok ? n * n + n : 0),
                                         m_ok ? s->m * n : n * n);
        }
        memcpy(dy + n, s->rhs, n * sizeof *dy);
        if (s->fr)
            dy[2 * n] = qd__sim_fric_power(s);
        if (s->fr && s->rheo)
            dy[2 * n + 1] = qd__sim_fric_surface_power(s);
        return QD_OK;
    }
    set_state(s, t, y, y + n);
    /* jitted with its solve (jit.c): M and f in acc_out either way, and
     * solve_mass only where that solve's tests fail, to decide as always */
    qd__jit_spd_fn spd = s->acc ? qd__prog_spd(s->acc) : NULL;
    if (spd && spd(s->in, s->acc_out, dy + n))
        return QD_OK;
    if (!spd)
        qd_prog_eval(s->acc, s->acc_w, s->in, s->acc_out);
    const double *M = s->acc_out, *f = M + n * n;
    return solve_mass(s, t, M, f, dy + n);
}

qd_status qd__sim_velocity(qd_sim *s, double t, const double *q, const double *p, double *qd) {
    size_t n = s->n;
    if (s->hamilton) {
        set_state(s, t, q, p);
        qd_prog_eval(s->mom, s->mom_w, s->in, qd);
        return QD_OK;
    }
    set_state(s, t, q, NULL);
    qd_prog_eval(s->mom, s->mom_w, s->in, s->mom_out);
    for (size_t j = 0; j < n; j++)
        qd[j] = p[j] - s->mom_out[n * n + j];
    return solve_mass(s, t, s->mom_out, qd, qd);
}

void qd__sim_momentum(qd_sim *s, double t, const double *q, const double *qd, double *p) {
    size_t n = s->n;
    set_state(s, t, q, qd);
    qd_prog_eval(s->mom, s->mom_w, s->in, s->mom_out);
    for (size_t i = 0; i < n; i++) {
        p[i] = s->mom_out[n * n + i];
        for (size_t j = 0; j < n; j++)
            p[i] += s->mom_out[i * n + j] * qd[j];
    }
}

void qd__sim_force(qd_sim *s, double t, const double *q, const double *qd, double *F) {
    set_state(s, t, q, qd);
    qd_prog_eval(s->force, s->force_w, s->in, F);
}

qd_status qd__sim_drift_velocity(qd_sim *s, const double *p, double *qd) {
    if (s->hamilton) {
        /* separable: dH/dp depends on p alone */
        for (size_t j = 0; j < s->n; j++)
            s->in[s->n + j] = p[j];
        qd_prog_eval(s->mom, s->mom_w, s->in, qd);
        return QD_OK;
    }
    /* M is constant: its value at the current inputs is the value */
    qd_prog_eval(s->mom, s->mom_w, s->in, s->mom_out);
    return solve_mass(s, s->tnow, s->mom_out, p, qd);
}

static qd_status form_rhs(qd_sim *s, qd__sim_form form, double t, const double *y, double *dy) {
    if (form == QD__LAG)
        return lag_rhs(s, t, y, dy);
    if (form == QD__SPD)
        return qd__sim_speeds_rhs(s, t, y, dy);
    size_t n = s->n;
    qd_status st = qd__sim_velocity(s, t, y, y + n, dy);
    if (st == QD_OK)
        qd__sim_force(s, t, y, qd__sim_second(s, y, dy), dy + n);
    return st;
}

qd_status qd__sim_rhs(qd_sim *s, qd__sim_form form, double t, const double *y, double *dy) {
    if ((++s->evals & 4095) == 0 && s->jit_mode == QD_SIM_JIT_AUTO && !s->jit_tried)
        qd__sim_jit_tier(s, false, t);
    if (s->ext_rhs)
        return s->ext_rhs(s->ext_data, t, y, dy);
    /* an input callback that failed ends the run: no more calls to it */
    if (s->uin_bad)
        return qd__sim_uin_failed(s);
    qd_status st = form_rhs(s, form, t, y, dy);
    return st == QD_OK && s->uin_bad ? qd__sim_uin_failed(s) : st;
}

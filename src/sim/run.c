/*
 * src/sim/run.c - the integration loop: initial state, steps, projection
 * onto the constraints, rows at the output grid, events, and the error
 * measures every method reports.
 */
#include "simint.h"
#include "sym/sym_export.h"
#include "../base/mem.h"
#include "../base/args.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static const qd__sim_method *const method_ops[QD_SIM_METHOD_COUNT] = {
    [QD_SIM_DOPRI5] = &qd__sim_dopri5,     [QD_SIM_DOP853] = &qd__sim_dop853,
    [QD_SIM_GL2] = &qd__sim_gauss2,        [QD_SIM_GL4] = &qd__sim_gauss4,
    [QD_SIM_GL6] = &qd__sim_gauss6,        [QD_SIM_VERLET] = &qd__sim_verlet,
    [QD_SIM_YOSHIDA4] = &qd__sim_yoshida4, [QD_SIM_YOSHIDA6] = &qd__sim_yoshida6,
    [QD_SIM_YOSHIDA8] = &qd__sim_yoshida8, [QD_SIM_BDF] = &qd__sim_bdf,
    [QD_SIM_TAYLOR] = &qd__sim_taylor,
};

static bool symplectic(qd_sim_method m) { return m >= QD_SIM_GL2 && m <= QD_SIM_YOSHIDA8; }
static bool splitting(qd_sim_method m) { return m >= QD_SIM_VERLET && m <= QD_SIM_YOSHIDA8; }

qd_status qd__sim_run_velocity(qd__sim_run *r, double t, const double *y) {
    size_t n = r->s->n;
    if (r->it->form == QD__LAG) {
        memcpy(r->qd, y + n, n * sizeof *r->qd);
        return QD_OK;
    }
    if (r->it->form == QD__SPD) {
        qd__sim_speeds_velocity(r->s, t, y, r->qd);
        return QD_OK;
    }
    return qd__sim_velocity(r->s, t, y, y + n, r->qd);
}

qd_status qd__sim_run_dense(qd__sim_run *r, double t, double *y) {
    qd__sim_integ *it = r->it;
    if (it->ops->dense) {
        it->ops->dense(it, t, y);
        return QD_OK;
    }
    size_t d = it->dim;
    if (!r->slopes) {
        /* the last step's end slope is this one's start slope when the step
         * starts at that very state: one right-hand side per step, not two
         * (a fixed-step method with events samples every step) */
        qd_status st = QD_OK;
        if (r->fb_valid && it->told == r->fb_t && !memcmp(it->yold, r->fb_y, d * sizeof *r->fb_y))
            memcpy(r->fa, r->fb, d * sizeof *r->fa);
        else
            st = qd__sim_rhs(r->s, it->form, it->told, it->yold, r->fa);
        r->fb_valid = false;
        if (st == QD_OK)
            st = qd__sim_rhs(r->s, it->form, it->t, it->y, r->fb);
        if (st != QD_OK)
            return st;
        r->fb_valid = true;
        r->fb_t = it->t;
        memcpy(r->fb_y, it->y, d * sizeof *r->fb_y);
        r->slopes = true;
    }
    double h = it->t - it->told, x = (t - it->told) / h;
    double h00 = (1 + 2 * x) * (1 - x) * (1 - x), h10 = x * (1 - x) * (1 - x);
    double h01 = x * x * (3 - 2 * x), h11 = x * x * (x - 1);
    for (size_t i = 0; i < d; i++)
        y[i] = h00 * it->yold[i] + h10 * h * r->fa[i] + h01 * it->y[i] + h11 * h * r->fb[i];
    return QD_OK;
}

qd_status qd__sim_run_events_at(qd__sim_run *r, double t, const double *y, double *g, bool *ok) {
    qd_sim *s = r->s;
    qd_status st = qd__sim_run_velocity(r, t, y);
    if (st != QD_OK)
        return st;
    /* the events alone when no guard is asked for: the samples of every step */
    const double *second = qd__sim_second(s, y, r->qd), *gv = NULL;
    if (g)
        gv = qd__sim_ev_eval(s, t, y, second);
    for (size_t k = 0; g && k < qd__sim_fev0(s); k++)
        g[k] = gv[k];
    /* the guards (in aux alone) only when asked for: at a located root */
    if (ok && s->nguard)
        qd__sim_aux_eval(s, t, y, second);
    const double *guard = s->aux_out + qd__sim_aux_guard(s);
    for (size_t k = 0, gi = 0; ok && k < s->nev; k++) {
        bool pass = true;
        for (size_t j = 0; j < s->ev[k].nguard; j++, gi++)
            pass = pass && guard[gi] > 0;
        ok[k] = pass;
    }
    for (size_t k = qd__sim_fev0(s); k < qd__sim_nev_all(s); k++) {
        if (ok)
            ok[k] = true;
        if (g && (st = qd__sim_fric_event(r, k - qd__sim_fev0(s), t, y, &g[k])) != QD_OK)
            return st;
    }
    return QD_OK;
}

/* The column name of component j of the state y of the run's form. */
static const char *state_name(const qd__sim_run *r, size_t j) {
    const qd_sim *s = r->s;
    size_t n = s->n;
    if (j >= (s->se ? n + s->nu : 2 * n))
        return s->names[s->nnames - qd__sim_fric_nextra(s) + (j - 2 * n)];
    return s->names[r->it->form == QD__HAM && j >= n ? 1 + n + j : 1 + j];
}

/* Every state the run reaches passes here, whatever the method: the
 * fixed-step ones (verlet, yoshida*, gl*, taylor with --dt, dopri5/dop853
 * --fixed) have no error estimate that could reject a step into
 * overflow, and a row of inf or NaN must never be written.  QD_ERR_NUMERIC
 * "non-finite state at t = ...", naming the first such component, the
 * last finite state's time and the cause. */
static qd_status check_state(qd__sim_run *r, double t, const double *y) {
    qd_sim *s = r->s;
    size_t d = r->it->dim, j = 0;
    while (j < d && isfinite(y[j]))
        j++;
    if (j == d && isfinite(t))
        return QD_OK;
    if (s->uin_bad)
        return qd__sim_uin_failed(s);
    /* the cause from the numbers: grown huge (this state or the last
     * finite one) is an overflow; an infinity from moderate numbers a
     * division by zero or an overflow in the step; a NaN from them the
     * right-hand side's */
    double big = 0;
    for (size_t i = 0; i < d; i++) {
        big = isfinite(y[i]) ? fmax(big, fabs(y[i])) : big;
        big = isfinite(r->it->yold[i]) ? fmax(big, fabs(r->it->yold[i])) : big;
    }
    const char *why =
        big > 1e100 ? "an overflow: the solution grows beyond what a double holds (it blows up "
                      "in finite time there, or the step is too long for it)"
        : j < d && isinf(y[j])
            ? "an overflow or a division by zero in the step (a point where the equations "
              "are infinite, or a step too long)"
            : "the step produced NaN (an overflow inside it, a step too long for a "
              "fast-growing solution; 0/0; or a state outside the domain of the model's "
              "expressions: a square root or logarithm of a negative number, a speed above c "
              "in sqrt(1 - v^2/c^2))";
    qd__sim_stop(s, QD_STOP_NONFINITE, t, j < d ? y[j] : t);
    qd_ctx_error(s->ctx, QD_ERR_NUMERIC,
                 "non-finite state at t = %.17g (%s = %g; the last finite state was at t = "
                 "%.17g): %s", t, j < d ? state_name(r, j) : "t", j < d ? y[j] : t,
                 r->it->told, why);
    return QD_ERR_NUMERIC;
}

/* A finite state whose energy is not: an overflow (x'^2 past 1e308) or a
 * state outside the model's domain; its row would print inf or NaN. */
static qd_status energy_not_finite(qd__sim_run *r, double t, double h) {
    qd__sim_stop(r->s, QD_STOP_NONFINITE, t, h);
    qd_ctx_error(r->s->ctx, QD_ERR_NUMERIC, "non-finite state at t = %.17g (energy = %g; the "
                 "last finite state was at t = %.17g): %s", t, h, r->it->told,
                 qd__sim_nonfinite_cause(r->s, &h, 1));
    return QD_ERR_NUMERIC;
}

struct qd__sim_measure {
    double E0, dEmax, Tmax, cmax;
    double lost; /* h taken by the impacts so far: E(t) is held to E0 - lost */
    double dErows; /* the largest |E - E0| over the rows made (what a caller gets) */
};
typedef struct qd__sim_measure measure;

/* The error measures at state y, t; q' in r->qd.  aux: s->aux_out holds
 * this state's values (a row was just made), else only h and T are
 * evaluated. */
static qd_status measure_at(qd__sim_run *r, measure *ms, double t, const double *y, bool aux) {
    qd_sim *s = r->s;
    size_t n = s->n;
    const double *hT = aux ? s->aux_out : qd__sim_energy_eval(s, t, y, qd__sim_second(s, y, r->qd));
    if (!isfinite(hT[0]))
        return energy_not_finite(r, t, hT[0]);
    /* friction's share, integrated as y[2n], and a moving surface's work,
     * y[2n + 1]: E + dissipated - surface_work = E0 */
    double dissipated = s->fr ? y[2 * n] : 0, work = s->fr && s->rheo ? y[2 * n + 1] : 0;
    ms->dEmax = fmax(ms->dEmax, fabs(hT[0] + dissipated - work - (ms->E0 - ms->lost)));
    ms->Tmax = fmax(ms->Tmax, fabs(hT[1]));
    if (!s->m)
        return QD_OK;
    qd__sim_con_eval(s, t, y, r->qd);
    const double *A = s->con_out, *a0 = A + s->m * n, *g = a0 + s->m;
    for (size_t c = 0; c < s->m; c++) {
        if (s->fr && !s->fr->on[c])
            continue; /* a slipping contact's row: its slip velocity, no error */
        double v = a0[c];
        for (size_t j = 0; j < n; j++)
            v += A[c * n + j] * r->qd[j];
        double err = fabs(v);
        if (s->holonomic[c])
            err = fmax(err, fabs(g[c]));
        s->con_err[c] = fmax(s->con_err[c], err);
        ms->cmax = fmax(ms->cmax, err);
    }
    return QD_OK;
}

/* The friction columns from row[k]: slip_NAME, mode_NAME per contact, then
 * dissipated (and surface_work on a moving surface); the next free index. */
static size_t friction_columns(qd__sim_run *r, double t, const double *y, double *row, size_t k) {
    qd_sim *s = r->s;
    qd__sim_prog_at(s, s->fprog, s->fprog_w, t, y, r->qd, s->fprog_out);
    for (size_t c = 0; c < s->nfc; c++) {
        row[k++] = qd__sim_fric_slip(s, c);
        row[k++] = s->fr->mode[c].slip ? 1 : 0;
    }
    row[k++] = y[2 * s->n];
    if (s->rheo)
        row[k++] = y[2 * s->n + 1];
    return k;
}

/* The row of state y at t, and (ms not NULL) the error measures there;
 * ms without a row: only the measures. */
static qd_status make_row(qd__sim_run *r, measure *ms, double t, const double *y, double *row) {
    qd_sim *s = r->s;
    size_t n = s->n, k = 0;
    qd_status st = check_state(r, t, y);
    if (st == QD_OK)
        st = qd__sim_run_velocity(r, t, y);
    if (st != QD_OK)
        return st;
    if (!row)
        return measure_at(r, ms, t, y, false);
    qd__sim_aux_eval(s, t, y, qd__sim_second(s, y, r->qd));
    const double *aux = s->aux_out;
    row[k++] = t;
    for (size_t j = 0; j < n; j++)
        row[k++] = y[j];
    for (size_t j = 0; r->it->form == QD__SPD && j < s->nu; j++)
        row[k++] = y[n + j];
    for (size_t j = 0; j < n; j++)
        row[k++] = r->qd[j];
    if (r->it->form == QD__HAM)
        for (size_t j = 0; j < n; j++)
            row[k++] = y[n + j];
    row[k++] = aux[0];
    for (size_t c = 0; c < s->m; c++)
        row[k++] = aux[2 + c];
    if (s->fr)
        k = friction_columns(r, t, y, row, k);
    for (size_t i = 0; i < s->nout; i++)
        row[k++] = aux[qd__sim_aux_out(s) + i];
    if (s->uin_bad)
        return qd__sim_uin_failed(s);
    if (r->meas && isfinite(aux[0])) {
        /* the energy error of the row itself (a grid row is the dense
         * output's, between steps): the measure reported */
        measure *mr = r->meas;
        double dissipated = s->fr ? y[2 * n] : 0, work = s->fr && s->rheo ? y[2 * n + 1] : 0;
        mr->dErows = fmax(mr->dErows, fabs(aux[0] + dissipated - work - (mr->E0 - mr->lost)));
        mr->Tmax = fmax(mr->Tmax, fabs(aux[1]));
    }
    if (ms)
        return measure_at(r, ms, t, y, true);
    if (!isfinite(aux[0]))
        return energy_not_finite(r, t, aux[0]);
    return QD_OK;
}

static size_t max_steps(const qd_sim_opts *o) {
    return o->max_steps ? o->max_steps : QD_SIM_MAX_STEPS;
}

/* A fixed step dt (or an output grid dt) from t0 to t_end: no more steps
 * (rows) than the maximum, counted in doubles before any loop starts. */
static qd_status check_count(qd_ctx *ctx, const qd_sim_opts *o, bool fixed) {
    double count = ceil((o->t_end - o->t0) / o->dt);
    if (!(o->dt > 0) || !(count > (double)max_steps(o)))
        return QD_OK;
    qd_ctx_error(ctx, QD_ERR_ARG,
                 "%s %.17g from t = %.17g to %.17g asks for %.3g %s, more than the maximum "
                 "of %zu", fixed ? "the step" : "the output step",
                 o->dt, o->t0, o->t_end, count, fixed ? "steps" : "rows", max_steps(o));
    qd_ctx_error_about(ctx, QD_SUBJECT_NONE, 0, "max_steps", QD_REASON_NONE, NULL);
    return QD_ERR_ARG;
}

qd_status qd_sim_check_opts(qd_ctx *ctx, const qd_sim_opts *o) {
    QD_ARGS_CTX(ctx, ctx && o);
    const char *name = qd_sim_method_name(o->method);
    if (o->method >= QD_SIM_METHOD_COUNT) {
        qd_ctx_error(ctx, QD_ERR_ARG, "unknown integration method");
        return QD_ERR_ARG;
    }
    /* a time that is not a number would run forever (t < inf) or never */
    if (!isfinite(o->t0) || !isfinite(o->t_end) || !isfinite(o->dt)) {
        const char *what = !isfinite(o->t0) ? "the start time t0" : !isfinite(o->t_end)
                               ? "the end time" : "the step dt";
        qd_ctx_error(ctx, QD_ERR_ARG, "%s must be a finite number, not %g", what,
                     !isfinite(o->t0) ? o->t0 : !isfinite(o->t_end) ? o->t_end : o->dt);
        return QD_ERR_ARG;
    }
    if (!(o->t_end > o->t0)) {
        qd_ctx_error(ctx, QD_ERR_ARG, "the end time must be after the start time");
        return QD_ERR_ARG;
    }
    if (!isfinite(o->every) || o->every < 0) {
        qd_ctx_error(ctx, QD_ERR_ARG, "the output spacing must be a positive number (0: "
                     "rows as the step says), not %g", o->every);
        qd_ctx_error_about(ctx, QD_SUBJECT_NONE, 0, "every", QD_REASON_NONE, NULL);
        return QD_ERR_ARG;
    }
    if (o->every > 0 && ceil((o->t_end - o->t0) / o->every) > (double)max_steps(o)) {
        qd_ctx_error(ctx, QD_ERR_ARG, "the output spacing %.17g from t = %.17g to %.17g asks "
                     "for %.3g rows, more than the maximum of %zu", o->every, o->t0, o->t_end,
                     ceil((o->t_end - o->t0) / o->every), max_steps(o));
        qd_ctx_error_about(ctx, QD_SUBJECT_NONE, 0, "max_steps", QD_REASON_NONE, NULL);
        return QD_ERR_ARG;
    }
    if (o->dt < 0) {
        qd_ctx_error(ctx, QD_ERR_ARG, "the step dt must be positive (0: a row at every "
                     "step of an adaptive method), not %g", o->dt);
        return QD_ERR_ARG;
    }
    bool needs_dt = !qd_sim_method_adaptive(o->method) || o->fixed;
    if (needs_dt && !(o->dt > 0 && isfinite(o->dt))) {
        qd_ctx_error(ctx, QD_ERR_ARG, "%s takes fixed steps: give the step, a positive number",
                     name);
        qd_ctx_error_about(ctx, QD_SUBJECT_NONE, 0, "dt", QD_REASON_NONE, NULL);
        return QD_ERR_ARG;
    }
    if (o->fixed && o->method == QD_SIM_BDF) {
        qd_ctx_error(ctx, QD_ERR_ARG, "bdf chooses its own steps");
        return QD_ERR_ARG;
    }
    if (o->rtol < 0 || o->atol < 0 || !isfinite(o->rtol) || !isfinite(o->atol)) {
        qd_ctx_error(ctx, QD_ERR_ARG, "tolerances must be positive");
        return QD_ERR_ARG;
    }
    return check_count(ctx, o, needs_dt);
}

/* Can the method take this system? */
static qd_status check_system(const qd_sim *s, const qd_sim_opts *o) {
    const char *name = qd_sim_method_name(o->method);
    if (splitting(o->method) && s->se) {
        qd_ctx_error(s->ctx, QD_ERR_ARG,
                     "%s cannot integrate the equations in generalized speeds (y = (q, u) is "
                     "not canonical): use dopri5, dop853, gl2, gl4, gl6 or bdf", name);
        return QD_ERR_ARG;
    }
    if (splitting(o->method) && !s->m && !s->separable) {
        qd_ctx_error(s->ctx, QD_ERR_ARG,
                     "%s needs a separable Hamiltonian H = T(p) + V(q) (constant mass "
                     "matrix, no velocity- or time-dependent forces); this H is not "
                     "separable: use gl2, gl4 or gl6", name);
        return QD_ERR_ARG;
    }
    if (s->nfc && symplectic(o->method)) {
        qd_ctx_error(s->ctx, QD_ERR_ARG,
                     "%s is a symplectic method, made for conservative systems; friction "
                     "dissipates energy and switches between stick and slip: use dop853, "
                     "dopri5 or bdf", name);
        return QD_ERR_ARG;
    }
    if (s->nfc && o->method == QD_SIM_TAYLOR) {
        /* its steps do not stop at the switching functions friction adds */
        qd_ctx_error(s->ctx, QD_ERR_ARG,
                     "taylor cannot follow friction's switches between stick and slip: use "
                     "dop853, dopri5 or bdf");
        return QD_ERR_ARG;
    }
    if (splitting(o->method) && s->m) {
        qd_ctx_error(s->ctx, QD_ERR_ARG,
                     "%s cannot integrate a constrained system: use dop853 or gl4", name);
        return QD_ERR_ARG;
    }
    return QD_OK;
}

static void run_free(qd__sim_run *r, qd__sim_integ *it) {
    if (it->ops && it->priv)
        it->ops->free(it);
    qd__free(it->y);
    qd__free(r->row);
    qd__free(r->ev_hit);
    qd__free(r->smp);
    qd__sim_impacts_free(r);
}

static qd_status run_alloc(qd__sim_run *r, qd__sim_integ *it, size_t ncols) {
    qd_sim *s = r->s;
    size_t d = it->dim, ne = qd__sim_nev_all(s);
    it->y = qd__malloc(s->ctx, (2 * d + 1) * sizeof *it->y);
    r->row = qd__malloc(s->ctx, (2 * ncols + s->n + 4 * d + 2 * ne + ne * d + ne + 1) * sizeof *r->row);
    r->ev_hit = qd__calloc(s->ctx, 2 * ne + 1, sizeof *r->ev_hit);
    r->smp = qd__malloc(s->ctx, ((QD__EV_SAMPLES_MAX + 1) * ne + 2 * ne + 1) * sizeof *r->smp);
    if (!it->y || !r->row || !r->ev_hit || !r->smp)
        return QD_ERR_NOMEM;
    it->yold = it->y + d;
    r->qd = r->row + 2 * ncols;
    r->ytmp = r->qd + s->n;
    r->fa = r->ytmp + d;
    r->fb = r->fa + d;
    r->gold = r->fb + d;
    r->gnew = r->gold + ne;
    r->ev_y = r->gnew + ne;
    r->ev_t = r->ev_y + ne * d;
    r->fb_y = r->ev_t + ne;
    r->ev_ok = r->ev_hit + ne;
    r->ev_after = r->smp + (QD__EV_SAMPLES_MAX + 1) * ne;
    return QD_OK;
}

static bool any_holonomic(const qd_sim *s) {
    for (size_t c = 0; c < s->m; c++)
        if (s->holonomic[c])
            return true;
    return false;
}

/* A system in speeds: q of y = (q, u) onto the holonomic constraints; u
 * stays, and q' = kin(q, u) keeps the velocity constraints by itself. */
static qd_status project_positions(qd__sim_run *r, double t, double *y) {
    qd__sim_speeds_velocity(r->s, t, y, r->qd);
    return qd__sim_project(r->s, t, y, r->qd);
}

/* y0 = (q0, u0), or u0 from q'0 projected onto the constraints. */
static qd_status initial_speeds(qd__sim_run *r, const qd_sim_opts *o) {
    qd_sim *s = r->s;
    double *y = r->it->y;
    bool project = any_holonomic(s) && !o->no_project;
    if (o->u0) {
        memcpy(y + s->n, o->u0, s->nu * sizeof *y);
        return project ? project_positions(r, o->t0, y) : QD_OK;
    }
    memcpy(r->qd, o->qd0, s->n * sizeof *r->qd);
    qd_status st = s->m && !o->no_project ? qd__sim_project_start(s, o->t0, y, r->qd,
                                                                   o->qd0_given) : QD_OK;
    if (st == QD_OK)
        qd__sim_speeds_from(s, o->t0, y, r->qd, y + s->n);
    return st;
}

/* The friction contacts' modes at the start (q in it->y, velocities qd);
 * nothing dissipated, no work done by the surfaces yet. */
static qd_status initial_modes(qd__sim_run *r, double t0, const double *qd) {
    qd__sim_integ *it = r->it;
    size_t n = r->s->n;
    memcpy(it->y + n, qd, n * sizeof *qd);
    for (size_t i = 0; i < qd__sim_fric_nextra(r->s); i++)
        it->y[2 * n + i] = 0;
    return qd__sim_fric_select(r, t0, it->y, (size_t)-1);
}

/* y0 from q0, q'0: projected onto the constraints, then (q, p) if canonical. */
static qd_status initial_state(qd__sim_run *r, const qd_sim_opts *o) {
    qd_sim *s = r->s;
    qd__sim_integ *it = r->it;
    size_t n = s->n;
    double *q = it->y, *qd = r->qd;
    memcpy(q, o->q0, n * sizeof *q);
    if (s->se)
        return initial_speeds(r, o);
    if (s->hamilton) {
        /* Hamilton's equations need the momenta: given, or from q' */
        if (o->p0) {
            memcpy(it->y + n, o->p0, n * sizeof *q);
            return QD_OK;
        }
        return qd__sim_hamilton_momenta(s, o->t0, q, o->qd0, it->y + n);
    }
    memcpy(qd, o->qd0, n * sizeof *qd);
    /* the contacts' modes first: a slipping one's row is not projected */
    qd_status st = s->fr ? initial_modes(r, o->t0, qd) : QD_OK;
    if (st == QD_OK && s->m && !o->no_project)
        st = qd__sim_project_start(s, o->t0, q, qd, o->qd0_given);
    if (st != QD_OK)
        return st;
    if (it->form == QD__HAM)
        qd__sim_momentum(s, o->t0, q, qd, it->y + n);
    else
        memcpy(it->y + n, qd, n * sizeof *qd);
    return s->fr ? initial_modes(r, o->t0, qd) : QD_OK;
}

typedef struct emitter {
    qd_sim_sink sink;
    void *data;
    bool stopped, failed; /* failed: the sink returned < 0 */
    double last_t;
    bool any;
} emitter;

static void emit(emitter *em, int event, const double *row) {
    if (em->stopped)
        return;
    em->last_t = row[0];
    em->any = true;
    int rc = em->sink ? em->sink(em->data, event, row) : 0;
    em->stopped = rc != 0;
    em->failed = rc < 0;
}

/* The earliest contact struck in the step (r->ev_hit), or nimp. */
static size_t first_impact(const qd__sim_run *r) {
    const qd_sim *s = r->s;
    size_t first = s->nimp;
    for (size_t i = 0; i < s->nimp; i++)
        if (r->ev_hit[s->nev + i] && (first == s->nimp || r->ev_t[s->nev + i] <
                                                              r->ev_t[s->nev + first]))
            first = i;
    return first;
}

/* The earliest friction switch in the step (r->ev_hit): its friction
 * event's index (0 .. 2 nfc), or (size_t)-1. */
static size_t first_friction(const qd__sim_run *r) {
    const qd_sim *s = r->s;
    size_t first = (size_t)-1, k0 = qd__sim_fev0(s);
    for (size_t k = k0; k < qd__sim_nev_all(s); k++)
        if (r->ev_hit[k] && (first == (size_t)-1 || r->ev_t[k] < r->ev_t[k0 + first]))
            first = k - k0;
    return first;
}

/* Rows of the output grid inside (told, t], and the events of the step in
 * time order, up to the first impact (*impact, or nimp) or friction switch
 * (*fric, or (size_t)-1); *stop when a stopping event happened first (the
 * state is then moved to it). */
static qd_status step_outputs(qd__sim_run *r, const qd_sim_opts *o, emitter *em, size_t *grid,
                              bool *stop, size_t *nevents, size_t *impact, size_t *fric) {
    qd_sim *s = r->s;
    qd__sim_integ *it = r->it;
    double tstop = it->t;
    size_t first = s->nev;
    *impact = first_impact(r);
    if (*impact < s->nimp)
        tstop = r->ev_t[s->nev + *impact];
    *fric = first_friction(r);
    if (*fric != (size_t)-1 && r->ev_t[qd__sim_fev0(s) + *fric] <= tstop) {
        tstop = r->ev_t[qd__sim_fev0(s) + *fric];
        *impact = s->nimp;
    } else {
        *fric = (size_t)-1;
    }
    for (size_t k = 0; k < s->nev; k++)
        if (r->ev_hit[k] && s->ev[k].stop && r->ev_t[k] <= tstop) {
            tstop = r->ev_t[k];
            first = k;
            *impact = s->nimp;
            *fric = (size_t)-1;
        }
    bool grid_rows = o->every > 0 || (qd_sim_method_adaptive(o->method) && !o->fixed && o->dt > 0);
    double spacing = o->every > 0 ? o->every : o->dt;
    /* merge grid rows and event rows by time */
    for (;;) {
        double tg = INFINITY, te = INFINITY;
        size_t ke = s->nev;
        if (grid_rows) {
            double t = o->t0 + (double)*grid * spacing;
            if (t <= tstop && t < o->t_end)
                tg = t;
        }
        for (size_t k = 0; k < s->nev; k++)
            if (r->ev_hit[k] && r->ev_t[k] <= tstop && r->ev_t[k] < te) {
                te = r->ev_t[k];
                ke = k;
            }
        if (tg == INFINITY && te == INFINITY)
            break;
        qd_status st;
        if (tg <= te) {
            st = qd__sim_run_dense(r, tg, r->ytmp);
            if (st == QD_OK)
                st = make_row(r, NULL, tg, r->ytmp, r->row);
            (*grid)++;
            if (st == QD_OK)
                emit(em, -1, r->row);
        } else {
            st = make_row(r, NULL, te, r->ev_y + ke * it->dim, r->row);
            r->ev_hit[ke] = false;
            (*nevents)++;
            if (st == QD_OK)
                emit(em, (int)ke, r->row);
            /* the same function may cross again later in the step */
            if (st == QD_OK && !s->ev[ke].stop)
                st = qd__sim_events_next(r, ke);
        }
        if (st != QD_OK)
            return st;
    }
    if (first < s->nev) {
        *stop = true;
        qd__sim_stop(s, QD_STOP_EVENT, r->ev_t[first], (double)first);
        it->t = r->ev_t[first];
        memcpy(it->y, r->ev_y + first * it->dim, it->dim * sizeof *it->y);
    }
    return QD_OK;
}

/* What the loop keeps: the fixed grid (gk of its points passed) and
 * whether the run has stopped. */
typedef struct loop {
    const qd_sim_opts *o;
    emitter *em;
    measure *ms;
    qd_sim_stats *stats;
    bool fixed, stop;
    size_t gk;
} loop;

/* Start the method afresh from (it->t, it->y): the state jumped, so the
 * FSAL stage, the dense output, the step history and the collocation
 * start values are stale.  h: the first step (0: the method's choice). */
static qd_status restart(qd__sim_run *r, loop *L, double h) {
    qd__sim_integ *it = r->it;
    if (it->priv)
        it->ops->free(it);
    it->h = L->fixed ? L->o->dt : h;
    qd_status st = it->ops->init(it);
    /* the steps count on: without this the explicit pairs would take the
     * stale last stage of the step before the jump as their first (FSAL) */
    it->y_changed = true;
    r->slopes = r->fb_valid = false;
    if (st == QD_OK)
        st = qd__sim_run_events_at(r, it->t, it->y, r->gold, NULL);
    return st;
}

/* Back from the end of the step to (t, y) inside it. */
static void back_to(qd__sim_run *r, loop *L, double t, const double *y) {
    qd__sim_integ *it = r->it;
    if (L->fixed && t < it->t && L->gk)
        L->gk--; /* that grid point is not reached yet */
    it->t = t;
    if (y != it->y)
        memcpy(it->y, y, it->dim * sizeof *it->y);
}

/* The row after contact i's impact; in contact the run ends. */
static qd_status after_impact(qd__sim_run *r, loop *L, size_t i, const qd__sim_impact_result *res) {
    qd_sim *s = r->s;
    qd__sim_integ *it = r->it;
    qd__sim_impacts *im = r->imp;
    L->ms->lost += res->lost;
    L->stats->impact_energy_lost += res->lost;
    if (res->contact) {
        L->stop = true;
        qd__sim_stop(s, QD_STOP_CONTACT, res->t_rest, (double)i);
        it->t = res->t_rest;
        L->stats->in_contact = true;
        L->stats->at_rest = res->at_rest;
        L->stats->contact = i;
        L->stats->chattering = res->zeno;
    }
    qd_status st = make_row(r, L->ms, it->t, it->y, r->row);
    if (st != QD_OK)
        return st;
    emit(L->em, (int)(s->nev + i), r->row);
    if (L->stop)
        return QD_OK;
    for (size_t j = 0; j < s->nimp; j++)
        im->fresh[j] = im->set[j];
    im->retries = 0;
    im->t_after = it->t;
    memcpy(im->y_after, it->y, it->dim * sizeof *it->y);
    return restart(r, L, 0);
}

/* Contact i struck in the step: a row just before, Newton's law, a row
 * just after (both with event index nev + i), and the method restarted. */
static qd_status strike(qd__sim_run *r, loop *L, size_t i) {
    qd_sim *s = r->s;
    size_t k = s->nev + i;
    back_to(r, L, r->ev_t[k], r->ev_y + k * r->it->dim);
    qd_status st = make_row(r, NULL, r->it->t, r->it->y, r->row);
    if (st != QD_OK)
        return st;
    emit(L->em, (int)k, r->row);
    qd__sim_impact_result res;
    st = qd__sim_impact_apply(r, i, r->it->t, r->it->y, &res);
    L->stats->impacts += res.count;
    return st == QD_OK ? after_impact(r, L, i, &res) : st;
}

/* A friction switch (event fev0 + k) in the step: back to it, the modes
 * chosen again, a row after it (event index nev + nimp + contact), and the
 * method restarted.  A paradox ends the run with a row at it. */
static qd_status switch_modes(qd__sim_run *r, loop *L, size_t k) {
    qd_sim *s = r->s;
    qd__sim_integ *it = r->it;
    size_t e = qd__sim_fev0(s) + k;
    back_to(r, L, r->ev_t[e], r->ev_y + e * it->dim);
    qd_status st = qd__sim_fric_select(r, it->t, it->y, k);
    qd_status st_row = make_row(r, L->ms, it->t, it->y, r->row);
    if (st_row == QD_OK)
        emit(L->em, (int)(s->nev + s->nimp + k / 2), r->row);
    if (st != QD_OK || st_row != QD_OK)
        return st != QD_OK ? st : st_row;
    st = restart(r, L, 0);
    /* a contact that starts to slip starts at v = 0: no switch there */
    for (size_t c = 0; st == QD_OK && c < s->nfc; c++)
        if (s->fr->fresh[c])
            r->gold[qd__sim_fev0(s) + 2 * c] = 0;
    return st;
}

/* Contact i's gap is below 0 at the end of the step with no place where
 * it closed: the step after its impact was longer than the rebound.  An
 * adaptive method retries from just after the impact with a step 16 times
 * shorter; otherwise (or after 6 tries) the rebound is below what the
 * steps resolve, and the contact comes to rest. */
static qd_status unresolved(qd__sim_run *r, loop *L) {
    qd__sim_integ *it = r->it;
    qd__sim_impacts *im = r->imp;
    size_t i = im->unresolved;
    bool fresh = im->fresh[i];
    double h = it->t - it->told;
    back_to(r, L, fresh ? im->t_after : it->told, fresh ? im->y_after : it->yold);
    if (fresh && !L->fixed && im->retries < 6) {
        im->retries++;
        it->rejected++;
        return restart(r, L, h / 16);
    }
    qd__sim_impact_result res;
    qd_status st = qd__sim_impact_rest(r, i, it->t, it->y, &res);
    return st == QD_OK ? after_impact(r, L, i, &res) : st;
}

/* One step with its projection, events and rows. */
static qd_status step(qd__sim_run *r, loop *L, size_t *grid) {
    qd_sim *s = r->s;
    qd__sim_integ *it = r->it;
    const qd_sim_opts *o = L->o;
    bool last, every = o->every > 0 ? false : L->fixed || !(o->dt > 0);
    bool project = s->m && !o->no_project && o->method != QD_SIM_BDF &&
                   (!s->se || any_holonomic(s));
    size_t N = L->fixed ? (size_t)ceil((o->t_end - o->t0) / o->dt - 1e-9) : 0;
    double target = 0;
    if (L->fixed) {
        /* the grid t0 + k dt: after an impact inside a step, the rest of it */
        last = L->gk + 1 >= N;
        target = last ? o->t_end : o->t0 + (double)(L->gk + 1) * o->dt;
        it->h = target - it->t;
    } else {
        /* as dop853.f: no sliver of a step left before the end */
        last = it->t + 1.01 * it->h >= o->t_end;
        if (last)
            it->h = o->t_end - it->t;
    }
    s->tnow = it->t;
    qd_status st = it->ops->step(it);
    if (st == QD_OK)
        st = check_state(r, it->t, it->y);
    if (st != QD_OK)
        return st;
    it->steps++;
    r->slopes = false;
    if (L->fixed) {
        it->t = target;
        L->gk++;
    } else if (last && fabs(it->t - o->t_end) <= 4e-16 * fabs(o->t_end) + 1e-300) {
        it->t = o->t_end;
    }
    if (project && s->se) {
        if ((st = project_positions(r, it->t, it->y)) != QD_OK)
            return st;
        it->y_changed = true;
    } else if (project) {
        size_t n = s->n;
        st = qd__sim_run_velocity(r, it->t, it->y);
        if (st == QD_OK)
            st = qd__sim_project(s, it->t, it->y, r->qd);
        if (st != QD_OK)
            return st;
        memcpy(it->y + n, r->qd, n * sizeof *r->qd);
        it->y_changed = true;
    }
    size_t ne = qd__sim_nev_all(s), impact = s->nimp, fric;
    if (ne && (st = qd__sim_run_events_at(r, it->t, it->y, r->gnew, NULL)) == QD_OK)
        st = qd__sim_events_locate(r);
    if (st != QD_OK)
        return st;
    if (r->imp && r->imp->unresolved < s->nimp)
        return unresolved(r, L);
    for (size_t j = 0; r->imp && j < s->nimp; j++)
        r->imp->fresh[j] = false;
    st = step_outputs(r, o, L->em, grid, &L->stop, &L->stats->events, &impact, &fric);
    if (st != QD_OK)
        return st;
    if (impact < s->nimp)
        return strike(r, L, impact);
    if (fric != (size_t)-1)
        return switch_modes(r, L, fric);
    /* a row only when it is written; the energy measure at every step */
    bool row = !L->stop && (every || it->t >= o->t_end);
    st = make_row(r, L->ms, it->t, it->y, row ? r->row : NULL);
    if (st != QD_OK)
        return st;
    if (row)
        emit(L->em, -1, r->row);
    if (ne)
        memcpy(r->gold, r->gnew, ne * sizeof *r->gold);
    return QD_OK;
}

/* An adaptive step that shrinks without reaching round-off (the methods'
 * underflow test, 10 ulp of t) can crawl for hours near a point where the
 * equations are singular: issue 37's Whipple bicycle, fallen over with its
 * front wheel flat on the ground (where the rolling contact is undefined),
 * took steps of 1e-8 s at a constant pace, the step limit of 1e8 hours
 * away.  Every COLLAPSE_WINDOW steps the pace of the window is compared with
 * the fastest window's and extrapolated to t_end: fallen more than
 * COLLAPSE_DROP times and needing more than max_steps at that pace, the
 * step has collapsed, named with its time and step.  Either test alone
 * would misname a run: a pericentre passage slows a run briefly, and a run
 * given few steps needs more than it has from the start. */
#define COLLAPSE_WINDOW 1000
#define COLLAPSE_DROP 1e3

typedef struct pace {
    double mark;    /* t at the window's start */
    double fastest; /* the longest mean step of a window so far */
} pace;

static qd_status collapsed(qd__sim_run *r, const qd_sim_opts *o, pace *p) {
    qd__sim_integ *it = r->it;
    double mean = (it->t - p->mark) / COLLAPSE_WINDOW, left = o->t_end - it->t;
    p->mark = it->t;
    if (!(mean > 0)) /* an impact or a switch went back: no pace */
        return QD_OK;
    p->fastest = fmax(p->fastest, mean);
    double need = left / mean;
    if (mean * COLLAPSE_DROP > p->fastest || need <= (double)(max_steps(o) - it->steps))
        return QD_OK;
    qd__sim_stop(r->s, QD_STOP_STEP_COLLAPSE, it->t, it->h);
    qd_ctx_error(r->s->ctx, QD_ERR_NUMERIC,
                 "step size collapse at t = %.17g: %d steps of %.3g on average, %.2g times "
                 "shorter than before; at that pace the end is %.3g steps away (the most is "
                 "%zu): the equations are singular near there", it->t, COLLAPSE_WINDOW, mean,
                 p->fastest / mean, need, max_steps(o));
    qd_ctx_error_about(r->s->ctx, QD_SUBJECT_NONE, 0, "max_steps", QD_REASON_NONE, NULL);
    return QD_ERR_NUMERIC;
}

static qd_status integrate(qd__sim_run *r, const qd_sim_opts *o, emitter *em, measure *ms,
                           qd_sim_stats *stats) {
    qd_sim *s = r->s;
    qd__sim_integ *it = r->it;
    loop L = {.o = o, .em = em, .ms = ms, .stats = stats,
              .fixed = !qd_sim_method_adaptive(o->method) || o->fixed};
    size_t grid = 1;
    pace p = {it->t, 0};
    qd_status st = make_row(r, ms, it->t, it->y, r->row);
    if (st != QD_OK)
        return st;
    emit(em, -1, r->row);
    if (qd__sim_nev_all(s) && (st = qd__sim_run_events_at(r, it->t, it->y, r->gold, NULL)) != QD_OK)
        return st;
    while (!L.stop && !em->stopped && it->t < o->t_end) {
        if (it->steps >= max_steps(o)) {
            qd__sim_stop(s, QD_STOP_STEP_LIMIT, it->t, (double)max_steps(o));
            qd_ctx_error(s->ctx, QD_ERR_NUMERIC,
                         "more than %zu steps before t = %.17g (at t = %.17g; raise the "
                         "maximum)", max_steps(o), o->t_end, it->t);
            qd_ctx_error_about(s->ctx, QD_SUBJECT_NONE, 0, "max_steps", QD_REASON_NONE, NULL);
            return QD_ERR_NUMERIC;
        }
        if ((st = step(r, &L, &grid)) != QD_OK)
            return st;
        if (!L.fixed && it->steps % COLLAPSE_WINDOW == 0 && (st = collapsed(r, o, &p)) != QD_OK)
            return st;
        if (o->progress && !em->stopped && o->progress(o->progress_data, it->t)) {
            em->stopped = true; /* as the row callback's stop: the rows written are whole */
            em->last_t = it->t;
        }
    }
    /* the final row: the state where the run ended */
    return make_row(r, NULL, it->t, it->y, r->row);
}

/* The initial values given (q0, q'0, p0, u0) finite, before anything is
 * made of them. */
static qd_status given_finite(const qd_sim *s, const qd_sim_opts *o) {
    size_t n = s->n;
    const double *given[] = {o->q0, o->qd0, o->p0, o->u0};
    size_t count[] = {n, n, n, s->se ? s->nu : 0};
    const char *pre[] = {"", "", "p_", ""}, *post[] = {"", "'", "", ""};
    for (size_t k = 0; k < 4; k++)
        for (size_t j = 0; given[k] && j < count[k]; j++)
            if (!isfinite(given[k][j])) {
                qd_ctx_error(s->ctx, QD_ERR_ARG, "the initial state is not finite (%s%s%s = %g)",
                             pre[k], s->names[k == 3 ? 1 + n + j : 1 + j], post[k], given[k][j]);
                return QD_ERR_ARG;
            }
    return QD_OK;
}

/* The state made of them (projected, its momenta) finite. */
static qd_status initial_finite(qd__sim_run *r) {
    for (size_t j = 0; j < r->it->dim; j++)
        if (!isfinite(r->it->y[j])) {
            qd_ctx_error(r->s->ctx, QD_ERR_ARG, "the initial state is not finite (%s = %g)",
                         state_name(r, j), r->it->y[j]);
            return QD_ERR_ARG;
        }
    return QD_OK;
}

/* The distances |q - q0| and |q' - q'0| the start's projection onto the
 * constraints moved the initial state (qd NULL: velocities not compared). */
static void initial_moved(size_t n, const qd_sim_opts *o, const double *q, const double *qd,
                          qd_sim_stats *stats) {
    double dq = 0, dv = 0;
    for (size_t j = 0; j < n; j++) {
        dq += (q[j] - o->q0[j]) * (q[j] - o->q0[j]);
        if (qd && o->qd0)
            dv += (qd[j] - o->qd0[j]) * (qd[j] - o->qd0[j]);
    }
    stats->initial_moved_q = sqrt(dq);
    stats->initial_moved_qd = sqrt(dv);
}

/* The run on s, a copy of the compiled system with its own workspace. */
/* Why the run ended: what a site recorded (a failure, a terminal event,
 * contact), else the row callback's stop, an unrecorded failure (before the
 * first step: refused) or the end time. */
static qd_sim_stop ended(const qd_sim *s, const emitter *em, qd_status st, bool started,
                         double t) {
    if (s->stop.code != QD_STOP_NONE)
        return s->stop;
    if (st != QD_OK && !started)
        return (qd_sim_stop){QD_STOP_REFUSED, NAN, NAN};
    if (em->stopped)
        return (qd_sim_stop){QD_STOP_CALLBACK, em->last_t, NAN};
    if (st != QD_OK)
        return (qd_sim_stop){QD_STOP_FAILURE, t, NAN};
    return (qd_sim_stop){QD_STOP_END, t, NAN};
}

static qd_status run(qd_sim *s, const qd_sim_opts *o, qd_sim_sink sink, void *data,
                     qd_sim_stats *stats, double *final) {
    s->stop = (qd_sim_stop){QD_STOP_NONE, NAN, NAN};
    qd_status st = qd_sim_check_opts(s->ctx, o);
    if (st == QD_OK)
        st = check_system(s, o);
    if (st != QD_OK) {
        stats->stop = (qd_sim_stop){QD_STOP_REFUSED, NAN, NAN};
        return st;
    }
    qd__sim_integ it = {.s = s, .method = o->method, .ops = method_ops[o->method],
                    .dim = s->se ? s->n + s->nu : 2 * s->n + qd__sim_fric_nextra(s),
                    .t = o->t0, .tend = o->t_end,
                    .rtol = o->rtol > 0 ? o->rtol : 1e-10, .atol = o->atol > 0 ? o->atol : 1e-12,
                    .fixed = o->fixed, .h = o->fixed ? o->dt : 0, .precision = o->precision};
    it.form = s->se ? QD__SPD
              : s->hamilton || (symplectic(o->method) && s->canonical) ? QD__HAM : QD__LAG;
    qd__sim_run r = {.s = s, .it = &it};
    size_t ncols = qd_sim_columns(s, o->method, NULL, 0);
    st = run_alloc(&r, &it, ncols);
    if (st == QD_OK)
        st = qd__sim_impacts_new(&r);
    if (st == QD_OK)
        st = qd__sim_fric_run_new(s);
    if (st == QD_OK)
        st = given_finite(s, o);
    if (st == QD_OK)
        st = initial_state(&r, o);
    if (st == QD_OK && s->m && !o->no_project && !s->hamilton) /* what the projection moved */
        initial_moved(s->n, o, it.y, s->se || o->u0 ? NULL : r.qd, stats);
    for (size_t j = 0; st == QD_OK && j < s->n; j++)
        stats->initial_solved += s->solved[j];
    if (st == QD_OK && s->nimp)
        st = qd__sim_impact_check_start(&r, it.t, it.y);
    if (st == QD_OK)
        st = initial_finite(&r);
    if (st == QD_OK)
        st = it.ops->init(&it);
    measure ms = {0};
    if (st == QD_OK) {
        st = qd__sim_run_velocity(&r, it.t, it.y);
        if (st == QD_OK) {
            qd__sim_aux_eval(s, it.t, it.y, qd__sim_second(s, it.y, r.qd));
            ms.E0 = s->aux_out[0];
            /* a start outside the model's domain would print a row of NaN */
            if (!isfinite(ms.E0))
                st = qd__sim_not_finite_at(s, it.t, "the energy at the initial state is",
                                           &ms.E0, 1);
        }
    }
    emitter em = {.sink = sink, .data = data};
    r.meas = &ms;
    bool started = st == QD_OK;
    if (st == QD_OK)
        st = integrate(&r, o, &em, &ms, stats);
    if (st == QD_OK && em.failed) {
        qd_ctx_error(s->ctx, QD_ERR_ARG, "the row callback reported a failure at t = %.17g: "
                     "the run stopped there", em.last_t);
        st = QD_ERR_ARG;
    }
    stats->steps = it.steps;
    stats->evals = s->evals;
    stats->jit = s->acc && (qd_prog_jitted(s->acc) || qd__prog_spd(s->acc));
    stats->rejected = it.rejected;
    stats->E0 = ms.E0;
    double den = fmax(fabs(ms.E0), ms.Tmax);
    stats->energy_error_max = den > 0 ? ms.dErows / den : ms.dErows;
    stats->energy_error_steps = den > 0 ? ms.dEmax / den : ms.dEmax;
    stats->constraint_error_max = ms.cmax;
    stats->t = it.t;
    stats->events_unresolved = r.fast_steps;
    stats->events_unresolved_t = r.fast_t;
    stats->events_unresolved_event = r.fast_event;
    stats->events_unresolved_spacing = r.fast_spacing;
    if (s->fr) {
        stats->transitions = s->fr->ntr;
        stats->friction_dissipated = it.y ? it.y[2 * s->n] : 0;
        stats->energy_balance_error = stats->energy_error_max;
        stats->surface_work = it.y && s->rheo ? it.y[2 * s->n + 1] : 0;
    }
    stats->stop = ended(s, &em, st, started, it.t);
    if (st == QD_OK && final)
        memcpy(final, r.row, ncols * sizeof *final);
    if (st != QD_OK && qd_ctx_status(s->ctx) == QD_OK)
        qd_ctx_error(s->ctx, st, "the integration failed: %s", qd_status_str(st));
    run_free(&r, &it);
    return st;
}

/* opts.par: the run's parameter values where every program (and the
 * native right-hand side) reads them, in the run's own inputs, so that
 * concurrent runs of one compiled system may differ in their parameters. */
static void use_par(qd_sim *w, const double *par) {
    for (size_t i = 0; i < w->np; i++)
        w->in[2 * w->n + 1 + i] = par[i];
}

/* A run on a copy of the compiled system s with its own workspace;
 * con_err (may be NULL) receives the per-constraint residuals. */
static qd_status run_copy(qd_ctx *ctx, const qd_sim *s, const qd_sim_opts *o, qd_sim_sink sink,
                          void *data, qd_sim_stats *stats, double *final, double *con_err,
                          qd_sim *keep) {
    qd_sim_stats dummy;
    stats = stats ? stats : &dummy;
    *stats = (qd_sim_stats){0};
    qd_sim w = *s;
    qd_status st = qd__sim_ws_alloc(&w, ctx);
    w.jit_mode = o->jit;
    w.jit_tried = false;
    w.jit_t0 = o->t0;
    w.jit_t1 = o->t_end;
    if (st == QD_OK && o->jit == QD_SIM_JIT_ON)
        qd__sim_jit_tier(&w, true, o->t0);
    if (st == QD_OK && o->par)
        use_par(&w, o->par);
    if (st == QD_OK)
        st = qd__sim_uin_check(&w, o->t0, o->t_end);
    else
        qd_ctx_error(ctx, st, "out of memory starting the simulation");
    if (st == QD_OK)
        st = run(&w, o, sink, data, stats, final);
    for (size_t c = 0; con_err && w.con_err && c < s->m; c++)
        con_err[c] = w.con_err[c];
    for (size_t j = 0; keep && w.solved && j < s->n; j++)
        keep->solved_last[j] = w.solved[j];
    if (keep)
        qd__sim_fric_keep(keep, &w);
    qd__sim_fric_run_free(&w);
    qd__sim_ws_free(&w);
    return st;
}

qd_status qd_sim_run_with(qd_ctx *ctx, const qd_sim *s, const qd_sim_opts *o, qd_sim_sink sink,
                          void *data, qd_sim_stats *stats, double *final) {
    QD_ARGS_CTX(ctx, ctx && s && o);
    if (!s->aux_ready) {
        qd_ctx_error(ctx, QD_ERR_ARG, "a shared simulation is compiled first (qd_sim_compile)");
        return QD_ERR_ARG;
    }
    return run_copy(ctx, s, o, sink, data, stats, final, NULL, NULL);
}

qd_status qd_sim_run(qd_sim *s, const qd_sim_opts *o, qd_sim_sink sink, void *data,
                     qd_sim_stats *stats, double *final) {
    QD_ARGS(QD_ERR_ARG, s && o);
    qd_status st = qd_sim_compile(s);
    if (st != QD_OK) {
        if (stats)
            *stats = (qd_sim_stats){0};
        return st;
    }
    return run_copy(s->ctx, s, o, sink, data, stats, final, s->con_err_last, s);
}

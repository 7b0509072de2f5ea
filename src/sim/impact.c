/*
 * src/sim/impact.c - unilateral contacts in a simulation: the model's
 * `impact NAME: GAP >= 0 restitution E`, Newton's law of restitution at
 * the located impact, and the end of a run in contact when the impacts
 * chatter.
 *
 * Across an impact q is frozen and only the velocities jump (Desloge
 * ch. 57 thm 1; Byerly ch. III art. 26): integrating Lagrange's equations
 * over the vanishing duration leaves M (q'+ - q'-) = A^T Lambda, A the rows
 * of the ordinary constraints (which keep holding) and of the gap's
 * gradient a = dGAP/dq, a0 = dGAP/dt.  Newton's law of restitution (Desloge
 * ch. 61, Byerly art. 33) gives the gap's rate after as -E times the rate
 * before, so q'+ solves the saddle system
 *
 *     [ M  -A^T ] [ q'+ - q'- ]   [ 0 ]
 *     [ A   0   ] [ Lambda    ] = [ b ],
 *
 *     b_c = -(A_c q'- + a0_c)          (the constraints hold after),
 *     b_gap = -(1 + E) (a q'- + a0)    (a q'+ + a0 = -E (a q'- + a0)).
 *
 * Chattering: with E < 1 a body dropped on a floor bounces infinitely often
 * in a finite time (the flights shrink like E^n).  A rebound whose rate is
 * below sqrt(rtol) times the contact's fastest approach rises (in a
 * uniform field) to rtol of the first bounce's height, which the tolerance
 * cannot resolve: the impact is then made plastic (E = 0), and if the free
 * motion presses the gap shut (d^2GAP/dt^2 <= 0 with the rate 0: the ball
 * under gravity) the run ends in contact (at rest, or still moving in a
 * sustained contact that is not integrated: a rod pivoting on a ledge);
 * otherwise the bodies part and the run goes on (E = 0 itself is the same
 * case).  When the flight times have been shrinking in proportion to the
 * rebound rates (a geometric series, ratio E for the ball), the rest of the
 * series is summed and the run ends at the accumulation time
 * t* = t_k + d_k rho / (1 - r), the positions moved along q'+ to it.
 */
#include "simint.h"
#include "../base/mem.h"
#include "num/num.h"

#include <math.h>
#include <string.h>

/* ---- setup (qd_sim_new) -------------------------------------------------------- */

/* E from its expression in the parameters (their values in s->par). */
static qd_status restitution(qd_sim *s, size_t i, const qd_expr *E) {
    double x = 0;
    if (E && qd_eval(s->ctx, E, s->np, s->in_syms + 2 * s->n + 1, s->par, &x) != QD_OK) {
        qd_ctx_clear_error(s->ctx);
        qd_ctx_error(s->ctx, QD_ERR_ARG, "impact '%s': the restitution is not a number "
                                         "(an expression in the parameters only)",
                     s->imp_name[i]);
        return QD_ERR_ARG;
    }
    if (!(x >= 0 && x <= 1)) {
        /* the parser refuses such numbers; qd_model_set_param does not */
        qd_ctx_error(s->ctx, QD_ERR_ARG, "impact '%s': the restitution %.6g is outside [0, 1]",
                     s->imp_name[i], x);
        return QD_ERR_ARG;
    }
    s->imp_E[i] = x;
    return QD_OK;
}

/* dGAP/dq_j (n), dGAP/dt and the part of d^2GAP/dt^2 without q'' (the
 * rate's derivative at fixed q') of gap i into outs; QD_ERR_ARG when GAP
 * has a velocity or does not move with the coordinates. */
static qd_status gradient(qd_sim *s, size_t i, const qd_expr **outs) {
    const qd_eom *e = s->e;
    size_t n = s->n;
    const qd_expr *gap = s->imp_gap[i];
    bool moves = false;
    for (size_t j = 0; j < n; j++) {
        if (qd_has(gap, e->qd[j])) {
            qd_ctx_error(s->ctx, QD_ERR_ARG, "impact '%s': the gap depends on %s; it is a "
                                             "function of the coordinates and t only",
                         s->imp_name[i], qd_expr_name(e->qd[j]));
            return QD_ERR_ARG;
        }
        outs[j] = qd_diff(s->ctx, gap, e->q[j]);
        moves = moves || (outs[j] && !qd_is_zero(outs[j]));
    }
    const qd_expr *t = qd_time(s->ctx);
    outs[n] = qd_diff(s->ctx, gap, t);
    const qd_expr *rate = outs[n], *acc = NULL;
    for (size_t j = 0; j < n; j++)
        rate = qd_add(s->ctx, rate, qd_mul(s->ctx, outs[j], e->qd[j]));
    acc = qd_diff(s->ctx, rate, t);
    for (size_t j = 0; j < n; j++)
        acc = qd_add(s->ctx, acc, qd_mul(s->ctx, qd_diff(s->ctx, rate, e->q[j]), e->qd[j]));
    outs[n + 1] = acc;
    if (qd_ctx_status(s->ctx) != QD_OK)
        return qd_ctx_status(s->ctx);
    if (!moves) {
        qd_ctx_error(s->ctx, QD_ERR_ARG, "impact '%s': the gap does not depend on the "
                                         "coordinates, so no motion can close it",
                     s->imp_name[i]);
        return QD_ERR_ARG;
    }
    return QD_OK;
}

qd_status qd__sim_impact_setup(qd_sim *s) {
    size_t ni = qd_model_nimpacts(s->model), n = s->n;
    if (!ni)
        return QD_OK;
    s->imp_name = qd__calloc(s->ctx, ni, sizeof *s->imp_name);
    s->imp_gap = qd__calloc(s->ctx, ni, sizeof *s->imp_gap);
    s->imp_E = qd__calloc(s->ctx, ni, sizeof *s->imp_E);
    const qd_expr **outs = qd__malloc(s->ctx, ni * (n + 2) * sizeof *outs);
    qd_status st = s->imp_name && s->imp_gap && s->imp_E && outs ? QD_OK : QD_ERR_NOMEM;
    s->nimp = st == QD_OK ? ni : 0;
    for (size_t i = 0; st == QD_OK && i < ni; i++) {
        s->imp_name[i] = qd_model_impact_name(s->model, i);
        s->imp_gap[i] = qd_model_impact_gap(s->model, i);
        st = restitution(s, i, qd_model_impact_restitution(s->model, i));
        if (st == QD_OK)
            st = gradient(s, i, outs + i * (n + 2));
    }
    if (st == QD_OK) {
        s->imp = qd__sim_prog(s, ni * (n + 2), outs, &s->imp_n);
        st = s->imp ? QD_OK : qd_ctx_status(s->ctx);
    }
    qd__free(outs);
    return st;
}

void qd__sim_impact_free(qd_sim *s) {
    qd_prog_free(s->imp);
    qd__free(s->imp_name);
    qd__free(s->imp_gap);
    qd__free(s->imp_E);
}

/* ---- a run's contacts ---------------------------------------------------------- */

qd_status qd__sim_impacts_new(qd__sim_run *r) {
    qd_sim *s = r->s;
    if (!s->nimp)
        return QD_OK;
    size_t n = s->n, N = n + s->m + s->nimp, d = r->it->dim;
    qd__sim_impacts *im = qd__calloc(s->ctx, 1, sizeof *im);
    if (!im)
        return QD_ERR_NOMEM;
    r->imp = im;
    im->c = qd__calloc(s->ctx, s->nimp, sizeof *im->c);
    im->fresh = qd__calloc(s->ctx, 2 * s->nimp, sizeof *im->fresh);
    im->K = qd__calloc(s->ctx, N * N + N + (N - n) * n + (N - n) + n + 3 * d + qd__sim_nev_all(s),
                       sizeof *im->K);
    if (!im->c || !im->fresh || !im->K)
        return QD_ERR_NOMEM;
    im->set = im->fresh + s->nimp;
    im->rhs = im->K + N * N;
    im->A = im->rhs + N;
    im->b = im->A + (N - n) * n;
    im->zero = im->b + (N - n);
    im->y_after = im->zero + n;
    im->ylag = im->y_after + d;
    im->dy = im->ylag + d;
    im->g = im->dy + d;
    im->unresolved = s->nimp;
    return QD_OK;
}

void qd__sim_impacts_free(qd__sim_run *r) {
    if (!r->imp)
        return;
    qd__free(r->imp->c);
    qd__free(r->imp->fresh);
    qd__free(r->imp->K);
    qd__free(r->imp);
    r->imp = NULL;
}

qd_status qd__sim_impact_check_start(qd__sim_run *r, double t, const double *y) {
    qd_sim *s = r->s;
    qd_status st = qd__sim_run_events_at(r, t, y, r->gold, NULL);
    for (size_t i = 0; st == QD_OK && i < s->nimp; i++) {
        double g = r->gold[s->nev + i];
        if (g < 0 || isnan(g)) {
            qd_ctx_error(s->ctx, QD_ERR_ARG, "impact '%s': the gap is negative at t0 (%.6g): "
                                             "the bodies start interpenetrating",
                         s->imp_name[i], g);
            return QD_ERR_ARG;
        }
    }
    return st;
}

/* a = dGAP/dq and a0 = dGAP/dt of contact i at (t, q) into s->imp_out;
 * returns a q' + a0 with q' in r->qd. */
static double rate_here(qd__sim_run *r, size_t i, double t, const double *q) {
    qd_sim *s = r->s;
    size_t n = s->n;
    qd__sim_prog_at(s, s->imp, s->imp_w, t, q, r->qd, s->imp_out);
    const double *a = s->imp_out + i * (n + 2);
    double v = a[n];
    for (size_t j = 0; j < n; j++)
        v += a[j] * r->qd[j];
    return v;
}

double qd__sim_impact_rate(qd__sim_run *r, size_t i, double t, const double *y) {
    if (qd__sim_run_velocity(r, t, y) != QD_OK)
        return NAN;
    return rate_here(r, i, t, y);
}

/* The contacts struck with i at (t, y): i, and every other whose gap is 0
 * to round-off and closing there (a rod falling flat on both ends), into
 * im->set; their count.  Struck one after the other, the first impact
 * would set the rod turning.  settling: also those just struck with i
 * (fresh, now opening), which come to rest with it. */
static size_t struck_with(qd__sim_run *r, size_t i, double t, const double *y, bool settling) {
    qd_sim *s = r->s;
    qd__sim_impacts *im = r->imp;
    size_t n = s->n, count = 0;
    double qmax = 1;
    for (size_t j = 0; j < n; j++)
        qmax = fmax(qmax, fabs(y[j]));
    if (qd__sim_run_events_at(r, t, y, im->g, NULL) != QD_OK)
        memset(im->g, 0, qd__sim_nev_all(s) * sizeof *im->g);
    for (size_t j = 0; j < s->nimp; j++) {
        double rate = qd__sim_impact_rate(r, j, t, y), amax = 1;
        for (size_t k = 0; k <= n; k++)
            amax = fmax(amax, fabs(s->imp_out[j * (n + 2) + k]));
        bool closing = rate < 0 || (settling && im->fresh[j]);
        bool touching = fabs(im->g[s->nev + j]) <= 64 * 0x1p-52 * qmax * amax;
        im->set[j] = j == i || (touching && closing);
        count += im->set[j];
    }
    return count;
}

/* The law's rows: the ordinary constraints, which hold after, and each
 * contact of im->set, whose rate after is -E times its rate before (E = 0
 * for them all when plastic); q' in r->qd. */
static size_t law_rows(qd__sim_run *r, double t, const double *q, bool plastic) {
    qd_sim *s = r->s;
    qd__sim_impacts *im = r->imp;
    size_t n = s->n, m = s->m, k = m;
    if (m) {
        qd__sim_con_eval(s, t, q, r->qd);
        const double *A = s->con_out, *a0 = A + m * n;
        for (size_t c = 0; c < m; c++) {
            double v = a0[c];
            for (size_t j = 0; j < n; j++)
                v += (im->A[c * n + j] = A[c * n + j]) * r->qd[j];
            im->b[c] = -v;
        }
    }
    for (size_t i = 0; i < s->nimp; i++) {
        if (!im->set[i])
            continue;
        double v = rate_here(r, i, t, q), E = plastic ? 0 : s->imp_E[i];
        memcpy(im->A + k * n, s->imp_out + i * (n + 2), n * sizeof *im->A);
        im->b[k++] = -(1 + E) * v;
    }
    return k;
}

/* Newton's law for the contacts of im->set at (t, y) (i names them in a
 * message): y gets the state after, r->qd its velocities, *lost the energy
 * h lost; *still: T after <= rtol T before. */
static qd_status law(qd__sim_run *r, size_t i, double t, double *y, bool plastic, double *lost,
                     bool *still) {
    qd_sim *s = r->s;
    qd__sim_impacts *im = r->imp;
    size_t n = s->n;
    qd_status st = qd__sim_run_velocity(r, t, y);
    if (st != QD_OK)
        return st;
    const double *hT = qd__sim_energy_eval(s, t, y, qd__sim_second(s, y, r->qd));
    double h_before = hT[0], T_before = hT[1];
    size_t rows = law_rows(r, t, y, plastic), N = n + rows;
    qd__sim_prog_at(s, s->acc, s->acc_w, t, y, r->qd, s->acc_out);
    qd__num_saddle(n, rows, s->acc_out, im->zero, im->A, im->b, im->K, im->rhs);
    if (!qd__num_solve(N, im->K, im->rhs, 1e-13 * (double)N)) {
        qd__sim_stop(s, QD_STOP_SINGULAR, t, NAN);
        qd_ctx_error(s->ctx, QD_ERR_SINGULAR,
                     "impact '%s' at t = %.17g: the impact equations are singular (the gap's "
                     "gradient is a combination of the constraints' rows, or M is singular)",
                     s->imp_name[i], t);
        return QD_ERR_SINGULAR;
    }
    for (size_t j = 0; j < n; j++)
        r->qd[j] += im->rhs[j];
    if (r->it->form == QD__HAM)
        qd__sim_momentum(s, t, y, r->qd, y + n);
    else
        memcpy(y + n, r->qd, n * sizeof *y);
    hT = qd__sim_energy_eval(s, t, y, qd__sim_second(s, y, r->qd));
    *lost = h_before - hT[0];
    *still = !(fabs(hT[1]) > r->it->rtol * fabs(T_before));
    return QD_OK;
}

/* The time the remaining bounces of contact c take: the geometric series
 * of the flights when they have shrunk in proportion to the rebound rates
 * (each flight d_k ~ vout_k, the ratio r = d_k / d_(k-1)); 0 otherwise. */
static double remaining_bounces(const qd__sim_contact *c) {
    if (c->count < 3)
        return 0;
    double d1 = c->t[1] - c->t[0], d2 = c->t[2] - c->t[1];
    if (!(d1 > 0 && d2 > 0 && c->vout[0] > 0 && c->vout[1] > 0))
        return 0;
    double ratio = d2 / d1, rho = c->vout[1] / c->vout[0];
    if (!(ratio < 1 && fabs(ratio - rho) <= 0.1 * rho))
        return 0;
    return d2 * (c->vout[2] / c->vout[1]) / (1 - ratio);
}

/* After a plastic impact at (t, y), velocities in r->qd: at rest in contact
 * from t plus the remaining bounces' time, the positions carried there. */
static qd_status settle(qd__sim_run *r, size_t i, double t, double *y, qd__sim_impact_result *res) {
    qd_sim *s = r->s;
    size_t n = s->n;
    /* not past the end of the run: the bounces left there are below the
     * tolerance anyway */
    double dt = fmin(remaining_bounces(&r->imp->c[i]), r->it->tend - t);
    res->contact = true;
    res->zeno = dt > 0;
    res->t_rest = t + dt;
    if (!(dt > 0))
        return QD_OK;
    for (size_t j = 0; j < n; j++)
        y[j] += r->qd[j] * dt;
    qd_status st = s->m ? qd__sim_project(s, res->t_rest, y, r->qd) : QD_OK;
    if (st != QD_OK)
        return st;
    if (r->it->form == QD__HAM)
        qd__sim_momentum(s, res->t_rest, y, r->qd, y + n);
    else
        memcpy(y + n, r->qd, n * sizeof *y);
    return QD_OK;
}

/* d^2GAP/dt^2 of contact i at (t, y), q' in r->qd, with the free motion's
 * q'' (the constraints' forces included, no contact force). */
static qd_status gap_acceleration(qd__sim_run *r, size_t i, double t, const double *y, double *gdd) {
    qd_sim *s = r->s;
    qd__sim_impacts *im = r->imp;
    size_t n = s->n;
    memcpy(im->ylag, y, n * sizeof *y);
    memcpy(im->ylag + n, r->qd, n * sizeof *y);
    qd_status st = qd__sim_rhs(s, QD__LAG, t, im->ylag, im->dy);
    if (st != QD_OK)
        return st;
    qd__sim_prog_at(s, s->imp, s->imp_w, t, y, r->qd, s->imp_out);
    const double *a = s->imp_out + i * (n + 2);
    *gdd = a[n + 1];
    for (size_t j = 0; j < n; j++)
        *gdd += a[j] * im->dy[n + j];
    return QD_OK;
}

/* Contact i's history: an impact at t with approach rate vin < 0. */
static void record(qd__sim_contact *c, double t, double vin, double E) {
    c->vmax = fmax(c->vmax, -vin);
    for (int k = 0; k < 2; k++) {
        c->t[k] = c->t[k + 1];
        c->vout[k] = c->vout[k + 1];
    }
    c->t[2] = t;
    c->vout[2] = -E * vin;
    c->count++;
}

qd_status qd__sim_impact_apply(qd__sim_run *r, size_t i, double t, double *y, qd__sim_impact_result *res) {
    qd_sim *s = r->s;
    qd__sim_impacts *im = r->imp;
    *res = (qd__sim_impact_result){.count = struck_with(r, i, t, y, false)};
    for (size_t j = 0; j < s->nimp; j++)
        if (im->set[j])
            record(&im->c[j], t, qd__sim_impact_rate(r, j, t, y), s->imp_E[j]);
    const qd__sim_contact *c = &im->c[i];
    bool rest = !(c->vout[2] > sqrt(r->it->rtol) * c->vmax);
    qd_status st = law(r, i, t, y, rest, &res->lost, &res->at_rest);
    /* a plastic impact rests in contact only while the motion presses the
     * gap shut; else (a rhombus hitting a wall, Desloge ch. 57 ex. 1) the
     * bodies part again and the run goes on */
    double gdd = 0;
    if (st == QD_OK && rest)
        st = gap_acceleration(r, i, t, y, &gdd);
    if (st == QD_OK && rest && !(gdd > 0))
        st = settle(r, i, t, y, res);
    return st;
}

qd_status qd__sim_impact_rest(qd__sim_run *r, size_t i, double t, double *y, qd__sim_impact_result *res) {
    *res = (qd__sim_impact_result){.count = struck_with(r, i, t, y, true)};
    qd_status st = law(r, i, t, y, true, &res->lost, &res->at_rest);
    return st == QD_OK ? settle(r, i, t, y, res) : st;
}

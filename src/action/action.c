/*
 * src/action/action.c - qd_action_at and qd_action_of_sep: the actions
 * J_k = oint p_k dq_k of a separated bounded motion at a state, the
 * frequencies omega_k = 2 pi dH/dJ_k from the Jacobian dJ/dalpha, the
 * angle variables 2 pi dW/dJ_k there, the commensurate pairs among them (Desloge ch. 79, thm 1: closed orbits),
 * and H(J) where it is recognised (Goldstein sec. 10.6-10.8).
 */
#include "act.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "base/mem.h"
#include "num/num.h"
#include "qdot/hamilton.h"
#include "qdot/mech.h"
#include "../base/args.h"

#define PI 3.14159265358979323846

/* ---- the constants at the state ------------------------------------------------ */

static bool lookup(const qd_expr *s, size_t n, const qd_expr *const *syms, const double *vals,
                   double *v) {
    for (size_t i = 0; i < n; i++)
        if (syms[i] == s) {
            *v = vals[i];
            return true;
        }
    return false;
}

/* alpha_j: the integral of the equation that introduces constant j. */
static bool constant_values(qd_ctx *ctx, const qd_hj *h, size_t nvals,
                            const qd_expr *const *syms, const double *vals, double *cv) {
    for (size_t j = 0; j < h->nconst; j++) {
        size_t k = 0;
        while (k < h->n && h->sep[k].constant != h->constants[j])
            k++;
        if (k == h->n || !h->sep[k].integral) {
            qd_ctx_error(ctx, QD_ERR_ARG, "the separation constant %s has no first integral",
                         qd_expr_name(h->constants[j]));
            return false;
        }
        if (qd_eval(ctx, h->sep[k].integral, nvals, syms, vals, &cv[j]) != QD_OK)
            return false;
    }
    return true;
}

/* ---- the frequencies ------------------------------------------------------------- */

/* A^T x = rhs for A_kj = dJ_k/dalpha_j (dJ, n x n); false when singular. */
static bool solve_transposed(qd_ctx *ctx, size_t n, const double *dJ, double *rhs) {
    double *At = qd__calloc(ctx, n * n, sizeof *At);
    if (!At)
        return false;
    for (size_t k = 0; k < n; k++)
        for (size_t j = 0; j < n; j++)
            At[j * n + k] = dJ[k * n + j];
    bool ok = qd__num_solve(n, At, rhs, 1e-12 * qd__num_norm_inf(n, At));
    qd__free(At);
    if (!ok)
        qd_ctx_error(ctx, QD_ERR_SINGULAR, "the Jacobian dJ/dalpha is singular: the actions do "
                                           "not determine the constants");
    return ok;
}

/* omega_k = 2 pi dH/dJ_k = 2 pi (A^-1)_{E,k}: row E of A^-1 solves
 * A^T x = unit_E.  The angles w_k = dW/dJ_k = sum_j beta_j (A^-1)_{jk},
 * beta_j = dW/dalpha_j (Goldstein sec. 10.6, with J for the alphas):
 * A^T w = beta; 2 pi w_k mod 2 pi is the angle, advancing at omega_k. */
static bool frequencies(qd_ctx *ctx, const qd_hj *h, double *beta, qd_action *a) {
    size_t n = a->n, e = 0;
    while (e < h->nconst && h->constants[e] != h->energy)
        e++;
    double *x = qd__calloc(ctx, n, sizeof *x);
    bool ok = x != NULL;
    for (size_t k = 0; ok && k < n; k++)
        x[k] = k == e;
    ok = ok && solve_transposed(ctx, n, a->dJ, x) && solve_transposed(ctx, n, a->dJ, beta);
    for (size_t k = 0; ok && k < n; k++) {
        a->c[k].omega = 2 * PI * x[k];
        a->c[k].angle = 2 * PI * (beta[k] - floor(beta[k]));
    }
    qd__free(x);
    return ok;
}

/* ---- degeneracies and H(J) ---------------------------------------------------- */

/* omega_i : omega_j = num : den with the smallest den <= max_den. */
static bool commensurate(double wi, double wj, double tol, long max_den, qd_act_ratio *r) {
    if (!(fabs(wi) > 0 && fabs(wj) > 0))
        return false;
    double q = fabs(wi / wj);
    for (long den = 1; den <= max_den; den++) {
        long num = lround(q * den);
        if (num >= 1 && num <= max_den && fabs(q - (double)num / den) <= tol * q) {
            r->num = num, r->den = den;
            return true;
        }
    }
    return false;
}

static bool degeneracies(qd_ctx *ctx, const qd_action_opts *o, qd_action *a) {
    double tol = o && o->degeneracy_tol > 0 ? o->degeneracy_tol : 1e-9;
    long max_den = o && o->max_den > 0 ? o->max_den : 12;
    a->ratio = qd__calloc(ctx, a->n * a->n + 1, sizeof *a->ratio);
    if (!a->ratio)
        return false;
    for (size_t i = 0; i < a->n; i++)
        for (size_t j = i + 1; j < a->n; j++) {
            qd_act_ratio r = {.i = i, .j = j};
            if (commensurate(a->c[i].omega, a->c[j].omega, tol, max_den, &r))
                a->ratio[a->nratio++] = r;
        }
    return true;
}

/* p^2 a polynomial of degree <= 2 in q: an oscillator's ellipse in (q, p). */
static bool quadratic_in_q(qd_ctx *ctx, const qd_hj_sep *s) {
    const qd_expr *d3 = qd_simplify(ctx, qd_diff_n(ctx, s->p2, s->q, 3));
    return d3 && qd_is_zero(d3);
}

/* H homogeneous of degree d in J gives sum J_k dH/dJ_k = d H (Euler): the
 * oscillators have d = 1 with p^2 quadratic in q, Kepler d = -2 with one
 * frequency (Goldstein eq. 10.137). */
static void closed_form(qd_ctx *ctx, const qd_hj *h, qd_action *a) {
    double sum = 0, sumJ = 0, E = a->energy, tol = 1e-9;
    bool quadratic = true, equal = true;
    for (size_t k = 0; k < a->n; k++) {
        sum += a->c[k].J * a->c[k].omega / (2 * PI);
        sumJ += a->c[k].J;
        quadratic = quadratic && a->c[k].kind == QD_ACT_LIBRATION &&
                    quadratic_in_q(ctx, &h->sep[k]);
        equal = equal && fabs(a->c[k].omega - a->c[0].omega) <= tol * fabs(a->c[0].omega);
    }
    qd__ctx_recover(ctx); /* a simplification that failed only withholds the form */
    if (quadratic && fabs(sum - E) <= tol * fabs(E))
        a->closed = QD_ACT_H_LINEAR;
    else if (E < 0 && equal && fabs(sum + 2 * E) <= tol * fabs(E)) {
        a->closed = QD_ACT_H_KEPLER;
        a->closed_c = -E * sumJ * sumJ;
    }
}

/* ---- each coordinate ------------------------------------------------------------- */

static qd_status fail_motion(qd_ctx *ctx, qd_action *a, qd_act_fail why, size_t k) {
    static const char *const what[] = {
        "",
        "%s is unbounded: p^2 has no second turning point, so there is no cycle",
        ("%s is on a separatrix: p^2 has a double root, the period and dJ/dE diverge "
         "logarithmically"),
        "%s is at rest at an equilibrium (p^2 <= 0 about the state): J = 0"};
    static const char *const hint[] = {
        NULL,
        ("an unbounded motion has no cycle and so no action; where the potential has a well, "
         "a state of lower energy stays in it"),
        "move the state off the separatrix: a libration just below or a rotation just above",
        "the small oscillations about it are `qdot modes`"};
    a->fail = why;
    a->fail_coord = k;
    const char *name = qd_expr_name(a->c[k].q);
    if (why == QD_ACT_SINGULAR) {
        qd_ctx_error(ctx, QD_ERR_ARG,
                     "%s reaches %s = %.6g with p != 0: p^2 does not vanish there (it is "
                     "infinite: a collision, or a singular point of the coordinates such as "
                     "an axis; or it ends: the edge of its domain), so it is no turning "
                     "point and there is no cycle", name, name, a->c[k].lo);
        qd_ctx_error_about(ctx, QD_SUBJECT_COORD, k, name, QD_REASON_NONE,
                           "a nearby state that turns back before it has an action (a little "
                           "angular momentum: Kepler's radial orbit, p_phi = 0 in parabolic "
                           "or spheroidal coordinates)");
        return QD_ERR_ARG;
    }
    qd_ctx_error(ctx, QD_ERR_ARG, what[why], name);
    qd_ctx_error_about(ctx, QD_SUBJECT_COORD, k, name, QD_REASON_NONE, hint[why]);
    return QD_ERR_ARG;
}

/* A cyclic coordinate not known to be an angle (it enters the model
 * nowhere inside sin, cos or tan): unbounded as a translation, a rotation
 * if it is an angle, which only the caller can say. */
static qd_status fail_cyclic(qd_ctx *ctx, qd_action *a, size_t k) {
    const char *name = qd_expr_name(a->c[k].q);
    a->fail = QD_ACT_UNBOUNDED;
    a->fail_coord = k;
    qd_ctx_error(ctx, QD_ERR_ARG, "%s is cyclic and not known to be an angle (it is inside no "
                 "sin, cos or tan of the model): as a translation it is unbounded, no cycle",
                 name);
    qd_ctx_error_about(ctx, QD_SUBJECT_COORD, k, name, QD_REASON_NONE,
                       "if it is an angle, say so (qdot action --angle NAME; "
                       "qd_action_opts.angles): it then rotates over one turn");
    return QD_ERR_ARG;
}

/* A cyclic coordinate whose momentum is 0 (phi of an orbit in a plane
 * phi = const): not an equilibrium of the system, as AT_REST's message
 * would say, but a cycle of zero width whose frequency has no meaning. */
static qd_status fail_still(qd_ctx *ctx, qd_action *a, size_t k) {
    const char *name = qd_expr_name(a->c[k].q);
    a->fail = QD_ACT_AT_REST;
    a->fail_coord = k;
    qd_ctx_error(ctx, QD_ERR_ARG, "%s is cyclic and its momentum is 0 at the state: it stays "
                 "constant (J = 0), so it has no cycle and no frequency", name);
    char hint[256];
    snprintf(hint, sizeof hint, "the motion keeps to %s = constant: give it a little "
             "momentum, or take the model without %s", name, name);
    qd_ctx_error_about(ctx, QD_SUBJECT_COORD, k, name, QD_REASON_NONE, hint);
    return QD_ERR_ARG;
}

/* beta_j += this coordinate's dW/dalpha_j at the state, moving with the
 * sign of its momentum there (forward when the state does not give it). */
static bool add_phase(qd__act_fn *f, const qd__act_cycle *c, const qd_hj_sep *sep, double q0,
                      const double *dJ, size_t nvals, const qd_expr *const *syms,
                      const double *vals, double *beta) {
    double p = 1, b[QD_ACT_MAX_CONST];
    if (sep->p)
        lookup(sep->p, nvals, syms, vals, &p);
    bool ok = f->nc <= QD_ACT_MAX_CONST && qd__act_phase(f, c, q0, p < 0 ? -1 : 1, dJ, b);
    for (size_t j = 0; ok && j < f->nc; j++)
        beta[j] += b[j];
    return ok;
}

static qd_status one_coord(qd_ctx *ctx, const qd_hj *h, size_t k, bool angle, const double *cv,
                           double q0, size_t nvals, const qd_expr *const *syms,
                           const double *vals, double *beta, qd_action *a) {
    qd__act_fn f;
    if (!h->sep[k].p2) { /* the momentum representation (qd_hj_sep.qk): no p(q) */
        qd_ctx_error(ctx, QD_ERR_ARG, "%s: the Hamilton-Jacobi equation was solved in the "
                     "momentum representation; action variables need p as a function of %s",
                     qd_expr_name(h->sep[k].q), qd_expr_name(h->sep[k].q));
        return QD_ERR_ARG;
    }
    if (!qd__act_fn_init(ctx, &f, h->sep[k].p2, h->sep[k].q, h->nconst, h->constants, cv, nvals,
                         syms, vals))
        return qd_ctx_status(ctx);
    double p0, p2 = qd__act_p2(&f, q0);
    if (lookup(h->sep[k].p, nvals, syms, vals, &p0) &&
        !(fabs(p2 - p0 * p0) <= 1e-8 * (1 + p0 * p0 + fabs(p2)))) {
        /* a separation on the wrong branch (sep1.c) would take the action
         * of another motion: never silently */
        qd_ctx_error(ctx, QD_ERR_NUMERIC, "the separated %s^2 = %.12g at the state, where "
                     "%s^2 = %.12g: the separation does not hold on this motion's branch",
                     qd_expr_name(h->sep[k].p), p2, qd_expr_name(h->sep[k].p), p0 * p0);
        qd__act_fn_free(&f);
        return QD_ERR_NUMERIC;
    }
    qd__act_cycle c;
    qd_act_fail why = qd__act_cycle_find(&f, q0, angle, &c);
    qd_status st = QD_OK;
    a->c[k].lo = c.lo;
    bool cyclic = !qd_has(h->sep[k].p2, h->sep[k].q);
    if (why == QD_ACT_UNBOUNDED && !angle && cyclic)
        st = fail_cyclic(ctx, a, k);
    else if (why == QD_ACT_AT_REST && cyclic)
        st = fail_still(ctx, a, k);
    else if (why != QD_ACT_OK)
        st = fail_motion(ctx, a, why, k);
    else if (!qd__act_integrals(&f, &c, &a->c[k].J, &a->dJ[k * a->n]) ||
             !add_phase(&f, &c, &h->sep[k], q0, &a->dJ[k * a->n], nvals, syms, vals, beta)) {
        qd_ctx_error(ctx, QD_ERR_NUMERIC, "the action integral of %s did not converge",
                     qd_expr_name(h->sep[k].q));
        st = QD_ERR_NUMERIC;
    }
    a->c[k].kind = c.kind;
    a->c[k].lo = c.lo;
    a->c[k].hi = c.hi;
    qd__act_fn_free(&f);
    return st;
}

/* ---- the entry points --------------------------------------------------------- */

static qd_status setup(qd_ctx *ctx, const qd_hj *h, qd_action *a) {
    *a = (qd_action){.n = h->n, .form = h->form};
    if (!h->separable) {
        a->fail = QD_ACT_NOT_SEPARABLE;
        qd_ctx_error(ctx, QD_ERR_ARG, "the Hamilton-Jacobi equation does not separate: %s",
                     h->why);
        qd_ctx_error_about(ctx, QD_SUBJECT_NONE, 0, NULL, QD_REASON_NONE,
                           "a non-separable motion has no actions of its own; see its surface "
                           "of section with `qdot poincare`");
        return QD_ERR_ARG;
    }
    if (!h->time_independent) {
        qd_ctx_error(ctx, QD_ERR_ARG, "H depends on t: the motion has no fixed cycle to take "
                                      "an action over");
        qd_ctx_error_about(ctx, QD_SUBJECT_NONE, 0, NULL, QD_REASON_NONE,
                           "under a slow change J is an adiabatic invariant: take the system "
                           "frozen at one time, its parameters given there with --set");
        return QD_ERR_ARG;
    }
    size_t e = 0;
    while (e < h->nconst && h->constants[e] != h->energy)
        e++;
    if (h->nconst != h->n || e == h->nconst) {
        qd_ctx_error(ctx, QD_ERR_ARG, "actions need one separation constant per coordinate, "
                                      "the energy among them (here %zu for %zu)",
                     h->nconst, h->n);
        return QD_ERR_ARG;
    }
    a->c = qd__calloc(ctx, h->n, sizeof *a->c);
    a->dJ = qd__calloc(ctx, h->n * h->n, sizeof *a->dJ);
    return a->c && a->dJ ? QD_OK : QD_ERR_NOMEM;
}

qd_status qd_action_of_sep(qd_ctx *ctx, const qd_hj *h, const bool *angle, size_t nvals,
                           const qd_expr *const *syms, const double *vals,
                           const qd_action_opts *opts, qd_action *out) {
    QD_ARGS_CTX(ctx, ctx && h && angle && (nvals == 0 || syms) && (nvals == 0 || vals) && out);
    qd_status st = setup(ctx, h, out);
    double *cv = st == QD_OK ? qd__calloc(ctx, 2 * h->nconst, sizeof *cv) : NULL;
    double *beta = cv ? cv + h->nconst : NULL;
    if (st == QD_OK && (!cv || !constant_values(ctx, h, nvals, syms, vals, cv)))
        st = qd_ctx_status(ctx);
    for (size_t k = 0; st == QD_OK && k < h->n; k++) {
        out->c[k].q = h->sep[k].q;
        out->c[k].constant = h->sep[k].constant;
        for (size_t j = 0; j < h->nconst; j++)
            if (h->constants[j] == h->sep[k].constant)
                out->c[k].value = cv[j];
        double q0;
        if (!lookup(h->sep[k].q, nvals, syms, vals, &q0)) {
            qd_ctx_error(ctx, QD_ERR_UNBOUND, "the state gives no value of %s",
                         qd_expr_name(h->sep[k].q));
            st = QD_ERR_UNBOUND;
            break;
        }
        st = one_coord(ctx, h, k, angle[k], cv, q0, nvals, syms, vals, beta, out);
    }
    for (size_t j = 0; st == QD_OK && j < h->nconst; j++)
        if (h->constants[j] == h->energy)
            out->energy = cv[j];
    if (st == QD_OK && (!frequencies(ctx, h, beta, out) || !degeneracies(ctx, opts, out)))
        st = qd_ctx_status(ctx);
    if (st == QD_OK)
        closed_form(ctx, h, out);
    if (st == QD_OK && qd__ctx_nomem(ctx))
        st = QD_ERR_NOMEM; /* the form withheld for want of memory is no answer */
    qd__free(cv);
    return st;
}

/* The momenta at the state from p = dL/dq' (an H model's q' = dH/dp
 * inverted), appended to the state: the integrals of an H model are in p.
 * A momentum the state gives already keeps its value. */
static bool with_momenta(qd_ctx *ctx, const qd_ham *hm, size_t nvals,
                         const qd_expr *const *syms, const double *vals,
                         const qd_expr ***s2, double **v2) {
    *s2 = qd__calloc(ctx, nvals + hm->n, sizeof **s2);
    *v2 = qd__calloc(ctx, nvals + hm->n, sizeof **v2);
    if (!*s2 || !*v2)
        return false;
    memcpy(*s2, syms, nvals * sizeof *syms);
    memcpy(*v2, vals, nvals * sizeof *vals);
    for (size_t j = 0; j < hm->n; j++) {
        (*s2)[nvals + j] = hm->p[j];
        if (lookup(hm->p[j], nvals, syms, vals, &(*v2)[nvals + j]))
            continue;
        if (!hm->pdef[j]) {
            qd_ctx_error(ctx, QD_ERR_ARG, "H is not regular: the velocities do not give %s; "
                         "give it with the state", qd_expr_name(hm->p[j]));
            return false;
        }
        if (qd_eval(ctx, hm->pdef[j], nvals, syms, vals, &(*v2)[nvals + j]) != QD_OK)
            return false;
    }
    return true;
}

static qd_ham *hamiltonian(qd_ctx *ctx, const qd_model *m, qd_eom **e) {
    *e = qd_model_hamiltonian_given(m) ? NULL : qd_eom_derive(ctx, m);
    if (!*e && !qd_model_hamiltonian_given(m))
        return NULL;
    qd_ham *h = qd_ham_derive(ctx, m, *e);
    if (qd_ham_require_closed(ctx, h, "the action variables") != QD_OK) {
        qd_ham_free(h);
        return NULL;
    }
    return h;
}

/* One degree of freedom is separated here; more by qd_hj_derive.  Forces
 * outside H (Q, Rayleigh's D) leave no cycle whatever H does. */
static qd_hj *separate(qd_ctx *ctx, const qd_model *m, const qd_ham *hm,
                       const qd_action_opts *opts) {
    const char *E = opts ? opts->energy_name : NULL;
    if (!hm->conserved && !qd_has(hm->H, qd_time(ctx))) {
        qd_ctx_error(ctx, QD_ERR_ARG, "generalized forces or dissipation act besides H: the "
                                      "energy changes and the motion has no cycle");
        return NULL;
    }
    if (hm->n == 1)
        return qd__act_sep1(ctx, hm, E);
    qd_hj_opts ho = {.energy_name = E};
    return qd_hj_derive(ctx, m, &ho);
}

/* Freed by whoever made it: separate() made it here for one coordinate. */
static void separation_free(qd_hj *h, const qd_ham *hm) {
    if (hm && hm->n == 1)
        qd__act_sep1_free(h);
    else
        qd_hj_free(h);
}

/* opts->angles marked among the coordinates; false (QD_ERR_ARG) for one
 * that is not a coordinate. */
static bool angles_given(qd_ctx *ctx, const qd_ham *hm, const qd_action_opts *opts,
                         bool *angle) {
    for (size_t i = 0; opts && i < opts->nangles; i++) {
        size_t k = 0;
        while (k < hm->n && hm->q[k] != opts->angles[i])
            k++;
        if (k == hm->n) {
            qd_ctx_error(ctx, QD_ERR_ARG, "%s is given as an angle but is not a coordinate",
                         opts->angles[i] ? qd_expr_name(opts->angles[i]) : "(null)");
            return false;
        }
        angle[k] = true;
    }
    return true;
}

qd_status qd_action_at(qd_ctx *ctx, const qd_model *m, size_t nvals, const qd_expr *const *syms,
                       const double *vals, const qd_action_opts *opts, qd_action *out) {
    QD_ARGS_CTX(ctx, ctx && m && (nvals == 0 || syms) && (nvals == 0 || vals) && out);
    *out = (qd_action){0};
    qd_eom *e = NULL;
    qd_ham *hm = hamiltonian(ctx, m, &e);
    qd_hj *h = hm ? separate(ctx, m, hm, opts) : NULL;
    bool *angle = h ? qd__calloc(ctx, h->n + 1, sizeof *angle) : NULL;
    const qd_expr **s2 = NULL;
    double *v2 = NULL;
    qd_status st;
    if (angle && with_momenta(ctx, hm, nvals, syms, vals, &s2, &v2) &&
        qd__act_angles(ctx, m, hm->n, hm->q, angle) && angles_given(ctx, hm, opts, angle))
        st = qd_action_of_sep(ctx, h, angle, nvals + hm->n, s2, v2, opts, out);
    else
        st = qd_ctx_status(ctx) != QD_OK ? qd_ctx_status(ctx) : QD_ERR_NOMEM;
    qd__free(s2);
    qd__free(v2);
    qd__free(angle);
    separation_free(h, hm);
    qd_ham_free(hm);
    qd_eom_free(e);
    return st;
}

void qd_action_free(qd_action *a) {
    if (!a)
        return;
    qd__free(a->c);
    qd__free(a->dJ);
    qd__free(a->ratio);
    *a = (qd_action){0};
}

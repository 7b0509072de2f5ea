/*
 * src/scatter/potential.c - the central potential of scattering: V(r)
 * compiled with its derivatives, the radii where its steps jump, its
 * range, and V read off a model by Routh's reduction.
 */
#include "sct.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "qdot/routh.h"
#include "../base/mem.h"
#include "../base/args.h"

#define JUMP_SCAN_PER_DECADE 40

/* ---- evaluation ---------------------------------------------------------- */

void qd__sct_eval(qd_scatter *s, double r, double lo, double hi, double out[4]) {
    /* a point on a jump must see its own side, not step's 1/2 */
    if (r <= lo)
        r = nextafter(lo, INFINITY);
    if (r >= hi)
        r = nextafter(hi, 0);
    qd_prog_run(s->prog, &r, out);
}

double qd__sct_V(qd_scatter *s, double r, double lo, double hi) {
    double v[4];
    qd__sct_eval(s, r, lo, hi, v);
    return v[0];
}

void qd__sct_segment(const qd_scatter *s, double r, int side, double *lo, double *hi) {
    *lo = s->core;
    *hi = INFINITY;
    for (size_t i = 0; i < s->njump; i++) {
        double a = s->jump[i];
        if (a < r || (a == r && side > 0))
            *lo = a;
        else {
            *hi = a;
            break;
        }
    }
}

double qd__sct_scale(const qd_scatter *s, double b) {
    double L = fmax(fmax(b, s->core), 1.0);
    return s->njump ? fmax(L, s->jump[s->njump - 1]) : L;
}

/* ---- the jumps ------------------------------------------------------------ */

/* The step arguments of e, each once, into args (at most cap). */
static size_t step_args(const qd_expr *e, const qd_expr **args, size_t n, size_t cap) {
    size_t na = qd_expr_nargs(e);
    if (qd_expr_kind(e) == QD_FUNC && qd_expr_func(e) == QD_STEP) {
        const qd_expr *a = qd_expr_arg(e, 0);
        bool seen = false;
        for (size_t i = 0; i < n; i++)
            seen |= args[i] == a;
        if (!seen && n < cap)
            args[n++] = a;
    }
    for (size_t i = 0; i < na && qd_expr_kind(e) != QD_UFUNC; i++)
        n = step_args(qd_expr_arg(e, i), args, n, cap);
    return n;
}

static void add_jump(qd_scatter *s, double a) {
    if (!(a > s->core) || s->njump == QD_SCT_MAX_JUMPS)
        return;
    for (size_t i = 0; i < s->njump; i++)
        if (s->jump[i] == a)
            return;
    size_t k = s->njump++;
    while (k && s->jump[k - 1] > a) {
        s->jump[k] = s->jump[k - 1];
        k--;
    }
    s->jump[k] = a;
}

/* Bisection of a sign change of the argument to adjacent doubles: the jump
 * radius to round-off (exact for step(a - r)). */
static double bisect_arg(qd_prog *p, double lo, double hi, double flo) {
    for (int it = 0; it < 200; it++) {
        double mid = 0.5 * (lo + hi), f;
        if (mid <= lo || mid >= hi)
            break;
        qd_prog_run(p, &mid, &f);
        if (f == 0)
            return mid;
        if ((f > 0) == (flo > 0))
            lo = mid, flo = f;
        else
            hi = mid;
    }
    return fabs(flo) == 0 ? lo : hi;
}

/* The zeros of each step argument over r in [1e-9, 1e9]. */
static bool find_jumps(qd_ctx *ctx, qd_scatter *s) {
    const qd_expr *args[QD_SCT_MAX_JUMPS];
    size_t n = step_args(s->V, args, 0, QD_SCT_MAX_JUMPS);
    for (size_t k = 0; k < n; k++) {
        qd_prog *p = qd_prog_new(ctx, 1, &s->r, 1, &args[k]);
        if (!p)
            return false;
        double r = 1e-9, f0;
        qd_prog_run(p, &r, &f0);
        for (int i = 1; i <= 18 * JUMP_SCAN_PER_DECADE; i++) {
            double r1 = 1e-9 * pow(10.0, (double)i / JUMP_SCAN_PER_DECADE), f1;
            qd_prog_run(p, &r1, &f1);
            if (f1 == 0)
                add_jump(s, r1);
            else if (f0 != 0 && (f0 > 0) != (f1 > 0))
                add_jump(s, bisect_arg(p, r, r1, f0));
            r = r1, f0 = f1;
        }
        qd_prog_free(p);
    }
    return true;
}

/* ---- range and decay ---------------------------------------------------------- */

/* V = 0 exactly beyond the last wall (jump or core): a finite range. */
static double find_range(qd_scatter *s) {
    double R = s->njump ? s->jump[s->njump - 1] : s->core;
    for (int i = 0; i <= 16 * 8; i++) {
        double r = fmax(R, 1e-9) * (1 + 1e-9) * pow(10.0, i / 8.0);
        if (qd__sct_V(s, r, R, INFINITY) != 0)
            return INFINITY;
    }
    return R;
}

static bool decays(qd_scatter *s) {
    double L = qd__sct_scale(s, 0), big = 0;
    for (int i = 0; i <= 10; i++)
        big = fmax(big, fabs(qd__sct_V(s, L * (1 + i), s->range < INFINITY ? s->range : L, INFINITY)));
    return fabs(qd__sct_V(s, 1e12 * L, 0, INFINITY)) <= 1e-4 * big;
}

/* ---- construction ---------------------------------------------------------- */

static bool compile(qd_ctx *ctx, qd_scatter *s) {
    const qd_expr *out[4] = {s->V, NULL, NULL, NULL};
    for (int k = 1; k < 4; k++)
        out[k] = qd_diff(ctx, out[k - 1], s->r);
    if (!out[3])
        return false;
    s->prog = qd_prog_new(ctx, 1, &s->r, 4, out);
    return s->prog != NULL;
}

qd_scatter *qd_scatter_new(qd_ctx *ctx, const qd_expr *V, const qd_expr *r, double core) {
    QD_ARGS(NULL, ctx && V && r);
    if (!V || !r)
        return NULL;
    if (!(core >= 0) || !isfinite(core)) {
        qd_ctx_error(ctx, QD_ERR_ARG, "the hard core's radius must be >= 0, not %g", core);
        return NULL;
    }
    qd_scatter *s = qd__calloc(ctx, 1, sizeof *s);
    if (!s)
        return NULL;
    s->V = V, s->r = r, s->core = core;
    if (!compile(ctx, s) || !find_jumps(ctx, s)) {
        qd_scatter_free(s);
        return NULL;
    }
    s->range = find_range(s);
    if (!decays(s)) {
        qd_ctx_error(ctx, QD_ERR_ARG,
                     "the potential does not vanish at infinity: scattering needs V -> 0 as "
                     "%s -> inf", qd_expr_name(r));
        qd_scatter_free(s);
        return NULL;
    }
    return s;
}

void qd_scatter_free(qd_scatter *s) {
    if (!s)
        return;
    qd_prog_free(s->prog);
    qd__free(s);
}

void qd_scatter_set_absorbing(qd_scatter *s, bool on) {
    if (s)
        s->absorbing = on;
}

const qd_expr *qd_scatter_potential(const qd_scatter *s) { QD_ARGS(NULL, s); return s->V; }
const qd_expr *qd_scatter_radius(const qd_scatter *s) { QD_ARGS(NULL, s); return s->r; }
size_t qd_scatter_njumps(const qd_scatter *s) { QD_ARGS(0, s); return s->njump; }
double qd_scatter_jump(const qd_scatter *s, size_t i) { QD_ARGS(NAN, s); return i < s->njump ? s->jump[i] : NAN; }
double qd_scatter_range(const qd_scatter *s) { QD_ARGS(NAN, s); return s->range; }

/* ---- from a model ------------------------------------------------------------ */

static const qd_expr *cyclic_coordinate(qd_ctx *ctx, const qd_model *m, const qd_eom *e,
                                        const char *ignore) {
    if (ignore)
        return qd_routh_lookup(ctx, m, ignore);
    const qd_expr *found = NULL;
    for (size_t j = 0; j < e->n; j++) {
        const char *why;
        if (!qd_routh_not_cyclic(ctx, m, e, j, &why)) {
            if (found) {
                qd_ctx_error(ctx, QD_ERR_ARG, "both %s and %s are cyclic: say which angle to "
                             "ignore (--ignore)", qd_expr_name(found), qd_expr_name(e->q[j]));
                return NULL;
            }
            found = e->q[j];
        }
    }
    if (!found)
        qd_ctx_error(ctx, QD_ERR_ARG, "no cyclic coordinate: scattering needs a central "
                     "potential, V(r) with an angle absent from L");
    return found;
}

/* e with every parameter of m replaced by its value. */
static const qd_expr *with_values(qd_ctx *ctx, const qd_model *m, const qd_expr *e) {
    size_t n = qd_model_nparams(m);
    const qd_expr **from = qd__malloc(ctx, (n + 1) * sizeof *from);
    const qd_expr **to = qd__malloc(ctx, (n + 1) * sizeof *to);
    if (!from || !to) {
        qd__free(from);
        qd__free(to);
        return NULL;
    }
    for (size_t i = 0; i < n; i++)
        from[i] = qd_model_param(m, i), to[i] = qd_model_param_value(m, i);
    const qd_expr *r = e ? qd_subs(ctx, e, n, from, to) : NULL;
    qd__free(from);
    qd__free(to);
    return r;
}

/* V_eff - V = p^2/(2 m r^2) at a few points: the centrifugal barrier of a
 * particle of constant mass m, i.e. T = m/2 (r'^2 + r^2 phi'^2). */
static bool is_central(qd_ctx *ctx, const qd_routh *h, const qd_expr *Veff, const qd_expr *V,
                       double m) {
    const qd_expr *syms[2] = {h->keep[0], h->beta[0]};
    static const double pts[3][2] = {{0.7, 0.9}, {1.3, -2.1}, {2.9, 0.4}};
    for (int k = 0; k < 3; k++) {
        double ve, v0, r = pts[k][0], p = pts[k][1];
        if (!Veff || qd_eval(ctx, Veff, 2, syms, pts[k], &ve) != QD_OK ||
            qd_eval(ctx, V, 2, syms, pts[k], &v0) != QD_OK)
            return false;
        double want = p * p / (2 * m * r * r);
        if (!(fabs(ve - v0 - want) <= 1e-9 * (fabs(want) + fabs(ve))))
            return false;
    }
    return true;
}

qd_scatter *qd_scatter_from_model(qd_ctx *ctx, const qd_model *m, const qd_eom *e,
                                  const char *ignore, double core, double *mass) {
    QD_ARGS(NULL, ctx && m && e);
    if (!m || !e)
        return NULL;
    if (e->n != 2) {
        qd_ctx_error(ctx, QD_ERR_ARG, "scattering needs a model in a plane: a radius and an "
                     "angle (this one has %zu coordinates)", e->n);
        return NULL;
    }
    const qd_expr *ign = cyclic_coordinate(ctx, m, e, ignore);
    qd_routh *h = ign ? qd_routh_derive(ctx, m, e, 1, &ign) : NULL;
    if (!h)
        return NULL;
    const qd_expr *zero = qd_int(ctx, 0), *M = with_values(ctx, m, h->M[0]);
    const qd_expr *V = with_values(ctx, m, qd_subs(ctx, h->Veff, 1, &h->beta[0], &zero));
    qd_scatter *s = NULL;
    if (!M || !qd_is_number(M) || !(qd_number_value(M) > 0) || !V) {
        if (V)
            qd_ctx_error(ctx, QD_ERR_ARG, "the radial mass is not a positive constant: not a "
                         "particle in a central potential");
    } else if (!is_central(ctx, h, with_values(ctx, m, h->Veff), V, qd_number_value(M))) {
        if (qd_ctx_status(ctx) == QD_OK)
            qd_ctx_error(ctx, QD_ERR_ARG, "V_eff is not V(%s) + p^2/(2 m %s^2): not a central "
                         "potential", qd_expr_name(h->keep[0]), qd_expr_name(h->keep[0]));
    } else {
        if (mass)
            *mass = qd_number_value(M);
        s = qd_scatter_new(ctx, V, h->keep[0], core);
    }
    qd_routh_free(h);
    return s;
}

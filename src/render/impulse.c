/*
 * src/render/impulse.c - the answer of qd_impulse_solve printed
 * (qd_render_impulse): the velocities after with their closed forms, the
 * impulsive multipliers and reactions, the energies, the theorems of
 * impulsive motion that apply and a two-body collision's description, as
 * text, JSON or LaTeX.  `qdot impulse` is this and its option parsing.
 */
#include <math.h>
#include <stdio.h>
#include "qdot/json.h"
#include "qdot/render.h"
#include "../base/args.h"

/* What every printer below reads. */
typedef struct imp_view {
    qd_ctx *ctx;
    const qd_model *m;
    const qd_impulse *res;
} imp_view;

/* ---- output: shared ---------------------------------------------------------------- */

static const char *qname(const imp_view *r, size_t j) { return qd_expr_name(r->res->q[j]); }

/* A result: the one digit rule (qd_buf_put_result, scale 1). */
static void put_num(qd_buf *b, double x) { qd_buf_put_result(b, x, 1); }

/* A vector's components against its largest (the digit rule's scale). */
static void put_vec(qd_buf *b, const double *v) {
    double big = fmax(fabs(v[0]), fmax(fabs(v[1]), fabs(v[2])));
    qd_buf_puts(b, "(");
    for (unsigned k = 0; k < 3; k++) {
        qd_buf_puts(b, k ? ", " : "");
        qd_buf_put_result(b, v[k], big);
    }
    qd_buf_puts(b, ")");
}

/* A closed form worth showing beside its number: not a plain integer. */
static bool shows(const qd_expr *x) { return x && !qd_is_integer(x); }

/* "closed = number", or the number alone. */
static void put_value(const imp_view *r, qd_buf *b, const qd_expr *exact, double x) {
    if (shows(exact)) {
        qd_print(r->ctx, exact, QD_FMT_TEXT, b);
        qd_buf_puts(b, " = ");
    }
    put_num(b, x);
}

static const qd_expr *exact_qd(const imp_view *r, size_t j) {
    return r->res->exact && r->res->qd_after_exact ? r->res->qd_after_exact[j] : NULL;
}

static const qd_expr *exact_mult(const imp_view *r, size_t k) {
    return r->res->exact && r->res->mult_exact ? r->res->mult_exact[k] : NULL;
}

static const qd_expr *exact_lost(const imp_view *r) {
    return r->res->exact ? r->res->energy_lost_exact : NULL;
}

/* ---- text ---------------------------------------------------------------------- */

static void text_velocities(const imp_view *r, qd_buf *b) {
    const qd_impulse *s = r->res;
    qd_buf_puts(b, "velocities before:");
    for (size_t j = 0; j < s->n; j++) {
        qd_buf_printf(b, "%s %s' = ", j ? "," : "", qname(r, j));
        put_num(b, s->qd_before[j]);
    }
    qd_buf_puts(b, "\nvelocities after:\n");
    for (size_t j = 0; j < s->n; j++) {
        qd_buf_printf(b, "  %s'+ = ", qname(r, j));
        put_value(r, b, exact_qd(r, j), s->qd_after[j]);
        qd_buf_puts(b, "\n");
    }
}

static void text_impulses(const imp_view *r, qd_buf *b) {
    const qd_impulse *s = r->res;
    if (qd_model_nblows(r->m)) {
        qd_buf_puts(b, "generalized impulses of the blows:");
        for (size_t j = 0; j < s->n; j++) {
            qd_buf_printf(b, "%s Qhat[%s] = ", j ? "," : "", qname(r, j));
            put_num(b, s->Qhat[j]);
        }
        qd_buf_puts(b, "\n");
    }
    if (s->nmult)
        qd_buf_puts(b, "impulsive multipliers:\n");
    for (size_t k = 0; k < s->nmult; k++) {
        qd_buf_printf(b, "  %s = ", s->mult_name[k]);
        put_value(r, b, exact_mult(r, k), s->mult[k]);
        qd_buf_puts(b, "\n");
    }
    if (s->nredundant) {
        qd_buf_puts(b, "note: redundant at the impact (dependent on the others and consistent "
                       "with them; reduced by rank, multiplier set to 0, not unique):");
        for (size_t k = 0; k < s->nmult; k++)
            if (s->redundant[k])
                qd_buf_printf(b, " %s", s->mult_name[k]);
        qd_buf_puts(b, "\n");
    }
    if (s->nreact)
        qd_buf_puts(b, "impulsive reactions:\n");
    for (size_t k = 0; k < s->nreact; k++) {
        qd_buf_printf(b, "  %s: ", s->react_name[k]);
        put_vec(b, s->react[k]);
        qd_buf_puts(b, "\n");
    }
}

static void text_energy(const imp_view *r, qd_buf *b) {
    const qd_impulse *s = r->res;
    qd_buf_puts(b, "kinetic energy: before ");
    put_num(b, s->T_before);
    qd_buf_puts(b, ", after ");
    put_num(b, s->T_after);
    /* a blow on a system at rest gives energy: say so, not "lost -3" */
    bool gained = s->energy_lost < -1e-12 * (s->T_before + s->T_after);
    const qd_expr *x = exact_lost(r);
    qd_buf_puts(b, gained ? "\nenergy gained: " : "\nenergy lost: ");
    put_value(r, b, x && gained ? qd_neg(r->ctx, x) : x, gained ? -s->energy_lost : s->energy_lost);
    qd_buf_puts(b, "\n");
}

/* The end of a theorem's line: a check that failed is said, not hidden. */
static void verdict(qd_buf *b, const qd_impulse_check *c) {
    qd_buf_puts(b, c->holds ? "\n" : " -- NOT verified here (to 1e-9)\n");
}

static void text_theorems(const imp_view *r, qd_buf *b) {
    const qd_impulse *s = r->res;
    if (s->carnot.applies) {
        qd_buf_puts(b, "Carnot: the energy lost, ");
        put_num(b, s->carnot.a);
        qd_buf_puts(b, ", equals the kinetic energy of the velocity change, ");
        put_num(b, s->carnot.b);
        verdict(b, &s->carnot);
    }
    if (s->bertrand.applies) {
        qd_buf_puts(b, "Bertrand: the sudden constraints lower the energy after from ");
        put_num(b, s->bertrand.a);
        qd_buf_puts(b, " (the same blows without them) to ");
        put_num(b, s->bertrand.b);
        qd_buf_puts(b, ", by the energy of the difference of the two motions, ");
        put_num(b, s->bertrand.c);
        verdict(b, &s->bertrand);
    }
    if (s->thomson.applies) {
        qd_buf_puts(b, "Thomson: the velocity change has the least energy, ");
        put_num(b, s->thomson.a);
        qd_buf_puts(b, ", of the motions giving the struck points the same velocities "
                       "(least found: ");
        put_num(b, s->thomson.b);
        qd_buf_puts(b, ")");
        verdict(b, &s->thomson);
    }
}

static double deg(double rad) { return rad * 45.0 / atan(1.0); }

static void put_angle(qd_buf *b, double rad) {
    put_num(b, rad);
    qd_buf_puts(b, " rad (");
    put_num(b, deg(rad));
    qd_buf_puts(b, " deg)");
}

static void text_collision(const imp_view *r, qd_buf *b) {
    const qd_collision *c = &r->res->col;
    qd_buf_puts(b, "collision of two bodies (centre-of-mass frame, Desloge ch. 61):\n  masses ");
    put_num(b, c->m1);
    qd_buf_puts(b, " and ");
    put_num(b, c->m2);
    qd_buf_puts(b, "; centre-of-mass velocity w = ");
    put_vec(b, c->w);
    for (int i = 0; i < 2; i++) {
        qd_buf_printf(b, "\n  body %d: ", i + 1);
        put_vec(b, i ? c->v2[0] : c->v1[0]);
        qd_buf_puts(b, " -> ");
        put_vec(b, i ? c->v2[1] : c->v1[1]);
    }
    qd_buf_puts(b, "\n  relative velocity u = v1 - v2: ");
    put_vec(b, c->u[0]);
    qd_buf_puts(b, " -> ");
    put_vec(b, c->u[1]);
    qd_buf_puts(b, "\n  relative kinetic energy: ");
    put_num(b, c->eps[0]);
    qd_buf_puts(b, " -> ");
    put_num(b, c->eps[1]);
    qd_buf_puts(b, "\n  lab energy of translation = (m1 + m2)|w|^2/2 + relative: ");
    for (int t = 0; t < 2; t++) {
        qd_buf_puts(b, t ? " -> " : "");
        put_num(b, c->T_cm);
        qd_buf_puts(b, " + ");
        put_num(b, c->eps[t]);
        qd_buf_puts(b, " = ");
        put_num(b, c->T_cm + c->eps[t]);
    }
    qd_buf_puts(b, "\n  body 1's speed in the CM frame: s = ");
    put_num(b, c->s[0]);
    qd_buf_puts(b, " -> s* = ");
    put_num(b, c->s[1]);
    qd_buf_puts(b, " (s*^2 = s^2 (1 + Delta eps/eps))");
    qd_buf_puts(b, "\n  deflection in the CM frame: ");
    put_angle(b, c->theta_cm);
    qd_buf_puts(b, "\n  lab angles from u before: body 1 ");
    put_angle(b, c->theta_lab1);
    qd_buf_puts(b, ", body 2 ");
    put_angle(b, c->theta_lab2);
    qd_buf_puts(b, "\n  gamma = |w|/s* = ");
    put_num(b, c->gamma);
    qd_buf_puts(b, " (tan theta_lab1 = sin theta/(cos theta + gamma) when body 2 is at rest "
                   "before)\n");
}

static void write_text(const imp_view *r, qd_buf *b) {
    text_velocities(r, b);
    text_impulses(r, b);
    text_energy(r, b);
    text_theorems(r, b);
    if (r->res->collision)
        text_collision(r, b);
}

/* ---- JSON ---------------------------------------------------------------------- */

static void json_num(qd_json *j, const char *key, double x) {
    qd_json_key(j, key);
    qd_json_number(j, x == 0 ? 0.0 : x);
}

static void json_vec(qd_json *j, const char *key, const double *v) {
    qd_json_key(j, key);
    qd_json_begin_array(j);
    for (unsigned k = 0; k < 3; k++)
        qd_json_number(j, v[k] == 0 ? 0.0 : v[k]);
    qd_json_end_array(j);
}

/* An object keyed by the coordinates ("x'" with prime), one number each. */
static void json_by_coord(const imp_view *r, qd_json *j, const char *key, const double *x,
                          bool prime) {
    char name[80];
    qd_json_key(j, key);
    qd_json_begin_object(j);
    for (size_t k = 0; k < r->res->n; k++) {
        snprintf(name, sizeof name, "%s%s", qname(r, k), prime ? "'" : "");
        json_num(j, name, x[k]);
    }
    qd_json_end_object(j);
}

static void json_multipliers(const imp_view *r, qd_json *j) {
    const qd_impulse *s = r->res;
    qd_json_key(j, "impulsive_multipliers");
    qd_json_begin_object(j);
    for (size_t k = 0; k < s->nmult; k++)
        json_num(j, s->mult_name[k], s->mult[k]);
    qd_json_end_object(j);
    qd_json_key(j, "redundant");
    qd_json_begin_array(j);
    for (size_t k = 0; k < s->nmult; k++)
        if (s->redundant[k])
            qd_json_string(j, s->mult_name[k]);
    qd_json_end_array(j);
    qd_json_key(j, "impulsive_reactions");
    qd_json_begin_object(j);
    for (size_t k = 0; k < s->nreact; k++)
        json_vec(j, s->react_name[k], s->react[k]);
    qd_json_end_object(j);
}

static void json_exact(const imp_view *r, qd_json *j) {
    const qd_impulse *s = r->res;
    char name[80];
    qd_json_key(j, "exact");
    if (!s->exact) {
        qd_json_null(j);
        return;
    }
    qd_json_begin_object(j);
    qd_json_key(j, "velocities_after");
    qd_json_begin_object(j);
    for (size_t k = 0; k < s->n; k++) {
        snprintf(name, sizeof name, "%s'", qname(r, k));
        qd_json_key(j, name);
        qd_json_expr(j, r->ctx, exact_qd(r, k));
    }
    qd_json_end_object(j);
    qd_json_key(j, "impulsive_multipliers");
    qd_json_begin_object(j);
    for (size_t k = 0; k < s->nmult; k++) {
        qd_json_key(j, s->mult_name[k]);
        qd_json_expr(j, r->ctx, exact_mult(r, k));
    }
    qd_json_end_object(j);
    qd_json_key(j, "energy_lost");
    qd_json_expr(j, r->ctx, exact_lost(r));
    qd_json_end_object(j);
}

/* One theorem: whether it applies and holds, and its numbers named. */
static void json_check(qd_json *j, const char *key, const qd_impulse_check *c,
                       const char *const names[3]) {
    qd_json_key(j, key);
    qd_json_begin_object(j);
    qd_json_key(j, "applies");
    qd_json_bool(j, c->applies);
    qd_json_key(j, "holds");
    qd_json_bool(j, c->applies && c->holds);
    const double v[3] = {c->a, c->b, c->c};
    for (int k = 0; k < 3 && c->applies; k++)
        if (names[k])
            json_num(j, names[k], v[k]);
    qd_json_end_object(j);
}

static void json_theorems(const imp_view *r, qd_json *j) {
    static const char *const carnot[3] = {"energy_lost", "energy_of_change", NULL};
    static const char *const bertrand[3] = {"energy_without", "energy_with",
                                            "energy_of_difference"};
    static const char *const thomson[3] = {"energy_of_change", "least_energy", NULL};
    qd_json_key(j, "theorems");
    qd_json_begin_object(j);
    json_check(j, "carnot", &r->res->carnot, carnot);
    json_check(j, "bertrand", &r->res->bertrand, bertrand);
    json_check(j, "thomson", &r->res->thomson, thomson);
    qd_json_end_object(j);
}

static void json_collision(const imp_view *r, qd_json *j) {
    const qd_collision *c = &r->res->col;
    qd_json_begin_object(j);
    json_num(j, "m1", c->m1);
    json_num(j, "m2", c->m2);
    json_vec(j, "w", c->w);
    json_vec(j, "v1_before", c->v1[0]);
    json_vec(j, "v1_after", c->v1[1]);
    json_vec(j, "v2_before", c->v2[0]);
    json_vec(j, "v2_after", c->v2[1]);
    json_vec(j, "u_before", c->u[0]);
    json_vec(j, "u_after", c->u[1]);
    json_num(j, "eps_before", c->eps[0]);
    json_num(j, "eps_after", c->eps[1]);
    json_num(j, "energy_cm", c->T_cm);
    json_num(j, "s_before", c->s[0]);
    json_num(j, "s_after", c->s[1]);
    json_num(j, "theta_cm", c->theta_cm);
    json_num(j, "theta_lab1", c->theta_lab1);
    json_num(j, "theta_lab2", c->theta_lab2);
    json_num(j, "gamma", c->gamma);
    qd_json_end_object(j);
}

static void write_json(const imp_view *r, qd_buf *b) {
    const qd_impulse *s = r->res;
    qd_json j;
    qd_json_init(&j, b);
    qd_json_begin_object(&j);
    json_by_coord(r, &j, "velocities_before", s->qd_before, true);
    json_by_coord(r, &j, "velocities_after", s->qd_after, true);
    json_by_coord(r, &j, "generalized_impulses", s->Qhat, false);
    json_multipliers(r, &j);
    json_num(&j, "kinetic_energy_before", s->T_before);
    json_num(&j, "kinetic_energy_after", s->T_after);
    json_num(&j, "energy_lost", s->energy_lost);
    json_exact(r, &j);
    json_theorems(r, &j);
    qd_json_key(&j, "collision");
    if (s->collision)
        json_collision(r, &j);
    else
        qd_json_null(&j);
    qd_json_end_object(&j);
    qd_buf_puts(b, "\n");
    b->failed = b->failed || !qd_json_ok(&j);
}

/* ---- LaTeX --------------------------------------------------------------------- */

/* One line "lhs &= closed form" (or the number when there is none). */
static void latex_line(const imp_view *r, qd_buf *b, bool *first, const qd_expr *lhs,
                       const char *suffix, const qd_expr *exact, double x) {
    qd_buf_puts(b, *first ? "  " : " \\\\\n  ");
    *first = false;
    qd_print(r->ctx, lhs, QD_FMT_LATEX, b);
    qd_buf_printf(b, "%s &= ", suffix);
    if (exact)
        qd_print(r->ctx, exact, QD_FMT_LATEX, b);
    else
        put_num(b, x);
}

static void write_latex(const imp_view *r, qd_buf *b) {
    const qd_impulse *s = r->res;
    bool first = true;
    qd_buf_puts(b, "\\begin{align}\n");
    for (size_t j = 0; j < s->n; j++)
        latex_line(r, b, &first, qd_jet(r->ctx, s->q[j], 1), "^{+}", exact_qd(r, j),
                   s->qd_after[j]);
    for (size_t k = 0; k < s->nmult; k++)
        latex_line(r, b, &first, qd_symbol(r->ctx, s->mult_name[k]), "", exact_mult(r, k),
                   s->mult[k]);
    qd_buf_puts(b, first ? "  " : " \\\\\n  ");
    qd_buf_puts(b, "T_- - T_+ &= ");
    if (exact_lost(r))
        qd_print(r->ctx, exact_lost(r), QD_FMT_LATEX, b);
    else
        put_num(b, s->energy_lost);
    qd_buf_puts(b, "\n\\end{align}\n");
}

qd_status qd_render_impulse(qd_ctx *ctx, const qd_model *m, const qd_impulse *res,
                            qd_render_format fmt, qd_buf *out) {
    QD_ARGS_CTX(ctx, ctx && m && res && out);
    const imp_view v = {ctx, m, res};
    if (fmt == QD_RENDER_JSON)
        write_json(&v, out);
    else if (fmt == QD_RENDER_LATEX)
        write_latex(&v, out);
    else if (fmt == QD_RENDER_TEXT)
        write_text(&v, out);
    else
    {
        qd_ctx_error(ctx, QD_ERR_ARG, "an impulse prints as text, json or latex");
        return QD_ERR_ARG;
    }
    /* a printer that ran out of memory marks the context too */
    if (out->failed || qd_ctx_status(ctx) == QD_ERR_NOMEM)
        return QD_ERR_NOMEM;
    return QD_OK;
}

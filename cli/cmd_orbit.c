/*
 * cli/cmd_orbit.c - `qdot orbit FILE --ignore Q[,Q...]`: the motion left in
 * one coordinate by Routh's reduction (qdot/orbit.h): V_eff, the energy and
 * momenta at the state (the model's `initial` values, then --at), the
 * turning points and the kind of orbit, the radial period and the advance
 * of each ignored coordinate, the circular orbits at the same momenta and
 * Kepler's conic.  --momentum and --energy replace the state's values;
 * --orbit adds the orbit equation.
 */
#include "cli.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "qdot/json.h"
#include "model_cli.h"
#include "model_file.h"
#include "qdot/orbit.h"
#include "state.h"

#define MAX_IGN 32

typedef struct orbit_args {
    const char *file, *ignore, *at, *momentum, *energy, *sets[QD_CLI_MAX_LIST];
    size_t nsets;
    bool json, equation;
} orbit_args;

typedef struct orbit_run {
    qd_ctx *ctx;
    cli_model_file mf;
    qd_eom *e;
    qd_orbit *o;
    cli_state st;
    size_t nign;
    const qd_expr *ign[MAX_IGN];
    const qd_expr **syms;   /* the state, then the momenta given */
    double *vals, E;
    size_t n;
    bool has_E;
    qd_orbit_result r;
} orbit_run;

static const char usage_text[] =
    "usage: qdot orbit FILE --ignore Q[,Q...] [--at \"q=VALUE, q'=VALUE, ...\"] "
    "[--momentum \"p_Q=VALUE\"] [--energy E] [--orbit] [--format text|json] [--set NAME=VALUE]...";

static const char *const formats[] = {"text", "json", NULL};

static int parse_option(int argc, char **argv, int *i, void *data) {
    orbit_args *a = data;
    const char *v;
    int f;
    if ((v = cli_value(argc, argv, i, "--format"))) {
        int rc = cli_choice("--format", v, formats, &f);
        a->json = f == 1;
        return rc;
    }
    if ((v = cli_value(argc, argv, i, "--set")))
        return cli_push("--set", a->sets, &a->nsets, QD_CLI_MAX_LIST, v);
    if ((v = cli_value(argc, argv, i, "--ignore")))
        return cli_once("--ignore", &a->ignore, v);
    if ((v = cli_value(argc, argv, i, "--at")))
        return cli_once("--at", &a->at, v);
    if ((v = cli_value(argc, argv, i, "--momentum")))
        return cli_once("--momentum", &a->momentum, v);
    if ((v = cli_value(argc, argv, i, "--energy")))
        return cli_once("--energy", &a->energy, v);
    if (!strcmp(argv[*i], "--orbit")) {
        a->equation = true;
        return QD_EXIT_OK;
    }
    return cli_bad_option(argv[*i], usage_text);
}

static int parse_args(int argc, char **argv, orbit_args *a) {
    int rc = cli_file_args(argc, argv, "orbit", usage_text, &a->file, parse_option, a);
    if (rc == QD_EXIT_OK && !a->ignore) {
        cli_diag_error("orbit needs --ignore with the cyclic coordinates to ignore (all but "
                       "one)\n%s", usage_text);
        rc = QD_EXIT_USAGE;
    }
    return rc;
}

/* ---- the state ------------------------------------------------------------------ */

static int initial_state(orbit_run *r, const orbit_args *a) {
    const qd_model *m = r->mf.model;
    size_t nq = qd_model_ncoords(m);
    int rc = cli_state_init(r->ctx, m, &r->st);
    for (size_t i = 0; rc == QD_EXIT_OK && i < nq; i++)
        for (unsigned o = 0; o < 2; o++) {
            const qd_expr *v = qd_model_initial(m, i, o);
            if (v && qd_eval(r->ctx, v, r->st.n, r->st.syms, r->st.vals,
                             &r->st.vals[o * nq + i]) != QD_OK)
                return cli_diag_ctx(r->ctx);
        }
    if (rc == QD_EXIT_OK && a->at)
        rc = cli_state_parse(r->ctx, m, a->at, &r->st);
    return rc;
}

/* "p_theta=VALUE[, p_psi=VALUE]": each the momentum of an ignored coordinate. */
/* --energy: an expression in the parameters (and the state's values), so that
 * "m*g*a" names the top of a pendulum's swing exactly. */
static int energy_value(orbit_run *r, const char *text) {
    const qd_read_opts opts = {.new_symbols = false};
    qd_diag err;
    const qd_expr *e = qd_read(r->ctx, text, &opts, &err);
    if (!e) {
        cli_diag_read("--energy", text, &err);
        return QD_EXIT_USAGE;
    }
    if (qd_eval(r->ctx, e, r->n, r->syms, r->vals, &r->E) != QD_OK || !isfinite(r->E)) {
        qd_ctx_clear_error(r->ctx);
        cli_diag_error("--energy: '%s' does not evaluate to a finite number", text);
        return QD_EXIT_USAGE;
    }
    return QD_EXIT_OK;
}

static int momentum_item(orbit_run *r, const char *item, size_t len) {
    const char *eq = memchr(item, '=', len);
    char name[128], text[256];
    size_t nl = eq ? (size_t)(eq - item) : 0;
    while (nl && item[nl - 1] == ' ')
        nl--;
    while (nl && *item == ' ')
        item++, nl--, len--;
    if (!eq || !nl || nl >= sizeof name || (size_t)(item + len - eq) >= sizeof text) {
        cli_diag_error("--momentum takes \"p_Q=VALUE, ...\", not '%.*s'", (int)len, item);
        return QD_EXIT_USAGE;
    }
    memcpy(name, item, nl);
    name[nl] = '\0';
    size_t tl = (size_t)(item + len - eq - 1);
    memcpy(text, eq + 1, tl);
    text[tl] = '\0';
    const qd_routh *h = r->o->routh;
    for (size_t i = 0; i < h->nign; i++)
        if (!strcmp(qd_expr_name(h->beta[i]), name)) {
            const qd_expr *x;
            int rc = cli_state_number(r->ctx, "--momentum", text, &x, &r->vals[r->n]);
            r->syms[r->n++] = h->beta[i];
            return rc;
        }
    cli_diag_error("--momentum: '%s' is not the momentum of an ignored coordinate (they are "
                   "p_<q>)", name);
    return QD_EXIT_USAGE;
}

static int build_state(orbit_run *r, const orbit_args *a) {
    size_t cap = r->st.n + r->nign;
    r->syms = malloc(cap * sizeof *r->syms);
    r->vals = malloc(cap * sizeof *r->vals);
    if (!r->syms || !r->vals) {
        cli_diag_error("out of memory");
        return QD_EXIT_FAIL;
    }
    memcpy(r->syms, r->st.syms, r->st.n * sizeof *r->syms);
    memcpy(r->vals, r->st.vals, r->st.n * sizeof *r->vals);
    r->n = r->st.n;
    int rc = QD_EXIT_OK;
    for (const char *s = a->momentum; s && rc == QD_EXIT_OK;) {
        const char *comma = strchr(s, ',');
        rc = momentum_item(r, s, comma ? (size_t)(comma - s) : strlen(s));
        s = comma ? comma + 1 : NULL;
    }
    if (rc == QD_EXIT_OK && a->energy) {
        r->has_E = true;
        rc = energy_value(r, a->energy);
    }
    return rc;
}

/* ---- text ---------------------------------------------------------------------- */

static void num(qd_buf *b, double x) {
    if (isinf(x))
        qd_buf_puts(b, x > 0 ? "inf" : "-inf");
    else
        cli_state_put_result(b, x);
}

static void by_name(const orbit_run *r, qd_buf *b, const char *what, const double *v) {
    const qd_routh *h = r->o->routh;
    qd_buf_printf(b, "%s:", what);
    for (size_t i = 0; i < h->nign; i++) {
        qd_buf_printf(b, "%s %s ", i ? "," : "", qd_expr_name(h->ign[i]));
        num(b, v[i]);
    }
    qd_buf_puts(b, "\n");
}

static void text_kind(const orbit_run *r, qd_buf *b) {
    const qd_orbit_result *o = &r->r;
    const char *x = qd_expr_name(r->o->x);
    qd_buf_printf(b, "kind: %s\n", qd_orbit_kind_name(o->kind));
    if (o->nturn) {
        qd_buf_printf(b, "turning points: %s = ", x);
        for (size_t k = 0; k < o->nturn; k++) {
            qd_buf_puts(b, k ? ", " : "");
            num(b, o->turn[k]);
        }
        qd_buf_puts(b, "\n");
    }
    qd_buf_printf(b, "motion: ");
    num(b, o->lo);
    qd_buf_printf(b, " <= %s <= ", x);
    num(b, o->hi);
    qd_buf_puts(b, "\n");
    if (o->kind == QD_ORBIT_UNBOUND) {
        qd_buf_puts(b, "radial period: none (unbound)\n");
        if (o->nign && isfinite(o->advance[0]))
            by_name(r, b, "turn from infinity and back", o->advance);
    }
    if (o->kind == QD_ORBIT_ASYMPTOTIC) {
        qd_buf_puts(b, "radial period: none (E is the top of V_eff: the motion creeps towards "
                       "the unstable circle at the end of its interval for ever)\n");
        by_name(r, b, "advance on the way", o->advance);
    }
    if (o->kind == QD_ORBIT_CAPTURE) {
        qd_buf_puts(b, "falls into the singular point of V_eff after time ");
        num(b, o->fall_time);
        qd_buf_puts(b, "\n");
        by_name(r, b, "advance until then", o->advance);
    }
    if (isfinite(o->period)) {
        qd_buf_puts(b, "radial period: ");
        num(b, o->period);
        qd_buf_puts(b, o->kind == QD_ORBIT_CIRCULAR ? " (small radial oscillations)\n" : "\n");
        by_name(r, b, "advance per period", o->advance);
        by_name(r, b, "apsidal angle", o->apsidal);
        by_name(r, b, "precession per period", o->precession);
    }
}

static void text_circles(const orbit_run *r, qd_buf *b) {
    const qd_orbit_result *o = &r->r;
    const char *x = qd_expr_name(r->o->x);
    qd_buf_printf(b, "circular orbits at these momenta:%s\n", o->ncircle ? "" : " none");
    for (size_t k = 0; k < o->ncircle; k++) {
        const qd_orbit_circle *c = &o->circle[k];
        qd_buf_printf(b, "  %s = ", x);
        num(b, c->x);
        qd_buf_puts(b, ": V_eff = ");
        num(b, c->energy);
        qd_buf_printf(b, ", %s", c->stable == 1 ? "stable" : c->stable == 0 ? "unstable"
                                                                           : "borderline");
        if (c->stable == 1) {
            qd_buf_puts(b, ", omega = ");
            num(b, c->omega);
            for (size_t i = 0; i < o->nign; i++) {
                qd_buf_printf(b, ", apsidal angle (%s) ", qd_expr_name(r->o->routh->ign[i]));
                num(b, c->apsidal[i]);
            }
            if (isfinite(c->bertrand)) {
                qd_buf_puts(b, " = pi/sqrt(3 + r f'/f) ");
                num(b, c->bertrand);
            }
        }
        qd_buf_puts(b, "\n");
    }
}

static void text_conic(const orbit_run *r, qd_buf *b) {
    const qd_orbit_result *o = &r->r;
    qd_buf_puts(b, "conic: p = ");
    num(b, o->p);
    qd_buf_puts(b, ", e = ");
    num(b, o->e);
    qd_buf_puts(b, ", a = ");
    num(b, o->a);
    if (o->nu != 1) {
        qd_buf_puts(b, ", nu = ");
        num(b, o->nu);
    }
    if (o->repulsive)
        qd_buf_puts(b, ", repulsive");
    if (isfinite(o->periapsis)) {
        qd_buf_printf(b, ", periapsis at %s = ", qd_expr_name(r->o->routh->ign[0]));
        num(b, o->periapsis);
    }
    qd_buf_puts(b, "\n");
}

/* The orbit equation: the conic with its numbers, else the quadrature. */
static void put_equation(orbit_run *r, qd_buf *b) {
    const qd_orbit_result *o = &r->r;
    const char *c = qd_expr_name(r->o->routh->ign[0]);
    if (o->conic) {
        qd_buf_printf(b, "%s = ", qd_expr_name(r->o->x));
        num(b, o->p);
        qd_buf_puts(b, o->repulsive ? "/(" : "/(1 + ");
        num(b, o->e);
        double peri = isfinite(o->periapsis) ? o->periapsis : 0;
        bool group = o->nu != 1 && peri != 0;
        qd_buf_puts(b, "*cos(");
        if (o->nu != 1) {
            num(b, o->nu);
            qd_buf_puts(b, group ? "*(" : "*");
        }
        qd_buf_printf(b, "%s", c);
        if (peri != 0) {
            qd_buf_printf(b, " %s ", peri < 0 ? "+" : "-");
            num(b, fabs(peri));
        }
        qd_buf_puts(b, group ? "))" : ")");
        qd_buf_puts(b, o->repulsive ? " - 1)" : ")"); /* C3's p/(e cos - 1) */
        return;
    }
    const qd_expr *lhs = NULL;
    const qd_expr *rhs = qd_orbit_equation(r->ctx, r->o, o, &lhs);
    if (!rhs || !lhs) {
        b->failed = true;
        return;
    }
    qd_print(r->ctx, lhs, QD_FMT_TEXT, b);
    qd_buf_puts(b, " = ");
    qd_print(r->ctx, rhs, QD_FMT_TEXT, b);
}

static void text_equation(orbit_run *r, qd_buf *b) {
    qd_buf_puts(b, "orbit: ");
    put_equation(r, b);
    qd_buf_puts(b, "\n");
}

static void write_text(orbit_run *r, const orbit_args *a, qd_buf *b) {
    const qd_orbit_result *o = &r->r;
    const qd_routh *h = r->o->routh;
    qd_buf_printf(b, "model: %s\nignored: ", r->mf.path);
    for (size_t i = 0; i < h->nign; i++) {
        qd_buf_printf(b, "%s%s (%s = ", i ? ", " : "", qd_expr_name(h->ign[i]),
                      qd_expr_name(h->beta[i]));
        num(b, o->momenta[i]);
        qd_buf_puts(b, ")");
    }
    qd_buf_puts(b, "\neffective potential: V_eff = ");
    qd_print(r->ctx, r->o->Veff, QD_FMT_TEXT, b);
    qd_buf_puts(b, "\nenergy: E = ");
    num(b, o->energy);
    qd_buf_puts(b, "\n");
    text_kind(r, b);
    text_circles(r, b);
    if (o->conic)
        text_conic(r, b);
    if (a->equation)
        text_equation(r, b);
}

/* ---- JSON ------------------------------------------------------------------------ */

/* null for the numbers an orbit does not have (NaN) and for infinity */
static void jnum(qd_json *j, double x) {
    if (isfinite(x))
        qd_json_number(j, x);
    else
        qd_json_null(j);
}

static void json_by_name(const orbit_run *r, qd_json *j, const char *key, const double *v) {
    const qd_routh *h = r->o->routh;
    qd_json_key(j, key);
    qd_json_begin_object(j);
    for (size_t i = 0; i < h->nign; i++) {
        qd_json_key(j, qd_expr_name(h->ign[i]));
        jnum(j, v[i]);
    }
    qd_json_end_object(j);
}

static void json_circles(const orbit_run *r, qd_json *j) {
    const qd_orbit_result *o = &r->r;
    qd_json_key(j, "circular");
    qd_json_begin_array(j);
    for (size_t k = 0; k < o->ncircle; k++) {
        const qd_orbit_circle *c = &o->circle[k];
        qd_json_begin_object(j);
        qd_json_key(j, qd_expr_name(r->o->x));
        jnum(j, c->x);
        qd_json_key(j, "effective_potential");
        jnum(j, c->energy);
        qd_json_key(j, "stable");
        if (c->stable < 0)
            qd_json_null(j);
        else
            qd_json_bool(j, c->stable == 1);
        qd_json_key(j, "omega");
        jnum(j, c->omega);
        json_by_name(r, j, "apsidal_angle", c->apsidal);
        qd_json_key(j, "bertrand");
        jnum(j, c->bertrand);
        qd_json_end_object(j);
    }
    qd_json_end_array(j);
}

static void json_conic(const orbit_run *r, qd_json *j) {
    const qd_orbit_result *o = &r->r;
    qd_json_key(j, "conic");
    if (!o->conic) {
        qd_json_null(j);
        return;
    }
    qd_json_begin_object(j);
    const char *keys[] = {"p", "e", "a", "nu", "periapsis"};
    double v[] = {o->p, o->e, o->a, o->nu, o->periapsis};
    for (int k = 0; k < 5; k++) {
        qd_json_key(j, keys[k]);
        jnum(j, v[k]);
    }
    qd_json_key(j, "repulsive");
    qd_json_bool(j, o->repulsive);
    qd_json_end_object(j);
}

static void json_equation(orbit_run *r, qd_json *j) {
    qd_buf b = QD_BUF_INIT;
    put_equation(r, &b);
    qd_json_key(j, "orbit");
    qd_json_string(j, qd_buf_str(&b));
    qd_buf_free(&b);
}

static void json_motion(const orbit_run *r, qd_json *j) {
    const qd_orbit_result *o = &r->r;
    qd_json_key(j, "kind");
    qd_json_string(j, qd_orbit_kind_name(o->kind));
    qd_json_key(j, "turning_points");
    qd_json_begin_array(j);
    for (size_t k = 0; k < o->nturn; k++)
        jnum(j, o->turn[k]);
    qd_json_end_array(j);
    qd_json_key(j, "interval");
    qd_json_begin_array(j);
    jnum(j, o->lo);
    jnum(j, o->hi);
    qd_json_end_array(j);
    qd_json_key(j, "radial_period");
    jnum(j, o->period);
    json_by_name(r, j, "advance", o->advance);
    json_by_name(r, j, "apsidal_angle", o->apsidal);
    json_by_name(r, j, "precession_per_period", o->precession);
    qd_json_key(j, "fall_time");
    jnum(j, o->fall_time);
    qd_json_key(j, "quadrature_error");
    jnum(j, o->quad_error);
}

static void write_json(orbit_run *r, const orbit_args *a, qd_buf *b) {
    qd_json j;
    qd_json_init(&j, b);
    qd_json_begin_object(&j);
    qd_json_key(&j, "file");
    qd_json_string(&j, r->mf.path);
    qd_json_key(&j, "coordinate");
    qd_json_string(&j, qd_expr_name(r->o->x));
    qd_json_key(&j, "effective_potential");
    qd_json_expr(&j, r->ctx, r->o->Veff);
    qd_json_key(&j, "energy");
    jnum(&j, r->r.energy);
    qd_json_key(&j, "momenta");
    qd_json_begin_object(&j);
    for (size_t i = 0; i < r->nign; i++) {
        qd_json_key(&j, qd_expr_name(r->o->routh->beta[i]));
        jnum(&j, r->r.momenta[i]);
    }
    qd_json_end_object(&j);
    json_motion(r, &j);
    json_circles(r, &j);
    json_conic(r, &j);
    if (a->equation)
        json_equation(r, &j);
    qd_json_end_object(&j);
    qd_buf_puts(b, "\n");
    b->failed = b->failed || !qd_json_ok(&j);
}

/* ---- run ----------------------------------------------------------------------- */

static int run(orbit_run *r, const orbit_args *a) {
    int rc = cli_load_derive(r->ctx, a->file, a->nsets, a->sets, false, NULL, &r->mf, &r->e);
    if (rc == QD_EXIT_OK)
        rc = cli_ignore_parse(r->ctx, r->mf.model, a->ignore, r->ign, MAX_IGN, &r->nign);
    if (rc == QD_EXIT_OK)
        rc = cli_ignore_check(r->ctx, &r->mf, r->e, r->ign, r->nign);
    if (rc == QD_EXIT_OK && !(r->o = qd_orbit_derive(r->ctx, r->mf.model, r->e, r->nign, r->ign)))
        rc = cli_diag_ctx(r->ctx);
    if (rc == QD_EXIT_OK)
        rc = initial_state(r, a);
    if (rc == QD_EXIT_OK)
        rc = build_state(r, a);
    if (rc != QD_EXIT_OK)
        return rc;
    if (qd_orbit_solve(r->ctx, r->o, r->n, r->syms, r->vals, r->has_E ? &r->E : NULL, &r->r))
        return cli_diag_ctx(r->ctx);
    qd_buf b = QD_BUF_INIT;
    if (a->json)
        write_json(r, a, &b);
    else
        write_text(r, a, &b);
    return cli_emit(&b, "orbit");
}

int cli_cmd_orbit(int argc, char **argv) {
    orbit_args a = {0};
    int rc = parse_args(argc, argv, &a);
    if (rc != QD_EXIT_OK)
        return rc;
    orbit_run r = {.ctx = qd_ctx_new()};
    if (!r.ctx) {
        cli_diag_error("out of memory");
        return QD_EXIT_FAIL;
    }
    rc = run(&r, &a);
    qd_orbit_result_free(&r.r);
    qd_orbit_free(r.o);
    free(r.syms);
    free(r.vals);
    cli_state_free(&r.st);
    if (r.e)
        qd_eom_free(r.e);
    cli_model_file_free(&r.mf);
    qd_ctx_free(r.ctx);
    return rc;
}

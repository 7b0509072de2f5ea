/*
 * cli/cmd_scatter.c - `qdot scatter FILE --energy E --b B | --theta TH`:
 * classical scattering by the central potential of a model in a plane
 * (qdot/scatter.h; Desloge ch. 60-61): the deflection of one impact
 * parameter, or the cross section at one centre-of-mass angle summed over
 * its branches; either way the features of the deflection function at
 * that energy (range and total cross section, rainbows, glories,
 * orbiting), and with --masses the laboratory frame, target at rest.
 */
#include "cli.h"

#include <math.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>
#include "qdot/json.h"
#include "model_cli.h"
#include "model_file.h"
#include "qdot/scatter.h"
#include "state.h"

#define PI 3.14159265358979323846 /* M_PI is not C11 */

typedef enum { FMT_TEXT, FMT_JSON } scatter_fmt;

typedef struct scatter_run {
    qd_ctx *ctx;
    cli_model_file mf;
    qd_eom *e;
    qd_scatter *s;
    scatter_fmt fmt;
    const char *file, *ignore, *energy_s, *b_s, *theta_s, *lab_s, *masses_s, *core_s;
    const char *sets[QD_CLI_MAX_LIST];
    size_t nsets;
    double E, b, theta, lab_theta, core, mass, m1, m2;
    size_t ncm;                 /* --lab-theta: the CM angles that reach it */
    double cm[2], cm_sigma[2], cm_jacobian[2];
    qd_scatter_path path;
    qd_scatter_section sec;
    qd_scatter_features feat;
} scatter_run;

static const char usage_text[] =
    "usage: qdot scatter FILE --energy E (--b B | --theta TH | --lab-theta TH) [--masses m1,m2] "
    "[--core A] "
    "[--ignore Q] [--set NAME=VALUE]... [--format text|json]";

static const char *const formats[] = {"text", "json", NULL};

static int parse_option(int argc, char **argv, int *i, void *data) {
    scatter_run *r = data;
    const char *v;
    int f;
    if ((v = cli_value(argc, argv, i, "--format"))) {
        int rc = cli_choice("--format", v, formats, &f);
        r->fmt = (scatter_fmt)f;
        return rc;
    }
    if ((v = cli_value(argc, argv, i, "--set")))
        return cli_push("--set", r->sets, &r->nsets, QD_CLI_MAX_LIST, v);
    static const struct { const char *opt; size_t off; } once[] = {
        {"--energy", offsetof(scatter_run, energy_s)}, {"--b", offsetof(scatter_run, b_s)},
        {"--theta", offsetof(scatter_run, theta_s)}, {"--lab-theta", offsetof(scatter_run, lab_s)},
        {"--masses", offsetof(scatter_run, masses_s)},
        {"--core", offsetof(scatter_run, core_s)}, {"--ignore", offsetof(scatter_run, ignore)},
    };
    for (size_t k = 0; k < sizeof once / sizeof once[0]; k++)
        if ((v = cli_value(argc, argv, i, once[k].opt)))
            return cli_once(once[k].opt, (const char **)((char *)r + once[k].off), v);
    return cli_bad_option(argv[*i], usage_text);
}

static int parse_args(int argc, char **argv, scatter_run *r) {
    int rc = cli_file_args(argc, argv, "scatter", usage_text, &r->file, parse_option, r);
    if (rc != QD_EXIT_OK)
        return rc;
    if (!r->energy_s || !!r->b_s + !!r->theta_s + !!r->lab_s != 1) {
        cli_diag_error("scatter needs --energy and one of --b, --theta and --lab-theta\n%s",
                       usage_text);
        return QD_EXIT_USAGE;
    }
    if (r->lab_s && !r->masses_s) {
        cli_diag_error("--lab-theta needs --masses m1,m2 (the lab frame depends on them)");
        return QD_EXIT_USAGE;
    }
    return QD_EXIT_OK;
}

/* ---- numbers on the command line: expressions in the parameters -------------- */

static int number(scatter_run *r, const char *opt, const char *text, double *out) {
    const qd_model *m = r->mf.model;
    size_t np = qd_model_nparams(m);
    const qd_expr **from = calloc(np + 1, sizeof *from), **to = calloc(np + 1, sizeof *to);
    const qd_expr *x = qd_read(r->ctx, text, NULL, NULL);
    for (size_t i = 0; x && from && to && i < np; i++)
        from[i] = qd_model_param(m, i), to[i] = qd_model_param_value(m, i);
    if (x && from && to)
        x = qd_subs(r->ctx, x, np, from, to);
    free(from);
    free(to);
    if (!x || qd_eval(r->ctx, x, 0, NULL, NULL, out) != QD_OK || !isfinite(*out)) {
        cli_diag_error("%s takes a number (an expression in the parameters), not '%s'", opt, text);
        return QD_EXIT_USAGE;
    }
    return QD_EXIT_OK;
}

static int masses(scatter_run *r) {
    const char *comma = strchr(r->masses_s, ',');
    if (!comma) {
        cli_diag_error("--masses takes m1,m2 (projectile, target), not '%s'", r->masses_s);
        return QD_EXIT_USAGE;
    }
    char first[128];
    size_t len = (size_t)(comma - r->masses_s);
    if (len >= sizeof first)
        len = sizeof first - 1;
    memcpy(first, r->masses_s, len);
    first[len] = '\0';
    int rc = number(r, "--masses", first, &r->m1);
    if (rc == QD_EXIT_OK)
        rc = number(r, "--masses", comma + 1, &r->m2);
    if (rc == QD_EXIT_OK && !(r->m1 > 0 && r->m2 > 0)) {
        cli_diag_error("--masses must be positive, not %g and %g", r->m1, r->m2);
        rc = QD_EXIT_USAGE;
    }
    return rc;
}

static int read_numbers(scatter_run *r) {
    int rc = number(r, "--energy", r->energy_s, &r->E);
    if (rc == QD_EXIT_OK && r->b_s)
        rc = number(r, "--b", r->b_s, &r->b);
    if (rc == QD_EXIT_OK && r->theta_s)
        rc = number(r, "--theta", r->theta_s, &r->theta);
    if (rc == QD_EXIT_OK && r->lab_s)
        rc = number(r, "--lab-theta", r->lab_s, &r->lab_theta);
    if (rc == QD_EXIT_OK && r->lab_s && !(r->lab_theta > 0 && r->lab_theta < PI)) {
        cli_diag_error("--lab-theta must lie in (0, pi), not %g", r->lab_theta);
        rc = QD_EXIT_USAGE;
    }
    if (rc == QD_EXIT_OK && r->core_s)
        rc = number(r, "--core", r->core_s, &r->core);
    if (rc == QD_EXIT_OK && r->masses_s)
        rc = masses(r);
    return rc;
}

/* ---- the computation ---------------------------------------------------------- */

/* The cross section at the angle of the --b orbit (when it leaves). */
static qd_status section_of_path(scatter_run *r) {
    double th = r->path.theta;
    if (!(th > 1e-12 && th < PI - 1e-12))
        return QD_OK;
    return qd_scatter_section_at(r->ctx, r->s, r->E, th, &r->sec);
}

/* --lab-theta: every CM angle that reaches it (two when m1 > m2), each
 * with its cross section and Jacobian (Desloge ch. 61 eqs. 36, 67). */
static qd_status lab_angles(scatter_run *r) {
    double g = r->m1 / r->m2, tl;
    r->theta = NAN;
    r->ncm = qd_scatter_lab_to_cm(g, r->lab_theta, r->cm);
    for (size_t k = 0; k < r->ncm; k++) {
        qd_scatter_section x;
        qd_status st = qd_scatter_section_at(r->ctx, r->s, r->E, r->cm[k], &x);
        if (st != QD_OK)
            return st;
        r->cm_sigma[k] = x.sigma;
        qd_scatter_lab_gamma(g, r->cm[k], &tl, &r->cm_jacobian[k]);
    }
    return QD_OK;
}

static int compute(scatter_run *r) {
    qd_status st;
    r->sec.sigma = NAN;
    if (r->b_s) {
        st = qd_scatter_deflect(r->ctx, r->s, r->E, r->b, &r->path);
        if (st == QD_OK)
            st = section_of_path(r);
        r->theta = r->path.theta;
    } else if (r->theta_s) {
        st = qd_scatter_section_at(r->ctx, r->s, r->E, r->theta, &r->sec);
    } else {
        st = lab_angles(r);
    }
    if (st == QD_OK)
        st = qd_scatter_features_at(r->ctx, r->s, r->E, &r->feat);
    return st == QD_OK ? QD_EXIT_OK : cli_diag_ctx(r->ctx);
}

/* sigma_lab at the lab angle of theta: every CM angle that reaches it
 * (two when m1 > m2), each through its Jacobian (Desloge ch. 61 eq. 67). */
static double lab_section(scatter_run *r, double theta_lab, size_t *ncm) {
    double cm[2], sum = 0;
    *ncm = qd_scatter_lab_to_cm(r->m1 / r->m2, theta_lab, cm);
    for (size_t k = 0; k < *ncm; k++) {
        qd_scatter_section x;
        double tl, J;
        if (qd_scatter_section_at(r->ctx, r->s, r->E, cm[k], &x) != QD_OK)
            return NAN;
        qd_scatter_lab_gamma(r->m1 / r->m2, cm[k], &tl, &J);
        sum += x.sigma * J;
    }
    return sum;
}

/* ---- text ------------------------------------------------------------------------ */

/* Nine significant digits: the cross sections come from differences of
 * the deflection (good to about 1e-10), so a tenth digit would be noise. */
static void num(qd_buf *b, double x) {
    if (isinf(x))
        qd_buf_puts(b, x > 0 ? "infinite" : "-infinite");
    else
        qd_buf_printf(b, "%.9g", fabs(x) < 1e-13 ? 0.0 : x);
}

static void angle(qd_buf *b, double x) {
    num(b, x);
    qd_buf_puts(b, " (");
    num(b, x * 180 / PI);
    qd_buf_puts(b, " deg)");
}

static void text_path(const scatter_run *r, qd_buf *b) {
    const qd_scatter_path *p = &r->path;
    qd_buf_printf(b, "impact parameter: ");
    num(b, r->b);
    qd_buf_printf(b, "\norbit: %s\n", qd_scatter_kind_name(p->kind));
    if (p->kind == QD_SCATTER_CAPTURED)
        return;
    qd_buf_puts(b, "closest approach: r0 = ");
    num(b, p->r0);
    qd_buf_puts(b, "\ndeflection: Theta = ");
    angle(b, p->theta);
    qd_buf_puts(b, "\ndeflection_signed: chi = ");
    num(b, p->chi);
    qd_buf_puts(b, "\n");
}

static void text_section(const scatter_run *r, qd_buf *b) {
    const qd_scatter_section *x = &r->sec;
    if (!isfinite(x->sigma))
        return;
    qd_buf_puts(b, "cross_section: dsigma/dOmega = ");
    num(b, x->sigma);
    qd_buf_printf(b, " at Theta = ");
    angle(b, x->theta);
    qd_buf_printf(b, ", %zu branch%s%s\n", x->nbranch, x->nbranch == 1 ? "" : "es",
                  x->truncated ? " (more not counted: orbiting)" : "");
    for (size_t i = 0; i < x->nbranch; i++) {
        qd_buf_puts(b, "  b = ");
        num(b, x->branch[i].b);
        qd_buf_puts(b, ": chi = ");
        num(b, x->branch[i].chi);
        qd_buf_puts(b, ", dchi/db = ");
        num(b, x->branch[i].dchi_db);
        qd_buf_puts(b, ", dsigma/dOmega = ");
        num(b, x->branch[i].sigma);
        qd_buf_puts(b, "\n");
    }
}

static void text_features(const scatter_run *r, qd_buf *b) {
    const qd_scatter_features *f = &r->feat;
    qd_buf_puts(b, "range: ");
    num(b, f->range);
    qd_buf_puts(b, "\ntotal cross section: ");
    num(b, f->total);
    qd_buf_puts(b, "\n");
    for (size_t i = 0; i < f->nrainbow; i++) {
        qd_buf_puts(b, "rainbow: Theta = ");
        angle(b, f->rainbow_theta[i]);
        qd_buf_puts(b, " at b = ");
        num(b, f->rainbow_b[i]);
        qd_buf_puts(b, "\n");
    }
    for (size_t i = 0; i < f->nglory; i++) {
        qd_buf_printf(b, "glory: %s at b = ", f->glory_theta[i] == 0 ? "forward" : "backward");
        num(b, f->glory_b[i]);
        qd_buf_puts(b, "\n");
    }
    if (f->orbiting) {
        qd_buf_puts(b, "orbiting: b = ");
        num(b, f->orbit_b);
        qd_buf_puts(b, " circles at r = ");
        num(b, f->orbit_r);
        qd_buf_puts(b, "\n");
    }
    if (f->capture) {
        qd_buf_puts(b, "capture: b < ");
        num(b, f->capture_b);
        qd_buf_puts(b, ", cross section ");
        num(b, PI * f->capture_b * f->capture_b);
        qd_buf_puts(b, "\n");
    }
}

static void text_lab(scatter_run *r, qd_buf *b) {
    qd_scatter_lab l;
    if (!r->masses_s || !(r->theta >= 0) ||
        qd_scatter_lab_map(r->ctx, r->m1, r->m2, r->theta, &l) != QD_OK)
        return;
    size_t ncm;
    double q = lab_section(r, l.theta_lab, &ncm);
    qd_buf_puts(b, "lab frame (target at rest, gamma = m1/m2 = ");
    num(b, l.gamma);
    qd_buf_puts(b, "):\n  lab_angle: ");
    angle(b, l.theta_lab);
    qd_buf_puts(b, "\n  energy after / before: ");
    num(b, l.energy_ratio);
    if (isfinite(q)) {
        qd_buf_puts(b, "\n  lab_cross_section: ");
        num(b, q);
        qd_buf_printf(b, " (%zu CM angle%s)", ncm, ncm == 1 ? "" : "s");
    }
    qd_buf_puts(b, "\n  recoil: angle ");
    angle(b, l.recoil_angle);
    qd_buf_puts(b, ", energy / projectile's ");
    num(b, l.recoil_ratio);
    qd_buf_puts(b, "\n");
}

static void text_lab_angles(const scatter_run *r, qd_buf *b) {
    double sum = 0;
    qd_buf_puts(b, "lab frame (target at rest, gamma = m1/m2 = ");
    num(b, r->m1 / r->m2);
    qd_buf_puts(b, "):\n  lab_angle: ");
    angle(b, r->lab_theta);
    qd_buf_puts(b, "\n");
    for (size_t k = 0; k < r->ncm; k++) {
        qd_buf_puts(b, "  CM angle ");
        angle(b, r->cm[k]);
        qd_buf_puts(b, ": dsigma/dOmega = ");
        num(b, r->cm_sigma[k]);
        qd_buf_puts(b, ", dOmega_cm/dOmega_lab = ");
        num(b, r->cm_jacobian[k]);
        qd_buf_puts(b, "\n");
        sum += r->cm_sigma[k] * r->cm_jacobian[k];
    }
    qd_buf_puts(b, "  lab_cross_section: ");
    num(b, sum);
    qd_buf_printf(b, " (%zu CM angle%s%s)\n", r->ncm, r->ncm == 1 ? "" : "s",
                  r->ncm ? "" : ": beyond the largest lab angle, asin(m2/m1)");
}

static void write_text(scatter_run *r, qd_buf *b) {
    qd_buf_printf(b, "model: %s\npotential: V = ", r->mf.path);
    qd_print(r->ctx, qd_scatter_potential(r->s), QD_FMT_TEXT, b);
    qd_buf_puts(b, "\nenergy: ");
    num(b, r->E);
    qd_buf_puts(b, "\n");
    if (r->b_s)
        text_path(r, b);
    text_section(r, b);
    if (r->lab_s)
        text_lab_angles(r, b);
    text_features(r, b);
    text_lab(r, b);
}

/* ---- JSON ------------------------------------------------------------------------ */

static void jnum(qd_json *j, const char *key, double x) {
    qd_json_key(j, key);
    if (isfinite(x))
        qd_json_number(j, x);
    else if (isinf(x))
        qd_json_string(j, x > 0 ? "infinite" : "-infinite");
    else
        qd_json_null(j);
}

static void json_pairs(qd_json *j, const char *key, size_t n, const double *bs,
                       const double *th) {
    qd_json_key(j, key);
    qd_json_begin_array(j);
    for (size_t i = 0; i < n; i++) {
        qd_json_begin_object(j);
        jnum(j, "b", bs[i]);
        jnum(j, "angle", th[i]);
        qd_json_end_object(j);
    }
    qd_json_end_array(j);
}

static void json_section(const scatter_run *r, qd_json *j) {
    const qd_scatter_section *x = &r->sec;
    jnum(j, "cross_section", x->sigma);
    qd_json_key(j, "branches");
    qd_json_begin_array(j);
    for (size_t i = 0; isfinite(x->sigma) && i < x->nbranch; i++) {
        qd_json_begin_object(j);
        jnum(j, "b", x->branch[i].b);
        jnum(j, "deflection_signed", x->branch[i].chi);
        jnum(j, "dchi_db", x->branch[i].dchi_db);
        jnum(j, "cross_section", x->branch[i].sigma);
        qd_json_end_object(j);
    }
    qd_json_end_array(j);
}

static void json_features(const scatter_run *r, qd_json *j) {
    const qd_scatter_features *f = &r->feat;
    jnum(j, "range", f->range);
    jnum(j, "total_cross_section", f->total);
    json_pairs(j, "rainbows", f->nrainbow, f->rainbow_b, f->rainbow_theta);
    json_pairs(j, "glories", f->nglory, f->glory_b, f->glory_theta);
    qd_json_key(j, "orbiting");
    if (f->orbiting) {
        qd_json_begin_object(j);
        jnum(j, "b", f->orbit_b);
        jnum(j, "r", f->orbit_r);
        qd_json_end_object(j);
    } else {
        qd_json_null(j);
    }
    jnum(j, "capture_cross_section", f->capture ? PI * f->capture_b * f->capture_b : 0);
}

static void json_lab(scatter_run *r, qd_json *j) {
    qd_scatter_lab l;
    if (!r->masses_s || !(r->theta >= 0) ||
        qd_scatter_lab_map(r->ctx, r->m1, r->m2, r->theta, &l) != QD_OK)
        return;
    size_t ncm;
    jnum(j, "gamma", l.gamma);
    jnum(j, "lab_angle", l.theta_lab);
    jnum(j, "lab_energy_ratio", l.energy_ratio);
    jnum(j, "lab_cross_section", lab_section(r, l.theta_lab, &ncm));
    jnum(j, "recoil_angle", l.recoil_angle);
    jnum(j, "recoil_energy_ratio", l.recoil_ratio);
}

static void json_lab_angles(const scatter_run *r, qd_json *j) {
    double sum = 0;
    jnum(j, "gamma", r->m1 / r->m2);
    jnum(j, "lab_angle", r->lab_theta);
    qd_json_key(j, "cm_angles");
    qd_json_begin_array(j);
    for (size_t k = 0; k < r->ncm; k++) {
        qd_json_begin_object(j);
        jnum(j, "angle", r->cm[k]);
        jnum(j, "cross_section", r->cm_sigma[k]);
        jnum(j, "jacobian", r->cm_jacobian[k]);
        qd_json_end_object(j);
        sum += r->cm_sigma[k] * r->cm_jacobian[k];
    }
    qd_json_end_array(j);
    jnum(j, "lab_cross_section", sum);
}

static void write_json(scatter_run *r, qd_buf *b) {
    qd_json j;
    qd_json_init(&j, b);
    qd_json_begin_object(&j);
    qd_json_key(&j, "file");
    qd_json_string(&j, r->mf.path);
    qd_json_key(&j, "potential");
    qd_json_expr(&j, r->ctx, qd_scatter_potential(r->s));
    qd_json_key(&j, "radius");
    qd_json_string(&j, qd_expr_name(qd_scatter_radius(r->s)));
    jnum(&j, "energy", r->E);
    if (r->b_s) {
        jnum(&j, "b", r->b);
        qd_json_key(&j, "kind");
        qd_json_string(&j, qd_scatter_kind_name(r->path.kind));
        jnum(&j, "closest_approach", r->path.r0);
        jnum(&j, "deflection", r->path.theta);
        jnum(&j, "deflection_signed", r->path.chi);
    } else if (r->theta_s) {
        jnum(&j, "deflection", r->theta);
    }
    if (r->lab_s)
        json_lab_angles(r, &j);
    else
        json_section(r, &j);
    json_features(r, &j);
    json_lab(r, &j);
    qd_json_end_object(&j);
    qd_buf_puts(b, "\n");
    b->failed = b->failed || !qd_json_ok(&j);
}

/* ---- the command ------------------------------------------------------------------ */

static int run(scatter_run *r) {
    int rc = cli_load_derive(r->ctx, r->file, r->nsets, r->sets, true, NULL, &r->mf, &r->e);
    if (rc == QD_EXIT_OK)
        rc = read_numbers(r);
    if (rc == QD_EXIT_OK &&
        !(r->s = qd_scatter_from_model(r->ctx, r->mf.model, r->e, r->ignore, r->core, &r->mass)))
        rc = cli_diag_ctx(r->ctx);
    if (rc == QD_EXIT_OK)
        rc = compute(r);
    if (rc != QD_EXIT_OK)
        return rc;
    qd_buf b = QD_BUF_INIT;
    if (r->fmt == FMT_JSON)
        write_json(r, &b);
    else
        write_text(r, &b);
    return cli_emit(&b, "scattering");
}

int cli_cmd_scatter(int argc, char **argv) {
    scatter_run r = {.fmt = FMT_TEXT};
    int rc = parse_args(argc, argv, &r);
    if (rc != QD_EXIT_OK)
        return rc;
    if (!(r.ctx = qd_ctx_new())) {
        cli_diag_error("out of memory");
        return QD_EXIT_FAIL;
    }
    rc = run(&r);
    qd_scatter_free(r.s);
    qd_eom_free(r.e);
    cli_model_file_free(&r.mf);
    qd_ctx_free(r.ctx);
    return rc;
}

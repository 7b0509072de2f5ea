/*
 * cli/cmd_orbit.c - `qdot orbit FILE --ignore Q[,Q...]`: the motion left in
 * one coordinate by Routh's reduction: V_eff, the turning points and the
 * kind of orbit, the radial period and advances, the circular orbits and
 * Kepler's conic (qd_orbit_derive, qd_orbit_solve_text, qd_orbit_render;
 * qdot/orbit.h).
 */
#include "driver.h"

#include "opt_diag.h"
#include "qdot/orbit.h"

#define MAX_IGN 32

typedef struct orbit_args {
    qd_orbit_text t;
    const char *ignore, *format, *out;
    cli_list sets;
    bool equation;
} orbit_args;

#define A(field) offsetof(orbit_args, field)
static const cli_opt opts[] = {
    {"--ignore", NULL, CLI_TEXT, A(ignore), "Q[,Q...]",
     "the cyclic coordinates to ignore: all but one", NULL, NULL},
    {"--at", NULL, CLI_TEXT, A(t.at), "\"q=VALUE, q'=VALUE, ...\"",
     "the state (default: the model's initial values); values may use the parameters", NULL,
     NULL},
    {"--momentum", NULL, CLI_TEXT, A(t.momentum), "\"p_Q=VALUE, ...\"",
     "momenta of ignored coordinates instead of their values at the state", NULL, NULL},
    {"--energy", NULL, CLI_TEXT, A(t.energy), "E",
     "the energy instead of the state's (an expression in the parameters)", NULL, NULL},
    {"--orbit", NULL, CLI_FLAG, A(equation), NULL,
     "also the orbit equation: the conic, else the quadrature", NULL, NULL},
    CLI_OPT_SET(orbit_args, sets),
    CLI_OPT_FORMAT(orbit_args, format),
    CLI_OPT_OUT(orbit_args, out),
    {0},
};
#undef A

static const cli_spec spec = {
    "orbit", "FILE --ignore Q[,Q...] [options]",
    "the motion left in one coordinate when the cyclic ones are ignored", opts, NULL, 1, 1,
    "FILE", false};

typedef struct orbit_run {
    cli_run c;
    orbit_args a;
    qd_eom *e;
    qd_orbit *o;
    qd_orbit_result r;
} orbit_run;

static int run(cli_run *c) {
    orbit_run *r = (orbit_run *)c;
    const orbit_args *a = &r->a;
    const qd_expr *ign[MAX_IGN];
    size_t nign = 0;
    int rc = cli_load_derive(c->ctx, c->file, a->sets.n, a->sets.items, "orbit", NULL, &c->mf,
                             &r->e);
    if (rc == QD_EXIT_OK)
        rc = cli_ignore(c->ctx, &c->mf, r->e, a->ignore, ign, MAX_IGN, &nign);
    if (rc == QD_EXIT_OK && !(r->o = qd_orbit_derive(c->ctx, c->mf.model, r->e, nign, ign)))
        rc = cli_diag_ctx(c->ctx);
    if (rc != QD_EXIT_OK)
        return rc;
    qd_buf b = QD_BUF_INIT;
    qd_status st = qd_orbit_solve_text(c->ctx, r->o, c->mf.model, &a->t, &r->r);
    if (st == QD_OK)
        st = qd_orbit_render(c->ctx, r->o, &r->r, c->mf.path, a->equation,
                             cli_json(a->format), &b);
    rc = st == QD_OK ? cli_out_emit(&b, a->out) : cli_diag_opts(c->ctx, &spec, a);
    qd_buf_free(&b);
    return rc;
}

static int check(cli_run *c) {
    if (((orbit_run *)c)->a.ignore)
        return QD_EXIT_OK;
    return cli_usage_error("orbit needs --ignore with the cyclic coordinates to ignore (all but "
                           "one)");
}

static void run_free(cli_run *c) {
    orbit_run *r = (orbit_run *)c;
    qd_orbit_result_free(&r->r);
    qd_orbit_free(r->o);
    qd_eom_free(r->e);
}

CLI_COMMAND(orbit, orbit_run, &spec, offsetof(orbit_run, a), 0, check, run, run_free)

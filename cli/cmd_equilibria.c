/*
 * cli/cmd_equilibria.c - `qdot equilibria FILE`: the configurations of rest
 * (libqdot's qd_equilibria_find), exact where the equations come apart one
 * unknown at a time, else by Newton from --near or a multi-start search over
 * --box; each classified by the Hessian of the potential.  The loading code
 * shared with `qdot modes` is in linear_cli.c.
 */
#include "linear_cli.h"

#include <stddef.h>
#include <string.h>
#include "qdot/json.h"
#include "model_cli.h"

/* ---- the command ------------------------------------------------------------ */

typedef struct eq_args {
    const char *near, *box, *format;
    cli_list sets;
} eq_args;

static const char *const formats[] = {"text", "json", NULL};

static const cli_opt opts[] = {
    {"--near", NULL, CLI_TEXT, offsetof(eq_args, near), "\"q1=VALUE, ...\"",
     "Newton from this point (only the equilibrium reached)", NULL, NULL},
    {"--box", NULL, CLI_TEXT, offsetof(eq_args, box), "\"q1=LOW:HIGH, ...\"",
     "search this box (default: [-pi, pi] for an angle, else [-10, 10])", NULL, NULL},
    {"--set", NULL, CLI_LIST, offsetof(eq_args, sets), "NAME=VALUE", "a parameter's value", NULL,
     NULL},
    {"--format", NULL, CLI_CHOICE, offsetof(eq_args, format), "NAME", "text or json", formats,
     NULL},
    {0},
};

static const cli_spec spec = {
    "equilibria", "FILE [--near \"q1=VALUE, ...\"] [--box \"q1=LOW:HIGH, ...\"] [options]",
    "the configurations of rest and their kind (the Hessian of the potential)", opts, NULL, 1, 1,
    "FILE", false};

enum { MAX_FAMILY_SHOWN = 10 };

static void put_text(cli_lin_run *r, const qd_equilibria *eq, qd_buf *b) {
    const qd_eom *e = r->e;
    qd_buf_printf(b, "%zu equilibri%s (%s%s)\n", eq->count, eq->count == 1 ? "um" : "a",
                  eq->method, eq->exact ? ": the complete set, angles in (-pi, pi]" : "");
    /* a family of equilibria is sampled, not enumerated: a few samples say it */
    size_t shown = eq->continuum && eq->count > MAX_FAMILY_SHOWN ? MAX_FAMILY_SHOWN : eq->count;
    for (size_t i = 0; i < shown; i++) {
        const qd_equilibrium *p = &eq->pts[i];
        qd_buf_printf(b, "%3zu  ", i + 1);
        for (size_t j = 0; j < e->n; j++) {
            qd_buf_printf(b, "%s%s = ", j ? ", " : "", qd_expr_name(e->q[j]));
            qd_equilibrium_put_value(r->ctx, p, j, b);
            if (p->exact && !qd_is_number(p->exact[j])) {
                qd_buf_puts(b, " (");
                cli_state_put_result(b, p->q[j]);
                qd_buf_puts(b, ")");
            }
        }
        qd_buf_printf(b, "\n     %s of the potential (Hessian: %zu positive, %zu negative, %zu "
                         "zero)%s, residual ",
                      qd_eq_kind_name(p->kind), p->npos, p->nneg, p->nzero,
                      p->symmetric ? "" : "; the forces are not from a potential: K is not "
                                          "symmetric, its symmetric part is classified");
        /* below 1e-14 the figure is round-off, different from build to build */
        if (p->residual < 1e-14)
            qd_buf_puts(b, "< 1e-14\n");
        else
            qd_buf_printf(b, "%.3g\n", p->residual);
    }
    if (shown < eq->count)
        qd_buf_printf(b, "  ... and %zu more samples (--format json lists them all)\n",
                      eq->count - shown);
    if (eq->continuum)
        qd_buf_puts(b, "note: the equilibria are not isolated (a family: a rigid motion or a "
                       "neutral direction); the points listed are samples of it\n");
}

static void put_json(cli_lin_run *r, const qd_equilibria *eq, qd_buf *b) {
    const qd_eom *e = r->e;
    qd_json j;
    qd_json_init(&j, b);
    qd_json_begin_object(&j);
    qd_json_key(&j, "method");
    qd_json_string(&j, eq->method);
    qd_json_key(&j, "exact");
    qd_json_bool(&j, eq->exact);
    qd_json_key(&j, "continuum");
    qd_json_bool(&j, eq->continuum);
    qd_json_key(&j, "equilibria");
    qd_json_begin_array(&j);
    for (size_t i = 0; i < eq->count; i++) {
        const qd_equilibrium *p = &eq->pts[i];
        qd_json_begin_object(&j);
        qd_json_key(&j, "equilibrium");
        qd_json_begin_object(&j);
        for (size_t k = 0; k < e->n; k++) {
            qd_json_key(&j, qd_expr_name(e->q[k]));
            qd_json_number(&j, p->q[k]);
        }
        qd_json_end_object(&j);
        if (p->exact) {
            qd_json_key(&j, "exact");
            qd_json_begin_object(&j);
            for (size_t k = 0; k < e->n; k++) {
                qd_json_key(&j, qd_expr_name(e->q[k]));
                qd_json_expr(&j, r->ctx, p->exact[k]);
            }
            qd_json_end_object(&j);
        }
        qd_json_key(&j, "kind");
        qd_json_string(&j, qd_eq_kind_name(p->kind));
        qd_json_key(&j, "hessian_signs");
        qd_json_begin_array(&j);
        qd_json_number(&j, (double)p->npos);
        qd_json_number(&j, (double)p->nneg);
        qd_json_number(&j, (double)p->nzero);
        qd_json_end_array(&j);
        qd_json_key(&j, "symmetric");
        qd_json_bool(&j, p->symmetric);
        qd_json_key(&j, "residual");
        qd_json_number(&j, p->residual);
        qd_json_end_object(&j);
    }
    qd_json_end_array(&j);
    qd_json_end_object(&j);
    qd_buf_puts(b, "\n");
    b->failed = b->failed || !qd_json_ok(&j);
}

int cli_cmd_equilibria(int argc, char **argv) {
    eq_args a = {0};
    const char *file = NULL;
    int rc = cli_parse(&spec, argc, argv, &a, &file);
    if (rc != QD_EXIT_OK)
        return rc;
    bool json = a.format && !strcmp(a.format, "json");
    cli_lin_run r = {.ctx = qd_ctx_new()};
    if (!r.ctx) {
        cli_diag_error("out of memory");
        return QD_EXIT_FAIL;
    }
    qd_equilibria eq = {0};
    rc = cli_lin_load_model(&r, file, a.sets.items, a.sets.n);
    bool speeds = rc == QD_EXIT_OK && qd_model_nspeeds(r.mf.model) > 0;
    if (speeds)
        rc = cli_speeds_equilibria(r.ctx, &r.mf, json, a.near ? "--near" : a.box ? "--box"
                                                                                  : NULL);
    else if (rc == QD_EXIT_OK)
        rc = cli_lin_derive(&r);
    if (rc == QD_EXIT_OK && !speeds)
        rc = cli_lin_equilibria(&r, a.near, a.box, &eq);
    if (rc == QD_EXIT_OK && !speeds) {
        qd_buf b = QD_BUF_INIT;
        (json ? put_json : put_text)(&r, &eq, &b);
        rc = cli_emit(&b, "equilibria");
    }
    qd_equilibria_free(&eq);
    cli_lin_free(&r);
    qd_ctx_free(r.ctx);
    return rc;
}

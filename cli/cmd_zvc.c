/*
 * cli/cmd_zvc.c - `qdot zvc FILE --box "x=A:B, y=C:D" (--level H | --through
 * POINT | --at STATE)`: Jacobi's integral h = T2 - T0 + V and the
 * zero-velocity curves W = h, W = V - T0 the integral at rest (qdot/zvc.h).
 * Text gives h, W, the level, the value of W at each equilibrium in the box
 * (for the restricted three-body problem: the Jacobi constants of L1..L5)
 * and a line per curve; csv the curves' points; json everything.
 */
#include "linear_cli.h"

#include <stdlib.h>
#include <string.h>
#include "qdot/zvc.h"

typedef struct zvc_args {
    const char *box, *level, *through, *at, *format;
    size_t cells;
    cli_list set;
} zvc_args;

typedef struct zvc_run {
    cli_lin_run lr; /* first: the run state starts with its cli_run */
    zvc_args a;
    qd_zvc z;
    qd_zvc_box box;
    double level;
    double *q;               /* e->n: the other coordinates' values */
    qd_zvc_picture pic;
} zvc_run;

static const char *const formats[] = {"text", "csv", "json", NULL};

static const cli_opt opts[] = {
    {"--box", NULL, CLI_TEXT, offsetof(zvc_args, box), "\"x=A:B, y=C:D\"",
     "the plane: two coordinates (across, up) and their ranges (required)", NULL, NULL},
    {"--level", NULL, CLI_TEXT, offsetof(zvc_args, level), "H",
     "the level h (an expression in the parameters)", NULL, NULL},
    {"--through", NULL, CLI_TEXT, offsetof(zvc_args, through), "\"x=..., y=...\"",
     "the level of W at this point at rest", NULL, NULL},
    {"--at", NULL, CLI_TEXT, offsetof(zvc_args, at), "\"x=..., x'=..., ...\"",
     "the level of h at this state", NULL, NULL},
    {"--cells", NULL, CLI_COUNT, offsetof(zvc_args, cells), "N",
     "grid cells each way, 2 to 4000 (default 400)", NULL, NULL},
    {"--format", NULL, CLI_CHOICE, offsetof(zvc_args, format), "FORMAT",
     "how to write it (csv: the curves' points)", formats, NULL},
    CLI_OPT_SET(zvc_args, set),
    {0},
};

static const cli_spec spec = {
    "zvc", "FILE --box \"x=A:B, y=C:D\" (--level H | --through POINT | --at STATE) [options]",
    "Jacobi's integral and the zero-velocity curves W = h over a box.",
    opts, NULL, 1, 1, "FILE", false,
};

/* ---- the level --------------------------------------------------------------------- */

/* The level (qd_zvc_level_read): --level, --through or --at; an error in
 * one shown under its text. */
static int read_level(zvc_run *r, const zvc_args *a) {
    qd_ctx *ctx = r->lr.c.ctx;
    const char *where = NULL;
    if (qd_zvc_level_read(ctx, &r->lr.pt, &r->z, a->level, a->through, a->at, r->q, &r->level,
                          &where) == QD_OK)
        return QD_EXIT_OK;
    if (!where && qd_ctx_status(ctx) == QD_ERR_ARG)
        return cli_usage_error("give the level once: --level H, --through POINT or --at STATE");
    if (!where)
        return cli_diag_ctx(ctx);
    const char *opt = where == a->level ? "--level" : where == a->through ? "--through" : "--at";
    if (!qd_ctx_diag(ctx)->located)
        return cli_usage_error("%s: %s", opt, qd_ctx_message(ctx));
    cli_diag_show(opt, where, qd_ctx_diag(ctx));
    return cli_exit(qd_ctx_status(ctx));
}

static int picture(zvc_run *r, const zvc_args *a) {
    cli_lin_run *lr = &r->lr;
    bool csv = a->format && !strcmp(a->format, "csv");
    if (lr->e->n < 2) {
        cli_diag_error("zero-velocity curves need two coordinates; the model has %zu", lr->e->n);
        return QD_EXIT_USAGE;
    }
    r->q = calloc(lr->e->n + 1, sizeof *r->q);
    if (!r->q)
        return QD_EXIT_FAIL;
    if (qd_zvc_box_read(lr->c.ctx, lr->c.mf.model, lr->e, a->box, &r->box) != QD_OK) {
        cli_diag_show("--box", a->box, qd_ctx_diag(lr->c.ctx));
        return cli_exit(qd_ctx_status(lr->c.ctx));
    }
    if (qd_zvc_derive(lr->c.ctx, lr->c.mf.model, lr->e, &r->z) != QD_OK)
        return cli_diag_ctx(lr->c.ctx);
    int rc = read_level(r, a);
    if (rc != QD_EXIT_OK)
        return rc;
    r->box.nx = r->box.ny = a->cells ? a->cells : 400;
    /* csv holds the curves only: no equilibria sought */
    if (qd_zvc_picture_make(lr->c.ctx, lr->c.mf.model, lr->e, &r->z, &r->box, lr->pt.st.n,
                            lr->pt.st.syms, lr->pt.st.vals, r->level, !csv,
                            &r->pic) != QD_OK)
        return cli_diag_ctx(lr->c.ctx);
    return QD_EXIT_OK;
}

static int check(cli_run *c) {
    const zvc_args *a = &((zvc_run *)c)->a;
    if (a->box && (!a->cells || (a->cells >= 2 && a->cells <= 4000)))
        return QD_EXIT_OK;
    return cli_usage_error(!a->box ? "give the plane of the curves with --box \"x=A:B, y=C:D\""
                                   : "--cells takes a number of grid cells from 2 to 4000");
}

static int run(cli_run *c) {
    zvc_run *r = (zvc_run *)c;
    int rc = cli_lin_load(&r->lr, c->file, r->a.set.items, r->a.set.n);
    if (rc == QD_EXIT_OK)
        rc = picture(r, &r->a);
    if (rc != QD_EXIT_OK)
        return rc;
    qd_buf b = QD_BUF_INIT;
    const char *f = r->a.format ? r->a.format : "text";
    qd_status st = (!strcmp(f, "csv")    ? qd_zvc_csv
                    : !strcmp(f, "json") ? qd_zvc_json
                                         : qd_zvc_print)(c->ctx, r->lr.e, &r->pic, &b);
    return cli_emit_status(c->ctx, st, &b, "zero-velocity curves");
}

static void run_free(cli_run *c) {
    zvc_run *r = (zvc_run *)c;
    free(r->q);
    qd_zvc_picture_free(&r->pic);
    cli_lin_free(&r->lr);
}

CLI_COMMAND(zvc, zvc_run, &spec, offsetof(zvc_run, a), 0, check, run, run_free)

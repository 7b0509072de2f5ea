/*
 * cli/cmd_zvc.c - `qdot zvc FILE --box "x=A:B, y=C:D" (--level H | --through
 * POINT | --at STATE)`: Jacobi's integral h = T2 - T0 + V and the
 * zero-velocity curves W = h, W = V - T0 the integral at rest (qdot/zvc.h).
 * Text gives h, W, the level, the value of W at each equilibrium in the box
 * (for the restricted three-body problem: the Jacobi constants of L1..L5)
 * and a line per curve; csv the curves' points; json everything.
 */
#include "linear_cli.h"

#include <ctype.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "model_cli.h"
#include "qdot/zvc.h"

typedef struct zvc_args {
    const char *file, *box, *level, *through, *at;
    long n;
    const char *sets[QD_LIN_MAX_SETS];
    size_t nsets;
    int format;   /* 0 text, 1 csv, 2 json */
} zvc_args;

typedef struct zvc_run {
    cli_lin_run lr;
    qd_zvc z;
    qd_zvc_box box;
    double level;
    double *q;               /* e->n: the other coordinates' values */
    qd_zvc_picture pic;
} zvc_run;

static const char usage_text[] =
    "usage: qdot zvc FILE --box \"x=A:B, y=C:D\" (--level H | --through \"x=..., y=...\" | "
    "--at \"x=..., y=..., x'=..., y'=...\") [--n CELLS] [--set NAME=VALUE]... "
    "[--format text|csv|json]";

static const char *const formats[] = {"text", "csv", "json", NULL};

static int parse_option(int argc, char **argv, int *i, void *data) {
    zvc_args *a = data;
    const char *v;
    if ((v = cli_value(argc, argv, i, "--format")))
        return cli_choice("--format", v, formats, &a->format);
    if ((v = cli_value(argc, argv, i, "--box")))
        return cli_once("--box", &a->box, v);
    if ((v = cli_value(argc, argv, i, "--level")))
        return cli_once("--level", &a->level, v);
    if ((v = cli_value(argc, argv, i, "--through")))
        return cli_once("--through", &a->through, v);
    if ((v = cli_value(argc, argv, i, "--at")))
        return cli_once("--at", &a->at, v);
    if ((v = cli_value(argc, argv, i, "--set")))
        return cli_push("--set", a->sets, &a->nsets, QD_LIN_MAX_SETS, v);
    if ((v = cli_value(argc, argv, i, "--n"))) {
        char *end;
        a->n = strtol(v, &end, 10);
        if (*end || a->n < 2 || a->n > 4000) {
            cli_diag_error("--n takes a number of grid cells from 2 to 4000, not '%s'", v);
            return QD_EXIT_USAGE;
        }
        return QD_EXIT_OK;
    }
    return cli_bad_option(argv[*i], usage_text);
}

/* ---- the box --------------------------------------------------------------------- */

/* One NAME=A:B item: the coordinate's index (k-th of the box) and range. */
static int box_item(zvc_run *r, const char *item, size_t k) {
    const char *eq = strchr(item, '='), *colon = eq ? strchr(eq, ':') : NULL;
    char name[128], lo[256];
    size_t s = 0, e = eq ? (size_t)(eq - item) : 0, la = colon ? (size_t)(colon - eq - 1) : 0;
    while (s < e && isspace((unsigned char)item[s]))
        s++;
    while (e > s && isspace((unsigned char)item[e - 1]))
        e--;
    if (!colon || e == s || e - s >= sizeof name || la >= sizeof lo) {
        cli_diag_error("--box takes two NAME=A:B items, not '%s'", item);
        return QD_EXIT_USAGE;
    }
    memcpy(name, item + s, e - s);
    name[e - s] = '\0';
    memcpy(lo, eq + 1, la);
    lo[la] = '\0';
    const qd_eom *q = r->lr.e;
    size_t j = 0;
    while (j < q->n && strcmp(qd_expr_name(q->q[j]), name))
        j++;
    if (j == q->n) {
        cli_diag_error("--box: '%s' is not an independent coordinate", name);
        return QD_EXIT_USAGE;
    }
    const qd_expr *x;
    int rc = cli_state_number(r->lr.ctx, "--box", lo, &x, &r->box.lo[k]);
    if (rc == QD_EXIT_OK)
        rc = cli_state_number(r->lr.ctx, "--box", colon + 1, &x, &r->box.hi[k]);
    if (rc == QD_EXIT_OK && !(r->box.lo[k] < r->box.hi[k])) {
        cli_diag_error("--box: the range of %s is empty", name);
        rc = QD_EXIT_USAGE;
    }
    *(k ? &r->box.iy : &r->box.ix) = j;
    return rc;
}

static int read_box(zvc_run *r, const char *text) {
    const char *comma = strchr(text, ',');
    if (!comma || strchr(comma + 1, ',')) {
        cli_diag_error("--box takes two items, \"x=A:B, y=C:D\", not '%s'", text);
        return QD_EXIT_USAGE;
    }
    char *first = malloc((size_t)(comma - text) + 1);
    if (!first)
        return QD_EXIT_FAIL;
    memcpy(first, text, (size_t)(comma - text));
    first[comma - text] = '\0';
    int rc = box_item(r, first, 0);
    free(first);
    if (rc == QD_EXIT_OK)
        rc = box_item(r, comma + 1, 1);
    if (rc == QD_EXIT_OK && r->box.ix == r->box.iy) {
        cli_diag_error("--box names %s twice: give two coordinates",
                      qd_expr_name(r->lr.e->q[r->box.ix]));
        rc = QD_EXIT_USAGE;
    }
    return rc;
}

/* ---- the level --------------------------------------------------------------------- */

/* h (or W, at rest) at the point or state given. */
static int level_at(zvc_run *r, const char *what, const char *text, bool rest) {
    cli_lin_run *lr = &r->lr;
    size_t n = lr->e->n;
    double *qd = calloc(n + 1, sizeof *qd);
    if (!qd)
        return QD_EXIT_FAIL;
    int rc = cli_lin_point(lr, what, text, r->q, rest ? NULL : qd);
    if (rc == QD_EXIT_OK) {
        cli_lin_set_state(lr, r->q, qd);
        if (qd_eval(lr->ctx, rest ? r->z.W : r->z.h, lr->st.n, lr->st.syms, lr->st.vals,
                    &r->level) != QD_OK || !isfinite(r->level)) {
            qd_ctx_clear_error(lr->ctx);
            cli_diag_error("%s: Jacobi's integral has no finite value there", what);
            rc = QD_EXIT_USAGE;
        }
    }
    free(qd);
    return rc;
}

static int read_level(zvc_run *r, const zvc_args *a) {
    int given = !!a->level + !!a->through + !!a->at;
    if (given != 1) {
        cli_diag_error("give the level once: --level H, --through POINT or --at STATE\n%s",
                      usage_text);
        return QD_EXIT_USAGE;
    }
    if (a->through)
        return level_at(r, "--through", a->through, true);
    if (a->at)
        return level_at(r, "--at", a->at, false);
    const qd_expr *x;
    return cli_state_number(r->lr.ctx, "--level", a->level, &x, &r->level);
}

static int run(zvc_run *r, const zvc_args *a) {
    cli_lin_run *lr = &r->lr;
    if (lr->e->n < 2) {
        cli_diag_error("zero-velocity curves need two coordinates; the model has %zu", lr->e->n);
        return QD_EXIT_USAGE;
    }
    r->q = calloc(lr->e->n + 1, sizeof *r->q);
    if (!r->q)
        return QD_EXIT_FAIL;
    int rc = read_box(r, a->box);
    if (rc != QD_EXIT_OK)
        return rc;
    if (qd_zvc_derive(lr->ctx, lr->mf.model, lr->e, &r->z) != QD_OK) {
        cli_diag_error("%s", qd_ctx_message(lr->ctx));
        return qd_ctx_status(lr->ctx) == QD_ERR_ARG ? QD_EXIT_USAGE : QD_EXIT_FAIL;
    }
    if ((rc = read_level(r, a)) != QD_EXIT_OK)
        return rc;
    cli_lin_set_state(lr, r->q, NULL);
    r->box.nx = r->box.ny = a->n ? (size_t)a->n : 400;
    /* csv holds the curves only: no equilibria sought */
    if (qd_zvc_picture_make(lr->ctx, lr->mf.model, lr->e, &r->z, &r->box, lr->st.n,
                            lr->st.syms, lr->st.vals, r->level, a->format != 1,
                            &r->pic) != QD_OK)
        return cli_diag_ctx(lr->ctx);
    return QD_EXIT_OK;
}

int cli_cmd_zvc(int argc, char **argv) {
    zvc_args a = {0};
    int rc = cli_file_args(argc, argv, "zvc", usage_text, &a.file, parse_option, &a);
    if (rc != QD_EXIT_OK)
        return rc;
    if (!a.box) {
        cli_diag_error("give the plane of the curves with --box \"x=A:B, y=C:D\"\n%s", usage_text);
        return QD_EXIT_USAGE;
    }
    zvc_run r = {.lr = {.ctx = qd_ctx_new()}};
    if (!r.lr.ctx) {
        cli_diag_error("out of memory");
        return QD_EXIT_FAIL;
    }
    rc = cli_lin_load(&r.lr, a.file, a.sets, a.nsets);
    if (rc == QD_EXIT_OK)
        rc = run(&r, &a);
    if (rc == QD_EXIT_OK) {
        qd_buf b = QD_BUF_INIT;
        qd_status st = (a.format == 0 ? qd_zvc_print : a.format == 1 ? qd_zvc_csv
                                                                      : qd_zvc_json)(
            r.lr.ctx, r.lr.e, &r.pic, &b);
        rc = st == QD_OK ? cli_emit(&b, "zero-velocity curves") : cli_diag_ctx(r.lr.ctx);
        if (st != QD_OK)
            qd_buf_free(&b);
    }
    free(r.q);
    qd_zvc_picture_free(&r.pic);
    cli_lin_free(&r.lr);
    qd_ctx_free(r.lr.ctx);
    return rc;
}

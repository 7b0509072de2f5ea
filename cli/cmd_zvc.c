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
#include "qdot/json.h"
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
    qd_equilibria eq;        /* in the box */
    qd_contour c;
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

/* ---- the work -------------------------------------------------------------------------- */

/* The equilibria in the box (the other coordinates in their default box). */
static int equilibria(zvc_run *r) {
    cli_lin_run *lr = &r->lr;
    size_t n = lr->e->n;
    double *lo = malloc((n + 1) * sizeof *lo), *hi = malloc((n + 1) * sizeof *hi);
    bool *angle = malloc((n + 1) * sizeof *angle);
    int rc = lo && hi && angle ? QD_EXIT_OK : QD_EXIT_FAIL;
    if (rc == QD_EXIT_OK &&
        qd_equilibria_default_box(lr->ctx, lr->e, lr->mf.model, angle, lo, hi) != QD_OK)
        rc = cli_diag_ctx(lr->ctx);
    if (rc == QD_EXIT_OK) {
        lo[r->box.ix] = r->box.lo[0];
        hi[r->box.ix] = r->box.hi[0];
        lo[r->box.iy] = r->box.lo[1];
        hi[r->box.iy] = r->box.hi[1];
        qd_equilibria_opts o = {.lo = lo, .hi = hi, .numeric_only = true};
        if (qd_equilibria_find(lr->ctx, lr->e, lr->mf.model, lr->st.n, lr->st.syms, lr->st.vals,
                               &o, &r->eq) != QD_OK)
            rc = cli_diag_ctx(lr->ctx);
    }
    free(lo);
    free(hi);
    free(angle);
    return rc;
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
    if (qd_zvc_curves(lr->ctx, lr->e, &r->z, &r->box, lr->st.n, lr->st.syms, lr->st.vals,
                      r->level, &r->c) != QD_OK)
        return cli_diag_ctx(lr->ctx);
    return a->format == 1 ? QD_EXIT_OK : equilibria(r);
}

/* ---- output ------------------------------------------------------------------------------ */

/* W at equilibrium k (the other coordinates as they are in the state). */
static double W_at(zvc_run *r, const double *q) {
    cli_lin_run *lr = &r->lr;
    double w = NAN;
    cli_lin_set_state(lr, q, NULL);
    if (qd_eval(lr->ctx, r->z.W, lr->st.n, lr->st.syms, lr->st.vals, &w) != QD_OK)
        qd_ctx_clear_error(lr->ctx);
    return w;
}

static void put_point(zvc_run *r, const double *q, qd_buf *b) {
    for (size_t j = 0; j < r->lr.e->n; j++) {
        qd_buf_printf(b, "%s%s = ", j ? ", " : "", qd_expr_name(r->lr.e->q[j]));
        cli_state_put_result(b, q[j]);
    }
}

static void put_text(zvc_run *r, qd_buf *b) {
    qd_ctx *ctx = r->lr.ctx;
    const char *x = qd_expr_name(r->lr.e->q[r->box.ix]), *y = qd_expr_name(r->lr.e->q[r->box.iy]);
    qd_buf_puts(b, "Jacobi's integral: h = ");
    qd_print(ctx, r->z.h, QD_FMT_TEXT, b);
    qd_buf_puts(b, "\nat rest: W = ");
    qd_print(ctx, r->z.W, QD_FMT_TEXT, b);
    qd_buf_puts(b, "\nlevel: h = ");
    cli_state_put_result(b, r->level);
    qd_buf_puts(b, " (zero-velocity curves W = h; the motion stays where W <= h)\n");
    qd_buf_printf(b, "equilibria in the box (h at rest there):\n");
    for (size_t k = 0; k < r->eq.count; k++) {
        qd_buf_puts(b, "  ");
        put_point(r, r->eq.pts[k].q, b);
        qd_buf_printf(b, " (%s): h = ", qd_eq_kind_name(r->eq.pts[k].kind));
        cli_state_put_result(b, W_at(r, r->eq.pts[k].q));
        qd_buf_puts(b, "\n");
    }
    qd_buf_printf(b, "%zu curve%s on a %zu x %zu grid:\n", r->c.count, r->c.count == 1 ? "" : "s",
                  r->box.nx, r->box.ny);
    for (size_t k = 0; k < r->c.count; k++) {
        const qd_polyline *p = &r->c.lines[k];
        double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
        for (size_t i = 0; i < p->count; i++) {
            x0 = fmin(x0, p->x[i]);
            x1 = fmax(x1, p->x[i]);
            y0 = fmin(y0, p->y[i]);
            y1 = fmax(y1, p->y[i]);
        }
        qd_buf_printf(b, "  curve %zu: %s, %zu points, %s in [%.4g, %.4g], %s in [%.4g, %.4g]\n",
                      k + 1, p->closed ? "closed" : "open", p->count, x, x0, x1, y, y0, y1);
    }
}

static void put_csv(zvc_run *r, qd_buf *b) {
    qd_buf_printf(b, "curve,%s,%s\n", qd_expr_name(r->lr.e->q[r->box.ix]),
                  qd_expr_name(r->lr.e->q[r->box.iy]));
    for (size_t k = 0; k < r->c.count; k++)
        for (size_t i = 0; i < r->c.lines[k].count; i++) {
            qd_buf_printf(b, "%zu,", k + 1);
            cli_state_put_double(b, r->c.lines[k].x[i]);
            qd_buf_puts(b, ",");
            cli_state_put_double(b, r->c.lines[k].y[i]);
            qd_buf_puts(b, "\n");
        }
}

static void json_equilibria(zvc_run *r, qd_json *j) {
    qd_json_key(j, "equilibria");
    qd_json_begin_array(j);
    for (size_t k = 0; k < r->eq.count; k++) {
        qd_json_begin_object(j);
        for (size_t i = 0; i < r->lr.e->n; i++) {
            qd_json_key(j, qd_expr_name(r->lr.e->q[i]));
            qd_json_number(j, r->eq.pts[k].q[i]);
        }
        qd_json_key(j, "kind");
        qd_json_string(j, qd_eq_kind_name(r->eq.pts[k].kind));
        qd_json_key(j, "h");
        qd_json_number(j, W_at(r, r->eq.pts[k].q));
        qd_json_end_object(j);
    }
    qd_json_end_array(j);
}

static void json_curves(zvc_run *r, qd_json *j) {
    qd_json_key(j, "curves");
    qd_json_begin_array(j);
    for (size_t k = 0; k < r->c.count; k++) {
        const qd_polyline *p = &r->c.lines[k];
        qd_json_begin_object(j);
        qd_json_key(j, "closed");
        qd_json_bool(j, p->closed);
        for (int axis = 0; axis < 2; axis++) {
            qd_json_key(j, qd_expr_name(r->lr.e->q[axis ? r->box.iy : r->box.ix]));
            qd_json_begin_array(j);
            for (size_t i = 0; i < p->count; i++)
                qd_json_number(j, axis ? p->y[i] : p->x[i]);
            qd_json_end_array(j);
        }
        qd_json_end_object(j);
    }
    qd_json_end_array(j);
}

static void put_json(zvc_run *r, qd_buf *b) {
    qd_json j;
    qd_json_init(&j, b);
    qd_json_begin_object(&j);
    qd_json_key(&j, "h");
    qd_json_expr(&j, r->lr.ctx, r->z.h);
    qd_json_key(&j, "W");
    qd_json_expr(&j, r->lr.ctx, r->z.W);
    qd_json_key(&j, "level");
    qd_json_number(&j, r->level);
    qd_json_key(&j, "grid");
    qd_json_begin_array(&j);
    qd_json_number(&j, (double)r->box.nx);
    qd_json_number(&j, (double)r->box.ny);
    qd_json_end_array(&j);
    json_equilibria(r, &j);
    json_curves(r, &j);
    qd_json_end_object(&j);
    qd_buf_puts(b, "\n");
    b->failed = b->failed || !qd_json_ok(&j);
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
        (a.format == 0 ? put_text : a.format == 1 ? put_csv : put_json)(&r, &b);
        rc = cli_emit(&b, "zero-velocity curves");
    }
    free(r.q);
    qd_contour_free(&r.c);
    qd_equilibria_free(&r.eq);
    cli_lin_free(&r.lr);
    qd_ctx_free(r.lr.ctx);
    return rc;
}

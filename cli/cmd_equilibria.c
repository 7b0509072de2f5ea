/*
 * cli/cmd_equilibria.c - `qdot equilibria FILE`: the configurations of rest
 * (libqdot's qd_equilibria_find), exact where the equations come apart one
 * unknown at a time, else by Newton from --near or a multi-start search over
 * --box; each classified by the Hessian of the potential.  The loading code
 * shared with `qdot modes` is here too (linear_cli.h).
 */
#include "linear_cli.h"

#include <ctype.h>
#include <stdlib.h>
#include <string.h>
#include "eom_out.h"
#include "json.h"

int qd_lin_load(qd_lin_run *r, const char *file, const char *const *sets, size_t nsets) {
    int rc = qd_model_file_load(r->ctx, file, &r->mf);
    for (size_t i = 0; rc == QD_EXIT_OK && i < nsets; i++) {
        const qd_expr *p, *v;
        rc = qd_state_set(r->ctx, r->mf.model, sets[i], &p, &v);
    }
    if (rc != QD_EXIT_OK)
        return rc;
    qd_eom_opts opts = {.eliminate = true};
    r->e = qd_eom_derive_opts(r->ctx, r->mf.model, &opts);
    if (!r->e)
        return qd_eom_derive_error(r->ctx, &r->mf);
    if (r->e->ncon) {
        qd_diag_error("the model keeps %zu constraint%s with multipliers after elimination: "
                      "equilibria and modes need independent coordinates", r->e->ncon,
                      r->e->ncon == 1 ? "" : "s");
        return QD_EXIT_USAGE;
    }
    return qd_state_init(r->ctx, r->mf.model, &r->st);
}

void qd_lin_free(qd_lin_run *r) {
    qd_state_free(&r->st);
    if (r->e)
        qd_eom_free(r->e);
    qd_model_file_free(&r->mf);
}

int qd_lin_coords(qd_lin_run *r, const char *what, const char *text, double *q) {
    qd_state s;
    int rc = qd_state_init(r->ctx, r->mf.model, &s);
    if (rc == QD_EXIT_OK)
        rc = qd_state_parse(r->ctx, r->mf.model, text, &s);
    size_t nq = qd_model_ncoords(r->mf.model);
    for (size_t i = 0; rc == QD_EXIT_OK && i < nq; i++) {
        if (s.vals[nq + i] != 0) {
            qd_diag_error("%s: give coordinates only (a point at rest)", what);
            rc = QD_EXIT_USAGE;
        }
        q[i] = s.vals[i];
    }
    qd_state_free(&s);
    return rc;
}

static size_t item_end(const char *t, size_t i) {
    int depth = 0;
    for (; t[i]; i++) {
        if (t[i] == '(')
            depth++;
        else if (t[i] == ')' && depth)
            depth--;
        else if (t[i] == ',' && !depth)
            break;
    }
    return i;
}

static int box_item(qd_lin_run *r, const char *item, double *lo, double *hi) {
    const char *eq = strchr(item, '='), *dots = eq ? strstr(eq, "..") : NULL;
    if (!eq || !dots) {
        qd_diag_error("--box takes NAME=LOW..HIGH items, not '%s'", item);
        return QD_EXIT_USAGE;
    }
    char name[128], a[256], b[256];
    size_t nl = (size_t)(eq - item);
    while (nl && isspace((unsigned char)item[nl - 1]))
        nl--;
    size_t s = 0;
    while (s < nl && isspace((unsigned char)item[s]))
        s++;
    if (nl - s >= sizeof name || (size_t)(dots - eq - 1) >= sizeof a || strlen(dots + 2) >= sizeof b) {
        qd_diag_error("--box: item too long: '%s'", item);
        return QD_EXIT_USAGE;
    }
    memcpy(name, item + s, nl - s);
    name[nl - s] = '\0';
    memcpy(a, eq + 1, (size_t)(dots - eq - 1));
    a[dots - eq - 1] = '\0';
    strcpy(b, dots + 2);
    size_t nq = qd_model_ncoords(r->mf.model), j = 0;
    while (j < nq && strcmp(qd_expr_name(qd_model_coord(r->mf.model, j)), name))
        j++;
    if (j == nq) {
        qd_diag_error("--box: '%s' is not a coordinate", name);
        return QD_EXIT_USAGE;
    }
    const qd_expr *x;
    int rc = qd_state_number(r->ctx, "--box", a, &x, &lo[j]);
    if (rc == QD_EXIT_OK)
        rc = qd_state_number(r->ctx, "--box", b, &x, &hi[j]);
    if (rc == QD_EXIT_OK && !(lo[j] < hi[j])) {
        qd_diag_error("--box: the range of %s is empty", name);
        rc = QD_EXIT_USAGE;
    }
    return rc;
}

int qd_lin_box(qd_lin_run *r, const char *text, double *lo, double *hi) {
    char item[512];
    for (size_t i = 0; text[i];) {
        size_t end = item_end(text, i);
        if (end - i >= sizeof item) {
            qd_diag_error("--box: item too long");
            return QD_EXIT_USAGE;
        }
        memcpy(item, text + i, end - i);
        item[end - i] = '\0';
        if (strspn(item, " \t") < strlen(item)) {
            int rc = box_item(r, item, lo, hi);
            if (rc != QD_EXIT_OK)
                return rc;
        }
        i = text[end] ? end + 1 : end;
    }
    return QD_EXIT_OK;
}

int qd_lin_equilibria(qd_lin_run *r, const char *near, const char *box, qd_equilibria *out) {
    size_t n = r->e->n;
    double *q = malloc((n + 1) * sizeof *q), *lo = malloc((n + 1) * sizeof *lo);
    double *hi = malloc((n + 1) * sizeof *hi);
    bool *angle = malloc((n + 1) * sizeof *angle);
    int rc = q && lo && hi && angle ? QD_EXIT_OK : QD_EXIT_FAIL;
    qd_equilibria_opts o = {0};
    if (rc == QD_EXIT_OK)
        qd_equilibria_default_box(r->ctx, r->e, r->mf.model, angle, lo, hi);
    if (rc == QD_EXIT_OK && near && (rc = qd_lin_coords(r, "--near", near, q)) == QD_EXIT_OK)
        o.near = q;
    if (rc == QD_EXIT_OK && box && (rc = qd_lin_box(r, box, lo, hi)) == QD_EXIT_OK) {
        o.lo = lo;
        o.hi = hi;
        o.numeric_only = true;
    }
    if (rc == QD_EXIT_OK &&
        qd_equilibria_find(r->ctx, r->e, r->mf.model, r->st.n, r->st.syms, r->st.vals, &o,
                           out) != QD_OK) {
        qd_diag_error("%s", qd_ctx_message(r->ctx));
        rc = QD_EXIT_FAIL;
    }
    free(q);
    free(lo);
    free(hi);
    free(angle);
    return rc;
}

void qd_lin_put_value(qd_lin_run *r, const qd_equilibrium *p, size_t j, qd_buf *b) {
    if (p->exact && p->exact[j])
        qd_print(r->ctx, p->exact[j], QD_FMT_TEXT, b);
    else
        qd_state_put_double(b, p->q[j]);
}

/* ---- the command ------------------------------------------------------------ */

typedef struct eq_args {
    const char *file, *near, *box;
    const char *sets[QD_LIN_MAX_SETS];
    size_t nsets;
    bool json;
} eq_args;

static const char usage_text[] =
    "usage: qdot equilibria FILE [--near \"q1=VALUE, ...\"] [--box \"q1=LOW..HIGH, ...\"] "
    "[--set NAME=VALUE]... [--format text|json]";

static int parse_option(int argc, char **argv, int *i, void *data) {
    eq_args *a = data;
    const char *v;
    if ((v = qd_cli_value(argc, argv, i, "--format"))) {
        if (strcmp(v, "text") && strcmp(v, "json")) {
            qd_diag_error("--format takes text or json, not '%s'", v);
            return QD_EXIT_USAGE;
        }
        a->json = !strcmp(v, "json");
    } else if ((v = qd_cli_value(argc, argv, i, "--near"))) {
        a->near = v;
    } else if ((v = qd_cli_value(argc, argv, i, "--box"))) {
        a->box = v;
    } else if ((v = qd_cli_value(argc, argv, i, "--set"))) {
        if (a->nsets == QD_LIN_MAX_SETS) {
            qd_diag_error("at most %d --set options", QD_LIN_MAX_SETS);
            return QD_EXIT_USAGE;
        }
        a->sets[a->nsets++] = v;
    } else {
        qd_diag_error("unknown option or missing value: '%s'\n%s", argv[*i], usage_text);
        return QD_EXIT_USAGE;
    }
    return QD_EXIT_OK;
}

static void put_text(qd_lin_run *r, const qd_equilibria *eq, qd_buf *b) {
    const qd_eom *e = r->e;
    qd_buf_printf(b, "%zu equilibri%s (%s%s)\n", eq->count, eq->count == 1 ? "um" : "a",
                  eq->method, eq->exact ? ": the complete set, angles in (-pi, pi]" : "");
    for (size_t i = 0; i < eq->count; i++) {
        const qd_equilibrium *p = &eq->pts[i];
        qd_buf_printf(b, "%3zu  ", i + 1);
        for (size_t j = 0; j < e->n; j++) {
            qd_buf_printf(b, "%s%s = ", j ? ", " : "", qd_expr_name(e->q[j]));
            qd_lin_put_value(r, p, j, b);
            if (p->exact && !qd_is_number(p->exact[j])) {
                qd_buf_puts(b, " (");
                qd_state_put_double(b, p->q[j]);
                qd_buf_puts(b, ")");
            }
        }
        qd_buf_printf(b, "\n     %s of the potential (Hessian: %zu positive, %zu negative, %zu "
                         "zero)%s, residual %.3g\n",
                      qd_eq_kind_name(p->kind), p->npos, p->nneg, p->nzero,
                      p->symmetric ? "" : "; the forces are not from a potential: K is not "
                                          "symmetric, its symmetric part is classified",
                      p->residual);
    }
    if (eq->continuum)
        qd_buf_puts(b, "note: the equilibria are not isolated (a family: a rigid motion or a "
                       "neutral direction); the points listed are samples of it\n");
}

static void put_json(qd_lin_run *r, const qd_equilibria *eq, qd_buf *b) {
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
                qd_buf t = QD_BUF_INIT;
                qd_print(r->ctx, p->exact[k], QD_FMT_TEXT, &t);
                qd_json_key(&j, qd_expr_name(e->q[k]));
                qd_json_string(&j, qd_buf_str(&t));
                qd_buf_free(&t);
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
}

int qd_cmd_equilibria(int argc, char **argv) {
    eq_args a = {0};
    int rc = qd_cli_file_args(argc, argv, "equilibria", usage_text, &a.file, parse_option, &a);
    if (rc != QD_EXIT_OK)
        return rc;
    qd_lin_run r = {.ctx = qd_ctx_new()};
    if (!r.ctx) {
        qd_diag_error("out of memory");
        return QD_EXIT_FAIL;
    }
    qd_equilibria eq = {0};
    rc = qd_lin_load(&r, a.file, a.sets, a.nsets);
    if (rc == QD_EXIT_OK)
        rc = qd_lin_equilibria(&r, a.near, a.box, &eq);
    if (rc == QD_EXIT_OK) {
        qd_buf b = QD_BUF_INIT;
        (a.json ? put_json : put_text)(&r, &eq, &b);
        if (b.failed) {
            qd_diag_error("cannot print the equilibria");
            rc = QD_EXIT_FAIL;
        } else {
            fputs(qd_buf_str(&b), stdout);
        }
        qd_buf_free(&b);
    }
    qd_equilibria_free(&eq);
    qd_lin_free(&r);
    qd_ctx_free(r.ctx);
    return rc;
}

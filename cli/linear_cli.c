/*
 * cli/linear_cli.c - what `qdot equilibria` and `qdot modes` share (see
 * linear_cli.h).  The equations are derived with the holonomic constraints
 * eliminated, so their coordinates e->q may be fewer than the model's: every
 * value read from the command line is matched to e->q by symbol, and a
 * coordinate that a constraint eliminated is refused by name rather than
 * taken for another one.
 */
#include "linear_cli.h"

#include <ctype.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include "eom_out.h"
#include "model_cli.h"

int cli_lin_load_model(cli_lin_run *r, const char *file, const char *const *sets,
                       size_t nsets) {
    return cli_load(r->ctx, file, nsets, sets, false, &r->mf);
}

int cli_lin_load(cli_lin_run *r, const char *file, const char *const *sets, size_t nsets) {
    int rc = cli_lin_load_model(r, file, sets, nsets);
    return rc == QD_EXIT_OK ? cli_lin_derive(r) : rc;
}

int cli_lin_derive(cli_lin_run *r) {
    qd_eom_opts opts = {.eliminate = true};
    if (!(r->e = qd_eom_derive_opts(r->ctx, r->mf.model, &opts)))
        return cli_eom_derive_error(r->ctx, &r->mf);
    return cli_lin_setup(r);
}

/* The constraints kept with multipliers are reduced on their manifold by
 * the library (qdot/constrained.h). */
int cli_lin_setup(cli_lin_run *r) {
    int rc = cli_state_init(r->ctx, r->mf.model, &r->st);
    if (rc != QD_EXIT_OK)
        return rc;
    /* the slot of each independent coordinate in the model's state */
    size_t nq = qd_model_ncoords(r->mf.model);
    r->slot = malloc((r->e->n + 1) * sizeof *r->slot);
    if (!r->slot) {
        cli_diag_error("out of memory");
        return QD_EXIT_FAIL;
    }
    for (size_t j = 0; j < r->e->n; j++) {
        r->slot[j] = SIZE_MAX;
        for (size_t i = 0; i < nq; i++)
            if (r->st.syms[i] == r->e->q[j])
                r->slot[j] = i;
        if (r->slot[j] == SIZE_MAX) {
            cli_diag_error("internal error: coordinate %s of the equations is not in the model",
                          qd_expr_name(r->e->q[j]));
            return QD_EXIT_FAIL;
        }
    }
    return QD_EXIT_OK;
}

void cli_lin_free(cli_lin_run *r) {
    cli_state_free(&r->st);
    free(r->slot);
    r->slot = NULL;
    if (r->e)
        qd_eom_free(r->e);
    r->e = NULL;
    cli_model_file_free(&r->mf);
}

void cli_lin_set_state(cli_lin_run *r, const double *q, const double *qd) {
    size_t nq = qd_model_ncoords(r->mf.model);
    for (size_t j = 0; j < r->e->n; j++) {
        r->st.vals[r->slot[j]] = q[j];
        r->st.vals[nq + r->slot[j]] = qd ? qd[j] : 0;
    }
}

/* "theta, phi": the independent coordinates, for messages. */
static void independent_names(const cli_lin_run *r, char *out, size_t cap) {
    size_t used = 0;
    out[0] = '\0';
    for (size_t j = 0; j < r->e->n && used < cap; j++)
        used += (size_t)snprintf(out + used, cap - used, "%s%s", j ? ", " : "",
                                 qd_expr_name(r->e->q[j]));
}

/* The index in e->q of the model's coordinate i, or e->n when a constraint
 * eliminated it. */
static size_t eom_index(const cli_lin_run *r, size_t i) {
    size_t j = 0;
    while (j < r->e->n && r->slot[j] != i)
        j++;
    return j;
}

static int eliminated(const cli_lin_run *r, const char *what, const char *name) {
    char names[512];
    independent_names(r, names, sizeof names);
    cli_diag_error("%s: %s is not an independent coordinate here (a constraint eliminates it); "
                  "give values of %s", what, name, names);
    return QD_EXIT_USAGE;
}

int cli_lin_point(cli_lin_run *r, const char *what, const char *text, double *q, double *qd) {
    const qd_model *m = r->mf.model;
    size_t nq = qd_model_ncoords(m);
    cli_state s;
    int rc = cli_state_init(r->ctx, m, &s);
    if (rc != QD_EXIT_OK)
        return rc;
    /* NaN marks what the text does not give: every value read is finite */
    for (size_t i = 0; i <= 2 * nq; i++)
        s.vals[i] = NAN;
    rc = cli_state_parse_as(r->ctx, m, what, text, &s);
    if (rc == QD_EXIT_OK && !isnan(s.vals[2 * nq])) {
        cli_diag_error("%s: give coordinates%s only, not the time t", what,
                      qd ? " and velocities" : "");
        rc = QD_EXIT_USAGE;
    }
    for (size_t i = 2 * nq + 1; rc == QD_EXIT_OK && i < s.n; i++)
        if (s.vals[i] != r->st.vals[i]) {
            cli_diag_error("%s: %s is a parameter: give it with --set", what,
                          qd_expr_name(s.syms[i]));
            rc = QD_EXIT_USAGE;
        }
    for (size_t i = 0; rc == QD_EXIT_OK && i < nq; i++) {
        bool given_q = !isnan(s.vals[i]), given_v = !isnan(s.vals[nq + i]);
        size_t j = eom_index(r, i);
        const char *name = qd_expr_name(s.syms[i]);
        if ((given_q || given_v) && j == r->e->n)
            rc = eliminated(r, what, name);
        else if (given_v && !qd) {
            cli_diag_error("%s: give coordinates only (a point at rest), not %s'", what, name);
            rc = QD_EXIT_USAGE;
        } else {
            if (given_q)
                q[j] = s.vals[i];
            if (given_v)
                qd[j] = s.vals[nq + i];
        }
    }
    cli_state_free(&s);
    return rc;
}

int cli_lin_coords(cli_lin_run *r, const char *what, const char *text, double *q) {
    for (size_t j = 0; j < r->e->n; j++)
        q[j] = 0;
    return cli_lin_point(r, what, text, q, NULL);
}

/* ---- --box ------------------------------------------------------------------ */

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

static int box_item(cli_lin_run *r, const char *item, double *lo, double *hi, bool *seen) {
    /* ranges are A:B in every command (issue 31) */
    const char *eq = strchr(item, '='), *dots = eq ? strchr(eq, ':') : NULL;
    if (!eq || !dots) {
        cli_diag_error("--box takes NAME=LOW:HIGH items, not '%s'", item);
        return QD_EXIT_USAGE;
    }
    char name[128], a[256], b[256];
    size_t nl = (size_t)(eq - item);
    while (nl && isspace((unsigned char)item[nl - 1]))
        nl--;
    size_t s = 0;
    while (s < nl && isspace((unsigned char)item[s]))
        s++;
    if (nl - s >= sizeof name || (size_t)(dots - eq - 1) >= sizeof a ||
        strlen(dots + 1) >= sizeof b) {
        cli_diag_error("--box: item too long: '%s'", item);
        return QD_EXIT_USAGE;
    }
    memcpy(name, item + s, nl - s);
    name[nl - s] = '\0';
    memcpy(a, eq + 1, (size_t)(dots - eq - 1));
    a[dots - eq - 1] = '\0';
    strcpy(b, dots + 1);
    size_t nq = qd_model_ncoords(r->mf.model), i = 0;
    while (i < nq && strcmp(qd_expr_name(qd_model_coord(r->mf.model, i)), name))
        i++;
    if (i == nq) {
        cli_diag_error("--box: '%s' is not a coordinate", name);
        return QD_EXIT_USAGE;
    }
    size_t j = eom_index(r, i);
    if (j == r->e->n)
        return eliminated(r, "--box", name);
    if (seen[j]) {
        cli_diag_error("--box: %s is given twice", name);
        return QD_EXIT_USAGE;
    }
    seen[j] = true;
    const qd_expr *x;
    int rc = cli_state_number(r->ctx, "--box", a, &x, &lo[j]);
    if (rc == QD_EXIT_OK)
        rc = cli_state_number(r->ctx, "--box", b, &x, &hi[j]);
    if (rc == QD_EXIT_OK && !(lo[j] < hi[j])) {
        cli_diag_error("--box: the range of %s is empty", name);
        rc = QD_EXIT_USAGE;
    } else if (rc == QD_EXIT_OK && !isfinite(hi[j] - lo[j])) {
        cli_diag_error("--box: the range of %s is too wide: its width %g - (%g) overflows a double",
                       name, hi[j], lo[j]);
        rc = QD_EXIT_USAGE;
    }
    return rc;
}

int cli_lin_box(cli_lin_run *r, const char *text, double *lo, double *hi) {
    char item[512];
    bool *seen = calloc(r->e->n + 1, sizeof *seen);
    if (!seen)
        return QD_EXIT_FAIL;
    int rc = QD_EXIT_OK;
    for (size_t i = 0; text[i] && rc == QD_EXIT_OK;) {
        size_t end = item_end(text, i);
        if (end - i >= sizeof item) {
            cli_diag_error("--box: item too long");
            rc = QD_EXIT_USAGE;
            break;
        }
        memcpy(item, text + i, end - i);
        item[end - i] = '\0';
        if (strspn(item, " \t") < strlen(item))
            rc = box_item(r, item, lo, hi, seen);
        i = text[end] ? end + 1 : end;
    }
    free(seen);
    return rc;
}

/* ---- the search -------------------------------------------------------------- */

int cli_lin_equilibria(cli_lin_run *r, const char *near, const char *box, qd_equilibria *out) {
    size_t n = r->e->n;
    double *q = malloc((n + 1) * sizeof *q), *lo = malloc((n + 1) * sizeof *lo);
    double *hi = malloc((n + 1) * sizeof *hi);
    bool *angle = malloc((n + 1) * sizeof *angle);
    int rc = q && lo && hi && angle ? QD_EXIT_OK : QD_EXIT_FAIL;
    qd_equilibria_opts o = {0};
    if (rc == QD_EXIT_OK &&
        qd_equilibria_default_box(r->ctx, r->e, r->mf.model, angle, lo, hi) != QD_OK)
        rc = cli_diag_ctx(r->ctx);
    if (rc == QD_EXIT_OK && near && (rc = cli_lin_coords(r, "--near", near, q)) == QD_EXIT_OK)
        o.near = q;
    if (rc == QD_EXIT_OK && box && (rc = cli_lin_box(r, box, lo, hi)) == QD_EXIT_OK) {
        o.lo = lo;
        o.hi = hi;
        o.numeric_only = true;
    }
    if (rc == QD_EXIT_OK &&
        qd_equilibria_find(r->ctx, r->e, r->mf.model, r->st.n, r->st.syms, r->st.vals, &o,
                           out) != QD_OK) {
        cli_diag_error("%s", qd_ctx_message(r->ctx));
        /* a constraint the manifold search does not take (with t, with velocities) */
        rc = qd_ctx_status(r->ctx) == QD_ERR_UNSUPPORTED ? QD_EXIT_USAGE : QD_EXIT_FAIL;
    }
    free(q);
    free(lo);
    free(hi);
    free(angle);
    return rc;
}

void cli_lin_put_value(cli_lin_run *r, const qd_equilibrium *p, size_t j, qd_buf *b) {
    if (p->exact && p->exact[j])
        qd_print(r->ctx, p->exact[j], QD_FMT_TEXT, b);
    else
        cli_state_put_result(b, p->q[j]);
}

void qd_json_frequency(qd_json *j, double w2) {
    qd_json_key(j, "omega2");
    qd_json_number(j, w2);
    qd_json_key(j, "omega");
    if (w2 >= 0)
        qd_json_number(j, sqrt(w2));
    else
        qd_json_null(j);
    qd_json_key(j, "period");
    if (w2 > 0)
        qd_json_number(j, 2 * 3.14159265358979323846 / sqrt(w2));
    else
        qd_json_null(j);
}

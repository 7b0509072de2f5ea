/*
 * src/path/path_out.c - the stationary paths of qdot/path.h written out,
 * as text (every tenth sample) or JSON (every sample): the one rendering the
 * program and Python share.
 */
#include <math.h>
#include <stdio.h>
#include "base/args.h"
#include "qdot/json.h"
#include "qdot/path.h"

typedef struct pt_out {
    const qd_path_set *ps;
    const qd_model *m;
    const qd_eom *e;
    bool any_free;
    bool all;            /* the --all search */
} pt_out;

/* A computed number for a reader: the one digit rule (qd_buf_put_result). */
static void put(qd_buf *b, double x) { qd_buf_put_result(b, x, 1); }

/* The name the ends' time goes by: t, or the model's independent x. */
static const char *time_name(const pt_out *r) {
    const char *x = qd_model_independent(r->m);
    return x ? x : "t";
}

static const char *mult_name(const pt_out *r, size_t i) {
    return qd_expr_name(qd_model_isoperimetric_multiplier(r->m, i));
}

/* Foci and minimum, or why they are not there. */
static void write_second_variation(const pt_out *r, const qd_path *p, qd_buf *b) {
    if (!p->examined && (p->nmult || r->any_free)) {
        qd_buf_printf(b, "\n  kinetic foci: not examined (%s)\n  minimum: not examined",
                      p->nmult ? "isoperimetric constraint" : "free end");
        return;
    }
    qd_buf_puts(b, "\n  kinetic foci:");
    for (size_t k = 0; k < p->nfoci; k++) {
        qd_buf_puts(b, k ? ", " : " ");
        put(b, p->foci[k]);
        if (p->foci_mult && p->foci_mult[k] > 1) /* J loses more than one rank (foci.c) */
            qd_buf_printf(b, " (multiplicity %zu)", p->foci_mult[k]);
    }
    qd_buf_printf(b, "%s\n  minimum: %s", p->nfoci ? "" : " none", p->minimum ? "yes" : "no");
    if (p->family)
        qd_buf_printf(b, "\n  family: not isolated, a %zu-parameter family of stationary paths "
                         "(the end is a kinetic focus of the start); this is one of them",
                      p->family);
}

/* --all: what the multistart covers, and how to ask for more (issue 33: a
 * search that stops short of a longer path must say so), in the text and
 * in JSON with the same words. */
static const char *search_covered(const pt_out *r) {
    bool energy = r->ps->count && !isnan(r->ps->paths[0].abbreviated);
    return energy ? "the first three near passes of each start's motion, within 12 chord times"
                  : "velocities spread about the chord's, to 2.5 times its speed or the "
                    "motion's own rate";
}

static const char *search_guess(const pt_out *r) {
    bool energy = r->ps->count && !isnan(r->ps->paths[0].abbreviated);
    return energy ? "--guess \"q'=...\" (aimed at its motion's nearest pass)"
                  : "--guess \"q'=...\"";
}

static void write_search_note(const pt_out *r, qd_buf *b) {
    qd_buf_printf(b, "note: more stationary paths may exist beyond those the starts aimed at "
                     "(%s); to ask for more: %s, --segments N\n",
                  search_covered(r), search_guess(r));
}

static void write_search_json(const pt_out *r, qd_json *j) {
    qd_json_key(j, "search");
    qd_json_begin_object(j);
    qd_json_key(j, "code");
    qd_json_string(j, "more_paths_may_exist");
    qd_json_key(j, "note");
    qd_json_string(j, "more stationary paths may exist beyond those the starts aimed at");
    qd_json_key(j, "covered");
    qd_json_string(j, search_covered(r));
    qd_json_key(j, "ask");
    qd_json_begin_array(j);
    qd_json_string(j, search_guess(r));
    qd_json_string(j, "--segments N");
    qd_json_end_array(j);
    qd_json_end_object(j);
}

static void write_text(const pt_out *r, qd_buf *b) {
    size_t n = r->e->n;
    qd_buf_printf(b, "paths: %zu\n", r->ps->count);
    if (r->all)
        write_search_note(r, b);
    for (size_t i = 0; i < r->ps->count; i++) {
        const qd_path *p = &r->ps->paths[i];
        qd_buf_printf(b, "path %zu:\n  action: ", i + 1);
        put(b, p->action);
        qd_buf_puts(b, "\n  initial velocities: ");
        for (size_t j = 0; j < n; j++) {
            qd_buf_printf(b, "%s%s' = ", j ? ", " : "", qd_expr_name(r->e->q[j]));
            put(b, p->v0[j]);
        }
        for (size_t k = 0; k < p->nmult; k++) {
            qd_buf_printf(b, "%s%s = ", k ? ", " : "\n  multipliers: ", mult_name(r, k));
            put(b, p->mult[k]);
        }
        if (!isnan(p->abbreviated)) {
            qd_buf_puts(b, "\n  least action (Maupertuis, integral of p.dq): ");
            put(b, p->abbreviated);
            qd_buf_puts(b, "\n  time: ");
            put(b, p->t[p->nsamples - 1] - p->t[0]);
        }
        write_second_variation(r, p, b);
        qd_buf_printf(b, "\n  samples (%s", time_name(r));
        for (size_t j = 0; j < n; j++)
            qd_buf_printf(b, ", %s", qd_expr_name(r->e->q[j]));
        size_t step = p->nsamples > 11 ? (p->nsamples - 1) / 10 : 1;
        qd_buf_printf(b, "; every %zu of %zu, --format json for all):\n", step, p->nsamples);
        for (size_t k = 0; k < p->nsamples; k += step) {
            qd_buf_puts(b, "   ");
            for (size_t j = 0; j <= n; j++) {
                qd_buf_puts(b, " ");
                double x = j ? p->q[k * n + j - 1] : p->t[k];
                put(b, fabs(x) < 1e-10 ? 0 : x);  /* an end reached to the tolerance */
            }
            qd_buf_puts(b, "\n");
        }
    }
}

static bool write_json(const pt_out *r, qd_buf *b) {
    size_t n = r->e->n;
    qd_json j;
    qd_json_init(&j, b);
    qd_json_begin_object(&j);
    qd_json_key(&j, "count");
    qd_json_number(&j, (double)r->ps->count);
    if (r->ps->searched)
        write_search_json(r, &j);
    qd_json_key(&j, "paths");
    qd_json_begin_array(&j);
    for (size_t i = 0; i < r->ps->count; i++) {
        const qd_path *p = &r->ps->paths[i];
        qd_json_begin_object(&j);
        qd_json_key(&j, "action");
        qd_json_number(&j, p->action);
        if (!isnan(p->abbreviated)) {
            qd_json_key(&j, "least_action");
            qd_json_number(&j, p->abbreviated);
            qd_json_key(&j, "time");
            qd_json_number(&j, p->t[p->nsamples - 1] - p->t[0]);
        }
        qd_json_key(&j, "initial_velocities");
        qd_json_begin_object(&j);
        for (size_t k = 0; k < n; k++) {
            char name[160];
            snprintf(name, sizeof name, "%s'", qd_expr_name(r->e->q[k]));
            qd_json_key(&j, name);
            qd_json_number(&j, p->v0[k]);
        }
        qd_json_end_object(&j);
        qd_json_key(&j, "multipliers");
        qd_json_begin_object(&j);
        for (size_t k = 0; k < p->nmult; k++) {
            qd_json_key(&j, mult_name(r, k));
            qd_json_number(&j, p->mult[k]);
        }
        qd_json_end_object(&j);
        qd_json_key(&j, "residual");
        qd_json_number(&j, p->residual);
        qd_json_key(&j, "samples");
        qd_json_begin_array(&j);
        for (size_t s = 0; s < p->nsamples; s++) {
            qd_json_begin_array(&j);
            qd_json_number(&j, p->t[s]);
            for (size_t k = 0; k < n; k++)
                qd_json_number(&j, p->q[s * n + k]);
            qd_json_end_array(&j);
        }
        qd_json_end_array(&j);
        qd_json_key(&j, "kinetic_foci");
        qd_json_begin_array(&j);
        for (size_t k = 0; k < p->nfoci; k++)
            qd_json_number(&j, p->foci[k]);
        qd_json_end_array(&j);
        qd_json_key(&j, "kinetic_foci_multiplicity"); /* Jacobi fields vanishing there */
        qd_json_begin_array(&j);
        for (size_t k = 0; k < p->nfoci; k++)
            qd_json_number(&j, p->foci_mult ? (double)p->foci_mult[k] : 1);
        qd_json_end_array(&j);
        qd_json_key(&j, "minimum");
        qd_json_bool(&j, p->minimum);
        qd_json_key(&j, "examined");  /* false: foci and minimum not decided */
        qd_json_bool(&j, p->examined);
        qd_json_key(&j, "family");    /* 0: isolated, else the family's dimension */
        qd_json_number(&j, (double)p->family);
        qd_json_end_object(&j);
    }
    qd_json_end_array(&j);
    qd_json_end_object(&j);
    qd_buf_puts(b, "\n");
    return qd_json_ok(&j);
}

static bool pt_any_free(const qd_path_set *ps, const qd_path_opts *opts) {
    size_t n = ps->count ? ps->paths[0].n : 0;
    for (size_t j = 0; opts && j < n; j++)
        if ((opts->free0 && opts->free0[j]) || (opts->free1 && opts->free1[j]))
            return true;
    return false;
}

qd_status qd_path_print(qd_ctx *ctx, const qd_path_set *ps, const qd_model *m, const qd_eom *e,
                        const qd_path_opts *opts, qd_buf *out) {
    QD_ARGS_CTX(ctx, ctx && ps && m && e && out);
    pt_out o = {ps, m, e, pt_any_free(ps, opts), opts && opts->all};
    write_text(&o, out);
    if (!out->failed)
        return QD_OK;
    qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory writing the paths");
    return QD_ERR_NOMEM;
}

qd_status qd_path_json(qd_ctx *ctx, const qd_path_set *ps, const qd_model *m, const qd_eom *e,
                       qd_buf *out) {
    QD_ARGS_CTX(ctx, ctx && ps && m && e && out);
    pt_out o = {ps, m, e, false, false};
    if (write_json(&o, out))
        return QD_OK;
    qd_ctx_error(ctx, out->failed ? QD_ERR_NOMEM : QD_ERR_NUMERIC, "%s",
                 out->failed ? "out of memory writing the paths"
                             : "a path holds a non-finite number (JSON cannot hold it)");
    return out->failed ? QD_ERR_NOMEM : QD_ERR_NUMERIC;
}

/* ---- the action of a trial path (qd_path_action_of_print) ----------------- */

static bool action_of_json(const char *source, const double v[4], qd_buf *out) {
    static const char *const keys[4] = {"t0", "t1", "action", "first_variation"};
    qd_json j;
    qd_json_init(&j, out);
    qd_json_begin_object(&j);
    qd_json_key(&j, "model");
    qd_json_string(&j, source);
    for (size_t k = 0; k < 4; k++) {
        qd_json_key(&j, keys[k]);
        qd_json_number(&j, v[k]);
    }
    qd_json_end_object(&j);
    qd_buf_puts(out, "\n");
    return qd_json_ok(&j) && !out->failed;
}

qd_status qd_path_action_of_print(qd_ctx *ctx, const char *source, double t0, double t1,
                                  double action, double first_variation, bool json,
                                  qd_buf *out) {
    QD_ARGS_CTX(ctx, ctx && source && out);
    const double v[4] = {t0, t1, action, first_variation};
    if (json && !action_of_json(source, v, out)) {
        qd_ctx_error(ctx, out->failed ? QD_ERR_NOMEM : QD_ERR_NUMERIC, "%s",
                     out->failed ? "out of memory writing the action"
                                 : "the action is not a finite number (JSON cannot hold it)");
        return out->failed ? QD_ERR_NOMEM : QD_ERR_NUMERIC;
    }
    if (!json) {
        qd_buf_puts(out, "action: ");
        qd_buf_put_result(out, action, 1);
        qd_buf_puts(out, "\nfirst_variation: ");
        qd_buf_put_result(out, first_variation, 1);
        qd_buf_puts(out, "\n");
    }
    if (!out->failed)
        return QD_OK;
    qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory writing the action");
    return QD_ERR_NOMEM;
}

/*
 * src/sweep/sweep.c - a sweep's setup: the runs (grid, random draw, list),
 * the parameters a run's inputs imply, the column names.
 *
 * Run i's inputs are a function of i alone (a grid's mixed-radix digits, a
 * counter-based random draw), never of the order runs are taken in: that
 * is what makes the rows identical on any number of threads or processes.
 */
#include "sweep_int.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "base/mem.h"
#include "../base/args.h"

qd_sweep *qd_sweep_new(qd_ctx *ctx, const qd_sim *s, const qd_model *m) {
    QD_ARGS(NULL, ctx && s && m);
    if (!ctx || !s || !m)
        return NULL;
    if (!qd_sim_compiled(s)) {
        qd_ctx_error(ctx, QD_ERR_ARG, "a sweep shares a compiled simulation (qd_sim_compile)");
        return NULL;
    }
    qd_sweep *w = qd__calloc(ctx, 1, sizeof *w);
    if (!w)
        return NULL;
    *w = (qd_sweep){.ctx = ctx, .s = s, .m = m, .n = qd_sim_ndof(s), .np = qd_model_nparams(m)};
    w->par0 = qd__calloc(ctx, w->np + 1, sizeof *w->par0);
    if (!w->par0) {
        qd_sweep_free(w);
        return NULL;
    }
    for (size_t i = 0; i < w->np; i++)
        qd_model_param_number(m, i, &w->par0[i]);
    return w;
}

void qd__sweep_free_inputs(qd_sweep *w) {
    for (size_t k = 0; k < w->nin; k++)
        qd__free(w->in[k].name);
    qd__free(w->in);
    qd__free(w->list);
    qd_prog_free(w->parprog);
    w->in = NULL;
    w->list = NULL;
    w->parprog = NULL;
    w->nin = w->nruns = 0;
    w->how = QD__SW_NONE;
}

void qd__sweep_free_measures(qd_sweep *w) {
    for (size_t k = 0; k < w->nms; k++) {
        qd__free(w->ms[k].text);
        qd__free(w->ms[k].col);
    }
    qd__free(w->ms);
    w->ms = NULL;
    w->nms = 0;
}

static void free_columns(qd_sweep *w) {
    for (size_t j = 0; j < w->ncols; j++)
        qd__free(w->cols[j]);
    qd__free(w->cols);
    w->cols = NULL;
    w->ncols = 0;
}

void qd_sweep_free(qd_sweep *w) {
    if (!w)
        return;
    qd__sweep_free_inputs(w);
    qd__sweep_free_measures(w);
    free_columns(w);
    qd_lyap_free(w->own_lyap);
    qd__free(w->par0);
    qd__free(w);
}

const char *qd__sweep_coord(const qd_sweep *w, size_t i) {
    const char *names[512];
    size_t nc = qd_sim_columns(w->s, QD_SIM_DOP853, names, 512);
    return 1 + i < nc && 1 + i < 512 ? names[1 + i] : "";
}

/* ---- the runs ---------------------------------------------------------------- */

static qd_status set_runs(qd_sweep *w, qd_status st) {
    if (st == QD_OK)
        st = qd__sweep_params(w);
    if (st == QD_OK)
        st = qd__sweep_columns(w);
    if (st != QD_OK)
        qd__sweep_free_inputs(w);
    return st;
}

qd_status qd_sweep_grid(qd_sweep *w, const char *spec) {
    QD_ARGS(QD_ERR_ARG, w && spec);
    qd__sweep_free_inputs(w);
    qd_status st = qd__sweep_parse_axes(w, spec, true);
    size_t runs = 1;
    for (size_t k = 0; st == QD_OK && k < w->nin; k++) {
        if (runs > ((size_t)1 << 40) / w->in[k].npts) {
            qd_ctx_error(w->ctx, QD_ERR_TOOBIG, "the grid has more than 2^40 points");
            st = QD_ERR_TOOBIG;
        }
        runs *= w->in[k].npts;
    }
    w->how = QD__SW_GRID;
    w->nruns = runs;
    return set_runs(w, st);
}

qd_status qd_sweep_random(qd_sweep *w, const char *spec, size_t n, uint64_t seed) {
    QD_ARGS(QD_ERR_ARG, w && spec);
    qd__sweep_free_inputs(w);
    qd_status st = qd__sweep_parse_axes(w, spec, false);
    if (st == QD_OK && n == 0) {
        qd_ctx_error(w->ctx, QD_ERR_ARG, "a random sweep needs at least one run");
        st = QD_ERR_ARG;
    }
    w->how = QD__SW_RANDOM;
    w->nruns = n;
    w->seed = seed;
    return set_runs(w, st);
}

qd_status qd_sweep_list(qd_sweep *w, size_t nnames, const char *const *names, size_t nrows,
                        const double *values) {
    QD_ARGS(QD_ERR_ARG, w && (nnames == 0 || names) && (nrows == 0 || values));
    qd__sweep_free_inputs(w);
    qd_status st = nnames && nrows ? QD_OK : QD_ERR_ARG;
    if (st != QD_OK)
        qd_ctx_error(w->ctx, st, "a list of runs needs at least one name and one row");
    w->in = st == QD_OK ? qd__calloc(w->ctx, nnames, sizeof *w->in) : NULL;
    w->list = st == QD_OK ? qd__malloc(w->ctx, nnames * nrows * sizeof *w->list) : NULL;
    if (st == QD_OK && (!w->in || !w->list))
        st = QD_ERR_NOMEM;
    for (size_t k = 0; st == QD_OK && k < nnames; k++) {
        w->in[k].name = qd__strdup(w->ctx, names[k]);
        w->nin++;
        st = w->in[k].name ? qd__sweep_resolve(w, &w->in[k], NULL, 0) : QD_ERR_NOMEM;
        for (size_t j = 0; st == QD_OK && j < k; j++)
            if (w->in[j].kind == w->in[k].kind && w->in[j].index == w->in[k].index) {
                qd_ctx_error(w->ctx, QD_ERR_ARG, "%s is given twice", names[k]);
                st = QD_ERR_ARG;
            }
    }
    for (size_t r = 0; st == QD_OK && r < nrows * nnames; r++)
        if (!isfinite(values[r])) {
            qd_ctx_error(w->ctx, QD_ERR_ARG, "run %zu: %s is not a finite number", r / nnames + 1,
                         names[r % nnames]);
            st = QD_ERR_ARG;
        }
    if (st == QD_OK)
        memcpy(w->list, values, nnames * nrows * sizeof *values);
    w->how = QD__SW_LIST;
    w->nruns = nrows;
    return set_runs(w, st);
}

/* splitmix64 (Steele, Lea, Flood, "Fast splittable pseudorandom number
 * generators", OOPSLA 2014): a counter-based draw, so run i's numbers
 * depend on (seed, i, axis) alone. */
static uint64_t mix(uint64_t z) {
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9u;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebu;
    return z ^ (z >> 31);
}

static double uniform(uint64_t seed, size_t i, size_t axis, size_t naxes) {
    uint64_t k = (uint64_t)i * (uint64_t)naxes + (uint64_t)axis + 1;
    uint64_t z = mix(seed + k * 0x9e3779b97f4a7c15u);
    return (double)(z >> 11) * 0x1p-53; /* [0, 1), 53 random bits */
}

/* Point j of N on [a, b]: the ends exact. */
static double grid_point(const qd__sw_in *x, size_t j) {
    if (x->npts == 1)
        return x->a;
    if (j + 1 == x->npts)
        return x->b;
    return x->a + (x->b - x->a) * ((double)j / (double)(x->npts - 1));
}

void qd__sweep_inputs_of(const qd_sweep *w, size_t i, double *x) {
    if (w->how == QD__SW_LIST) {
        memcpy(x, w->list + i * w->nin, w->nin * sizeof *x);
        return;
    }
    if (w->how == QD__SW_RANDOM) {
        for (size_t k = 0; k < w->nin; k++)
            x[k] = w->in[k].a + (w->in[k].b - w->in[k].a) * uniform(w->seed, i, k, w->nin);
        return;
    }
    /* the grid: the first axis slowest, the last fastest */
    for (size_t k = w->nin; k-- > 0;) {
        x[k] = grid_point(&w->in[k], i % w->in[k].npts);
        i /= w->in[k].npts;
    }
}

/* ---- parameters ----------------------------------------------------------- */

static bool swept_param(const qd_sweep *w, size_t p) {
    for (size_t k = 0; k < w->nin; k++)
        if (w->in[k].kind == QD__SW_PAR && w->in[k].index == p)
            return true;
    return false;
}

/* Each parameter's value as an expression of the swept ones: those
 * defined from a swept parameter (`w = sqrt(k/m)`) follow it. */
qd_status qd__sweep_params(qd_sweep *w) {
    bool any = false;
    for (size_t k = 0; k < w->nin; k++)
        any = any || w->in[k].kind == QD__SW_PAR;
    if (!any)
        return QD_OK;
    const qd_expr **syms = qd__calloc(w->ctx, 2 * w->np, sizeof *syms), **vals = syms + w->np;
    if (!syms)
        return QD_ERR_NOMEM;
    for (size_t p = 0; p < w->np; p++) {
        syms[p] = qd_model_param(w->m, p);
        const qd_expr *def = qd_model_param_definition(w->m, p);
        if (!def)
            def = qd_model_param_value(w->m, p);
        vals[p] = swept_param(w, p) ? syms[p] : qd_subs(w->ctx, def, p, syms, vals);
    }
    w->parprog = qd_prog_new(w->ctx, w->np, syms, w->np, vals);
    qd__free(syms);
    return w->parprog ? QD_OK : qd_ctx_status(w->ctx);
}

/* ---- columns ----------------------------------------------------------------- */

static qd_status add_col(qd_sweep *w, size_t *j, const char *a, const char *b) {
    if (w->cols) {
        size_t len = strlen(a) + strlen(b) + 1;
        w->cols[*j] = qd__malloc(w->ctx, len);
        if (!w->cols[*j])
            return QD_ERR_NOMEM;
        snprintf(w->cols[*j], len, "%s%s", a, b);
    }
    (*j)++;
    return QD_OK;
}

/* prefix NAME for each coordinate, then prefix NAME' for each velocity. */
static qd_status state_cols(qd_sweep *w, size_t *j, const char *prefix) {
    qd_status st = QD_OK;
    char name[160];
    for (size_t i = 0; st == QD_OK && i < w->n; i++)
        st = add_col(w, j, prefix, qd__sweep_coord(w, i));
    for (size_t i = 0; st == QD_OK && i < w->n; i++) {
        snprintf(name, sizeof name, "%s'", qd__sweep_coord(w, i));
        st = add_col(w, j, prefix, name);
    }
    return st;
}

static qd_status measure_cols(qd_sweep *w, qd__sw_ms *x, size_t *j) {
    char name[32];
    x->first = *j;
    qd_status st = QD_OK;
    switch (x->kind) {
    case QD__MS_FINAL:
        st = state_cols(w, j, "final_");
        break;
    case QD__MS_EVENT:
        st = add_col(w, j, "event_t", "");
        st = st == QD_OK ? state_cols(w, j, "event_") : st;
        break;
    case QD__MS_LYAP:
        st = add_col(w, j, "lyapunov", "");
        st = st == QD_OK ? add_col(w, j, "lyapunov_error", "") : st;
        break;
    case QD__MS_LYAPSPEC:
        for (size_t i = 0; st == QD_OK && i < 2 * w->n; i++) {
            snprintf(name, sizeof name, "lyapunov_%zu", i + 1);
            st = add_col(w, j, name, "");
        }
        break;
    default:
        st = add_col(w, j, x->text, "");
    }
    x->ncols = *j - x->first;
    return st;
}

/* Two passes: count, then name. */
qd_status qd__sweep_columns(qd_sweep *w) {
    free_columns(w);
    qd_status st = QD_OK;
    for (int pass = 0; pass < 2 && st == QD_OK; pass++) {
        size_t j = 0;
        for (size_t k = 0; st == QD_OK && k < w->nin; k++)
            st = add_col(w, &j, w->in[k].name, "");
        for (size_t k = 0; st == QD_OK && k < w->nms; k++)
            st = measure_cols(w, &w->ms[k], &j);
        if (pass == 0) {
            w->cols = qd__calloc(w->ctx, j + 1, sizeof *w->cols);
            st = w->cols ? QD_OK : QD_ERR_NOMEM;
        } else {
            w->ncols = j;
        }
    }
    return st;
}

/* ---- accessors ------------------------------------------------------------- */

static qd_status event_index(qd_sweep *w, size_t k, const char *what) {
    if (k < qd_sim_nevents(w->s))
        return QD_OK;
    qd_ctx_error(w->ctx, QD_ERR_ARG, "%s: event %zu, but the simulation has %zu", what, k,
                 qd_sim_nevents(w->s));
    return QD_ERR_ARG;
}

qd_status qd_sweep_set_event(qd_sweep *w, size_t k) {
    QD_ARGS(QD_ERR_ARG, w);
    qd_status st = event_index(w, k, "the measure event");
    if (st == QD_OK)
        w->event = k;
    return st;
}

qd_status qd_sweep_set_section(qd_sweep *w, size_t k) {
    QD_ARGS(QD_ERR_ARG, w);
    qd_status st = event_index(w, k, "the section");
    if (st == QD_OK) {
        w->section = k;
        w->has_section = true;
    }
    return st;
}

qd_status qd_sweep_set_lyap(qd_sweep *w, const qd_lyap *l, const qd_lyap_opts *lo) {
    QD_ARGS(QD_ERR_ARG, w && l);
    if (l && qd_lyap_ndof(l) != w->n) {
        qd_ctx_error(w->ctx, QD_ERR_ARG, "the Lyapunov system has %zu degrees of freedom, the "
                     "simulation %zu", qd_lyap_ndof(l), w->n);
        return QD_ERR_ARG;
    }
    w->lyap = l;
    w->lyap_opts = lo ? *lo : (qd_lyap_opts){0};
    return QD_OK;
}

size_t qd_sweep_nruns(const qd_sweep *w) { QD_ARGS(0, w); return w->nruns; }
size_t qd_sweep_ninputs(const qd_sweep *w) { QD_ARGS(0, w); return w->nin; }
size_t qd_sweep_ncols(const qd_sweep *w) { QD_ARGS(0, w); return w->ncols; }
const char *qd_sweep_col(const qd_sweep *w, size_t j) {
    QD_ARGS(NULL, w);
    return j < w->ncols && w->cols ? w->cols[j] : NULL;
}

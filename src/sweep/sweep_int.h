/*
 * src/sweep/sweep_int.h - what the sweep's files share: the inputs a run
 * varies, the runs (grid, random draw or list), the measures and their
 * columns.
 */
#ifndef QD_SWEEP_INT_H
#define QD_SWEEP_INT_H

#include "qdot/eval.h"
#include "qdot/sweep.h"

typedef enum qd__sw_kind { QD__SW_Q, QD__SW_QD, QD__SW_PAR } qd__sw_kind;

/* One input of the runs: what it sets, and its axis. */
typedef struct qd__sw_in {
    char *name;
    qd__sw_kind kind;
    size_t index;      /* in q0 / qd0 (the equations' order) or in the parameters */
    double a, b;       /* grid and random: the range */
    size_t npts;       /* grid: points on the axis */
} qd__sw_in;

typedef enum qd__sw_how { QD__SW_NONE, QD__SW_GRID, QD__SW_RANDOM, QD__SW_LIST } qd__sw_how;

typedef enum qd__ms_kind {
    QD__MS_FINAL, QD__MS_ENERGY, QD__MS_EVENT, QD__MS_ESCAPE, QD__MS_MAX, QD__MS_MIN,
    QD__MS_PCOUNT, QD__MS_LYAP, QD__MS_LYAPSPEC
} qd__ms_kind;

/* One measure: its kind, the column of the run it reads (escape, max, min:
 * found by name per method) and its first column in a sweep's row. */
typedef struct qd__sw_ms {
    qd__ms_kind kind;
    char *text;        /* as written (the column name of escape, max, min) */
    char *col;         /* escape, max, min: the run's column read */
    int sign;          /* escape: +1 for COL > VAL, -1 for COL < VAL */
    double val;
    size_t first, ncols;
} qd__sw_ms;

struct qd_sweep {
    qd_ctx *ctx;
    const qd_sim *s;
    const qd_model *m;
    size_t n;          /* degrees of freedom (q0, qd0 entries) */
    size_t np;         /* the model's parameters */
    double *par0;      /* their values in the model */
    /* the inputs and the runs */
    qd__sw_how how;
    qd__sw_in *in;
    size_t nin, nruns;
    uint64_t seed;
    double *list;      /* QD__SW_LIST: nruns * nin values */
    /* the parameters of a run from the swept ones (definitions followed):
     * inputs all np parameter symbols, outputs their values; NULL when no
     * parameter is swept */
    qd_prog *parprog;
    /* the measures and the column names (inputs then measures) */
    qd__sw_ms *ms;
    size_t nms;
    char **cols;
    size_t ncols;
    size_t event, section;
    bool has_section;
    const qd_lyap *lyap;   /* the measures lyapunov, lyapunov-spectrum */
    qd_lyap *own_lyap;     /* lyap when qd_sweep_setup_new made it (freed with w) */
    qd_lyap_opts lyap_opts;
};

/* Names of the coordinates (n) and velocities as the system's columns give
 * them: column 1 + i and the column named "NAME'". */
const char *qd__sweep_coord(const qd_sweep *w, size_t i);

/* Parse a list of "NAME=A:B[:N]" items into w->in (grid: with N).
 * QD_ERR_PARSE or QD_ERR_ARG, located in spec, reason in w->ctx. */
qd_status qd__sweep_parse_axes(qd_sweep *w, const char *spec, bool grid);
/* One input name resolved (coordinate, velocity NAME', parameter); text
 * (may be NULL) and off locate an error. */
qd_status qd__sweep_resolve(qd_sweep *w, qd__sw_in *x, const char *text, size_t off);
/* Rebuild w->parprog for the parameters among w->in. */
qd_status qd__sweep_params(qd_sweep *w);
/* The column names after a change of inputs or measures. */
qd_status qd__sweep_columns(qd_sweep *w);
void qd__sweep_free_inputs(qd_sweep *w);
void qd__sweep_free_measures(qd_sweep *w);

/* Whether the sweep can run: runs, measures, and what they need (an
 * event, a section); QD_ERR_ARG with the reason in ctx. */
qd_status qd__sweep_ready(qd_ctx *ctx, const qd_sweep *w);

/* Some method's run of s has a column of that name. */
bool qd__sweep_is_column(const qd_sim *s, const char *name);

/* Run i's input values (w->nin numbers). */
void qd__sweep_inputs_of(const qd_sweep *w, size_t i, double *x);

#endif

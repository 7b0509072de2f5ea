/*
 * src/sweep/spec.c - reading a sweep's specs: the axes "NAME=A:B[:N], ..."
 * of a grid or a random draw, and the measures "final, max:EXPR, ...".
 * Every error is located in the text it was read from (qd_ctx_error_at),
 * so the CLI can draw the caret under the item at fault.
 */
#include "sweep_int.h"

#include <ctype.h>
#include <math.h>
#include <string.h>

#include "base/mem.h"
#include "qdot/read.h"
#include "../base/args.h"

/* [*a, *b) without the spaces at either end. */
static void trim(const char *text, size_t *a, size_t *b) {
    while (*a < *b && isspace((unsigned char)text[*a]))
        (*a)++;
    while (*b > *a && isspace((unsigned char)text[*b - 1]))
        (*b)--;
}

/* The error just recorded is about text[a, b). */
static qd_status at(qd_ctx *ctx, qd_status st, const char *text, size_t a, size_t b) {
    qd_ctx_error_about(ctx, QD_SUBJECT_TEXT, 0, NULL, QD_REASON_NONE, NULL);
    qd_ctx_error_at(ctx, text, a, b > a ? b - a : 1);
    return st;
}

#define FAIL_AT(ctx, st, text, a, b, ...) \
    (qd_ctx_error((ctx), (st), __VA_ARGS__), at((ctx), (st), (text), (a), (b)))

/* End of the item starting at p: the next comma outside brackets. */
static size_t item_end(const char *text, size_t p) {
    int depth = 0;
    for (; text[p]; p++) {
        if (text[p] == '(' || text[p] == '[')
            depth++;
        else if ((text[p] == ')' || text[p] == ']') && depth > 0)
            depth--;
        else if (text[p] == ',' && depth == 0)
            break;
    }
    return p;
}

/* A constant expression text[a, b) ("-pi/2", "0.5") as a number. */
static qd_status number(qd_sweep *w, const char *text, size_t a, size_t b, double *x) {
    char buf[128];
    trim(text, &a, &b);
    if (a == b || b - a >= sizeof buf)
        return FAIL_AT(w->ctx, QD_ERR_PARSE, text, a, b, "expected a number");
    memcpy(buf, text + a, b - a);
    buf[b - a] = '\0';
    qd_diag d;
    const qd_read_opts opts = {.new_symbols = false};
    const qd_expr *e = qd_read(w->ctx, buf, &opts, &d);
    if (e && qd_eval(w->ctx, e, 0, NULL, NULL, x) == QD_OK && isfinite(*x))
        return QD_OK;
    qd_ctx_clear_error(w->ctx);
    return FAIL_AT(w->ctx, QD_ERR_PARSE, text, a, b, "'%s' is not a number", buf);
}

/* The points of a grid axis: a whole number >= 1. */
static qd_status count(qd_sweep *w, const char *text, size_t a, size_t b, size_t *npts) {
    trim(text, &a, &b);
    size_t k = 0, p = a;
    for (; p < b && isdigit((unsigned char)text[p]) && k < ((size_t)1 << 40); p++)
        k = 10 * k + (size_t)(text[p] - '0');
    if (a == b || p < b)
        return FAIL_AT(w->ctx, QD_ERR_PARSE, text, a, b,
                       "the points of an axis are a whole number, as in x=0:1:5");
    if (k == 0)
        return FAIL_AT(w->ctx, QD_ERR_ARG, text, a, b,
                       "an axis needs at least one point (N = 0)");
    *npts = k;
    return QD_OK;
}

/* Where the item's ':' separators are: up to three fields. */
static size_t fields(const char *text, size_t a, size_t b, size_t *cut) {
    size_t k = 0;
    for (size_t p = a; p < b; p++)
        if (text[p] == ':') {
            if (k == 3)
                return 4;
            cut[k++] = p;
        }
    return k;
}

static qd_status add_input(qd_sweep *w, const char *text, size_t a, size_t b, qd__sw_in **x) {
    trim(text, &a, &b);
    if (a == b)
        return FAIL_AT(w->ctx, QD_ERR_PARSE, text, a, b, "expected NAME=A:B before '='");
    qd__sw_in *grown = qd__realloc(w->ctx, w->in, (w->nin + 1) * sizeof *grown);
    if (!grown)
        return QD_ERR_NOMEM;
    w->in = grown;
    *x = &w->in[w->nin];
    **x = (qd__sw_in){.name = qd__malloc(w->ctx, b - a + 1)};
    if (!(*x)->name)
        return QD_ERR_NOMEM;
    memcpy((*x)->name, text + a, b - a);
    (*x)->name[b - a] = '\0';
    w->nin++;
    qd_status st = qd__sweep_resolve(w, *x, text, a);
    for (size_t k = 0; st == QD_OK && k + 1 < w->nin; k++)
        if (w->in[k].kind == (*x)->kind && w->in[k].index == (*x)->index)
            return FAIL_AT(w->ctx, QD_ERR_ARG, text, a, b, "%s is given twice", (*x)->name);
    return st;
}

/* One item NAME=A:B[:N] at text[a, b). */
static qd_status axis(qd_sweep *w, const char *text, size_t a, size_t b, bool grid) {
    const char *eq = memchr(text + a, '=', b - a);
    if (!eq)
        return FAIL_AT(w->ctx, QD_ERR_PARSE, text, a, b,
                       grid ? "expected NAME=A:B:N" : "expected NAME=A:B");
    size_t e = (size_t)(eq - text), cut[4];
    qd__sw_in *x = NULL;
    qd_status st = add_input(w, text, a, e, &x);
    if (st != QD_OK)
        return st;
    size_t nf = fields(text, e + 1, b, cut);
    if (nf != (grid ? 2u : 1u))
        return FAIL_AT(w->ctx, QD_ERR_PARSE, text, e + 1, b,
                       grid ? "expected A:B:N after '=' (from A to B in N points)"
                            : "expected A:B after '=' (uniform between A and B)");
    st = number(w, text, e + 1, cut[0], &x->a);
    if (st == QD_OK)
        st = number(w, text, cut[0] + 1, grid ? cut[1] : b, &x->b);
    if (st == QD_OK && grid)
        st = count(w, text, cut[1] + 1, b, &x->npts);
    if (st == QD_OK && x->a > x->b && (!grid || x->npts > 1))
        return FAIL_AT(w->ctx, QD_ERR_ARG, text, e + 1, b,
                       "the axis of %s runs backwards (A > B)", x->name);
    return st;
}

qd_status qd__sweep_parse_axes(qd_sweep *w, const char *spec, bool grid) {
    size_t p = 0;
    qd_status st = QD_OK;
    while (st == QD_OK && spec[p]) {
        size_t e = item_end(spec, p), a = p, b = e;
        trim(spec, &a, &b);
        st = a < b ? axis(w, spec, a, b, grid)
                   : FAIL_AT(w->ctx, QD_ERR_PARSE, spec, p, e + 1, "an empty item");
        p = spec[e] ? e + 1 : e;
    }
    if (st == QD_OK && w->nin == 0)
        return FAIL_AT(w->ctx, QD_ERR_PARSE, spec, 0, 1,
                       grid ? "no axes: expected NAME=A:B:N, ..." : "no axes: expected NAME=A:B, ...");
    return st;
}

/* ---- names ----------------------------------------------------------------- */

static bool find_coord(const qd_sweep *w, const char *name, size_t len, size_t *k) {
    for (size_t i = 0; i < w->n; i++) {
        const char *c = qd__sweep_coord(w, i);
        if (strlen(c) == len && !strncmp(c, name, len)) {
            *k = i;
            return true;
        }
    }
    return false;
}

static bool find_param(const qd_sweep *w, const char *name, size_t *k) {
    for (size_t i = 0; i < w->np; i++)
        if (!strcmp(qd_expr_name(qd_model_param(w->m, i)), name)) {
            *k = i;
            return true;
        }
    return false;
}

qd_status qd__sweep_resolve(qd_sweep *w, qd__sw_in *x, const char *text, size_t off) {
    size_t len = strlen(x->name), end = off + len;
    if (len > 1 && x->name[len - 1] == '\'' && find_coord(w, x->name, len - 1, &x->index)) {
        x->kind = QD__SW_QD;
        return QD_OK;
    }
    if (find_coord(w, x->name, len, &x->index)) {
        x->kind = QD__SW_Q;
        return QD_OK;
    }
    if (find_param(w, x->name, &x->index)) {
        x->kind = QD__SW_PAR;
        if (!qd_model_param_fixed(w->m, x->index))
            return QD_OK;
        qd_ctx_error(w->ctx, QD_ERR_ARG, "parameter %s is fixed in the equations: it cannot vary",
                     x->name);
    } else {
        qd_ctx_error(w->ctx, QD_ERR_ARG, "unknown name '%s' (a sweep varies coordinates, "
                     "velocities NAME' and parameters)", x->name);
    }
    if (text)
        at(w->ctx, QD_ERR_ARG, text, off, end);
    return QD_ERR_ARG;
}

/* ---- measures -------------------------------------------------------------- */

static const struct {
    const char *name;
    qd__ms_kind kind;
} plain[] = {
    {"final", QD__MS_FINAL},          {"energy_error", QD__MS_ENERGY},
    {"event", QD__MS_EVENT},          {"poincare-count", QD__MS_PCOUNT},
    {"lyapunov", QD__MS_LYAP},        {"lyapunov-spectrum", QD__MS_LYAPSPEC},
};

/* Some method's run of s has a column of that name. */
bool qd__sweep_is_column(const qd_sim *s, const char *name) {
    const char *names[512];
    for (int k = 0; k < QD_SIM_METHOD_COUNT; k++) {
        size_t nc = qd_sim_columns(s, (qd_sim_method)k, names, 512);
        for (size_t j = 0; j < nc && j < 512; j++)
            if (!strcmp(names[j], name))
                return true;
    }
    return false;
}

static char *copy(qd_ctx *ctx, const char *text, size_t a, size_t b) {
    char *c = qd__malloc(ctx, b - a + 1);
    if (c) {
        memcpy(c, text + a, b - a);
        c[b - a] = '\0';
    }
    return c;
}

/* The column COL of "max:COL", "min:COL", "escape:COL>VAL" at text[a, b). */
static qd_status column_arg(qd_sweep *w, qd__sw_ms *x, const char *text, size_t a, size_t b) {
    trim(text, &a, &b);
    x->col = copy(w->ctx, text, a, b);
    if (!x->col)
        return QD_ERR_NOMEM;
    if (a < b && qd__sweep_is_column(w->s, x->col))
        return QD_OK;
    return FAIL_AT(w->ctx, QD_ERR_ARG, text, a, b,
                   "'%s' is not a column of the run (a coordinate, a velocity NAME', energy, "
                   "or an output: qdot sweep adds EXPR as an --output)", x->col);
}

/* "escape:COL>VAL" or "escape:COL<VAL" after the colon at text[a, b). */
static qd_status escape(qd_sweep *w, qd__sw_ms *x, const char *text, size_t a, size_t b) {
    size_t c = b;
    while (c > a && text[c - 1] != '>' && text[c - 1] != '<')
        c--;
    if (c == a)
        return FAIL_AT(w->ctx, QD_ERR_PARSE, text, a, b,
                       "expected escape:EXPR>VALUE or escape:EXPR<VALUE");
    x->sign = text[c - 1] == '>' ? 1 : -1;
    qd_status st = number(w, text, c, b, &x->val);
    return st == QD_OK ? column_arg(w, x, text, a, c - 1) : st;
}

static qd_status measure(qd_sweep *w, const char *text, size_t a, size_t b) {
    qd__sw_ms *grown = qd__realloc(w->ctx, w->ms, (w->nms + 1) * sizeof *grown);
    if (!grown)
        return QD_ERR_NOMEM;
    w->ms = grown;
    qd__sw_ms *x = &w->ms[w->nms++];
    *x = (qd__sw_ms){.text = copy(w->ctx, text, a, b)};
    if (!x->text)
        return QD_ERR_NOMEM;
    for (size_t k = 0; k < sizeof plain / sizeof *plain; k++)
        if (!strcmp(x->text, plain[k].name)) {
            x->kind = plain[k].kind;
            return QD_OK;
        }
    const char *colon = memchr(text + a, ':', b - a);
    size_t c = colon ? (size_t)(colon - text) : b, h = a, t = c;
    trim(text, &h, &t);
    if (colon && t - h == 3 && !strncmp(text + h, "max", 3)) {
        x->kind = QD__MS_MAX;
        return column_arg(w, x, text, c + 1, b);
    }
    if (colon && t - h == 3 && !strncmp(text + h, "min", 3)) {
        x->kind = QD__MS_MIN;
        return column_arg(w, x, text, c + 1, b);
    }
    if (colon && t - h == 6 && !strncmp(text + h, "escape", 6)) {
        x->kind = QD__MS_ESCAPE;
        return escape(w, x, text, c + 1, b);
    }
    return FAIL_AT(w->ctx, QD_ERR_ARG, text, a, b,
                   "unknown measure '%s' (final, energy_error, event, escape:EXPR>VALUE, "
                   "max:EXPR, min:EXPR, poincare-count, lyapunov, lyapunov-spectrum)", x->text);
}

qd_status qd_sweep_measures(qd_sweep *w, const char *spec) {
    QD_ARGS(QD_ERR_ARG, w && spec);
    qd__sweep_free_measures(w);
    size_t p = 0;
    qd_status st = QD_OK;
    while (st == QD_OK && spec[p]) {
        size_t e = item_end(spec, p), a = p, b = e;
        trim(spec, &a, &b);
        st = a < b ? measure(w, spec, a, b)
                   : FAIL_AT(w->ctx, QD_ERR_PARSE, spec, p, e + 1, "an empty item");
        p = spec[e] ? e + 1 : e;
    }
    if (st == QD_OK && w->nms == 0)
        st = FAIL_AT(w->ctx, QD_ERR_PARSE, spec, 0, 1, "no measures");
    if (st == QD_OK)
        st = qd__sweep_columns(w);
    if (st != QD_OK)
        qd__sweep_free_measures(w);
    return st;
}

/* ---- what the measures need before the run is compiled ---------------------- */

/* The needs of the measure text[a, b) (trimmed) into out (at most two: an
 * escape's output and crossing), as measure() reads it; its flag into
 * *flags.  Malformed text needs nothing: qd_sweep_measures says why. */
static size_t item_needs(const char *text, size_t a, size_t b, qd_sweep_need out[2],
                         unsigned *flags) {
    static const struct {
        const char *name;
        unsigned flag;
    } flagged[] = {{"event", QD_SWEEP_NEEDS_EVENT},
                   {"poincare-count", QD_SWEEP_NEEDS_SECTION},
                   {"lyapunov", QD_SWEEP_NEEDS_LYAP},
                   {"lyapunov-spectrum", QD_SWEEP_NEEDS_LYAP}};
    for (size_t k = 0; k < sizeof flagged / sizeof *flagged; k++)
        if (b - a == strlen(flagged[k].name) && !strncmp(text + a, flagged[k].name, b - a)) {
            *flags |= flagged[k].flag;
            return 0;
        }
    const char *colon = memchr(text + a, ':', b - a);
    if (!colon)
        return 0;
    size_t c = (size_t)(colon - text), h = a, t = c;
    trim(text, &h, &t);
    bool escape = t - h == 6 && !strncmp(text + h, "escape", 6);
    if (!escape && !(t - h == 3 && (!strncmp(text + h, "max", 3) || !strncmp(text + h, "min", 3))))
        return 0;
    size_t e0 = c + 1, e1 = b, v0 = b, v1 = b;
    if (escape) { /* EXPR before the last '>' or '<', VALUE after it */
        while (e1 > e0 && text[e1 - 1] != '>' && text[e1 - 1] != '<')
            e1--;
        if (e1 == e0)
            return 0;
        v0 = e1--;
        trim(text, &v0, &v1);
    }
    trim(text, &e0, &e1);
    if (e0 == e1 || (escape && v0 == v1))
        return 0;
    out[0] = (qd_sweep_need){QD_SWEEP_NEED_OUTPUT, e0, e1, 0, 0};
    out[1] = (qd_sweep_need){QD_SWEEP_NEED_CROSSING, e0, e1, v0, v1};
    return escape ? 2 : 1;
}

/* Calls f(spec, a, b, data) for each item spec[a, b) of spec, trimmed and
 * not empty, with a < end, until f returns false. */
static void each_item(const char *spec, size_t end,
                      bool (*f)(const char *spec, size_t a, size_t b, void *data), void *data) {
    for (size_t p = 0; spec[p];) {
        size_t e = item_end(spec, p), a = p, b = e;
        trim(spec, &a, &b);
        if (a >= end || (a < b && !f(spec, a, b, data)))
            return;
        p = spec[e] ? e + 1 : e;
    }
}

typedef struct needs_acc {
    const qd_sim *s;
    qd_sweep_need *needs;
    size_t cap, n;
    unsigned flags;
    size_t e0, e1; /* same_output: the EXPR looked for */
    bool found;
} needs_acc;

static bool same_output(const char *spec, size_t a, size_t b, void *data) {
    needs_acc *q = data;
    qd_sweep_need x[2];
    unsigned flags = 0;
    if (item_needs(spec, a, b, x, &flags) && x[0].e1 - x[0].e0 == q->e1 - q->e0 &&
        !strncmp(spec + x[0].e0, spec + q->e0, q->e1 - q->e0))
        q->found = true;
    return !q->found;
}

/* EXPR spec[e0, e1) of the item at a is a column of s already, or the
 * output of an item before it. */
static bool has_output(const qd_sim *s, const char *spec, size_t a, size_t e0, size_t e1) {
    char name[512];
    if (s && e1 - e0 < sizeof name) {
        memcpy(name, spec + e0, e1 - e0);
        name[e1 - e0] = '\0';
        if (qd__sweep_is_column(s, name))
            return true;
    }
    needs_acc q = {.e0 = e0, .e1 = e1};
    each_item(spec, a, same_output, &q);
    return q.found;
}

static bool add_needs(const char *spec, size_t a, size_t b, void *data) {
    needs_acc *q = data;
    qd_sweep_need x[2];
    size_t k = item_needs(spec, a, b, x, &q->flags);
    for (size_t j = 0; j < k; j++) {
        if (x[j].kind == QD_SWEEP_NEED_OUTPUT && has_output(q->s, spec, a, x[j].e0, x[j].e1))
            continue;
        if (q->n < q->cap)
            q->needs[q->n] = x[j];
        q->n++;
    }
    return true;
}

size_t qd_sweep_needs(const qd_sim *s, const char *spec, qd_sweep_need *needs, size_t cap,
                      unsigned *flags) {
    QD_ARGS(0, spec && (needs || cap == 0) && flags);
    needs_acc q = {.s = s, .needs = needs, .cap = cap};
    each_item(spec, (size_t)-1, add_needs, &q);
    *flags = q.flags;
    return q.n;
}

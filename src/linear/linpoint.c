/*
 * src/linear/linpoint.c - the point of a linear analysis, read against the
 * equations' coordinates (qdot/linpoint.h).  The model's state reader does
 * the reading and locates the errors; this file maps the model's slots to
 * e->q, the equations' order, which may leave out eliminated coordinates.
 */
#include "qdot/linpoint.h"

#include <stdint.h>
#include <string.h>

#include "../base/args.h"
#include "../base/mem.h"

qd_status qd_linpoint_init(qd_ctx *ctx, const qd_model *m, const qd_eom *e, qd_linpoint *out) {
    QD_ARGS_CTX(ctx, ctx && m && e && out);
    memset(out, 0, sizeof *out);
    out->m = m;
    out->e = e;
    qd_status st = qd_state_init(ctx, m, &out->st);
    if (st != QD_OK)
        return st;
    if (!(out->slot = qd__calloc(ctx, e->n + 1, sizeof *out->slot)))
        return QD_ERR_NOMEM;
    size_t nq = qd_model_ncoords(m);
    for (size_t j = 0; j < e->n; j++) {
        size_t i = qd_state_find(&out->st, e->q[j]);
        if (i >= nq) {
            qd_ctx_error(ctx, QD_ERR_ARG, "coordinate %s of the equations is not in the model",
                         qd_expr_name(e->q[j]));
            return QD_ERR_ARG;
        }
        out->slot[j] = i;
    }
    return QD_OK;
}

void qd_linpoint_free(qd_linpoint *p) {
    if (!p)
        return;
    qd_state_free(&p->st);
    qd__free(p->slot);
    p->slot = NULL;
}

void qd_linpoint_set(qd_linpoint *p, const double *q, const double *qd) {
    if (!p || !q || !p->slot)
        return;
    size_t nq = qd_model_ncoords(p->m);
    for (size_t j = 0; j < p->e->n; j++) {
        p->st.vals[qd_slot_coord(nq, p->slot[j])] = q[j];
        p->st.vals[qd_slot_velocity(nq, p->slot[j])] = qd ? qd[j] : 0;
    }
}

/* A working copy of p's state and the reader's marks of the slots named,
 * so that reading leaves p as it is. */
typedef struct scratch {
    qd_state st;
    bool *given;
    const qd_expr **exact;
} scratch;

static qd_status scratch_init(qd_ctx *ctx, const qd_linpoint *p, scratch *s) {
    size_t ns = p->st.n;
    s->st = (qd_state){ns, p->st.syms, qd__malloc(ctx, (ns + 1) * sizeof *s->st.vals)};
    s->given = qd__calloc(ctx, ns + 1, sizeof *s->given);
    s->exact = qd__calloc(ctx, ns + 1, sizeof *s->exact);
    if (!s->st.vals || !s->given || !s->exact)
        return QD_ERR_NOMEM;
    memcpy(s->st.vals, p->st.vals, ns * sizeof *s->st.vals);
    return QD_OK;
}

static void scratch_free(scratch *s) {
    qd__free(s->st.vals);
    qd__free(s->given);
    qd__free(s->exact);
}

/* The reader's options: the equations' coordinates independent, t and the
 * parameters refused, and what else refuse adds. */
static qd_state_read_opts read_opts(const qd_linpoint *p, unsigned refuse, scratch *s) {
    return (qd_state_read_opts){.refuse = QD_STATE_TIME | QD_STATE_PARAMS | refuse,
                                .independent = p->e->q, .nindependent = p->e->n,
                                .given = s->given, .exact = s->exact};
}

qd_status qd_linpoint_read(qd_ctx *ctx, const qd_linpoint *p, const char *text, double *q,
                           double *qd) {
    QD_ARGS_CTX(ctx, ctx && p && p->slot && text && q);
    scratch s = {0};
    qd_status st = scratch_init(ctx, p, &s);
    qd_state_read_opts o = read_opts(p, qd ? 0 : QD_STATE_VELOCITIES, &s);
    if (st == QD_OK)
        st = qd_state_read(ctx, p->m, &s.st, text, &o);
    size_t nq = qd_model_ncoords(p->m);
    for (size_t j = 0; st == QD_OK && j < p->e->n; j++) {
        size_t c = qd_slot_coord(nq, p->slot[j]), v = qd_slot_velocity(nq, p->slot[j]);
        if (s.given[c])
            q[j] = s.st.vals[c];
        if (qd && s.given[v])
            qd[j] = s.st.vals[v];
    }
    scratch_free(&s);
    return st;
}

qd_status qd_linpoint_read_coords(qd_ctx *ctx, const qd_linpoint *p, const char *text,
                                  double *q) {
    QD_ARGS_CTX(ctx, ctx && p && text && q);
    for (size_t j = 0; j < p->e->n; j++)
        q[j] = 0;
    return qd_linpoint_read(ctx, p, text, q, NULL);
}

qd_status qd_linpoint_read_box(qd_ctx *ctx, const qd_linpoint *p, const char *text, double *lo,
                               double *hi) {
    QD_ARGS_CTX(ctx, ctx && p && p->slot && text && lo && hi);
    size_t ns = p->st.n;
    scratch s = {0};
    double *l = qd__malloc(ctx, (ns + 1) * sizeof *l), *h = qd__malloc(ctx, (ns + 1) * sizeof *h);
    qd_status st = l && h ? scratch_init(ctx, p, &s) : QD_ERR_NOMEM;
    qd_state_read_opts o = read_opts(p, QD_STATE_VELOCITIES | QD_STATE_EXTRA, &s);
    o.exact = NULL;
    if (st == QD_OK)
        st = qd_state_read_ranges(ctx, p->m, &p->st, text, &o, l, h);
    for (size_t j = 0; st == QD_OK && j < p->e->n; j++)
        if (s.given[p->slot[j]]) {
            lo[j] = l[p->slot[j]];
            hi[j] = h[p->slot[j]];
        }
    scratch_free(&s);
    qd__free(l);
    qd__free(h);
    return st;
}

qd_status qd_linpoint_read_exact(qd_ctx *ctx, const qd_linpoint *p, const char *text,
                                 const qd_expr **about) {
    QD_ARGS_CTX(ctx, ctx && p && p->slot && text && about);
    /* the model layer's reader of such a point (qdot/state.h), on the
     * equations' coordinates */
    return qd_state_read_point(ctx, p->m, &p->st, text, p->e->n, p->e->q, about);
}

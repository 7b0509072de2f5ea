/*
 * src/num/contour.c - a level set of gridded values: marching squares, with
 * the segments joined into polylines (qd_contour_grid, qdot/contour.h).
 *
 * Each cell's corners are marked above (f > level) or not; an edge whose
 * ends differ is crossed once, at the linear interpolate.  A cell has 0, 2
 * or 4 crossed edges; with 4 (a saddle cell: opposite corners alike) the
 * mean of the corners decides which pair of corners the level set
 * separates, so the curves never cross (Lorensen and Cline's ambiguity,
 * resolved by the centre value as in most contouring codes).  Every edge
 * belongs to at most two cells, hence to at most two segments: the
 * polylines are found by walking from segment to segment through shared
 * edges.
 */
#include "qdot/contour.h"
#include "base/mem.h"
#include "../base/args.h"

#include <math.h>
#include <stdint.h>
#include <string.h>

/* The grid, the crossing point of each edge and the segments. */
typedef struct march {
    qd_ctx *ctx;
    size_t nx, ny;
    const double *f;
    double x0, dx, y0, dy, level;
    size_t nh;               /* horizontal edges: nx (ny + 1); vertical ones follow */
    double *ex, *ey;         /* per edge: the crossing (when crossed) */
    size_t *seg;             /* 2 per segment: the edges it joins */
    size_t nseg;
    size_t *at;              /* 2 per edge: the segments on it (SIZE_MAX: none) */
} march;

static double fv(const march *m, size_t i, size_t j) {
    return m->f[i + j * (m->nx + 1)];
}

static size_t hedge(const march *m, size_t i, size_t j) {
    return j * m->nx + i;
}

static size_t vedge(const march *m, size_t i, size_t j) {
    return m->nh + j * (m->nx + 1) + i;
}

/* The crossing on the edge from grid point a to b (values fa, fb). */
static void crossing(march *m, size_t edge, size_t ia, size_t ja, size_t ib, size_t jb) {
    double fa = fv(m, ia, ja), fb = fv(m, ib, jb), t = (m->level - fa) / (fb - fa);
    double xa = m->x0 + m->dx * (double)ia, xb = m->x0 + m->dx * (double)ib;
    double ya = m->y0 + m->dy * (double)ja, yb = m->y0 + m->dy * (double)jb;
    m->ex[edge] = xa + t * (xb - xa);
    m->ey[edge] = ya + t * (yb - ya);
}

static void add_segment(march *m, size_t a, size_t b) {
    size_t s = m->nseg++;
    m->seg[2 * s] = a;
    m->seg[2 * s + 1] = b;
    m->at[2 * a + (m->at[2 * a] != SIZE_MAX)] = s;
    m->at[2 * b + (m->at[2 * b] != SIZE_MAX)] = s;
}

/* The segments of cell (i, j).  Corners 0..3: (i, j), (i+1, j), (i+1, j+1),
 * (i, j+1); edges 0..3: bottom, right, top, left (edge k joins corners k
 * and k + 1). */
static void cell(march *m, size_t i, size_t j) {
    double c[4] = {fv(m, i, j), fv(m, i + 1, j), fv(m, i + 1, j + 1), fv(m, i, j + 1)};
    size_t ci[4] = {i, i + 1, i + 1, i}, cj[4] = {j, j, j + 1, j + 1};
    size_t edge[4] = {hedge(m, i, j), vedge(m, i + 1, j), hedge(m, i, j + 1), vedge(m, i, j)};
    bool up[4];
    size_t cut[4], ncut = 0;
    for (int k = 0; k < 4; k++) {
        if (!isfinite(c[k]))
            return;
        up[k] = c[k] > m->level;
    }
    for (int k = 0; k < 4; k++)
        if (up[k] != up[(k + 1) % 4]) {
            crossing(m, edge[k], ci[k], cj[k], ci[(k + 1) % 4], cj[(k + 1) % 4]);
            cut[ncut++] = (size_t)k;
        }
    if (ncut == 2) {
        add_segment(m, edge[cut[0]], edge[cut[1]]);
    } else if (ncut == 4) {
        bool centre = (c[0] + c[1] + c[2] + c[3]) / 4 > m->level;
        if (centre == up[0]) {        /* corners 0 and 2 joined: cut off 1 and 3 */
            add_segment(m, edge[0], edge[1]);
            add_segment(m, edge[2], edge[3]);
        } else {                      /* cut off 0 and 2 */
            add_segment(m, edge[3], edge[0]);
            add_segment(m, edge[1], edge[2]);
        }
    }
}

/* ---- joining ------------------------------------------------------------------ */

/* A growable list of edges. */
typedef struct chain {
    size_t *e;
    size_t len, cap;
} chain;

static bool chain_push(qd_ctx *ctx, chain *c, size_t edge) {
    if (c->len == c->cap) {
        size_t cap = c->cap ? 2 * c->cap : 64;
        size_t *e = qd__realloc(ctx, c->e, cap * sizeof *e);
        if (!e)
            return false;
        c->e = e;
        c->cap = cap;
    }
    c->e[c->len++] = edge;
    return true;
}

/* Walk out through the edge `from` (an end of a segment already used),
 * marking segments used, pushing each edge reached after `from`.  Returns
 * false when out of memory. */
static bool walk(march *m, bool *used, size_t from, chain *c) {
    size_t cur = from;
    for (;;) {
        size_t next = SIZE_MAX;
        for (int k = 0; k < 2; k++) {
            size_t t = m->at[2 * cur + k];
            if (t != SIZE_MAX && !used[t])
                next = t;
        }
        if (next == SIZE_MAX)
            return true;
        used[next] = true;
        cur = m->seg[2 * next] == cur ? m->seg[2 * next + 1] : m->seg[2 * next];
        if (!chain_push(m->ctx, c, cur))
            return false;
    }
}

static qd_status emit(march *m, const chain *back, const chain *fwd, bool closed,
                      qd_contour *out) {
    size_t n = back->len + fwd->len, k = 0;
    qd_polyline *lines = qd__realloc(m->ctx, out->lines, (out->count + 1) * sizeof *lines);
    if (!lines)
        return QD_ERR_NOMEM;
    out->lines = lines;
    qd_polyline *p = &lines[out->count++];
    *p = (qd_polyline){0};
    p->x = qd__malloc(m->ctx, (n + 1) * sizeof *p->x);
    p->y = qd__malloc(m->ctx, (n + 1) * sizeof *p->y);
    if (!p->x || !p->y)
        return QD_ERR_NOMEM;
    for (size_t i = back->len; i-- > 0; k++) {
        p->x[k] = m->ex[back->e[i]];
        p->y[k] = m->ey[back->e[i]];
    }
    for (size_t i = 0; i < fwd->len; i++, k++) {
        p->x[k] = m->ex[fwd->e[i]];
        p->y[k] = m->ey[fwd->e[i]];
    }
    p->count = k;
    p->closed = closed;
    return QD_OK;
}

/* The polyline through segment s: forward from its second edge, then,
 * unless it closed, backward from its first.  A closed one comes back to
 * its first edge, so its first point ends it again. */
static qd_status trace(march *m, bool *used, size_t s, qd_contour *out) {
    chain fwd = {0}, back = {0};
    size_t a = m->seg[2 * s], b = m->seg[2 * s + 1];
    used[s] = true;
    qd_status st = chain_push(m->ctx, &back, a) && chain_push(m->ctx, &fwd, b) &&
                   walk(m, used, b, &fwd) ? QD_OK : QD_ERR_NOMEM;
    bool closed = st == QD_OK && fwd.len > 1 && fwd.e[fwd.len - 1] == a;
    if (st == QD_OK && !closed && !walk(m, used, a, &back))
        st = QD_ERR_NOMEM;
    if (st == QD_OK)
        st = emit(m, &back, &fwd, closed, out);
    qd__free(fwd.e);
    qd__free(back.e);
    return st;
}

/* ---- the level set -------------------------------------------------------------- */

qd_status qd_contour_grid(qd_ctx *ctx, size_t nx, size_t ny, const double *f, double x0,
                          double x1, double y0, double y1, double level, qd_contour *out) {
    QD_ARGS_CTX(ctx, ctx && (ny == 0 || f) && out);
    memset(out, 0, sizeof *out);
    if (!ctx || !f || nx == 0 || ny == 0 || !isfinite(level)) {
        if (ctx)
            qd_ctx_error(ctx, QD_ERR_ARG, "contour: a grid of at least one cell and a finite "
                         "level are needed");
        return QD_ERR_ARG;
    }
    march m = {.ctx = ctx, .nx = nx, .ny = ny, .f = f, .x0 = x0, .y0 = y0, .level = level,
               .dx = (x1 - x0) / (double)nx, .dy = (y1 - y0) / (double)ny};
    m.nh = nx * (ny + 1);
    size_t nedge = m.nh + (nx + 1) * ny, ncell = nx * ny;
    m.ex = qd__malloc(ctx, nedge * sizeof *m.ex);
    m.ey = qd__malloc(ctx, nedge * sizeof *m.ey);
    m.at = qd__malloc(ctx, 2 * nedge * sizeof *m.at);
    m.seg = qd__malloc(ctx, 4 * ncell * sizeof *m.seg);
    bool *used = NULL;
    qd_status st = m.ex && m.ey && m.at && m.seg ? QD_OK : QD_ERR_NOMEM;
    if (st == QD_OK) {
        for (size_t k = 0; k < 2 * nedge; k++)
            m.at[k] = SIZE_MAX;
        for (size_t j = 0; j < ny; j++)
            for (size_t i = 0; i < nx; i++)
                cell(&m, i, j);
        used = qd__calloc(ctx, m.nseg + 1, sizeof *used);
        st = used ? QD_OK : QD_ERR_NOMEM;
    }
    for (size_t s = 0; st == QD_OK && s < m.nseg; s++)
        if (!used[s])
            st = trace(&m, used, s, out);
    qd__free(used);
    qd__free(m.ex);
    qd__free(m.ey);
    qd__free(m.at);
    qd__free(m.seg);
    if (st != QD_OK) {
        qd_contour_free(out);
        qd_ctx_error(ctx, st, "out of memory tracing a contour");
    }
    return st;
}

void qd_contour_free(qd_contour *c) {
    if (!c)
        return;
    for (size_t i = 0; i < c->count; i++) {
        qd__free(c->lines[i].x);
        qd__free(c->lines[i].y);
    }
    qd__free(c->lines);
    memset(c, 0, sizeof *c);
}

/*
 * src/scene/page.c - the scene of a picture put together (qdot/scene.h):
 * the points' masses, the links (the springs asked for, then the rods of
 * the motion) with the drawing plane, the whole as the JSON a page plays,
 * and that page: the template page.html, embedded at build time
 * (cmake/embed.cmake), with the JSON in place of its marker.
 */
#include "qdot/scene.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/args.h"

qd_status qd_scene_masses(qd_ctx *ctx, const qd_scene_point *pts, size_t n, size_t nsyms,
                          const qd_expr *const *syms, const double *vals, double *mass) {
    QD_ARGS_CTX(ctx, (pts || !n) && mass && ((syms && vals) || !nsyms));
    for (size_t i = 0; i < n; i++) {
        mass[i] = 1; /* a named position: every one drawn alike */
        if (pts[i].mass) {
            qd_status st = qd_eval(ctx, pts[i].mass, nsyms, syms, vals, &mass[i]);
            if (st != QD_OK)
                return st;
        }
    }
    return QD_OK;
}

qd_status qd_scene_links(qd_ctx *ctx, const double *pos, size_t nframes, size_t npts,
                         const size_t *springs, size_t nsprings, qd_scene_link **links,
                         size_t *nlinks, int plane[2]) {
    QD_ARGS_CTX(ctx, pos && (springs || !nsprings) && links && nlinks && plane);
    *links = NULL;
    *nlinks = 0;
    qd_scene_shape sh;
    qd_status st = qd_scene_analyse(ctx, pos, nframes, npts, springs, nsprings, &sh);
    if (st != QD_OK) {
        qd_scene_shape_free(&sh);
        return st;
    }
    qd_scene_link *l = malloc((nsprings + sh.nrods + 1) * sizeof *l);
    if (!l) {
        qd_scene_shape_free(&sh);
        if (ctx)
            qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory linking the scene's points");
        return QD_ERR_NOMEM;
    }
    for (size_t k = 0; k < nsprings; k++)
        l[k] = (qd_scene_link){.a = springs[2 * k], .b = springs[2 * k + 1], .spring = true};
    for (size_t k = 0; k < sh.nrods; k++)
        l[nsprings + k] = (qd_scene_link){.a = sh.rods[k].a, .b = sh.rods[k].b};
    *links = l;
    *nlinks = nsprings + sh.nrods;
    plane[0] = sh.plane[0];
    plane[1] = sh.plane[1];
    qd_scene_shape_free(&sh);
    return QD_OK;
}

/* ---- JSON ----------------------------------------------------------------------- */

/* A string inside a <script>: no quote, backslash or '<' may end either. */
static void json_name(qd_buf *b, const char *name) {
    qd_buf_puts(b, "\"");
    for (const char *p = name ? name : ""; *p; p++)
        if (*p == '"' || *p == '\\' || *p == '<' || (unsigned char)*p < 0x20)
            qd_buf_printf(b, "\\u%04x", (unsigned char)*p);
        else
            qd_buf_putn(b, p, 1);
    qd_buf_puts(b, "\"");
}

/* Numbers to 7 digits: a picture needs no more, and the page stays small. */
static void json_numbers(qd_buf *b, const char *key, const double *v, size_t n) {
    qd_buf_printf(b, ",\"%s\":[", key);
    for (size_t i = 0; i < n; i++) {
        if (i)
            qd_buf_puts(b, ",");
        if (isfinite(v[i]))
            qd_buf_printf(b, "%.7g", v[i]);
        else
            qd_buf_puts(b, "null");
    }
    qd_buf_puts(b, "]");
}

/* A body's ground and shape, when it has them: ,"ground":[6],"shape":"rod","size":[l,0,0],"axis":2,... */
static void json_look(qd_buf *b, const qd_scene_look *l) {
    static const char *const names[] = {"", "rod", "disk", "ring", "sphere", "box"};
    if (l && l->has_ground)
        json_numbers(b, "ground", l->ground, 6);
    if (!l || l->shape <= QD_SHAPE_NONE || l->shape > QD_SHAPE_BOX)
        return;
    qd_buf_printf(b, ",\"shape\":\"%s\"", names[l->shape]);
    json_numbers(b, "size", l->size, 3);
    qd_buf_printf(b, ",\"axis\":%d,\"inferred\":%s", l->axis, l->inferred ? "true" : "false");
}

static long link_end(size_t i) {
    return i == QD_SCENE_ORIGIN ? -1 : (long)i;
}

qd_status qd_scene_json(const qd_scene *s, qd_buf *out) {
    QD_ARGS(QD_ERR_ARG, s && out && s->fr && (s->pts || !s->npts) && (s->mass || !s->npts) &&
                            (s->links || !s->nlinks) && (s->traces || !s->ntraces) &&
                            (s->walls || !s->nwalls));
    const qd_scene_frames *fr = s->fr;
    QD_ARGS(QD_ERR_ARG, (fr->t || !fr->nframes) && (fr->pos || !fr->nframes || !s->npts) &&
                            (fr->rot || !fr->nframes || !fr->nbodies));
    qd_buf_puts(out, "{\"model\":");
    json_name(out, s->model);
    qd_buf_puts(out, ",\"method\":");
    json_name(out, s->method);
    qd_buf_printf(out, ",\"plane\":[%d,%d],\"conservative\":%s,\"energy_error_max\":%.7g",
                  s->plane[0], s->plane[1], s->conservative ? "true" : "false",
                  s->energy_error_max);
    qd_buf_puts(out, ",\"points\":[");
    for (size_t i = 0; i < s->npts; i++) {
        qd_buf_puts(out, i ? ",{\"name\":" : "{\"name\":");
        json_name(out, s->pts[i].name);
        qd_buf_printf(out, ",\"body\":%s,\"mass\":%.7g",
                      s->pts[i].kind == QD_SCENE_BODY ? "true" : "false", s->mass[i]);
        json_look(out, s->looks ? &s->looks[i] : NULL);
        qd_buf_puts(out, "}");
    }
    qd_buf_puts(out, "],\"links\":[");
    for (size_t k = 0; k < s->nlinks; k++)
        qd_buf_printf(out, "%s[%ld,%ld,%d]", k ? "," : "", link_end(s->links[k].a),
                      link_end(s->links[k].b), s->links[k].spring);
    qd_buf_puts(out, "],\"traces\":[");
    for (size_t k = 0; k < s->ntraces; k++)
        qd_buf_printf(out, "%s%zu", k ? "," : "", s->traces[k]);
    qd_buf_puts(out, "],\"walls\":[");
    for (size_t k = 0; k < s->nwalls; k++)
        qd_buf_printf(out, "%s[%d,%.7g,%d]", k ? "," : "", s->walls[k].axis, s->walls[k].at,
                      s->walls[k].side);
    qd_buf_puts(out, "]");
    json_numbers(out, "t", fr->t, fr->nframes);
    if (fr->energy)
        json_numbers(out, "energy_error", fr->energy, fr->nframes);
    json_numbers(out, "pos", fr->pos, fr->nframes * s->npts * 3);
    json_numbers(out, "rot", fr->rot, fr->nframes * fr->nbodies * 9);
    qd_buf_puts(out, "}");
    return out->failed ? QD_ERR_NOMEM : QD_OK;
}

extern const unsigned char qd__scene_page_bytes[]; /* generated from page.html */

qd_status qd_scene_html(const qd_scene *s, qd_buf *out) {
    QD_ARGS(QD_ERR_ARG, s && out);
    static const char marker[] = "@QDOT_DATA@";
    const char *page = (const char *)qd__scene_page_bytes;
    const char *at = strstr(page, marker);
    if (!at)
        return QD_ERR_UNSUPPORTED; /* a build that embedded another file */
    qd_buf json = QD_BUF_WITH(out->alloc); /* first: a refused scene leaves out as it was */
    qd_status st = qd_scene_json(s, &json);
    if (st == QD_OK) {
        qd_buf_putn(out, page, (size_t)(at - page));
        qd_buf_putn(out, qd_buf_str(&json), json.len);
        qd_buf_puts(out, at + strlen(marker));
    }
    qd_buf_free(&json);
    return st == QD_OK && out->failed ? QD_ERR_NOMEM : st;
}

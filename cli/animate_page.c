/*
 * cli/animate_page.c - the scene of `qdot animate` analysed (the rods, the
 * drawing plane) and written into the page: the template animate_page.html,
 * embedded at build time (cmake/embed.cmake), with the scene as JSON in
 * place of its @QDOT_DATA@ marker.  docs/cli.md states the drawing rules.
 */
#include "animate.h"

#include <math.h>
#include <string.h>

#include "cli.h"

extern const unsigned char cli_animate_page_bytes[]; /* generated from animate_page.html */
#define cli_animate_page ((const char *)cli_animate_page_bytes)

#define FLAT 1e-9   /* an axis no point moves along, relative to the scene */
#define RIGID 1e-6  /* a distance that stays constant, relative to the scene */

static const double *pos(const an_scene *s, size_t f, size_t i) {
    return s->pos + (f * s->npts + i) * 3;
}

/* The largest extent of the motion along an axis, or distance from the
 * origin: the length the tolerances are relative to. */
static double scene_scale(const an_scene *s, double range[3]) {
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    double scale = 0;
    for (size_t f = 0; f < s->nframes; f++)
        for (size_t i = 0; i < s->npts; i++)
            for (int k = 0; k < 3; k++) {
                double x = pos(s, f, i)[k];
                lo[k] = fmin(lo[k], x);
                hi[k] = fmax(hi[k], x);
                scale = fmax(scale, fabs(x));
            }
    for (int k = 0; k < 3; k++) {
        range[k] = hi[k] - lo[k];
        scale = fmax(scale, range[k]);
    }
    return scale > 0 ? scale : 1;
}

/* A plane when some axis is flat for every point: z first (y up on the
 * page), then y, then x. */
static void find_plane(an_scene *s, const double range[3], double scale) {
    static const int planes[3][3] = {{2, 0, 1}, {1, 0, 2}, {0, 1, 2}}; /* flat, across, up */
    s->plane[0] = s->plane[1] = -1;
    for (int p = 0; p < 3; p++)
        if (range[planes[p][0]] <= FLAT * scale) {
            s->plane[0] = planes[p][1];
            s->plane[1] = planes[p][2];
            return;
        }
}

static double distance(const an_scene *s, size_t f, size_t a, size_t b) {
    static const double origin[3] = {0, 0, 0};
    const double *p = a == AN_ORIGIN ? origin : pos(s, f, a);
    const double *q = b == AN_ORIGIN ? origin : pos(s, f, b);
    return hypot(hypot(p[0] - q[0], p[1] - q[1]), p[2] - q[2]);
}

static bool moves(const an_scene *s, size_t i, double scale) {
    for (size_t f = 1; i != AN_ORIGIN && f < s->nframes; f++) {
        const double *p = pos(s, f, i), *p0 = pos(s, 0, i);
        if (fabs(p[0] - p0[0]) + fabs(p[1] - p0[1]) + fabs(p[2] - p0[2]) > RIGID * scale)
            return true;
    }
    return false;
}

/* A rod: two points (the origin among them) whose distance is constant over
 * the whole run while at least one of them moves, and not already joined
 * by a spring. */
static bool rigid(const an_scene *s, size_t a, size_t b, double scale) {
    for (size_t k = 0; k < s->nlinks; k++)
        if ((s->links[k].a == a && s->links[k].b == b) || (s->links[k].a == b && s->links[k].b == a))
            return false;
    if (!moves(s, a, scale) && !moves(s, b, scale))
        return false;
    double d0 = distance(s, 0, a, b);
    if (d0 <= RIGID * scale)
        return false;
    for (size_t f = 1; f < s->nframes; f++)
        if (fabs(distance(s, f, a, b) - d0) > RIGID * scale)
            return false;
    return true;
}

int cli_animate_analyse(an_scene *s) {
    double range[3];
    double scale = scene_scale(s, range);
    find_plane(s, range, scale);
    for (size_t b = 0; b < s->npts; b++) {
        if (rigid(s, AN_ORIGIN, b, scale))
            s->links[s->nlinks++] = (an_link){.a = AN_ORIGIN, .b = b};
        for (size_t a = 0; a < b; a++)
            if (rigid(s, a, b, scale))
                s->links[s->nlinks++] = (an_link){.a = a, .b = b};
    }
    return QD_EXIT_OK;
}

/* ---- JSON ------------------------------------------------------------------------ */

/* A name in a JSON string inside a <script>: no quote, backslash or '<'
 * may end either. */
static void json_name(FILE *f, const char *name) {
    fputc('"', f);
    for (const char *p = name; *p; p++)
        if (*p == '"' || *p == '\\' || *p == '<' || (unsigned char)*p < 0x20)
            fprintf(f, "\\u%04x", (unsigned char)*p);
        else
            fputc(*p, f);
    fputc('"', f);
}

/* Numbers to 7 digits: a picture needs no more, and the page stays small. */
static void json_numbers(FILE *f, const char *key, const double *v, size_t n) {
    fprintf(f, ",\"%s\":[", key);
    for (size_t i = 0; i < n; i++) {
        if (i)
            fputc(',', f);
        if (isfinite(v[i]))
            fprintf(f, "%.7g", v[i]);
        else
            fputs("null", f);
    }
    fputc(']', f);
}

static long link_end(size_t i) {
    return i == AN_ORIGIN ? -1 : (long)i;
}

static void json_scene(FILE *f, const an_scene *s) {
    fputs("{\"model\":", f);
    json_name(f, s->model);
    fputs(",\"method\":", f);
    json_name(f, s->method);
    fprintf(f, ",\"plane\":[%d,%d],\"conservative\":%s,\"energy_error_max\":%.7g", s->plane[0],
            s->plane[1], s->conservative ? "true" : "false", s->energy_error_max);
    fputs(",\"points\":[", f);
    for (size_t i = 0; i < s->npts; i++) {
        fputs(i ? ",{\"name\":" : "{\"name\":", f);
        json_name(f, s->pts[i].name);
        fprintf(f, ",\"body\":%s,\"mass\":%.7g}", s->pts[i].body ? "true" : "false",
                s->pts[i].mass);
    }
    fputs("],\"links\":[", f);
    for (size_t k = 0; k < s->nlinks; k++)
        fprintf(f, "%s[%ld,%ld,%d]", k ? "," : "", link_end(s->links[k].a),
                link_end(s->links[k].b), s->links[k].spring);
    fputs("],\"traces\":[", f);
    for (size_t k = 0; k < s->ntraces; k++)
        fprintf(f, "%s%zu", k ? "," : "", s->traces[k]);
    fputc(']', f);
    json_numbers(f, "t", s->t, s->nframes);
    if (s->energy)
        json_numbers(f, "energy_error", s->energy, s->nframes);
    json_numbers(f, "pos", s->pos, s->nframes * s->npts * 3);
    json_numbers(f, "rot", s->rot, s->nframes * s->nbodies * 9);
    fputc('}', f);
}

int cli_animate_write(FILE *f, const an_scene *s) {
    static const char marker[] = "@QDOT_DATA@";
    const char *at = strstr(cli_animate_page, marker);
    if (!at) {
        cli_diag_error("the page template has no %s marker (a build problem)", marker);
        return QD_EXIT_FAIL;
    }
    fwrite(cli_animate_page, 1, (size_t)(at - cli_animate_page), f);
    json_scene(f, s);
    fputs(at + strlen(marker), f);
    return ferror(f) ? QD_EXIT_FAIL : QD_EXIT_OK;
}

/*
 * cli/animate_page.c - the scene of `qdot animate` analysed (the rods, the
 * drawing plane) and written into the page: the template animate_page.html,
 * embedded at build time (cmake/embed.cmake), with the scene as JSON in
 * place of its @QDOT_DATA@ marker.  docs/cli.md states the drawing rules.
 */
#include "animate.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"

extern const unsigned char cli_animate_page_bytes[]; /* generated from animate_page.html */
#define cli_animate_page ((const char *)cli_animate_page_bytes)

/* The library finds the plane and the rods; the springs named are not rods. */
int cli_animate_analyse(an_scene *s) {
    size_t *skip = malloc((2 * s->nlinks + 1) * sizeof *skip);
    if (!skip)
        return QD_EXIT_FAIL;
    for (size_t k = 0; k < s->nlinks; k++) {
        skip[2 * k] = s->links[k].a;
        skip[2 * k + 1] = s->links[k].b;
    }
    qd_scene_shape sh;
    qd_status st = qd_scene_analyse(NULL, s->fr.pos, s->fr.nframes, s->npts, skip, s->nlinks, &sh);
    free(skip);
    if (st != QD_OK) {
        free(sh.rods);
        cli_diag_error("the scene's positions could not be analysed (%s)", qd_status_str(st));
        return QD_EXIT_FAIL;
    }
    s->plane[0] = sh.plane[0];
    s->plane[1] = sh.plane[1];
    for (size_t k = 0; k < sh.nrods; k++)
        s->links[s->nlinks++] = (an_link){.a = sh.rods[k].a, .b = sh.rods[k].b};
    free(sh.rods);
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
        fprintf(f, ",\"body\":%s,\"mass\":%.7g}",
                s->pts[i].kind == QD_SCENE_BODY ? "true" : "false", s->mass[i]);
    }
    fputs("],\"links\":[", f);
    for (size_t k = 0; k < s->nlinks; k++)
        fprintf(f, "%s[%ld,%ld,%d]", k ? "," : "", link_end(s->links[k].a),
                link_end(s->links[k].b), s->links[k].spring);
    fputs("],\"traces\":[", f);
    for (size_t k = 0; k < s->ntraces; k++)
        fprintf(f, "%s%zu", k ? "," : "", s->traces[k]);
    fputc(']', f);
    const qd_scene_frames *fr = &s->fr;
    json_numbers(f, "t", fr->t, fr->nframes);
    if (fr->energy)
        json_numbers(f, "energy_error", fr->energy, fr->nframes);
    json_numbers(f, "pos", fr->pos, fr->nframes * s->npts * 3);
    json_numbers(f, "rot", fr->rot, fr->nframes * fr->nbodies * 9);
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

/*
 * cli/animate_page.c - the page of `qdot animate`: the template
 * animate_page.html, embedded at build time (cmake/embed.cmake), with the
 * scene as JSON (qd_scene_json) in place of its @QDOT_DATA@ marker.
 * docs/cli.md states the drawing rules.
 */
#include "animate.h"

#include <string.h>

#include "cli.h"

extern const unsigned char cli_animate_page_bytes[]; /* generated from animate_page.html */
#define cli_animate_page ((const char *)cli_animate_page_bytes)

int cli_animate_write(FILE *f, const qd_scene *s) {
    static const char marker[] = "@QDOT_DATA@";
    const char *at = strstr(cli_animate_page, marker);
    if (!at) {
        cli_diag_error("the page template has no %s marker (a build problem)", marker);
        return QD_EXIT_FAIL;
    }
    qd_buf b = QD_BUF_INIT;
    if (qd_scene_json(s, &b) != QD_OK) {
        qd_buf_free(&b);
        cli_diag_error("out of memory writing the scene");
        return QD_EXIT_FAIL;
    }
    fwrite(cli_animate_page, 1, (size_t)(at - cli_animate_page), f);
    fwrite(b.s, 1, b.len, f);
    fputs(at + strlen(marker), f);
    qd_buf_free(&b);
    return ferror(f) ? QD_EXIT_FAIL : QD_EXIT_OK;
}

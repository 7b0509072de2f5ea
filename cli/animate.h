/*
 * cli/animate.h - what `qdot animate` computes (cmd_animate.c) and writes
 * into its page (animate_page.c): the points drawn, sampled at the frames.
 */
#ifndef QDOT_CLI_ANIMATE_H
#define QDOT_CLI_ANIMATE_H

#include <stdbool.h>
#include <stdio.h>

#include "qdot/scene.h"

#define AN_ORIGIN QD_SCENE_ORIGIN /* a link's end at the fixed origin (the pivot) */

typedef struct an_link {
    size_t a, b;    /* point indices, or AN_ORIGIN */
    bool spring;    /* a zigzag (--spring); else a rigid rod */
} an_link;

typedef struct an_scene {
    const char *model;           /* the file, for the page's title */
    qd_scene_point *pts;         /* the points drawn (qd_scene_choose) */
    size_t npts;
    double *mass;                /* per point (1 for a named position) */
    qd_scene_frames fr;          /* sampled at the frames (qd_scene_sample) */
    an_link *links;
    size_t nlinks;
    size_t *traces, ntraces;     /* points whose paths are drawn */
    int plane[2];                /* the drawing plane's axes, or -1 for 3-D */
    double energy_error_max;     /* the run's measure (qd_sim_stats) */
    bool conservative;
    const char *method;
} an_scene;

/* The rods and the drawing plane (qd_scene_analyse) added to the scene. */
int cli_animate_analyse(an_scene *s);
/* The page: the template (animate_page.html) with the scene as JSON. */
int cli_animate_write(FILE *f, const an_scene *s);

#endif

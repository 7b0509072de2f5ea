/*
 * cli/animate.h - the page `qdot animate` writes (animate_page.c): the
 * scene (qd_scene, qdot/scene.h) as JSON in the page's template.
 */
#ifndef QDOT_CLI_ANIMATE_H
#define QDOT_CLI_ANIMATE_H

#include <stdio.h>

#include "qdot/scene.h"

/* The page: the template (animate_page.html) with the scene as JSON
 * (qd_scene_json). */
int cli_animate_write(FILE *f, const qd_scene *s);

#endif

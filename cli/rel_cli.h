/*
 * cli/rel_cli.h - what `qdot lorentz` and `qdot collide` share: numbers,
 * vectors and particles read from option values in which c is the speed of
 * light (--c, default 1), and the output of vectors and particles.
 */
#ifndef QDOT_CLI_REL_H
#define QDOT_CLI_REL_H

#include "qdot/qdot.h"
#include "qdot/json.h"

/* text (what names it: "--frame") as an expression in c (and t when t_ok:
 * *expr gets it with c replaced); a number unless t_ok.  Prints its errors. */
int rel_read(qd_ctx *ctx, double c, const char *what, const char *text, bool t_ok,
             const qd_expr **expr, double *val);
/* "a, b, c" (or "(a, b, c)"): exactly n numbers, or n expressions in t when
 * exprs is not NULL. */
int rel_list(qd_ctx *ctx, double c, const char *what, const char *text, size_t n, double *out,
             const qd_expr **exprs);
/* "m=..., v=(vx, vy, vz)" (v defaults to rest) into *p. */
int rel_particle(qd_ctx *ctx, double c, const char *what, const char *text, qd_rel_particle *p);
/* --c's value: a positive finite number. */
int rel_speed_of_light(qd_ctx *ctx, const char *text, double *c);

void rel_put_vec(qd_buf *b, const double *v, size_t n); /* (x, y, z) */
void rel_json_vec(qd_json *j, const char *key, const double *v, size_t n);
void rel_json_particle(qd_json *j, const qd_rel_particle *p);
void rel_text_particle(qd_buf *b, const char *label, const qd_rel_particle *p);

#endif

/*
 * tests/cross/gen_hamiltonian.c - the SymPy scripts of qd_render_hamiltonian
 * for the cross-check tests/cross/check_hamiltonian_render_sympy.py.
 *
 * Usage: gen_hamiltonian NAME   writes the script of model NAME:
 *   polar     a particle in V = -k/r + c r^2, in polar coordinates, from L;
 *   polar_H   the same particle given by its H (`momenta`, `H = ...`);
 *   rotating  a bead on a wire spinning at w (rheonomic: H is not T + V).
 * Exit status 1 for another name or a failure (the message on stderr).
 */
#include <stdio.h>
#include <string.h>

#include "qdot/qdot.h"
#include "qdot/render.h"

static const struct {
    const char *name, *text;
    int given;
} cases[] = {
    {"polar",
     "coordinates r, th\n"
     "parameters m = 2, k = 3, c = 1/4\n"
     "T = m/2*(r'^2 + r^2*th'^2)\n"
     "V = -k/r + c*r^2\n", 0},
    {"polar_H",
     "coordinates r, th\n"
     "momenta p_r, p_th\n"
     "parameters m = 2, k = 3, c = 1/4\n"
     "H = p_r^2/(2*m) + p_th^2/(2*m*r^2) - k/r + c*r^2\n", 1},
    {"rotating",
     "coordinates s\n"
     "parameters m = 1, w = 2\n"
     "T = m/2*(s'^2 + s^2*w^2)\n", 0},
};

int main(int argc, char **argv) {
    size_t i = 0, n = sizeof cases / sizeof cases[0];
    while (argc == 2 && i < n && strcmp(argv[1], cases[i].name))
        i++;
    if (argc != 2 || i == n) {
        fprintf(stderr, "usage: gen_hamiltonian polar|polar_H|rotating\n");
        return 1;
    }
    qd_ctx *ctx = qd_ctx_new();
    qd_diag d;
    memset(&d, 0, sizeof d);
    qd_model *m = ctx ? qd_model_parse(ctx, cases[i].text, &d) : NULL;
    qd_eom *e = m && !cases[i].given ? qd_eom_derive(ctx, m) : NULL;
    qd_ham *h = m && (e || cases[i].given) ? qd_ham_derive(ctx, m, e) : NULL;
    qd_buf b = QD_BUF_INIT;
    int rc = 1;
    if (h && qd_render_hamiltonian(ctx, m, h, cases[i].name, NULL, QD_RENDER_SYMPY, &b) == QD_OK) {
        fputs(qd_buf_str(&b), stdout);
        rc = 0;
    } else {
        fprintf(stderr, "gen_hamiltonian %s: %s\n", cases[i].name,
                m ? qd_ctx_message(ctx) : d.message);
    }
    qd_buf_free(&b);
    qd_ham_free(h);
    qd_eom_free(e);
    qd_model_free(m);
    qd_ctx_free(ctx);
    return rc;
}

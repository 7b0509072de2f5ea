/*
 * tests/cross/gen_impulse.c - cases for the SymPy cross-check of the
 * impulse solver's closed forms (tests/cross/check_impulse_exact_sympy.py).
 *
 * For each model below, qd_impulse_solve with exact = true; prints, in
 * SymPy syntax, one per line:
 *   case <name>
 *   params <name> <value> ...        (the model's parameter values)
 *   after <coordinate> <q'+>
 *   mult <Lambda_NAME> <multiplier>
 *   lost <energy lost>
 *   numeric <q'+_1> ... <q'+_n>      (the numeric solve, for the same values)
 * The Python side builds each system itself (T from the bodies' geometry,
 * or the impulse from conservation laws) and compares.
 * Usage: gen_impulse
 */
#include <stdio.h>

#include "qdot/qdot.h"

typedef struct icase {
    const char *name, *text;
} icase;

static const icase cases[] = {
    /* Desloge ch. 57 Ex. 1 (T55): T as the seed gives it; SymPy sums the
     * four rods */
    {"rhombus",
     "coordinates x, th\n"
     "parameters m = 1, a = 1, v = 1, al = pi/6\n"
     "T = 2*m*x'^2 + 8/3*m*a^2*th'^2\n"
     "impact constraint wall: x - 2*a*cos(th) = 0\n"
     "initial x = 2*a*cos(al), th = al, x' = -v, th' = 0\n"},
    /* the chain of two rods (Britannica B01/B03) bent at angles al, be,
     * moving, struck at A, its joint suddenly made rigid */
    {"chain",
     "coordinates xb, yb, th1, th2\n"
     "parameters m = 1, a = 1, J = 2, al = 1/3, be = -1/2, u = 1/2\n"
     "body r1 mass m inertia rod(m, 2*a) at (xb - a*cos(th1), yb - a*sin(th1)) "
     "orientation rot_z(th1)*rot_y(pi/2)\n"
     "body r2 mass m inertia rod(m, 2*a) at (xb + a*cos(th2), yb + a*sin(th2)) "
     "orientation rot_z(th2)*rot_y(pi/2)\n"
     "A = (xb - 2*a*cos(th1), yb - 2*a*sin(th1), 0)\n"
     "impulse (0, J, 0) at A\n"
     "impact constraint rigid: th1 - th2 = al - be\n"
     "initial xb = 0, yb = 0, th1 = al, th2 = be, xb' = u, yb' = 0, th1' = u, th2' = -u\n"},
    /* head-on collision with restitution k */
    {"headon",
     "coordinates x1, x2\n"
     "parameters m1 = 2, m2 = 5, k = 1/2, v1 = 3, v2 = -1, R = 1\n"
     "particle m1 at (x1, 0, 0)\n"
     "particle m2 at (x2, 0, 0)\n"
     "impact constraint hit: x2 - x1 = R restitution k\n"
     "initial x1 = 0, x2 = R, x1' = v1, x2' = v2\n"},
    /* Byerly TC25, Thomson's form: the foot given the velocity v */
    {"lamina",
     "coordinates x, y, th\n"
     "parameters m = 2, k = 1/2, a = 3/4, v = 5, ph = 1/5\n"
     "T = m/2*(x'^2 + y'^2) + m*k^2/2*th'^2\n"
     "F = (x + a*cos(th), y + a*sin(th), 0)\n"
     "prescribe foot: F.y' = v\n"
     "initial x = 0, y = 0, th = ph, x' = 0, y' = 0, th' = 0\n"},
};

static int line(qd_ctx *ctx, const char *tag, const char *name, const qd_expr *e) {
    qd_buf b = QD_BUF_INIT;
    if (!e || qd_print(ctx, e, QD_FMT_SYMPY, &b) != QD_OK) {
        fprintf(stderr, "gen_impulse: %s %s failed: %s\n", tag, name, qd_ctx_message(ctx));
        qd_buf_free(&b);
        return 1;
    }
    printf("%s %s %s\n", tag, name, qd_buf_str(&b));
    qd_buf_free(&b);
    return 0;
}

static int params(qd_ctx *ctx, const qd_model *m) {
    printf("params");
    for (size_t i = 0; i < qd_model_nparams(m); i++) {
        double v = 0;
        if (qd_eval(ctx, qd_model_param_value(m, i), 0, NULL, NULL, &v) != QD_OK)
            return 1;
        printf(" %s %.17g", qd_expr_name(qd_model_param(m, i)), v);
    }
    printf("\n");
    return 0;
}

static int one(const icase *c) {
    qd_ctx *ctx = qd_ctx_new();
    qd_diag d;
    qd_model *m = qd_model_parse(ctx, c->text, &d);
    qd_impulse r;
    qd_impulse_opts o = {.exact = true};
    int bad = !m || qd_impulse_solve(ctx, m, &o, &r) != QD_OK || !r.exact;
    if (bad) {
        fprintf(stderr, "gen_impulse: %s: %s\n", c->name, m ? qd_ctx_message(ctx) : d.message);
        qd_model_free(m);
        qd_ctx_free(ctx);
        return 1;
    }
    printf("case %s\n", c->name);
    bad |= params(ctx, m);
    for (size_t j = 0; j < r.n; j++)
        bad |= line(ctx, "after", qd_expr_name(r.q[j]), r.qd_after_exact[j]);
    for (size_t k = 0; k < r.nmult; k++)
        bad |= line(ctx, "mult", r.mult_name[k], r.mult_exact[k]);
    bad |= line(ctx, "lost", "-", r.energy_lost_exact);
    printf("numeric");
    for (size_t j = 0; j < r.n; j++)
        printf(" %.17g", r.qd_after[j]);
    printf("\n");
    qd_impulse_free(&r);
    qd_model_free(m);
    qd_ctx_free(ctx);
    return bad;
}

int main(void) {
    int bad = 0;
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++)
        bad |= one(&cases[i]);
    return bad;
}

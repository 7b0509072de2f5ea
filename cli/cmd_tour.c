/*
 * cli/cmd_tour.c - `qdot tour`: one minute with the symbolic kernel.
 *
 * Builds the double pendulum's kinetic energy from the positions of its two
 * bobs, reads the mass matrix off it by differentiation, simplifies it to the
 * textbook form, prints it as text, LaTeX and C, and evaluates it through a
 * compiled program.  (The model language, `qdot eom FILE`, will replace this
 * with a real system file.)
 */
#include "driver.h"

static void show(qd_ctx *ctx, const char *label, const qd_expr *e, qd_format fmt) {
    qd_buf b = QD_BUF_INIT;
    qd_print(ctx, e, fmt, &b);
    printf("  %-10s %s\n", label, qd_buf_str(&b));
    qd_buf_free(&b);
}

static const qd_expr *read_expr(qd_ctx *ctx, const char *text) {
    qd_diag err;
    const qd_expr *e = qd_read(ctx, text, NULL, &err);
    if (!e)
        cli_diag_read("<tour>", text, &err);
    return e;
}

static const cli_opt tour_opts[] = {{0}};
static const cli_spec tour_spec = {
    "tour", "", "a one-minute tour of the symbolic kernel", tour_opts, NULL, 0, 0, NULL, false,
};

static int run(cli_run *c) {
    qd_ctx *ctx = c->ctx;
    const qd_expr *q1 = qd_coord(ctx, "theta1"), *q2 = qd_coord(ctx, "theta2");
    const char *params[] = {"m1", "m2", "l1", "l2", "g"};
    for (size_t i = 0; i < 5; i++)
        qd_param(ctx, params[i]);

    printf("1. Positions of the two bobs of a double pendulum, read from text:\n");
    const qd_expr *x2 = read_expr(ctx, "l1*sin(theta1) + l2*sin(theta2)");
    const qd_expr *y2 = read_expr(ctx, "-l1*cos(theta1) - l2*cos(theta2)");
    const qd_expr *T = read_expr(ctx, "m1/2*(l1*theta1')^2");
    if (!x2 || !y2 || !T)
        return QD_EXIT_FAIL;
    show(ctx, "x2 =", x2, QD_FMT_TEXT);
    show(ctx, "y2 =", y2, QD_FMT_TEXT);

    printf("\n2. Velocities by the total time derivative over the jet (x2' = d/dt x2):\n");
    const qd_expr *vx = qd_dt(ctx, x2), *vy = qd_dt(ctx, y2);
    show(ctx, "x2' =", vx, QD_FMT_TEXT);
    show(ctx, "y2' =", vy, QD_FMT_TEXT);

    printf("\n3. Kinetic energy T = m1/2 (l1 theta1')^2 + m2/2 (x2'^2 + y2'^2), expanded, "
           "then simplified:\n");
    const qd_expr *m2 = qd_lookup(ctx, "m2");
    T = qd_add(ctx, T, qd_mul_n(ctx, 3, (const qd_expr *[]){qd_rat(ctx, 1, 2), m2,
        qd_add(ctx, qd_powi(ctx, vx, 2), qd_powi(ctx, vy, 2))}));
    T = qd_expand(ctx, T);
    show(ctx, "T =", T, QD_FMT_TEXT);
    show(ctx, "T =", qd_simplify(ctx, T), QD_FMT_TEXT);

    printf("\n4. Mass matrix M_jk = d^2T/dtheta_j' dtheta_k', simplified "
           "(sin a sin b + cos a cos b = cos(a - b)):\n");
    const qd_expr *v[2] = {qd_jet(ctx, q1, 1), qd_jet(ctx, q2, 1)};
    const qd_expr *M[4];
    for (int j = 0; j < 2; j++)
        for (int k = 0; k < 2; k++)
            M[2 * j + k] = qd_simplify(ctx, qd_diff(ctx, qd_diff(ctx, T, v[j]), v[k]));
    if (qd_ctx_status(ctx) != QD_OK)
        return cli_diag_ctx(ctx);
    show(ctx, "M11 =", M[0], QD_FMT_TEXT);
    show(ctx, "M12 =", M[1], QD_FMT_TEXT);
    show(ctx, "M22 =", M[3], QD_FMT_TEXT);

    printf("\n5. The same entry as LaTeX, SymPy and C:\n");
    show(ctx, "LaTeX", M[1], QD_FMT_LATEX);
    show(ctx, "SymPy", M[1], QD_FMT_SYMPY);
    qd_buf b = QD_BUF_INIT;
    const char *lhs[3] = {"M[0]", "M[1]", "M[3]"};
    const qd_expr *outs[3] = {M[0], M[1], M[3]};
    qd_print_c_block(ctx, 3, outs, lhs, &b);
    printf("  C (shared subexpressions hoisted):\n%s", qd_buf_str(&b));
    qd_buf_free(&b);

    printf("\n6. Compiled to a straight-line program and evaluated at theta1 = 0.3, "
           "theta2 = -0.2, m = l = 1:\n");
    const qd_expr *in[6] = {q1, q2, qd_lookup(ctx, "m1"), m2, qd_lookup(ctx, "l1"),
                            qd_lookup(ctx, "l2")};
    qd_prog *p = qd_prog_new(ctx, 6, in, 3, outs);
    if (!p)
        return cli_diag_ctx(ctx);
    double x[6] = {0.3, -0.2, 1, 1, 1, 1}, y[3];
    qd_prog_run(p, x, y);
    printf("  M = [[%.6f, %.6f], [%.6f, %.6f]]   (%zu instructions)\n", y[0], y[1], y[1], y[2],
           qd_prog_ninstr(p));
    qd_prog_free(p);
    printf("\nExpressions are hash-consed: this tour made %zu distinct nodes.\n",
           qd_ctx_node_count(ctx));
    return QD_EXIT_OK;
}

CLI_COMMAND(tour, cli_run, &tour_spec, 0, 0, NULL, run, NULL)

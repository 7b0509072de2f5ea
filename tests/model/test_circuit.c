/*
 * tests/model/test_circuit.c - the circuit statements `inductance`,
 * `capacitance`, `resistance` and `source`: each adds to T, V, D and Q
 * exactly what the energies written by hand give (compared as expressions:
 * the simplified difference is 0), the electromechanical force between two
 * wires comes out of the Lagrangian as Ampere's law, and every error is
 * located (line, column, span asserted).
 *
 * Byerly, Generalized Coordinates, ch. V Art. 53 (seed 001; reference
 * seed-byerly.md key extension 13 and pitfall 13): T = A x'^2 + L y1'^2 +
 * M(x) y1'y2' + L y2'^2 with Byerly's L half the usual self-inductance, so
 * `inductance Lw on y1` must give Lw/2 y1'^2, not Lw y1'^2.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "qdot/qdot.h"
#include "qdot/model.h"
#include "util/fault.h"

static qd_model *parse_ok(qd_ctx *ctx, const char *text) {
    qd_diag d;
    memset(&d, 0, sizeof d);
    qd_model *m = qd_model_parse(ctx, text, &d);
    if (!m)
        fail_msg("%zu:%zu: %s [hint: %s]", d.line, d.col, d.message, d.hint);
    return m;
}

static const qd_expr *or_zero(qd_ctx *ctx, const qd_expr *e) { return e ? e : qd_int(ctx, 0); }

static void assert_same(qd_ctx *ctx, const qd_expr *got, const qd_expr *want, const char *what) {
    const qd_expr *d = qd_simplify(ctx, qd_sub(ctx, or_zero(ctx, got), or_zero(ctx, want)));
    assert_non_null(d);
    if (!qd_is_zero(d)) {
        qd_buf b = QD_BUF_INIT;
        qd_print(ctx, d, QD_FMT_TEXT, &b);
        fail_msg("%s differs from the hand-written one by %s", what, qd_buf_str(&b));
    }
}

/* The model with circuit statements and the one written by hand (the same
 * header, read in the same context so the symbols are shared) have the same
 * T, V, D and every Q. */
static void assert_as_by_hand(const char *head, const char *circuit, const char *hand) {
    qd_ctx *ctx = qd_ctx_new();
    char a[1024], b[1024];
    snprintf(a, sizeof a, "%s%s", head, circuit);
    snprintf(b, sizeof b, "%s%s", head, hand);
    qd_model *mc = parse_ok(ctx, a), *mh = parse_ok(ctx, b);
    assert_same(ctx, qd_model_kinetic(mc), qd_model_kinetic(mh), "T");
    assert_same(ctx, qd_model_potential(mc), qd_model_potential(mh), "V");
    assert_same(ctx, qd_model_dissipation(mc), qd_model_dissipation(mh), "D");
    assert_same(ctx, qd_model_lagrangian(mc), qd_model_lagrangian(mh), "L");
    assert_int_equal(qd_model_ncoords(mc), qd_model_ncoords(mh));
    for (size_t j = 0; j < qd_model_ncoords(mc); j++)
        assert_same(ctx, qd_model_force(mc, j), qd_model_force(mh, j), "Q");
    qd_model_free(mc);
    qd_model_free(mh);
    qd_ctx_free(ctx);
}

/* The three-section ladder of examples/circuit_lc_ladder.qd: the usual
 * self-inductance (L/2 i^2), shared capacitors on differences of charges. */
static void ladder_as_by_hand(void **state) {
    (void)state;
    assert_as_by_hand("coordinates q1, q2, q3\nparameters L = 1, C = 2\n",
                      "inductance L on q1\ninductance L on q2\ninductance L on q3\n"
                      "capacitance C on q1 - q2\ncapacitance C on q2 - q3\ncapacitance C on q3\n",
                      "T = L/2*(q1'^2 + q2'^2 + q3'^2)\n"
                      "V = ((q1 - q2)^2 + (q2 - q3)^2 + q3^2)/(2*C)\n");
}

/* Byerly Art. 53 in the usual inductances: T = A x'^2 + (Lw/2)(y1'^2 + y2'^2)
 * + M(x) y1'y2', resistances as Rayleigh's function, EMFs as forces. */
static void wires_as_by_hand(void **state) {
    (void)state;
    assert_as_by_hand("coordinates x, y1, y2\n"
                      "parameters A = 2, Lw = 3, R = 1/2, E = 5, w = 7, b = 11\n"
                      "M = log(b/x)\n",
                      "T = A*x'^2\ninductance Lw on y1\ninductance Lw on y2\n"
                      "inductance M between y1, y2\nresistance R on y1\nresistance R on y2\n"
                      "source E*sin(w*t) on y1\n",
                      "T = A*x'^2 + Lw/2*(y1'^2 + y2'^2) + M*y1'*y2'\n"
                      "dissipation = R/2*(y1'^2 + y2'^2)\nQ[y1] = E*sin(w*t)\n");
}

/* A branch is any linear combination with constant coefficients: an
 * element between two loops, or counted twice (two turns). */
static void branches_as_by_hand(void **state) {
    (void)state;
    assert_as_by_hand("coordinates q1, q2, q3\nparameters L = 2, M = 1/3, C = 5, R = 7, E = 3, n = 2\n",
                      "inductance L on q1 - q2\ninductance M between q1 - q2, n*q3\n"
                      "capacitance C on 2*q1 + q2/3\nresistance R on q2 - q3\n"
                      "source E on q1 - n*q3\n",
                      "T = L/2*(q1' - q2')^2 + M*(q1' - q2')*n*q3'\n"
                      "V = (2*q1 + q2/3)^2/(2*C)\ndissipation = R/2*(q2' - q3')^2\n"
                      "Q[q1] = E\nQ[q3] = -n*E\n");
}

/* A branch may be a definition (and then the coordinate check is the
 * linearity check's). */
static void branch_from_definition(void **state) {
    (void)state;
    assert_as_by_hand("coordinates q1, q2\nparameters C = 3\nb = q1 - q2\n",
                      "capacitance C on b\nT = q1'^2 + q2'^2\n",
                      "V = (q1 - q2)^2/(2*C)\nT = q1'^2 + q2'^2\n");
    /* a coefficient of many parameters is still a constant (was: at most 8) */
    assert_as_by_hand("coordinates q1, q2\nparameters a = 1, b = 2, c = 3, d = 4, f = 5, g = 6, "
                      "h = 7, k = 8, n = 9, C = 3\nT = q1'^2 + q2'^2\n",
                      "capacitance C on (a + b + c + d + f + g + h + k + n)*q1 + q2\n",
                      "V = ((a + b + c + d + f + g + h + k + n)*q1 + q2)^2/(2*C)\n");
}

/* The elements add to the energies given by hand, before or after them
 * (`V = ...` after a capacitance was "V is given twice" before). */
static void elements_add_to_energies(void **state) {
    (void)state;
    assert_as_by_hand("coordinates q, x\nparameters L = 2, C = 3, R = 5, k = 7, m = 1, b = 1/2\n",
                      "capacitance C on q\nV = k/2*x^2\nresistance R on q\n"
                      "dissipation = b/2*x'^2\nT = m/2*x'^2\ninductance L on q\n",
                      "T = m/2*x'^2 + L/2*q'^2\nV = q^2/(2*C) + k/2*x^2\n"
                      "dissipation = R/2*q'^2 + b/2*x'^2\n");
    assert_as_by_hand("coordinates q\nparameters L = 2, C = 3, R = 5\n",
                      "V = q^4\ndissipation = q'^4\ncapacitance C on q\nresistance R on q\n"
                      "inductance L on q\n",
                      "T = L/2*q'^2\nV = q^4 + q^2/(2*C)\ndissipation = q'^4 + R/2*q'^2\n");
}

/* Byerly Art. 53: the force on wire 2 is dL/dx = y1' y2' dM/dx; with the
 * mutual inductance of two long wires, M = (mu0 l/(2 pi))(log(2 l/x) - 1),
 * it is -mu0 l i1 i2/(2 pi x): Ampere's attraction, 2e-3 N for 10 A each way
 * at 1 cm over 1 m, and a repulsion of the same size for opposed currents. */
static void wires_attract(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m = parse_ok(ctx, "coordinates x, y1, y2\n"
                                "parameters mu0 = 4*pi*1e-7, l = 1, m = 1e-3, Lw = 1.4e-6\n"
                                "T = m/2*x'^2\ninductance Lw on y1\ninductance Lw on y2\n"
                                "inductance mu0*l/(2*pi)*(log(2*l/x) - 1) between y1, y2\n");
    const qd_expr *x = qd_model_coord(m, 0);
    const qd_expr *F = qd_diff(ctx, qd_model_lagrangian(m), x);
    const qd_expr *sym[] = {x, qd_jet(ctx, qd_model_coord(m, 1), 1),
                            qd_jet(ctx, qd_model_coord(m, 2), 1), qd_jet(ctx, x, 1),
                            qd_model_param(m, 0), qd_model_param(m, 1), qd_model_param(m, 2),
                            qd_model_param(m, 3)};
    double same[] = {0.01, 10, 10, 0, 4e-7 * acos(-1), 1, 1e-3, 1.4e-6}, f;
    assert_int_equal(qd_eval(ctx, F, 8, sym, same, &f), QD_OK);
    assert_true(fabs(f + 2e-3) < 1e-15);
    double opposed[] = {0.01, 10, -10, 0, 4e-7 * acos(-1), 1, 1e-3, 1.4e-6};
    assert_int_equal(qd_eval(ctx, F, 8, sym, opposed, &f), QD_OK);
    assert_true(fabs(f - 2e-3) < 1e-15);
    qd_model_free(m);
    qd_ctx_free(ctx);
}

/* `source` and the others are statements only when no '=' follows: a model
 * that defined them as names still reads. */
static void names_still_definitions(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m = parse_ok(ctx, "coordinates q\nsource = 3\nresistance = 2\n"
                                "T = source*q'^2\ndissipation = resistance*q'^2\n");
    assert_non_null(qd_model_definition(m, "source"));
    qd_model_free(m);
    qd_ctx_free(ctx);
}

/* A statement added after the parse is the same as one in the text, and a
 * failed one leaves the model as it was. */
static void added_statement(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_model *m = parse_ok(ctx, "coordinates q\nparameters L = 2, C = 3\ninductance L on q\n");
    qd_model *h = parse_ok(ctx, "coordinates q\nparameters L = 2, C = 3\n"
                                "T = L/2*q'^2\nV = q^2/(2*C)\n");
    qd_diag d;
    assert_int_equal(qd_model_add_statement(m, "capacitance C on q", &d), QD_OK);
    assert_same(ctx, qd_model_lagrangian(m), qd_model_lagrangian(h), "L");
    assert_int_equal(qd_model_add_statement(m, "capacitance -C on q", &d), QD_ERR_PARSE);
    assert_same(ctx, qd_model_potential(m), qd_model_potential(h), "V");
    qd_model_free(m);
    qd_model_free(h);
    qd_ctx_free(ctx);
}

typedef struct bad {
    const char *line;      /* the third line of the model */
    size_t col, len;       /* where the caret is, on line 3 */
    const char *message;   /* its start */
    const char *hint;      /* its start, or NULL */
} bad;

static const bad bads[] = {
    {"inductance -1 on q1", 12, 2, "an inductance must be positive, but it is -1",
     "give a positive value: inductance L on q"},
    {"inductance L - 3 on q1", 12, 5, "an inductance must be positive", NULL},
    {"capacitance 0 on q1", 13, 1, "a capacitance must be positive, but it is 0", NULL},
    {"resistance -R on q1", 12, 2, "a resistance must be zero or positive", NULL},
    {"inductance L*q2' on q1", 12, 5, "an inductance cannot depend on the rate q2'", NULL},
    {"inductance 2*M between q1, q1", 28, 2, "a mutual inductance is between two different",
     "a self-inductance is: inductance L on q"},
    {"inductance M between q1 q2", 25, 2, "expected ',' between the two branches", NULL},
    {"inductance L at q1", 14, 2, "expected 'on', found", "write: inductance L on q"},
    {"capacitance C on q1^2", 18, 4, "a branch must be linear in the charges", "a branch is"},
    {"capacitance C on q1*q2", 18, 5, "a branch must be linear in the charges", NULL},
    {"capacitance C on q1 + 1", 18, 6, "a branch must be linear in the charges", NULL},
    {"resistance R on q1'", 17, 3, "a branch is a charge, not a current (q1')",
     "write the charge: q for the current q'"},
    {"resistance R on q1 + q2'", 17, 8, "a branch is a charge, not a current (q2')", NULL},
    {"source sin(t) on t*q1", 18, 4, "a branch must be linear in the charges", NULL},
    {"capacitance C on q3", 18, 2, "'q3' is not a coordinate", "did you mean 'q1'?"},
    {"source 1 on R", 13, 1, "'R' is not a coordinate", NULL},
    {"capacitance C on 0*q1", 18, 4, "the branch has no charge coordinate", NULL},
    {"capacitance C on R*t", 18, 3, "the branch has no charge coordinate", NULL},
    {"capacitance C on 2*R", 18, 3, "the branch has no charge coordinate", NULL},
    {"resistance R on q1 q2", 20, 2, "unexpected a name after the statement", NULL},
};

static void errors_located(void **state) {
    (void)state;
    for (size_t i = 0; i < sizeof bads / sizeof bads[0]; i++) {
        qd_ctx *ctx = qd_ctx_new();
        char text[256];
        snprintf(text, sizeof text, "coordinates q1, q2\nparameters L = 1, C = 1, R = 1, M = 1\n%s\n",
                 bads[i].line);
        qd_diag d;
        memset(&d, 0, sizeof d);
        qd_model *m = qd_model_parse(ctx, text, &d);
        if (m)
            fail_msg("parsed but must fail: %s", bads[i].line);
        if (d.line != 3 || d.col != bads[i].col || d.length != bads[i].len ||
            strncmp(d.message, bads[i].message, strlen(bads[i].message)) ||
            (bads[i].hint && strncmp(d.hint, bads[i].hint, strlen(bads[i].hint))))
            fail_msg("%s: got %zu:%zu (%zu bytes) %s [hint: %s]", bads[i].line, d.line, d.col,
                     d.length, d.message, d.hint);
        assert_int_equal(d.status, QD_ERR_PARSE);
        qd_ctx_free(ctx);
    }
}

/* An unknown statement's hint lists every keyword, the circuit ones too,
 * and still says what else a line may be (it was cut at "resistance, "). */
static void unknown_statement_hint(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_diag d;
    memset(&d, 0, sizeof d);
    assert_null(qd_model_parse(ctx, "coordinates q\nzzzzzzzzzzzz q\n", &d));
    assert_non_null(strstr(d.hint, "a statement starts with a keyword (coordinates parameters"));
    assert_non_null(strstr(d.hint, " inductance capacitance resistance source) or NAME = ..."));
    qd_ctx_free(ctx);
}

/* A model given by H has no energies to add an inductance to. */
static void not_with_hamiltonian(void **state) {
    (void)state;
    qd_ctx *ctx = qd_ctx_new();
    qd_diag d;
    memset(&d, 0, sizeof d);
    qd_model *m = qd_model_parse(ctx, "coordinates q\nmomenta p\nH = p^2/2\ncapacitance 1 on q\n", &d);
    assert_null(m);
    assert_int_equal(d.line, 4);
    assert_int_equal(d.col, 1);
    assert_non_null(strstr(d.message, "a capacitance cannot be given with H (line 3)"));
    qd_ctx_free(ctx);
}

/* Every allocation of the parse refused in turn: a clean out-of-memory or
 * the right model: two loops with a mutual inductance, a shared capacitor,
 * resistance and source.  At q = (1, 2), q' = (3, 5), t = 0:
 * L = (3^2 + 5^2)/2 + 2*3*5 - ((1 - 2)^2 + 2^2)/(2*4) = 47 - 5/8,
 * D = 7/2*(3 - 5)^2 = 14, Q[q2] = -cos(0) = -1 (the source on q1 - q2). */
static qd_status fault_body(qd_ctx *ctx, qt_faulty *f, void *data) {
    (void)f;
    (void)data;
    qd_diag d;
    qd_model *m = qd_model_parse(ctx, "coordinates q1, q2\nparameters L = 1, M = 2, C = 4, R = 7\n"
                                      "inductance L on q1\ninductance L on q2\n"
                                      "inductance M between q1, q2\ncapacitance C on q1 - q2\n"
                                      "capacitance C on q2\nresistance R on q1 - q2\n"
                                      "source cos(t) on q1 - q2\n", &d);
    if (!m)
        return qd_ctx_status(ctx);
    const qd_expr *sym[] = {qd_model_coord(m, 0), qd_model_coord(m, 1),
                            qd_jet(ctx, qd_model_coord(m, 0), 1), qd_jet(ctx, qd_model_coord(m, 1), 1),
                            qd_time(ctx), qd_model_param(m, 0), qd_model_param(m, 1),
                            qd_model_param(m, 2), qd_model_param(m, 3)};
    double at[] = {1, 2, 3, 5, 0, 1, 2, 4, 7}, L = 0, D = 0, Q2 = 0;
    qd_status st = qd_eval(ctx, qd_model_lagrangian(m), 9, sym, at, &L);
    if (st == QD_OK)
        st = qd_eval(ctx, qd_model_dissipation(m), 9, sym, at, &D);
    if (st == QD_OK)
        st = qd_eval(ctx, qd_model_force(m, 1), 9, sym, at, &Q2);
    if (st == QD_OK) {
        assert_true(fabs(L - (47 - 5.0 / 8)) < 1e-12);
        assert_true(fabs(D - 14) < 1e-12);
        assert_true(fabs(Q2 + 1) < 1e-12);
    }
    qd_model_free(m);
    return st;
}

static void out_of_memory(void **state) {
    (void)state;
    qt_fault_stats ls = qt_fault_loop("circuit statements", fault_body, NULL, 1);
    assert_true(ls.allocs > 10);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(ladder_as_by_hand),       cmocka_unit_test(wires_as_by_hand),
        cmocka_unit_test(branches_as_by_hand),     cmocka_unit_test(elements_add_to_energies),
        cmocka_unit_test(wires_attract),           cmocka_unit_test(names_still_definitions),
        cmocka_unit_test(added_statement),         cmocka_unit_test(errors_located),
        cmocka_unit_test(not_with_hamiltonian),    cmocka_unit_test(out_of_memory),
        cmocka_unit_test(unknown_statement_hint),  cmocka_unit_test(branch_from_definition),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

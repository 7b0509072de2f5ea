/*
 * src/mech/certify_out.c - the zero test behind a yes/no verdict written
 * out (qdot/certify.h): the witness of a "no", the point count and
 * precision of a numerical "yes", as text or as JSON members.  In mech, not
 * beside qd_zero_test in sym: the JSON writer ranks above sym.
 */
#include "qdot/certify.h"
#include "base/args.h"

void qd_zero_result_print(qd_buf *out, const qd_zero_result *z) {
    QD_ARGS(, out && z);
    if (z->kind != QD_ZERO_NONZERO)
        return;
    qd_buf_puts(out, "  witness: ");
    if (z->witness.n) {
        qd_buf_puts(out, "at ");
        for (size_t i = 0; i < z->witness.n; i++)
            qd_buf_printf(out, "%s%s = %.17g", i ? ", " : "", qd_expr_name(z->witness.sym[i]),
                          z->witness.at[i]);
        qd_buf_puts(out, " ");
    }
    qd_buf_printf(out, "the difference is %.17g +- %.3g (certified, %u-bit ball arithmetic)\n",
                  z->witness.value, z->witness.radius, z->bits);
}

void qd_zero_result_note(qd_buf *out, const qd_zero_result *z) {
    QD_ARGS(, out && z);
    if (z->kind == QD_ZERO_NUMERIC)
        qd_buf_printf(out, " (verified numerically at %u points, %u bits)", z->points, z->bits);
}

void qd_zero_result_json(qd_json *j, const qd_zero_result *z) {
    QD_ARGS(, j && z);
    qd_json_key(j, "certainty");
    qd_json_string(j, qd_zero_kind_name(z->kind));
    qd_json_key(j, "witness");
    if (z->kind == QD_ZERO_NONZERO) {
        qd_json_begin_object(j);
        qd_json_key(j, "point");
        qd_json_begin_object(j);
        for (size_t i = 0; i < z->witness.n; i++) {
            qd_json_key(j, qd_expr_name(z->witness.sym[i]));
            qd_json_number(j, z->witness.at[i]);
        }
        qd_json_end_object(j);
        qd_json_key(j, "value");
        qd_json_number(j, z->witness.value);
        qd_json_key(j, "radius");
        qd_json_number(j, z->witness.radius);
        qd_json_end_object(j);
    } else {
        qd_json_null(j);
    }
    qd_json_key(j, "points");
    if (z->kind == QD_ZERO_NUMERIC)
        qd_json_number(j, z->points);
    else
        qd_json_null(j);
    qd_json_key(j, "bits");
    qd_json_number(j, z->bits);
}

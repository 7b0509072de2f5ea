/*
 * cli/witness.c - printing a verdict's zero test (cli/witness.h).
 */
#include "witness.h"

#include <stdio.h>

void cli_witness_text(qd_buf *b, const qd_zero_result *z) {
    if (z->kind != QD_ZERO_NONZERO)
        return;
    qd_buf_puts(b, "  witness: ");
    if (z->witness.n) {
        qd_buf_puts(b, "at ");
        for (size_t i = 0; i < z->witness.n; i++)
            qd_buf_printf(b, "%s%s = %.17g", i ? ", " : "", qd_expr_name(z->witness.sym[i]),
                          z->witness.at[i]);
        qd_buf_puts(b, " ");
    }
    qd_buf_printf(b, "the difference is %.17g +- %.3g (certified, %u-bit ball arithmetic)\n",
                  z->witness.value, z->witness.radius, z->bits);
}

const char *cli_witness_how(const qd_zero_result *z, char *buf, size_t size) {
    if (z->kind == QD_ZERO_NUMERIC)
        snprintf(buf, size, " (verified numerically at %u points, %u bits)", z->points, z->bits);
    else if (size)
        buf[0] = 0;
    return buf;
}

void cli_witness_json(qd_json *j, const qd_zero_result *z) {
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

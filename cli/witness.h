/*
 * cli/witness.h - how every yes/no verdict prints the zero test behind it
 * (qdot/certify.h, issue 33): the witness of a "no", the point count and
 * precision of a numerical "yes".
 */
#ifndef QD_CLI_WITNESS_H
#define QD_CLI_WITNESS_H

#include "qdot/certify.h"
#include "qdot/json.h"

/* Text: "  witness: at q = 0.5, p = 1.25 the difference is 0.75 +- 1e-38\n" for
 * NONZERO, nothing otherwise. */
void cli_witness_text(qd_buf *b, const qd_zero_result *z);
/* " (verified numerically at 12 points, 128 bits)" for NUMERIC, "" otherwise. */
const char *cli_witness_how(const qd_zero_result *z, char *buf, size_t size);
/* JSON: "certainty": "proven|numeric|nonzero|unknown", "witness": {point,
 * value, radius} or null, "points": n (NUMERIC) or null, "bits". */
void cli_witness_json(qd_json *j, const qd_zero_result *z);

#endif

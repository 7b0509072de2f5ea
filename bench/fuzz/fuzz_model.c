/*
 * bench/fuzz/fuzz_model.c - libFuzzer target: the model language's lexer,
 * parser and lowering must never crash, hang or trip a sanitizer, whatever
 * the text.  A model that parses is also printed, to exercise the printers
 * on what the parser built.
 *
 *   bench/fuzz/run.sh [SECONDS]      builds with clang and runs on corpus/
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "qdot/qdot.h"
#include "qdot/model.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    if (size > 4096)
        return 0; /* long inputs only slow the search down */
    char *text = malloc(size + 1);
    if (!text)
        return 0;
    memcpy(text, data, size);
    text[size] = '\0';
    qd_ctx *ctx = qd_ctx_new();
    qd_diag d;
    qd_model *m = qd_model_parse(ctx, text, &d);
    qd_buf b = QD_BUF_INIT;
    if (m) {
        /* a model given by H has no L; its symmetries and integrals are printed too */
        const qd_expr *L = qd_model_lagrangian(m);
        qd_print(ctx, L ? L : qd_model_hamiltonian(m), QD_FMT_TEXT, &b);
        for (size_t i = 0; i < qd_model_nsymmetries(m); i++)
            for (size_t j = 0; j < qd_model_ncoords(m); j++)
                qd_print(ctx, qd_model_symmetry_field(m, i, j), QD_FMT_TEXT, &b);
        for (size_t i = 0; i < qd_model_nintegrals(m); i++)
            qd_print(ctx, qd_model_integral(m, i), QD_FMT_TEXT, &b);
        /* and what acts at an impulse */
        for (size_t j = 0; j < qd_model_ncoords(m); j++)
            qd_print(ctx, qd_model_impulse(m, j), QD_FMT_TEXT, &b);
        for (size_t i = 0; i < qd_model_nimpact_constraints(m); i++)
            qd_print(ctx, qd_model_impact_constraint(m, i), QD_FMT_TEXT, &b);
        for (size_t i = 0; i < qd_model_nimpacts(m); i++)
            qd_print(ctx, qd_model_impact_gap(m, i), QD_FMT_TEXT, &b);
        for (size_t i = 0; i < qd_model_nprescribed(m); i++)
            qd_print(ctx, qd_model_prescribed(m, i), QD_FMT_TEXT, &b);
        for (size_t i = 0; i < qd_model_nspeeds(m); i++) {
            qd_print(ctx, qd_model_speed_definition(m, i), QD_FMT_TEXT, &b);
            if (qd_model_speed_initial(m, i))
                qd_print(ctx, qd_model_speed_initial(m, i), QD_FMT_TEXT, &b);
        }
        qd_model_free(m);
    } else {
        qd_diag_format(&d, "fuzz.qd", text, &b);
    }
    qd_buf_free(&b);
    qd_ctx_free(ctx);
    free(text);
    return 0;
}

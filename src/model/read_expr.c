/*
 * src/model/read_expr.c - one expression read as the model language reads
 * it after the model's statements (qd_model_read_expr, qdot/model.h): the
 * definitions with their vectors and components (P.x, P'.x, dot(r', r')),
 * position(BODY), omega(BODY), rotations, as well as the names the kernel
 * reader knows.  What a command line's --output or a Python output needs
 * beyond the kernel's grammar.
 *
 * The text is read from a copy with everything outside the span blanked,
 * so the parser's errors carry the caller's offsets, lines and columns.
 */
#include "parser.h"
#include "base/diag.h"
#include "../base/args.h"

#include <stdlib.h>

const qd_expr *qd_model_read_expr(qd_ctx *ctx, const qd_model *m, const char *text, size_t a,
                                  size_t b) {
    if (!(ctx && m && text && a <= b)) {
        qd__args_null(ctx, __func__);
        return NULL;
    }
    char *copy = qd__diag_blanked(text, a, b);
    if (!copy) {
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory");
        return NULL;
    }
    /* the parser only reads the model here: its definitions, bodies, names */
    parser p = {ctx, {0}, (qd_model *)m, NULL, false, NULL, false, false, 0, NULL, NULL, false,
                false, false};
    p.momenta_ok = qd_model_hamiltonian(m) != NULL;
    qd__mdl_lex_init(&p.lx, copy);
    const qd_expr *x = NULL;
    if (p.lx.tok.kind == TK_EOF || p.lx.tok.kind == TK_NEWLINE)
        qd__mdl_perr(&p, a, 1, NULL, "an expression is missing");
    else if (qd__mdl_parse_scalar(&p, &x, "an expression") && p.lx.tok.kind != TK_EOF)
        qd__mdl_perr_tok(&p, NULL, "expected the end of the expression");
    free(copy);
    return p.failed ? NULL : x;
}

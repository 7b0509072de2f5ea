/*
 * cli/eom_out.h - `qdot eom` output: the equations M q'' = f of a model in
 * one of five formats (text, latex, json, sympy, c); with constraints
 * M q'' = f + A^T lambda and A q'' = b, the multipliers named
 * lambda_<constraint>.
 */
#ifndef QDOT_CLI_EOM_OUT_H
#define QDOT_CLI_EOM_OUT_H

#include "qdot/mech.h"
#include "model_file.h"
#include "state.h"

typedef enum cli_eom_format { QD_EOM_TEXT, QD_EOM_LATEX, QD_EOM_JSON, QD_EOM_SYMPY, QD_EOM_C }
    cli_eom_format;

/* What is printed.  In numeric mode (--at) every entry of M, f, acc, A, b,
 * lambda, R and T is a number node (qd_float) and st is the state they were
 * evaluated at. */
typedef struct cli_eom_view {
    qd_ctx *ctx;
    const cli_model_file *mf;
    const qd_eom *e;                /* n, q, qd, qdd */
    const qd_expr **M, **f;         /* n*n row-major, n */
    const qd_expr **acc;            /* n, or NULL when not solved */
    const qd_expr **A, **b;         /* ncon*n row-major, ncon: A q'' = b */
    const qd_expr **lambda;         /* ncon multipliers (numbers, or solved), or NULL */
    const qd_expr **R;              /* n constraint forces A^T lambda (numeric mode), or NULL */
    const qd_expr *T[3];            /* T2, T1, T0; NULL when L was given without T */
    bool split;                     /* T1 or T0 is not identically zero */
    bool numeric;
    const cli_state *st;             /* numeric mode only */
    /* Numeric mode: the reactions of the model's `reaction` statements that
     * could be computed (qd_eom_reaction): nreact names, 3 components each
     * as number nodes, and the relative residual of each. */
    size_t nreact;
    const char **react_name;
    const qd_expr **react;
    const double *react_res;
} cli_eom_view;

bool cli_eom_format_from_name(const char *name, cli_eom_format *out);
/* Append the view to out; QD_OK, or the status of a printer that failed. */
qd_status cli_eom_write(const cli_eom_view *v, cli_eom_format fmt, qd_buf *out);

/* "holonomic", "integrable" or "nonholonomic". */
const char *cli_eom_con_kind_name(qd_con_kind k);
/* The SymPy binding "name = Function('name')" (fn) or "= Symbol('name')"
 * of sym, when the SymPy printer prints it by its bare name (the speeds'
 * output shares it). */
void cli_eom_sympy_bind(qd_ctx *ctx, qd_buf *b, const qd_expr *sym, bool fn);
/* NAME = Matrix([...]) of the rows x cols expressions x (a column when cols
 * is 1), appended to b. */
qd_status cli_eom_sympy_matrix(qd_ctx *ctx, qd_buf *b, const char *name,
                               const qd_expr *const *x, size_t rows, size_t cols);

/* Print why qd_eom_derive failed, at the model statement to blame (a
 * constraint the message names, or T/L for a singular mass matrix); returns
 * the exit status. */
int cli_eom_derive_error(const qd_ctx *ctx, const cli_model_file *mf);

#endif

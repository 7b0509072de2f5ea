/*
 * cli/cmd_canonical.c - `qdot canonical FILE --Q "..." --P "..."`: is the
 * change of variables (q, p) -> (Q, P) canonical (qd_canonical_check)?  A
 * yes/no question, so the status carries the answer: canonical exits 0; a
 * scaled map ([Q_i, P_i] = c, c != 1: Goldstein's extended canonical
 * transformation, not a canonical one) and a map with a failing fundamental
 * bracket are a certified "no", exit 3 (QD_EXIT_NO) with the verdict and its
 * witness printed; a bracket neither proved nor refuted exits 1.
 * `--generator F1..F4 EXPR` instead gives the transformation a generating
 * function defines and K = H + dF/dt (qd_generate).  The variables are the
 * library's phase space (qd_phase): new ones Q, P or Q1..Qn, P1..Pn.
 */
#include "cli.h"

#include <stddef.h>
#include <stdlib.h>
#include <string.h>
#include "qdot/json.h"
#include "witness.h"
#include "model_cli.h"
#include "model_file.h"

typedef struct can_args {
    const char *Q, *P, *gen, *format;
    bool lagrange, newham;
    cli_list set;
} can_args;

static const char *const formats[] = {"text", "json", NULL};
static const char *const gen_types[] = {"F1", "F2", "F3", "F4", NULL};

static const cli_opt opts[] = {
    {"--Q", NULL, CLI_TEXT, offsetof(can_args, Q), "\"Q1, ...\"",
     "the new coordinates, one expression in q, p_q, t per coordinate", NULL, NULL},
    {"--P", NULL, CLI_TEXT, offsetof(can_args, P), "\"P1, ...\"", "the new momenta, likewise",
     NULL, NULL},
    {"--lagrange", NULL, CLI_FLAG, offsetof(can_args, lagrange), NULL,
     "the Lagrange brackets of the old variables and their duality", NULL, NULL},
    {"--K", NULL, CLI_FLAG, offsetof(can_args, newham), NULL,
     "F and the new Hamiltonian K = c H + sum P dQ/dt + dF/dt", NULL, NULL},
    {"--generator", NULL, CLI_CHOICE, offsetof(can_args, gen), "TYPE",
     "the map of the generating function EXPR (the argument after FILE) of this type",
     gen_types, NULL},
    {"--format", NULL, CLI_CHOICE, offsetof(can_args, format), "FORMAT", "how to write it",
     formats, NULL},
    {"--set", NULL, CLI_LIST, offsetof(can_args, set), "NAME=VALUE",
     "read the model with this parameter value", NULL, NULL},
    {0},
};

static const cli_spec spec = {
    "canonical", "FILE --Q \"Q1, ...\" --P \"P1, ...\" [options] | FILE --generator TYPE EXPR",
    "Is (q, p) -> (Q, P) canonical (exit 0 yes, 3 no)?  Or the map a generating function "
    "gives, with K = H + dF/dt.",
    opts, NULL, 1, 2, "FILE", true,
};

typedef struct can_run {
    qd_ctx *ctx;
    cli_model_file mf;
    qd_phase ph;
    const qd_expr **Q, **P; /* --Q and --P */
    qd_lagrange_result lb;  /* --lagrange */
    qd_newham nh;           /* --K */
    bool json;
} can_run;

/* ---- output ------------------------------------------------------------------ */

static char *text_of(qd_ctx *ctx, const qd_expr *x) {
    qd_buf b = QD_BUF_INIT;
    qd_print(ctx, x, QD_FMT_TEXT, &b);
    char *s = b.failed ? NULL : malloc(strlen(qd_buf_str(&b)) + 1);
    if (s)
        strcpy(s, qd_buf_str(&b));
    qd_buf_free(&b);
    return s;
}

/* key = x: a JSON member, or a line "  key = x" (nothing for NULL). */
static void put_expr(qd_ctx *ctx, qd_json *j, qd_buf *b, const char *key, const qd_expr *x) {
    if (j) {
        qd_json_key(j, key);
        qd_json_expr(j, ctx, x);
    } else if (x) {
        qd_buf_printf(b, "  %s = ", key);
        qd_print(ctx, x, QD_FMT_TEXT, b);
        qd_buf_puts(b, "\n");
    }
}

static int flush(qd_buf *b, qd_json *j) {
    if (j) {
        qd_json_end_object(j);
        qd_buf_puts(b, "\n");
        b->failed = b->failed || !qd_json_ok(j);
    }
    return cli_emit(b, "result");
}

/* The variables' names: old (q..., p...) or new (Q..., P...), 2n of each. */
static const char *var_name(const qd_phase *ph, bool new_vars, size_t a) {
    const qd_expr *const *q = new_vars ? ph->Q : ph->q, *const *p = new_vars ? ph->P : ph->p;
    return qd_expr_name(a < ph->n ? q[a] : p[a - ph->n]);
}

/* A 2n x 2n matrix as rows of expressions. */
static void put_matrix(can_run *r, qd_json *j, qd_buf *b, const char *key,
                       const qd_expr *const *M) {
    size_t m = 2 * r->ph.n;
    if (j) {
        qd_json_key(j, key);
        qd_json_begin_array(j);
    }
    for (size_t x = 0; x < m; x++) {
        if (j)
            qd_json_begin_array(j);
        else
            qd_buf_puts(b, "  [");
        for (size_t y = 0; y < m; y++) {
            if (j) {
                qd_json_expr(j, r->ctx, M[x * m + y]);
                continue;
            }
            qd_buf_puts(b, y ? ", " : "");
            qd_print(r->ctx, M[x * m + y], QD_FMT_TEXT, b);
        }
        if (j)
            qd_json_end_array(j);
        else
            qd_buf_puts(b, "]\n");
    }
    if (j)
        qd_json_end_array(j);
}

/* --lagrange: the brackets [u, v] of the old variables and L^T PB = I;
 * --K: F and the new Hamiltonian. */
static void write_extras(can_run *r, const can_args *a, bool answered, qd_buf *b, qd_json *j) {
    if (a->lagrange) {
        if (!j) {
            qd_buf_puts(b, "Lagrange brackets [u, v] = sum dQ/du dP/dv - dQ/dv dP/du, "
                           "rows and columns ");
            for (size_t k = 0; k < 2 * r->ph.n; k++)
                qd_buf_printf(b, "%s%s", k ? ", " : "", var_name(&r->ph, false, k));
            qd_buf_puts(b, "\n");
        }
        put_matrix(r, j, b, "lagrange", r->lb.L);
        if (r->lb.PB) {
            if (!j)
                qd_buf_puts(b, "Poisson brackets of the old variables in the new ones\n");
            put_matrix(r, j, b, "poisson_old_in_new", r->lb.PB);
        }
        if (j) {
            qd_json_key(j, "duality");
            if (r->lb.singular)
                qd_json_null(j);
            else
                qd_json_bool(j, r->lb.dual);
        } else {
            qd_buf_printf(b, "%s\n", r->lb.singular ? "duality: the Jacobian is singular (no inverse map)"
                                    : r->lb.dual    ? "duality: [L]^T (P) = 1 holds"
                                                    : "duality: [L]^T (P) = 1 FAILS");
        }
    }
    if (!a->newham)
        return;
    if (!answered) {
        if (j) {
            qd_json_key(j, "K");
            qd_json_null(j);
        } else {
            qd_buf_puts(b, "no new Hamiltonian: the map is neither canonical nor scaled\n");
        }
        return;
    }
    if (!j)
        qd_buf_puts(b, "new Hamiltonian K = c H + sum P dQ/dt + dF/dt, dF = c p dq - P dQ "
                       "(fixed t)\n");
    put_expr(r->ctx, j, b, j ? "valence" : "c", r->nh.valence);
    put_expr(r->ctx, j, b, "F", r->nh.F);
    put_expr(r->ctx, j, b, j ? "K_old" : "K(q, p, t)", r->nh.K_old);
    put_expr(r->ctx, j, b, j ? "K_new" : "K(Q, P, t)", r->nh.K_new);
    if (!j && !r->nh.F)
        qd_buf_puts(b, "  F: the exact form's antiderivative was not found in closed form\n");
}

/* The verdict, its witness and the extras; the exit status carries the
 * answer: 0 canonical, 3 a certified no (scaled or a failing bracket), 1
 * undecided. */
static int write_verdict(can_run *r, const can_args *a, const qd_canon_verdict *v) {
    static const char *const kind[] = {"canonical", "scaled", "not canonical", "undecided"};
    qd_ctx *ctx = r->ctx;
    size_t n = r->ph.n;
    qd_buf b = QD_BUF_INIT;
    qd_json j, *jp = r->json ? &j : NULL;
    char pair[160] = "";
    bool failed = v->kind == QD_CANON_NO || v->kind == QD_CANON_UNDECIDED;
    if (failed) /* "[Q1, P2]" */
        snprintf(pair, sizeof pair, "[%s, %s]",
                 var_name(&r->ph, true, v->pair == QD_PAIR_PP ? n + v->i : v->i),
                 var_name(&r->ph, true, v->pair == QD_PAIR_QQ ? v->j : n + v->j));
    char *s = text_of(ctx, failed ? v->value : v->scale);
    char *want = failed ? text_of(ctx, v->target) : NULL;
    if (jp) {
        qd_json_init(jp, &b);
        qd_json_begin_object(jp);
        qd_json_key(jp, "verdict");
        qd_json_string(jp, kind[v->kind]);
        put_expr(ctx, jp, &b, "scale", failed ? NULL : v->scale);
        qd_json_key(jp, "bracket");
        qd_json_string(jp, failed ? pair : NULL);
        put_expr(ctx, jp, &b, "value", failed ? v->value : NULL);
        put_expr(ctx, jp, &b, "should_be", failed ? v->target : NULL);
        cli_witness_json(jp, &v->check);
    } else {
        char how[96];
        cli_witness_how(&v->check, how, sizeof how);
        if (v->kind == QD_CANON_YES)
            qd_buf_printf(&b, "canonical%s\n", how);
        else if (v->kind == QD_CANON_SCALED)
            qd_buf_printf(&b, "not canonical (a scaled canonical map, c = %s): [Q_i, P_i] = %s%s\n",
                          s ? s : "?", s ? s : "?", how);
        else if (v->kind == QD_CANON_UNDECIDED)
            qd_buf_printf(&b, "could not decide: %s = %s, neither proved nor refuted equal to %s\n",
                          pair, s ? s : "?", want ? want : "?");
        else
            qd_buf_printf(&b, "not canonical: %s = %s (should be %s)\n", pair, s ? s : "?",
                          want ? want : "?");
        cli_witness_text(&b, &v->check);
    }
    free(s);
    free(want);
    write_extras(r, a, !failed, &b, jp);
    int rc = flush(&b, jp);
    if (rc != QD_EXIT_OK)
        return rc;
    return v->kind == QD_CANON_YES ? QD_EXIT_OK
           : v->kind == QD_CANON_UNDECIDED ? QD_EXIT_FAIL
                                           : QD_EXIT_NO;
}

/* ---- the two modes -------------------------------------------------------------- */

/* --Q or --P: one expression per coordinate; the error shown in the list. */
static int read_list(can_run *r, const char *what, const char *text, const qd_expr ***out) {
    qd_diag err;
    if (!(*out = calloc(r->ph.n + 1, sizeof **out))) {
        cli_diag_error("out of memory");
        return QD_EXIT_FAIL;
    }
    if (qd_phase_read_list(r->ctx, &r->ph, text, *out, &err) == QD_OK)
        return QD_EXIT_OK;
    cli_diag_read(what, text, &err);
    return cli_exit(err.status);
}

/* An error after the model was read: at its statement when it is about one. */
static int failure(const can_run *r) {
    return cli_diag_model(r->ctx, r->mf.path, r->mf.text, r->mf.model);
}

static int check(can_run *r, const can_args *a) {
    qd_ctx *ctx = r->ctx;
    qd_phase *ph = &r->ph;
    int rc = read_list(r, "--Q", a->Q, &r->Q);
    if (rc == QD_EXIT_OK)
        rc = read_list(r, "--P", a->P, &r->P);
    if (rc != QD_EXIT_OK)
        return rc;
    qd_canon_verdict v;
    if (qd_canonical_check(ctx, ph->n, ph->q, ph->p, r->Q, r->P, qd_time(ctx), &v) != QD_OK ||
        (a->newham && qd_phase_ham(ctx, ph, true) != QD_OK) ||
        ((a->lagrange || a->newham) && qd_phase_new_vars(ctx, ph) != QD_OK) ||
        (a->lagrange &&
         qd_lagrange_brackets(ctx, ph->n, ph->q, ph->p, r->Q, r->P, &r->lb) != QD_OK))
        return failure(r);
    bool answered = v.kind == QD_CANON_YES || v.kind == QD_CANON_SCALED;
    if (a->newham && answered &&
        qd_transformed_hamiltonian(ctx, ph->n, ph->q, ph->p, r->Q, r->P, ph->Q, ph->P,
                                   qd_time(ctx), ph->h->H, &r->nh) != QD_OK)
        return failure(r);
    if (!ph->Q && qd_phase_new_vars(ctx, ph) != QD_OK) /* the names of a failing bracket */
        return failure(r);
    return write_verdict(r, a, &v);
}

static int write_generated(can_run *r, const can_args *a, const qd_expr *F,
                           const qd_gen_result *g) {
    qd_ctx *ctx = r->ctx;
    size_t n = r->ph.n;
    qd_buf b = QD_BUF_INIT;
    qd_json j, *jp = r->json ? &j : NULL;
    if (jp) {
        qd_json_init(jp, &b);
        qd_json_begin_object(jp);
        qd_json_key(jp, "type");
        qd_json_string(jp, a->gen);
    } else {
        qd_buf_printf(&b, "generating function %s\n", a->gen);
    }
    put_expr(ctx, jp, &b, "F", F);
    if (!jp)
        qd_buf_puts(&b, "transformation (in q, p, t)\n");
    for (size_t k = 0; k < 2 * n; k++)
        put_expr(ctx, jp, &b, var_name(&r->ph, true, k), k < n ? g->Q[k] : g->P[k - n]);
    if (!jp)
        qd_buf_puts(&b, "new Hamiltonian K = H + dF/dt\n");
    put_expr(ctx, jp, &b, jp ? "K_old" : "K(q, p, t)", g->K_old);
    put_expr(ctx, jp, &b, jp ? "K_new" : "K(Q, P, t)", g->K_new);
    return flush(&b, jp);
}

static int generate(can_run *r, const can_args *a, const char *text) {
    qd_ctx *ctx = r->ctx;
    qd_phase *ph = &r->ph;
    qd_diag err;
    if (qd_phase_new_vars(ctx, ph) != QD_OK) /* F is a function of them too */
        return failure(r);
    const qd_expr *F = qd_phase_read(ctx, ph, text, &err);
    if (!F) {
        cli_diag_read("generator", text, &err);
        return cli_exit(err.status);
    }
    if (qd_phase_ham(ctx, ph, true) != QD_OK)
        return failure(r);
    qd_gen_result g = {0};
    qd_status st = qd_generate(ctx, (qd_gen_type)(a->gen[1] - '0'), ph->n, ph->q, ph->p, ph->Q,
                               ph->P, F, qd_time(ctx), ph->h->H, &g);
    int rc = st == QD_OK ? write_generated(r, a, F, &g) : failure(r);
    qd_gen_result_free(&g);
    return rc;
}

/* The options' combinations: --Q with --P, or --generator with its EXPR. */
static int combination(const can_args *a, const char *expr) {
    const char *why = a->gen && (a->Q || a->P) ? "give either --Q and --P or --generator"
                      : a->gen && (a->lagrange || a->newham)
                          ? "--lagrange and --K go with --Q and --P"
                      : a->gen && !expr ? "--generator needs its expression EXPR after FILE"
                      : !a->gen && expr ? "an expression after FILE goes with --generator"
                      : !a->gen && !a->Q ? "--Q is missing"
                      : !a->gen && !a->P ? "--P is missing"
                                         : NULL;
    if (!why)
        return QD_EXIT_OK;
    cli_diag_error("%s (qdot canonical --help)", why);
    return QD_EXIT_USAGE;
}

int cli_cmd_canonical(int argc, char **argv) {
    can_args a = {0};
    const char *pos[2];
    int rc = cli_parse(&spec, argc, argv, &a, pos);
    if (rc == QD_EXIT_OK)
        rc = combination(&a, pos[1]);
    if (rc != QD_EXIT_OK)
        return rc;
    can_run r = {.ctx = qd_ctx_new(), .json = a.format && !strcmp(a.format, "json")};
    if (!r.ctx) {
        cli_diag_error("out of memory");
        return QD_EXIT_FAIL;
    }
    rc = cli_load(r.ctx, pos[0], a.set.n, a.set.items, true, &r.mf);
    if (rc == QD_EXIT_OK && qd_phase_init(r.ctx, r.mf.model, &r.ph) != QD_OK)
        rc = cli_diag_ctx(r.ctx);
    if (rc == QD_EXIT_OK)
        rc = a.gen ? generate(&r, &a, pos[1]) : check(&r, &a);
    free(r.Q);
    free(r.P);
    qd_lagrange_result_free(&r.lb);
    qd_phase_free(&r.ph);
    cli_model_file_free(&r.mf);
    qd_ctx_free(r.ctx);
    return rc;
}

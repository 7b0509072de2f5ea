/*
 * cli/cmd_canonical.c - `qdot canonical FILE --Q "..." --P "..."`: is the
 * change of variables (q, p) -> (Q, P) canonical (qd_canonical_check)?  The
 * verdict answers a yes/no question, so the status carries the answer:
 * canonical exits 0; a scaled map ([Q_i, P_i] = c, c != 1: Goldstein's
 * extended canonical transformation, not a canonical one) and a map with a
 * failing fundamental bracket exit EXIT_NOT_CANONICAL, with the verdict
 * printed as usual (a failure prints nothing on standard output).
 * `--generator F1..F4 EXPR` instead gives the transformation a generating
 * function defines and K = H + dF/dt (qd_generate, H from hamilton.h).
 * The new variables are Q, P for a model with one coordinate and Q1..Qn,
 * P1..Pn otherwise: both in the verdict's brackets and in a generator.
 */
#include "cli.h"

#include <stdlib.h>
#include <string.h>
#include "qdot/json.h"
#include "witness.h"
#include "model_cli.h"
#include "model_file.h"

/* The answer "no"; a failure prints nothing on standard output. */
enum { EXIT_NOT_CANONICAL = QD_EXIT_FAIL };

typedef struct can_args {
    const char *file, *Q, *P, *gen_type, *gen;
    bool json, lagrange, newham;
    const char *sets[QD_CLI_MAX_LIST];
    size_t nsets;
} can_args;

typedef struct can_run {
    cli_phase ph;
    const qd_expr **Q, **P; /* expressions (--Q/--P) or the new symbols (--generator) */
    const qd_expr **newQ, **newP;
    char **names;           /* 2n names of the new variables */
    qd_lagrange_result lb;  /* --lagrange */
    qd_newham nh;           /* --K */
} can_run;

static const char usage_text[] =
    "usage: qdot canonical FILE --Q \"Q1, ...\" --P \"P1, ...\" [--lagrange] [--K] "
    "[--format text|json] [--set NAME=VALUE]...\n"
    "       qdot canonical FILE --generator F1|F2|F3|F4 EXPR [--format text|json] "
    "[--set NAME=VALUE]...";

static int parse_option(int argc, char **argv, int *i, void *data) {
    can_args *a = data;
    const char *v;
    if ((v = cli_value(argc, argv, i, "--set")))
        return cli_push("--set", a->sets, &a->nsets, QD_CLI_MAX_LIST, v);
    if ((v = cli_value(argc, argv, i, "--Q")) && !a->Q)
        a->Q = v;
    else if ((v = cli_value(argc, argv, i, "--P")) && !a->P)
        a->P = v;
    else if (!strcmp(argv[*i], "--lagrange"))
        a->lagrange = true;
    else if (!strcmp(argv[*i], "--K"))
        a->newham = true;
    else if ((v = cli_value(argc, argv, i, "--format")) && (!strcmp(v, "text") || !strcmp(v, "json")))
        a->json = !strcmp(v, "json");
    else if (!strcmp(argv[*i], "--generator") && *i + 2 < argc && !a->gen) {
        a->gen_type = argv[++*i];
        a->gen = argv[++*i];
    } else {
        cli_diag_error("bad, repeated or incomplete option '%s'\n%s", argv[*i], usage_text);
        return QD_EXIT_USAGE;
    }
    return QD_EXIT_OK;
}

static int parse_args(int argc, char **argv, can_args *a) {
    *a = (can_args){0};
    int rc = cli_file_args(argc, argv, "canonical", usage_text, &a->file, parse_option, a);
    if (rc != QD_EXIT_OK)
        return rc;
    const char *why = a->gen && (a->Q || a->P) ? "give either --Q and --P or --generator"
                      : a->gen && (a->lagrange || a->newham) ? "--lagrange and --K go with --Q and --P"
                      : !a->gen && !a->Q       ? "--Q is missing"
                      : !a->gen && !a->P       ? "--P is missing"
                                               : NULL;
    if (why) {
        cli_diag_error("%s\n%s", why, usage_text);
        return QD_EXIT_USAGE;
    }
    return QD_EXIT_OK;
}

/* The new variables' names and symbols: Q, P or Q1.., P1... */
static int new_symbols(can_run *r) {
    size_t n = r->ph.n;
    r->names = calloc(2 * n, sizeof *r->names);
    r->newQ = calloc(n + 1, sizeof *r->newQ);
    r->newP = calloc(n + 1, sizeof *r->newP);
    if (!r->names || !r->newQ || !r->newP)
        return QD_EXIT_FAIL;
    for (size_t k = 0; k < 2 * n; k++) {
        if (!(r->names[k] = malloc(32)))
            return QD_EXIT_FAIL;
        snprintf(r->names[k], 32, n == 1 ? "%c" : "%c%zu", k < n ? 'Q' : 'P', k % n + 1);
    }
    return QD_EXIT_OK;
}

static int make_symbols(can_run *r) {
    for (size_t k = 0; k < 2 * r->ph.n; k++) {
        const qd_expr *s = qd_symbol(r->ph.ctx, r->names[k]);
        if (!s)
            return cli_diag_ctx(r->ph.ctx);
        (k < r->ph.n ? r->newQ : r->newP)[k % r->ph.n] = s;
    }
    return QD_EXIT_OK;
}

/* One comma-separated item of --Q or --P; out[k] gets it. */
static int read_item(can_run *r, const char *what, const char *s, size_t len,
                     const qd_expr **out) {
    char *text = malloc(len + 1);
    if (!text)
        return QD_EXIT_FAIL;
    memcpy(text, s, len);
    text[len] = '\0';
    int rc = cli_phase_read(&r->ph, what, text, out);
    free(text);
    return rc;
}

/* "e1, e2, ..." split at the commas outside parentheses: exactly n items. */
static int read_list(can_run *r, const char *what, const char *s, const qd_expr **out) {
    size_t k = 0, start = 0, i = 0;
    int depth = 0, rc = QD_EXIT_OK;
    for (;; i++) {
        depth += (s[i] == '(') - (s[i] == ')');
        if (s[i] && (s[i] != ',' || depth))
            continue;
        if (k == r->ph.n) {
            k++;
            break;
        }
        if ((rc = read_item(r, what, s + start, i - start, &out[k++])) != QD_EXIT_OK || !s[i])
            break;
        start = i + 1;
    }
    if (rc == QD_EXIT_OK && k != r->ph.n) {
        cli_diag_error("%s needs %zu expression%s, one per coordinate", what, r->ph.n,
                      r->ph.n == 1 ? "" : "s");
        rc = QD_EXIT_USAGE;
    }
    return rc;
}

/* ---- output ------------------------------------------------------------------ */

static char *text_of(qd_ctx *ctx, const qd_expr *x) {
    qd_buf b = QD_BUF_INIT;
    qd_print(ctx, x, QD_FMT_TEXT, &b);
    size_t len = b.failed ? 0 : strlen(qd_buf_str(&b));
    char *s = b.failed ? NULL : malloc(len + 1);
    if (s)
        memcpy(s, qd_buf_str(&b), len + 1);
    qd_buf_free(&b);
    return s;
}

static void put_expr(qd_ctx *ctx, qd_json *j, qd_buf *b, const char *key, const qd_expr *x) {
    char *s = x ? text_of(ctx, x) : NULL;
    if (j) {
        qd_json_key(j, key);
        if (s)
            qd_json_string(j, s);
        else
            qd_json_null(j);
    } else if (s) {
        qd_buf_printf(b, "  %s = %s\n", key, s);
    }
    free(s);
}

static int flush(qd_buf *b, qd_json *j) {
    if (j) {
        qd_json_end_object(j);
        qd_buf_puts(b, "\n");
        b->failed = b->failed || !qd_json_ok(j);
    }
    bool ok = !b->failed;
    if (ok)
        fputs(qd_buf_str(b), stdout);
    else
        cli_diag_error("cannot print the result");
    qd_buf_free(b);
    return ok ? QD_EXIT_OK : QD_EXIT_FAIL;
}

/* "[Q1, P2]" for the failing bracket of a verdict. */
static void pair_name(const can_run *r, const qd_canon_verdict *v, char *out, size_t size) {
    size_t n = r->ph.n;
    const char *a = r->names[v->pair == QD_PAIR_PP ? n + v->i : v->i];
    const char *b = r->names[v->pair == QD_PAIR_QQ ? v->j : n + v->j];
    snprintf(out, size, "[%s, %s]", a, b);
}

/* The exit status of a printed verdict. */
static int answer(const qd_canon_verdict *v, int printed) {
    return printed == QD_EXIT_OK && v->kind != QD_CANON_YES ? EXIT_NOT_CANONICAL : printed;
}

static void write_extras(can_run *r, const can_args *a, const qd_canon_verdict *v, qd_buf *b,
                         qd_json *j);

static int write_verdict(can_run *r, const can_args *a, const qd_canon_verdict *v, bool json) {
    qd_ctx *ctx = r->ph.ctx;
    static const char *const kind[] = {"canonical", "scaled", "not canonical", "undecided"};
    qd_buf b = QD_BUF_INIT;
    qd_json j;
    char pair[128] = "";
    bool failed = v->kind == QD_CANON_NO || v->kind == QD_CANON_UNDECIDED;
    if (failed)
        pair_name(r, v, pair, sizeof pair);
    if (json) {
        qd_json_init(&j, &b);
        qd_json_begin_object(&j);
        qd_json_key(&j, "verdict");
        qd_json_string(&j, kind[v->kind]);
        put_expr(ctx, &j, &b, "scale", failed ? NULL : v->scale);
        qd_json_key(&j, "bracket");
        if (pair[0])
            qd_json_string(&j, pair);
        else
            qd_json_null(&j);
        put_expr(ctx, &j, &b, "value", pair[0] ? v->value : NULL);
        put_expr(ctx, &j, &b, "should_be", pair[0] ? v->target : NULL);
        cli_witness_json(&j, &v->check);
        write_extras(r, a, v, &b, &j);
        return answer(v, flush(&b, &j));
    }
    char *s = text_of(ctx, failed ? v->value : v->scale);
    char *want = failed ? text_of(ctx, v->target) : NULL;
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
    free(s);
    free(want);
    write_extras(r, a, v, &b, NULL);
    return answer(v, flush(&b, NULL));
}

/* The old variables' names: q..., p_q... */
static const char *old_name(const can_run *r, size_t a) {
    return qd_expr_name(a < r->ph.n ? r->ph.q[a] : r->ph.p[a - r->ph.n]);
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
            char *s = text_of(r->ph.ctx, M[x * m + y]);
            if (j)
                qd_json_string(j, s ? s : "?");
            else
                qd_buf_printf(b, "%s%s", y ? ", " : "", s ? s : "?");
            free(s);
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
static void write_extras(can_run *r, const can_args *a, const qd_canon_verdict *v, qd_buf *b,
                         qd_json *j) {
    qd_ctx *ctx = r->ph.ctx;
    size_t n = r->ph.n;
    if (a->lagrange) {
        if (!j) {
            qd_buf_puts(b, "Lagrange brackets [u, v] = sum dQ/du dP/dv - dQ/dv dP/du, "
                           "rows and columns ");
            for (size_t k = 0; k < 2 * n; k++)
                qd_buf_printf(b, "%s%s", k ? ", " : "", old_name(r, k));
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
    if (a->newham) {
        if (v->kind == QD_CANON_NO || v->kind == QD_CANON_UNDECIDED) {
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
        put_expr(ctx, j, b, j ? "valence" : "c", r->nh.valence);
        put_expr(ctx, j, b, "F", r->nh.F);
        put_expr(ctx, j, b, j ? "K_old" : "K(q, p, t)", r->nh.K_old);
        put_expr(ctx, j, b, j ? "K_new" : "K(Q, P, t)", r->nh.K_new);
        if (!j && !r->nh.F)
            qd_buf_puts(b, "  F: the exact form's antiderivative was not found in closed form\n");
    }
}

/* ---- the two modes -------------------------------------------------------------- */

static int check(can_run *r, const can_args *a, bool json) {
    size_t n = r->ph.n;
    r->Q = calloc(n + 1, sizeof *r->Q);
    r->P = calloc(n + 1, sizeof *r->P);
    if (!r->Q || !r->P)
        return QD_EXIT_FAIL;
    int rc = read_list(r, "--Q", a->Q, r->Q);
    if (rc == QD_EXIT_OK)
        rc = read_list(r, "--P", a->P, r->P);
    if (rc != QD_EXIT_OK)
        return rc;
    qd_canon_verdict v;
    if (qd_canonical_check(r->ph.ctx, n, r->ph.q, r->ph.p, r->Q, r->P, qd_time(r->ph.ctx), &v) !=
        QD_OK)
        return cli_diag_ctx(r->ph.ctx);
    if (a->newham && (rc = cli_phase_ham(&r->ph, true)) != QD_EXIT_OK)
        return rc;
    if ((a->lagrange || a->newham) && make_symbols(r) != QD_EXIT_OK)
        return cli_diag_ctx(r->ph.ctx);
    if (a->lagrange &&
        qd_lagrange_brackets(r->ph.ctx, n, r->ph.q, r->ph.p, r->Q, r->P, &r->lb) != QD_OK)
        return cli_diag_ctx(r->ph.ctx);
    if (a->newham && v.kind != QD_CANON_NO && v.kind != QD_CANON_UNDECIDED &&
        qd_transformed_hamiltonian(r->ph.ctx, n, r->ph.q, r->ph.p, r->Q, r->P, r->newQ, r->newP,
                                   qd_time(r->ph.ctx), r->ph.h->H, &r->nh) != QD_OK)
        return cli_diag_ctx(r->ph.ctx);
    return write_verdict(r, a, &v, json);
}

static int gen_type(const char *s, qd_gen_type *t) {
    if ((s[0] == 'F' || s[0] == 'f') && s[1] >= '1' && s[1] <= '4' && !s[2]) {
        *t = (qd_gen_type)(s[1] - '0');
        return QD_EXIT_OK;
    }
    cli_diag_error("--generator takes a type F1, F2, F3 or F4, not '%s'\n%s", s, usage_text);
    return QD_EXIT_USAGE;
}

static int write_generated(can_run *r, const can_args *a, const qd_expr *F,
                           const qd_gen_result *g) {
    qd_ctx *ctx = r->ph.ctx;
    size_t n = r->ph.n;
    qd_buf b = QD_BUF_INIT;
    qd_json j, *jp = a->json ? &j : NULL;
    if (jp) {
        qd_json_init(jp, &b);
        qd_json_begin_object(jp);
        qd_json_key(jp, "type");
        qd_json_string(jp, a->gen_type);
    } else {
        qd_buf_printf(&b, "generating function %s\n", a->gen_type);
    }
    put_expr(ctx, jp, &b, "F", F);
    if (!jp)
        qd_buf_puts(&b, "transformation (in q, p, t)\n");
    for (size_t k = 0; k < 2 * n; k++)
        put_expr(ctx, jp, &b, r->names[k], k < n ? g->Q[k] : g->P[k - n]);
    if (!jp)
        qd_buf_puts(&b, "new Hamiltonian K = H + dF/dt\n");
    put_expr(ctx, jp, &b, jp ? "K_old" : "K(q, p, t)", g->K_old);
    put_expr(ctx, jp, &b, jp ? "K_new" : "K(Q, P, t)", g->K_new);
    return flush(&b, jp);
}

static int generate(can_run *r, const can_args *a) {
    qd_gen_type type;
    const qd_expr *F;
    int rc = gen_type(a->gen_type, &type);
    if (rc == QD_EXIT_OK)
        rc = make_symbols(r);
    if (rc == QD_EXIT_OK)
        rc = cli_phase_read(&r->ph, "generator", a->gen, &F);
    if (rc == QD_EXIT_OK)
        rc = cli_phase_ham(&r->ph, true);
    if (rc != QD_EXIT_OK)
        return rc;
    qd_gen_result g = {0};
    qd_status st = qd_generate(r->ph.ctx, type, r->ph.n, r->ph.q, r->ph.p, r->newQ, r->newP, F,
                               qd_time(r->ph.ctx), r->ph.h->H, &g);
    rc = st == QD_OK ? write_generated(r, a, F, &g) : cli_diag_ctx(r->ph.ctx);
    qd_gen_result_free(&g);
    return rc;
}

static void can_free(can_run *r) {
    for (size_t k = 0; r->names && k < 2 * r->ph.n; k++)
        free(r->names[k]);
    free(r->names);
    free(r->newQ);
    free(r->newP);
    free(r->Q);
    free(r->P);
    qd_lagrange_result_free(&r->lb);
    cli_phase_free(&r->ph);
}

int cli_cmd_canonical(int argc, char **argv) {
    can_args a;
    int rc = parse_args(argc, argv, &a);
    if (rc != QD_EXIT_OK)
        return rc;
    can_run r = {0};
    rc = cli_phase_load(a.file, a.nsets, a.sets, &r.ph);
    if (rc == QD_EXIT_OK && (rc = new_symbols(&r)) != QD_EXIT_OK)
        cli_diag_error("out of memory");
    if (rc == QD_EXIT_OK)
        rc = a.gen ? generate(&r, &a) : check(&r, &a, a.json);
    can_free(&r);
    return rc;
}

/*
 * cli/cmd_stability.c - `qdot stability FILE`: steady motions of a system
 * with cyclic coordinates and their stability (libqdot's qdot/stability.h).
 *
 *   --ignore phi[,psi]          the cyclic momenta are free (Routhian, V + K)
 *   --driven "phi' = Omega"     the rate is maintained (V - T0); "phi" alone
 *                               leaves Omega to be found from --at
 *   --momentum "p_phi=3"        free case: the momentum (else found from --at)
 *   --omega "phi'=2"            free case: the steady rate instead of p
 *   --at "theta=pi/3"           kept coordinates held at these values: the rate
 *                               (or momentum) that makes them steady is found
 *   --guess "r=1"               starting values of the search, not held: kept
 *                               coordinates, rates ("phi'=2") or momenta
 *                               ("p_phi=3", turned into rates at the start)
 * Every steady motion for the values given is found (qd_steady_find_all:
 * the two precessions of a top) and each is analysed; the first printed is
 * the one nearest the starting values.
 * Values are expressions in the parameters (--set applies first).
 *   --scan NAME=A:B [--steps N] the steady motion followed as the parameter
 *                               goes from A to B (qd_stability_scan), the
 *                               given values held at their numbers
 */
#include "cli.h"

#include <ctype.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "qdot/json.h"
#include "linear_cli.h"
#include "model_cli.h"
#include "model_file.h"
#include "qdot/stability.h"
#include "state.h"

#define MAX_SETS QD_CLI_MAX_LIST
#define MAX_LIST 16

typedef struct stab_args {
    const char *file, *ignore, *driven[MAX_LIST], *momentum, *omega, *at, *guess, *scan;
    size_t steps;
    const char *sets[MAX_SETS];
    size_t nsets, ndriven;
    bool json;
} stab_args;

typedef struct stab_run {
    qd_ctx *ctx;
    cli_model_file mf;
    qd_eom *e;
    qd_steady *s;
    cli_state st;                     /* parameters (and t) for evaluation */
    size_t ncyc;
    const qd_expr *cyc[MAX_LIST];
    bool *xfix, wfix[MAX_LIST], pfix[MAX_LIST];
    bool pguess[MAX_LIST], wguess[MAX_LIST];  /* --guess gave p_Q or Q' */
    bool *xseen;                     /* named in the --guess or --at being read */
    qd_steady_point pt;              /* the given values and the starting guesses */
    qd_steady_set set;               /* every steady motion found */
    qd_stability *an;                /* set.count analyses */
    size_t nsingular;                /* motions left out: singular coordinates there */
    const qd_expr *last;             /* the expression value_of read last */
    const qd_expr **given;           /* nkeep + 2 ncyc: the held values as read (x, w, p),
                                        for --scan to follow the parameter */
} stab_run;

static const char usage_text[] =
    "usage: qdot stability FILE (--ignore Q[,Q...] [--momentum \"p_Q=VALUE\"] [--omega \"Q'=VALUE\"]"
    " | --driven \"Q' = VALUE\"...) [--at \"q=VALUE, ...\"] [--guess \"q=VALUE, ...\"] "
    "[--scan NAME=A:B [--steps N]] [--set NAME=VALUE]... [--format text|json]";

static const char *const formats[] = {"text", "json", NULL};

static int steps_option(const char *v, size_t *steps) {
    char *end;
    long k = strtol(v, &end, 10);
    if (*end || k < 1 || k > 100000) {
        cli_diag_error("--steps takes a number of steps from 1 to 100000, not '%s'", v);
        return QD_EXIT_USAGE;
    }
    *steps = (size_t)k;
    return QD_EXIT_OK;
}

static int parse_option(int argc, char **argv, int *i, void *data) {
    stab_args *a = data;
    const char *v;
    int f;
    if ((v = cli_value(argc, argv, i, "--format"))) {
        int rc = cli_choice("--format", v, formats, &f);
        a->json = f == 1;
        return rc;
    }
    if ((v = cli_value(argc, argv, i, "--set")))
        return cli_push("--set", a->sets, &a->nsets, MAX_SETS, v);
    if ((v = cli_value(argc, argv, i, "--driven")))
        return cli_push("--driven", a->driven, &a->ndriven, MAX_LIST, v);
    if ((v = cli_value(argc, argv, i, "--ignore")))
        return cli_once("--ignore", &a->ignore, v);
    if ((v = cli_value(argc, argv, i, "--momentum")))
        return cli_once("--momentum", &a->momentum, v);
    if ((v = cli_value(argc, argv, i, "--omega")))
        return cli_once("--omega", &a->omega, v);
    if ((v = cli_value(argc, argv, i, "--at")))
        return cli_once("--at", &a->at, v);
    if ((v = cli_value(argc, argv, i, "--guess")))
        return cli_once("--guess", &a->guess, v);
    if ((v = cli_value(argc, argv, i, "--scan")))
        return cli_once("--scan", &a->scan, v);
    if ((v = cli_value(argc, argv, i, "--steps")))
        return steps_option(v, &a->steps);
    return cli_bad_option(argv[*i], usage_text);
}

static int parse_args(int argc, char **argv, stab_args *a) {
    *a = (stab_args){.json = false};
    int rc = cli_file_args(argc, argv, "stability", usage_text, &a->file, parse_option, a);
    if (rc != QD_EXIT_OK)
        return rc;
    if (!a->ignore == !a->ndriven) {
        cli_diag_error("give the cyclic coordinates with either --ignore (free momenta) or "
                      "--driven (maintained rates)\n%s", usage_text);
        return QD_EXIT_USAGE;
    }
    if (a->ndriven && (a->momentum || a->omega)) {
        cli_diag_error("--momentum and --omega go with --ignore; a driven rate is given as "
                      "--driven \"q' = VALUE\"");
        return QD_EXIT_USAGE;
    }
    if (a->steps && !a->scan) {
        cli_diag_error("--steps is the number of steps of --scan: give --scan NAME=A:B");
        return QD_EXIT_USAGE;
    }
    return QD_EXIT_OK;
}

/* ---- names and values --------------------------------------------------- */

static void trim(const char **a, const char **b) {
    while (*a < *b && isspace((unsigned char)**a))
        (*a)++;
    while (*b > *a && isspace((unsigned char)(*b)[-1]))
        (*b)--;
}

/* A value: an expression in the parameters, evaluated at their values. */
static int value_of(stab_run *r, const char *what, const char *a, const char *b, double *out) {
    trim(&a, &b);
    char *text = malloc((size_t)(b - a) + 1);
    if (!text)
        return QD_EXIT_FAIL;
    memcpy(text, a, (size_t)(b - a));
    text[b - a] = '\0';
    qd_diag err;
    const qd_read_opts opts = {.new_symbols = false};
    const qd_expr *e = qd_read(r->ctx, text, &opts, &err);
    /* the parameters only: st's coordinates, velocities and t are 0 there */
    size_t skip = 2 * qd_model_ncoords(r->mf.model) + 1;
    int rc = QD_EXIT_OK;
    if (!e) {
        cli_diag_read(what, text, &err);
        rc = QD_EXIT_USAGE;
    } else if ((r->last = e),
               qd_eval(r->ctx, e, r->st.n - skip, r->st.syms + skip, r->st.vals + skip, out) !=
                   QD_OK ||
               !isfinite(*out)) {
        qd_ctx_clear_error(r->ctx);
        cli_diag_error("%s: '%s' is not a number (only parameters may appear in it)", what, text);
        rc = QD_EXIT_USAGE;
    }
    free(text);
    return rc;
}

static int coord_index(const stab_run *r, const char *a, const char *b) {
    const qd_model *m = r->mf.model;
    for (size_t i = 0; i < qd_model_ncoords(m); i++) {
        const char *q = qd_expr_name(qd_model_coord(m, i));
        if (strlen(q) == (size_t)(b - a) && !strncmp(q, a, (size_t)(b - a)))
            return (int)i;
    }
    return -1;
}

static int unknown_coord(const char *what, const char *a, const char *b) {
    cli_diag_error("%s: '%.*s' is not a coordinate of the model", what, (int)(b - a), a);
    return QD_EXIT_USAGE;
}

/* Add coordinate text[a, b) to the cyclic list. */
static int add_cyclic(stab_run *r, const char *what, const char *a, const char *b) {
    trim(&a, &b);
    int i = coord_index(r, a, b);
    if (i < 0)
        return unknown_coord(what, a, b);
    for (size_t c = 0; c < r->ncyc; c++)
        if (r->cyc[c] == qd_model_coord(r->mf.model, (size_t)i)) {
            cli_diag_error("%s: %.*s is listed twice", what, (int)(b - a), a);
            return QD_EXIT_USAGE;
        }
    if (r->ncyc == MAX_LIST) {
        cli_diag_error("at most %d cyclic coordinates", MAX_LIST);
        return QD_EXIT_USAGE;
    }
    r->cyc[r->ncyc++] = qd_model_coord(r->mf.model, (size_t)i);
    return QD_EXIT_OK;
}

/* Call item(r, what, name_a, name_b, value_a, value_b) on each NAME=VALUE
 * (or NAME alone when bare is allowed) of a comma-separated list. */
typedef int (*item_fn)(stab_run *r, const char *what, const char *na, const char *nb,
                       const char *va, const char *vb);

static int each_item(stab_run *r, const char *what, const char *text, bool bare, item_fn fn) {
    const char *p = text;
    while (*p) {
        const char *end = p;
        int depth = 0;
        for (; *end && (*end != ',' || depth > 0); end++)
            depth += (*end == '(' || *end == '[') - ((*end == ')' || *end == ']') && depth > 0);
        const char *eq = memchr(p, '=', (size_t)(end - p)), *na = p, *nb = eq ? eq : end;
        trim(&na, &nb);
        if (na < nb) {
            if (!eq && !bare) {
                cli_diag_error("%s: expected NAME=VALUE, not '%.*s'", what, (int)(end - p), p);
                return QD_EXIT_USAGE;
            }
            int rc = fn(r, what, na, nb, eq ? eq + 1 : NULL, end);
            if (rc != QD_EXIT_OK)
                return rc;
        }
        p = *end ? end + 1 : end;
    }
    return QD_EXIT_OK;
}

static int ignore_item(stab_run *r, const char *what, const char *na, const char *nb,
                       const char *va, const char *vb) {
    (void)va;
    (void)vb;
    return add_cyclic(r, what, na, nb);
}

static size_t cyc_slot(const stab_run *r, const qd_expr *q) {
    size_t c = 0;
    while (c < r->ncyc && r->cyc[c] != q)
        c++;
    return c;
}

/* The coordinate of a --driven item ("phi' = VALUE" or "phi"), added once. */
static int driven_name_item(stab_run *r, const char *what, const char *na, const char *nb,
                            const char *va, const char *vb) {
    (void)va;
    (void)vb;
    while (nb > na && nb[-1] == '\'')
        nb--;
    int k = coord_index(r, na, nb);
    if (k < 0)
        return unknown_coord(what, na, nb);
    if (cyc_slot(r, qd_model_coord(r->mf.model, (size_t)k)) < r->ncyc)
        return QD_EXIT_OK;
    return add_cyclic(r, what, na, nb);
}

/* --driven "phi' = VALUE" or "phi"; --omega "phi'=VALUE". */
static int rate_item(stab_run *r, const char *what, const char *na, const char *nb,
                     const char *va, const char *vb) {
    const char *q_end = nb;
    while (q_end > na && q_end[-1] == '\'')
        q_end--;
    if (va && q_end == nb) {
        cli_diag_error("%s: a rate is written with a prime, %.*s' = VALUE", what,
                      (int)(nb - na), na);
        return QD_EXIT_USAGE;
    }
    int i = coord_index(r, na, q_end);
    if (i < 0)
        return unknown_coord(what, na, q_end);
    size_t c = cyc_slot(r, qd_model_coord(r->mf.model, (size_t)i));
    if (c == r->ncyc) {  /* only --omega can name another coordinate */
        cli_diag_error("--omega: %.*s is not among the --ignore coordinates", (int)(q_end - na),
                      na);
        return QD_EXIT_USAGE;
    }
    if (!va)
        return QD_EXIT_OK;
    if (r->wfix[c]) {
        cli_diag_error("%s: the rate %.*s' is given twice", what, (int)(q_end - na), na);
        return QD_EXIT_USAGE;
    }
    r->wfix[c] = true;
    int rc = value_of(r, what, va, vb, &r->pt.w[c]);
    if (rc == QD_EXIT_OK)
        r->given[r->s->nkeep + c] = r->last;
    return rc;
}

static int momentum_item(stab_run *r, const char *what, const char *na, const char *nb,
                         const char *va, const char *vb) {
    for (size_t c = 0; c < r->ncyc; c++) {
        const char *p = qd_expr_name(r->s->beta[c]);
        if (strlen(p) == (size_t)(nb - na) && !strncmp(p, na, (size_t)(nb - na))) {
            if (r->pfix[c]) {
                cli_diag_error("%s: %s is given twice", what, p);
                return QD_EXIT_USAGE;
            }
            r->pfix[c] = true;
            int rc = value_of(r, what, va, vb, &r->pt.p[c]);
            if (rc == QD_EXIT_OK)
                r->given[r->s->nkeep + r->ncyc + c] = r->last;
            return rc;
        }
    }
    cli_diag_error("%s: '%.*s' is not the momentum of an ignored coordinate (they are p_<q>)",
                  what, (int)(nb - na), na);
    return QD_EXIT_USAGE;
}

static int kept_slot(const stab_run *r, const char *what, const char *na, const char *nb,
                     size_t *slot) {
    int i = coord_index(r, na, nb);
    if (i < 0)
        return unknown_coord(what, na, nb);
    for (size_t j = 0; j < r->s->nkeep; j++)
        if (r->s->keep[j] == qd_model_coord(r->mf.model, (size_t)i)) {
            *slot = j;
            return QD_EXIT_OK;
        }
    cli_diag_error("%s: %.*s is cyclic here; give its rate with --driven or --omega", what,
                  (int)(nb - na), na);
    return QD_EXIT_USAGE;
}

static int at_item(stab_run *r, const char *what, const char *na, const char *nb,
                   const char *va, const char *vb) {
    size_t j = 0;
    int rc = kept_slot(r, what, na, nb, &j);
    if (rc == QD_EXIT_OK && r->xseen[j]) {
        cli_diag_error("%s: %.*s is given twice", what, (int)(nb - na), na);
        rc = QD_EXIT_USAGE;
    }
    if (rc == QD_EXIT_OK) {
        r->xseen[j] = true;
        rc = value_of(r, what, va, vb, &r->pt.x[j]);
    }
    if (rc == QD_EXIT_OK)
        r->xfix[j] = !strcmp(what, "--at");
    if (rc == QD_EXIT_OK && r->xfix[j])
        r->given[j] = r->last;
    return rc;
}

/* --guess: a kept coordinate, a rate "Q'" or a momentum "p_Q", none held. */
static int guess_item(stab_run *r, const char *what, const char *na, const char *nb,
                      const char *va, const char *vb) {
    const char *q_end = nb;
    while (q_end > na && q_end[-1] == '\'')
        q_end--;
    for (size_t c = 0; c < r->ncyc; c++) {
        const char *q = qd_expr_name(r->cyc[c]);
        size_t len = strlen(q);
        bool rate = q_end < nb && (size_t)(q_end - na) == len && !strncmp(q, na, len);
        bool mom = q_end == nb && (size_t)(nb - na) == len + 2 && !strncmp(na, "p_", 2) &&
                   !strncmp(na + 2, q, len);
        if (!rate && !mom)
            continue;
        if (r->wfix[c] || (mom && r->pfix[c])) {   /* a rate whose momentum is given is
                                                       still unknown: guessing it is fine */
            cli_diag_error("%s: %.*s is given (--omega, --momentum or --driven): a guess "
                           "cannot change it", what, (int)(nb - na), na);
            return QD_EXIT_USAGE;
        }
        if (r->wguess[c] || r->pguess[c]) {
            cli_diag_error("%s: a starting value for %s is given twice", what, q);
            return QD_EXIT_USAGE;
        }
        *(rate ? &r->wguess[c] : &r->pguess[c]) = true;
        return value_of(r, what, va, vb, rate ? &r->pt.w[c] : &r->pt.p[c]);
    }
    if (q_end < nb || (coord_index(r, na, nb) < 0 && !strncmp(na, "p_", 2))) {
        cli_diag_error("%s: %.*s is not the rate or momentum of a cyclic coordinate (the kept "
                       "coordinates are at rest)", what, (int)(nb - na), na);
        return QD_EXIT_USAGE;
    }
    return at_item(r, what, na, nb, va, vb);
}

/* ---- the pipeline ---------------------------------------------------------- */

/* The starting values: the model's `initial` values, else 0 for coordinates
 * and 1 for rates. */
static int initial_guesses(stab_run *r) {
    const qd_model *m = r->mf.model;
    for (size_t i = 0; i < qd_model_ncoords(m); i++) {
        const qd_expr *q = qd_model_coord(m, i);
        size_t c = cyc_slot(r, q);
        const qd_expr *x = qd_model_initial(m, i, c < r->ncyc ? 1 : 0);
        double v = c < r->ncyc ? 1 : 0;
        if (x && (qd_eval(r->ctx, x, r->st.n, r->st.syms, r->st.vals, &v) != QD_OK ||
                  !isfinite(v))) {
            qd_ctx_clear_error(r->ctx);
            v = c < r->ncyc ? 1 : 0;
        }
        if (c < r->ncyc) {
            r->pt.w[c] = v != 0 ? v : 1;
            continue;
        }
        for (size_t j = 0; j < r->s->nkeep; j++)
            if (r->s->keep[j] == q)
                r->pt.x[j] = v;
    }
    return QD_EXIT_OK;
}

static int prepare(stab_run *r, const stab_args *a) {
    int rc = QD_EXIT_OK;
    if (a->ignore)
        rc = each_item(r, "--ignore", a->ignore, true, ignore_item);
    /* --driven names its coordinates; their values wait for the point. */
    for (size_t i = 0; rc == QD_EXIT_OK && i < a->ndriven; i++)
        rc = each_item(r, "--driven", a->driven[i], true, driven_name_item);
    if (rc != QD_EXIT_OK)
        return rc;
    r->s = qd_steady_derive(r->ctx, r->mf.model, r->e, r->ncyc, r->cyc, a->ndriven > 0);
    if (!r->s) {
        cli_diag_error("%s", qd_ctx_message(r->ctx));
        return qd_ctx_status(r->ctx) == QD_ERR_ARG ? QD_EXIT_USAGE : QD_EXIT_FAIL;
    }
    size_t nk = r->s->nkeep;
    r->xfix = calloc(nk + 1, sizeof *r->xfix);
    r->xseen = calloc(nk + 1, sizeof *r->xseen);
    r->pt.x = calloc(nk + 1, sizeof *r->pt.x);
    r->pt.w = calloc(MAX_LIST, sizeof *r->pt.w);
    r->pt.p = calloc(MAX_LIST, sizeof *r->pt.p);
    r->given = calloc(nk + 2 * r->ncyc + 1, sizeof *r->given);
    if (!r->xfix || !r->xseen || !r->pt.x || !r->pt.w || !r->pt.p || !r->given)
        return QD_EXIT_FAIL;
    rc = initial_guesses(r);
    for (size_t i = 0; rc == QD_EXIT_OK && i < a->ndriven; i++)
        rc = each_item(r, "--driven", a->driven[i], true, rate_item);
    if (rc == QD_EXIT_OK && a->omega)
        rc = each_item(r, "--omega", a->omega, false, rate_item);
    if (rc == QD_EXIT_OK && a->momentum)
        rc = each_item(r, "--momentum", a->momentum, false, momentum_item);
    if (rc == QD_EXIT_OK && a->guess)
        rc = each_item(r, "--guess", a->guess, false, guess_item);
    memset(r->xseen, 0, (nk + 1) * sizeof *r->xseen);
    if (rc == QD_EXIT_OK && a->at)
        rc = each_item(r, "--at", a->at, false, at_item);
    return rc;
}

static int fail(stab_run *r, qd_status st) {
    cli_diag_error("%s", qd_ctx_message(r->ctx)[0] ? qd_ctx_message(r->ctx) : qd_status_str(st));
    return st == QD_ERR_ARG ? QD_EXIT_USAGE : QD_EXIT_FAIL;
}

/* Every steady motion and its analysis: the library has left out the
 * motions where the coordinates are singular (counted in set.nsingular). */
static int solve(stab_run *r) {
    qd_status st = qd_steady_find_all(r->ctx, r->s, r->st.n, r->st.syms, r->st.vals, r->xfix,
                                      r->wfix, r->pfix, r->pguess, &r->pt, &r->set);
    if (st != QD_OK)
        return fail(r, st);
    r->nsingular = r->set.nsingular;
    r->an = calloc(r->set.count + 1, sizeof *r->an);
    if (!r->an)
        return QD_EXIT_FAIL;
    for (size_t k = 0; k < r->set.count; k++) {
        st = qd_stability_analyze(r->ctx, r->s, r->st.n, r->st.syms, r->st.vals, &r->set.pts[k],
                                  &r->an[k]);
        if (st != QD_OK)
            return fail(r, st);
    }
    return QD_EXIT_OK;
}

/* ---- --scan ------------------------------------------------------------------ */

/* Column names: the kept coordinates, Q' and p_Q (room: 64 bytes each). */
static void scan_names(const qd_steady *s, char (*buf)[64], const char **names) {
    size_t nk = s->nkeep, nc = s->ncyc;
    for (size_t j = 0; j < nk; j++)
        names[j] = qd_expr_name(s->keep[j]);
    for (size_t c = 0; c < nc; c++) {
        snprintf(buf[c], sizeof buf[c], "%s'", qd_expr_name(s->cyc[c]));
        snprintf(buf[nc + c], sizeof buf[nc + c], "p_%s", qd_expr_name(s->cyc[c]));
        names[nk + c] = buf[c];
        names[nk + nc + c] = buf[nc + c];
    }
}

/* The steady motion followed along a parameter: a table and the changes of
 * its stability. */
static int scan(stab_run *r, const stab_args *a) {
    char name[128];
    double lo, hi;
    int rc = cli_scan_range(r->ctx, a->scan, name, sizeof name, &lo, &hi);
    size_t nu = r->s->nkeep + 2 * r->ncyc;
    const char **names = calloc(nu + 1, sizeof *names);
    char (*buf)[64] = calloc(2 * r->ncyc + 1, sizeof *buf);
    if (!names || !buf)
        rc = QD_EXIT_FAIL;
    qd_scan_opts o = {.steps = a->steps, .about = r->given};
    qd_scan sc = {0};
    if (rc == QD_EXIT_OK && qd_stability_scan(r->ctx, r->s, r->mf.model, name, lo, hi, r->xfix,
                                              r->wfix, r->pfix, r->pguess, &r->pt, &o,
                                              &sc) != QD_OK) {
        rc = qd_ctx_status(r->ctx) == QD_ERR_ARG ? QD_EXIT_USAGE : QD_EXIT_FAIL;
        cli_diag_error("--scan: %s", qd_ctx_message(r->ctx));
    } else if (rc == QD_EXIT_OK) {
        scan_names(r->s, buf, names);
        const char *how = r->s->driven ? "rates maintained: V - T0" : "momenta free: Routhian";
        char followed[160];
        snprintf(followed, sizeof followed, "the steady motion (%s); %s stability", how,
                 sc.damped ? "with the model's damping" : "ordinary");
        cli_scan_view v = {name, names, followed, "steady_motion"};
        rc = cli_scan_emit(&v, &sc, a->json);
    }
    qd_scan_free(&sc);
    free(names);
    free(buf);
    return rc;
}

/* ---- output ------------------------------------------------------------------ */

static void put_num(qd_buf *b, double x) { cli_state_put_result(b, x); }

static void put_matrix(qd_buf *b, const char *name, const double *A, size_t n) {
    qd_buf_printf(b, "  %s = [", name);
    for (size_t i = 0; i < n; i++) {
        qd_buf_puts(b, i ? "; " : "");
        for (size_t j = 0; j < n; j++) {
            qd_buf_puts(b, j ? ", " : "");
            put_num(b, A[i * n + j]);
        }
    }
    qd_buf_puts(b, "]\n");
}

static const char *tri(int v, const char *yes, const char *no, const char *border) {
    return v == 1 ? yes : v == 0 ? no : border;
}

static double max_re(const qd_modes_result *m) {
    double x = -INFINITY;
    for (size_t i = 0; i < m->neig; i++)
        x = fmax(x, m->eig_re[i]);
    return x;
}

/* Rounding noise (1e-16 against roots of order 1) printed as 0: the real
 * parts of undamped gyroscopic roots are 0 exactly. */
static double shown(const qd_modes_result *m, double x) {
    double big = 0;
    for (size_t i = 0; i < m->neig; i++)
        big = fmax(big, hypot(m->eig_re[i], m->eig_im[i]));
    return fabs(x) <= 1e-13 * big ? 0 : x;
}

static void put_roots(qd_buf *b, const qd_modes_result *m) {
    for (size_t i = 0; i < m->neig; i++) {
        double im = shown(m, m->eig_im[i]);
        qd_buf_puts(b, i ? ", " : "");
        put_num(b, shown(m, m->eig_re[i]));
        qd_buf_puts(b, im < 0 ? " - " : " + ");
        put_num(b, fabs(im));
        qd_buf_puts(b, "i");
    }
}

/* How many motions, said once before them when there is more than one (or
 * some were left out). */
static void text_count(stab_run *r, qd_buf *b) {
    size_t n = r->set.count;
    if (n > 1)
        qd_buf_printf(b, "%zu steady motions for these values%s; the first is the one nearest "
                         "the starting values\n", n, r->set.complete ? "" : " (found from the "
                         "starting values: there may be others)");
    if (r->nsingular)
        qd_buf_printf(b, "(%zu more at singular points of the coordinates, left out)\n",
                      r->nsingular);
}

static void text_motion(stab_run *r, qd_buf *b, size_t k) {
    const qd_steady *s = r->s;
    const qd_stability *an = &r->an[k];
    const qd_steady_point *pt = &r->set.pts[k];
    if (r->set.count > 1)
        qd_buf_printf(b, "steady motion %zu of %zu (%s):\n", k + 1, r->set.count,
                      s->driven ? "rates maintained: V_eff = V - T0"
                                : "momenta free: V_eff = V + K, Routhian");
    else
        qd_buf_printf(b, "steady motion (%s):\n", s->driven ? "rates maintained: V_eff = V - T0"
                                                            : "momenta free: V_eff = V + K, "
                                                              "Routhian");
    for (size_t j = 0; j < s->nkeep; j++) {
        qd_buf_printf(b, "  %s = ", qd_expr_name(s->keep[j]));
        put_num(b, pt->x[j]);
        qd_buf_puts(b, r->xfix[j] ? "  (given)\n" : "\n");
    }
    for (size_t c = 0; c < s->ncyc; c++) {
        qd_buf_printf(b, "  %s = ", qd_expr_name(s->cycd[c]));
        put_num(b, pt->w[c]);
        qd_buf_printf(b, "%s, p_%s = ", r->wfix[c] ? " (given)" : "", qd_expr_name(s->cyc[c]));
        put_num(b, pt->p[c]);
        qd_buf_puts(b, r->pfix[c] ? " (given)\n" : "\n");
    }
    qd_buf_puts(b, "effective potential: V_eff = ");
    qd_print(r->ctx, s->Veff, QD_FMT_TEXT, b);
    qd_buf_puts(b, "\nlinearized about it: M0 x'' + (C0 + G0) x' + K0 x = 0\n");
    put_matrix(b, "M0", an->lin.M, an->n);
    if (an->dissipative)
        put_matrix(b, "C0", an->lin.C, an->n);
    put_matrix(b, "G0", an->lin.G, an->n);
    put_matrix(b, "K0", an->lin.K, an->n);
    put_matrix(b, "Hessian of V_eff", an->hessian, an->n);
    qd_buf_puts(b, "frequencies:");
    for (size_t i = 0; i < an->nfreq; i++) {
        qd_buf_puts(b, " ");
        put_num(b, an->freq[i]);
    }
    qd_buf_puts(b, an->nfreq ? "\n" : " none\n");
    qd_buf_puts(b, "roots s (no dissipation): ");
    put_roots(b, &an->ordinary);
    qd_buf_printf(b, "\nordinary stability: %s\n",
                  tri(an->ordinary_stable, "stable", "unstable", "borderline"));
    qd_buf_printf(b, "secular stability: %s\n",
                  tri(an->secular_stable, "stable (V_eff is a minimum)",
                      "unstable (V_eff is not a minimum)",
                      "borderline (the Hessian of V_eff is singular)"));
    if (an->dissipative) {
        qd_buf_puts(b, "with the model's dissipation: roots ");
        put_roots(b, &an->damped);
        qd_buf_printf(b, "\n  %s (max Re s = ", tri(an->damped_stable, "stable", "unstable",
                                                    "borderline"));
        put_num(b, max_re(&an->damped));
        qd_buf_puts(b, ")\n");
    }
    qd_buf_printf(b, "verdict: %s\n", an->verdict);
}

static void text_out(stab_run *r, qd_buf *b) {
    qd_buf_printf(b, "model: %s\n", r->mf.path);
    text_count(r, b);
    for (size_t k = 0; k < r->set.count; k++) {
        qd_buf_puts(b, k ? "\n" : "");
        text_motion(r, b, k);
    }
}

static void json_tri(qd_json *j, int v) {
    if (v < 0)
        qd_json_null(j);
    else
        qd_json_bool(j, v == 1);
}

static void json_matrix(qd_json *j, const char *key, const double *A, size_t n) {
    qd_json_key(j, key);
    qd_json_begin_array(j);
    for (size_t i = 0; i < n; i++) {
        qd_json_begin_array(j);
        for (size_t k = 0; k < n; k++)
            qd_json_number(j, A[i * n + k]);
        qd_json_end_array(j);
    }
    qd_json_end_array(j);
}

static void json_roots(qd_json *j, const char *key, const qd_modes_result *m) {
    qd_json_key(j, key);
    qd_json_begin_array(j);
    for (size_t i = 0; i < m->neig; i++) {
        qd_json_begin_array(j);
        qd_json_number(j, shown(m, m->eig_re[i]));
        qd_json_number(j, shown(m, m->eig_im[i]));
        qd_json_end_array(j);
    }
    qd_json_end_array(j);
}

static void json_steady(qd_json *j, const qd_steady *s, const qd_steady_point *pt) {
    qd_json_key(j, "steady");
    qd_json_begin_object(j);
    for (size_t k = 0; k < s->nkeep; k++) {
        qd_json_key(j, qd_expr_name(s->keep[k]));
        qd_json_number(j, pt->x[k]);
    }
    for (size_t c = 0; c < s->ncyc; c++) {
        qd_json_key(j, qd_expr_name(s->cycd[c]));
        qd_json_number(j, pt->w[c]);
        char name[160];
        snprintf(name, sizeof name, "p_%s", qd_expr_name(s->cyc[c]));
        qd_json_key(j, name);
        qd_json_number(j, pt->p[c]);
    }
    qd_json_end_object(j);
}

/* Every motion in short: where it is, its frequencies and verdicts. */
static void json_all(qd_json *j, stab_run *r) {
    qd_json_key(j, "steady_motions");
    qd_json_begin_array(j);
    for (size_t k = 0; k < r->set.count; k++) {
        const qd_stability *an = &r->an[k];
        qd_json_begin_object(j);
        json_steady(j, r->s, &r->set.pts[k]);
        qd_json_key(j, "residual");
        qd_json_number(j, r->set.residual[k]);
        qd_json_key(j, "frequencies");
        qd_json_begin_array(j);
        for (size_t i = 0; i < an->nfreq; i++)
            qd_json_number(j, an->freq[i]);
        qd_json_end_array(j);
        json_roots(j, "roots", &an->ordinary);
        qd_json_key(j, "stable");
        json_tri(j, an->ordinary_stable);
        qd_json_key(j, "secular");
        json_tri(j, an->secular_stable);
        qd_json_key(j, "verdict");
        qd_json_string(j, an->verdict);
        qd_json_end_object(j);
    }
    qd_json_end_array(j);
    qd_json_key(j, "complete");
    qd_json_bool(j, r->set.complete);
}

static void json_out(stab_run *r, qd_buf *b) {
    const qd_steady *s = r->s;
    const qd_stability *an = &r->an[0];
    qd_json j;
    qd_json_init(&j, b);
    qd_json_begin_object(&j);
    qd_json_key(&j, "model");
    qd_json_string(&j, r->mf.path);
    qd_json_key(&j, "kind");
    qd_json_string(&j, s->driven ? "driven" : "free");
    json_steady(&j, s, &r->set.pts[0]);
    qd_json_key(&j, "residual");
    qd_json_number(&j, r->set.residual[0]);
    qd_json_key(&j, "Veff");
    qd_json_expr(&j, r->ctx, s->Veff);
    json_matrix(&j, "M", an->lin.M, an->n);
    json_matrix(&j, "C", an->lin.C, an->n);
    json_matrix(&j, "G", an->lin.G, an->n);
    json_matrix(&j, "K", an->lin.K, an->n);
    json_matrix(&j, "hessian", an->hessian, an->n);
    qd_json_key(&j, "frequencies");
    qd_json_begin_array(&j);
    for (size_t i = 0; i < an->nfreq; i++)
        qd_json_number(&j, an->freq[i]);
    qd_json_end_array(&j);
    json_roots(&j, "roots", &an->ordinary);
    qd_json_key(&j, "stable");
    json_tri(&j, an->ordinary_stable);
    qd_json_key(&j, "secular");
    json_tri(&j, an->secular_stable);
    if (an->dissipative) {
        qd_json_key(&j, "dissipation");
        qd_json_begin_object(&j);
        json_roots(&j, "roots", &an->damped);
        qd_json_key(&j, "stable");
        json_tri(&j, an->damped_stable);
        qd_json_key(&j, "max_re");
        qd_json_number(&j, max_re(&an->damped));
        qd_json_end_object(&j);
    }
    qd_json_key(&j, "verdict");
    qd_json_string(&j, an->verdict);
    json_all(&j, r);
    qd_json_end_object(&j);
    qd_buf_puts(b, "\n");
    if (!qd_json_ok(&j))
        b->failed = true;
}

static int emit(stab_run *r, bool json) {
    qd_buf b = QD_BUF_INIT;
    if (json)
        json_out(r, &b);
    else
        text_out(r, &b);
    return cli_emit(&b, "result (a number that is not finite?)");
}

int cli_cmd_stability(int argc, char **argv) {
    stab_args a;
    int rc = parse_args(argc, argv, &a);
    if (rc != QD_EXIT_OK)
        return rc;
    stab_run r = {.ctx = qd_ctx_new()};
    if (!r.ctx) {
        cli_diag_error("out of memory");
        return QD_EXIT_FAIL;
    }
    rc = cli_load_derive(r.ctx, a.file, a.nsets, a.sets, false, NULL, &r.mf, &r.e);
    if (rc == QD_EXIT_OK)
        rc = cli_state_init(r.ctx, r.mf.model, &r.st);
    if (rc == QD_EXIT_OK)
        rc = prepare(&r, &a);
    if (rc == QD_EXIT_OK && a.scan) {
        rc = scan(&r, &a);
        goto done;
    }
    if (rc == QD_EXIT_OK)
        rc = solve(&r);
    if (rc == QD_EXIT_OK)
        rc = emit(&r, a.json);
done:
    for (size_t k = 0; r.an && k < r.set.count; k++)
        qd_stability_free(&r.an[k]);
    free(r.an);
    qd_steady_set_free(&r.set);
    free(r.xfix);
    free(r.xseen);
    free(r.pt.x);
    free(r.pt.w);
    free(r.pt.p);
    free(r.given);
    qd_steady_free(r.s);
    cli_state_free(&r.st);
    if (r.e)
        qd_eom_free(r.e);
    cli_model_file_free(&r.mf);
    qd_ctx_free(r.ctx);
    return rc;
}

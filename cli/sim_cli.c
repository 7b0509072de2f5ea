/*
 * cli/sim_cli.c - the setup `qdot simulate` and `qdot poincare` share.
 *
 * Expressions on the command line (--output, --event) are read in the model
 * language; a name the reader does not know is looked up among the model's
 * definitions (x2 = x1 + l2*sin(theta2)) and replaced by its value, and a
 * definition's name with a prime (x2') is its time derivative.  A speed's
 * name (`speeds`) stands for its definition, as in the model.
 *
 * A model with speeds is simulated in them, y = (q, u) (qd_sim_new_speeds):
 * the initial speeds are those given (`initial u = ...`, --initial "u=..."),
 * the others those of the initial velocities; --no-speeds integrates the
 * multiplier form instead.
 */
#include "sim_cli.h"

#include <ctype.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "eom_out.h"
#include "model_cli.h"
#include "qdot/codegen.h"

static const char *const methods[] = {"dopri5", "dop853", "gl2",     "gl4",      "gl6",
                                      "verlet", "yoshida4", "yoshida6", "yoshida8", "bdf",
                                      "taylor", NULL};
static const char *const precisions[] = {"64", "80", "128", NULL};

#define SIM(field) offsetof(cli_sim_args, field)
const cli_opt cli_sim_opts[] = {
    {"--t-end", NULL, CLI_TEXT, SIM(t_end), "T",
     "end time (an expression in the parameters)", NULL, NULL},
    {"--dt", NULL, CLI_TEXT, SIM(dt), "H",
     "the step of a fixed-step method, the output grid of an adaptive one", NULL, NULL},
    {"--every", NULL, CLI_TEXT, SIM(every), "H",
     "a row every H, whatever the steps are", NULL, NULL},
    {"--rtol", NULL, CLI_TEXT, SIM(rtol), "TOL",
     "relative tolerance (step control; 1e-10)", NULL, NULL},
    {"--atol", NULL, CLI_TEXT, SIM(atol), "TOL", "absolute tolerance (1e-12)", NULL, NULL},
    {"--max-steps", NULL, CLI_TEXT, SIM(max_steps), "N",
     "the most steps a run takes (1e8)", NULL, NULL},
    {"--method", NULL, CLI_CHOICE, SIM(method), "M",
     "the integrator (default dop853; gl4 with --dt for a conservative system)", methods, NULL},
    {"--precision", NULL, CLI_CHOICE, SIM(precision), "BITS",
     "the taylor method's arithmetic: 64, 80 or 128 bits", precisions, NULL},
    {"--initial", NULL, CLI_TEXT, SIM(initial), "STATE",
     "initial values \"q=VALUE, q'=VALUE, t=VALUE\" (momenta, speeds too)", NULL, NULL},
    {"--set", NULL, CLI_LIST, SIM(sets), "NAME=VALUE",
     "a parameter's value (repeatable)", NULL, NULL},
    {"--output", NULL, CLI_TEXT, SIM(output), "\"EXPR, ...\"",
     "more columns: expressions in the model's names", NULL, NULL},
    {"--out", "-o", CLI_TEXT, SIM(out), "FILE", "write the rows to FILE", NULL, NULL},
    {"--input", NULL, CLI_LIST, SIM(inputs), "\"F = EXPR\"",
     "an input's source: an expression, F=FILE.csv or \"F = lqr\" (repeatable)", NULL, NULL},
    {"--about", NULL, CLI_TEXT, SIM(about), "STATE", "the point LQR linearizes about", NULL, NULL},
    {"--lqr", NULL, CLI_TEXT, SIM(lqr), "\"Q = ..., R = ...\"", "the LQR weights", NULL, NULL},
    {"--event", NULL, CLI_LIST, SIM(events), "\"EXPR = EXPR[, EXPR > EXPR]\"",
     "rows where a crossing happens under the conditions (repeatable)", NULL, NULL},
    {"--stop-at", NULL, CLI_LIST, SIM(stops), "\"EXPR = EXPR[, ...]\"",
     "an event that ends the run (repeatable; numbered after the --event ones)", NULL, NULL},
    {"--native", NULL, CLI_FLAG, SIM(native), NULL, "compile the right-hand side to C", NULL, NULL},
    {"--no-project", NULL, CLI_FLAG, SIM(no_project), NULL,
     "do not project onto the constraints after each step", NULL, NULL},
    {"--no-speeds", NULL, CLI_FLAG, SIM(no_speeds), NULL,
     "a model with speeds: integrate the multiplier form", NULL, NULL},
    {NULL, NULL, CLI_FLAG, 0, NULL, NULL, NULL, NULL},
};
#undef SIM

/* The interim reader of one option of the table (until cli_parse). */
bool cli_sim_took_option(int argc, char **argv, int *i, cli_sim_args *a, int *rc) {
    *rc = QD_EXIT_OK;
    for (const cli_opt *o = cli_sim_opts; o->name; o++) {
        char *field = (char *)a + o->offset;
        if (o->kind == CLI_FLAG) {
            if (strcmp(argv[*i], o->name))
                continue;
            *(bool *)field = true;
            return true;
        }
        const char *v = cli_value(argc, argv, i, o->name);
        if (!v && o->alias)
            v = cli_value(argc, argv, i, o->alias);
        if (!v)
            continue;
        if (o->kind == CLI_LIST) {
            cli_list *l = (cli_list *)(void *)field;
            if (l->n == CLI_LIST_MAX) {
                cli_diag_error("at most %d %s options", CLI_LIST_MAX, o->name);
                *rc = QD_EXIT_USAGE;
            } else {
                l->items[l->n++] = v;
            }
            return true;
        }
        if (o->kind == CLI_CHOICE) {
            size_t k = 0;
            while (o->choices[k] && strcmp(o->choices[k], v))
                k++;
            if (!o->choices[k]) {
                char list[256];
                size_t at = 0;
                for (k = 0; o->choices[k] && at < sizeof list; k++)
                    at += (size_t)snprintf(list + at, sizeof list - at, "%s%s",
                                           !k ? "" : o->choices[k + 1] ? ", " : " or ",
                                           o->choices[k]);
                cli_diag_error("%s takes %s, not '%s'", o->name, list, v);
                *rc = QD_EXIT_USAGE;
                return true;
            }
        }
        if (*(const char **)(void *)field) {
            cli_diag_error("%s is given twice%s; give it once", o->name,
                           o->alias ? " (or as its alias)" : "");
            *rc = QD_EXIT_USAGE;
            return true;
        }
        *(const char **)(void *)field = v;
        return true;
    }
    return false;
}

/* ---- expressions ---------------------------------------------------------- */

static void trim(const char **a, const char **b) {
    while (*a < *b && isspace((unsigned char)**a))
        (*a)++;
    while (*b > *a && isspace((unsigned char)(*b)[-1]))
        (*b)--;
}

/* A constraint's multiplier: outputs and events may use it ("when does the
 * particle leave the sphere": lambda_sphere = 0). */
static bool is_multiplier(const cli_sim *c, const qd_expr *x) {
    for (size_t k = 0; c->e && k < c->e->ncon; k++)
        if (c->e->con[k].lambda == x)
            return true;
    return false;
}

/* A momentum of a model given by H: its outputs and events may use them. */
static bool is_momentum(const cli_sim *c, const qd_expr *x) {
    const qd_model *m = c->mf.model;
    for (size_t j = 0; qd_model_hamiltonian_given(m) && j < qd_model_ncoords(m); j++)
        if (qd_model_momentum(m, j) == x)
            return true;
    return false;
}

/* The definition of the model's speed named name, or NULL. */
static const qd_expr *speed_definition(const cli_sim *c, const char *name) {
    const qd_model *m = c->mf.model;
    for (size_t r = 0; r < qd_model_nspeeds(m); r++)
        if (!strcmp(qd_expr_name(qd_model_speed(m, r)), name))
            return qd_model_speed_definition(m, r);
    return NULL;
}

/* A definition's value: `NAME = EXPR`, or a speed's definition. */
static const qd_expr *definition(const cli_sim *c, const char *name) {
    const qd_expr *d = qd_model_definition(c->mf.model, name);
    return d ? d : speed_definition(c, name);
}

/* Simulating in speeds, a constraint's multiplier lambda_NAME by name. */
static bool speeds_multiplier(const cli_sim *c, const char *name) {
    for (size_t k = 0; c->se && k < c->se->ncon; k++)
        if (!strcmp(qd_expr_name(c->se->con[k].lambda), name))
            return true;
    return false;
}

/* Read text[a, b) against the model: definitions substituted. */
static bool is_input(const cli_sim *c, const qd_expr *x) {
    for (size_t k = 0; k < qd_model_ninputs(c->mf.model); k++)
        if (qd_model_input(c->mf.model, k) == x)
            return true;
    return false;
}

/* An error at text[at, at + len) of the user's option text full. */
static void located(const char *what, const char *full, size_t at, size_t len, const char *msg,
                    const char *hint) {
    qd_read_error err;
    memset(&err, 0, sizeof err);
    err.status = QD_ERR_ARG;
    err.offset = at;
    err.length = len ? len : 1;
    snprintf(err.message, sizeof err.message, "%s", msg);
    snprintf(err.hint, sizeof err.hint, "%s", hint);
    cli_diag_read(what, full, &err);
}

/* Where name stands in [a, b) as a whole word, or a. */
static const char *word_in(const char *a, const char *b, const char *name) {
    size_t n = strlen(name);
    for (const char *p = a; n && p + n <= b; p++)
        if (!strncmp(p, name, n) && (p == a || !(isalnum((unsigned char)p[-1]) || p[-1] == '_')) &&
            (p + n == b || !(isalnum((unsigned char)p[n]) || p[n] == '_')))
            return p;
    return a;
}

/* text[a, b) read against the model; full: the option text the user wrote
 * that [a, b) lies in (errors are shown in it, at their place), or NULL
 * (shown in [a, b) itself). */
static const qd_expr *read_expr_in(cli_sim *c, const char *what, const char *full, const char *a,
                                   const char *b);

static const qd_expr *read_expr(cli_sim *c, const char *what, const char *a, const char *b) {
    return read_expr_in(c, what, NULL, a, b);
}

static const qd_expr *read_expr_in(cli_sim *c, const char *what, const char *full, const char *a,
                                   const char *b) {
    trim(&a, &b);
    size_t len = (size_t)(b - a);
    char *text = malloc(len + 1);
    if (!text)
        return NULL;
    memcpy(text, a, len);
    text[len] = '\0';
    const qd_expr *x = NULL;
    /* NAME' of a definition: its time derivative */
    if (len > 1 && text[len - 1] == '\'') {
        text[len - 1] = '\0';
        const qd_expr *d = definition(c, text);
        text[len - 1] = '\'';
        if (d)
            x = qd_dt(c->ctx, d);
    }
    qd_diag err;
    const qd_read_opts opts = {.new_symbols = true};
    if (!x)
        x = qd_read(c->ctx, text, &opts, &err);
    if (!x) {
        if (full) {
            err.offset += (size_t)(a - full);
            cli_diag_read(what, full, &err);
        } else {
            cli_diag_read(what, text, &err);
        }
        free(text);
        return NULL;
    }
    size_t k = qd_free_symbols(c->ctx, x, NULL, 0);
    const qd_expr **syms = malloc((k + 1) * sizeof *syms);
    qd_free_symbols(c->ctx, x, syms, k);
    for (size_t i = 0; x && i < k; i++) {
        if (qd_symbol_role(syms[i]) != QD_ROLE_PLAIN || is_multiplier(c, syms[i]) ||
            is_momentum(c, syms[i]) || is_input(c, syms[i]))
            continue;
        const qd_expr *d = definition(c, qd_expr_name(syms[i]));
        const char *nm = qd_expr_name(syms[i]);
        if (!d && full) {
            char msg[256];
            snprintf(msg, sizeof msg, "%s '%s'", speeds_multiplier(c, nm)
                     ? "the multipliers are not computed in generalized speeds (use --no-speeds):"
                     : "unknown name", nm);
            const char *at = word_in(a, b, nm);
            located(what, full, (size_t)(at - full), strlen(nm), msg,
                    "use coordinates, velocities q', t, parameters, the model's definitions "
                    "and the multipliers lambda_<constraint>");
            x = NULL;
            break;
        }
        if (!d && speeds_multiplier(c, qd_expr_name(syms[i]))) {
            cli_diag_error("%s: '%s' in '%s': the multipliers are not computed in generalized "
                          "speeds (use --no-speeds)", what, qd_expr_name(syms[i]), text);
            x = NULL;
            break;
        }
        if (!d) {
            cli_diag_error("%s: unknown name '%s' in '%s' (use coordinates, velocities q', t, "
                          "parameters, the model's definitions and the multipliers "
                          "lambda_<constraint>)",
                          what, qd_expr_name(syms[i]), text);
            x = NULL;
            break;
        }
        x = qd_subs(c->ctx, x, 1, &syms[i], &d);
    }
    free(syms);
    free(text);
    return x;
}

/* End of the item at p: the next comma outside brackets. */
static const char *item_end(const char *p) {
    int depth = 0;
    for (; *p; p++) {
        if (*p == '(' || *p == '[')
            depth++;
        else if ((*p == ')' || *p == ']') && depth > 0)
            depth--;
        else if (*p == ',' && depth == 0)
            break;
    }
    return p;
}

static int add_outputs(cli_sim *c, const char *list) {
    for (const char *p = list; *p;) {
        const char *end = item_end(p), *a = p, *b = end;
        trim(&a, &b);
        if (a < b) {
            const qd_expr *x = read_expr(c, "--output", a, b);
            if (!x)
                return QD_EXIT_USAGE;
            char name[128];
            snprintf(name, sizeof name, "%.*s", (int)(b - a), a);
            if (qd_sim_add_output(c->s, name, x) != QD_OK)
                return cli_diag_ctx(c->ctx);
        }
        p = *end ? end + 1 : end;
    }
    return QD_EXIT_OK;
}

/* The model's `outputs` are columns too, before those of --output. */
static int model_outputs(cli_sim *c) {
    for (size_t i = 0; i < qd_model_noutputs(c->mf.model); i++)
        if (qd_sim_add_output(c->s, qd_model_output_name(c->mf.model, i),
                              qd_model_output(c->mf.model, i)) != QD_OK)
            return cli_diag_ctx(c->ctx);
    return QD_EXIT_OK;
}

/* The NAME of "NAME = ..." into name (empty when there is no '='). */
static const char *input_name(const char *text, char *name, size_t cap) {
    const char *eq = strchr(text, '='), *a = text, *b = eq ? eq : text;
    trim(&a, &b);
    snprintf(name, cap, "%.*s", (int)((size_t)(b - a) < cap ? b - a : (long)cap - 1), a);
    return eq;
}

/* --input "F = EXPR" (EXPR read like --output: t, the state, parameters and
 * definitions), --input F=FILE.csv (a value ending in .csv) or --input
 * "F = lqr" (the LQR feedback): list[i]. */
int cli_sim_input(cli_sim *c, const char *const *list, size_t i) {
    char name[128], other[128];
    const char *eq = input_name(list[i], name, sizeof name);
    if (!eq || !name[0]) {
        cli_diag_error("--input: expected \"NAME = EXPR\" or NAME=FILE.csv, not '%s'", list[i]);
        return QD_EXIT_USAGE;
    }
    for (size_t k = 0; k < i; k++)
        if (input_name(list[k], other, sizeof other) && !strcmp(name, other)) {
            cli_diag_error("--input: %s is given twice", name);
            return QD_EXIT_USAGE;
        }
    const char *va = eq + 1, *vb = eq + strlen(eq);
    trim(&va, &vb);
    size_t vlen = (size_t)(vb - va);
    if (vlen > 4 && !strncmp(vb - 4, ".csv", 4))
        return cli_sim_input_csv(c, name, va, vlen);
    if (vlen == 3 && !strncmp(va, "lqr", 3))
        return cli_sim_input_lqr(c, name);
    const qd_expr *x = read_expr(c, "--input", va, vb);
    if (!x)
        return QD_EXIT_USAGE;
    if (qd_sim_input_expr(c->s, name, x) != QD_OK) {
        cli_diag_error("--input: %s", qd_ctx_message(c->ctx));
        return QD_EXIT_USAGE;
    }
    return QD_EXIT_OK;
}

/* "g1 = g2, guard > 0, guard < 0, ...": g = g1 - g2, guards as a - b > 0. */
static int add_event(cli_sim *c, const char *text, bool stop, const char *label) {
    const char *what = label ? label : stop ? "--stop-at" : "--event";
    const qd_expr *g = NULL, *guards[QD_SIM_MAX_LIST];
    size_t ng = 0;
    for (const char *p = text; *p;) {
        const char *end = item_end(p);
        const char *op = p;
        while (op < end && *op != '=' && *op != '>' && *op != '<')
            op++;
        if (op == end || (g == NULL) != (*op == '=') || ng == QD_SIM_MAX_LIST) {
            cli_diag_error("%s takes \"EXPR = EXPR[, EXPR > EXPR]...\" (the crossing first, "
                          "then conditions with > or <), not '%s'", what, text);
            return QD_EXIT_USAGE;
        }
        const qd_expr *l = read_expr(c, what, p, op), *r = read_expr(c, what, op + 1, end);
        if (!l || !r)
            return QD_EXIT_USAGE;
        if (*op == '=')
            g = qd_sub(c->ctx, l, r);
        else
            guards[ng++] = *op == '>' ? qd_sub(c->ctx, l, r) : qd_sub(c->ctx, r, l);
        p = *end ? end + 1 : end;
    }
    if (!g) {
        cli_diag_error("%s: no crossing 'EXPR = EXPR' in '%s'", what, text);
        return QD_EXIT_USAGE;
    }
    if (qd_sim_add_event(c->s, g, ng, guards, stop) != QD_OK)
        return cli_diag_ctx(c->ctx);
    return QD_EXIT_OK;
}

/* ---- setup ----------------------------------------------------------------- */

/* A model given by H: the momenta when --initial names any (those not
 * named are 0), else the library finds them from the velocities. */
static int initial_momenta(cli_sim *c) {
    size_t n = qd_model_ncoords(c->mf.model), at = c->st.n - n;
    bool any = false;
    for (size_t j = 0; j < n; j++)
        any = any || !isnan(c->st.vals[at + j]);
    if (!any)
        return QD_EXIT_OK;
    c->p0 = malloc((n + 1) * sizeof *c->p0);
    if (!c->p0)
        return QD_EXIT_FAIL;
    for (size_t j = 0; j < n; j++)
        c->p0[j] = isnan(c->st.vals[at + j]) ? 0 : c->st.vals[at + j];
    return QD_EXIT_OK;
}

/* Extra names after the state's own (NaN until given): the momenta of a
 * model given by H, or a model's speeds. */
static int add_names(cli_sim *c, size_t count, const qd_expr *(*sym)(const qd_model *, size_t)) {
    const qd_model *m = c->mf.model;
    size_t at = c->st.n;
    const qd_expr **syms = realloc(c->st.syms, (at + count + 1) * sizeof *syms);
    if (syms)
        c->st.syms = syms;
    double *vals = syms ? realloc(c->st.vals, (at + count + 1) * sizeof *vals) : NULL;
    if (!vals)
        return QD_EXIT_FAIL;
    c->st.vals = vals;
    for (size_t j = 0; j < count; j++) {
        c->st.syms[at + j] = sym(m, j);
        c->st.vals[at + j] = NAN;
    }
    c->st.n += count;
    return QD_EXIT_OK;
}

/* A model in speeds: the speeds given by `initial` (the model's values are
 * read before --initial, which may override them). */
static int model_speeds(cli_sim *c) {
    const qd_model *m = c->mf.model;
    size_t nu = qd_model_nspeeds(m), at = c->st.n - nu;
    for (size_t r = 0; r < nu; r++) {
        const qd_expr *v = qd_model_speed_initial(m, r);
        if (v && qd_eval(c->ctx, v, c->st.n, c->st.syms, c->st.vals, &c->st.vals[at + r]) !=
                     QD_OK)
            return cli_diag_ctx(c->ctx);
    }
    return QD_EXIT_OK;
}

/* A model in speeds: u0 when any speed is given, the others from the
 * initial velocities by their definitions; else the library finds all of
 * them from the velocities (projected onto the constraints first). */
static int initial_speeds(cli_sim *c) {
    const qd_model *m = c->mf.model;
    size_t nu = qd_model_nspeeds(m), at = c->st.n - nu;
    bool any = false;
    for (size_t r = 0; r < nu; r++)
        any = any || !isnan(c->st.vals[at + r]);
    if (!any)
        return QD_EXIT_OK;
    c->u0 = malloc((nu + 1) * sizeof *c->u0);
    if (!c->u0)
        return QD_EXIT_FAIL;
    for (size_t r = 0; r < nu; r++) {
        c->u0[r] = c->st.vals[at + r];
        if (isnan(c->u0[r]) && qd_eval(c->ctx, qd_model_speed_definition(m, r), at,
                                       c->st.syms, c->st.vals, &c->u0[r]) != QD_OK)
            return cli_diag_ctx(c->ctx);
        c->st.vals[at + r] = c->u0[r];
    }
    return QD_EXIT_OK;
}

/* --no-speeds with speeds given: the velocities they stand for, by the
 * kinematics q' = W u + w (which also keep the constraints). */
static int velocities_from_speeds(cli_sim *c) {
    qd_speeds_eom *se = qd_speeds_derive(c->ctx, c->mf.model, NULL);
    if (!se)
        return cli_eom_derive_error(c->ctx, &c->mf);
    size_t n = se->n;
    double *qd = malloc((n + 1) * sizeof *qd);
    qd_status st = qd ? qd_speeds_eval(c->ctx, se, c->st.n, c->st.syms, c->st.vals, qd, NULL,
                                       NULL)
                      : QD_ERR_NOMEM;
    for (size_t j = 0; st == QD_OK && j < n; j++)
        for (size_t i = 0; i < n; i++)
            if (se->q[i] == c->e->q[j])
                c->qd0[j] = qd[i];
    free(qd);
    qd_speeds_eom_free(se);
    free(c->u0); /* the multiplier form takes velocities */
    c->u0 = NULL;
    return st == QD_OK ? QD_EXIT_OK : cli_diag_ctx(c->ctx);
}

/* --initial onto the state.  When it names a velocity, the model's initial
 * speeds it does not name give way (they follow from the velocities): the
 * motion is the command line's.  A speed it names replaces the model's. */
static int parse_initial(cli_sim *c, const char *text) {
    const qd_model *m = c->mf.model;
    size_t n = qd_model_ncoords(m), nu = qd_model_nspeeds(m), at = c->st.n - nu;
    cli_state g = {.n = c->st.n, .syms = c->st.syms, .vals = malloc(c->st.n * sizeof(double))};
    if (!g.vals)
        return QD_EXIT_FAIL;
    for (size_t i = 0; i < g.n; i++)
        g.vals[i] = NAN;
    int rc = cli_state_parse_as(c->ctx, m, "--initial", text, &g);
    bool motion = false;
    for (size_t i = 0; i < g.n; i++)
        motion = motion || (!isnan(g.vals[i]) && i >= n && i < 2 * n);
    for (size_t i = 0; rc == QD_EXIT_OK && i < g.n; i++)
        if (!isnan(g.vals[i]))
            c->st.vals[i] = g.vals[i];
        else if (motion && nu && i >= at)
            c->st.vals[i] = NAN;
    free(g.vals);
    return rc;
}

static int initial_values(cli_sim *c, const cli_sim_args *a) {
    const qd_model *m = c->mf.model;
    size_t n = qd_model_ncoords(m);
    bool speeds = qd_model_nspeeds(m) > 0;
    int rc = cli_state_init(c->ctx, m, &c->st);
    if (rc == QD_EXIT_OK && !c->e && !c->se)
        rc = add_names(c, n, qd_model_momentum);
    if (rc == QD_EXIT_OK && speeds)
        rc = add_names(c, qd_model_nspeeds(m), qd_model_speed);
    if (rc != QD_EXIT_OK)
        return rc;
    for (size_t i = 0; i < n; i++)
        for (unsigned o = 0; o < 2; o++) {
            const qd_expr *v = qd_model_initial(m, i, o);
            if (v && qd_eval(c->ctx, v, c->st.n, c->st.syms, c->st.vals,
                             &c->st.vals[o * n + i]) != QD_OK)
                return cli_diag_ctx(c->ctx);
        }
    if (speeds && (rc = model_speeds(c)) != QD_EXIT_OK)
        return rc;
    if (a->initial && (rc = parse_initial(c, a->initial)) != QD_EXIT_OK)
        return rc;
    /* the equations' coordinates are the model's, in its order */
    c->q0 = malloc((2 * n + 1) * sizeof *c->q0);
    if (!c->q0)
        return QD_EXIT_FAIL;
    c->qd0 = c->q0 + n;
    for (size_t j = 0; j < n; j++) {
        size_t i = c->e ? 0 : j;
        while (c->e && i < n && qd_model_coord(m, i) != c->e->q[j])
            i++;
        c->q0[j] = c->st.vals[i];
        c->qd0[j] = c->st.vals[n + i];
    }
    if (speeds && (rc = initial_speeds(c)) == QD_EXIT_OK && c->e && c->u0)
        rc = velocities_from_speeds(c);
    return speeds || c->e ? rc : initial_momenta(c);
}

/* The value of option opt given as text (NULL: not given, *out unchanged),
 * an expression in the parameters read against the model: errors shown in
 * the option's text with a caret. */
static int option_value(cli_sim *c, const char *opt, const char *text, bool positive,
                        double *out) {
    if (!text)
        return QD_EXIT_OK;
    if (qd_model_number(c->ctx, c->mf.model, text, out) != QD_OK) {
        cli_diag_show(opt, text, qd_ctx_diag(c->ctx));
        return qd_ctx_status(c->ctx) == QD_ERR_NOMEM ? QD_EXIT_FAIL : QD_EXIT_USAGE;
    }
    if (positive && !(*out > 0)) {
        cli_diag_error("%s takes a positive number, not '%s'", opt, text);
        return QD_EXIT_USAGE;
    }
    return QD_EXIT_OK;
}

static int choose_method(cli_sim *c, const cli_sim_args *a) {
    qd_sim_opts *o = &c->opts;
    double t_end = 0, dt = 0, rtol = 0, atol = 0, every = 0, steps = 0;
    int rc = option_value(c, "--t-end", a->t_end, false, &t_end);
    if (rc == QD_EXIT_OK)
        rc = option_value(c, "--dt", a->dt, true, &dt);
    if (rc == QD_EXIT_OK)
        rc = option_value(c, "--every", a->every, true, &every);
    if (rc == QD_EXIT_OK)
        rc = option_value(c, "--rtol", a->rtol, true, &rtol);
    if (rc == QD_EXIT_OK)
        rc = option_value(c, "--atol", a->atol, true, &atol);
    if (rc == QD_EXIT_OK)
        rc = option_value(c, "--max-steps", a->max_steps, true, &steps);
    if (rc == QD_EXIT_OK && steps != floor(steps)) {
        cli_diag_error("--max-steps takes a whole number, not '%s'", a->max_steps);
        rc = QD_EXIT_USAGE;
    }
    if (rc != QD_EXIT_OK)
        return rc;
    if (a->dt && a->rtol && !a->method) {
        cli_diag_error("give --dt (fixed step) or --rtol (step control), or name a --method\n"
                       "hint: for rows every %g with step control: --every %g --rtol %g (--dt "
                       "is the step of a fixed-step method)", dt, dt, rtol);
        return QD_EXIT_USAGE;
    }
    if (a->method)
        qd_sim_method_from_name(a->method, &o->method);
    else
        o->method = qd_sim_default_method(c->s, a->dt != NULL);
    o->dt = dt;
    o->every = every;
    o->rtol = rtol;
    o->atol = atol;
    o->fixed = a->fixed && a->dt;
    o->no_project = a->no_project;
    /* (size_t)x is undefined beyond SIZE_MAX: clamp first */
    o->max_steps = steps >= 0x1p63 ? (size_t)-1 : (size_t)steps;
    o->precision = a->precision ? atoi(a->precision) : 0;
    if (o->precision && o->precision != 64 && o->method != QD_SIM_TAYLOR) {
        cli_diag_error("--precision %d is for --method taylor", o->precision);
        return QD_EXIT_USAGE;
    }
    o->t0 = c->st.vals[2 * qd_model_ncoords(c->mf.model)];
    o->t_end = t_end;
    o->q0 = c->q0;
    o->qd0 = c->qd0;
    o->p0 = c->p0;
    o->u0 = c->u0;
    if (!qd_sim_method_adaptive(o->method) && !a->dt) {
        cli_diag_error("--method %s takes fixed steps: give --dt", qd_sim_method_name(o->method));
        return QD_EXIT_USAGE;
    }
    if (!(o->t_end > o->t0)) {
        cli_diag_error("--t-end must be after the start time (%g)", o->t0);
        return QD_EXIT_USAGE;
    }
    /* before any output file is opened: a refused run writes nothing */
    if (qd_sim_check_opts(c->ctx, o) != QD_OK)
        return cli_diag_ctx(c->ctx);
    return QD_EXIT_OK;
}

static int load_native(cli_sim *c) {
    qd_native *nat = calloc(1, sizeof *nat);
    if (!nat)
        return QD_EXIT_FAIL;
    if (qd_native_load(c->ctx, c->mf.model, c->e, NULL, nat) != QD_OK) {
        fprintf(stderr, "qdot: note: --native unavailable (%s); using the compiled programs\n",
                qd_ctx_message(c->ctx));
        qd_ctx_clear_error(c->ctx);
        free(nat);
        return QD_EXIT_OK;
    }
    c->native = nat;
    qd_sim_set_native(c->s, nat->rhs);
    return QD_EXIT_OK;
}

/* taylor's own generated code: its recurrences, in every form, in double
 * (the rhs is not what it evaluates). */
static void load_native_taylor(cli_sim *c) {
    if (c->opts.precision == 80 || c->opts.precision == 128) {
        fprintf(stderr, "qdot: note: --native generates the taylor recurrences in double only; "
                        "--precision %d keeps the interpreted ones\n", c->opts.precision);
        return;
    }
    if (qd_sim_load_native_taylor(c->s, NULL, NULL) != QD_OK) {
        fprintf(stderr, "qdot: note: --native unavailable (%s); using the compiled programs\n",
                qd_ctx_message(c->ctx));
        qd_ctx_clear_error(c->ctx);
    }
}

/* The model's impacts at the initial state: a gap below 0 is bad input
 * (exit 2), said before any output as the run would say it. */
static int check_gaps(cli_sim *c) {
    const qd_model *m = c->mf.model;
    for (size_t i = 0; i < qd_model_nimpacts(m); i++) {
        double g = 0;
        if (qd_eval(c->ctx, qd_model_impact_gap(m, i), c->st.n, c->st.syms, c->st.vals, &g) !=
            QD_OK)
            return cli_diag_ctx(c->ctx);
        if (g < 0) {
            cli_diag_error("impact '%s': the gap is negative at t0 (%.6g): the bodies start "
                           "interpenetrating", qd_model_impact_name(m, i), g);
            return QD_EXIT_USAGE;
        }
    }
    return QD_EXIT_OK;
}

int cli_sim_setup(cli_sim *c, const cli_sim_args *a) {
    c->ctx = qd_ctx_new();
    if (!c->ctx) {
        cli_diag_error("out of memory");
        return QD_EXIT_FAIL;
    }
    int rc = cli_load(c->ctx, a->file, a->sets.n, a->sets.items, false, &c->mf);
    if (rc != QD_EXIT_OK)
        return rc;
    if (qd_model_hamiltonian_given(c->mf.model)) {
        /* Hamilton's equations as given: no Lagrangian needed */
        c->s = qd_sim_new_hamilton(c->ctx, c->mf.model);
        if (!c->s)
            return cli_diag_ctx(c->ctx);
    } else if (qd_model_nspeeds(c->mf.model) && !a->no_speeds) {
        /* the constraints eliminated: no multipliers to solve for */
        c->se = qd_speeds_derive(c->ctx, c->mf.model, NULL);
        if (!c->se)
            return cli_eom_derive_error(c->ctx, &c->mf);
        c->s = qd_sim_new_speeds(c->ctx, c->mf.model, c->se);
    } else {
        c->e = qd_eom_derive(c->ctx, c->mf.model);
        if (!c->e)
            return cli_eom_derive_error(c->ctx, &c->mf);
        c->s = qd_sim_new(c->ctx, c->mf.model, c->e);
    }
    if (!c->s)
        return cli_diag_ctx(c->ctx);
    rc = initial_values(c, a);
    if (rc == QD_EXIT_OK)
        rc = check_gaps(c);
    if (rc == QD_EXIT_OK)
        rc = model_outputs(c);
    if (rc == QD_EXIT_OK && a->output)
        rc = add_outputs(c, a->output);
    c->about = a->about;
    c->lqr = a->lqr;
    for (size_t i = 0; rc == QD_EXIT_OK && i < a->inputs.n; i++)
        rc = cli_sim_input(c, a->inputs.items, i);
    if (rc == QD_EXIT_OK && (a->about || a->lqr) && !c->lqr_used) {
        cli_diag_error("%s is for --input \"NAME = lqr\" (the LQR feedback), which is not given",
                       a->lqr ? "--lqr" : "--about");
        rc = QD_EXIT_USAGE;
    }
    for (size_t i = 0; rc == QD_EXIT_OK && i < a->events.n; i++)
        rc = add_event(c, a->events.items[i], false, NULL);
    for (size_t i = 0; rc == QD_EXIT_OK && i < a->stops.n; i++)
        rc = add_event(c, a->stops.items[i], true, NULL);
    if (rc == QD_EXIT_OK && a->section)
        rc = add_event(c, a->section, false, "--section");
    if (rc == QD_EXIT_OK)
        rc = choose_method(c, a);
    if (rc == QD_EXIT_OK && qd_sim_inputs_ready(c->s, c->opts.t0, c->opts.t_end) != QD_OK) {
        cli_diag_error("--input: %s", qd_ctx_message(c->ctx));
        rc = QD_EXIT_USAGE;
    }
    if (rc == QD_EXIT_OK && a->native && c->opts.method == QD_SIM_TAYLOR)
        load_native_taylor(c);
    else if (rc == QD_EXIT_OK && a->native && c->se)
        fprintf(stderr, "qdot: note: --native takes the multiplier form (--no-speeds); using "
                        "the compiled programs\n");
    else if (rc == QD_EXIT_OK && a->native && !c->e)
        fprintf(stderr, "qdot: note: --native takes models given by T and V or L; using the "
                        "compiled programs\n");
    else if (rc == QD_EXIT_OK && a->native && qd_sim_method_adaptive(c->opts.method))
        rc = load_native(c);
    return rc;
}

void cli_sim_free(cli_sim *c) {
    if (c->native)
        qd_native_unload(c->native);
    free(c->native);
    free(c->q0);
    free(c->p0);
    free(c->u0);
    qd_sim_free(c->s);
    if (c->se)
        qd_speeds_eom_free(c->se);
    cli_state_free(&c->st);
    if (c->e)
        qd_eom_free(c->e);
    cli_model_file_free(&c->mf);
    qd_ctx_free(c->ctx);
}

size_t cli_sim_ncon(const cli_sim *c) {
    return c->se ? c->se->ncon : c->e ? c->e->ncon : 0;
}

const qd_con *cli_sim_con(const cli_sim *c, size_t k) {
    return c->se ? &c->se->con[k] : &c->e->con[k];
}

int cli_sim_fail(cli_sim *c, qd_status st) {
    const char *msg = qd_ctx_message(c->ctx);
    cli_diag_error("%s", msg[0] ? msg : qd_status_str(st));
    /* options were checked before the run: what fails now is the system's,
     * but for an output or event the user wrote that has no value (q''',
     * a name that is not an input), found when the run compiles them */
    return st == QD_ERR_UNBOUND ? QD_EXIT_USAGE : QD_EXIT_FAIL;
}

/* ---- qdot sweep (issue 21) -------------------------------------------------- */

/* One more output column, read as --output reads it and named by its text:
 * what a sweep's max:EXPR, min:EXPR and escape:EXPR>VALUE measure. */
int cli_sim_output(cli_sim *c, const char *expr) {
    return add_outputs(c, expr);
}

int cli_sim_output_in(cli_sim *c, const char *what, const char *full, size_t a, size_t b) {
    const qd_expr *x = read_expr_in(c, what, full, full + a, full + b);
    if (!x)
        return QD_EXIT_USAGE;
    char *name = malloc(b - a + 1);
    if (!name)
        return QD_EXIT_FAIL;
    memcpy(name, full + a, b - a);
    name[b - a] = '\0';
    int rc = qd_sim_add_output(c->s, name, x) == QD_OK ? QD_EXIT_OK : cli_diag_ctx(c->ctx);
    free(name);
    return rc;
}

int cli_sim_crossing_in(cli_sim *c, const char *what, const char *full, size_t a0, size_t a1,
                        size_t b0, size_t b1) {
    const qd_expr *l = read_expr_in(c, what, full, full + a0, full + a1);
    const qd_expr *r = l ? read_expr_in(c, what, full, full + b0, full + b1) : NULL;
    if (!l || !r)
        return QD_EXIT_USAGE;
    if (qd_sim_add_event(c->s, qd_sub(c->ctx, l, r), 0, NULL, false) != QD_OK)
        return cli_diag_ctx(c->ctx);
    return QD_EXIT_OK;
}

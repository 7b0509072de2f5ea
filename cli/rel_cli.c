/*
 * cli/rel_cli.c - option values of `qdot lorentz` and `qdot collide`: an
 * expression may use c, the speed of light of the run ("0.6*c",
 * "sqrt(3)/2*c"); lists split at the commas outside brackets.
 */
#include "rel_cli.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "cli.h"
#include "state.h"

int rel_read(qd_ctx *ctx, double c, const char *what, const char *text, bool t_ok,
             const qd_expr **expr, double *val) {
    qd_diag err;
    const qd_read_opts opts = {.new_symbols = true};
    const qd_expr *e = qd_read(ctx, text, &opts, &err);
    if (!e) {
        cli_diag_read(what, text, &err);
        return QD_EXIT_USAGE;
    }
    const qd_expr *csym = qd_symbol(ctx, "c"), *cval = qd_float(ctx, c);
    e = csym && cval ? qd_subs(ctx, e, 1, &csym, &cval) : NULL;
    if (!e)
        return cli_diag_ctx(ctx);
    if (t_ok) {
        *expr = e;
        return QD_EXIT_OK;
    }
    if (qd_eval(ctx, e, 0, NULL, NULL, val) != QD_OK || !isfinite(*val)) {
        qd_ctx_clear_error(ctx);
        cli_diag_error("%s: '%s' does not evaluate to a finite number (names allowed: c, pi, e)",
                       what, text);
        return QD_EXIT_USAGE;
    }
    return QD_EXIT_OK;
}

/* text[a, b) as a fresh string without the blanks around it. */
static char *slice(const char *text, size_t a, size_t b) {
    while (a < b && (text[a] == ' ' || text[a] == '\t'))
        a++;
    while (b > a && (text[b - 1] == ' ' || text[b - 1] == '\t'))
        b--;
    char *s = malloc(b - a + 1);
    if (s) {
        memcpy(s, text + a, b - a);
        s[b - a] = '\0';
    }
    return s;
}

/* "(...)" around the whole of s: its inside (s is modified). */
static char *unwrap(char *s) {
    size_t n = strlen(s);
    if (n < 2 || s[0] != '(' || s[n - 1] != ')')
        return s;
    int depth = 0;
    for (size_t i = 0; i < n - 1; i++) {
        depth += (s[i] == '(') - (s[i] == ')');
        if (depth == 0)
            return s; /* "(a) + (b)": not one bracket */
    }
    s[n - 1] = '\0';
    return s + 1;
}

int rel_list(qd_ctx *ctx, double c, const char *what, const char *text, size_t n, double *out,
             const qd_expr **exprs) {
    char *all = slice(text, 0, strlen(text));
    if (!all)
        return QD_EXIT_FAIL;
    const char *s = unwrap(all);
    size_t k = 0, i = 0;
    int rc = QD_EXIT_OK;
    while (rc == QD_EXIT_OK && k <= n) {
        size_t end = cli_item_end(s, i);
        char *item = slice(s, i, end);
        if (!item)
            rc = QD_EXIT_FAIL;
        else if (k < n)
            rc = rel_read(ctx, c, what, item, exprs != NULL, exprs ? &exprs[k] : NULL,
                          exprs ? NULL : &out[k]);
        free(item);
        k++;
        if (!s[end])
            break;
        i = end + 1;
    }
    if (rc == QD_EXIT_OK && k != n) {
        cli_diag_error("%s needs %zu comma-separated values, not '%s'", what, n, text);
        rc = QD_EXIT_USAGE;
    }
    free(all);
    return rc;
}

int rel_particle(qd_ctx *ctx, double c, const char *what, const char *text, qd_rel_particle *p) {
    double m = NAN, v[3] = {0, 0, 0};
    int rc = QD_EXIT_OK;
    for (size_t i = 0; rc == QD_EXIT_OK;) {
        size_t end = cli_item_end(text, i);
        char *item = slice(text, i, end);
        char *eq = item ? strchr(item, '=') : NULL;
        if (!item)
            rc = QD_EXIT_FAIL;
        else if (!eq || eq - item != 1 || (item[0] != 'm' && item[0] != 'v')) {
            cli_diag_error("%s takes \"m=MASS, v=(VX, VY, VZ)\", not '%s'", what, text);
            rc = QD_EXIT_USAGE;
        } else if (item[0] == 'm')
            rc = rel_read(ctx, c, what, eq + 1, false, NULL, &m);
        else
            rc = rel_list(ctx, c, what, eq + 1, 3, v, NULL);
        free(item);
        if (!text[end])
            break;
        i = end + 1;
    }
    if (rc == QD_EXIT_OK && isnan(m)) {
        cli_diag_error("%s: the rest mass m=... is missing in '%s'", what, text);
        rc = QD_EXIT_USAGE;
    }
    if (rc == QD_EXIT_OK && qd_rel_particle_make(ctx, c, m, v, p) != QD_OK) {
        cli_diag_error("%s: %s", what, qd_ctx_message(ctx));
        qd_ctx_clear_error(ctx);
        rc = QD_EXIT_USAGE;
    }
    return rc;
}

int rel_speed_of_light(qd_ctx *ctx, const char *text, double *c) {
    const qd_expr *x;
    int rc = cli_state_number(ctx, "--c", text, &x, c);
    if (rc == QD_EXIT_OK && !(*c > 0)) {
        cli_diag_error("--c: the speed of light must be positive, not '%s'", text);
        rc = QD_EXIT_USAGE;
    }
    return rc;
}

void rel_put_vec(qd_buf *b, const double *v, size_t n) {
    qd_buf_puts(b, "(");
    for (size_t i = 0; i < n; i++) {
        if (i)
            qd_buf_puts(b, ", ");
        cli_state_put_result(b, v[i]);
    }
    qd_buf_puts(b, ")");
}

void rel_json_vec(qd_json *j, const char *key, const double *v, size_t n) {
    if (key)
        qd_json_key(j, key);
    qd_json_begin_array(j);
    for (size_t i = 0; i < n; i++)
        qd_json_number(j, v[i]);
    qd_json_end_array(j);
}

void rel_json_particle(qd_json *j, const qd_rel_particle *p) {
    qd_json_begin_object(j);
    qd_json_key(j, "mass");
    qd_json_number(j, p->m);
    rel_json_vec(j, "velocity", p->v, 3);
    qd_json_key(j, "energy");
    qd_json_number(j, p->E);
    rel_json_vec(j, "momentum", p->p, 3);
    qd_json_end_object(j);
}

void rel_text_particle(qd_buf *b, const char *label, const qd_rel_particle *p) {
    qd_buf_printf(b, "%s: m = ", label);
    cli_state_put_result(b, p->m);
    qd_buf_puts(b, ", v = ");
    rel_put_vec(b, p->v, 3);
    qd_buf_puts(b, ", E = ");
    cli_state_put_result(b, p->E);
    qd_buf_puts(b, ", p = ");
    rel_put_vec(b, p->p, 3);
    qd_buf_puts(b, "\n");
}

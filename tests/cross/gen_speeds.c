/*
 * tests/cross/gen_speeds.c - qdot's equations in generalized speeds, printed
 * for the SymPy cross-check (tests/cross/check_speeds_sympy.py).
 *
 * For each model file given, qd_speeds_derive by each method (Kane,
 * Gibbs-Appell, Boltzmann-Hamel), always with the Gibbs-Appell function S.
 * Prints one item per line, expressions in SymPy syntax (qd_print
 * QD_FMT_SYMPY: coordinates and speeds as functions of t):
 *   case <name>
 *   coords <q_1> ... <q_n>
 *   speeds <u_1> ... <u_m>
 *   params <name> <value> ...          (the model's defaults, as doubles)
 *   def <r> <u_r as the model defines it, in q, q', t>
 *   method <kane|appell|hamel>
 *   M <r> <s> <M_u entry>
 *   f <r> <f_u entry>
 *   kin <j> <q'_j from the kinematics>
 *   S <the Gibbs-Appell function>
 *   con <k> <sum_j a_kj q'_j + a0_k, constraint k's velocity form>
 *   error <method> <message>          (when a derivation fails)
 * The Python side does everything else; a failed derivation makes the exit
 * status 1 but the other methods and models are still printed.
 * Usage: gen_speeds FILE.qd ...
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "qdot/qdot.h"
#include "qdot/speeds.h"

/* strdup is POSIX, not C11. */
static char *copy(const char *s) {
    size_t n = strlen(s) + 1;
    char *c = malloc(n);
    return c ? memcpy(c, s, n) : NULL;
}

static char *slurp(const char *path) {
    FILE *fp = fopen(path, "rb");
    if (!fp)
        return NULL;
    qd_buf b = QD_BUF_INIT;
    char chunk[4096];
    size_t k;
    while ((k = fread(chunk, 1, sizeof chunk, fp)) > 0)
        qd_buf_putn(&b, chunk, k);
    fclose(fp);
    char *text = copy(qd_buf_str(&b));
    qd_buf_free(&b);
    return text;
}

/* "tag expr" with the expression in SymPy syntax; tag already formatted. */
static int item(qd_ctx *ctx, const char *tag, const qd_expr *e) {
    qd_buf b = QD_BUF_INIT;
    int bad = !e || qd_print(ctx, e, QD_FMT_SYMPY, &b) != QD_OK;
    if (bad)
        fprintf(stderr, "gen_speeds: %s: %s\n", tag, qd_ctx_message(ctx));
    else
        printf("%s %s\n", tag, qd_buf_str(&b));
    qd_buf_free(&b);
    return bad;
}

static int header(qd_ctx *ctx, const char *name, const qd_model *m) {
    int bad = 0;
    printf("case %s\ncoords", name);
    for (size_t j = 0; j < qd_model_ncoords(m); j++)
        printf(" %s", qd_expr_name(qd_model_coord(m, j)));
    printf("\nspeeds");
    for (size_t r = 0; r < qd_model_nspeeds(m); r++)
        printf(" %s", qd_expr_name(qd_model_speed(m, r)));
    printf("\nparams");
    for (size_t i = 0; i < qd_model_nparams(m); i++) {
        double v = 0;
        bad |= qd_model_param_number(m, i, &v) != QD_OK;
        printf(" %s %.17g", qd_expr_name(qd_model_param(m, i)), v);
    }
    printf("\n");
    char tag[32];
    for (size_t r = 0; r < qd_model_nspeeds(m); r++) {
        snprintf(tag, sizeof tag, "def %zu", r);
        bad |= item(ctx, tag, qd_model_speed_definition(m, r));
    }
    return bad;
}

/* Constraint k as a velocity form (a holonomic one differentiated), which
 * the kinematics must make 0 for every u. */
static const qd_expr *velocity_form(qd_ctx *ctx, const qd_speeds_eom *e, size_t k) {
    const qd_expr *sum = e->con[k].a0;
    for (size_t j = 0; j < e->n && sum; j++)
        sum = qd_add(ctx, sum, qd_mul(ctx, e->con[k].a[j], e->qd[j]));
    return sum;
}

static int equations(qd_ctx *ctx, const qd_speeds_eom *e) {
    int bad = 0;
    char tag[48];
    printf("method %s\n", qd_speeds_method_name(e->method));
    for (size_t r = 0; r < e->m; r++)
        for (size_t s = 0; s < e->m; s++) {
            snprintf(tag, sizeof tag, "M %zu %zu", r, s);
            bad |= item(ctx, tag, e->M[r * e->m + s]);
        }
    for (size_t r = 0; r < e->m; r++) {
        snprintf(tag, sizeof tag, "f %zu", r);
        bad |= item(ctx, tag, e->f[r]);
    }
    for (size_t j = 0; j < e->n; j++) {
        snprintf(tag, sizeof tag, "kin %zu", j);
        bad |= item(ctx, tag, e->kin[j]);
    }
    bad |= item(ctx, "S", e->S);
    for (size_t k = 0; k < e->ncon; k++) {
        snprintf(tag, sizeof tag, "con %zu", k);
        bad |= item(ctx, tag, velocity_form(ctx, e, k));
    }
    return bad;
}

static int one(const char *path) {
    char *text = slurp(path);
    if (!text) {
        fprintf(stderr, "gen_speeds: cannot read %s\n", path);
        return 1;
    }
    const char *base = strrchr(path, '/');
    char name[256];
    snprintf(name, sizeof name, "%s", base ? base + 1 : path);
    char *dot = strrchr(name, '.');
    if (dot)
        *dot = '\0';
    qd_ctx *ctx = qd_ctx_new();
    qd_diag d;
    qd_model *m = qd_model_parse(ctx, text, &d);
    int bad = !m;
    if (!m)
        fprintf(stderr, "gen_speeds: %s:%zu: %s\n", path, d.line, d.message);
    else
        bad |= header(ctx, name, m);
    for (int k = 0; m && k < QD_SPEEDS_METHOD_COUNT; k++) {
        qd_speeds_opts o = {.method = (qd_speeds_method)k, .appell = true};
        qd_speeds_eom *e = qd_speeds_derive(ctx, m, &o);
        if (!e) {
            printf("error %s %s\n", qd_speeds_method_name(o.method), qd_ctx_message(ctx));
            qd_ctx_clear_error(ctx);
            bad = 1;
            continue;
        }
        bad |= equations(ctx, e);
        qd_speeds_eom_free(e);
    }
    qd_model_free(m);
    qd_ctx_free(ctx);
    free(text);
    return bad;
}

int main(int argc, char **argv) {
    if (argc < 2) {
        fprintf(stderr, "usage: gen_speeds FILE.qd ...\n");
        return 2;
    }
    int bad = 0;
    for (int i = 1; i < argc; i++)
        bad |= one(argv[i]);
    return bad;
}

/*
 * cli/constrained_cli.c - `qdot modes` and `qdot linearize` on a model that
 * keeps holonomic constraints with multipliers (a pendulum as
 * x^2 + y^2 = l^2): the library reduces onto the constraint manifold
 * (qd_constrained_linear_about); this file reads --independent, prints.
 */
#include "linear_cli.h"

#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "model_cli.h"
#include "qdot/constrained.h"

static const char *verdict(int s) {
    return s == 1 ? "stable" : s == 0 ? "unstable" : "borderline";
}

/* "x, y": indices into e->q, exactly n - ncon of them. */
static int read_indep(const qd_eom *e, const char *text, size_t *out) {
    size_t want = e->n - e->ncon, got = 0;
    const char *p = text;
    while (*p) {
        while (*p == ',' || isspace((unsigned char)*p))
            p++;
        if (!*p)
            break;
        const char *s = p;
        while (*p && *p != ',' && !isspace((unsigned char)*p))
            p++;
        size_t len = (size_t)(p - s), j = 0;
        while (j < e->n && !(strlen(qd_expr_name(e->q[j])) == len &&
                             strncmp(qd_expr_name(e->q[j]), s, len) == 0))
            j++;
        if (j == e->n) {
            cli_diag_error("--independent: '%.*s' is not a coordinate of the equations", (int)len,
                          s);
            return QD_EXIT_USAGE;
        }
        for (size_t i = 0; i < got; i++)
            if (out[i] == j) {
                cli_diag_error("--independent: %.*s is named twice", (int)len, s);
                return QD_EXIT_USAGE;
            }
        if (got == want) {
            got++;
            break;
        }
        out[got++] = j;
    }
    if (got != want) {
        cli_diag_error("--independent: the %zu constraint%s leave %zu independent coordinate%s; "
                      "name exactly %zu", e->ncon, e->ncon == 1 ? "" : "s", want,
                      want == 1 ? "" : "s", want);
        return QD_EXIT_USAGE;
    }
    for (size_t a = 1; a < want; a++) /* ascending, as the library reports them */
        for (size_t b = a; b > 0 && out[b - 1] > out[b]; b--) {
            size_t t = out[b];
            out[b] = out[b - 1];
            out[b - 1] = t;
        }
    return QD_EXIT_OK;
}

static int reduce(cli_lin_run *r, const double *q0, const char *indep,
                  qd_constrained_linear *c) {
    size_t *ix = NULL;
    int rc = QD_EXIT_OK;
    if (indep) {
        ix = calloc(r->e->n + 1, sizeof *ix);
        if (!ix) {
            cli_diag_error("out of memory");
            return QD_EXIT_FAIL;
        }
        rc = read_indep(r->e, indep, ix);
    }
    cli_lin_set_state(r, q0, NULL);
    if (rc == QD_EXIT_OK &&
        qd_constrained_linear_about(r->ctx, r->e, r->st.n, r->st.syms, r->st.vals, ix, c) !=
            QD_OK) {
        cli_diag_error("%s", qd_ctx_message(r->ctx));
        rc = qd_ctx_status(r->ctx) == QD_ERR_ARG || qd_ctx_status(r->ctx) == QD_ERR_UNSUPPORTED
                 ? QD_EXIT_USAGE
                 : QD_EXIT_FAIL;
    }
    free(ix);
    return rc;
}

int cli_con_point(cli_lin_run *r, const char *about, bool quiet, double *q0) {
    if (about)
        return cli_lin_coords(r, "--about", about, q0);
    qd_equilibrium_choice ch = {0};
    int rc = QD_EXIT_OK;
    if (qd_equilibria_choose(r->ctx, r->e, r->mf.model, r->st.n, r->st.syms, r->st.vals, &ch) !=
        QD_OK) {
        cli_diag_error("%s", qd_ctx_message(r->ctx));
        rc = QD_EXIT_FAIL;
    } else if (!ch.pt) {
        cli_diag_error("no equilibrium found on the constraints (qdot equilibria lists none): "
                      "give a point with --about");
        rc = QD_EXIT_FAIL;
    } else {
        memcpy(q0, ch.pt->q, r->e->n * sizeof *q0);
        if (!quiet) {
            fprintf(stderr, "qdot: note: about ");
            for (size_t j = 0; j < r->e->n; j++)
                fprintf(stderr, "%s%s = %.12g", j ? ", " : "", qd_expr_name(r->e->q[j]), q0[j]);
            fprintf(stderr, ", %s (%zu other equilibri%s found; choose with --about)\n",
                    ch.pt->kind == QD_EQ_MINIMUM ? "a minimum of the potential on the constraints"
                                                 : "the first equilibrium found",
                    ch.others, ch.others == 1 ? "um" : "a");
        }
    }
    qd_equilibrium_choice_free(&ch);
    return rc;
}

static void put_names(qd_buf *b, const qd_eom *e, size_t k, const size_t *ix) {
    for (size_t i = 0; i < k; i++)
        qd_buf_printf(b, "%s%s", i ? ", " : "", qd_expr_name(e->q[ix[i]]));
}

static void put_head(qd_buf *b, const qd_eom *e, const qd_constrained_linear *c) {
    qd_buf_printf(b, "on the constraint manifold (%zu coordinates, %zu constraint%s): "
                     "independent ", c->n, c->ncon, c->ncon == 1 ? "" : "s");
    put_names(b, e, c->r, c->indep);
    qd_buf_puts(b, "; dependent ");
    put_names(b, e, c->ncon, c->dep);
    qd_buf_puts(b, "\nabout ");
    for (size_t j = 0; j < c->n; j++) {
        qd_buf_printf(b, "%s%s = ", j ? ", " : "", qd_expr_name(e->q[j]));
        cli_state_put_result(b, c->q[j]);
    }
    qd_buf_puts(b, "\nmultipliers ");
    for (size_t k = 0; k < c->ncon; k++) {
        qd_buf_printf(b, "%s%s = ", k ? ", " : "", qd_expr_name(e->con[k].lambda));
        cli_state_put_result(b, c->lambda[k]);
    }
    qd_buf_puts(b, "\n");
}

static void json_head(qd_json *j, const qd_eom *e, const qd_constrained_linear *c) {
    qd_json_key(j, "independent");
    qd_json_begin_array(j);
    for (size_t i = 0; i < c->r; i++)
        qd_json_string(j, qd_expr_name(e->q[c->indep[i]]));
    qd_json_end_array(j);
    qd_json_key(j, "dependent");
    qd_json_begin_array(j);
    for (size_t i = 0; i < c->ncon; i++)
        qd_json_string(j, qd_expr_name(e->q[c->dep[i]]));
    qd_json_end_array(j);
    qd_json_key(j, "equilibrium");
    qd_json_begin_object(j);
    for (size_t k = 0; k < c->n; k++) {
        qd_json_key(j, qd_expr_name(e->q[k]));
        qd_json_number(j, c->q[k]);
    }
    qd_json_end_object(j);
    qd_json_key(j, "multipliers");
    qd_json_begin_object(j);
    for (size_t k = 0; k < c->ncon; k++) {
        qd_json_key(j, qd_expr_name(e->con[k].lambda));
        qd_json_number(j, c->lambda[k]);
    }
    qd_json_end_object(j);
}

static void json_matrix(qd_json *j, size_t r, size_t c, const double *x) {
    qd_json_begin_array(j);
    for (size_t i = 0; i < r; i++) {
        qd_json_begin_array(j);
        for (size_t k = 0; k < c; k++)
            qd_json_number(j, x[i * c + k]);
        qd_json_end_array(j);
    }
    qd_json_end_array(j);
}

static void json_eigs(qd_json *j, const qd_modes_result *res) {
    qd_json_key(j, "eigenvalues");
    qd_json_begin_array(j);
    for (size_t k = 0; k < res->neig; k++) {
        qd_json_begin_array(j);
        qd_json_number(j, res->eig_re[k]);
        qd_json_number(j, res->eig_im[k]);
        qd_json_end_array(j);
    }
    qd_json_end_array(j);
    qd_json_key(j, "stable");
    if (res->stable == -1)
        qd_json_null(j);
    else
        qd_json_bool(j, res->stable == 1);
    qd_json_key(j, "verdict");
    qd_json_string(j, verdict(res->stable));
}

static void text_eigs(qd_buf *b, const qd_modes_result *res) {
    qd_buf_puts(b, "eigenvalues of A:\n");
    for (size_t k = 0; k < res->neig; k++)
        qd_buf_printf(b, "  s = %.10g %s %.10gi\n", res->eig_re[k], res->eig_im[k] < 0 ? "-" : "+",
                      fabs(res->eig_im[k]));
}

static void modes_text(qd_buf *b, const qd_eom *e, const qd_constrained_linear *c,
                       const qd_modes_result *res) {
    qd_buf_puts(b, "small oscillations ");
    put_head(b, e, c);
    if (res->conservative) {
        for (size_t k = 0; k < res->n; k++) {
            double w2 = res->omega2[k];
            qd_buf_printf(b, "mode %zu: w^2 = %.12g", k + 1, w2);
            if (w2 > 0)
                qd_buf_printf(b, ", w = %.10g rad/s, period = %.10g s", sqrt(w2),
                              2 * 3.14159265358979323846 / sqrt(w2));
            qd_buf_puts(b, "\n  shape:");
            for (size_t i = 0; i < c->r; i++)
                qd_buf_printf(b, "%s %s = %.12g", i ? "," : "", qd_expr_name(e->q[c->indep[i]]),
                              res->shapes[i * res->n + k]);
            qd_buf_puts(b, "\n");
        }
    } else
        text_eigs(b, res);
    qd_buf_printf(b, "verdict: %s\n", verdict(res->stable));
}

static void modes_json(qd_buf *b, const qd_eom *e, const qd_constrained_linear *c,
                       const qd_modes_result *res) {
    qd_json j;
    qd_json_init(&j, b);
    qd_json_begin_object(&j);
    json_head(&j, e, c);
    qd_json_key(&j, "conservative");
    qd_json_bool(&j, res->conservative);
    const double *mats[] = {c->lin.M, c->lin.C, c->lin.G, c->lin.K};
    const char *keys[] = {"M", "C", "G", "K"};
    for (int i = 0; i < 4; i++) {
        qd_json_key(&j, keys[i]);
        json_matrix(&j, c->r, c->r, mats[i]);
    }
    if (res->conservative) {
        qd_json_key(&j, "modes");
        qd_json_begin_array(&j);
        for (size_t k = 0; k < res->n; k++) {
            qd_json_begin_object(&j);
            qd_json_key(&j, "omega2");
            qd_json_number(&j, res->omega2[k]);
            if (res->omega2[k] >= 0) {
                qd_json_key(&j, "omega");
                qd_json_number(&j, sqrt(res->omega2[k]));
            }
            qd_json_key(&j, "shape");
            qd_json_begin_object(&j);
            for (size_t i = 0; i < c->r; i++) {
                qd_json_key(&j, qd_expr_name(e->q[c->indep[i]]));
                qd_json_number(&j, res->shapes[i * res->n + k]);
            }
            qd_json_end_object(&j);
            qd_json_end_object(&j);
        }
        qd_json_end_array(&j);
    }
    json_eigs(&j, res);
    qd_json_end_object(&j);
    qd_buf_puts(b, "\n");
    b->failed = b->failed || !qd_json_ok(&j);
}

int cli_con_modes(cli_lin_run *r, const double *q0, const char *indep, bool json) {
    qd_constrained_linear c = {0};
    qd_modes_result res = {0};
    int rc = reduce(r, q0, indep, &c);
    if (rc == QD_EXIT_OK && qd_modes_solve(r->ctx, &c.lin, &res) != QD_OK) {
        cli_diag_error("%s", qd_ctx_message(r->ctx));
        rc = QD_EXIT_FAIL;
    }
    if (rc == QD_EXIT_OK) {
        qd_buf b = QD_BUF_INIT;
        (json ? modes_json : modes_text)(&b, r->e, &c, &res);
        rc = cli_emit(&b, "modes");
    }
    qd_modes_result_free(&res);
    qd_constrained_linear_free(&c);
    return rc;
}

typedef struct con_inputs {
    size_t nu;
    const qd_expr **u;
    double *B; /* 2r * nu */
} con_inputs;

static void lin_text(qd_buf *b, const qd_eom *e, const qd_constrained_linear *c, const double *A,
                     const con_inputs *in, const qd_modes_result *res) {
    size_t N = 2 * c->r;
    qd_buf_puts(b, in->nu ? "state-space form x' = A x + B u " : "state-space form x' = A x ");
    put_head(b, e, c);
    qd_buf_puts(b, "x = (");
    for (size_t i = 0; i < N; i++)
        qd_buf_printf(b, "%s%s%s", i ? ", " : "", qd_expr_name(e->q[c->indep[i % c->r]]),
                      i < c->r ? "" : "'");
    qd_buf_puts(b, ")\nA =\n");
    for (size_t i = 0; i < N; i++) {
        qd_buf_puts(b, " ");
        for (size_t k = 0; k < N; k++)
            qd_buf_printf(b, " %14.10g", A[i * N + k]);
        qd_buf_puts(b, "\n");
    }
    if (in->nu) {
        qd_buf_puts(b, "u = (");
        for (size_t k = 0; k < in->nu; k++)
            qd_buf_printf(b, "%s%s", k ? ", " : "", qd_expr_name(in->u[k]));
        qd_buf_puts(b, ")\nB =\n");
        for (size_t i = 0; i < N; i++) {
            qd_buf_puts(b, " ");
            for (size_t k = 0; k < in->nu; k++)
                qd_buf_printf(b, " %14.10g", in->B[i * in->nu + k]);
            qd_buf_puts(b, "\n");
        }
    }
    text_eigs(b, res);
    qd_buf_printf(b, "verdict: %s\n", verdict(res->stable));
}

static void lin_json(qd_buf *b, const qd_eom *e, const qd_constrained_linear *c, const double *A,
                     const con_inputs *in, const qd_modes_result *res) {
    size_t N = 2 * c->r;
    qd_json j;
    qd_json_init(&j, b);
    qd_json_begin_object(&j);
    json_head(&j, e, c);
    qd_json_key(&j, "states");
    qd_json_begin_array(&j);
    char name[256];
    for (size_t i = 0; i < N; i++) {
        snprintf(name, sizeof name, "%s%s", qd_expr_name(e->q[c->indep[i % c->r]]),
                 i < c->r ? "" : "'");
        qd_json_string(&j, name);
    }
    qd_json_end_array(&j);
    qd_json_key(&j, "A");
    json_matrix(&j, N, N, A);
    qd_json_key(&j, "inputs");
    qd_json_begin_array(&j);
    for (size_t k = 0; k < in->nu; k++)
        qd_json_string(&j, qd_expr_name(in->u[k]));
    qd_json_end_array(&j);
    qd_json_key(&j, "B");
    json_matrix(&j, N, in->nu, in->B);
    json_eigs(&j, res);
    qd_json_end_object(&j);
    qd_buf_puts(b, "\n");
    b->failed = b->failed || !qd_json_ok(&j);
}

int cli_con_linearize(cli_lin_run *r, const double *q0, const char *indep, bool json) {
    qd_constrained_linear c = {0};
    qd_modes_result res = {0};
    double *A = NULL;
    con_inputs in = {.nu = qd_model_ninputs(r->mf.model)};
    int rc = reduce(r, q0, indep, &c);
    if (rc == QD_EXIT_OK && (!(A = calloc(4 * c.r * c.r + 1, sizeof *A)) ||
                             !(in.B = calloc(2 * c.r * in.nu + 1, sizeof *in.B)) ||
                             !(in.u = calloc(in.nu + 1, sizeof *in.u)))) {
        cli_diag_error("out of memory");
        rc = QD_EXIT_FAIL;
    }
    for (size_t k = 0; rc == QD_EXIT_OK && k < in.nu; k++)
        in.u[k] = qd_model_input(r->mf.model, k);
    if (rc == QD_EXIT_OK && (qd_constrained_state_matrix(r->ctx, &c, A) != QD_OK ||
                             qd_constrained_input_matrix(r->ctx, r->e, &c, in.nu, in.u, r->st.n,
                                                         r->st.syms, r->st.vals, in.B) != QD_OK ||
                             qd_modes_solve(r->ctx, &c.lin, &res) != QD_OK)) {
        cli_diag_error("%s", qd_ctx_message(r->ctx));
        rc = QD_EXIT_FAIL;
    }
    if (rc == QD_EXIT_OK) {
        qd_buf b = QD_BUF_INIT;
        (json ? lin_json : lin_text)(&b, r->e, &c, A, &in, &res);
        rc = cli_emit(&b, "state-space form");
    }
    free(A);
    free(in.B);
    free(in.u);
    qd_modes_result_free(&res);
    qd_constrained_linear_free(&c);
    return rc;
}

/*
 * cli/cmd_bracket.c - `qdot bracket FILE F G`: the Poisson bracket [F, G]
 * (qd_bracket) in the model's canonical variables (qd_phase); `--dt F`
 * gives dF/dt along the motion (qd_phase_dt: [F, H], the explicit t and the
 * forces' part; for an implicit H in q' too).  F and G are expressions, so
 * "-x" is one and `--` ends the options.
 */
#include "cli.h"

#include <stddef.h>
#include <string.h>
#include "qdot/json.h"
#include "model_cli.h"
#include "model_file.h"

typedef struct br_args {
    bool dt;
    const char *format;
} br_args;

static const char *const formats[] = {"text", "json", "latex", NULL};

static const cli_opt opts[] = {
    {"--dt", NULL, CLI_FLAG, offsetof(br_args, dt), NULL,
     "dF/dt along the motion instead of [F, G] (give F only)", NULL, NULL},
    {"--format", NULL, CLI_CHOICE, offsetof(br_args, format), "FORMAT", "how to write it",
     formats, NULL},
    {0},
};

static const cli_spec spec = {
    "bracket", "FILE F G | FILE --dt F [options]",
    "The Poisson bracket [F, G] in the model's coordinates and momenta p_<q>, or dF/dt.",
    opts, NULL, 2, 3, "FILE and expressions", true,
};

static void json_expr(qd_ctx *ctx, qd_json *j, const char *key, const qd_expr *x) {
    qd_json_key(j, key);
    qd_json_expr(j, ctx, x);
}

static void write_json(qd_ctx *ctx, const qd_phase *ph, const qd_expr *F, const qd_expr *G,
                       const qd_expr *r, qd_buf *b) {
    qd_json j;
    qd_json_init(&j, b);
    qd_json_begin_object(&j);
    qd_json_key(&j, "momenta");
    qd_json_begin_array(&j);
    for (size_t k = 0; k < ph->n; k++)
        qd_json_string(&j, qd_expr_name(ph->p[k]));
    qd_json_end_array(&j);
    json_expr(ctx, &j, "F", F);
    if (!G) {
        json_expr(ctx, &j, "H", ph->h->H);
        json_expr(ctx, &j, "dF_dt", r);
        if (ph->h->implicit) { /* H and dF_dt are in q' too, defined by p = dL/dq' */
            qd_json_key(&j, "implicit");
            qd_json_bool(&j, true);
        }
    } else {
        json_expr(ctx, &j, "G", G);
        json_expr(ctx, &j, "bracket", r);
    }
    qd_json_end_object(&j);
    qd_buf_puts(b, "\n");
    b->failed = b->failed || !qd_json_ok(&j);
}

/* "[F, G] = r" or "d/dt(F) = r", in LaTeX \{F, G\} and \frac{d}{dt}. */
static void write_line(qd_ctx *ctx, const qd_phase *ph, bool tex, const qd_expr *F,
                       const qd_expr *G, const qd_expr *r, qd_buf *b) {
    qd_format f = tex ? QD_FMT_LATEX : QD_FMT_TEXT;
    qd_buf_puts(b, G ? (tex ? "\\left\\{" : "[") : (tex ? "\\frac{d}{dt}\\left(" : "d/dt("));
    qd_print(ctx, F, f, b);
    if (G) {
        qd_buf_puts(b, ", ");
        qd_print(ctx, G, f, b);
    }
    qd_buf_puts(b, G ? (tex ? "\\right\\} = " : "] = ") : (tex ? "\\right) = " : ") = "));
    qd_print(ctx, r, f, b);
    qd_buf_puts(b, "\n");
    if (!G && ph->h->implicit)
        qd_buf_puts(b, tex ? "% q' solves p = dL/dq' (no closed form)\n"
                           : "  (q' solves p = dL/dq': no closed form)\n");
}

/* Read what (F or G) as a function on phase space; the error shown in it. */
static int read_fn(qd_ctx *ctx, const qd_phase *ph, const char *what, const char *text,
                   const qd_expr **out) {
    qd_diag err;
    if ((*out = qd_phase_read(ctx, ph, text, &err)))
        return QD_EXIT_OK;
    cli_diag_read(what, text, &err);
    return cli_exit(err.status);
}

static int run(qd_ctx *ctx, const cli_model_file *mf, qd_phase *ph, const br_args *a,
               const char *const *pos) {
    const qd_expr *F, *G = NULL, *r;
    int rc = read_fn(ctx, ph, "F", pos[1], &F);
    if (rc == QD_EXIT_OK && !a->dt)
        rc = read_fn(ctx, ph, "G", pos[2], &G);
    if (rc != QD_EXIT_OK)
        return rc;
    r = a->dt ? qd_phase_dt(ctx, ph, F) : qd_bracket(ctx, ph->n, ph->q, ph->p, F, G);
    if (!r)
        return cli_diag_model(ctx, mf->path, mf->text, mf->model);
    qd_buf b = QD_BUF_INIT;
    if (a->format && !strcmp(a->format, "json"))
        write_json(ctx, ph, F, G, r, &b);
    else
        write_line(ctx, ph, a->format && !strcmp(a->format, "latex"), F, G, r, &b);
    return cli_emit(&b, "bracket");
}

int cli_cmd_bracket(int argc, char **argv) {
    br_args a = {0};
    const char *pos[3];
    int rc = cli_parse(&spec, argc, argv, &a, pos);
    if (rc == QD_EXIT_OK && (a.dt ? pos[2] != NULL : pos[2] == NULL)) {
        cli_diag_error(a.dt ? "bracket --dt takes one expression F" : "bracket needs F and G");
        cli_usage(&spec, stderr);
        rc = QD_EXIT_USAGE;
    }
    if (rc != QD_EXIT_OK)
        return rc;
    qd_ctx *ctx = qd_ctx_new();
    cli_model_file mf = {0};
    qd_phase ph = {0};
    if (!ctx)
        cli_diag_error("out of memory");
    rc = ctx ? cli_load(ctx, pos[0], 0, NULL, true, &mf) : QD_EXIT_FAIL;
    if (rc == QD_EXIT_OK && qd_phase_init(ctx, mf.model, &ph) != QD_OK)
        rc = cli_diag_ctx(ctx);
    if (rc == QD_EXIT_OK)
        rc = run(ctx, &mf, &ph, &a, pos);
    qd_phase_free(&ph);
    cli_model_file_free(&mf);
    qd_ctx_free(ctx);
    return rc;
}

/*
 * cli/cmd_codegen.c - `qdot codegen FILE [-o DIR] [--prefix NAME] [--set
 * NAME=VALUE]... [--eliminate]`: the equations of motion as self-contained C
 * (qd_codegen_c), written to DIR/NAME.c and DIR/NAME.h.  NAME defaults to
 * the file's base name made into a C identifier (qd_codegen_prefix_from_path,
 * qdot/codegen.h), DIR to the current directory.  --set changes the default
 * parameter values written into the file (parameters stay arguments of the
 * functions).
 */
#define _POSIX_C_SOURCE 200809L /* mkdir */
#include "driver.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include "eom_out.h"
#include "qdot/codegen.h"


typedef struct cg_run {
    cli_run c; /* the options follow */
    const char *dir, *prefix;
    cli_list sets;
    bool eliminate;
    char name[QD_CODEGEN_PREFIX_MAX + 1];
} cg_run;

static const cli_opt cg_opts[] = {
    {"--out", "-o", CLI_TEXT, offsetof(cg_run, dir), "DIR",
     "the directory NAME.c and NAME.h are written to (made when missing; default .)", NULL, NULL},
    {"--prefix", NULL, CLI_TEXT, offsetof(cg_run, prefix), "NAME",
     "the C name of the files and functions (default: the file's base name)", NULL, NULL},
    {"--set", NULL, CLI_LIST, offsetof(cg_run, sets), "NAME=VALUE",
     "a parameter's default value written into the file", NULL, NULL},
    {"--eliminate", NULL, CLI_FLAG, offsetof(cg_run, eliminate), NULL,
     "substitute the holonomic constraints that can be solved for a coordinate", NULL, NULL},
    {0},
};

static const cli_spec cg_spec = {
    "codegen", "FILE [-o DIR] [options]", "self-contained C for the right-hand side",
    cg_opts, NULL, 1, 1, "FILE", false,
};

static int write_text(const char *dir, const char *name, const char *ext, const qd_buf *b) {
    size_t len = strlen(dir) + strlen(name) + 8;
    char *path = malloc(len);
    if (!path)
        return QD_EXIT_FAIL;
    snprintf(path, len, "%s/%s.%s", dir, name, ext);
    int rc = QD_EXIT_OK, err = 0;
    FILE *f = cli_out_open(path, &rc); /* a directory named like the file: exit 2 */
    if (f) {
        const char *text = qd_buf_str(b);
        cli_out_write(f, text, strlen(text), &err);
        rc = cli_out_close(f, path, err);
    }
    if (rc == QD_EXIT_OK)
        printf("wrote %s\n", path);
    free(path);
    return rc;
}

/* The library's files for the model (qd_codegen_model_c). */
static int generate(qd_ctx *ctx, cg_run *r, cli_model_file *mf, qd_buf *c, qd_buf *h) {
    int rc = cli_load(ctx, r->c.file, r->sets.n, r->sets.items, "codegen", mf);
    if (rc != QD_EXIT_OK || qd_codegen_model_c(ctx, mf->model, r->eliminate, r->name, c, h) ==
                                QD_OK)
        return rc;
    if (qd_ctx_status(ctx) == QD_ERR_ARG && !strcmp(qd_ctx_diag(ctx)->name, "eliminate"))
        return cli_usage_error("--%s", qd_ctx_message(ctx));
    return cli_eom_derive_error(ctx, mf);
}

static int run(cli_run *cr) {
    cg_run *r = (cg_run *)cr;
    qd_buf c = QD_BUF_INIT, h = QD_BUF_INIT;
    int rc = generate(cr->ctx, r, &cr->mf, &c, &h);
    /* -o names the directory to write into: made when missing (not its parents) */
    if (rc == QD_EXIT_OK && mkdir(r->dir, 0777) != 0 && errno != EEXIST) {
        cli_diag_error("cannot create the directory %s: %s", r->dir, strerror(errno));
        rc = QD_EXIT_FAIL;
    }
    if (rc == QD_EXIT_OK)
        rc = write_text(r->dir, r->name, "c", &c);
    if (rc == QD_EXIT_OK)
        rc = write_text(r->dir, r->name, "h", &h);
    qd_buf_free(&c);
    qd_buf_free(&h);
    return rc;
}

/* --prefix a C identifier (else the name from FILE), -o not empty. */
static int check(cli_run *c) {
    cg_run *r = (cg_run *)c;
    if (r->prefix && !qd_codegen_prefix_valid(r->prefix))
        return cli_usage_error("--prefix takes a C identifier, not '%s'", r->prefix);
    if (r->prefix)
        strcpy(r->name, r->prefix);
    else
        qd_codegen_prefix_from_path(c->file, r->name, sizeof r->name);
    if (r->dir && !r->dir[0]) {  /* "" would write to "/NAME.c" */
        return cli_usage_error("-o takes a directory, not an empty name");
    }
    r->dir = r->dir ? r->dir : ".";
    return QD_EXIT_OK;
}

CLI_COMMAND(codegen, cg_run, &cg_spec, 0, 0, check, run, NULL)

/*
 * cli/model_file.c - reading a model file and showing its errors: the
 * library locates an error (qd_diag), the program prints it.
 */
#include "model_file.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include "cli.h"

/* The whole stream in one NUL-terminated block; NULL with errno set. */
static char *slurp(FILE *fp, size_t *len) {
    size_t cap = 4096, n = 0;
    char *s = malloc(cap);
    while (s) {
        n += fread(s + n, 1, cap - n - 1, fp);
        if (ferror(fp) || feof(fp))
            break;
        char *t = cap > SIZE_MAX / 2 ? NULL : realloc(s, cap * 2);
        if (!t) {
            free(s);
            errno = ENOMEM;
            return NULL;
        }
        s = t;
        cap *= 2;
    }
    if (s && ferror(fp)) {
        int saved = errno ? errno : EIO;
        free(s);
        errno = saved;
        return NULL;
    }
    if (s) {
        s[n] = '\0';
        *len = n;
    }
    return s;
}

static int read_text(const char *path, cli_model_file *mf) {
    bool std_in = !strcmp(path, "-");
    mf->path = std_in ? "<stdin>" : path;
    FILE *fp = std_in ? stdin : fopen(path, "rb");
    if (!fp) {
        cli_diag_error("cannot open '%s': %s", path, strerror(errno));
        return QD_EXIT_USAGE;
    }
    errno = 0;
    mf->text = slurp(fp, &mf->len);
    int err = errno;
    if (!std_in)
        fclose(fp);
    if (!mf->text) {
        cli_diag_error("cannot read '%s': %s", mf->path, strerror(err ? err : EIO));
        return QD_EXIT_USAGE;
    }
    /* the parser reads up to the first NUL: the rest would be ignored silently */
    if (strlen(mf->text) != mf->len) {
        cli_diag_error("%s: the file contains a NUL byte at offset %zu (not a text file?)",
                      mf->path, strlen(mf->text));
        return QD_EXIT_USAGE;
    }
    return QD_EXIT_OK;
}

int cli_model_file_load_opts(qd_ctx *ctx, const char *path, const qd_model_opts *opts,
                             cli_model_file *mf) {
    *mf = (cli_model_file){0};
    int rc = read_text(path, mf);
    if (rc != QD_EXIT_OK)
        return rc;
    qd_diag d;
    memset(&d, 0, sizeof d);
    mf->model = qd_model_parse_opts(ctx, mf->text, opts, &d);
    if (mf->model && qd_model_independent(mf->model)) /* print x, not t, everywhere */
        qd_print_set_time_name(ctx, qd_model_independent(mf->model));
    if (mf->model)
        return QD_EXIT_OK;
    if (qd_ctx_status(ctx) == QD_ERR_NOMEM) {
        cli_diag_error("out of memory while reading '%s'", mf->path);
        return QD_EXIT_FAIL;
    }
    if (!d.located) /* not in the text: a value given on the command line */
        cli_diag_error("--set: %s", d.message);
    else
        cli_diag_show(mf->path, mf->text, &d);
    return QD_EXIT_USAGE;
}

int cli_model_file_load(qd_ctx *ctx, const char *path, cli_model_file *mf) {
    return cli_model_file_load_opts(ctx, path, NULL, mf);
}

void cli_model_file_free(cli_model_file *mf) {
    if (mf->model)
        qd_model_free(mf->model);
    free(mf->text);
    *mf = (cli_model_file){0};
}

void cli_model_file_error(const cli_model_file *mf, const char *what, const char *message,
                         const char *hint) {
    qd_diag d;
    if (!qd_model_where(mf->model, what, &d))
        memset(&d, 0, sizeof d); /* shown without a caret */
    snprintf(d.message, sizeof d.message, "%s", message);
    snprintf(d.hint, sizeof d.hint, "%s", hint ? hint : "");
    cli_diag_show(mf->path, mf->text, &d);
}

/*
 * cli/model_file.c - reading a model file and showing its errors: the
 * library locates an error (qd_diag), the program prints it.
 */
#define _POSIX_C_SOURCE 200809L /* fileno, fstat */
#include "model_file.h"
#include "out.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include "cli.h"

/* Why a stream could not be read whole. */
typedef enum { READ_OK, READ_ERRNO, READ_NUL, READ_BIG } read_end;

/* The stream in one NUL-terminated block, read a chunk at a time and
 * checked as it comes: reading stops at the first NUL byte (*len is then
 * its offset) and past QD_MODEL_MAX_BYTES, so `qdot check /dev/zero` stops
 * at once.  *text is the block (also after READ_NUL, for the caret). */
static read_end slurp(FILE *fp, char **text, size_t *len) {
    size_t cap = 4096, n = 0;
    char *s = malloc(cap);
    *text = NULL;
    *len = 0;
    if (!s) {
        errno = ENOMEM;
        return READ_ERRNO;
    }
    for (;;) {
        size_t got = fread(s + n, 1, cap - n - 1, fp);
        const char *nul = memchr(s + n, '\0', got);
        n += got;
        s[n] = '\0';
        if (nul) {
            *text = s;
            *len = (size_t)(nul - s);
            return READ_NUL;
        }
        if (n > QD_MODEL_MAX_BYTES) {
            free(s);
            return READ_BIG;
        }
        if (ferror(fp)) {
            int saved = errno ? errno : EIO;
            free(s);
            errno = saved;
            return READ_ERRNO;
        }
        if (feof(fp))
            break;
        if (n + 1 < cap)
            continue;
        size_t grown = cap * 2 > QD_MODEL_MAX_BYTES + 2 ? QD_MODEL_MAX_BYTES + 2 : cap * 2;
        char *t = realloc(s, grown);
        if (!t) {
            free(s);
            errno = ENOMEM;
            return READ_ERRNO;
        }
        s = t;
        cap = grown;
    }
    *text = s;
    *len = n;
    return READ_OK;
}

int cli_read_text(const char *path, const char *what, char **text, size_t *len) {
    bool std_in = !strcmp(path, "-");
    const char *shown = std_in ? "<stdin>" : path;
    *text = NULL;
    *len = 0;
    int rc = QD_EXIT_USAGE;
    FILE *fp = std_in ? stdin : cli_in_open(path, &rc);
    if (!fp)
        return rc;
    errno = 0;
    read_end how = slurp(fp, text, len);
    int err = errno;
    if (!std_in)
        fclose(fp);
    if (how == READ_ERRNO) {
        cli_diag_error("cannot read '%s': %s", shown, strerror(err ? err : EIO));
        return err == ENOMEM ? QD_EXIT_FAIL : QD_EXIT_USAGE;
    }
    if (how == READ_BIG)
        return cli_usage_error("'%s' is longer than %zu MiB, the most %s may be", shown,
                               QD_MODEL_MAX_BYTES >> 20, what);
    if (how == READ_NUL) { /* a reader would stop at it and ignore the rest silently */
        qd_diag d;
        memset(&d, 0, sizeof d);
        d.status = QD_ERR_PARSE;
        d.located = true;
        d.offset = *len;
        d.length = 1;
        snprintf(d.message, sizeof d.message, "a NUL byte at byte %zu: this is not a text file",
                 *len);
        snprintf(d.hint, sizeof d.hint, "%s is UTF-8 text", what);
        cli_diag_show(shown, *text, &d);
        free(*text);
        *text = NULL;
        return QD_EXIT_USAGE;
    }
    return QD_EXIT_OK;
}

static int read_text(const char *path, cli_model_file *mf) {
    mf->path = !strcmp(path, "-") ? "<stdin>" : path;
    return cli_read_text(path, "a model file", &mf->text, &mf->len);
}

/* The parser's refusal d of mf's text (a model's or a field's). */
static int parse_error(const qd_ctx *ctx, const cli_model_file *mf, const qd_diag *d) {
    if (qd_ctx_status(ctx) == QD_ERR_NOMEM) {
        cli_diag_error("out of memory while reading '%s'", mf->path);
        return QD_EXIT_FAIL;
    }
    if (!d->located) /* not in the text: a value given on the command line */
        cli_diag_error("--set: %s", d->message);
    else
        cli_diag_show(mf->path, mf->text, d);
    return QD_EXIT_USAGE;
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
    return mf->model ? QD_EXIT_OK : parse_error(ctx, mf, &d);
}

bool cli_model_file_is_field(const char *path) {
    if (!strcmp(path, "-"))
        return false;
    FILE *fp = fopen(path, "rb");
    if (!fp)
        return false;
    char *text;
    size_t len;
    read_end how = slurp(fp, &text, &len);
    fclose(fp);
    bool field = how == READ_OK && qd_field_declared(text);
    if (how == READ_OK || how == READ_NUL)
        free(text);
    return field;
}

int cli_field_file_load(qd_ctx *ctx, const char *path, const qd_model_opts *opts,
                        cli_model_file *mf) {
    *mf = (cli_model_file){0};
    int rc = read_text(path, mf);
    if (rc != QD_EXIT_OK)
        return rc;
    qd_diag d;
    memset(&d, 0, sizeof d);
    mf->field = qd_field_parse(ctx, mf->text, opts, &d);
    return mf->field ? QD_EXIT_OK : parse_error(ctx, mf, &d);
}

int cli_model_file_load(qd_ctx *ctx, const char *path, cli_model_file *mf) {
    return cli_model_file_load_opts(ctx, path, NULL, mf);
}

void cli_model_file_free(cli_model_file *mf) {
    if (mf->model)
        qd_model_free(mf->model);
    qd_field_free(mf->field);
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

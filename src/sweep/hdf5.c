/*
 * src/sweep/hdf5.c - qd_sweep_hdf5: a sweep's rows into an HDF5 file.  The
 * optional module qdot_hdf5.so (modules/hdf5.c) builds the file's image in
 * memory; this file gathers what it holds and writes the image with
 * checked writes, so that a full disk is an error with errno's reason and
 * never a partial file.
 */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "base/args.h"
#include "base/mem.h"
#include "base/module.h"
#include "ext.h"
#include "qdot/version.h"
#include "sweep_int.h"

static void *module(qd_ctx *ctx) {
    return qd__module_open(ctx, "hdf5", 0, QD__EXT_ABI, "HDF5", "libhdf5-dev");
}

qd_status qd_sweep_hdf5_ready(qd_ctx *ctx) {
    QD_ARGS_CTX(ctx, ctx);
    return module(ctx) ? QD_OK : QD_ERR_UNSUPPORTED;
}

/* The image of size bytes into path; errno's reason when it fails. */
static qd_status write_image(qd_ctx *ctx, const char *path, const void *image, size_t size) {
    struct stat sb;
    if (stat(path, &sb) == 0 && S_ISDIR(sb.st_mode)) {
        qd_ctx_error(ctx, QD_ERR_IO, "cannot write %s: is a directory", path);
        return QD_ERR_IO;
    }
    FILE *f = fopen(path, "wb");
    if (!f) {
        qd_ctx_error(ctx, QD_ERR_IO, "cannot write %s: %s", path, strerror(errno));
        return QD_ERR_IO;
    }
    /* only a regular file is removed when the write fails (never /dev/full) */
    bool regular = fstat(fileno(f), &sb) == 0 && S_ISREG(sb.st_mode);
    errno = 0;
    int e = fwrite(image, 1, size, f) == size ? 0 : errno ? errno : EIO;
    errno = 0;
    if (fflush(f) != 0 && !e)
        e = errno ? errno : EIO;
    errno = 0;
    if (fclose(f) != 0 && !e)
        e = errno ? errno : EIO;
    if (!e)
        return QD_OK;
    if (regular)
        remove(path); /* a partial file is no file */
    qd_ctx_error(ctx, QD_ERR_IO, "cannot write %s: %s", path, strerror(e));
    return QD_ERR_IO;
}

qd_status qd_sweep_hdf5(qd_ctx *ctx, const qd_sweep *w, const double *rows,
                        const qd_sweep_outcome *outcome, size_t nattrs,
                        const char *const *attr_names, const char *const *attr_values,
                        const char *path) {
    QD_ARGS_CTX(ctx, ctx && w && rows && outcome && path &&
                         (nattrs == 0 || (attr_names && attr_values)));
    void *h = module(ctx);
    qd__h5_image_fn image_of = NULL;
    if (!h || !qd__module_fn(ctx, h, "qdot_hdf5.so", "qd_ext_hdf5_image", &image_of,
                             sizeof image_of))
        return QD_ERR_UNSUPPORTED;
    size_t n = w->nruns, one = n ? n : 1;
    const char **names = qd__calloc(ctx, w->ncols + 1, sizeof *names);
    int *status = qd__calloc(ctx, one, sizeof *status);
    const char **reason = qd__calloc(ctx, one, sizeof *reason);
    char *text = qd__calloc(ctx, one, QD_SWEEP_OUTCOME_MAX);
    const char **an = qd__calloc(ctx, nattrs + 1, sizeof *an);
    const char **av = qd__calloc(ctx, nattrs + 1, sizeof *av);
    qd_status st = names && status && reason && text && an && av ? QD_OK : QD_ERR_NOMEM;
    if (st == QD_OK) {
        for (size_t j = 0; j < w->ncols; j++)
            names[j] = qd_sweep_col(w, j);
        for (size_t i = 0; i < n; i++) {
            status[i] = (int)outcome[i].status;
            reason[i] = status[i] == QD_OK
                            ? ""
                            : qd_sweep_outcome_str(&outcome[i], text + i * QD_SWEEP_OUTCOME_MAX,
                                                   QD_SWEEP_OUTCOME_MAX);
        }
        an[0] = "qdot_version";
        av[0] = QDOT_VERSION;
        for (size_t k = 0; k < nattrs; k++) {
            an[k + 1] = attr_names[k];
            av[k + 1] = attr_values[k];
        }
        qd__h5_table t = {.nruns = n, .ncols = w->ncols, .names = names, .rows = rows,
                          .status = status, .reason = reason, .nattrs = nattrs + 1,
                          .attr_names = an, .attr_values = av};
        size_t size = 0;
        void *image = image_of(&t, &size);
        if (!image) {
            qd_ctx_error(ctx, QD_ERR_IO, "cannot write %s: HDF5 failed to build the file", path);
            st = QD_ERR_IO;
        } else {
            st = write_image(ctx, path, image, size);
            free(image); /* the module's malloc: the C library's, not qd__malloc's */
        }
    }
    qd__free(names);
    qd__free(status);
    qd__free(reason);
    qd__free(text);
    qd__free(an);
    qd__free(av);
    return st;
}

qd_status qd_sweep_hdf5_made(qd_ctx *ctx, const qd_sweep *w, const qd_sweep_result *r,
                             const qd_sweep_spec *sp, const char *model, const char *list,
                             const char *path) {
    QD_ARGS_CTX(ctx, ctx && w && r && sp && sp->measures && path);
    char n[32], seed[32];
    snprintf(n, sizeof n, "%zu", sp->n);
    snprintf(seed, sizeof seed, "%llu", (unsigned long long)sp->seed);
    const char *how = sp->grid ? "grid" : sp->random ? "random" : "list";
    const char *names[] = {"model", "measures", how, "n", "seed"};
    const char *values[] = {model ? model : "", sp->measures,
                            sp->grid ? sp->grid : sp->random ? sp->random : list ? list : "",
                            n, seed};
    return qd_sweep_hdf5(ctx, w, r->rows, r->outcome, sp->random ? 5 : 3, names, values, path);
}

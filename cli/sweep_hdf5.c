/*
 * cli/sweep_hdf5.c - the writer behind qdot sweep --format hdf5 (the layout
 * is in sweep_hdf5.h).  Every HDF5 handle is closed on every path; HDF5's
 * own error stack printing is off, so a failure reads as one qdot message.
 * The file is built in memory and written by qdot's own checked writes; a
 * failed write removes the partial file.
 */
#define _POSIX_C_SOURCE 200809L
#include "sweep_hdf5.h"

#include <stdio.h>

#ifndef QDOT_HAVE_HDF5

bool cli_hdf5_built(void) { return false; }

bool cli_hdf5_write_sweep(const char *path, const cli_h5_sweep *s, char *err, size_t errcap) {
    (void)s;
    snprintf(err, errcap, "cannot write '%s': this qdot was built without HDF5 (libhdf5-dev)",
             path);
    return false;
}

#else

#include <errno.h>
#include <hdf5.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include "qdot/qdot.h"

bool cli_hdf5_built(void) { return true; }

/* A variable-length C string type; the caller closes it. */
static hid_t vlen_string(void) {
    hid_t t = H5Tcopy(H5T_C_S1);
    if (t >= 0 && H5Tset_size(t, H5T_VARIABLE) < 0) {
        H5Tclose(t);
        return -1;
    }
    return t;
}

/* Attribute name on obj: n strings (n == 0: one scalar string, text[0]). */
static bool put_strings_attr(hid_t obj, const char *name, size_t n, const char *const *text) {
    hsize_t dim = n;
    hid_t t = vlen_string();
    hid_t sp = n == 0 ? H5Screate(H5S_SCALAR) : H5Screate_simple(1, &dim, NULL);
    hid_t a = t >= 0 && sp >= 0 ? H5Acreate2(obj, name, t, sp, H5P_DEFAULT, H5P_DEFAULT) : -1;
    bool ok = a >= 0 && H5Awrite(a, t, text) >= 0;
    if (a >= 0)
        H5Aclose(a);
    if (sp >= 0)
        H5Sclose(sp);
    if (t >= 0)
        H5Tclose(t);
    return ok;
}

/* Dataset name of rank 1 or 2 (dims[1] == 0 for rank 1) of memory type mt,
 * stored as ft; returns it open (or -1) after writing data. */
static hid_t put_dataset(hid_t file, const char *name, hid_t ft, hid_t mt, hsize_t d0, hsize_t d1,
                         const void *data) {
    hsize_t dims[2] = {d0, d1};
    hid_t sp = H5Screate_simple(d1 > 0 ? 2 : 1, dims, NULL);
    hid_t d = sp >= 0 ? H5Dcreate2(file, name, ft, sp, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT) : -1;
    if (d >= 0 && d0 > 0 && H5Dwrite(d, mt, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) < 0) {
        H5Dclose(d);
        d = -1;
    }
    if (sp >= 0)
        H5Sclose(sp);
    return d;
}

static bool put_runs(hid_t file, const cli_h5_sweep *s) {
    hid_t d = put_dataset(file, "runs", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, s->nruns, s->ncols,
                          s->rows);
    if (d < 0)
        return false;
    bool ok = put_strings_attr(d, "columns", s->ncols, s->names);
    H5Dclose(d);
    return ok;
}

static bool put_status(hid_t file, const cli_h5_sweep *s) {
    int *st = malloc((s->nruns ? s->nruns : 1) * sizeof *st);
    const char **why = malloc((s->nruns ? s->nruns : 1) * sizeof *why);
    char *text = malloc((s->nruns ? s->nruns : 1) * QD_SWEEP_OUTCOME_MAX);
    bool ok = st && why && text;
    for (size_t i = 0; ok && i < s->nruns; i++) {
        st[i] = (int)s->outcome[i].status;
        why[i] = st[i] == 0 ? "" : qd_sweep_outcome_str(&s->outcome[i],
                                                        text + i * QD_SWEEP_OUTCOME_MAX,
                                                        QD_SWEEP_OUTCOME_MAX);
    }
    hid_t d = ok ? put_dataset(file, "status", H5T_STD_I32LE, H5T_NATIVE_INT, s->nruns, 0, st) : -1;
    ok = d >= 0;
    if (d >= 0)
        H5Dclose(d);
    hid_t t = ok ? vlen_string() : -1;
    d = t >= 0 ? put_dataset(file, "reason", t, t, s->nruns, 0, why) : -1;
    ok = ok && d >= 0;
    if (d >= 0)
        H5Dclose(d);
    if (t >= 0)
        H5Tclose(t);
    free(st);
    free(why);
    free(text);
    return ok;
}

static bool put_root_attrs(hid_t file, const cli_h5_sweep *s) {
    const char *version[1] = {QDOT_VERSION};
    bool ok = put_strings_attr(file, "qdot_version", 0, version);
    for (size_t k = 0; ok && k < s->nattrs; k++)
        ok = put_strings_attr(file, s->attr_names[k], 0, &s->attr_values[k]);
    return ok;
}

/* The file built in memory (HDF5's core driver, no backing store): HDF5
 * itself never writes to the disk, so a full disk cannot leave it with a
 * file it failed to flush (which crashed at exit).  NULL on failure. */
static void *build_image(const cli_h5_sweep *s, size_t *size) {
    void *image = NULL;
    hid_t fapl = H5Pcreate(H5P_FILE_ACCESS);
    if (fapl < 0)
        return NULL;
    hid_t file = H5Pset_fapl_core(fapl, 1 << 20, 0) >= 0
                     ? H5Fcreate("qdot-sweep.h5", H5F_ACC_TRUNC, H5P_DEFAULT, fapl)
                     : -1;
    H5Pclose(fapl);
    if (file < 0)
        return NULL;
    bool ok = put_runs(file, s) && put_status(file, s) && put_root_attrs(file, s) &&
              H5Fflush(file, H5F_SCOPE_GLOBAL) >= 0;
    ssize_t n = ok ? H5Fget_file_image(file, NULL, 0) : -1;
    image = n > 0 ? malloc((size_t)n) : NULL;
    if (image && H5Fget_file_image(file, image, (size_t)n) != n) {
        free(image);
        image = NULL;
    }
    if (H5Fclose(file) < 0 && image) {
        free(image);
        image = NULL;
    }
    *size = image ? (size_t)n : 0;
    return image;
}

bool cli_hdf5_write_sweep(const char *path, const cli_h5_sweep *s, char *err, size_t errcap) {
    H5Eset_auto2(H5E_DEFAULT, NULL, NULL);
    size_t size = 0;
    void *image = build_image(s, &size);
    if (!image) {
        snprintf(err, errcap, "cannot write %s: HDF5 failed to build the file", path);
        return false;
    }
    struct stat sb;
    if (stat(path, &sb) == 0 && S_ISDIR(sb.st_mode)) {
        free(image);
        snprintf(err, errcap, "cannot write %s: is a directory", path);
        return false;
    }
    FILE *f = fopen(path, "wb");
    if (!f) {
        snprintf(err, errcap, "cannot write %s: %s", path, strerror(errno));
        free(image);
        return false;
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
    free(image);
    if (!e)
        return true;
    if (regular)
        remove(path); /* a partial file is no file */
    snprintf(err, errcap, "cannot write %s: %s", path, strerror(e));
    return false;
}

#endif

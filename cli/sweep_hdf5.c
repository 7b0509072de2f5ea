/*
 * cli/sweep_hdf5.c - the writer behind qdot sweep --format hdf5 (the layout
 * is in sweep_hdf5.h).  Every HDF5 handle is closed on every path; HDF5's
 * own error stack printing is off, so a failure reads as one qdot message.
 */
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

#include <hdf5.h>
#include <stdlib.h>
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
    bool ok = st && why;
    for (size_t i = 0; ok && i < s->nruns; i++) {
        st[i] = (int)s->status[i];
        why[i] = s->reasons && st[i] != 0 ? s->reasons + i * s->reason_size : "";
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
    return ok;
}

static bool put_root_attrs(hid_t file, const cli_h5_sweep *s) {
    const char *version[1] = {QDOT_VERSION};
    bool ok = put_strings_attr(file, "qdot_version", 0, version);
    for (size_t k = 0; ok && k < s->nattrs; k++)
        ok = put_strings_attr(file, s->attr_names[k], 0, &s->attr_values[k]);
    return ok;
}

bool cli_hdf5_write_sweep(const char *path, const cli_h5_sweep *s, char *err, size_t errcap) {
    H5Eset_auto2(H5E_DEFAULT, NULL, NULL);
    hid_t file = H5Fcreate(path, H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
    if (file < 0) {
        snprintf(err, errcap, "cannot write '%s' (HDF5 could not create it)", path);
        return false;
    }
    bool ok = put_runs(file, s) && put_status(file, s) && put_root_attrs(file, s);
    if (H5Fclose(file) < 0)
        ok = false;
    if (!ok)
        snprintf(err, errcap, "cannot write '%s' (HDF5 failed while writing)", path);
    return ok;
}

#endif

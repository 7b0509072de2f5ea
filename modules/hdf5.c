/*
 * modules/hdf5.c - qdot_hdf5.so: the HDF5 file image behind
 * qd_sweep_hdf5 (qdot sweep --format hdf5; the layout is in qdot/sweep.h).
 * libqdot opens it only when such a file is asked for; the interface is
 * src/sweep/ext.h, and this file calls nothing of libqdot's.
 *
 * The file is built in memory (HDF5's core driver, no backing store), so
 * HDF5 itself never writes to the disk and a full disk cannot leave it
 * with a file it failed to flush (which crashed at exit); libqdot writes
 * the image with its own checked writes.  Every HDF5 handle is closed on
 * every path, and HDF5's own error printing is off.
 */
#include <hdf5.h>
#include <stdlib.h>

#include "sweep/ext.h"

unsigned qd_ext_hdf5_abi(void);
void *qd_ext_hdf5_image(const qd__h5_table *t, size_t *size);

unsigned qd_ext_hdf5_abi(void) { return QD__EXT_ABI; }

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

/* Dataset name of rank 1 or 2 (d1 == 0 for rank 1) of memory type mt,
 * stored as ft, written from data; true when it was. */
static bool put_dataset(hid_t file, const char *name, hid_t ft, hid_t mt, hsize_t d0, hsize_t d1,
                        const void *data, const char *cols_attr, const qd__h5_table *t) {
    hsize_t dims[2] = {d0, d1};
    hid_t sp = H5Screate_simple(d1 > 0 ? 2 : 1, dims, NULL);
    hid_t d = sp >= 0 ? H5Dcreate2(file, name, ft, sp, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT) : -1;
    bool ok = d >= 0 && (d0 == 0 || H5Dwrite(d, mt, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) >= 0);
    if (ok && cols_attr)
        ok = put_strings_attr(d, cols_attr, t->ncols, t->names);
    if (d >= 0)
        H5Dclose(d);
    if (sp >= 0)
        H5Sclose(sp);
    return ok;
}

static bool put_tables(hid_t file, const qd__h5_table *t) {
    hid_t s = vlen_string();
    bool ok = s >= 0 &&
              put_dataset(file, "runs", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, t->nruns, t->ncols,
                          t->rows, "columns", t) &&
              put_dataset(file, "status", H5T_STD_I32LE, H5T_NATIVE_INT, t->nruns, 0, t->status,
                          NULL, t) &&
              put_dataset(file, "reason", s, s, t->nruns, 0, t->reason, NULL, t);
    if (s >= 0)
        H5Tclose(s);
    for (size_t k = 0; ok && k < t->nattrs; k++)
        ok = put_strings_attr(file, t->attr_names[k], 0, &t->attr_values[k]);
    return ok;
}

void *qd_ext_hdf5_image(const qd__h5_table *t, size_t *size) {
    *size = 0;
    H5Eset_auto2(H5E_DEFAULT, NULL, NULL);
    hid_t fapl = H5Pcreate(H5P_FILE_ACCESS);
    if (fapl < 0)
        return NULL;
    hid_t file = H5Pset_fapl_core(fapl, 1 << 20, 0) >= 0
                     ? H5Fcreate("qdot-sweep.h5", H5F_ACC_TRUNC, H5P_DEFAULT, fapl)
                     : -1;
    H5Pclose(fapl);
    if (file < 0)
        return NULL;
    bool ok = put_tables(file, t) && H5Fflush(file, H5F_SCOPE_GLOBAL) >= 0;
    ssize_t n = ok ? H5Fget_file_image(file, NULL, 0) : -1;
    void *image = n > 0 ? malloc((size_t)n) : NULL;
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

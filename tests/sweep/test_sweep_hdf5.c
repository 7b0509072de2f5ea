/*
 * tests/sweep/test_sweep_hdf5.c - qd_sweep_hdf5 (src/sweep/hdf5.c and the
 * module modules/hdf5.c, found through QDOT_MODULE_DIR) read back through
 * libhdf5: the rows bit for bit (NaN where a measure has none), the column
 * names, each run's status and reason, the attributes saying how the
 * sweep was made; a sweep of no runs; a file that cannot be made.  Without
 * HDF5 the call refuses, saying so, and the test says it skips.
 * `test_sweep_hdf5 --dump FILE.h5` prints a file's runs, status and
 * reason as tab-separated text (%.17g): tests/cli/check_sweep_mpi_cli.py
 * compares what `qdot sweep --format hdf5` wrote with its CSV.
 */
#define _POSIX_C_SOURCE 200809L
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "qdot/qdot.h"
#include "qdot/sweep.h"
#include "sim/sim_fixture.h"

/* A 3-run grid over x of the oscillator, its final state and energy error. */
static const char osc[] = "coordinates x\nparameters k = 1\nT = x'^2/2\nV = k*x^2/2\n"
                          "initial x = 0, x' = 1\n";
#define NRUNS 3

typedef struct h5_fix {
    sim_fix *f;
    qd_sweep *w;
    size_t ncols;
    double *rows;
    qd_sweep_outcome outcome[NRUNS];
} h5_fix;

/* The sweep run for real; then run 1 recorded as failed (dop853's step fell
 * below round-off at t = 0.25), its measures NaN, as a failed run's are. */
static h5_fix *h5_fix_new(bool grid) {
    h5_fix *h = calloc(1, sizeof *h);
    h->f = sf_load(osc);
    assert_non_null(h->f);
    assert_int_equal(qd_sim_compile(h->f->s), QD_OK);
    h->w = qd_sweep_new(h->f->ctx, h->f->s, h->f->m);
    assert_non_null(h->w);
    if (grid)
        assert_int_equal(qd_sweep_grid(h->w, "x=0.1:0.3:3"), QD_OK);
    assert_int_equal(qd_sweep_measures(h->w, "final, energy_error"), QD_OK);
    h->ncols = qd_sweep_ncols(h->w);
    h->rows = calloc(NRUNS * h->ncols, sizeof *h->rows);
    if (!grid)
        return h;
    qd_sim_opts o = {.method = QD_SIM_DOP853, .t_end = 1, .rtol = 1e-12, .atol = 1e-14,
                     .q0 = h->f->q0, .qd0 = h->f->qd0};
    assert_int_equal(qd_sweep_run(h->f->ctx, h->w, &o, 0, NRUNS, 1, h->rows, h->outcome, NULL,
                                  NULL),
                     QD_OK);
    h->outcome[1] = (qd_sweep_outcome){QD_ERR_NUMERIC, {QD_STOP_STEP_UNDERFLOW, 0.25, NAN}};
    for (size_t j = qd_sweep_ninputs(h->w); j < h->ncols; j++)
        h->rows[1 * h->ncols + j] = NAN;
    return h;
}

static void h5_fix_free(h5_fix *h) {
    qd_sweep_free(h->w);
    sf_free(h->f);
    free(h->rows);
    free(h);
}

#ifdef QDOT_HAVE_HDF5
#include <hdf5.h>

static char *tmp_path(const char *leaf) {
    static char path[256];
    const char *dir = getenv("TMPDIR");
    snprintf(path, sizeof path, "%s/qdot_test_%ld_%s", dir ? dir : "/tmp", (long)getpid(), leaf);
    return path;
}

static const char *const attr_names[3] = {"model", "grid", "measures"};
static const char *const attr_values[3] = {"examples/oscillator.qd", "x=0.1:0.3:3",
                                           "final, energy_error"};

/* The scalar string attribute name of obj, into out. */
static void read_string_attr(hid_t obj, const char *name, char *out, size_t cap) {
    hid_t a = H5Aopen(obj, name, H5P_DEFAULT);
    assert_true(a >= 0);
    hid_t t = H5Tcopy(H5T_C_S1);
    H5Tset_size(t, H5T_VARIABLE);
    char *s = NULL;
    assert_true(H5Aread(a, t, &s) >= 0);
    snprintf(out, cap, "%s", s);
    H5free_memory(s);
    H5Tclose(t);
    H5Aclose(a);
}

static void check_runs(hid_t f, const h5_fix *h) {
    size_t NCOLS = h->ncols;
    const double *rows = h->rows;
    hid_t d = H5Dopen2(f, "runs", H5P_DEFAULT);
    assert_true(d >= 0);
    hid_t sp = H5Dget_space(d);
    hsize_t dims[2];
    assert_int_equal(H5Sget_simple_extent_ndims(sp), 2);
    H5Sget_simple_extent_dims(sp, dims, NULL);
    assert_int_equal(dims[0], NRUNS);
    assert_int_equal(dims[1], NCOLS);
    double back[NRUNS * 16];
    assert_true(NCOLS <= 16);
    assert_true(H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, back) >= 0);
    for (size_t k = 0; k < NRUNS * NCOLS; k++)
        if (isnan(rows[k]))
            assert_true(isnan(back[k]));
        else
            assert_memory_equal(&back[k], &rows[k], sizeof(double)); /* bit for bit */
    hid_t a = H5Aopen(d, "columns", H5P_DEFAULT);
    hid_t t = H5Tcopy(H5T_C_S1);
    H5Tset_size(t, H5T_VARIABLE);
    char *cols[16];
    assert_true(H5Aread(a, t, cols) >= 0);
    for (size_t j = 0; j < NCOLS; j++) {
        assert_string_equal(cols[j], qd_sweep_col(h->w, j));
        H5free_memory(cols[j]);
    }
    H5Tclose(t);
    H5Aclose(a);
    H5Sclose(sp);
    H5Dclose(d);
}

static void check_status(hid_t f, const h5_fix *h) {
    hid_t d = H5Dopen2(f, "status", H5P_DEFAULT);
    assert_true(d >= 0);
    int st[NRUNS];
    assert_true(H5Dread(d, H5T_NATIVE_INT, H5S_ALL, H5S_ALL, H5P_DEFAULT, st) >= 0);
    for (size_t i = 0; i < NRUNS; i++)
        assert_int_equal(st[i], (int)h->outcome[i].status);
    H5Dclose(d);
    d = H5Dopen2(f, "reason", H5P_DEFAULT);
    assert_true(d >= 0);
    hid_t t = H5Tcopy(H5T_C_S1);
    H5Tset_size(t, H5T_VARIABLE);
    char *why[NRUNS];
    assert_true(H5Dread(d, t, H5S_ALL, H5S_ALL, H5P_DEFAULT, why) >= 0);
    assert_string_equal(why[0], "");
    assert_string_equal(why[1], "step size underflow at t = 0.25");
    assert_string_equal(why[2], "");
    for (size_t i = 0; i < NRUNS; i++)
        H5free_memory(why[i]);
    H5Tclose(t);
    H5Dclose(d);
}

static void test_round_trip(void **state) {
    (void)state;
    h5_fix *h = h5_fix_new(true);
    assert_true(h->ncols >= 3); /* x, then final's state and energy_error */
    assert_int_equal(qd_sweep_hdf5_ready(h->f->ctx), QD_OK);
    const char *path = tmp_path("round.h5");
    assert_int_equal(qd_sweep_hdf5(h->f->ctx, h->w, h->rows, h->outcome, 3, attr_names,
                                   attr_values, path),
                     QD_OK);
    hid_t f = H5Fopen(path, H5F_ACC_RDONLY, H5P_DEFAULT);
    assert_true(f >= 0);
    check_runs(f, h);
    check_status(f, h);
    char text[128];
    for (size_t k = 0; k < 3; k++) {
        read_string_attr(f, attr_names[k], text, sizeof text);
        assert_string_equal(text, attr_values[k]);
    }
    read_string_attr(f, "qdot_version", text, sizeof text);
    assert_string_equal(text, QDOT_VERSION);
    H5Fclose(f);
    remove(path);
    h5_fix_free(h);
}

/* qd_sweep_hdf5_made: the attributes say how the sweep was made (a random
 * draw: its spec, n and the seed as a whole number of 64 bits). */
static void test_made(void **state) {
    (void)state;
    h5_fix *h = h5_fix_new(true);
    const char *path = tmp_path("made.h5");
    qd_sweep_result r = {.nruns = NRUNS, .ncols = h->ncols, .rows = h->rows,
                         .outcome = h->outcome};
    qd_sweep_spec sp = {.random = "x=0.1:0.3", .n = 3, .seed = 18446744073709551615u,
                        .measures = "final, energy_error"};
    assert_int_equal(qd_sweep_hdf5_made(h->f->ctx, h->w, &r, &sp, "osc.qd", NULL, path), QD_OK);
    hid_t f = H5Fopen(path, H5F_ACC_RDONLY, H5P_DEFAULT);
    assert_true(f >= 0);
    check_runs(f, h);
    const char *names[] = {"model", "measures", "random", "n", "seed"};
    const char *values[] = {"osc.qd", "final, energy_error", "x=0.1:0.3", "3",
                            "18446744073709551615"};
    char text[128];
    for (size_t k = 0; k < 5; k++) {
        read_string_attr(f, names[k], text, sizeof text);
        assert_string_equal(text, values[k]);
    }
    H5Fclose(f);
    remove(path);
    h5_fix_free(h);
}

/* A sweep of no runs still makes a readable file of 0 rows. */
static void test_no_runs(void **state) {
    (void)state;
    h5_fix *h = h5_fix_new(false);
    assert_int_equal(qd_sweep_nruns(h->w), 0);
    const char *path = tmp_path("empty.h5");
    assert_int_equal(qd_sweep_hdf5(h->f->ctx, h->w, h->rows, h->outcome, 0, NULL, NULL, path),
                     QD_OK);
    hid_t f = H5Fopen(path, H5F_ACC_RDONLY, H5P_DEFAULT);
    hid_t d = H5Dopen2(f, "runs", H5P_DEFAULT);
    hsize_t dims[2] = {99, 99};
    hid_t sp = H5Dget_space(d);
    H5Sget_simple_extent_dims(sp, dims, NULL);
    assert_int_equal(dims[0], 0);
    assert_int_equal(dims[1], h->ncols);
    H5Sclose(sp);
    H5Dclose(d);
    H5Fclose(f);
    remove(path);
    h5_fix_free(h);
}

/* The disk's refusal is an I/O error naming the file; a directory too. */
static void test_unwritable(void **state) {
    (void)state;
    h5_fix *h = h5_fix_new(true);
    assert_int_equal(qd_sweep_hdf5(h->f->ctx, h->w, h->rows, h->outcome, 0, NULL, NULL,
                                   "/nonexistent-dir/x.h5"),
                     QD_ERR_IO);
    assert_non_null(strstr(qd_ctx_message(h->f->ctx), "/nonexistent-dir/x.h5"));
    qd_ctx_clear_error(h->f->ctx);
    assert_int_equal(qd_sweep_hdf5(h->f->ctx, h->w, h->rows, h->outcome, 0, NULL, NULL, "/tmp"),
                     QD_ERR_IO);
    assert_non_null(strstr(qd_ctx_message(h->f->ctx), "is a directory"));
    h5_fix_free(h);
}

/* ---- --dump FILE.h5 ---- */

static char **read_strings(hid_t obj, bool attr, size_t n) {
    char **v = calloc(n ? n : 1, sizeof *v);
    hid_t t = H5Tcopy(H5T_C_S1);
    H5Tset_size(t, H5T_VARIABLE);
    herr_t e = attr ? H5Aread(obj, t, v) : H5Dread(obj, t, H5S_ALL, H5S_ALL, H5P_DEFAULT, v);
    H5Tclose(t);
    return e < 0 ? NULL : v;
}

static void free_strings(char **v, size_t n) {
    for (size_t k = 0; v && k < n; k++)
        H5free_memory(v[k]);
    free(v);
}

static int dump(const char *path) {
    hid_t f = H5Fopen(path, H5F_ACC_RDONLY, H5P_DEFAULT);
    hid_t d = f >= 0 ? H5Dopen2(f, "runs", H5P_DEFAULT) : -1;
    if (d < 0)
        return fprintf(stderr, "cannot read %s\n", path), 1;
    hsize_t dims[2];
    hid_t sp = H5Dget_space(d);
    H5Sget_simple_extent_dims(sp, dims, NULL);
    H5Sclose(sp);
    size_t nr = dims[0], nc = dims[1];
    double *v = malloc((nr * nc + 1) * sizeof *v);
    int *st = malloc((nr + 1) * sizeof *st);
    H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v);
    hid_t a = H5Aopen(d, "columns", H5P_DEFAULT);
    char **cols = read_strings(a, true, nc);
    H5Aclose(a);
    H5Dclose(d);
    d = H5Dopen2(f, "status", H5P_DEFAULT);
    H5Dread(d, H5T_NATIVE_INT, H5S_ALL, H5S_ALL, H5P_DEFAULT, st);
    H5Dclose(d);
    d = H5Dopen2(f, "reason", H5P_DEFAULT);
    char **why = read_strings(d, false, nr);
    H5Dclose(d);
    for (size_t j = 0; j < nc; j++)
        printf("%s\t", cols[j]);
    printf("status\treason\n");
    for (size_t i = 0; i < nr; i++) {
        for (size_t j = 0; j < nc; j++)
            printf("%.17g\t", v[i * nc + j]);
        printf("%d\t%s\n", st[i], why[i]);
    }
    free_strings(cols, nc);
    free_strings(why, nr);
    free(v);
    free(st);
    H5Fclose(f);
    return 0;
}

int main(int argc, char **argv) {
    if (argc == 3 && !strcmp(argv[1], "--dump"))
        return dump(argv[2]);
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_round_trip),
        cmocka_unit_test(test_made),
        cmocka_unit_test(test_no_runs),
        cmocka_unit_test(test_unwritable),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

#else

int main(void) {
    /* --dump has nothing to read with: the CLI check skips on its own */
    h5_fix *h = h5_fix_new(true);
    qd_status ready = qd_sweep_hdf5_ready(h->f->ctx);
    qd_ctx_clear_error(h->f->ctx);
    qd_status st = qd_sweep_hdf5(h->f->ctx, h->w, h->rows, h->outcome, 0, NULL, NULL, "x.h5");
    bool says = strstr(qd_ctx_message(h->f->ctx), "without HDF5") != NULL;
    h5_fix_free(h);
    if (ready != QD_ERR_UNSUPPORTED || st != QD_ERR_UNSUPPORTED || !says) {
        fprintf(stderr, "qd_sweep_hdf5 claims HDF5 in a build without it\n");
        return 1;
    }
    printf("skipped: qdot was built without HDF5 (libhdf5-dev not found)\n");
    return 77; /* ctest: skipped (SKIP_RETURN_CODE in tests/CMakeLists.txt) */
}

#endif

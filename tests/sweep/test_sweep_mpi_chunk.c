/*
 * tests/sweep/test_sweep_mpi_chunk.c - how rank 0 of `mpirun qdot sweep`
 * sizes the chunks it deals (qd_sweep_mpi_chunk, src/sweep/mpi.c):
 * dealt one after another they cover every run exactly once, shrink, stay
 * at least one run per thread (but the last), and their number stays near
 * the 4P (ln(R/4P) + 1) that docs/design.md ("Expected scaling") counts
 * the messages by; and which environments say a launcher started us.
 */
#define _POSIX_C_SOURCE 200809L /* setenv */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdlib.h>

#include "qdot/sweep.h"

/* Deal R runs to P ranks of T threads; returns the number of chunks. */
static size_t deal(size_t R, int P, unsigned T) {
    size_t left = R, n = 0, prev = (size_t)-1;
    while (left > 0) {
        size_t c = qd_sweep_mpi_chunk(left, P, T);
        assert_true(c >= 1 && c <= left);
        assert_true(c <= prev);                 /* never grows */
        assert_true(c >= T || c == left);       /* a run per thread, but the last */
        assert_true(c <= 65536);
        prev = c;
        left -= c;
        n++;
    }
    assert_int_equal(qd_sweep_mpi_chunk(0, P, T), 0); /* nothing left: "stop" */
    return n;
}

static void test_cover_and_count(void **state) {
    (void)state;
    static const struct { size_t R; int P; } cases[] = {
        {1, 2}, {7, 2}, {400, 2}, {400, 8}, {100000, 64}, {1000000, 256}};
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        size_t R = cases[k].R;
        int P = cases[k].P;
        size_t n = deal(R, P, 1);
        double model = 4.0 * P * (log((double)R / (4.0 * P)) + 1);
        if ((double)R > 4.0 * P)
            assert_true(fabs((double)n - model) <= 0.15 * model + 2);
        else
            assert_true(n == R); /* fewer runs than 4P: one at a time */
    }
}

/* Threads per rank set the least chunk: a rank of 8 threads gets 8 runs. */
static void test_threads(void **state) {
    (void)state;
    assert_int_equal(qd_sweep_mpi_chunk(20, 4, 8), 8);
    assert_int_equal(qd_sweep_mpi_chunk(5, 4, 8), 5);
    assert_int_equal(qd_sweep_mpi_chunk(400, 2, 1), 50);
    deal(1000, 3, 4);
}

/* A chunk never exceeds 65536 runs: huge sweeps still send small messages. */
static void test_cap(void **state) {
    (void)state;
    assert_int_equal(qd_sweep_mpi_chunk((size_t)1 << 32, 2, 1), 65536);
}

static void test_launched(void **state) {
    (void)state;
    /* ctest runs the test plainly: no launcher's variables in sight */
    assert_false(qd_sweep_mpi_launched());
    /* OpenMPI's mpirun, then srun (PMI-2) */
    static const char *const vars[] = {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"};
    for (size_t k = 0; k < 2; k++) {
        setenv(vars[k], "2", 1);
        assert_true(qd_sweep_mpi_launched());
        unsetenv(vars[k]);
        assert_false(qd_sweep_mpi_launched());
    }
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_cover_and_count),
        cmocka_unit_test(test_threads),
        cmocka_unit_test(test_cap),
        cmocka_unit_test(test_launched),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

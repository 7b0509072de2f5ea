/*
 * cli/sweep_hdf5.h - qdot sweep --format hdf5: the rows of a sweep in one
 * HDF5 file, for sweeps too large for CSV (issue 21).
 *
 * The file holds
 *   /runs    nruns x ncols doubles, the CSV's rows (inputs, then measures;
 *            NaN where a measure has no value), in run order; its
 *            attribute "columns" names the columns (variable-length strings);
 *   /status  nruns ints: 0 for a run that went through, else the qd_status
 *            it failed with;
 *   /reason  nruns variable-length strings: why it failed ("" when it did not;
 *            qd_sweep_outcome_str);
 * and, on the root group, string attributes saying how the sweep was made
 * (the model file, the grid, random or list spec, the measures, qdot's
 * version).  Built only with HDF5 (QDOT_HAVE_HDF5).
 */
#ifndef QDOT_CLI_SWEEP_HDF5_H
#define QDOT_CLI_SWEEP_HDF5_H

#include <stdbool.h>
#include <stddef.h>
#include "qdot/sweep.h"

typedef struct cli_h5_sweep {
    size_t nruns, ncols;
    const char *const *names; /* ncols column names */
    const double *rows;       /* nruns rows of ncols */
    const qd_sweep_outcome *outcome; /* nruns: status, and reason worded from it */
    size_t nattrs;            /* root attributes: name = value */
    const char *const *attr_names;
    const char *const *attr_values;
} cli_h5_sweep;

/* Is HDF5 support built in? */
bool cli_hdf5_built(void);

/* Write s into path (replacing it).  False with a message in err (at most
 * errcap bytes) when the file cannot be made or written, or without HDF5. */
bool cli_hdf5_write_sweep(const char *path, const cli_h5_sweep *s, char *err, size_t errcap);

#endif

/*
 * src/linear/symmetry_method.c - which way the symmetry of small
 * oscillations is had (qd_symmetry_fast_cell, qdot/symmetry.h): the cyclic
 * fast path for a long ring of identical cells, else the group.
 */
#include "qdot/symmetry.h"
#include "../base/args.h"

size_t qd_symmetry_fast_cell(const qd_linear *lin) {
    QD_ARGS(0, lin);
    return lin->n >= QD_SYMMETRY_FAST_N ? qd_cyclic_cell(lin) : 0;
}

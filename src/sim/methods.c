/*
 * src/sim/methods.c - the integration methods by name and what they are.
 */
#include "simint.h"
#include "../base/args.h"

#include <string.h>

static const struct {
    const char *name;
    int order;
    bool adaptive;
} methods[QD_SIM_METHOD_COUNT] = {
    [QD_SIM_DOPRI5] = {"dopri5", 5, true},     [QD_SIM_DOP853] = {"dop853", 8, true},
    [QD_SIM_GL2] = {"gl2", 2, false},          [QD_SIM_GL4] = {"gl4", 4, false},
    [QD_SIM_GL6] = {"gl6", 6, false},          [QD_SIM_VERLET] = {"verlet", 2, false},
    [QD_SIM_YOSHIDA4] = {"yoshida4", 4, false}, [QD_SIM_YOSHIDA6] = {"yoshida6", 6, false},
    [QD_SIM_YOSHIDA8] = {"yoshida8", 8, false}, [QD_SIM_BDF] = {"bdf", 5, true},
    [QD_SIM_TAYLOR] = {"taylor", 20, true}, /* order from the tolerance: 20 at 1e-16 */
};

const char *qd_sim_method_name(qd_sim_method m) {
    return m < QD_SIM_METHOD_COUNT ? methods[m].name : "?";
}

bool qd_sim_method_from_name(const char *name, qd_sim_method *m) {
    QD_ARGS(false, name && m);
    for (int i = 0; i < QD_SIM_METHOD_COUNT; i++)
        if (!strcmp(name, methods[i].name)) {
            *m = (qd_sim_method)i;
            return true;
        }
    return false;
}

int qd_sim_method_order(qd_sim_method m) { return m < QD_SIM_METHOD_COUNT ? methods[m].order : 0; }

bool qd_sim_method_adaptive(qd_sim_method m) {
    return m < QD_SIM_METHOD_COUNT && methods[m].adaptive;
}

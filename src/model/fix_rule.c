/*
 * src/model/fix_rule.c - which derivations show the parameter values given
 * from outside (qd_model_opts, the command line's --set) as numbers in their
 * formulas (qd_model_opts_for, qdot/model.h).
 *
 * One table, so that the program and the Python package cannot disagree:
 * a derivation whose result is formulas to read fixes the values into them
 * (`qdot hamiltonian --set k=5` prints 5*x^2/2); one whose result is numbers
 * or code keeps the parameters symbols holding the values, so generated code
 * stays adjustable and a run may change them later (qd_model_set_param).
 */
#include "qdot/model.h"

#include <stddef.h>
#include <string.h>

static const struct {
    const char *name;
    bool fix;
} rule[] = {
    /* formulas to read */
    {"eom", true},        {"hamiltonian", true}, {"routh", true},     {"integrals", true},
    {"hj", true},         {"metric", true},      {"bracket", true},   {"canonical", true},
    {"scatter", true},    {"field", true},
    /* numbers, or code with adjustable parameters */
    {"action", false},    {"action_of", false},  {"codegen", false},  {"impulse", false},
    {"linearize", false}, {"orbit", false},      {"path", false},     {"stability", false},
    {"equilibria", false}, {"modes", false},     {"lqr", false},      {"zvc", false},
    {"check", false},     {"simulate", false},   {"poincare", false}, {"sweep", false},
    {"lyapunov", false},  {"animate", false},
};

qd_status qd_model_opts_for(qd_model_opts *opts, const char *derivation) {
    if (!opts || !derivation)
        return QD_ERR_ARG;
    for (size_t i = 0; i < sizeof rule / sizeof rule[0]; i++)
        if (!strcmp(rule[i].name, derivation)) {
            opts->fix_params = rule[i].fix;
            return QD_OK;
        }
    return QD_ERR_ARG;
}

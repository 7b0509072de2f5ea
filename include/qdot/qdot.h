/*
 * qdot/qdot.h - everything of libqdot in one include.
 */
#ifndef QDOT_QDOT_H
#define QDOT_QDOT_H

#include "status.h"
#include "expr.h"
#include "print.h"
#include "read.h"
#include "eval.h"
#include "model.h"
#include "state.h"       /* issue 31: states and their reader */
#include "mech.h"
#include "certify.h"     /* issue 33: certified zero tests */
#include "canonical.h"
#include "hamilton.h"
#include "integrals.h"
#include "impulse.h"
#include "hj.h"
#include "sim.h"
#include "codegen.h"
#include "equilibria.h"
#include "modes.h"
#include "linpoint.h"     /* issue 31: the point of a linear analysis */
#include "routh.h"
#include "stability.h"
#include "control.h"
#include "contour.h"
#include "zvc.h"
#include "speeds.h"
#include "path.h"
#include "scatter.h"
#include "plot.h"
#include "sweep.h"
#include "lyapunov.h"
#include "scene.h"
#include "metric.h"
#include "symmetry.h"   /* issue 19: symmetry-adapted modes */
#include "relativity.h" /* issue 35: Lorentz kinematics, collisions */
#include "form.h"       /* issue 35: quadratic forms */
#include "field.h"      /* issue 35: continuous systems */
#include "action.h"
#include "orbit.h"
#include "statespace.h"
#include "constrained.h"
#include "tangent.h"      /* issue 37: forward-mode Jacobians of compiled programs */
#include "conlin.h"       /* issue 37: linearization of constrained systems */
#include "scanplot.h"     /* issue 37: a scan's eigenvalues drawn */
#include "json.h"
#include "simsetup.h"
#include "render.h"     /* issue 31: printers of whole results */

#include "version.h"    /* QDOT_VERSION, qd_version() */

#endif

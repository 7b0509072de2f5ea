# python/qdot/__init__.py - the qdot package: libqdot's public C API from
# Python (docs/python.md).
"""qdot: Lagrangian and Hamiltonian mechanics from a model text.

    import qdot
    m = qdot.Model.load("examples/double_pendulum.qd")
    m.eom().M                      # the mass matrix, as text
    m.modes()[0].omega             # the slow normal mode
    r = m.simulate(10, rtol=1e-10)
    r.t, r["theta1"], r.energy_error_max

The package is a binding over libqdot (cffi, declarations made from the C
headers): every result is computed by the C library.  The library is found
through QDOT_LIB, the build tree next to the package, the installed prefix,
then the system's library path.
"""

from ._core import Error, ArgumentError, ModelError, NumericalError
from .commands import Output, Fields
from .model import Model, Equations, Hamiltonian, Equilibrium, Equilibria, Mode, Modes, Metric
from .sim import Result, Table, Rhs
from .runs import Animation
from .control import StateSpace, Lqr, lqr
from .relativity import lorentz, proper_time, collide
from .forms import (Homogeneity, Periods, QuadraticForm, homogeneity, periods, quadratic_form,
                    tour)
from .field import Field
from .appendix import (GramSchmidt, gram_schmidt, ChangeOfVariables, change_of_variables,
                       condensed, fourier)
from .kernel import Expr, Code, parse, diff, expand, simplify, print_expr
from ._progress import set_progress

__all__ = ["Model", "ModelError", "NumericalError", "Error", "ArgumentError", "Output", "Fields",
           "Equations", "Hamiltonian", "Equilibrium", "Equilibria", "Metric",
           "Mode", "Modes", "Result", "Table", "Rhs", "Animation", "StateSpace", "Lqr", "lqr",
           "lorentz", "proper_time", "collide", "QuadraticForm", "quadratic_form", "Homogeneity",
           "homogeneity", "Periods", "periods", "tour", "Field",
           "Expr", "Code", "parse", "diff", "expand", "simplify", "print_expr", "set_progress",
           "GramSchmidt", "gram_schmidt", "ChangeOfVariables", "change_of_variables",
           "condensed", "fourier"]
from ._lib import VERSION as __version__

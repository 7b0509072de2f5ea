# python/tests/test_output_sympy.py - Output.sympy(KEY): a command's formulas
# as SymPy values, read and printed by the library (qd_read, QD_FMT_SYMPY);
# checked against the textbook formulas built here in SymPy: the
# oscillator's H = p^2/(2m) + k x^2/2 and Kepler's effective potential
# -k/r + p^2/(2 m r^2) (Goldstein eqs. 8.17, 3.22); and the Jupyter LaTeX of
# the equations of motion.
import os

import pytest

import qdot

from conftest import EXAMPLES
from test_commands import OSCILLATOR

sp = pytest.importorskip("sympy")


def test_hamiltonian_sympy():
    m = qdot.Model(OSCILLATOR)
    out = m.hamiltonian().output
    H = out.sympy("H")
    x = sp.Function("x")(sp.Symbol("t"))
    p, mass, k = sp.symbols("p_x m k")
    assert sp.simplify(H - (p**2 / (2 * mass) + k * x**2 / 2)) == 0
    assert sp.simplify(out.sympy("dp_dt")[0] + k * x) == 0
    assert out.sympy("H_is_energy") is True                   # not a formula: as given
    fixed = m.set(k=5).hamiltonian().output.sympy("H")       # the set value fixed in
    assert sp.simplify(fixed - (p**2 / (2 * mass) + 5 * x**2 / 2)) == 0


def test_routh_sympy():
    r = qdot.Model.load(os.path.join(EXAMPLES, "kepler_polar.qd")).routh("theta")
    V = r.sympy("effective_potential")
    rr = sp.Function("r")(sp.Symbol("t"))
    p, mass, k = sp.symbols("p_theta m k")
    assert sp.simplify(V - (-k / rr + p**2 / (2 * mass * rr**2))) == 0


def test_eom_latex_for_jupyter():
    e = qdot.Model(OSCILLATOR).eom()
    tex = e._repr_latex_()
    assert tex.startswith("$$\\begin{aligned}") and tex.endswith("\\end{aligned}$$")
    assert "\\ddot{x}" in tex

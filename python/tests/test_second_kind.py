"""Model.hamiltonian(second_kind=True): Hamilton's equations of the second
kind (Desloge vol. 2 ch. 72 Thm 1, seed 000; seed-desloge-C.md C10, T17),
checked against the chapter's Example 1 and SymPy."""
import os

import pytest
import sympy as sp
import qdot

from conftest import EXAMPLES

RESISTED = ("coordinates x\nparameters m = 2, k = 3, alpha = 0.5\nT = m/2*x'^2\n"
            "V = k/2*x^2\ndissipation = alpha/2*x'^2\n")


def test_example1_sympy():
    # Ex. 1 eqs. 25, 29-30: K = s^2/(2m), x' = s/m, s' = -k x - alpha s/m
    h = qdot.Model(RESISTED).hamiltonian(second_kind=True, sympy=True)
    m, k, a, s = sp.symbols("m k alpha s_x")
    x = sp.Function("x")(sp.Symbol("t"))  # coordinates are functions of t, as in eom
    assert sp.simplify(h.H - s**2 / (2 * m)) == 0
    assert sp.simplify(h.dq[0] - s / m) == 0
    assert sp.simplify(h.dp[0] - (-k * x - a * s / m)) == 0
    assert h.momenta == ["s_x"] and h.is_energy and h.s_is_p and not h.conserved


def test_at_point():
    # s' at x = 0.5, s = 4 (x' = 2): -k x - alpha x' = -1.5 - 1
    h = qdot.Model(RESISTED).hamiltonian(second_kind=True, at={"x": 0.5, "s_x": 4})
    assert h.output.ds_dt[0] == pytest.approx(-2.5, abs=1e-14)
    assert h.output.K == pytest.approx(4.0, abs=1e-14)


def test_lorentz_force():
    # U = q phi - q A.v: Q = q (E + v x B) and s = m v, not p (eq. 6)
    h = qdot.Model.load(os.path.join(EXAMPLES, "charged_particle_EB.qd")).hamiltonian(
        second_kind=True, sympy=True)
    assert not h.s_is_p
    m, q, Ex, Ey, Ez, Bx, By, Bz, sx, sy, sz = sp.symbols("m q Ex Ey Ez Bx By Bz s_x s_y s_z")
    F = q * (sp.Matrix([Ex, Ey, Ez]) + (sp.Matrix([sx, sy, sz]) / m).cross(
        sp.Matrix([Bx, By, Bz])))
    for k in range(3):
        assert sp.simplify(h.dp[k] - F[k]) == 0


def test_needs_T():
    with pytest.raises(qdot.ModelError, match="built from the kinetic energy T"):
        qdot.Model("coordinates x\nL = x'^2/2 - x^2/2\n").hamiltonian(second_kind=True)

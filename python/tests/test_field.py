# python/tests/test_field.py - qdot.Field: a field model's equation and
# normal modes (qdot/field.h), against the seed's results and the CLI's JSON.
# Physics: the stretched string fixed at both ends (Desloge ch. 83 Problem 4,
# seed-desloge-D.md) has rho y_tt - tau y_xx = 0 and omega_n = (n pi/l)
# sqrt(tau/rho), shapes sin(n pi x/l); the hanging chain (tau = rho g x, x up
# from the free end) has omega_n = (j_0n/2) sqrt(g/l), j_0n the zeros of
# Bessel's J0 (Abramowitz & Stegun table 9.5).
import math
import os

import pytest
import sympy as sp

import qdot

from conftest import EXAMPLES
from test_commands import cli, same

J0_ZEROS = [2.404825557695773, 5.520078110286311, 8.653727912911013]


def test_string_equation_and_exact_modes():
    path = os.path.join(EXAMPLES, "string.qd")
    f = qdot.Field.load(path)
    eq = f.eom()
    rho, tau, y_tt, y_xx = sp.symbols("rho tau y_tt y_xx")
    assert sp.simplify(sp.sympify(eq.equation) - (rho * y_tt - tau * y_xx)) == 0
    assert eq.boundary == ["fixed", "fixed"] and list(eq.interval) == [0, 0.5]
    m = f.modes(3)
    rho_v, tau_v, l_v = 0.01, 100, 0.5
    want = [n * math.pi / l_v * math.sqrt(tau_v / rho_v) for n in (1, 2, 3)]
    assert m.method == "exact"
    assert [md["omega"] for md in m.modes] == pytest.approx(want, rel=1e-14)
    assert [md["error"] for md in m.modes] == [0, 0, 0]
    same(m.json, cli("modes", path, "--count", "3"))
    same(eq.json, cli("eom", path))
    # params as --set: four times the tension doubles every frequency
    m4 = qdot.Field.load(path, params={"tau": 400}).modes(1)
    assert m4.modes[0]["omega"] == pytest.approx(2 * want[0], rel=1e-14)


def test_hanging_chain_converged_modes():
    f = qdot.Field.load(os.path.join(EXAMPLES, "hanging_chain.qd"))
    m = f.modes(3)
    g, l = 9.81, 2
    assert m.method == "finite elements" and m.converged
    for md, j in zip(m.modes, J0_ZEROS):
        exact = j / 2 * math.sqrt(g / l)
        assert abs(md["omega"] - exact) < max(md["error"], 1e-12) * 10
        assert abs(md["omega"] - exact) < 1e-6 * exact
    with pytest.warns(UserWarning, match="did not converge"):
        assert not f.modes(3, tol=1e-15).converged


def test_field_errors():
    with pytest.raises(qdot.ModelError, match="no Lagrangian density"):
        qdot.Field("field y(x, t) on x = 0 .. 1\n")
    bad = qdot.Field("field y(x, t) on x = 0 .. 1\nLdensity = y_t^4 - y_x^2\n"
                     "boundary y(0) = 0, y(1) = 0\n")
    with pytest.raises(qdot.ModelError, match="not quadratic") as err:
        bad.modes()
    assert err.value.line == 2
    with pytest.raises(ValueError):
        qdot.Field.load(os.path.join(EXAMPLES, "string.qd")).modes(0)
    with pytest.raises(TypeError):
        qdot.Field(3)

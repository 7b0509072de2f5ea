# python/tests/test_modes.py - equilibria and normal modes of the double
# pendulum (examples/double_pendulum.qd; Goldstein ch. 1 Ex. 22 for the
# model, seed 002_3e07e211eebc00b9.txt) against the closed form of
# det(K - w^2 M) = 0 about the hanging state:
#   m1 l1 l2 w^4 - (m1 + m2) g (l1 + l2) w^2 + (m1 + m2) g^2 = 0.
import math
import os

import numpy as np
import pytest

import qdot
from conftest import EXAMPLES


def closed_form(m1, m2, l1, l2, g):
    a, b, c = m1 * l1 * l2, -(m1 + m2) * g * (l1 + l2), (m1 + m2) * g * g
    d = math.sqrt(b * b - 4 * a * c)
    return (-b - d) / (2 * a), (-b + d) / (2 * a)


@pytest.fixture
def model():
    return qdot.Model.load(os.path.join(EXAMPLES, "double_pendulum.qd"))


def test_equilibria_are_the_four_hanging_and_inverted_states(model):
    eq = model.equilibria()
    kinds = {(round(e.q["theta1"], 12), round(e.q["theta2"], 12)): e.kind for e in eq}
    pi = round(math.pi, 12)
    assert kinds == {(0, 0): "minimum", (0, pi): "saddle", (pi, 0): "saddle",
                     (pi, pi): "maximum"}
    assert all(e.exact is not None and e.residual < 1e-12 for e in eq)


@pytest.mark.parametrize("params", [{}, {"m1": 2, "m2": 0.5, "l1": 1.5, "l2": 0.7, "g": 3}])
def test_modes_against_closed_form(model, params):
    model.set(**params)
    p = model.params
    modes = model.modes()
    w2 = closed_form(p["m1"], p["m2"], p["l1"], p["l2"], p["g"])
    assert modes.about == {"theta1": 0.0, "theta2": 0.0}
    assert [mo.omega2 for mo in modes] == pytest.approx(w2, rel=1e-12)
    assert [mo.omega for mo in modes] == pytest.approx([math.sqrt(x) for x in w2], rel=1e-12)
    M = np.array([[(p["m1"] + p["m2"]) * p["l1"] ** 2, p["m2"] * p["l1"] * p["l2"]],
                  [p["m2"] * p["l1"] * p["l2"], p["m2"] * p["l2"] ** 2]])
    K = np.diag([(p["m1"] + p["m2"]) * p["g"] * p["l1"], p["m2"] * p["g"] * p["l2"]])
    for mo in modes:
        a = np.array([mo.shape["theta1"], mo.shape["theta2"]])
        assert np.allclose(K @ a, mo.omega2 * (M @ a), rtol=1e-10, atol=1e-12)
        assert a @ M @ a == pytest.approx(1, rel=1e-12)
    # the slow mode swings both rods the same way, the fast one against
    slow, fast = modes
    assert slow.shape["theta1"] * slow.shape["theta2"] > 0
    assert fast.shape["theta1"] * fast.shape["theta2"] < 0
    assert modes.conservative and modes.stable == 1


def test_modes_about_inverted_state_are_unstable(model):
    top = model.modes(about={"theta1": math.pi, "theta2": math.pi})
    # about the top every stiffness changes sign: w^2 -> -w^2 of the bottom
    bottom = model.modes()
    assert sorted(mo.omega2 for mo in top) == pytest.approx(
        sorted(-mo.omega2 for mo in bottom), rel=1e-12)
    assert top.stable == 0 and all(math.isnan(mo.omega) for mo in top)
    # a name that is not a coordinate: the library's reader, shown in the text as --about
    with pytest.raises(qdot.ModelError, match="unknown name 'phi'") as err:
        model.modes(about={"phi": 0})
    assert (err.value.file, err.value.line, err.value.col) == ("about", 1, 1)


def test_damped_modes_have_state_space_eigenvalues():
    # x'' + 2 z w x' + w^2 x = 0: s = -z w +- i w sqrt(1 - z^2)
    m = qdot.Model("coordinates x\nparameters m = 2, k = 8, c = 0.8\n"
                   "T = m/2*x'^2\nV = k/2*x^2\ndissipation = c/2*x'^2\n")
    modes = m.modes()
    w, z = 2.0, 0.8 / (2 * math.sqrt(2 * 8))
    assert not modes.conservative and len(modes) == 0
    s = sorted(modes.eigenvalues, key=lambda x: x.imag)
    assert s[1].real == pytest.approx(-z * w, rel=1e-12)
    assert s[1].imag == pytest.approx(w * math.sqrt(1 - z * z), rel=1e-12)
    assert modes.stable == 1

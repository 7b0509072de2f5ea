# python/tests/test_compile.py - Model.compile()'s right-hand side, driven
# by a plain classical RK4 written here, reaches the state qdot's own
# simulate reaches; and it is M^-1 f of the equations at a state.
import os

import numpy as np
import pytest

import qdot
from conftest import EXAMPLES


def rk4(rhs, t0, y0, t1, steps):
    """The classical fourth-order Runge-Kutta method with a fixed step."""
    h = (t1 - t0) / steps
    t, y = t0, np.array(y0, dtype=float)
    for _ in range(steps):
        k1 = rhs(t, y)
        k2 = rhs(t + h / 2, y + h / 2 * k1)
        k3 = rhs(t + h / 2, y + h / 2 * k2)
        k4 = rhs(t + h, y + h * k3)
        y = y + h / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
        t += h
    return y


@pytest.fixture
def model():
    return qdot.Model.load(os.path.join(EXAMPLES, "double_pendulum.qd")).set(m2=0.7, l2=0.6)


def test_rk4_on_compiled_rhs_matches_simulate(model):
    rhs = model.compile()
    assert rhs.coordinates == ["theta1", "theta2"]
    assert rhs.params["m2"] == 0.7
    y0 = [1.0, -0.5, 0.2, 0.0]
    y = {}
    for steps in (1000, 2000):
        y[steps] = rk4(rhs, 0.0, y0, 2.0, steps)
    r = model.simulate(2.0, rtol=1e-13, atol=1e-14, initial={
        "theta1": 1.0, "theta2": -0.5, "theta1'": 0.2, "theta2'": 0.0})
    ref = np.array([r[c][-1] for c in ("theta1", "theta2", "theta1'", "theta2'")])
    err1, err2 = np.max(np.abs(y[1000] - ref)), np.max(np.abs(y[2000] - ref))
    # RK4 converges to simulate's answer at its order: halving h divides the
    # gap by about 2^4 = 16
    assert err2 < 1e-8
    assert 10 < err1 / err2 < 22


def test_rhs_is_mass_matrix_solve(model):
    rhs = model.compile()
    q1, q2, v1, v2 = 0.4, -1.1, 0.9, -0.3
    p = model.params
    m1, m2, l1, l2, g = p["m1"], p["m2"], p["l1"], p["l2"], p["g"]
    c, s = np.cos(q1 - q2), np.sin(q1 - q2)
    # Goldstein ch. 1 Ex. 22 (examples/double_pendulum.qd's header)
    M = np.array([[(m1 + m2) * l1 ** 2, m2 * l1 * l2 * c], [m2 * l1 * l2 * c, m2 * l2 ** 2]])
    f = np.array([-l1 * (m2 * l2 * v2 ** 2 * s + (m1 + m2) * g * np.sin(q1)),
                  -m2 * l2 * (g * np.sin(q2) - l1 * v1 ** 2 * s)])
    dy = rhs(0.0, [q1, q2, v1, v2])
    assert dy[:2] == pytest.approx([v1, v2], abs=0)
    assert dy[2:] == pytest.approx(np.linalg.solve(M, f), rel=1e-13)
    with pytest.raises(ValueError):
        rhs(0.0, [q1, q2])


def test_rhs_keeps_its_parameters_after_set(model):
    rhs = model.compile()
    before = rhs(0.0, [0.3, 0.0, 0.0, 0.0])
    model.set(g=1.62)  # the model moves on; the compiled rhs keeps its own
    assert np.array_equal(rhs(0.0, [0.3, 0.0, 0.0, 0.0]), before)
    moon = model.compile()(0.0, [0.3, 0.0, 0.0, 0.0])
    assert moon[2:] == pytest.approx(before[2:] * 1.62 / 9.81, rel=1e-12)

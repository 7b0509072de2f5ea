# python/tests/test_systems.py - the other kinds of model through the same
# API: one given by H (simulated by Hamilton's equations, momenta as
# columns) and one with a constraint (multipliers; examples/pendulum_cartesian.qd,
# Britannica (1911) Dynamics sec. 3 (28)-(30), seed 004_89e868a35cdf1de6.txt).
import math
import os

import numpy as np
import pytest

import qdot
from conftest import EXAMPLES

OSCILLATOR_H = ("coordinates x\nmomenta p\nparameters k = 4, m = 0.5\n"
                "H = p^2/(2*m) + k*x^2/2\ninitial x = 1\n")


def test_model_given_by_h_matches_closed_form():
    h = qdot.Model(OSCILLATOR_H)
    r = h.simulate(3, rtol=1e-12, initial={"p": 0.5})
    k, m = h.params["k"], h.params["m"]
    w = math.sqrt(k / m)
    # x = x0 cos wt + p0/(m w) sin wt, p = m x'
    assert np.allclose(r["x"], np.cos(w * r.t) + 0.5 / (m * w) * np.sin(w * r.t), atol=1e-9)
    assert np.allclose(r["p"], m * r["x'"], rtol=1e-12, atol=1e-12)
    assert r.energy_error_max < 1e-9
    with pytest.raises(qdot.Error, match="unknown name"):
        h.simulate(1, initial={"p_x": 1})


def test_constrained_pendulum_rhs_is_tangential_gravity():
    c = qdot.Model.load(os.path.join(EXAMPLES, "pendulum_cartesian.qd"))
    assert c.eom().constraints == ["rod"]
    rhs = c.compile()
    g, l = c.params["g"], c.params["l"]
    ang = 0.7
    pos = np.array([l * math.sin(ang), -l * math.cos(ang)])
    acc = rhs(0.0, np.r_[pos, 0.0, 0.0])[2:]
    # at rest the rod takes the normal part of gravity: a = g_t, |a| = g sin(angle)
    n = pos / l
    gravity = np.array([0.0, -g])
    assert acc == pytest.approx(gravity - (gravity @ n) * n, rel=1e-12, abs=1e-12)
    assert np.hypot(*acc) == pytest.approx(g * math.sin(ang), rel=1e-12)


def test_constrained_run_reports_its_residual():
    c = qdot.Model.load(os.path.join(EXAMPLES, "pendulum_cartesian.qd"))
    r = c.simulate(3, rtol=1e-10, dt=0.01)
    assert "res_rod" in r
    l = c.params["l"]
    assert np.max(np.abs(np.hypot(r["x"], r["y"]) - l)) < 1e-9
    assert r.stats["constraint_error_max"] < 1e-9


def test_chaplygin_sleigh_in_speeds_against_tanh_law():
    # Desloge ch. 69 thm 2 (seed 000; the model's header): u' = a w^2,
    # J w' = -m a u w, J = Ic + m a^2, so u = U tanh(m a U t / J + c),
    # U = sqrt(2E/m); integrated in the speeds (u, w) the model declares,
    # starting from its `initial u = 0.1, w = 1`.
    s = qdot.Model.load(os.path.join(EXAMPLES, "chaplygin_sleigh.qd"))
    r = s.simulate(20, rtol=1e-11, dt=0.1)
    assert {"u", "w"} <= set(r.columns)
    p = s.params
    m, a = p["m"], p["a"]
    J = p["Ic"] + m * a * a
    u0, w0 = r["u"][0], r["w"][0]
    assert (u0, w0) == (0.1, 1.0)
    U = math.sqrt((m * u0 ** 2 + J * w0 ** 2) / m)
    c = math.atanh(u0 / U)
    assert np.allclose(r["u"], U * np.tanh(m * a * U * r.t / J + c), rtol=1e-8, atol=1e-9)
    # the blade never slides sideways, and the kinematics x' = u cos(th)
    assert np.max(np.abs(-r["x'"] * np.sin(r["th"]) + r["y'"] * np.cos(r["th"]))) < 1e-12
    assert np.allclose(r["x'"], r["u"] * np.cos(r["th"]), atol=1e-12)
    # naming a velocity instead: the speeds follow from the velocities
    v = s.simulate(1, rtol=1e-10, initial={"th'": 0.5})
    assert (v["u"][0], v["w"][0]) == (0.0, 0.5)
    # the multiplier form takes velocities only (no speed columns)
    assert "u" not in s.simulate(1, rtol=1e-10, speeds=False)

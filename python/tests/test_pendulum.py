# python/tests/test_pendulum.py - the simple pendulum from Python: its
# large-amplitude period from simulate's events against the closed form
# T = 4 sqrt(l/g) K(sin(theta0/2)) (Goldstein ch. 3; Byerly Art. 5), and
# the energy the run reports conserved.
import math

import numpy as np
import pytest

import qdot

PENDULUM = """
coordinates theta
parameters m = 1, l = 2, g = 9.81
T = m/2*l^2*theta'^2
V = -m*g*l*cos(theta)
initial theta = 0.3, theta' = 0
"""


def ellipk(k):
    """K(k) by the arithmetic-geometric mean: K = pi / (2 AGM(1, sqrt(1 - k^2)))."""
    a, b = 1.0, math.sqrt(1 - k * k)
    for _ in range(40):  # quadratic convergence: 6 rounds reach round-off
        a, b = (a + b) / 2, math.sqrt(a * b)
    return math.pi / (2 * a)


@pytest.mark.parametrize("theta0", [0.3, 1.5, 2.8])
def test_period_against_elliptic_integral(theta0):
    m = qdot.Model(PENDULUM).set(l=1.3)
    r = m.simulate(12, rtol=1e-12, initial={"theta": theta0},
                   events=["theta = 0, theta' > 0"])
    t = r.events[0].t
    assert len(t) >= 2
    period = np.diff(t)
    l, g = m.params["l"], m.params["g"]
    exact = 4 * math.sqrt(l / g) * ellipk(math.sin(theta0 / 2))
    # located to round-off on a 1e-12 run: far tighter than the small-angle
    # formula 2 pi sqrt(l/g), which is 0.2% .. 60% off over these amplitudes
    assert np.max(np.abs(period - exact)) < 1e-8 * exact
    assert abs(2 * math.pi * math.sqrt(l / g) - exact) > 1e-3 * exact
    # at the crossing the velocity is the one energy conservation gives
    v = r.events[0]["theta'"]
    assert np.allclose(v, math.sqrt(2 * g / l * (1 - math.cos(theta0))), rtol=1e-9)


def test_energy_conserved_and_reported():
    m = qdot.Model(PENDULUM)
    r = m.simulate(20, method="gl4", dt=0.01, initial={"theta": 2.0})
    E = r["energy"]
    drift = np.max(np.abs(E - E[0])) / abs(E[0])
    # the symplectic method keeps E to O(dt^4); what it reports is what the
    # rows show (relative to max(|E0|, max T) >= |E0|)
    assert 0 < r.energy_error_max <= drift * (1 + 1e-12)
    assert r.energy_error_max < 1e-7
    assert r.stats["steps"] == 2000
    assert r.method == "gl4"
    # a cruder step shows a larger error: the number is measured, not fixed
    coarse = m.simulate(20, method="gl4", dt=0.1, initial={"theta": 2.0})
    assert coarse.energy_error_max > 100 * r.energy_error_max


def test_stop_at_and_outputs():
    m = qdot.Model(PENDULUM)
    r = m.simulate(10, rtol=1e-12, initial={"theta": "pi/2"}, stop_at="theta = 0",
                   outputs={"x": "l*sin(theta)"})
    # from rest at 90 degrees the bob reaches the bottom after a quarter period
    l, g = m.params["l"], m.params["g"]
    quarter = math.sqrt(l / g) * ellipk(math.sin(math.pi / 4))
    assert r.events[0].t[0] == pytest.approx(quarter, rel=1e-9)
    assert r.stats["t"] == pytest.approx(quarter, rel=1e-9)
    assert np.allclose(r["x"], l * np.sin(r["theta"]), atol=1e-14)


def test_stats_are_the_runs_counts():
    r = qdot.Model(PENDULUM).simulate(1, method="gl4", dt=0.125)
    assert set(r.stats) == {"steps", "evals", "rejected", "energy_error_max",
                            "constraint_error_max", "E0", "events", "t", "impacts",
                            "impact_energy_lost", "in_contact", "at_rest", "chattering",
                            "contact", "transitions", "friction_dissipated",
                            "energy_balance_error", "surface_work", "initial_moved_q",
                            "initial_moved_qd", "initial_solved", "events_unresolved", "events_unresolved_t",
                            "events_unresolved_spacing", "events_unresolved_event",
                            "energy_error_steps", "jit", "initial_solved", "stop"}
    assert r.stats["initial_solved"] == 0   # no constraint: no velocity solved at the start
    assert r.stop["reason"] == "reached the end time" and r.stop["t"] == 1.0
    assert r.stop["code"] == "end" and r.stop["ok"] is True
    # a fixed step: t_end/dt steps, none rejected, E0 = -m g l cos(theta0)
    assert (r.stats["steps"], r.stats["rejected"], r.stats["t"]) == (8, 0, 1.0)
    assert r.stats["E0"] == pytest.approx(-1 * 9.81 * 2 * math.cos(0.3), rel=1e-14)

"""Model.simulate(dt=H) is the output spacing of every method, step=H the
step of a fixed-step method (issue 33; the rule is libqdot's
qd_sim_setup_options, the same as `qdot simulate --dt/--step`).

The double pendulum of examples/double_pendulum.qd over 10 s: dt=0.2 alone
(and with rtol, refused before) is adaptive (dop853), its rows at 0.2 k
within 1e-7 of a dop853 run at rtol 1e-13; step=0.2 is gl4 with that step,
far off; step=0.01, dt=1 gives gl4's rows at spacing 1; every= (dt's older
name) the same rows.  The oscillator x'' = -x: dt=0.2 within 2e-9 of cos t.
"""
from pathlib import Path

import numpy as np
import pytest

import qdot

MODEL = (Path(__file__).resolve().parents[2] / "examples" / "double_pendulum.qd").read_text()


def test_dt_is_the_output_spacing():
    m = qdot.Model(MODEL)
    ref = m.simulate(10, method="dop853", rtol=1e-13, dt=0.2)
    r = m.simulate(10, dt=0.2)
    assert r.method == "dop853" and len(r) == 51
    assert np.allclose(r.t, 0.2 * np.arange(51), rtol=0, atol=1e-12)
    assert np.max(np.abs(r["theta1"] - ref["theta1"])) < 1e-7
    r2 = m.simulate(10, rtol=1e-10, dt=0.2)
    assert r2.method == "dop853" and np.array_equal(r2.data, r.data)
    r3 = m.simulate(10, rtol=1e-10, every=0.2)
    assert np.array_equal(r3.data, r.data)
    coarse = m.simulate(10, step=0.2)
    assert coarse.method == "gl4" and np.max(np.abs(coarse["theta1"] - ref["theta1"])) > 1e-3
    g = m.simulate(10, step=0.01, dt=1)
    assert g.method == "gl4" and g.stats["steps"] == 1000
    assert len(g) == 11 and np.max(np.abs(g["theta2"] - ref["theta2"][::5])) < 1e-5
    g2 = m.simulate(10, method="gl4", dt=0.01, every=1)
    assert np.array_equal(g2.data, g.data)
    with pytest.raises(qdot.Error, match="step"):
        m.simulate(10, step=0.2, rtol=1e-10)


def test_oscillator_rows_exact():
    osc = qdot.Model("coordinates x\nT = x'^2/2\nV = x^2/2\ninitial x = 1, x' = 0\n")
    r = osc.simulate(20, dt=0.2)
    assert r.method == "dop853" and len(r) == 101
    assert np.max(np.abs(r["x"] - np.cos(r.t))) < 2e-9


def test_energy_error_over_the_rows():
    """energy_error_max is the worst over the rows returned (dense output
    between the steps), energy_error_steps the integrator's own."""
    m = qdot.Model(MODEL)
    for kw in (dict(method="dop853", rtol=1e-9, dt=0.01), dict(method="dopri5", dt=0.01),
               dict(step=0.05, dt=0.01)):
        r = m.simulate(20, **kw)
        E = r["energy"]
        want = np.max(np.abs(E - E[0])) / abs(E[0])
        assert abs(r.energy_error_max - want) <= 1e-9 * want, (kw, r.energy_error_max, want)
        assert r.stats["energy_error_steps"] < r.energy_error_max

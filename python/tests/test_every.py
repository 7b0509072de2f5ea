"""Model.simulate(every=H): the output spacing apart from the step (issue 33).

The double pendulum of examples/double_pendulum.qd over 10 s: with rtol and
every=0.2 (no dt) the run is adaptive (dop853) and its rows lie at 0.2 k,
within 1e-7 of a dop853 run at rtol 1e-13; gl4 with the fixed step 0.01
and every=1 gives rows at spacing 1.
"""
from pathlib import Path

import numpy as np

import qdot

MODEL = (Path(__file__).resolve().parents[2] / "examples" / "double_pendulum.qd").read_text()


def test_every_with_step_control():
    m = qdot.Model(MODEL)
    ref = m.simulate(10, method="dop853", rtol=1e-13, every=0.2)
    r = m.simulate(10, rtol=1e-10, every=0.2)
    assert r.method == "dop853" and len(r) == 51
    assert np.allclose(r.t, 0.2 * np.arange(51), rtol=0, atol=1e-12)
    assert np.max(np.abs(r["theta1"] - ref["theta1"])) < 1e-7
    g = m.simulate(10, method="gl4", dt=0.01, every=1)
    assert len(g) == 11 and np.max(np.abs(g["theta2"] - ref["theta2"][::5])) < 1e-5

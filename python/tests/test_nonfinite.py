# python/tests/test_nonfinite.py - no run ends well with non-finite data
# (issue 30): times that are not finite are refused by the library before
# any run; a run that would give NaN rows raises; an input callable that
# returns NaN ends the run; an exception in the row sink is raised by
# simulate, never printed as "Exception ignored".
import math

import pytest

import qdot
import qdot.sim

OSC = """
coordinates x
T = x'^2/2
V = x^2/2
initial x = 1
"""

# x'' = 1/(2 sqrt(x)) from x = 1, x' = -5: x reaches 0 at t = 0.2028, where
# sqrt(x) and dop853's error estimate become NaN
ROOT = """
coordinates x
T = x'^2/2
V = -sqrt(x)
initial x = 1, x' = -5
"""

FORCED = """
coordinates x
inputs F
T = x'^2/2
V = x^2/2
Q[x] = F
initial x = 1
"""


@pytest.mark.parametrize("t_end", [math.inf, math.nan, -math.inf])
def test_end_time_not_finite(t_end):
    with pytest.raises(qdot.Error, match="the end time must be a finite number"):
        qdot.Model(OSC).simulate(t_end)


def test_step_not_finite():
    with pytest.raises(qdot.Error, match="the step dt must be a finite number, not inf"):
        qdot.Model(OSC).simulate(1, method="dop853", dt=math.inf)


def test_initial_not_finite():
    with pytest.raises(qdot.Error, match="the initial state is not finite"):
        qdot.Model(OSC).simulate(1, initial={"x": math.nan})


def test_nan_estimate_raises():
    with pytest.raises(qdot.Error, match="step size underflow at t = 0.2027"):
        qdot.Model(ROOT).simulate(2, method="dop853")


def test_input_nan_ends_run():
    with pytest.raises(qdot.Error, match="input F is not finite at t = 0.5"):
        qdot.Model(FORCED).simulate(2, method="gl4", dt=0.01,
                                    inputs={"F": lambda t, y: math.nan if t > 0.5 else 0.0})


class _Failing:
    """Stands for an input callable in qdot.sim._run's list: reading its
    error raises in the row sink from the third row on."""

    def __init__(self):
        self.reads = 0

    @property
    def error(self):
        self.reads += 1
        if self.reads >= 3:
            raise RuntimeError("the sink failed")
        return None


def test_sink_exception_raised(monkeypatch, capfd):
    fake = _Failing()
    monkeypatch.setattr(qdot.sim, "_add_inputs", lambda *args: [fake])
    with pytest.raises(RuntimeError, match="the sink failed"):
        qdot.Model(OSC).simulate(10, method="dop853", rtol=1e-10, dt=0.01)
    err = capfd.readouterr().err
    assert "Exception ignored" not in err
    assert fake.reads <= 4  # the run ended at the failing row, not at t = 10

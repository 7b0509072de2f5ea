# python/tests/test_conlin.py - Model.linearize on models that keep
# constraints (qdot/conlin.h, issue 37): through the library's manifold path,
# the CLI's JSON keys and values.
#
#   SymPy's non-minimal pendulum (test_linearize.py's
#   test_linearize_pendulum_lagrange_nonminimal: q1^2 + q2^2 = L^2, gravity
#   along +q1): over (q2, q2'), A = [0 1; -g/L 0] (Desloge ch. 62, the simple
#   pendulum's small oscillations), the multiplier -m g/(2L); with outputs,
#   C = dy/dz T: the height q1 = sqrt(L^2 - q2^2) gives dq1/dq2 = -q2/q1;
#   the rolling disc (test_linearize_rolling_disc_kane, m = r = g = 1, spin w):
#   five ignorable states and s^2 = 4/5 - 12 w^2/5 (Neimark and Fufaev ch. III).
import math
import os

import numpy as np
import pytest

import qdot
from test_commands import cli, same

NONMINIMAL = """parameters m = 0.9, g = 9.8, L = 1.3
inputs F
coordinates q1, q2
T = m/2*(q1'^2 + q2'^2)
V = -m*g*q1
Q[q2] = F
constraint rod: q1^2 + q2^2 = L^2
outputs height = q1
initial q1 = L, q2 = 0
"""
DISC = """parameters m = 1, r = 1, g = 1, w = 0.8
coordinates q1, q2, q3, x, y, z
body disc mass m inertia (m*r^2/4, m*r^2/4, m*r^2/2) at (x, y, z) orientation rot_z(q1)*rot_x(q2)*rot_y(q3)*rot_x(-pi/2)
V = m*g*z
rolls disc on plane((0, 0, 1), (0, 0, 0)) as disk(r)
initial q1 = 0, q2 = 0, q3 = 0, x = 0, y = 0, z = r, q3' = w
"""


def load(tmp_path, name, text):
    path = os.path.join(str(tmp_path), name)
    with open(path, "w") as f:
        f.write(text)
    return path, qdot.Model.load(path)


def test_nonminimal_pendulum(tmp_path):
    path, model = load(tmp_path, "nonminimal.qd", NONMINIMAL)
    ss = model.linearize()
    g, L, m = 9.8, 1.3, 0.9
    assert ss.states == ["q2", "q2'"] and ss.inputs == ["F"] and ss.outputs == ["height"]
    np.testing.assert_allclose(ss.A, [[0, 1], [-g / L, 0]], rtol=1e-13, atol=1e-14)
    np.testing.assert_allclose(ss.B, [[0], [1 / m]], rtol=1e-13, atol=1e-14)
    assert ss.json["multipliers"]["lambda_rod"] == pytest.approx(-m * g / (2 * L), rel=1e-13)
    assert ss.verdict == "marginally stable" and ss.dependent == ["q1", "q1'"]
    # off the bottom: the height's row of C is dq1/dq2 = -q2/q1 along the circle
    q2 = 0.6
    off = model.linearize(about={"q2": q2}, independent=["q2", "q2'"])
    q1 = math.sqrt(L * L - q2 * q2)
    np.testing.assert_allclose(off.C, [[-q2 / q1, 0]], rtol=1e-13, atol=1e-14)
    np.testing.assert_allclose(off.y0, [q1], rtol=1e-14)
    assert off.verdict == "not steady"
    # the CLI's JSON, key by key
    same(ss.json, cli("linearize", path))
    same(off.json, cli("linearize", path, "--about", "q2=0.6", "--independent", "q2, q2'"))


@pytest.mark.parametrize("w", [0.3, 1.5])
def test_rolling_disc(tmp_path, w):
    path, model = load(tmp_path, "disc.qd", DISC.replace("w = 0.8", "w = %r" % w))
    ss = model.linearize()
    assert ss.A.shape == (8, 8) and len(ss.ignorable) == 5
    s2 = 4 / 5 - 12 * w * w / 5
    want = sorted([0] * 6 + [np.sqrt(complex(s2)), -np.sqrt(complex(s2))],
                  key=lambda z: (round(z.real, 8), round(z.imag, 8)))
    got = sorted(np.linalg.eigvals(ss.A), key=lambda z: (round(z.real, 8), round(z.imag, 8)))
    np.testing.assert_allclose(got, want, atol=1e-10)
    assert ss.verdict == ("unstable" if s2 > 0 else "marginally stable")
    same(ss.json, cli("linearize", path))


def test_errors(tmp_path):
    _, model = load(tmp_path, "nonminimal.qd", NONMINIMAL)
    with pytest.raises(qdot.ModelError, match="zz"):
        model.linearize(independent="zz, q2'")
    with pytest.raises(qdot.ModelError, match="unknown name"):
        model.linearize(about="q3 = 1")

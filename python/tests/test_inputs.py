# python/tests/test_inputs.py - model inputs from Python (issue 23): a forced
# oscillator x'' + w^2 x = F driven by a constant, an expression and Python
# callables against the closed forms; a callable that raises; the state-space
# form of examples/cart_pendulum.qd against the hand linearization; the LQR
# gain against the Riccati equation and SciPy; the closed loop settling.
import math
import os

import numpy as np
import pytest

import qdot
from conftest import EXAMPLES

OSC = """
coordinates x
parameters w = 3
inputs F
T = x'^2/2
V = w^2*x^2/2
Q[x] = F
initial x = 0.1, x' = 0.2
"""
W, X0, V0 = 3.0, 0.1, 0.2
TIGHT = dict(rtol=1e-12, atol=1e-14, dt=0.25)


def free(t, x0, v0, w):
    """The homogeneous solution x0 cos(wt) + v0/w sin(wt) and its rate."""
    return (x0 * np.cos(w * t) + v0 / w * np.sin(w * t),
            -x0 * w * np.sin(w * t) + v0 * np.cos(w * t))


def assert_close(r, x, v, tol=1e-8):
    assert len(r) > 20
    assert np.max(np.abs(r["x"] - x)) < tol
    assert np.max(np.abs(r["x'"] - v)) < tol


@pytest.mark.parametrize("F", [0.5, -2, np.float64(0.25), "1/2"])
def test_constant_force_shifts_the_centre(F):
    # x = F/w^2 + (x0 - F/w^2) cos wt + v0/w sin wt
    r = qdot.Model(OSC).simulate(8, inputs={"F": F}, **TIGHT)
    c = (0.5 if F == "1/2" else float(F)) / W**2
    x, v = free(r.t, X0 - c, V0, W)
    assert_close(r, x + c, v)


def driven(t):
    """x'' + w^2 x = cos(2t): the particular cos(2t)/(w^2 - 4) plus the free motion."""
    a = 1 / (W**2 - 4)
    x, v = free(t, X0 - a, V0, W)
    return x + a * np.cos(2 * t), v - 2 * a * np.sin(2 * t)


def test_expression_input_in_t():
    r = qdot.Model(OSC).simulate(8, inputs={"F": "cos(2*t)"}, **TIGHT)
    assert_close(r, *driven(r.t))


def test_callable_input_in_t():
    r = qdot.Model(OSC).simulate(8, inputs={"F": lambda t, y: math.cos(2 * t)}, **TIGHT)
    assert_close(r, *driven(r.t))


def test_callable_feedback_reads_the_state():
    # F = -k x - c x' makes x'' + c x' + (w^2 + k) x = 0: underdamped,
    # x = e^(-ct/2) (x0 cos(wd t) + (v0 + c x0/2)/wd sin(wd t)), wd^2 = w^2 + k - c^2/4
    k, c = 7.0, 0.6
    seen = []

    def law(t, y):
        seen.append(y.shape)
        return -k * y[0] - c * y[1]

    r = qdot.Model(OSC).simulate(6, inputs={"F": law}, **TIGHT)
    wd = math.sqrt(W**2 + k - c * c / 4)
    b = (V0 + c * X0 / 2) / wd
    e = np.exp(-c * r.t / 2)
    x = e * (X0 * np.cos(wd * r.t) + b * np.sin(wd * r.t))
    v = -c / 2 * x + e * wd * (-X0 * np.sin(wd * r.t) + b * np.cos(wd * r.t))
    assert_close(r, x, v)
    assert set(seen) == {(2,)}


# each method family meets the NaN the failed callable leaves differently:
# step control rejects it, the collocation iteration fails, CVODE gives up
@pytest.mark.parametrize("method", [dict(method="dop853", **TIGHT),
                                    dict(method="gl4", dt=0.01), dict(method="bdf")])
def test_callable_exception_reaches_the_caller(method):
    calls = []

    def law(t, y):
        calls.append(t)
        if t > 1.0:
            raise ZeroDivisionError("controller failed at t = %g" % t)
        return 0.0

    m = qdot.Model(OSC)
    with pytest.raises(ZeroDivisionError, match="controller failed"):
        m.simulate(5, inputs={"F": law}, **method)
    assert sum(t > 1.0 for t in calls) == 1  # never called again after raising
    # the context holds no stale error: the next run is clean and right
    r = m.simulate(8, inputs={"F": "cos(2*t)"}, **TIGHT)
    assert_close(r, *driven(r.t))


def test_callable_with_many_values_is_refused():
    with pytest.raises(ValueError, match="returned 2 values"):
        qdot.Model(OSC).simulate(1, inputs={"F": lambda t, y: y}, **TIGHT)


def test_input_errors():
    m = qdot.Model(OSC)
    with pytest.raises(qdot.Error, match="input F is used but not supplied"):
        m.simulate(1, **TIGHT)
    with pytest.raises(qdot.Error, match="'G' is not an input of the model"):
        m.simulate(1, inputs={"F": 0, "G": 1}, **TIGHT)
    with pytest.raises(qdot.Error, match="takes a number, an expression"):
        m.simulate(1, inputs={"F": [1, 2]}, **TIGHT)
    with pytest.raises(qdot.ModelError):
        m.simulate(1, inputs={"F": "cos(2*"}, **TIGHT)


# ---- examples/cart_pendulum.qd: x the cart, th the tilt from upright -------------
# T = (M+m)/2 x'^2 - m l cos(th) x' th' + m l^2/2 th'^2, V = m g l cos(th), Q[x] = F;
# about th = 0: M x'' = F + m g th, M l th'' = F + (M + m) g th, so
# A[2][1] = m g/M, A[3][1] = (M + m) g/(M l), B = (0, 0, 1/M, 1/(M l)) and the
# eigenvalues 0, 0, +-sqrt(g (M + m)/(M l)) (SymPy's n_link_pendulum_on_cart, n = 1).
PAR = dict(M=2.0, m=0.3, l=0.7, g=9.81)


def cart():
    return qdot.Model.load(os.path.join(EXAMPLES, "cart_pendulum.qd")).set(**PAR)


def test_cart_pendulum_state_space_upright():
    M, m, l, g = PAR["M"], PAR["m"], PAR["l"], PAR["g"]
    ss = cart().linearize(about={"th": 0})
    assert ss.states == ["x", "th", "x'", "th'"]
    assert ss.inputs == ["F"] and ss.outputs == ["position", "tilt"]
    A = np.zeros((4, 4))
    A[0, 2] = A[1, 3] = 1
    A[2, 1], A[3, 1] = m * g / M, (M + m) * g / (M * l)
    B = np.array([[0], [0], [1 / M], [1 / (M * l)]])
    assert np.allclose(ss.A, A, rtol=1e-14, atol=1e-14)
    assert np.allclose(ss.B, B, rtol=1e-14, atol=1e-14)
    assert np.allclose(ss.C, np.eye(2, 4)) and np.allclose(ss.D, 0)
    s = math.sqrt(g * (M + m) / (M * l))
    eig = sorted(ss.eigenvalues, key=lambda z: z.real)
    assert np.allclose(eig, [-s, 0, 0, s], atol=1e-12)
    assert ss.controllable and ss.observable and ss.uncontrollable == []
    assert ss.B_exact == [["0"], ["0"], ["1/M"], ["1/(M*l)"]]


def test_cart_pendulum_hanging_oscillates():
    # about th = pi the sign of g flips: eigenvalues +-i sqrt(g (M + m)/(M l))
    M, m, l, g = PAR["M"], PAR["m"], PAR["l"], PAR["g"]
    ss = cart().linearize(about={"th": "pi"})
    s = math.sqrt(g * (M + m) / (M * l))
    assert np.allclose(sorted(abs(ss.eigenvalues.imag)), [0, 0, s, s], atol=1e-12)
    assert np.allclose(ss.eigenvalues.real, 0, atol=1e-12)
    # a name not of the model: the library's reader, shown in the text as --about
    with pytest.raises(qdot.ModelError, match="unknown name 'y'") as err:
        cart().linearize(about={"y": 1})
    assert (err.value.file, err.value.col) == ("about", 1)


def riccati_residual(A, B, Q, R, X):
    """||A^T X + X A - X B R^-1 B^T X + Q|| relative to its terms (qdot/control.h)."""
    G = B @ np.linalg.solve(R, B.T)
    res = A.T @ X + X @ A - X @ G @ X + Q
    size = np.linalg.norm(Q) + 2 * np.linalg.norm(A.T @ X) + np.linalg.norm(X @ G @ X)
    return np.linalg.norm(res) / size


Q4, R1 = np.diag([1.0, 10.0, 1.0, 1.0]), np.array([[0.1]])


def test_lqr_gain_solves_riccati():
    ss = cart().linearize()
    lq = ss.lqr(Q4, R1)
    assert riccati_residual(ss.A, ss.B, Q4, R1, lq.X) < 1e-10
    assert np.allclose(lq.X, lq.X.T, rtol=1e-12, atol=0)
    assert np.allclose(lq.K, np.linalg.solve(R1, ss.B.T @ lq.X), rtol=1e-12, atol=0)
    closed = np.linalg.eigvals(ss.A - ss.B @ lq.K)
    assert max(closed.real) < 0
    assert np.allclose(sorted(closed, key=lambda z: (z.real, z.imag)),
                       sorted(lq.eigenvalues, key=lambda z: (z.real, z.imag)), rtol=1e-9)
    linalg = pytest.importorskip("scipy.linalg")
    assert np.allclose(lq.X, linalg.solve_continuous_are(ss.A, ss.B, Q4, R1), rtol=1e-9)
    # a diagonal and a number are the same Q and R
    assert np.allclose(ss.lqr([1, 10, 1, 1], 0.1).K, lq.K, rtol=1e-14)


def test_lqr_refusals():
    ss = cart().linearize()
    with pytest.raises(qdot.Error) as err:
        ss.lqr(Q4, -1)
    assert err.value.failure == "R not positive definite"
    with pytest.raises(qdot.Error, match="Q must be"):
        ss.lqr(np.eye(3), 1)


def test_lqr_closed_loop_settles_from_a_tilt():
    m = cart()
    ss = m.linearize()
    K = ss.lqr(Q4, R1).K
    y0 = np.zeros(4)  # the upright equilibrium
    # max_steps: a wrong gain or state order diverges, which must fail, not hang
    run = dict(rtol=1e-11, atol=1e-13, dt=0.1, initial={"th": 0.2, "x": 0}, max_steps=20000)
    r = m.simulate(15, **run,
                   inputs={"F": lambda t, y: -K @ (y - y0)})
    late = r.t >= 12
    for name in ss.states:
        assert np.max(np.abs(r[name][late])) < 1e-3, name
    assert abs(r["th"][0] - 0.2) < 1e-15 and np.max(np.abs(r["th"])) < 0.3
    assert np.allclose(r["tilt"], r["th"])  # the model's outputs are columns
    # the same law as text goes through qd_sim_input_expr: the two runs agree
    law = " + ".join("(%r)*%s" % (-k, s) for k, s in zip(K[0], ss.states))
    r2 = m.simulate(15, **run, inputs={"F": law})
    assert np.max(np.abs(r2["th"] - r["th"])) < 1e-8
    assert np.max(np.abs(r2["x"] - r["x"])) < 1e-8

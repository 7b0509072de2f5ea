# python/tests/test_eom_sympy.py - the equations and the Hamiltonian the
# package returns, against SymPy's own derivation of the same model:
# M_jk = d^2 L / dq'_j dq'_k and f = dL/dq - d/dt(dL/dq') + M q'' from
# Lagrange's equations (Goldstein ch. 1 eq. 1.53; the double pendulum is
# Goldstein ch. 1 Ex. 22, seed 002_3e07e211eebc00b9.txt), and
# H = p^2 / (2 m l^2) - m g l cos(theta) for the pendulum.
import os

import pytest

import qdot
from conftest import EXAMPLES

sp = pytest.importorskip("sympy")


def sympy_lagrange(L, qs, t):
    """M and f of M q'' = f from L(q(t), q'(t)) by SymPy's differentiation."""
    qd = [q.diff(t) for q in qs]
    qdd = [q.diff(t, 2) for q in qs]
    M = sp.Matrix([[sp.diff(L, a, b) for b in qd] for a in qd])
    eqs = [sp.diff(L, q) - sp.diff(sp.diff(L, v), t) for q, v in zip(qs, qd)]
    f = sp.Matrix([sp.expand(e + sum(M[i, k] * qdd[k] for k in range(len(qs))))
                   for i, e in enumerate(eqs)])
    return M, f


def test_double_pendulum_eom_equals_sympy_derivation():
    model = qdot.Model.load(os.path.join(EXAMPLES, "double_pendulum.qd"))
    e = model.eom(sympy=True)
    t = sp.Symbol("t")
    m1, m2, l1, l2, g = sp.symbols("m1 m2 l1 l2 g")
    th1, th2 = sp.Function("theta1")(t), sp.Function("theta2")(t)
    x1, y1 = l1 * sp.sin(th1), -l1 * sp.cos(th1)
    x2, y2 = x1 + l2 * sp.sin(th2), y1 - l2 * sp.cos(th2)
    T = m1 / 2 * (x1.diff(t) ** 2 + y1.diff(t) ** 2) + m2 / 2 * (x2.diff(t) ** 2 + y2.diff(t) ** 2)
    V = m1 * g * y1 + m2 * g * y2
    M, f = sympy_lagrange(T - V, [th1, th2], t)
    assert e.coordinates == ["theta1", "theta2"]
    assert isinstance(e.M, sp.MatrixBase) and e.M.shape == (2, 2)
    assert sp.simplify(e.M - M) == sp.zeros(2, 2)
    assert sp.simplify(e.f - f) == sp.zeros(2, 1)
    # the strings are the same equations in the model language
    text = model.eom()
    assert text.M[0][1] == "l1*l2*m2*cos(theta1 - theta2)"


def test_eom_sympy_can_fail():
    # a model with another potential must not pass the comparison above
    model = qdot.Model("coordinates th\nparameters m = 1, l = 1, g = 9.81\n"
                       "T = m/2*l^2*th'^2\nV = m*g*l*cos(th)\n")
    t = sp.Symbol("t")
    m, l, g = sp.symbols("m l g")
    th = sp.Function("th")(t)
    M, f = sympy_lagrange(m / 2 * l ** 2 * th.diff(t) ** 2 + m * g * l * sp.cos(th), [th], t)
    e = model.eom(sympy=True)
    assert sp.simplify(e.M - M) == sp.zeros(1, 1)
    assert sp.simplify(e.f - f) != sp.zeros(1, 1)


def test_pendulum_hamiltonian():
    model = qdot.Model("coordinates th\nparameters m = 1, l = 2, g = 9.81\n"
                       "T = m/2*l^2*th'^2\nV = -m*g*l*cos(th)\n")
    h = model.hamiltonian(sympy=True)
    t = sp.Symbol("t")
    m, l, g, p = sp.symbols("m l g p_th")
    th = sp.Function("th")(t)
    assert h.momenta == ["p_th"]
    assert sp.simplify(h.H - (p ** 2 / (2 * m * l ** 2) - m * g * l * sp.cos(th))) == 0
    assert sp.simplify(h.dq[0] - p / (m * l ** 2)) == 0
    assert sp.simplify(h.dp[0] + m * g * l * sp.sin(th)) == 0
    assert h.conserved and h.is_energy

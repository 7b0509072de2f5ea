# python/tests/test_render.py - the whole-system printers (qdot/render.h) from
# Python: the SymPy script of the pendulum's equations, run by SymPy, gives
# the equations sympy.physics.mechanics derives (LagrangesMethod: Goldstein
# ch. 1, ml^2 theta'' = -m g l sin(theta)); Euler's free body in its speeds
# gives Euler's equations (Desloge ch. 68 Ex. 2); the numbers at a state
# are the textbook accelerations.
import math
import os

import pytest

import qdot
from conftest import EXAMPLES

sp = pytest.importorskip("sympy")
me = pytest.importorskip("sympy.physics.mechanics")

PENDULUM = ("coordinates theta\nparameters m = 1, l = 2, g = 9.81\n"
            "T = m/2*l^2*theta'^2\nV = -m*g*l*cos(theta)\n")


def run(script):
    """The names the SymPy script defines."""
    ns = {}
    exec(script, ns)  # noqa: S102 (the library's SymPy rendering, run as a user would)
    return ns


def test_pendulum_sympy_text_is_lagranges_method():
    ns = run(qdot.Model(PENDULUM).eom().sympy_text())
    theta = me.dynamicsymbols("theta")
    m, l, g = sp.symbols("m l g")
    L = m / 2 * l ** 2 * theta.diff() ** 2 + m * g * l * sp.cos(theta)
    lm = me.LagrangesMethod(L, [theta])
    lm.form_lagranges_equations()
    # the script's theta(t) is SymPy's dynamicsymbol theta: the same Function of t
    assert sp.simplify(ns["M"] - lm.mass_matrix) == sp.zeros(1, 1)
    assert sp.simplify(ns["f"] - lm.forcing) == sp.zeros(1, 1)


def test_pendulum_sympy_text_can_fail():
    # the comparison above tells another potential apart
    ns = run(qdot.Model(PENDULUM.replace("-m*g*l*cos", "m*g*l*cos")).eom().sympy_text())
    theta = me.dynamicsymbols("theta")
    m, l, g = sp.symbols("m l g")
    lm = me.LagrangesMethod(m / 2 * l ** 2 * theta.diff() ** 2 + m * g * l * sp.cos(theta),
                            [theta])
    lm.form_lagranges_equations()
    assert sp.simplify(ns["f"] - lm.forcing) != sp.zeros(1, 1)


def test_double_pendulum_sympy_text_has_the_package_equations():
    model = qdot.Model.load(os.path.join(EXAMPLES, "double_pendulum.qd"))
    ns = run(model.eom().sympy_text())
    e = model.eom(sympy=True)
    assert sp.simplify(ns["M"] - e.M) == sp.zeros(2, 2)
    assert sp.simplify(ns["f"] - e.f) == sp.zeros(2, 1)


def test_latex_and_c_of_the_pendulum():
    e = qdot.Model(PENDULUM).eom()
    tex = e.latex()
    assert tex.startswith("\\begin{align}") and "\\ddot{\\theta}" in tex
    assert "\\sin" in tex
    c = e.c_code()
    assert "M[0][0] =" in c and "f[0] =" in c and "sin(theta)" in c


def test_pendulum_at_a_state_is_the_textbook_acceleration():
    model = qdot.Model(PENDULUM)
    out = model.eom().json(at={"theta": 0.3, "theta'": 0.5})
    g, l = 9.81, 2.0
    assert out["state"]["theta"] == 0.3
    assert out["accelerations"][0] == pytest.approx(-g / l * math.sin(0.3), rel=1e-14)
    assert out["mass_matrix"] == [[pytest.approx(l ** 2)]]
    assert "theta'' = " in model.eom().text(at={"theta": 0.3})


def test_at_a_misspelt_name_is_an_error():
    with pytest.raises(qdot.Error, match="thetta"):
        qdot.Model(PENDULUM).eom().text(at={"thetta": 1})


def test_euler_body_in_its_speeds_gives_eulers_equations():
    model = qdot.Model.load(os.path.join(EXAMPLES, "euler_free_body.qd"))
    s = model.speeds_eom()
    assert s.speeds == ["w1", "w2", "w3"] and s.method == "kane"
    ns = run(s.sympy_text())
    A, B, C, G1, G2, G3 = sp.symbols("A B C G1 G2 G3")
    t = sp.Symbol("t")
    w1, w2, w3 = (sp.Function(n)(t) for n in ("w1", "w2", "w3"))
    assert sp.simplify(ns["M"] - sp.diag(A, B, C)) == sp.zeros(3, 3)
    euler = sp.Matrix([G1 + (B - C) * w2 * w3, G2 + (C - A) * w3 * w1, G3 + (A - B) * w1 * w2])
    assert sp.simplify(ns["f"] - euler) == sp.zeros(3, 1)
    # at a state: A w1' = (B - C) w2 w3 with A, B, C = 1, 2, 3
    rates = s.json(at={"theta": 1, "w1": 0.2, "w2": 1, "w3": 0.5})["rates"]
    assert rates == [pytest.approx((2 - 3) * 1 * 0.5 / 1), pytest.approx((3 - 1) * 0.5 * 0.2 / 2),
                     pytest.approx((1 - 2) * 0.2 * 1 / 3)]
    # Euler angles give gamma = -eps (Desloge ch. 68)
    gamma = s.hamel("json")["gamma"]
    assert gamma[0][1][2] == "-1" and gamma[0][2][1] == "1"


def test_quadratic_form_printers():
    # x^2 + 4xy + y^2 = (x + 2y)^2 - 3y^2: indefinite, inertia (1, 1, 0) (Sylvester)
    f = qdot.quadratic_form("x^2 + 4*x*y + y^2", ["x", "y"])
    assert f.json()["inertia"] == {"positive": 1, "negative": 1, "zero": 0}
    assert f.json()["matrix"] == [["1", "2"], ["2", "1"]]
    assert "n+ = 1, n- = 1, n0 = 0" in f.text()


def test_lagrange_form_of_a_speeds_model_at_a_state_read_by_the_library():
    # The rolling disk's equations in q, q' (Model.eom of a model with
    # `speeds`): at= read by the library's state reader (qd_state_read, as
    # `qdot eom --at`), so "pi/6" is exact text and a bad name is located.
    # f[q2] = m r (4 g sin q2 + 2 q1' q3' r cos q2 + 5 q1'^2 r sin q2 cos q2)/4
    # (the model's forcing, written out), f[y] = -m r q1'^2 sin q2 cos q1.
    e = qdot.Model.load(os.path.join(EXAMPLES, "rolling_disk_speeds.qd")).eom()
    m_, r, g, q2, w = 1.4, 0.35, 9.81, math.pi / 6, 2.0
    for at in ("q2=pi/6, q1'=2", {"q2": "pi/6", "q1'": 2}):
        j = e.json(at=at)
        assert j["state"]["q2"] == pytest.approx(q2, rel=1e-15)
        assert j["forcing"][3] == pytest.approx(
            m_ * r * (4 * g * math.sin(q2) + 5 * w**2 * r * math.sin(q2) * math.cos(q2)) / 4,
            rel=1e-13)
        assert j["forcing"][1] == pytest.approx(-m_ * r * w**2 * math.sin(q2), rel=1e-13)
    for bad, col, words in (("q2=1, thet=2", 7, "unknown name 'thet'"),
                            ("q2=2*/3", 6, "expected an expression"),
                            ("q2=1, q2=2", 7, "'q2' is given twice"),
                            ("u1=1", 1, "'u1' is a speed")):
        with pytest.raises(qdot.ModelError) as err:
            e.text(at=bad)
        assert (err.value.file, err.value.line, err.value.col) == ("at", 1, col)
        assert words in str(err.value) and "^" in str(err.value)

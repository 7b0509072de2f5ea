"""qdot.gram_schmidt: Desloge App. 21 Thm 1 (worked by hand) and Thm 2 (the
double pendulum's kinetic metric), against the CLI's JSON;
qdot.change_of_variables: App. 19 in polar coordinates and ch. 60 eq. 6
(Rutherford's cross section through J(s, psi/theta, phi))."""
import json
import os
import subprocess

import pytest
import qdot

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def test_thm1_by_hand():
    # (1,1,0), (1,0,1), (0,1,1): b2 = a2 - 1/2 b1, b3 = a3 - 1/2 b1 - 1/3 b2
    g = qdot.gram_schmidt("x^2 + y^2 + z^2", ["x", "y", "z"], [[1, 1, 0], [1, 0, 1], [0, 1, 1]])
    assert g.euclidean and g.metric is None
    assert g.orthogonal == [["1", "1", "0"], ["1/2", "-1/2", "1"], ["-2/3", "2/3", "2/3"]]
    assert g.norms == ["2", "3/2", "4/3"]
    assert g.coefficients[2][:2] == ["1/2", "1/3"]


def test_thm2_metric_tangents_match_cli():
    path = os.path.join(ROOT, "examples", "double_pendulum.qd")
    g = qdot.gram_schmidt(qdot.Model.load(path))
    assert not g.euclidean and g.vectors == [["1", "0"], ["0", "1"]]
    build = os.environ.get("QDOT_BUILD")
    if build:
        out = subprocess.run([os.path.join(build, "qdot"), "metric", path, "--gram-schmidt",
                              "--format", "json"], capture_output=True, text=True, check=True)
        cli = json.loads(out.stdout)
        assert cli["orthogonal"] == g.orthogonal and cli["norms"] == g.norms


def test_errors():
    with pytest.raises(qdot.Error, match="a2 is a linear combination"):
        qdot.gram_schmidt("x^2 + y^2", "x, y".split(", "), "1, 2; 2, 4")
    with pytest.raises(qdot.Error, match="not definite"):
        qdot.gram_schmidt("x^2 - y^2", ["x", "y"], [[1, 1]])
    with pytest.raises(ValueError):
        qdot.gram_schmidt("x^2 + y^2", ["x", "y"], "1, 2; 3")


def test_change_polar():
    c = qdot.change_of_variables("x^2 + y^2", ["x", "y"], {"x": "r*cos(th)", "y": "r*sin(th)"},
                                 ["r", "th"], positive="r")
    assert c.jacobian_det == "r" and c.sign == "nonnegative" and c.integrand == "r^3"
    assert c.inverse_det == "1/r" and c.singular == []


def test_change_rutherford():
    sympy = pytest.importorskip("sympy")
    c = qdot.change_of_variables("s", "s, psi", "s = b*cos(th/2)/sin(th/2), psi = ph",
                                 "th, ph", positive=["b"])
    assert c.sign == "nonpositive"
    th, b = sympy.Symbol("th"), sympy.Symbol("b", positive=True)
    sigma = sympy.sympify(c.integrand.replace("^", "**"), locals={"b": b}) / sympy.sin(th)
    assert sympy.simplify(sigma - b**2 / (4 * sympy.sin(th / 2)**4)) == 0


def test_change_errors():
    with pytest.raises(qdot.Error, match="0 everywhere"):
        qdot.change_of_variables("1", "x, y", "x = u + v, y = 2*u + 2*v", "u, v")
    with pytest.raises(ValueError, match="y is not given"):
        qdot.change_of_variables("1", "x, y", "x = u + v", "u, v")


def test_condensed_thm1():
    # Desloge ch. 75 Thm 1 on T41's exchange Q = p, P = -q, and a scaling
    m = qdot.Model("coordinates q\nparameters m = 1, k = 1\nT = m/2*q'^2\nV = k/2*q^2\n")
    out = qdot.condensed(m, "p_q", "-q")
    assert out["verdict"] == "canonical" and out["jacobian_det"] == "1"
    assert out["mu"] == [["0", "1"], ["-1", "0"]] and out["r_dot"] == ["p_q/m", "-k*q"]
    out = qdot.condensed(m, ["2*q"], ["p_q"])
    assert out["verdict"] == "scaled" and out["scale"] == "2"


def test_fourier_power_reduction():
    # cos^3 x = (3 cos x + cos 3x)/4
    d = qdot.fourier("cos(x)^3", ["x"])
    got = {tuple(h["k"]): (h["cos"], h["sin"]) for h in d["harmonics"]}
    assert got == {("3",): ("1/4", "0"), ("1",): ("3/4", "0")}
    with pytest.raises(qdot.Error, match="not a trigonometric polynomial"):
        qdot.fourier("1/(2 - cos(x))", "x")

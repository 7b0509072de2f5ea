"""Model.metric(): the tensors of the coordinates (qdot/metric.h) for
spherical coordinates, Desloge ch. 55 (seed 000; reference
seed-desloge-A.md T49): Gamma^r_thth = -r, Gamma^th_rth = 1/r; det J =
r^2 sin th, singular at r = 0 and th = 0 + k pi (App. 18)."""
import sympy as sp

import qdot

SPHERICAL = """coordinates r, th, ph
parameters m = 2, k = 1
particle m at (r*sin(th)*cos(ph), r*sin(th)*sin(ph), r*cos(th))
V = -k/r
"""


def test_spherical_christoffel_symbols():
    g = qdot.Model(SPHERICAL).metric()
    assert g.coordinates == ["r", "th", "ph"]
    assert g.christoffel_second["r"]["th"]["th"] == "-r"
    assert g.christoffel_second["th"]["r"]["th"] == "1/r"
    assert g.christoffel_second["r"]["r"]["r"] == "0"
    assert g.metric["th"]["th"] == "m*r^2"
    assert g.jacobian_det == "r^2*sin(th)"
    assert g.singular == [("r", "0", None), ("th", "0", "pi")]
    assert g.orthogonal


def test_sympy_values():
    g = qdot.Model(SPHERICAL).metric(sympy=True)
    th = sp.Symbol("th")
    # coordinates print as functions of t in SymPy's text
    got = g.christoffel_second["ph"]["th"]["ph"]
    assert sp.simplify(got.subs(sp.Function("th")(sp.Symbol("t")), th) - sp.cot(th)) == 0

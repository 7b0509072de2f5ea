"""qdot.quadratic_form: Desloge App. 27 Thm 3 (Lagrange's reduction) and Thm 4
(Sylvester's inertia), P16 (every diagonal element 0)."""
import pytest
import qdot


def test_reduction_and_inertia():
    f = qdot.quadratic_form("x^2 + 4*x*y + y^2", ["x", "y"])
    assert f.coefficients == ["1", "-3"]
    assert f.linear_forms == ["x + 2*y", "y"]
    assert f.inertia == (1, 1, 0) and f.kind == "indefinite" and f.rank == 2


def test_pair_substitution():
    f = qdot.quadratic_form("2*x*y + 2*y*z", ["x", "y", "z"])
    assert f.paired and f.inertia == (1, 1, 1)


def test_not_quadratic():
    with pytest.raises(qdot.Error):
        qdot.quadratic_form("x^2 + x", ["x"])


def test_quadratic_form_refuses_constants():
    # pi is the constant 3.14159..., not a variable: it was taken as a
    # symbol of that name, absent from the form, and the reduction failed
    # with "a term of degree other than 2" instead of saying why (issue 32)
    for names, bad in ((["x", "pi"], "pi"), (["e", "x"], "e"), (["x", "x"], "x")):
        with pytest.raises(ValueError) as err:
            qdot.quadratic_form("x^2 + pi*y^2", names)
        assert isinstance(err.value, qdot.Error)
        assert ("'%s' is not a variable name" % bad in str(err.value)
                or "'%s' is given twice" % bad in str(err.value))
        assert str(err.value).startswith("variables:1:")
    # the variables as --vars reads them: the reduction is the same
    f = qdot.quadratic_form("x^2 + 4*x*y + y^2", "x y".split())
    assert f.coefficients == ["1", "-3"]
    # pi as a coefficient is the positive constant: Sylvester's inertia decided
    f = qdot.quadratic_form("x^2 - pi*y^2", ["x", "y"])
    assert f.inertia == (1, 1, 0) and f.kind == "indefinite"


def test_homogeneity_euler():
    # Desloge App. 20 (seed-desloge-D.md T27): T in the velocities has
    # degree 2, so sum q' dT/dq' = 2T
    h = qdot.homogeneity("m/2*(r'^2 + r^2*phi'^2)", ["r'", "phi'"])
    assert h.homogeneous is True and h.degree == "2" and h.certainty == "proven"
    assert h.euler == "m*(phi'^2*r^2 + r'^2)"


def test_homogeneity_witness():
    # x^2 + x: f(x) f(4x) - f(2x)^2 = 4 x^3, which the witness's value is
    h = qdot.homogeneity("x^2 + x", ["x"])
    assert h.homogeneous is False and h.degree is None
    x = h.witness["point"]["x"]
    assert h.witness["value"] == pytest.approx(4 * x**3, rel=1e-14)


def test_homogeneity_refuses_constants():
    with pytest.raises(ValueError, match="not a variable name"):
        qdot.homogeneity("x^2", ["pi"])


def test_periods_fundamental_system():
    # Desloge App. 31 Thm 4: 2 pi and 4 pi/3 are periods of sin(3x), and
    # their fundamental system is 2 pi/3 (2 pi = 3 e, 4 pi/3 = 2 e, eq. 3)
    p = qdot.periods("sin(3*x)", ["x"], [["2*pi"], ["4*pi/3"]])
    assert p.is_period == [True, True] and p.fundamental == [["2*pi/3"]]
    assert p.coordinates == [[3], [2]] and p.rank == 1


def test_periods_incommensurable():
    with pytest.raises(qdot.Error, match="not a rational multiple"):
        qdot.periods("x", ["x"], "1; sqrt(2)")

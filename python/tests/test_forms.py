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

"""qdot.gram_schmidt: Desloge App. 21 Thm 1 (worked by hand) and Thm 2 (the
double pendulum's kinetic metric), against the CLI's JSON."""
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

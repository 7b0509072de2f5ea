# python/tests/test_errors.py - errors reach Python as qdot.ModelError with
# the file:line:col message and caret of qd_diag_format, the same text the
# command line prints for the same file; other misuse raises qdot.Error.
import math
import os
import subprocess

import pytest

import qdot

BUILD = os.environ.get("QDOT_BUILD", "")


def cli_stderr(path):
    """What `qdot eom FILE` prints for a bad file, when the build is known."""
    exe = os.path.join(BUILD, "qdot")
    if not os.access(exe, os.X_OK):
        return None
    run = subprocess.run([exe, "eom", path], capture_output=True, text=True)
    assert run.returncode == 2
    return run.stderr.rstrip("\n")


def test_parse_error_located(tmp_path):
    path = tmp_path / "bad.qd"
    path.write_text("coordinates x\nparameters m = 1, k = 2\nT = m/2*x'^2\n"
                    "V = k/2*x^2 + * x\n")
    with pytest.raises(qdot.ModelError) as err:
        qdot.Model.load(path)
    e = err.value
    assert (e.file, e.line, e.col) == (str(path), 4, 15)
    assert str(e).startswith("%s:4:15: error: " % path)
    assert "\n  V = k/2*x^2 + * x\n" in str(e)
    cli = cli_stderr(str(path))
    if cli is not None:
        assert str(e) == cli


def test_derivation_error_located_at_statement(tmp_path):
    # the model reads, but y has no inertia: the error points at the T line
    text = "coordinates x, y\nparameters m = 1\nT = m/2*x'^2\nV = m*x\n"
    m = qdot.Model(text)
    with pytest.raises(qdot.ModelError) as err:
        m.eom()
    assert (err.value.line, err.value.col) == (3, 1)
    assert "mass matrix is singular" in err.value.message
    assert err.value.hint
    path = tmp_path / "sing.qd"
    path.write_text(text)
    with pytest.raises(qdot.ModelError) as err2:
        qdot.Model.load(path).simulate(1)
    cli = cli_stderr(str(path))
    if cli is not None:
        assert str(err2.value) == cli
    # the context's error was cleared: a good call on the same model works
    assert m.coordinates == ["x", "y"]


def test_bad_use_raises():
    m = qdot.Model("coordinates x\nparameters k = 2\nT = x'^2/2\nV = k/2*x^2\n")
    with pytest.raises(qdot.ModelError, match="unknown parameter 'kk'"):
        m.set(kk=1)
    assert m.params == {"k": 2.0}  # unchanged by the failed set
    with pytest.raises(qdot.ModelError, match="unknown name 'z'"):
        m.simulate(1, initial={"z": 1})
    with pytest.raises(qdot.Error, match="method takes"):
        m.simulate(1, method="euler")
    with pytest.raises(qdot.Error, match="fixed steps"):
        m.simulate(1, method="gl4")
    with pytest.raises(qdot.ModelError):
        m.simulate(1, events=["x = (1"])
    # after every failure above the model still runs
    r = m.simulate(1, rtol=1e-10, initial={"x": 1})
    assert r["x"][-1] == pytest.approx(__import__("math").cos(2 ** 0.5), rel=1e-8)


def test_set_refuses_what_is_not_a_finite_number():
    m = qdot.Model("coordinates x\nparameters k = 2\nT = x'^2/2\nV = k/2*x^2\n")
    for bad in (float("nan"), float("inf"), True):
        with pytest.raises(qdot.Error, match="not a finite number"):
            m.set(k=bad)
    with pytest.raises(qdot.ModelError, match="set k"):
        m.set(k="2 +")
    # text is read in the model language and goes in as its value
    m.set(k="pi/6")
    assert m.params["k"] == pytest.approx(math.pi / 6, rel=1e-15)
    assert m.modes()[0].omega2 == pytest.approx(math.pi / 6, rel=1e-12)


def cli_simulate_stderr(path, *args):
    """What `qdot simulate FILE ARGS` prints when refused (exit 2), when the
    build is known."""
    exe = os.path.join(BUILD, "qdot")
    if not os.access(exe, os.X_OK):
        return None
    run = subprocess.run([exe, "simulate", str(path), "--t-end", "1", *args],
                         capture_output=True, text=True)
    assert run.returncode == 2, run.stderr
    return run.stderr


@pytest.mark.parametrize("kw, args", [
    ({"outputs": ["2*thetaa + 1"]}, ["--output", "2*thetaa + 1"]),
    ({"events": ["thetaa = 0, theta' > 0"]}, ["--event", "thetaa = 0, theta' > 0"]),
    ({"stop_at": "theta = 0, omgea > 0"}, ["--stop-at", "theta = 0, omgea > 0"]),
    ({"initial": {"thetaa": 1}}, ["--initial", "thetaa=1.0"]),
])
def test_same_name_same_message_as_cli(tmp_path, kw, args):
    # one reader of names (qdot/simsetup.h): Python and the command line say
    # the same sentence, hint and place for the same misspelt name
    path = tmp_path / "pend.qd"
    path.write_text("coordinates theta\nparameters l = 1, g = 9.81, omega = 2\n"
                    "T = l^2/2*theta'^2\nV = -g*l*cos(theta)\n")
    with pytest.raises(qdot.ModelError) as err:
        qdot.Model.load(path).simulate(1, **kw)
    e = err.value
    assert "unknown name" in e.message and e.hint.startswith("did you mean")
    cli = cli_simulate_stderr(path, *args)
    if cli is not None:
        assert e.message in cli and e.hint in cli
        assert ":%d:%d: error: " % (e.line, e.col) in cli  # the same place in the same text

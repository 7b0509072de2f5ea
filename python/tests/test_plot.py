# python/tests/test_plot.py - a run's pictures from Python (issue 32):
# Result.png() is the picture `qdot simulate --plot` draws from the same
# rows (the same library call, qd_plot_run), read back pixel by pixel;
# Jupyter's _repr_png_; Result.plot()'s matplotlib lines are the run's x(t)
# of the oscillator x'' = -x, x = cos t (Goldstein ch. 1's harmonic
# oscillator), and energy_error its E(t) - E(0).
import os
import subprocess
import sys
import tempfile

import numpy as np
import pytest

import qdot

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "tests", "util"))
from png import read_png  # noqa: E402  (tests/util/png.py)

OSCILLATOR = """
coordinates x
parameters k = 1
T = x'^2/2
V = k*x^2/2
initial x = 1, x' = 0
"""


def _png_file(data):
    fd, path = tempfile.mkstemp(suffix=".png")
    with os.fdopen(fd, "wb") as f:
        f.write(data)
    return path


def test_png_is_the_cli_plot():
    """The same rows, the same options: the same pixels as the CLI's."""
    r = qdot.Model(OSCILLATOR).simulate(6.0, dt=0.05, rtol=1e-10)
    mine = _png_file(r.png(y="x, x'", title="oscillator", size="640x420"))
    with tempfile.TemporaryDirectory() as d:
        model = os.path.join(d, "osc.qd")
        with open(model, "w") as f:
            f.write(OSCILLATOR)
        cli = os.path.join(d, "cli.png")
        qdot_exe = os.path.join(os.environ["QDOT_BUILD"], "qdot")
        subprocess.run([qdot_exe, "simulate", model, "--t-end", "6", "--dt", "0.05",
                        "--rtol", "1e-10", "--plot", cli, "--plot-y", "x, x'",
                        "--title", "oscillator", "--size", "640x420"],
                       check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        w1, h1, px1 = read_png(mine)
        w2, h2, px2 = read_png(cli)
    os.unlink(mine)
    assert (w1, h1) == (w2, h2) == (640, 420)
    diff = sum(px1(x, y) != px2(x, y) for x in range(0, w1, 3) for y in range(0, h1, 3))
    assert diff == 0
    # a picture, not a blank: the two curves' colours cover many pixels
    coloured = sum(len(set(px1(x, y))) > 1 for x in range(0, w1, 2) for y in range(0, h1, 2))
    assert coloured > 200


def test_repr_png_and_bad_columns():
    r = qdot.Model(OSCILLATOR).simulate(3.0, dt=0.1)
    data = r._repr_png_()
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    path = _png_file(data)
    w, h, _ = read_png(path)
    os.unlink(path)
    assert (w, h) == (800, 500)
    with pytest.raises(qdot.ArgumentError, match="y"):
        r.png(y="nosuch")
    with pytest.raises(qdot.ArgumentError):
        r.png(size="10x10")


def test_matplotlib_lines_are_the_motion():
    pytest.importorskip("matplotlib")
    import matplotlib
    matplotlib.use("Agg")
    r = qdot.Model(OSCILLATOR).simulate(2 * np.pi, dt=0.01, rtol=1e-11, atol=1e-12)
    fig = r.plot(y="x; energy_error")
    ax0, ax1 = fig.axes
    t, x = ax0.lines[0].get_data()
    assert np.max(np.abs(x - np.cos(t))) < 1e-8
    _, de = ax1.lines[0].get_data()
    assert np.max(np.abs(de)) < 1e-9  # E conserved: the second panel is E(t) - E(0)
    fig = r.plot(phase="x")
    (ax,) = fig.axes
    q, qd = ax.lines[0].get_data()
    assert np.max(np.abs(q * q + qd * qd - 1)) < 1e-8  # the phase circle


def test_poincare_orbits_png_is_the_cli_plot():
    """Model.poincare(initial=[...]): a Result an orbit, each through the
    section at its own energy (Henon-Heiles, examples/henon_heiles.qd: E =
    (x'^2 + y'^2)/2 + V is conserved, here x = y' = 0 at the start); their
    picture (png(orbits=...)) is the CLI's with --initial given twice, pixel
    for pixel, each orbit's dots in its own colour."""
    model = os.path.join(os.path.dirname(HERE), "..", "examples", "henon_heiles.qd")
    m = qdot.Model.load(model)
    starts = [{"y": -0.25, "x'": 0.42}, {"y": 0.55, "x'": 0.3}]
    rs = m.poincare("x = 0, x' > 0", 30, initial=starts)
    assert isinstance(rs, list) and [len(r) for r in rs] == [30, 30]
    for r, s in zip(rs, starts):
        y0 = s["y"]
        e = s["x'"] ** 2 / 2 + y0 ** 2 / 2 - y0 ** 3 / 3
        x, y, xd, yd = r["x"], r["y"], r["x'"], r["y'"]
        energy = (xd ** 2 + yd ** 2) / 2 + (x ** 2 + y ** 2) / 2 + x ** 2 * y - y ** 3 / 3
        assert np.abs(energy - e).max() < 1e-8 and np.abs(x).max() < 1e-9 and (xd > 0).all()
    with pytest.raises(qdot.ModelError, match="unknown name 'z'"):
        m.poincare("x = 0, x' > 0", 3, initial=[{"y": 0.1}, {"z": 1}])
    mine = _png_file(rs[0].png(phase="y", point_size=2, orbits=rs[1:], size="640x420"))
    with tempfile.TemporaryDirectory() as d:
        cli = os.path.join(d, "cli.png")
        qdot_exe = os.path.join(os.environ["QDOT_BUILD"], "qdot")
        args = [qdot_exe, "poincare", model, "--section", "x = 0, x' > 0", "--crossings", "30",
                "--phase", "y", "--point-size", "2", "--size", "640x420", "--plot", cli,
                "--title", ""]
        for r in rs:
            args += ["--initial", r.label]
        subprocess.run(args, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        w1, h1, px1 = read_png(mine)
        w2, h2, px2 = read_png(cli)
    os.unlink(mine)
    assert (w1, h1) == (w2, h2) == (640, 420)
    assert sum(px1(x, y) != px2(x, y) for x in range(w1) for y in range(0, h1, 2)) == 0
    blue, orange = (0x1f, 0x77, 0xb4), (0xff, 0x7f, 0x0e)
    seen = {c: sum(px1(x, y) == c for x in range(w1) for y in range(60, h1)) for c in
            (blue, orange)}
    assert seen[blue] > 100 and seen[orange] > 100

# python/tests/test_runs.py - Model.poincare, Model.lyapunov, Model.flow, Model.animate:
# the physics of each result, then the same numbers as the CLI's on the same
# model (`qdot poincare` CSV, `qdot lyapunov --format json`, `qdot animate`'s
# page).  Physics: the oscillator x = cos(w t), w = sqrt(k/m), crosses x = 0
# upwards at w t = 3 pi/2 + 2 pi j with x' = w (Goldstein ch. 6); the
# inverted oscillator x'' = x has the exponents +1 and -1 (the eigenvalues of
# its linear flow; Ott, Chaos in Dynamical Systems ch. 4); the pendulum's bob
# stays at the rod's length from the pivot.
import csv
import io
import math
import os
import subprocess

import numpy as np
import pytest

import qdot

from conftest import EXAMPLES
from test_commands import BUILD, OSCILLATOR, PENDULUM, cli, model_file, same


def cli_text(*args):
    exe = os.path.join(BUILD, "qdot")
    if not os.access(exe, os.X_OK):
        pytest.skip("no build/qdot to compare with")
    run = subprocess.run([exe, *args], capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    return run.stdout


def test_poincare_oscillator(tmp_path):
    path = model_file(tmp_path, OSCILLATOR)
    m = qdot.Model.load(path)
    p = m.poincare("x = 0, x' > 0", 3, rtol=1e-12)
    w = math.sqrt(3 / 2)
    assert len(p) == 3 and p.columns == ["t", "x", "x'", "energy"]
    assert p.t == pytest.approx([(1.5 * math.pi + 2 * math.pi * j) / w for j in range(3)],
                                rel=1e-9)
    assert p["x'"] == pytest.approx([w] * 3, rel=1e-9)
    assert abs(p["x"]).max() < 1e-9
    rows = list(csv.reader(io.StringIO(cli_text("poincare", path, "--section", "x = 0, x' > 0",
                                                "--crossings", "3", "--rtol", "1e-12"))))
    assert rows[0] == p.columns
    assert np.array(rows[1:], dtype=float) == pytest.approx(p.data, rel=1e-12, abs=1e-15)


def test_poincare_fewer_crossings_warns_and_bad_section(tmp_path):
    m = qdot.Model(OSCILLATOR)
    with pytest.warns(UserWarning, match="only 1 of 5 crossings"):
        p = m.poincare("x = 0, x' > 0", 5, t_end=5)
    assert len(p) == 1
    with pytest.raises(qdot.ModelError, match="unknown name 'y'"):
        m.poincare("y = 0", 2)
    with pytest.raises(ValueError):
        m.poincare("x = 0", 0)


INVERTED = "coordinates x\nT = x'^2/2\nV = -x^2/2\ninitial x = 1e-3\n"


def test_lyapunov_inverted_oscillator(tmp_path):
    path = model_file(tmp_path, INVERTED)
    out = qdot.Model.load(path).lyapunov(200, exponents=2)
    lam = out.exponents
    assert isinstance(lam, np.ndarray)
    assert lam[0] == pytest.approx(1, abs=out.errors[0]) and lam[0] == pytest.approx(1, abs=0.01)
    assert lam[1] == pytest.approx(-1, abs=0.01)
    assert abs(lam.sum()) < 1e-9 and out.conservative    # Liouville: the sum is 0
    same(out.json, cli("lyapunov", path, "--t-end", "200", "--exponents", "2"))
    with pytest.raises(ValueError):
        qdot.Model(INVERTED).lyapunov(10, exponents=3)   # 2n = 2


def test_flow_oscillator_and_damped(tmp_path):
    # the oscillator's flow is the rotation [[cos wt, sin wt/w], [-w sin wt, cos wt]]
    # (w = sqrt(k/m)); over the period 2 pi sqrt(m/k) the monodromy is I, both Floquet
    # multipliers 1, and the map is symplectic (Britannica 1911 "Dynamics" sec. 9)
    path = model_file(tmp_path, OSCILLATOR)
    m = qdot.Model.load(path)
    w, t = math.sqrt(3 / 2), 0.7
    out = m.flow(t_end=t, rtol=1e-12, atol=1e-12)
    rot = [[math.cos(w * t), math.sin(w * t) / w], [-w * math.sin(w * t), math.cos(w * t)]]
    assert out.flow_jacobian == pytest.approx(np.array(rot), abs=1e-9)
    assert out.hamiltonian and out.symplectic_error < 1e-9
    per = m.flow(period="2*pi*sqrt(m/k)")
    assert per.period == pytest.approx(2 * math.pi / w, rel=1e-15)
    assert per.monodromy == pytest.approx(np.eye(2), abs=1e-8)
    assert per.multipliers == pytest.approx(np.array([[1, 0], [1, 0]]), abs=1e-8)
    same(per.json, {k: v for k, v in cli("simulate", path, "--variational", "--period",
                                          "2*pi*sqrt(m/k)").items() if k in per.json})
    # Liouville: det = exp(-b t/m) with damping b (examples/damped_oscillator.qd)
    d = qdot.Model.load(os.path.join(EXAMPLES, "damped_oscillator.qd")).flow(t_end=2)
    assert d.flow_det == pytest.approx(math.exp(-0.4 * 2 / 1.2), rel=1e-8)
    assert not d.hamiltonian and d.symplectic_error is None
    with pytest.raises(ValueError):
        m.flow()                                          # neither t_end nor period
    with pytest.raises(qdot.Error, match="given by H"):
        qdot.Model("coordinates x\nmomenta p\nH = p^2/2 + x^2/2\n").flow(t_end=1)


def test_animate_pendulum(tmp_path):
    path = model_file(tmp_path, PENDULUM)
    a = qdot.Model.load(path).animate(2)
    pos = np.array(a.pos, dtype=float).reshape(len(a.t), len(a.points), 3)
    # the bob at the rod's length l = 2 from the pivot in every frame (7 digits)
    assert np.linalg.norm(pos[:, 0, :], axis=1) == pytest.approx(2, rel=1e-6)
    assert a.t[0] == 0 and a.t[-1] == pytest.approx(2)
    assert list(a.plane) == [0, 1]                    # the motion is in the x, y plane
    page = tmp_path / "cli.html"
    cli_text("animate", path, "--t-end", "2", "-o", str(page))
    assert a.html == page.read_text()
    assert a._repr_html_().startswith("<iframe srcdoc=")
    a.save(str(tmp_path / "py.html"))
    assert (tmp_path / "py.html").read_text() == a.html


def test_animate_unknown_point():
    with pytest.raises(qdot.Error, match="draw"):
        qdot.Model.load(os.path.join(EXAMPLES, "double_pendulum.qd")).animate(1, draw="p9")


def test_sweep_grid_oscillator(tmp_path):
    # x(t) = x0 cos(w t), w = sqrt(k/m), m = 2, from rest
    path = model_file(tmp_path, OSCILLATOR)
    m = qdot.Model.load(path)
    out = m.sweep(1, "final, max:x", grid="x=0.5:1:2, k=1:4:2", rtol=1e-12)
    assert out.columns == ["x", "k", "final_x", "final_x'", "max:x"]
    assert out.rows.shape == (4, 5) and out.status == ["ok"] * 4
    for x0, k, xf, vf, xmax in out.rows:
        w = math.sqrt(k / 2)
        assert xf == pytest.approx(x0 * math.cos(w), rel=1e-9)
        assert vf == pytest.approx(-x0 * w * math.sin(w), rel=1e-9)
        assert xmax == pytest.approx(x0)
    same(out.json, cli("sweep", path, "--grid", "x=0.5:1:2, k=1:4:2", "--t-end", "1",
                       "--measure", "final, max:x", "--rtol", "1e-12"))


def test_sweep_section_and_lyapunov(tmp_path):
    m = qdot.Model(OSCILLATOR)
    # upward zeros of cos(w t) at w t = 3 pi/2 + 2 pi j before t = 20: w = sqrt(3/2)
    w = math.sqrt(1.5)
    expect = math.floor((w * 20 - 1.5 * math.pi) / (2 * math.pi)) + 1
    out = m.sweep(20, "poincare-count", grid="x=1:2:2", section="x = 0, x' > 0")
    assert list(out.rows[:, 1]) == [expect, expect]
    with pytest.raises(ValueError, match="needs a section"):
        m.sweep(20, "poincare-count", grid="x=1:2:2")
    inv = qdot.Model(INVERTED).sweep(100, "lyapunov", grid="x=1e-3:2e-3:2")
    assert inv.rows[:, 1] == pytest.approx([1, 1], abs=0.02)
    with pytest.raises(qdot.ModelError, match="grid"):
        m.sweep(1, "final", grid="y=0:1:2")

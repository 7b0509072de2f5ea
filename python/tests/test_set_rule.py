# python/tests/test_set_rule.py - Model.set() follows the library's rule of
# which derivations show the set values in their formulas
# (qd_model_opts_for, docs/design.md "Parameters given from outside"): the
# symbolic ones print the number (as `qdot CMD --set k=5` does), the numeric
# ones keep the parameter a symbol holding the value.  Physics: the harmonic
# oscillator H = p^2/(2m) + k x^2/2, x(t) = cos(sqrt(k/m) t) from x = 1 at
# rest (Goldstein ch. 8), and Kepler's effective potential
# V_eff = -k/r + p^2/(2 m r^2) (Goldstein eq. 3.22).
import math
import os

import pytest

import qdot
from qdot._lib import lib, new

from conftest import ROOT
from test_commands import OSCILLATOR, cli, model_file, num, same

FIXED = ["eom", "hamiltonian", "routh", "integrals", "hj", "metric", "bracket",
         "canonical", "scatter", "field"]
SYMBOLS = ["simulate", "poincare", "sweep", "lyapunov", "animate", "modes", "equilibria",
           "stability", "linearize", "lqr", "zvc", "orbit", "path", "action", "action_of",
           "impulse", "check", "codegen"]


def rule(name):
    opts = new("qd_model_opts")
    assert lib.qd_model_opts_for(opts, name.encode()) == 0, name
    return bool(opts.fix_params)


def test_the_rule_as_documented():
    assert all(rule(n) for n in FIXED)
    assert not any(rule(n) for n in SYMBOLS)
    assert lib.qd_model_opts_for(new("qd_model_opts"), b"hamiltonain") != 0


def test_hamiltonian_shows_the_value(tmp_path):
    path = model_file(tmp_path, OSCILLATOR)
    m = qdot.Model.load(path).set(k=5)
    h = m.hamiltonian()
    # H read back with m = 2 only: k is no longer in it
    x, p = 0.5, 2.0
    assert num(h.H, x=x, p_x=p, m=2) == pytest.approx(p**2 / 4 + 5 * x**2 / 2)
    assert num(h.dp[0], x=x) == pytest.approx(-5 * x)
    same(h.json, cli("hamiltonian", path, "--set", "k=5"))


def test_other_symbolic_commands_match_the_cli(tmp_path):
    path = model_file(tmp_path, OSCILLATOR)
    m = qdot.Model.load(path).set(k=5)
    assert num(m.eom().f[0], x=0.5) == pytest.approx(-2.5)
    same(m.eom().json(), cli("eom", path, "--set", "k=5"))
    same(m.integrals().json, cli("integrals", path, "--set", "k=5"))
    same(m.hj().json, cli("hj", path, "--set", "k=5"))
    kepler = os.path.join(ROOT, "examples", "kepler_polar.qd")
    r = qdot.Model.load(kepler).set(k=2).routh("theta")
    assert num(r.effective_potential, m=1.3, r=2.0, p_theta=1.5) == pytest.approx(
        -2 / 2.0 + 1.5**2 / (2 * 1.3 * 2.0**2))
    same(r.json, cli("routh", kepler, "--ignore", "theta", "--set", "k=2"))


def test_numeric_commands_keep_the_symbol(tmp_path):
    path = model_file(tmp_path, OSCILLATOR)
    m = qdot.Model.load(path).set(k=5)
    ss = m.linearize()
    assert ss.A_exact[1][0] == "-k/m"                 # the symbol, holding 5
    assert ss.A[1][0] == pytest.approx(-2.5)
    ref = cli("linearize", path, "--set", "k=5")
    assert ref["A_exact"] == ss.A_exact and ref["A"][1][0] == pytest.approx(-2.5)
    r = m.simulate(2, rtol=1e-12, dt=1)
    w = math.sqrt(5 / 2)
    assert r["x"] == pytest.approx([math.cos(w * t) for t in r.t], abs=1e-9)
    assert m.params == {"m": 2.0, "k": 5.0}
    # a symbolic result made before does not change what a later set() gives
    assert num(m.set(k=8).hamiltonian().H, x=1, p_x=0, m=2) == pytest.approx(4.0)

# python/tests/test_commands.py - the Model methods that stand for CLI
# commands: each checks the physics of its result, then that its fields are
# the JSON `qdot CMD FILE --format json` prints for the same model (the
# same keys and values: the method calls the printer the command calls).
import math
import os
import subprocess
import json

import numpy as np
import pytest

import qdot

from conftest import ROOT, EXAMPLES

BUILD = os.environ.get("QDOT_BUILD") or os.path.join(ROOT, "build")

OSCILLATOR = """coordinates x
parameters m = 2, k = 3
particle m at (x, 0)
V = k*x^2/2
initial x = 1
"""

PENDULUM = """coordinates theta
parameters m = 1, l = 2, g = 9.81
particle m at l*(sin(theta), -cos(theta))
V = -m*g*l*cos(theta)
initial theta = 0.3
"""


def model_file(tmp_path, text, name="model.qd"):
    path = tmp_path / name
    path.write_text(text)
    return str(path)


def cli(*args):
    """The JSON `qdot ARGS --format json` prints (skip without a build)."""
    exe = os.path.join(BUILD, "qdot")
    if not os.access(exe, os.X_OK):
        pytest.skip("no build/qdot to compare with")
    run = subprocess.run([exe, *args, "--format", "json"], capture_output=True, text=True)
    assert run.returncode in (0, 3), run.stderr
    return json.loads(run.stdout)


def same(py, ref):
    """py (an Output's JSON) equals the CLI's, key by key, numbers to 1e-12."""
    assert list(py) == list(ref)
    for key in ref:
        close(py[key], ref[key], key)


def num(text, **vals):
    """The value of a formula of the model language (a result's string) at
    vals (NAME' written NAME_d), read by SymPy: the tests' own reading."""
    import re
    import sympy
    src = re.sub(r"([A-Za-z_]\w*)'", r"\1_d", text).replace("^", "**")
    names = {k: sympy.Symbol(k) for k in vals}
    return float(sympy.sympify(src, locals=names).subs({names[k]: v for k, v in vals.items()}))


def close(a, b, where):
    if isinstance(b, dict):
        assert isinstance(a, dict) and list(a) == list(b), where
        for k in b:
            close(a[k], b[k], "%s.%s" % (where, k))
    elif isinstance(b, list):
        assert isinstance(a, list) and len(a) == len(b), where
        for i, (x, y) in enumerate(zip(a, b)):
            close(x, y, "%s[%d]" % (where, i))
    elif isinstance(b, float) or (isinstance(b, int) and not isinstance(b, bool)
                                  and isinstance(a, float)):
        assert a == pytest.approx(b, rel=1e-12, abs=1e-12), where
    else:
        assert a == b, where


# ---- hamiltonian -------------------------------------------------------------

def test_hamiltonian_oscillator(tmp_path):
    path = model_file(tmp_path, OSCILLATOR)
    m = qdot.Model.load(path)
    h = m.hamiltonian()
    assert h.momenta == ["p_x"] and h.conserved and h.H_is_energy
    x, p, mass, k = 0.5, 2.0, 2.0, 3.0
    at = m.hamiltonian(at={"x": x, "p_x": p}).output  # H is the formula's attribute
    assert at.H == pytest.approx(p**2 / (2 * mass) + k * x**2 / 2)
    assert at.dq_dt == pytest.approx([p / mass]) and at.dp_dt == pytest.approx([-k * x])
    assert isinstance(at.dq_dt, np.ndarray)
    same(h.json, cli("hamiltonian", path))
    same(at.json, cli("hamiltonian", path, "--at", "x=0.5, p_x=2"))
    assert "\\frac{p_{x}^{2}}{2 m}" in h._repr_latex_()


# ---- routh -------------------------------------------------------------------

def test_routh_kepler():
    path = os.path.join("examples", "kepler_polar.qd")
    m = qdot.Model.load(os.path.join(ROOT, path))
    r = m.routh("theta")
    assert r.ignored == ["theta"] and r.kept == ["r"] and r.conserved
    mass, k, rr, p = 1.3, 4.0, 2.0, 1.5
    assert num(r.effective_potential, k=k, m=mass, r=rr, p_theta=p) == pytest.approx(
        -k / rr + p**2 / (2 * mass * rr**2))
    assert num(r.quadratures["theta'"], m=mass, r=rr, p_theta=p) == pytest.approx(
        p / (mass * rr**2))
    assert r.equations[0].q == "r"
    same(r.json, cli("routh", m._core.file, "--ignore", "theta"))
    assert "\\frac{p_{\\theta}^{2}}" in r._repr_latex_()
    with pytest.raises(ValueError):
        m.routh("r")   # not cyclic: V depends on it
    with pytest.raises(ValueError):
        m.routh("rho")


# ---- integrals ---------------------------------------------------------------

def test_integrals_kepler():
    path = os.path.join(EXAMPLES, "kepler_cartesian.qd")
    out = qdot.Model.load(path).integrals()
    assert out.jacobi.conserved and out.jacobi.equals_energy
    assert out.noether[0].name == "rot" and out.noether[0].conserved
    L = num(out.noether[0].integral, m=1.3, x=1.0, y=0.5, x_d=0.2, y_d=1.5)
    assert L == pytest.approx(1.3 * (1.0 * 1.5 - 0.2 * 0.5))   # m (x y' - y x')
    assert [p.name for p in out.proposed] == ["energy", "Ax", "Ay"]
    assert all(p.conserved for p in out.proposed)
    assert "angular momentum about z" in out.tested
    same(out.json, cli("integrals", path))
    same(qdot.Model.load(path).integrals(search=False).json,
         cli("integrals", path, "--no-search"))


# ---- hj ----------------------------------------------------------------------

def test_hj_oscillator():
    path = os.path.join(EXAMPLES, "hj_oscillator.qd")
    m = qdot.Model.load(path)
    out = m.hj(solve=True)
    assert out.separable and out.constants == ["E"]
    mass, k, E, t = 2.0, 8.0, 1.0, 0.3
    x = num(out.separation[0].motion, k=k, m=mass, E=E, beta_x=0.0, t=t)
    assert x == pytest.approx(math.sqrt(2 * E / k) * math.sin(math.sqrt(k / mass) * t))
    same(out.json, cli("hj", path, "--solve"))
    same(m.hj(energy="h").json, cli("hj", path, "--energy", "h"))
    assert out._repr_latex_().startswith("$$")


# ---- check -------------------------------------------------------------------

def test_check_pendulum(tmp_path):
    path = model_file(tmp_path, PENDULUM)
    out = qdot.Model.load(path).check()
    assert out.ok and out.coordinates == ["theta"]
    assert out.degrees_of_freedom.configurational == 1
    assert out.energy_conserved
    same(out.json, cli("check", path))


# ---- equilibria --------------------------------------------------------------

def test_equilibria_pendulum(tmp_path):
    path = model_file(tmp_path, PENDULUM)
    eqs = qdot.Model.load(path).equilibria()
    assert [e.kind for e in eqs] == ["minimum", "maximum"]
    assert eqs[0].q["theta"] == 0 and eqs[1].q["theta"] == pytest.approx(math.pi)
    assert eqs.method == "exact" and not eqs.continuum
    assert [p.exact.theta for p in eqs.equilibria] == ["0", "pi"]
    assert eqs.equilibria[1].hessian_signs.tolist() == [0, 1, 0]   # one negative direction
    same(eqs.json, cli("equilibria", path))


# ---- linearize ---------------------------------------------------------------

def test_linearize_cart_pendulum():
    path = os.path.join(EXAMPLES, "cart_pendulum.qd")
    ss = qdot.Model.load(path).linearize(about={"th": 0})
    assert ss.states == ["x", "th", "x'", "th'"] and ss.inputs == ["F"]
    growth = math.sqrt(9.81 * 1.1 / 0.5)   # the inverted pendulum falls: sqrt(g (M + m)/(M l))
    assert max(re for re, im in ss.json["eigenvalues"]) == pytest.approx(growth)
    assert ss.controllable and ss.controllability_rank == 4 and ss.uncontrollable_modes == []
    assert ss.output.A.shape == (4, 4) and np.allclose(ss.output.A, ss.A)
    same(ss.json, cli("linearize", path, "--about", "th=0"))


# ---- orbit -------------------------------------------------------------------

def test_orbit_kepler():
    path = os.path.join(EXAMPLES, "kepler_polar.qd")
    m = qdot.Model.load(path)
    o = m.orbit("theta", equation=True)
    mass, k = 1.3, 4.0
    a = o.conic.a
    assert a == pytest.approx(-k / (2 * o.energy))                 # a = -k/(2E)
    assert o.radial_period == pytest.approx(2 * math.pi * math.sqrt(mass * a**3 / k))
    assert o.kind == "bound" and o.advance.theta == pytest.approx(2 * math.pi)
    assert o.turning_points == pytest.approx([a * (1 - o.conic.e), a * (1 + o.conic.e)])
    same(o.json, cli("orbit", path, "--ignore", "theta", "--orbit"))
    o2 = m.orbit(["theta"], at={"r": 1, "theta'": 1.2}, momentum={"p_theta": 1.4})
    assert o2.momenta.p_theta == pytest.approx(1.4)
    same(o2.json, cli("orbit", path, "--ignore", "theta", "--at", "r=1, theta'=1.2",
                      "--momentum", "p_theta=1.4"))
    assert m.orbit("theta", energy=1.0).kind == "unbound"        # E > 0
    with pytest.raises(qdot.Error, match="unknown name 'kk'"):
        m.orbit("theta", energy="kk")


# ---- action ------------------------------------------------------------------

def test_action_oscillators_and_pendulum():
    path = os.path.join(EXAMPLES, "action_anisotropic.qd")
    m = qdot.Model.load(path)
    out = m.action()
    # J = 2 pi E_k/omega_k for each oscillator: E_x = kx/2, E_y = m y'^2/2
    assert out.frequencies.x == pytest.approx(1.0) and out.frequencies.y == pytest.approx(
        math.sqrt(2))
    assert out.actions.x == pytest.approx(2 * math.pi * 0.5 / 1.0)
    assert out.actions.y == pytest.approx(2 * math.pi * 0.5 / math.sqrt(2))
    same(out.json, cli("action", path))
    at = m.action(at={"x": 0.5})
    assert at.actions.x == pytest.approx(2 * math.pi * 0.125)
    same(at.json, cli("action", path, "--at", "x=0.5"))
    # the pendulum from rest at theta0 = 1: T = 4 sqrt(l/g) K(sin(theta0/2))
    pend = os.path.join(EXAMPLES, "action_pendulum.qd")
    out = qdot.Model.load(pend).action()
    k = math.sin(0.5)
    a, b = 1.0, math.sqrt(1 - k * k)
    for _ in range(30):
        a, b = (a + b) / 2, math.sqrt(a * b)
    period = 4 * math.sqrt(1 / 9.81) * math.pi / (2 * a)
    assert out.frequencies.theta == pytest.approx(2 * math.pi / period, rel=1e-9)
    assert out.coordinates[0].kind == "libration"
    same(out.json, cli("action", pend))
    with pytest.raises(ValueError, match="unknown coordinate"):
        m.action(angles=["z"])


# ---- metric ------------------------------------------------------------------

def test_metric_polar():
    path = os.path.join(EXAMPLES, "kepler_polar.qd")
    m = qdot.Model.load(path)
    g = m.metric()
    mass, r = 1.3, 2.0
    assert num(g.metric["theta"]["theta"], m=mass, r=r) == pytest.approx(mass * r**2)
    assert num(g.det, m=mass, r=r) == pytest.approx(mass**2 * r**2)
    # Gamma^r_{theta theta} = -r, Gamma^theta_{r theta} = 1/r
    assert num(g.json["christoffel_second"]["r"]["theta"]["theta"], r=r) == pytest.approx(-r)
    assert num(g.json["christoffel_second"]["theta"]["r"]["theta"], r=r) == pytest.approx(1 / r)
    assert g.chart["jacobian_det"] == "r" and not g.force["given"]
    same(g.json, cli("metric", path))
    f = m.metric(force="0, k")     # a torque k: its physical component k/r
    assert num(f.force["physical"]["theta"], k=4.0, r=r) == pytest.approx(4.0 / r)
    same(f.json, cli("metric", path, "--force", "0, k"))


# ---- bracket -----------------------------------------------------------------

def test_bracket_kepler():
    cart = os.path.join(EXAMPLES, "kepler_cartesian.qd")
    m = qdot.Model.load(cart)
    assert m.bracket("x", "p_x").bracket == "1" and m.bracket("x", "p_y").bracket == "0"
    Lz = "x*p_y - y*p_x"
    assert num(m.bracket(Lz, "x").bracket, y=0.7) == pytest.approx(0.7)   # {Lz, x} = y
    assert m.bracket(Lz, dt=True).dF_dt == "0"                           # conserved
    same(m.bracket(Lz, "x").json, cli("bracket", cart, Lz, "x"))
    polar = os.path.join(EXAMPLES, "kepler_polar.qd")
    rate = qdot.Model.load(polar).bracket("p_r", dt=True)
    k, mass, r, p = 4.0, 1.3, 2.0, 1.5      # p_r' = p_theta^2/(m r^3) - k/r^2
    assert num(rate.dF_dt, k=k, m=mass, r=r, p_theta=p) == pytest.approx(
        p**2 / (mass * r**3) - k / r**2)
    same(rate.json, cli("bracket", polar, "--dt", "p_r"))
    with pytest.raises(qdot.ModelError, match="no place in a function on phase space"):
        m.bracket("x'", "x")
    with pytest.raises(ValueError):
        m.bracket("x")


# ---- canonical ---------------------------------------------------------------

def test_canonical_oscillator():
    path = os.path.join(EXAMPLES, "hj_oscillator.qd")
    m = qdot.Model.load(path)
    # the action-angle map of the oscillator: Q = atan(m w x/p), P = E/w
    Q, P = "atan(sqrt(k*m)*x/p_x)", "(p_x^2 + k*m*x^2)/(2*sqrt(k*m))"
    out = m.canonical(Q=Q, P=P)
    assert out.verdict == "canonical" and out.certainty == "proven"
    same(out.json, cli("canonical", path, "--Q", Q, "--P", P))
    # x -> x^2 is not: [Q, P] = 2x, and the witness is a point where 2x - 1 != 0
    no = m.canonical(Q="x^2", P="p_x")
    assert no.verdict == "not canonical" and no.value == "2*x"
    assert 2 * no.witness.point.x - 1 == pytest.approx(no.witness.value)
    same(no.json, cli("canonical", path, "--Q", "x^2", "--P", "p_x"))
    # p x -> (Q, P) = (p, -x) scaled by 2: [Q, P] = 2, Goldstein's extended map
    assert m.canonical(Q="p_x", P="-2*x").verdict == "scaled"
    # F1 = x Q: p = dF/dx = Q, P = -dF/dQ = -x, and K(Q, P) = k P^2/2 + Q^2/(2 m)
    gen = m.canonical(generator="F1", F="x*Q")
    assert (gen.Q, gen.P) == ("p_x", "-x")
    assert num(gen.K_new, P=0.3, Q=0.4, k=8.0, m=2.0) == pytest.approx(
        8.0 * 0.3**2 / 2 + 0.4**2 / 4)
    same(gen.json, cli("canonical", path, "--generator", "F1", "x*Q"))
    with pytest.raises(ValueError):
        m.canonical(Q="p_x")


# ---- stability ---------------------------------------------------------------

def test_stability_conical_pendulum():
    path = os.path.join(EXAMPLES, "spherical_pendulum.qd")
    m = qdot.Model.load(path)
    out = m.stability(ignore="phi", at={"theta": "pi/3"})
    g, a, th = 9.81, 0.9, math.pi / 3
    rate2 = g / (a * math.cos(th))                     # the conical pendulum: phi'^2 = g/(a cos)
    assert out.steady["phi'"] ** 2 == pytest.approx(rate2)
    # small oscillations about it: w^2 = phi'^2 (1 + 3 cos^2 theta)
    assert out.frequencies[0] == pytest.approx(math.sqrt(rate2 * (1 + 3 * math.cos(th) ** 2)))
    assert out.stable and out.kind == "free" and len(out.steady_motions) == 2
    same(out.json, cli("stability", path, "--ignore", "phi", "--at", "theta=pi/3"))
    with pytest.raises(qdot.Error, match="not cyclic"):
        m.stability(ignore="theta")
    with pytest.raises(ValueError):
        m.stability()
    bowl = os.path.join(EXAMPLES, "rotating_bowl.qd")
    d = qdot.Model.load(bowl).stability(driven="phi' = 2")
    assert d.kind == "driven"
    same(d.json, cli("stability", bowl, "--driven", "phi' = 2"))
    with pytest.raises(qdot.ModelError, match="not a coordinate") as err:
        m.stability(ignore="phi", at={"thta": 1})
    assert err.value.file == "at" and err.value.hint == "did you mean 'theta'?"


def test_stability_scan_sleeping_top():
    # the sleeping top (Britannica 1911 Dynamics sec. 6 (1), seed 004;
    # seed-goldstein-britannica.md B11) is stable while nu^2 > 4 A M g h:
    # with nu = 3, A = 1, M = 1, h = 1/2, up to g = 4.5
    path = os.path.join(EXAMPLES, "sleeping_top.qd")
    top = qdot.Model.load(path)
    s = top.stability(ignore="psi", momentum="p_psi=3", scan="g=1:8")
    assert s.transitions[-1].g == pytest.approx(9 / (4 * 1 * 1 * 0.5), rel=1e-9)
    assert s.transitions[-1].to == "unstable" and s.samples[0].verdict == "stable"
    same(s.json, cli("stability", path, "--ignore", "psi", "--momentum", "p_psi=3",
                     "--scan", "g=1:8"))
    with pytest.raises(qdot.ModelError) as err:
        top.stability(ignore="psi", momentum="p_psi=3", scan="g=1")
    assert err.value.file == "scan"
    with pytest.raises(ValueError, match="steps is the number of steps of scan"):
        top.stability(ignore="psi", steps=3)


# ---- zvc ---------------------------------------------------------------------

def test_zvc_henon_heiles():
    path = os.path.join(EXAMPLES, "henon_heiles.qd")
    z = qdot.Model.load(path).zvc("x=-1:1, y=-1:1", 0.125, cells=100)
    W = lambda x, y: (x**2 + y**2) / 2 + x**2 * y - y**3 / 3   # noqa: E731
    assert [e.kind for e in z.equilibria].count("saddle") == 3
    assert all(e.h == pytest.approx(1 / 6) for e in z.equilibria if e.kind == "saddle")
    assert len(z.curves) == 1 and z.curves[0].closed       # below the escape energy 1/6
    c = z.curves[0]
    assert np.abs(W(c.x, c.y) - 0.125).max() < 1e-3          # on W = h
    same(z.json, cli("zvc", path, "--box", "x=-1:1, y=-1:1", "--level", "0.125",
                     "--cells", "100"))
    with pytest.raises(ValueError):
        qdot.Model.load(path).zvc("x=-1:1, y=-1:1", 0.1, cells=1)


def test_zvc_level_through_a_point_and_at_a_state():
    # Henon-Heiles (examples/henon_heiles.qd): W = (x^2 + y^2)/2 + x^2 y - y^3/3,
    # h = W + (x'^2 + y'^2)/2: through (0.5, 0) at rest, or from the origin
    # with x' = 0.5, the level is 1/8
    path = os.path.join(EXAMPLES, "henon_heiles.qd")
    hh = qdot.Model.load(path)
    through = hh.zvc("x=-1:1, y=-1:1", through={"x": 0.5, "y": 0}, cells=60)
    at = hh.zvc("x=-1:1, y=-1:1", at="x=0, y=0, x'=0.5", cells=60)
    assert through.level == at.level == pytest.approx(0.125, rel=1e-15)
    assert through.json == hh.zvc("x=-1:1, y=-1:1", 0.125, cells=60).json
    same(through.json, cli("zvc", path, "--box", "x=-1:1, y=-1:1", "--through", "x=0.5, y=0",
                           "--cells", "60"))
    with pytest.raises(qdot.ModelError) as err:
        hh.zvc("x=-1:1, y=-1:1", through="x=0.5, x'=1")
    assert err.value.file == "through"
    with pytest.raises(qdot.ArgumentError, match="give the level once"):
        hh.zvc("x=-1:1, y=-1:1", 0.1, through="x=0")
    with pytest.raises(qdot.ModelError) as err:
        hh.zvc("x=-1:1, z=-1:1", 0.1)
    assert err.value.file == "box"



# ---- impulse -----------------------------------------------------------------

def test_impulse_dumbbell():
    path = os.path.join(EXAMPLES, "dumbbell_struck.qd")
    m = qdot.Model.load(path)
    out = m.impulse()
    M, mm, a, f = 3.0, 1.0, 2.0, 1.0
    v = out.velocities_after
    # the blow f along y: momentum M y' + m (y' + a th') = f, none along x
    assert M * v["y'"] + mm * (v["y'"] + a * v["th'"]) == pytest.approx(f)
    assert v["x'"] == 0
    # from rest, T after = (1/2) sum of the generalized impulses times the velocities
    J = out.generalized_impulses
    assert out.kinetic_energy_after == pytest.approx(
        0.5 * sum(J[q] * v[q + "'"] for q in ("x", "y", "th")))
    assert out.theorems.thomson.applies and out.theorems.thomson.holds
    same(out.json, cli("impulse", path))
    same(m.impulse(at={"th": "pi/2"}).json, cli("impulse", path, "--at", "th=pi/2"))
    assert out._repr_latex_().startswith("$$")
    with pytest.raises(ValueError):
        m.impulse(at={"z": 1})
    # Bertrand (Britannica 1911 "Dynamics" B03, examples/chain_struck.qd): the
    # joint made rigid takes the energy from 7 J^2/(4 m) to J^2/m, and with B
    # held it is 3 J^2/(2 m); the model itself keeps no prescription
    chain = os.path.join(EXAMPLES, "chain_struck.qd")
    c = qdot.Model.load(chain)
    assert c.impulse(prescribe="th1' = th2'").kinetic_energy_after == pytest.approx(1.0)
    held = c.impulse(prescribe=["x' = 0, y' = 0"])
    assert held.kinetic_energy_after == pytest.approx(1.5)
    same(held.json, cli("impulse", chain, "--prescribe", "x' = 0, y' = 0"))
    assert c.impulse().kinetic_energy_after == pytest.approx(7 / 4)
    with pytest.raises(ValueError):
        c.impulse(prescribe="x' = , y' = 0")


# ---- scatter -----------------------------------------------------------------

def test_scatter_rutherford():
    path = os.path.join(EXAMPLES, "rutherford.qd")
    m = qdot.Model.load(path)
    k, E, b = 1.0, 1.0, 0.7
    out = m.scatter(E, b=b)
    assert out.deflection == pytest.approx(2 * math.atan(k / (2 * E * b)))   # tan(chi/2)
    assert out.cross_section == pytest.approx((k / (4 * E)) ** 2 / math.sin(out.deflection / 2)
                                              ** 4, rel=1e-8)
    same(out.json, cli("scatter", path, "--energy", "1", "--b", "0.7"))
    th = m.scatter(E, theta=1.0)
    assert th.cross_section == pytest.approx((k / (4 * E)) ** 2 / math.sin(0.5) ** 4, rel=1e-8)
    same(th.json, cli("scatter", path, "--energy", "1", "--theta", "1.0"))
    lab = m.scatter(E, lab_theta=0.5, masses="1,2")
    same(lab.json, cli("scatter", path, "--energy", "1", "--lab-theta", "0.5",
                       "--masses", "1,2"))



def test_scatter_absorbing_and_recoil(tmp_path):
    # Desloge ch. 60 P5 (seed-desloge-B.md T19): an absorbing sphere a >= r*
    # in -k/r^4 captures pi a^2 (1 + k/(E a^4)); ch. 61 P3 (T23): two protons,
    # both counted, Q = (k/E_lab)^2 (sin^-4 + cos^-4) cos, E_lab = 2 E here
    path = model_file(tmp_path, "coordinates r, ph\nparameters m = 1, k = 1\n"
                      "particle m at (r*cos(ph), r*sin(ph))\nV = -k/r^4\n")
    m = qdot.Model.load(path)
    out = m.scatter(1, b=0.5, core=1.5, absorbing=True)
    assert out.kind == "captured"
    assert out.capture_cross_section == pytest.approx(math.pi * 2.25 * (1 + 1 / 1.5 ** 4),
                                                      rel=1e-10)
    same(out.json, cli("scatter", path, "--energy", "1", "--b", "0.5", "--core", "1.5",
                       "--absorbing"))
    ru = qdot.Model.load(os.path.join(EXAMPLES, "rutherford.qd"))
    lab = ru.scatter(1, lab_theta=0.5, masses="2,2", recoil=True)
    El, c, s_ = 2.0, math.cos(0.5), math.sin(0.5)   # reduced mass m = 1 of two m = 2
    assert lab.lab_cross_section == pytest.approx((1 / El) ** 2 * (s_ ** -4 + c ** -4) * c,
                                                  rel=1e-7)


# ---- path --------------------------------------------------------------------

FREE = """coordinates x
parameters m = 1.5
T = m*x'^2/2
"""


def test_path_free_particle_and_pendulum(tmp_path):
    path = model_file(tmp_path, FREE)
    m = qdot.Model.load(path)
    out = m.path("x=0, t=0", {"x": 2, "t": 1})
    p = out.paths[0]
    assert out.count == 1 and p.minimum
    assert p.action == pytest.approx(1.5 * 2**2 / (2 * 1))        # S = m d^2/(2 T)
    assert p.initial_velocities["x'"] == pytest.approx(2)
    assert p.samples[:, 1] == pytest.approx(2 * p.samples[:, 0])  # the straight line
    same(out.json, cli("path", path, "--from", "x=0, t=0", "--to", "x=2, t=1"))
    # the pendulum with omega = pi: past half a period the path has a kinetic
    # focus near t = pi/omega = 1 and is no longer a minimum
    pend = os.path.join(EXAMPLES, "path_pendulum.qd")
    pp = qdot.Model.load(pend).path("th=0.1", "th=0.2, t=1.5")
    assert pp.paths[0].kinetic_foci[0] == pytest.approx(1.0, rel=0.02)
    assert not pp.paths[0].minimum
    same(pp.json, cli("path", pend, "--from", "th=0.1", "--to", "th=0.2, t=1.5"))
    with pytest.raises(ValueError):
        m.path("x=0", "x=1")        # no end time, no energy
    # a free end: m x'(1) = 0 there (the natural boundary condition, Gelfand &
    # Fomin sec. 6), so the free particle stays where it starts, at no action
    fr = m.path("x=0.5, t=0", "x=free, t=1", guess=["x'=3"])
    assert fr.paths[0].initial_velocities["x'"] == pytest.approx(0, abs=1e-9)
    assert fr.paths[0].action == pytest.approx(0, abs=1e-9)
    same(fr.json, cli("path", path, "--from", "x=0.5, t=0", "--to", "x=free, t=1", "--guess",
                      "x'=3"))


# ---- lqr ---------------------------------------------------------------------

def test_lqr_double_integrator():
    A, B = [[0, 1], [0, 0]], [[0], [1]]
    out = qdot.lqr(A, B, "Q = diag(1, 1), R = 1")
    # x'' = u with Q = I, R = 1: K = [1, sqrt 3], closed loop s^2 + sqrt 3 s + 1 = 0
    assert out.K == pytest.approx(np.array([[1, math.sqrt(3)]]))
    eig = sorted((complex(re, im) for re, im in out.closed_loop_eigenvalues),
                 key=lambda z: z.imag)
    assert [(z.real, z.imag) for z in eig] == [
        pytest.approx((-math.sqrt(3) / 2, -0.5)), pytest.approx((-math.sqrt(3) / 2, 0.5))]
    assert out.residual < 1e-12
    same(out.json, cli("lqr", "--A", "[[0, 1], [0, 0]]", "--B", "[[0], [1]]",
                       "--weights", "Q = diag(1, 1), R = 1"))
    assert qdot.lqr(A, B, ([1, 1], 1)).K == pytest.approx(out.K)
    with pytest.raises(qdot.Error, match="not stabilizable") as err:
        qdot.lqr([[1, 0], [0, -1]], B, "Q = 1, R = 1")
    assert err.value.failure == "not stabilizable"
    with pytest.raises(ValueError, match="more than 2 entries"):
        qdot.lqr(A, B, "Q = diag(1, 1, 10), R = 1")


# ---- lorentz, collide ----------------------------------------------------------

def test_lorentz_and_collide_json():
    r = qdot.lorentz((0.6, 0, 0), event=(1, 0.5, 0, 0), velocity=(0, 0.5, 0))
    g = 1 / math.sqrt(1 - 0.36)
    assert r.json["gamma"] == pytest.approx(g)
    assert r.json["event"][:2] == pytest.approx([g * (1 - 0.6 * 0.5), g * (0.5 - 0.6)])
    # the velocity (0, 0.5, 0) seen from the frame: (-V, u/gamma, 0)
    assert r.json["velocity"][:2] == pytest.approx([-0.6, 0.5 / g])
    same(r.json, cli("lorentz", "--frame", "0.6, 0, 0", "--event", "1, 0.5, 0, 0",
                     "--velocity", "0, 0.5, 0"))
    c = qdot.collide([(1, (0.6, 0, 0)), (2, (-0.8, 0, 0))], merge=True)
    E = sum(m / math.sqrt(1 - v * v) for m, v in ((1, 0.6), (2, -0.8)))
    p = sum(m * v / math.sqrt(1 - v * v) for m, v in ((1, 0.6), (2, -0.8)))
    assert c.json["invariant_mass"] == pytest.approx(math.sqrt(E * E - p * p))
    same(c.json, cli("collide", "--particle", "m=1, v=(0.6, 0, 0)", "--particle",
                     "m=2, v=(-0.8, 0, 0)", "--merge"))


# ---- the result object -------------------------------------------------------

def test_output_fields():
    out = qdot.Model.load(os.path.join(EXAMPLES, "kepler_polar.qd")).orbit("theta")
    assert out.keys() == list(out.json) and "conic" in out and "nothing" not in out
    assert out["energy"] == out.energy and isinstance(out.energy, float)
    assert isinstance(out.turning_points, np.ndarray)
    assert isinstance(out.conic, qdot.Fields) and out.conic["a"] == out.conic.a
    assert repr(out).startswith("<qdot.Output orbit: model=")
    with pytest.raises(AttributeError, match="no field 'nothing'"):
        out.nothing
    with pytest.raises(AttributeError):
        out.energy = 1.0
    assert out._repr_latex_() is None         # orbit has no LaTeX printer


def test_hamiltonian_at_reads_as_the_cli(tmp_path):
    # H = p^2/(2m) + k x^2/2; the names --at does not give are 0, not the
    # model's initial x = 1: at p_x = 2 alone H = 4/4 = 1
    path = model_file(tmp_path, OSCILLATOR)
    h = qdot.Model.load(path).hamiltonian(at={"p_x": 2})
    assert h.output.H == pytest.approx(2.0**2 / (2 * 2), rel=1e-15)
    assert h.output.dp_dt == pytest.approx([0.0], abs=0)
    assert h.output.dq_dt == pytest.approx([2.0 / 2], rel=1e-15)
    same(h.json, cli("hamiltonian", path, "--at", "p_x=2"))
    with pytest.raises(qdot.ModelError, match="unknown name") as err:
        qdot.Model.load(path).hamiltonian(at="p_y=1")
    assert err.value.file == "at"


def test_action_of_a_model_given_by_h_takes_its_momenta(tmp_path):
    # H = p^2/(2m) + k q^2/2 at q = 1, p = 0.5: E = 0.625, J = 2 pi E/omega,
    # omega = sqrt(k/m) = 2; q' = p/m = 0.25 gives the same J
    text = "coordinates q\nmomenta p\nparameters m = 2, k = 8\nH = p^2/(2*m) + k*q^2/2\n"
    path = model_file(tmp_path, text)
    m = qdot.Model.load(path)
    E = 0.5**2 / (2 * 2) + 8 / 2
    by_p = m.action(at={"q": 1, "p": 0.5})
    assert by_p.energy == pytest.approx(E, rel=1e-15)
    assert by_p.actions.q == pytest.approx(2 * math.pi * E / 2, rel=1e-12)
    assert m.action(at="q=1, q'=0.25").actions.q == pytest.approx(by_p.actions.q, rel=1e-14)
    same(by_p.json, cli("action", path, "--at", "q=1.0, p=0.5"))
    with pytest.raises(qdot.ModelError, match="unknown name") as err:
        m.action(at="z=1")
    assert err.value.file == "at"

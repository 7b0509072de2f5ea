#!/usr/bin/env python3
"""End-to-end checks of `qdot modes --scan` and `qdot zvc`.

    python3 tests/cli/check_scan_cli.py --build BUILD_DIR

Expected values come from SymPy, not from the code under test:
  - L4 of the restricted three-body problem (Desloge ch. 62 eqs. 75-77,
    seed-desloge-B.md C6): the linearization about (1/2 - mu, sqrt 3/2) has
    det = s^4 + (4 + Wxx + Wyy) s^2 + Wxx Wyy - Wxy^2 (W = U_std); stability
    is lost where the discriminant in s^2 vanishes, solved by SymPy to 30
    digits (Routh's value (1 - sqrt(23/27))/2);
  - the bead on a spinning hoop (Desloge ch. 50 ex. 1 eq. 39, seed 000): the
    bottom's stiffness d^2(V - T0)/dtheta^2 = m g a - m a^2 omega^2 vanishes at
    omega = sqrt(g/a);
  - the inverted pendulum on a spring (examples/inverted_pendulum_spring.qd):
    d^2V/dtheta^2 at the top vanishes at k = m g/l;
  - steady motions (`qdot stability --scan`): the sleeping top (Britannica
    1911 sec. 6 (1), seed 004; seed-goldstein-britannica.md B11) is stable
    while nu^2 > 4 A M g h: SymPy solves for g; circular orbits r = 1 under
    -k r^n (B08, B09): V_eff = p^2/(2 m r^2) + k r^(n+1)/(n+1) with
    p^2 = m k r^(n+3) has V_eff'' = 0 at n = -3 (SymPy), and with theta'
    maintained (V - T0)'' = 0 at n = 1;
  - zero-velocity curves: the Jacobi constants h = W of L1..L5 (collinear
    points by SymPy's nsolve bracketed on the three intervals, seed-desloge-B.md
    pitfall 8; L4, L5 exactly -3/2 + mu (1 - mu)/2), and the topology of the
    Hill regions between them (two ovals and the outer curve below h(L1),
    joined above it; a horseshoe between h(L2) and h(L3); two tadpoles between
    h(L3) and h(L4); nothing above); the circle x^2 + y^2 = 2h of a harmonic
    oscillator;
  - a regression: `qdot stability` on a system with a steady motion where
    the mass matrix vanishes (T = x^2 x'^2/2 + (1 + x^2) phi'^2/2, x = 0) left
    that motion out and then freed library memory with free() (an abort);
    the other two motions are x = +-sqrt(u), 4 (u - 1)(1 + u)^2 = p^2 (SymPy),
    with frequency^2 = V_eff''/x^2;
  - the errors: unknown parameter, empty range, a lost equilibrium (V = x^3/3
    + c x has x = -sqrt(-c) only for c < 0), --steps without --scan, a Jacobi
    integral that is not conserved, a bad box.
Prints "N passed, N failed"; exit 1 on failure.
"""
import argparse
import json
import math
import sys
import tempfile
from pathlib import Path

import sympy as sp

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "util"))
from clicheck import check, run, finish  # noqa: E402  (tests/util/clicheck.py)

EX = Path(__file__).resolve().parents[2] / "examples"


def model(text):
    f = tempfile.NamedTemporaryFile("w", suffix=".qd", delete=False)
    f.write(text)
    f.close()
    return f.name


X, Y, MU = sp.symbols("x y mu", real=True)
W3 = -(X**2 + Y**2) / 2 - (1 - MU) / sp.sqrt((X + MU)**2 + Y**2) \
    - MU / sp.sqrt((X - 1 + MU)**2 + Y**2)


def routh_mu():
    at = {X: sp.Rational(1, 2) - MU, Y: sp.sqrt(3) / 2}
    wxx, wyy, wxy = (sp.diff(W3, a, b).subs(at) for a, b in ((X, X), (Y, Y), (X, Y)))
    b, c = 4 + wxx + wyy, wxx * wyy - wxy**2
    disc = sp.simplify(b**2 - 4 * c)
    return sp.nsolve(disc, MU, 0.04, prec=30)


def scan_l4(qdot):
    rc, out, err = run(qdot, "modes", str(EX / "restricted_three_body.qd"), "--scan",
                       "mu=0.02:0.05", "--steps", "30", "--about", "x = 1/2 - mu, y = sqrt(3)/2",
                       "--format", "json")
    check("l4 rc", rc == 0, err)
    if rc:
        return
    d = json.loads(out)
    mu_c = float(routh_mu())
    tr = d["transitions"]
    check("l4 one transition", len(tr) == 1, tr)
    check("l4 Routh's value", abs(tr[0]["mu"] - mu_c) < 1e-10, (tr[0]["mu"], mu_c))
    check("l4 stable -> unstable", tr[0]["from"] == "stable" and tr[0]["to"] == "unstable", tr)
    check("l4 Routh closed form", abs(mu_c - (1 - math.sqrt(23 / 27)) / 2) < 1e-15)
    check("l4 samples", len(d["samples"]) == 31)
    for s in d["samples"]:
        mu = s["mu"]
        ok = abs(s["equilibrium"]["x"] - (0.5 - mu)) < 1e-10 and \
            abs(s["equilibrium"]["y"] - math.sqrt(3) / 2) < 1e-10 and \
            s["stable"] == (27 * mu * (1 - mu) < 1)
        check(f"l4 sample mu={mu}", ok, s)
    rc, out, err = run(qdot, "modes", str(EX / "restricted_three_body.qd"), "--scan",
                       "mu=0.02:0.05", "--steps", "4", "--about", "x = 1/2 - mu, y = sqrt(3)/2")
    lines = out.splitlines()
    check("l4 text table", rc == 0 and len(lines) == 1 + 1 + 5 + 1, out + err)
    check("l4 text transition", rc == 0 and lines[-1].startswith("transition: mu = 0.0385208965,")
          and lines[-1].endswith("stable -> unstable"), out)


def scan_hoop(qdot):
    th, m, a, g, w = sp.symbols("theta m a g omega", positive=True)
    veff = -m * g * a * sp.cos(th) - m * a**2 * w**2 * sp.sin(th)**2 / 2
    k0 = sp.diff(veff, th, 2).subs(th, 0)
    wc = [r for r in sp.solve(k0, w) if r.is_positive][0]
    wc = float(wc.subs({a: sp.Rational(8, 10), g: sp.Rational(981, 100)}))
    for about in (["--about", "theta=0"], []):
        rc, out, err = run(qdot, "modes", str(EX / "bead_spinning_hoop.qd"), "--scan", "omega=1:6",
                           "--steps", "9", *about, "--format", "json")
        check("hoop rc", rc == 0, err)
        if rc:
            continue
        d = json.loads(out)
        tr = d["transitions"]
        check("hoop transition", len(tr) == 1 and abs(tr[0]["omega"] - wc) < 1e-10, (tr, wc))
        for s in d["samples"]:
            want = 9.81 / 0.8 - s["omega"]**2
            check("hoop w^2", abs(s["min_omega2"] - want) < 1e-9, s)


def scan_inverted(qdot):
    th, m, l, g, k = sp.symbols("theta m l g k", positive=True)
    V = m * g * l * sp.cos(th) + k / 2 * (l * sp.sin(th))**2
    kc = sp.solve(sp.diff(V, th, 2).subs(th, 0), k)[0]
    kc = float(kc.subs({m: sp.Rational(3, 2), l: sp.Rational(7, 10), g: sp.Rational(981, 100)}))
    rc, out, err = run(qdot, "modes", str(EX / "inverted_pendulum_spring.qd"), "--scan",
                       "k=1:50", "--about", "theta=0", "--format", "json")
    check("inverted rc", rc == 0, err)
    if rc:
        return
    tr = json.loads(out)["transitions"]
    check("inverted k = m g/l", len(tr) == 1 and abs(tr[0]["k"] - kc) < 1e-10 * kc, (tr, kc))
    check("inverted unstable -> stable", tr[0]["from"] == "unstable" and tr[0]["to"] == "stable")


def scan_errors(qdot):
    f = str(EX / "restricted_three_body.qd")
    rc, out, err = run(qdot, "modes", f, "--scan", "nu=0.02:0.05")
    check("unknown parameter", rc == 2 and "'nu' is not a parameter" in err, err)
    rc, out, err = run(qdot, "modes", f, "--scan", "mu=0.05:0.02")
    check("empty range", rc == 2 and "give A < B" in err, err)
    rc, out, err = run(qdot, "modes", f, "--steps", "10")
    check("steps without scan", rc == 2 and "--scan" in err, err)
    rc, out, err = run(qdot, "modes", f, "--scan", "mu=0.01:0.02", "--at-equilibrium", "1")
    check("scan with --at-equilibrium", rc == 2, err)
    rc, out, err = run(qdot, "modes", f, "--scan", "mu=0.01:0.02", "--about", "x = y, y = 1")
    # the state reader's one wording, at its place (issue 31)
    check("about not in the parameters", rc == 2 and "only pi, e and the parameters" in err
          and "--about:1:5:" in err, err)
    rc, out, err = run(qdot, "modes", f, "--scan", "mu=0.01:0.02", "--about", "x = 1, z = 1")
    check("about: not a coordinate, located", rc == 2 and "--about:1:8:" in err
          and "unknown name 'z'" in err, err)
    rc, out, err = run(qdot, "modes", f, "--scan", "mu=0.01,0.02")
    check("scan: not a range, located", rc == 2 and "expected a range A:B" in err, err)
    fold = model("coordinates x\nparameters c = -1\nT = x'^2/2\nV = x^3/3 + c*x\n")
    rc, out, err = run(qdot, "modes", fold, "--scan", "c=-1:1", "--steps", "20", "--about",
                       "x = -1")
    check("lost", rc == 1 and "the equilibrium is lost at c = " in err, err)
    if "lost at c = " in err:
        at = float(err.split("lost at c = ")[1].split(":")[0])
        check("lost where the fold is", 0 <= at <= 0.1 + 1e-12, err)


def scan_steady(qdot):
    nu, A, M, g, h = sp.symbols("nu A M g h", positive=True)
    gc = float(sp.solve(nu**2 - 4 * A * M * g * h, g)[0].subs(
        {nu: 3, A: 1, M: 1, h: sp.Rational(1, 2)}))
    rc, out, err = run(qdot, "stability", str(EX / "sleeping_top.qd"), "--ignore", "psi",
                       "--momentum", "p_psi=3", "--scan", "g=1:8", "--steps", "11", "--format",
                       "json")
    check("top rc", rc == 0, err)
    if rc == 0:
        d = json.loads(out)
        tr = d["transitions"]
        check("top g = nu^2/(4 A M h)", len(tr) == 1 and abs(tr[0]["g"] - gc) < 1e-10, (tr, gc))
        check("top stable -> unstable", tr and tr[0]["from"] == "stable"
              and tr[0]["to"] == "unstable", tr)
        check("top upright", all(abs(s["steady_motion"]["a"]) < 1e-12 and
                                 s["steady_motion"]["p_psi"] == 3 for s in d["samples"]))
    r, n, m, k, p, w = sp.symbols("r n m k p w", real=True)
    veff = p**2 / (2 * m * r**2) + k * r**(n + 1) / (n + 1)
    free = sp.diff(veff, r, 2).subs(p**2, m * k * r**(n + 3)).subs({r: 1, m: 1, k: 1})
    ndrv = sp.diff(k * r**(n + 1) / (n + 1) - m * w**2 * r**2 / 2, r, 2).subs(
        w**2, k * r**(n - 1) / m).subs({r: 1, m: 1, k: 1})
    cases = [("free", ["--ignore", "theta"], "n=-4:-2", float(sp.solve(free, n)[0]),
              "unstable", "stable"),
             ("driven", ["--driven", "theta"], "n=0:3", float(sp.solve(ndrv, n)[0]),
              "unstable", "stable")]
    for name, how, rng, nc, frm, to in cases:
        rc, out, err = run(qdot, "stability", str(EX / "power_law_orbit.qd"), "--set", "n=-0.5",
                           *how, "--at", "r=1", "--scan", rng, "--steps", "7", "--format", "json")
        check(f"orbit {name} rc", rc == 0, err)
        if rc:
            continue
        tr = json.loads(out)["transitions"]
        check(f"orbit {name} n = {nc}", len(tr) == 1 and abs(tr[0]["n"] - nc) < 1e-10
              and tr[0]["from"] == frm and tr[0]["to"] == to, (tr, nc))
    rc, out, err = run(qdot, "stability", str(EX / "sleeping_top.qd"), "--ignore", "psi",
                       "--momentum", "p_psi=3", "--steps", "5")
    check("stability steps without scan", rc == 2 and "--scan" in err, err)


def singular_left_out(qdot):
    f = model("coordinates x, phi\nparameters k = 1\nT = x^2*x'^2/2 + (1 + x^2)*phi'^2/2\n"
              "V = k*(x^2 - 1)^2\n")
    rc, out, err = run(qdot, "stability", f, "--ignore", "phi", "--momentum", "p_phi=1",
                       "--format", "json")
    check("singular left out rc", rc == 0, err)
    if rc:
        return
    d = json.loads(out)
    x = sp.symbols("x", positive=True)
    veff = (x**2 - 1)**2 + sp.Rational(1, 2) / (1 + x**2)
    x0 = [r for r in sp.solve(sp.diff(veff, x), x) if r.is_real and r > 0][0]
    w2 = float((sp.diff(veff, x, 2) / x**2).subs(x, x0))
    xs = sorted(m["steady"]["x"] for m in d["steady_motions"])
    check("singular left out motions", len(xs) == 2 and abs(xs[0] + float(x0)) < 1e-10
          and abs(xs[1] - float(x0)) < 1e-10, (xs, x0))
    check("singular left out frequency", abs(d["frequencies"][0]**2 - w2) < 1e-9 * w2,
          (d["frequencies"], w2))


def lagrange_levels():
    mu = sp.Rational(1, 100)
    w = W3.subs(MU, mu)
    dw = sp.diff(w, X).subs(Y, 0)
    pts = [sp.nsolve(dw, X, x0, prec=30) for x0 in (0.85, 1.15, -1.0)]
    levels = [float(w.subs({X: p, Y: 0})) for p in pts]
    l4 = float(sp.Rational(-3, 2) + mu * (1 - mu) / 2)
    return [float(p) for p in pts], levels, l4


def inside(xs, ys, x, y):
    c = False
    n = len(xs)
    for i in range(n):
        j = i - 1
        if (ys[i] > y) != (ys[j] > y) and \
                x < (xs[j] - xs[i]) * (y - ys[i]) / (ys[j] - ys[i]) + xs[i]:
            c = not c
    return c


def zvc(qdot):
    f = str(EX / "restricted_three_body.qd")
    box = "x=-1.6:1.6, y=-1.6:1.6"
    pts, (h1, h2, h3), h4 = lagrange_levels()
    rc, out, err = run(qdot, "zvc", f, "--box", box, "--level", repr(h1), "--format", "json")
    check("zvc rc", rc == 0, err)
    if rc:
        return
    d = json.loads(out)
    eq = d["equilibria"]
    check("zvc five equilibria", len(eq) == 5, eq)
    want = {(round(pts[0], 6), 0.0): h1, (round(pts[1], 6), 0.0): h2,
            (round(pts[2], 6), 0.0): h3, (0.49, round(math.sqrt(3) / 2, 6)): h4,
            (0.49, -round(math.sqrt(3) / 2, 6)): h4}
    for e in eq:
        key = (round(e["x"], 6), round(e["y"], 6) + 0.0)
        check(f"zvc Jacobi constant at {key}", key in want and abs(e["h"] - want[key]) < 1e-10,
              (e, want))
    m1, m2 = (-0.01, 0.001), (0.99, 0.001)
    # (level, closed curves, how many contain each primary, extra point checks)
    cases = [("below L1", h1 - 0.003, 3, [(m1, 2), (m2, 2), ((pts[0], 0), 1)]),
             ("above L1", h1 + 0.003, 2, [(m1, 2), (m2, 2), ((pts[0], 0), 2)]),
             ("horseshoe", (h2 + h3) / 2, 1, [(m1, 0), (m2, 0), ((0.49, 0.866), 1),
                                              ((0.49, -0.866), 1), ((pts[2], 0), 1)]),
             ("tadpoles", (h3 + h4) / 2, 2, [((0.49, 0.866), 1), ((0.49, -0.866), 1),
                                             ((pts[2], 0), 0)]),
             ("above L4", h4 + 0.01, 0, [])]
    for name, level, ncurves, where in cases:
        rc, out, err = run(qdot, "zvc", f, "--box", box, "--level", repr(level), "--cells", "320",
                           "--format", "json")
        if rc:
            check(f"zvc {name} rc", False, err)
            continue
        curves = json.loads(out)["curves"]
        check(f"zvc {name} count", len(curves) == ncurves and all(c["closed"] for c in curves),
              [(c["closed"], len(c["x"])) for c in curves])
        for (x, y), k in where:
            got = sum(inside(c["x"], c["y"], x, y) for c in curves)
            check(f"zvc {name} around ({x:.3f}, {y:.3f})", got == k, got)
    osc = model("coordinates x, y\nparameters k = 1\nT = (x'^2 + y'^2)/2\nV = k/2*(x^2 + y^2)\n")
    rc, out, err = run(qdot, "zvc", osc, "--box", "x=-2:2, y=-2:2", "--at", "x=1, x'=1",
                       "--cells", "200", "--format", "csv")
    rows = [r.split(",") for r in out.splitlines()[1:]]
    r = [math.hypot(float(a), float(b)) for _, a, b in rows]
    check("zvc circle", rc == 0 and rows and max(abs(v - math.sqrt(2)) for v in r) < 1e-3,
          (rc, err, r[:3]))
    check("zvc circle one curve", {c for c, _, _ in rows} == {"1"})


def zvc_errors(qdot):
    damped = model("coordinates x, y\nparameters c = 0.1\nT = (x'^2 + y'^2)/2\n"
                   "V = (x^2 + y^2)/2\ndissipation = c/2*(x'^2 + y'^2)\n")
    rc, out, err = run(qdot, "zvc", damped, "--box", "x=-1:1, y=-1:1", "--level", "1")
    check("zvc not conserved", rc == 2 and "not conserved" in err, err)
    f = str(EX / "restricted_three_body.qd")
    rc, out, err = run(qdot, "zvc", f, "--box", "x=-1:1", "--level", "1")
    check("zvc one-item box", rc == 2 and "--box" in err, err)
    rc, out, err = run(qdot, "zvc", f, "--box", "x=-1:1, x=0:1", "--level", "1")
    check("zvc box twice", rc == 2 and "twice" in err, err)
    rc, out, err = run(qdot, "zvc", f, "--box", "x=-1:1, y=-1:1")
    check("zvc no level", rc == 2 and "--level" in err, err)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", required=True)
    qdot = Path(ap.parse_args().build) / "qdot"
    for t in (scan_l4, scan_hoop, scan_inverted, scan_errors, scan_steady, singular_left_out, zvc, zvc_errors):
        t(qdot)
    return finish()


if __name__ == "__main__":
    sys.exit(main())

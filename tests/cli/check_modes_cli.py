#!/usr/bin/env python3
"""End-to-end checks of `qdot equilibria` and `qdot modes`.

    python3 tests/cli/check_modes_cli.py --build BUILD_DIR

Expected values are textbook results, not output of the code under test:
  - double pendulum, equal masses and lengths (Goldstein ch. 6, seed 002;
    examples/double_pendulum.qd): w^2 = (g/l)(2 -+ sqrt 2), shapes
    theta2/theta1 = +-sqrt 2; equilibria (0,0) minimum, (pi,pi) maximum and
    two saddles; the exact w^2 (printed as an expression) is checked with
    SymPy against the roots of det(K - w^2 M) = 0 for general parameters;
  - three equal masses in a ring of springs (Desloge ch. 66, seed-desloge-D.md
    T33): w^2 = 0 (x3), 3k/2m (x2), 3k/m;
  - rod on an elastic string (Desloge ch. 65 P11, seed-desloge-B.md T59):
    g/w^2 = 7a/3, a/6, a/6 about r = 7a/6;
  - restricted three-body problem (Desloge ch. 62): five equilibria; L4 stable
    for mu = 0.01, unstable for mu = 0.1 (27 mu (1 - mu) < 1); the eigenvalues
    at L1, L2, L3 from eqs. 53-66 and T27's table (seed-desloge-B.md);
  - the motion from --initial for the double pendulum: q(t) from the normal
    coordinates equals the closed-form superposition;
  - the ring with no --about: the equilibrium chosen is the equilateral one
    (from the model's initial state, or of lowest V without one), its w^2
    from SymPy's Hessian, and the choice is said;
  - the bead on a spinning hoop (Desloge ch. 50 Ex. 1 eq. 39): w^2 =
    omega^2 sin^2 th0, labelled exact only at the parameters' values when th0
    = acos(g/(a omega^2)) is numeric, g/a - omega^2 in the parameters at 0.
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
from clicheck import check, run, close, finish  # noqa: E402  (tests/util/clicheck.py)

EX = Path(__file__).resolve().parents[2] / "examples"


def double_pendulum(qdot):
    rc, out, err = run(qdot, "modes", str(EX / "double_pendulum.qd"), "--format", "json")
    check("dp rc", rc == 0, err)
    if rc:
        return
    d = json.loads(out)
    g = 9.81
    w = d["frequencies"]
    check("dp w1", close(w[0], math.sqrt(g * (2 - math.sqrt(2)))), str(w))
    check("dp w2", close(w[1], math.sqrt(g * (2 + math.sqrt(2)))), str(w))
    s1, s2 = d["modes"][0]["shape"], d["modes"][1]["shape"]
    check("dp shape1", close(s1["theta2"] / s1["theta1"], math.sqrt(2)), str(s1))
    check("dp shape2", close(s2["theta2"] / s2["theta1"], -math.sqrt(2)), str(s2))
    check("dp stable", d["stable"] is True)
    check("dp equilibrium", d["equilibrium"] == {"theta1": 0, "theta2": 0}, str(d["equilibrium"]))
    # the exact w^2 against SymPy's roots of det(K - x M) for general parameters
    m1, m2, l1, l2, g_, x = sp.symbols("m1 m2 l1 l2 g x", positive=True)
    M = sp.Matrix([[(m1 + m2) * l1**2, m2 * l1 * l2], [m2 * l1 * l2, m2 * l2**2]])
    K = sp.Matrix([[(m1 + m2) * g_ * l1, 0], [0, m2 * g_ * l2]])
    roots = sorted(sp.solve(sp.Eq((K - x * M).det(), 0), x), key=lambda r: float(
        r.subs({m1: 1.3, m2: 0.7, l1: 0.9, l2: 1.6, g_: 9.81})))
    vals = {m1: 1.3, m2: 0.7, l1: 0.9, l2: 1.6, g_: 9.81}
    for k in range(2):
        text = d["modes"][k].get("omega2_exact")
        check(f"dp exact {k}", text is not None)
        if text is None:
            continue
        e = sp.sympify(text, locals={"g": g_, "m1": m1, "m2": m2, "l1": l1, "l2": l2})
        check(f"dp exact value {k}", close(float(e.subs(vals)), float(roots[k].subs(vals)), 1e-10),
              text)
    rc, out, err = run(qdot, "equilibria", str(EX / "double_pendulum.qd"), "--format", "json")
    d = json.loads(out)
    kinds = [(round(p["equilibrium"]["theta1"], 12), round(p["equilibrium"]["theta2"], 12),
              p["kind"]) for p in d["equilibria"]]
    pi = round(math.pi, 12)
    check("dp equilibria", d["exact"] and kinds == [(0, 0, "minimum"), (0, pi, "saddle"),
                                                    (pi, 0, "saddle"), (pi, pi, "maximum")],
          str(kinds))
    check("dp exact pi", d["equilibria"][3]["exact"] == {"theta1": "pi", "theta2": "pi"})
    # --initial: theta1(0) = 0.01 at rest; q(t) = sum_j a_j Q_j cos(w_j t)
    rc, out, err = run(qdot, "modes", str(EX / "double_pendulum.qd"), "--initial",
                       "theta1=0.01", "--format", "json")
    d = json.loads(out)
    # textbook: with M = [[2,1],[1,1]] (l = m = 1), x(0) = (0.01, 0) splits into the
    # modes (1, sqrt2) and (1, -sqrt2) with weights 0.005 each
    t = 0.7
    w1, w2 = math.sqrt(g * (2 - math.sqrt(2))), math.sqrt(g * (2 + math.sqrt(2)))
    th2 = 0.005 * math.sqrt(2) * (math.cos(w1 * t) - math.cos(w2 * t))
    got = sum(m["shape"]["theta2"] * m["Q0"] * math.cos(m["omega"] * t) for m in d["modes"])
    check("dp initial", close(got, th2, 1e-9), f"{got} {th2}")


def ring(qdot):
    rc, out, err = run(qdot, "modes", str(EX / "ring_three_masses.qd"), "--about",
                       "x1=0, y1=0, x2=1, y2=0, x3=0.5, y3=sqrt(3)/2", "--set", "k=3",
                       "--set", "m=2", "--format", "json")
    check("ring rc", rc == 0, err)
    if rc:
        return
    d = json.loads(out)
    w2 = [m["omega2"] for m in d["modes"]]
    want = [0, 0, 0, 1.5 * 3 / 2, 1.5 * 3 / 2, 3 * 3 / 2]
    check("ring w2", all(abs(a - b) < 1e-9 for a, b in zip(w2, want)), str(w2))
    check("ring multiplicity", [m["multiplicity"] for m in d["modes"]] == [3, 3, 3, 2, 2, 1])
    check("ring verdict", d["stable"] is None and d["verdict"] == "borderline")


def ring_sympy_omega2(k, m, a):
    """w^2 of the spring triangle about the equilateral configuration, from SymPy: the
    Hessian of V = (k/2) sum (d_ij - a)^2 at side a, divided by m (Desloge ch. 66)."""
    xs = sp.symbols("x1 y1 x2 y2 x3 y3", real=True)
    K_, A_ = sp.symbols("k a", positive=True)
    P = [(xs[0], xs[1]), (xs[2], xs[3]), (xs[4], xs[5])]
    V = sum(K_ / 2 * (sp.sqrt((P[i][0] - P[j][0])**2 + (P[i][1] - P[j][1])**2) - A_)**2
            for i, j in ((0, 1), (1, 2), (2, 0)))
    at = dict(zip(xs, (0, 0, A_, 0, A_ / 2, sp.sqrt(3) * A_ / 2)))
    H = sp.hessian(V, xs).subs(at).subs({K_: k, A_: a})
    return sorted(float(sp.nsimplify(ev)) / m for ev, mult in H.eigenvals().items()
                  for _ in range(mult))


def ring_auto(qdot, tmp):
    # No --about: the model's initial state (nearly equilateral) leads to the equilateral
    # triangle, a minimum of V up to the rigid motions; before, the first of the listed
    # equilibria was taken: a collinear one with w^2 = -1.5 (unstable).
    want = ring_sympy_omega2(3, 2, 1)
    check("ring sympy", all(abs(x - y) < 1e-12 for x, y in
                            zip(want, [0, 0, 0, 9 / 4, 9 / 4, 9 / 2])), str(want))
    model = EX / "ring_three_masses.qd"
    no_init = tmp / "ring_no_initial.qd"
    no_init.write_text("".join(l for l in model.read_text().splitlines(True)
                               if not l.startswith("initial")))
    for f, why in ((model, "nearest the model's initial state"), (no_init, "lowest V")):
        rc, out, err = run(qdot, "modes", str(f), "--set", "k=3", "--set", "m=2",
                           "--format", "json")
        check(f"ring auto rc {f.name}", rc == 0, err)
        if rc:
            continue
        d = json.loads(out)
        w2 = [m["omega2"] for m in d["modes"]]
        check(f"ring auto w2 {f.name}", all(abs(x - y) < 1e-9 for x, y in zip(w2, want)),
              str(w2))
        q = d["equilibrium"]
        sides = [math.dist((q[f"x{i}"], q[f"y{i}"]), (q[f"x{j}"], q[f"y{j}"]))
                 for i, j in ((1, 2), (2, 3), (3, 1))]
        check(f"ring auto equilateral {f.name}", all(close(x, 1) for x in sides), str(sides))
        c = d.get("choice", {})
        check(f"ring auto choice {f.name}", why in c.get("reason", "") and c.get("others", 0) > 0,
              str(c))
    rc, out, err = run(qdot, "modes", str(model))
    check("ring auto note", rc == 0 and "qdot: note: modes about" in err and
          "other equilibria" in err and "w^2 = 3," in out, err)


def exact_label(qdot):
    # Bead on a hoop spinning at omega (Desloge ch. 50 Ex. 1 eq. 39): about cos th0 =
    # g/(a omega^2) the frequency^2 is omega^2 sin^2 th0.  That equilibrium is acos of a
    # number made of the parameters' values, so w^2 is exact only at these values; about
    # th = 0 (omega^2 < g/a) it is g/a - omega^2 in the parameters.
    f = str(EX / "bead_spinning_hoop.qd")
    rc, out, err = run(qdot, "modes", f)
    check("hoop label", rc == 0 and "w^2 (exact, mode" not in out and
          "w^2 (exact at these parameter values, mode 1)" in out, out + err)
    rc, out, err = run(qdot, "modes", f, "--format", "json")
    d = json.loads(out)
    g, a, om = 9.81, 0.8, 4.0
    want = om**2 * (1 - (g / (a * om**2))**2)
    mode = d["modes"][0]
    check("hoop w2", close(mode["omega2"], want), str(mode))
    check("hoop exact value", mode.get("omega2_exact_in_parameters") is False and
          close(float(sp.sympify(mode["omega2_exact"])), want, 1e-12), str(mode))
    rc, out, err = run(qdot, "modes", f, "--set", "omega=2", "--format", "json")
    mode = json.loads(out)["modes"][0]
    G, A, W = sp.symbols("g a omega", positive=True)
    e = sp.sympify(mode.get("omega2_exact", "0"), locals={"g": G, "a": A, "omega": W})
    check("hoop symbolic", mode.get("omega2_exact_in_parameters") is True and
          sp.simplify(e - (G / A - W**2)) == 0, str(mode))


def rod(qdot):
    rc, out, err = run(qdot, "modes", str(EX / "rod_elastic_string.qd"), "--set", "a=2",
                       "--format", "json")
    check("rod rc", rc == 0, err)
    if rc:
        return
    d = json.loads(out)
    a, g = 2, 9.81
    check("rod r0", close(d["equilibrium"]["r"], 7 * a / 6), str(d["equilibrium"]))
    lengths = [g / m["omega2"] for m in d["modes"]]
    want = [7 * a / 3, a / 6, a / 6]
    check("rod lengths", all(close(x, y) for x, y in zip(lengths, want)), str(lengths))


# Desloge ch. 62 eqs. 53-66 (seed-desloge-B.md T27, mu = 0.01, w = 1): at a
# collinear point lambda^2 = (Om^2 - 2)/2 +- sqrt(9 Om^4 - 8 Om^2)/2 with
# Om^2 = (1 - mu)/|x + mu|^3 + mu/|x - 1 + mu|^3; one real pair, one imaginary.
T27 = [(1.0087902754, 0.1614765578, 1.0086051771),   # L3, x < -mu
       (5.0652478406, 2.9037378316, 2.3165589900),   # L1, between the primaries
       (3.2352741919, 2.1795542907, 1.8748820534)]   # L2, beyond m2


def collinear_eigenvalues(qdot, f, xs, mu):
    check("3b three collinear", len(xs) == 3, str(xs))
    for x, (om2_t27, real_t27, freq_t27) in zip(xs, T27):
        om2 = (1 - mu) / abs(x + mu)**3 + mu / abs(x - 1 + mu)**3
        root = math.sqrt(9 * om2**2 - 8 * om2) / 2
        real, freq = math.sqrt((om2 - 2) / 2 + root), math.sqrt(root - (om2 - 2) / 2)
        check(f"3b T27 closed form x={x:.6f}", close(om2, om2_t27, 1e-9) and
              close(real, real_t27, 1e-9) and close(freq, freq_t27, 1e-9), (om2, real, freq))
        rc, out, err = run(qdot, "modes", f, "--about", f"x={x!r}, y=0", "--format", "json")
        if rc:
            check(f"3b modes at x={x}", False, err)
            continue
        key = lambda z: (round(z[0], 6), z[1])   # a real part of 1e-17 either sign is 0
        ev = sorted(json.loads(out)["eigenvalues"], key=key)
        want = sorted([[-real, 0], [0, -freq], [0, freq], [real, 0]], key=key)
        check(f"3b T27 eigenvalues x={x:.6f}",
              all(close(a[0], b[0], 1e-10) and close(a[1], b[1], 1e-10)
                  for a, b in zip(ev, want)), (ev, want))


def three_body(qdot):
    f = str(EX / "restricted_three_body.qd")
    rc, out, err = run(qdot, "equilibria", f, "--format", "json")
    check("3b rc", rc == 0, err)
    if rc:
        return
    d = json.loads(out)
    pts = [p["equilibrium"] for p in d["equilibria"]]
    check("3b five", len(pts) == 5, str(pts))
    mu = 0.01
    l4 = [i for i, p in enumerate(pts) if p["y"] > 0.5]
    check("3b L4", len(l4) == 1 and close(pts[l4[0]]["x"], 0.5 - mu, 1e-10) and
          close(pts[l4[0]]["y"], math.sqrt(3) / 2, 1e-10), str(pts))
    # collinear points: F_x = 0 on the axis, checked from the formula directly
    for p in pts:
        if abs(p["y"]) < 1e-12:
            x = p["x"]
            fx = x - (1 - mu) * (x + mu) / abs(x + mu)**3 - mu * (x - 1 + mu) / abs(x - 1 + mu)**3
            check("3b collinear root", abs(fx) < 1e-10, str(x))
    collinear_eigenvalues(qdot, f, sorted(p["x"] for p in pts if abs(p["y"]) < 1e-12), mu)
    n = l4[0] + 1
    for mu_, want in (("0.01", True), ("0.1", False)):
        rc, out, err = run(qdot, "modes", f, "--set", f"mu={mu_}", "--about",
                           f"x={0.5 - float(mu_)}, y=sqrt(3)/2", "--format", "json")
        d = json.loads(out)
        check(f"3b L4 mu={mu_}", rc == 0 and d["stable"] is want and not d["conservative"],
              out + err)
    rc, out, err = run(qdot, "modes", f, "--at-equilibrium", str(n))
    check("3b text", rc == 0 and "stabilized by the gyroscopic terms" in out, out + err)


def usage(qdot):
    rc, out, err = run(qdot, "modes", str(EX / "double_pendulum.qd"), "--about", "nope=1")
    check("usage about", rc == 2 and "unknown name" in err, err)
    rc, out, err = run(qdot, "modes", str(EX / "double_pendulum.qd"), "--at-equilibrium", "9")
    check("usage eq index", rc == 2, err)
    rc, out, err = run(qdot, "equilibria", str(EX / "rod_elastic_string.qd"), "--guess",
                       "r=1.1, phi=0.1, theta=0.1")
    check("near", rc == 0 and "r = 1.1666666666" in out, out + err)
    rc, out, err = run(qdot, "equilibria", str(EX / "double_pendulum.qd"), "--box",
                       "theta1=1:2")
    check("box", rc == 0 and out.startswith("0 equilibria"), out + err)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", required=True)
    qdot = Path(ap.parse_args().build) / "qdot"
    for f in (double_pendulum, ring, rod, three_body, usage, exact_label):
        f(qdot)
    with tempfile.TemporaryDirectory() as tmp:
        ring_auto(qdot, Path(tmp))
    sys.exit(finish())


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""tests/cross/relativistic_hamilton_sympy.py - qdot's H for L not quadratic in q' against SymPy.

    python3 tests/cross/relativistic_hamilton_sympy.py --build BUILD_DIR

For each examples/relativistic_*.qd, SymPy builds L = -m c^2 sqrt(1 - v^2/c^2) - U
itself (Desloge ch. 92 Thm 1; seed 000_46d037099a6cfcd7.txt; seed-desloge-D.md
C2, C5, T19, T22, T23, pitfalls P5, P6, P13) and, at random states (q, q') with
|v| < c, the Legendre transform there: p = dL/dq', H = p.q' - L.  `qdot
hamiltonian --format sympy` prints H(q, p), q' = dH/dp and p' = -dH/dq; at
(q, p(q, q')) to 25 digits:
  - qdot's H equals SymPy's p.q' - L (rest energy included: ch. 93 Thm 1);
  - dq/dt is q' (the velocities are recovered from p);
  - dp/dt is dL/dq at (q, q') (Lagrange's equations d/dt dL/dq' = dL/dq, so
    Hamilton's and Lagrange's equations are one motion: ch. 93);
  - the closed forms: the cyclotron's H = sqrt(m^2 c^4 + c^2 (p - e A)^2), the
    E field's sqrt(m^2 c^4 + c^2 p^2) - e E x, Kepler's sqrt(m^2 c^4 + c^2
    (p_r^2 + p_th^2/r^2)) - k/r (T19), the oscillator's sqrt(m^2 c^4 + c^2 p^2)
    + k x^2/2 (T25), also at momenta that no sampled velocity gave;
  - brackets: `qdot bracket --dt` of p_th (Kepler) and of x p_y - y p_x (the
    cyclotron in the symmetric gauge) is 0, of p_x (E field) is e E.
Prints "N passed, N failed"; exit 1 on failure.
"""
import argparse
import json
import random
import re
import subprocess
import sys
from pathlib import Path

import sympy as sp

EX = Path(__file__).resolve().parents[2] / "examples"
DIGITS = 25
STATES = 4
results = {"passed": 0, "failed": 0}


def check(name, ok, detail=""):
    results["passed" if ok else "failed"] += 1
    if not ok:
        print(f"FAIL {name} {detail}")


def run(qdot, *args):
    p = subprocess.run([str(qdot), *args], capture_output=True, text=True, timeout=120)
    return p.returncode, p.stdout, p.stderr


m, c, e, B, E, k = sp.symbols("m c e B E k", positive=True)
x, y, r, th = sp.symbols("x y r th")
xd, yd, rd, thd = sp.symbols("xd yd rd thd")
px, py, pr, pth = sp.symbols("p_x p_y p_r p_th")


def R(v2):
    return -m * c ** 2 * sp.sqrt(1 - v2 / c ** 2)


def rest(p2):
    return sp.sqrt(m ** 2 * c ** 4 + c ** 2 * p2)


# name: (q, q', p, L, parameters, closed-form H(q, p), metric factor of each q'^2)
MODELS = {
    "relativistic_cyclotron": ((x, y), (xd, yd), (px, py),
                               R(xd ** 2 + yd ** 2) + e * B / 2 * (x * yd - y * xd), (m, e, B, c),
                               rest((px + e * B * y / 2) ** 2 + (py - e * B * x / 2) ** 2)),
    "relativistic_E_field": ((x, y), (xd, yd), (px, py), R(xd ** 2 + yd ** 2) + e * E * x,
                             (m, e, E, c), rest(px ** 2 + py ** 2) - e * E * x),
    "relativistic_kepler": ((r, th), (rd, thd), (pr, pth), R(rd ** 2 + r ** 2 * thd ** 2) + k / r,
                            (m, c, k), rest(pr ** 2 + pth ** 2 / r ** 2) - k / r),
    "relativistic_oscillator": ((x,), (xd,), (px,), R(xd ** 2) - k * x ** 2 / 2, (m, k, c),
                                rest(px ** 2) + k * x ** 2 / 2),
}


def random_state(rng, q, qd, pars):
    """Parameters and coordinates in [0.5, 2]; velocities with |v| < 0.9 c."""
    vals = {s: sp.Rational(rng.randint(50, 200), 100) for s in (*pars, *q)}
    raw = [sp.Rational(rng.randint(-100, 100), 100) for _ in qd]
    metric = [vals[q[0]] ** 2 if str(s) == "thd" else 1 for s in qd]
    v2 = sum(a * a * g for a, g in zip(raw, metric))
    scale = sp.Rational(rng.randint(10, 90), 100) * vals[c] / sp.sqrt(max(v2, sp.Rational(1, 10 ** 6)))
    vals.update({s: sp.nsimplify(sp.N(a * scale, 40)) for a, s in zip(raw, qd)})
    return vals


def qdot_hamiltonian(qdot, name, q, p, pars):
    """qdot's H, dq/dt, dp/dt as SymPy expressions in our plain symbols."""
    rc, out, err = run(qdot, "hamiltonian", str(EX / f"{name}.qd"), "--format", "sympy")
    check(f"{name} hamiltonian rc", rc == 0, err)
    if rc:
        return None
    ns = {}
    exec(out, ns)  # qdot's own sympy output: plain assignments of SymPy objects
    t = ns["t"]
    plain = {ns[str(s)](t): s for s in q}
    plain.update({ns[str(s)]: s for s in (*p, *pars)})
    conv = lambda ex: sp.sympify(ex).subs(plain)
    return conv(ns["H"]), [conv(a) for a in ns["dq_dt"]], [conv(a) for a in ns["dp_dt"]]


def model(qdot, rng, name):
    q, qd, p, L, pars, closed = MODELS[name]
    got = qdot_hamiltonian(qdot, name, q, p, pars)
    if got is None:
        return
    H, dq, dp = got
    pdef = [sp.diff(L, v) for v in qd]
    Hsym = sum(a * v for a, v in zip(pdef, qd)) - L
    for i in range(STATES):
        vals = random_state(rng, q, qd, pars)
        at = {s: vals[s] for s in (*q, *pars)}
        at.update({pp: sp.N(a.subs(vals), 40) for pp, a in zip(p, pdef)})
        num = lambda ex, where: sp.N(ex.subs(where), DIGITS)
        dH = abs(num(H, at) - num(Hsym, vals))
        check(f"{name} H = p.q' - L at state {i}", dH < 1e-20, str(dH))
        for j, v in enumerate(qd):
            d = abs(num(dq[j], at) - vals[v])
            check(f"{name} dq/dt[{j}] = q' at state {i}", d < 1e-20, str(d))
            d = abs(num(dp[j], at) - num(sp.diff(L, q[j]), vals))
            check(f"{name} dp/dt[{j}] = dL/dq at state {i}", d < 1e-20, str(d))
        # any momentum is reachable (|v| < c for every p): the closed form there
        anyp = dict(at)
        anyp.update({pp: sp.Rational(rng.randint(-300, 300), 100) for pp in p})
        d = abs(num(H, anyp) - num(closed, anyp))
        check(f"{name} closed-form H at state {i}", d < 1e-20, str(d))


def brackets(qdot):
    for name, F, want in (("relativistic_kepler", "p_th", sp.Integer(0)),
                          ("relativistic_cyclotron", "x*p_y - y*p_x", sp.Integer(0)),
                          ("relativistic_E_field", "p_x", e * E)):
        rc, out, err = run(qdot, "bracket", str(EX / f"{name}.qd"), "--dt", F, "--format",
                           "json")
        check(f"{name} d/dt {F} rc", rc == 0, err)
        if rc == 0:
            got = sp.sympify(json.loads(out)["dF_dt"].replace("^", "**"),
                             locals={"e": e, "E": E, "B": B, "m": m, "c": c, "k": k})
            check(f"{name} d/dt {F}", sp.simplify(got - want) == 0, str(got))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", required=True)
    qdot = Path(ap.parse_args().build) / "qdot"
    rng = random.Random(20261127)
    for name in sorted(MODELS):
        model(qdot, rng, name)
    brackets(qdot)
    print(f"{results['passed']} passed, {results['failed']} failed")
    sys.exit(1 if results["failed"] else 0)


if __name__ == "__main__":
    main()

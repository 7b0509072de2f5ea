#!/usr/bin/env python3
"""tests/cross/relativistic_eom_sympy.py - the relativistic examples' equations against SymPy.

    python3 tests/cross/relativistic_eom_sympy.py --build BUILD_DIR

For each examples/relativistic_*.qd, SymPy builds the Lagrangian itself from
Desloge ch. 92 Thm 1, L = -m c^2 sqrt(1 - v^2/c^2) - U (seed
000_46d037099a6cfcd7.txt; seed-desloge-D.md C5, T23, pitfall P5), written out
below independently of the .qd file, and derives Lagrange's equations
M q'' = f with M = d^2L/dq'dq' and f = dL/dq - (d^2L/dq'dq) q'.  `qdot eom
--format json` prints M and f as strings; at random states with |v| < c and
random positive parameters both must agree to 25 digits (M depends on the
velocities here, which no quadratic-L example exercises).

The cyclotron's canonical momentum p = dL/dq' = m gamma v + e A gives
H = p.q' - L = sqrt(m^2 c^4 + c^2 (p - e A)^2) (Desloge ch. 93; T22, P6): SymPy
checks that identity at the same states, and `qdot bracket` must give the
brackets of the kinetic momenta pi = p - e A: [pi_x, pi_y] = e B,
[x, pi_x] = 1.
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


def R(v2):
    """Desloge ch. 92's relativistic kinetic term."""
    return -m * c ** 2 * sp.sqrt(1 - v2 / c ** 2)


# name: (coordinates, velocities, L, parameters, states(rng) -> {q, qd} with |v| < c)
MODELS = {
    "relativistic_cyclotron": ((x, y), (xd, yd),
                               R(xd ** 2 + yd ** 2) + e * B / 2 * (x * yd - y * xd),
                               (m, e, B, c)),
    "relativistic_E_field": ((x, y), (xd, yd), R(xd ** 2 + yd ** 2) + e * E * x, (m, e, E, c)),
    "relativistic_kepler": ((r, th), (rd, thd), R(rd ** 2 + r ** 2 * thd ** 2) + k / r,
                            (m, c, k)),
    "relativistic_oscillator": ((x,), (xd,), R(xd ** 2) - k * x ** 2 / 2, (m, k, c)),
}


def lagrange(q, qd, L):
    n = len(q)
    M = sp.Matrix(n, n, lambda i, j: sp.diff(L, qd[i], qd[j]))
    f = sp.Matrix([sp.diff(L, q[i]) - sum(sp.diff(L, qd[i], q[j]) * qd[j] for j in range(n))
                   for i in range(n)])
    return M, f


def reader(q, qd, pars):
    """qdot's printed syntax (x', ^) as a SymPy expression in our symbols."""
    names = {str(s): s for s in (*q, *pars)}
    names.update({f"{s}_d": v for s, v in zip(q, qd)})

    def read(text):
        text = re.sub(r"(\w+)'", r"\1_d", text).replace("^", "**")
        return sp.sympify(text, locals=names)
    return read


def random_state(rng, q, qd, pars):
    """Parameters in [0.5, 2], coordinates in [0.5, 2], velocities with |v| < 0.9 c."""
    vals = {p: sp.Rational(rng.randint(50, 200), 100) for p in pars}
    vals.update({s: sp.Rational(rng.randint(50, 200), 100) for s in q})
    # the speed: |v|^2 = sum of the metric's terms; scale the velocities below c
    raw = [sp.Rational(rng.randint(-100, 100), 100) for _ in qd]
    v2 = sum(a * a * (vals[q[0]] ** 2 if str(s) == "thd" else 1) for a, s in zip(raw, qd))
    scale = sp.Rational(rng.randint(10, 90), 100) * vals.get(c, 1) / sp.sqrt(max(v2, 1e-6))
    vals.update({s: sp.nsimplify(sp.N(a * scale, 30)) for a, s in zip(raw, qd)})
    return vals


def model_eom(qdot, rng, name):
    q, qd, L, pars = MODELS[name]
    rc, out, err = run(qdot, "eom", str(EX / f"{name}.qd"), "--format", "json")
    check(f"{name} eom rc", rc == 0, err)
    if rc:
        return
    d = json.loads(out)
    check(f"{name} coordinates", d["coordinates"] == [str(s) for s in q], str(d["coordinates"]))
    read = reader(q, qd, pars)
    Mq = sp.Matrix([[read(a) for a in row] for row in d["mass_matrix"]])
    fq = sp.Matrix([read(a) for a in d["forcing"]])
    M, f = lagrange(q, qd, L)
    for i in range(STATES):
        vals = random_state(rng, q, qd, pars)
        dM = max(abs(sp.N((Mq - M)[j].subs(vals), DIGITS)) for j in range(len(M)))
        df = max(abs(sp.N((fq - f)[j].subs(vals), DIGITS)) for j in range(len(f)))
        scale = 1 + max(abs(sp.N(a.subs(vals), DIGITS)) for a in (*M, *f))
        check(f"{name} M at state {i}", dM < 1e-20 * scale, f"{dM} at {vals}")
        check(f"{name} f at state {i}", df < 1e-20 * scale, f"{df} at {vals}")


def cyclotron_hamiltonian(rng):
    """H = p.q' - L equals sqrt(m^2 c^4 + c^2 (p - e A)^2) at p = dL/dq'."""
    q, qd, L, pars = MODELS["relativistic_cyclotron"]
    p = [sp.diff(L, v) for v in qd]
    H = sum(a * v for a, v in zip(p, qd)) - L
    A = (-B * y / 2, B * x / 2)
    closed = sp.sqrt(m ** 2 * c ** 4 + c ** 2 * sum((a - e * b) ** 2 for a, b in zip(p, A)))
    for i in range(STATES):
        vals = random_state(rng, q, qd, pars)
        diff = abs(sp.N((H - closed).subs(vals), DIGITS))
        check(f"cyclotron H closed form at state {i}", diff < 1e-20, str(diff))


def cyclotron_brackets(qdot):
    path = str(EX / "relativistic_cyclotron.qd")
    for F, G, want in (("p_x + e*B*y/2", "p_y - e*B*x/2", e * B),
                       ("x", "p_x + e*B*y/2", sp.Integer(1)),
                       ("x*p_y - y*p_x", "x^2 + y^2", sp.Integer(0))):
        rc, out, err = run(qdot, "bracket", path, F, G, "--format", "json")
        check(f"bracket [{F}, {G}] rc", rc == 0, err)
        if rc == 0:
            got = sp.sympify(json.loads(out)["bracket"].replace("^", "**"),
                             locals={"e": e, "B": B})
            check(f"bracket [{F}, {G}]", sp.simplify(got - want) == 0, str(got))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", required=True)
    qdot = Path(ap.parse_args().build) / "qdot"
    rng = random.Random(20261126)
    for name in sorted(MODELS):
        model_eom(qdot, rng, name)
    cyclotron_hamiltonian(rng)
    cyclotron_brackets(qdot)
    print(f"{results['passed']} passed, {results['failed']} failed")
    sys.exit(1 if results["failed"] else 0)


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""`qdot form EXPR --vars ... --homogeneity` against Desloge vol. 2 App. 20
(Euler's theorem, p. 914; seed 000_46d037099a6cfcd7.txt; reference
seed-desloge-D.md App. 20, C14 and T27) and SymPy.

    python3 tests/cli/check_homogeneity_cli.py --build BUILD_DIR

App. 20 eq. 1: f is homogeneous of degree n in x_1..x_r (the other symbols
passive) when f(lambda x) = lambda^n f(x) for every lambda > 0; eq. 2
(Euler): then sum x_i df/dx_i = n f.  Each degree printed is checked by
SymPy with lambda positive (f(lambda x) - lambda^n f(x) simplifies to 0) and
the printed Euler sum against SymPy's; each "not homogeneous" by its
witness: f, f(2x), f(4x) are real there (mpmath, 50 digits) and
f(x) f(4x) - f(2x)^2, 0 for every homogeneous f, is the printed value, not 0.
T27: T = m/2 (r'^2 + r^2 phi'^2) has degree 2 in the velocities (so
sum q' dT/dq' = 2T), -m c sqrt(c^2 t'^2 - x'^2) degree 1 (t' written y': t is qdot's time, t' = 1), the relativistic
-m c^2 sqrt(1 - v^2/c^2) none.
Prints "N passed, N failed"; exit 1 on failure.
"""
import argparse
import json
import os
import subprocess
import sys

import mpmath
import sympy as sp

results = {"passed": 0, "failed": 0}


def check(name, ok, detail=""):
    results["passed" if ok else "failed"] += 1
    if not ok:
        print(f"FAIL {name} {detail}")


def run(qdot, *args):
    p = subprocess.run([qdot, *args], capture_output=True, text=True, timeout=120)
    return p.returncode, p.stdout, p.stderr


def sym(text, names):
    """Model-language text in SymPy: r' becomes the symbol r_d."""
    for n in sorted(names, key=len, reverse=True):
        text = text.replace(n + "'", n + "_d")
    loc = {n: sp.Symbol(n) for n in names}
    loc.update({n + "_d": sp.Symbol(n + "_d") for n in names})
    return sp.sympify(text.replace("^", "**"), locals=loc)


def homog(qdot, expr, variables):
    rc, out, err = run(qdot, "form", expr, "--vars", ", ".join(variables), "--homogeneity",
                       "--format", "json")
    return rc, (json.loads(out) if out.strip() else None), err


NAMES = ["x", "y", "z", "a", "m", "c", "r", "phi", "t", "v"]

# (expression, variables, degree): App. 20 and T27, and the kinds of f the
# definition covers: passive symbols, a symbolic degree, 0, negative and
# fractional degrees, a function of a ratio (degree 0 times x)
YES = [
    ("m/2*(r'^2 + r^2*phi'^2)", ["r'", "phi'"], "2"),        # T27: T, degree 2
    ("-m*c*sqrt(c^2*y'^2 - x'^2)", ["y'", "x'"], "1"),       # T27 (t' as y'): degree 1
    ("x^2*y + y^3/3", ["x", "y"], "3"),
    ("x^2 + a*x*y", ["x", "y"], "2"),                         # a passive
    ("x/y", ["x", "y"], "0"),
    ("sqrt(x^2 + y^2)", ["x", "y"], "1"),
    ("(x^2 + y^2 + z^2)^(-1/2)", ["x", "y", "z"], "-1"),     # the Kepler potential's 1/r
    ("x^(3/2)", ["x"], "3/2"),
    ("x^a", ["x"], "a"),                                      # a symbolic degree
    ("x*exp(x/y)", ["x", "y"], "1"),
    ("x^2*exp(z)", ["x"], "2"),                               # z passive
]
NO = [
    ("x^2 + x", ["x"]),
    ("sin(x)", ["x"]),
    ("x^2 + y", ["x", "y"]),
    ("-m*c^2*sqrt(1 - v^2/c^2)", ["v"]),                     # T27: no degree
    ("log(x)", ["x"]),
]


def test_yes(qdot):
    lam = sp.Symbol("lam", positive=True)
    for expr, xs, deg in YES:
        rc, j, err = homog(qdot, expr, xs)
        name = "%s in %s" % (expr, xs)
        check(name + " rc", rc == 0, err)
        if rc != 0:
            continue
        check(name + " verdict", j["verdict"] == "homogeneous" and j["homogeneous"] is True, str(j))
        check(name + " degree", j["degree"] is not None and
              sp.simplify(sym(j["degree"], NAMES) - sym(deg, NAMES)) == 0, str(j["degree"]))
        f = sym(expr, NAMES)
        v = [sym(x, NAMES) for x in xs]
        n = sym(deg, NAMES)
        scaled = f.subs({x: lam * x for x in v}, simultaneous=True)
        check(name + " f(lambda x) = lambda^n f (App. 20 eq. 1)",
              sp.simplify(sp.powsimp(scaled - lam**n * f, force=True)) == 0)
        euler = sum(x * sp.diff(f, x) for x in v)
        check(name + " Euler sum", sp.simplify(sym(j["euler"], NAMES) - euler) == 0, j["euler"])
        check(name + " Euler's theorem (eq. 2)", sp.simplify(euler - n * f) == 0)


def value(f, point):
    mpmath.mp.dps = 50
    subs = {sp.Symbol(k): sp.Rational(v) for k, v in point.items()}
    return sp.N(f.subs(subs), 50)


def test_no(qdot):
    for expr, xs in NO:
        rc, j, err = homog(qdot, expr, xs)
        name = "%s in %s" % (expr, xs)
        check(name + " rc 3 (a certified no)", rc == 3, "%d %s" % (rc, err))
        if not j:
            continue
        check(name + " verdict", j["verdict"] == "not homogeneous" and
              j["homogeneous"] is False and j["degree"] is None, str(j))
        w = j["witness"]
        check(name + " witness", w is not None and j["certainty"] == "nonzero", str(j))
        if not w:
            continue
        f = sym(expr, NAMES)
        v = [sym(x, NAMES) for x in xs]
        vals = [value(f.subs({x: k * x for x in v}, simultaneous=True), w["point"])
                for k in (1, 2, 4)]
        check(name + " f real at the witness", all(x.is_real for x in vals), str(vals))
        d = vals[0] * vals[2] - vals[1] ** 2
        check(name + " f(x) f(4x) - f(2x)^2 there", abs(d - w["value"]) <= 1e-12 * (1 + abs(d))
              and abs(d) > w["radius"], "%s vs %s" % (d, w))


def test_text_and_errors(qdot):
    rc, out, err = run(qdot, "form", "x^2*y + y^3/3", "--vars", "x, y", "--homogeneity")
    check("text", rc == 0 and "homogeneous of degree 3" in out, out + err)
    rc, out, err = run(qdot, "form", "0", "--vars", "x", "--homogeneity", "--format", "json")
    j = json.loads(out) if rc == 0 else {}
    check("0: every degree", rc == 0 and j.get("verdict") == "every degree"
          and j.get("homogeneous") is True and j.get("degree") is None, out + err)
    rc, out, err = run(qdot, "form", "x^2", "--vars", "x, x", "--homogeneity")
    check("x twice: exit 2", rc == 2 and "twice" in err, err)
    rc, out, err = run(qdot, "form", "x^2", "--vars", "pi", "--homogeneity")
    check("pi (the constant): exit 2", rc == 2 and "not a variable name" in err, err)
    rc, out, err = run(qdot, "form", "x^2", "--vars", "t'", "--homogeneity")
    check("t' (= 1): exit 2", rc == 2 and "not a variable name" in err, err)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", required=True)
    a = ap.parse_args()
    qdot = os.path.join(os.path.abspath(a.build), "qdot")
    test_yes(qdot)
    test_no(qdot)
    test_text_and_errors(qdot)
    print("%d passed, %d failed" % (results["passed"], results["failed"]))
    return 1 if results["failed"] else 0


if __name__ == "__main__":
    sys.exit(main())

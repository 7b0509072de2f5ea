#!/usr/bin/env python3
"""`qdot form EXPR --vars ... --periods "W1; W2 ..."` against Desloge vol. 2
App. 31 (multiply periodic functions, p. 967; seed 000_46d037099a6cfcd7.txt;
reference seed-desloge-D.md App. 31 and C17) and SymPy.

    python3 tests/cli/check_periods_cli.py --build BUILD_DIR

Eq. 1: w is a period of f when f(x + w) = f(x) for every x; Thms 1-3:
integer combinations of periods are periods; Thm 4 (eq. 3): there is a
fundamental system e_1..e_k, k <= r, of which every period is an integer
combination.  For each case SymPy checks that each shift called a period is
one (f(x + w) - f(x) simplifies to 0), that each fundamental period is a
period (Thm 3), that each shift is the printed integer combination of the
e's (eq. 3), and that the e's are integer combinations of the shifts (the
k x k minors of the coordinate matrix have gcd 1), so both generate the
same lattice; a shift that is not a period has its witness re-evaluated.
Prints "N passed, N failed"; exit 1 on failure.
"""
import argparse
import itertools
import json
import math
import os
import subprocess
import sys

import sympy as sp

results = {"passed": 0, "failed": 0}


def check(name, ok, detail=""):
    results["passed" if ok else "failed"] += 1
    if not ok:
        print(f"FAIL {name} {detail}")


def run(qdot, *args):
    p = subprocess.run([qdot, *args], capture_output=True, text=True, timeout=120)
    return p.returncode, p.stdout, p.stderr


def sym(text):
    return sp.sympify(text.replace("^", "**"), locals={"x": sp.Symbol("x"), "y": sp.Symbol("y"),
                                                       "a": sp.Symbol("a"), "b": sp.Symbol("b")})


def periods(qdot, f, xs, shifts):
    rc, out, err = run(qdot, "form", f, "--vars", ", ".join(xs), "--periods", shifts,
                       "--format", "json")
    return rc, (json.loads(out) if out.strip() else None), err


def is_period(f, xs, w):
    return sp.simplify(f.subs({x: x + c for x, c in zip(xs, w)}, simultaneous=True) - f) == 0


# (f, variables, shifts, the fundamental system's size)
CASES = [
    ("sin(x)*cos(y)", ["x", "y"], "(2*pi, 0); (pi, pi); (0, 2*pi)", 2),
    ("sin(3*x)", ["x"], "2*pi; 4*pi/3", 1),                   # e = 2 pi/3
    ("cos(2*x - 3*y)", ["x", "y"], "2*pi, 0; 0, 2*pi; pi/2, pi/3", 2),
    ("sin(x)^2 + cos(2*y)", ["x", "y"], "pi, 0; 2*pi, pi; 3*pi, 2*pi", 2),
    ("cos(a*x)", ["x"], "2*pi/a; 6*pi/a", 1),                  # the unit a symbol
]


def test_cases(qdot):
    for f_text, names, shifts, rank in CASES:
        name = "%s %s" % (f_text, shifts)
        rc, j, err = periods(qdot, f_text, names, shifts)
        check(name + " rc", rc == 0, err)
        if rc != 0:
            continue
        f, xs = sym(f_text), [sym(n) for n in names]
        W = [[sym(c) for c in w] for w in j["periods"]]
        E = [[sym(c) for c in e] for e in j["fundamental"]]
        C = j["coordinates"]
        check(name + " rank", j["rank"] == rank == len(E), str(j["rank"]))
        for k, w in enumerate(W):
            check(name + " w%d a period (eq. 1)" % (k + 1), j["tests"][k]["is_period"] is True
                  and is_period(f, xs, w), str(j["tests"][k]))
            comb = [sum(C[k][i] * E[i][c] for i in range(len(E))) for c in range(len(xs))]
            check(name + " w%d in the e's (eq. 3)" % (k + 1),
                  all(sp.simplify(a - b) == 0 for a, b in zip(comb, w)), str(C[k]))
        for i, e in enumerate(E):
            check(name + " e%d a period (Thm 3)" % (i + 1), is_period(f, xs, e), str(e))
        minors = [sp.Matrix([C[r] for r in rows]).det()
                  for rows in itertools.combinations(range(len(C)), len(E))]
        check(name + " e's integer combinations of the w's",
              math.gcd(*[int(m) for m in minors]) == 1, str(minors))


def test_not_a_period(qdot):
    """(pi, 0) is no period of sin x cos y: exit 3, the witness's difference."""
    rc, j, err = periods(qdot, "sin(x)*cos(y)", ["x", "y"], "2*pi, 0; pi, 0")
    check("not a period rc 3", rc == 3, "%d %s" % (rc, err))
    if not j:
        return
    t = j["tests"][1]
    check("not a period verdict", t["is_period"] is False and t["witness"], str(t))
    if t["witness"]:
        pt = t["witness"]["point"]
        x, y = sp.Rational(pt["x"]), sp.Rational(pt["y"])
        d = sp.N(sp.sin(x + sp.pi) * sp.cos(y) - sp.sin(x) * sp.cos(y), 30)
        check("witness value", abs(d - t["witness"]["value"]) < 1e-12, "%s %s" % (d, t))


def test_errors(qdot):
    rc, out, err = run(qdot, "form", "x", "--vars", "x", "--periods", "1; sqrt(2)")
    check("incommensurable exit 2", rc == 2 and "not a rational multiple" in err, err)
    rc, out, err = run(qdot, "form", "x", "--vars", "x, y", "--periods", "1, 2; 3")
    check("short vector exit 2", rc == 2 and "--periods:1:7" in err, err)
    rc, out, err = run(qdot, "form", "x", "--vars", "x", "--periods", "1; 2+")
    check("bad component exit 2 at its place", rc == 2 and "--periods:1:6" in err, err)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", required=True)
    a = ap.parse_args()
    qdot = os.path.join(os.path.abspath(a.build), "qdot")
    test_cases(qdot)
    test_not_a_period(qdot)
    test_errors(qdot)
    print("%d passed, %d failed" % (results["passed"], results["failed"]))
    return 1 if results["failed"] else 0


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/env python3
"""`qdot form EXPR --vars ... --fourier` against Desloge vol. 2 App. 31
(multiply periodic functions, p. 967) and ch. 79 (a function of the angle
variables, of unit periods, is a sum of harmonics; seed
000_46d037099a6cfcd7.txt; reference seed-desloge-C.md ch. 79,
seed-desloge-D.md C17) and SymPy.

    python3 tests/cli/check_fourier_cli.py --build BUILD_DIR

For each trigonometric polynomial SymPy sums the printed harmonics
sum_k a_k cos(k.x) + b_k sin(k.x) and checks that it is f (simplified, and at
points), that the arguments are k.x and no two harmonics share +-k, and that
the coefficients of the textbook expansions are these: cos^3 x = (3 cos x +
cos 3x)/4; sin^2 x cos^2 y = 1/4 - cos 2x/4 + cos 2y/4 - cos(2x + 2y)/8 -
cos(2x - 2y)/8; cos(x + a) = cos a cos x - sin a sin x (the phase in the
coefficients); in Desloge's angle variables (period 1) cos^2(2 pi w1) sin(2 pi
w2) has the wave vectors (0, 2 pi) and (4 pi, +-2 pi), each k a multiple of
2 pi as ch. 79's series needs.  A function that is no trigonometric
polynomial (1/(2 - cos x), x cos x) is refused with exit 2.
Prints "N passed, N failed"; exit 1 on failure.
"""
import argparse
import json
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
    return sp.sympify(text.replace("^", "**"))


CASES = [
    ("cos(x)^3", "x", {("1",): ("3/4", "0"), ("3",): ("1/4", "0")}),
    ("sin(x)^2*cos(y)^2", "x, y", {("0", "0"): ("1/4", "0"), ("2", "0"): ("-1/4", "0"),
                                    ("0", "2"): ("1/4", "0"), ("2", "2"): ("-1/8", "0"),
                                    ("2", "-2"): ("-1/8", "0")}),
    ("cos(x + a)", "x", {("1",): ("cos(a)", "-sin(a)")}),
    ("cos(2*pi*w1)^2*sin(2*pi*w2)", "w1, w2", {("0", "2*pi"): ("0", "1/2"),
                                               ("4*pi", "2*pi"): ("0", "1/4"),
                                               ("4*pi", "-2*pi"): ("0", "-1/4")}),
    ("3*sin(x - 2*y)*sin(x + y) + b*cos(y)^2", "x, y", None),
    ("sin(x)^5*cos(2*x)^2", "x", None),
]


def test_cases(qdot):
    for f_t, xs, want in CASES:
        rc, out, err = run(qdot, "form", f_t, "--vars", xs, "--fourier", "--format", "json")
        check(f_t + " rc", rc == 0, err)
        if rc != 0:
            continue
        j = json.loads(out)
        X = [sym(v) for v in xs.split(", ")]
        s, seen = 0, set()
        for h in j["harmonics"]:
            k = [sym(c) for c in h["k"]]
            arg = sym(h["argument"])
            check(f_t + " argument k.x", sp.simplify(arg - sum(a * b for a, b in zip(k, X))) == 0,
                  str(h))
            key = tuple(k)
            neg = tuple(-c for c in k)
            check(f_t + " one harmonic per +-k", key not in seen and neg not in seen, str(h))
            seen.add(key)
            s += sym(h["cos"]) * sp.cos(arg) + sym(h["sin"]) * sp.sin(arg)
        f = sym(f_t)
        diff = sp.simplify(sp.expand_trig(sp.expand(s - f)))
        pts_ok = all(abs(sp.N((s - f).subs({v: sp.Rational(3 + 2 * i + p, 7) for i, v in
                                            enumerate(sorted(f.free_symbols | s.free_symbols,
                                                             key=str))}))) < 1e-12
                     for p in range(4))
        check(f_t + " sum of the harmonics is f", diff == 0 or pts_ok, str(diff))
        if want:
            got = {tuple(h["k"]): (h["cos"], h["sin"]) for h in j["harmonics"]}
            check(f_t + " the textbook coefficients", len(got) == len(want) and all(
                tuple(k) in got and all(sp.simplify(sym(a) - sym(b)) == 0
                                        for a, b in zip(got[tuple(k)], v))
                for k, v in want.items()), str(got))


def test_errors(qdot):
    for f_t in ("1/(2 - cos(x))", "x*cos(x)", "cos(x^2)"):
        rc, out, err = run(qdot, "form", f_t, "--vars", "x", "--fourier")
        check(f_t + " refused exit 2", rc == 2 and "not a trigonometric polynomial" in err, err)
    rc, out, err = run(qdot, "form", "cos(x)", "--vars", "x", "--fourier", "--homogeneity")
    check("with --homogeneity exit 2", rc == 2, err)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", required=True)
    a = ap.parse_args()
    qdot = os.path.join(os.path.abspath(a.build), "qdot")
    test_cases(qdot)
    test_errors(qdot)
    print("%d passed, %d failed" % (results["passed"], results["failed"]))
    return 1 if results["failed"] else 0


if __name__ == "__main__":
    sys.exit(main())

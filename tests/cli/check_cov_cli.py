#!/usr/bin/env python3
"""End-to-end checks of the calculus of variations in the model language.

    python3 tests/cli/check_cov_cli.py --build BUILD_DIR

`qdot eom --format sympy` on the examples catenary.qd, brachistochrone.qd and
sphere_geodesic.qd is cross-checked against SymPy's own Euler-Lagrange
equations (sympy.calculus.euler.euler_equations) of the integrand written
here from the textbook, not from qdot:
  - the hanging chain, F = w y sqrt(1 + y'^2) - lambda sqrt(1 + y'^2), the
    isoperimetric multiplier a constant (Desloge vol. 2, App. 32, Thm 5;
    seed-desloge-D.md P19);
  - the brachistochrone, F = sqrt((1 + y'^2)/(2 g y)) (Desloge App. 32 Ex. 2,
    seed-desloge-D.md T35);
  - the sphere's geodesics, F = R sqrt(1 + sin(theta)^2 phi'^2) (Byerly
    Art. 48 and Appendix B).
qdot's M q'' - f must equal d/dx dF/dy' - dF/dy at random points.  The text
output names the independent variable and the multiplier; the errors (a second
`independent`, integral() outside a constraint) exit 2 with a located caret.
Prints "N passed, N failed"; exit 1 on failure.
"""
import argparse
import random
import subprocess
import sys
import tempfile
from pathlib import Path

import sympy as sp
from sympy.calculus.euler import euler_equations

EX = Path(__file__).resolve().parents[2] / "examples"
results = {"passed": 0, "failed": 0}


def check(name, ok, detail=""):
    if ok:
        results["passed"] += 1
    else:
        results["failed"] += 1
        print("FAIL %s %s" % (name, detail))


def qdot(build, *args):
    return subprocess.run([str(Path(build).resolve() / "qdot")] + [str(a) for a in args],
                          capture_output=True, text=True, timeout=120)


def qdot_residual(build, example):
    """M*q'' - f of `qdot eom --format sympy` (one coordinate), and its namespace."""
    r = qdot(build, "eom", EX / example, "--format", "sympy")
    if r.returncode != 0:
        raise RuntimeError("qdot eom %s: %s" % (example, r.stderr))
    ns = {}
    exec(r.stdout, ns)  # the printed program defines t, the coordinate, M, f
    q = ns["q"][0]
    return (ns["M"] * ns["q"].diff(ns["t"], 2) - ns["f"])[0], q, ns


def sympy_el(F, y, x):
    """d/dx dF/dy' - dF/dy, from SymPy's euler_equations (dF/dy - d/dx dF/dy' = 0)."""
    (eq,) = euler_equations(F, [y], x)
    return -eq.lhs


def same(name, qd_expr, want, q, t, consts, bounds):
    """Equal at random (t, q, q', q'') in bounds, the constants at random too."""
    rng = random.Random(16)
    worst = 0.0
    for _ in range(8):
        vals = {c: rng.uniform(0.5, 2.0) for c in consts}
        d2, d1 = q.diff(t, 2), q.diff(t)
        pt = {t: rng.uniform(*bounds["t"])}
        sub = [(d2, rng.uniform(-2, 2)), (d1, rng.uniform(-2, 2)), (q, rng.uniform(*bounds["q"]))]
        a = qd_expr.subs(sub).subs(pt).subs(vals)
        b = want.subs(sub).subs(pt).subs(vals)
        worst = max(worst, abs(complex(sp.N(a - b))) / (1 + abs(complex(sp.N(b)))))
    check(name, worst < 1e-12, "worst relative difference %g" % worst)


def check_catenary(build):
    res, q, ns = qdot_residual(build, "catenary.qd")
    t, w, lam = ns["t"], ns["w"], ns["lambda_length"]
    x, y = sp.Symbol("x"), sp.Function("y")
    yp = y(x).diff(x)
    F = w * y(x) * sp.sqrt(1 + yp**2) - lam * sp.sqrt(1 + yp**2)
    want = sympy_el(F, y(x), x).subs(x, t).replace(y, ns[str(q.func)])
    same("catenary: qdot eom = SymPy euler_equations", res, want, q, t, [w, lam],
         {"t": (-1, 1), "q": (-1, 1)})
    # y = lambda/w + a cosh((x - b)/a) solves it (Desloge App. 32 Thm 5)
    a, b = sp.Rational(13, 10), sp.Rational(1, 5)
    sol = lam / w + a * sp.cosh((t - b) / a)
    on = res.subs(q, sol).doit()
    vals = {w: 2, lam: sp.Rational(7, 10)}
    worst = max(abs(float(on.subs(vals).subs(t, tv))) for tv in (-1, -0.3, 0.4, 1))
    check("catenary: lambda/w + a cosh((x - b)/a) is an extremal", worst < 1e-12, "residual %g" % worst)


def check_brachistochrone(build):
    res, q, ns = qdot_residual(build, "brachistochrone.qd")
    t, g = ns["t"], ns["g"]
    x, y = sp.Symbol("x"), sp.Function("y")
    F = sp.sqrt((1 + y(x).diff(x)**2) / (2 * g * y(x)))
    want = sympy_el(F, y(x), x).subs(x, t).replace(y, ns[str(q.func)])
    same("brachistochrone: qdot eom = SymPy euler_equations", res, want, q, t, [g],
         {"t": (0, 2), "q": (0.2, 2)})


def check_geodesic(build):
    res, q, ns = qdot_residual(build, "sphere_geodesic.qd")
    t, R = ns["t"], ns["R"]
    th, phi = sp.Symbol("theta"), sp.Function("phi")
    F = R * sp.sqrt(1 + sp.sin(th)**2 * phi(th).diff(th)**2)
    want = sympy_el(F, phi(th), th).subs(th, t).replace(phi, ns[str(q.func)])
    same("sphere geodesic: qdot eom = SymPy euler_equations", res, want, q, t, [R],
         {"t": (0.3, 2.8), "q": (-3, 3)})
    # the great circle cot(theta) = k cos(phi)
    k = 2
    sol = sp.acos(sp.cot(t) / k)
    on = res.subs(q, sol).doit()
    worst = max(abs(float(on.subs(R, 1).subs(t, tv))) for tv in (0.7, 1.2, 1.9, 2.4))
    check("sphere geodesic: a great circle is an extremal", worst < 1e-12, "residual %g" % worst)


def check_text(build):
    r = qdot(build, "eom", EX / "catenary.qd")
    check("catenary text: exit 0", r.returncode == 0, r.stderr)
    check("catenary text: the independent variable",
          "independent variable: x (written t)\n" in r.stdout, r.stdout)
    check("catenary text: the multiplier",
          "multiplier lambda_length (a constant)" in r.stdout, r.stdout)


def check_errors(build):
    cases = [
        ("independent x\nindependent s\ncoordinates y\nL = y'^2\n",
         ":2:1: error: the independent variable is declared twice", "^~~~~~~~~~~~~"),
        ("independent x\ncoordinates y\nL = integral(y)\n",
         ":3:5: error: integral() is only meaningful in a constraint", "^~~~~~~~"),
    ]
    with tempfile.TemporaryDirectory() as d:
        for i, (text, msg, caret) in enumerate(cases):
            path = Path(d) / ("bad%d.qd" % i)
            path.write_text(text)
            r = qdot(build, "eom", path)
            check("error %d: exit 2" % i, r.returncode == 2, "exit %d" % r.returncode)
            check("error %d: message" % i, msg in r.stderr, r.stderr)
            check("error %d: caret" % i, caret in r.stderr, r.stderr)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", required=True)
    args = ap.parse_args()
    for f in (check_catenary, check_brachistochrone, check_geodesic, check_text, check_errors):
        f(args.build)
    print("%d passed, %d failed" % (results["passed"], results["failed"]))
    return 1 if results["failed"] else 0


if __name__ == "__main__":
    sys.exit(main())

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

The independent variable prints under its own name in every format (issue
16): no `t` anywhere in text, JSON, LaTeX (primes there, not dots) or SymPy
(which binds x, not t); the text equations of the catenary and of
F = sqrt(1 + y'^2)/x (x explicit: the hyperbolic half-plane, whose
extremals are the circles centred on x = 0), read back by SymPy with x as
the variable, are SymPy's Euler-Lagrange equations; `--at` takes x=; the
SymPy scripts of hamiltonian, routh and hj bind x and run; `qdot path` names x in
its samples and marks a focus of multiplicity 2.
Prints "N passed, N failed"; exit 1 on failure.
"""
import argparse
import random
import re
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


def qdot_residual(build, example, var):
    """M*q'' - f of `qdot eom --format sympy` (one coordinate), and its
    namespace, where the independent variable is bound as var (and t is not)."""
    r = qdot(build, "eom", EX / example, "--format", "sympy")
    if r.returncode != 0:
        raise RuntimeError("qdot eom %s: %s" % (example, r.stderr))
    ns = {}
    exec(r.stdout, ns)  # the printed program defines var, the coordinate, M, f
    check("%s sympy: binds %s, not t" % (example, var), var in ns and "t" not in ns, sorted(ns))
    ns["t"] = ns.get(var, ns.get("t"))  # the checks below call the independent variable t
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
    res, q, ns = qdot_residual(build, "catenary.qd", "x")
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
    res, q, ns = qdot_residual(build, "brachistochrone.qd", "x")
    t, g = ns["t"], ns["g"]
    x, y = sp.Symbol("x"), sp.Function("y")
    F = sp.sqrt((1 + y(x).diff(x)**2) / (2 * g * y(x)))
    want = sympy_el(F, y(x), x).subs(x, t).replace(y, ns[str(q.func)])
    same("brachistochrone: qdot eom = SymPy euler_equations", res, want, q, t, [g],
         {"t": (0, 2), "q": (0.2, 2)})


def check_geodesic(build):
    res, q, ns = qdot_residual(build, "sphere_geodesic.qd", "theta")
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
          "independent variable: x\n" in r.stdout, r.stdout)
    check("catenary text: the multiplier",
          "multiplier lambda_length (a constant)" in r.stdout, r.stdout)


T_TOKEN = re.compile(r"(?<![A-Za-z0-9_'])t(?![A-Za-z0-9_(])")


def equations(text):
    """{name: expression text} of the `M[y,y] = ...` and `f[y] = ...` lines."""
    out = {}
    for line in text.splitlines():
        m = re.match(r"\s+([Mf])\[[^]]*\] = (.*)$", line)
        if m:
            out[m.group(1)] = m.group(2)
    return out


def read_back(s, y, x, names):
    """qdot's text syntax (y', y'', ^) parsed by SymPy with y a function of x."""
    s = s.replace("y''", "Y2").replace("y'", "Y1").replace("^", "**")
    loc = dict(names, Y2=y(x).diff(x, 2), Y1=y(x).diff(x), y=y(x), x=x)
    return sp.sympify(s, locals=loc)


def check_printed_in_x(build, path, F, consts, bounds, extremal=None):
    """No t in any format; the text equation read back is SymPy's
    Euler-Lagrange equation of F(x, y, y') (y a Function, x a Symbol)."""
    name = Path(path).name
    for fmt in ("text", "json", "latex", "sympy"):
        r = qdot(build, "eom", path, "--format", fmt)
        body = r.stdout.split("\n", 1)[1] if fmt != "latex" else r.stdout  # past the path line
        check("%s %s: exit 0" % (name, fmt), r.returncode == 0, r.stderr)
        check("%s %s: no t" % (name, fmt), not T_TOKEN.search(body), body)
        if fmt == "latex":
            check("%s latex: primes, not dots" % name, "\\dot" not in body and "y''" in body, body)
    x, y = sp.Symbol("x"), sp.Function("y")
    eq = equations(qdot(build, "eom", path).stdout)
    names = {str(c): c for c in consts}
    res = read_back(eq["M"], y, x, names) * y(x).diff(x, 2) - read_back(eq["f"], y, x, names)
    want = sympy_el(F(x, y(x), y(x).diff(x)), y(x), x)
    rng = random.Random(7)
    worst = 0.0
    for _ in range(8):
        pt = [(y(x).diff(x, 2), rng.uniform(-2, 2)), (y(x).diff(x), rng.uniform(-2, 2)),
              (y(x), rng.uniform(*bounds["q"]))]
        vals = {c: rng.uniform(0.5, 2.0) for c in consts}
        vals[x] = rng.uniform(*bounds["x"])
        a, b = res.subs(pt).subs(vals), want.subs(pt).subs(vals)
        if not sp.N(a - b).is_number:  # a symbol left over (t printed for x)
            worst = float("inf")
            break
        worst = max(worst, abs(float(sp.N(a - b))) / (1 + abs(float(sp.N(b)))))
    check("%s: the text equation in x = SymPy euler_equations" % name, worst < 1e-12,
          "worst relative difference %g" % worst)
    if extremal:
        sol, xs, vals = extremal
        on = res.subs(y(x), sol).doit().subs(vals)
        worst = max(abs(complex(sp.N(on.subs(x, xv)))) if on.subs(x, xv).is_number
                    else float("inf") for xv in xs)
        check("%s: the textbook extremal solves the printed equation" % name, worst < 1e-12,
              "residual %g" % worst)


def check_independent_printing(build):
    w, lam = sp.Symbol("w"), sp.Symbol("lambda_length")
    check_printed_in_x(build, EX / "catenary.qd",
                       lambda x, y, yp: (w * y - lam) * sp.sqrt(1 + yp**2), [w, lam],
                       {"x": (-1, 1), "q": (-1, 1)})
    # x explicit: ds/x, the half-plane's metric; extremals x^2 + (y - b)^2 = R^2
    with tempfile.TemporaryDirectory() as d:
        path = Path(d) / "halfplane.qd"
        path.write_text("independent x\ncoordinates y\nparameters c = 1\n"
                        "L = c*sqrt(1 + y'^2)/x\n")
        c, x = sp.Symbol("c"), sp.Symbol("x")
        b, R = sp.Rational(1, 3), sp.Rational(5, 2)
        check_printed_in_x(build, path, lambda x, y, yp: c * sp.sqrt(1 + yp**2) / x, [c],
                           {"x": (0.5, 2), "q": (-1, 1)},
                           (b + sp.sqrt(R**2 - x**2), (0.4, 1.1, 1.9, 2.3), {c: 1}))
        r = qdot(build, "check", path)
        check("halfplane check: depends on x", "L depends on x explicitly" in r.stdout, r.stdout)
        # --at takes the state in x: y'' = (1 + y'^2) y'/x, the Euler-Lagrange equation
        r = qdot(build, "eom", path, "--at", "y=1, y'=0.5, x=0.25")
        check("halfplane --at x: y'' = (1 + y'^2) y'/x",
              "  y'' = 2.5\n" in r.stdout, r.stdout + r.stderr)


def check_sympy_scripts(build):
    """hamiltonian, routh, hj --format sympy on an `independent x` model:
    the scripts bind x (not t) and run; H = p^2/2 + a x y there."""
    with tempfile.TemporaryDirectory() as d:
        path = Path(d) / "linear.qd"
        path.write_text("independent x\ncoordinates y, z\nparameters a = 2\n"
                        "L = (y'^2 + z'^2)/2 - a*x*y\n")
        for cmd in (["hamiltonian"], ["routh", "--ignore", "z"], ["hj"]):
            r = qdot(build, cmd[0], path, *cmd[1:], "--format", "sympy")
            ns = {}
            try:
                exec(r.stdout, ns)
                ran = True
            except Exception as exc:  # an unbound t or x
                ran = False
                r.stdout += "\n%r" % exc
            check("%s sympy on independent x: runs, binds x not t" % cmd[0],
                  r.returncode == 0 and ran and "x" in ns and "t" not in ns, r.stdout + r.stderr)
            if cmd[0] == "hamiltonian" and ran:
                x, y, a = ns["x"], ns["y"], ns["a"]
                want = (ns["p_y"]**2 + ns["p_z"]**2) / 2 + a * x * y(x)
                check("hamiltonian in x: H = p^2/2 + a x y", sp.simplify(ns["H"] - want) == 0,
                      ns["H"])


def check_path_text(build):
    """qdot path: the samples' header names x; a focus of multiplicity 2 (the
    isotropic plane oscillator at half a period, Gelfand and Fomin ch. 5)
    says so and the path past it is no minimum."""
    brach = EX / "brachistochrone.qd"
    for var in ("x", "t"):  # the end points' variable, either spelling
        r = qdot(build, "path", brach, "--from", "y=1, %s=0.5" % var, "--to", "y=0.8, %s=1" % var)
        if r.returncode == 0:
            break
    check("path brachistochrone: exit 0", r.returncode == 0, r.stderr)
    check("path brachistochrone: samples in x", "samples (x, y;" in r.stdout, r.stdout)
    with tempfile.TemporaryDirectory() as d:
        path = Path(d) / "iso.qd"
        path.write_text("coordinates x, y\nparameters m = 1, k = 1\nT = m*(x'^2 + y'^2)/2\n"
                        "V = k*(x^2 + y^2)/2\n")
        r = qdot(build, "path", path, "--from", "x=1, y=0, t=0", "--to", "x=0, y=1, t=1.2*pi")
        check("path isotropic: a double focus at pi",
              "kinetic foci: 3.14159265359 (multiplicity 2)\n" in r.stdout, r.stdout)
        check("path isotropic: no minimum", "minimum: no\n" in r.stdout, r.stdout)


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
    for f in (check_catenary, check_brachistochrone, check_geodesic, check_text,
              check_independent_printing, check_sympy_scripts, check_path_text, check_errors):
        f(args.build)
    print("%d passed, %d failed" % (results["passed"], results["failed"]))
    return 1 if results["failed"] else 0


if __name__ == "__main__":
    sys.exit(main())

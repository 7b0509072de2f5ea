#!/usr/bin/env python3
"""`qdot form EXPR --vars ... --change "x = X(y), ..." --new "y, ..."` against
Desloge vol. 2 App. 19 (change of variables in an integral, pp. 912-913),
App. 18 (inverse transformations) and ch. 60 eq. 6 (the scattering cross
section through the Jacobian J(s, psi/theta, phi)); seed
000_46d037099a6cfcd7.txt, reference seed-desloge-D.md App. 18-19, C13, P18.

    python3 tests/cli/check_change_cli.py --build BUILD_DIR

For each case SymPy recomputes the Jacobian matrix and determinant from the
map as given, checks J(y/x) J(x/y) = 1, that |J| is J or -J (or abs(J)) as
the printed sign says, the integrand f(x(y)) |J|, and that each printed zero
of J is one.  App. 19 eq. 1 is checked by integrating: int over the unit disk
of x^2 + y^2 = pi/2 in Cartesian coordinates and from the printed integrand
in polar ones; the ball's volume 4 pi/3 from r^2 sin(th).  Ch. 60 eq. 6 with
s = b cot(theta/2) (Rutherford's impact parameter) and psi = phi gives
sigma = f(x(y)) |J| / sin(theta) = b^2/(4 sin^4(theta/2)).  App. 18: y = u^3
has J = 0 at u = 0 without changing sign.
Prints "N passed, N failed"; exit 1 on failure.
"""
import argparse
import json
import os
import subprocess
import sys

import sympy as sp

results = {"passed": 0, "failed": 0}
r, th, ph, b, u, v = sp.symbols("r th ph b u v")
POS = {"r": sp.Symbol("r", positive=True), "b": sp.Symbol("b", positive=True)}


def check(name, ok, detail=""):
    results["passed" if ok else "failed"] += 1
    if not ok:
        print(f"FAIL {name} {detail}")


def run(qdot, *args):
    p = subprocess.run([qdot, *args], capture_output=True, text=True, timeout=120)
    return p.returncode, p.stdout, p.stderr


def sym(text, pos=()):
    loc = {k: POS[k] for k in pos}
    return sp.sympify(text.replace("^", "**"), locals=loc)


def zero(e):
    return sp.simplify(sp.trigsimp(sp.expand(e))) == 0


def change(qdot, f, xs, mapping, new, positive=None):
    args = ["form", f, "--vars", xs, "--change", mapping, "--new", new, "--format", "json"]
    if positive:
        args += ["--positive", positive]
    rc, out, err = run(qdot, *args)
    return rc, (json.loads(out) if rc == 0 else None), err


# (f, old, map, new, positive, sign)
CASES = [
    ("x^2 + y^2", "x, y", "x = r*cos(th), y = r*sin(th)", "r, th", "r", "nonnegative"),
    ("1", "x, y, z", "x = r*sin(th)*cos(ph), y = r*sin(th)*sin(ph), z = r*cos(th)",
     "r, th, ph", None, "unknown"),
    ("s", "s, psi", "s = b*cos(th/2)/sin(th/2), psi = ph", "th, ph", "b", "nonpositive"),
    ("x*y", "x, y", "x = u^2 - v^2, y = 2*u*v", "u, v", None, "nonnegative"),
    ("1", "x, y", "x = u + v, y = u^3", "u, v", None, "nonpositive"),
]


def test_cases(qdot):
    for f_t, old, mapping, new, pos, sign in CASES:
        name = "%s [%s]" % (mapping, new)
        rc, j, err = change(qdot, f_t, old, mapping, new, pos)
        check(name + " rc", rc == 0, err)
        if rc != 0:
            continue
        ps = pos.split(", ") if pos else ()
        X = [sym(n) for n in old.split(", ")]
        Y = [sym(n, ps) for n in new.split(", ")]
        M = {sym(k): sym(e, ps) for k, e in
             (item.split(" = ") for item in mapping.split(", "))}
        Jm = sp.Matrix([[sp.diff(M[x], y) for y in Y] for x in X])
        J = sp.simplify(Jm.det())
        got = sp.Matrix([[sym(c, ps) for c in row] for row in j["jacobian"]])
        check(name + " Jacobian matrix", all(zero(a - c) for a, c in zip(got, Jm)), str(got))
        check(name + " J(x/y)", zero(sym(j["jacobian_det"], ps) - J), j["jacobian_det"])
        check(name + " J(y/x) J(x/y) = 1 (App. 18)",
              zero(sym(j["inverse_det"], ps) * J - 1), j["inverse_det"])
        check(name + " sign", j["sign"] == sign, j["sign"])
        A = sym(j["abs_det"], ps)
        want = {"nonnegative": J, "nonpositive": -J}.get(sign)
        if want is not None:
            check(name + " |J|", zero(A - want), j["abs_det"])
        else:  # |J| agrees with abs(J) at sample points
            pts = [dict(zip(Y, (sp.Rational(k + 2, 7) * (-1) ** k for k in range(len(Y)))))]
            check(name + " |J| = abs(J)", all(abs(sp.N(A.subs(p) - abs(J.subs(p)))) < 1e-12
                                                for p in pts), j["abs_det"])
        fx = sym(f_t, ps).subs(M, simultaneous=True)
        check(name + " f(x(y)) |J|", zero(sym(j["integrand"], ps) - fx * A), j["integrand"])
        for z in j["singular"]:
            lhs = sym(z["lhs"], ps)
            if lhs in Y:  # solved for a variable: J vanishes there
                ok = zero(J.subs(lhs, sym(z["rhs"], ps)))
            else:  # a factor of J left unsolved: it divides J
                ok = sp.denom(sp.cancel(sp.factor(J) / lhs)) == 1
            check(name + " zero %s = %s" % (z["lhs"], z["rhs"]), ok, str(z))
        yield j, ps


def test_integrals(qdot):
    js = list(test_cases(qdot))
    if len(js) < 3:
        return
    (polar, pp), (sph, sp_), (ruth, rp) = js[0], js[1], js[2]
    x, y = sp.symbols("x y")
    cart = sp.integrate(sp.integrate(x**2 + y**2, (y, -sp.sqrt(1 - x**2), sp.sqrt(1 - x**2))),
                        (x, -1, 1))
    R = POS["r"]
    pol = sp.integrate(sym(polar["integrand"], pp), (R, 0, 1), (th, 0, 2 * sp.pi))
    check("App. 19 eq. 1: the disk, pi/2 both ways", zero(cart - sp.pi / 2) and zero(pol - cart),
          "%s %s" % (cart, pol))
    ball = sym(sph["integrand"]).subs(sp.Abs(sp.sin(th)), sp.sin(th))  # 0 < th < pi
    vol = sp.integrate(ball, (r, 0, 1), (th, 0, sp.pi), (ph, 0, 2 * sp.pi))
    check("App. 19 eq. 1: the ball's volume 4 pi/3", zero(vol - 4 * sp.pi / 3), str(vol))
    B = POS["b"]
    sigma = sym(ruth["integrand"], rp) / sp.sin(th)
    check("ch. 60 eq. 6: Rutherford's b^2/(4 sin^4(theta/2))",
          zero(sigma - B**2 / (4 * sp.sin(th / 2)**4)), str(sigma))


def test_app18(qdot):
    rc, out, err = run(qdot, "form", "1", "--vars", "x, y", "--change", "x = u + v, y = u^3",
                       "--new", "u, v")
    check("App. 18 y = u^3: J = 0 at u = 0, no change of sign",
          rc == 0 and "J = 0 where: u = 0" in out and "no split is needed" in out, out + err)


def test_errors(qdot):
    rc, out, err = run(qdot, "form", "1", "--vars", "x, y", "--change", "x = u + v, y = 2*u + 2*v",
                       "--new", "u, v")
    check("J = 0 everywhere exit 1", rc == 1 and "0 everywhere" in err, err)
    rc, out, err = run(qdot, "form", "1", "--vars", "x, y", "--change", "x = u + v, z = 2",
                       "--new", "u, v")
    check("unknown old variable at its place", rc == 2 and "--change:1:12" in err, err)
    rc, out, err = run(qdot, "form", "1", "--vars", "x, y", "--change", "x = u + v", "--new",
                       "u, v")
    check("a variable not given", rc == 2 and "y is not given" in err, err)
    rc, out, err = run(qdot, "form", "1", "--vars", "x, y", "--change", "x = u + y, y = v",
                       "--new", "u, v")
    check("map in an old variable", rc == 2 and "depends on y" in err, err)
    rc, out, err = run(qdot, "form", "1", "--vars", "x, y", "--change", "x = u, y = v")
    check("--change without --new", rc == 2 and "--new" in err, err)
    rc, out, err = run(qdot, "form", "x", "--vars", "x", "--positive", "x", "--change", "x = u",
                       "--new", "u")
    check("--positive then --vars: the same symbol", rc == 0, err)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", required=True)
    a = ap.parse_args()
    qdot = os.path.join(os.path.abspath(a.build), "qdot")
    test_integrals(qdot)
    test_app18(qdot)
    test_errors(qdot)
    print("%d passed, %d failed" % (results["passed"], results["failed"]))
    return 1 if results["failed"] else 0


if __name__ == "__main__":
    sys.exit(main())

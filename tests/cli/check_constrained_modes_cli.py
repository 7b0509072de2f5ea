#!/usr/bin/env python3
"""End-to-end checks of `qdot equilibria`, `qdot modes` and `qdot linearize`
on models that keep holonomic constraints with multipliers (issue 33,
"Capability that users hit first"; issue 37, first bullet).

    python3 tests/cli/check_constrained_modes_cli.py --build BUILD_DIR

Expected values are textbook results or the same system in independent
coordinates, never output of the code under test:
  - the pendulum as x^2 + y^2 = l^2 against the pendulum in an angle:
    bottom (0, -l) a minimum, top (0, l) a maximum; w^2 = g/l (the potential
    m g y is linear: all of it comes from the multiplier's second-order term
    lambda Hess phi); A = [[0, 1], [-g/l, 0]], eigenvalues +-i sqrt(g/l); the
    top w^2 = -g/l; a horizontal force F on the bob: B = (0, 1/m);
  - the double pendulum in Cartesian coordinates with two rod constraints
    against the angle model's two w^2, the roots of det(K - w^2 M) = 0 with
    M = [[(m1+m2) l1^2, m2 l1 l2], [m2 l1 l2, m2 l2^2]],
    K = diag((m1+m2) g l1, m2 g l2) (Goldstein ch. 6);
  - the spherical pendulum on a constraint sphere: w^2 = g/l twice at the
    bottom, two negative directions at the top;
  - SymPy's non-minimal pendulum (sympy/physics/mechanics/tests/
    test_linearize.py, test_linearize_pendulum_lagrange_nonminimal): gravity
    along +x, the point q1 = L, q2 = 0, q2 independent: qdot's A against
    the A of SymPy's LagrangesMethod.linearize computed here;
  - the user's choice of independent coordinates (--independent) and its
    refusals: a coordinate that cannot parametrize the constraint there, a
    wrong count, a point that is not an equilibrium.
Prints "N passed, N failed"; exit 1 on failure.
"""
import argparse
import json
import math
import sys
import tempfile
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "util"))
from clicheck import check, run, close, finish  # noqa: E402  (tests/util/clicheck.py)

G, L = 9.81, 2.0

PEND_XY = f"""parameters m = 1.5, g = {G}, l = {L}
coordinates x, y
T = m/2*(x'^2 + y'^2)
V = m*g*y
constraint rod: x^2 + y^2 = l^2
"""
PEND_TH = f"""parameters m = 1.5, g = {G}, l = {L}
coordinates th
T = m/2*l^2*th'^2
V = -m*g*l*cos(th)
"""
M1, M2, L1, L2 = 1.0, 1.5, 1.0, 0.7
DP_XY = f"""parameters m1 = {M1}, m2 = {M2}, g = {G}, l1 = {L1}, l2 = {L2}
coordinates x1, y1, x2, y2
T = m1/2*(x1'^2 + y1'^2) + m2/2*(x2'^2 + y2'^2)
V = m1*g*y1 + m2*g*y2
constraint rod1: x1^2 + y1^2 = l1^2
constraint rod2: (x2 - x1)^2 + (y2 - y1)^2 = l2^2
"""
SPHERE = f"""parameters m = 0.8, g = {G}, l = {L}
coordinates x, y, z
T = m/2*(x'^2 + y'^2 + z'^2)
V = m*g*z
constraint sphere: x^2 + y^2 + z^2 = l^2
"""
PEND_IN = f"""parameters m = 1.5, g = {G}, l = {L}
coordinates x, y
inputs F
T = m/2*(x'^2 + y'^2)
V = m*g*y
Q[x] = F
constraint rod: x^2 + y^2 = l^2
"""
SYMPY_PEND = """parameters m = 0.9, L = 1.3
coordinates q1, q2
T = m/2*(q1'^2 + q2'^2)
V = -m*9.8*q1
constraint c: q1^2 + q2^2 = L^2
"""


def w2s(m):
    return [x["omega2"] for x in m["modes"]]


def modes_json(qdot, f, *extra):
    rc, out, err = run(qdot, "modes", f, "--format", "json", *extra)
    return rc, (json.loads(out) if rc == 0 else None), err


def pendulum(qdot, d):
    xy, th = d / "pend_xy.qd", d / "pend_th.qd"
    rc, out, err = run(qdot, "equilibria", xy, "--format", "json")
    check("pendulum equilibria rc", rc == 0, err)
    if rc == 0:
        eq = json.loads(out)["equilibria"]
        pts = sorted((round(p["equilibrium"]["x"], 9) + 0.0, round(p["equilibrium"]["y"], 9),
                      p["kind"]) for p in eq)
        check("pendulum equilibria", pts == [(0.0, -L, "minimum"), (0.0, L, "maximum")], str(pts))
    # the same pendulum in an angle: bottom minimum, top maximum
    rc, out, err = run(qdot, "equilibria", th, "--format", "json")
    kinds = sorted(p["kind"] for p in json.loads(out)["equilibria"]) if rc == 0 else []
    check("angle pendulum equilibria", kinds == ["maximum", "minimum"], out + err)
    rc, m, err = modes_json(qdot, xy)
    check("pendulum modes rc", rc == 0, err)
    _, mt, _ = modes_json(qdot, th)
    if m and mt:
        check("pendulum w^2 = g/l", close(w2s(m)[0], G / L), str(w2s(m)))
        check("pendulum w^2 as in the angle", close(w2s(m)[0], w2s(mt)[0]),
              f"{w2s(m)} {w2s(mt)}")
        check("pendulum point", close(m["equilibrium"]["y"], -L) and abs(m["equilibrium"]["x"]) < 1e-12,
              str(m["equilibrium"]))
        check("pendulum multiplier", close(m["multipliers"]["lambda_rod"], -1.5 * G / (2 * L)),
              str(m["multipliers"]))
        check("pendulum stable", m["verdict"] == "stable", m["verdict"])
    rc, m, err = modes_json(qdot, xy, "--about", "x = 0, y = 1.9")
    check("pendulum top rc", rc == 0, err)
    if m:
        check("pendulum top w^2", close(w2s(m)[0], -G / L) and m["verdict"] == "unstable",
              str(m))
    rc, out, err = run(qdot, "linearize", xy, "--about", "x = 0, y = -1.99", "--format", "json")
    check("pendulum linearize rc", rc == 0, err)
    if rc == 0:
        d_ = json.loads(out)
        A = d_["A"]
        check("pendulum A", d_["states"] == ["x", "x'"] and close(A[0][1], 1) and
              abs(A[0][0]) < 1e-12 and abs(A[1][1]) < 1e-12 and close(A[1][0], -G / L), str(A))
        ev = sorted(d_["eigenvalues"], key=lambda s: s[1])
        w = math.sqrt(G / L)
        check("pendulum eigenvalues +-i sqrt(g/l)",
              all(abs(s[0]) < 1e-12 for s in ev) and close(ev[0][1], -w) and close(ev[1][1], w),
              str(ev))
    # a horizontal force F on the bob: x'' = -(g/l) x + F/m at the bottom
    rc, out, err = run(qdot, "linearize", d / "pend_in.qd", "--about", "x = 0, y = -2",
                       "--format", "json")
    check("pendulum input rc", rc == 0, err)
    if rc == 0:
        d_ = json.loads(out)
        check("pendulum B = (0, 1/m)", d_["inputs"] == ["F"] and abs(d_["B"][0][0]) < 1e-15 and
              close(d_["B"][1][0], 1 / 1.5) and close(d_["A"][1][0], -G / L), str(d_))
    # the user's independent coordinate y cannot parametrize the circle at the bottom
    rc, out, err = run(qdot, "linearize", xy, "--about", "x = 0, y = -2", "--independent", "y")
    check("independent y refused at the bottom, x offered",
          rc == 2 and "--independent" in err and "e.g. --independent \"x, x'\"" in err, err)
    # x at a point off the vertical, at rest: the dependent y solved there (y = -sqrt(l^2 -
    # x^2)) and x' = (0, x'') the affine term, x'' = -g sin(th) cos(th) (th the angle from the
    # bottom: x = l sin th; Desloge ch. 62's pendulum, th'' = -(g/l) sin th, at th' = 0), and
    # no verdict: the point is no steady motion
    rc, out, err = run(qdot, "linearize", xy, "--about", "x = 0.5, y = -1.9", "--format", "json")
    d_ = json.loads(out) if rc == 0 else {}
    sth = 0.5 / L
    check("off the vertical: y solved, x'' = -g sin cos, not steady",
          rc == 0 and close(d_["point"]["y"], -math.sqrt(L * L - 0.25)) and
          abs(d_["xdot0"][0][0]) < 1e-14 and
          close(d_["xdot0"][0][1], -G * sth * math.sqrt(1 - sth * sth)) and
          d_["verdict"] == "not steady" and d_["stable"] is None, out + err)
    rc, out, err = run(qdot, "modes", xy, "--independent", "x, y")
    check("independent count refused", rc == 2 and "name exactly 1" in err, err)
    rc, out, err = run(qdot, "modes", th, "--independent", "th")
    check("independent without constraints refused", rc == 2 and "no constraints" in err, err)


def double_pendulum(qdot, d):
    rc, m, err = modes_json(qdot, d / "dp_xy.qd")
    check("double pendulum rc", rc == 0, err)
    if not m:
        return
    M = np.array([[(M1 + M2) * L1**2, M2 * L1 * L2], [M2 * L1 * L2, M2 * L2**2]])
    K = np.diag([(M1 + M2) * G * L1, M2 * G * L2])
    w2 = sorted(np.linalg.eigvals(np.linalg.solve(M, K)).real)
    check("double pendulum two modes", len(w2s(m)) == 2 and
          all(close(a, b) for a, b in zip(w2s(m), w2)), f"{w2s(m)} {w2}")
    check("double pendulum independent", m["independent"] == ["x1", "x2"], str(m))
    rc, out, err = run(qdot, "equilibria", d / "dp_xy.qd", "--format", "json")
    kinds = sorted(p["kind"] for p in json.loads(out)["equilibria"]) if rc == 0 else []
    check("double pendulum equilibria", kinds == ["maximum", "minimum", "saddle", "saddle"],
          out + err)


def sphere(qdot, d):
    rc, m, err = modes_json(qdot, d / "sphere.qd")
    check("spherical pendulum rc", rc == 0, err)
    if m:
        check("spherical pendulum w^2 = g/l twice", len(w2s(m)) == 2 and
              all(close(w, G / L) for w in w2s(m)), str(w2s(m)))
        check("spherical pendulum bottom", close(m["equilibrium"]["z"], -L), str(m["equilibrium"]))
    rc, out, err = run(qdot, "equilibria", d / "sphere.qd", "--format", "json")
    pts = json.loads(out)["equilibria"] if rc == 0 else []
    got = sorted((round(p["equilibrium"]["z"], 9), p["kind"], p["hessian_signs"]) for p in pts)
    check("spherical pendulum equilibria",
          got == [(-L, "minimum", [2, 0, 0]), (L, "maximum", [0, 2, 0])], str(got))


def sympy_nonminimal(qdot, d):
    """test_linearize_pendulum_lagrange_nonminimal, its A computed by SymPy."""
    from sympy import symbols, atan, Matrix, Symbol
    from sympy.physics.mechanics import (dynamicsymbols, ReferenceFrame, Point, Particle,
                                         Lagrangian, LagrangesMethod)
    q1, q2 = dynamicsymbols('q1:3')
    q1d, q2d = dynamicsymbols('q1:3', level=1)
    Ls, m, t = symbols('L, m, t')
    g = 9.8
    N = ReferenceFrame('N')
    pN = Point('N*')
    pN.set_vel(N, 0)
    N.orientnew('A', 'axis', [atan(q2 / q1), N.z])
    P = pN.locatenew('P1', q1 * N.x + q2 * N.y)
    P.set_vel(N, P.pos_from(pN).dt(N))
    pP = Particle('pP', P, m)
    LM = LagrangesMethod(Lagrangian(N, pP), [q1, q2], hol_coneqs=Matrix([q1**2 + q2**2 - Ls**2]),
                         forcelist=[(P, m * g * N.x)], frame=N)
    LM.form_lagranges_equations()
    op = {q1: Ls, q2: 0, q1d: 0, q2d: 0, q1d.diff(t): 0, q2d.diff(t): 0}
    op.update(LM.solve_multipliers(op_point=op))
    A, _, _ = LM.linearize([q2], [q2d], [q1], [q1d], op_point=op, A_and_B=True)
    A = np.array(A.subs({Ls: 1.3, m: 0.9}).evalf(), dtype=float)
    rc, out, err = run(qdot, "linearize", d / "sympy_pend.qd", "--about", "q1 = 1.3, q2 = 0",
                       "--independent", "q2", "--format", "json")
    check("sympy nonminimal rc", rc == 0, err)
    if rc == 0:
        Aq = np.array(json.loads(out)["A"])
        check("sympy nonminimal A", Aq.shape == A.shape and np.allclose(Aq, A, rtol=1e-12,
                                                                         atol=1e-12),
              f"{Aq} {A}")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", required=True)
    qdot = Path(ap.parse_args().build) / "qdot"
    with tempfile.TemporaryDirectory() as tmp:
        d = Path(tmp)
        for name, text in (("pend_xy", PEND_XY), ("pend_th", PEND_TH), ("dp_xy", DP_XY),
                           ("sphere", SPHERE), ("sympy_pend", SYMPY_PEND),
                           ("pend_in", PEND_IN)):
            (d / f"{name}.qd").write_text(text)
        for f in (pendulum, double_pendulum, sphere, sympy_nonminimal):
            f(qdot, d)
    sys.exit(finish())


if __name__ == "__main__":
    main()

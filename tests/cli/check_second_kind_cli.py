#!/usr/bin/env python3
"""Hamilton's equations of the second kind (`qdot hamiltonian --second-kind`)
against Desloge vol. 2 ch. 72 (seed 000_46d037099a6cfcd7.txt, pp. 744-749;
reference seed-desloge-C.md C10, T17, pitfall 20) and SymPy.

    python3 tests/cli/check_second_kind_cli.py --build BUILD_DIR

Thm 1: s_j = dT/dq'_j, K = sum s q' - T, q'_j = dK/ds_j (4a),
s'_j = -dK/dq_j + Q_j (4b) with Q_j every force T does not hold; K = T when
T is homogeneous quadratic (5); s = p when U = U(q, t) (6).
- Ex. 1 (eqs. 23-31): m on the x axis, force -k x, resistance -alpha x':
  s = m x', K = s^2/(2m), x' = s/m, s' = -k x - alpha s/m.
- P. 1: resistance k x'^2 (x' > 0): m x'' = -k x'^2, s' = -k s^2/m^2.
- The SymPy cross-check: for each model the printed K, velocities and s'
  are compared with SymPy's own Legendre transform of T, and s' at
  s = dT/dq' with Lagrange's equation (1), d/dt(dT/dq') = dT/dq + Q, the
  forces derived by SymPy from V, U and D (a rotating wire: T not
  homogeneous, K - T = -m w^2 r^2; a charge in E and B: Q is the Lorentz
  force q (E + v x B) and s = m v is not p = m v + q A).
Prints "N passed, N failed"; exit 1 on failure.
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile

import sympy as sp

results = {"passed": 0, "failed": 0}


def check(name, ok, detail=""):
    results["passed" if ok else "failed"] += 1
    if not ok:
        print(f"FAIL {name} {detail}")


def run(qdot, *args):
    p = subprocess.run([qdot, *args], capture_output=True, text=True, timeout=120)
    return p.returncode, p.stdout, p.stderr


def write(d, name, text):
    path = os.path.join(d, name)
    with open(path, "w") as f:
        f.write(text)
    return path


def parse(s, syms):
    return sp.sympify(s.replace("^", "**"), locals=syms)


def zero(x):
    return sp.simplify(sp.expand(x)) == 0


class Sym:
    """SymPy's Hamilton of the second kind for T, V, U, D and given forces
    in the coordinates qs (velocities named q' in qdot, qd_q here)."""

    def __init__(self, qs, params):
        self.q = [sp.Symbol(n) for n in qs]
        self.v = [sp.Symbol("qd_" + n) for n in qs]
        self.s = [sp.Symbol("s_" + n) for n in qs]
        self.t = sp.Symbol("t")
        self.names = {n: sp.Symbol(n) for n in qs + params + ["s_" + n for n in qs] + ["t"]}
        self.names.update({"qd_" + n: sp.Symbol("qd_" + n) for n in qs})

    def e(self, text):
        for q in sorted(self.q, key=lambda x: -len(x.name)):
            text = text.replace(q.name + "'", "qd_" + q.name)
        return parse(text, self.names)

    def derive(self, T, V="0", U="0", D="0", given=None):
        T, V, U, D = self.e(T), self.e(V), self.e(U), self.e(D)
        n = len(self.q)
        sdef = [sp.diff(T, v) for v in self.v]
        sol = sp.solve([self.s[j] - sdef[j] for j in range(n)], self.v, dict=True)[0]
        vel = [sp.simplify(sol[v]) for v in self.v]
        K = sp.simplify((sum(s * v for s, v in zip(self.s, self.v)) - T).subs(sol))
        # Q_j = given - dV/dq + d/dt(dU/dq') - dU/dq - dD/dq' (Desloge ch. 72 eq. 1)
        Q = []
        for j in range(n):
            g = sp.diff(U, self.v[j])
            dt = sp.diff(g, self.t) + sum(sp.diff(g, q) * v for q, v in zip(self.q, self.v))
            x = (self.e(given[j]) if given else 0) - sp.diff(V, self.q[j]) + dt \
                - sp.diff(U, self.q[j]) - sp.diff(D, self.v[j])
            Q.append(x)
        self.T, self.sdef, self.vel, self.K, self.Q, self.sol = T, sdef, vel, K, Q, sol
        return self

    def lagrange_rhs(self, j):
        """dT/dq_j + Q_j in q, q' (Lagrange's equations (1): d/dt dT/dq'_j)."""
        return sp.diff(self.T, self.q[j]) + self.Q[j]


def second_kind(qdot, path, *extra):
    rc, out, err = run(qdot, "hamiltonian", path, "--second-kind", "--format", "json", *extra)
    return rc, (json.loads(out) if rc == 0 else None), err


def compare(name, j, sym):
    """The printed K, velocities, forces and equations against SymPy's."""
    n = len(sym.q)
    check(name + " kind", j.get("kind") == "second", str(j))
    check(name + " momenta named s_q", j["momenta"] == [s.name for s in sym.s], str(j["momenta"]))
    e = lambda text: parse(text, sym.names)
    check(name + " K", zero(e(j["K"]) - sym.K), j["K"] + " vs " + str(sym.K))
    for k in range(n):
        check(name + " s = dT/dq'", zero(sym.e(j["definitions"][k]) - sym.sdef[k]),
              j["definitions"][k])
        check(name + " q' = dK/ds (4a)", zero(e(j["dq_dt"][k]) - sym.vel[k])
              and zero(e(j["dq_dt"][k]) - sp.diff(sym.K, sym.s[k])), j["dq_dt"][k])
        Qs = sym.Q[k].subs(sym.sol)
        check(name + " Q", zero(e(j["forces"][k]) - Qs), j["forces"][k] + " vs " + str(Qs))
        ds = e(j["ds_dt"][k])
        check(name + " s' = -dK/dq + Q (4b)", zero(ds - (-sp.diff(sym.K, sym.q[k]) + Qs)),
              j["ds_dt"][k])
        # Lagrange's equations (1): s' at s = dT/dq' is dT/dq + Q
        at = ds.subs(dict(zip(sym.s, sym.sdef)))
        check(name + " Lagrange (1)", zero(at - sym.lagrange_rhs(k)), str(at))
    KT = sp.simplify(sym.K.subs({s: d for s, d in zip(sym.s, sym.sdef)}) - sym.T)
    check(name + " K = T verdict (5)", j["K_is_T"] == (KT == 0), str(j["K_is_T"]))


def test_example1(qdot, d):
    """Desloge ch. 72 Ex. 1 (eqs. 23-31), the resistance as a dissipation
    function and, the same force, as a given generalized force."""
    for tag, body in (("D", "V = k/2*x^2\ndissipation = alpha/2*x'^2\n"),
                      ("Q", "Q[x] = -k*x - alpha*x'\n")):
        path = write(d, "ex1_%s.qd" % tag,
                     "coordinates x\nparameters m = 2, k = 3, alpha = 0.5\nT = m/2*x'^2\n" + body)
        rc, j, err = second_kind(qdot, path)
        check("Ex1 %s rc" % tag, rc == 0, err)
        if rc != 0:
            continue
        sym = Sym(["x"], ["m", "k", "alpha"])
        m, k, a, x, s = (sym.names[n] for n in ("m", "k", "alpha", "x", "s_x"))
        e = lambda text: parse(text, sym.names)
        check("Ex1 %s s = m x' (24)" % tag, zero(sym.e(j["definitions"][0]) - m * sym.v[0]))
        check("Ex1 %s K = s^2/2m (25)" % tag, zero(e(j["K"]) - s**2 / (2 * m)), j["K"])
        check("Ex1 %s x' = s/m (29)" % tag, zero(e(j["dq_dt"][0]) - s / m), j["dq_dt"][0])
        check("Ex1 %s s' = -k x - alpha s/m (30)" % tag,
              zero(e(j["ds_dt"][0]) - (-k * x - a * s / m)), j["ds_dt"][0])
        check("Ex1 %s K = T (5)" % tag, j["K_is_T"] is True and j["K_minus_T"] == "0", str(j))
        check("Ex1 %s s = p (6)" % tag, j["s_is_p"] is True, str(j))
        check("Ex1 %s K not conserved" % tag, j["conserved"] is False, str(j))
        if tag == "D":
            compare("Ex1 sympy", j, Sym(["x"], ["m", "k", "alpha"]).derive(
                "m/2*x'^2", V="k/2*x^2", D="alpha/2*x'^2"))
    # the text form: the seed's eqs. 29-30 under their headings
    rc, out, err = run(qdot, "hamiltonian", os.path.join(d, "ex1_D.qd"), "--second-kind")
    check("Ex1 text", rc == 0 and "Hamilton's equations of the second kind" in out
          and "K = T: yes" in out and "s = p: yes" in out, out + err)


def test_problem1(qdot, d):
    """Desloge ch. 72 P. 1: resistance k x'^2 (x' > 0): m x'' = -k x'^2."""
    path = write(d, "p1.qd", "coordinates x\nparameters m = 2, k = 0.3\nT = m/2*x'^2\n"
                 "Q[x] = -k*x'^2\n")
    rc, j, err = second_kind(qdot, path)
    check("P1 rc", rc == 0, err)
    if rc == 0:
        sym = Sym(["x"], ["m", "k"])
        m, k, s = sym.names["m"], sym.names["k"], sym.names["s_x"]
        check("P1 s' = -k s^2/m^2", zero(parse(j["ds_dt"][0], sym.names) + k * s**2 / m**2),
              j["ds_dt"][0])
        compare("P1 sympy", j, sym.derive("m/2*x'^2", given=["-k*x'^2"]))
        # --at: s' at x' = 2 (s = m x' = 4) is -k x'^2 = -1.2
        rc, out, err = run(qdot, "hamiltonian", path, "--second-kind", "--at", "x=0, s_x=4",
                           "--format", "json")
        check("P1 --at rc", rc == 0, err)
        if rc == 0:
            a = json.loads(out)
            check("P1 --at s' = -k x'^2", abs(a["ds_dt"][0] + 1.2) < 1e-14, out)
            check("P1 --at x' = 2", abs(a["dq_dt"][0] - 2) < 1e-14, out)


def test_rotating_wire(qdot, d):
    """T not homogeneous (a bead on a wire turning at w): K = T2 - T0, so
    K - T = -2 T0 = -m w^2 r^2 (eq. 5 does not apply), and s' is
    Lagrange's m r'' = m w^2 r."""
    path = write(d, "wire.qd", "coordinates r\nparameters m = 1, w = 2\n"
                 "T = m/2*(r'^2 + w^2*r^2)\n")
    rc, j, err = second_kind(qdot, path)
    check("wire rc", rc == 0, err)
    if rc == 0:
        sym = Sym(["r"], ["m", "w"])
        m, w, r = sym.names["m"], sym.names["w"], sym.names["r"]
        check("wire K - T = -m w^2 r^2", zero(parse(j["K_minus_T"], sym.names) + m * w**2 * r**2),
              j["K_minus_T"])
        check("wire K is not T", j["K_is_T"] is False, str(j))
        check("wire K conserved", j["conserved"] is True, str(j))
        compare("wire sympy", j, sym.derive("m/2*(r'^2 + w^2*r^2)"))


def test_paraboloid(qdot, d):
    """Desloge ch. 72 P. 2's system (seed-desloge-C.md T19): a mass on
    z = rho^2 under gravity, in rho, ph; two degrees of freedom, ph cyclic
    so s_ph' = 0."""
    path = write(d, "bowl.qd", "coordinates rho, ph\nparameters m = 1, g = 9.8\n"
                 "T = m/2*((1 + 4*rho^2)*rho'^2 + rho^2*ph'^2)\nV = m*g*rho^2\n")
    rc, j, err = second_kind(qdot, path)
    check("bowl rc", rc == 0, err)
    if rc == 0:
        check("bowl s_ph' = 0", j["ds_dt"][1] == "0", str(j["ds_dt"]))
        compare("bowl sympy", j, Sym(["rho", "ph"], ["m", "g"]).derive(
            "m/2*((1 + 4*rho^2)*rho'^2 + rho^2*ph'^2)", V="m*g*rho^2"))


def test_charge(qdot, root):
    """A charge in uniform E and B (examples/charged_particle_EB.qd, U =
    q phi - q A.v): Q is the Lorentz force q (E + v x B) (Goldstein
    eq. 1.63), and s = m v, not p = m v + q A (eq. 6 needs U = U(q, t))."""
    path = os.path.join(root, "examples", "charged_particle_EB.qd")
    rc, j, err = second_kind(qdot, path)
    check("charge rc", rc == 0, err)
    if rc != 0:
        return
    check("charge s is not p", j["s_is_p"] is False, str(j))
    sym = Sym(["x", "y", "z"], ["m", "q", "Ex", "Ey", "Ez", "Bx", "By", "Bz"])
    n = sym.names
    v = sp.Matrix([n["s_x"], n["s_y"], n["s_z"]]) / n["m"]
    F = n["q"] * (sp.Matrix([n["Ex"], n["Ey"], n["Ez"]]) +
                  v.cross(sp.Matrix([n["Bx"], n["By"], n["Bz"]])))
    for k, c in enumerate("xyz"):
        check("charge Q_%s Lorentz" % c, zero(parse(j["forces"][k], n) - F[k]), j["forces"][k])
        check("charge s_%s' Lorentz" % c, zero(parse(j["ds_dt"][k], n) - F[k]), j["ds_dt"][k])


def test_refusals(qdot, d):
    """A model without T (L or H given) and a U quadratic in the velocities
    are bad input (exit 2), with the reason."""
    lpath = write(d, "l.qd", "coordinates x\nL = x'^2/2 - x^2/2\n")
    rc, out, err = run(qdot, "hamiltonian", lpath, "--second-kind")
    check("L refused", rc == 2 and "built from the kinetic energy T" in err
          and "gives L" in err, "%d %s" % (rc, err))
    hpath = write(d, "h.qd", "coordinates x\nmomenta p_x\nH = p_x\n")
    rc, out, err = run(qdot, "hamiltonian", hpath, "--second-kind")
    check("H refused", rc == 2 and "gives H" in err, "%d %s" % (rc, err))
    upath = write(d, "u.qd", "coordinates x\nT = x'^2/2\nU = x^2*x'^2\n")
    rc, out, err = run(qdot, "hamiltonian", upath, "--second-kind")
    check("U quadratic refused", rc in (1, 2) and "not linear in the velocities" in err,
          "%d %s" % (rc, err))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", required=True)
    a = ap.parse_args()
    qdot = os.path.join(os.path.abspath(a.build), "qdot")
    root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    with tempfile.TemporaryDirectory() as d:
        test_example1(qdot, d)
        test_problem1(qdot, d)
        test_rotating_wire(qdot, d)
        test_paraboloid(qdot, d)
        test_charge(qdot, root)
        test_refusals(qdot, d)
    print("%d passed, %d failed" % (results["passed"], results["failed"]))
    return 1 if results["failed"] else 0


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/env python3
"""Tests of `qdot bracket` and `qdot canonical`, run against the built program.

    python3 tests/cli/check_canonical_cli.py --build BUILD_DIR

Expected values are textbook mathematics (Goldstein ch. 9): the angular
momentum algebra [L_x, L_y] = L_z of a free particle; Q = q^(1/2) cos(2p),
P = q^(1/2) sin(2p) canonical, while b = 1 scales [Q, P] to 1/2; the F2
generator q*P is the identity with K = H.  Results are compared with SymPy
where they are expressions.  Prints "N passed, N failed"; exit 1 on failure.
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile

import sympy as sp

FREE = "coordinates x, y, z\nparameters m = 1\nparticle m at (x, y, z)\n"
ONE = "coordinates q\nparameters m = 1, k = 2\nT = m/2*q'^2\nV = k/2*q^2\n"
OSC = "coordinates q\nparameters m = 1.5, w = 2\nT = m/2*q'^2\nV = m*w^2/2*q^2\n"

results = {"passed": 0, "failed": 0}


def check(name, ok, detail=""):
    results["passed" if ok else "failed"] += 1
    if not ok:
        print(f"FAIL {name} {detail}")


def run(qdot, *args):
    p = subprocess.run([qdot, *args], capture_output=True, text=True, timeout=60)
    return p.returncode, p.stdout, p.stderr


def same(a, b, names):
    syms = {n: sp.Symbol(n) for n in names}
    return sp.simplify(sp.sympify(a.replace("^", "**"), locals=syms)
                       - sp.sympify(b, locals=syms)) == 0


def test_bracket(qdot, free):
    names = ["x", "y", "z", "p_x", "p_y", "p_z", "m"]
    Lx, Ly, Lz = "y*p_z - z*p_y", "z*p_x - x*p_z", "x*p_y - y*p_x"
    rc, out, err = run(qdot, "bracket", free, Lx, Ly, "--format", "json")
    check("bracket rc", rc == 0, err)
    if rc == 0:
        check("[Lx, Ly] = Lz", same(json.loads(out)["bracket"], Lz, names), out)
    rc, out, err = run(qdot, "bracket", free, "x", "p_x")
    check("[x, p_x] = 1", rc == 0 and out.strip().endswith("= 1"), out + err)
    # Poisson's theorem: Lx, Ly integrals, so their bracket is one: d/dt Lz = 0
    rc, out, err = run(qdot, "bracket", free, "--dt", Lz, "--format", "json")
    check("dLz/dt = 0", rc == 0 and same(json.loads(out)["dF_dt"], "0", names), out + err)
    # d/dt (x p_x) = [x p_x, p^2/2m] = p_x^2/m
    rc, out, err = run(qdot, "bracket", free, "--dt", "x*p_x", "--format", "json")
    check("d(x p_x)/dt", rc == 0 and same(json.loads(out)["dF_dt"], "p_x**2/m", names), out + err)
    rc, out, err = run(qdot, "bracket", free, "w*x", "p_x")
    check("unknown name exit 2", rc == 2 and "unknown name" in err, err)
    rc, out, err = run(qdot, "bracket", free, "x'", "p_x")
    check("velocity exit 2", rc == 2 and "velocity" in err, err)


def verdict(qdot, one, Q, P):
    """The exit status and the JSON verdict (printed for "yes", exit 0, and
    for "no", exit 3), or standard error when nothing was printed."""
    rc, out, err = run(qdot, "canonical", one, "--Q", Q, "--P", P, "--format", "json")
    return rc, (json.loads(out) if out else err)


def test_canonical(qdot, one, free):
    rc, v = verdict(qdot, one, "q^(1/2)*cos(2*p_q)", "q^(1/2)*sin(2*p_q)")
    check("a=1/2 b=2 canonical", rc == 0 and v["verdict"] == "canonical", str(v))
    # a scaled map ([Q, P] = c != 1, Goldstein's extended canonical
    # transformation) is not canonical: the certified answer "no" exits 3
    rc, v = verdict(qdot, one, "q^(1/2)*cos(p_q)", "q^(1/2)*sin(p_q)")
    check("b=1 scaled 1/2", rc == 3 and v["verdict"] == "scaled"
          and same(v["scale"], "1/2", []), str(v))
    # the exchange Q = p, P = q has [Q, P] = -1 (Goldstein ch. 9.1: Q = p,
    # P = -q is the canonical one)
    rc, out, err = run(qdot, "canonical", one, "--Q", "p_q", "--P", "q")
    check("exchange: not canonical, c = -1, exit 3", rc == 3 and out ==
          "not canonical (a scaled canonical map, c = -1): [Q_i, P_i] = -1\n", out + err)
    rc, out, err = run(qdot, "canonical", one, "--Q", "p_q", "--P", "-q")
    check("Q = p, P = -q canonical, exit 0", rc == 0 and out == "canonical\n", out + err)
    rc, v = verdict(qdot, one, "q*cos(2*p_q)", "q*sin(2*p_q)")
    check("a=1 not canonical", rc == 3 and v["verdict"] == "not canonical"
          and v["bracket"] == "[Q, P]" and same(v["value"], "2*q", ["q"]), str(v))
    rc, out, err = run(qdot, "canonical", one, "--Q", "q*cos(2*p_q)", "--P", "q*sin(2*p_q)")
    check("text verdict", rc == 3 and out.startswith("not canonical: [Q, P] = "), out + err)
    # linear map Q = A q, P = B p canonical iff B = (A^-1)^T
    rc, out, err = run(qdot, "canonical", free, "--Q", "x + y, y, z",
                       "--P", "p_x, p_y - p_x, p_z", "--format", "json")
    check("linear map canonical", rc == 0 and json.loads(out)["verdict"] == "canonical", out + err)
    rc, out, err = run(qdot, "canonical", free, "--Q", "x + y, y, z",
                       "--P", "p_x, p_y + p_x, p_z", "--format", "json")
    check("linear map not canonical", rc == 3
          and json.loads(out)["verdict"] == "not canonical", out + err)
    rc, out, err = run(qdot, "canonical", one, "--Q", "q")
    check("missing --P exit 2", rc == 2 and "--P is missing" in err, err)
    rc, out, err = run(qdot, "canonical", one, "--Q", "q, p_q", "--P", "p_q")
    check("wrong count exit 2", rc == 2 and "needs 1" in err, err)
    rc, out, err = run(qdot, "canonical", one, "--Q", "zz*q", "--P", "p_q")
    check("unknown name in --Q exit 2", rc == 2 and "unknown name" in err, err)


def test_generator(qdot, one):
    names = ["q", "p_q", "Q", "P", "m", "k"]
    rc, out, err = run(qdot, "canonical", one, "--generator", "F2", "q*P", "--format", "json")
    ok = rc == 0
    g = json.loads(out) if ok else {}
    check("F2 identity", ok and same(g["Q"], "q", names) and same(g["P"], "p_q", names), out + err)
    check("F2 K = H", ok and same(g["K_new"], "P**2/(2*m) + k*Q**2/2", names), out)
    # F2 = q*P + t*P: Q = q + t, P = p, K = H + P
    rc, out, err = run(qdot, "canonical", one, "--generator", "F2", "q*P + t*P", "--format", "json")
    ok = rc == 0
    g = json.loads(out) if ok else {}
    check("F2 time-dependent", ok and same(g["Q"], "q + t", names + ["t"])
          and same(g["K_old"], "p_q**2/(2*m) + k*q**2/2 + p_q", names), out + err)
    rc, out, err = run(qdot, "canonical", one, "--generator", "F7", "q*P")
    check("bad generator type exit 2", rc == 2, err)


def test_nonlinear_generator(qdot, osc, one):
    """F1 = (m w q^2/2) cot Q, the harmonic oscillator's (Goldstein ch. 9;
    Desloge ch. 76 P7, seed-desloge-C.md T39): Q enters p = m w q cot Q
    nonlinearly.  Q = atan(m w q/p), P = E/w, canonical, K = w P."""
    names = ["q", "p_q", "Q", "P", "m", "w"]
    syms = {n: sp.Symbol(n, positive=True) for n in names}
    q, p, m, w = syms["q"], syms["p_q"], syms["m"], syms["w"]
    rc, out, err = run(qdot, "canonical", osc, "--generator", "F1",
                       "m*w*q^2/2*cos(Q)/sin(Q)", "--format", "json")
    ok = rc == 0
    g = json.loads(out) if ok else {}
    check("F1 oscillator solved", ok, err)
    if not ok:
        return
    Q = sp.sympify(g["Q"].replace("^", "**"), locals=syms)
    P = sp.sympify(g["P"].replace("^", "**"), locals=syms)
    check("F1 oscillator: tan Q = m w q/p", sp.simplify(sp.tan(Q) - m * w * q / p) == 0, g["Q"])
    check("F1 oscillator: P = E/w", sp.simplify(
        P - (p**2 / (2 * m) + m * w**2 * q**2 / 2) / w) == 0, g["P"])
    # [Q, P] = 1 by SymPy, and by qdot itself on the printed map
    check("F1 oscillator: [Q, P] = 1 (SymPy)", sp.simplify(
        sp.diff(Q, q) * sp.diff(P, p) - sp.diff(Q, p) * sp.diff(P, q) - 1) == 0)
    rc, out2, err2 = run(qdot, "canonical", osc, "--Q", g["Q"], "--P", g["P"])
    check("F1 oscillator: the map is canonical", rc == 0 and out2 == "canonical\n", out2 + err2)
    check("F1 oscillator: K = w P", g["K_new"] is not None
          and same(g["K_new"], "w*P", names), str(g["K_new"]))
    # cot as 1/tan: F1 = q^2/2 cot Q, the unit-frequency generator, maps q = sqrt(2P) sin Q,
    # p = sqrt(2P) cos Q, so H = p^2/2m + k q^2/2 becomes K = P (cos^2 Q/m + k sin^2 Q)
    rc, out, err = run(qdot, "canonical", one, "--generator", "F1", "q^2/(2*tan(Q))",
                       "--format", "json")
    ok = rc == 0
    check("F1 with 1/tan", ok and same(json.loads(out)["K_new"],
                                       "P*(cos(Q)**2/m + k*sin(Q)**2)", names + ["k"]),
          out + err)
    # p = Q + 2 q e^Q has no closed-form inverse (Lambert's W): a named error, exit 2
    rc, out, err = run(qdot, "canonical", osc, "--generator", "F1", "q*Q + exp(Q)*q^2")
    check("unsolvable generator: named error, exit 2", rc == 2 and out == "" and
          "cannot solve p_q = dF/dq for Q in closed form" in err, err)


def test_log_generator(qdot, one):
    """Desloge ch. 84 (seed-desloge-C.md T27): Q = log p, P = -(1 + q + log p) p
    is canonical, and F with dF = p dq - P dQ is elementary, q p + p log p
    (it needs the integral of log p; it was "not found in closed form")."""
    rc, out, err = run(qdot, "canonical", one, "--Q", "log(p_q)", "--P", "-(1+q+log(p_q))*p_q",
                       "--K", "--format", "json")
    d = json.loads(out) if rc == 0 else {}
    check("log map canonical", d.get("verdict") == "canonical", err)
    q, p = sp.symbols("q p", positive=True)
    F = sp.sympify(str(d.get("F")).replace("^", "**"), locals={"q": q, "p_q": p})
    Q, P = sp.log(p), -(1 + q + sp.log(p)) * p
    check("log map F", sp.simplify(sp.diff(F, q) - p) == 0 and
          sp.simplify(sp.diff(F, p) + P * sp.diff(Q, p)) == 0, str(d.get("F")))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", required=True)
    qdot = os.path.join(ap.parse_args().build, "qdot")
    with tempfile.TemporaryDirectory() as d:
        free, one = os.path.join(d, "free.qd"), os.path.join(d, "one.qd")
        with open(free, "w") as f:
            f.write(FREE)
        with open(one, "w") as f:
            f.write(ONE)
        test_bracket(qdot, free)
        test_canonical(qdot, one, free)
        test_generator(qdot, one)
        test_log_generator(qdot, one)
        osc = os.path.join(d, "osc.qd")
        with open(osc, "w") as f:
            f.write(OSC)
        test_nonlinear_generator(qdot, osc, one)
    print(f"{results['passed']} passed, {results['failed']} failed")
    return 1 if results["failed"] else 0


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/env python3
"""Certified verdicts of `qdot canonical` (issue 33), run against the built program.

    python3 tests/cli/check_certified_cli.py --build BUILD_DIR

A "no" comes with a witness point where the failing bracket minus its
required value is certainly nonzero: the test recomputes the bracket there
with SymPy (exact at the dyadic point) and checks it lies outside the printed
ball.  Canonical maps the simplifier reduces only through 1 + tan^2 = 1/cos^2
say "canonical"; a zero it cannot reduce says "verified numerically".
Prints "N passed, N failed"; exit 1 on failure.
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile

import sympy as sp

ONE = "coordinates q\nparameters m = 1, k = 2\nT = m/2*q'^2\nV = k/2*q^2\n"
OSC = ("coordinates q\nparameters m = 1, K = 2\nT = m/2*q'^2\nV = m*K^2/2*q^2\n")

results = {"passed": 0, "failed": 0}


def check(name, ok, detail=""):
    results["passed" if ok else "failed"] += 1
    if not ok:
        print(f"FAIL {name} {detail}")


def run(qdot, *args):
    p = subprocess.run([qdot, *args], capture_output=True, text=True, timeout=120)
    return p.returncode, p.stdout, p.stderr


def canonical(qdot, model, Q, P, fmt="text"):
    return run(qdot, "canonical", model, "--Q", Q, "--P", P, "--format", fmt)


def test_tan_maps(qdot, one):
    # [Q, P] = cos(p)^2 (tan(p)^2 + 1) = 1 and its log/sin/tan cousin
    for Q, P in (("q*cos(p_q)^2", "tan(p_q)"), ("log(sin(p_q)/q)", "q/tan(p_q)")):
        rc, out, err = canonical(qdot, one, Q, P)
        check(f"{Q}, {P} canonical", rc == 0 and out.startswith("canonical"), out + err)
        rc, out, err = canonical(qdot, one, Q, P, "json")
        ok = rc == 0 and json.loads(out)["verdict"] == "canonical"
        check(f"{Q}, {P} json", ok and json.loads(out)["witness"] is None, out + err)


def test_witness(qdot, one):
    # Q = q^2, P = p: [Q, P] = 2q, not 1
    rc, out, err = canonical(qdot, one, "q^2", "p_q", "json")
    check("q^2 not canonical rc (a certified no: 3)", rc == 3, out + err)
    if rc != 3:
        return
    j = json.loads(out)
    check("certainty nonzero", j["verdict"] == "not canonical" and j["certainty"] == "nonzero", out)
    w = j["witness"]
    q = sp.Rational(w["point"]["q"])  # exact: the point is dyadic
    exact = 2 * q - 1
    check("witness value", abs(float(exact) - w["value"]) <= 1e-15 * (1 + abs(w["value"])), out)
    check("witness certified", abs(exact) > w["radius"] and exact != 0, out)
    rc, out, err = canonical(qdot, one, "q^2", "p_q")
    check("text witness", rc == 3 and "witness: at q = " in out and "certified" in out, out + err)


def test_numeric(qdot, one):
    # (asin + acos)(p/2) = pi/2: zero the simplifier does not reduce
    rc, out, err = canonical(qdot, one, "2*q*(asin(p_q/2) + acos(p_q/2))/pi", "p_q")
    check("numeric yes", rc == 0 and "canonical (verified numerically at 12 points" in out,
          out + err)
    rc, out, err = canonical(qdot, one, "2*q*(asin(p_q/2) + acos(p_q/2))/pi", "p_q", "json")
    ok = rc == 0 and json.loads(out)["certainty"] == "numeric" and json.loads(out)["points"] == 12
    check("numeric json", ok, out + err)


def test_generator_f1(qdot, osc):
    # Goldstein ch. 9 / Desloge: the oscillator's F1 with an asin; p = dF/dq
    # = -K sqrt(2Q - K^2 q^2) solves for Q = (p^2/K^2 + K^2 q^2)/2.
    F = "-(K/2)*q*sqrt(2*Q - K^2*q^2) - Q*asin(K*q/sqrt(2*Q))"
    rc, out, err = run(qdot, "canonical", osc, "--generator", "F1", F, "--format", "json")
    check("F1 rc", rc == 0, out + err)
    if rc != 0:
        return
    j = json.loads(out)
    q, p, K = sp.symbols("q p_q K", positive=True)
    loc = {"q": q, "p_q": p, "K": K}
    Qx = sp.sympify(j["Q"].replace("^", "**"), locals=loc)
    check("F1 Q", sp.simplify(Qx - (p**2 / K**2 + K**2 * q**2) / 2) == 0, out)
    # and p = dF/dq holds there on its branch: p^2 = K^2 (2Q - K^2 q^2)
    check("F1 p^2", sp.simplify(K**2 * (2 * Qx - K**2 * q**2) - p**2) == 0, out)


def test_integrals(qdot, free):
    # issue 33: a "not conserved" only when certified.  I = q' (sqrt(1 + sinh(40 q)^2)
    # - cosh(40 q)) + q' is q' (conserved on a free particle), but its dI/dt, which the
    # simplifier does not reduce, cancels e^40 against e^40: sampled in doubles it read
    # "not conserved: dI/dt = -40*q'^2*sinh(40*q)*(...)".  Ball arithmetic keeps it zero.
    I = "I: q'*(sqrt(1 + sinh(40*q)^2) - cosh(40*q)) + q'"
    rc, out, err = run(qdot, "integrals", free, "--integral", I, "--no-search", "--format", "json")
    ok = rc == 0
    if ok:
        p = json.loads(out)["proposed"][0]
        ok = p["conserved"] is True and p["numeric"] is True
    check("sinh(40 q) integral conserved (numerically)", ok, out + err)
    # and a true "no" stays one: I = q q' has dI/dt = q'^2
    rc, out, err = run(qdot, "integrals", free, "--integral", "I: q*q'", "--no-search", "--format", "json")
    ok = rc == 0 and json.loads(out)["proposed"][0]["conserved"] is False
    check("q q' not conserved", ok, out + err)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", required=True)
    args = ap.parse_args()
    qdot = os.path.join(args.build, "qdot")
    with tempfile.TemporaryDirectory() as d:
        one = os.path.join(d, "one.qd")
        with open(one, "w") as f:
            f.write(ONE)
        test_tan_maps(qdot, one)
        test_witness(qdot, one)
        test_numeric(qdot, one)
        osc = os.path.join(d, "osc.qd")
        with open(osc, "w") as f:
            f.write(OSC)
        test_generator_f1(qdot, osc)
        free = os.path.join(d, "free.qd")
        with open(free, "w") as f:
            f.write("coordinates q\nT = q'^2/2\n")
        test_integrals(qdot, free)
    print(f"{results['passed']} passed, {results['failed']} failed")
    return 1 if results["failed"] else 0


if __name__ == "__main__":
    sys.exit(main())

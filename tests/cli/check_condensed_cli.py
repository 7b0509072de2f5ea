#!/usr/bin/env python3
"""`qdot canonical FILE --Q ... --P ... --condensed` against Desloge vol. 2
ch. 75 (a condensed notation, pp. 768-772; seed 000_46d037099a6cfcd7.txt;
reference seed-desloge-C.md ch. 75, C14, T27, T33, T41, T59) and SymPy.

    python3 tests/cli/check_condensed_cli.py --build BUILD_DIR

Eqs. 2-13: lambda_ij = 1 for j = i + f, mu = lambda - lambda^T, mu^T = -mu,
mu mu^T = 1, |mu| = 1, checked on the printed matrices.  Eq. 14: the printed
r' = mu grad H is Hamilton's equations of the model's H (SymPy's
derivatives of H = p^2/(2m) + k q^2/2, and of H = (p1^2 + p2^2)/2).  Eq. 16:
the printed Lagrange brackets equal M^T mu M of SymPy's own Jacobian of the
map.  Thm 1 (eq. 17): canonical exactly when M^T mu M = mu: T27 (Q = ln p,
P = -(1 + q + ln p) p), T41 (the exchange Q = p, P = -q), T33 (Q1 = q1^2,
Q2 = q1 + q2, P1 = (p1 - p2)/(2 q1), P2 = p2 + (q1 + q2)^2), T59 (one
symplectic Euler step, q' = q + h (p - h q), p' = p - h q) are canonical with
|dR/dr| = 1 (Ex. 2, eq. 28); Q = 2q, P = p has valence 2 (exit 3); Q = q^2,
P = p is not canonical, with the witness of [q, p] = 2q re-evaluated.
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

ONE = "coordinates q\nparameters m = 1, k = 1, h = 1\nT = m/2*q'^2\nV = k/2*q^2\n"
TWO = "coordinates q1, q2\nT = (q1'^2 + q2'^2)/2\n"


def check(name, ok, detail=""):
    results["passed" if ok else "failed"] += 1
    if not ok:
        print(f"FAIL {name} {detail}")


def run(qdot, *args):
    p = subprocess.run([qdot, *args], capture_output=True, text=True, timeout=120)
    return p.returncode, p.stdout, p.stderr


def sym(text):
    return sp.sympify(text.replace("^", "**"))


def zero(e):
    return sp.simplify(sp.expand(e)) == 0


def mat(rows):
    return sp.Matrix([[sym(c) for c in r] for r in rows])


# (model, Q, P, verdict, rc, det)
CASES = [
    ("one", "log(p_q)", "-(1 + q + log(p_q))*p_q", "canonical", 0, 1),       # T27
    ("one", "p_q", "-q", "canonical", 0, 1),                                  # T41
    ("one", "q + h*(p_q - h*q)", "p_q - h*q", "canonical", 0, 1),             # T59
    ("two", "q1^2, q1 + q2", "(p_q1 - p_q2)/(2*q1), p_q2 + (q1 + q2)^2", "canonical", 0, 1),
    ("one", "2*q", "p_q", "scaled", 3, 2),
    ("one", "q^2", "p_q", "not canonical", 3, None),
]


def test_cases(qdot, files):
    for model, Qt, Pt, verdict, rc_want, det in CASES:
        name = "%s: Q = %s, P = %s" % (model, Qt, Pt)
        rc, out, err = run(qdot, "canonical", files[model], "--Q", Qt, "--P", Pt, "--condensed",
                           "--format", "json")
        check(name + " rc", rc == rc_want, "%d %s" % (rc, err))
        if not out.strip():
            continue
        j = json.loads(out)
        r = [sym(x) for x in j["r"]]
        R = sp.Matrix([sym(x) for x in j["R"]])
        f = len(r) // 2
        lam, mu = mat(j["lambda"]), mat(j["mu"])
        want_lam = sp.Matrix(2 * f, 2 * f, lambda i, k: 1 if k == i + f else 0)
        check(name + " lambda (eq. 2)", lam == want_lam, str(lam))
        check(name + " mu = lambda - lambda^T, mu^T = -mu, mu mu^T = 1, |mu| = 1 (eqs. 3-10)",
              mu == lam - lam.T and mu.T == -mu and mu * mu.T == sp.eye(2 * f) and mu.det() == 1)
        M = R.jacobian(r)
        check(name + " jacobian", all(zero(a - b) for a, b in zip(mat(j["jacobian"]), M)))
        L = mat(j["lagrange"])
        check(name + " [r_k, r_l] = M^T mu M (eq. 16)",
              all(zero(a - b) for a, b in zip(L, M.T * mu * M)), str(L))
        canon = all(zero(a - b) for a, b in zip(M.T * mu * M, mu))
        check(name + " Thm 1 verdict", (j["verdict"] == "canonical") == canon == (verdict ==
                                                                                  "canonical")
              and j["verdict"] == verdict, j["verdict"])
        if det is not None:
            check(name + " |dR/dr| (Ex. 2)", zero(sym(j["jacobian_det"]) - det) and
                  zero(M.det() - det), j["jacobian_det"])
        if verdict == "scaled":
            check(name + " valence 2", zero(sym(j["scale"]) - 2), str(j["scale"]))
        if verdict == "not canonical":
            w = j["witness"]
            v = (L[j["entry"][0] - 1, j["entry"][1] - 1] - sym(j["should_be"])).subs(
                {sp.Symbol(k): sp.Rational(x) for k, x in w["point"].items()})
            check(name + " witness", abs(float(v) - w["value"]) <= 1e-12 + w["radius"], str(w))
        H = (sym("p_q")**2 / (2 * sp.Symbol("m")) + sp.Symbol("k") * sym("q")**2 / 2
             if model == "one" else (sym("p_q1")**2 + sym("p_q2")**2) / 2)
        grad = [sp.diff(H, x) for x in r]
        rdot = [sym(x) for x in j["r_dot"]]
        want = [grad[i + f] for i in range(f)] + [-grad[i] for i in range(f)]
        check(name + " r' = mu grad H (eq. 14)", all(zero(a - b) for a, b in zip(rdot, want)),
              str(rdot))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", required=True)
    a = ap.parse_args()
    qdot = os.path.join(os.path.abspath(a.build), "qdot")
    with tempfile.TemporaryDirectory() as d:
        files = {}
        for name, text in (("one", ONE), ("two", TWO)):
            files[name] = os.path.join(d, name + ".qd")
            with open(files[name], "w") as fh:
                fh.write(text)
        test_cases(qdot, files)
        rc, out, err = run(qdot, "canonical", files["one"], "--Q", "q", "--P", "p_q",
                           "--condensed", "--K")
        check("--condensed with --K exit 2", rc == 2, err)
    print("%d passed, %d failed" % (results["passed"], results["failed"]))
    return 1 if results["failed"] else 0


if __name__ == "__main__":
    sys.exit(main())

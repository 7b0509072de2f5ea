#!/usr/bin/env python3
"""`qdot form EXPR --vars ... --gram-schmidt "A1; A2 ..."` and `qdot metric
FILE --gram-schmidt` against Desloge vol. 2 App. 21 (the Gram-Schmidt
orthogonalization process, pp. 915-917; seed 000_46d037099a6cfcd7.txt;
reference seed-desloge-D.md App. 21) and SymPy.

    python3 tests/cli/check_gram_cli.py --build BUILD_DIR

Thm 1 (eqs. 1a-1b): b(1) = a(1), b(r) = a(r) - sum_{j<r} [a(r).b(j)/b(j).b(j)]
b(j), with b(i).b(j) = 0 for i != j (eq. 2); Thm 2 (eqs. 3a-3b, 4): the same
with u^T T v for u.v and a symmetric T.  For each case SymPy rebuilds the b's
by its own loop (and, for Thm 1, by sympy.GramSchmidt) from the printed a's
and T and compares them entry by entry, checks eq. 4 on the printed b's, and
checks that each a(r) is b(r) plus the printed coefficients times the b's
before it.  The metric cases take T = g_ij of the model's T: the double
pendulum's tangents (b2 = e2 - g12/g11 e1, norm det g / g11) and the
spherical coordinates' (orthogonal: the e's unchanged).
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


def zero(e):
    return sp.simplify(sp.trigsimp(sp.expand(e))) == 0


def rebuild(A, T):
    """App. 21 eq. 3b by SymPy's arithmetic."""
    B = []
    for a in A:
        b = a
        for c in B:
            b = b - ((a.T * T * c)[0] / (c.T * T * c)[0]) * c
        B.append(sp.simplify(b))
    return B


def verify(name, j):
    n = len(j["vectors"][0])
    T = sp.eye(n) if j["metric"] is None else sp.Matrix([[sym(c) for c in r] for r in j["metric"]])
    A = [sp.Matrix([sym(c) for c in a]) for a in j["vectors"]]
    B = [sp.Matrix([sym(c) for c in b]) for b in j["orthogonal"]]
    C = [[sym(c) for c in r] for r in j["coefficients"]]
    want = rebuild(A, T)
    for r, (b, w) in enumerate(zip(B, want)):
        check("%s b%d (eq. 3b)" % (name, r + 1), all(zero(x - y) for x, y in zip(b, w)),
              "%s against %s" % (list(b), list(w)))
        check("%s norm %d" % (name, r + 1), zero(sym(j["norms"][r]) - (b.T * T * b)[0]),
              j["norms"][r])
        back = b + sum((C[r][k] * B[k] for k in range(r)), sp.zeros(n, 1))
        check("%s a%d in the b's" % (name, r + 1), all(zero(x) for x in back - A[r]), str(back))
    for i in range(len(B)):
        for k in range(i + 1, len(B)):
            check("%s b%d^T T b%d = 0 (eq. 4)" % (name, i + 1, k + 1),
                  zero((B[i].T * T * B[k])[0]))
    if j["euclidean"]:
        sg = sp.GramSchmidt(A)
        check(name + " sympy.GramSchmidt", all(zero(x - y) for b, w in zip(B, sg)
                                               for x, y in zip(b, w)), str(sg))


# (form, variables, vectors, euclidean)
CASES = [
    ("x^2 + y^2 + z^2", "x, y, z", "1, 1, 0; 1, 0, 1; 0, 1, 1", True),     # Thm 1
    ("x^2 + y^2 + z^2 + w^2", "x, y, z, w", "1, 1, 1, 1; 1, -1, 2, 0; 0, 3, 1, 1", True),
    ("2*x^2 + 2*x*y + 3*y^2 + z^2", "x, y, z", "1, 0, 0; 0, 1, 0; 1, 1, 1", False),  # Thm 2
    ("m*(x^2 + 2*cos(al)*x*y + y^2)", "x, y", "1, 0; 0, 1", False),  # oblique axes, m T
]


def test_forms(qdot):
    for phi, xs, vecs, euclid in CASES:
        name = "%s %s" % (phi, vecs)
        rc, out, err = run(qdot, "form", phi, "--vars", xs, "--gram-schmidt", vecs, "--format",
                           "json")
        check(name + " rc", rc == 0, err)
        if rc != 0:
            continue
        j = json.loads(out)
        check(name + " euclidean", j["euclidean"] is euclid, str(j["euclidean"]))
        verify(name, j)
    # Thm 1 by hand: (1,1,0), (1,0,1), (0,1,1) -> b3 = (-2/3, 2/3, 2/3), b3.b3 = 4/3
    rc, out, err = run(qdot, "form", "x^2 + y^2 + z^2", "--vars", "x, y, z", "--gram-schmidt",
                       "1, 1, 0; 1, 0, 1; 0, 1, 1")
    check("Thm 1 text", rc == 0 and "b3 = a3 - (1/2) b1 - (1/3) b2 = (-2/3, 2/3, 2/3), "
          "b3.b3 = 4/3" in out, out + err)
    # oblique axes at angle al: b2 = e2 - cos(al) e1, |b2|^2 = m sin(al)^2
    rc, out, err = run(qdot, "form", "m*(x^2 + 2*cos(al)*x*y + y^2)", "--vars", "x, y",
                       "--gram-schmidt", "1, 0; 0, 1", "--format", "json")
    if rc == 0:
        j = json.loads(out)
        check("oblique b2", zero(sym(j["orthogonal"][1][0]) + sp.cos(sp.Symbol("al"))), out)
        check("oblique norm m sin^2", zero(sym(j["norms"][1]) -
                                           sp.Symbol("m") * sp.sin(sp.Symbol("al"))**2), out)


def test_metric(qdot, root):
    for model in ("double_pendulum.qd", "free_particle_spherical.qd"):
        path = os.path.join(root, "examples", model)
        rc, out, err = run(qdot, "metric", path, "--gram-schmidt", "--format", "json")
        check(model + " rc", rc == 0, err)
        if rc != 0:
            continue
        j = json.loads(out)
        verify(model, j)
        T = sp.Matrix([[sym(c) for c in r] for r in j["metric"]])
        n = T.shape[0]
        check(model + " a = e's", j["vectors"] == [["1" if i == k else "0" for i in range(n)]
                                                   for k in range(n)], str(j["vectors"]))
        if model == "double_pendulum.qd":  # the Schur complement det g / g11
            check(model + " norm2 det g/g11", zero(sym(j["norms"][1]) - T.det() / T[0, 0]),
                  j["norms"][1])
        else:  # orthogonal coordinates: the tangents are already orthogonal
            check(model + " b = e's", j["orthogonal"] == j["vectors"], str(j["orthogonal"]))


def test_errors(qdot):
    rc, out, err = run(qdot, "form", "x^2 + y^2", "--vars", "x, y", "--gram-schmidt", "1, 2; 2, 4")
    check("dependent exit 2", rc == 2 and "a2 is a linear combination" in err, err)
    rc, out, err = run(qdot, "form", "x^2 - y^2", "--vars", "x, y", "--gram-schmidt", "1, 1")
    check("null vector exit 1", rc == 1 and "not definite" in err, err)
    rc, out, err = run(qdot, "form", "x^2 + y^2", "--vars", "x, y", "--gram-schmidt", "1, 2; 3")
    check("short vector exit 2 at its place", rc == 2 and "--gram-schmidt:1:7" in err, err)
    rc, out, err = run(qdot, "form", "x^2 + y^2", "--vars", "x, y", "--gram-schmidt", "1, 0",
                       "--homogeneity")
    check("with --homogeneity exit 2", rc == 2, err)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", required=True)
    a = ap.parse_args()
    qdot = os.path.join(os.path.abspath(a.build), "qdot")
    root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    test_forms(qdot)
    test_metric(qdot, root)
    test_errors(qdot)
    print("%d passed, %d failed" % (results["passed"], results["failed"]))
    return 1 if results["failed"] else 0


if __name__ == "__main__":
    sys.exit(main())

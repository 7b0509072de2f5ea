#!/usr/bin/env python3
"""End-to-end checks of `qdot modes --symmetry` (issue 19).

    python3 tests/cli/check_symmetry_cli.py --build BUILD_DIR

Expected values are closed forms, not output of the code under test:
  - the equilateral triangle of springs (examples/ring_three_masses.qd;
    Desloge ch. 66 worked example, App. 30 eq. 22, seed-desloge-D.md T33):
    C3v, chi = (6, 0, 0), Gamma = A1 + A2 + 2E, w^2 = 3k/m (A1) and
    3k/(2m) (E), zero modes translations (E) and the rotation (A2); the
    w^2 also from SymPy's Hessian of V;
  - the linear symmetric triatomic (examples/symmetric_triatomic.qd):
    w^2 = k/m (even under the mirror), (k/m)(1 + 2m/M) (odd), at two M;
  - the square (examples/symmetric_square.qd): C4v, A1 + A2 + B1 + B2 + 2E,
    w^2 = 2k/m (B and E), 2kd/m (B), 2(k + kd)/m (A1);
  - the tetrahedral XY4 (examples/symmetric_tetrahedron.qd): Td,
    A1 + E + T1 + 3T2, A1 breathing w^2 = (k + 4kh)/m at two kh;
  - the ring of six on a circle (examples/symmetric_ring6.qd): C6v,
    w_j = 2 sqrt(k/m) |sin(pi j/6)|; the same ring from T and V alone: an
    abstract group of order 12; a ring of 64 by the cyclic fast path;
  - every character table by both orthogonality relations;
  - a scalene triangle: no symmetry said on stderr, plain modes, exit 0;
    --symmetry with --scan is a usage error (exit 2).
Prints "N passed, N failed"; exit 1 on failure.
"""
import argparse
import cmath
import json
import math
import subprocess
import sys
import tempfile
from pathlib import Path

import sympy as sp

EX = Path(__file__).resolve().parents[2] / "examples"
results = {"passed": 0, "failed": 0}
TRIANGLE_AT = "x1=0, y1=0, x2=1, y2=0, x3=0.5, y3=sqrt(3)/2"
SQUARE_AT = "x1=1, y1=1, x2=-1, y2=1, x3=-1, y3=-1, x4=1, y4=-1"
C = "1/sqrt(3)"
TETRA_AT = ("x0=0, y0=0, z0=0, x1=c, y1=c, z1=c, x2=c, y2=-c, z2=-c, x3=-c, y3=c, z3=-c, "
            "x4=-c, y4=-c, z4=c").replace("c", C)


def check(name, ok, detail=""):
    results["passed" if ok else "failed"] += 1
    if not ok:
        print(f"FAIL {name} {detail}")


def run(qdot, *args):
    p = subprocess.run([str(qdot), *args], capture_output=True, text=True, timeout=120)
    return p.returncode, p.stdout, p.stderr


def close(a, b, tol=1e-9):
    return abs(a - b) <= tol * (1 + abs(b))


def symmetry_json(qdot, name, path, about, *extra):
    rc, out, err = run(qdot, "modes", str(path), "--about", about, "--symmetry",
                       "--format", "json", *extra)
    check(f"{name} rc", rc == 0, err)
    if rc != 0:
        return None
    return json.loads(out)


def orthogonality(name, sym):
    """Rows: sum_c |c| conj(chi_i) chi_j = |G| delta_ij; columns:
    sum_i conj(chi_i(c)) chi_i(c') = |G|/|c| delta_cc' (Desloge App. 29)."""
    sizes = [c["size"] for c in sym["classes"]]
    g = sym["order"]
    chars = [[complex(r, i) for r, i in zip(x["chi"], x.get("chi_imag", [0] * len(sizes)))]
             for x in sym["characters"]]
    check(f"{name} sum of classes", sum(sizes) == g)
    check(f"{name} sum d^2", sum(x["dimension"] ** 2 for x in sym["characters"]) == g)
    ok = True
    for a in chars:
        for b in chars:
            s = sum(n * x.conjugate() * y for n, x, y in zip(sizes, a, b))
            ok = ok and abs(s - (g if a is b else 0)) < 1e-8
    for c in range(len(sizes)):
        for d in range(len(sizes)):
            s = sum(x[c].conjugate() * x[d] for x in chars)
            ok = ok and abs(s - (g / sizes[c] if c == d else 0)) < 1e-8
    check(f"{name} orthogonality", ok)


def modes_by_irrep(doc):
    return [(m["omega2"], m["irrep"]) for m in doc["modes"]]


def triangle_sympy(k, m, a):
    """w^2 of the triangle: eigenvalues of SymPy's Hessian of V over m."""
    x = sp.symbols("x1 y1 x2 y2 x3 y3")
    p = [(x[0], x[1]), (x[2], x[3]), (x[4], x[5])]
    d = lambda i, j: sp.sqrt((p[i][0] - p[j][0]) ** 2 + (p[i][1] - p[j][1]) ** 2)
    V = sp.Rational(k) / 2 * sum((d(i, j) - a) ** 2 for i, j in ((0, 1), (1, 2), (2, 0)))
    at = dict(zip(x, [0, 0, a, 0, sp.Rational(a, 2), a * sp.sqrt(3) / 2]))
    H = sp.hessian(V, x).subs(at) / m
    return sorted(float(v) for v, mult in H.eigenvals().items() for _ in range(mult))


def triangle(qdot):
    doc = symmetry_json(qdot, "triangle", EX / "ring_three_masses.qd", TRIANGLE_AT)
    if not doc:
        return
    sym = doc["symmetry"]
    check("triangle group", sym["group"] == "C3v" and sym["order"] == 6, sym["group"])
    check("triangle classes", sorted(c["size"] for c in sym["classes"]) == [1, 2, 3])
    check("triangle reducible", [round(x, 9) for x in sym["reducible"]] == [6, 0, 0],
          sym["reducible"])
    check("triangle multiplicities", sym["multiplicities"] == {"A1": 1, "A2": 1, "E": 2},
          sym["multiplicities"])
    orthogonality("triangle", sym)
    k, m = 1, 1
    want = [(0, None), (0, None), (0, None), (1.5 * k / m, "E"), (1.5 * k / m, "E"),
            (3 * k / m, "A1")]
    got = modes_by_irrep(doc)
    check("triangle w2", all(close(g[0], w[0], 1e-10) for g, w in zip(got, want)), got)
    check("triangle labels", [g[1] for g in got[3:]] == ["E", "E", "A1"], got)
    kinds = sorted((x["kind"], x["irrep"]) for x in doc["modes"][:3])
    check("triangle zero modes", kinds == [("rotation", "A2"), ("translation", "E"),
                                           ("translation", "E")], kinds)
    check("triangle sympy", all(abs(g[0] - s) < 1e-12 for g, s in
                                zip(got, triangle_sympy(k, m, 1))))
    rc, out, err = run(qdot, "modes", str(EX / "ring_three_masses.qd"), "--about", TRIANGLE_AT,
                       "--symmetry")
    check("triangle text rc", rc == 0, err)
    check("triangle text group", "symmetry group: C3v (order 6, 3 classes)" in out, out)
    check("triangle text Gamma", "Gamma = A1 + A2 + 2E" in out, out)
    check("triangle text mode", "mode 6: w^2 = 3, w = 1.732050808 rad/s, A1 (multiplicity 1)"
          in out, out)


def triatomic(qdot):
    for M in (3, 5):
        doc = symmetry_json(qdot, f"triatomic M={M}", EX / "symmetric_triatomic.qd",
                            "x1=-1, x2=0, x3=1", "--set", f"M={M}")
        if not doc:
            continue
        m, k = 1, 2
        got = modes_by_irrep(doc)
        check(f"triatomic M={M} order", doc["symmetry"]["order"] == 2)
        orthogonality("triatomic", doc["symmetry"])
        check(f"triatomic M={M} w2", close(got[0][0], 0, 1e-12) and close(got[1][0], k / m) and
              close(got[2][0], k / m * (1 + 2 * m / M)), got)
        # the symmetric stretch alone is in its irrep; the translation shares the other
        check(f"triatomic M={M} irreps", got[1][1] != got[2][1] and got[0][1] == got[2][1], got)
        check(f"triatomic M={M} translation", doc["modes"][0]["kind"] == "translation")


def square(qdot):
    doc = symmetry_json(qdot, "square", EX / "symmetric_square.qd", SQUARE_AT)
    if not doc:
        return
    sym = doc["symmetry"]
    check("square group", sym["group"] == "C4v" and sym["order"] == 8, sym["group"])
    check("square multiplicities", sym["multiplicities"] ==
          {"A1": 1, "A2": 1, "B1": 1, "B2": 1, "E": 2}, sym["multiplicities"])
    orthogonality("square", sym)
    m, k, kd = 1.5, 1, 1.5
    got = modes_by_irrep(doc)
    want = [0, 0, 0, 2 * k / m, 2 * k / m, 2 * k / m, 2 * kd / m, 2 * (k + kd) / m]
    check("square w2", all(close(g[0], w, 1e-10) for g, w in zip(got, want)), got)
    check("square A1", got[7][1] == "A1" and got[6][1][0] == "B", got)
    check("square 2k/m", sorted(g[1][0] for g in got[3:6]) == ["B", "E", "E"], got)


def tetrahedron(qdot):
    for kh in (0.5, 1):
        doc = symmetry_json(qdot, f"tetra kh={kh}", EX / "symmetric_tetrahedron.qd", TETRA_AT,
                            "--set", f"kh={kh}")
        if not doc:
            continue
        sym = doc["symmetry"]
        check("tetra group", sym["group"] == "Td" and sym["order"] == 24, sym["group"])
        check("tetra multiplicities", sym["multiplicities"] ==
              {"A1": 1, "A2": 0, "E": 1, "T1": 1, "T2": 3}, sym["multiplicities"])
        orthogonality("tetra", sym)
        a1 = [x["omega2"] for x in doc["modes"] if x["irrep"] == "A1"]
        check(f"tetra kh={kh} A1", len(a1) == 1 and close(a1[0], (2 + 4 * kh) / 1), a1)
        zero = sorted((x["kind"], x["irrep"]) for x in doc["modes"] if x["omega2"] == 0)
        check(f"tetra kh={kh} zero modes", zero == [("rotation", "T1")] * 3 +
              [("translation", "T2")] * 3, zero)
        check(f"tetra kh={kh} degeneracy", all(x["multiplicity"] == {"A": 1, "E": 2, "T": 3}
                                                [x["irrep"][0]] for x in doc["modes"]))


def ring_w2(n, k=1, m=1):
    return sorted(4 * k / m * math.sin(math.pi * j / n) ** 2 for j in range(n))


def ring6(qdot, tmp):
    doc = symmetry_json(qdot, "ring6", EX / "symmetric_ring6.qd", "s1=0")
    if doc:
        check("ring6 group", doc["symmetry"]["group"] == "C6v", doc["symmetry"]["group"])
        orthogonality("ring6", doc["symmetry"])
        got = [x["omega2"] for x in doc["modes"]]
        check("ring6 w2", all(close(g, w, 1e-12) for g, w in zip(got, ring_w2(6))), got)
        check("ring6 rotation", doc["modes"][0]["kind"] == "rotation")
    f = tmp / "ring_tv.qd"
    f.write_text(ring_model(6))
    doc = symmetry_json(qdot, "ring6 abstract", f, "s1=0")
    if doc:
        check("ring6 abstract group", doc["symmetry"]["group"] is None and
              doc["symmetry"]["order"] == 12, doc["symmetry"])
        orthogonality("ring6 abstract", doc["symmetry"])
        got = [x["omega2"] for x in doc["modes"]]
        check("ring6 abstract w2", all(close(g, w, 1e-12) for g, w in zip(got, ring_w2(6))))


def ring_model(n):
    s = [f"s{i}" for i in range(1, n + 1)]
    return (f"coordinates {', '.join(s)}\nparameters m = 1, k = 1\n"
            f"T = m/2*({' + '.join(x + chr(39) + '^2' for x in s)})\n"
            f"V = k/2*({' + '.join(f'({s[(i + 1) % n]} - {s[i]})^2' for i in range(n))})\n")


def ring_fast(qdot, tmp):
    n = 64
    f = tmp / "ring64.qd"
    f.write_text(ring_model(n))
    rc, out, err = run(qdot, "modes", str(f), "--about", "s1=0", "--symmetry", "--format",
                       "json")
    check("ring64 rc", rc == 0, err)
    if rc != 0:
        return
    doc = json.loads(out)
    check("ring64 fast path", doc["symmetry"].get("fast_path") is True, doc["symmetry"])
    check("ring64 note", "cyclic fast path" in err and "faster" in err, err)
    got = [x["omega2"] for x in doc["modes"]]
    check("ring64 w2", len(got) == n and all(close(g, w, 1e-11) for g, w in
                                             zip(got, ring_w2(n))), got[:4])
    ks = [x["harmonic"] for x in doc["modes"]]
    check("ring64 harmonics", ks[0] == 0 and ks[-1] == n // 2)


def no_symmetry(qdot, tmp):
    f = tmp / "scalene.qd"
    f.write_text("coordinates x1, y1, x2, y2, x3, y3\nparameters m = 1, k = 1\n"
                 "d12 = sqrt((x1 - x2)^2 + (y1 - y2)^2)\nd23 = sqrt((x2 - x3)^2 + (y2 - y3)^2)\n"
                 "d31 = sqrt((x3 - x1)^2 + (y3 - y1)^2)\n"
                 "particle m at (x1, y1)\nparticle 2*m at (x2, y2)\nparticle m at (x3, y3)\n"
                 "V = k/2*((d12 - 1)^2 + (d23 - 1.2)^2 + (d31 - 1.5)^2)\n")
    c = (1 + 1.5 ** 2 - 1.2 ** 2) / 2
    about = f"x1=0, y1=0, x2=1, y2=0, x3={c!r}, y3={math.sqrt(1.5 ** 2 - c * c)!r}"
    rc, out, err = run(qdot, "modes", str(f), "--about", about, "--symmetry")
    check("scalene rc", rc == 0, err)
    check("scalene note", "no symmetry" in err, err)
    check("scalene plain modes", "mode 6: w^2" in out and "symmetry group" not in out, out)
    rc, out, err = run(qdot, "modes", str(EX / "ring_three_masses.qd"), "--scan", "k=1:2",
                       "--symmetry")
    check("scan usage", rc == 2, err)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", required=True)
    qdot = Path(ap.parse_args().build) / "qdot"
    for f in (triangle, triatomic, square, tetrahedron):
        f(qdot)
    with tempfile.TemporaryDirectory() as tmp:
        for f in (ring6, ring_fast, no_symmetry):
            f(qdot, Path(tmp))
    print(f"{results['passed']} passed, {results['failed']} failed")
    sys.exit(1 if results["failed"] else 0)


if __name__ == "__main__":
    main()

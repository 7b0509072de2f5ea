#!/usr/bin/env python3
"""End-to-end checks of `qdot linearize` (issue 23) and of inputs in the model language.

    python3 tests/cli/check_linearize_cli.py --build BUILD_DIR

Expected values are closed forms, not output of the code under test:
  - a chain of two masses, springs and dampers (wall -k1,c1- m1 -k2,c2- m2, F on m2):
    M x'' + C x' + K x = [0, F] gives A = [0 I; -M^-1 K  -M^-1 C] and
    B = [0; M^-1 (0, 1)], checked in numbers (1e-12) and as qdot's exact entries
    evaluated by SymPy at random parameters; the output y = x2 - x1 gives C = [-1 1 0 0];
  - two uncoupled oscillators with F on the first: not controllable, Kalman rank 2 of 4,
    the uncontrollable modes are s = +-i sqrt(k2/m2) moving x2 and x2' (PBH), and with
    y = x1 the same modes are unobservable;
  - the cart-pendulum (examples/cart_pendulum.qd) upright: controllable, eigenvalues
    0, 0, +-sqrt(g (M + m) / (M l));
  - errors (exit 2): an unknown name in --about, a value that is not a number, an input
    used where Lagrange's equations would differentiate it (T), an input used but not
    supplied to `qdot simulate`.
Prints "N passed, N failed"; exit 1 on failure.
"""
import argparse
import json
import math
import random
import subprocess
import sys
import tempfile
from pathlib import Path

import sympy as sp

EX = Path(__file__).resolve().parents[2] / "examples"
results = {"passed": 0, "failed": 0}


def report(ok, label, detail=""):
    results["passed" if ok else "failed"] += 1
    print("%s %s %s" % ("ok  " if ok else "FAIL", label, detail))


def run(qdot, *args):
    return subprocess.run([qdot, *args], capture_output=True, text=True, timeout=60)


def lin(qdot, path, *args):
    out = run(qdot, "linearize", str(path), "--format", "json", *args)
    if out.returncode != 0:
        raise SystemExit("qdot linearize failed: " + out.stderr)
    return json.loads(out.stdout)


def maxdiff(a, b):
    return max(abs(float(x) - float(y)) for x, y in zip(sp.Matrix(a), sp.Matrix(b)))


CHAIN = """coordinates x1, x2
parameters m1 = 1, m2 = 2, k1 = 3, k2 = 5, c1 = 0.1, c2 = 0.3
inputs F
T = m1*x1'^2/2 + m2*x2'^2/2
V = k1*x1^2/2 + k2*(x2 - x1)^2/2
dissipation = c1*x1'^2/2 + c2*(x2' - x1')^2/2
Q[x2] = F
outputs stretch = x2 - x1
"""


def check_chain(qdot, tmp, rng):
    path = Path(tmp) / "chain.qd"
    path.write_text(CHAIN)
    p = {k: rng.uniform(0.5, 3) for k in ("m1", "m2", "k1", "k2", "c1", "c2")}
    sets = sum((["--set", "%s=%r" % kv] for kv in p.items()), [])
    d = lin(qdot, path, *sets)
    M = sp.diag(p["m1"], p["m2"])
    K = sp.Matrix([[p["k1"] + p["k2"], -p["k2"]], [-p["k2"], p["k2"]]])
    C = sp.Matrix([[p["c1"] + p["c2"], -p["c2"]], [-p["c2"], p["c2"]]])
    A = sp.zeros(4, 4)
    A[0:2, 2:4] = sp.eye(2)
    A[2:4, 0:2] = -M.inv() * K
    A[2:4, 2:4] = -M.inv() * C
    B = sp.zeros(4, 1)
    B[2:4, 0] = M.inv() * sp.Matrix([0, 1])
    report(d["states"] == ["x1", "x2", "x1'", "x2'"], "chain: state order [q..., q'...]",
           str(d["states"]))
    report(maxdiff(d["A"], A) < 1e-12, "chain: A = [0 I; -M^-1 K, -M^-1 C]")
    report(maxdiff(d["B"], B) < 1e-12, "chain: B = [0; M^-1 (0, 1)]")
    report(maxdiff(d["C"], [[-1, 1, 0, 0]]) == 0 and maxdiff(d["D"], [[0]]) == 0,
           "chain: C, D of y = x2 - x1")
    syms = {k: sp.Symbol(k) for k in p}
    sub = {syms[k]: v for k, v in p.items()}
    Ae = sp.Matrix([[sp.sympify(e, locals=syms) for e in row] for row in d["A_exact"]])
    report(maxdiff(Ae.xreplace(sub), A) < 1e-12, "chain: exact A in the parameters")
    char = (A - sp.Symbol("s") * sp.eye(4)).det()
    ok = all(abs(complex(char.subs(sp.Symbol("s"), complex(*z)))) < 1e-9 for z in d["eigenvalues"])
    report(ok and d["controllable"], "chain: eigenvalues are roots of det(A - sI), controllable")


DECOUPLED = """coordinates x1, x2
parameters m1 = 1, m2 = 2, k1 = 3, k2 = 8
inputs F
T = m1*x1'^2/2 + m2*x2'^2/2
V = k1*x1^2/2 + k2*x2^2/2
Q[x1] = F
outputs y = x1
"""


def check_decoupled(qdot, tmp):
    path = Path(tmp) / "two.qd"
    path.write_text(DECOUPLED)
    d = lin(qdot, path)
    report(not d["controllable"] and d["controllability_rank"] == 2,
           "decoupled: not controllable, Kalman rank 2 of 4")
    w = math.sqrt(8 / 2)
    modes = d["uncontrollable_modes"]
    ok = len(modes) == 2 and all(m["states"] == ["x2", "x2'"] for m in modes)
    ims = sorted(m["eigenvalue"][1] for m in modes) if ok else []
    ok = ok and abs(ims[0] + w) < 1e-12 and abs(ims[1] - w) < 1e-12
    ok = ok and all(abs(m["eigenvalue"][0]) < 1e-12 for m in modes)
    report(ok, "decoupled: uncontrollable modes s = +-2i moving x2, x2'", json.dumps(modes))
    um = d["unobservable_modes"]
    report(not d["observable"] and len(um) == 2 and all(m["states"] == ["x2", "x2'"] for m in um),
           "decoupled: with y = x1 the x2 modes are unobservable")
    text = run(qdot, "linearize", str(path)).stdout
    named = [ln for ln in text.splitlines() if ln.strip().startswith("uncontrollable mode:")]
    report(len(named) == 2 and all(ln.endswith("moving x2, x2'") for ln in named),
           "decoupled: the text names the modes by their states", str(named))


def check_cart(qdot):
    path = EX / "cart_pendulum.qd"
    d = lin(qdot, path, "--about", "th=0")
    M, m, l, g = 1.0, 0.1, 0.5, 9.81
    lam = math.sqrt(g * (M + m) / (M * l))
    re = sorted(z[0] for z in d["eigenvalues"])
    ok = abs(re[0] + lam) < 1e-12 and abs(re[3] - lam) < 1e-12 and abs(re[1]) < 1e-12
    report(ok and d["controllable"], "cart-pendulum upright: s = 0, 0, +-sqrt(g(M+m)/(M l)), "
           "controllable", str(re))


def check_errors(qdot, tmp):
    path = Path(tmp) / "two.qd"
    out = run(qdot, "linearize", str(path), "--about", "zz=1")
    report(out.returncode == 2 and "zz" in out.stderr, "error: unknown name in --about",
           out.stderr.strip())
    out = run(qdot, "linearize", str(path), "--about", "x1=(")
    report(out.returncode == 2, "error: --about value that does not parse", out.stderr.strip())
    bad = Path(tmp) / "bad.qd"
    bad.write_text("coordinates x\ninputs F\nT = F*x'^2/2\n")
    out = run(qdot, "linearize", str(bad))
    report(out.returncode == 2 and "time derivative" in out.stderr,
           "error: input in T (its rate would be needed)", out.stderr.strip().splitlines()[0])


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", required=True)
    qdot = str(Path(ap.parse_args().build) / "qdot")
    rng = random.Random(23)
    with tempfile.TemporaryDirectory() as tmp:
        check_chain(qdot, tmp, rng)
        check_decoupled(qdot, tmp)
        check_cart(qdot)
        check_errors(qdot, tmp)
    print("%d passed, %d failed" % (results["passed"], results["failed"]))
    sys.exit(1 if results["failed"] else 0)


if __name__ == "__main__":
    main()

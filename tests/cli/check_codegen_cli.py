#!/usr/bin/env python3
"""End-to-end tests of `qdot codegen`, run against the built program.

    python3 tests/cli/check_codegen_cli.py --build BUILD_DIR

The written NAME.c and NAME.h must compile on their own with
`cc -std=c11 -Wall -Wextra -Wpedantic -Werror` (a selection of examples:
constraints, rolling, rheonomic, bodies, forces, dissipation).  For the
double pendulum (Goldstein ch. 1 ex. 22, seed 002_3e07e211eebc00b9.txt) a
small driver linked with the generated file prints q'', the energy and the
Jacobian at a state, checked against the textbook equations

    (m1 + m2) l1 th1'' + m2 l2 th2'' cos(th1 - th2) + m2 l2 th2'^2 sin(th1 - th2)
        + (m1 + m2) g sin th1 = 0
    l2 th2'' + l1 th1'' cos(th1 - th2) - l1 th1'^2 sin(th1 - th2) + g sin th2 = 0

solved here with NumPy-free 2x2 algebra, E = T + V written out, and the
Jacobian against central differences of those equations.  --set changes the
default parameters written; usage errors exit 2.  Prints "N passed, N
failed"; exit 1 on failure.
"""
import argparse
import math
import os
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
CC = os.environ.get("CC", "cc")
CFLAGS = ["-std=c11", "-Wall", "-Wextra", "-Wpedantic", "-Werror"]
SELECTION = ["double_pendulum", "pendulum_cartesian", "atwood", "bead_rotating_wire",
             "charged_particle_EB", "damped_pendulum", "heavy_top", "rolling_disk",
             "polar_generalized_force", "sphere_on_wedge", "double_pendulum_force"]

results = {"passed": 0, "failed": 0}


def check(name, ok, detail=""):
    results["passed" if ok else "failed"] += 1
    if not ok:
        print(f"FAIL {name} {detail}")


def run(cmd, cwd=None):
    p = subprocess.run(cmd, capture_output=True, text=True, timeout=120, cwd=cwd)
    return p.returncode, p.stdout, p.stderr


DRIVER = r"""
#include <stdio.h>
#include "dp.h"
int main(void) {
    double y[4] = {0.7, -0.4, 0.9, -1.3}, d[4], J[16];
    if (dp_N != 2 || dp_NPAR != 5)
        return 3;
    int rc = dp_rhs(0.0, y, dp_par_default, d);
    printf("%d %.17g %.17g %.17g %.17g\n", rc, d[0], d[1], d[2], d[3]);
    printf("%.17g\n", dp_energy(0.0, y, dp_par_default));
    dp_jacobian(0.0, y, dp_par_default, J);
    for (int i = 0; i < 16; i++)
        printf("%.17g%s", J[i], i == 15 ? "\n" : " ");
    for (int i = 0; i < dp_NPAR; i++)
        printf("%s=%.17g%s", dp_param_names[i], dp_par_default[i], i == dp_NPAR - 1 ? "\n" : " ");
    printf("%s %s\n", dp_coord_names[0], dp_coord_names[1]);
    return 0;
}
"""


def textbook_rhs(y, m1, m2, l1, l2, g):
    """Goldstein's double pendulum solved for the accelerations."""
    t1, t2, w1, w2 = y
    c, s = math.cos(t1 - t2), math.sin(t1 - t2)
    a11, a12 = (m1 + m2) * l1, m2 * l2 * c
    a21, a22 = l1 * c, l2
    b1 = -m2 * l2 * w2 * w2 * s - (m1 + m2) * g * math.sin(t1)
    b2 = l1 * w1 * w1 * s - g * math.sin(t2)
    det = a11 * a22 - a12 * a21
    return [w1, w2, (b1 * a22 - a12 * b2) / det, (a11 * b2 - a21 * b1) / det]


def textbook_energy(y, m1, m2, l1, l2, g):
    t1, t2, w1, w2 = y
    T = 0.5 * (m1 + m2) * l1**2 * w1**2 + 0.5 * m2 * l2**2 * w2**2 \
        + m2 * l1 * l2 * w1 * w2 * math.cos(t1 - t2)
    V = -(m1 + m2) * g * l1 * math.cos(t1) - m2 * g * l2 * math.cos(t2)
    return T + V


def close(a, b, tol):
    return abs(a - b) <= tol * (1 + abs(a) + abs(b))


def test_double_pendulum(qdot, tmp):
    out = tmp / "dp"
    out.mkdir()
    rc, so, se = run([qdot, "codegen", str(EXAMPLES / "double_pendulum.qd"), "-o", str(out),
                      "--prefix", "dp", "--set", "m2=1.5", "--set", "l2=0.75"])
    check("codegen dp rc", rc == 0, se)
    check("codegen dp says what it wrote", "dp.c" in so and "dp.h" in so, so)
    (out / "main.c").write_text(DRIVER)
    rc, _, se = run([CC, *CFLAGS, "-O2", "-o", "drv", "main.c", "dp.c", "-lm"], cwd=out)
    check("driver compiles with -Werror", rc == 0, se)
    if rc != 0:
        return
    rc, so, se = run([str(out / "drv")])
    check("driver runs", rc == 0, se)
    lines = so.splitlines()
    par = dict(kv.split("=") for kv in lines[3].split())
    check("--set reaches the defaults", float(par["m2"]) == 1.5 and float(par["l2"]) == 0.75
          and float(par["g"]) == 9.81, lines[3])
    check("coordinate names", lines[4] == "theta1 theta2", lines[4])
    p = [float(par[k]) for k in ("m1", "m2", "l1", "l2", "g")]
    y = [0.7, -0.4, 0.9, -1.3]
    f = lines[0].split()
    check("rhs returns 0", f[0] == "0", lines[0])
    want = textbook_rhs(y, *p)
    got = [float(x) for x in f[1:]]
    check("rhs = Goldstein's equations", all(close(a, b, 1e-12) for a, b in zip(got, want)),
          f"{got} vs {want}")
    E = float(lines[1])
    check("energy = T + V", close(E, textbook_energy(y, *p), 1e-12), f"{E}")
    J = [float(x) for x in lines[2].split()]
    worst = 0.0
    for k in range(4):
        h = 1e-6
        yp, ym = list(y), list(y)
        yp[k] += h
        ym[k] -= h
        fp, fm = textbook_rhs(yp, *p), textbook_rhs(ym, *p)
        for i in range(4):
            worst = max(worst, abs(J[4 * i + k] - (fp[i] - fm[i]) / (2 * h)))
    check("jacobian = finite differences of the textbook rhs", worst < 1e-6, f"{worst}")


def test_examples_compile(qdot, tmp):
    out = tmp / "ex"
    out.mkdir()
    for name in SELECTION:
        rc, _, se = run([qdot, "codegen", str(EXAMPLES / f"{name}.qd"), "-o", str(out)])
        check(f"codegen {name}", rc == 0, se)
        if rc != 0:
            continue
        rc, _, se = run([CC, *CFLAGS, "-c", f"{name}.c", "-o", f"{name}.o"], cwd=out)
        check(f"{name}.c compiles standalone with -Werror", rc == 0, se[:600])


def test_usage(qdot, tmp):
    dp = str(EXAMPLES / "double_pendulum.qd")
    rc, _, se = run([qdot, "codegen", dp, "--prefix", "9lives", "-o", str(tmp)])
    check("bad prefix exits 2", rc == 2, se)
    rc, _, se = run([qdot, "codegen", dp, "--bogus"])
    check("unknown option exits 2", rc == 2, se)
    rc, _, se = run([qdot, "codegen", str(tmp / "missing.qd"), "-o", str(tmp)])
    check("missing file exits 2", rc == 2, se)
    rc, _, se = run([qdot, "codegen", dp, "--set", "nosuch=1", "-o", str(tmp)])
    check("unknown --set exits 2", rc == 2, se)
    rc, _, se = run([qdot, "codegen", dp, "-o", str(tmp / "no" / "such" / "dir")])
    check("unwritable directory exits 1", rc == 1, se)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", required=True)
    args = ap.parse_args()
    qdot = os.path.join(args.build, "qdot")
    if not shutil.which(CC):
        print(f"skipped: no C compiler ({CC})")
        return 77  # ctest: skipped (SKIP_RETURN_CODE), not passed
    with tempfile.TemporaryDirectory() as d:
        tmp = Path(d)
        test_double_pendulum(qdot, tmp)
        test_examples_compile(qdot, tmp)
        test_usage(qdot, tmp)
    print(f"{results['passed']} passed, {results['failed']} failed")
    return 1 if results["failed"] else 0


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/env python3
"""End-to-end checks of `qdot codegen`, `qdot equilibria` and `qdot modes` on
models with `speeds` (the state is q and u).

    python3 tests/cli/check_speeds_linear_cli.py --build BUILD_DIR

Expected values are textbook results, not output of the code under test:
  - the thin uniform disk rolling upright (speeds u1 = theta', u2 the
    vertical angular velocity, u3 the spin about the axle): equilibria
    theta = +-pi/2 with x, y, phi, psi free; rolling straight at spin Omega
    it is stable iff Omega^2 > g/(3a) (I_axle = m a^2/2, I_diam = m a^2/4;
    Neimark and Fufaev, Dynamics of Nonholonomic Systems, ch. III; Routh,
    Advanced Rigid Dynamics art. 244), the tilt's root s^2 =
    -(4/5)(3 Omega^2 - g/a); checked either side of the threshold, and with
    --set g moving the threshold, and the threshold itself from --scan u3;
  - the same threshold from examples/rolling_disk_speeds.qd, the disk written
    independently in SymPy's rolling-disc frames (lean q2, spin u2);
  - examples/bicycle_speeds.qd: with the rear wheel driven (tau != 0) no
    state is at rest; with tau = 0 the steering spring's d = 0, the other
    coordinates free (more equations than unknowns: tau and k d);
  - the Chaplygin sleigh (examples/chaplygin_sleigh.qd): every configuration
    is at rest (no force), no equation left;
  - the double pendulum of examples/double_pendulum.qd with speeds u1 =
    theta1', u2 = theta1' + theta2' has the equilibria of the model without
    them (f_u(q, 0) = W^T f(q, 0) with W invertible);
  - the generated C of the Chaplygin sleigh, compiled with -Wpedantic
    -Werror, gives m v' = -m b w^2, (I + m b^2) w' = m b v w (Chaplygin 1911;
    Bloch, Nonholonomic Mechanics and Control, sec. 1.7, his contact point
    behind the centre: a = -b);
  - the model read once: from standard input (`-`) with and without speeds
    (a second read would find it empty);
  - errors: options that need coordinates alone, an unknown name in
    --about, a rheonomic speed map for equilibria, --eliminate for codegen.
Prints "N passed, N failed"; exit 1 on failure.
"""
import argparse
import json
import math
import os
import subprocess
import sys
import tempfile
from pathlib import Path

EX = Path(__file__).resolve().parents[2] / "examples"
results = {"passed": 0, "failed": 0}

DISK = """coordinates x, y, phi, theta, psi
parameters m = 1.4, a = 0.35, g = 9.81
body disk mass m inertia disk(m, a) at (x, y, a*sin(theta)) orientation euler(phi, theta, psi)
V = m*g*a*sin(theta)
rolls disk on plane((0, 0, 1), (0, 0, 0)) as disk(a)
speeds u1 = theta', u2 = omega_space(disk).z, u3 = omega(disk).z
"""

SLEIGH = """coordinates x, y, th
parameters m = 2, I = 0.3, b = 0.4
T = m/2*(x'^2 + y'^2) + I/2*th'^2
constraint blade: -x'*sin(th) + y'*cos(th) + b*th' = 0
speeds v = x'*cos(th) + y'*sin(th), w = th'
"""


def check(name, ok, detail=""):
    results["passed" if ok else "failed"] += 1
    if not ok:
        print(f"FAIL {name} {detail}")


def run(qdot, *args, cwd=None):
    p = subprocess.run([str(qdot), *args], capture_output=True, text=True, timeout=120,
                       cwd=cwd)
    return p.returncode, p.stdout, p.stderr


def close(a, b, tol=1e-9):
    return abs(a - b) <= tol * (1 + abs(b))


def disk_equilibria(qdot, path):
    rc, out, err = run(qdot, "equilibria", path, "--format", "json")
    check("disk equilibria rc", rc == 0, err)
    if rc:
        return
    j = json.loads(out)
    check("disk free", j["free"] == ["x", "y", "phi", "psi"], j["free"])
    check("disk speeds", j["speeds"] == ["u1", "u2", "u3"], j["speeds"])
    th = sorted(p["equilibrium"]["theta"] for p in j["equilibria"])
    check("disk theta", len(th) == 2 and close(th[0], -math.pi / 2, 1e-13)
          and close(th[1], math.pi / 2, 1e-13), th)
    check("disk exact", j["exact"] and j["method"] == "exact", out)


def disk_modes(qdot, path, g=9.81, a=0.35, sets=()):
    oc = math.sqrt(g / (3 * a))
    for factor, want in ((1.15, "stable"), (0.85, "unstable")):
        om = oc * factor
        rc, out, err = run(qdot, "modes", path, "--about", f"theta=pi/2, u3={om!r}",
                           "--format", "json", *sets)
        check(f"disk modes rc {factor} {sets}", rc == 0, err)
        if rc:
            continue
        j = json.loads(out)
        check(f"disk verdict {factor} {sets}", j["verdict"] == want, j["verdict"])
        check("disk reduced", j["kept"] == ["theta"]
              and j["ignorable"] == ["x", "y", "phi", "psi"], out)
        s2 = -0.8 * (3 * om * om - g / a)
        top = max(j["eigenvalues"], key=lambda s: math.hypot(*s))
        got = top[0] ** 2 - top[1] ** 2
        check(f"disk tilt root {factor} {sets}", close(got, s2, 1e-9), (got, s2))


def disk_scan(qdot, path, g=9.81, a=0.35):
    rc, out, err = run(qdot, "modes", path, "--about", "theta=pi/2", "--scan", "u3=1:6",
                       "--steps", "10", "--format", "json")
    check("disk scan rc", rc == 0, err)
    if rc:
        return
    t = json.loads(out)["transitions"]
    oc = math.sqrt(g / (3 * a))
    check("disk scan threshold", len(t) == 1 and close(t[0]["u3"], oc, 1e-8)
          and t[0]["from"] == "unstable" and t[0]["to"] == "stable", t)


def example_disk_scan(qdot, g=9.81, r=0.35):
    rc, out, err = run(qdot, "modes", str(EX / "rolling_disk_speeds.qd"), "--about", "q2=0",
                       "--scan", "u2=1:6", "--steps", "10", "--format", "json")
    check("example disk scan rc", rc == 0, err)
    if rc:
        return
    t = json.loads(out)["transitions"]
    check("example disk threshold", len(t) == 1 and close(t[0]["u2"], math.sqrt(g / (3 * r)),
                                                          1e-8), t)


def bicycle_and_sleigh(qdot):
    bike = str(EX / "bicycle_speeds.qd")
    rc, out, err = run(qdot, "equilibria", bike, "--format", "json")
    check("bicycle driven rc", rc == 0, err)
    if rc == 0:
        check("bicycle driven: none", json.loads(out)["equilibria"] == [], out)
    rc, out, err = run(qdot, "equilibria", bike, "--set", "tau=0", "--format", "json")
    check("bicycle free rc", rc == 0, err)
    if rc == 0:
        j = json.loads(out)
        eq = j["equilibria"]
        check("bicycle d = 0", len(eq) == 1 and abs(eq[0]["equilibrium"]["d"]) < 1e-12, out)
        check("bicycle free", j["free"] == ["x", "y", "th", "pr", "pf"], j["free"])
    rc, out, err = run(qdot, "equilibria", str(EX / "chaplygin_sleigh.qd"), "--format", "json")
    check("sleigh rc", rc == 0, err)
    if rc == 0:
        j = json.loads(out)
        check("sleigh any", j["free"] == ["x", "y", "th"] and len(j["equilibria"]) == 1
              and j["equilibria"][0]["equilibrium"] == {}, out)


def pendulum_with_speeds(qdot, tmp):
    src = (EX / "double_pendulum.qd").read_text()
    path = os.path.join(tmp, "dp_speeds.qd")
    with open(path, "w") as f:
        f.write(src + "\nspeeds u1 = theta1', u2 = theta1' + theta2'\n")
    rc1, out1, err1 = run(qdot, "equilibria", path, "--format", "json")
    rc2, out2, err2 = run(qdot, "equilibria", str(EX / "double_pendulum.qd"), "--format", "json")
    check("dp speeds rc", rc1 == 0 and rc2 == 0, err1 + err2)
    if rc1 or rc2:
        return
    a = sorted((p["equilibrium"]["theta1"], p["equilibrium"]["theta2"])
               for p in json.loads(out1)["equilibria"])
    b = sorted((p["equilibrium"]["theta1"], p["equilibrium"]["theta2"])
               for p in json.loads(out2)["equilibria"])
    check("dp speeds equilibria", len(a) == len(b) == 4 and all(
        close(x, y, 1e-12) for pa, pb in zip(a, b) for x, y in zip(pa, pb)), (a, b))


DRIVER = r"""
#include <stdio.h>
#include "sleigh.h"
int main(void) {
    double y[5] = {0.3, -0.2, 0.7, 1.3, -0.8}, d[5];
    if (sleigh_rhs(0.0, y, sleigh_par_default, d))
        return 1;
    printf("%.17g %.17g\n", d[3], d[4]);
    return 0;
}
"""


def sleigh_codegen(qdot, tmp):
    path = os.path.join(tmp, "sleigh.qd")
    with open(path, "w") as f:
        f.write(SLEIGH)
    rc, out, err = run(qdot, "codegen", path, "-o", tmp)
    check("sleigh codegen rc", rc == 0, err)
    if rc:
        return
    with open(os.path.join(tmp, "main.c"), "w") as f:
        f.write(DRIVER)
    cc = os.environ.get("CC") or "cc"
    exe = os.path.join(tmp, "sleigh_main")
    p = subprocess.run([cc, "-std=c11", "-Wall", "-Wextra", "-Wpedantic", "-Werror", "-O2",
                        "-o", exe, "main.c", "sleigh.c", "-lm"], cwd=tmp, capture_output=True,
                       text=True)
    check("sleigh compiles", p.returncode == 0, p.stderr)
    if p.returncode:
        return
    p = subprocess.run([exe], capture_output=True, text=True)
    vd, wd = (float(x) for x in p.stdout.split())
    m, I, b, v, w = 2, 0.3, 0.4, 1.3, -0.8
    check("sleigh v'", close(vd, -b * w * w, 1e-13), (vd, -b * w * w))
    check("sleigh w'", close(wd, m * b * v * w / (I + m * b * b), 1e-13), wd)


def stdin_once(qdot, disk):
    for path, want in ((disk, "theta = pi/2"), (str(EX / "double_pendulum.qd"),
                                                 "theta1 = 0, theta2 = 0")):
        for cmd in ("equilibria", "modes"):
            with open(path) as f:
                p = subprocess.run([str(qdot), cmd, "-"], stdin=f, capture_output=True,
                                   text=True, timeout=60)
            check(f"stdin {cmd} {os.path.basename(path)}",
                  p.returncode == 0 and (want in p.stdout or cmd == "modes"), p.stderr)


def errors(qdot, disk, tmp):
    rc, out, err = run(qdot, "modes", disk, "--initial", "theta=1")
    check("initial refused", rc == 2 and "--initial is not available for a model with speeds"
          in err, err)
    rc, out, err = run(qdot, "modes", disk, "--scan", "w9=1:2")
    check("scan unknown", rc == 2 and "w9 is not a parameter, coordinate or speed" in err, err)
    rc, out, err = run(qdot, "modes", disk, "--about", "theta=pi/2, w9=1")
    check("about unknown", rc == 2 and "w9=1" in err, err)
    rc, out, err = run(qdot, "equilibria", disk, "--guess", "theta=1")
    check("guess refused", rc == 2 and "--guess" in err, err)
    rc, out, err = run(qdot, "codegen", disk, "--eliminate", "-o", tmp)
    check("eliminate refused", rc == 2 and "--eliminate" in err, err)
    path = os.path.join(tmp, "drift.qd")
    with open(path, "w") as f:
        f.write("coordinates x\nparameters k = 2, c = 0.5\nparticle 1 at (x, 0)\n"
                "V = k*x^2/2\nspeeds u = x' - c\n")
    rc, out, err = run(qdot, "equilibria", path)
    check("rheonomic refused", rc == 1 and "free of the speeds" in err, (rc, err))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", required=True)
    args = ap.parse_args()
    qdot = Path(args.build) / "qdot"
    with tempfile.TemporaryDirectory() as tmp:
        disk = os.path.join(tmp, "disk.qd")
        with open(disk, "w") as f:
            f.write(DISK)
        disk_equilibria(qdot, disk)
        disk_modes(qdot, disk)
        disk_modes(qdot, disk, g=4.0, sets=("--set", "g=4"))
        disk_scan(qdot, disk)
        example_disk_scan(qdot)
        bicycle_and_sleigh(qdot)
        pendulum_with_speeds(qdot, tmp)
        sleigh_codegen(qdot, tmp)
        stdin_once(qdot, disk)
        errors(qdot, disk, tmp)
    print(f"{results['passed']} passed, {results['failed']} failed")
    return 1 if results["failed"] else 0


if __name__ == "__main__":
    sys.exit(main())

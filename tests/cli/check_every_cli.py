#!/usr/bin/env python3
"""`qdot simulate --dt H` is the output spacing of every method, `--step H`
the step of a fixed-step method (issue 33).

examples/double_pendulum.qd over 10 s against a reference (dop853, rtol
1e-13, --dt 0.2):
- `--dt 0.2` alone: an adaptive method (dop853: rows asked for, no step),
  rows exactly at t = 0, 0.2, ..., 10, each within 1e-7 of the reference;
  `--dt 0.2 --rtol 1e-10` (refused before) the same rows;
- `--step 0.2`: gl4 with the step 0.2 (what `--dt 0.2` used to give), far
  off: the point of separating the two;
- `--dt 1 --step 0.01`: gl4's step 0.01 with rows every 1 (11 rows, within
  1e-5); the older spelling `--every 1 --method gl4 --dt 0.01` the same
  rows; `--method gl4 --dt 0.01` takes the spacing as its step (1000 steps);
- `--every 0.2 --rtol 1e-10` (the older name) = `--dt 0.2 --rtol 1e-10`;
- `--step 0.2 --rtol 1e-10` without --method is refused (exit 2), and so
  is `--step` with an adaptive method.
The harmonic oscillator x'' = -x from x = 1: `--dt 0.2 --t-end 20` rows
within 2e-9 of cos t (gl4 with the step 0.2 is 100 times further off).
(Python's dt=, step=: python/tests/test_every.py.)

Usage: check_every_cli.py --build BUILD_DIR
"""
import argparse
import csv
import io
import math
import re
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
MODEL = str(ROOT / "examples" / "double_pendulum.qd")


def rows(qdot, *args, model=MODEL, t_end="10"):
    p = subprocess.run([qdot, "simulate", model, "--t-end", t_end, *args], capture_output=True,
                       text=True)
    return p, list(csv.DictReader(io.StringIO(p.stdout))) if p.returncode == 0 else []


def worst(a, b):
    if not a or len(a) != len(b):
        return float("inf")
    return max(abs(float(x[k]) - float(y[k])) for x, y in zip(a, b) for k in ("theta1", "theta2"))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", required=True)
    build = Path(ap.parse_args().build)
    qdot = str(build / "qdot")
    failures = 0

    def check(ok, what):
        nonlocal failures
        print("%s %s" % ("ok" if ok else "FAIL", what))
        failures += not ok

    _, ref = rows(qdot, "--dt", "0.2", "--method", "dop853", "--rtol", "1e-13")
    check(len(ref) == 51, "reference: 51 rows")
    p, got = rows(qdot, "--dt", "0.2")
    check(p.returncode == 0 and "dop853" in p.stderr, "--dt alone: adaptive (dop853)")
    check([round(float(r["t"]) / 0.2, 9) for r in got] == list(range(51)), "rows at t = 0.2 k")
    check(worst(got, ref) < 1e-7, "--dt 0.2: within 1e-7 of the reference (%.3g)"
          % worst(got, ref))
    p, both = rows(qdot, "--dt", "0.2", "--rtol", "1e-10")
    check(p.returncode == 0 and both == got, "--dt 0.2 --rtol 1e-10: runs, the same rows")
    p, old = rows(qdot, "--every", "0.2", "--rtol", "1e-10")
    check(p.returncode == 0 and old == got, "--every 0.2 --rtol 1e-10: the same rows")
    p, coarse = rows(qdot, "--step", "0.2")
    check("gl4" in p.stderr and worst(coarse, ref) > 1e-3,
          "--step 0.2: gl4's step 0.2, off by %.3g" % worst(coarse, ref))
    p, g = rows(qdot, "--dt", "1", "--step", "0.01")
    check("gl4" in p.stderr and "1000 steps" in p.stderr and worst(g, ref[::5]) < 1e-5,
          "--dt 1 --step 0.01: gl4, 11 rows within 1e-5 (%.3g)" % worst(g, ref[::5]))
    p, g2 = rows(qdot, "--every", "1", "--method", "gl4", "--dt", "0.01")
    check(p.returncode == 0 and g2 == g, "--every 1 --method gl4 --dt 0.01: the same rows")
    p, g3 = rows(qdot, "--method", "gl4", "--dt", "0.01")
    check(len(g3) == 1001 and "1000 steps" in p.stderr,
          "--method gl4 --dt 0.01: the spacing is the step")
    p, _ = rows(qdot, "--step", "0.2", "--rtol", "1e-10")
    check(p.returncode == 2 and p.stdout == "" and "--step" in p.stderr,
          "--step 0.2 --rtol 1e-10: exit 2")
    p, _ = rows(qdot, "--step", "0.2", "--method", "dop853")
    check(p.returncode == 2 and "--step" in p.stderr, "--step with dop853: exit 2")

    with tempfile.TemporaryDirectory() as d:
        osc = Path(d) / "osc.qd"
        osc.write_text("coordinates x\nT = x'^2/2\nV = x^2/2\ninitial x = 1, x' = 0\n")
        err = {}
        for name, args in (("dt", ["--dt", "0.2"]), ("step", ["--step", "0.2"])):
            p, r = rows(qdot, *args, model=str(osc), t_end="20")
            err[name] = (max(abs(float(x["x"]) - math.cos(float(x["t"]))) for x in r)
                         if len(r) == 101 else float("inf"))
            method = re.search(r"simulate: (\w+)", p.stderr)
            print("  oscillator %s 0.2: %s, %d rows, max |x - cos t| %.3g"
                  % (name, method.group(1) if method else "?", len(r), err[name]))
        check(err["dt"] < 2e-9, "oscillator --dt 0.2: within 2e-9 of cos t (%.3g)" % err["dt"])
        check(err["step"] > 100 * err["dt"], "oscillator --step 0.2 (gl4) further off (%.3g)"
              % err["step"])
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()

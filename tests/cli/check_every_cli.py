#!/usr/bin/env python3
"""`qdot simulate --every H`: an output spacing every method honours through
its dense output, apart from the step (issue 33).

examples/double_pendulum.qd over 10 s against a reference (dop853, rtol
1e-13, --every 0.2):
- `--every 0.2 --rtol 1e-10`: an adaptive method (dop853, no --dt given),
  rows exactly at t = 0, 0.2, ..., 10, each within 1e-7 of the reference
  (gl4 with the step 0.2, what `--dt 0.2` alone gives, is far off: the
  point of separating the two);
- `--every 1 --method gl4 --dt 0.01`: rows at spacing 1 from the fixed
  step 0.01, within 1e-5;
- `--dt 0.2 --rtol 1e-10` without --method is refused (exit 2) with a hint
  naming `--every 0.2`.
(Python's every=: python/tests/test_every.py.)

Usage: check_every_cli.py --build BUILD_DIR
"""
import argparse
import csv
import io
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
MODEL = str(ROOT / "examples" / "double_pendulum.qd")


def rows(qdot, *args):
    p = subprocess.run([qdot, "simulate", MODEL, "--t-end", "10", *args], capture_output=True,
                       text=True)
    return p, list(csv.DictReader(io.StringIO(p.stdout))) if p.returncode == 0 else []


def worst(a, b):
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

    _, ref = rows(qdot, "--every", "0.2", "--method", "dop853", "--rtol", "1e-13")
    check(len(ref) == 51, "reference: 51 rows")
    p, got = rows(qdot, "--every", "0.2", "--rtol", "1e-10")
    check(p.returncode == 0 and "dop853" in p.stderr, "--every --rtol: adaptive (dop853)")
    check([round(float(r["t"]) / 0.2, 9) for r in got] == list(range(51)),
          "rows at t = 0.2 k")
    check(len(got) == 51 and worst(got, ref) < 1e-7, "within 1e-7 of the reference (%.3g)"
          % (worst(got, ref) if got else float("nan")))
    _, old = rows(qdot, "--dt", "0.2")
    check(len(old) == 51 and worst(old, ref) > 1e-3,
          "--dt 0.2 alone is gl4's step 0.2 (off by %.3g)" % (worst(old, ref) if old else 0))
    p, g = rows(qdot, "--every", "1", "--method", "gl4", "--dt", "0.01")
    check(len(g) == 11 and worst(g, ref[::5]) < 1e-5,
          "--every 1 with gl4 --dt 0.01: 11 rows within 1e-5 (%.3g)"
          % (worst(g, ref[::5]) if g else float("nan")))
    p, _ = rows(qdot, "--dt", "0.2", "--rtol", "1e-10")
    check(p.returncode == 2 and "every 0.2" in p.stderr and p.stdout == "",
          "--dt 0.2 --rtol 1e-10: exit 2 with the hint")

    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()

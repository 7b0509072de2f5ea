#!/usr/bin/env python3
"""No command exits 0 with non-finite rows (issue 30).

    python3 tests/cli/check_nonfinite_cli.py --build BUILD_DIR

  - the finite-time blow-up x'' = 4 x^3 from x = 1, x' = 1 (the blow-up at
    t = integral_1^inf dx / sqrt(2 x^4 - 1) = 0.7531): every adaptive method,
    bdf included, stops with "step size underflow at t = 0.753" (exit 1);
    every fixed-step method stops at the first non-finite state (exit 1);
    no row printed holds inf or NaN;
  - x'' = 1/(2 sqrt(x)) from x = 1, x' = -5 (x = 0 at t = 0.2028, sqrt of a
    negative number beyond): dop853 fails as dopri5 does, and in a sweep
    the runs fail with their reason instead of "ok" with NaN;
  - sweep --threads above the most (1024) exits 2 naming the limit; the
    summary reports the threads started (at most the runs).
Prints "N passed, N failed"; exit 1 on failure.
"""
import argparse
import math
import subprocess
import sys
import tempfile
from pathlib import Path

BLOWUP = "coordinates x\nparameters m = 1\nT = m/2*x'^2\nV = -x^4\ninitial x = 1, x' = 1\n"
ROOT = "coordinates x\nT = x'^2/2\nV = -sqrt(x)\ninitial x = 1, x' = -5\n"

passed = failed = 0


def check(name, ok, detail=""):
    global passed, failed
    if ok:
        passed += 1
    else:
        failed += 1
        print("FAIL", name, detail[:400])


def finite_rows(out):
    """Every number of every CSV row after the header is finite."""
    for line in out.splitlines()[1:]:
        for cell in line.split(","):
            try:
                if not math.isfinite(float(cell)):
                    return False
            except ValueError:
                pass
    return True


def run(qdot, *args, timeout=120):
    return subprocess.run([qdot, *args], capture_output=True, text=True, timeout=timeout)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", required=True)
    qdot = str(Path(ap.parse_args().build) / "qdot")
    with tempfile.TemporaryDirectory() as tmp:
        blow, root = Path(tmp) / "blow.qd", Path(tmp) / "root.qd"
        blow.write_text(BLOWUP)
        root.write_text(ROOT)
        for m in ["dopri5", "dop853", "bdf", "taylor"]:
            r = run(qdot, "simulate", str(blow), "--t-end", "2", "--method", m,
                    "--max-steps", "1000000")
            check(f"blow-up {m} underflow", r.returncode == 1 and
                  "step size underflow at t = 0.753" in r.stderr, r.stderr)
            check(f"blow-up {m} rows finite", finite_rows(r.stdout))
        for m in ["verlet", "yoshida4", "yoshida6", "yoshida8", "gl2", "gl4", "gl6", "taylor"]:
            r = run(qdot, "simulate", str(blow), "--t-end", "2", "--method", m, "--dt", "0.01")
            check(f"blow-up {m} fails", r.returncode == 1 and "error" in r.stderr, r.stderr)
            check(f"blow-up {m} rows finite", finite_rows(r.stdout), r.stdout[-300:])
            if m.startswith("verlet") or m.startswith("yoshida"):
                check(f"blow-up {m} names t", "non-finite state at t = 0.7" in r.stderr
                      or "non-finite state at t = 0.8" in r.stderr, r.stderr)
        for m in ["dop853", "dopri5"]:
            r = run(qdot, "simulate", str(root), "--t-end", "2", "--method", m)
            check(f"sqrt {m} fails", r.returncode == 1 and
                  "step size underflow at t = 0.2027" in r.stderr, r.stderr)
            check(f"sqrt {m} rows finite", finite_rows(r.stdout))
        r = run(qdot, "sweep", str(root), "--grid", "x'=-5:-4:3", "--t-end", "2",
                "--measure", "final", "--method", "dop853")
        rows = r.stdout.splitlines()[1:]
        check("sweep sqrt runs fail", len(rows) == 3 and
              all("step size underflow" in row and not row.endswith(",ok") for row in rows),
              r.stdout)
        check("sweep sqrt summary", "3 failed" in r.stderr, r.stderr)
        r = run(qdot, "sweep", str(root), "--grid", "x'=1:2:3", "--t-end", "0.1",
                "--measure", "final", "--threads", "1e12")
        check("sweep --threads 1e12 refused", r.returncode == 2 and "1024" in r.stderr and
              "3567587328" not in r.stderr, r.stderr)
        r = run(qdot, "sweep", str(root), "--grid", "x'=1:2:3", "--t-end", "0.1",
                "--measure", "final", "--threads", "1024")
        check("sweep threads reported as started", r.returncode == 0 and
              "3 runs on 3 threads" in r.stderr, r.stderr)
    print(f"{passed} passed, {failed} failed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())

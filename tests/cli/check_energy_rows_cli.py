#!/usr/bin/env python3
"""The energy error `qdot simulate` reports is the one of the rows it writes
(issue 33).

examples/double_pendulum.qd from theta1 = 0.5 at rest with dop853 and an
output grid of 0.01: the rows between the steps are the dense output's, whose
energy error is larger than at the steps.  `energy_error_max` (JSON) and the
summary's "energy error" equal max |E - E0| / max(|E0|, max T) recomputed
from the CSV rows (here |E0| > max T = E0 - min V, so the denominator is
|E0|); `energy_error_steps` is the integrator's own, at its steps.  Also for
a coarse grid (0.5) and for rows at every step; with dopri5 (its quartic
dense output), with event rows, and with gl4's step 0.05 and rows every
0.01 (`--step 0.05 --dt 0.01`: cubic Hermite rows, whose energy error is
several times the steps').

Usage: check_energy_rows_cli.py --build BUILD_DIR
"""
import argparse
import csv
import json
import re
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", required=True)
    qdot = str(Path(ap.parse_args().build) / "qdot")
    model = str(ROOT / "examples" / "double_pendulum.qd")
    failures = 0
    dop853 = ["--method", "dop853", "--rtol", "1e-9"]
    cases = [dop853 + ["--dt", "0.01"], dop853 + ["--dt", "0.5"], dop853,
             ["--method", "dopri5", "--rtol", "1e-9", "--dt", "0.01"],
             ["--method", "dopri5", "--dt", "0.01", "--event", "theta1 = 0"],
             ["--step", "0.05", "--dt", "0.01"]]
    for grid in cases:
        with tempfile.TemporaryDirectory() as d:
            out = Path(d) / "rows.csv"
            p = subprocess.run([qdot, "simulate", model, "--t-end", "20", *grid, "--out",
                                str(out), "--format", "json"],
                               capture_output=True, text=True)
            if p.returncode != 0:
                print("FAIL", grid, p.stderr)
                failures += 1
                continue
            summary = json.loads(p.stdout)
            with open(out) as f:
                rows = list(csv.DictReader(f))
        E = [float(r["energy"]) for r in rows]
        want = max(abs(e - E[0]) for e in E) / abs(E[0])
        got = summary["energy_error_max"]
        m = re.search(r"energy error ([0-9.e+-]+) over the rows written \(([0-9.e+-]+) at the "
                      r"steps\)", p.stderr)
        ok = (abs(got - want) <= 1e-6 * want and m is not None
              and abs(float(m.group(1)) - want) <= 6e-3 * want
              and "energy_error_steps" in summary)
        print("%s %s: %d rows, energy_error_max %.6g, from the rows %.6g, at the steps %.6g"
              % ("ok" if ok else "FAIL", grid or "every step", len(rows), got, want,
                 summary.get("energy_error_steps", float("nan"))))
        failures += not ok
        if grid[-2:] == ["--dt", "0.01"] and not summary["energy_error_steps"] < got:
            print("FAIL: the dense rows should show a larger error than the steps here")
            failures += 1
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()

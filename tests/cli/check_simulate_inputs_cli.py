#!/usr/bin/env python3
"""End-to-end checks of inputs in `qdot simulate` (issue 23).

    python3 tests/cli/check_simulate_inputs_cli.py --build BUILD_DIR

The forced oscillator m x'' + k x = F (w^2 = k/m = 4; Goldstein sec. 1.6, seed 002)
against closed forms, not output of the code under test:
  - --input "F = 3*cos(t)" from rest: x = 3/(m (w^2 - 1)) (cos t - cos 2t);
  - --input "F = -c*x'" (a feedback law in the state): the damped oscillator,
    x = e^(-g t) (x0 cos wd t + (v0 + g x0)/wd sin wd t), g = c/2m;
  - --input F=ramp.csv with samples of F = a t (linear interpolation is exact on it):
    x = a/k (t - sin(w t)/w); the model's `outputs` column equals the interpolated F;
  - errors, exit 2: an input used but not supplied, a CSV that does not cover the run,
    an unknown input, an input given twice;
  - the cart-pendulum example with a PD law on the tilt, F = -30 th - 5 th' (stable by its
    linearization th'' = g (M + m)/(M l) th + F/(M l)), stays near upright (|th| <= 0.1
    over 5 s, |th| < 0.01 at the end), while with F = 0 it falls (|th| > 1).
Prints "N passed, N failed"; exit 1 on failure.
"""
import argparse
import csv
import io
import math
import subprocess
import sys
import tempfile
from pathlib import Path

EX = Path(__file__).resolve().parents[2] / "examples"
results = {"passed": 0, "failed": 0}

OSC = """coordinates x
parameters m = 2, k = 8
inputs F
T = m*x'^2/2
V = k*x^2/2
Q[x] = F
outputs force = F
"""


def report(ok, label, detail=""):
    results["passed" if ok else "failed"] += 1
    print("%s %s %s" % ("ok  " if ok else "FAIL", label, detail))


def sim(qdot, path, *args):
    out = subprocess.run([qdot, "simulate", str(path), "--rtol", "1e-12", *args],
                         capture_output=True, text=True, timeout=60)
    rows = list(csv.DictReader(io.StringIO(out.stdout))) if out.returncode == 0 else []
    return out, rows


def worst(rows, fn, col="x"):
    return max(abs(float(r[col]) - fn(float(r["t"]))) for r in rows)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", required=True)
    qdot = str(Path(ap.parse_args().build) / "qdot")
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "osc.qd"
        path.write_text(OSC)
        out, rows = sim(qdot, path, "--t-end", "10", "--input", "F = 3*cos(t)")
        err = worst(rows, lambda t: 0.5 * (math.cos(t) - math.cos(2 * t))) if rows else 1
        report(err < 1e-9, "--input F = 3*cos(t): the driven response", "%.3g" % err)

        g, wd = 0.2, math.sqrt(4 - 0.04)
        out, rows = sim(qdot, path, "--t-end", "8", "--input", "F = -4/5*x'",
                        "--initial", "x=1, x'=0.5")
        err = worst(rows, lambda t: math.exp(-g * t) * (math.cos(wd * t) +
                                                          (0.5 + g) / wd * math.sin(wd * t))) \
            if rows else 1
        report(err < 1e-9, "--input F = -c x': a feedback law gives the damped oscillator",
               "%.3g" % err)

        a = 0.7
        ramp = Path(tmp) / "ramp.csv"
        ramp.write_text("t,F\n" + "".join("%r,%r\n" % (t, a * t) for t in (0.0, 3.0, 7.5, 10.0)))
        out, rows = sim(qdot, path, "--t-end", "10", "--input", "F=%s" % ramp)
        err = worst(rows, lambda t: a / 8 * (t - math.sin(2 * t) / 2)) if rows else 1
        ferr = worst(rows, lambda t: a * t, "force") if rows else 1
        report(err < 1e-9 and ferr < 1e-12, "--input F=ramp.csv: linear interpolation, the "
               "`outputs` column", "%.3g %.3g" % (err, ferr))

        out, _ = sim(qdot, path, "--t-end", "1")
        report(out.returncode == 2 and "input F is used but not supplied" in out.stderr,
               "error: input used but not supplied", out.stderr.strip())
        short = Path(tmp) / "short.csv"
        short.write_text("0,1\n0.5,1\n")
        out, _ = sim(qdot, path, "--t-end", "1", "--input", "F=%s" % short)
        report(out.returncode == 2 and "covers t = 0 to 0.5" in out.stderr,
               "error: a CSV that does not cover the run", out.stderr.strip())
        out, _ = sim(qdot, path, "--t-end", "1", "--input", "G = 1")
        report(out.returncode == 2 and "'G' is not an input" in out.stderr,
               "error: an unknown input", out.stderr.strip())
        out, _ = sim(qdot, path, "--t-end", "1", "--input", "F = 1", "--input", "F=2")
        report(out.returncode == 2 and "given twice" in out.stderr, "error: an input given twice",
               out.stderr.strip())

        cart = EX / "cart_pendulum.qd"
        out, rows = sim(qdot, cart, "--t-end", "5", "--input",
                        "F = -30*th - 5*th'")
        held = rows and max(abs(float(r["th"])) for r in rows) <= 0.1 + 1e-12 and \
            abs(float(rows[-1]["th"])) < 1e-2
        out2, rows2 = sim(qdot, cart, "--t-end", "5", "--input", "F = 0")
        fell = rows2 and max(abs(float(r["th"])) for r in rows2) > 1
        report(bool(held and fell), "cart-pendulum: a PD law holds it up, F = 0 lets it fall")
    print("%d passed, %d failed" % (results["passed"], results["failed"]))
    sys.exit(1 if results["failed"] else 0)


if __name__ == "__main__":
    main()

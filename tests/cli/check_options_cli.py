#!/usr/bin/env python3
"""Options read as the user wrote them (issue 30):

  - an option given twice is refused (exit 2, "--t-end is given twice"),
    the ones meant to repeat (--set, --event, ...) excepted; a parameter
    --set twice and a name twice in --initial are refused;
  - numeric options (--t-end, --dt, --rtol, --atol) take constant
    expressions in pi, e and the model's parameters: --t-end "2*pi/w" is
    one period of an oscillator of angular frequency w = sqrt(k/m), so the
    last row is back at the start (x = 0, x' = 1) and at t = 2 pi/w
    exactly as computed in double; an unknown name is located in the
    option's text (the option's name, a caret under the name, "did you
    mean"), exit 2;
  - a bad expression in a sweep's --measure (max:, min:, escape:) is shown
    in the --measure text at its place, not under an --output or --event
    option the user never typed.

    python3 tests/cli/check_options_cli.py --build BUILD_DIR
"""
import argparse
import math
import subprocess
import sys
import tempfile
from pathlib import Path

OSC = """coordinates x
parameters m = 2, k = 8
T = m*x'^2/2
V = k*x^2/2
initial x = 0, x' = 1
"""
results = {"passed": 0, "failed": 0}


def check(name, ok, detail=""):
    if ok:
        results["passed"] += 1
    else:
        results["failed"] += 1
        print("FAIL %s %s" % (name, detail))


def run(qdot, *args):
    return subprocess.run([str(qdot)] + [str(a) for a in args], capture_output=True, text=True,
                          timeout=120)


def duplicates(qdot, osc):
    cases = [
        (["simulate", osc, "--t-end", "1", "--t-end", "2"], "--t-end is given twice"),
        (["simulate", osc, "--t-end=1", "--t-end=2"], "--t-end is given twice"),
        (["simulate", osc, "--t-end", "1", "--rtol", "1e-8", "--rtol", "1e-9"],
         "--rtol is given twice"),
        (["simulate", osc, "--t-end", "1", "--output", "x", "--output", "x'"],
         "--output is given twice"),
        (["simulate", osc, "--t-end", "1", "--set", "m=2", "--set", "m=3"],
         "--set: m is given twice"),
        (["eom", osc, "--set", "k=1", "--set", "k = 2"], "--set: k is given twice"),
        (["simulate", osc, "--t-end", "1", "--initial", "x=1, x=2"], "'x' is given twice"),
        (["sweep", osc, "--grid", "m=1:2:2", "--t-end", "1", "--t-end", "2", "--measure",
          "final"], "--t-end is given twice"),
        (["eom", osc, "--format", "json", "--format", "text"], "--format is given twice"),
        (["diff", "x^2", "x", "--format", "text", "--format", "latex"],
         "--format is given twice"),
    ]
    for args, want in cases:
        r = run(qdot, *args)
        name = " ".join(str(a) for a in args[2:])
        check("twice: %s: exit 2" % name, r.returncode == 2, "exit %d %r" % (r.returncode,
                                                                            r.stderr))
        check("twice: %s: says so" % name, want in r.stderr, repr(r.stderr))
    # the options that repeat still do
    r = run(qdot, "simulate", osc, "--t-end", "1", "--set", "m=2", "--set", "k=8",
            "--event", "x = 0", "--event", "x' = 0")
    check("--set and --event repeat", r.returncode == 0, r.stderr)


def expressions(qdot, osc):
    w = math.sqrt(8 / 2)
    r = run(qdot, "simulate", osc, "--t-end", "2*pi/sqrt(k/m)", "--rtol", "1e-12",
            "--atol", "1e-14")
    check("--t-end 2*pi/sqrt(k/m): exit 0", r.returncode == 0, r.stderr)
    if r.returncode == 0:
        last = [float(v) for v in r.stdout.strip().splitlines()[-1].split(",")]
        check("--t-end 2*pi/sqrt(k/m): ends at one period",
              abs(last[0] - 2 * math.pi / w) <= 4e-16 * math.pi, repr(last[0]))
        check("--t-end 2*pi/sqrt(k/m): back at the start", abs(last[1]) < 1e-9 and
              abs(last[2] - 1) < 1e-9, repr(last))
    r = run(qdot, "simulate", osc, "--t-end", "1", "--dt", "pi/(100*k)", "--method", "verlet")
    rows = r.stdout.strip().splitlines()[1:] if r.returncode == 0 else []
    check("--dt pi/(100*k): the step", r.returncode == 0 and len(rows) >= 2 and
          float(rows[1].split(",")[0]) == math.pi / 800, r.stderr + repr(rows[:2]))
    r = run(qdot, "simulate", osc, "--t-end", "2*pj")
    check("--t-end 2*pj: exit 2", r.returncode == 2, r.stderr)
    lines = r.stderr.splitlines()
    check("--t-end 2*pj: located in the option", len(lines) >= 4 and
          lines[0].startswith("--t-end:1:3: error: unknown name 'pj'") and
          lines[1] == "  2*pj" and lines[2] == "    ^~" and "did you mean 'pi'?" in lines[3],
          repr(r.stderr))
    r = run(qdot, "simulate", osc, "--t-end", "1", "--rtol", "1e-8*pii")
    check("--rtol 1e-8*pii: did you mean pi", r.returncode == 2 and
          r.stderr.startswith("--rtol:1:6: error:") and "did you mean 'pi'?" in r.stderr,
          repr(r.stderr))
    r = run(qdot, "simulate", osc, "--t-end", "1", "--dt", "-m", "--method", "verlet")
    check("--dt -m: refused as not positive", r.returncode == 2 and "the output spacing must "
          "be a positive number, not '-m' (--dt)" in r.stderr, repr(r.stderr))
    r = run(qdot, "simulate", osc, "--t-end", "1", "--step", "-m", "--method", "verlet")
    check("--step -m: refused as not positive", r.returncode == 2 and "the step must be a "
          "positive number, not '-m' (--step)" in r.stderr, repr(r.stderr))
    r = run(qdot, "simulate", osc, "--t-end", "2*x")
    check("--t-end 2*x: a coordinate is not a constant", r.returncode == 2 and
          "'x' is not a constant" in r.stderr, repr(r.stderr))
    # a vector of the model where a scalar is needed is said as such, with
    # its components, not "unknown name" (the model's reader knows it)
    vec = Path(osc).with_name("vec.qd")
    vec.write_text("coordinates x, y\nP = (x, y, 0)\nparticle 1 at P\nV = (x^2 + y^2)/2\n")
    r = run(qdot, "simulate", vec, "--t-end", "1", "--output", "P")
    check("--output P (a vector): said so, with its components", r.returncode == 2 and
          "'P' is a vector where a scalar is needed" in r.stderr and "P.x, P.y or P.z" in r.stderr
          and "unknown name" not in r.stderr, repr(r.stderr))
    r = run(qdot, "simulate", vec, "--t-end", "1", "--output", "P.y")
    check("--output P.y: a component is a column", r.returncode == 0 and
          r.stdout.splitlines()[0].endswith(",P.y"), repr(r.stdout[:200]) + r.stderr)


def measures(qdot, osc):
    cases = [
        ("final, max:foo", "--measure:1:12: error: unknown name 'foo'", "             ^~~"),
        ("escape:foo>3", "--measure:1:8: error: unknown name 'foo'", "         ^~~"),
        ("final, escape: x > 1+", "--measure:1:22: error:", "                       ^"),
        ("escape:x>bar", "--measure:1:10: error: unknown name 'bar'", "           ^~~"),
    ]
    for spec, first, caret in cases:
        r = run(qdot, "sweep", osc, "--grid", "m=1:2:2", "--t-end", "1", "--measure", spec)
        lines = r.stderr.splitlines()
        check("--measure %r: exit 2" % spec, r.returncode == 2, r.stderr)
        check("--measure %r: in the measure text" % spec, len(lines) >= 3 and
              lines[0].startswith(first) and lines[1] == "  " + spec and lines[2] == caret,
              repr(r.stderr))
        check("--measure %r: no --output/--event" % spec,
              "--output" not in r.stderr and "--event" not in r.stderr, repr(r.stderr))
    # the escape still measures: x = sin(w t)/w first exceeds 0.25 at asin(w/4)/w
    r = run(qdot, "sweep", osc, "--grid", "m=2:2:1", "--t-end", "2", "--rtol", "1e-12",
            "--measure", "escape:x>0.25")
    w = 2.0
    got = float(r.stdout.splitlines()[1].split(",")[1]) if r.returncode == 0 else float("nan")
    check("escape:x>0.25 at asin(w/4)/w", abs(got - math.asin(w / 4) / w) < 1e-9,
          "%r %s" % (got, r.stderr))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", required=True)
    qdot = Path(ap.parse_args().build).resolve() / "qdot"
    with tempfile.TemporaryDirectory(prefix="qdot-opt-") as t:
        osc = Path(t) / "osc.qd"
        osc.write_text(OSC)
        duplicates(qdot, osc)
        expressions(qdot, osc)
        measures(qdot, osc)
    print("%d passed, %d failed" % (results["passed"], results["failed"]))
    return 1 if results["failed"] else 0


if __name__ == "__main__":
    sys.exit(main())

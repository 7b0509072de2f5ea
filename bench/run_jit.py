#!/usr/bin/env python3
"""bench/run_jit.py - the JIT (issue 34) against the interpreter and
against --native (gcc -O2 of the generated C), measured in the same run on
the double pendulum (examples/double_pendulum.qd, 1000 s) and the 8- and
20-link pendulums (written here), dop853 at rtol 1e-12 / 1e-10.

Each row: the run's own time (qdot's summary line, median of REPS) and the
whole process (bench/timing.py: wall, and processor time, the steadier
figure on a loaded machine) for --no-jit (the interpreter), the default
(AUTO: machine code once the run is long), --jit (from the start) and
--native (its object cached by a first run that is not counted), with the
ratios default/native and interpreter/jit.  The rows of every variant are
checked equal to the interpreter's bit for bit (the JIT's promise) and the
first --native run's wall time is printed as the compile cost to compare
with --jit's.

Usage: run_jit.py BUILD_DIR
"""
import os
import re
import statistics
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from timing import timed  # noqa: E402

REPS = 5
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def chain(n):
    """The n-link planar pendulum of unit masses and lengths."""
    th = ["th%d" % i for i in range(1, n + 1)]
    lines = ["coordinates " + ", ".join(th), "parameters m = 1, l = 1, g = 9.81"]
    for k in range(1, n + 1):
        xs = " + ".join("l*sin(%s)" % t for t in th[:k])
        ys = " + ".join("l*cos(%s)" % t for t in th[:k])
        lines.append("particle m at (%s, -(%s))" % (xs, ys))
    lines.append("V = " + " + ".join("-m*g*(%s)" % " + ".join("l*cos(%s)" % t for t in th[:k])
                                     for k in range(1, n + 1)))
    lines.append("initial " + ", ".join("%s = %g" % (t, 0.3 + 0.01 * i)
                                        for i, t in enumerate(th)))
    return "\n".join(lines) + "\n"


def in_run(cmd):
    """The run's own seconds from the summary line, and the rows written."""
    p = subprocess.run(cmd, check=True, capture_output=True, text=True)
    m = re.search(r"rejected, ([0-9.e+-]+) s;", p.stderr)
    return float(m.group(1)), p.stdout


def main():
    build = sys.argv[1] if len(sys.argv) > 1 else "build"
    qdot = os.path.join(build, "qdot")
    tmp = tempfile.mkdtemp()
    cache = os.path.join(tmp, "cache")
    env = dict(os.environ, XDG_CACHE_HOME=cache)
    os.environ.update(env)
    cases = [("double pendulum", os.path.join(ROOT, "examples", "double_pendulum.qd"), "1000",
              "1e-12")]
    for n in (8, 20):
        path = os.path.join(tmp, "chain%d.qd" % n)
        with open(path, "w") as f:
            f.write(chain(n))
        cases.append(("%d-link pendulum" % n, path, "100", "1e-10"))
    print("%-16s %9s %9s %9s %9s %8s %8s %10s" % ("model", "interp", "default", "jit",
                                                   "native", "dflt/nat", "int/jit",
                                                   "1st native"))
    for name, path, t_end, rtol in cases:
        base = [qdot, "simulate", path, "--t-end", t_end, "--method", "dop853", "--rtol", rtol]
        first = timed(base + ["--native"], 1, quiet=True)[0]  # compiles and caches the object
        runs, wall, cpu = {}, {}, {}
        ref = in_run(base + ["--no-jit"])[1]
        for label, extra in (("interp", ["--no-jit"]), ("default", []), ("jit", ["--jit"]),
                             ("native", ["--native"])):
            ts = []
            for _ in range(REPS):
                t, rows = in_run(base + extra)
                ts.append(t)
                if label != "native" and rows != ref:
                    sys.exit("%s %s: the rows differ from the interpreter's" % (name, label))
            runs[label] = statistics.median(ts)
            wall[label], cpu[label] = timed(base + extra, REPS, quiet=True)
        print("%-16s %9.3f %9.3f %9.3f %9.3f %8.2f %8.2f %10.2f   (in the run, s)"
              % (name, runs["interp"], runs["default"], runs["jit"], runs["native"],
                 runs["default"] / runs["native"], runs["interp"] / runs["jit"], first))
        print("%-16s %9.3f %9.3f %9.3f %9.3f %8.2f %8.2f %10s   (whole process, s)"
              % ("", wall["interp"], wall["default"], wall["jit"], wall["native"],
                 wall["default"] / wall["native"], wall["interp"] / wall["jit"], ""))
        print("%-16s %9.3f %9.3f %9.3f %9.3f %8.2f %8.2f %10s   (whole process, processor s)"
              % ("", cpu["interp"], cpu["default"], cpu["jit"], cpu["native"],
                 cpu["default"] / cpu["native"], cpu["interp"] / cpu["jit"], ""))


if __name__ == "__main__":
    main()

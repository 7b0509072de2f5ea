#!/usr/bin/python3
"""The Python package's costs (issue 32): the time of `import qdot`, and one
derivation from Python (Model(text).eom(): parse, derive, the entries as
text) against the `qdot eom FILE` process doing the same, in the same run.

Usage: run_python.py BUILD_DIR [--reps N]

`import qdot` is timed as whole interpreters (`python3 -c "import qdot"`)
less a bare one (`python3 -c pass`), numpy's share (`-c "import numpy"`)
beside it: the package imports numpy, and a user who has numpy loaded
already pays the rest only.  The derivation is timed in this process, after
one warm-up, as the median of N; the CLI as the median wall time of N
processes (timing.timed).  BUILD_DIR's libqdot.so.0 and python/_ffi.py are
used (QDOT_LIB), the package from python/ of this tree.
"""
import argparse
import os
import statistics
import sys
import time

from timing import timed

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
MODEL = os.path.join(ROOT, "examples", "double_pendulum.qd")
PY = "/usr/bin/python3"


def import_times(env_cmd, reps):
    """(wall, processor) medians of a bare interpreter, numpy's import and
    qdot's, the last two less the first."""
    bare = timed(env_cmd + ["-c", "pass"], reps)
    numpy = timed(env_cmd + ["-c", "import numpy"], reps)
    qdot = timed(env_cmd + ["-c", "import qdot"], reps)
    less = lambda x: (x[0] - bare[0], x[1] - bare[1])  # noqa: E731
    return bare, less(numpy), less(qdot)


def derivation_time(reps):
    """(wall, processor) medians of qdot.Model(text).eom() in this process."""
    import qdot
    with open(MODEL) as fh:
        text = fh.read()
    qdot.Model(text).eom()  # warm-up: the first call builds cffi's functions
    wall, cpu = [], []
    for _ in range(reps):
        t0, c0 = time.perf_counter(), time.process_time()
        qdot.Model(text, file=MODEL).eom()
        wall.append(time.perf_counter() - t0)
        cpu.append(time.process_time() - c0)
    return statistics.median(wall), statistics.median(cpu)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("build")
    ap.add_argument("--reps", type=int, default=20)
    a = ap.parse_args()
    build = os.path.abspath(a.build)
    exe = os.path.join(build, "qdot")
    if not os.access(exe, os.X_OK):
        sys.exit("run_python.py: no %s (build it first)" % exe)
    os.environ["QDOT_LIB"] = build
    os.environ["PYTHONPATH"] = os.path.join(ROOT, "python")
    os.environ["PYTHONDONTWRITEBYTECODE"] = "1"
    sys.path.insert(0, os.path.join(ROOT, "python"))
    bare, numpy, imp = import_times([PY], a.reps)
    derive = derivation_time(a.reps * 10)
    cli = timed([exe, "eom", MODEL], a.reps)
    print("Python package (examples/double_pendulum.qd), medians of %d runs" % a.reps)
    print("  %-40s %10s %10s" % ("", "wall", "processor"))
    rows = [("import qdot (numpy included)", imp, 1, "s"),
            ("  of which import numpy", numpy, 1, "s"),
            ("python3 itself (subtracted)", bare, 1, "s"),
            ("Model(text).eom() in process", derive, 1e3, "ms"),
            ("qdot eom FILE (a process)", cli, 1e3, "ms")]
    for name, (w, c), scale, unit in rows:
        print("  %-40s %7.3f %-2s %7.3f %-2s" % (name, w * scale, unit, c * scale, unit))
    print("  %-40s %7.0fx    %7.0fx" % ("process / in-process", cli[0] / derive[0],
                                         cli[1] / max(derive[1], 1e-9)))


if __name__ == "__main__":
    main()

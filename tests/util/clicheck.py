"""tests/util/clicheck.py - what the end-to-end checks of the CLI share.

A check script (tests/cli/check_*.py) runs build/qdot as a user would,
counts its checks here and ends with finish(): the failures are printed as
they happen, so one run shows all of them, not just the first.  Imported
with tests/util on sys.path (not from tests/cross, where every .py is a
test of its own).
"""
import math
import subprocess
from pathlib import Path

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
results = {"passed": 0, "failed": 0}


def check(name, ok, detail=""):
    """Count one check; print it when it fails."""
    results["passed" if ok else "failed"] += 1
    if not ok:
        print(f"FAIL {name} {detail}")
    return ok


def run(qdot, *args, timeout=120):
    """(exit status, stdout, stderr) of `qdot ARGS`."""
    p = subprocess.run([str(qdot), *map(str, args)], capture_output=True, text=True,
                       timeout=timeout)
    return p.returncode, p.stdout, p.stderr


def close(a, b, tol=1e-9):
    """a equals b to the relative (and, near 0, absolute) tolerance tol."""
    return abs(a - b) <= tol * (1 + abs(b))


def ev(text, values):
    """A printed expression (qdot's text syntax) at values ({name: number},
    velocities named with a trailing ')."""
    names = {k.replace("'", "_d"): v for k, v in values.items()}
    expr = text.replace("^", "**")
    for k in sorted(values, key=len, reverse=True):
        if "'" in k:
            expr = expr.replace(k, k.replace("'", "_d"))
    env = {n: getattr(math, n) for n in ("sin", "cos", "tan", "sinh", "cosh", "tanh", "asin",
                                         "acos", "atan", "sqrt", "exp", "log", "pi")}
    env.update(names)
    return eval(expr, {"__builtins__": {}}, env)


def finish():
    """Print the tally; the exit status for sys.exit (1 if any check failed)."""
    print(f"{results['passed']} passed, {results['failed']} failed")
    return 1 if results["failed"] else 0

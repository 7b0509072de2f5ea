#!/usr/bin/python3
"""SymPy side of the kernel benchmark (see bench/README.md).

Prints one line per benchmark, tab-separated, the same protocol as
kernel_qdot and kernel_ginac:  name reps median_s min_s size value
The caches are cleared before every repetition so that a repetition cannot
reuse the previous one's work.  Times are processor time of this process, as
in the C and C++ programs.
"""
import argparse
import statistics
import sys
import time

import sympy
from sympy.core.cache import clear_cache

# The evaluation point, the same in all three programs.
POINT = {"x": 0.125, "y": 0.25, "z": 0.375, "w": 0.5}


def expand1():
    x, y, z = sympy.symbols("x y z")
    return sympy.expand((1 + x + y + z) ** 20)


def expand2():
    x, y, z, w = sympy.symbols("x y z w")
    e = sympy.expand((x + y + z + w) ** 15)
    return sympy.expand(e * sympy.diff(e, x))


def diff10():
    x = sympy.Symbol("x")
    f = sympy.sin(x) ** 4 * sympy.cos(x) * sympy.exp(x)
    return sympy.diff(f, x, 10)


def trig200():
    x, y = sympy.symbols("x y")
    s = sympy.Integer(0)
    for k in range(1, 201):
        s = s + k * sympy.sin(k * x) * sympy.cos(k * y)
    return (sympy.diff(s, x), sympy.diff(s, y))


BENCHES = [("expand1", expand1), ("expand2", expand2), ("diff10", diff10),
           ("trig200", trig200)]


def nterms(e):
    return len(e.args) if isinstance(e, sympy.Add) else 1


def size_and_value(r):
    """Top-level terms (summed over the outputs) and the value at POINT."""
    outs = r if isinstance(r, tuple) else (r,)
    sub = {sympy.Symbol(k): sympy.Float(v) for k, v in POINT.items()}
    size = sum(nterms(e) for e in outs)
    value = sum(float(e.xreplace(sub).evalf()) for e in outs)
    return size, value


def run(fn, a):
    """Timed repetitions; also returns the first one's result for the check.
    A benchmark slower than a.slow seconds runs once: SymPy's own spread is
    far below the ratios being measured."""
    times, first = [], None
    while len(times) < a.max_reps and (len(times) < a.min_reps or sum(times) < a.budget):
        clear_cache()
        t0 = time.process_time()
        r = fn()
        times.append(time.process_time() - t0)
        if first is None:
            first = r
        del r
        if times[0] > a.slow:
            break
    return times, first


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("names", nargs="*", help="benchmarks to run (default: all)")
    ap.add_argument("--budget", type=float, default=5.0,
                    help="seconds of timed runs per benchmark (default 5)")
    ap.add_argument("--min-reps", type=int, default=3)
    ap.add_argument("--max-reps", type=int, default=50)
    ap.add_argument("--slow", type=float, default=10.0,
                    help="a benchmark whose first run takes longer runs once")
    a = ap.parse_args()
    for name, fn in BENCHES:
        if a.names and name not in a.names:
            continue
        times, first = run(fn, a)
        size, value = size_and_value(first)  # untimed
        print(f"{name}\t{len(times)}\t{statistics.median(times):.6e}\t"
              f"{min(times):.6e}\t{size}\t{value:.15g}", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())

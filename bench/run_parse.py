#!/usr/bin/python3
"""Reading a large model: `qdot check` on N definitions and on N parameters,
each timed against the same shape at a tenth of the size, in the same run
(issue 30: 32k definitions took 7.7 s and 20k parameters over 30 s while
every name lookup scanned every name; with the hashed name table the time
grows linearly).

Usage: run_parse.py BUILD_DIR [--defs N] [--params N] [--repeat K]

Prints, for each shape, the best of K wall times at N/10 and at N and their
ratio; linear growth gives a ratio near 10 (start-up makes it less), a
quadratic one near 100.  The goal: 100k definitions in under 1 s and 20k
parameters well under 1 s on a 2-core machine.
"""
import argparse
import os
import subprocess
import sys
import tempfile
import time


def defs_text(n):
    lines = ['coordinates q', 'parameters m = 1']
    lines += ['d%d = m*q + %d' % (i, i) for i in range(n)]
    lines += ["T = m/2*q'^2", 'V = d0 + d%d' % (n - 1)]
    return '\n'.join(lines) + '\n'


def params_text(n):
    return ('coordinates q\nparameters ' +
            ', '.join('p%d = %d' % (i, i + 1) for i in range(n)) +
            "\nT = p0/2*q'^2\nV = p%d*q^2\n" % (n - 1))


def best_time(qdot, text, repeat):
    with tempfile.NamedTemporaryFile('w', suffix='.qd', delete=False) as f:
        f.write(text)
        path = f.name
    try:
        best = None
        for _ in range(repeat):
            t0 = time.perf_counter()
            subprocess.run([qdot, 'check', path], capture_output=True, check=True)
            t = time.perf_counter() - t0
            best = t if best is None else min(best, t)
        return best
    finally:
        os.unlink(path)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('build')
    ap.add_argument('--defs', type=int, default=100000)
    ap.add_argument('--params', type=int, default=20000)
    ap.add_argument('--repeat', type=int, default=3)
    a = ap.parse_args()
    qdot = os.path.join(a.build, 'qdot')
    if not os.access(qdot, os.X_OK):
        sys.exit('run_parse.py: no qdot in %s' % a.build)
    for label, make, n in (('definitions', defs_text, a.defs), ('parameters', params_text, a.params)):
        small = best_time(qdot, make(n // 10), a.repeat)
        big = best_time(qdot, make(n), a.repeat)
        print('%-11s %7d: %.3f s   %7d: %.3f s   ratio %.1f (linear ~10, quadratic ~100)' %
              (label, n // 10, small, n, big, big / small))
    print('load average: %.2f %.2f %.2f' % os.getloadavg())


if __name__ == '__main__':
    main()

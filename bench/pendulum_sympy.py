#!/usr/bin/python3
"""SymPy side of the n-link pendulum benchmark (see bench/README.md).

The planar n-link pendulum the way a SymPy user derives it: angles as
dynamicsymbols, T and V built from the positions, LagrangesMethod,
form_lagranges_equations(), then mass_matrix and forcing, unsimplified.
A repetition is timed from clear_cache() (untimed) through building the
Lagrangian to mass_matrix and forcing.

Usage: pendulum_sympy.py [--budget S] [--min-reps N] [--slow S] [--limit S]
                         [--simplify N] [n...]
Prints one tab-separated line per n:  n reps median_s min_s ops
and for --simplify N one line  simplify<N> 1 time_s time_s ops  (simplify()
on every entry of M and f of the n = N result).  ops is size() below.  An n
whose derivation passes --limit seconds (120) is cut off: the line is
"n  timeout  LIMIT" and no larger n is tried.

Also a module: size(), read_qdot() and read_ginac() let the driver count
qdot's and GiNaC's results with the same function.
"""
import argparse
import re
import signal
import statistics
import sys
import time

import sympy
from sympy import count_ops, cos, sin, symbols
from sympy.core.cache import clear_cache
from sympy.physics.mechanics import LagrangesMethod, dynamicsymbols

t = dynamicsymbols._t


def derive(n):
    """M and f (M q'' = f) of the n-link pendulum, as LagrangesMethod gives them."""
    q = dynamicsymbols('theta1:%d' % (n + 1))
    m = symbols('m1:%d' % (n + 1))
    l = symbols('l1:%d' % (n + 1))
    g = symbols('g')
    x = y = T = V = 0
    for i in range(n):
        x = x + l[i] * sin(q[i])
        y = y - l[i] * cos(q[i])
        T += m[i] / 2 * (x.diff(t)**2 + y.diff(t)**2)
        V += m[i] * g * y
    lm = LagrangesMethod(T - V, q)
    lm.form_lagranges_equations()
    return lm.mass_matrix, lm.forcing


def size(M, f):
    """count_ops (visual=False) summed over the n*n entries of M and the n of f.

    Coordinates are functions of t here, so each theta_i(t) and each
    Derivative counts as an operation, for every system alike."""
    return sum(count_ops(e) for e in list(M) + list(f))


def _namespace(n):
    ns = {'sin': sympy.sin, 'cos': sympy.cos, 'tan': sympy.tan, 'sqrt': sympy.sqrt}
    for i in range(1, n + 1):
        q = dynamicsymbols('theta%d' % i)
        ns['theta%d' % i] = q
        ns['thetad%d' % i] = q.diff(t)
        ns['m%d' % i] = sympy.Symbol('m%d' % i)
        ns['l%d' % i] = sympy.Symbol('l%d' % i)
    ns['g'] = sympy.Symbol('g')
    ns['t'] = t
    return ns


def read_ginac(lines, n):
    """GiNaC's printed entries (pendulum_ginac --print: theta<i>, thetad<i>, ^)."""
    ns = _namespace(n)
    return [sympy.parse_expr(s.replace('^', '**'), local_dict=dict(ns)) for s in lines]


def read_qdot(strings, n):
    """Entries in the model language (`^` power, theta1' velocity), as qdot
    eom --format json prints them; the reader of tests/cross/check_lagrange_sympy.py."""
    ns = _namespace(n)
    out = []
    for s in strings:
        s = re.sub(r"(theta\d+)'", r"\1_d", s).replace('^', '**')
        s = re.sub(r"theta(\d+)_d", r"thetad\1", s)
        out.append(sympy.parse_expr(s, local_dict=dict(ns)))
    return out


class Timeout(Exception):
    pass


def _alarm(signum, frame):
    raise Timeout()


def one_run(n, limit):
    clear_cache()
    signal.signal(signal.SIGALRM, _alarm)
    signal.alarm(int(limit))
    try:
        t0 = time.process_time()
        M, f = derive(n)
        return time.process_time() - t0, M, f
    finally:
        signal.alarm(0)


def bench(n, a):
    """Repeat until the budget (at least min_reps), once when slow."""
    times = []
    dt, M, f = one_run(n, a.limit)
    times.append(dt)
    while dt < a.slow and (len(times) < a.min_reps or sum(times) < a.budget):
        dt, _, _ = one_run(n, a.limit)
        times.append(dt)
    print('%d\t%d\t%.6e\t%.6e\t%d' % (n, len(times), statistics.median(times), min(times),
                                      size(M, f)), flush=True)
    return M, f


def simplified(n):
    M, f = derive(n)
    clear_cache()
    t0 = time.process_time()
    Ms = [sympy.simplify(e) for e in M]
    fs = [sympy.simplify(e) for e in f]
    dt = time.process_time() - t0
    print('simplify%d\t1\t%.6e\t%.6e\t%d' % (n, dt, dt, size(Ms, fs)), flush=True)


def main():
    p = argparse.ArgumentParser()
    p.add_argument('--budget', type=float, default=3.0)
    p.add_argument('--min-reps', type=int, default=3)
    p.add_argument('--slow', type=float, default=5.0, help='one repetition when the first takes longer')
    p.add_argument('--limit', type=float, default=120.0)
    p.add_argument('--simplify', type=int, default=0)
    p.add_argument('n', type=int, nargs='*')
    a = p.parse_args()
    for n in a.n or [2, 4, 6, 8, 10, 12]:
        try:
            bench(n, a)
        except Timeout:
            print('%d\ttimeout\t%g' % (n, a.limit), flush=True)
            break
    if a.simplify:
        simplified(a.simplify)


if __name__ == '__main__':
    sys.exit(main())

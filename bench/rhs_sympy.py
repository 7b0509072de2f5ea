#!/usr/bin/python3
"""The n-link pendulum's right-hand side the SymPy way (bench/run_rhs.py).

Usage: rhs_sympy.py N [seconds]

Derives M and f from the Lagrangian with SymPy (no simplification, as a user
would for speed): positions link by link, T and V as sums,
M_jk = d^2 L/dq'_j dq'_k and f = dL/dq - (d^2 L/dq' dq) q'; lambdify([q, q', par],
[M, f], cse=True) with NumPy; the rhs solves M q'' = f with numpy.linalg.solve.
Checks one state against the textbook formula (bench/rhs_hand.c's, in
Python), then times the call.  Prints `info KEY VALUE` and `time sympy N NS`
lines like rhs_bench.  Parameters as in rhs_bench.c: m_i = 1 + 0.1 (i mod 3),
l_i = 1 - 0.01 i, g = 9.81.
"""
import math
import sys
import time
import timeit

import numpy as np
import sympy as sp


def params(n):
    return [1 + 0.1 * (i % 3) for i in range(1, n + 1)] + \
           [1 - 0.01 * i for i in range(1, n + 1)] + [9.81]


def derive(n):
    q = sp.symbols('q1:%d' % (n + 1))
    qd = sp.symbols('u1:%d' % (n + 1))
    m = sp.symbols('m1:%d' % (n + 1))
    l = sp.symbols('l1:%d' % (n + 1))
    g = sp.Symbol('g')
    x = y = xd = yd = 0
    T = V = 0
    for i in range(n):
        x += l[i] * sp.sin(q[i])
        y -= l[i] * sp.cos(q[i])
        xd += l[i] * sp.cos(q[i]) * qd[i]
        yd += l[i] * sp.sin(q[i]) * qd[i]
        T += m[i] / 2 * (xd**2 + yd**2)
        V += m[i] * g * y
    L = T - V
    dLdqd = [sp.diff(L, v) for v in qd]
    M = [[sp.diff(dLdqd[j], qd[k]) for k in range(n)] for j in range(n)]
    f = [sp.diff(L, q[j]) - sum(sp.diff(dLdqd[j], q[k]) * qd[k] for k in range(n))
         for j in range(n)]
    fn = sp.lambdify([q, qd, list(m) + list(l) + [g]], [M, f], modules='numpy', cse=True)
    return fn


def textbook(n, y, p):
    m, l, g = p[:n], p[n:2 * n], p[2 * n]
    mu = [sum(m[i:]) for i in range(n)]
    th, w = y[:n], y[n:]
    M = np.empty((n, n))
    f = np.empty(n)
    for j in range(n):
        f[j] = -mu[j] * g * l[j] * math.sin(th[j])
        for k in range(n):
            a = mu[max(j, k)] * l[j] * l[k]
            M[j, k] = a * math.cos(th[j] - th[k])
            f[j] -= a * math.sin(th[j] - th[k]) * w[k]**2
    return np.concatenate([w, np.linalg.solve(M, f)])


def main():
    n = int(sys.argv[1])
    seconds = float(sys.argv[2]) if len(sys.argv) > 2 else 2.0
    t0 = time.perf_counter()
    fn = derive(n)
    print('info\tsympy_build_s\t%.3f' % (time.perf_counter() - t0), flush=True)
    p = params(n)
    rng = np.random.default_rng(7)
    y = rng.uniform(-1, 1, 2 * n)

    def rhs(y):
        M, f = fn(y[:n], y[n:], p)
        return np.concatenate([y[n:], np.linalg.solve(np.array(M), np.array(f))])

    got, want = rhs(y), textbook(n, y, p)
    err = float(np.max(np.abs(got - want) / np.maximum(1, np.abs(want))))
    print('info\tsympy_max_rel_diff\t%.3g' % err)
    if not err < 1e-9:
        print('rhs_sympy: disagrees with the textbook formula', file=sys.stderr)
        return 1
    number = 1
    while timeit.timeit(lambda: rhs(y), number=number) < seconds / 20:
        number *= 2
    best = min(timeit.repeat(lambda: rhs(y), number=number, repeat=5)) / number
    print('time\tsympy\t%d\t%.2f' % (n, best * 1e9))
    return 0


if __name__ == '__main__':
    sys.exit(main())

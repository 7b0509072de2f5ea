#!/usr/bin/env python3
"""Cross-check qdot's Riccati solver (qd_care_solve) against SciPy.

`qdot lqr --A ... --B ... --weights "Q = [[...]], R = [[...]]" --format json`
reads random systems (every double written with repr, so read back exactly)
and prints qdot's stabilizing X, gain K and closed-loop eigenvalues (the
whole path: the matrix and weight readers, qd_care_solve, the JSON);
SciPy's solve_continuous_are (its own
Schur/QZ method on the extended pencil, Arnold & Laub 1984) solves the same
systems.  Every closed-loop eigenvalue must be stable.  How close two
backward-stable solvers can agree is set by the problem's condition number
(Byers 1985; Higham, "Accuracy and Stability of Numerical Algorithms",
16.4 on the Sylvester/Lyapunov part):
    kappa = (||Q|| + 2 ||A|| ||X|| + ||G|| ||X||^2) / (sep(Ac^T, -Ac) ||X||),
with Ac = A - G X, G = B R^-1 B^T, sep the smallest singular value of the
Lyapunov operator I (x) Ac^T + Ac^T (x) I.  For kappa <= 1e8, X and K must
agree to 1e-9 relative (Frobenius) and qdot's reported residual be below
1e-10; above it (random single-input systems of order 5-8 with X ~ 1e6 reach
kappa ~ 1e13, where the two differ by 1e-7 while both have residuals near
1e-10), qdot's residual must be no worse than 4 times SciPy's.

Systems without a stabilizing solution (an unstable mode the input does not
reach) must be refused by qdot (exit 2, "not stabilizable"), where SciPy
either raises or returns an X whose closed loop is unstable.
Usage: check_care_scipy.py --build BUILD_DIR [--count N]
"""
import argparse
import json
import os
import subprocess
import sys

try:
    import numpy as np
    import scipy.linalg
except ImportError:
    print('check_care_scipy needs python3-scipy (scripts/deps.sh test)')
    sys.exit(1)

def random_system(rng, n, m):
    """A with entries of any sign (often unstable), B full, Q = C^T C with
    C of 1..n rows (singular for fewer rows), R = D^T D + I/2."""
    scale = 10.0 ** rng.uniform(-1, 1)
    A = scale * rng.standard_normal((n, n))
    B = rng.standard_normal((n, m))
    C = rng.standard_normal((int(rng.integers(1, n + 1)), n))
    D = rng.standard_normal((m, m))
    return A, B, C.T @ C, D.T @ D + 0.5 * np.eye(m)


def unstabilizable(rng, n, m):
    """A random system with its first state an unstable mode, 1 + |x|, that
    neither the input nor the other states reach."""
    A, B, Q, R = random_system(rng, n, m)
    A[0, :] = 0
    A[:, 0] = 0
    A[0, 0] = 1 + abs(rng.standard_normal())
    B[0, :] = 0
    return A, B, Q, R


def matrix(M):
    return '[' + ', '.join('[' + ', '.join(repr(float(v)) for v in row) + ']' for row in M) + ']'


def run_qdot(qdot, system):
    """qdot lqr on one system: (exit status, JSON or None, stderr)."""
    A, B, Q, R = system
    cmd = [qdot, 'lqr', '--A', matrix(A), '--B', matrix(B),
           '--weights', 'Q = %s, R = %s' % (matrix(Q), matrix(R)), '--format', 'json']
    p = subprocess.run(cmd, capture_output=True, text=True)
    return p.returncode, json.loads(p.stdout) if p.returncode == 0 else None, p.stderr


def rel(got, want):
    return np.linalg.norm(got - want) / max(np.linalg.norm(want), 1e-300)


def condition(A, G, Q, X):
    """kappa above: the Riccati equation's relative condition number."""
    n = A.shape[0]
    Ac = A - G @ X
    eye = np.eye(n)
    sep = np.linalg.svd(np.kron(eye, Ac.T) + np.kron(Ac.T, eye), compute_uv=False)[-1]
    nx = np.linalg.norm(X)
    return (np.linalg.norm(Q) + 2 * np.linalg.norm(A) * nx + np.linalg.norm(G) * nx**2) / (sep * nx)


def residual(A, G, Q, X):
    """qd_care_result.residual's measure (qdot/control.h), for SciPy's X."""
    quad = X @ G @ X
    res = A.T @ X + X @ A - quad + Q
    return np.linalg.norm(res) / (np.linalg.norm(Q) + 2 * np.linalg.norm(A.T @ X)
                                  + np.linalg.norm(quad))


def check_solved(k, system, got, failures, worst):
    A, B, Q, R = system
    n, m = B.shape
    X, K, res = np.array(got['X']), np.array(got['K']), got['residual']
    eig = [re for re, im in got['closed_loop_eigenvalues']]
    Xs = scipy.linalg.solve_continuous_are(A, B, Q, R)
    Ks = np.linalg.solve(R, B.T @ Xs)
    G = B @ np.linalg.solve(R, B.T)
    kappa, errs = condition(A, G, Q, Xs), (rel(X, Xs), rel(K, Ks))
    what = 'system %d (n %d, m %d, kappa %.2g): X off by %.3g, K by %.3g, residual %.3g, ' \
           'max Re s %.3g' % (k, n, m, kappa, errs[0], errs[1], res, max(eig))
    if kappa <= 1e8:
        worst['well'] = max(worst['well'], *errs)
        ok = max(errs) <= 1e-9 and res <= 1e-10
    else:
        worst['ill'] += 1
        ok = res <= 4 * residual(A, G, Q, Xs)
    if not ok or max(eig) >= 0 or X.shape != (n, n) or K.shape != (m, n):
        failures.append(what)


def scipy_refuses(system):
    A, B, Q, R = system
    try:
        Xs = scipy.linalg.solve_continuous_are(A, B, Q, R)
    except (np.linalg.LinAlgError, ValueError):
        return True
    closed = A - B @ np.linalg.solve(R, B.T @ Xs)
    return max(np.linalg.eigvals(closed).real) >= -1e-9


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--build', required=True)
    ap.add_argument('--count', type=int, default=120)
    args = ap.parse_args()
    rng = np.random.default_rng(23)
    solvable = [random_system(rng, 1 + k % 8, 1 + (k // 8) % 3) for k in range(args.count)]
    refused = [unstabilizable(rng, 2 + k % 6, 1 + k % 2) for k in range(6)]
    qdot = os.path.join(args.build, 'qdot')
    failures, worst = [], {'well': 0.0, 'ill': 0}
    for k, system in enumerate(solvable):
        rc, got, err = run_qdot(qdot, system)
        if rc != 0:
            failures.append('system %d refused (exit %d): %s' % (k, rc, err.strip()))
            continue
        check_solved(k, system, got, failures, worst)
    for k, system in enumerate(refused):
        rc, got, err = run_qdot(qdot, system)
        if rc != 2 or '(A, B) is not stabilizable' not in err:
            failures.append('unstabilizable system %d: exit %d, %s' % (k, rc, err.strip()))
        if not scipy_refuses(system):
            failures.append('unstabilizable system %d: SciPy found a stabilizing X' % k)
    for f in failures:
        print('FAIL', f)
    print('%d systems against SciPy %s: worst relative difference in X or K %.3g on the '
          '%d with kappa <= 1e8; %d ill-conditioned checked by residual; %d unstabilizable '
          'refused; %d failures'
          % (len(solvable), scipy.__version__, worst['well'], len(solvable) - worst['ill'],
             worst['ill'], len(refused), len(failures)))
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())

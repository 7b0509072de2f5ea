#!/usr/bin/python3
"""tests/cross/check_conlin_sympy.py - linearization on the state manifold
(qdot/conlin.h, issue 37) against SymPy and textbook results.

1. SymPy's non-minimal pendulum (test_linearize.py's
   test_linearize_pendulum_lagrange_nonminimal: a particle at (q1, q2) with
   q1^2 + q2^2 = L^2, gravity along +q1): `qdot linearize --format sympy`
   (the manifold's path, its output run as SymPy code) gives the A of
   SymPy's LagrangesMethod.linearize, built here, to 1e-12; its eigenvalues
   are +-i sqrt(g/L), those of the same pendulum written in its angle
   (`qdot linearize` without constraints; Desloge ch. 62, small oscillations
   of the simple pendulum, seed-desloge-B.md C6).
2. SymPy's rolling disc (test_linearize.py's test_linearize_rolling_disc_kane:
   m = r = g = 1, upright, spin rate w; its Linearizer's A over 8 states,
   A_sol there): a disc in qdot with `rolls` (5 coordinates after z is
   eliminated, 2 velocity constraints, 8 independent states).  The states
   differ (qdot's q', SymPy's u), the eigenvalues do not: at each w they
   agree to 1e-10, i.e. 0 five times and s^2 = 4/5 - 12 w^2/5 (Neimark and
   Fufaev, Dynamics of Nonholonomic Systems, ch. III: the upright disc is
   stable for w > 1/sqrt(3)); at w = 1/sqrt(3) all vanish (SymPy's own
   assertion there).
3. `modes` and `stability --ignore q1, x, y` on the disc's steady motion take
   the same path: the same eigenvalues and verdict as `linearize` at
   w = 0.3 (unstable) and 0.8 (marginally stable), and `--scan w=0:1.5` the
   critical spin 1/sqrt(3); a lean named cyclic is refused.

Usage: check_conlin_sympy.py --build BUILD_DIR
"""
import argparse
import json
import math
import subprocess
import sys
import tempfile
from pathlib import Path

import numpy as np

NONMINIMAL = """parameters m = 0.9, g = 9.8, L = 1.3
coordinates q1, q2
T = m/2*(q1'^2 + q2'^2)
V = -m*g*q1
constraint rod: q1^2 + q2^2 = L^2
initial q1 = L, q2 = 0
"""
ANGLE = """parameters m = 0.9, g = 9.8, L = 1.3
coordinates th
T = m/2*L^2*th'^2
V = -m*g*L*cos(th)
"""
DISC = """parameters m = 1, r = 1, g = 1, w = 0.8
coordinates q1, q2, q3, x, y, z
body disc mass m inertia (m*r^2/4, m*r^2/4, m*r^2/2) at (x, y, z) orientation rot_z(q1)*rot_x(q2)*rot_y(q3)*rot_x(-pi/2)
V = m*g*z
rolls disc on plane((0, 0, 1), (0, 0, 0)) as disk(r)
initial q1 = 0, q2 = 0, q3 = 0, x = 0, y = 0, z = r, q3' = w
"""

failed = 0


def report(ok, what, detail=''):
    global failed
    failed += not ok
    print('%s %s %s' % ('ok  ' if ok else 'FAIL', what, detail if not ok else ''))


def run(qdot, *args):
    p = subprocess.run([qdot] + [str(a) for a in args], capture_output=True, text=True,
                       timeout=300)
    return p.returncode, p.stdout, p.stderr


def sympy_nonminimal_A(L, m):
    from sympy import symbols, atan, Matrix
    from sympy.physics.mechanics import (dynamicsymbols, ReferenceFrame, Point, Particle,
                                         Lagrangian, LagrangesMethod)
    q1, q2 = dynamicsymbols('q1:3')
    q1d, q2d = dynamicsymbols('q1:3', level=1)
    Ls, ms, t = symbols('L, m, t')
    g = 9.8
    N = ReferenceFrame('N')
    pN = Point('N*')
    pN.set_vel(N, 0)
    N.orientnew('A', 'axis', [atan(q2 / q1), N.z])
    P = pN.locatenew('P1', q1 * N.x + q2 * N.y)
    P.set_vel(N, P.pos_from(pN).dt(N))
    pP = Particle('pP', P, ms)
    LM = LagrangesMethod(Lagrangian(N, pP), [q1, q2], hol_coneqs=Matrix([q1**2 + q2**2 - Ls**2]),
                         forcelist=[(P, ms * g * N.x)], frame=N)
    LM.form_lagranges_equations()
    op = {q1: Ls, q2: 0, q1d: 0, q2d: 0, q1d.diff(t): 0, q2d.diff(t): 0}
    op.update(LM.solve_multipliers(op_point=op))
    A, _, _ = LM.linearize([q2], [q2d], [q1], [q1d], op_point=op, A_and_B=True)
    return np.array(A.subs({Ls: L, ms: m}).evalf(), dtype=float)


def sympy_disc_A(w):
    """test_linearize_rolling_disc_kane's A_sol (m = r = g = 1, q2 = q1' = 0) at q1 = 0."""
    q1 = 0.0
    s, c = math.sin(q1), math.cos(q1)
    return np.array([[0, 0, 0, 0, 0, 0, 0, 1],
                     [0, 0, 0, 0, 0, 1, 0, 0],
                     [0, 0, 0, 0, 0, 0, 1, 0],
                     [s * w, 0, 0, 0, 0, -s, -c, 0],
                     [-c * w, 0, 0, 0, 0, c, -s, 0],
                     [0, 4 / 5, 0, 0, 0, 0, 0, 6 * w / 5],
                     [0, 0, 0, 0, 0, 0, 0, 0],
                     [0, 0, 0, 0, 0, -2 * w, 0, 0]], dtype=float)


def eigs(A):
    return sorted(np.linalg.eigvals(np.asarray(A, dtype=float)),
                  key=lambda z: (round(z.real, 6), round(z.imag, 6)))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--build', required=True)
    qdot = Path(ap.parse_args().build) / 'qdot'
    with tempfile.TemporaryDirectory() as tmp:
        d = Path(tmp)
        for name, text in (('nonminimal', NONMINIMAL), ('angle', ANGLE), ('disc', DISC)):
            (d / (name + '.qd')).write_text(text)

        # 1. the non-minimal pendulum
        L, m, g = 1.3, 0.9, 9.8
        rc, out, err = run(qdot, 'linearize', d / 'nonminimal.qd', '--format', 'sympy')
        ns = {}
        if rc == 0:
            from sympy import Matrix
            ns['Matrix'] = Matrix
            exec(out, ns)
        Aq = np.array(ns['A'].evalf(), dtype=float) if 'A' in ns else np.zeros((0, 0))
        As = sympy_nonminimal_A(L, m)
        report(rc == 0 and Aq.shape == As.shape and np.allclose(Aq, As, rtol=1e-12, atol=1e-12),
               'non-minimal pendulum: A (--format sympy, the manifold) = LagrangesMethod.linearize',
               '%s %s %s' % (Aq, As, err))
        rc2, out2, err2 = run(qdot, 'linearize', d / 'angle.qd', '--about', 'th = 0',
                              '--format', 'json')
        Aa = np.array(json.loads(out2)['A']) if rc2 == 0 else np.zeros((2, 2))
        w0 = math.sqrt(g / L)
        report(rc == 0 and rc2 == 0 and np.allclose(eigs(Aq), eigs(Aa), atol=1e-12) and
               np.allclose(eigs(Aq), [complex(0, -w0), complex(0, w0)], atol=1e-12),
               'non-minimal pendulum: eigenvalues = the angle pendulum\'s = +-i sqrt(g/L)',
               '%s %s %s' % (eigs(Aq), eigs(Aa), err2))

        # 2. the rolling disc
        for w in [0.0, 0.3, 0.8, 1.0 / math.sqrt(3) + 0.1, 1.5]:
            rc, out, err = run(qdot, 'linearize', d / 'disc.qd', '--set', 'w=%r' % w,
                               '--format', 'json')
            data = json.loads(out) if rc == 0 else {}
            got = [complex(a, b) for a, b in data.get('eigenvalues', [])]
            want = eigs(sympy_disc_A(w))
            s2 = 4 / 5 - 12 * w * w / 5
            book = [0] * 5 + ([math.sqrt(s2), -math.sqrt(s2)] if s2 > 0 else
                              [complex(0, math.sqrt(-s2)), complex(0, -math.sqrt(-s2))]) + [0]
            ok = (rc == 0 and len(got) == 8 and
                  np.allclose(sorted(got, key=lambda z: (round(z.real, 6), round(z.imag, 6))),
                              want, atol=1e-10) and
                  np.allclose(want, sorted(book, key=lambda z: (round(complex(z).real, 6),
                                                                round(complex(z).imag, 6))),
                              atol=1e-12))
            report(ok, 'rolling disc w=%.4g: eigenvalues = SymPy\'s A_sol\'s (s^2 = 4/5 - '
                   '12 w^2/5, five 0)' % w, '%s %s %s' % (got, want, err))
        wc = 1.0 / math.sqrt(3)
        rc, out, err = run(qdot, 'linearize', d / 'disc.qd', '--set', 'w=%r' % wc,
                           '--format', 'json')
        got = [complex(a, b) for a, b in json.loads(out)['eigenvalues']] if rc == 0 else [1]
        # a triple root: rounding eps moves it by eps^(1/3) ~ 6e-6
        report(rc == 0 and max(abs(z) for z in got) < 1e-4,
               'rolling disc at w = 1/sqrt(3): every eigenvalue 0 (a triple root: to 1e-4)',
               str(got))
        rc, out, err = run(qdot, 'linearize', d / 'disc.qd', '--scan', 'w=0:1.5', '--format',
                           'json')
        cr = json.loads(out)['crossings'] if rc == 0 else []
        report(rc == 0 and len(cr) == 1 and abs(cr[0]['value'] - wc) < 1e-6 and
               cr[0]['to_stable'] and cr[0]['marginal'],
               'rolling disc scan: marginally stable (s = +-i w) from w = 1/sqrt(3)',
               '%s %s' % (cr, err))
        # 3. modes and stability of the disc's steady motion (issue 37): the same path as
        # linearize, so the same eigenvalues and verdict; the critical spin from either scan
        for w in [0.3, 0.8]:
            lin = run(qdot, 'linearize', d / 'disc.qd', '--set', 'w=%r' % w, '--format', 'json')
            mod = run(qdot, 'modes', d / 'disc.qd', '--set', 'w=%r' % w, '--format', 'json')
            stb = run(qdot, 'stability', d / 'disc.qd', '--ignore', 'q1, x, y', '--set',
                      'w=%r' % w, '--format', 'json')
            ds = [json.loads(out) if rc == 0 else {} for rc, out, _ in (lin, mod, stb)]
            want = 'unstable' if 4 / 5 - 12 * w * w / 5 > 0 else 'marginally stable'
            report(all(x.get('verdict') == want for x in ds) and
                   all(np.allclose(x['eigenvalues'], ds[0]['eigenvalues'], atol=1e-14)
                       for x in ds),
                   'rolling disc w=%g: modes and stability = linearize (%s)' % (w, want),
                   '%s %s' % ([x.get('verdict') for x in ds], [e for _, _, e in (lin, mod, stb)]))
        for cmd in (['modes', d / 'disc.qd'], ['stability', d / 'disc.qd', '--ignore', 'q1']):
            rc, out, err = run(qdot, *cmd, '--scan', 'w=0:1.5', '--format', 'json')
            cr = json.loads(out)['crossings'] if rc == 0 else []
            report(rc == 0 and len(cr) == 1 and abs(cr[0]['value'] - wc) < 1e-6 and
                   cr[0]['to_stable'] and cr[0]['marginal'],
                   '%s --scan: the critical spin 1/sqrt(3)' % cmd[0], '%s %s' % (cr, err))
        rc, out, err = run(qdot, 'stability', d / 'disc.qd', '--ignore', 'q2')
        report(rc == 2 and "'q2' is not cyclic" in err, 'stability --ignore of a lean refused',
               err)
    print('%d failed' % failed)
    return 1 if failed else 0


if __name__ == '__main__':
    sys.exit(main())

#!/usr/bin/env python3
"""End-to-end checks of the LQR wired into models: `qdot linearize --lqr`
and `qdot simulate --input "F = lqr"` on the inverted pendulum on a cart
(examples/cart_pendulum.qd: SymPy's n_link_pendulum_on_cart with n = 1).

What is asserted is mathematics, computed here in plain Python:
  - the gain of `linearize --lqr` equals the gain `qdot lqr` finds for the
    same A and B (the two paths share qd_care_solve, but not the matrices'
    route into it), and X solves A^T X + X A - X B R^-1 B^T X + Q = 0 with
    K = R^-1 B^T X (qdot/control.h);
  - the cart position is cyclic (A's first column zero), so the (x, x)
    entry of the Riccati equation forces |K_x| = sqrt(Q_xx / R);
  - the closed-loop eigenvalues are the roots of det(sI - (A - B K)): the
    polynomial with those roots has the coefficients of the characteristic
    polynomial of A - B K (Faddeev-LeVerrier), and all lie in Re s < 0;
  - the simulation applies u = u0 - K (x - x0): its F column is that law
    at every row, about the upright point and about a shifted cart
    position x_ref (x0 = x_ref, the pendulum then settles there);
  - near the point the closed loop decays at the rate its linearization
    implies: from a tiny tilt, |x(t)| shrinks like exp(max Re s t);
  - from th0 = 0.2 rad the closed loop settles (|th|, |x - x_ref| < 1e-3
    after 10 s), the energy obeys its balance dE/dt = F x' (the only
    nonconservative force is F on the cart) and stays bounded, and the
    cost-to-go x^T X x of the linear design does not grow; the open loop
    (F = 0) falls, |th| > 1 within 3 s;
  - `--format c` prints the same K (every digit) as an array;
  - refusals with exit status 2: R not positive definite, Q of the wrong
    size, a mode the input does not reach (not stabilizable), `lqr`
    without --lqr or --about, --lqr with no `lqr` input.
Run: python3 check_lqr_closed_loop_cli.py --build BUILD_DIR
"""
import argparse
import csv
import io
import json
import math
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
MODEL = str(ROOT / 'examples' / 'cart_pendulum.qd')
ABOUT = "th=0, th'=0, x=0, x'=0, F=0"
WEIGHTS = 'Q = diag(1, 10, 1, 1), R = 0.1'  # states [x, th, x', th']
M, m, l, g = 1.0, 0.1, 0.5, 9.81            # the example's parameters

FAILED, PASSED = [], []


def check(name, cond, detail=''):
    (PASSED if cond else FAILED).append(name)
    print('%s %s %s' % ('ok  ' if cond else 'FAIL', name, detail if not cond else ''))


def qdot_run(qdot, *args):
    p = subprocess.run([qdot, *args], capture_output=True, text=True, timeout=120)
    return p.returncode, p.stdout, p.stderr


def simulate(qdot, *args, dt='0.01'):
    rc, out, err = qdot_run(qdot, 'simulate', MODEL, '--method', 'dop853', '--rtol', '1e-11',
                            '--dt', dt,
                            '--output', 'F', *args)
    rows = [{k: float(v) for k, v in r.items()} for r in csv.DictReader(io.StringIO(out))] \
        if rc == 0 else []
    return rc, rows, err


# ---- small dense linear algebra -------------------------------------------------

def matmul(a, b):
    return [[sum(a[i][k] * b[k][j] for k in range(len(b))) for j in range(len(b[0]))]
            for i in range(len(a))]


def transpose(a):
    return [list(r) for r in zip(*a)]


def add(a, b, s=1.0):
    return [[x + s * y for x, y in zip(ra, rb)] for ra, rb in zip(a, b)]


def fro(a):
    return math.sqrt(sum(x * x for r in a for x in r))


def charpoly(a):
    """Coefficients c[0..n] of det(sI - a) = s^n + c1 s^(n-1) + ... (Faddeev-LeVerrier)."""
    n = len(a)
    c = [1.0]
    mk = [[0.0] * n for _ in range(n)]
    for k in range(1, n + 1):
        mk = add(matmul(a, mk), [[c[-1] if i == j else 0.0 for j in range(n)] for i in range(n)])
        am = matmul(a, mk)
        c.append(-sum(am[i][i] for i in range(n)) / k)
    return c


def poly_from_roots(roots):
    p = [1 + 0j]
    for r in roots:
        p = [x - r * y for x, y in zip(p + [0], [0] + p)]
    return [x.real for x in p]


# ---- the design -------------------------------------------------------------------

def design(qdot):
    rc, out, err = qdot_run(qdot, 'linearize', MODEL, '--about', ABOUT, '--lqr', WEIGHTS,
                            '--format', 'json')
    check('linearize --lqr runs', rc == 0, err)
    return json.loads(out) if rc == 0 else None


def consistency(qdot, d):
    A, B, lq = d['A'], d['B'], d['lqr']
    K = lq['K']
    rc, out, err = qdot_run(qdot, 'lqr', '--A', repr(A), '--B', repr(B), '--weights', WEIGHTS,
                            '--format', 'json')
    ok = rc == 0
    if ok:
        K2 = json.loads(out)['K']
        dev = max(abs(a - b) / max(1, abs(b)) for ra, rb in zip(K, K2) for a, b in zip(ra, rb))
        ok = dev < 1e-10
    check('K of linearize --lqr equals K of qdot lqr on the same A, B', ok, err or K)
    X = lq['X']
    Q = [[[1, 10, 1, 1][i] if i == j else 0 for j in range(4)] for i in range(4)]
    Rinv = 1 / 0.1
    G = [[Rinv * x for x in r] for r in matmul(B, transpose(B))]
    AtX = matmul(transpose(A), X)
    res = add(add(add(AtX, transpose(AtX)), matmul(matmul(X, G), X), -1), Q)
    rel = fro(res) / (fro(Q) + 2 * fro(AtX) + fro(matmul(matmul(X, G), X)))
    check('X solves the Riccati equation (relative residual < 1e-10)', rel < 1e-10, rel)
    Kx = [[Rinv * x for x in r] for r in matmul(transpose(B), X)]
    dev = max(abs(a - b) for ra, rb in zip(K, Kx) for a, b in zip(ra, rb))
    check('K = R^-1 B^T X', dev < 1e-9 * fro(K), dev)
    # x is cyclic (A's first column zero), so the (x, x) entry of the Riccati
    # equation is (B^T X)_x^2 / R = Q_xx: |K_x| = sqrt(Q_xx / R) exactly
    check('|K_x| = sqrt(Q_xx / R): the cart position is cyclic',
          abs(abs(K[0][0]) - math.sqrt(1 / 0.1)) < 1e-10, K[0][0])
    # about upright (the bob at x - l sin th): x'' = m g th / M + F / M,
    # th'' = (M+m) g th / (M l) + F / (M l)
    check('A has the textbook entries (M+m) g/(M l) and m g/M',
          abs(A[3][1] - (M + m) * g / (M * l)) < 1e-12 and abs(A[2][1] - m * g / M) < 1e-12,
          A)


def c_format(qdot, d):
    """--format c gives K as an array, every digit: the JSON's K."""
    rc, out, err = qdot_run(qdot, 'linearize', MODEL, '--about', ABOUT, '--lqr', WEIGHTS,
                            '--format', 'c')
    body = out.split('static const double K[1][4] = {')[-1] if rc == 0 else ''
    nums = [float(v) for v in body.replace('{', ' ').replace('}', ' ').replace(';', ' ')
            .replace(',', ' ').split()] if body else []
    check('--format c: K as an array equal to the JSON K', nums == d['lqr']['K'][0],
          (nums, err))


def eigenvalues(d):
    A, B, K = d['A'], d['B'], d['lqr']['K']
    Acl = add(A, matmul(B, K), -1)
    eig = [complex(re, im) for re, im in d['lqr']['closed_loop_eigenvalues']]
    check('closed-loop eigenvalues all in Re s < 0', all(e.real < 0 for e in eig), eig)
    want, got = charpoly(Acl), poly_from_roots(eig)
    dev = max(abs(a - b) / max(1, abs(a)) for a, b in zip(want, got))
    check('closed-loop eigenvalues are the roots of det(sI - (A - B K))', dev < 1e-9,
          (want, got))
    return eig


# ---- the simulation ---------------------------------------------------------------

def law_applied(rows, K, xref):
    dev = 0.0
    for r in rows:
        dx = [r['x'] - xref, r['th'], r["x'"], r["th'"]]
        dev = max(dev, abs(r['F'] + sum(k * v for k, v in zip(K[0], dx))))
    return dev


def energy(r):
    vx, vt, th = r["x'"], r["th'"], r['th']
    T = 0.5 * M * vx * vx + 0.5 * m * ((vx - l * math.cos(th) * vt) ** 2 +
                                       (l * math.sin(th) * vt) ** 2)
    return T + m * g * l * math.cos(th)


def settles(qdot, d, xref):
    K, X = d['lqr']['K'], d['lqr']['X']
    about = "th=0, th'=0, x=%r, x'=0, F=0" % xref
    rc, rows, err = simulate(qdot, '--t-end', '10', '--initial', "th=0.2, th'=0, x=0, x'=0",
                             '--input', 'F = lqr', '--about', about, '--lqr', WEIGHTS, dt='0.002')
    check('closed loop runs (x_ref = %g)' % xref, rc == 0 and rows, err)
    if not rows:
        return
    dev = law_applied(rows, K, xref)
    check('the simulation applies F = -K (x - x0) (x_ref = %g)' % xref, dev < 1e-8, dev)
    last = rows[-1]
    check('closed loop settles: |th| and |x - x_ref| < 1e-3 after 10 s (x_ref = %g)' % xref,
          abs(last['t'] - 10) < 1e-9 and abs(last['th']) < 1e-3 and abs(last['x'] - xref) < 1e-3,
          last)
    # dE/dt = F x': the work of the force, by Simpson's rule over pairs of
    # the (equally spaced) rows
    work, worst, E0 = 0.0, 0.0, energy(rows[0])
    p = [r['F'] * r["x'"] for r in rows]
    for k in range(2, len(rows), 2):
        h = (rows[k]['t'] - rows[k - 2]['t']) / 2
        work += h / 3 * (p[k - 2] + 4 * p[k - 1] + p[k])
        worst = max(worst, abs(energy(rows[k]) - E0 - work))
    check('energy balance E(t) - E(0) = int F x\' dt (x_ref = %g)' % xref, worst < 1e-7, worst)
    Emax = max(energy(r) for r in rows)
    check('energy bounded and back to the upright rest m g l (x_ref = %g)' % xref,
          Emax < 10 * E0 and abs(energy(last) - m * g * l) < 1e-5, (Emax, energy(last)))
    V = [sum(X[i][j] * v[i] * v[j] for i in range(4) for j in range(4))
         for v in ([r['x'] - xref, r['th'], r["x'"], r["th'"]] for r in rows)]
    grows = max(b - a for a, b in zip(V, V[1:]))
    check('cost-to-go x^T X x does not grow (x_ref = %g)' % xref, grows < 1e-3 * V[0],
          (grows, V[0]))


def linear_rate(qdot, eig):
    """From a tiny tilt the motion is the linear closed loop: its norm decays like
    exp(a t), a = the largest real part among the eigenvalues."""
    rc, rows, err = simulate(qdot, '--t-end', '12', '--initial', "th=1e-6, th'=0, x=0, x'=0",
                             '--input', 'F = lqr', '--about', ABOUT, '--lqr', WEIGHTS)
    if not rows:
        check('closed loop from a tiny tilt runs', False, err)
        return
    a = max(e.real for e in eig)
    slow = [e for e in eig if abs(e.real - a) < 1e-9]

    def peak(t0, t1):
        return max(abs(r['x']) for r in rows if t0 <= r['t'] <= t1)
    # over windows longer than the slow mode's period, the envelope of x
    span = 2 * math.pi / max(abs(slow[0].imag), 1.0) + 1.0
    rate = math.log(peak(8, 8 + span) / peak(4, 4 + span)) / 4
    check('near the point the loop decays at max Re s of A - B K', abs(rate - a) < 0.05 * abs(a),
          (rate, a))


def open_loop_falls(qdot):
    rc, rows, err = simulate(qdot, '--t-end', '3', '--initial', "th=0.2, th'=0, x=0, x'=0",
                             '--input', 'F = 0')
    fell = [r['t'] for r in rows if abs(r['th']) > 1]
    check('open loop (F = 0) falls: |th| > 1 within 3 s', rc == 0 and fell, err)


def refusals(qdot, tmp):
    lin = ['linearize', MODEL, '--about', ABOUT, '--lqr']
    rc, _, err = qdot_run(qdot, *lin, 'Q = 1, R = -1')
    check('R not positive definite: exit 2', rc == 2 and 'R is not positive definite' in err, err)
    rc, _, err = qdot_run(qdot, *lin, 'Q = diag(1, 2, 3), R = 1')
    check('Q of the wrong size: exit 2', rc == 2 and 'diag' in err, err)
    loose = Path(tmp) / 'loose.qd'
    # a cart pushed by F beside an inverted pendulum it does not touch
    loose.write_text('coordinates x, th\nparameters M = 1, m = 1, l = 1, g = 9.81\n'
                     'inputs F\nT = M*x\'^2/2 + m*l^2*th\'^2/2\nV = m*g*l*cos(th)\nQ[x] = F\n')
    rc, _, err = qdot_run(qdot, 'linearize', str(loose), '--lqr', 'Q = 1, R = 1')
    check('an unstable mode F does not reach: not stabilizable, exit 2',
          rc == 2 and 'not stabilizable' in err, err)
    sim = ['simulate', MODEL, '--t-end', '1', '--input', 'F = lqr']
    rc, out, err = qdot_run(qdot, *sim, '--about', ABOUT)
    check('F = lqr without --lqr: exit 2, named', rc == 2 and '--lqr' in err and not out, err)
    rc, out, err = qdot_run(qdot, *sim, '--lqr', WEIGHTS)
    check('F = lqr without --about: exit 2, named', rc == 2 and '--about' in err and not out, err)
    rc, out, err = qdot_run(qdot, 'simulate', MODEL, '--t-end', '1', '--input', 'F = 0',
                            '--lqr', WEIGHTS, '--about', ABOUT)
    check('--lqr with no lqr input: exit 2', rc == 2 and 'lqr' in err and not out, err)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--build', required=True)
    qdot = str(Path(ap.parse_args().build) / 'qdot')
    d = design(qdot)
    if d:
        consistency(qdot, d)
        c_format(qdot, d)
        eig = eigenvalues(d)
        settles(qdot, d, 0.0)
        settles(qdot, d, 0.5)
        linear_rate(qdot, eig)
    open_loop_falls(qdot)
    with tempfile.TemporaryDirectory() as tmp:
        refusals(qdot, tmp)
    print('%d passed, %d failed' % (len(PASSED), len(FAILED)))
    return 1 if FAILED else 0


if __name__ == '__main__':
    sys.exit(main())

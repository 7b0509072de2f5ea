#!/usr/bin/env python3
"""Cross-check of `qdot linearize` against SymPy's own model library (issue 23).

SymPy's n_link_pendulum_on_cart (sympy.physics.mechanics.models, n = 1 and 2: a cart q0
pushed by the specified force F, links at absolute angles q1..qn from the upward
vertical, particles at the cart and the link ends, gravity -g along y) is written as the
equivalent qdot model with `inputs F`, and at random parameters:

- about the upright equilibrium, qdot's A and B must equal
  KanesMethod.linearize(A_and_B=True) (state order [q..., u...] = [q..., q'...]);
- about a random non-equilibrium point (tilted, moving, F != 0), qdot's A and B must equal
  the Jacobians of SymPy's own right-hand side M_full^-1 f_full with respect to the state
  and F, differentiated symbolically and evaluated there (this is where the term
  -M^-1 (dM/dq) q''0 matters);

each to 1e-10 relative to the largest entry.  The exact A and B qdot prints (in the
parameters) are also evaluated at the same parameters and compared.
Run: python3 check_linearize_sympy.py --build BUILD_DIR
"""
import argparse
import json
import random
import subprocess
import sys
import tempfile
from pathlib import Path

import sympy as sp
from sympy.physics.mechanics import models, dynamicsymbols


def qdot_model(n):
    lines = ['coordinates ' + ', '.join('q%d' % i for i in range(n + 1)),
             'parameters ' + ', '.join(['m%d = 1' % i for i in range(n + 1)] +
                                       ['l%d = 1' % i for i in range(n)] + ['g = 9.81']),
             'inputs F',
             'particle m0 at (q0, 0, 0)']
    x, y, V = 'q0', '0', []
    for i in range(n):
        x = '%s - l%d*sin(q%d)' % (x, i, i + 1)
        y = '%s + l%d*cos(q%d)' % (y, i, i + 1)
        lines += ['x%d = %s' % (i + 1, x), 'y%d = %s' % (i + 1, y),
                  'particle m%d at (x%d, y%d, 0)' % (i + 1, i + 1, i + 1)]
        V.append('m%d*g*y%d' % (i + 1, i + 1))
    lines += ['V = ' + ' + '.join(V), 'Q[q0] = F']
    return '\n'.join(lines) + '\n'


def run_qdot(qdot, path, params, about):
    args = [qdot, 'linearize', path, '--format', 'json', '--about', about]
    for k, v in params.items():
        args += ['--set', '%s=%r' % (k, v)]
    out = subprocess.run(args, capture_output=True, text=True, timeout=120)
    if out.returncode != 0:
        raise SystemExit('qdot failed: %s' % out.stderr)
    return json.loads(out.stdout)


def close(label, got, want, tol=1e-10):
    got, want = sp.Matrix(got), sp.Matrix(want)
    scale = max(1.0, max(abs(float(x)) for x in want))
    err = max(abs(float(a) - float(b)) for a, b in zip(got, want))
    ok = got.shape == want.shape and err <= tol * scale
    print('%s %s: max error %.3g (scale %.3g)' % ('ok  ' if ok else 'FAIL', label, err, scale))
    return ok


def exact_values(mat, params):
    """qdot's exact entries (strings in the parameters) at the parameters' values."""
    syms = {k: sp.Symbol(k) for k in params}
    sub = {syms[k]: sp.Float(v, 30) for k, v in params.items()}
    return [[float(sp.sympify(e, locals=syms).xreplace(sub)) for e in row] for row in mat]


def check(qdot, n, rng, tmp):
    kane = models.n_link_pendulum_on_cart(n=n, cart_force=True, joint_torques=False)
    q, u = list(kane.q), list(kane.u)
    F = dynamicsymbols('F')
    m = sp.symbols('m:%d' % (n + 1))
    l = sp.symbols('l:%d' % n)
    g = sp.Symbol('g')
    params = {str(s): rng.uniform(0.5, 2.0) for s in list(m) + list(l)}
    params['g'] = rng.uniform(5, 15)
    pv = {sp.Symbol(k): v for k, v in params.items()}
    path = Path(tmp) / ('cart_%d.qd' % n)
    path.write_text(qdot_model(n))
    ok = True

    # about the upright equilibrium: SymPy's linearizer
    op = {**{x: 0 for x in q}, **{x: 0 for x in u}, F: 0}
    A, B, _ = kane.linearize(A_and_B=True, op_point=op)
    A, B = A.xreplace(pv), B.xreplace(pv)
    d = run_qdot(qdot, str(path), params, 'q1=0')
    ok &= close('n=%d upright A' % n, d['A'], A)
    ok &= close('n=%d upright B' % n, d['B'], B)
    ok &= close('n=%d upright exact A' % n, exact_values(d['A_exact'], params), A)
    ok &= close('n=%d upright exact B' % n, exact_values(d['B_exact'], params), B)
    if not d['controllable']:
        print('FAIL n=%d: the cart-pendulum is controllable from F' % n)
        ok = False

    # about a moving, tilted, pushed point: Jacobians of SymPy's right-hand side
    point = {x: rng.uniform(-0.8, 0.8) for x in q + u}
    point[F] = rng.uniform(-2, 2)
    rhs = kane.mass_matrix_full.LUsolve(kane.forcing_full)
    xs = sp.Matrix(q + u)
    sub = {**point, **pv}
    Aw = rhs.jacobian(xs).xreplace(sub).evalf(30)
    Bw = rhs.jacobian(sp.Matrix([F])).xreplace(sub).evalf(30)
    about = ', '.join(['q%d=%r' % (i, point[x]) for i, x in enumerate(q)] +
                      ["q%d'=%r" % (i, point[x]) for i, x in enumerate(u)] +
                      ['F=%r' % point[F]])
    d = run_qdot(qdot, str(path), params, about)
    ok &= close('n=%d moving A' % n, d['A'], Aw)
    ok &= close('n=%d moving B' % n, d['B'], Bw)
    xdot = rhs.xreplace(sub).evalf(30)
    ok &= close('n=%d moving xdot0' % n, d['xdot0'], xdot.T)
    return ok


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--build', required=True)
    qdot = str(Path(ap.parse_args().build) / 'qdot')
    rng = random.Random(20261126)
    ok = True
    with tempfile.TemporaryDirectory() as tmp:
        for n in (1, 2):
            ok &= check(qdot, n, rng, tmp)
    sys.exit(0 if ok else 1)


if __name__ == '__main__':
    main()

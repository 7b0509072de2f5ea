#!/usr/bin/env python3
"""Cross-check qdot's constrained equations against SymPy's LagrangesMethod.

For the holonomic constrained examples, this script builds each system
itself with sympy.physics.mechanics (dynamicsymbols; the Lagrangian and the
constraints written here from the example's header, independently of the .qd
file) and gives the constraints to LagrangesMethod as hol_coneqs.  qdot's
equations come from `qdot eom FILE --format json` (symbolic: M, f and each
constraint's row A and right-hand side b) and `qdot eom FILE --at STATE
--format json` (numbers: the accelerations and the multipliers).

Conventions.  qdot (docs/design.md, include/qdot/mech.h):

    M q'' = f + A^T lambda,    A q'' = b,    A_kj = d g_k / dq_j,

g_k = lhs - rhs of constraint k.  SymPy, with the same g_k as hol_coneqs,
differentiates each once (coneqs = g_k') and sets lam_coeffs = -C with
C = d coneqs / dq' = A.  Its augmented system (mass_matrix_full,
forcing_full; mass_matrix = [M | lam_coeffs^T] = [M | -A^T]) is

    [ 1  0    0  ] [ q'  ]   [ q'   ]
    [ 0  M  -A^T ] [ q'' ] = [ f    ]
    [ 0  A    0  ] [ lam ]   [ f_cd ]

whose middle row is M q'' = f + A^T lam: the same equation as qdot's, so

    lam (SymPy's augmented system) = lambda (qdot).

SymPy's `eom` attribute, term1 - term2 - term4 - lam_coeffs^T lam = 0, is
M q'' - f + A^T lam = 0, i.e. M q'' = f - A^T lam: there the sign is the
opposite one, lam (eom) = -lambda (qdot).  Both are checked.  Term by
term: qdot's M = SymPy's _m_d, f = forcing (_f_d), A = -lam_coeffs =
_m_cd, b = _f_cd.

Checks per example: every entry of M, f, A, b of qdot minus SymPy simplifies
to zero (tests/cross/check_lagrange_sympy.py's zero test); then at random
states (fixed seed) the accelerations and multipliers of qdot against the
solution of SymPy's augmented system, and SymPy's eom residual with
lam = -lambda.

Usage: check_constrained_sympy.py --build BUILD_DIR [--examples DIR] [--only a,b]
Prints "N passed, N failed"; exits 1 on any failure.
"""
import argparse
import json
import os
import random
import re
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, HERE)

import sympy                                                       # noqa: E402
from sympy import Matrix, Symbol, cos, pi, sin                     # noqa: E402
from sympy.physics.mechanics import LagrangesMethod                # noqa: E402

import check_lagrange_sympy as cl                                  # noqa: E402

t = cl.t
STATES = 4
SEED = 4242
TOL = 1e-9

MODELS = {}


def model(fn):
    MODELS[fn.__name__] = fn
    return fn


# ---------------------------------------------------------------------------
# The systems, from the examples' headers.  Each returns (System, [g_k]) with
# g_k = lhs - rhs as the header writes the constraint.

@model
def atwood_rope():
    # Goldstein sec. 1.6 ex. 2: x1, x2 depths below the pulley, rope x1 + x2 = l
    s = cl.System('x1 x2', 'm1 m2 l g')
    x1, x2 = s.q
    m1, m2, l, g = s.p
    s.particle(m1, [0, -x1])
    s.particle(m2, [0, -x2])
    s.V = -m1 * g * x1 - m2 * g * x2
    return s, [x1 + x2 - l]


@model
def pendulum_cartesian():
    # Britannica sec. 3 (28)-(30): bob at (x, y), y up, rod x^2 + y^2 = l^2
    s = cl.System('x y', 'm l g')
    x, y = s.q
    m, l, g = s.p
    s.particle(m, [x, y])
    s.V = m * g * y
    return s, [x**2 + y**2 - l**2]


@model
def particle_leaving_sphere():
    # Goldstein sec. 1.3, Desloge ch. 51 P6: on the sphere of radius a, z up
    s = cl.System('x y z', 'm a g')
    x, y, z = s.q
    m, a, g = s.p
    s.particle(m, [x, y, z])
    s.V = m * g * z
    return s, [x**2 + y**2 + z**2 - a**2]


@model
def bead_wire_cartesian():
    # Goldstein sec. 1.6 ex. 3: the wire turns at omega, no gravity
    s = cl.System('x y', 'm omega')
    x, y = s.q
    m, w = s.p
    s.particle(m, [x, y])
    return s, [y * cos(w * t) - x * sin(w * t)]


@model
def ladder():
    # Desloge ch. 50 P8: rod (m, l, inertia m l^2/12) with its centre at (x, y),
    # angle theta from the wall; top on x = 0, foot on y = 0
    s = cl.System('x y theta', 'm l g')
    x, y, th = s.q
    m, l, g = s.p
    s.particle(m, [x, y])
    s.T += m * l**2 / 24 * th.diff(t)**2
    s.V = m * g * y
    return s, [x - l / 2 * sin(th), y - l / 2 * cos(th)]


@model
def bead_helix_reaction():
    # Desloge ch. 51 ex. 1: rho = a built in, helix z = b ph, gravity along +z
    s = cl.System('ph z', 'm a b g')
    ph, z = s.q
    m, a, b, g = s.p
    s.particle(m, [a * cos(ph), a * sin(ph), z])
    s.V = -m * g * z
    return s, [z - b * ph]


# ---------------------------------------------------------------------------

def read_parameters(path):
    """The defaults of the example's `parameters` lines: {name: value}."""
    params = {}
    with open(path) as fh:
        for line in fh:
            line = line.split('#', 1)[0].strip()
            if line.startswith('parameters '):
                for item in line[len('parameters '):].split(','):
                    name, value = item.split('=')
                    params[name.strip()] = float(sympy.sympify(value.strip()).evalf())
    return params


def qdot_json(build, path, at=None):
    cmd = [os.path.join(build, 'qdot'), 'eom', path, '--format', 'json']
    if at:
        cmd += ['--at', at]
    proc = subprocess.run(cmd, capture_output=True, text=True, timeout=120)
    if proc.returncode != 0:
        raise RuntimeError('%s: exit %d: %s' % (' '.join(cmd), proc.returncode,
                                               proc.stderr.strip()[:400]))
    return json.loads(proc.stdout)


def lagranges(s, cons):
    lm = LagrangesMethod(s.T - s.V, s.q, hol_coneqs=cons)
    lm.form_lagranges_equations()
    return lm


def symbolic(name, s, lm, data):
    """qdot - SymPy for M, f, A, b: each entry must simplify to zero."""
    n, read, rng = len(s.q), cl.reader(s), random.Random(SEED)
    M, f = lm._m_d, lm.forcing
    qM = [read(x) for x in cl.flat(data['mass_matrix'])]
    pairs = [('M[%d][%d]' % (i, j), qM[i * n + j], M[i, j]) for i in range(n) for j in range(n)]
    pairs += [('f[%d]' % i, read(data['forcing'][i]), f[i]) for i in range(n)]
    for k, con in enumerate(data['constraints']):
        pairs += [('A[%s][%d]' % (con['name'], j), read(con['A'][j]), -lm.lam_coeffs[k, j])
                  for j in range(n)]
        pairs += [('A[%s][%d] (_m_cd)' % (con['name'], j), read(con['A'][j]), lm._m_cd[k, j])
                  for j in range(n)]
        pairs.append(('b[%s]' % con['name'], read(con['b']), lm._f_cd[k]))
    errs = []
    for what, a, b in pairs:
        d = cl.normalize(a, s) - cl.normalize(b, s)
        if not cl.is_zero(d):
            how = 'numerically nonzero' if not cl.numerically_zero(d, rng) else 'did not simplify'
            errs.append('%s %s: qdot %s, SymPy %s (%s)' % (name, what, a, b, how))
    return errs


def at_state(e, s, params, q, v, tt):
    """e with the state and the parameters put in, as a float matrix."""
    sub = {Symbol(k): x for k, x in params.items()}
    for qq, vv in zip(s.q, v):
        sub[qq.diff(t)] = vv
    e = e.subs(sub)
    e = e.subs({qq: x for qq, x in zip(s.q, q)})
    return e.subs(t, tt).evalf()


def numeric(name, s, lm, path, build, params, rng):
    """Accelerations and multipliers at random states; SymPy's eom residual."""
    n, m = len(s.q), len(lm.coneqs)
    errs = []
    for k in range(STATES):
        q = [rng.uniform(-1.5, 1.5) for _ in s.q]
        v = [rng.uniform(-1.5, 1.5) for _ in s.q]
        tt = rng.uniform(0, 3)
        at = ', '.join(['%s=%r' % (c, x) for c, x in zip(s.names, q)] +
                       ["%s'=%r" % (c, x) for c, x in zip(s.names, v)] + ['t=%r' % tt])
        data = qdot_json(build, path, at)
        acc = [float(x) for x in data['accelerations']]
        lam = [float(data['multipliers'][c['name']]) for c in data['constraints']]
        MM = at_state(lm.mass_matrix_full, s, params, q, v, tt)
        FF = at_state(lm.forcing_full, s, params, q, v, tt)
        sol = [float(x) for x in MM.LUsolve(FF)]
        want_acc, want_lam = sol[n:2 * n], sol[2 * n:]        # augmented lam = qdot's lambda
        scale = 1 + max(abs(x) for x in want_acc + want_lam)
        if any(abs(a - b) > TOL * scale for a, b in zip(acc + lam, want_acc + want_lam)):
            errs.append('%s state %d: qdot q\'\' %r lambda %r, SymPy %r %r\n  --at "%s"'
                        % (name, k, acc, lam, want_acc, want_lam, at))
            continue
        # SymPy's eom with lam = -lambda and qdot's accelerations vanishes
        sub = {qq.diff(t, 2): a for qq, a in zip(s.q, acc)}
        sub.update({lv: -x for lv, x in zip(lm.lam_vec, lam)})
        res = at_state(lm.eom.subs(sub), s, params, q, v, tt)
        if any(abs(float(r)) > 1e-8 * scale for r in res):
            errs.append('%s state %d: SymPy eom residual %r with lam = -lambda'
                        % (name, k, list(res)))
    return errs


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--build', required=True)
    ap.add_argument('--examples', default=os.path.join(ROOT, 'examples'))
    ap.add_argument('--only', help='comma-separated example names')
    args = ap.parse_args()
    rng = random.Random(SEED)
    passed = failed = 0
    for name, make in MODELS.items():
        if args.only and name not in args.only.split(','):
            continue
        start = time.time()
        path = os.path.join(args.examples, name + '.qd')
        results = []
        try:
            s, cons = make()
            lm = lagranges(s, cons)
            data = qdot_json(args.build, path)
            if data.get('coordinates') != s.names:
                raise RuntimeError('coordinates %r, expected %r' % (data.get('coordinates'),
                                                                   s.names))
            results.append(('symbolic', symbolic(name, s, lm, data)))
            params = read_parameters(path)
            results.append(('numeric', numeric(name, s, lm, path, args.build, params, rng)))
        except Exception as exc:      # a crash, bad JSON, a timeout
            results.append(('run', ['%s: %s: %s' % (name, type(exc).__name__, exc)]))
        for what, errs in results:
            for e in errs:
                print('FAIL ' + e)
            passed += not errs
            failed += bool(errs)
        print('%-28s %s (%.1f s)' % (name, 'ok' if all(not e for _, e in results) else 'FAILED',
                                     time.time() - start))
    print('%d passed, %d failed' % (passed, failed))
    return 1 if failed else 0


if __name__ == '__main__':
    sys.exit(main())

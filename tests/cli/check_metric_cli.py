#!/usr/bin/env python3
"""Tests of `qdot metric`, run against the built program.

    python3 tests/cli/check_metric_cli.py --build BUILD_DIR

- The double pendulum (examples/double_pendulum.qd; Goldstein ch. 1
  Exercise 22, seed 002): the metric g_ij = d^2 T/dq'_i dq'_j, its inverse
  and the Christoffel symbols of both kinds ([ij,l] = 1/2 (d_i g_jl + d_j g_il
  - d_l g_ij), Gamma^l_ij = g^lk [ij,k]: Desloge App. 23 eqs. 22-23, seed
  000) recomputed by SymPy from the JSON's T2, every entry compared by
  simplify(ours - SymPy's) == 0.  The JSON is indexed by coordinate names
  as [l][i][j].  The metric never degenerates for positive masses: no
  singular points.
- Spherical coordinates (Desloge ch. 55, reference seed-desloge-A.md T49):
  Gamma^r_thth = -r, Gamma^th_rth = 1/r, Gamma^ph_thph = cot th; the chart's
  det J = r^2 sin th and its singular points r = 0, th = 0 + k pi (App. 18).
- --force with the covariant components of a central force F_r: the
  contravariant components F_r/m, 0, 0 and the physical ones F_r, 0, 0.
- Errors (exit 2): --force with the wrong count, a model given by H, a
  relativistic L (not quadratic in the velocities).

Prints "N passed, N failed"; exit 1 on failure."""
import argparse
import json
import subprocess
import sys
import tempfile
from pathlib import Path

import sympy as sp

EXAMPLES = Path(__file__).resolve().parents[2] / 'examples'
results = {'passed': 0, 'failed': 0}


def check(name, ok, detail=''):
    results['passed' if ok else 'failed'] += 1
    if not ok:
        print('FAIL %s %s' % (name, detail))


def run(qdot, *args):
    p = subprocess.run([qdot, 'metric', *args], capture_output=True, text=True, timeout=120)
    return p.returncode, p.stdout, p.stderr


def parse(text, names):
    """Our text syntax into SymPy: ^ is **, q' is q_d."""
    text = text.replace('^', '**')
    for q in sorted(names, key=len, reverse=True):
        text = text.replace(q + "'", q + '_d')
    return sp.sympify(text, locals={n: sp.Symbol(n) for n in names})


def same(a, b):
    return sp.simplify(sp.expand_trig(a - b)) == 0


def double_pendulum(qdot):
    rc, out, err = run(qdot, str(EXAMPLES / 'double_pendulum.qd'), '--format', 'json')
    check('double pendulum runs', rc == 0, err)
    if rc:
        return
    d = json.loads(out)
    qs = d['coordinates']
    names = qs + ['m1', 'm2', 'l1', 'l2', 'g']
    q = [sp.Symbol(n) for n in qs]
    qd = [sp.Symbol(n + '_d') for n in qs]
    syms = {n: sp.Symbol(n) for n in names}
    # T of the example, written out independently of qdot
    m1, m2, l1, l2 = (syms[k] for k in ('m1', 'm2', 'l1', 'l2'))
    x1, y1 = l1 * sp.sin(q[0]), -l1 * sp.cos(q[0])
    x2, y2 = x1 + l2 * sp.sin(q[1]), y1 - l2 * sp.cos(q[1])
    dt = lambda f: sum(sp.diff(f, q[i]) * qd[i] for i in range(2))
    T = m1 / 2 * (dt(x1)**2 + dt(y1)**2) + m2 / 2 * (dt(x2)**2 + dt(y2)**2)
    g = sp.Matrix(2, 2, lambda i, j: sp.simplify(sp.diff(T, qd[i], qd[j])))
    ginv = sp.simplify(g.inv())
    n = 2
    first = [[[sp.Rational(1, 2) * (sp.diff(g[j, l], q[i]) + sp.diff(g[i, l], q[j]) -
                                    sp.diff(g[i, j], q[l]))
               for j in range(n)] for i in range(n)] for l in range(n)]
    second = [[[sum(ginv[l, k] * first[k][i][j] for k in range(n)) for j in range(n)]
               for i in range(n)] for l in range(n)]
    ok_g = all(same(parse(d['metric'][qs[i]][qs[j]], names), g[i, j])
               for i in range(n) for j in range(n))
    check('double pendulum metric = SymPy', ok_g)
    ok_inv = all(same(parse(d['metric_inverse'][qs[i]][qs[j]], names), ginv[i, j])
                 for i in range(n) for j in range(n))
    check('double pendulum inverse metric = SymPy', ok_inv)
    for kind, ref in (('christoffel_first', first), ('christoffel_second', second)):
        ok = all(same(parse(d[kind][qs[l]][qs[i]][qs[j]], names), ref[l][i][j])
                 for l in range(n) for i in range(n) for j in range(n))
        check('double pendulum %s = SymPy' % kind, ok)
    check('double pendulum: no singular points for positive masses',
          d['chart']['singular'] == [], d['chart'])


SPHERICAL = """coordinates r, th, ph
parameters m = 2, k = 1, Fr = 3
particle m at (r*sin(th)*cos(ph), r*sin(th)*sin(ph), r*cos(th))
V = -k/r
"""


def spherical(qdot, tmp):
    model = tmp / 'spherical.qd'
    model.write_text(SPHERICAL)
    names = ['r', 'th', 'ph', 'm', 'k', 'Fr']
    rc, out, err = run(qdot, str(model), '--format', 'json', '--force', 'Fr, 0, 0')
    check('spherical runs', rc == 0, err)
    if rc:
        return
    d = json.loads(out)
    G = d['christoffel_second']
    r, th = sp.symbols('r th')
    for (l, i, j), want in {('r', 'th', 'th'): -r, ('th', 'r', 'th'): 1 / r,
                            ('th', 'th', 'r'): 1 / r, ('ph', 'th', 'ph'): sp.cot(th),
                            ('r', 'r', 'r'): 0}.items():
        got = parse(G[l][i][j], names)
        check('Gamma^%s_%s%s' % (l, i, j), same(got, want), '%s' % got)
    ch = d['chart']
    check('det J = r^2 sin th', same(parse(ch['jacobian_det'], names), r**2 * sp.sin(th)),
          ch['jacobian_det'])
    sing = [(s['lhs'], s['rhs'], s['period']) for s in ch['singular']]
    check('singular at r = 0 and th = k pi', sing == [('r', '0', None), ('th', '0', 'pi')], sing)
    f = d['force']
    check('force given', f['given'] is True)
    check('contravariant F_r/m', same(parse(f['contravariant']['r'], names),
                                      sp.Symbol('Fr') / sp.Symbol('m')), f['contravariant'])
    check('physical F_r', f['physical'] == {'r': 'Fr', 'th': '0', 'ph': '0'}, f['physical'])
    check('orthogonal', d['orthogonal'] is True)
    rc, out, err = run(qdot, str(model))
    check('text lists Gamma^r_th th = -r', rc == 0 and 'Gamma^r_th th = -r' in out, out)
    check('text lists the singular points', 'singular where: r = 0; th = 0 + k*pi' in out, out)


def errors(qdot, tmp):
    model = tmp / 'spherical.qd'
    rc, _, err = run(qdot, str(model), '--force', 'Fr, 0')
    check('--force count: exit 2', rc == 2 and '--force' in err, err)
    rc, _, err = run(qdot, str(model), '--force', 'Fr, 0, )')
    check('--force syntax: exit 2', rc == 2, err)
    rel = tmp / 'rel.qd'
    rel.write_text('coordinates x\nparameters m = 1, c = 1\nL = -m*c^2*sqrt(1 - x\'^2/c^2)\n')
    rc, _, err = run(qdot, str(rel))
    check('relativistic L: exit 2 or 1 with a reason', rc in (1, 2) and 'velocit' in err, err)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--build', required=True)
    qdot = str(Path(ap.parse_args().build) / 'qdot')
    with tempfile.TemporaryDirectory() as d:
        tmp = Path(d)
        double_pendulum(qdot)
        spherical(qdot, tmp)
        errors(qdot, tmp)
    print('%d passed, %d failed' % (results['passed'], results['failed']))
    return 1 if results['failed'] else 0


if __name__ == '__main__':
    sys.exit(main())

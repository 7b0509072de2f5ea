#!/usr/bin/env python3
"""Cross-check qdot's closed-form impulses against SymPy.

gen_impulse prints, for a few models, qdot's closed forms (exact = true of
qd_impulse_solve): the velocities after, the impulsive multipliers and the
energy lost, in the parameters.  Here each system is built again from its
description, independently of the .qd text:

  rhombus  Desloge ch. 57 Ex. 1 (T55): T summed over the four rods (m, 2a),
           the wall's impulse at C from the impulse equations;
  chain    two rods (m, 2a) hinged at B, bent at al and be and moving,
           struck by J across A, the joint suddenly made rigid
           (Britannica B01/B03 at a general configuration): T summed over
           the rods, Qhat = J . dA/dq;
  headon   two particles meeting head on, restitution k: conservation of
           momentum and Newton's law, not the impulse equations;
  lamina   Byerly TC25 in Thomson's form, the foot's velocity v given at
           the angle ph: the least T under the prescription (Lagrange's
           rule for a minimum), the impulse as its multiplier.

Sign convention (docs/design.md, impulsive motion): M (q'+ - q'-) =
Qhat + A^T Lambda, A the rows' velocity coefficients (for a holonomic row
phi = 0, A = dphi/dq).  Each system is solved by SymPy at four random rational
parameter points in 30-digit arithmetic, and qdot's closed forms must
agree there to 25 digits.  The numeric solve is compared at the model's
values.

Usage: check_impulse_exact_sympy.py --build BUILD_DIR
Prints "N passed, N failed"; exits 1 on any failure.
"""
import argparse
import os
import random
import subprocess
import sys

import sympy
from sympy import Rational, Symbol, cos, diff, sin, solve, symbols


def sym(names):
    return {n: Symbol(n, real=True) for n in names.split()}



def impulse_solution(T, q, qd_before, state, rows, Qhat, restitution=None):
    """Solve dT/dq'(after) - dT/dq'(before) = Qhat + sum_k Lambda_k a_k with
    a_k . q'+ = -E_k a_k . q'- at the frozen configuration `state`."""
    n = len(q)
    v = symbols('w0:%d' % n)
    lam = symbols('L0:%d' % len(rows))
    qdot = [Symbol(str(x) + 'd', real=True) for x in q]
    p = [diff(T, qd) for qd in qdot]
    after = {qdot[j]: v[j] for j in range(n)}
    before = {qdot[j]: qd_before[j] for j in range(n)}
    eqs = []
    for j in range(n):
        jump = p[j].subs(after) - p[j].subs(before)
        eqs.append((jump - Qhat[j] - sum(lam[k] * rows[k][j] for k in range(len(rows)))).subs(state))
    for k, a in enumerate(rows):
        E = restitution[k] if restitution else 0
        eqs.append(sum((a[j] * (v[j] + E * qd_before[j])).subs(state) for j in range(n)))
    unknowns = list(v) + list(lam)
    K, rhs = sympy.linear_eq_to_matrix(eqs, unknowns)
    sol = dict(zip(unknowns, K.LUsolve(rhs)))
    Tb = T.subs(before).subs(state)
    Ta = T.subs({qdot[j]: sol[v[j]] for j in range(n)}).subs(state)
    return [sol[x] for x in v], [sol[x] for x in lam], Tb - Ta


def rod_energy(m, a, c, th, qdot_of):
    """A uniform rod (m, length 2a) with centre c (x, y) turning at th'."""
    vc = [qdot_of(ci) for ci in c]
    return m / 2 * (vc[0] ** 2 + vc[1] ** 2) + Rational(1, 2) * m * (2 * a) ** 2 / 12 * qdot_of(th) ** 2


def total_dt(q):
    qdot = {x: Symbol(str(x) + 'd', real=True) for x in q}
    return lambda e: sum(diff(e, x) * qdot[x] for x in q)


def digits30(P):
    """30-digit numbers: the linear solves stay fast and exact enough."""
    return {k: sympy.Float(v, 30) for k, v in P.items()}


def rhombus(P):
    P = digits30(P)
    x, th = Symbol('x', real=True), Symbol('th', real=True)
    m, a, v, al = P['m'], P['a'], P['v'], P['al']
    dt = total_dt([x, th])
    A = (x + 2 * a * cos(th), 0)
    B = (x, 2 * a * sin(th))
    C = (x - 2 * a * cos(th), 0)
    D = (x, -2 * a * sin(th))
    T = 0
    for (p1, p2) in ((A, B), (B, C), (C, D), (D, A)):
        T += rod_energy(m, a, [(p1[i] + p2[i]) / 2 for i in range(2)], th, dt)
    wall = C[0]
    rows = [[diff(wall, x), diff(wall, th)]]
    after, lam, lost = impulse_solution(T, [x, th], [-v, 0], {x: 2 * a * cos(al), th: al},
                                        rows, [0, 0])
    return {'x': after[0], 'th': after[1]}, {'Lambda_wall': lam[0]}, lost


def chain(P):
    P = digits30(P)
    xb, yb, th1, th2 = symbols('xb yb th1 th2', real=True)
    q = [xb, yb, th1, th2]
    m, a, J, al, be, u = (P[k] for k in 'm a J al be u'.split())
    dt = total_dt(q)
    c1 = (xb - a * cos(th1), yb - a * sin(th1))
    c2 = (xb + a * cos(th2), yb + a * sin(th2))
    T = rod_energy(m, a, c1, th1, dt) + rod_energy(m, a, c2, th2, dt)
    A = (xb - 2 * a * cos(th1), yb - 2 * a * sin(th1))
    Qhat = [J * diff(A[1], x) for x in q]
    rows = [[diff(th1 - th2, x) for x in q]]
    after, lam, lost = impulse_solution(T, q, [u, 0, u, -u],
                                        {xb: 0, yb: 0, th1: al, th2: be}, rows, Qhat)
    return dict(zip(['xb', 'yb', 'th1', 'th2'], after)), {'Lambda_rigid': lam[0]}, lost


def headon(P):
    m1, m2, k, v1, v2 = (P[n] for n in 'm1 m2 k v1 v2'.split())
    w1, w2 = symbols('w1 w2')
    sol = solve([m1 * w1 + m2 * w2 - m1 * v1 - m2 * v2, (w2 - w1) + k * (v2 - v1)], [w1, w2],
                dict=True)[0]
    lost = m1 * v1 ** 2 / 2 + m2 * v2 ** 2 / 2 - m1 * sol[w1] ** 2 / 2 - m2 * sol[w2] ** 2 / 2
    # the impulse on particle 2 pushes it along +x; hit = x2 - x1 - R has
    # dphi/dx2 = +1, so Lambda_hit is that impulse
    return {'x1': sol[w1], 'x2': sol[w2]}, {'Lambda_hit': m2 * (sol[w2] - v2)}, lost


def lamina(P):
    m, k, a, v, ph = (P[n] for n in 'm k a v ph'.split())
    xd, yd, thd, mu = symbols('xd yd thd mu')
    T = m / 2 * (xd ** 2 + yd ** 2) + m * k ** 2 / 2 * thd ** 2
    foot = yd + a * cos(ph) * thd             # F.y' at th = ph
    L = T - mu * (foot - v)
    sol = solve([diff(L, z) for z in (xd, yd, thd)] + [foot - v], [xd, yd, thd, mu], dict=True)[0]
    lost = -T.subs(sol)
    return {'x': sol[xd], 'y': sol[yd], 'th': sol[thd]}, {'Lambda_foot': sol[mu]}, lost


SYSTEMS = {'rhombus': rhombus, 'chain': chain, 'headon': headon, 'lamina': lamina}


def parse_cases(lines):
    cases, cur = [], None
    for line in lines:
        tag, _, rest = line.partition(' ')
        if tag == 'case':
            cur = {'name': rest, 'after': {}, 'mult': {}}
            cases.append(cur)
        elif tag == 'params':
            w = rest.split()
            cur['params'] = {w[i]: w[i + 1] for i in range(0, len(w), 2)}
        elif tag in ('after', 'mult'):
            name, _, expr = rest.partition(' ')
            cur[tag][name] = expr
        elif tag == 'lost':
            cur['lost'] = rest.partition(' ')[2]
        elif tag == 'numeric':
            cur['numeric'] = [float(x) for x in rest.split()]
    return cases


def points(case):
    """Four random rational parameter points, then the model's own values
    (as printed, read exactly)."""
    rng = random.Random(7)
    pts = [{k: Rational(rng.randint(2, 40), 17) for k in case['params']} for _ in range(4)]
    return pts + [{k: Rational(v) for k, v in case['params'].items()}]


def close(got, want, digits):
    return abs(got - want) <= 10 ** -digits * (1 + abs(want))


def check(case, failures):
    """qdot's closed forms against SymPy's solution at each point: to 25
    digits at the random points, and qdot's numeric solve to 1e-9 at the
    model's values."""
    ns = {k: getattr(sympy, k) for k in dir(sympy) if not k.startswith('_')}
    ns.update(sym(' '.join(case['params'])))
    exact = {('after', k): sympy.sympify(eval(e, ns)) for k, e in case['after'].items()}
    exact.update({('mult', k): sympy.sympify(eval(e, ns)) for k, e in case['mult'].items()})
    exact[('lost', '-')] = sympy.sympify(eval(case['lost'], ns))
    ok = True
    for i, pt in enumerate(points(case)):
        after, mult, lost = SYSTEMS[case['name']](pt)
        want = {('after', k): v for k, v in after.items()}
        want.update({('mult', k): v for k, v in mult.items()})
        want[('lost', '-')] = lost
        subs = {ns[k]: v for k, v in pt.items()}
        for key, w in want.items():
            got, w = exact[key].subs(subs).evalf(30), sympy.sympify(w).evalf(30)
            if not close(got, w, 25):
                failures.append('%s %s %s at %s: qdot %s, sympy %s' % (case['name'], key[0],
                                                                    key[1], pt, got, w))
                ok = False
        if i == 4:  # the model's values: the numeric solve too
            for key, num in zip(after, case['numeric']):
                if not close(num, sympy.sympify(after[key]).evalf(30), 9):
                    failures.append('%s numeric %s: %r vs %s' % (case['name'], key, num,
                                                                after[key]))
                    ok = False
    return ok


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--build', required=True)
    args = ap.parse_args()
    gen = os.path.join(args.build, 'tests', 'gen_impulse')
    out = subprocess.run([gen], check=True, capture_output=True, text=True).stdout.splitlines()
    cases = parse_cases(out)
    failures = []
    passed = sum(check(c, failures) for c in cases)
    for f in failures:
        print('FAIL', f)
    print('%d passed, %d failed' % (passed, len(cases) - passed))
    return 0 if passed == len(cases) == len(SYSTEMS) else 1


if __name__ == '__main__':
    sys.exit(main())

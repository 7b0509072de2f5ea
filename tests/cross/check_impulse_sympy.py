#!/usr/bin/env python3
"""Cross-check `qdot impulse` against the impulse equations solved by SymPy.

Random systems (fixed seed): two to four coordinates, particles at positions
that are trigonometric and polynomial in the coordinates, a kinetic term on
each coordinate (so that M is positive definite), a blow J at a point, and
some of: an ordinary holonomic constraint, a sudden constraint with a
random restitution E, a prescription.  The model text is written here; the
answer is computed here, independently of qdot, from the textbook equations
(Desloge ch. 57 thm 1; Byerly art. 27):

    M (q'+ - q'-) = Qhat + A^T Lambda,      Qhat_j = J . dr/dq_j,
    c_k(q'+) = -E_k c_k(q'-)                (sudden, Newton's law),
    c_k(q'+) = 0                            (ordinary, prescribed),

c_k = a_k . q' + a0_k the velocity form of constraint k, with SymPy's exact
rationals at a rational state.  Checked against `qdot impulse FILE --format
json`: the velocities after, the multipliers (sign: M dq' = Qhat + A^T
Lambda), the kinetic energies before and after, and, when the case has
sudden constraints and blows, Bertrand's comparison (T after without the
sudden constraints and prescriptions >= T after with them, the difference
being T of the difference motion).

Usage: check_impulse_sympy.py --build BUILD_DIR [--count N]
Prints "N passed, N failed"; exits 1 on any failure.
"""
import argparse
import json
import os
import random
import subprocess
import sys
import tempfile

import sympy
from sympy import Matrix, Rational, Symbol, cos, sin

TOL = 1e-9


def rat(rng, lo=-9, hi=9, den=7):
    while True:
        x = Rational(rng.randint(lo, hi), rng.randint(1, den))
        if x != 0:
            return x


class Case:
    """One random system: its model text and its SymPy ingredients."""

    def __init__(self, rng, index):
        self.n = rng.randint(2, 4)
        self.names = ['q%d' % (j + 1) for j in range(self.n)]
        self.q = [Symbol(nm) for nm in self.names]
        self.v = [Symbol(nm + 'd') for nm in self.names]
        lines = ['# random impulse case %d' % index,
                 'coordinates ' + ', '.join(self.names)]
        T = 0
        for j in range(self.n):
            k = Rational(rng.randint(1, 5), 2)
            T += k * self.v[j] ** 2 / 2
            lines.append('T_%d = %s*%s\'^2/2' % (j, k, self.names[j]))
        self.points = []
        for i in range(rng.randint(1, 2)):
            m = Rational(rng.randint(1, 6), rng.randint(1, 3))
            comps, texts = [], []
            for _ in range(2):
                a, b = rat(rng), rat(rng)
                j1, j2 = rng.randrange(self.n), rng.randrange(self.n)
                trig = rng.choice([sin, cos])
                comps.append(a * self.q[j1] + b * trig(self.q[j2]))
                texts.append('%s*%s + %s*%s(%s)' % (a, self.names[j1], b, trig.__name__,
                                                     self.names[j2]))
            self.points.append((m, comps))
            lines.append('P%d = (%s, %s, 0)' % (i, texts[0], texts[1]))
            lines.append('particle %s at P%d' % (m, i))
            vel = [sum(sympy.diff(c, self.q[j]) * self.v[j] for j in range(self.n))
                   for c in comps]
            T += m * (vel[0] ** 2 + vel[1] ** 2) / 2
        # the T_j lines are definitions: add them to T
        lines.append('T = ' + ' + '.join('T_%d' % j for j in range(self.n)))
        self.T = T
        self.M = Matrix(self.n, self.n, lambda a, b: sympy.diff(T, self.v[a], self.v[b]))
        # the blow: J at the first point
        J = (rat(rng), rat(rng))
        lines.append('impulse (%s, %s, 0) at P0' % J)
        comps = self.points[0][1]
        self.Qhat = [J[0] * sympy.diff(comps[0], qj) + J[1] * sympy.diff(comps[1], qj)
                     for qj in self.q]
        # constraints: (a, a0 = 0 here, E, kind, name)
        self.rows = []
        kinds = rng.sample(['ordinary', 'sudden', 'sudden2', 'prescribe'], rng.randint(1, 2))
        for kind in kinds:
            j1, j2 = rng.sample(range(self.n), 2)
            c1, c2 = rat(rng), rat(rng)
            name = {'ordinary': 'hold', 'sudden': 'hit', 'sudden2': 'hit2',
                    'prescribe': 'given'}[kind]
            if kind == 'prescribe':
                val = rat(rng)
                expr = c1 * self.v[j1] + c2 * self.v[j2] * cos(self.q[j1]) - val
                lines.append("prescribe %s: %s*%s' + %s*%s'*cos(%s) = %s"
                             % (name, c1, self.names[j1], c2, self.names[j2], self.names[j1], val))
                self.rows.append((expr, 0, name))
                continue
            phi = c1 * self.q[j1] + c2 * sin(self.q[j2])
            expr = sum(sympy.diff(phi, qj) * vj for qj, vj in zip(self.q, self.v))
            text = '%s*%s + %s*sin(%s)' % (c1, self.names[j1], c2, self.names[j2])
            if kind == 'ordinary':
                self.rows.append((expr, None, name))
                lines.append('constraint %s: %s = const_%s' % (name, text, name))
                lines.insert(2, 'parameters const_%s = 0' % name)
            else:
                E = Rational(rng.randint(0, 4), 4)
                self.rows.append((expr, E, name))
                lines.append('impact constraint %s: %s = 0 restitution %s' % (name, text, E))
        # the state: rational, consistent with the ordinary constraint's
        # velocity form (it holds before as it holds after)
        self.q0 = [rat(rng, -3, 3, 5) for _ in range(self.n)]
        self.v0 = [rat(rng, -4, 4, 3) for _ in range(self.n)]
        subs_q = dict(zip(self.q, self.q0))
        for expr, E, name in self.rows:
            if E is None:
                a = [sympy.diff(expr, vj).subs(subs_q) for vj in self.v]
                j = next(j for j in range(self.n) if a[j] != 0)
                rest = sum(a[k] * self.v0[k] for k in range(self.n) if k != j)
                self.v0[j] = sympy.nsimplify(-rest / a[j])
        init = ', '.join('%s = %s' % (nm, x) for nm, x in zip(self.names, self.q0))
        init += ', ' + ', '.join("%s' = %s" % (nm, x) for nm, x in zip(self.names, self.v0))
        lines.append('initial ' + init)
        self.text = '\n'.join(lines) + '\n'
        self.subs_q = subs_q
        # the ordinary constraint holds at q0: its constant is phi(q0)
        for expr, E, name in self.rows:
            if E is None:
                line = next(l for l in lines if l.startswith('constraint %s:' % name))
                phi_text = line.split(':', 1)[1].split('=')[0]
                phi = sympy.sympify(phi_text.replace('^', '**'),
                                    locals={nm: s for nm, s in zip(self.names, self.q)})
                self.text = self.text.replace('parameters const_%s = 0' % name,
                                              'parameters const_%s = %s'
                                              % (name, sympy.sstr(phi.subs(subs_q))))

    def solve(self, with_sudden=True):
        """q'+ and the multipliers, to 40 digits (exact rationals and
        sines of them grow too large to solve in closed form)."""
        n = self.n
        at = self.subs_q
        M = self.M.subs(at).evalf(40)
        rows = [(e, E, nm) for e, E, nm in self.rows if with_sudden or E is None]
        m = len(rows)
        K = sympy.zeros(n + m, n + m)
        rhs = sympy.zeros(n + m, 1)
        v0 = Matrix(self.v0)
        K[:n, :n] = M
        rhs[:n, 0] = M * v0 + Matrix([Q.subs(at).evalf(40) for Q in self.Qhat])
        for k, (expr, E, name) in enumerate(rows):
            a = [sympy.diff(expr, vj).subs(at).evalf(40) for vj in self.v]
            a0 = expr.subs({vj: 0 for vj in self.v}).subs(at).evalf(40)
            for j in range(n):
                K[j, n + k] = -a[j]
                K[n + k, j] = a[j]
            before = sum(a[j] * self.v0[j] for j in range(n)) + a0
            target = -E * before if E else 0
            rhs[n + k, 0] = target - a0
        x = K.LUsolve(rhs)
        return [x[j] for j in range(n)], \
            {'Lambda_' + rows[k][2]: x[n + k] for k in range(m)}

    def kinetic(self, v):
        return self.T.subs(self.subs_q).subs(dict(zip(self.v, v))).evalf(40)


def close(a, b):
    return abs(float(a) - float(b)) <= TOL * max(1.0, abs(float(b)))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--build', required=True)
    ap.add_argument('--count', type=int, default=12)
    args = ap.parse_args()
    qdot = os.path.join(args.build, 'qdot')
    rng = random.Random(20261125)
    passed = failed = 0
    with tempfile.TemporaryDirectory() as tmp:
        for i in range(args.count):
            case = Case(rng, i)
            path = os.path.join(tmp, 'case%d.qd' % i)
            with open(path, 'w') as f:
                f.write(case.text)
            r = subprocess.run([qdot, 'impulse', path, '--format', 'json'],
                               capture_output=True, text=True)
            problems = []
            if r.returncode != 0:
                problems.append('exit %d: %s' % (r.returncode, r.stderr.strip()))
            else:
                out = json.loads(r.stdout)
                v1, lam = case.solve()
                got_v = out['velocities_after']
                for nm, x in zip(case.names, v1):
                    if not close(got_v[nm + "'"], x):
                        problems.append("%s' after: %s, want %s" % (nm, got_v[nm + "'"], float(x)))
                for key, x in lam.items():
                    got = out['impulsive_multipliers'].get(key)
                    if got is None or not close(got, x):
                        problems.append('%s: %s, want %s' % (key, got, float(x)))
                T0, T1 = case.kinetic(case.v0), case.kinetic(v1)
                if not close(out['kinetic_energy_before'], T0):
                    problems.append('T before %s, want %s' % (out['kinetic_energy_before'], float(T0)))
                if not close(out['kinetic_energy_after'], T1):
                    problems.append('T after %s, want %s' % (out['kinetic_energy_after'], float(T1)))
                if not close(out['energy_lost'], T0 - T1):
                    problems.append('energy lost %s, want %s' % (out['energy_lost'], float(T0 - T1)))
                # Bertrand (Byerly art. 31): the same blow without the
                # sudden constraints and prescriptions leaves more energy,
                # by T of the difference, when every sudden E is 0.
                sudden = [E for _, E, _ in case.rows if E is not None]
                if sudden and all(E == 0 for E in sudden):
                    vf, _ = case.solve(with_sudden=False)
                    diff = [a - b for a, b in zip(vf, v1)]
                    Tf = case.kinetic(vf)
                    Td = case.T.subs(case.subs_q).subs(dict(zip(case.v, diff)))
                    b = out.get('theorems', {}).get('bertrand', {})
                    if Tf < T1 or not close(Tf - T1, Td):
                        problems.append('SymPy itself breaks Bertrand: a bug in this check')
                    elif b.get('applies') and not b.get('holds'):
                        problems.append('qdot says Bertrand does not hold: %s' % b)
            if problems:
                failed += 1
                print('FAIL case %d:\n%s\n  %s' % (i, case.text, '\n  '.join(problems)))
            else:
                passed += 1
    print('%d passed, %d failed' % (passed, failed))
    return 1 if failed else 0


if __name__ == '__main__':
    sys.exit(main())

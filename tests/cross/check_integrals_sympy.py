#!/usr/bin/env python3
"""SymPy cross-check of `qdot integrals`: every integral qdot reports as
conserved is differentiated by SymPy along SymPy's own equations of motion,
derived from the textbook Lagrangian written out below (not from qdot), and
must give 0; the energy balance dh/dt must equal -2D (+ Q q').

Cases (reference notes in /work/shared/reference/):
  kepler_cartesian       L = m/2 v^2 + k/r: energy, Runge-Lenz, L_z (Desloge
                         ch. 56 Noether Ex. 4; seed-desloge-B.md C3)
  two_particles_spring_2d  P_x, P_y, L_z (Desloge ch. 56 thms 5, 6)
  charged_particle_EB    uniform E and B, U = q phi - q A.v with A = B x r/2:
                         the time-dependent integrals m x' + q (B x r)_x/... - q E_x t
                         (Desloge T35, Noether with F(q, t))
  bead_rotating_wire     h = m/2 (r'^2 - w^2 r^2) (Goldstein sec. 1.6 ex. 3)
  total_derivative_potential  rotation, a symmetry up to dF/dt (Desloge ch. 54 P7)
  damped_oscillator      dh/dt = -b x'^2 = -2D (Goldstein sec. 1.5)
Usage: check_integrals_sympy.py --build BUILD_DIR
"""
import argparse
import json
import subprocess
import sys
from pathlib import Path

import sympy as sp

EXAMPLES = Path(__file__).resolve().parents[2] / 'examples'
t = sp.Symbol('t')
FAILS = []


class Case:
    def __init__(self, coords, params):
        self.q = [sp.Symbol(c) for c in coords]
        self.v = [sp.Symbol(c + '_d') for c in coords]
        self.names = {c: s for c, s in zip(coords, self.q)}
        self.names.update({c + "'": s for c, s in zip(coords, self.v)})
        self.names.update({p: sp.Symbol(p) for p in params})
        self.names['t'] = t

    def parse(self, text):
        s = text.replace('^', '**')
        for c in sorted(self.names, key=len, reverse=True):
            if c.endswith("'"):
                s = s.replace(c, c[:-1] + '_d')
        loc = {k.replace("'", '_d'): v for k, v in self.names.items()}
        return sp.sympify(s, locals=loc)

    def accelerations(self, L, D=0, Q=None):
        """Lagrange's equations, solved for the accelerations (SymPy's own)."""
        n = len(self.q)
        a = [sp.Symbol(str(q) + '_dd') for q in self.q]
        Q = Q or [0] * n

        def ddt(f):
            return (sp.diff(f, t) + sum(sp.diff(f, q) * v for q, v in zip(self.q, self.v))
                    + sum(sp.diff(f, v) * ac for v, ac in zip(self.v, a)))
        eqs = [ddt(sp.diff(L, v)) - sp.diff(L, q) + sp.diff(D, v) - Qj
               for q, v, Qj in zip(self.q, self.v, Q)]
        sol = sp.solve(eqs, a, dict=True)[0]
        return [sol[x] for x in a]

    def rate(self, I, acc):
        return (sp.diff(I, t) + sum(sp.diff(I, q) * v for q, v in zip(self.q, self.v))
                + sum(sp.diff(I, v) * ac for v, ac in zip(self.v, acc)))


def qdot_json(build, name, *extra):
    p = subprocess.run([str(Path(build) / 'qdot'), 'integrals', str(EXAMPLES / name),
                        '--format', 'json', *extra], capture_output=True, text=True, timeout=60)
    if p.returncode:
        raise RuntimeError('%s: exit %d: %s' % (name, p.returncode, p.stderr))
    return json.loads(p.stdout)


def conserved(case, name, what, text, acc):
    r = sp.simplify(case.rate(case.parse(text), acc))
    if r != 0:
        FAILS.append('%s %s: SymPy gives dI/dt = %s for I = %s' % (name, what, r, text))


def all_reported(case, name, d, acc, expect):
    """Every integral qdot calls conserved is; the expected ones are among them."""
    got = set()
    for c in d['cyclic']:
        if c['conserved']:
            conserved(case, name, 'p_' + c['coordinate'], c['momentum'], acc)
    for group in ('found', 'noether'):
        for f in d[group]:
            if f['invariant'] and f['conserved']:
                conserved(case, name, f['name'], f['integral'], acc)
                got.add(f['name'])
    for p in d['proposed']:
        if p['conserved']:
            conserved(case, name, p['name'], p['expr'], acc)
            got.add(p['name'])
    if d['jacobi']['conserved']:
        conserved(case, name, 'h', d['jacobi']['h'], acc)
    missing = set(expect) - got
    if missing:
        FAILS.append('%s: not reported as conserved: %s' % (name, sorted(missing)))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--build', required=True)
    build = ap.parse_args().build

    c = Case(['x', 'y'], ['m', 'k'])
    x, y, xd, yd = c.q + c.v
    m, k = sp.symbols('m k')
    acc = c.accelerations(m / 2 * (xd**2 + yd**2) + k / sp.sqrt(x**2 + y**2))
    all_reported(c, 'kepler_cartesian', qdot_json(build, 'kepler_cartesian.qd'), acc,
                 ['rot', 'angular momentum about z', 'energy', 'Ax', 'Ay'])

    c = Case(['x1', 'y1', 'x2', 'y2'], ['m1', 'm2', 'k', 'd'])
    x1, y1, x2, y2, x1d, y1d, x2d, y2d = c.q + c.v
    m1, m2, kk, dd = sp.symbols('m1 m2 k d')
    rho = sp.sqrt((x1 - x2)**2 + (y1 - y2)**2)
    acc = c.accelerations(m1 / 2 * (x1d**2 + y1d**2) + m2 / 2 * (x2d**2 + y2d**2)
                          - kk / 2 * (rho - dd)**2)
    all_reported(c, 'two_particles_spring_2d', qdot_json(build, 'two_particles_spring_2d.qd'),
                 acc, ['linear momentum along x', 'linear momentum along y',
                       'angular momentum about z'])

    P = ['m', 'q', 'Ex', 'Ey', 'Ez', 'Bx', 'By', 'Bz']
    c = Case(['x', 'y', 'z'], P)
    m, q, Ex, Ey, Ez, Bx, By, Bz = sp.symbols(' '.join(P))
    r, v = sp.Matrix(c.q), sp.Matrix(c.v)
    B, E = sp.Matrix([Bx, By, Bz]), sp.Matrix([Ex, Ey, Ez])
    A = B.cross(r) / 2
    L = m / 2 * v.dot(v) + q * E.dot(r) + q * A.dot(v)   # Desloge T35: L = T - q phi + q v.A
    acc = c.accelerations(L)
    all_reported(c, 'charged_particle_EB', qdot_json(build, 'charged_particle_EB.qd'), acc,
                 ['linear momentum along x', 'linear momentum along y', 'linear momentum along z'])

    c = Case(['r'], ['m', 'omega'])
    rr, rd = c.q + c.v
    m, w = sp.symbols('m omega')
    acc = c.accelerations(m / 2 * (rd**2 + w**2 * rr**2))
    d = qdot_json(build, 'bead_rotating_wire.qd')
    all_reported(c, 'bead_rotating_wire', d, acc, [])
    if not d['jacobi']['conserved'] or sp.simplify(c.parse(d['jacobi']['h'])
                                                   - m / 2 * (rd**2 - w**2 * rr**2)) != 0:
        FAILS.append('bead_rotating_wire: h = %s' % d['jacobi']['h'])

    c = Case(['x', 'y'], ['m', 'K', 'c', 'b', 'w'])
    x, y, xd, yd = c.q + c.v
    m, K, cc, b, w = sp.symbols('m K c b w')
    G = -cc / 2 * (x**2 + y**2) - b * x**2 * y * sp.sin(w * t)
    dG = sp.diff(G, t) + sp.diff(G, x) * xd + sp.diff(G, y) * yd
    acc = c.accelerations(m / 2 * (xd**2 + yd**2) - K / 2 * (x**2 + y**2) + dG)
    all_reported(c, 'total_derivative_potential', qdot_json(build, 'total_derivative_potential.qd'),
                 acc, ['angular momentum about z'])

    c = Case(['x'], ['m', 'k', 'b'])
    x, xd = c.q + c.v
    m, k, b = sp.symbols('m k b')
    D = b / 2 * xd**2
    acc = c.accelerations(m / 2 * xd**2 - k / 2 * x**2, D)
    d = qdot_json(build, 'damped_oscillator.qd')
    rate = sp.simplify(c.rate(c.parse(d['jacobi']['h']), acc) + 2 * D)
    if rate != 0 or sp.simplify(c.parse(d['energy_balance']['dhdt']) + 2 * D) != 0:
        FAILS.append('damped_oscillator: dh/dt + 2D = %s, qdot dh/dt = %s'
                     % (rate, d['energy_balance']['dhdt']))

    for f in FAILS:
        print('FAIL', f)
    print('%d failures' % len(FAILS))
    return 1 if FAILS else 0


if __name__ == '__main__':
    sys.exit(main())

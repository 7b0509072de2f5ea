#!/usr/bin/env python3
"""Check the constrained and rigid-body models in examples/ against the books.

The models checked here carry the header line `# checked by check_constrained.py`
(check_examples.py skips them).  For each, at several random states that satisfy
the model's constraints (fixed seed) run

    qdot eom FILE --at "q=..., q'=..., t=..." --format json

and compare with the textbook, written out below with the math module, one
function per example (each cites its seed, chapter and equation; the
reference notes are in /work/shared/reference/):

  - the accelerations q'';
  - the multipliers, by constraint name.  qdot writes M q'' = f + A^T lambda
    with A_kj = d(lhs - rhs)/dq'_j of constraint k as the model writes it
    (include/qdot/mech.h); each function gives the book's physical reaction
    expressed as that multiplier (a rope tension T is lambda = -T when the
    rope is x1 + x2 - l = 0 and x is down, ...);
  - the generalized constraint forces R_j = sum_k lambda_k A_kj, with A_kj
    differentiated here by hand from the constraint, not taken from qdot;
  - where the book says energy is conserved (or gives the power), dE/dt from
    the accelerations: sum_j dE/dq_j q'_j + dE/dq'_j q''_j with E the book's
    energy, differentiated here by central differences;
  - qdot's own consistency: M q'' = f + A^T lambda with the M, f, A it prints.

The formulas are independent of qdot.  Parameters take the example's defaults
(read from its `parameters` line), then perturbed values, then any value sets
an example lists (forces switched on, ...).

Besides the numbers: the kind qdot gives each constraint (holonomic,
integrable, nonholonomic; from the JSON) and the configurational and motional
degrees of freedom `qdot check` reports, against the books.

Models written with `rolls` that have a hand-written twin in the same
coordinates (EQUIVALENT) are also run against the twin state by state: the
same accelerations, multipliers (renamed) and constraint forces.

Checks listed in EXPECTED_TO_FAIL (by example, or example:kinds,
example:dof) wait for a feature; their failures are reported as XFAIL, not
counted as passes or failures.

Usage: check_constrained.py --build BUILD_DIR --examples EXAMPLES_DIR
Prints "N passed, N failed" and exits 1 on any failure.
"""
import argparse
import json
import math
import os
import random
import re
import subprocess
import sys

from math import sin, cos, sqrt, pi, tan

REL_TOL = 1e-9
ENERGY_TOL = 1e-6          # central differences of E
STATES = 5
SEED = 20260504
MARKER = '# checked by check_constrained.py'

# name -> the feature it waits for (reported, not counted)
EXPECTED_TO_FAIL = {
}

EXAMPLES = {}


def example(name, coords, state, sets=(), energy=None, power=None, special=(), kinds=None,
            dof=None):
    """Register examples/NAME.qd.

    state(rng, p) -> (q, v, t), a random state on the constraints;
    the decorated function (q, v, t, p) -> dict(acc=[...], mult={name: value},
    grad={name: [dC/dq'_j]}) gives the book's results; energy(q, v, t, p) the
    book's E, with dE/dt = power(q, v, t, p) (0 when not given); special is a
    list of (label, state function) for the book's special states (from rest at
    the top, ...): the function is called with the label there.  kinds gives the
    book's classification of each constraint (holonomic, integrable,
    nonholonomic), dof the configurational and motional degrees of freedom."""
    def wrap(fn):
        EXAMPLES[name] = dict(coords=coords, state=state, sets=list(sets), book=fn,
                              energy=energy, power=power, special=list(special),
                              kinds=kinds, dof=dof)
        return fn
    return wrap


def solve(M, f):
    """M x = f by Gaussian elimination with partial pivoting (small n)."""
    n = len(f)
    a = [list(map(float, M[i])) + [float(f[i])] for i in range(n)]
    for c in range(n):
        p = max(range(c, n), key=lambda r: abs(a[r][c]))
        a[c], a[p] = a[p], a[c]
        for r in range(c + 1, n):
            k = a[r][c] / a[c][c]
            for j in range(c, n + 1):
                a[r][j] -= k * a[c][j]
    x = [0.0] * n
    for i in reversed(range(n)):
        x[i] = (a[i][n] - sum(a[i][j] * x[j] for j in range(i + 1, n))) / a[i][i]
    return x


def u(rng, lo=-1.5, hi=1.5):
    return rng.uniform(lo, hi)


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


# ---------------------------------------------------------------------------
# Atwood's machine with a rope constraint

def atwood_state(rng, p):
    x1, v1 = u(rng, 0.2, 1.8), u(rng)
    return {'x1': x1, 'x2': p['l'] - x1}, {'x1': v1, 'x2': -v1}, u(rng, 0, 3)


@example('atwood_rope', ['x1', 'x2'], atwood_state, kinds={'rope': 'holonomic'}, dof=(1, 1))
def _(q, v, t, p, label=None):
    # Goldstein sec. 1.6 example 2: x1'' = (m1 - m2) g/(m1 + m2); the rope's tension
    # 2 m1 m2 g/(m1 + m2) pulls both masses up (x down): lambda_rope = -tension.
    m1, m2, g = p['m1'], p['m2'], p['g']
    a = (m1 - m2) / (m1 + m2) * g
    tension = 2 * m1 * m2 * g / (m1 + m2)
    return dict(acc=[a, -a], mult={'rope': -tension}, grad={'rope': [1, 1]})


# ---------------------------------------------------------------------------
# Bead on a uniformly rotating wire, Cartesian

def bead_wire_state(rng, p):
    w, t = p['omega'], u(rng, 0, 3)
    r, rd = u(rng, 0.1, 2.0), u(rng)
    c, s = cos(w * t), sin(w * t)
    return ({'x': r * c, 'y': r * s},
            {'x': rd * c - r * w * s, 'y': rd * s + r * w * c}, t)


@example('bead_wire_cartesian', ['x', 'y'], bead_wire_state, kinds={'wire': 'holonomic'},
         dof=(1, 1))
def _(q, v, t, p, label=None):
    # Goldstein sec. 1.6 example 3, reference G03 and pitfall P2: r'' = omega^2 r along the
    # wire, and the wire's force 2 m omega r' along the normal n = (-sin wt, cos wt) (not
    # Goldstein's printed m r omega^2 e^(omega t)).  The bead's acceleration is
    # (r'' - r w^2) e_r + 2 r' w n = 2 r' w n.
    m, w = p['m'], p['omega']
    c, s = cos(w * t), sin(w * t)
    rd = v['x'] * c + v['y'] * s
    F = 2 * m * w * rd
    return dict(acc=[-F / m * s, F / m * c], mult={'wire': F}, grad={'wire': [-s, c]})


# ---------------------------------------------------------------------------
# Particle on a smooth sphere

def sphere_point(rng, a, cth):
    ph = u(rng, -pi, pi)
    sth = sqrt(1 - cth * cth)
    n = [sth * cos(ph), sth * sin(ph), cth]
    return n


def sphere_state(rng, p):
    a = p['a']
    n = sphere_point(rng, a, u(rng, -0.9, 0.95))
    w = [u(rng), u(rng), u(rng)]
    vel = cross(w, n)                       # tangent
    r = [a * x for x in n]
    return dict(zip('xyz', r)), dict(zip('xyz', vel)), u(rng, 0, 3)


def sphere_leaving_state(cth):
    """From rest at the top, at polar angle theta (cos theta = cth):
    v^2 = 2 g a (1 - cos theta), the velocity tangent in a vertical plane."""
    def gen(rng, p):
        a, g = p['a'], p['g']
        n = sphere_point(rng, a, cth)
        sth = sqrt(1 - cth * cth)
        e_th = [cth * n[0] / sth, cth * n[1] / sth, -sth]     # down the meridian
        speed = sqrt(2 * g * a * (1 - cth))
        return (dict(zip('xyz', [a * x for x in n])),
                dict(zip('xyz', [speed * x for x in e_th])), 0.0)
    return gen


def sphere_energy(q, v, t, p):
    return p['m'] / 2 * (v['x']**2 + v['y']**2 + v['z']**2) + p['m'] * p['g'] * q['z']


@example('particle_leaving_sphere', ['x', 'y', 'z'], sphere_state, energy=sphere_energy,
         kinds={'sphere': 'holonomic'}, dof=(2, 2),
         special=[('from rest at the top, cos(theta) = 0.9', sphere_leaving_state(0.9)),
                  ('from rest at the top, cos(theta) = 0.75', sphere_leaving_state(0.75)),
                  ('from rest at the top, cos(theta) = 2/3: leaves', sphere_leaving_state(2 / 3))])
def _(q, v, t, p, label=None):
    # Goldstein sec. 1.3 (G25), Desloge ch. 51 P6 (T27): N = m g cos th - m v^2/a along the
    # outward normal; from rest at the top N = m g (3 cos th - 2), zero at cos th = 2/3.
    m, a, g = p['m'], p['a'], p['g']
    r = [q['x'], q['y'], q['z']]
    vv = [v['x'], v['y'], v['z']]
    cth = r[2] / a
    N = m * g * cth - m * dot(vv, vv) / a
    if label:
        N = m * g * (3 * cth - 2)
    acc = [N / m * x / a for x in r]
    acc[2] -= g
    return dict(acc=acc, mult={'sphere': N / (2 * a)}, grad={'sphere': [2 * x for x in r]})


# ---------------------------------------------------------------------------
# Cylinder rolling on a cylinder

def cyl_state(rng, p, th=None, thd=None):
    a, b = p['a'], p['b']
    th = u(rng, -1.2, 1.2) if th is None else th
    thd = u(rng) if thd is None else thd
    return ({'r': a + b, 'theta': th, 'phi': u(rng, -3, 3)},
            {'r': 0.0, 'theta': thd, 'phi': (a + b) * thd / b}, u(rng, 0, 3))


def cyl_leaving_state(cth):
    def gen(rng, p):
        # from rest at the top: (3/4) m (a+b)^2 th'^2 = m g (a+b) (1 - cos th)
        thd = sqrt(4 * p['g'] * (1 - cth) / (3 * (p['a'] + p['b'])))
        return cyl_state(rng, p, th=math.acos(cth), thd=thd)
    return gen


def cyl_energy(q, v, t, p):
    m, b = p['m'], p['b']
    return (m / 2 * (v['r']**2 + q['r']**2 * v['theta']**2) + m * b**2 / 4 * v['phi']**2
            + m * p['g'] * q['r'] * cos(q['theta']))


# roll alone is not integrable (r dtheta - b dphi), with contact (dr = 0) it is: the pair is
# integrable by Frobenius, (a + b) theta - b phi = const (Desloge ch. 49, seed-desloge-A.md C6 and
# pitfall 4: uniplanar rolling is holonomic).
@example('cylinder_on_cylinder', ['r', 'theta', 'phi'], cyl_state, energy=cyl_energy,
         kinds={'contact': 'holonomic', 'roll': 'integrable'}, dof=(1, 1),
         special=[('from rest at the top, cos(theta) = 0.8', cyl_leaving_state(0.8)),
                  ('from rest at the top, cos(theta) = 4/7: leaves', cyl_leaving_state(4 / 7))])
def _(q, v, t, p, label=None):
    # Rolling (Byerly Art. 9c, TC17, k^2 = b^2/2): (3/2) m (a+b) th'' = m g sin th,
    # friction F = m g sin th/3, N = m g cos th - m (a+b) th'^2; from rest at the top
    # N = m g (7 cos th - 4)/3 (issue 4: leaves at cos th = 4/7).
    m, a, b, g = p['m'], p['a'], p['b'], p['g']
    th, thd = q['theta'], v['theta']
    thdd = 2 * g * sin(th) / (3 * (a + b))
    F = m * g * sin(th) / 3
    N = m * g * cos(th) - m * (a + b) * thd**2
    if label:
        N = m * g * (7 * cos(th) - 4) / 3
    return dict(acc=[0.0, thdd, (a + b) * thdd / b],
                mult={'contact': N, 'roll': -F},
                grad={'contact': [1, 0, 0], 'roll': [0, q['r'], -b]})


# ---------------------------------------------------------------------------
# Ladder on a smooth wall and floor

def ladder_state(rng, p, rest=False):
    h = p['l'] / 2
    th = u(rng, 0.1, 1.4)
    thd = 0.0 if rest else u(rng)
    return ({'x': h * sin(th), 'y': h * cos(th), 'theta': th},
            {'x': h * cos(th) * thd, 'y': -h * sin(th) * thd, 'theta': thd}, u(rng, 0, 3))


def ladder_energy(q, v, t, p):
    m, l = p['m'], p['l']
    return m / 2 * (v['x']**2 + v['y']**2) + m * l**2 / 24 * v['theta']**2 + m * p['g'] * q['y']


@example('ladder', ['x', 'y', 'theta'], ladder_state, energy=ladder_energy,
         kinds={'wall': 'holonomic', 'floor': 'holonomic'}, dof=(1, 1),
         special=[('from rest', lambda rng, p: ladder_state(rng, p, rest=True))])
def _(q, v, t, p, label=None):
    # Desloge ch. 50 P8 (T19, planar): th'' = 3 g sin th/(2 l); N_w = m x'', N_f = m (g + y'');
    # from rest the centre starts down at (3 g/4) sin^2 th, N_w = (3/4) m g sin th cos th,
    # N_f = m g (1 - (3/4) sin^2 th).
    m, l, g = p['m'], p['l'], p['g']
    h = l / 2
    th, thd = q['theta'], v['theta']
    thdd = 3 * g * sin(th) / (2 * l)
    xdd = h * (cos(th) * thdd - sin(th) * thd**2)
    ydd = -h * (sin(th) * thdd + cos(th) * thd**2)
    Nw, Nf = m * xdd, m * (g + ydd)
    if label:
        ydd = -3 * g / 4 * sin(th)**2
        Nw = 3 / 4 * m * g * sin(th) * cos(th)
        Nf = m * g * (1 - 3 / 4 * sin(th)**2)
    return dict(acc=[xdd, ydd, thdd], mult={'wall': Nw, 'floor': Nf},
                grad={'wall': [1, 0, -h * cos(th)], 'floor': [0, 1, h * sin(th)]})


# ---------------------------------------------------------------------------
# Rod on a wall and a floor in three dimensions, from rest

def rod3d_from(al, be, ga, a):
    """The state of T19: floor end (2 al, -be, 0), wall end (0, be, 2 ga), at rest."""
    th = math.acos(ga / a)
    ph = math.atan2(be, -al)
    q = {'X': al, 'Y': 0.0, 'Z': ga, 'theta': th, 'phi': ph}
    return q, {c: 0.0 for c in q}, 0.0


def rod3d_state(rng, p):
    a = p['a']
    while True:
        al, be = u(rng, 0.1, 0.8) * a, u(rng, -0.6, 0.6) * a
        if al * al + be * be < 0.9 * a * a:
            break
    ga = sqrt(a * a - al * al - be * be)
    q, v, t = rod3d_from(al, be, ga, a)
    q['Y'] = u(rng)                        # the wall and the floor do not care
    return q, v, u(rng, 0, 3)


def rod3d_reference(rng, p):
    return rod3d_from(0.3, 0.4, sqrt(0.75), 1.0)


@example('rod_wall_floor', ['X', 'Y', 'Z', 'theta', 'phi'], rod3d_state,
         kinds={'wall': 'holonomic', 'floor': 'holonomic'}, dof=(3, 3),
         special=[('reference numbers al = 0.3, be = 0.4, ga = sqrt(0.75): 3.6290', rod3d_reference)])
def _(q, v, t, p, label=None):
    # Desloge ch. 50 P8 (T19): from rest the centre starts down at
    # (3 g/4) (al^2 + 4 be^2)/(al^2 + 4 be^2 + ga^2).  The other accelerations by Newton and
    # Euler for the rod at rest (not from Lagrange): unknowns a_C (3), angular
    # acceleration al_v (3), N_w, N_f:
    #   m a_C = N_w e_x + (N_f - m g) e_z,
    #   (m a^2/3) al_v = (a u) x N_w e_x + (-a u) x N_f e_z   (gives al_v . u = 0),
    #   (a_C + al_v x a u) . e_x = 0,  (a_C - al_v x a u) . e_z = 0.
    m, a, g = p['m'], p['a'], p['g']
    th, ph = q['theta'], q['phi']
    uu = [sin(th) * cos(ph), sin(th) * sin(ph), cos(th)]
    al, be, ga = -a * uu[0], a * uu[1], a * uu[2]
    I = m * a * a / 3
    rows, rhs = [], []
    for i in range(3):                                  # Newton
        row = [0.0] * 8
        row[i] = m
        if i == 0:
            row[6] = -1
        if i == 2:
            row[7] = -1
        rows.append(row)
        rhs.append(-m * g if i == 2 else 0.0)
    tw = cross([a * x for x in uu], [1, 0, 0])          # torque per unit N_w
    tf = cross([-a * x for x in uu], [0, 0, 1])         # per unit N_f
    for i in range(3):                                  # Euler
        row = [0.0] * 8
        row[3 + i] = I
        row[6], row[7] = -tw[i], -tf[i]
        rows.append(row)
        rhs.append(0.0)
    # (al_v x a u)_k = sum_j al_j (e_j x a u)_k
    ej = [[1, 0, 0], [0, 1, 0], [0, 0, 1]]
    ex = [cross(e, [a * x for x in uu]) for e in ej]
    rows.append([1, 0, 0] + [ex[j][0] for j in range(3)] + [0, 0])
    rhs.append(0.0)
    rows.append([0, 0, 1] + [-ex[j][2] for j in range(3)] + [0, 0])
    rhs.append(0.0)
    s = solve(rows, rhs)
    aC, alv, Nw, Nf = s[0:3], s[3:6], s[6], s[7]
    if label:
        assert abs(-aC[2] - 3.6290) < 5e-5, aC    # the reference's number, by Newton-Euler
    zdd = -3 * g / 4 * (al**2 + 4 * be**2) / (al**2 + 4 * be**2 + ga**2)   # the book's
    # u'' = al_v x u at rest; u'' = u_th th'' + u_ph ph''
    udd = cross(alv, uu)
    u_th = [cos(th) * cos(ph), cos(th) * sin(ph), -sin(th)]
    u_ph = [-sin(th) * sin(ph), sin(th) * cos(ph), 0.0]
    thdd = dot(udd, u_th)                    # u_th and u_ph / sin th are orthonormal
    phdd = dot(udd, u_ph) / sin(th)**2
    return dict(acc=[aC[0], aC[1], zdd, thdd, phdd],
                mult={'floor': m * (g + zdd), 'wall': Nw},
                grad={'floor': [0, 0, 1, a * sin(th), 0],
                      'wall': [1, 0, 0, a * cos(th) * cos(ph), -a * sin(th) * sin(ph)]})


# ---------------------------------------------------------------------------
# Heavy symmetric top

def top_state(rng, p):
    q = {'phi': u(rng, -3, 3), 'theta': u(rng, 0.3, 2.8), 'psi': u(rng, -3, 3)}
    v = {'phi': u(rng, -3, 3), 'theta': u(rng, -3, 3), 'psi': u(rng, -20, 20)}
    return q, v, u(rng, 0, 3)


def top_steady(rng, p):
    """Steady precession: theta' = 0 and M g h = phi' (C w3 - A phi' cos theta), the slow root."""
    A, C, Mgh = p['A'], p['C'], p['M'] * p['g'] * p['h']
    th, w3 = u(rng, 0.3, 1.3), u(rng, 15, 30)
    c = cos(th)
    # A c phi'^2 - C w3 phi' + M g h = 0
    phd = (C * w3 - sqrt(C * C * w3 * w3 - 4 * A * c * Mgh)) / (2 * A * c)
    return ({'phi': u(rng, -3, 3), 'theta': th, 'psi': u(rng, -3, 3)},
            {'phi': phd, 'theta': 0.0, 'psi': w3 - phd * cos(th)}, 0.0)


def top_energy(q, v, t, p):
    A, C = p['A'], p['C']
    th = q['theta']
    w3 = v['psi'] + v['phi'] * cos(th)
    return (A / 2 * (v['theta']**2 + v['phi']**2 * sin(th)**2) + C / 2 * w3**2
            + p['M'] * p['g'] * p['h'] * cos(th))


@example('heavy_top', ['phi', 'theta', 'psi'], top_state, energy=top_energy,
         special=[('steady precession', top_steady)])
def _(q, v, t, p, label=None):
    # Desloge ch. 64 Ex. 1 (seed-desloge-B.md C10): w3 = psi' + phi' cos th constant,
    # d/dt(A phi' sin^2 th + C w3 cos th) = 0,
    # A th'' = A phi'^2 sin th cos th - C w3 phi' sin th + M g h sin th.
    A, C, Mgh = p['A'], p['C'], p['M'] * p['g'] * p['h']
    th, phd, thd, psd = q['theta'], v['phi'], v['theta'], v['psi']
    s, c = sin(th), cos(th)
    w3 = psd + phd * c
    thdd = (A * phd**2 * s * c - C * w3 * phd * s + Mgh * s) / A
    phdd = (C * w3 * thd * s - 2 * A * phd * thd * s * c) / (A * s * s)
    psdd = phd * thd * s - phdd * c
    if label:
        assert abs(thdd) < 1e-9 * Mgh, thdd      # the steady-precession relation itself
        thdd = 0.0
    return dict(acc=[phdd, thdd, psdd], mult={}, grad={})


# ---------------------------------------------------------------------------
# Rolling upright disk

def disk_state_of(xn, yn):
    """A rolling state of an upright disk: contact point (xn, yn), heading ph, roll psi."""
    def gen(rng, p):
        a = p['a']
        ph, phd, psd = u(rng, -3, 3), u(rng), u(rng, -4, 4)
        q = {xn: u(rng), yn: u(rng), 'ph': ph, 'psi': u(rng, -3, 3)}
        v = {xn: -a * psd * cos(ph), yn: -a * psd * sin(ph), 'ph': phd, 'psi': psd}
        return q, v, u(rng, 0, 3)
    return gen


disk_state = disk_state_of('x1', 'x2')


def disk_energy(q, v, t, p):
    m, a = p['m'], p['a']
    vx, vy = [v[c] for c in v if c not in ('ph', 'psi')]
    return m / 2 * (vx**2 + vy**2) + m * a * a / 8 * (v['ph']**2 + 2 * v['psi']**2)


def disk_power(q, v, t, p):
    return p['f1'] * v['x1'] + p['f2'] * v['x2']


@example('rolling_disk', ['x1', 'x2', 'ph', 'psi'], disk_state,
         kinds={'roll1': 'nonholonomic', 'roll2': 'nonholonomic'}, dof=(4, 2),   # T09
         sets=[{'f1': 0.7, 'f2': -1.3}, {'f1': -2.1, 'f2': 0.4}],
         energy=disk_energy, power=disk_power)
def _(q, v, t, p, label=None):
    # Desloge ch. 52 Ex. 1 (T31), constraints of ch. 49 Ex. 1 (T09).
    m, a, f1, f2 = p['m'], p['a'], p['f1'], p['f2']
    ph, phd, psd = q['ph'], v['ph'], v['psi']
    fp = f1 * cos(ph) + f2 * sin(ph)
    l1 = -f1 + 2 / 3 * cos(ph) * fp + m * a * phd * psd * sin(ph)
    l2 = -f2 + 2 / 3 * sin(ph) * fp - m * a * phd * psd * cos(ph)
    psdd = -2 * fp / (3 * m * a)
    return dict(acc=[(f1 + l1) / m, (f2 + l2) / m, 0.0, psdd],
                mult={'roll1': l1, 'roll2': l2},
                grad={'roll1': [1, 0, 0, a * cos(ph)], 'roll2': [0, 1, 0, a * sin(ph)]})


# ---------------------------------------------------------------------------
# Disk rolling on an incline

def incline_energy(q, v, t, p):
    return disk_energy(q, v, t, p) - p['m'] * p['g'] * sin(p['al']) * q['x']


@example('rolling_disk_incline', ['x', 'y', 'ph', 'psi'], disk_state_of('x', 'y'), energy=incline_energy,
         kinds={'roll1': 'nonholonomic', 'roll2': 'nonholonomic'}, dof=(4, 2))
def _(q, v, t, p, label=None):
    # Desloge ch. 52 P3 (T33): ph'' = 0, v' = (2/3) g sin(al) cos(ph), v = -a psi'.
    m, a, g, al = p['m'], p['a'], p['g'], p['al']
    ph, phd = q['ph'], v['ph']
    vel = -a * v['psi']
    vd = 2 / 3 * g * sin(al) * cos(ph)
    xdd = vd * cos(ph) - vel * sin(ph) * phd
    ydd = vd * sin(ph) + vel * cos(ph) * phd
    return dict(acc=[xdd, ydd, 0.0, -vd / a],
                mult={'roll1': m * xdd - m * g * sin(al), 'roll2': m * ydd},
                grad={'roll1': [1, 0, 0, a * cos(ph)], 'roll2': [0, 1, 0, a * sin(ph)]})


# ---------------------------------------------------------------------------
# Two disks on an axle

def axle_state(rng, p):
    """A rolling state: forward speed w along n = (-sin th, cos th), turning rate om."""
    a, b = p['a'], p['b']
    th, w, om = u(rng, -3, 3), u(rng), u(rng)
    q = {'x': u(rng), 'y': u(rng), 'th': th, 'phi': u(rng, -3, 3), 'psi': u(rng, -3, 3)}
    v = {'x': -w * sin(th), 'y': w * cos(th), 'th': om, 'phi': (w + b * om) / a,
         'psi': (w - b * om) / a}
    return q, v, u(rng, 0, 3)


def axle_energy(q, v, t, p):
    m, a, b = p['m'], p['a'], p['b']
    return (m * (v['x']**2 + v['y']**2) + (m * b * b + m * a * a / 4) * v['th']**2
            + m * a * a / 4 * (v['phi']**2 + v['psi']**2))


@example('two_disks_axle', ['x', 'y', 'th', 'phi', 'psi'], axle_state, energy=axle_energy,
         kinds={'side': 'nonholonomic', 'roll1': 'nonholonomic', 'roll2': 'nonholonomic'},
         dof=(4, 2))
def _(q, v, t, p, label=None):
    # Desloge ch. 52 P5 (p. 557; 4 configurational, 2 motional degrees of freedom).  Derived
    # by d'Alembert with the admissible displacements (d sigma along n, d theta): with
    # w = -x' sin th + y' cos th, the sigma equation is 2 (m + 2J/a^2) w' = 0 and the theta
    # equation 2 (I + 2 J b^2/a^2) th'' = 0 (J = m a^2/4, I = m b^2 + J): the axle keeps its
    # speed and turning rate, x'' = -w th' cos th, y'' = -w th' sin th, and the wheels their
    # rates.  The multipliers: the th and phi rows give lambda_roll1 = lambda_roll2 = 0, and
    # the side force is the centripetal force of the mass 2m, lambda_side = -2 m w th'.
    m, a, b, th = p['m'], p['a'], p['b'], q['th']
    w, om = -v['x'] * sin(th) + v['y'] * cos(th), v['th']
    c, s = cos(th), sin(th)
    return dict(acc=[-w * om * c, -w * om * s, 0.0, 0.0, 0.0],
                mult={'side': -2 * m * w * om, 'roll1': 0.0, 'roll2': 0.0},
                grad={'side': [c, s, 0, 0, 0], 'roll1': [-s, c, b, -a, 0],
                      'roll2': [-s, c, -b, 0, -a]})


# ---------------------------------------------------------------------------
# Sphere on a turntable

def omega_space(ph, th, phd, thd, psd):
    """Desloge ch. 63 (seed-desloge-B.md C8), z-x-z."""
    return [thd * cos(ph) + psd * sin(ph) * sin(th),
            thd * sin(ph) - psd * cos(ph) * sin(th),
            phd + psd * cos(th)]


def turntable_state(rng, p):
    a, W = p['a'], p['Omega']
    q = {'x': u(rng), 'y': u(rng), 'phi': u(rng, -3, 3), 'theta': u(rng, 0.3, 2.8),
         'psi': u(rng, -3, 3)}
    vv = {'phi': u(rng, -3, 3), 'theta': u(rng, -3, 3), 'psi': u(rng, -3, 3)}
    w = omega_space(q['phi'], q['theta'], vv['phi'], vv['theta'], vv['psi'])
    vv['x'] = a * w[1] - W * q['y']
    vv['y'] = -a * w[0] + W * q['x']
    return q, vv, u(rng, 0, 3)


@example('sphere_turntable', ['x', 'y', 'phi', 'theta', 'psi'], turntable_state,
         kinds={'roll_x': 'nonholonomic', 'roll_y': 'nonholonomic'}, dof=(5, 3))
def _(q, v, t, p, label=None):
    # Desloge ch. 64 P10 (seed-desloge-B.md T47): r'' = (I Omega/(I + m a^2)) e_z x r',
    # 2 Omega/7 for I = 2 m a^2/5; F = m r'' is the friction; I w' = (-a e_z) x F.
    m, a, W = p['m'], p['a'], p['Omega']
    I = 2 / 5 * m * a * a
    k = I * W / (I + m * a * a)
    assert abs(k - 2 * W / 7) < 1e-12 * W
    xdd, ydd = -k * v['y'], k * v['x']
    F = [m * xdd, m * ydd, 0.0]
    wd = [x / I for x in cross([0, 0, -a], F)]
    # w = J (phi', theta', psi'); w' = J (phi'', theta'', psi'') + J' (phi', theta', psi')
    ph, th = q['phi'], q['theta']
    phd, thd, psd = v['phi'], v['theta'], v['psi']
    J = [[0, cos(ph), sin(ph) * sin(th)],
         [0, sin(ph), -cos(ph) * sin(th)],
         [1, 0, cos(th)]]
    Jdot_v = [-thd * sin(ph) * phd + psd * (cos(ph) * sin(th) * phd + sin(ph) * cos(th) * thd),
              thd * cos(ph) * phd + psd * (sin(ph) * sin(th) * phd - cos(ph) * cos(th) * thd),
              -psd * sin(th) * thd]
    angles = solve(J, [wd[i] - Jdot_v[i] for i in range(3)])
    return dict(acc=[xdd, ydd] + angles,
                mult={'roll_x': F[0], 'roll_y': F[1]},
                grad={'roll_x': [1, 0, 0, -a * sin(ph), a * cos(ph) * sin(th)],
                      'roll_y': [0, 1, 0, a * cos(ph), a * sin(ph) * sin(th)]})


# ---------------------------------------------------------------------------
# Rolling written by `rolls` (src/model/roll.c): the same books, and where a hand-written model
# of the same system exists, the same numbers as that model (EQUIVALENT below).

def renamed(name, names):
    """The book function of example `name` with its multipliers renamed (old -> new)."""
    book = EXAMPLES[name]['book']

    def fn(q, v, t, p, label=None):
        out = book(q, v, t, p, label)
        return dict(acc=out['acc'], mult={names[k]: x for k, x in out['mult'].items()},
                    grad={names[k]: x for k, x in out['grad'].items()})
    return fn


# examples whose rolls model must give, state by state, the accelerations, multipliers (renamed)
# and constraint forces of a hand-written model in the same coordinates
EQUIVALENT = {
    'rolling_disk_rolls': ('rolling_disk', {'disk_roll1': 'roll1', 'disk_roll2': 'roll2'}),
    'sphere_turntable_rolls': ('sphere_turntable', {'ball_roll1': 'roll_x', 'ball_roll2': 'roll_y'}),
}

example('rolling_disk_rolls', ['x1', 'x2', 'ph', 'psi'], disk_state,
        kinds={'disk_roll1': 'nonholonomic', 'disk_roll2': 'nonholonomic'}, dof=(4, 2),
        sets=[{'f1': 0.7, 'f2': -1.3}, {'f1': -2.1, 'f2': 0.4}],
        energy=disk_energy, power=disk_power)(
    renamed('rolling_disk', {'roll1': 'disk_roll1', 'roll2': 'disk_roll2'}))

example('sphere_turntable_rolls', ['x', 'y', 'phi', 'theta', 'psi'], turntable_state,
        kinds={'ball_roll1': 'nonholonomic', 'ball_roll2': 'nonholonomic'}, dof=(5, 3))(
    renamed('sphere_turntable', {'roll_x': 'ball_roll1', 'roll_y': 'ball_roll2'}))


def euler_matrix(ph, th, ps):
    """rot_z(ph) rot_x(th) rot_z(ps), body -> space (Desloge ch. 63, seed-desloge-B.md C8)."""
    def rz(a):
        return [[cos(a), -sin(a), 0], [sin(a), cos(a), 0], [0, 0, 1]]

    def rx(a):
        return [[1, 0, 0], [0, cos(a), -sin(a)], [0, sin(a), cos(a)]]

    def mul(A, B):
        return [[sum(A[i][k] * B[k][j] for k in range(3)) for j in range(3)] for i in range(3)]
    return mul(mul(rz(ph), rx(th)), rz(ps))


def euler_accelerations(wd, q, v):
    """(phi'', theta'', psi'') from the space angular acceleration wd: w = J(q) (phi', theta',
    psi''), w' = J q_ang'' + J' q_ang'."""
    ph, th = q['phi'], q['theta']
    phd, thd, psd = v['phi'], v['theta'], v['psi']
    J = [[0, cos(ph), sin(ph) * sin(th)],
         [0, sin(ph), -cos(ph) * sin(th)],
         [1, 0, cos(th)]]
    Jdot_v = [-thd * sin(ph) * phd + psd * (cos(ph) * sin(th) * phd + sin(ph) * cos(th) * thd),
              thd * cos(ph) * phd + psd * (sin(ph) * sin(th) * phd - cos(ph) * cos(th) * thd),
              -psd * sin(th) * thd]
    return solve(J, [wd[i] - Jdot_v[i] for i in range(3)])


def body_rates(q, v):
    return omega_space(q['phi'], q['theta'], v['phi'], v['theta'], v['psi'])


def contact_velocity_grad(coords, q, rho, tangent):
    """d(tangent . v_p)/dq'_j, v_p = c' + w x rho, by linearity in the velocities."""
    out = []
    for c in coords:
        e = {k: float(k == c) for k in coords}
        w = body_rates(q, e)
        vp = [e['x'] + cross(w, rho)[0], e['y'] + cross(w, rho)[1], e['z'] + cross(w, rho)[2]]
        out.append(dot(tangent, vp))
    return out


def rigid_energy(m, I_body, q, v, V):
    R = euler_matrix(q['phi'], q['theta'], q['psi'])
    w = body_rates(q, v)
    wb = [sum(R[k][i] * w[k] for k in range(3)) for i in range(3)]
    return (m / 2 * (v['x']**2 + v['y']**2 + v['z']**2)
            + sum(I_body[i] * wb[i]**2 for i in range(3)) / 2 + V)


# ---------------------------------------------------------------------------
# Rolling coin: a thin disk rolling and leaning on a horizontal plane

TILT_COORDS = ['x', 'y', 'z', 'phi', 'theta', 'psi']


def coin_rho(a, ph, th):
    """p - c = -a (e_z - cos(th) k)/sin(th): the rim point lowest along e_z (k the axis)."""
    k = [sin(th) * sin(ph), -sin(th) * cos(ph), cos(th)]
    return [-a * ((i == 2) - cos(th) * k[i]) / sin(th) for i in range(3)]


def coin_rho_dot(a, ph, th, phd, thd, w):
    k = [sin(th) * sin(ph), -sin(th) * cos(ph), cos(th)]
    kd = cross(w, k)
    s, c = sin(th), cos(th)
    return [-a * ((s * thd * k[i] - c * kd[i]) / s - ((i == 2) - c * k[i]) * c * thd / (s * s))
            for i in range(3)]


def coin_state(rng, p):
    a = p['a']
    th = u(rng, 0.4, 2.7)
    q = {'x': u(rng), 'y': u(rng), 'z': a * sin(th), 'phi': u(rng, -3, 3), 'theta': th,
         'psi': u(rng, -3, 3)}
    v = {'phi': u(rng, -3, 3), 'theta': u(rng, -2, 2), 'psi': u(rng, -6, 6)}
    spin = cross(body_rates(q, v), coin_rho(a, q['phi'], th))
    v['x'], v['y'], v['z'] = -spin[0], -spin[1], -spin[2]
    assert abs(v['z'] - a * cos(th) * v['theta']) < 1e-12
    return q, v, u(rng, 0, 3)


def coin_energy(q, v, t, p):
    m, a = p['m'], p['a']
    return rigid_energy(m, [m * a * a / 4, m * a * a / 4, m * a * a / 2], q, v, m * p['g'] * q['z'])


def newton_euler(m, I_space, w, rho, rho_dot, gravity):
    """Solve m c'' = F + m gravity, I w' + w x I w = rho x F, c'' + w' x rho + w x rho' = 0
    for (c'', w', F) (Byerly Art. 10a: friction unknown, contact point at rest)."""
    A, b = [], []
    Iw = [sum(I_space[i][j] * w[j] for j in range(3)) for i in range(3)]
    gyro = cross(w, Iw)
    wrd = cross(w, rho_dot)
    for i in range(3):      # m c''_i - F_i = m g_i
        A.append([m * (j == i) for j in range(3)] + [0] * 3 + [-(j == i) for j in range(3)])
        b.append(m * gravity[i])
    for i in range(3):      # I w' - rho x F = -w x I w
        row = [0] * 3 + [I_space[i][j] for j in range(3)]
        row += [-cross(rho, [float(j == k) for k in range(3)])[i] for j in range(3)]
        A.append(row)
        b.append(-gyro[i])
    for i in range(3):      # c'' + w' x rho = -w x rho'
        row = [float(j == i) for j in range(3)]
        row += [cross([float(j == k) for k in range(3)], rho)[i] for j in range(3)]
        A.append(row + [0] * 3)
        b.append(-wrd[i])
    x = solve(A, b)
    return x[0:3], x[3:6], x[6:9]


def inertia_in_space(q, I_body):
    R = euler_matrix(q['phi'], q['theta'], q['psi'])
    return [[sum(R[i][k] * I_body[k] * R[j][k] for k in range(3)) for j in range(3)]
            for i in range(3)]


@example('rolling_disk_tilted', TILT_COORDS, coin_state, energy=coin_energy,
         kinds={'disk_roll1': 'nonholonomic', 'disk_roll2': 'nonholonomic',
                'disk_contact': 'holonomic'}, dof=(5, 3))
def _(q, v, t, p, label=None):
    # Newton-Euler with the contact force unknown (Byerly Art. 10a); the rolling constraints of
    # Desloge ch. 49 Ex. 1 (T09) at theta = pi/2, here for any lean.
    m, a, g = p['m'], p['a'], p['g']
    ph, th = q['phi'], q['theta']
    w = body_rates(q, v)
    rho = coin_rho(a, ph, th)
    rho_dot = coin_rho_dot(a, ph, th, v['phi'], v['theta'], w)
    I = inertia_in_space(q, [m * a * a / 4, m * a * a / 4, m * a * a / 2])
    cdd, wd, F = newton_euler(m, I, w, rho, rho_dot, [0, 0, -g])
    grads = {'disk_roll1': contact_velocity_grad(TILT_COORDS, q, rho, [1, 0, 0]),
             'disk_roll2': contact_velocity_grad(TILT_COORDS, q, rho, [0, 1, 0]),
             'disk_contact': [0, 0, 1, 0, -a * cos(th), 0]}
    return dict(acc=cdd + euler_accelerations(wd, q, v),
                mult={'disk_roll1': F[0], 'disk_roll2': F[1], 'disk_contact': F[2]},
                grad=grads)


# ---------------------------------------------------------------------------
# Sphere rolling on an incline (horizontal axes, the plane's normal tilted)

def incline_sphere_state(rng, p):
    a, al = p['a'], p['al']
    n = [sin(al), 0.0, cos(al)]
    x = u(rng)
    q = {'x': x, 'y': u(rng), 'z': (a - x * sin(al)) / cos(al), 'phi': u(rng, -3, 3),
         'theta': u(rng, 0.3, 2.8), 'psi': u(rng, -3, 3)}
    v = {'phi': u(rng, -3, 3), 'theta': u(rng, -3, 3), 'psi': u(rng, -3, 3)}
    spin = cross(body_rates(q, v), [-a * c for c in n])
    v['x'], v['y'], v['z'] = -spin[0], -spin[1], -spin[2]
    return q, v, u(rng, 0, 3)


def incline_sphere_energy(q, v, t, p):
    m, a = p['m'], p['a']
    I = 2 / 5 * m * a * a
    return rigid_energy(m, [I, I, I], q, v, m * p['g'] * q['z'])


@example('sphere_incline_rolls', TILT_COORDS, incline_sphere_state, energy=incline_sphere_energy,
         kinds={'ball_roll1': 'nonholonomic', 'ball_roll2': 'nonholonomic',
                'ball_contact': 'holonomic'}, dof=(5, 3))
def _(q, v, t, p, label=None):
    # Byerly Art. 10a exercise (TC19 note): c'' = (5/7) g sin(al) down the slope; friction
    # (2/7) m g sin(al) up it, normal force m g cos(al); I w' = (-a n) x F.
    m, a, g, al = p['m'], p['a'], p['g'], p['al']
    n, down = [sin(al), 0.0, cos(al)], [cos(al), 0.0, -sin(al)]
    cdd = [5 / 7 * g * sin(al) * d for d in down]
    F = [m * cdd[i] + m * g * (i == 2) for i in range(3)]
    rho = [-a * c for c in n]
    wd = [x / (2 / 5 * m * a * a) for x in cross(rho, F)]
    return dict(acc=cdd + euler_accelerations(wd, q, v),
                mult={'ball_roll1': -2 / 7 * m * g * sin(al), 'ball_roll2': 0.0,
                      'ball_contact': m * g * cos(al)},
                grad={'ball_roll1': contact_velocity_grad(TILT_COORDS, q, rho, down),
                      'ball_roll2': contact_velocity_grad(TILT_COORDS, q, rho, [0, 1, 0]),
                      'ball_contact': [sin(al), 0, cos(al), 0, 0, 0]})


# ---------------------------------------------------------------------------
# Cylinder rolling inside a fixed cylinder

def cyl_in_state(rng, p, th=None, thd=None):
    R, b = p['R'], p['b']
    th = u(rng, -1.5, 1.5) if th is None else th
    thd = u(rng) if thd is None else thd
    return ({'r': R - b, 'theta': th, 'phi': u(rng, -3, 3)},
            {'r': 0.0, 'theta': thd, 'phi': -(R - b) * thd / b}, u(rng, 0, 3))


def cyl_in_energy(q, v, t, p):
    m, b = p['m'], p['b']
    return (m / 2 * (v['r']**2 + q['r']**2 * v['theta']**2) + m * b**2 / 4 * v['phi']**2
            - m * p['g'] * q['r'] * cos(q['theta']))


def cyl_in_bottom(rng, p):
    """At the bottom, moving: theta'' = 0, the normal force m g + m (R - b) theta'^2."""
    return cyl_in_state(rng, p, th=0.0)


@example('cylinder_in_cylinder', ['r', 'theta', 'phi'], cyl_in_state, energy=cyl_in_energy,
         kinds={'wheel_contact': 'holonomic', 'wheel_roll1': 'integrable'}, dof=(1, 1),
         special=[('at the bottom', cyl_in_bottom)])
def _(q, v, t, p, label=None):
    # Byerly Art. 9c (TC17, k^2 = b^2/2) inside a circle: (3/2) m (R - b) th'' = -m g sin th;
    # friction m g sin th/3 along increasing theta; N = m g cos th + m (R - b) th'^2.
    m, R, b, g = p['m'], p['R'], p['b'], p['g']
    th, thd = q['theta'], v['theta']
    thdd = -2 * g * sin(th) / (3 * (R - b))
    if label:
        assert th == 0.0
    return dict(acc=[0.0, thdd, -(R - b) * thdd / b],
                mult={'wheel_contact': m * g * cos(th) + m * (R - b) * thd**2,
                      'wheel_roll1': m * g * sin(th) / 3},
                grad={'wheel_contact': [-1, 0, 0], 'wheel_roll1': [0, q['r'], b]})


# ---------------------------------------------------------------------------
# Compound pendulum with a pivot

def compound_state(rng, p):
    h = p['h']
    th, thd = u(rng, -3, 3), u(rng, -3, 3)
    return ({'x': h * sin(th), 'y': -h * cos(th), 'theta': th},
            {'x': h * cos(th) * thd, 'y': h * sin(th) * thd, 'theta': thd}, u(rng, 0, 3))


def compound_energy(q, v, t, p):
    m, k = p['m'], p['k']
    return m / 2 * (v['x']**2 + v['y']**2 + k * k * v['theta']**2) + m * p['g'] * q['y']


@example('compound_pendulum', ['x', 'y', 'theta'], compound_state, energy=compound_energy,
         kinds={'pivot_x': 'holonomic', 'pivot_y': 'holonomic'}, dof=(1, 1))
def _(q, v, t, p, label=None):
    # Byerly Art. 9a (TC15): th'' = -g h sin th/(h^2 + k^2); pivot force P = m (x'', y'' + g).
    m, h, k, g = p['m'], p['h'], p['k'], p['g']
    th, thd = q['theta'], v['theta']
    thdd = -g * h * sin(th) / (h * h + k * k)
    xdd = h * (cos(th) * thdd - sin(th) * thd**2)
    ydd = h * (sin(th) * thdd + cos(th) * thd**2)
    return dict(acc=[xdd, ydd, thdd], mult={'pivot_x': m * xdd, 'pivot_y': m * (ydd + g)},
                grad={'pivot_x': [1, 0, -h * cos(th)], 'pivot_y': [0, 1, -h * sin(th)]})


# ---------------------------------------------------------------------------
# Double pendulum of two rods

def free_state(ranges):
    def gen(rng, p):
        q = {c: u(rng, *r) for c, r in ranges.items()}
        v = {c: u(rng) for c in ranges}
        return q, v, u(rng, 0, 3)
    return gen


def rods_energy(q, v, t, p):
    m1, m2, l1, l2, g = p['m1'], p['m2'], p['l1'], p['l2'], p['g']
    t1, t2, w1, w2 = q['theta1'], q['theta2'], v['theta1'], v['theta2']
    T = ((m1 / 3 + m2) * l1**2 * w1**2 / 2 + m2 * l2**2 * w2**2 / 6
         + m2 * l1 * l2 * w1 * w2 * cos(t1 - t2) / 2)
    return T - (m1 / 2 + m2) * g * l1 * cos(t1) - m2 * g * l2 * cos(t2) / 2


@example('double_rod_pendulum', ['theta1', 'theta2'],
         free_state({'theta1': (-3, 3), 'theta2': (-3, 3)}), energy=rods_energy)
def _(q, v, t, p, label=None):
    # Desloge ch. 50 P1 (T13) with T_rod of seed-desloge-A.md C1.
    m1, m2, l1, l2, g = p['m1'], p['m2'], p['l1'], p['l2'], p['g']
    t1, t2, w1, w2 = q['theta1'], q['theta2'], v['theta1'], v['theta2']
    d = t1 - t2
    k = m2 * l1 * l2 / 2
    M = [[(m1 / 3 + m2) * l1**2, k * cos(d)], [k * cos(d), m2 * l2**2 / 3]]
    f = [-k * sin(d) * w2**2 - (m1 / 2 + m2) * g * l1 * sin(t1),
         k * sin(d) * w1**2 - m2 * g * l2 / 2 * sin(t2)]
    return dict(acc=solve(M, f), mult={}, grad={})


# ---------------------------------------------------------------------------
# Pendulum in Cartesian coordinates

def pend_state(rng, p):
    l = p['l']
    th, thd = u(rng, -3, 3), u(rng, -3, 3)
    return ({'x': l * sin(th), 'y': -l * cos(th)},
            {'x': l * cos(th) * thd, 'y': l * sin(th) * thd}, u(rng, 0, 3))


def pend_energy(q, v, t, p):
    return p['m'] / 2 * (v['x']**2 + v['y']**2) + p['m'] * p['g'] * q['y']


@example('pendulum_cartesian', ['x', 'y'], pend_state, energy=pend_energy,
         kinds={'rod': 'holonomic'}, dof=(1, 1))
def _(q, v, t, p, label=None):
    # Britannica sec. 3 (28)-(30) (B23): tension S = m (l th'^2 + g cos th);
    # th'' = -(g/l) sin th; force on the bob -S (x, y)/l = lambda (2x, 2y).
    m, l, g = p['m'], p['l'], p['g']
    x, y = q['x'], q['y']
    th = math.atan2(x, -y)
    thd = (x * v['y'] - y * v['x']) / l**2
    S = m * (l * thd**2 + g * cos(th))
    return dict(acc=[-S * x / (m * l), -S * y / (m * l) - g], mult={'rod': -S / (2 * l)},
                grad={'rod': [2 * x, 2 * y]})


# ---------------------------------------------------------------------------
# Bead on a helix

def helix_state(rng, p):
    ph, phd = u(rng, -3, 3), u(rng)
    return {'ph': ph, 'z': p['b'] * ph}, {'ph': phd, 'z': p['b'] * phd}, u(rng, 0, 3)


@example('bead_helix_reaction', ['ph', 'z'], helix_state, kinds={'helix': 'holonomic'},
         dof=(1, 1))
def _(q, v, t, p, label=None):
    # Desloge ch. 51 Ex. 1 (T15): z'' = g b^2/(a^2+b^2), lambda = -m g a^2/(a^2+b^2).
    m, a, b, g = p['m'], p['a'], p['b'], p['g']
    D = a * a + b * b
    return dict(acc=[g * b / D, g * b * b / D], mult={'helix': -m * g * a * a / D},
                grad={'helix': [-b, 1]})


# ---------------------------------------------------------------------------

# ---------------------------------------------------------------------------
# Coulomb friction (issue 18): examples/friction_*.qd.  qdot eom writes a friction contact
# as it sticks: the equations of the ideal constraints, each multiplier the friction force
# (the sliding is simulate's, tests/cli/check_friction_cli.py).

def slides_state(rng, p):
    xd = u(rng)
    return {'x': u(rng), 'th': u(rng, -3, 3)}, {'x': xd, 'th': -xd / p['a']}, u(rng, 0, 3)


def slides_energy(q, v, t, p):
    return p['m'] / 2 * v['x'] ** 2 + p['kappa'] * p['m'] * p['a'] ** 2 / 2 * v['th'] ** 2


@example('friction_sphere_slides', ['x', 'th'], slides_state, energy=slides_energy,
         sets=[{'kappa': 0.5}], kinds={'slip': 'integrable'}, dof=(1, 1))
def _(q, v, t, p, label=None):
    # Byerly Art. 10a (seed-byerly.md TC20): rolling on a level table, no friction, uniform motion.
    return dict(acc=[0.0, 0.0], mult={'slip': 0.0}, grad={'slip': [1, p['a']]})


def incline_roll_state(rng, p):
    xd = u(rng)
    return {'x': u(rng), 'th': u(rng, -3, 3)}, {'x': xd, 'th': xd / p['a']}, u(rng, 0, 3)


def incline_roll_energy(q, v, t, p):
    return slides_energy(q, v, t, p) - p['m'] * p['g'] * sin(p['al']) * q['x']


@example('friction_sphere_incline', ['x', 'th'], incline_roll_state, energy=incline_roll_energy,
         sets=[{'kappa': 0.5, 'mu': 0.5}], kinds={'slip': 'integrable'}, dof=(1, 1))
def _(q, v, t, p, label=None):
    # Byerly Art. 9c (seed-byerly.md TC17): x'' = g sin(al) a^2/(a^2 + k^2), friction
    # k^2/(a^2 + k^2) m g sin(al) up the slope (lambda_slip = -F: the slip's gradient is (1, -a)).
    m, a, g, al, kap = p['m'], p['a'], p['g'], p['al'], p['kappa']
    xdd = g * sin(al) / (1 + kap)
    return dict(acc=[xdd, xdd / a], mult={'slip': -kap / (1 + kap) * m * g * sin(al)},
                grad={'slip': [1, -a]})


def block_state(rng, p):
    return {'x': u(rng)}, {'x': 0.0}, u(rng, 0, 3)


@example('friction_block_incline', ['x'], block_state, kinds={'stick': 'integrable'}, dof=(0, 0))
def _(q, v, t, p, label=None):
    # Byerly Art. 9c: at rest the friction m g sin(al) holds the block up the slope.
    return dict(acc=[0.0], mult={'stick': -p['m'] * p['g'] * sin(p['al'])}, grad={'stick': [1]})


def belt_state(rng, p):
    # sticking needs k |x| <= mu_s m g
    lim = p['mu_s'] * p['m'] * p['g'] / p['k']
    return {'x': u(rng, -lim, lim)}, {'x': p['vb']}, u(rng, 0, 3)


@example('friction_stick_slip', ['x'], belt_state,
         energy=lambda q, v, t, p: p['m'] / 2 * v['x'] ** 2 + p['k'] / 2 * q['x'] ** 2,
         power=lambda q, v, t, p: p['k'] * q['x'] * p['vb'],
         kinds={'belt': 'integrable'}, dof=(0, 0))
def _(q, v, t, p, label=None):
    # Carried by the belt: the friction k x balances the spring, and works k x vb on the block.
    return dict(acc=[0.0], mult={'belt': p['k'] * q['x']}, grad={'belt': [1]})


def wedge_state(rng, p):
    yd = u(rng)
    return ({'x': u(rng), 'y': u(rng), 'z': p['a'], 'th': u(rng, -3, 3)},
            {'x': u(rng), 'y': yd, 'z': 0.0, 'th': yd / p['a']}, u(rng, 0, 3))


def wedge_energy(q, v, t, p):
    M, m, a, al, g = p['M'], p['m'], p['a'], p['al'], p['g']
    cx = v['x'] - v['y'] * cos(al) - v['z'] * sin(al)
    cy = -v['y'] * sin(al) + v['z'] * cos(al)
    return (M / 2 * v['x'] ** 2 + m / 2 * (cx * cx + cy * cy) + 0.2 * m * a * a * v['th'] ** 2 +
            m * g * (-q['y'] * sin(al) + q['z'] * cos(al)))


@example('friction_wedge_sphere', ['x', 'y', 'z', 'th'], wedge_state, energy=wedge_energy,
         kinds={'contact': 'holonomic', 'slip': 'integrable'}, dof=(2, 2))
def _(q, v, t, p, label=None):
    # Byerly Art. 9 Ex. 3 (seed-byerly.md TC19): y'' = 5 (M + m) g sin(al)/(7 (M + m) -
    # 5 m cos^2(al)), x'' = 5 m g sin(al) cos(al)/(same); the ball's turn k^2 th'' = -a F/m
    # (k^2 = 2 a^2/5), the normal force m g cos(al) - m sin(al) x'' (the z equation).
    M, m, a, al, g = p['M'], p['m'], p['a'], p['al'], p['g']
    den = 7 * (M + m) - 5 * m * cos(al) ** 2
    ydd, xdd = 5 * (M + m) * g * sin(al) / den, 5 * m * g * sin(al) * cos(al) / den
    return dict(acc=[xdd, ydd, 0.0, ydd / a],
                mult={'contact': m * g * cos(al) - m * sin(al) * xdd, 'slip': -0.4 * m * ydd},
                grad={'contact': [0, 0, 1, 0], 'slip': [0, 1, 0, -a]})


def billiard_state(rng, p):
    a = p['a']
    q = {'x': u(rng), 'y': u(rng), 'phi': u(rng, -3, 3), 'theta': u(rng, 0.3, 2.8),
         'psi': u(rng, -3, 3)}
    vv = {'phi': u(rng, -3, 3), 'theta': u(rng, -3, 3), 'psi': u(rng, -3, 3)}
    w = omega_space(q['phi'], q['theta'], vv['phi'], vv['theta'], vv['psi'])
    vv['x'], vv['y'] = a * w[1], -a * w[0]
    return q, vv, u(rng, 0, 3)


@example('friction_billiard', ['x', 'y', 'phi', 'theta', 'psi'], billiard_state,
         kinds={'ball_roll1': 'nonholonomic', 'ball_roll2': 'nonholonomic'}, dof=(5, 3))
def _(q, v, t, p, label=None):
    # Byerly Art. 10a (seed-byerly.md TC20): rolling on a level table, the centre moves
    # uniformly, w is constant, no friction.  roll1 = x' - a w_y, roll2 = y' + a w_x.
    a, ph, th = p['a'], q['phi'], q['theta']
    J = [[0, cos(ph), sin(ph) * sin(th)], [0, sin(ph), -cos(ph) * sin(th)], [1, 0, cos(th)]]
    return dict(acc=[0.0, 0.0] + euler_accelerations([0.0, 0.0, 0.0], q, v),
                mult={'ball_roll1': 0.0, 'ball_roll2': 0.0},
                grad={'ball_roll1': [1, 0] + [-a * x for x in J[1]],
                      'ball_roll2': [0, 1] + [a * x for x in J[0]]})


def particle_incline_state(rng, p):
    x = u(rng)
    return {'x': x, 'y': u(rng), 'z': -x * tan(p['al'])}, {'x': 0.0, 'y': 0.0, 'z': 0.0}, \
        u(rng, 0, 3)


@example('friction_particle_incline', ['x', 'y', 'z'], particle_incline_state,
         kinds={'plane': 'holonomic', 'P_slip1': 'integrable', 'P_slip2': 'integrable'},
         dof=(0, 0))
def _(q, v, t, p, label=None):
    # Byerly Art. 5c (seed-byerly.md TC03): at rest on the plane the normal force is
    # R = m g cos(al) and friction holds the particle with m g sin(al) up the slope; P_slip1
    # is the velocity up the slope, -(cos(al) x' - sin(al) z'), P_slip2 = -y' across it.
    m, g, al = p['m'], p['g'], p['al']
    return dict(acc=[0.0, 0.0, 0.0],
                mult={'plane': m * g * cos(al), 'P_slip1': m * g * sin(al), 'P_slip2': 0.0},
                grad={'plane': [sin(al), 0, cos(al)], 'P_slip1': [-cos(al), 0, sin(al)],
                      'P_slip2': [0, -1, 0]})




def read_parameters(path):
    """The defaults on the example's `parameters` lines: {name: value}."""
    params = {}
    with open(path) as fh:
        for line in fh:
            line = line.split('#', 1)[0].strip()
            if not line.startswith('parameters '):
                continue
            for item in line[len('parameters '):].split(','):
                name, value = item.split('=')
                # a value may use earlier parameters (mu = tan(al))
                scope = dict(params, sqrt=sqrt, pi=pi, sin=sin, cos=cos, tan=tan)
                params[name.strip()] = float(eval(value, scope))
    return params


def marked(path):
    with open(path) as fh:
        return any(line.strip() == MARKER for line in fh)


def run_qdot(qdot, path, state, sets):
    at = ', '.join('%s=%r' % kv for kv in state.items())
    cmd = [qdot, 'eom', path, '--at', at, '--format', 'json']
    for name, value in sets.items():
        cmd += ['--set', '%s=%r' % (name, value)]
    proc = subprocess.run(cmd, capture_output=True, text=True, timeout=120)
    if proc.returncode != 0:
        raise RuntimeError('exit %d: %s' % (proc.returncode, proc.stderr.strip()[:400]))
    return json.loads(proc.stdout), cmd


def flat(m):
    out = []
    for x in m:
        out.extend(flat(x) if isinstance(x, list) else [x])
    return out


def close(got, want, tol=REL_TOL):
    scale = max([1.0] + [abs(w) for w in want])
    return len(got) == len(want) and all(
        abs(g - w) <= tol * max(abs(w), 1e-300) or abs(g - w) <= tol * scale
        for g, w in zip(got, want))


def consistent(data, n):
    """M q'' = f + A^T lambda with qdot's own M, f, A."""
    acc = [float(a) for a in data['accelerations']]
    M = [float(x) for x in flat(data['mass_matrix'])]
    f = [float(x) for x in data['forcing']]
    rhs = list(f)
    for con in data.get('constraints', []):
        lam = float(data['multipliers'][con['name']])
        for j, a in enumerate(con['A']):
            rhs[j] += float(a) * lam
    Mq = [sum(M[i * n + j] * acc[j] for j in range(n)) for i in range(n)]
    if not close(Mq, rhs, 1e-8):
        return 'M q\'\' = %r but f + A^T lambda = %r' % (Mq, rhs)
    return None


def energy_rate(E, q, v, t, acc, p, coords):
    """dE/dt along the motion by central differences; also the sum of |terms| (its scale)."""
    total, scale = 0.0, 0.0
    for j, c in enumerate(coords):
        for var, rate in ((q, v[c]), (v, acc[j])):
            h = 1e-6 * max(1.0, abs(var[c]))
            old = var[c]
            var[c] = old + h
            ep = E(q, v, t, p)
            var[c] = old - h
            em = E(q, v, t, p)
            var[c] = old
            term = (ep - em) / (2 * h) * rate
            total += term
            scale += abs(term)
    h = 1e-6
    total += (E(q, v, t + h, p) - E(q, v, t - h, p)) / (2 * h)
    return total, scale


def check_one(qdot, path, spec, q, v, t, params, sets, label):
    state = dict(q)
    state.update({c + "'": x for c, x in v.items()})
    state['t'] = t
    data, cmd = run_qdot(qdot, path, state, sets)
    coords = spec['coords']
    if data.get('coordinates') != coords:
        return 'coordinates %r, expected %r' % (data.get('coordinates'), coords), cmd
    book = spec['book'](q, v, t, params, label)
    if 'accelerations' not in data:
        return 'no "accelerations" in the JSON output', cmd
    got = [float(a) for a in data['accelerations']]
    if not close(got, book['acc']):
        return 'accelerations %r, textbook %r' % (got, book['acc']), cmd
    if book['mult']:
        if 'multipliers' not in data or 'constraint_forces' not in data:
            return 'no "multipliers"/"constraint_forces" in the JSON output', cmd
        names = sorted(book['mult'])
        if sorted(data['multipliers']) != names:
            return 'multipliers %r, expected the constraints %r' % (
                sorted(data['multipliers']), names), cmd
        lam = [float(data['multipliers'][k]) for k in names]
        want = [book['mult'][k] for k in names]
        if not close(lam, want):
            return 'multipliers %r = %r, textbook %r' % (names, lam, want), cmd
        R = [float(data['constraint_forces'][c]) for c in coords]
        Rw = [sum(book['mult'][k] * book['grad'][k][j] for k in names)
              for j in range(len(coords))]
        if not close(R, Rw):
            return 'constraint forces %r, textbook %r' % (R, Rw), cmd
    err = consistent(data, len(coords))
    if err:
        return err, cmd
    if spec['energy']:
        rate, scale = energy_rate(spec['energy'], dict(q), dict(v), t, got, params, coords)
        want = spec['power'](q, v, t, params) if spec['power'] else 0.0
        if abs(rate - want) > ENERGY_TOL * max(1.0, scale):
            return 'dE/dt = %r from the accelerations, textbook %r' % (rate, want), cmd
    return None, cmd


def perturbed(defaults, rng):
    return {k: float('%.6g' % (x * rng.uniform(0.85, 1.15))) for k, x in defaults.items()}


def runs_of(spec, defaults, rng, nstates):
    """(label, sets) pairs: the defaults, perturbed values, the example's own sets."""
    runs = [(None, {})] * nstates + [(None, perturbed(defaults, rng))]
    runs += [(None, s) for s in spec['sets']]
    for label, gen in spec['special']:
        runs += [((label, gen), {})] * 2
    return runs


def check_example(qdot, path, name, spec, rng, nstates):
    defaults = read_parameters(path)
    passed, errors = 0, []
    for special, sets in runs_of(spec, defaults, rng, nstates):
        params = dict(defaults)
        params.update(sets)
        label = special[0] if special else None
        gen = special[1] if special else spec['state']
        try:
            q, v, t = gen(rng, params)
            err, cmd = check_one(qdot, path, spec, q, v, t, params, sets, label)
        except Exception as exc:     # a crash, bad JSON, a timeout
            err, cmd = '%s: %s' % (type(exc).__name__, exc), None
        if err:
            errors.append(('[%s] ' % label if label else '') + err +
                          ('\n  ' + ' '.join("'%s'" % c if ' ' in c else c for c in cmd)
                           if cmd else ''))
        else:
            passed += 1
    return passed, errors


def check_kinds(qdot, path, spec):
    """The constraint kinds qdot reports (qdot eom --format json) against the book's."""
    proc = subprocess.run([qdot, 'eom', path, '--format', 'json'], capture_output=True,
                          text=True, timeout=120)
    if proc.returncode != 0:
        return ['qdot eom: exit %d: %s' % (proc.returncode, proc.stderr.strip()[:300])]
    data = json.loads(proc.stdout)
    got = {c['name']: c.get('kind') for c in data.get('constraints', [])}
    if got != spec['kinds']:
        return ['constraint kinds %r, textbook %r' % (got, spec['kinds'])]
    return []


def check_dof(qdot, path, spec):
    """qdot check's configurational and motional degrees of freedom."""
    proc = subprocess.run([qdot, 'check', path], capture_output=True, text=True, timeout=120)
    if proc.returncode != 0:
        return ['qdot check: exit %d: %s' % (proc.returncode, proc.stderr.strip()[:300])]
    found = []
    for word in ('configurational', 'motional'):
        # "2 configurational" or "configurational: 2"
        m = (re.search(r'(\d+)\s+' + word, proc.stdout, re.IGNORECASE) or
             re.search(r'\b' + word + r'[\s:=]*(\d+)', proc.stdout, re.IGNORECASE))
        found.append(int(m.group(1)) if m else None)
    if tuple(found) != spec['dof']:
        return ['qdot check: degrees of freedom (configurational, motional) %r, textbook %r'
                % (tuple(found), spec['dof'])]
    return []


def check_equivalent(qdot, path, name, spec, rng, nstates):
    """The rolls model and the hand-written one (EQUIVALENT) at the same states: the same
    accelerations, multipliers (by the renaming) and constraint forces."""
    other, names = EQUIVALENT[name]
    other_path = os.path.join(os.path.dirname(path), other + '.qd')
    defaults = read_parameters(path)
    passed, errors = 0, []
    for _, sets in runs_of(spec, defaults, rng, nstates):
        params = dict(defaults)
        params.update(sets)
        q, v, t = spec['state'](rng, params)
        state = dict(q)
        state.update({c + "'": x for c, x in v.items()})
        state['t'] = t
        try:
            mine, cmd = run_qdot(qdot, path, state, sets)
            theirs, _ = run_qdot(qdot, other_path, state, sets)
        except Exception as exc:
            errors.append('%s: %s' % (type(exc).__name__, exc))
            continue
        got = [float(x) for x in mine['accelerations']]
        want = [float(x) for x in theirs['accelerations']]
        lam = [float(mine['multipliers'][k]) for k in sorted(names)]
        lam_want = [float(theirs['multipliers'][names[k]]) for k in sorted(names)]
        R = [float(mine['constraint_forces'][c]) for c in spec['coords']]
        R_want = [float(theirs['constraint_forces'][c]) for c in spec['coords']]
        if not (close(got, want) and close(lam, lam_want) and close(R, R_want)):
            errors.append('differs from %s.qd: accelerations %r vs %r, multipliers %r vs %r\n  %s'
                          % (other, got, want, lam, lam_want, ' '.join(cmd)))
        else:
            passed += 1
    return passed, errors


def aspects(qdot, path, name, spec, rng, nstates):
    """(key, passed, errors) for the equations, the constraint kinds, the counts."""
    ok, errors = check_example(qdot, path, name, spec, rng, nstates)
    out = [(name, ok, errors)]
    if name in EQUIVALENT:
        out.append(('%s:equivalent' % name,) + check_equivalent(qdot, path, name, spec, rng,
                                                                 nstates))
    for key, fn, want in (('kinds', check_kinds, spec['kinds']),
                          ('dof', check_dof, spec['dof'])):
        if want is None:
            continue
        try:
            errs = fn(qdot, path, spec)
        except Exception as exc:
            errs = ['%s: %s' % (type(exc).__name__, exc)]
        out.append(('%s:%s' % (name, key), 0 if errs else 1, errs))
    return out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--build', required=True)
    ap.add_argument('--examples', required=True)
    ap.add_argument('--states', type=int, default=STATES)
    ap.add_argument('--seed', type=int, default=SEED)
    ap.add_argument('--only', help='comma-separated example names')
    args = ap.parse_args()
    qdot = os.path.join(args.build, 'qdot')
    rng = random.Random(args.seed)
    files = sorted(f[:-3] for f in os.listdir(args.examples)
                   if f.endswith('.qd') and marked(os.path.join(args.examples, f)))
    if args.only:
        files = [f for f in files if f in args.only.split(',')]
    passed = failed = 0
    xfailed = []
    for name in files:
        path = os.path.join(args.examples, name + '.qd')
        spec = EXAMPLES.get(name)
        if spec is None:
            print('FAIL %s: no textbook formula in check_constrained.py' % name)
            failed += 1
            continue
        bad = []
        for key, ok, errors in aspects(qdot, path, name, spec, rng, args.states):
            why = EXPECTED_TO_FAIL.get(key)
            if why and errors:
                xfailed.append(key)
                print('XFAIL %s: expected to fail until %s (%d checks failed; first: %s)'
                      % (key, why, len(errors), errors[0].splitlines()[0][:240]))
                continue
            if why:
                print('XPASS %s: passes although expected to fail until %s: remove it from '
                      'EXPECTED_TO_FAIL' % (key, why))
            for err in errors:
                print('FAIL %s: %s' % (key, err))
            passed += ok
            failed += len(errors)
            bad += [key] if errors else []
        xf = [k for k in xfailed if k == name or k.startswith(name + ':')]
        print('%-28s %s%s' % (name, 'checked' if not bad else 'FAILED: ' + ', '.join(bad),
                              ' (expected to fail: %s)' % ', '.join(xf) if xf else ''))
    for name in EXAMPLES:
        if name not in files and not args.only:
            print('FAIL %s: examples/%s.qd is missing or not marked' % (name, name))
            failed += 1
    extra = ''
    if xfailed:
        extra = ', %d expected to fail (not counted): %s' % (len(xfailed), ', '.join(xfailed))
    print('%d passed, %d failed%s' % (passed, failed, extra))
    return 1 if failed else 0


if __name__ == '__main__':
    sys.exit(main())

#!/usr/bin/env python3
"""Check every model in examples/ against its textbook equations of motion.

For each example, at several random states (fixed seed) run

    qdot eom FILE --at "q=..., q'=..., t=..." --format json

and compare the accelerations qdot reports with the textbook formula for the
accelerations, written out below with the math module, one function per
example (each cites its seed, chapter and equation; the reference notes are
in /work/shared/reference/).  The formulas are independent of qdot: they are
the books' results, not something derived from qdot's output.  Parameters take
the example's defaults (read from its `parameters` line), and once more values
given with --set.

Usage: check_examples.py --build BUILD_DIR --examples EXAMPLES_DIR
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

from math import sin, cos, sqrt, pi

REL_TOL = 1e-9
STATES = 5
SEED = 20260503

EXAMPLES = {}


def example(name, coords, ranges=None, vel=1.5, t=(0.0, 3.0)):
    """Register the textbook accelerations of examples/NAME.qd.

    ranges maps a coordinate to the interval its random values come from
    (default [-1.5, 1.5]); velocities come from [-vel, vel], t from t."""
    def wrap(fn):
        EXAMPLES[name] = dict(coords=coords, ranges=ranges or {}, vel=vel, t=t, acc=fn)
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


# ---------------------------------------------------------------------------
# The textbook formulas.  Each gets q (coordinates), v (velocities), t and p
# (parameters), all by name, and returns the accelerations in coordinate order.

@example('double_pendulum', ['theta1', 'theta2'])
def _(q, v, t, p):
    # Goldstein ch. 1 Exercise 22; reference seed-goldstein-britannica.md G13:
    # (m1+m2) l1 th1'' + m2 l2 th2'' cos(d) + m2 l2 th2'^2 sin(d) + (m1+m2) g sin th1 = 0
    # l2 th2'' + l1 th1'' cos(d) - l1 th1'^2 sin(d) + g sin th2 = 0,  d = th1 - th2
    m1, m2, l1, l2, g = p['m1'], p['m2'], p['l1'], p['l2'], p['g']
    th1, th2, w1, w2 = q['theta1'], q['theta2'], v['theta1'], v['theta2']
    d = th1 - th2
    M = [[(m1 + m2) * l1, m2 * l2 * cos(d)], [l1 * cos(d), l2]]
    f = [-m2 * l2 * w2**2 * sin(d) - (m1 + m2) * g * sin(th1),
         l1 * w1**2 * sin(d) - g * sin(th2)]
    return solve(M, f)


# The calculus of variations (`independent x`; Desloge vol. 2, App. 32,
# seed-desloge-D.md): t below is the model's independent variable.
@example('catenary', ['y'], ranges={'y': (0.5, 2.0)})
def _(q, v, t, p):
    # App. 32 Thm 5, the hanging chain: (w y - lambda) y'' = w (1 + y'^2); a
    # numeric eom takes the multiplier lambda_length (not a parameter) as 0
    lam = 0.0
    return [p['w'] * (1 + v['y']**2) / (p['w'] * q['y'] - lam)]


@example('brachistochrone', ['y'], ranges={'y': (0.2, 2.0)})
def _(q, v, t, p):
    # App. 32 Ex. 2 (T35): 2 y y'' + 1 + y'^2 = 0, whatever g
    return [-(1 + v['y']**2) / (2 * q['y'])]


@example('routh_implicit', ['x', 'y'], ranges={'y': (-1.5, 1.5)})
def _(q, v, t, p):
    # made up (issue 17, the implicit Routhian; no book): Lagrange's equations
    # of L = cosh(x') + y'^2/2 + x' y' y/2 - y^2 written out by hand,
    # cosh(x') x'' + (y/2) y'' = -y'^2/2 and (y/2) x'' + y'' = -2 y
    y, xd, yd = q['y'], v['x'], v['y']
    return solve([[math.cosh(xd), y / 2], [y / 2, 1.0]], [-yd**2 / 2, -2 * y])


@example('sphere_geodesic', ['phi'], t=(0.3, 2.8))
def _(q, v, t, p):
    # App. 32 Thm 3 Case 1 (phi absent): sin^2 th phi'/sqrt(1 + sin^2 th phi'^2)
    # is constant; its derivative gives phi'' = -cos th phi' (2 + sin^2 th phi'^2)/sin th
    s, P = sin(t), v['phi']
    return [-cos(t) * P * (2 + s * s * P * P) / s]


# The action-angle examples (qdot action; Desloge ch. 79, seed-desloge-D.md).
@example('action_pendulum', ['theta'])
def _(q, v, t, p):
    # Goldstein ch. 1 Ex. 19 (seed 002): th'' = -(g/l) sin th
    return [-p['g'] / p['l'] * sin(q['theta'])]


@example('action_pendulum_rotation', ['theta'])
def _(q, v, t, p):
    return [-p['g'] / p['l'] * sin(q['theta'])]


@example('action_anisotropic', ['x', 'y'])
def _(q, v, t, p):
    # Goldstein sec. 10.6: x'' = -kx x/m, y'' = -ky y/m
    return [-p['kx'] * q['x'] / p['m'], -p['ky'] * q['y'] / p['m']]


@example('action_pendulum_lengthening', ['theta'])
def _(q, v, t, p):
    # Goldstein sec. 10.7: d/dt(m l^2 th') = -m g l sin th, l = l0 (1 + eps t)
    l, ld = p['l0'] * (1 + p['eps'] * t), p['l0'] * p['eps']
    return [-2 * ld / l * v['theta'] - p['g'] / l * sin(q['theta'])]


@example('free_particle_spherical', ['r', 'theta', 'phi'],
         ranges={'r': (0.5, 2.0), 'theta': (0.3, 2.8)})
def _(q, v, t, p):
    # Desloge ch. 48 Ex. 1; Byerly Art. 15a; seed-byerly.md TC01 with no force:
    # r'' = r (th'^2 + sin^2 th ph'^2); (1/r) d/dt(r^2 th') = r sin th cos th ph'^2;
    # d/dt(r^2 sin^2 th ph') = 0
    r, th = q['r'], q['theta']
    rd, thd, phd = v['r'], v['theta'], v['phi']
    return [r * (thd**2 + sin(th)**2 * phd**2),
            sin(th) * cos(th) * phd**2 - 2 * rd * thd / r,
            -2 * rd * phd / r - 2 * cos(th) / sin(th) * thd * phd]


@example('atwood', ['x'])
def _(q, v, t, p):
    # Goldstein sec. 1.6 example 2: (M1 + M2) x'' = (M1 - M2) g
    return [(p['M1'] - p['M2']) / (p['M1'] + p['M2']) * p['g']]


@example('compound_atwood', ['x', 'y'])
def _(q, v, t, p):
    # Byerly Art. 8b, p. 19; seed-byerly.md TC11: x'' = g/23, y'' = 8 g/23
    return [p['g'] / 23, 8 * p['g'] / 23]


@example('bouncing_ball', ['y'], ranges={'y': (0.0, 2.0)})
def _(q, v, t, p):
    # between impacts a free fall (Desloge ch. 61 for the impacts): y'' = -g
    return [-p['g']]


@example('grazing_disc', ['x', 'y'], ranges={'x': (1.5, 3.0)})
def _(q, v, t, p):
    # between impacts a free particle (Newton's first law): x'' = y'' = 0
    return [0.0, 0.0]


@example('pendulum_wall', ['th'], ranges={'th': (0.0, 1.5)})
def _(q, v, t, p):
    # between impacts the pendulum, Goldstein sec. 1.6: th'' = -(g/l) sin th
    return [-p['g'] / p['l'] * sin(q['th'])]


@example('rhombus_wall', ['x', 'th'], ranges={'x': (1.0, 3.0), 'th': (0.2, 1.3)})
def _(q, v, t, p):
    # Desloge ch. 57 ex. 1 (T55): T = 2 m x'^2 + (8/3) m a^2 th'^2, no forces
    return [0.0, 0.0]


@example('rod_ledge', ['x', 'y', 'th'])
def _(q, v, t, p):
    # a free rod under gravity between impacts: x'' = 0, y'' = -g, th'' = 0
    return [0.0, -p['g'], 0.0]


@example('bead_rotating_wire', ['r'], ranges={'r': (0.1, 2.0)})
def _(q, v, t, p):
    # Goldstein sec. 1.6 example 3 (G03, pitfall P2): r'' = omega^2 r
    return [p['omega']**2 * q['r']]


@example('bead_spinning_hoop', ['theta'])
def _(q, v, t, p):
    # Desloge ch. 50 Ex. 1 eq. 39: th'' - w^2 sin th cos th + (g/a) sin th = 0
    th = q['theta']
    return [p['omega']**2 * sin(th) * cos(th) - p['g'] / p['a'] * sin(th)]


@example('power_law_orbit', ['r', 'theta'], ranges={'r': (0.3, 2.0)})
def _(q, v, t, p):
    # Britannica sec. 5-6 (reference B08); Desloge ch. 59 eq. 1:
    # m r'' - m r th'^2 = -k r^n,  d/dt(m r^2 th') = 0
    r, rd, thd = q['r'], v['r'], v['theta']
    return [r * thd**2 - p['k'] / p['m'] * r**p['n'], -2 * rd * thd / r]


def lorentz(q, v, p):
    # Goldstein eqs. 1.60-1.66; Desloge ch. 53 Ex. 1 (T35): m r'' = q (E + v x B)
    vx, vy, vz = v['x'], v['y'], v['z']
    Bx, By, Bz = p['Bx'], p['By'], p['Bz']
    k = p['q'] / p['m']
    return [k * (p['Ex'] + vy * Bz - vz * By),
            k * (p['Ey'] + vz * Bx - vx * Bz),
            k * (p['Ez'] + vx * By - vy * Bx)]


@example('charged_particle_EB', ['x', 'y', 'z'])
def _(q, v, t, p):
    return lorentz(q, v, p)


@example('charged_particle_gauge', ['x', 'y', 'z'])
def _(q, v, t, p):
    # Goldstein Derivation 9 (G05): a gauge transformation leaves the Lorentz force
    return lorentz(q, v, p)


@example('rotating_frame', ['x', 'y'])
def _(q, v, t, p):
    # Byerly Art. 6 Ex. 2 (TC09); Britannica sec. 3 eqs. 9-15 (B05):
    # m (x'' - 2 w y' - w^2 x) = -mu (x - a),  m (y'' + 2 w x' - w^2 y) = -mu y
    w, mu, m, a = p['w'], p['mu'], p['m'], p['a']
    x, y, xd, yd = q['x'], q['y'], v['x'], v['y']
    return [2 * w * yd + w**2 * x - mu / m * (x - a),
            -2 * w * xd + w**2 * y - mu / m * y]


@example('damped_pendulum', ['theta'])
def _(q, v, t, p):
    # Goldstein eqs. 1.67-1.70: m l^2 th'' + k l^2 th' + m g l sin th = 0
    return [-p['g'] / p['l'] * sin(q['theta']) - p['k'] / p['m'] * v['theta']]


@example('spring_pendulum', ['r', 'theta'], ranges={'r': (0.5, 2.0)})
def _(q, v, t, p):
    # Goldstein ch. 1 Exercise 24:
    # m r'' = m r th'^2 + m g cos th - k (r - l0);  r th'' + 2 r' th' + g sin th = 0
    r, th, rd, thd = q['r'], q['theta'], v['r'], v['theta']
    g = p['g']
    return [r * thd**2 + g * cos(th) - p['k'] / p['m'] * (r - p['l0']),
            -(2 * rd * thd + g * sin(th)) / r]


@example('two_particles_interaction', ['x1', 'y1', 'x2', 'y2'],
         ranges={'x1': (-1.5, -0.3), 'x2': (0.3, 1.5)})
def _(q, v, t, p):
    # Goldstein eq. 1.36, Desloge ch. 47 P2 (T03): pair force along r1 - r2,
    # V12 = k/2 (rho - d)^2, V12' = k (rho - d); gravity -g on each
    dx, dy = q['x1'] - q['x2'], q['y1'] - q['y2']
    rho = math.hypot(dx, dy)
    f = p['k'] * (rho - p['d']) / rho          # force on 1 is -f (r1 - r2)
    m1, m2, g = p['m1'], p['m2'], p['g']
    return [-f * dx / m1, -g - f * dy / m1, f * dx / m2, -g + f * dy / m2]


@example('driven_pendulum_vertical', ['theta'])
def _(q, v, t, p):
    # Desloge ch. 54 P1 method (T39) with the support at (0, a cos wt):
    # b th'' + (g - a w^2 cos wt) sin th = 0
    a, w, b, g = p['a'], p['w'], p['b'], p['g']
    return [-(g - a * w**2 * cos(w * t)) * sin(q['theta']) / b]


@example('pendulum_support_circle', ['theta'])
def _(q, v, t, p):
    # Desloge ch. 54 P1 (T39): b th'' + g sin th - a w^2 cos(th - w t) = 0
    a, w, b, g = p['a'], p['w'], p['b'], p['g']
    th = q['theta']
    return [(a * w**2 * cos(th - w * t) - g * sin(th)) / b]


@example('total_derivative_potential', ['x', 'y'])
def _(q, v, t, p):
    # Desloge ch. 54 eqs. 5-9, P7 (T45): a total time derivative in U exerts no
    # force, so m x'' = -K x, m y'' = -K y (the free oscillator)
    k = p['K'] / p['m']
    return [-k * q['x'], -k * q['y']]


@example('cylindrical_force', ['rho', 'ph', 'z'], ranges={'rho': (0.3, 2.0)})
def _(q, v, t, p):
    # Desloge ch. 48 P1 (T05):  m (rho'' - rho ph'^2) = F_rho,
    # m (rho ph'' + 2 rho' ph') = F_ph,  m z'' = Fz
    rho, ph, rhod, phd = q['rho'], q['ph'], v['rho'], v['ph']
    m = p['m']
    Frho = p['Fx'] * cos(ph) + p['Fy'] * sin(ph)
    Fph = -p['Fx'] * sin(ph) + p['Fy'] * cos(ph)
    return [rho * phd**2 + Frho / m, (Fph / m - 2 * rhod * phd) / rho, p['Fz'] / m]


@example('polar_generalized_force', ['r', 'theta'], ranges={'r': (0.3, 2.0)})
def _(q, v, t, p):
    # Goldstein sec. 1.6 example 1(b) (G01): m r'' - m r th'^2 = F_r,
    # m r^2 th'' + 2 m r r' th' = r F_th
    r, rd, thd, m = q['r'], v['r'], v['theta'], p['m']
    return [r * thd**2 + p['Fr'] / m, (p['Fth'] / m - 2 * rd * thd) / r]


@example('paraboloid', ['rho', 'ph'], ranges={'rho': (0.2, 2.0)})
def _(q, v, t, p):
    # Desloge ch. 72 P2 (C T19), z = c rho^2:
    # (1 + 4c^2 rho^2) rho'' + 4 c^2 rho rho'^2 - rho ph'^2 + 2 g c rho = 0;  d/dt(rho^2 ph') = 0
    rho, rhod, phd = q['rho'], v['rho'], v['ph']
    c, g = p['c'], p['g']
    return [(rho * phd**2 - 4 * c**2 * rho * rhod**2 - 2 * g * c * rho) / (1 + 4 * c**2 * rho**2),
            -2 * rhod * phd / rho]


@example('spherical_pendulum', ['theta', 'phi'], ranges={'theta': (0.3, 2.8)})
def _(q, v, t, p):
    # Byerly Art. 5 Ex. 3 (TC05): th'' - sin th cos th ph'^2 + (g/a) sin th = 0,
    # sin^2 th ph' = C
    th, thd, phd = q['theta'], v['theta'], v['phi']
    return [sin(th) * cos(th) * phd**2 - p['g'] / p['a'] * sin(th),
            -2 * cos(th) / sin(th) * thd * phd]


@example('torus', ['th', 'phi'])
def _(q, v, t, p):
    # A bead on a torus (derived in the model's header): from T = (m/2)(a^2 th'^2 + rho^2 phi'^2),
    # rho = R + a cos th: m a^2 th'' = -m a rho sin th phi'^2,
    # d/dt(m rho^2 phi') = 0  =>  phi'' = 2 a sin th th' phi'/rho
    R, a = p['R'], p['a']
    th, thd, phd = q['th'], v['th'], v['phi']
    rho = R + a * cos(th)
    return [-rho * sin(th) * phd**2 / a, 2 * a * sin(th) * thd * phd / rho]


@example('kepler_polar', ['r', 'theta'], ranges={'r': (0.3, 3.0)})
def _(q, v, t, p):
    # Desloge ch. 58-59 (B T13): m (r'' - r th'^2) = -k/r^2;  d/dt(m r^2 th') = 0
    r, rd, thd = q['r'], v['r'], v['theta']
    return [r * thd**2 - p['k'] / (p['m'] * r**2), -2 * rd * thd / r]


@example('inverse_cube_orbit', ['r', 'phi'], ranges={'r': (0.3, 3.0)})
def _(q, v, t, p):
    # Desloge ch. 58 P9 (B T09): m (r'' - r phi'^2) = -(h0^2/m)(2/(a r^2) + 1/r^3);
    # d/dt(m r^2 phi') = 0
    r, rd, phd = q['r'], v['r'], v['phi']
    m, h0 = p['m'], p['h0']
    F = -(h0**2 / m) * (2 / (p['a'] * r**2) + 1 / r**3)
    return [r * phd**2 + F / m, -2 * rd * phd / r]


@example('r4_potential', ['r', 'phi'], ranges={'r': (0.3, 3.0)})
def _(q, v, t, p):
    # Desloge ch. 58 (B C3): V = -a/(4 r^4), m (r'' - r phi'^2) = -a/r^5;
    # d/dt(m r^2 phi') = 0
    r, rd, phd = q['r'], v['r'], v['phi']
    return [r * phd**2 - p['a'] / (p['m'] * r**5), -2 * rd * phd / r]


def central(r, rd, phd, m, dV):
    # Desloge ch. 58 eq. 1-3: m (r'' - r phi'^2) = -V'(r), d/dt(m r^2 phi') = 0
    return [r * phd**2 - dV / m, -2 * rd * phd / r]


@example('rutherford', ['r', 'phi'], ranges={'r': (0.3, 3.0)})
def _(q, v, t, p):
    # Desloge ch. 60 ex. 2 (B C4, T15): V = k/r, a repulsive inverse square
    return central(q['r'], v['r'], v['phi'], p['m'], -p['k'] / q['r']**2)


@example('hard_sphere', ['r', 'phi'], ranges={'r': (1.6, 3.0)})
def _(q, v, t, p):
    # Desloge ch. 60 ex. 1: free motion outside the sphere (the wall is scatter's --core)
    return central(q['r'], v['r'], v['phi'], p['m'], 0.0)


@example('refracting_sphere', ['r', 'phi'], ranges={'r': (0.3, 1.8)})
def _(q, v, t, p):
    # Desloge ch. 60 problems; Landau sec. 18 pb. 2: V = -V0 step(a - r) exerts no
    # force away from r = a (the jump is an impulse, handled by qdot scatter)
    return central(q['r'], v['r'], v['phi'], p['m'], 0.0)


@example('gaussian_well', ['r', 'phi'], ranges={'r': (0.3, 3.0)})
def _(q, v, t, p):
    # Desloge ch. 60 (B C4): V = -V0 exp(-r^2/s^2), V' = 2 V0 r/s^2 exp(-r^2/s^2)
    r = q['r']
    dV = 2 * p['V0'] * r / p['s']**2 * math.exp(-r**2 / p['s']**2)
    return central(r, v['r'], v['phi'], p['m'], dV)


@example('lennard_jones', ['r', 'phi'], ranges={'r': (0.8, 3.0)})
def _(q, v, t, p):
    # Desloge ch. 60 (B C4, pitfalls 5-6): V = 4 eps ((s/r)^12 - (s/r)^6)
    r, s_ = q['r'], p['s']
    dV = 4 * p['eps'] * (-12 * s_**12 / r**13 + 6 * s_**6 / r**7)
    return central(r, v['r'], v['phi'], p['m'], dV)

@example('table_hanging_mass', ['r', 'theta'], ranges={'r': (0.3, 1.8)})
def _(q, v, t, p):
    # Goldstein ch. 1 Exercise 21 (G11): (m1 + m2) r'' - m1 r th'^2 + m2 g = 0;
    # d/dt(m1 r^2 th') = 0
    r, rd, thd = q['r'], v['r'], v['theta']
    m1, m2 = p['m1'], p['m2']
    return [(m1 * r * thd**2 - m2 * p['g']) / (m1 + m2), -2 * rd * thd / r]


@example('sphere_on_wedge', ['x', 'y'])
def _(q, v, t, p):
    # Byerly Art. 9 Ex. 3 (TC19):
    # y'' = a^2 (M+m) g sin al / ((M+m)(a^2+k^2) - m a^2 cos^2 al), (M+m) x'' = m y'' cos al
    M, m, a, k, al, g = p['M'], p['m'], p['a'], p['kg'], p['alpha'], p['g']
    ydd = a**2 * (M + m) * g * sin(al) / ((M + m) * (a**2 + k**2) - m * a**2 * cos(al)**2)
    return [m * ydd * cos(al) / (M + m), ydd]


@example('spring_supported_pendulum', ['y', 'theta'])
def _(q, v, t, p):
    # Desloge ch. 53 P2 (T37):
    # m (y'' - b th'' sin th - b th'^2 cos th) + k y + c (y' - b th' sin th) = 0
    # m b^2 th'' - m b y'' sin th + m g b sin th + c (b^2 th' - b y' sin th) = 0
    m, b, k, c, g = p['m'], p['b'], p['k'], p['c'], p['g']
    y, th, yd, thd = q['y'], q['theta'], v['y'], v['theta']
    s, co = sin(th), cos(th)
    M = [[m, -m * b * s], [-m * b * s, m * b**2]]
    f = [m * b * thd**2 * co - k * y - c * (yd - b * thd * s),
         -m * g * b * s - c * (b**2 * thd - b * yd * s)]
    return solve(M, f)


@example('double_pendulum_force', ['theta1', 'theta2'])
def _(q, v, t, p):
    # Goldstein Exercise 22 (G13) with Desloge ch. 50 P1 (T13):
    # Q_th1 = F l1 cos th1, Q_th2 = F l2 cos th2
    m1, m2, l1, l2, g, F = p['m1'], p['m2'], p['l1'], p['l2'], p['g'], p['F']
    th1, th2, w1, w2 = q['theta1'], q['theta2'], v['theta1'], v['theta2']
    d = th1 - th2
    M = [[(m1 + m2) * l1**2, m2 * l1 * l2 * cos(d)], [m2 * l1 * l2 * cos(d), m2 * l2**2]]
    f = [-m2 * l1 * l2 * w2**2 * sin(d) - (m1 + m2) * g * l1 * sin(th1) + F * l1 * cos(th1),
         m2 * l1 * l2 * w1**2 * sin(d) - m2 * g * l2 * sin(th2) + F * l2 * cos(th2)]
    return solve(M, f)


@example('tethered_spinning_disk', ['theta'])
def _(q, v, t, p):
    # Desloge ch. 50 P5 (T17): th'' + (b w^2/a) sin th = 0
    return [-p['b'] * p['w']**2 / p['a'] * sin(q['theta'])]


@example('bead_helix', ['ph'])
def _(q, v, t, p):
    # Desloge ch. 51 Ex. 1 (T15), gravity along -z: (a^2 + b^2) ph'' = -g b
    a, b = p['a'], p['b']
    return [-p['g'] * b / (a**2 + b**2)]


# ---------------------------------------------------------------------------



# Desloge ch. 71 Problems 1-10 (seed 000, pp. 741-743; reference seed-desloge-C.md T7, T9,
# T11, T13, T15): the accelerations from each problem's own Lagrangian, written out by hand.

@example('desloge71_p1', ['rho', 'phi', 'z'], ranges={'rho': (0.3, 2.0)})
def _(q, v, t, p):
    # T7: rho'' = rho phi'^2 + 2 a rho phi';  d/dt(rho^2 phi' + a rho^2) = 0;  z'' = 0
    rho, rd, pd, a = q['rho'], v['rho'], v['phi'], p['a']
    return [rho * pd**2 + 2 * a * rho * pd, -2 * rd * (pd + a) / rho, 0.0]


@example('desloge71_p2', ['r', 'phi'], ranges={'r': (0.3, 2.0)})
def _(q, v, t, p):
    # P2, unit mass, V = k cos(phi)/r^2: r'' = r phi'^2 + 2k cos(phi)/r^3,
    # d/dt(r^2 phi') = k sin(phi)/r^2
    r, ph, rd, pd, k = q['r'], q['phi'], v['r'], v['phi'], p['k']
    return [r * pd**2 + 2 * k * cos(ph) / r**3, (k * sin(ph) / r**2 - 2 * r * rd * pd) / r**2]


@example('desloge71_p3', ['r', 'phi'], ranges={'r': (0.3, 2.0)})
def _(q, v, t, p):
    # T9, V = 2 lam r - mu^2/(2 r^2): r'' = r phi'^2 - 2 lam - mu^2/r^3;  d/dt(r^2 phi') = 0
    r, rd, pd = q['r'], v['r'], v['phi']
    return [r * pd**2 - 2 * p['lam'] - p['mu']**2 / r**3, -2 * rd * pd / r]


def _spherical(r, th, rd, thd, phd, mass, k):
    """m (r'' - r th'^2 - r sin^2 th ph'^2) = -k/r^2, d/dt(m r^2 th') = m r^2 sin cos ph'^2,
    d/dt(m r^2 sin^2 th ph') = 0."""
    return [r * thd**2 + r * sin(th)**2 * phd**2 - k / (mass * r**2),
            sin(th) * cos(th) * phd**2 - 2 * rd * thd / r,
            -2 * rd * phd / r - 2 * cos(th) / sin(th) * thd * phd]


@example('desloge71_p4', ['r', 'theta', 'phi'], ranges={'r': (0.3, 2.0), 'theta': (0.3, 2.8)})
def _(q, v, t, p):
    # P4 with V(r) = -k/r
    return _spherical(q['r'], q['theta'], v['r'], v['theta'], v['phi'], p['m'], p['k'])


@example('desloge71_p5', ['X', 'Y', 'Z', 'r', 'theta', 'phi'],
         ranges={'r': (0.3, 2.0), 'theta': (0.3, 2.8)})
def _(q, v, t, p):
    # T11: the centre of mass moves uniformly; r, theta, phi as one body of mass
    # mu = m M/(m + M) in V(r) = -k/r
    mu = p['m'] * p['M'] / (p['m'] + p['M'])
    return [0.0, 0.0, 0.0] + _spherical(q['r'], q['theta'], v['r'], v['theta'], v['phi'], mu,
                                        p['k'])


@example('desloge71_p6', ['theta'], t=(0.0, 3.0))
def _(q, v, t, p):
    # P6, l = l0 - a t: d/dt(m l^2 th') = -m g l sin th, so th'' = (2 a th' - g sin th)/l
    l = p['l0'] - p['a'] * t
    return [(2 * p['a'] * v['theta'] - p['g'] * sin(q['theta'])) / l]


@example('desloge71_p7', ['theta', 'phi'], ranges={'theta': (0.3, 2.8)})
def _(q, v, t, p):
    # T13 with R = R0 + c t: th'' = sin cos ph'^2 + g sin th/R - 2 R' th'/R,
    # d/dt(R^2 sin^2 th ph') = 0
    R, c, th, thd, phd = p['R0'] + p['c'] * t, p['c'], q['theta'], v['theta'], v['phi']
    return [sin(th) * cos(th) * phd**2 + p['g'] * sin(th) / R - 2 * c * thd / R,
            -2 * c * phd / R - 2 * cos(th) / sin(th) * thd * phd]


@example('desloge71_p8', ['x'], ranges={'x': (0.3, 2.0)})
def _(q, v, t, p):
    # P8: m x'' = (k/x^2) exp(-t/tau)
    return [p['k'] / q['x']**2 * math.exp(-t / p['tau']) / p['m']]


@example('desloge71_p9', ['r', 'theta'], ranges={'r': (2.5, 4.0)})
def _(q, v, t, p):
    # T15, U = (1 + r'^2)/r: (1 - 2/r) r'' = r th'^2 + (1 - r'^2)/r^2;  d/dt(r^2 th') = 0
    r, rd, thd = q['r'], v['r'], v['theta']
    return [(r * thd**2 + (1 - rd**2) / r**2) / (1 - 2 / r), -2 * rd * thd / r]


@example('desloge71_p10', ['x1', 'x2', 'x3'])
def _(q, v, t, p):
    # P10, earth turning at w about e3: x'' = -2 w e3 x x' - w e3 x (w e3 x r) - g e3
    w = p['w']
    return [2 * w * v['x2'] + w**2 * q['x1'], -2 * w * v['x1'] + w**2 * q['x2'], -p['g']]


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
                params[name.strip()] = float(eval(value, {'sqrt': sqrt, 'pi': pi}))
    return params


def constrained(path):
    """Does the model's header say `# checked by check_<x>`: another test
    checks it (constrained systems, steady motions, ...)?"""
    with open(path) as fh:
        return any(line.strip().startswith('# checked by check_') for line in fh)


def run_qdot(qdot, path, state, sets):
    at = ', '.join('%s=%r' % kv for kv in state.items())
    cmd = [qdot, 'eom', path, '--at', at, '--format', 'json']
    for name, value in sets.items():
        cmd += ['--set', '%s=%r' % (name, value)]
    proc = subprocess.run(cmd, capture_output=True, text=True, timeout=60)
    if proc.returncode != 0:
        raise RuntimeError('exit %d: %s' % (proc.returncode, proc.stderr.strip()[:400]))
    return json.loads(proc.stdout), cmd


def flat(m):
    out = []
    for x in m:
        out.extend(flat(x) if isinstance(x, list) else [x])
    return out


def qdot_accelerations(data, n):
    if 'accelerations' not in data:
        raise KeyError('no "accelerations" in the JSON output')
    acc = [float(a) for a in data['accelerations']]
    # M q'' = f must hold too, with the M and f printed beside q''.
    M = [float(x) for x in flat(data['mass_matrix'])]
    f = [float(x) for x in data['forcing']]
    Mq = [sum(M[i * n + j] * acc[j] for j in range(n)) for i in range(n)]
    if not close(Mq, f):
        raise ValueError('M q\'\' = %r but f = %r' % (Mq, f))
    return acc


def close(got, want):
    scale = max([1.0] + [abs(w) for w in want])
    return len(got) == len(want) and all(
        abs(g - w) <= REL_TOL * max(abs(w), 1e-300) or abs(g - w) <= REL_TOL * scale
        for g, w in zip(got, want))


def check_one(qdot, path, spec, rng, sets, defaults):
    params = dict(defaults)
    params.update(sets)
    q = {c: rng.uniform(*spec['ranges'].get(c, (-1.5, 1.5))) for c in spec['coords']}
    v = {c: rng.uniform(-spec['vel'], spec['vel']) for c in spec['coords']}
    t = rng.uniform(*spec['t'])
    state = dict(q)
    state.update({c + "'": x for c, x in v.items()})
    state['t'] = t
    data, cmd = run_qdot(qdot, path, state, sets)
    if data.get('coordinates') != spec['coords']:
        return 'coordinates %r, expected %r' % (data.get('coordinates'), spec['coords']), cmd
    want = spec['acc'](q, v, t, params)
    got = qdot_accelerations(data, len(spec['coords']))
    if not close(got, want):
        return 'accelerations %r, textbook %r' % (got, want), cmd
    return None, cmd


def perturbed(defaults, rng):
    return {k: float('%.6g' % (x * rng.uniform(0.6, 1.4))) for k, x in defaults.items()}


@example('damped_oscillator', ['x'])
def _(q, v, t, p):
    # Goldstein sec. 1.5, eqs. 1.67-1.70: m x'' + b x' + k x = 0
    return [-(p['k'] * q['x'] + p['b'] * v['x']) / p['m']]


@example('henon_heiles', ['x', 'y'], ranges={'x': (-0.5, 0.5), 'y': (-0.5, 0.5)})
def _(q, v, t, p):
    # Henon & Heiles, Astron. J. 69 (1964) 73: x'' = -x - 2 x y, y'' = -y - x^2 + y^2
    x, y = q['x'], q['y']
    return [-x - 2 * x * y, -y - x * x + y * y]


@example('kepler_cartesian', ['x', 'y'], ranges={'x': (0.4, 2.0), 'y': (0.4, 2.0)})
def _(q, v, t, p):
    # Desloge ch. 58-59 (B C3): m r'' = -k r / |r|^3
    r3 = (q['x']**2 + q['y']**2)**1.5
    return [-p['k'] * q['x'] / (p['m'] * r3), -p['k'] * q['y'] / (p['m'] * r3)]


@example('two_masses_spring', ['x1', 'x2'])
def _(q, v, t, p):
    # Desloge ch. 56 thm 5; Goldstein sec. 1.2: m1 x1'' = k (x2 - x1 - d) = -m2 x2''
    f = p['k'] * (q['x2'] - q['x1'] - p['d'])
    return [f / p['m1'], -f / p['m2']]


@example('two_particles_spring_2d', ['x1', 'y1', 'x2', 'y2'])
def _(q, v, t, p):
    # Goldstein sec. 1.2 eq. 1.36 without gravity: m1 r1'' = -k (rho - d)(r1 - r2)/rho = -m2 r2''
    dx, dy = q['x1'] - q['x2'], q['y1'] - q['y2']
    rho = sqrt(dx * dx + dy * dy)
    s = -p['k'] * (rho - p['d']) / rho
    return [s * dx / p['m1'], s * dy / p['m1'], -s * dx / p['m2'], -s * dy / p['m2']]


@example('charged_particle_landau', ['x', 'y', 'z'])
def _(q, v, t, p):
    # Goldstein eqs. 1.60-1.66, B along z, no E: m r'' = q r' x B
    k = p['q'] * p['B'] / p['m']
    return [k * v['y'], -k * v['x'], 0.0]


@example('wire_curve_x4', ['x', 'phi'], ranges={'x': (0.3, 1.5)})
def _(q, v, t, p):
    # Desloge ch. 54 P6 (A pitfall 7, T42/T44): T = m/2 (x'^2 (1 + 16 x^6/a^6) + x^2 phi'^2),
    # V = m g x^4/a^3:  (1 + 16 x^6/a^6) x'' + 48 x^5 x'^2/a^6 - x phi'^2 + 4 g x^3/a^3 = 0;
    # d/dt(x^2 phi') = 0
    x, xd, phd = q['x'], v['x'], v['phi']
    a, g = p['a'], p['g']
    return [(x * phd**2 - 48 * x**5 * xd**2 / a**6 - 4 * g * x**3 / a**3) / (1 + 16 * x**6 / a**6),
            -2 * xd * phd / x]


@example('wire_curve_x4_driven', ['x'], ranges={'x': (0.3, 1.5)})
def _(q, v, t, p):
    # Desloge ch. 54 P6, the wire driven at phi' = Omega:
    # (1 + 16 x^6/a^6) x'' + 48 x^5 x'^2/a^6 - x Omega^2 + 4 g x^3/a^3 = 0
    x, xd = q['x'], v['x']
    a, g, w = p['a'], p['g'], p['Omega']
    return [(x * w**2 - 48 * x**5 * xd**2 / a**6 - 4 * g * x**3 / a**3) / (1 + 16 * x**6 / a**6)]


@example('restricted_three_body', ['x', 'y'], ranges={'x': (0.1, 0.8), 'y': (0.3, 1.5)})
def _(q, v, t, p):
    # Desloge ch. 62 (rotating frame, unit angular velocity): x'' - 2 y' = -dU/dx,
    # y'' + 2 x' = -dU/dy, U = -(x^2 + y^2)/2 - (1 - mu)/rho1 - mu/rho2
    x, y, mu = q['x'], q['y'], p['mu']
    r1 = ((x + mu)**2 + y**2)**1.5
    r2 = ((x - 1 + mu)**2 + y**2)**1.5
    return [2 * v['y'] + x - (1 - mu) * (x + mu) / r1 - mu * (x - 1 + mu) / r2,
            -2 * v['x'] + y - (1 - mu) * y / r1 - mu * y / r2]


@example('inverted_pendulum_spring', ['theta'])
def _(q, v, t, p):
    # derived from V = m g l cos th + k/2 (l sin th)^2 (examples/inverted_pendulum_spring.qd):
    # m l^2 th'' = m g l sin th - k l^2 sin th cos th
    th = q['theta']
    return [p['g'] / p['l'] * sin(th) - p['k'] / p['m'] * sin(th) * cos(th)]


@example('cart_pendulum', ['x', 'th'])
def _(q, v, t, p):
    # the inverted pendulum on a cart (issue 23), F = 0 as `eom --at` leaves an input unset:
    # the n = 1 case of SymPy's n_link_pendulum_on_cart, whose mass matrix and forcing are
    # [[M + m, -m l cos th], [-m l cos th, m l^2]] and [F - m l th'^2 sin th, m g l sin th]
    th, thd = q['th'], v['th']
    M, m, l, g = p['M'], p['m'], p['l'], p['g']
    A = [[M + m, -m * l * cos(th)], [-m * l * cos(th), m * l * l]]
    return solve(A, [-m * l * thd**2 * sin(th), m * g * l * sin(th)])


@example('ring_three_masses', ['x1', 'y1', 'x2', 'y2', 'x3', 'y3'])
def _(q, v, t, p):
    # Desloge ch. 66: each spring pulls its ends together with k (d - a) along the line
    # joining them: m r_i'' = -k sum_j (d_ij - a)(r_i - r_j)/d_ij
    pts = [(q['x1'], q['y1']), (q['x2'], q['y2']), (q['x3'], q['y3'])]
    acc = []
    for i in range(3):
        fx = fy = 0.0
        for j in range(3):
            if j != i:
                dx, dy = pts[i][0] - pts[j][0], pts[i][1] - pts[j][1]
                d = sqrt(dx * dx + dy * dy)
                fx -= p['k'] * (d - p['a']) * dx / d
                fy -= p['k'] * (d - p['a']) * dy / d
        acc += [fx / p['m'], fy / p['m']]
    return acc


# ---- symmetric vibrating systems (Desloge ch. 66; issue 19) ----------------------------

def spring_network(pts, masses, springs):
    """Accelerations of point masses joined by springs (i, j, k, natural length): each
    pulls its ends together with k (d - L) along the line joining them (Hooke)."""
    force = [[0.0] * len(pts[0]) for _ in pts]
    for i, j, k, length in springs:
        dr = [a - b for a, b in zip(pts[i], pts[j])]
        d = sqrt(sum(c * c for c in dr))
        for c in range(len(dr)):
            force[i][c] -= k * (d - length) * dr[c] / d
            force[j][c] += k * (d - length) * dr[c] / d
    return [f / m for fi, m in zip(force, masses) for f in fi]


@example('symmetric_triatomic', ['x1', 'x2', 'x3'],
         ranges={'x1': (-1.3, -0.7), 'x2': (-0.2, 0.2), 'x3': (0.7, 1.3)})
def _(q, v, t, p):
    # bonds k along the axis: m x1'' = k e12, M x2'' = -k e12 + k e23, m x3'' = -k e23
    e12 = q['x2'] - q['x1'] - p['a']
    e23 = q['x3'] - q['x2'] - p['a']
    return [p['k'] * e12 / p['m'], (-p['k'] * e12 + p['k'] * e23) / p['M'],
            -p['k'] * e23 / p['m']]


@example('symmetric_square', ['x1', 'y1', 'x2', 'y2', 'x3', 'y3', 'x4', 'y4'],
         ranges={'x1': (0.7, 1.3), 'y1': (0.7, 1.3), 'x2': (-1.3, -0.7), 'y2': (0.7, 1.3),
                 'x3': (-1.3, -0.7), 'y3': (-1.3, -0.7), 'x4': (0.7, 1.3), 'y4': (-1.3, -0.7)})
def _(q, v, t, p):
    pts = [(q['x%d' % i], q['y%d' % i]) for i in range(1, 5)]
    a, k, kd = p['a'], p['k'], p['kd']
    springs = [(0, 1, k, a), (1, 2, k, a), (2, 3, k, a), (3, 0, k, a),
               (0, 2, kd, a * sqrt(2)), (1, 3, kd, a * sqrt(2))]
    return spring_network(pts, [p['m']] * 4, springs)


_TETRA = ['%s%d' % (c, i) for i in range(5) for c in 'xyz']
_TETRA_AT = [(0, 0, 0), (1, 1, 1), (1, -1, -1), (-1, 1, -1), (-1, -1, 1)]


@example('symmetric_tetrahedron', _TETRA,
         ranges={'%s%d' % (c, i): (_TETRA_AT[i][n] / sqrt(3) - 0.2, _TETRA_AT[i][n] / sqrt(3) + 0.2)
                 for i in range(5) for n, c in enumerate('xyz')})
def _(q, v, t, p):
    pts = [tuple(q['%s%d' % (c, i)] for c in 'xyz') for i in range(5)]
    b, dh = p['b'], p['b'] * sqrt(8.0 / 3.0)
    springs = [(0, i, p['k'], b) for i in range(1, 5)]
    springs += [(i, j, p['kh'], dh) for i in range(1, 5) for j in range(i + 1, 5)]
    return spring_network(pts, [p['M']] + [p['m']] * 4, springs)


@example('symmetric_ring6', ['s1', 's2', 's3', 's4', 's5', 's6'])
def _(q, v, t, p):
    # arc coordinates on a circle: T = m/2 sum s_i'^2, so m s_i'' = k (s_i+1 - 2 s_i + s_i-1)
    s = [q['s%d' % i] for i in range(1, 7)]
    return [p['k'] * (s[(i + 1) % 6] - 2 * s[i] + s[i - 1]) / p['m'] for i in range(6)]


@example('rod_elastic_string', ['r', 'phi', 'theta'], ranges={'r': (0.5, 2.0)})
def _(q, v, t, p):
    # Desloge ch. 65 P11: rod centre G = r (sin phi, -cos phi) + a (sin th, -cos th),
    # T = M/2 |G'|^2 + M a^2 th'^2/6, V = M g G_y + 3 M g (r - a)^2/a; Lagrange's
    # equations worked by hand (c = cos(phi - th), s = sin(phi - th)):
    #   r'' + a s th'' = r phi'^2 + a th'^2 c + g cos phi - 6 g (r - a)/a
    #   r^2 phi'' + a r c th'' = -2 r r' phi' - a r th'^2 s - g r sin phi
    #   a s r'' + a r c phi'' + 4 a^2 th''/3 = -2 a r' phi' c + a r phi'^2 s - g a sin th
    r, ph, th = q['r'], q['phi'], q['theta']
    rd, phd, thd = v['r'], v['phi'], v['theta']
    a, g = p['a'], p['g']
    c, s = cos(ph - th), sin(ph - th)
    M = [[1, 0, a * s], [0, r * r, a * r * c], [a * s, a * r * c, 4 * a * a / 3]]
    f = [r * phd**2 + a * thd**2 * c + g * cos(ph) - 6 * g * (r - a) / a,
         -2 * r * rd * phd - a * r * thd**2 * s - g * r * sin(ph),
         -2 * a * rd * phd * c + a * r * phd**2 * s - g * a * sin(th)]
    return solve(M, f)


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
    # The constrained and rigid-body models are check_constrained.py's.
    files = sorted(f[:-3] for f in os.listdir(args.examples)
                   if f.endswith('.qd') and not constrained(os.path.join(args.examples, f)))
    if args.only:
        files = [f for f in files if f in args.only.split(',')]
    passed = failed = 0
    for name in files:
        path = os.path.join(args.examples, name + '.qd')
        spec = EXAMPLES.get(name)
        if spec is None:
            print('FAIL %s: no textbook formula in check_examples.py' % name)
            failed += 1
            continue
        defaults = read_parameters(path)
        runs = [{}] * args.states + [perturbed(defaults, rng)]
        for sets in runs:
            try:
                err, cmd = check_one(qdot, path, spec, rng, sets, defaults)
            except Exception as exc:     # a crash, bad JSON, a timeout
                err, cmd = '%s: %s' % (type(exc).__name__, exc), None
            if err:
                failed += 1
                print('FAIL %s: %s' % (name, err))
                if cmd:
                    print('  ' + ' '.join("'%s'" % c if ' ' in c else c for c in cmd))
            else:
                passed += 1
        print('%-28s checked' % name)
    print('%d passed, %d failed' % (passed, failed))
    return 1 if failed else 0


if __name__ == '__main__':
    sys.exit(main())

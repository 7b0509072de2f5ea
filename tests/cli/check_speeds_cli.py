#!/usr/bin/env python3
"""`qdot eom` on models with generalized speeds (issue 15).

    python3 tests/cli/check_speeds_cli.py --build BUILD_DIR

Every result is checked against a textbook form written here, through
Debian's SymPy, never against qdot's own printing:

- Euler's equations of a rigid body under a torque G fixed in it (Desloge
  ch. 68 Ex. 2; reference seed-desloge-C.md C13, pitfall 18: z-x-z angles,
  body components): A w1' = (B - C) w2 w3 + G1 and cyclic, from
  examples/euler_free_body.qd (w-cross's, also check_speeds_sympy's), by
  --method kane, appell and hamel, and --appell's S against ch. 70 thm 2
  (S = 1/2 w'.I.w' + w'.(w x I w)); the SymPy script and the JSON document of
  each method, and the three methods with each other, agree exactly
  (simplify of the difference is 0).
- The central force in polar coordinates with the areal velocity
  A = r^2 th'/2 (seed-desloge-C.md T1, ch. 68 Ex. 1: m r'' - 4 m A^2/r^3 = F_r,
  A' = 0) by all three methods, and the Gibbs-Appell function of --appell
  against T3 (ch. 69 Ex. 1: S = m/2 r''^2 + 2 m A'^2/r^2 - 4 m A^2 r''/r^3 up to
  terms free of the quasi-accelerations).
- The Chaplygin sleigh (the knife edge): its two equations and the blade's
  multiplier, with speeds named u and S (the script's outputs become u_, S_).
- The kinematics q' = W u + w: put back into the speeds' definitions (C13's
  map for the body, the T1 definitions for the particle) they give u.
- --multipliers on the rolling disk (Desloge ch. 52 Ex. 1, examples/
  rolling_disk.qd with a force) equal the multipliers of `qdot eom --solve`
  of the same model without its speeds line, at random states (q' from the
  kinematics, u' from M u' = f solved), to 1e-10.
- --at: the speeds' rates of the body are Euler's and its velocities
  give back the speeds; on the rolling disk the multipliers and rates equal
  those of `qdot eom --at` without the speeds (1e-10).
- --format c compiles and gives the SymPy script's numbers; --format latex
  has one line per equation.
- Errors: speeds that repeat a constraint or another speed (exit 2, at the
  statement to blame); an unknown --method (exit 2, the names listed);
  --appell, --multipliers or --method on a model without speeds, --eliminate on
  one with, a velocity in --at with speeds (exit 2); a state where the speed
  map is singular (exit 1).

Prints "N passed, N failed"; exit 1 on failure."""
import argparse
import json
import os
import random
import re
import shutil
import subprocess
import sys
import tempfile

import sympy
from sympy import Function, Matrix, Symbol, cos, sin, simplify

results = {'passed': 0, 'failed': 0}
METHODS = ('kane', 'appell', 'hamel')

CENTRAL = """coordinates r, th
parameters m = 1
functions F
T = m/2*(r'^2 + r^2*th'^2)
Q[r] = F(r)
speeds v = r', A = r^2*th'/2
"""

# examples/rolling_disk.qd with a force, so that the multipliers depend on it.
DISK = """coordinates x1, x2, ph, psi
parameters m = 1.4, a = 0.35, g = 9.81, f1 = 0.3, f2 = -0.2

body disk mass m inertia disk(m, a) at (x1, x2, a) orientation euler(ph, pi/2, psi)
V = m*g*a
force (f1, f2, 0) at (x1, x2, a)

constraint roll1: x1' + a*psi'*cos(ph) = 0
constraint roll2: x2' + a*psi'*sin(ph) = 0
"""
DISK_SPEEDS = "speeds u_ph = ph', u_psi = psi'\n"

# The Chaplygin sleigh (a knife edge at (x, y), the centre of mass a ahead
# on the blade), with speeds named u and S like two of the script's outputs.
SLEIGH = """coordinates x, y, th
parameters m = 1, Ic = 1/5, a = 1/2
body sled mass m inertia (0, 0, Ic) at (x + a*cos(th), y + a*sin(th)) orientation rot_z(th)
constraint blade: -x'*sin(th) + y'*cos(th) = 0
speeds u = x'*cos(th) + y'*sin(th), S = th'
"""


def check(name, ok, detail=''):
    results['passed' if ok else 'failed'] += 1
    if not ok:
        print('FAIL %s %s' % (name, str(detail)[:600]))


def zero(e):
    return simplify(sympy.expand(e)) == 0


def run(qdot, *args):
    return subprocess.run([qdot, *args], capture_output=True, text=True, timeout=300)


def script(qdot, path, *args):
    """The names the printed SymPy script defines, or None (and a failure)."""
    p = run(qdot, 'eom', path, '--format', 'sympy', *args)
    if p.returncode != 0:
        check('eom %s %s' % (path, ' '.join(args)), False, p.stderr)
        return None
    ns = {}
    try:
        exec(compile(p.stdout, '<qdot eom>', 'exec'), ns)
    except Exception as ex:  # the script must run as printed
        check('eom %s script runs' % path, False, '%s\n%s' % (ex, p.stdout[:400]))
        return None
    return ns


def document(qdot, path, *args):
    p = run(qdot, 'eom', path, '--format', 'json', *args)
    if p.returncode != 0:
        check('eom %s json' % path, False, p.stderr)
        return None
    return json.loads(p.stdout)


class Plain:
    """Coordinates and speeds as plain symbols: x(t) -> x, x' -> x__d,
    x'' -> x__dd, the same for the SymPy script and for the JSON text."""

    def __init__(self, names):
        self.names = names
        t = Symbol('t')
        self.rules = []
        for n in names:
            f = Function(n)(t)
            self.rules += [(f.diff(t, 2), Symbol(n + '__dd')), (f.diff(t), Symbol(n + '__d')),
                           (f, Symbol(n))]

    def __call__(self, x):
        for old, new in self.rules:  # derivatives before the functions
            x = x.subs(old, new)
        return x

    def read(self, text):
        s = re.sub(r"([A-Za-z_]\w*)''", r'\1__dd', text)
        s = re.sub(r"([A-Za-z_]\w*)'", r'\1__d', s).replace('^', '**')
        names = set(re.findall(r'[A-Za-z_]\w*', s)) - {'sin', 'cos', 'tan', 'sqrt', 'exp',
                                                         'log', 'atan2', 'pi'}
        return sympy.sympify(s, locals={n: Symbol(n) for n in names})

    def sym(self, name, order=0):
        return Symbol(name + ('', '__d', '__dd')[order])


def equations(ns, plain):
    """M u' - f of a script, in plain symbols."""
    u = [plain(x) for x in ns['u']]
    ud = Matrix([Symbol(str(x) + '__d') for x in u])
    return plain(ns['M'] * ud - ns['f'])


def euler_reference():
    """Euler's equations I1 w1' - (I2 - I3) w2 w3 = G1 and cyclic (C13), G the
    torque's body components, as M u' - f."""
    A, B, C = Symbol('A'), Symbol('B'), Symbol('C')
    G = [Symbol('G%d' % i) for i in (1, 2, 3)]
    w = [Symbol('w%d' % i) for i in (1, 2, 3)]
    wd = [Symbol('w%d__d' % i) for i in (1, 2, 3)]
    return Matrix([A * wd[0] - (B - C) * w[1] * w[2] - G[0],
                   B * wd[1] - (C - A) * w[2] * w[0] - G[1],
                   C * wd[2] - (A - B) * w[0] * w[1] - G[2]])


def euler_appell():
    """S = 1/2 w'.I.w' + w'.(w x I w), I = diag(A, B, C) (Desloge ch. 70
    thm 2; the torque enters Pi, not S)."""
    A, B, C = Symbol('A'), Symbol('B'), Symbol('C')
    w = Matrix([Symbol('w%d' % i) for i in (1, 2, 3)])
    wd = Matrix([Symbol('w%d__d' % i) for i in (1, 2, 3)])
    Iw = Matrix([A * w[0], B * w[1], C * w[2]])
    return (A * wd[0]**2 + B * wd[1]**2 + C * wd[2]**2) / 2 + wd.dot(w.cross(Iw))


def euler_definitions():
    """The body components of the angular velocity in z-x-z angles (C13)."""
    ph, th, ps = Symbol('phi'), Symbol('theta'), Symbol('psi')
    phd, thd, psd = Symbol('phi__d'), Symbol('theta__d'), Symbol('psi__d')
    return [cos(ps) * thd + sin(th) * sin(ps) * phd, -sin(ps) * thd + sin(th) * cos(ps) * phd,
            cos(th) * phd + psd]


def check_kinematics(name, kin, qs, defs, us):
    """Substituting q' = kin into each definition gives back the speed."""
    rule = {Symbol(q + '__d'): k for q, k in zip(qs, kin)}
    for d, u in zip(defs, us):
        back = sympy.trigsimp(simplify(d.subs(rule)))
        check('%s kinematics give %s' % (name, u), zero(back - Symbol(u)), back)


def check_euler(qdot, root):
    path = os.path.join(root, 'examples', 'euler_free_body.qd')
    plain = Plain(['phi', 'theta', 'psi', 'w1', 'w2', 'w3'])
    ref = euler_reference()
    got = {}
    for method in METHODS:
        ns = script(qdot, path, '--method', method, '--appell')
        doc = document(qdot, path, '--method', method, '--appell')
        if ns is None or doc is None:
            continue
        eq = equations(ns, plain)
        for r in range(3):
            check('euler %s row %d is Euler\'s' % (method, r), zero(eq[r] - ref[r]), eq[r])
        kin = [plain(x) for x in ns['kin']]
        check_kinematics('euler %s' % method, kin, ['phi', 'theta', 'psi'],
                         euler_definitions(), ['w1', 'w2', 'w3'])
        check('euler %s json keys' % method,
              doc.get('speeds') == ['w1', 'w2', 'w3'] and doc.get('method') == method
              and doc.get('coordinates') == ['phi', 'theta', 'psi'], doc)
        M = Matrix([[plain.read(x) for x in row] for row in doc['mass_matrix']])
        f = Matrix([plain.read(x) for x in doc['forcing']])
        check('euler %s json M = script M' % method, zero(sum(M - plain(ns['M']))), M)
        check('euler %s json f = script f' % method,
              all(zero(a - b) for a, b in zip(f, plain(ns['f']))), f)
        jkin = {k['coordinate']: plain.read(k['expression']) for k in doc['kinematics']}
        check('euler %s json kinematics' % method,
              all(zero(jkin[q] - k) for q, k in zip(['phi', 'theta', 'psi'], kin)), jkin)
        S = plain(ns['S'])
        check('euler %s S is ch. 70 thm 2\'s' % method, zero(S - euler_appell()), S)
        check('euler %s json S = script S' % method, zero(plain.read(doc.get('S', '0')) - S))
        got[method] = (eq, kin)
    for method in METHODS[1:]:
        if 'kane' in got and method in got:
            same = all(zero(a - b) for a, b in zip(got['kane'][0], got[method][0]))
            check('euler kane = %s' % method, same)


def central_reference():
    m, r, A = Symbol('m'), Symbol('r'), Symbol('A')
    rdd, Ad, Fr = Symbol('v__d'), Symbol('A__d'), Function('F')(r)
    # dS/du' - Pi in T1/T3's scale: m r'' - 4 m A^2/r^3 - F_r and 4 m A'/r^2
    eqs = Matrix([m * rdd - 4 * m * A**2 / r**3 - Fr, 4 * m * Ad / r**2])
    S = m / 2 * rdd**2 + 2 * m * Ad**2 / r**2 - 4 * m * A**2 * rdd / r**3
    return eqs, S


def check_central(qdot, d):
    path = os.path.join(d, 'central.qd')
    with open(path, 'w') as fh:
        fh.write(CENTRAL)
    plain = Plain(['r', 'th', 'v', 'A'])
    ref, S_ref = central_reference()
    for method in METHODS:
        ns = script(qdot, path, '--method', method, '--appell')
        if ns is None:
            continue
        eq = equations(ns, plain)
        for k in range(2):
            check('central %s Hamel row %d' % (method, k), zero(eq[k] - ref[k]), eq[k])
        S = plain(ns['S'])
        for ud in (Symbol('v__d'), Symbol('A__d')):
            check('central %s S = T3 up to %s-free terms' % (method, ud),
                  zero(sympy.diff(S - S_ref, ud)), S)
        r, A, thd = Symbol('r'), Symbol('A'), Symbol('th__d')
        check_kinematics('central %s' % method, [plain(x) for x in ns['kin']], ['r', 'th'],
                         [Symbol('r__d'), r**2 * thd / 2], ['v', 'A'])


def check_sleigh(qdot, d):
    """The knife edge (Neimark and Fufaev ch. III; w-cross's chaplygin_sleigh.qd):
    m u' = m a w^2, (Ic + m a^2) w' = -m a u w, the blade's multiplier
    m (u w + a w'), and the script's names kept clear of the speeds."""
    path = os.path.join(d, 'sleigh.qd')
    with open(path, 'w') as fh:
        fh.write(SLEIGH)
    ns = script(qdot, path, '--appell', '--multipliers')
    if ns is None:
        return
    check('sleigh: the speeds u and S stay functions, the outputs are u_ and S_',
          isinstance(ns.get('u_'), sympy.MatrixBase) and 'S_' in ns
          and isinstance(ns['u'], sympy.FunctionClass) and isinstance(ns['S'], sympy.FunctionClass),
          sorted(k for k in ns if not k.startswith('__'))[:40])
    if not isinstance(ns.get('u_'), sympy.MatrixBase):
        return
    ns['u'] = ns['u_']
    plain = Plain(['x', 'y', 'th', 'u', 'S'])
    m, Ic, a = Symbol('m'), Symbol('Ic'), Symbol('a')
    u, w, ud, wd = Symbol('u'), Symbol('S'), Symbol('u__d'), Symbol('S__d')
    eq = equations(ns, plain)
    ref = [m * ud - m * a * w**2, (Ic + m * a**2) * wd + m * a * u * w]
    for k in range(2):
        check('sleigh row %d' % k, zero(eq[k] - ref[k]), eq[k])
    lam = plain(ns['lam_value'][0])
    check('sleigh multiplier', zero(lam - m * (u * w + a * wd)), lam)
    th = Symbol('th')
    check_kinematics('sleigh', [plain(x) for x in ns['kin']], ['x', 'y', 'th'],
                     [Symbol('x__d') * cos(th) + Symbol('y__d') * sin(th), Symbol('th__d')],
                     ['u', 'S'])


def disk_values(ns):
    return {ns[p]: v for p, v in (('m', 1.4), ('a', 0.35), ('g', 9.81), ('f1', 0.3),
                                  ('f2', -0.2))}


def check_disk(qdot, d):
    plain_path, speeds_path = os.path.join(d, 'disk.qd'), os.path.join(d, 'disk_speeds.qd')
    with open(plain_path, 'w') as fh:
        fh.write(DISK)
    with open(speeds_path, 'w') as fh:
        fh.write(DISK + DISK_SPEEDS)
    coords = script(qdot, plain_path, '--solve')
    speeds = script(qdot, speeds_path, '--multipliers', '--solve')
    if coords is None or speeds is None:
        return
    check('disk: two dynamic equations', speeds['M'].shape == (2, 2), speeds['M'].shape)
    qs = ['x1', 'x2', 'ph', 'psi']
    plain = Plain(qs + ['u_ph', 'u_psi'])
    lam_c = plain(coords['lam_value'].subs(disk_values(coords)))
    lam_s = plain(speeds['lam_value'].subs(disk_values(speeds)))
    vals = disk_values(speeds)
    M, f = plain(speeds['M'].subs(vals)), plain(speeds['f'].subs(vals))
    kin = plain(speeds['kin'].subs(vals))
    rates = plain(speeds['ud'].subs(vals))
    rng = random.Random(15)
    worst = worst_rate = 0.0
    for _ in range(5):
        state = {Symbol(q): rng.uniform(-2, 2) for q in qs}
        state.update({Symbol('u_ph'): rng.uniform(-2, 2), Symbol('u_psi'): rng.uniform(-2, 2)})
        qd = kin.subs(state)
        ud = M.subs(state).LUsolve(f.subs(state))
        for r in range(2):  # --solve's u' = M^-1 f against SymPy's solve of M, f
            x = float(rates[r].subs(state))
            worst_rate = max(worst_rate, abs(x - float(ud[r])) / max(1.0, abs(x)))
        at = dict(state)
        at.update({Symbol(q + '__d'): qd[j] for j, q in enumerate(qs)})
        at.update({Symbol('u_ph__d'): ud[0], Symbol('u_psi__d'): ud[1]})
        for k in range(2):
            a, b = float(lam_c[k].subs(at)), float(lam_s[k].subs(at))
            worst = max(worst, abs(a - b) / max(1.0, abs(a)))
    check('disk multipliers: speeds = coordinates (1e-10)', worst < 1e-10, worst)
    check('disk --solve: u\' = M^-1 f (1e-12)', worst_rate < 1e-12, worst_rate)


C_MAIN = """#include <math.h>
#include <stdio.h>
int main(void) {
    double %s;
    double qd[3], M[3][3], f[3], S;
%s
    printf("%%.17g %%.17g %%.17g %%.17g %%.17g %%.17g %%.17g %%.17g\\n", qd[0], qd[1], qd[2],
           M[0][0], M[1][1], f[0], f[2], S);
    return 0;
}
"""


def check_c(qdot, root, d):
    """The C block, compiled, gives the numbers of the SymPy script at a state."""
    cc = os.environ.get('CC', 'cc')
    if not shutil.which(cc):
        print('note: no C compiler (%s): the C format is not checked' % cc)
        return
    path = os.path.join(root, 'examples', 'euler_free_body.qd')
    p = run(qdot, 'eom', path, '--format', 'c', '--appell')
    ns = script(qdot, path, '--appell')
    if p.returncode != 0 or ns is None:
        check('euler --format c', False, p.stderr)
        return
    inputs = re.search(r'inputs \(doubles in scope\):([^*]*)\*/', p.stdout).group(1).split()
    plain = Plain(['phi', 'theta', 'psi', 'w1', 'w2', 'w3'])
    rng = random.Random(68)
    vals = {name: rng.uniform(0.3, 1.2) for name in inputs}
    vals.update(A=1.0, B=2.0, C=3.0, t=0.0)
    src = os.path.join(d, 'euler.c')
    with open(src, 'w') as fh:
        fh.write(C_MAIN % (', '.join('%s = %r' % kv for kv in vals.items()), p.stdout))
    exe = os.path.join(d, 'euler')
    comp = subprocess.run([cc, '-std=c99', '-o', exe, src, '-lm'], capture_output=True, text=True)
    if comp.returncode != 0:
        check('euler C block compiles', False, comp.stderr)
        return
    got = [float(x) for x in subprocess.run([exe], capture_output=True, text=True).stdout.split()]
    at = {Symbol(k.replace('_d', '__d') if k.endswith('_d') else k): v for k, v in vals.items()}
    want = [plain(x) for x in list(ns['kin']) + [ns['M'][0, 0], ns['M'][1, 1], ns['f'][0],
                                                 ns['f'][2], ns['S']]]
    want = [float(w.subs(at)) for w in want]
    check('euler C block = SymPy script', len(got) == len(want) and all(
        abs(a - b) <= 1e-12 * max(1.0, abs(b)) for a, b in zip(got, want)), (got, want))


def check_latex(qdot, root):
    """One align line per kinematic and dynamic equation, and one for S."""
    path = os.path.join(root, 'examples', 'euler_free_body.qd')
    p = run(qdot, 'eom', path, '--format', 'latex', '--appell')
    lines = [x for x in p.stdout.splitlines() if '&=' in x]
    check('euler latex: 3 + 3 + 1 lines', p.returncode == 0 and len(lines) == 7, p.stdout)
    check('euler latex: the speeds\' rates', '\\dot{w_{1}}' in p.stdout
          or '\\dot{w}_{1}' in p.stdout or '\\dot{w_1}' in p.stdout, p.stdout)


def at_json(qdot, path, state, *args):
    at = ', '.join('%s=%r' % kv for kv in state.items())
    p = run(qdot, 'eom', path, '--at', at, '--format', 'json', *args)
    if p.returncode != 0:
        check('eom %s --at %s' % (path, at), False, p.stderr)
        return None
    return json.loads(p.stdout)


def check_euler_at(qdot, root):
    """--at: u' from Euler's equations (with a torque G named in --at) and q'
    that give back the speeds through C13's map, at random states (numbers
    from qd_speeds_eval)."""
    path = os.path.join(root, 'examples', 'euler_free_body.qd')
    rng = random.Random(682)
    A, B, C = 1.0, 2.0, 3.0
    for _ in range(3):
        q = {'phi': rng.uniform(-3, 3), 'theta': rng.uniform(0.3, 2.8), 'psi': rng.uniform(-3, 3)}
        w = [rng.uniform(-2, 2) for _ in range(3)]
        G = [rng.uniform(-1, 1) for _ in range(3)]
        state = dict(q)
        state.update({'w%d' % (i + 1): w[i] for i in range(3)})
        state.update({'G%d' % (i + 1): G[i] for i in range(3)})
        doc = at_json(qdot, path, state)
        if doc is None:
            return
        want = [((B - C) * w[1] * w[2] + G[0]) / A, ((C - A) * w[2] * w[0] + G[1]) / B,
                ((A - B) * w[0] * w[1] + G[2]) / C]
        got = doc.get('rates', [])
        check('euler --at rates are Euler\'s', len(got) == 3 and all(
            abs(g - x) <= 1e-12 * max(1.0, abs(x)) for g, x in zip(got, want)), (got, want))
        rule = {Symbol(n): v for n, v in q.items()}
        rule.update({Symbol(n + '__d'): v for n, v in zip(('phi', 'theta', 'psi'),
                                                          doc.get('velocities', []))})
        back = [float(x.subs(rule)) for x in euler_definitions()]
        check('euler --at velocities give the speeds back', all(
            abs(b - x) <= 1e-12 * max(1.0, abs(x)) for b, x in zip(back, w)), (back, w))


def check_disk_at(qdot, d):
    """--multipliers --at against `qdot eom --at` without the speeds: the
    library's numeric paths (qd_speeds_eval, qd_eom_eval) agree to 1e-10."""
    rng = random.Random(52)
    worst = 0.0
    for _ in range(3):
        q = {n: rng.uniform(-2, 2) for n in ('x1', 'x2', 'ph', 'psi')}
        u = {'u_ph': rng.uniform(-2, 2), 'u_psi': rng.uniform(-2, 2)}
        state = dict(q)
        state.update(u)
        ds = at_json(qdot, os.path.join(d, 'disk_speeds.qd'), state, '--multipliers')
        if ds is None:
            return
        coords = dict(q)
        coords.update({n + "'": v for n, v in zip(ds['coordinates'], ds['velocities'])})
        dc = at_json(qdot, os.path.join(d, 'disk.qd'), coords)
        if dc is None:
            return
        for k in ('roll1', 'roll2'):
            a, b = dc['multipliers'][k], ds['multipliers'][k]
            worst = max(worst, abs(a - b) / max(1.0, abs(a)))
        # the rates of the speeds are the accelerations of ph and psi
        acc = dict(zip(dc['coordinates'], dc['accelerations']))
        for r, n in enumerate(('ph', 'psi')):
            worst = max(worst, abs(acc[n] - ds['rates'][r]) / max(1.0, abs(acc[n])))
    check('disk --at: speeds = coordinates (multipliers, rates; 1e-10)', worst < 1e-10, worst)


def check_errors(qdot, root, d):
    euler = os.path.join(root, 'examples', 'euler_free_body.qd')
    p = run(qdot, 'eom', euler, '--method', 'lagrange')
    check('unknown --method: exit 2 listing the names',
          p.returncode == 2 and all(m in p.stderr for m in METHODS) and not p.stdout, p.stderr)
    p = run(qdot, 'eom', euler, '--multipliers', '--format', 'json')
    check('--multipliers without constraints: an empty "multipliers"',
          p.returncode == 0 and json.loads(p.stdout).get('multipliers') == {}, p.stderr)
    p = run(qdot, 'eom', euler, '--eliminate')
    check('--eliminate with speeds: exit 2', p.returncode == 2 and 'speeds' in p.stderr,
          p.stderr)
    # A speed that repeats a constraint leaves q' undetermined: a located
    # error (QD_REASON_DEPENDENT_SPEEDS) at the model's line, exit 2.
    dep = os.path.join(d, 'disk_dependent.qd')
    with open(dep, 'w') as fh:
        fh.write(DISK + "speeds u_ph = ph', u_roll = x1' + a*psi'*cos(ph)\n")
    p = run(qdot, 'eom', dep)
    check('a speed repeating roll1: exit 2 at the constraint roll1 (line 8)',
          p.returncode == 2 and re.search(r'disk_dependent\.qd:8:\d+: error: .*roll1', p.stderr)
          and not p.stdout, p.stderr)
    # Two speeds along theta': the second is the one to blame, at its name.
    rep = os.path.join(d, 'euler_repeated.qd')
    with open(rep, 'w') as fh:
        fh.write("coordinates phi, theta, psi\nparameters A = 1, B = 2, C = 3\n"
                 "body b mass 1 inertia (A, B, C) at (0, 0, 0) orientation euler(phi, theta, psi)\n"
                 "speeds w1 = theta', w2 = 2*theta', w3 = psi'\n")
    p = run(qdot, 'eom', rep)
    check('a speed repeating another: exit 2 at w2 (4:21)',
          p.returncode == 2 and 'euler_repeated.qd:4:21: error' in p.stderr and 'w2' in p.stderr,
          p.stderr)
    p = run(qdot, 'eom', euler, '--at', "theta=1, phi'=0.5")
    check('--at with a velocity on a model with speeds: exit 2',
          p.returncode == 2 and 'speeds' in p.stderr and not p.stdout, p.stderr)
    # theta = 0: phi' = (w1 sin(psi) + w2 cos(psi))/sin(theta) is not a number
    p = run(qdot, 'eom', euler, '--at', 'theta=0, w1=1')
    check('--at where the speed map is singular: exit 1, no numbers',
          p.returncode == 1 and 'finite' in p.stderr and not p.stdout, p.stderr)
    p = run(qdot, 'eom', euler, '--at', 'theta=1', '--format', 'latex')
    check('--at with speeds in latex: exit 2', p.returncode == 2 and not p.stdout, p.stderr)
    path = os.path.join(d, 'disk.qd')
    for opt in (['--multipliers'], ['--appell'], ['--method', 'kane']):
        p = run(qdot, 'eom', path, *opt)
        check('%s without speeds: exit 2' % opt[0],
              p.returncode == 2 and 'declares no speeds' in p.stderr and not p.stdout, p.stderr)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--build', required=True)
    ap.add_argument('--root', default=os.path.join(os.path.dirname(__file__), '..', '..'))
    args = ap.parse_args()
    qdot = os.path.join(args.build, 'qdot')
    with tempfile.TemporaryDirectory() as d:
        check_euler(qdot, args.root)
        check_central(qdot, d)
        check_disk(qdot, d)
        check_sleigh(qdot, d)
        check_euler_at(qdot, args.root)
        check_disk_at(qdot, d)
        check_c(qdot, args.root, d)
        check_latex(qdot, args.root)
        check_errors(qdot, args.root, d)
    print('%d passed, %d failed' % (results['passed'], results['failed']))
    return 1 if results['failed'] else 0


if __name__ == '__main__':
    sys.exit(main())

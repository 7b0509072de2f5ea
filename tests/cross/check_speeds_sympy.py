#!/usr/bin/python3
"""tests/cross/check_speeds_sympy.py - the equations in generalized speeds
against SymPy: the three methods against each other, every speeds example
against its textbook result, and the rolling disc against KanesMethod.

gen_speeds (tests/cross/gen_speeds.c) prints, for every examples/*.qd with a
`speeds` statement, qdot's M_u, f_u, the kinematics q' = W u + w and the
Gibbs-Appell function S by each method (Kane, Gibbs-Appell,
Boltzmann-Hamel).  At random states and parameter values (exact rationals,
evaluated to 30 digits) this checks, for each example:

  1. the three methods agree: M_u, f_u, the kinematics and S, to 1e-24
     (they are the same equations, include/qdot/speeds.h), and the
     differences of M_u, f_u and the kinematics simplify to 0 in SymPy
     (entries qdot prints in different forms are counted and shown);
  2. the kinematics solve the speeds' definitions, def_r(q, kin) = u_r, and
     satisfy every constraint of the model: the constraints are eliminated
     for every value of the speeds (Desloge ch. 69 thm 2);
  3. S = 1/2 u'^T M_u u' + g^T u': its Hessian in u' is M_u;
  4. the textbook: u' = M_u^-1 f_u, and where the book gives them the
     kinematics and S (u'-free terms dropped), against the formulas below,
     each citing its seed, chapter and equation;
  5. the rolling disc (examples/rolling_disk_speeds.qd) and the bicycle
     (examples/bicycle_speeds.qd) against SymPy's KanesMethod with the same
     speeds, the systems of bench/speeds_sympy.py (the disc is the system of
     SymPy's own test_rolling_disc: contact point at rest, speeds the
     lean-frame components of the angular velocity; the bicycle has
     dependent speeds and velocity constraints): u' to 1e-10 relative, and
     for the disc M_u and f_u entry by entry.  The bicycle has no closed
     form in a book: KanesMethod is its reference, with the kinematics.

Usage: check_speeds_sympy.py --build BUILD_DIR [--states N]
Prints one line per check and "N passed, N failed"; exits 1 on any failure.
"""
import argparse
import random
import re
import subprocess
import sys
from pathlib import Path

import sympy
from sympy import (Derivative, Float, Function, Matrix, Rational, Symbol, cos, diff, sin,
                   tan)

ROOT = Path(__file__).resolve().parents[2]
EXAMPLES = ROOT / 'examples'
DIGITS = 30
EXACT_TOL = Float('1e-24', DIGITS)
KANE_TOL = 1e-10
STATES = 4
SEED = 20261126

# Where random coordinates come from, by name (else [-1.5, 1.5]): away from
# the poles of the Euler angles, the disc lying flat, the origin of r.
RANGES = {'theta': (0.3, 2.8), 'q2': (-1.0, 1.0), 'r': (0.5, 2.0)}
SPEED_RANGE = 2.0


def rand(rng, lo, hi):
    """An exact rational in [lo, hi] (three decimals)."""
    return Rational(rng.randint(int(lo * 1000), int(hi * 1000)), 1000)


# ---------------------------------------------------------------------------
# Reading gen_speeds' output.

class Case:
    def __init__(self, name):
        self.name = name
        self.coords, self.speeds, self.params = [], [], {}
        self.defs, self.cons = {}, {}
        self.methods = {}     # method -> {'M': {}, 'f': {}, 'kin': {}, 'S': expr}
        self.errors = []


def read_cases(text):
    cases, case, cur = [], None, None
    for line in text.splitlines():
        tag, _, rest = line.partition(' ')
        if tag == 'case':
            case = Case(rest)
            cases.append(case)
        elif tag == 'coords':
            case.coords = rest.split()
        elif tag == 'speeds':
            case.speeds = rest.split()
        elif tag == 'params':
            f = rest.split()
            case.params = {f[i]: float(f[i + 1]) for i in range(0, len(f), 2)}
        elif tag == 'def':
            k, _, e = rest.partition(' ')
            case.defs[int(k)] = e
        elif tag == 'con':
            k, _, e = rest.partition(' ')
            case.cons[int(k)] = e
        elif tag == 'method':
            cur = case.methods.setdefault(rest, {'M': {}, 'f': {}, 'kin': {}, 'S': None})
        elif tag == 'M':
            r, s, e = rest.split(' ', 2)
            cur['M'][int(r), int(s)] = e
        elif tag in ('f', 'kin'):
            k, _, e = rest.partition(' ')
            cur[tag][int(k)] = e
        elif tag == 'S':
            cur['S'] = rest
        elif tag == 'error':
            case.errors.append(rest)
    return cases


class Symbols:
    """The case's names as SymPy objects, and the map from qdot's printed
    functions of t to plain symbols q, qd, u, ud."""

    def __init__(self, case):
        t = Symbol('t')
        self.ns = {'t': t}
        exec('from sympy import *', self.ns)
        self.ns['t'] = t
        self.q = {n: Symbol(n) for n in case.coords}
        self.qd = {n: Symbol(n + '_d') for n in case.coords}
        self.u = {n: Symbol(n) for n in case.speeds}
        self.ud = {n: Symbol(n + '_d') for n in case.speeds}
        self.p = {n: Symbol(n) for n in case.params}
        self.plain = {}
        for n in case.coords + case.speeds:
            fn = Function(n)
            self.ns[n] = fn
            self.plain[Derivative(fn(t), t)] = Symbol(n + '_d')
            self.plain[fn(t)] = Symbol(n)
        for n in case.params:
            self.ns[n] = Symbol(n)

    def expr(self, text):
        return sympy.sympify(eval(text, self.ns)).xreplace(self.plain)


def expressions(case, sy):
    """The case's printed items as SymPy expressions in plain symbols."""
    m, n = len(case.speeds), len(case.coords)
    out = {}
    for meth, d in case.methods.items():
        out[meth] = {
            'M': Matrix(m, m, lambda r, s: sy.expr(d['M'][r, s])),
            'f': Matrix([sy.expr(d['f'][r]) for r in range(m)]),
            'kin': Matrix([sy.expr(d['kin'][j]) for j in range(n)]),
            'S': sy.expr(d['S']) if d['S'] else None,
        }
    defs = [sy.expr(case.defs[r]) for r in range(m)]
    cons = [sy.expr(case.cons[k]) for k in sorted(case.cons)]
    return out, defs, cons


def random_state(case, sy, rng):
    """Values for q, u, u', t and the parameters (defaults scaled by
    [0.5, 1.5]; a zero default drawn from [-1, 1])."""
    vals = {Symbol('t'): rand(rng, 0, 3)}
    for n in case.coords:
        lo, hi = RANGES.get(n, (-1.5, 1.5))
        vals[sy.q[n]] = rand(rng, lo, hi)
    for n in case.speeds:
        vals[sy.u[n]] = rand(rng, -SPEED_RANGE, SPEED_RANGE)
        vals[sy.ud[n]] = rand(rng, -SPEED_RANGE, SPEED_RANGE)
    for n, v in case.params.items():
        x = Rational(v).limit_denominator(10**6)
        vals[sy.p[n]] = x * rand(rng, 0.5, 1.5) if v != 0 else rand(rng, -1, 1)
    return vals


def num(e, vals):
    return sympy.N(e.xreplace(vals), DIGITS)


def close_exact(a, b):
    return abs(a - b) <= EXACT_TOL * (1 + abs(a) + abs(b))


def close(a, b, tol=KANE_TOL):
    return abs(a - b) <= tol * (1 + abs(a) + abs(b))


# ---------------------------------------------------------------------------
# The textbook results.  Each gets q, u (values by name) and p (parameters)
# and returns u' (speed order); KIN returns q' (coordinate order); S returns
# the book's S, from which the u'-free terms are dropped before comparing.

TEXTBOOK, KIN, S_BOOK = {}, {}, {}


def textbook(name, table):
    def wrap(fn):
        table[name] = fn
        return fn
    return wrap


@textbook('euler_free_body', TEXTBOOK)
def _(q, u, p):
    # Desloge ch. 68 Ex 2 (seed-desloge-C.md C13): Euler's equations
    # A w1' - (B - C) w2 w3 = G1 and cyclically, G the body-axis torque
    A, B, C = p['A'], p['B'], p['C']
    w1, w2, w3 = u['w1'], u['w2'], u['w3']
    return [((B - C) * w2 * w3 + p['G1']) / A, ((C - A) * w3 * w1 + p['G2']) / B,
            ((A - B) * w1 * w2 + p['G3']) / C]


@textbook('euler_free_body', KIN)
def _(q, u, p):
    # the inverse of C13's w = b^-1 q' (z-x-z angles, body components)
    th, ps = q['theta'], q['psi']
    w1, w2, w3 = u['w1'], u['w2'], u['w3']
    phid = (w1 * sin(ps) + w2 * cos(ps)) / sin(th)
    return [phid, w1 * cos(ps) - w2 * sin(ps), w3 - cos(th) * phid]


@textbook('euler_free_body', S_BOOK)
def _(q, u, ud, p):
    # Desloge ch. 70 thm 2: S = 1/2 w'.I w' + w'.(w x I w)
    I = Matrix.diag(p['A'], p['B'], p['C'])
    w = Matrix([u['w1'], u['w2'], u['w3']])
    a = Matrix([ud['w1'], ud['w2'], ud['w3']])
    return (a.T * I * a)[0] / 2 + a.dot(w.cross(I * w))


@textbook('central_areal', TEXTBOOK)
def _(q, u, p):
    # Desloge ch. 68 Ex 1 (T1): m r'' - 4 m A^2/r^3 = F_r = -k/r^2, A' = 0
    r, m, k = q['r'], p['m'], p['k']
    return [(4 * m * u['A'] ** 2 / r ** 3 - k / r ** 2) / m, 0]


@textbook('central_areal', KIN)
def _(q, u, p):
    return [u['v'], 2 * u['A'] / q['r'] ** 2]


@textbook('central_areal', S_BOOK)
def _(q, u, ud, p):
    # Desloge ch. 69 Ex 1 (T3), in (r, A)
    r, m, A = q['r'], p['m'], u['A']
    return (m / 2 * ud['v'] ** 2 + 2 * m * ud['A'] ** 2 / r ** 2
            - 4 * m * A ** 2 * ud['v'] / r ** 3 + 8 * m * A ** 4 / r ** 6)


@textbook('chaplygin_sleigh', TEXTBOOK)
def _(q, u, p):
    # Neimark-Fufaev ch. III; Desloge ch. 69 thm 2: u' = a w^2,
    # (Ic + m a^2) w' = -m a u w
    m, a, J = p['m'], p['a'], p['Ic'] + p['m'] * p['a'] ** 2
    return [a * u['w'] ** 2, -m * a * u['u'] * u['w'] / J]


@textbook('chaplygin_sleigh', KIN)
def _(q, u, p):
    return [u['u'] * cos(q['th']), u['u'] * sin(q['th']), u['w']]


@textbook('chaplygin_sleigh', S_BOOK)
def _(q, u, ud, p):
    # S = m/2 |a_c|^2 + Ic/2 w'^2, a_c = (u' - a w^2) e + (u w + a w') n
    m, a = p['m'], p['a']
    return (m / 2 * ((ud['u'] - a * u['w'] ** 2) ** 2 + (u['u'] * u['w'] + a * ud['w']) ** 2)
            + p['Ic'] / 2 * ud['w'] ** 2)


@textbook('particle_rphi', TEXTBOOK)
def _(q, u, p):
    # polar acceleration components (Desloge ch. 67, ch. 69 thm 1):
    # m (vr' - vphi^2/r) = -k r - c vr, m (vphi' + vr vphi/r) = -c vphi
    r, m = q['r'], p['m']
    vr, vp = u['vr'], u['vphi']
    return [vp ** 2 / r + (-p['k'] * r - p['c'] * vr) / m, -vr * vp / r - p['c'] * vp / m]


@textbook('particle_rphi', KIN)
def _(q, u, p):
    return [u['vr'], u['vphi'] / q['r']]


@textbook('particle_rphi', S_BOOK)
def _(q, u, ud, p):
    r, m = q['r'], p['m']
    return m / 2 * ((ud['vr'] - u['vphi'] ** 2 / r) ** 2
                    + (ud['vphi'] + u['vr'] * u['vphi'] / r) ** 2)


@textbook('rolling_disk_speeds', TEXTBOOK)
def _(q, u, p):
    # SymPy's test_rolling_disc (Kane and Levinson's disc), m dropping out
    r, g, q2 = p['r'], p['g'], q['q2']
    u1, u2, u3 = u['u1'], u['u2'], u['u3']
    return [(6 * u2 * u3 * r - u3 ** 2 * r * tan(q2) + 4 * g * sin(q2)) / (5 * r),
            -2 * u1 * u3 / 3, u1 * (u3 * tan(q2) - 2 * u2)]


@textbook('bicycle_speeds', KIN)
def _(q, u, p):
    # rolling of both wheels: the rear contact moves along the heading at v,
    # the front one along the front wheel at v/cos(d), so th' = v tan(d)/b
    th, d, v = q['th'], q['d'], u['v']
    return [v * cos(th), v * sin(th), v * tan(d) / p['b'], u['s'], v / p['r'],
            v / (p['r'] * cos(d))]


@textbook('sphere_turntable_speeds', TEXTBOOK)
def _(q, u, p):
    # Desloge ch. 70 Ex 1 (T5): vx' = -w0 vy, vy' = w0 vx, wz' = 0,
    # w0 = Omega/(1 + m a^2/I), I = 2 m a^2/5 (sphere(m, a))
    w0 = p['Omega'] / (1 + Rational(5, 2))
    return [-w0 * u['vy'], w0 * u['vx'], 0]


@textbook('sphere_turntable_speeds', S_BOOK)
def _(q, u, ud, p):
    # Desloge ch. 70 Ex 1 (T5)
    m, a, Om = p['m'], p['a'], p['Omega']
    I = Rational(2, 5) * m * a ** 2
    return (m / 2 * (ud['vx'] ** 2 + ud['vy'] ** 2)
            + I / (2 * a ** 2) * ((Om * u['vx'] - ud['vy']) ** 2 + (ud['vx'] + Om * u['vy']) ** 2
                                  + a ** 2 * ud['wz'] ** 2))


# ---------------------------------------------------------------------------
# The checks.  Each returns a list of failure messages (empty: passed).

def by_name(case, sy, vals):
    q = {n: vals[sy.q[n]] for n in case.coords}
    u = {n: vals[sy.u[n]] for n in case.speeds}
    ud = {n: vals[sy.ud[n]] for n in case.speeds}
    p = {n: vals[sy.p[n]] for n in case.params}
    return q, u, ud, p


def check_methods(case, eqs, vals):
    bad = []
    ref = eqs['kane']
    for meth in ('appell', 'hamel'):
        other = eqs[meth]
        for key in ('M', 'f', 'kin'):
            for a, b in zip(ref[key], other[key]):
                x, y = num(a, vals), num(b, vals)
                if not close_exact(x, y):
                    bad.append('%s %s differs from kane: %s vs %s' % (meth, key, y, x))
                    break
        if ref['S'] is not None and other['S'] is not None:
            if not close_exact(num(ref['S'], vals), num(other['S'], vals)):
                bad.append('%s S differs from kane' % meth)
    return bad


def check_methods_symbolic(eqs):
    """The methods' differences simplify to 0 in SymPy, entry by entry (M_u,
    f_u, kinematics): equal as expressions, not only at the states drawn.
    Also how many entries qdot already printed identically."""
    bad, same, total = [], 0, 0
    ref = eqs['kane']
    for meth in ('appell', 'hamel'):
        for key in ('M', 'f', 'kin'):
            for i, (a, b) in enumerate(zip(ref[key], eqs[meth][key])):
                total += 1
                if a == b:
                    same += 1
                elif sympy.simplify(a - b) != 0:
                    bad.append('%s %s[%d] - kane\'s does not simplify to 0' % (meth, key, i))
    return bad, same, total


def kin_values(case, sy, kin, vals):
    """The velocities from the kinematics, as values of the q' symbols."""
    return {sy.qd[n]: num(kin[j], vals) for j, n in enumerate(case.coords)}


def check_kinematics(case, sy, eq, defs, cons, vals):
    bad = []
    at = dict(vals)
    at.update(kin_values(case, sy, eq['kin'], vals))
    for r, d in enumerate(defs):
        if not close_exact(num(d, at), vals[sy.u[case.speeds[r]]]):
            bad.append('def(%s) at the kinematics is %s, not the speed' % (
                case.speeds[r], num(d, at)))
    for k, c in enumerate(cons):
        if not close_exact(num(c, at), 0):
            bad.append('constraint %d violated by the kinematics: %s' % (k, num(c, at)))
    return bad


def check_appell(case, sy, eq, vals):
    S = eq['S']
    if S is None:
        return ['no S']
    bad = []
    for r, a in enumerate(case.speeds):
        for s, b in enumerate(case.speeds):
            h = num(diff(S, sy.ud[a], sy.ud[b]), vals)
            if not close_exact(h, num(eq['M'][r, s], vals)):
                bad.append('d2S/d%s\'d%s\' = %s, M_u = %s' % (a, b, h, num(eq['M'][r, s], vals)))
    return bad


def solve_ud(eq, vals):
    M = eq['M'].xreplace(vals).evalf(DIGITS)
    f = eq['f'].xreplace(vals).evalf(DIGITS)
    return list(M.LUsolve(f))


def check_textbook(case, sy, eq, vals):
    bad = []
    q, u, ud, p = by_name(case, sy, vals)
    if case.name in TEXTBOOK:
        got = solve_ud(eq, vals)
        want = [sympy.N(w, DIGITS) for w in TEXTBOOK[case.name](q, u, p)]
        for n, x, y in zip(case.speeds, got, want):
            if not close_exact(x, y):
                bad.append("%s' = %s, textbook %s" % (n, x, y))
    if case.name in KIN:
        for j, (n, y) in enumerate(zip(case.coords, KIN[case.name](q, u, p))):
            x = num(eq['kin'][j], vals)
            if not close_exact(x, sympy.N(y, DIGITS)):
                bad.append("%s' = %s from the kinematics, textbook %s" % (n, x, sympy.N(y)))
    if case.name in S_BOOK and eq['S'] is not None:
        zero = {k: 0 for k in ud}
        book = S_BOOK[case.name](q, u, ud, p) - S_BOOK[case.name](q, u, zero, p)
        x = num(eq['S'], vals)
        if not close_exact(x, sympy.N(book, DIGITS)):
            bad.append('S = %s, textbook %s' % (x, sympy.N(book, DIGITS)))
    return bad


# ---------------------------------------------------------------------------
# SymPy's KanesMethod: the systems of bench/speeds_sympy.py (the rolling disc
# of SymPy's own test_rolling_disc, built from the contact point up with the
# contact point at rest; the bicycle with dependent speeds and velocity
# constraints), with the same speeds as the examples.

def kane_systems():
    sys.path.insert(0, str(ROOT / 'bench'))
    import speeds_sympy
    return {name: build() for name, build in speeds_sympy.SYSTEMS.items()}


def check_kane(case, sy, eq, vals, ks):
    """u' (and, without dependent speeds, M_u and f_u entry by entry) from
    qdot and from KanesMethod at one state."""
    t = Symbol('t')
    at = {Function(n)(t): vals[sy.q[n]] for n in case.coords}
    at.update({Function(n)(t): vals[sy.u[n]] for n in case.speeds})
    at.update({Symbol(n): vals[sy.p[n]] for n in case.params})
    m = len(case.speeds)
    udep = ks['u'][m:]
    if udep:   # the dependent speeds from the velocity constraints
        eqs = [sympy.N(c.xreplace(at), DIGITS) for c in ks['vc']]
        at.update(sympy.solve(eqs, udep, dict=True)[0])
    Ms = ks['M'].xreplace(at).evalf(DIGITS)
    fs = ks['f'].xreplace(at).evalf(DIGITS)
    Mq = eq['M'].xreplace(vals).evalf(DIGITS)
    fq = eq['f'].xreplace(vals).evalf(DIGITS)
    bad = []
    if not udep:
        for i in range(m):
            if not close(fq[i], fs[i]):
                bad.append('f_u[%d] = %s, KanesMethod %s' % (i, fq[i], fs[i]))
            for j in range(m):
                if not close(Mq[i, j], Ms[i, j]):
                    bad.append('M_u[%d,%d] = %s, KanesMethod %s' % (i, j, Mq[i, j], Ms[i, j]))
    for n, x, y in zip(case.speeds, Mq.LUsolve(fq), Ms.LUsolve(fs)):
        if not close(x, y):
            bad.append("%s' = %s, KanesMethod %s" % (n, x, y))
    return bad


# ---------------------------------------------------------------------------

def speeds_examples():
    pat = re.compile(r'^\s*speeds\s', re.M)
    return sorted(p for p in EXAMPLES.glob('*.qd') if pat.search(p.read_text()))


def check_case(case, states, kane):
    """kane: KanesMethod's systems by example name (kane_systems)."""
    """(checks passed, failure messages) for one example."""
    if case.errors:
        return 0, ['derivation failed: ' + e for e in case.errors]
    if set(case.methods) != {'kane', 'appell', 'hamel'}:
        return 0, ['methods printed: %s' % sorted(case.methods)]
    sy = Symbols(case)
    eqs, defs, cons = expressions(case, sy)
    rng = random.Random('%d:%s' % (SEED, case.name))
    passed, fails = 0, []
    checks = [('methods', lambda v: check_methods(case, eqs, v)),
              ('kinematics', lambda v: check_kinematics(case, sy, eqs['kane'], defs, cons, v)),
              ('appell', lambda v: check_appell(case, sy, eqs['kane'], v))]
    if case.name in TEXTBOOK or case.name in KIN:
        checks.append(('textbook', lambda v: check_textbook(case, sy, eqs['kane'], v)))
    if case.name not in TEXTBOOK and case.name not in kane:
        fails.append("no textbook u' (nor KanesMethod) in check_speeds_sympy.py")
    if case.name in kane:
        ks = kane[case.name]
        checks.append(('KanesMethod', lambda v: check_kane(case, sy, eqs['kane'], v, ks)))
    bad, same, total = check_methods_symbolic(eqs)
    if bad:
        fails.extend('symbolic: ' + b for b in bad[:3])
    else:
        passed += 1
    if same < total:
        print('  %-24s %d of %d entries printed alike by the three methods' % (
            case.name, same, total))
    for _ in range(states):
        vals = random_state(case, sy, rng)
        for what, fn in checks:
            bad = fn(vals)
            if bad:
                fails.extend('%s: %s' % (what, b) for b in bad[:3])
            else:
                passed += 1
    return passed, fails


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--build', required=True)
    ap.add_argument('--states', type=int, default=STATES)
    args = ap.parse_args()
    files = speeds_examples()
    if len(files) < 7:
        print('FAIL: only %d examples with speeds in %s' % (len(files), EXAMPLES))
        return 1
    gen = Path(args.build).resolve() / 'tests' / 'gen_speeds'
    if not gen.exists():
        gen = Path(args.build).resolve() / 'gen_speeds'
    p = subprocess.run([str(gen)] + [str(f) for f in files], capture_output=True, text=True,
                       timeout=600)
    sys.stderr.write(p.stderr)
    cases = read_cases(p.stdout)
    kane = kane_systems()
    passed = failed = 0
    for case in cases:
        n, fails = check_case(case, args.states, kane)
        passed += n
        failed += len(fails)
        print('%-26s %s' % (case.name, 'ok (%d checks)' % n if not fails else 'FAIL'))
        for msg in fails:
            print('  ' + msg)
    if len(cases) != len(files):
        print('FAIL: gen_speeds printed %d of %d models (exit %d)' % (
            len(cases), len(files), p.returncode))
        failed += 1
    print('%d passed, %d failed' % (passed, failed))
    return 1 if failed or p.returncode else 0


if __name__ == '__main__':
    sys.exit(main())

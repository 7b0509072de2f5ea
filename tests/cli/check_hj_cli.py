#!/usr/bin/env python3
"""Tests of `qdot hj`, run against the built program, checked with SymPy.

    python3 tests/cli/check_hj_cli.py --build BUILD_DIR

For every examples/hj_*.qd (and kepler_polar.qd) the JSON output must name
the separation form the books give, and the SymPy script (--format sympy
--solve) is executed and checked independently of qdot's kernel:

- W substituted for S = W - E t in the printed Hamilton-Jacobi equation
  H(q, dS/dq, t) + dS/dt gives 0 at random points (SymPy's doit on the
  derivatives, Integral differentiated by the fundamental theorem);
- (dW/dq_k)^2 = p2_k at those points;
- each motion q_k(clock) of --solve satisfies (dq_k/dclock)^2 =
  (v_k / v_clock)^2, v = dH/dp with p = sqrt(p2): Hamilton's equations.

Sources: Desloge ch. 78 (the oscillator, the projectile, H = p^2 - q with
q = (t - beta)^2 - E), ch. 79 and Goldstein 10.8 (Kepler in polar and
spherical coordinates), Landau-Lifshitz §48 problems 2-3 (parabolic and
elliptic coordinates: the Stark problem, two fixed centres; eq. (48.8), the
general potential separable in spherical coordinates: the Staeckel form).  Not separable:
V = x^2/2 + y^2/2 + a x y^3 (the obstruction named).  Errors: constraints, a
singular Legendre transform, exit 2.

Prints "N passed, N failed"; exit 1 on failure."""
import argparse
import json
import random
import subprocess
import sys
from pathlib import Path

import sympy as sp

EXAMPLES = Path(__file__).resolve().parents[2] / 'examples'
results = {'passed': 0, 'failed': 0}
SEED = 1478
POINTS = 4

# example: (form, number of closed motions, coordinate ranges)
CASES = {
    'hj_oscillator': ('one coordinate', 1, {'x': (-1, 1)}),
    'hj_desloge78': ('one coordinate', 1, {'q': (-1, 1)}),
    'hj_projectile': ('cyclic', 2, {'x': (-1, 1), 'y': (-1, 1)}),
    'hj_anisotropic': ('additive', 2, {'x': (-1, 1), 'y': (-1, 1)}),
    'kepler_polar': ('cyclic', 1, {'r': (0.5, 2), 'theta': (-3, 3)}),
    'hj_kepler_spherical': ('cyclic + Liouville', 1,
                            {'r': (0.5, 2), 'theta': (0.3, 2.8), 'phi': (-3, 3)}),
    'hj_stark': ('cyclic + Liouville', 0, {'xi': (0.3, 2), 'eta': (0.3, 2), 'phi': (-3, 3)}),
    'hj_two_centres': ('Liouville', 0, {'s': (0.2, 2), 'u': (-3, 3)}),
    'hj_prolate': ('cyclic + Liouville', 0, {'xi': (1.1, 3), 'eta': (-0.9, 0.9), 'phi': (-3, 3)}),
    'hj_staeckel': ('Staeckel', 0, {'r': (0.5, 2), 'theta': (0.3, 2.8), 'phi': (-3, 3)}),
}


def check(name, ok, detail=''):
    results['passed' if ok else 'failed'] += 1
    if not ok:
        print('FAIL %s %s' % (name, detail))


def run(qdot, *args):
    p = subprocess.run([qdot, *args], capture_output=True, text=True, timeout=120)
    return p.returncode, p.stdout, p.stderr


def script(qdot, path):
    rc, out, err = run(qdot, 'hj', str(path), '--format', 'sympy', '--solve')
    if rc != 0:
        raise RuntimeError('exit %d: %s' % (rc, err))
    ns = {}
    exec(out, ns)
    return ns


def plain(ns, coords):
    """q(t) -> a plain symbol q_, for each coordinate."""
    t = ns['t']
    return {ns[q](t): sp.Symbol(q + '_') for q in coords}


def random_point(rng, ns, coords, ranges, consts, p2):
    """Values for q, the constants and the parameters where every p2 > 0."""
    free = set()
    for e in p2:
        free |= e.free_symbols
    for _ in range(500):
        v = {sp.Symbol(q + '_'): rng.uniform(*ranges[q]) for q in coords}
        # by name: a set's order follows PYTHONHASHSEED, and the draws must not
        for s in sorted(free, key=lambda x: x.name):
            if s not in v:
                v[s] = rng.uniform(-2, 2) if s.name in consts else rng.uniform(0.5, 2)
        if all(complex(e.subs(v).evalf()).real > 1e-3 for e in p2):
            return v
    raise RuntimeError('no point with every p2 > 0')


def check_example(qdot, rng, name, form, nmotion, ranges):
    path = EXAMPLES / (name + '.qd')
    rc, out, err = run(qdot, 'hj', str(path), '--format', 'json', '--solve')
    check(name + ' json exit', rc == 0, err)
    if rc:
        return
    d = json.loads(out)
    keys = ('separable', 'form', 'separation', 'W', 'constants', 'energy_constant')
    check(name + ' json keys', all(k in d for k in keys), str(list(d)))
    check(name + ' separable', d['separable'] and d['form'] == form, '%s %s' % (d['form'], d['why']))
    check(name + ' energy last', d['constants'][-1] == d['energy_constant'] == 'E', str(d['constants']))
    closed = [s for s in d['separation'] if s['motion'] is not None]
    check(name + ' motions', len(closed) == nmotion, str([s['coordinate'] for s in closed]))

    ns = script(qdot, path)
    coords = [s['coordinate'] for s in d['separation']]
    to_plain = plain(ns, coords)
    Q = [to_plain[ns[q](ns['t'])] for q in coords]
    E = sp.Symbol('E')
    W = ns['W'].subs(to_plain)
    p2 = [e.subs(to_plain) for e in ns['p2']]
    consts = set(d['constants']) | {'beta_' + q for q in coords}
    # the HJ equation with S = W - E t
    u = sp.symbols('_u0:%d' % (len(coords) + 1))
    S = sp.Lambda(u, W.subs(dict(zip(Q, u[:-1]))) - E * u[-1])
    hj = ns['HJ'].replace(ns['S'], S).doit().subs(to_plain)
    grads = [sp.diff(W, q).doit() for q in Q]
    for i in range(POINTS):
        v = random_point(rng, ns, coords, ranges, consts, p2)
        v[ns['t']] = rng.uniform(-1, 1)
        r = complex(hj.subs(v).evalf())
        check('%s HJ(W) = 0 at point %d' % (name, i), abs(r) < 1e-9, str(r))
        for k, q in enumerate(coords):
            r = complex((grads[k]**2 - p2[k]).subs(v).evalf())
            check('%s (dW/d%s)^2 = p2' % (name, q), abs(r) < 1e-9, str(r))
    check_motion(rng, ns, d, coords, to_plain, p2, ranges, consts)


def check_motion(rng, ns, d, coords, to_plain, p2, ranges, consts):
    """(dq/dclock)^2 = (v_q/v_clock)^2 on the motion, v = dH/dp at p = sqrt(p2)."""
    H = ns['H'].subs(to_plain)
    at_p = {}
    for k, s in enumerate(d['separation']):
        cyc = s['cyclic'] and s['constant'] != d['energy_constant']
        at_p[sp.Symbol(s['momentum'])] = sp.Symbol(s['constant']) if cyc else sp.sqrt(p2[k])
    vel = {s['coordinate']: sp.diff(H, sp.Symbol(s['momentum'])).subs(at_p) for s in d['separation']}
    t = ns['t']
    for q, (clock, motion) in ns['motion'].items():
        clock_name = 't' if clock == t else str(clock.func)
        clock_sym = t if clock == t else sp.Symbol(clock_name + '_')
        m = motion.subs(to_plain)
        ratio = vel[q] / (vel[clock_name] if clock_name != 't' else 1)
        lhs = sp.diff(m, clock_sym)**2
        rhs = (ratio**2).subs(sp.Symbol(q + '_'), m)
        for i in range(POINTS):
            v = random_point(rng, ns, coords, ranges, consts, p2)
            for c in consts:
                if c.startswith('beta_'):
                    v[sp.Symbol(c)] = rng.uniform(-1, 1)
            v[t] = rng.uniform(-1, 1)
            if clock_sym != t:
                v[clock_sym] = rng.uniform(-3, 3)
            # at 30 digits and relative: near a pole of the orbit (1 + e cos -> 0)
            # both sides are large and a 15-digit absolute test fails on round-off
            a, b = (complex(x.evalf(30, subs=v)) for x in (lhs, rhs))
            r = abs(a - b) / max(1.0, abs(a), abs(b))
            check('%s motion %s(%s)' % (d['model'], q, clock_name), r < 1e-10, '%r %r' % (a, b))


def check_textbook(qdot):
    """Desloge ch. 78: W = (2/3)(E + q)^(3/2), q(t) = (t - beta)^2 - E."""
    ns = script(qdot, EXAMPLES / 'hj_desloge78.qd')
    q, t, E, b = ns['q'](ns['t']), ns['t'], sp.Symbol('E'), sp.Symbol('beta_q')
    check('desloge78 W', sp.simplify(ns['W'] - sp.Rational(2, 3) * (E + q)**sp.Rational(3, 2)) == 0,
          str(ns['W']))
    check('desloge78 q(t)', sp.simplify(ns['motion']['q'][1] - ((t - b)**2 - E)) == 0,
          str(ns['motion']))


def check_formats(qdot):
    """text and LaTeX print the same story; --energy renames E everywhere."""
    path = str(EXAMPLES / 'hj_projectile.qd')
    rc, out, err = run(qdot, 'hj', path, '--solve')
    check('text', rc == 0 and 'separable: yes (cyclic' in out and 'y(t) = ' in out, out + err)
    rc, out, err = run(qdot, 'hj', path, '--format', 'latex')
    check('latex', rc == 0 and '% separable: yes' in out and '\\alpha_{x}' in out, out + err)
    rc, out, err = run(qdot, 'hj', path, '--format', 'json', '--energy', 'h')
    d = json.loads(out) if rc == 0 else {}
    check('--energy', d.get('energy_constant') == 'h' and 'h' in d['separation'][1]['p2']
          and 'E' not in d['W'], out + err)


def check_failures(qdot, tmp):
    rc, out, err = run(qdot, 'hj', str(EXAMPLES / 'hj_coupled.qd'), '--format', 'json')
    d = json.loads(out) if rc == 0 else {}
    check('coupled not separable', rc == 0 and d['separable'] is False and d['W'] is None, out + err)
    check('coupled obstruction', 'a*x*y^3 couples x and y' in d.get('why', ''), d.get('why', ''))
    con = tmp / 'constrained.qd'
    con.write_text('coordinates x, y\nparameters m = 1\nparticle m at (x, y)\n'
                   'constraint c: x^2 + y^2 = 1\n')
    rc, out, err = run(qdot, 'hj', str(con))
    check('constraint refused', rc == 2 and 'independent coordinates' in err, '%d %s' % (rc, err))
    sing = tmp / 'singular.qd'
    sing.write_text("coordinates x, y\nL = x*y' - x^2/2 - y^2/2\n")
    rc, out, err = run(qdot, 'hj', str(sing))
    check('singular Legendre refused', rc == 2 and 'singular' in err, '%d %s' % (rc, err))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--build', required=True)
    args = ap.parse_args()
    qdot = str(Path(args.build) / 'qdot')
    rng = random.Random(SEED)
    for name, (form, nmotion, ranges) in CASES.items():
        try:
            check_example(qdot, rng, name, form, nmotion, ranges)
        except Exception as exc:  # a crash, bad JSON, a SymPy failure
            check(name, False, '%s: %s' % (type(exc).__name__, exc))
    check_textbook(qdot)
    check_formats(qdot)
    import tempfile
    with tempfile.TemporaryDirectory() as d:
        check_failures(qdot, Path(d))
    print('%d passed, %d failed' % (results['passed'], results['failed']))
    return 1 if results['failed'] else 0


if __name__ == '__main__':
    sys.exit(main())

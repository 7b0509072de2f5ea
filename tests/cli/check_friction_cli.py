#!/usr/bin/env python3
"""tests/cli/check_friction_cli.py - Coulomb friction in `qdot simulate`, end to end (issue 18).

Each model of examples/friction_*.qd is run with `--format json` and its rows,
`transitions` and stats are compared with the closed forms, derived here (by
hand or with SymPy), never from qdot's output; the derivations and their
sources are here, next to each check.

- friction_sphere_slides.qd: a ball struck with no spin slides, then rolls
  from t* = 2 v0/(7 mu g) at 5 v0/7 (Byerly Art. 10b, seed-byerly.md TC21),
  the cylinder (--set kappa=0.5) from v0/(3 mu g) at 2 v0/3; friction took
  m v0^2/7 (m v0^2/6).  Struck above the centre (top spin), it rolls on at the
  speed that keeps the angular momentum about the contact point.
- friction_sphere_incline.qd: from rest the ball rolls (x'' = 5/7 g sin al,
  no transition) iff tan al <= 7 mu/2, else it slips with x'' = g (sin al -
  mu cos al) and slip S = g t (sin al - 7/2 mu cos al) (Byerly Art. 9 Ex. 2);
  both sides of the threshold, one percent from it.
- friction_block_incline.qd: below the static angle a block at rest stays at
  rest, but sent down the slope it slides for ever when tan al > mu_k (static
  versus kinetic); with tan al < mu_k it stops at v0/(g (mu_k cos al - sin al))
  and sticks; above the static angle it slips from rest.
- friction_wedge_sphere.qd: a spinning ball set on a rough wedge on a smooth
  table (Byerly Art. 28b, Art. 9 Ex. 3 / TC19): the slipping phase by SymPy
  (constant accelerations and normal force), the stick time, then TC19's
  rolling; horizontal momentum 0; spun both ways; spun up the face, as mu
  rises to mu_c (SymPy: where N = N0/(1 - c mu) has its pole) the velocities
  after the stick tend to Byerly's for a perfectly rough face, and beyond
  mu_c there is Painleve's paradox, exit 1.
- friction_billiard.qd (`rolls ... friction`, a 2-D contact): the slip keeps
  its direction, |S| = S0 - 7/2 mu g t, the centre draws the parabola
  c0 + v0 t - mu g S0/|S0| t^2/2, rolling from 2 S0/(7 mu g), spin about the
  vertical constant (Byerly Art. 10b).
- friction_particle_incline.qd (`friction MU on POINT against CONSTRAINT`):
  with mu = tan al, v (1 + cos phi) = v0 at every row and the speed tends to v0/2.
- friction_stick_slip.qd: the belt-driven oscillator's stick/slip times, the
  limit cycle's period 2 D/vb + (pi + 2 b)/w and amplitude sqrt(D^2 + (vb/w)^2)
  about mu_k m g/k, and the energy friction dissipates, mu_k m g (vb t_slip +
  2 D) per slip arc; the belt's work (`surface_work`), k (x^2 - x_a^2)/2 over
  a stick that began at x_a (x' = vb: the integral of k x vb) and mu_k m g vb
  per unit time of slip, row by row against that closed form, and the balance
  E + dissipated - surface_work = E(0) row by row and in the stats.
- In every run on a fixed surface: E(t) + dissipated(t) = E(0) row by row and
  the stats `friction_dissipated`, `energy_balance_error`; no `surface_work`
  column and the stat `surface_work` exactly 0.
- Errors (exit 2, FILE:LINE:COL, the caret, a hint): friction on a holonomic
  constraint, a negative MU, an unknown normal constraint.

A part the engine does not give (a model `qdot check` refuses, a column or a
stat missing, a command that fails) is a FAILURE with what is missing named:
these features are in qdot, and a qdot that lost one must not pass.  The only
skip is for a missing prerequisite of the test itself (SymPy), reported to
ctest as skipped (exit 77, SKIP_RETURN_CODE).

Usage: check_friction_cli.py --build BUILD_DIR
Prints "N passed, N failed, N skipped"; exit 1 on any failure, else 77 when
something was skipped, else 0.
"""
import argparse
import json
import math
import os
import subprocess
import sys
import tempfile
from math import atan, cos, pi, sin, sqrt, tan
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
EX = ROOT / 'examples'
RTOL = '1e-12'
TOL = 1e-8            # closed forms against runs at rtol 1e-12, events located to round-off

results = {'passed': 0, 'failed': 0, 'skipped': 0}


def check(cond, what):
    if cond:
        results['passed'] += 1
    else:
        results['failed'] += 1
        print('FAIL', what)
    return cond


def skip(what, prerequisite):
    """A part the test cannot run here: a prerequisite of the test is missing."""
    results['skipped'] += 1
    print('SKIP %s: %s' % (what, prerequisite))


def lacks(what, feature):
    """The engine does not give what the part checks: a failure, never a skip."""
    check(False, '%s: qdot does not give %s' % (what, feature))


def close(got, want, tol=TOL, scale=None):
    return abs(got - want) <= tol * (scale if scale is not None else max(1.0, abs(want)))


def run(qdot, *args):
    p = subprocess.run([qdot, *map(str, args)], capture_output=True, text=True, timeout=120)
    return p.returncode, p.stdout, p.stderr


class Run:
    """A `qdot simulate --format json` run: rows by column name, transitions, stats."""

    def __init__(self, data):
        self.data = data
        cols = data['columns']
        self.rows = [dict(zip(cols, r)) for r in data['rows']]
        self.cols = cols
        self.transitions = data.get('transitions', [])

    def col(self, name):
        return [r[name] for r in self.rows]

    def contact(self, prefix='slip_'):
        names = [c[len(prefix):] for c in self.cols if c.startswith(prefix)]
        return names[0] if len(names) == 1 else None


def supported(qdot, model):
    """None when `qdot check` reads the model, else the first line of its error."""
    rc, out, err = run(qdot, 'check', model)
    return None if rc == 0 else (err.strip().splitlines() or ['exit %d' % rc])[0][:200]


def simulate(qdot, what, model, *args):
    """The run, or None (with a FAIL said) when the engine cannot give it."""
    missing = supported(qdot, model)
    if missing:
        lacks(what, 'the model statement %s uses (qdot check: %s)' % (Path(model).name, missing))
        return None
    rc, out, err = run(qdot, 'simulate', model, '--method', 'dop853', '--rtol', RTOL,
                       '--format', 'json', *args)
    if not check(rc == 0, '%s: exit %d: %s' % (what, rc, err.strip()[:400])):
        return None
    data = json.loads(out)
    if 'transitions' not in data or not any(c.startswith('mode_') for c in data['columns']):
        lacks(what, 'hybrid stick/slip in simulate (no `transitions` or `mode_` column)')
        return None
    return Run(data)


def check_balance(what, r, e0=None, scale=0.0):
    """E(t) + dissipated(t) = E(0) row by row, and the stats that report it; relative
    to the largest |E| or to scale, an energy of the motion (T + V may stay 0 on an
    incline, where T = -V grows)."""
    if 'dissipated' not in r.cols:
        lacks(what + ': energy balance', 'the `dissipated` column')
        return
    e0 = r.rows[0]['energy'] if e0 is None else e0
    scale = max(abs(e0), max(abs(x['energy']) for x in r.rows), scale, 1e-300)
    worst = max(abs(x['energy'] + x['dissipated'] - e0) for x in r.rows) / scale
    check(worst < 1e-9, '%s: E + dissipated - E0 up to %.3g of E' % (what, worst))
    check(all(b['dissipated'] >= a['dissipated'] - 1e-12 * scale
              for a, b in zip(r.rows, r.rows[1:])), '%s: dissipated decreases' % what)
    st = r.data
    if 'friction_dissipated' in st and 'energy_balance_error' in st:
        check(close(st['friction_dissipated'], r.rows[-1]['dissipated'], 1e-12, scale),
              '%s: friction_dissipated %r, last row %r' % (what, st['friction_dissipated'],
                                                          r.rows[-1]['dissipated']))
        check(st['energy_balance_error'] < 1e-9,
              '%s: energy_balance_error %r' % (what, st['energy_balance_error']))
        # a surface at rest does no work: the stat is 0 and no column is added
        check('surface_work' not in r.cols and st.get('surface_work') == 0,
              '%s: surface_work %r on a fixed surface' % (what, st.get('surface_work')))
    else:
        lacks(what + ': JSON stats', '`friction_dissipated` and `energy_balance_error`')


def check_transitions(what, r, want):
    """want: [(t, from, to)] for the only contact, after the start (a transition
    listed at the start time is the initial choice of mode, not checked here)."""
    got = [x for x in r.transitions if x['t'] > r.rows[0]['t']]
    ok = check(len(got) == len(want), '%s: transitions %r, want %r' % (what, got, want))
    contact = r.contact()
    for x, (t, a, b) in zip(got, want) if ok else ():
        check(close(x['t'], t) and x['from'] == a and x['to'] == b and
              (contact is None or x['contact'] == contact),
              '%s: transition %r, want t = %.15g %s -> %s' % (what, x, t, a, b))


def modes_agree(what, r, name, t_switch, before, after):
    """The mode column: `before` up to t_switch, `after` from it (rows at t_switch
    itself may be either)."""
    col = 'mode_' + name
    bad = [x['t'] for x in r.rows
           if (x['t'] < t_switch - 1e-9 and x[col] != before) or
           (x['t'] > t_switch + 1e-9 and x[col] != after)]
    check(not bad, '%s: %s wrong at t = %r' % (what, col, bad[:5]))


# ---------------------------------------------------------------------------
# The ball that slides, then rolls (Byerly Art. 10b; seed-byerly.md TC21 and its extension D)

def ball_slides(qdot, kappa, x0d, th0d, what):
    m, a, g, mu = 0.17, 0.028, 9.81, 0.2           # examples/friction_sphere_slides.qd
    args = ['--t-end', 0.6, '--dt', 0.01, '--initial', "x = 0, th = 0, x' = %r, th' = %r" % (x0d, th0d)]
    if kappa != 0.4:
        args += ['--set', 'kappa=%r' % kappa]
    r = simulate(qdot, what, EX / 'friction_sphere_slides.qd', *args)
    if r is None:
        return
    s0 = x0d + a * th0d                             # the contact point's velocity
    rate = (1 + 1 / kappa) * mu * g                 # |S|' = -(1 + a^2/k^2) mu g
    tstar = abs(s0) / rate
    sign = math.copysign(1, s0)
    # rolling keeps kappa m a^2 th' - m a x' (the angular momentum about the contact point)
    v_end = (x0d - kappa * a * th0d) / (1 + kappa)
    check_transitions(what, r, [(tstar, 'slip', 'stick')])
    name = r.contact()
    for x in r.rows:
        t = x['t']
        if t < tstar:
            want_v, want_x = x0d - sign * mu * g * t, x0d * t - sign * mu * g * t * t / 2
            want_s = abs(s0) - rate * t
        else:
            want_v = v_end
            want_x = x0d * tstar - sign * mu * g * tstar ** 2 / 2 + v_end * (t - tstar)
            want_s = 0.0
        ok = close(x["x'"], want_v) and close(x['x'], want_x) and \
            (name is None or close(abs(x['slip_' + name]), want_s))
        if not check(ok, "%s: t = %r: x = %r, x' = %r, slip %r; want %r, %r, %r"
                     % (what, t, x['x'], x["x'"], x.get('slip_' + str(name)), want_x, want_v,
                        want_s)):
            break
    last = r.rows[-1]
    check(close(last["th'"], -v_end / a), "%s: th' %r at the end, rolling -v/a = %r"
          % (what, last["th'"], -v_end / a))
    if name:
        modes_agree(what, r, name, tstar, 1, 0)
    e0 = m / 2 * x0d ** 2 + kappa * m * a * a / 2 * th0d ** 2
    e1 = m / 2 * v_end ** 2 * (1 + kappa)
    check_balance(what, r, e0)
    if 'dissipated' in r.cols:
        check(close(last['dissipated'], e0 - e1, 1e-9, e0),
              '%s: dissipated %r, want %r' % (what, last['dissipated'], e0 - e1))
    return tstar, v_end


def check_sliding(qdot):
    v0 = 2.0
    ball_slides(qdot, 0.4, v0, 0.0, 'sphere slides (t* = 2 v0/(7 mu g), 5 v0/7)')
    ball_slides(qdot, 0.5, v0, 0.0, 'cylinder slides (t* = v0/(3 mu g), 2 v0/3)')
    # A cue striking at h = 0.7 a above the centre: x' = P/m, kappa m a^2 th' = -P h.
    a, h = 0.028, 0.7 * 0.028
    got = ball_slides(qdot, 0.4, v0, -h * v0 / (0.4 * a * a), 'billiard ball with top spin')
    if got:
        check(close(got[1], 5 * v0 * (1 + h / a) / 7),
              'top spin: rolls at %r, want 5 v0 (1 + h/a)/7' % got[1])


# ---------------------------------------------------------------------------
# The ball on a rough incline (Byerly Art. 9 Ex. 2: rolls iff mu >= (2/7) tan al)

def check_incline(qdot):
    m, a, g, al = 1.0, 0.1, 9.81, 0.5
    mu_edge = 2 * tan(al) / 7
    for mu in (1.01 * mu_edge, 0.99 * mu_edge, 0.05):
        rolls = mu >= mu_edge
        what = 'sphere on incline, mu = %.6g (%s)' % (mu, 'rolls' if rolls else 'slips')
        r = simulate(qdot, what, EX / 'friction_sphere_incline.qd', '--t-end', 1, '--dt', 0.05,
                     '--set', 'mu=%r' % mu)
        if r is None:
            continue
        acc = 5 * g * sin(al) / 7 if rolls else g * (sin(al) - mu * cos(al))
        slip_rate = 0.0 if rolls else g * (sin(al) - 3.5 * mu * cos(al))
        name = r.contact()
        bad = [x['t'] for x in r.rows
               if not (close(x['x'], acc * x['t'] ** 2 / 2) and close(x["x'"], acc * x['t']) and
                       (name is None or close(x['slip_' + name], slip_rate * x['t'])))]
        check(not bad, '%s: x, x\' or the slip off the closed form (x\'\' = %r) at t = %r'
              % (what, acc, bad[:4]))
        if name:
            mode = 0 if rolls else 1
            bad = [x['t'] for x in r.rows[1:] if x['mode_' + name] != mode]
            check(not bad, '%s: mode not %d at t = %r' % (what, mode, bad[:4]))
        check_transitions(what, r, [])
        check_balance(what, r, scale=m * g * sin(al) * r.rows[-1]['x'])
        if 'dissipated' in r.cols:
            # the friction mu m g cos al works against the slip g t (sin al - 7/2 mu cos al)
            want = 0.0 if rolls else mu * m * g * cos(al) * slip_rate / 2
            check(close(r.rows[-1]['dissipated'], want, 1e-9),
                  '%s: dissipated %r, want %r' % (what, r.rows[-1]['dissipated'], want))


# ---------------------------------------------------------------------------
# The block on an incline: static versus kinetic friction

def check_block(qdot):
    m, g, al, mu_s = 2.0, 9.81, 0.5, 0.6
    model = EX / 'friction_block_incline.qd'
    what = 'block at rest below the static angle'
    r = simulate(qdot, what, model, '--t-end', 2, '--dt', 0.1)
    if r is not None:
        check(all(abs(x['x']) < 1e-12 and abs(x["x'"]) < 1e-12 for x in r.rows),
              '%s: it moved (x = %r)' % (what, r.rows[-1]['x']))
        check_transitions(what, r, [])
        check_balance(what, r, scale=m * g)       # the work of gravity down 1 m of slope

    what = 'block sent down between the kinetic and static angles'
    r = simulate(qdot, what, model, '--t-end', 2, '--dt', 0.1, '--initial', "x = 0, x' = 1")
    if r is not None:
        acc = g * (sin(al) - 0.4 * cos(al))
        bad = [x['t'] for x in r.rows if not (close(x['x'], x['t'] + acc * x['t'] ** 2 / 2) and
                                               close(x["x'"], 1 + acc * x['t']))]
        check(not bad, "%s: off x'' = g (sin al - mu_k cos al) at t = %r" % (what, bad[:4]))
        check_transitions(what, r, [])
        check_balance(what, r)

    what = 'block sent down below the kinetic angle'
    mu_k = 0.58
    r = simulate(qdot, what, model, '--t-end', 5, '--dt', 0.1, '--initial', "x = 0, x' = 1",
                 '--set', 'mu_k=%r' % mu_k)
    if r is not None:
        dec = g * (mu_k * cos(al) - sin(al))
        ts, xs = 1 / dec, 1 / (2 * dec)
        check_transitions(what, r, [(ts, 'slip', 'stick')])
        bad = [x['t'] for x in r.rows
               if not close(x['x'], x['t'] - dec * x['t'] ** 2 / 2 if x['t'] < ts else xs)]
        check(not bad, '%s: x off the closed form (stops at %r after %r) at t = %r'
              % (what, ts, xs, bad[:4]))
        check_balance(what, r)
        if 'dissipated' in r.cols:
            want = m / 2 + m * g * sin(al) * xs
            check(close(r.rows[-1]['dissipated'], want, 1e-9),
                  '%s: dissipated %r, want m v0^2/2 + m g sin(al) d = %r'
                  % (what, r.rows[-1]['dissipated'], want))

    what = 'block at rest above the static angle'
    al2 = 0.7
    assert tan(al2) > mu_s
    r = simulate(qdot, what, model, '--t-end', 1, '--dt', 0.1, '--set', 'al=%r' % al2)
    if r is not None:
        acc = g * (sin(al2) - 0.4 * cos(al2))
        bad = [x['t'] for x in r.rows if not close(x['x'], acc * x['t'] ** 2 / 2)]
        check(not bad, '%s: x off g (sin al - mu_k cos al) t^2/2 at t = %r' % (what, bad[:4]))
        check_transitions(what, r, [])
        check_balance(what, r)


# ---------------------------------------------------------------------------
# The spinning ball set on a rough wedge (Byerly Art. 28b, Art. 9 Ex. 3): derived with SymPy

def wedge_equations(p, mu):
    """Lagrange's equations of the model's T and V with the multipliers N (contact) and
    F (slip), M q'' - f - A^T lambda = 0, by SymPy: (equations, accelerations, N, F, a)."""
    import sympy as sp
    assert p['al'] == pi / 6
    M, m, a, g = (sp.nsimplify(p[k]) for k in ('M', 'm', 'a', 'g'))
    al = sp.pi / 6
    t = sp.Symbol('t')
    x, y, z, th = (sp.Function(n)(t) for n in ('x', 'y', 'z', 'th'))
    q = [x, y, z, th]
    cx = x - y * sp.cos(al) - z * sp.sin(al)
    cy = -y * sp.sin(al) + z * sp.cos(al)
    T = M / 2 * x.diff(t) ** 2 + m / 2 * (cx.diff(t) ** 2 + cy.diff(t) ** 2) + \
        sp.Rational(2, 5) * m * a ** 2 / 2 * th.diff(t) ** 2
    L = T - m * g * cy
    acc = sp.symbols('xdd ydd zdd thdd')
    N, F = sp.symbols('N F')
    sub = {qi.diff(t, 2): ai for qi, ai in zip(q, acc)}
    eqs = [sp.expand((sp.diff(L.diff(qi.diff(t)), t) - L.diff(qi)).subs(sub)) for qi in q]
    # the constraints' rows: contact z - a (0, 0, 1, 0), slip y' - a th' (0, 1, 0, -a)
    rows = ((0, 0, 1, 0), (0, 1, 0, -a))
    lag = [eqs[j] - N * rows[0][j] - F * rows[1][j] for j in range(4)] + [acc[2]]
    return lag, list(acc), N, F, a


def wedge_closed_form(p):
    """The accelerations, N and F while the ball slips and while it rolls.  The slip
    y' - a th' starts at -a Omega, so the friction is F = sgn(Omega) mu N."""
    import sympy as sp
    lag, acc, N, F, a = wedge_equations(p, p['mu'])
    mu = sp.nsimplify(p['mu'])
    sign = 1 if p['Omega'] > 0 else -1
    slipping = sp.solve(lag + [F - sign * mu * N], acc + [N, F], dict=True)[0]
    rolling = sp.solve(lag + [acc[1] - a * acc[3]], acc + [N, F], dict=True)[0]
    num = lambda d: {str(k): float(v) for k, v in d.items()}
    return num(slipping), num(rolling)


def wedge_painleve_mu(p):
    """The mu beyond which the ball spun up the face (Omega < 0) has no consistent
    slipping: N = N0/(1 - c mu) changes sign through infinity (Painleve)."""
    import sympy as sp
    lag, acc, N, F, a = wedge_equations(p, None)
    mu = sp.Symbol('mu', positive=True)
    sol = sp.solve(lag + [F + mu * N], acc + [N, F], dict=True)[0]
    roots = sp.solve(sp.denom(sp.together(sol[N])), mu)
    return float(roots[0]) if len(roots) == 1 else None


def wedge_run(qdot, what, p):
    slipping, rolling = wedge_closed_form(p)
    M, m, a, al, g, mu, Om = (p[k] for k in ('M', 'm', 'a', 'al', 'g', 'mu', 'Omega'))
    check(slipping['N'] > 0, '%s: SymPy gives N = %r < 0 while it slips' % (what, slipping['N']))
    # TC19 (Byerly Art. 9 Ex. 3): y'' = 5 (M + m) g sin al/(7 (M + m) - 5 m cos^2 al)
    check(close(rolling['ydd'], 5 * (M + m) * g * sin(al) / (7 * (M + m) - 5 * m * cos(al) ** 2),
                1e-12), 'wedge: SymPy rolling y\'\' %r is not TC19\'s' % rolling['ydd'])
    check(abs(rolling['F']) <= mu * rolling['N'], 'wedge: mu = %r too small to roll' % mu)
    srate = slipping['ydd'] - a * slipping['thdd']           # the slip's constant rate
    tstar = a * Om / srate
    r = simulate(qdot, what, EX / 'friction_wedge_sphere.qd', '--t-end', 0.5, '--dt', 0.01,
                 '--output', 'lambda_contact', '--set', 'mu=%r' % mu, '--set', 'Omega=%r' % Om)
    if r is None:
        return None
    check_transitions(what, r, [(tstar, 'slip', 'stick')])
    ys, yds = slipping['ydd'] * tstar ** 2 / 2, slipping['ydd'] * tstar
    xs, xds = slipping['xdd'] * tstar ** 2 / 2, slipping['xdd'] * tstar
    bad = []
    for x in r.rows:
        t = x['t']
        if t < tstar:
            want = dict(x=slipping['xdd'] * t * t / 2, y=slipping['ydd'] * t * t / 2,
                        th=Om * t + slipping['thdd'] * t * t / 2)
            want["th'"] = Om + slipping['thdd'] * t
            n = slipping['N']
        else:
            u = t - tstar
            want = dict(x=xs + xds * u + rolling['xdd'] * u * u / 2,
                        y=ys + yds * u + rolling['ydd'] * u * u / 2)
            want["th'"] = (yds + rolling['ydd'] * u) / a
            n = rolling['N']
        if abs(t - tstar) < 1e-9:             # the rows at the switch: either side's N
            n = x.get('lambda_contact', n)
        px = (M + m) * x["x'"] - m * (x["y'"] * cos(al) + x["z'"] * sin(al))
        if not (all(close(x[k], v) for k, v in want.items()) and abs(px) < 1e-9 and
                ('lambda_contact' not in x or close(x['lambda_contact'], n))):
            bad.append((t, {k: x[k] for k in want}, want, px, x.get('lambda_contact'), n))
    check(not bad, '%s: off the closed form at %r' % (what, bad[:2]))
    check_balance(what, r)
    return r


def byerly_limit(qdot, p, mu_c):
    """Just below mu_c the slip ends in microseconds, N and F nearly impulses in the
    ratio mu_c: the velocities after it are Byerly's for a perfectly rough face (Art.
    28b): (M + m) x' = m y' cos al, y' = k^2 a Omega/(k^2 + a^2 - a^2 m cos^2(al)/(M + m)),
    k^2 = 2 a^2/5.  (Spun down the face Byerly's answer needs the face to pull the ball,
    a normal impulse -m sin(al) dx' < 0: no mu gives it.)"""
    M, m, a, al, Om = p['M'], p['m'], p['a'], p['al'], -20
    what = 'spinning ball up a rough wedge, mu -> mu_c: Byerly Art. 28b'
    _, rolling = wedge_closed_form(dict(p, Omega=Om))
    r = simulate(qdot, what, EX / 'friction_wedge_sphere.qd', '--t-end', 0.01, '--dt', 0.01,
                 '--set', 'mu=%r' % (mu_c * (1 - 1e-4)), '--set', 'Omega=%r' % Om)
    if r is None or not check(len(r.transitions) >= 1, '%s: no transition' % what):
        return
    k2 = 0.4 * a * a
    yd = k2 * a * Om / (k2 + a * a - a * a * m * cos(al) ** 2 / (M + m))
    t1 = [x['t'] for x in r.transitions if x['to'] == 'stick'][0]
    row = [x for x in r.rows if x['t'] >= t1][0]
    yd_now = yd + rolling['ydd'] * (row['t'] - t1)
    xd_now = m * yd * cos(al) / (M + m) + rolling['xdd'] * (row['t'] - t1)
    check(t1 < 1e-5 and close(row["y'"], yd_now, 1e-4, abs(yd)) and
          close(row["x'"], xd_now, 1e-4, abs(yd)),
          "%s: stick at %r, y' = %r, x' = %r; Byerly's %r, %r"
          % (what, t1, row["y'"], row["x'"], yd_now, xd_now))


def check_wedge(qdot):
    p = dict(M=3, m=1, a=0.1, al=pi / 6, g=9.8, mu=0.3, Omega=20)
    try:
        import sympy  # noqa: F401
    except ImportError:
        skip('spinning ball on a rough wedge', 'SymPy (python3-sympy) is missing here')
        return
    wedge_run(qdot, 'spinning ball on a rough wedge, rolling down', p)
    # Spun the other way the friction pushes the ball up the face and the wedge into it;
    # the reaction on the wedge then raises N with mu, without bound at mu_c: beyond it
    # no slipping is consistent and sticking cannot hold a slip (Painleve's paradox).
    mu_c = wedge_painleve_mu(p)
    if not check(mu_c is not None and 1 < mu_c < 100, 'wedge: Painleve mu %r' % mu_c):
        return
    r = wedge_run(qdot, 'spinning ball on a rough wedge, spun up the face',
                  dict(p, Omega=-20, mu=mu_c / 2))
    byerly_limit(qdot, p, mu_c)
    what = "spinning ball on a rough wedge, mu = 2 mu_c (Painleve's paradox)"
    if r is None:
        lacks(what, 'hybrid stick/slip in simulate')
        return
    rc, out, err = run(qdot, 'simulate', EX / 'friction_wedge_sphere.qd', '--t-end', 0.5,
                       '--method', 'dop853', '--rtol', RTOL, '--set', 'Omega=-20',
                       '--set', 'mu=%r' % (2 * mu_c), '--format', 'json')
    check(rc == 1 and 'painlev' in err.lower(),
          '%s: exit %d, stderr %r' % (what, rc, err[-400:]))


# ---------------------------------------------------------------------------
# The billiard ball on a rough table in 3-D (Byerly Art. 10b): a 2-D contact

def omega_space(q, v):
    """w of euler(phi, theta, psi) = Rz(phi) Rx(theta) Rz(psi):
    phi' e_z + theta' Rz(phi) e_x + psi' Rz(phi) Rx(theta) e_z."""
    ph, th = q['phi'], q['theta']
    e1 = (cos(ph), sin(ph), 0.0)
    e3 = (sin(ph) * sin(th), -cos(ph) * sin(th), cos(th))
    return [v["phi'"] * z + v["theta'"] * a + v["psi'"] * c
            for z, a, c in zip((0.0, 0.0, 1.0), e1, e3)]


def check_billiard(qdot):
    m, a, g, mu = 0.17, 0.028, 9.81, 0.2
    what = 'billiard ball (rolls ... friction)'
    r = simulate(qdot, what, EX / 'friction_billiard.qd', '--t-end', 0.6, '--dt', 0.01)
    if r is None:
        return

    def slip(x):
        w = omega_space(x, x)
        return (x["x'"] - a * w[1], x["y'"] + a * w[0]), w

    (s0x, s0y), w0 = slip(r.rows[0])
    s0 = math.hypot(s0x, s0y)
    check(close(s0x, 1 + 20 * a * sin(1), 1e-12) and close(s0y, 0.5, 1e-12),
          'billiard: S0 = (%r, %r) from the initial state' % (s0x, s0y))
    ux, uy = s0x / s0, s0y / s0
    tstar = 2 * s0 / (7 * mu * g)
    check_transitions(what, r, [(tstar, 'slip', 'stick')])
    name = r.contact()
    bad = []
    for x in r.rows:
        t = min(x['t'], tstar)
        (sx, sy), w = slip(x)
        want_s = s0 - 3.5 * mu * g * t
        cx = x['t'] - mu * g * ux * t * t / 2 - mu * g * ux * t * (x['t'] - t)
        cy = 0.5 * x['t'] - mu * g * uy * t * t / 2 - mu * g * uy * t * (x['t'] - t)
        ok = close(math.hypot(sx, sy), want_s) and close(x['x'], cx) and close(x['y'], cy) and \
            close(w[2], w0[2]) and (name is None or close(x['slip_' + name], want_s))
        if want_s > 1e-6:              # the slip's direction is kept while there is one
            ok = ok and close(sx * uy - sy * ux, 0.0, TOL, want_s)
        if not ok:
            bad.append((x['t'], sx, sy, want_s, x['x'], cx, x['y'], cy, w[2], w0[2]))
    check(not bad, '%s: off the closed form at %r' % (what, bad[:2]))
    if name:
        modes_agree(what, r, name, tstar, 1, 0)
    check_balance(what, r)


# ---------------------------------------------------------------------------
# A particle on a rough incline with mu = tan al: v (1 + cos phi) = v0

def check_particle(qdot):
    g, al, v0 = 9.81, 0.3, 1.0
    what = 'particle across a rough incline (friction ... on ... against)'
    r = simulate(qdot, what, EX / 'friction_particle_incline.qd', '--t-end', 6, '--dt', 0.05)
    if r is None:
        return
    down = (cos(al), 0.0, -sin(al))
    bad = []
    for x in r.rows:
        v = (x["x'"], x["y'"], x["z'"])
        speed = math.sqrt(sum(c * c for c in v))
        cphi = sum(c * d for c, d in zip(v, down)) / speed
        if not close(speed * (1 + cphi), v0):
            bad.append((x['t'], speed, cphi))
    check(not bad, '%s: v (1 + cos phi) != v0 at %r' % (what, bad[:3]))
    last = r.rows[-1]
    speed = math.sqrt(last["x'"] ** 2 + last["y'"] ** 2 + last["z'"] ** 2)
    check(close(speed, v0 / 2, 1e-6), '%s: final speed %r, want v0/2' % (what, speed))
    check_transitions(what, r, [])
    check_balance(what, r)


# ---------------------------------------------------------------------------
# The stick-slip oscillator on a belt (docs/design.md, "Friction")

def check_stick_slip(qdot):
    m, k, g, vb, mu_s, mu_k = 1.0, 10.0, 9.81, 0.2, 0.4, 0.3
    w = sqrt(k / m)
    D = (mu_s - mu_k) * m * g / k
    x0 = mu_k * m * g / k
    A = sqrt(D * D + (vb / w) ** 2)
    b = atan(vb / (w * D))
    t_slip, t_stick = (pi + 2 * b) / w, 2 * D / vb
    t1 = mu_s * m * g / k / vb                      # carried from x = 0 to mu_s m g/k
    want = []
    t = t1
    while t < 9:
        want.append((t, 'stick', 'slip'))
        if t + t_slip < 9:
            want.append((t + t_slip, 'slip', 'stick'))
        t += t_slip + t_stick
    what = 'stick-slip oscillator'
    r = simulate(qdot, what, EX / 'friction_stick_slip.qd', '--t-end', 9, '--dt', 0.001)
    if r is None:
        return
    check_transitions(what, r, want)
    later = [x['x'] for x in r.rows if x['t'] > t1]
    check(close(max(later), x0 + A, 1e-6) and close(min(later), x0 - A, 1e-6),
          '%s: x within [%r, %r], the limit cycle [%r, %r]'
          % (what, min(later), max(later), x0 - A, x0 + A))
    starts = [x['t'] for x in r.transitions if x['to'] == 'slip' and x['t'] > 0]
    periods = [b2 - a2 for a2, b2 in zip(starts, starts[1:])]
    check(periods and all(close(p, t_stick + t_slip) for p in periods),
          '%s: periods %r, want 2 D/vb + (pi + 2 b)/w = %r' % (what, periods, t_stick + t_slip))
    # What friction dissipates is its force times the slip, mu_k m g (vb - x') on each arc:
    # mu_k m g (vb t_slip + 2 D) a whole arc; nothing while the block sticks.  (The belt
    # also works on the block while it sticks, so E + dissipated is not E(0) here.)
    if 'dissipated' in r.cols:
        slips = [t for t, a2, _ in want if a2 == 'stick']
        T = r.rows[-1]['t']
        whole = sum(1 for t in slips if t + t_slip <= T)
        part = [t for t in slips if t + t_slip > T]
        d = mu_k * m * g * (vb * t_slip + 2 * D) * whole
        if part:
            u = T - part[0]
            x_now = x0 + A * cos(w * u - b)
            d += mu_k * m * g * (vb * u - (x_now - mu_s * m * g / k))
        check(close(r.rows[-1]['dissipated'], d, 1e-8),
              '%s: dissipated %r, want %r' % (what, r.rows[-1]['dissipated'], d))
    belt_work(what, r, want, t_slip, (m, k, g, vb, mu_k, x0 - D))
    for x in r.rows:
        if x['t'] > t1 and abs(x["x'"] - vb) < 1e-9 and x['mode_' + r.contact()] == 0:
            if not check(abs(k * x['x']) <= mu_s * m * g * (1 + 1e-9),
                         '%s: sticks at t = %r with spring force %r > mu_s m g'
                         % (what, x['t'], k * x['x'])):
                break


def belt_closed_work(t, want, t_slip, p):
    """The belt's work on the block by time t: sticking (x' = vb) the integral of
    k x vb, k (x^2 - x_a^2)/2 from the stick's start x_a (0 at first, x0 - D after a
    slip); slipping, the kinetic force mu_k m g times vb."""
    m, k, g, vb, mu_k, x_low = p
    starts = [a for a, fr, _ in want if fr == 'stick']
    W, t0, xa = 0.0, 0.0, 0.0
    for ts in starts:
        end = min(t, ts)
        if end > t0:
            xe = xa + vb * (end - t0)
            W += k * (xe * xe - xa * xa) / 2
        if t <= ts:
            return W
        W += mu_k * m * g * vb * min(t - ts, t_slip)
        if t <= ts + t_slip:
            return W
        t0, xa = ts + t_slip, x_low
    xe = xa + vb * (t - t0)
    return W + k * (xe * xe - xa * xa) / 2


def belt_work(what, r, want, t_slip, p):
    """surface_work against its closed form and E + dissipated - surface_work = E(0),
    row by row (relative to the largest energy), and the JSON stats."""
    if 'surface_work' not in r.cols:
        lacks(what + ': the belt\'s work', 'the `surface_work` column')
        return
    scale = max(abs(x['energy']) for x in r.rows)
    worst = max(abs(x['surface_work'] - belt_closed_work(x['t'], want, t_slip, p))
                for x in r.rows) / scale
    check(worst < 1e-8, '%s: surface_work off its closed form by %.3g of E' % (what, worst))
    e0 = r.rows[0]['energy']
    worst = max(abs(x['energy'] + x['dissipated'] - x['surface_work'] - e0)
                for x in r.rows) / scale
    check(worst < 1e-8, '%s: E + dissipated - surface_work - E0 up to %.3g of E'
          % (what, worst))
    st = r.data
    check(close(st.get('surface_work', math.nan), r.rows[-1]['surface_work'], 1e-12, scale)
          and st['energy_balance_error'] < 1e-8,
          '%s: stats surface_work %r (last row %r), energy_balance_error %r'
          % (what, st.get('surface_work'), r.rows[-1]['surface_work'],
             st['energy_balance_error']))


# ---------------------------------------------------------------------------
# Errors: exit 2, FILE:LINE:COL, the line with a caret, a hint

BASE = """coordinates x, y
parameters m = 1, g = 9.81
particle m at (x, y, 0)
V = m*g*y
"""

# (model, line, words of the message, the text the caret points at, what)
ERRORS = [
    ('holonomic', BASE + 'constraint floor: y = 0 friction 0.3 normal m*g\n', 5,
     ['friction', 'velocity'], 'friction', 'friction on a holonomic constraint'),
    ('negative', BASE + "constraint slip: x' = 0 friction -0.3 normal m*g\n", 5,
     ['friction', 'negative'], '-0.3', 'a negative friction coefficient'),
    ('unknown_normal', BASE + "constraint floor: y = 0\n"
     "constraint slip: x' = 0 friction 0.3 normal flor\n", 6, ['flor'], 'flor',
     'an unknown normal constraint'),
]


def check_errors(qdot):
    missing = supported(qdot, EX / 'friction_block_incline.qd')
    if missing:
        for *_, what in ERRORS:
            lacks('error: ' + what, 'the friction clause (qdot check: %s)' % missing)
        return
    with tempfile.TemporaryDirectory() as tmp:
        for name, text, line, words, spot, what in ERRORS:
            path = os.path.join(tmp, name + '.qd')
            with open(path, 'w') as f:
                f.write(text)
            rc, out, err = run(qdot, 'check', path)
            src = text.splitlines()[line - 1]
            lines = err.splitlines()
            ok = rc == 2 and out == '' and len(lines) >= 4 and \
                lines[0].startswith('%s:%d:' % (path, line)) and ': error: ' in lines[0] and \
                all(w in lines[0] for w in words) and src in lines[1] and '^' in lines[2] and \
                'hint:' in lines[3]
            if ok:
                col = int(lines[0][len(path):].split(':')[2])
                ok = lines[2].index('^') - lines[1].index(src) + 1 == col and \
                    src[col - 1:].startswith(spot)
            check(ok, 'error: %s: exit %d, stderr %r' % (what, rc, err))
    # a method that cannot follow the switches is refused by name (exit 1, as
    # for any method the system does not suit: verlet on a non-separable H)
    for method in (['--method', 'gl4', '--dt', '0.01'], ['--method', 'taylor']):
        rc, out, err = run(qdot, 'simulate', EX / 'friction_sphere_slides.qd', '--t-end', '1',
                           *method)
        check(rc == 1 and out == '' and 'friction' in err,
              'error: %s on friction: exit %d, stderr %r' % (method[1], rc, err))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--build', required=True)
    args = ap.parse_args()
    qdot = str(Path(args.build).resolve() / 'qdot')
    for part in (check_sliding, check_incline, check_block, check_wedge, check_billiard,
                 check_particle, check_stick_slip, check_errors):
        part(qdot)
    print('%(passed)d passed, %(failed)d failed, %(skipped)d skipped' % results)
    if results['failed'] or not results['passed']:
        return 1
    return 77 if results['skipped'] else 0


if __name__ == '__main__':
    sys.exit(main())

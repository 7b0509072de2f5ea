#!/usr/bin/python3
"""Cross-check the Hamiltonians of Desloge ch. 71 Problems 1-10 (seed 000, pp. 741-743;
reference seed-desloge-C.md T7, T9, T11, T13, T15) in both directions.

Forward: for each examples/desloge71_pN.qd, SymPy builds the Lagrangian here from the
problem's own positions and energies (written by hand, not read from qdot), forms
p = dL/dq', solves for q', H = p.q' - L and Hamilton's equations; qdot's H, dq_dt and
dp_dt (`qdot hamiltonian --format sympy`) must agree, and so must the textbook's H.

Backward: the textbook's H is written as a model given by H (`momenta ...`, `H = ...`,
a scratch file); qdot's inverse Legendre transform L must equal the hand-written L, and
its Hamilton's equations SymPy's.  Also a non-regular H (H = p_x) must give no L, with
the singular d^2H/dp^2 named.

Equality: a - b vanishes at random points, evaluated to 30 digits (simplify would
prove it, but takes minutes on the six-coordinate two-body H; values take
milliseconds, and four random points at 30 digits leave no doubt)."""
import random
import subprocess
import sys
import tempfile
from pathlib import Path

from sympy import (Matrix, Symbol, Derivative, cos, diff, exp, sin, simplify, symbols,
                   sympify)

ROOT = Path(__file__).resolve().parents[2]
t = Symbol('t')
rng = random.Random(7101)


def spherical(r, th, ph):
    return Matrix([r * sin(th) * cos(ph), r * sin(th) * sin(ph), r * cos(th)])


def velocity(x, q, qd):
    """d/dt of a position (Matrix or scalar) along q(t): chain rule plus explicit t."""
    return x.diff(t) + sum((x.diff(a) * b for a, b in zip(q, qd)), x * 0)


def sym(names):
    return symbols(names)  # plain, as qdot prints them


# Each problem: coordinates, L(q, qd, t) written from the problem statement, and the
# expected H in the model language (also read by SymPy with ^ as **): the reference's
# answer for P1, P3, P5, P7, P9 (T7, T9, T11, T13, T15), the problem statement's own
# constant of motion for P4, and for P2, P6, P8, P10 (no answer printed) H worked out by
# hand from the statement, as the comments say.
def p1():
    rho, ph, z, rhod, phd, zd, a = sym('rho phi z rhod phid zd a')
    L = (rhod**2 + rho**2 * phd**2 + zd**2) / 2 + a * rho**2 * phd
    return [rho, ph, z], [rhod, phd, zd], L, \
        '(p_rho^2 + (p_phi - a*rho^2)^2/rho^2 + p_z^2)/2'          # T7


def p2():
    r, ph, rd, phd, k = sym('r phi rd phid k')
    L = (rd**2 + r**2 * phd**2) / 2 - k * cos(ph) / r**2
    return [r, ph], [rd, phd], L, 'p_r^2/2 + p_phi^2/(2*r^2) + k*cos(phi)/r^2'  # by hand


def p3():
    r, ph, rd, phd, lam, mu = sym('r phi rd phid lam mu')
    L = (rd**2 + r**2 * phd**2) / 2 - (2 * lam * r - mu**2 / (2 * r**2))
    return [r, ph], [rd, phd], L, 'p_r^2/2 + p_phi^2/(2*r^2) + 2*lam*r - mu^2/(2*r^2)'  # T9


def p4():
    r, th, ph, rd, thd, phd, m, k = sym('r theta phi rd thetad phid m k')
    q, qd = [r, th, ph], [rd, thd, phd]
    v = velocity(spherical(r, th, ph), q, qd)
    return q, qd, m / 2 * v.dot(v) + k / r, \
        'p_r^2/(2*m) + p_theta^2/(2*m*r^2) + p_phi^2/(2*m*r^2*sin(theta)^2) - k/r'  # P4 text


def p5():
    X, Y, Z, r, th, ph = sym('X Y Z r theta phi')
    Xd, Yd, Zd, rd, thd, phd = sym('Xd Yd Zd rd thetad phid')
    m, M, k = sym('m M k')
    q, qd = [X, Y, Z, r, th, ph], [Xd, Yd, Zd, rd, thd, phd]
    R, rel = Matrix([X, Y, Z]), spherical(r, th, ph)
    v1 = velocity(R + M / (m + M) * rel, q, qd)
    v2 = velocity(R - m / (m + M) * rel, q, qd)
    L = m / 2 * v1.dot(v1) + M / 2 * v2.dot(v2) + k / r
    return q, qd, L, ('(p_X^2 + p_Y^2 + p_Z^2)/(2*(m + M)) + (m + M)/(m*M)*(p_r^2/2 '
                      '+ p_theta^2/(2*r^2) + p_phi^2/(2*r^2*sin(theta)^2)) - k/r')  # T11


def p6():
    th, thd, m, g, l0, a = sym('theta thetad m g l0 a')
    l = l0 - a * t
    x = Matrix([l * sin(th), -l * cos(th)])
    v = velocity(x, [th], [thd])
    L = m / 2 * v.dot(v) + m * g * l * cos(th)
    return [th], [thd], L, ('p_theta^2/(2*m*(l0 - a*t)^2) - m*g*(l0 - a*t)*cos(theta) '
                            '- m*a^2/2')  # by hand: T = m/2 (a^2 + l^2 theta'^2)


def p7():
    th, ph, thd, phd, m, g, R0, c = sym('theta phi thetad phid m g R0 c')
    R = R0 + c * t
    q, qd = [th, ph], [thd, phd]
    v = velocity(spherical(R, th, ph), q, qd)
    L = m / 2 * v.dot(v) - m * g * R * cos(th)
    return q, qd, L, ('p_theta^2/(2*m*(R0 + c*t)^2) + p_phi^2/(2*m*(R0 + c*t)^2*sin(theta)^2)'
                      ' + m*g*(R0 + c*t)*cos(theta) - m*c^2/2')  # T13, R' = c


def p8():
    x, xd, m, k, tau = sym('x xd m k tau')
    return [x], [xd], m / 2 * xd**2 - k * exp(-t / tau) / x, \
        'p_x^2/(2*m) + k*exp(-t/tau)/x'  # by hand: V = k exp(-t/tau)/x


def p9():
    r, th, rd, thd = sym('r theta rd thetad')
    L = (rd**2 + r**2 * thd**2) / 2 - (1 + rd**2) / r
    return [r, th], [rd, thd], L, 'r*p_r^2/(2*(r - 2)) + p_theta^2/(2*r^2) + 1/r'  # T15


def p10():
    x1, x2, x3, v1, v2, v3, m, w, g = sym('x1 x2 x3 x1d x2d x3d m w g')
    q, qd = [x1, x2, x3], [v1, v2, v3]
    rot = Matrix([[cos(w * t), -sin(w * t), 0], [sin(w * t), cos(w * t), 0], [0, 0, 1]])
    v = velocity(rot * Matrix(q), q, qd)
    L = m / 2 * v.dot(v) - m * g * x3
    return q, qd, L, ('(p_x1^2 + p_x2^2 + p_x3^2)/(2*m) - w*(x1*p_x2 - x2*p_x1) '
                      '+ m*g*x3')  # by hand: p = m (x' + w e3 x r)


PROBLEMS = [p1, p2, p3, p4, p5, p6, p7, p8, p9, p10]


def legendre(q, qd, L):
    p = [Symbol('p_' + s.name) for s in q]
    pd = Matrix([diff(L, v) for v in qd])
    # sin^2 + cos^2 left in M makes LUsolve's result enormous
    M = pd.jacobian(qd).applyfunc(simplify)
    b = pd.subs({v: 0 for v in qd}).applyfunc(simplify)
    vel = M.LUsolve(Matrix(p) - b).applyfunc(simplify)
    H = (sum(pj * v for pj, v in zip(p, qd)) - L).subs(dict(zip(qd, vel)))
    return p, H, [diff(H, pj) for pj in p], [-diff(H, s) for s in q]


def same(a, b, free):
    a, b = sympify(a), sympify(b)
    for _ in range(4):
        # r > 2 keeps P9's mass matrix 1 - 2/r regular
        pt = {s: rng.uniform(2.3, 3.1) if s.name == 'r' else rng.uniform(0.4, 1.4)
              for s in sorted(free, key=str)}
        x, y = complex(a.evalf(30, subs=pt)), complex(b.evalf(30, subs=pt))
        if abs(x - y) > 1e-20 * (1 + abs(x) + abs(y)):
            return False
    return True


def params_of(example):
    for line in example.read_text().splitlines():
        line = line.split('#', 1)[0].strip()
        if line.startswith('parameters '):
            return line[len('parameters '):]
    return None


def run_qdot(build, path):
    out = subprocess.run([build + '/qdot', 'hamiltonian', str(path), '--format', 'sympy'],
                         capture_output=True, text=True, check=True, cwd=ROOT).stdout
    ns = {}
    exec(out, ns)
    return ns


def plain(ns, q, qd, x):
    """qdot prints q as functions of t: back to the plain symbols q, qd."""
    x = sympify(x)
    fs = {ns[s.name](t): s for s in q}
    x = x.subs({Derivative(f, t): v for f, v in zip(fs, qd)})
    return x.subs(fs)


def textbook(q, text):
    names = {s.name: s for s in q}
    names.update({'p_' + s.name: Symbol('p_' + s.name) for s in q})
    names['t'] = t
    return sympify(text.replace('^', '**'), locals=names)


def check_forward(build, name, q, qd, L, Htext, leg):
    p, H, dq, dp = leg
    ns = run_qdot(build, ROOT / 'examples' / (name + '.qd'))
    free = set(q) | set(p) | L.free_symbols | {t}
    checks = [('H vs SymPy', plain(ns, q, qd, ns['H']), H),
              ('textbook H vs SymPy', textbook(q, Htext), H)]
    checks += [('dq_dt', plain(ns, q, qd, a), b) for a, b in zip(ns['dq_dt'], dq)]
    checks += [('dp_dt', plain(ns, q, qd, a), b) for a, b in zip(ns['dp_dt'], dp)]
    return [w for w, a, b in checks if not same(a, b, free)]


def check_backward(build, name, q, qd, L, Htext, leg, scratch):
    """The textbook H as a model given by H: its L and Hamilton's equations."""
    params = params_of(ROOT / 'examples' / (name + '.qd'))
    text = 'coordinates %s\n%smomenta %s\nH = %s\n' % (
        ', '.join(s.name for s in q), 'parameters %s\n' % params if params else '',
        ', '.join('p_' + s.name for s in q), Htext)
    path = Path(scratch) / (name + '_H.qd')
    path.write_text(text)
    ns = run_qdot(build, path)
    p, H, dq, dp = leg
    free = set(q) | set(qd) | set(p) | L.free_symbols | {t}
    if ns['L'] is None:
        return ['no L from H']
    checks = [('L from H', plain(ns, q, qd, ns['L']), L)]
    checks += [('H-model dq_dt', plain(ns, q, qd, a), b) for a, b in zip(ns['dq_dt'], dq)]
    checks += [('H-model dp_dt', plain(ns, q, qd, a), b) for a, b in zip(ns['dp_dt'], dp)]
    return [w for w, a, b in checks if not same(a, b, free)]


def check_singular(build, scratch):
    path = Path(scratch) / 'px.qd'
    path.write_text('coordinates x\nmomenta p_x\nH = p_x\n')
    ns = run_qdot(build, path)
    return [] if ns['L'] is None and ns['dq_dt'] == [1] else ['H = p_x gave an L']


def check_at(build, scratch):
    """`--at` on a model given by H: the numbers of Hamilton's equations for Kepler
    (seed-desloge-B.md C3), H = p_r^2/2m + p_theta^2/(2 m r^2) - k/r."""
    import json
    path = Path(scratch) / 'kepler_H.qd'
    path.write_text('coordinates r, theta\nparameters m = 1.3, k = 4\nmomenta p_r, p_theta\n'
                    'H = p_r^2/(2*m) + p_theta^2/(2*m*r^2) - k/r\n')
    out = json.loads(subprocess.run(
        [build + '/qdot', 'hamiltonian', str(path), '--format', 'json',
         '--at', 'r=1.25, theta=0.2, p_r=0.5, p_theta=1.1'],
        capture_output=True, text=True, check=True).stdout)
    m, k, r, pr, pth = 1.3, 4.0, 1.25, 0.5, 1.1
    want = {'H': pr**2 / (2 * m) + pth**2 / (2 * m * r**2) - k / r,
            'dq_dt': [pr / m, pth / (m * r**2)],
            'dp_dt': [pth**2 / (m * r**3) - k / r**2, 0.0]}
    got = {key: out[key] for key in want}
    flat = lambda d: [d['H']] + d['dq_dt'] + d['dp_dt']
    bad = [] if out['momenta'] == ['p_r', 'p_theta'] else ['momenta']
    if any(abs(a - b) > 1e-12 * (1 + abs(b)) for a, b in zip(flat(got), flat(want))):
        bad.append('--at values %s, want %s' % (got, want))
    return bad


def main():
    build = (sys.argv[sys.argv.index('--build') + 1] if '--build' in sys.argv
             else str(ROOT / 'build'))
    passed = failed = 0
    with tempfile.TemporaryDirectory() as scratch:
        for k, make in enumerate(PROBLEMS, 1):
            name = 'desloge71_p%d' % k
            q, qd, L, Htext = make()
            try:
                leg = legendre(q, qd, L)
                bad = check_forward(build, name, q, qd, L, Htext, leg)
                bad += check_backward(build, name, q, qd, L, Htext, leg, scratch)
            except Exception as ex:  # a crash of qdot or of the printed Python
                bad = [repr(ex)]
            if bad:
                failed += 1
                print('FAIL %s: %s' % (name, ', '.join(bad)))
            else:
                passed += 1
                print('ok   %s' % name, flush=True)
        for what, check in (('H = p_x has no Lagrangian', check_singular),
                            ('--at on a model given by H', check_at)):
            try:
                bad = check(build, scratch)
            except Exception as ex:
                bad = [repr(ex)]
            print(('FAIL %s: %s' % (what, bad)) if bad else 'ok   ' + what)
            failed += bool(bad)
            passed += not bad
    print('%d passed, %d failed' % (passed, failed))
    return 1 if failed else 0


if __name__ == '__main__':
    sys.exit(main())

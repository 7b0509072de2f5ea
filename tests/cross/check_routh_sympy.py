#!/usr/bin/python3
"""Cross-check `qdot routh` against an independent Routh reduction in SymPy.

Each Lagrangian is written here by hand from the example's definitions (the
textbook forms its header cites).  SymPy then does the partial Legendre
transform on the ignored velocities alone: p_c = dL/dc' solved for c', R =
sum p_c c' - L with c' substituted everywhere (Goldstein's sign), R split by
degree in the kept velocities, and Lagrange's equations of -R for the kept
coordinates written M k'' = f.  qdot's R, R2, R1, R0, V_eff, quadratures, M,
f and G (its --format sympy output) must simplify to the same expressions.

A last case feeds a model with a gyroscopic coupling ([B] B07,
seed-goldstein-britannica.md) and checks the reduced equations against the
full Lagrange equations of SymPy's own L with c' eliminated, and G against
the skew part of the velocity-linear terms."""
import os
import random
import subprocess
import sys
import tempfile

from sympy import Float, Matrix, Symbol, cos, diff, sin, symbols, sympify

t = Symbol('t')
ROOT = __file__.rsplit('/tests/', 1)[0]


def case_wire():
    # Desloge ch. 54 P6: the bead on a^3 y = x^4, the wire turning freely about y.
    m, a, g, x, phi, xd, phid = symbols('m a g x phi xd phid')
    y = x**4 / a**3
    T = m / 2 * (xd**2 + (diff(y, x) * xd)**2 + x**2 * phid**2)
    return 'wire_curve_x4', 'phi', [x, phi], [xd, phid], T - m * g * y


def case_top(ignore):
    # Desloge ch. 72 Example 2 (32); Goldstein (5.55): A about the fixed point.
    def make():
        A, C, M, g, h = symbols('A C M g h')
        ph, th, ps, phd, thd, psd = symbols('phi theta psi phid thetad psid')
        L = A / 2 * (thd**2 + phd**2 * sin(th)**2) + C / 2 * (psd + phd * cos(th))**2 \
            - M * g * h * cos(th)
        return 'heavy_top', ignore, [ph, th, ps], [phd, thd, psd], L
    return make


def case_paraboloid():
    # Desloge ch. 72 P2 (z = c rho^2; c = 1 in the book).
    m, c, g, rho, ph, rhod, phd = symbols('m c g rho ph rhod phd')
    T = m / 2 * (rhod**2 + rho**2 * phd**2 + (2 * c * rho * rhod)**2)
    return 'paraboloid', 'ph', [rho, ph], [rhod, phd], T - m * g * c * rho**2


def case_spherical():
    m, a, g, th, ph, thd, phd = symbols('m a g theta phi thetad phid')
    T = m * a**2 / 2 * (thd**2 + sin(th)**2 * phd**2)
    return 'spherical_pendulum', 'phi', [th, ph], [thd, phd], T + m * g * a * cos(th)


def case_kepler():
    m, k, r, th, rd, thd = symbols('m k r theta rd thetad')
    return 'kepler_polar', 'theta', [r, th], [rd, thd], m / 2 * (rd**2 + r**2 * thd**2) + k / r


def routh(q, qd, L, ignore):
    """Routh's reduction by hand: returns the dict qdot's output is compared with."""
    ign = [i for i, s in enumerate(q) if s.name in ignore.split(',')]
    keep = [i for i in range(len(q)) if i not in ign]
    p = [Symbol('p_' + q[i].name) for i in ign]
    cd = [qd[i] for i in ign]
    pd = Matrix([diff(L, v) for v in cd])
    A = pd.jacobian(cd)
    rest = pd - A * Matrix(cd)
    vel = A.LUsolve(Matrix(p) - rest)
    sub = dict(zip(cd, vel))
    R = (sum(pi * v for pi, v in zip(p, cd)) - L).subs(sub)
    kq = [q[i] for i in keep]
    kd = [qd[i] for i in keep]
    kdd = [Symbol(s.name + 'dd') for s in kq]
    s = Symbol('s_scale')
    Rs = R.subs({v: s * v for v in kd}, simultaneous=True)
    R2 = diff(Rs, s, 2).subs(s, 0) / 2
    R1 = diff(Rs, s).subs(s, 0)
    R0 = Rs.subs(s, 0)
    lag = -R

    def ddt(F):
        return sum(diff(F, a) * b for a, b in zip(kq, kd)) + \
            sum(diff(F, a) * b for a, b in zip(kd, kdd)) + diff(F, t)
    E = [ddt(diff(lag, kd[j])) - diff(lag, kq[j]) for j in range(len(kq))]
    M = Matrix([[diff(e, a) for a in kdd] for e in E])
    f = Matrix([-e.subs({a: 0 for a in kdd}) for e in E])
    gvec = [diff(R1, v) for v in kd]
    G = Matrix(len(kq), len(kq), lambda i, j: diff(gvec[i], kq[j]) - diff(gvec[j], kq[i]))
    return {'routh_R': R, 'routh_R2': R2, 'routh_R1': R1, 'routh_R0': R0, 'routh_V_eff': R0,
            'routh_quadratures': list(vel), 'routh_M': M, 'routh_f': f, 'routh_G': G}


def qdot_output(build, path, ignore):
    out = subprocess.run([build + '/qdot', 'routh', path, '--ignore', ignore, '--format', 'sympy'],
                         capture_output=True, text=True, check=True, cwd=ROOT).stdout
    ns = {}
    exec(out, ns)
    return ns


def plain(ns, q, qd, x):
    """qdot prints coordinates as functions of t: back to plain symbols."""
    x = sympify(x)
    funcs = [ns[s.name](t) for s in q]
    x = x.subs({fq.diff(t): v for fq, v in zip(funcs, qd)})
    return x.subs({fq: s for fq, s in zip(funcs, q)})


RNG = random.Random(5)


def zero(x):
    """x is identically 0: by value at random points (every symbol in [0.3, 1.5),
    where the books' expressions are regular) -- exact simplify() is too slow
    for the top's entries."""
    x = sympify(x)
    syms = sorted(x.free_symbols, key=lambda s: s.name)
    for _ in range(3):
        v = abs(complex(x.xreplace({s: Float(RNG.uniform(0.3, 1.5), 30) for s in syms}).evalf(30)))
        if v > 1e-12:
            return False
    return True


def same(ns, q, qd, mine, theirs):
    if isinstance(mine, list):
        mine = Matrix(mine)
    if hasattr(mine, 'shape'):
        theirs = Matrix(theirs)
        if mine.shape != theirs.shape:
            return False
        return all(zero(plain(ns, q, qd, a) - b) for a, b in zip(theirs, mine))
    return zero(plain(ns, q, qd, theirs) - mine)


def compare(build, path, q, qd, L, ignore):
    want = routh(q, qd, L, ignore)
    ns = qdot_output(build, path, ignore)
    return [k for k, v in want.items() if not same(ns, q, qd, v, ns[k])]


B07_MODEL = """coordinates q1, q2, chi
T = ((2 + q1^2)*q1'^2 + 2*sin(q2)*q1'*q2' + (3 + q2^2)*q2'^2)/2 + (q2*q1' + q1*q2*q2')*chi' + (1 + q1^2 + q2^2/2)*chi'^2/2
V = q1^2/2 + cos(q2)
"""


def case_b07(build):
    """[B] B07: the reduced equations are the full ones with chi' eliminated."""
    q1, q2, chi, v1, v2, vc = symbols('q1 q2 chi q1d q2d chid')
    a1, a2, ac = symbols('q1dd q2dd chidd')
    T = ((2 + q1**2) * v1**2 + 2 * sin(q2) * v1 * v2 + (3 + q2**2) * v2**2) / 2 \
        + (q2 * v1 + q1 * q2 * v2) * vc + (1 + q1**2 + q2**2 / 2) * vc**2 / 2
    L = T - q1**2 / 2 - cos(q2)
    q, qd, qdd = [q1, q2, chi], [v1, v2, vc], [a1, a2, ac]

    def ddt(F):
        return sum(diff(F, a) * b for a, b in zip(q + qd, qd + qdd))
    full = [ddt(diff(L, qd[j])) - diff(L, q[j]) for j in range(3)]
    kappa = Symbol('p_chi')
    # chi' from the constant momentum, chi'' from its time derivative being 0.
    chid = (kappa - q2 * v1 - q1 * q2 * v2) / (1 + q1**2 + q2**2 / 2)
    pc = diff(L, vc)
    dpc = ddt(pc)  # linear in chi'', which it fixes in terms of q1'', q2''
    chidd_val = (-dpc.subs(ac, 0) / diff(dpc, ac)).subs(vc, chid)
    with tempfile.TemporaryDirectory() as d:
        path = os.path.join(d, 'b07.qd')
        with open(path, 'w') as fh:
            fh.write(B07_MODEL)
        ns = qdot_output(build, path, 'chi')
    Mq, fq = plain(ns, q, qd, ns['routh_M']), plain(ns, q, qd, ns['routh_f'])
    bad = []
    for j in range(2):
        red = (Mq.row(j) * Matrix([a1, a2]))[0] - fq[j]
        fl = full[j].subs(ac, chidd_val).subs(vc, chid)
        if not zero(red - fl):
            bad.append('equation %d' % j)
    want = routh(q, qd, L, 'chi')
    if not all(zero(x) for x in plain(ns, q, qd, ns['routh_G']) - want['routh_G']):
        bad.append('G')
    return bad


def main():
    build = sys.argv[sys.argv.index('--build') + 1] if '--build' in sys.argv else ROOT + '/build'
    passed = failed = 0
    cases = [case_wire, case_top('phi,psi'), case_top('psi'), case_top('phi'), case_paraboloid,
             case_spherical, case_kepler]
    for make in cases:
        name, ignore, q, qd, L = make()
        label = '%s --ignore %s' % (name, ignore)
        try:
            bad = compare(build, 'examples/' + name + '.qd', q, qd, L, ignore)
        except Exception as ex:  # a crash of qdot or of the printed Python
            bad = [repr(ex)]
        if bad:
            failed += 1
            print('FAIL %s: %s' % (label, ', '.join(bad)))
        else:
            passed += 1
            print('ok   %s' % label, flush=True)
    try:
        bad = case_b07(build)
    except Exception as ex:
        bad = [repr(ex)]
    if bad:
        failed += 1
        print('FAIL B07: %s' % ', '.join(bad))
    else:
        passed += 1
        print('ok   B07 reduced = full with chi eliminated')
    print('%d passed, %d failed' % (passed, failed))
    return 1 if failed else 0


if __name__ == '__main__':
    sys.exit(main())

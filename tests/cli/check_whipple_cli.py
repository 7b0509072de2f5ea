#!/usr/bin/python3
"""tests/cli/check_whipple_cli.py - `qdot linearize` on the Whipple bicycle in
multiplier form (examples/whipple_bicycle.qd, issue 37) against the benchmark.

The benchmark is Meijaard, Papadopoulos, Ruina and Schwab, Proc. R. Soc. A
463 (2007) 1955-1982: the linearized lean (phi) and steer (delta) equations

    M qdd + v C1 qd + (g K0 + v^2 K2) q = 0,      q = (phi, delta),    (eq. 5.3)

with M, C1, K0, K2 of its Table 2 (the benchmark bicycle's, 14 digits), so
that the paper's A = [0 I; -M^-1 (g K0 + v^2 K2)  -v M^-1 C1].  Checked:

  1. at v = 5: JSON `A` over the 10 independent states (16 less the pitch and
     the 5 constraints' dependent velocities), six eigenvalues exactly 0
     (the contact point, yaw, both wheel angles and the rear wheel rate:
     ignorable) and the others Table 2's -14.0784, -0.7754 +- 4.4649i,
     -0.3229;
  2. at v = 0, 1.5, 3, 4.5, 6 and 8: the eigenvalues of the lean/steer block
     (rows and columns q2, q5, q2', q5') equal those of the paper's A to
     1e-10 (their sign conventions differ from SymPy's frames, the
     eigenvalues do not), and the block equals SymPy's own precomputed
     matrix (test_kane3.py's `Res`, Debian's python3-sympy) to 1e-10;
  3. `--scan v=0:10`: the weave and capsize speeds to 1e-6 of those of the
     paper's A, found here by bisection on the largest real part (the
     paper's 4.2924 and 6.0243 m/s, sec. 5), a complex pair at the weave
     speed and a real eigenvalue at capsize;
  4. `--lqr` on a model without inputs, and a wrong `--independent`, are
     clear errors (exit 2);
  5. the same bicycle in generalized speeds (tests/speeds/whipple_speeds.qd):
     its speeds' velocities independent, the point from `initial u3 = v/rr`,
     the paper's eigenvalues at v = 5;
  6. a steer torque input: B = M^-1 (0, 1) (the paper's eq. 5.3 with the
     torque on the right), and `--lqr` on the core closes the loop;
  7. `simulate` at v = 5 from a lean rate: the lean dies out, T + V kept;
  8. `modes` and `stability --ignore "x, y, q1"` at v = 3 and 5: linearize's
     eigenvalues and verdict (unstable below the weave speed, stable above),
     and `modes --scan v=0:10` its weave and capsize speeds.

Usage: check_whipple_cli.py --build BUILD_DIR
"""
import argparse
import json
import subprocess
import sys
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[2]
MODEL = ROOT / 'examples' / 'whipple_bicycle.qd'
G = 9.81
# Meijaard et al. 2007, Table 2 (the benchmark's coefficient matrices)
M = np.array([[80.81722, 2.31941332208709], [2.31941332208709, 0.29784188199686]])
C1 = np.array([[0.0, 33.86641391492494], [-0.85035641456978, 1.68540397397560]])
K0 = np.array([[-80.95, -2.59951685249872], [-2.59951685249872, -0.80329488458618]])
K2 = np.array([[0.0, 76.59734589573222], [0.0, 2.65431523794604]])
PAPER_V5 = [-14.0784, complex(-0.7754, 4.4649), complex(-0.7754, -4.4649), -0.3229]
INDEP = "x, y, q1, q2, q3, q5, q6, q2', q3', q5'"

failed = 0


def report(ok, what, detail=''):
    global failed
    failed += not ok
    print('%s %s %s' % ('ok  ' if ok else 'FAIL', what, detail if not ok else ''))


def paper_A(v):
    Mi = np.linalg.inv(M)
    return np.block([[np.zeros((2, 2)), np.eye(2)],
                     [-Mi @ (G * K0 + v * v * K2), -v * Mi @ C1]])


def sympy_res(v):
    """test_kane3.py's Res (SymPy's frames: lean, steer, lean rate, steer rate)."""
    return np.array([
        [0, 0, 1.0, 0], [0, 0, 0, 1.0],
        [9.48977444677355, -0.891197738059089 * v**2 - 0.571523173729245,
         -0.105522449805691 * v, -0.330515398992311 * v],
        [11.7194768719633, -1.97171508499972 * v**2 + 30.9087533932407,
         3.67680523332152 * v, -3.08486552743311 * v]])


def sorted_eigs(x):
    return sorted(np.asarray(x, dtype=complex), key=lambda s: (round(s.real, 6), s.imag))


def same_eigs(a, b, tol):
    a, b = sorted_eigs(a), sorted_eigs(b)
    return len(a) == len(b) and all(abs(x - y) <= tol * max(1, abs(y)) for x, y in zip(a, b))


def run(qdot, *args):
    p = subprocess.run([qdot, 'linearize', str(MODEL)] + list(args), capture_output=True,
                       text=True, timeout=600)
    return p.returncode, p.stdout, p.stderr


def linearize(qdot, v):
    rc, out, err = run(qdot, '--set', 'v=%r' % v, '--independent', INDEP, '--format', 'json')
    if rc != 0:
        raise RuntimeError('linearize at v=%r: exit %d: %s' % (v, rc, err))
    return json.loads(out)


def block(d):
    idx = [d['states'].index(s) for s in ("q2", "q5", "q2'", "q5'")]
    A = np.array(d['A'])
    return A[np.ix_(idx, idx)]


def margin(v):
    return max(np.linalg.eigvals(paper_A(v)).real)


def paper_crossings(a, b, steps=1000):
    out, vs = [], np.linspace(a, b, steps + 1)
    for lo, hi in zip(vs[:-1], vs[1:]):
        if (margin(lo) > 0) != (margin(hi) > 0):
            mlo = margin(lo) > 0
            for _ in range(100):
                mid = 0.5 * (lo + hi)
                if (margin(mid) > 0) == mlo:
                    lo = mid
                else:
                    hi = mid
            out.append(0.5 * (lo + hi))
    return out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--build', required=True)
    qdot = str(Path(ap.parse_args().build) / 'qdot')

    # 1. v = 5, the states chosen by the library
    rc, out, err = run(qdot, '--set', 'v=5', '--format', 'json')
    d = json.loads(out) if rc == 0 else {}
    A = np.array(d.get('A', [[0]]))
    eig = [complex(re, im) for re, im in d.get('eigenvalues', [])]
    zeros = [s for s in eig if s == 0]
    rest = [s for s in eig if s != 0]
    report(rc == 0 and A.shape == (10, 10), 'v=5: A is 10x10 over the independent states',
           '%d %s %s' % (rc, A.shape, err))
    report(len(zeros) == 6 and sorted(d.get('ignorable', [])) ==
           sorted(["x", "y", "q1", "q3", "q6", "q3'"]),
           'v=5: six eigenvalues exactly 0, from the ignorable states', str(eig))
    report(same_eigs(rest, np.linalg.eigvals(paper_A(5.0)), 1e-10) and
           same_eigs(rest, PAPER_V5, 1e-4),
           'v=5: the others are Table 2\'s (-14.0784, -0.7754 +- 4.4649i, -0.3229)', str(rest))
    report(d.get('dependent', [None])[0] == 'q4', 'v=5: the pitch q4 is dependent (solved)',
           str(d.get('dependent')))

    # 2. the lean/steer block at several speeds
    for v in [0.0, 1.5, 3.0, 4.5, 6.0, 8.0]:
        try:
            Ab = block(linearize(qdot, v))
        except RuntimeError as e:
            report(False, 'v=%g: linearize' % v, str(e))
            continue
        report(same_eigs(np.linalg.eigvals(Ab), np.linalg.eigvals(paper_A(v)), 1e-10),
               'v=%g: lean/steer eigenvalues = the paper\'s A (M, C1, K0, K2) to 1e-10' % v,
               '%s vs %s' % (sorted_eigs(np.linalg.eigvals(Ab)),
                             sorted_eigs(np.linalg.eigvals(paper_A(v)))))
        report(np.max(np.abs(Ab - sympy_res(v))) <= 1e-10,
               'v=%g: lean/steer block = test_kane3.py\'s Res to 1e-10' % v,
               str(np.max(np.abs(Ab - sympy_res(v)))))

    # 3. the weave and capsize speeds
    rc, out, err = run(qdot, '--scan', 'v=0:10', '--format', 'json')
    s = json.loads(out) if rc == 0 else {'crossings': []}
    cross = s['crossings']
    want = paper_crossings(0.0, 10.0)
    report(rc == 0 and len(cross) == 2 and len(want) == 2, 'scan: two stability changes',
           '%d %s %s %s' % (rc, cross, want, err))
    if len(cross) == 2 and len(want) == 2:
        weave, capsize = cross
        report(abs(weave['value'] - want[0]) <= 1e-6 and abs(weave['value'] - 4.2924) < 5e-5
               and weave['omega'] > 1 and weave['to_stable'],
               'scan: weave speed %.9f (paper\'s A %.9f, paper 4.2924), a complex pair'
               % (weave['value'], want[0]), str(weave))
        report(abs(capsize['value'] - want[1]) <= 1e-6 and abs(capsize['value'] - 6.0243) < 5e-5
               and capsize['omega'] == 0 and not capsize['to_stable'],
               'scan: capsize speed %.9f (paper\'s A %.9f, paper 6.0243), a real eigenvalue'
               % (capsize['value'], want[1]), str(capsize))
    report(s.get('starts_above_zero') is True, 'scan: v assumed positive, starts above 0')

    # 5. the same bicycle written in generalized speeds (tests/speeds/whipple_speeds.qd:
    # `speeds u2 = q2', u3 = q3', u5 = q5'`, `initial u3 = v/rr` with a lean rate u2 = 0.5,
    # which --about sets back to 0): the speeds' velocities stay independent, and A has the
    # same eigenvalues as the paper's at v = 5
    p = subprocess.run([qdot, 'linearize', str(ROOT / 'tests' / 'speeds' / 'whipple_speeds.qd'),
                        '--about', "q2' = 0", '--format', 'json'], capture_output=True,
                       text=True, timeout=600)
    d = json.loads(p.stdout) if p.returncode == 0 else {}
    core = [complex(a, b) for a, b in d.get('core_eigenvalues', [])]
    report(p.returncode == 0 and d['point']["q3'"] == 5 / 0.3 and
           all(s in d['independent'] for s in ("q2'", "q3'", "q5'")) and
           same_eigs(core, np.linalg.eigvals(paper_A(5.0)), 1e-10),
           'in speeds: u3 = v/rr from initial, the speeds independent, the paper\'s eigenvalues',
           '%s %s' % (core, p.stderr))

    # 6. a steer torque Td (Q[q5] = Td): B's lean/steer rows are the paper's M^-1 (0, 1)
    # (up to the steer's sign, SymPy's frames against the paper's), the core is
    # controllable, and --lqr (designed on the core: the ignorable states' s = 0 are out
    # of reach) closes the loop with every Re s < 0
    import tempfile
    with tempfile.TemporaryDirectory() as tmp:
        text = MODEL.read_text().replace('parameters mfork = 4',
                                         'inputs Td\nQ[q5] = Td\nparameters mfork = 4')
        tq = Path(tmp) / 'torque.qd'
        tq.write_text(text)
        p = subprocess.run([qdot, 'linearize', str(tq), '--independent', INDEP, '--format',
                            'json'], capture_output=True, text=True, timeout=600)
        d = json.loads(p.stdout) if p.returncode == 0 else {}
        B = np.array(d.get('B', [[0]] * 10))
        rows = [d['states'].index(s) for s in ("q2'", "q5'")] if d else [0, 1]
        want = np.linalg.inv(M) @ np.array([0.0, 1.0])
        report(p.returncode == 0 and np.allclose(np.abs(B[rows, 0]), np.abs(want),
                                                 rtol=1e-10, atol=1e-12),
               'steer torque: B = M^-1 (0, 1) in the lean and steer rates', '%s %s %s'
               % (B[rows, 0], want, p.stderr))
        p = subprocess.run([qdot, 'linearize', str(tq), '--lqr', 'Q = 1, R = 1', '--format',
                            'json'], capture_output=True, text=True, timeout=600)
        d = json.loads(p.stdout) if p.returncode == 0 else {}
        cl = d.get('lqr', {}).get('closed_loop_eigenvalues', [])
        report(p.returncode == 0 and d.get('controllable') is True and len(cl) == 4 and
               all(re < 0 for re, im in cl) and sorted(d['states']) ==
               sorted(["q2", "q5", "q2'", "q5'"]),
               '--lqr: on the core (lean, steer and their rates), closed loop stable',
               '%s %s' % (cl, p.stderr))

    # 7. self-stability (Meijaard et al. sec. 5: stable between the weave and capsize
    # speeds): at v = 5 a lean rate of 0.5 rad/s dies out, the lean under 0.01 rad after
    # 10 s (the slowest mode, -0.3229, takes it down e^-3.2 ~ 1/25 from its peak ~0.03),
    # and T + V is conserved (no dissipation, ideal rolling: Desloge ch. 52) to 1e-8
    p = subprocess.run([qdot, 'simulate', str(MODEL), '--initial', "q2'=0.5", '--t-end', '10',
                        '--dt', '0.5', '--rtol', '1e-10'], capture_output=True, text=True,
                       timeout=600)
    rows = [l.split(',') for l in p.stdout.splitlines()]
    col = rows[0].index('q2') if rows else 0
    lean = [abs(float(r[col])) for r in rows[1:]]
    m = __import__('re').search(r'energy error ([0-9.e+-]+)', p.stderr)
    report(p.returncode == 0 and lean and max(lean) > 0.02 and max(lean[-4:]) < 0.01 and
           m and float(m.group(1)) < 1e-8,
           'v=5: a lean disturbance dies out (self-stable), energy conserved',
           '%s %s' % (lean[-4:], p.stderr[-300:]))

    # 8. modes and stability of the straight run take linearize's path (issue 37): the same
    # eigenvalues and verdict at v = 3 (below the weave speed: unstable) and v = 5 (between
    # weave and capsize: stable, Meijaard et al. sec. 5), and modes --scan the same weave and
    # capsize speeds
    def cmd(*args):
        p = subprocess.run([qdot, *args], capture_output=True, text=True, timeout=600)
        return json.loads(p.stdout) if p.returncode == 0 else {'stderr': p.stderr}
    for v, want in ((3.0, 'unstable'), (5.0, 'stable')):
        ds = [cmd(c, str(MODEL), '--set', 'v=%r' % v, *extra, '--format', 'json')
              for c, extra in (('linearize', ()), ('modes', ()),
                               ('stability', ('--ignore', 'x, y, q1')))]
        report(all(d.get('verdict') == want for d in ds) and
               all(np.allclose(d['eigenvalues'], ds[0]['eigenvalues'], atol=1e-14) for d in ds)
               and same_eigs([complex(a, b) for a, b in ds[1]['core_eigenvalues']],
                             np.linalg.eigvals(paper_A(v)), 1e-10),
               'v=%g: modes and stability = linearize = the paper (%s)' % (v, want),
               str([d.get('verdict', d.get('stderr')) for d in ds]))
    ms = cmd('modes', str(MODEL), '--scan', 'v=0:10', '--format', 'json')
    report([c['value'] for c in ms.get('crossings', [])] == [c['value'] for c in cross] and
           len(cross) == 2, 'modes --scan v=0:10: the weave and capsize speeds of linearize\'s',
           str(ms.get('crossings', ms)))

    # 4. errors
    rc, out, err = run(qdot, '--lqr', 'Q = 1, R = 1')
    report(rc == 2 and 'error' in err, '--lqr without inputs: exit 2', '%d %s' % (rc, err))
    rc, out, err = run(qdot, '--independent', 'x, y, q1, q2, q3, q5, q6, q2\', q3\', zz')
    report(rc == 2 and 'zz' in err, '--independent with a name that is none: exit 2',
           '%d %s' % (rc, err))
    rc, out, err = run(qdot, '--independent', 'x, y, q1, q2, q3, q5, q6, q2\'')
    report(rc == 2 and 'velocities' in err, '--independent with too few: exit 2',
           '%d %s' % (rc, err))
    print('%d failed' % failed)
    return 1 if failed else 0


if __name__ == '__main__':
    sys.exit(main())

#!/usr/bin/python3
"""Run the n-link pendulum benchmark: qdot, GiNaC and SymPy, one table.

Usage: run_pendulum.py BUILD_DIR [--quick] [--no-sympy] [--no-ginac] [--sympy-limit S]

BUILD_DIR is a build configured with -DQDOT_BENCH=ON (Release), holding
qdot, bench/pendulum_qdot and bench/pendulum_ginac.  The programs run one
after the other, never at once.  Sizes are SymPy's count_ops, summed over the
n*n entries of M and the n of f, of every system's result read into SymPy
the same way (pendulum_sympy.size).  Before the table the three results for
n = 4 are compared at a random state (they must agree to 1e-9 relative).
Exits 1 when a program fails or the results disagree; missing a goal is
reported, not an error.  See bench/README.md.
"""
import argparse
import json
import os
import random
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import pendulum_sympy as ps  # noqa: E402
from timing import timed  # noqa: E402

PYTHON = '/usr/bin/python3'
N_QDOT = [2, 4, 6, 8, 10, 12, 16, 32]
N_SYMPY = [2, 4, 6, 8, 10, 12]
N_GINAC_SIZE = 12       # GiNaC's unsimplified results beyond this take long to read into SymPy
GOAL_MS = 50.0
GOAL_N = 16
GOAL_SPEEDUP = 1000     # issue 34, n = 8
ISSUE_SIMPLIFIED = 374  # the issue's figure for SymPy's simplified n = 4


def log(msg):
    print(msg, file=sys.stderr, flush=True)


def run_lines(label, cmd):
    """Rows {n: fields} from a program printing `n reps median min size` lines."""
    log('running %s: %s' % (label, ' '.join(cmd)))
    p = subprocess.run(cmd, stdout=subprocess.PIPE, text=True)
    if p.returncode != 0:
        raise RuntimeError('%s failed (exit %d)' % (label, p.returncode))
    rows = {}
    for line in p.stdout.splitlines():
        f = line.split('\t')
        if len(f) == 5:
            key = int(f[0]) if f[0].isdigit() else f[0]
            rows[key] = {'reps': int(f[1]), 'med': float(f[2]), 'min': float(f[3]), 'size': int(f[4])}
        elif len(f) == 3 and f[1] == 'timeout':
            rows[int(f[0])] = {'timeout': float(f[2])}
    return rows


def best_of(rounds):
    """Per n the row with the smallest median (a burst of load elsewhere
    cannot decide the figure), repetitions summed."""
    out = {}
    for rows in rounds:
        for n, r in rows.items():
            if n not in out or r['med'] < out[n]['med']:
                reps = r['reps'] + out.get(n, {}).get('reps', 0)
                out[n] = dict(r, reps=reps)
            else:
                out[n]['reps'] += r['reps']
    return out


def qdot_json(build, path):
    p = subprocess.run([os.path.join(build, 'qdot'), 'eom', path, '--format', 'json'],
                       capture_output=True, text=True)
    if p.returncode != 0:
        raise RuntimeError('qdot eom %s: exit %d: %s' % (path, p.returncode, p.stderr[:400]))
    return json.loads(p.stdout)


def write_model(build, tmp, n):
    path = os.path.join(tmp, 'pendulum%d.qd' % n)
    text = subprocess.run([os.path.join(build, 'bench', 'pendulum_qdot'), '--emit', str(n)],
                          check=True, capture_output=True, text=True).stdout
    with open(path, 'w') as fh:
        fh.write(text)
    return path


def qdot_entries(build, tmp, n):
    d = qdot_json(build, write_model(build, tmp, n))
    e = ps.read_qdot([x for row in d['mass_matrix'] for x in row] + d['forcing'], n)
    return e[:n * n], e[n * n:]


def cli_time(build, path, reps):
    """Wall and processor time (user + system of the child) of `qdot eom`."""
    return timed([os.path.join(build, 'qdot'), 'eom', path, '--format', 'json'], reps)


def ginac_entries(build, n):
    out = subprocess.run([os.path.join(build, 'bench', 'pendulum_ginac'), '--print', str(n)],
                         check=True, capture_output=True, text=True).stdout.splitlines()
    e = ps.read_ginac(out, n)
    return e[:n * n], e[n * n:]


def agree(n, systems):
    """The systems' M and f at one random state, pairwise within 1e-9."""
    rng = random.Random(4)
    ns = ps._namespace(n)
    vel = {ns['thetad%d' % i]: rng.uniform(-1, 1) for i in range(1, n + 1)}
    rest = {ns['g']: 9.81}
    for i in range(1, n + 1):
        rest[ns['theta%d' % i]] = rng.uniform(-1, 1)
        rest[ns['m%d' % i]] = rng.uniform(0.5, 2)
        rest[ns['l%d' % i]] = rng.uniform(0.5, 2)

    def at(e):  # velocities first: they contain theta_i(t)
        return float(e.subs(vel).subs(rest))

    ref_name, (rm, rf) = systems[0]
    ref = [at(e) for e in list(rm) + list(rf)]
    ok = True
    for name, (m, f) in systems[1:]:
        got = [at(e) for e in list(m) + list(f)]
        bad = [i for i, (a, b) in enumerate(zip(ref, got)) if abs(a - b) > 1e-9 * max(1, abs(a))]
        if bad:
            log('n = %d: %s and %s disagree at entry %d: %r vs %r'
                % (n, ref_name, name, bad[0], ref[bad[0]], got[bad[0]]))
            ok = False
    log('n = %d: %s agree at a random state%s' % (n, ' / '.join(s[0] for s in systems),
                                                  '' if ok else ': NO'))
    return ok


def fmt_t(r):
    if r is None:
        return '-'
    if 'timeout' in r:
        return '> %g s' % r['timeout']
    s = r['med']
    return '%.2f s' % s if s >= 1 else '%.2f ms' % (s * 1e3) if s >= 1e-3 else '%.1f us' % (s * 1e6)


def ratio(a, b):
    if a is None or b is None or 'med' not in a or 'med' not in b:
        return '-'
    x = a['med'] / b['med']
    return '%.0fx' % x if x >= 10 else '%.2fx' % x


def table(q, g, s, sizes, sympy_status):
    hdr = ('n', 'qdot', 'GiNaC', 'SymPy', 'SymPy/qdot', 'GiNaC/qdot',
           'ops qdot', 'ops GiNaC', 'ops SymPy')
    rows = []
    for n in N_QDOT:
        sr = s.get(n)
        st = fmt_t(sr) if sr else sympy_status(n)
        rows.append((str(n), fmt_t(q.get(n)), fmt_t(g.get(n)) if g is not None else 'n/a', st,
                     ratio(sr, q.get(n)), ratio(g.get(n) if g else None, q.get(n)),
                     str(sizes['qdot'].get(n, '-')), str(sizes['ginac'].get(n, '-')),
                     str(sizes['sympy'].get(n, '-'))))
    w = [max(len(h), *(len(r[i]) for r in rows)) for i, h in enumerate(hdr)]
    print('  '.join(h.rjust(w[i]) for i, h in enumerate(hdr)))
    print('  '.join('-' * x for x in w))
    for r in rows:
        print('  '.join(c.rjust(w[i]) for i, c in enumerate(r)))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('build')
    ap.add_argument('--quick', action='store_true', help='one round, short budgets, SymPy to n = 6')
    ap.add_argument('--no-sympy', action='store_true')
    ap.add_argument('--no-ginac', action='store_true')
    ap.add_argument('--sympy-limit', default='120', help='cut SymPy off at this many seconds for one n')
    a = ap.parse_args()
    build = os.path.abspath(a.build)
    qbin = os.path.join(build, 'bench', 'pendulum_qdot')
    gbin = os.path.join(build, 'bench', 'pendulum_ginac')
    for b in (qbin, os.path.join(build, 'qdot')) + (() if a.no_ginac else (gbin,)):
        if not os.path.exists(b):
            log('%s is missing (configure with -DQDOT_BENCH=ON and build)' % b)
            return 1
    budget = '0.3' if a.quick else '1'
    nq = [str(n) for n in N_QDOT]
    q = best_of([run_lines('qdot', [qbin, '--budget', budget, '--min-reps', '5'] + nq)
                 for _ in range(1 if a.quick else 3)])

    g = None
    if not a.no_ginac:
        small = [str(n) for n in N_QDOT if n < 32]
        g = run_lines('GiNaC', [gbin, '--budget', budget, '--min-reps', '3'] + small)
        g.update(run_lines('GiNaC', [gbin, '--budget', '0', '--min-reps', '1', '32']))

    s = {}
    n_sympy = N_SYMPY[:3] if a.quick else N_SYMPY
    if not a.no_sympy:
        s = run_lines('SymPy', [PYTHON, os.path.join(HERE, 'pendulum_sympy.py'), '--simplify', '4',
                                       '--limit', a.sympy_limit]
                      + [str(n) for n in n_sympy])

    sizes = {'qdot': {}, 'ginac': {}, 'sympy': {n: r['size'] for n, r in s.items()
                                                if isinstance(n, int) and 'size' in r}}
    ok = True
    with tempfile.TemporaryDirectory(prefix='qdot-pendulum-') as tmp:
        log('reading the results into SymPy for count_ops')
        for n in N_QDOT:
            m, f = qdot_entries(build, tmp, n)
            sizes['qdot'][n] = ps.size(m, f)
            if n == 4:
                systems = [('qdot', (m, f)), ('SymPy', ps.derive(4))]
            if g is not None and n <= N_GINAC_SIZE:
                gm, gf = ginac_entries(build, n)
                sizes['ginac'][n] = ps.size(gm, gf)
                if n == 4:
                    systems.append(('GiNaC', (gm, gf)))
        ok = agree(4, systems)
        cli_wall, cli_cpu = cli_time(build, write_model(build, tmp, GOAL_N), 3 if a.quick else 7)
        cli8_wall, cli8_cpu = cli_time(build, write_model(build, tmp, 8), 3 if a.quick else 7)

    timed_out = [n for n, r in s.items() if isinstance(n, int) and 'timeout' in r]

    def sympy_status(n):
        if a.no_sympy:
            return 'not run'
        if timed_out and n > timed_out[0]:
            return 'skipped'
        return 'not run' if n not in n_sympy else '-'

    print()
    print('planar n-link pendulum: parse/build + Lagrange\'s equations, M q\'\' = f')
    print('(median processor time; qdot: every entry simplified; GiNaC, SymPy: unsimplified;')
    print(' ops: count_ops over M and f, every result read into SymPy the same way)')
    print()
    table(q, g, s, sizes, sympy_status)
    if g is None:
        print('GiNaC: not run')
    simp = s.get('simplify4')
    print()
    if simp:
        print('n = 4, SymPy simplify() on every entry of M and f: %s, %d ops (qdot: %d ops, in %s)'
              % (fmt_t(simp), simp['size'], sizes['qdot'][4], fmt_t(q[4])))
    print('n = %d end to end, `qdot eom FILE --format json` as a process: %.1f ms wall, %.1f ms processor'
          % (GOAL_N, cli_wall * 1e3, cli_cpu * 1e3))
    print()
    t16 = q[GOAL_N]['med'] * 1e3
    print('goal: n = %d fully simplified in under %g ms: %s (%.1f ms)'
          % (GOAL_N, GOAL_MS, 'met' if t16 < GOAL_MS else 'NOT MET', t16))
    ref = simp['size'] if simp else ISSUE_SIMPLIFIED
    src = 'measured' if simp else "the issue's figure"
    print('goal: n = 4 no larger than SymPy after simplify (%d, %s; the issue says %d): %s (qdot %d)'
          % (ref, src, ISSUE_SIMPLIFIED, 'met' if sizes['qdot'][4] <= min(ref, ISSUE_SIMPLIFIED)
             else 'NOT MET', sizes['qdot'][4]))
    s8 = s.get(8)
    if s8 and 'med' in s8:  # issue 34: the 8-link derivation >= 1000x SymPy, same run
        print('goal: n = 8 at least %dx faster than SymPy (%s): in process %s (%.0fx); '
              'as a process %.1f ms wall, %.1f ms processor (%.0fx)'
              % (GOAL_SPEEDUP, fmt_t(s8), 'met' if s8['med'] >= GOAL_SPEEDUP * q[8]['med']
                 else 'NOT MET', s8['med'] / q[8]['med'], cli8_wall * 1e3, cli8_cpu * 1e3,
                 s8['med'] / cli8_wall))
    return 0 if ok else 1


if __name__ == '__main__':
    try:
        sys.exit(main())
    except (RuntimeError, subprocess.CalledProcessError) as e:
        log(str(e))
        sys.exit(1)

#!/usr/bin/python3
"""bench/run_bicycle.py - issue 37's figures: the Whipple bicycle derived in
multiplier form and in generalized speeds, `qdot check` on it, and a 3-D
chain of rigid bodies, against SymPy's KanesMethod in the same run.

Usage: run_bicycle.py BUILD_DIR [--reps N] [--no-sympy] [--links N]

Workloads (each a whole qdot command, median of --reps runs, wall time and
peak resident memory of the child; every run under a 3 GB address-space
limit and a 120 s timeout, so that a swelling derivation cannot take the
machine down):

  multipliers     qdot eom on tests/speeds/whipple_speeds.qd without its
                  `speeds` line (M q'' = f + A^T lambda, A q'' = b), at a state
  speeds:METHOD   qdot eom on the model in speeds, --method kane|appell|hamel,
                  at a state (--at: the numbers; the text of the unsimplified
                  DAG parts is not the point)
  check           qdot check on the model in speeds and in multiplier form
  linearize       qdot linearize on examples/whipple_bicycle.qd (multiplier
                  form, the state manifold's path) at v = 2, 4, 5, 6, each a
                  whole derivation; their sum against the goal < 10 s (the
                  eigenvalues are tests/cli/check_whipple_cli.py's to check);
                  and --scan v=0:10
  chain           bench/chain_model.py's chain of --links bodies (3 angles
                  each, spherical joints): qdot simulate 10 s at rtol 1e-10,
                  derivation included; the energy error simulate reports
  SymPy           KanesMethod on test_kane3.py's bicycle (Debian's
                  python3-sympy), the code of that test up to
                  kanes_equations, timed in this process's child

The goals (issue 37): speeds (Kane) < 1 s and < 500 MB, check < 2 s, the
chain < 2 s with energy error < 1e-8; missing one is reported, not an error.
Exits 1 when a command fails.
"""
import argparse
import os
import re
import resource
import statistics
import subprocess
import sys
import tempfile
import threading
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
MODEL = ROOT / 'tests' / 'speeds' / 'whipple_speeds.qd'
KANE3 = Path('/usr/lib/python3/dist-packages/sympy/physics/mechanics/tests/test_kane3.py')
PYTHON = '/usr/bin/python3'
LIMIT_AS = 3_000_000_000
TIMEOUT = 120
LIN_SPEEDS = (2, 4, 5, 6)
STATE = 'x=0,y=0,q1=0.1,q2=0.2,q3=0.3,q4=0,q5=0.4,q6=0,u2=0.5,u3=3,u5=0.2'
MULT_STATE = ("x=0,y=0,q1=0.1,q2=0.2,q3=0.3,q4=0,q5=0.4,q6=0,x'=0.9,y'=0.09,q1'=-0.37,"
              "q2'=0.5,q3'=3,q4'=0.01,q5'=0.2,q6'=2.8")


def limit():
    resource.setrlimit(resource.RLIMIT_AS, (LIMIT_AS, LIMIT_AS))


def waited(cmd, stdout=subprocess.DEVNULL):
    """(wall s, peak RSS MB, exit code, stdout, stderr) of one run under the
    limits; the exit code is 'timeout' when it was killed at TIMEOUT."""
    with tempfile.TemporaryFile() as out, tempfile.TemporaryFile() as err:
        t0 = time.perf_counter()
        p = subprocess.Popen(cmd, stdout=out, stderr=err, preexec_fn=limit)
        timer = threading.Timer(TIMEOUT, p.kill)
        timer.start()
        _, status, ru = os.wait4(p.pid, 0)  # the child's own peak memory
        wall = time.perf_counter() - t0
        killed = not timer.is_alive()
        timer.cancel()
        p.returncode = os.waitstatus_to_exitcode(status)
        out.seek(0)
        err.seek(0)
        return (wall, ru.ru_maxrss / 1024, 'timeout' if killed else p.returncode,
                out.read().decode(), err.read().decode())


def measure(cmd, reps):
    walls, rss = [], []
    for _ in range(reps):
        wall, mb, code, _, err = waited(cmd)
        if code == 'timeout':
            return {'timeout': True}
        walls.append(wall)
        rss.append(mb)
        if code != 0:
            break
    return {'wall': statistics.median(walls), 'rss': max(rss), 'code': code, 'err': err}


SYMPY_PROG = r'''
import resource, sys, textwrap, time
src = open(sys.argv[1]).read()
body = src[src.index('def test_bicycle'):]
body = body[body.index('\n', body.index('skip(')) + 1:]
body = body[:body.index('(fr, frstar) = KM.kanes_equations(BL, FL)')]
body += '(fr, frstar) = KM.kanes_equations(BL, FL)\n'
head = src[:src.index('@slow')]
t0 = time.perf_counter()
exec(head + textwrap.dedent(body), {})
print('%.3f' % (time.perf_counter() - t0))
'''


def sympy_kane():
    wall, mb, code, out, err = waited([PYTHON, '-c', SYMPY_PROG, str(KANE3)])
    if code != 0:
        return {'code': code, 'err': err.strip()[-300:]}
    return {'wall': float(out.split()[-1]), 'rss': mb, 'code': 0}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('build')
    ap.add_argument('--reps', type=int, default=3)
    ap.add_argument('--no-sympy', action='store_true')
    ap.add_argument('--links', type=int, default=10)
    a = ap.parse_args()
    qdot = str(Path(a.build) / 'qdot')
    text = MODEL.read_text()
    rows, failed = [], False
    with tempfile.TemporaryDirectory() as tmp:
        mult = Path(tmp) / 'whipple_mult.qd'
        mult.write_text('\n'.join(l for l in text.splitlines()
                                  if not l.startswith(('speeds', 'initial'))) + '\n')
        chain = Path(tmp) / 'chain.qd'
        chain.write_text(subprocess.run([PYTHON, str(HERE / 'chain_model.py'), str(a.links)],
                                        stdout=subprocess.PIPE, text=True, check=True).stdout)
        work = [('bicycle: eom, multiplier form', [qdot, 'eom', str(mult), '--at', MULT_STATE], None)]
        for m in ('kane', 'appell', 'hamel'):
            work.append(('bicycle: eom in speeds, %s' % m,
                         [qdot, 'eom', str(MODEL), '--method', m, '--at', STATE],
                         (1.0, 500) if m == 'kane' else None))
        work.append(('bicycle: check, in speeds', [qdot, 'check', str(MODEL)], (2.0, None)))
        work.append(('bicycle: check, multiplier form', [qdot, 'check', str(mult)], (2.0, None)))
        work.append(('chain of %d bodies: derive + simulate 10 s, rtol 1e-10' % a.links,
                     [qdot, 'simulate', str(chain), '--t-end', '10', '--rtol', '1e-10',
                      '--dt', '10'], (2.0, None)))
        bike = str(ROOT / 'examples' / 'whipple_bicycle.qd')
        for v in LIN_SPEEDS:
            work.append(('bicycle: derive + linearize (multiplier form), v = %g' % v,
                         [qdot, 'linearize', bike, '--set', 'v=%g' % v], None))
        work.append(('bicycle: linearize --scan v=0:10 (101 speeds, weave and capsize)',
                     [qdot, 'linearize', bike, '--scan', 'v=0:10'], None))
        for name, cmd, goal in work:
            print('running %s' % name, file=sys.stderr, flush=True)
            r = measure(cmd, a.reps)
            note = ''
            if r.get('timeout'):
                note, failed = 'timeout', True
            elif r['code'] != 0:
                note, failed = 'failed: ' + r['err'].strip()[-120:], True
            else:
                m = re.search(r'energy error ([0-9.e+-]+)', r['err'])
                if m:
                    note = 'energy error %s' % m.group(1)
                    if float(m.group(1)) > 1e-8:
                        note += ' (goal < 1e-8: missed)'
                if goal and r['wall'] > goal[0]:
                    note += ' (goal < %g s: missed)' % goal[0]
                if goal and goal[1] and r['rss'] > goal[1]:
                    note += ' (goal < %d MB: missed)' % goal[1]
            rows.append((name, r.get('wall'), r.get('rss'), note))
    lin = [w for n, w, _, _ in rows if n.startswith('bicycle: derive + linearize')]
    if len(lin) == len(LIN_SPEEDS) and None not in lin:
        rows.append(('bicycle: derive and linearize at four speeds, in all', sum(lin), None,
                     '' if sum(lin) < 10 else '(goal < 10 s: missed)'))
    if not a.no_sympy:
        print('running SymPy KanesMethod (test_kane3)', file=sys.stderr, flush=True)
        r = sympy_kane()
        rows.append(('bicycle: SymPy KanesMethod.kanes_equations', r.get('wall'), r.get('rss'),
                     '' if r['code'] == 0 else 'failed: ' + r['err']))
    print('| workload | wall s | peak MB | note |')
    print('|---|---|---|---|')
    for name, wall, rss, note in rows:
        print('| %s | %s | %s | %s |' % (name, '-' if wall is None else '%.3f' % wall,
                                         '-' if rss is None else '%.0f' % rss, note))
    return 1 if failed else 0


if __name__ == '__main__':
    sys.exit(main())

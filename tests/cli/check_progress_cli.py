#!/usr/bin/env python3
"""The progress bar of the long runs (cli/progress.c): `qdot simulate` and
`qdot poincare` draw it on stderr when stderr is a terminal (a pseudo-
terminal here) and the run takes longer than the delay, with the time left,
and erase it at the end; with stderr redirected they print only the summary.

The delay is one second unless QDOT_PROGRESS_DELAY says otherwise (docs/cli.md,
Progress).  A test must not depend on the machine's speed, so the runs on a
terminal force it: 0 (the bar must show, however fast the run), and 1e9 (it
must not, however slow); an unusable value is named in a warning.

The runs are the chaotic double pendulum (examples/double_pendulum.qd,
Goldstein ch. 1 ex. 22, seed 002) at a tight tolerance; the summary's energy
error is checked too (the bar must not disturb the run).
"""
import argparse
import os
import pty
import re
import select
import subprocess
import sys
from pathlib import Path

EX = Path(__file__).resolve().parents[2] / 'examples'
DP = EX / 'double_pendulum.qd'
START = ['--initial', 'theta1=1.5, theta2=1', '--rtol', '1e-12']
RUNS = {
    'simulate': ['simulate', DP, '--t-end', 50, *START, '--out', os.devnull],
    'poincare': ['poincare', DP, '--section', "theta1 = 0, theta1' > 0", '--crossings', 30, *START,
                 '--out', os.devnull],
}


def on_terminal(cmd, delay):
    """Run with stderr on a pseudo-terminal and QDOT_PROGRESS_DELAY=delay;
    return (status, what it showed)."""
    env = dict(os.environ, QDOT_PROGRESS_DELAY=delay)
    master, slave = pty.openpty()
    p = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=slave, env=env)
    os.close(slave)
    out = b''
    while True:
        ready, _, _ = select.select([master], [], [], 1)
        if not ready:
            if p.poll() is not None:
                break
            continue
        try:
            chunk = os.read(master, 4096)
        except OSError:  # the child closed the terminal
            break
        if not chunk:
            break
        out += chunk
    os.close(master)
    return p.wait(timeout=300), out.decode(errors='replace')


def redirected(cmd):
    p = subprocess.run(cmd, capture_output=True, text=True, timeout=300)
    return p.returncode, p.stderr


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--build', required=True)
    qdot = str(Path(ap.parse_args().build).resolve() / 'qdot')
    failures = []

    def check(cond, what):
        if not cond:
            failures.append(what)

    for name, args in RUNS.items():
        cmd = [qdot, *map(str, args)]
        rc, err = redirected(cmd)
        check(rc == 0, f'{name} redirected: {rc} {err}')
        check('\r' not in err and '[#' not in err and 'left' not in err,
              f'{name}: a bar on a redirected stderr: {err[:200]!r}')
        m = re.search(r'energy error ([0-9.e+-]+)', err)
        check(m and float(m.group(1)) < 1e-7, f'{name}: energy error in {err!r}')
        check(err.count('\n') == 1, f'{name}: more than the summary: {err!r}')

        rc, shown = on_terminal(cmd, '0')
        check(rc == 0, f'{name} on a terminal: {rc} {shown[-300:]}')
        bar = re.search(r'\rqdot: ' + name + r' \[#*\s*\]\s+\d+%\s+t = \S+\s+(\d+m)?\d+s left', shown)
        check(bar is not None, f'{name}: no bar with the time left on a terminal: {shown[:300]!r}')
        # erased before the summary: blanks, then a carriage return
        check(re.search(r'\r +\rqdot: ' + name + ': ', shown) is not None,
              f'{name}: the bar is not erased before the summary: {shown[-300:]!r}')

        # a delay longer than any run: the summary alone, even on a terminal
        rc, shown = on_terminal(cmd, '1e9')
        check(rc == 0, f'{name} on a terminal, delay 1e9: {rc} {shown[-300:]}')
        check('[#' not in shown and 'left' not in shown and '\r' not in shown.replace('\r\n', ''),
              f'{name}: a bar before the delay: {shown[:300]!r}')
        check(re.search(r'qdot: ' + name + r': ', shown) is not None,
              f'{name}: no summary on a terminal: {shown!r}')

    # an unusable delay is named, and the default (one second) is kept
    for bad in ('soon', '-1', 'nan'):
        rc, shown = on_terminal([qdot, *map(str, RUNS['simulate'])], bad)
        check(rc == 0 and f"QDOT_PROGRESS_DELAY='{bad}' is not a number of seconds" in shown,
              f'QDOT_PROGRESS_DELAY={bad}: no warning: {rc} {shown[:300]!r}')

    for f in failures:
        print('FAIL:', f)
    if not failures:
        print('check_progress_cli: ok')
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())

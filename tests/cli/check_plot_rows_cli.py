#!/usr/bin/env python3
"""The rows `qdot simulate` writes do not depend on --plot (issue 36).

Before, --plot without --dt made an adaptive run write its rows on a grid of
1000 intervals instead of at its steps: the same command with --plot gave
other CSV (and JSON) rows.  Checked on the double pendulum (dop853, the
default, and --rtol 1e-9) and the LQR cart: --out FILE with and without
--plot FILE.png is byte for byte the same CSV, --format json the same rows;
the picture is still written (a PNG of the default size).
"""
import argparse
import json
import subprocess
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / 'util'))
from png import read_png  # noqa: E402

EX = Path(__file__).resolve().parents[2] / 'examples'
CASES = [
    [EX / 'double_pendulum.qd', '--t-end', '5'],
    [EX / 'double_pendulum.qd', '--t-end', '5', '--rtol', '1e-9'],
    [EX / 'cart_pendulum.qd', '--t-end', '4', '--initial', 'th=0.2', '--input', 'F = lqr',
     '--about', "th=0, th'=0, x=0, x'=0, F=0", '--lqr', 'Q = diag(1, 10, 1, 1), R = 0.1'],
]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--build', required=True)
    qdot = str(Path(ap.parse_args().build).resolve() / 'qdot')
    tmp = Path(tempfile.mkdtemp(prefix='qdot-plot-rows-'))
    failures = []
    for k, case in enumerate(CASES):
        args = [qdot, 'simulate', *map(str, case)]
        plain, plotted, png = tmp / f'a{k}.csv', tmp / f'b{k}.csv', tmp / f'p{k}.png'
        p1 = subprocess.run(args + ['--out', plain], capture_output=True, text=True, timeout=120)
        p2 = subprocess.run(args + ['--out', plotted, '--plot', png], capture_output=True,
                            text=True, timeout=120)
        if p1.returncode or p2.returncode:
            failures.append(f'{case}: exit {p1.returncode} {p2.returncode} {p2.stderr}')
            continue
        a, b = plain.read_text(), plotted.read_text()
        if a != b:
            failures.append(f'{case}: CSV with --plot has {b.count(chr(10))} lines, '
                            f'without {a.count(chr(10))}')
        if not png.exists() or read_png(png)[0] <= 0:
            failures.append(f'{case}: no picture')
        j1 = subprocess.run(args + ['--format', 'json'], capture_output=True, text=True,
                            timeout=120)
        j2 = subprocess.run(args + ['--format', 'json', '--plot', png], capture_output=True,
                            text=True, timeout=120)
        if j1.returncode or j2.returncode:
            failures.append(f'{case} json: exit {j1.returncode} {j2.returncode}')
        elif json.loads(j1.stdout)['rows'] != json.loads(j2.stdout)['rows']:
            failures.append(f'{case}: JSON rows differ with --plot')
    for f in failures:
        print('FAIL:', f)
    print('check_plot_rows_cli:', 'FAIL' if failures else 'ok')
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())

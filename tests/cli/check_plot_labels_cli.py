#!/usr/bin/env python3
"""--title, --xlabel, --ylabel and --size of `qdot simulate --plot` (issue 36),
read back in the pixels (tests/util/png.py).

The same run is drawn twice, once with the defaults and once with a title,
an x label and a y label of our own: the pictures differ in the title band
(the top 30 rows), in the x label's band (the bottom 25 rows) and in the y
label's band (the left 30 columns), and nowhere inside the axes' frame (the
curves are the same).  --size 1200x800 gives a 1200 x 800 PNG; a bad --size,
or --title without --plot, is exit 2.
"""
import argparse
import subprocess
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / 'util'))
from png import read_png  # noqa: E402

EX = Path(__file__).resolve().parents[2] / 'examples'


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--build', required=True)
    qdot = str(Path(ap.parse_args().build).resolve() / 'qdot')
    tmp = Path(tempfile.mkdtemp(prefix='qdot-plot-labels-'))
    failures = []
    base = [qdot, 'simulate', str(EX / 'double_pendulum.qd'), '--t-end', '5', '--size', '1200x800']

    def draw(name, *extra):
        png = tmp / name
        p = subprocess.run(base + ['--plot', str(png), *extra], capture_output=True, text=True,
                           timeout=120)
        if p.returncode:
            failures.append(f'{name}: exit {p.returncode} {p.stderr}')
            return None
        return read_png(png)

    a = draw('a.png')
    b = draw('b.png', '--title', 'A pendulum of two links', '--xlabel', 'time since release',
             '--ylabel', 'angles from the vertical')
    if a and b:
        (w, h, pa), (_, _, pb) = a, b
        if (w, h) != (1200, 800):
            failures.append(f'--size 1200x800 gave {w}x{h}')

        def differ(xs, ys):
            return sum(pa(x, y) != pb(x, y) for y in ys for x in xs)

        top = differ(range(0, w, 2), range(0, 30))
        bottom = differ(range(0, w, 2), range(h - 25, h))
        left = differ(range(0, 30), range(0, h, 2))
        inside = differ(range(150, w - 100, 3), range(120, h - 100, 3))
        if top < 20 or bottom < 20 or left < 20 or inside:
            failures.append(f'pixels changed: title band {top}, x label {bottom}, y label {left}, '
                            f'inside the frame {inside}')
    for bad in (['--size', '1200'], ['--size', '50x50'], ['--size', '1200x800x3']):
        p = subprocess.run(base[:-2] + bad + ['--plot', str(tmp / 'c.png')], capture_output=True,
                           text=True, timeout=120)
        if p.returncode != 2 or 'takes WxH' not in p.stderr or '(--size)' not in p.stderr:
            failures.append(f'{bad}: exit {p.returncode} {p.stderr}')
    p = subprocess.run(base[:-2] + ['--title', 'x'], capture_output=True, text=True, timeout=120)
    if p.returncode != 2 or 'give the file with --plot' not in p.stderr:
        failures.append(f'--title without --plot: exit {p.returncode} {p.stderr}')
    for f in failures:
        print('FAIL:', f)
    print('check_plot_labels_cli:', 'FAIL' if failures else 'ok')
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())

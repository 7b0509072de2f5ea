#!/usr/bin/env python3
"""The picture's options of every command that draws (issue 36), read back
in the pixels (tests/util/png.py): --dpi, and --title, --size on modes.

- simulate --dpi 192 draws the same picture twice as large: a PNG of twice
  the width and height, and the title's letters twice as tall (the rows of
  dark ink in the title band, counted at 96 and at 192 dpi);
- a resolution outside 72 to 1200 dpi, or --dpi without --plot, is exit 2;
- modes --plot takes the same options: --size 1200x800 gives 1200 x 800,
  --title changes the title band and nothing inside the panels (the
  springs and masses are the same); --symmetry writes each panel's irrep
  in its top-left corner, so the pictures with and without it differ there;
- one unit to a panel: the spring pendulum (examples/spring_pendulum.qd, r
  in the length's unit, theta an angle: its positions and V repeat in 2 pi
  of theta, not of r) drawn by default gets two panels, r's range (about
  l0 = 1 stretched, 1.2 at the start) in the first and theta's (within
  +-0.35 rad of a 0.3 rad start) in the second; the double pendulum's two
  angles share one panel.
"""
import json
import argparse
import subprocess
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / 'util'))
from png import read_png  # noqa: E402

EX = Path(__file__).resolve().parents[2] / 'examples'
RING = [str(EX / 'ring_three_masses.qd'), '--about',
        'x1=0, y1=0, x2=1, y2=0, x3=0.5, y3=sqrt(3)/2']


def ink_rows(png, rows):
    """How many of the rows hold a dark pixel (the title's letters)."""
    w, _, px = png
    return sum(any(max(px(x, y)) < 100 for x in range(w)) for y in rows)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--build', required=True)
    qdot = str(Path(ap.parse_args().build).resolve() / 'qdot')
    tmp = Path(tempfile.mkdtemp(prefix='qdot-plot-look-'))
    failures = []

    def draw(cmd, name, *extra):
        png = tmp / name
        p = subprocess.run([qdot, *cmd, '--plot', str(png), *extra], capture_output=True,
                           text=True, timeout=120)
        if p.returncode:
            failures.append(f'{name}: exit {p.returncode} {p.stderr}')
            return None
        return read_png(png)

    sim = ['simulate', str(EX / 'double_pendulum.qd'), '--t-end', '2']
    a = draw(sim, 'a.png')
    b = draw(sim, 'b.png', '--dpi', '192')
    if a and b:
        if (b[0], b[1]) != (2 * a[0], 2 * a[1]):
            failures.append(f'--dpi 192: {b[0]}x{b[1]}, at 96 dpi {a[0]}x{a[1]}')
        ta, tb = ink_rows(a, range(0, 30)), ink_rows(b, range(0, 60))
        if not (ta > 5 and abs(tb - 2 * ta) <= 3):
            failures.append(f'title ink rows: {ta} at 96 dpi, {tb} at 192')
    for bad in (['--dpi', '50', '--plot', str(tmp / 'c.png')], ['--dpi', '150']):
        p = subprocess.run([qdot, *sim, *bad], capture_output=True, text=True, timeout=120)
        if p.returncode != 2:
            failures.append(f'{bad}: exit {p.returncode} {p.stderr}')

    modes = ['modes', *RING]
    m0 = draw(modes, 'm0.png', '--size', '1200x800')
    m1 = draw(modes, 'm1.png', '--size', '1200x800', '--title', 'Three masses, three springs')
    m2 = draw(modes, 'm2.png', '--size', '1200x800', '--symmetry')
    if m0 and m1 and m2:
        w, h, p0 = m0
        if (w, h) != (1200, 800):
            failures.append(f'modes --size 1200x800 gave {w}x{h}')

        def differ(other, xs, ys):
            return sum(p0(x, y) != other[2](x, y) for y in ys for x in xs)

        title = differ(m1, range(0, w, 2), range(0, 30))
        below = differ(m1, range(0, w, 2), range(60, h, 2))
        if title < 20 or below:
            failures.append(f'--title changed {title} pixels of the title band, {below} below')
        # the irreps' notes: in the panels (below the title and legend), and
        # not in the title band
        notes = differ(m2, range(0, w, 2), range(60, h, 2))
        top = differ(m2, range(0, w, 2), range(0, 30))
        if notes < 20 or top:
            failures.append(f'--symmetry changed {notes} pixels in the panels, {top} above')
    def panels(model):
        p = subprocess.run([qdot, 'simulate', str(EX / model), '--t-end', '5', '--format', 'json',
                            '--plot', str(tmp / 'u.png')], capture_output=True, text=True,
                           timeout=120)
        if p.returncode:
            failures.append(f'{model}: exit {p.returncode} {p.stderr}')
            return []
        return json.loads(p.stdout)['plot']['panels']

    sp = panels('spring_pendulum.qd')
    if len(sp) != 2 or not (1.0 < sp[0]['y0'] < 1.2 < sp[0]['y1'] < 1.6) or \
            not (-0.4 < sp[1]['y0'] < -0.3 and 0.3 < sp[1]['y1'] < 0.4):
        failures.append(f'spring pendulum: panels {sp} (r, then theta)')
    if len(panels('double_pendulum.qd')) != 1:
        failures.append('double pendulum: its two angles in more than one panel')
    for f in failures:
        print('FAIL:', f)
    print('check_plot_look_cli:', 'FAIL' if failures else 'ok')
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())

#!/usr/bin/env python3
"""End-to-end checks of the --plot options (simulate, poincare, modes).

The pictures are looked at: a small PNG decoder (8-bit RGB/RGBA,
non-interlaced: what Cairo writes) reads them back.  The undamped pendulum
(examples/damped_pendulum.qd with k = 0) is simulated with --plot and --out:
the plot's frame is found by its black border, and the curve's pixels in
each column must sit on a straight-line image of theta(t) from the CSV (the
y axis is an affine map: fitted, then the residual must be under 2 px and
the frame must show the data's whole range); the phase portrait's pixels lie
where the data (theta, theta') puts them between the curve's own extremes;
SVG and PDF by their magic; poincare's dots; modes --plot on the elastic
pendulum, whose swing mode moves the bob sideways and whose stretch mode moves
it vertically (Goldstein ch. 1 ex. 24, seed 002); and the documented errors'
exit statuses.
"""
import argparse
import csv
import io
import json
import subprocess
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / 'util'))
from png import read_png  # noqa: E402  (tests/util/png.py)

EX = Path(__file__).resolve().parents[2] / 'examples'
BLUE = (0x1f, 0x77, 0xb4)  # the first series' colour (src/plot/plot.c palette)


def run(qdot, *args):
    p = subprocess.run([str(qdot), *map(str, args)], capture_output=True, text=True,
                       timeout=120)
    return p.returncode, p.stdout, p.stderr


def near(c, want, tol=40):
    return max(abs(a - b) for a, b in zip(c, want)) <= tol


def frame(w, h, at):
    """The plot area's border: columns and rows holding a long black run."""
    cols = [x for x in range(w) if sum(at(x, y) == (0, 0, 0) for y in range(0, h, 2)) > h // 4]
    rows = [y for y in range(h) if sum(at(x, y) == (0, 0, 0) for x in range(0, w, 2)) > w // 4]
    return cols[0], cols[-1], rows[0], rows[-1]


def fit(xs, ys):
    n = len(xs)
    mx, my = sum(xs) / n, sum(ys) / n
    b = sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sum((x - mx) ** 2 for x in xs)
    return my - b * mx, b


def table(path):
    r = list(csv.reader(io.StringIO(Path(path).read_text())))
    return r[0], [[float(v) for v in row] for row in r[1:]]


def interp(ts, vs, t):
    lo, hi = 0, len(ts) - 1
    while hi - lo > 1:
        mid = (lo + hi) // 2
        lo, hi = (mid, hi) if ts[mid] <= t else (lo, mid)
    f = (t - ts[lo]) / (ts[hi] - ts[lo])
    return vs[lo] + f * (vs[hi] - vs[lo])


def check_mapped(png, csvpath, rng, check):
    """Every 5th row of the CSV where the JSON's axis ranges put it inside
    the frame found in the picture: a curve pixel within a pixel of it."""
    w, h, at = read_png(png)
    left, right, top, bottom = frame(w, h, at)
    names, rows = table(csvpath)
    x0, x1, y0, y1 = rng['x0'], rng['x1'], rng['y0'], rng['y1']
    check(x0 == 0 and x1 == 5, f'time axis {x0}..{x1}, not exactly the run 0..5')
    width, height = right - left - 1, bottom - top - 1
    bad = 0
    for r in rows[::5]:
        px = left + 1 + (r[0] - x0) / (x1 - x0) * width
        py = top + 1 + height - (r[names.index('theta')] - y0) / (y1 - y0) * height
        if not any(near(at(int(px) + dx, int(py) + dy), BLUE)
                   for dx in (-1, 0, 1) for dy in (-1, 0, 1)):
            bad += 1
    check(bad == 0, f'{bad} of {len(rows[::5])} rows have no curve pixel where the axes put them')


def check_time_series(png, csvpath, t_end, check):
    w, h, at = read_png(png)
    check((w, h) == (800, 500), f'size {w}x{h}')
    left, right, top, bottom = frame(w, h, at)
    ink = sum(at(x, y) != (255, 255, 255) for y in range(0, h, 3) for x in range(0, w, 3))
    check(ink > 500, f'blank picture ({ink} samples of ink)')
    names, rows = table(csvpath)
    ts, th = [r[0] for r in rows], [r[names.index('theta')] for r in rows]
    # x: t = 0 at the frame's inner left edge, t_end at its right
    width = right - left - 1
    xs, ys = [], []
    for col in range(left + 3, right - 2):
        hits = [y for y in range(top + 1, bottom) if near(at(col, y), BLUE)]
        if hits:
            t = (col + 0.5 - (left + 1)) / width * t_end
            xs.append(interp(ts, th, t))
            ys.append(sum(hits) / len(hits))
    check(len(xs) > 0.9 * (right - left - 5), f'curve found in {len(xs)} columns')
    if len(xs) < 10:
        return
    a, b = fit(xs, ys)
    worst = max(abs(a + b * x - y) for x, y in zip(xs, ys))
    check(b < 0, f'theta up is pixel row down: slope {b}')
    check(worst < 2.5, f'curve off the data by {worst:.2f} px')
    # the frame shows the data's whole range, padded by at most 30%
    ymin, ymax = a + b * max(th), a + b * min(th)
    check(top < ymin and ymax < bottom, f'data rows {ymin:.1f}..{ymax:.1f} outside {top}..{bottom}')
    check((bottom - top) / (ymax - ymin) < 1.3, f'y range too wide: {(bottom - top) / (ymax - ymin):.2f}')


def check_phase(png, csvpath, check):
    w, h, at = read_png(png)
    left, right, top, bottom = frame(w, h, at)
    pts = [(x, y) for y in range(top + 1, bottom) for x in range(left + 1, right)
           if near(at(x, y), BLUE)]
    check(len(pts) > 500, f'phase curve: {len(pts)} pixels')
    if len(pts) < 10:
        return
    names, rows = table(csvpath)
    q, v = [r[names.index('theta')] for r in rows], [r[names.index("theta'")] for r in rows]
    # the curve's extreme pixels are the data's extremes (line 2 px wide)
    x0, x1 = min(p[0] for p in pts) + 1, max(p[0] for p in pts)
    y0, y1 = min(p[1] for p in pts) + 1, max(p[1] for p in pts)
    bad = 0
    for qi, vi in list(zip(q, v))[::7]:
        px = x0 + (qi - min(q)) / (max(q) - min(q)) * (x1 - x0)
        py = y1 - (vi - min(v)) / (max(v) - min(v)) * (y1 - y0)
        if not any(near(at(int(px) + dx, int(py) + dy), BLUE)
                   for dx in (-2, -1, 0, 1, 2) for dy in (-2, -1, 0, 1, 2)):
            bad += 1
    check(bad == 0, f'phase: {bad} data points with no curve pixel near them')
    # the centre of the loop (theta = 0, theta' = 0) is background
    cx, cy = (x0 + x1) // 2, (y0 + y1) // 2
    check(at(cx, cy) == (255, 255, 255), f'phase loop centre {at(cx, cy)}')


def centroid(pts):
    return (sum(p[0] for p in pts) / len(pts), sum(p[1] for p in pts) / len(pts)) if pts else None


def check_spring_modes(png, check):
    w, h, at = read_png(png)
    orange = (0xff, 0x7f, 0x0e)
    for k, along in ((0, 'x'), (1, 'y')):
        # panel k: the k-th half of the picture, below its legend
        xs = range(k * w // 2, (k + 1) * w // 2)
        pix = [(x, y) for y in range(90, h) for x in xs]
        rest = centroid([p for p in pix if near(at(*p), BLUE, 30)])
        moved = centroid([p for p in pix if near(at(*p), orange, 30)])
        check(rest and moved, f'mode {k + 1}: dots not found')
        if not (rest and moved):
            continue
        dx, dy = abs(moved[0] - rest[0]), abs(moved[1] - rest[1])
        ok = (dx > 20 and dy < 1.5) if along == 'x' else (dy > 20 and dx < 1.5)
        check(ok, f'mode {k + 1} should move the bob along {along}: dx {dx:.1f}, dy {dy:.1f}')


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--build', required=True)
    qdot = Path(ap.parse_args().build).resolve() / 'qdot'
    failures = []
    tmp = Path(tempfile.mkdtemp(prefix='qdot-plot-'))

    def check(cond, what):
        if not cond:
            failures.append(what)

    pend = [EX / 'damped_pendulum.qd', '--set', 'k=0', '--t-end', 5, '--dt', 0.01]
    rc, out, err = run(qdot, 'simulate', *pend, '--plot', tmp / 'p.png', '--out', tmp / 'p.csv')
    check(rc == 0, f'simulate --plot: {rc} {err}')
    if rc == 0:
        check_time_series(tmp / 'p.png', tmp / 'p.csv', 5, check)
    # --format json reports the axes' ranges: the data must be drawn there
    rc, out, err = run(qdot, 'simulate', *pend, '--plot', tmp / 'j.png', '--out', tmp / 'j.csv',
                       '--format', 'json')
    check(rc == 0 and 'plot' in out, f'--plot --format json: {rc} {err}')
    if rc == 0:
        check_mapped(tmp / 'j.png', tmp / 'j.csv', json.loads(out)['plot']['panels'][0], check)
    # the rows written do not depend on --plot (issue 36): the steps, as without it
    rc, out, err = run(qdot, 'simulate', EX / 'damped_pendulum.qd', '--t-end', 5, '--plot',
                       tmp / 'g.png', '--out', tmp / 'g.csv')
    run(qdot, 'simulate', EX / 'damped_pendulum.qd', '--t-end', 5, '--out', tmp / 'g0.csv')
    check(rc == 0 and (tmp / 'g.csv').read_text() == (tmp / 'g0.csv').read_text(),
          f'--plot changed the rows: {rc} {err}')
    # --plot alone: the picture, and no CSV on stdout
    rc, out, err = run(qdot, 'simulate', *pend, '--plot', tmp / 'q.png')
    check(rc == 0 and out == '' and (tmp / 'q.png').stat().st_size > 5000,
          f'--plot alone: {rc} {len(out)} {err}')
    rc, out, err = run(qdot, 'simulate', *pend, '--phase', 'theta', '--plot', tmp / 'ph.png',
                       '--out', tmp / 'ph.csv')
    check(rc == 0, f'--phase: {rc} {err}')
    if rc == 0:
        check_phase(tmp / 'ph.png', tmp / 'ph.csv', check)
    rc, out, err = run(qdot, 'simulate', *pend, '--plot-y', "theta', energy_error",
                       '--plot', tmp / 'e.png')
    check(rc == 0, f'--plot-y energy_error: {rc} {err}')
    for ext, magic in (('svg', (b'<?xml', b'<svg')), ('pdf', (b'%PDF-',))):
        f = tmp / f'p.{ext}'
        rc, out, err = run(qdot, 'simulate', *pend, '--plot', f)
        head = f.read_bytes()[:64] if f.exists() else b''
        check(rc == 0 and any(head.startswith(m) for m in magic) and f.stat().st_size > 3000,
              f'{ext}: {rc} {head[:10]} {err}')

    # poincare: the section's points, in the coordinate the section leaves free
    dp = EX / 'double_pendulum.qd'
    rc, out, err = run(qdot, 'poincare', dp, '--section', "theta1 = 0, theta1' > 0", '--crossings', 40,
                       '--initial', 'theta1=1, theta2=0.5', '--plot', tmp / 'pc.png')
    check(rc == 0 and len(out.splitlines()) == 41, f'poincare --plot: {rc} {err}')
    if rc == 0:
        w, h, at = read_png(tmp / 'pc.png')
        dots = sum(near(at(x, y), BLUE) for y in range(h) for x in range(w))
        check(dots > 40 * 8, f'poincare: {dots} dot pixels for 40 crossings')

    # modes: the elastic pendulum about its hanging rest (examples/spring_pendulum.qd)
    # decouples into the swing (w^2 = g/r0), which moves the bob sideways, and the
    # stretch (w^2 = k/m), which moves it along the vertical: in each mode's panel
    # the moved bob (orange) is level with the bob at rest (blue), or right under it.
    rc, out, err = run(qdot, 'modes', EX / 'spring_pendulum.qd', '--plot', tmp / 'm.png')
    check(rc == 0 and 'mode 2' in out, f'modes --plot: {rc} {err}')
    if rc == 0:
        check_spring_modes(tmp / 'm.png', check)
    rc, out, err = run(qdot, 'modes', EX / 'damped_pendulum.qd', '--plot', tmp / 'd.png')
    check(rc == 2 and not (tmp / 'd.png').exists(), f'modes --plot with damping: {rc}')

    # errors: bad input 2, as --out's unwritable file
    for args, what in (
            (['--plot', tmp / 'p.jpg'], 'unknown extension'),
            (['--plot', tmp / 'no-such-dir' / 'p.png'], 'unwritable'),
            (['--plot', tmp / 'x.png', '--plot-y', 'nosuch'], '--plot-y unknown name'),
            (['--plot', tmp / 'x.png', '--phase', 'nosuch'], '--phase unknown name'),
            (['--phase', 'theta'], '--phase without --plot'),
            (['--plot', tmp / 'x.png', '--phase', 'theta', '--plot-y', 'theta'], 'both')):
        rc, out, err = run(qdot, 'simulate', *pend, *args)
        check(rc == 2 and 'error' in err, f'{what}: exit {rc}, {err}')
    check(not (tmp / 'p.jpg').exists(), 'an unknown extension wrote a file')
    check(not (tmp / 'x.png').exists(), 'a refused --plot-y wrote a file')

    for f in failures:
        print('FAIL:', f)
    print(f'check_plot_cli: {"FAILED" if failures else "ok"}')
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())

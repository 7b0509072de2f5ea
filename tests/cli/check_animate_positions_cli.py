#!/usr/bin/env python3
"""`qdot animate` on models written with named positions, and with every
option of `simulate` (issue 36).

1. The README's flagship, examples/double_pendulum.qd (Goldstein ch. 1
   ex. 22), has no `particle`: its points are the named positions
   (x1, y1) and (x2, y2).  The page draws both, with the rods origin-(x1,y1)
   and (x1,y1)-(x2,y2) found from their constant distances l1 = l2 = 1, in
   the x-y plane; in headless chromium each bob is at the pixel where
   `qdot simulate --output "x1, y1, x2, y2"` puts it at t = 0 and t = 1.5.
2. The LQR-balanced cart of the README (`--input "F = lqr" --about ... --lqr
   ...`, options animate used to refuse): the page renders the pendulum's bob
   where simulate puts it at t = 0.5, and at t = 10 the bob stands upright
   over the cart (tilt < 1e-3 rad: balanced).
3. --draw chooses the points; a name that is no point is exit 2 with the
   points listed.
"""
import argparse
import csv
import io
import json
import os
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
sys.path.insert(0, str(Path(__file__).resolve().parents[1] / 'util'))
from check_animate_cli import (browser, chrome, dot, page_state, radius, run, scene,  # noqa: E402
                               P1_RGB, P2_RGB, CANVAS, WINDOW)
from png import read_png  # noqa: E402

EX = Path(__file__).resolve().parents[2] / 'examples'
DP = EX / 'double_pendulum.qd'
CART = EX / 'cart_pendulum.qd'
CART_ARGS = ['--dt', '0.01', '--initial', 'th=0.2', '--input', 'F = lqr', '--about',
             "th=0, th'=0, x=0, x'=0, F=0", '--lqr', 'Q = diag(1, 10, 1, 1), R = 0.1']


def simulated(qdot, model, args, t, out):
    """The last row of `simulate --output out` run to t (t = 0: the first row)."""
    rc, text, err = run(qdot, 'simulate', model, *args, '--t-end', t or 1e-9, '--output', out)
    assert rc == 0, err
    rows = list(csv.reader(io.StringIO(text)))
    return [float(v) for v in (rows[1] if t == 0 else rows[-1])]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--build', required=True)
    qdot = Path(ap.parse_args().build).resolve() / 'qdot'
    failures = []
    tmp = Path(tempfile.mkdtemp(prefix='qdot-animate-pos-'))

    def check(cond, what):
        if not cond:
            failures.append(what)

    dp = tmp / 'dp.html'
    rc, _, err = run(qdot, 'animate', DP, '--t-end', 3, '--trace', 'x2', '-o', dp)
    check(rc == 0, f'flagship animate: {rc} {err}')
    cart = tmp / 'cart.html'
    rc2, _, err2 = run(qdot, 'animate', CART, *CART_ARGS, '--t-end', 10, '-o', cart)
    check(rc2 == 0, f'LQR cart animate: {rc2} {err2}')
    if rc or rc2:
        return report(failures)
    s = scene(dp.read_text())
    check([p['name'] for p in s['points']] == ['x1,y1', 'x2,y2'], f'points {s["points"]}')
    check(sorted(map(tuple, s['links'])) == [(-1, 0, 0), (0, 1, 0)], f'links {s["links"]}')
    check(s['plane'] == [0, 1] and s['traces'] == [1], f'plane {s["plane"]} traces {s["traces"]}')
    c = scene(cart.read_text())
    # the cart p1 and the bob p2 at distance l = 0.5: one rod
    check(sorted(map(tuple, c['links'])) == [(0, 1, 0)], f'cart links {c["links"]}')
    f = len(c['t']) - 1
    cx, cy, bx, by = c['pos'][f * 6], c['pos'][f * 6 + 1], c['pos'][f * 6 + 3], c['pos'][f * 6 + 4]
    check(abs(bx - cx) < 0.5e-3 and abs(by - 0.5) < 1e-6 and abs(c['t'][f] - 10) < 1e-9,
          f'the cart is not balanced at t = {c["t"][f]}: cart {cx},{cy} bob {bx},{by}')

    rc, _, err = run(qdot, 'animate', DP, '--draw', 'x9', '-o', tmp / 'none.html')
    check(rc == 2 and "no point 'x9'" in err and 'x1,y1; x2,y2' in err, f'--draw x9: {rc} {err}')
    rc, _, err = run(qdot, 'animate', DP, '--draw', 'y2', '-o', tmp / 'one.html')
    check(rc == 0 and [p['name'] for p in scene((tmp / 'one.html').read_text())['points']]
          == ['x2,y2'], f'--draw y2: {rc} {err}')
    rc, _, err = run(qdot, 'animate', EX / 'double_pendulum_force.qd', '--set', 'F=0',
                     '--draw', 'positions', '--t-end', 1, '-o', tmp / 'both.html')
    # its particles are not drawn when --draw asks only for named positions, of which it has none
    check(rc == 2 and 'nothing to draw' in err, f'--draw positions: {rc} {err}')

    exe = browser()
    if not exe:
        if os.environ.get('QDOT_ALLOW_NO_BROWSER') == '1':
            print('check_animate_positions_cli: SKIP the browser half: no chromium')
            return report(failures)
        failures.append('no chromium (scripts/deps.sh test), or set QDOT_ALLOW_NO_BROWSER=1')
        return report(failures)
    profile = tmp / 'profile'

    def shot(html, t, name):
        url = f'{html.as_uri()}#t={t}&paused=1&size={CANVAS[0]}x{CANVAS[1]}'
        png = tmp / f'{name}{t}.png'
        st = page_state(exe, profile, url)
        chrome(exe, profile, f'--screenshot={png}', url)
        if not png.exists() or 'transform' not in st:
            failures.append(f'{name} t = {t}: no picture or no transform')
            return None, None
        w, h, px = read_png(png)
        check((w, h) == WINDOW, f'{name}: screenshot {w}x{h}')
        tr = json.loads(st['transform'])
        return px, lambda r: (round(tr['ox'] + tr['s'] * r[0]), round(tr['oy'] - tr['s'] * r[1]))

    for t in (0, 1.5):
        px, pixel = shot(dp, t, 'dp')
        if not px:
            continue
        row = simulated(qdot, DP, [], t, 'x1, y1, x2, y2')
        for k, rgb in ((0, P1_RGB), (1, P2_RGB)):
            x, y = pixel((row[-4 + 2 * k], row[-3 + 2 * k]))
            check(dot(px, x, y, rgb, radius(1, 1)), f'flagship t = {t}: bob {k + 1} not at {x},{y}')
    for t in (0.5, 10):
        px, pixel = shot(cart, t, 'cart')
        if not px:
            continue
        row = simulated(qdot, CART, CART_ARGS, t, 'x - 0.5*sin(th), 0.5*cos(th)')
        x, y = pixel((row[-2], row[-1]))
        m = [p['mass'] for p in c['points']]
        check(dot(px, x, y, P2_RGB, radius(m[1], max(m))), f'cart t = {t}: bob not at {x},{y}')
    return report(failures)


def report(failures):
    for f in failures:
        print('FAIL:', f)
    print('check_animate_positions_cli:', 'FAIL' if failures else 'ok')
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())

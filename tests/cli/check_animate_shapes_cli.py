#!/usr/bin/env python3
"""`qdot animate` draws bodies as their shapes, on the ground they roll on
(issue 36), checked against the mechanics and in headless chromium.

1. examples/disk_incline_shape.qd, a uniform disk rolling down an incline
   (Byerly Art. 9c, reference seed-byerly.md TC17): the scene's disk has the
   radius a of its `shape` line and the incline's plane as its ground; its
   centre at t = 1 has gone (1/2)(2/3) g sin(al) t^2 down the slope, where
   `simulate` puts it; in the page the centre's dot is at that pixel, the
   circle's rim a pixels above it, and the incline's line at the contact
   point c - a n.
2. examples/double_rod_pendulum.qd (Desloge ch. 50 Problem 1): each rod
   drawn from its inertia rod(m, l) as a segment of its length; in the page
   at t = 1 rod 1 covers the pixels between the pivot and the hinge and rod 2
   those between the hinge and its free end, where `simulate` puts them.
3. `qdot animate --help` says how to choose what is drawn.
"""
import argparse
import json
import math
import os
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
sys.path.insert(0, str(Path(__file__).resolve().parents[1] / 'util'))
from check_animate_cli import browser, chrome, found, page_state, run, scene  # noqa: E402
from check_animate_cli import P1_RGB, P2_RGB, CANVAS, WINDOW  # noqa: E402
from check_animate_positions_cli import simulated  # noqa: E402
from png import read_png  # noqa: E402

EX = Path(__file__).resolve().parents[2] / 'examples'
DISK = EX / 'disk_incline_shape.qd'
RODS = EX / 'double_rod_pendulum.qd'
G, AL, A = 9.81, 0.3, 0.3            # the disk model's g, al, a
L1, L2 = 1.2, 0.9                    # the rods' lengths
CENTRE_RGB = (0x22, 0x22, 0x22)      # a shape's centre dot
GROUND_RGB = (0x8a, 0x7a, 0x5a)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--build', required=True)
    qdot = Path(ap.parse_args().build).resolve() / 'qdot'
    failures = []
    tmp = Path(tempfile.mkdtemp(prefix='qdot-animate-shapes-'))

    def check(cond, what):
        if not cond:
            failures.append(what)

    rc, out, err = run(qdot, 'animate', '--help')
    check(rc == 0 and 'shape BODY as' in out and '--draw' in out, f'--help: {rc} {out} {err}')

    disk, rods = tmp / 'disk.html', tmp / 'rods.html'
    rc, _, err = run(qdot, 'animate', DISK, '--t-end', 1, '-o', disk)
    check(rc == 0, f'disk animate: {rc} {err}')
    rc2, _, err2 = run(qdot, 'animate', RODS, '--t-end', 1, '-o', rods)
    check(rc2 == 0, f'rods animate: {rc2} {err2}')
    if rc or rc2:
        return report(failures)

    d = scene(disk.read_text())
    p = d['points'][0]
    n = (math.sin(AL), math.cos(AL), 0)
    check(p.get('shape') == 'disk' and abs(p['size'][0] - A) < 1e-12 and p['axis'] == 2,
          f'the disk is drawn as {p}')
    check(all(abs(u - v) < 1e-7 for u, v in zip(p.get('ground', []), (*n, 0, 0, 0))),
          f'the ground {p.get("ground")}')
    f = len(d['t']) - 1
    s = 0.5 * (2 / 3) * G * math.sin(AL) * d['t'][f] ** 2     # down the slope
    c0 = (A * n[0], A * n[1])
    want = (c0[0] + s * math.cos(AL), c0[1] - s * math.sin(AL))
    got = d['pos'][3 * f:3 * f + 2]
    check(abs(d['t'][f] - 1) < 1e-12 and math.dist(want, got) < 1e-5,  # the page keeps 7 digits
          f'the disk at t = {d["t"][f]}: {got}, not (2/3) g sin(al) down the slope {want}')
    r = scene(rods.read_text())
    check([q.get('shape') for q in r['points']] == ['rod', 'rod'] and
          [round(q['size'][0], 12) for q in r['points']] == [L1, L2], f'the rods {r["points"]}')

    exe = browser()
    if not exe:
        if os.environ.get('QDOT_ALLOW_NO_BROWSER') == '1':
            print('check_animate_shapes_cli: SKIP the browser half: no chromium')
            return report(failures)
        failures.append('no chromium (scripts/deps.sh test), or set QDOT_ALLOW_NO_BROWSER=1')
        return report(failures)
    profile = tmp / 'profile'

    def shot(html, t, name):
        url = f'{html.as_uri()}#t={t}&paused=1&size={CANVAS[0]}x{CANVAS[1]}'
        png = tmp / f'{name}.png'
        st = page_state(exe, profile, url)
        chrome(exe, profile, f'--screenshot={png}', url)
        if not png.exists() or 'transform' not in st:
            failures.append(f'{name}: no picture or no transform')
            return None, None, None
        w, h, px = read_png(png)
        check((w, h) == WINDOW, f'{name}: screenshot {w}x{h}')
        tr = json.loads(st['transform'])
        return px, tr, lambda q: (round(tr['ox'] + tr['s'] * q[0]),
                                  round(tr['oy'] - tr['s'] * q[1]))

    px, tr, pixel = shot(disk, 1, 'disk')
    if px:
        c = simulated(qdot, DISK, [], 1, 'x, y')[-2:]
        x, y = pixel(c)
        check(found(px, x, y, CENTRE_RGB, r=1), f'disk centre not at {x},{y}: {px(x, y)}')
        xr, yr = pixel((c[0], c[1] + A))   # the rim above the centre (a 2 px line)
        check(found(px, xr, yr, P1_RGB, tol=40, r=2), f'disk rim not at {xr},{yr}: {px(xr, yr)}')
        xg, yg = pixel((c[0] - A * n[0], c[1] - A * n[1]))     # the contact, on the incline
        check(found(px, xg, yg, GROUND_RGB, tol=40, r=2),
              f'incline not at {xg},{yg}: {px(xg, yg)}')
        check(not found(px, xg, yg - round(2 * A * tr['s']) - 8, GROUND_RGB, tol=40, r=2),
              'the incline line drawn above the disk')

    px, tr, pixel = shot(rods, 1, 'rods')
    if px:
        th1, th2 = simulated(qdot, RODS, [], 1, 'theta1, theta2')[-2:]
        hinge = (L1 * math.sin(th1), -L1 * math.cos(th1))
        tip = (hinge[0] + L2 * math.sin(th2), hinge[1] - L2 * math.cos(th2))
        for w in (0.2, 0.8):     # away from the centre dots (at 0.5) and the ends
            q1 = pixel((w * hinge[0], w * hinge[1]))
            q2 = pixel((hinge[0] + w * (tip[0] - hinge[0]), hinge[1] + w * (tip[1] - hinge[1])))
            check(found(px, *q1, P1_RGB), f'rod 1 not at {q1} ({w} along): {px(*q1)}')
            check(found(px, *q2, P2_RGB), f'rod 2 not at {q2} ({w} along): {px(*q2)}')
        beyond = pixel((tip[0] + 0.15 * (tip[0] - hinge[0]), tip[1] + 0.15 * (tip[1] - hinge[1])))
        check(not found(px, *beyond, P2_RGB, r=2), f'rod 2 drawn past its end at {beyond}')
    return report(failures)


def report(failures):
    for f in failures:
        print('FAIL:', f)
    print('check_animate_shapes_cli:', 'FAIL' if failures else 'ok')
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())

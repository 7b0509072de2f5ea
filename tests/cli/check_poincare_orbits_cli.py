#!/usr/bin/env python3
"""End-to-end checks of `qdot poincare` with several orbits (--initial given
again, issue 36) and --point-size.

The Henon-Heiles system (examples/henon_heiles.qd; Henon & Heiles, Astron. J.
69 (1964) 73) at E = 1/8, the chaotic orbit from y = -0.25 and the regular one
from y = 0.55 (Skokos, Lect. Notes Phys. 790 (2010) 63), and a third at E =
1/12:
  - the CSV has an orbit column before the run's, the orbits in turn, each
    with its crossings; every crossing is on the section (x = 0, x' > 0) and
    has its own orbit's energy E = (x'^2 + y'^2)/2 + V(0, y) (the energy is
    conserved, and computed here from the --initial values, not by qdot);
  - without --initial, or with one, the CSV is as before (no orbit column);
  - --plot draws each orbit in its own colour of the palette (the first
    three: blue, orange, green), each colour's pixels where that orbit's
    crossings are (the regular orbit's islands keep |y'| < 0.2, the chaotic
    orbit's crossings reach |y'| > 0.4: the first colour spans more than
    twice the second's height, both about y' = 0); --point-size
    6 paints more of a colour than --point-size 1;
  - --help lists --initial once; a mistake in the second --initial is shown
    there, with exit 2 and no row written; --point-size without --plot or
    out of range is exit 2.
"""
import argparse
import math
import subprocess
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / 'util'))
from png import read_png  # noqa: E402  (tests/util/png.py)

EX = Path(__file__).resolve().parents[2] / 'examples'
HH = EX / 'henon_heiles.qd'
PALETTE = [(0x1f, 0x77, 0xb4), (0xff, 0x7f, 0x0e), (0x2c, 0xa0, 0x2c)]  # src/plot/plot.c
SECTION = ['--section', "x = 0, x' > 0"]


def V(x, y):
    return (x * x + y * y) / 2 + x * x * y - y ** 3 / 3


def xdot(E, y):
    return math.sqrt(2 * (E - V(0, y)))


ORBITS = [(-0.25, 1 / 8), (0.55, 1 / 8), (0.1, 1 / 12)]  # (y0, E), x = y' = 0 at the start
INITIAL = [f"y={y!r}, x'={xdot(E, y)!r}" for y, E in ORBITS]


def run(qdot, *args):
    p = subprocess.run([str(qdot), *map(str, args)], capture_output=True, text=True,
                       timeout=120)
    return p.returncode, p.stdout, p.stderr


def near(c, want, tol=30):
    return max(abs(a - b) for a, b in zip(c, want)) <= tol


def frame(w, h, at):
    """The plot area's border: columns and rows holding a long black run."""
    cols = [x for x in range(w) if sum(at(x, y) == (0, 0, 0) for y in range(0, h, 2)) > h // 4]
    rows = [y for y in range(h) if sum(at(x, y) == (0, 0, 0) for x in range(0, w, 2)) > w // 4]
    return cols[0], cols[-1], rows[0], rows[-1]


def colour_pixels(png):
    """The pixels of each palette colour inside the plot area (not the legend's)."""
    w, h, at = read_png(png)
    left, right, top, bottom = frame(w, h, at)
    found = [[] for _ in PALETTE]
    for y in range(top + 1, bottom):
        for x in range(left + 1, right):
            c = at(x, y)
            for k, want in enumerate(PALETTE):
                if near(c, want):
                    found[k].append((x, y))
    return found


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--build', required=True)
    qdot = Path(ap.parse_args().build).resolve() / 'qdot'
    tmp = Path(tempfile.mkdtemp(prefix='qdot-orbits-'))
    failures = []

    def check(cond, what):
        if not cond:
            failures.append(what)

    n = 150
    args = [HH, *SECTION, '--crossings', n]
    for init in INITIAL:
        args += ['--initial', init]
    rc, out, err = run(qdot, 'poincare', *args, '--phase', 'y', '--plot', tmp / 'o.png',
                       '--point-size', 2)
    lines = out.splitlines()
    check(rc == 0 and lines and lines[0] == "orbit,t,x,y,x',y',energy",
          f'orbits: {rc} {lines[:1]} {err}')
    check(err.count('orbit ') == 3 and 'orbit 3: dop853, 150 crossings' in err, err)
    rows = [[float(v) for v in l.split(',')] for l in lines[1:]]
    orbit = [int(r[0]) for r in rows]
    check(orbit == sorted(orbit) and [orbit.count(k) for k in (1, 2, 3)] == [n] * 3,
          f'orbit column: {[orbit.count(k) for k in (1, 2, 3)]}')
    worst = 0
    for r in rows:
        k, x, y, xd, yd = int(r[0]) - 1, r[2], r[3], r[4], r[5]
        E = ORBITS[k][1]
        worst = max(worst, abs((xd * xd + yd * yd) / 2 + V(x, y) - E), abs(x) * 1e-2)
        check(xd > 0, f'orbit {k + 1}: x\' = {xd} at a crossing')
    check(worst < 1e-8, f'energy at the crossings off by {worst}')
    # the regular orbit from y = 0.55 stays on its islands, |y'| < 0.2; the chaotic one not
    yd = [[abs(r[5]) for r in rows if r[0] == k] for k in (1, 2)]
    check(max(yd[1]) < 0.2 and max(yd[0]) > 0.4, f"max |y'| {max(yd[0])}, {max(yd[1])}")
    if rc == 0:
        found = colour_pixels(tmp / 'o.png')
        counts = [len(f) for f in found]
        check(all(c > 200 for c in counts), f'colour pixels per orbit {counts}')
        # up (y'): the chaotic orbit's dots span more than twice the regular one's, both
        # centred on y' = 0 (the section is symmetric under y' -> -y')
        lo = [min(y for _, y in f) for f in found[:2]]
        hi = [max(y for _, y in f) for f in found[:2]]
        check(hi[0] - lo[0] > 2 * (hi[1] - lo[1]) and
              abs((hi[0] + lo[0]) - (hi[1] + lo[1])) / 2 < 0.1 * (hi[0] - lo[0]),
              f'rows of the chaotic orbit {lo[0]}..{hi[0]}, the regular {lo[1]}..{hi[1]}')

    # one orbit: as before, no orbit column
    rc, out, err = run(qdot, 'poincare', HH, *SECTION, '--crossings', 3, '--initial', INITIAL[0])
    check(rc == 0 and out.splitlines()[0] == "t,x,y,x',y',energy" and 'orbit' not in err,
          f'one orbit: {rc} {out[:40]} {err}')

    # --point-size: a larger dot paints more pixels
    sizes = []
    for ps in (1, 6):
        rc, out, err = run(qdot, 'poincare', HH, *SECTION, '--crossings', 60, '--initial',
                           INITIAL[1], '--plot', tmp / f's{ps}.png', '--point-size', ps)
        check(rc == 0, f'--point-size {ps}: {rc} {err}')
        sizes.append(len(colour_pixels(tmp / f's{ps}.png')[0]) if rc == 0 else 0)
    check(sizes[1] > 4 * sizes[0], f'--point-size 1 and 6 paint {sizes} pixels')

    rc, out, err = run(qdot, 'poincare', '--help')
    check(rc == 0 and out.count('--initial') == 1 and '--point-size' in out, out)
    rc, out, err = run(qdot, 'poincare', HH, *SECTION, '--crossings', 3, '--initial', INITIAL[0],
                       '--initial', "y=0.1, z=2")
    check(rc == 2 and out == '' and 'z=2' in err and "unknown name 'z'" in err,
          f'a bad second --initial: {rc} {out[:40]} {err}')
    for extra, what in ((['--point-size', 2], 'without --plot'),
                        (['--plot', tmp / 'x.png', '--point-size', 50], 'out of range')):
        rc, out, err = run(qdot, 'poincare', HH, *SECTION, '--crossings', 3, *extra)
        check(rc == 2 and 'error' in err, f'--point-size {what}: {rc} {err}')
    check(not (tmp / 'x.png').exists(), 'a refused --point-size wrote a file')

    for f in failures:
        print('FAIL:', f)
    print(f'check_poincare_orbits_cli: {"FAILED" if failures else "ok"}')
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())

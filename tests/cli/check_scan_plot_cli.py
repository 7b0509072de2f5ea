#!/usr/bin/python3
"""tests/cli/check_scan_plot_cli.py - `qdot linearize --scan v=0:10 --plot
FILE.png` on the Whipple bicycle (examples/whipple_bicycle.qd, issue 37):
the eigenvalues against the forward speed v, read back from the pixels.

Meijaard, Papadopoulos, Ruina and Schwab, Proc. R. Soc. A 463 (2007), sec. 5
and fig. 3: the benchmark bicycle is self-stable between the weave speed
4.2924 m/s (a complex pair crosses the imaginary axis) and the capsize
speed 6.0243 m/s (a real eigenvalue crosses 0).  Checked:

  1. the scan's JSON crossings are the paper's speeds (to 1e-4) and kinds;
  2. in the picture's upper panel (Re s), the two vertical lines (the
     second and third colours of the palette) stand where those speeds fall
     on the axis the eigenvalue dots span (v from 0 to 10: the leftmost and
     rightmost dots' centres), to 1.5 pixels;
  3. the lower panel (Im s) has the weave pair: dots above the zero row at
     the weave speed and none at v = 0.5 (all four eigenvalues real there:
     fig. 3's real pairs below 0.68 m/s);
  4. --plot without --scan is refused (exit 2).

Usage: check_scan_plot_cli.py --build BUILD_DIR
"""
import argparse
import json
import subprocess
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / 'util'))
from png import read_png  # noqa: E402

MODEL = Path(__file__).resolve().parents[2] / 'examples' / 'whipple_bicycle.qd'
WEAVE, CAPSIZE = 4.2924, 6.0243
BLUE, ORANGE, GREEN = (0x1f, 0x77, 0xb4), (0xff, 0x7f, 0x0e), (0x2c, 0xa0, 0x2c)
failed = 0


def report(ok, what, detail=''):
    global failed
    print(('ok   ' if ok else 'FAIL ') + what + ('' if ok else ': ' + detail))
    failed += 0 if ok else 1


def near(c, ref, tol=40):
    return all(abs(a - b) <= tol for a, b in zip(c, ref))


def columns_of(png, colour, rows):
    """{x: count} of the pixels of colour in the rows given."""
    w, _, px = png
    out = {}
    for y in rows:
        for x in range(w):
            if near(px(x, y), colour):
                out[x] = out.get(x, 0) + 1
    return out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--build', required=True)
    qdot = str(Path(ap.parse_args().build) / 'qdot')
    with tempfile.TemporaryDirectory() as tmp:
        png_path = Path(tmp) / 'eig.png'
        p = subprocess.run([qdot, 'linearize', str(MODEL), '--scan', 'v=0:10', '--format',
                            'json', '--plot', str(png_path)], capture_output=True, text=True,
                           timeout=300)
        report(p.returncode == 0 and png_path.exists(), 'the scan and its picture',
               f'{p.returncode} {p.stderr}')
        if p.returncode != 0:
            return 1
        cross = json.loads(p.stdout)['crossings']
        got = [(round(c['value'], 4), c['omega'] > 0, c['to_stable']) for c in cross]
        report(got == [(WEAVE, True, True), (CAPSIZE, False, False)],
               'weave (complex, stable above) and capsize (real, unstable above) speeds',
               str(got))
        png = read_png(png_path)
        w, h, px = png
        top = range(90, h // 2)  # the upper panel, under the title and legend
        orange, green = columns_of(png, ORANGE, top), columns_of(png, GREEN, top)
        blue = columns_of(png, BLUE, top)
        if not (orange and green and blue):
            report(False, 'the lines and dots drawn', f'{len(orange)} {len(green)} {len(blue)}')
            return 1
        xl, xr = min(blue), max(blue)
        width = 0
        while xl + width in blue:
            width += 1
        r = width / 2  # a dot's radius: the first dot's width
        x0, x1 = xl + r - 0.5, xr - r + 0.5  # the centres of the dots at v = 0 and v = 10

        def at(v):
            return x0 + (x1 - x0) * v / 10

        xo = max(orange, key=orange.get)
        xg = max(green, key=green.get)
        report(abs(xo - at(WEAVE)) <= 1.5,
               f'the weave line at v = {WEAVE} (pixel {xo}, expected {at(WEAVE):.1f})')
        report(abs(xg - at(CAPSIZE)) <= 1.5,
               f'the capsize line at v = {CAPSIZE} (pixel {xg}, expected {at(CAPSIZE):.1f})')
        bottom = range(h // 2 + 60, h - 60)
        low = columns_of(png, BLUE, bottom)
        zero_row = max(bottom, key=lambda y: sum(near(px(x, y), BLUE) for x in range(w)))

        def dots_above(v):
            x = int(round(at(v)))
            return sum(near(px(xx, y), BLUE) for xx in range(x - 2, x + 3)
                       for y in range(bottom.start, zero_row - 8))

        report(bool(low) and dots_above(WEAVE) > 0 and dots_above(0.5) == 0,
               'Im s: the weave pair above zero at the weave speed, none at v = 0.5',
               f'{dots_above(WEAVE)} {dots_above(0.5)}')
    p = subprocess.run([qdot, 'linearize', str(MODEL), '--plot', '/tmp/never.png'],
                       capture_output=True, text=True)
    report(p.returncode == 2 and '--scan' in p.stderr, '--plot without --scan refused',
           f'{p.returncode} {p.stderr}')
    print('FAILED %d' % failed if failed else 'all passed')
    return 1 if failed else 0


if __name__ == '__main__':
    sys.exit(main())

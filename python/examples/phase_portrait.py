#!/usr/bin/env python3
# python/examples/phase_portrait.py - a use of the qdot package: the double
# pendulum's normal modes and a phase portrait of the simple pendulum
# (librations inside the separatrix, rotations outside), written as SVG
# with nothing but the standard library and numpy.
#
#   PYTHONPATH=python /usr/bin/python3 python/examples/phase_portrait.py out.svg
#
# docs/img/python_phase.png is this SVG rendered by headless Chromium
# (docs/python.md says how).
"""Draw the simple pendulum's phase portrait from qdot.Model.simulate."""

import math
import sys

import numpy as np

import qdot

PENDULUM = """
coordinates theta
parameters m = 1, l = 1, g = 9.81
T = m/2*l^2*theta'^2
V = -m*g*l*cos(theta)
"""

W, H, PAD = 640, 400, 50


def trajectories(model):
    """(theta, theta', energy) of runs through theta = 0 at several speeds."""
    g_l = model.params["g"] / model.params["l"]
    sep = 2 * math.sqrt(g_l)  # the separatrix's speed at the bottom
    for frac in (0.3, 0.6, 0.85, 0.98, 1.05, 1.25):
        v0 = frac * sep
        r = model.simulate(6, rtol=1e-10, dt=0.005, initial={"theta'": v0})
        th = (r["theta"] + math.pi) % (2 * math.pi) - math.pi  # one turn
        yield th, r["theta'"], frac, r.energy_error_max
        yield -th, -r["theta'"], frac, r.energy_error_max


def to_px(th, v, vmax):
    """Pixel coordinates of (theta, theta') in a plot whose speed axis spans vmax."""
    x = PAD + (th + math.pi) / (2 * math.pi) * (W - 2 * PAD)
    y = H / 2 - v / vmax * (H / 2 - PAD)
    return x, y


def polyline(th, v, vmax, colour):
    """Pieces of the curve, broken where theta wraps from pi to -pi."""
    out, pts = [], []
    for a, b, jump in zip(th, v, np.r_[0, np.abs(np.diff(th))]):
        if jump > math.pi and pts:
            out.append(pts)
            pts = []
        pts.append("%.1f,%.1f" % to_px(a, b, vmax))
    out.append(pts)
    return "".join('<polyline fill="none" stroke="%s" stroke-width="1.6" points="%s"/>'
                   % (colour, " ".join(p)) for p in out if len(p) > 1)


def svg(model):
    """The whole picture as SVG text."""
    runs = list(trajectories(model))
    vmax = 1.1 * max(np.max(np.abs(v)) for _, v, _, _ in runs)
    parts = ['<svg xmlns="http://www.w3.org/2000/svg" width="%d" height="%d" '
             'font-family="sans-serif" font-size="13">' % (W, H),
             '<rect width="100%" height="100%" fill="white"/>']
    x0, yc = to_px(-math.pi, 0, vmax)
    x1, _ = to_px(math.pi, 0, vmax)
    parts.append('<line x1="%g" y1="%g" x2="%g" y2="%g" stroke="#888"/>' % (x0, yc, x1, yc))
    xm, _ = to_px(0, 0, vmax)
    parts.append('<line x1="%g" y1="%d" x2="%g" y2="%d" stroke="#888"/>' % (xm, PAD, xm,
                                                                              H - PAD))
    for th, label in ((-math.pi, "-pi"), (0, "0"), (math.pi, "pi")):
        x, _ = to_px(th, 0, vmax)
        parts.append('<text x="%g" y="%d" text-anchor="middle">%s</text>' % (x, H - PAD + 18,
                                                                              label))
    for v in range(-8, 9, 4):
        _, y = to_px(0, v, vmax)
        parts.append('<text x="%d" y="%g" text-anchor="end">%d</text>' % (PAD - 6, y + 4, v))
    parts.append('<text x="%d" y="%d" text-anchor="middle">theta (rad)</text>'
                 % (W / 2, H - 12))
    parts.append('<text x="14" y="%d" transform="rotate(-90 14 %d)" text-anchor="middle">'
                 "theta' (rad/s)</text>" % (H / 2, H / 2))
    worst = 0
    for th, v, frac, err in runs:
        colour = "#1f77b4" if frac < 1 else "#d62728"
        parts.append(polyline(th, v, vmax, colour))
        worst = max(worst, err)
    parts.append('<text x="%d" y="24" text-anchor="middle">simple pendulum, g/l = %g: '
                 'librations (blue) and rotations (red); energy error &lt;= %.0e</text>'
                 % (W / 2, model.params["g"] / model.params["l"], max(worst, 1e-16)))
    parts.append("</svg>\n")
    return "\n".join(parts)


def main():
    """Write the SVG to the file named on the command line."""
    out = sys.argv[1] if len(sys.argv) > 1 else "phase_portrait.svg"
    model = qdot.Model(PENDULUM, file="pendulum")
    with open(out, "w") as fh:
        fh.write(svg(model))
    print("wrote %s" % out)


if __name__ == "__main__":
    main()

# python/tests/test_example.py - python/examples/phase_portrait.py (the
# picture in docs/img/python_phase.png) still runs, and what it draws is the
# pendulum's phase portrait: at theta = 0 the librations (blue) cross below
# the separatrix's speed 2 sqrt(g/l), the rotations (red) above it.
import os
import runpy
import sys
import xml.etree.ElementTree as ET

import numpy as np

import qdot
from conftest import ROOT

SVG = "{http://www.w3.org/2000/svg}"


def test_phase_portrait_draws_librations_inside_separatrix(tmp_path, monkeypatch):
    out = tmp_path / "phase.svg"
    monkeypatch.setattr(sys, "argv", ["phase_portrait.py", str(out)])
    ns = runpy.run_path(os.path.join(ROOT, "python", "examples", "phase_portrait.py"),
                        run_name="__main__")
    lines = ET.parse(out).getroot().findall(SVG + "polyline")
    colour = {"#1f77b4": True, "#d62728": False}  # libration?
    assert sum(colour[p.get("stroke")] for p in lines) >= 8
    assert sum(not colour[p.get("stroke")] for p in lines) >= 4
    # the script's own scale, to read theta' back from the pixels
    model = qdot.Model(ns["PENDULUM"])
    vmax = 1.1 * max(np.max(np.abs(v)) for _, v, _, _ in ns["trajectories"](model))
    x0, y_sep = ns["to_px"](0, 2 * np.sqrt(model.params["g"] / model.params["l"]), vmax)
    _, y_mid = ns["to_px"](0, 0, vmax)
    seen = 0
    for p in lines:
        for xy in p.get("points").split():
            x, y = map(float, xy.split(","))
            if abs(x - x0) < 1.0:  # crossing theta = 0
                assert (abs(y - y_mid) < abs(y_sep - y_mid)) == colour[p.get("stroke")]
                seen += 1
    assert seen >= 12

# python/tests/test_sim_output.py - a run's CSV and summary from Python
# (Result.csv, Result.summary, Result.record: libqdot's qd_sim_csv_row,
# qd_sim_summary_print and qd_sim_summary_json), on the oscillator m x'' = -k x, w = sqrt(k/m) = 2,
# from x = 1 at rest: x = cos 2t, x' = -2 sin 2t, energy
# h = m x'^2/2 + k x^2/2 = 4 conserved (Goldstein sec. 1.6).  The CSV read
# back follows the motion, its event column marks the crossings x = 0 at
# t = pi/4 + k pi/2, and it is the bytes `qdot simulate` writes for the
# same run, as the summary is its lines and the record its JSON summary.
import json
import math
import os
import re
import subprocess

import numpy as np

import qdot

OSC = """coordinates x
parameters m = 2, k = 8
T = m/2*x'^2
V = k/2*x^2
initial x = 1
"""


def rows_of(text):
    lines = text.splitlines()
    return lines[0].split(","), np.array([[float(v) for v in ln.split(",")] for ln in lines[1:]])


def test_csv_follows_the_motion():
    r = qdot.Model(OSC).simulate(3, dt=0.1, rtol=1e-12, atol=1e-14, events=["x = 0"])
    header, rows = rows_of(r.csv())
    assert header == ["t", "x", "x'", "energy", "event"]
    t = rows[:, 0]
    assert np.max(np.abs(rows[:, 1] - np.cos(2 * t))) < 1e-9
    assert np.max(np.abs(rows[:, 2] + 2 * np.sin(2 * t))) < 1e-9
    assert np.max(np.abs(rows[:, 3] - 4)) < 1e-9  # the energy, conserved
    crossings = t[rows[:, 4] == 1]
    k = (crossings - math.pi / 4) / (math.pi / 2)
    assert len(crossings) == 2 and np.max(np.abs(k - np.round(k))) < 1e-9
    assert np.all(rows[rows[:, 4] != 1, 4] == 0)
    assert len(rows) == len(r) + len(r.events[0])  # the grid's rows and the event's


def test_the_bytes_and_lines_of_qdot_simulate(tmp_path):
    exe = os.path.join(os.environ.get("QDOT_BUILD", ""), "qdot")
    if not os.path.exists(exe):
        import pytest
        pytest.skip("no qdot program in QDOT_BUILD")
    model = tmp_path / "osc.qd"
    model.write_text(OSC)
    r = qdot.Model(OSC).simulate(3, dt=0.25, rtol=1e-10, events=["x = 0, x' < 0"])
    p = subprocess.run([exe, "simulate", str(model), "--t-end", "3", "--dt", "0.25",
                        "--rtol", "1e-10", "--event", "x = 0, x' < 0"],
                       capture_output=True, text=True, check=True)
    assert r.csv() == p.stdout

    def lines(text):  # the wall time is the run's own
        return [re.sub(r"[0-9.e+-]+ s;", "W s;", ln) for ln in text.splitlines()]
    prefix = "qdot: simulate: "
    assert lines(r.summary) == [ln[len(prefix):] for ln in lines(p.stderr)]
    assert "energy error" in r.summary and "1 event" in r.summary
    # the record: --format json's summary members, the final state x = cos 6
    p = subprocess.run([exe, "simulate", str(model), "--t-end", "3", "--dt", "0.25",
                        "--rtol", "1e-10", "--event", "x = 0, x' < 0", "--format", "json"],
                       capture_output=True, text=True, check=True)
    doc = json.loads(p.stdout)
    assert abs(r.record["final"]["x"] - math.cos(6)) < 1e-8
    assert r.record["events"] == 1 and r.record["method"] == "dop853"
    for key in set(r.record) - {"wall_s"}:
        assert r.record[key] == doc[key], key

# python/tests/test_interrupt.py - Ctrl-C from Python (issue 32) and the
# refusals of the library's set-ups as the CLI words them.  A run whose
# callback sees the stop flag ends after a whole row and raises
# KeyboardInterrupt carrying the rows kept; those rows are still the
# motion: the forced-free oscillator x = x0 cos(w t) + v0/w sin(w t)
# (Goldstein ch. 6 -- here F = 0) and the upward zeros of x = cos(w t),
# w t = 3 pi/2 + 2 pi j.  A SIGINT sent to a long Python run ends it with
# KeyboardInterrupt, never a crash nor "Exception ignored".
import math
import os
import re
import signal
import subprocess
import sys

import numpy as np
import pytest

import qdot
from qdot import _progress
from test_commands import BUILD, OSCILLATOR, model_file

OSC = """
coordinates x
parameters w = 3
inputs F
T = x'^2/2
V = w^2*x^2/2
Q[x] = F
initial x = 0.1, x' = 0.2
"""

OSCILLATOR_DRAWN = """
coordinates x
parameters w = 3, m = 1
particle m at (x, 0)
V = w^2*x^2/2
initial x = 0.1, x' = 0.2
"""


def test_simulate_stopped_by_sigint_keeps_whole_rows():
    def force(t, _y):  # the input callable presses Ctrl-C once, at t = 2
        if t >= 2 and not force.sent:
            force.sent = True
            signal.raise_signal(signal.SIGINT)
        return 0.0
    force.sent = False
    with pytest.raises(KeyboardInterrupt) as err:
        qdot.Model(OSC).simulate(100, inputs={"F": force}, rtol=1e-12, atol=1e-14, dt=0.25)
    r = err.value.result
    assert force.sent and 2 <= r.t[-1] < 3      # stopped early, after the flag
    assert r.data.shape[1] == len(r.columns) and np.isfinite(r.data).all()
    x = 0.1 * np.cos(3 * r.t) + 0.2 / 3 * np.sin(3 * r.t)
    assert np.max(np.abs(r["x"] - x)) < 1e-8    # every row kept is the motion
    # the handler is back: a later SIGINT is Python's own KeyboardInterrupt
    assert signal.getsignal(signal.SIGINT) is signal.default_int_handler


def test_poincare_stopped_by_its_progress_callback(monkeypatch):
    update = _progress.Run.update

    def stop_late(self, frac, t):  # the flag as the SIGINT handler sets it
        if t > 20:
            self.stop = True
        update(self, frac, t)
    monkeypatch.setattr(_progress.Run, "update", stop_late)
    with pytest.raises(KeyboardInterrupt) as err:
        qdot.Model(OSCILLATOR).poincare("x = 0, x' > 0", 1000, rtol=1e-12)
    p = err.value.result
    w = math.sqrt(3 / 2)
    assert 0 < len(p) < 1000
    assert p.t == pytest.approx([(1.5 * math.pi + 2 * math.pi * j) / w
                                 for j in range(len(p))], rel=1e-9)
    assert p["x'"] == pytest.approx([w] * len(p), rel=1e-9)


def test_lyapunov_and_sweep_stop_mid_run(monkeypatch):
    """The library's hooks (qd_lyap_opts.progress, qd_sweep_progress) end
    the run when Ctrl-C's flag is set, long before it would end."""
    update = _progress.Run.update
    seen = []

    def stop_early(self, frac, t):  # the flag as the SIGINT handler sets it
        seen.append(frac)
        if frac > 0.01:
            self.stop = True
        update(self, frac, t)
    monkeypatch.setattr(_progress.Run, "update", stop_early)
    with pytest.raises(KeyboardInterrupt, match="lyapunov"):
        qdot.Model(OSCILLATOR).lyapunov(1e6, renorm=1)
    assert 0.01 < seen[-1] < 0.5      # stopped after the renormalization that saw it
    seen.clear()
    with pytest.raises(KeyboardInterrupt, match="sweep"):
        qdot.Model(OSCILLATOR).sweep(2000, "final", grid="k=1:3:400", threads=1)
    assert 0.01 < seen[-1] < 0.5      # most of the 400 runs never started



def test_animate_stopped_keeps_the_page_so_far(monkeypatch):
    """qd_scene_setup_record's progress returning nonzero ends the run after
    a whole row; the KeyboardInterrupt's .result is the Animation of the
    motion up to then, and its frames are still x = 0.1 cos 3t + (0.2/3)
    sin 3t (the oscillator above with F = 0)."""
    update = _progress.Run.update

    def stop_late(self, frac, t):  # the flag as the SIGINT handler sets it
        if t > 2:
            self.stop = True
        update(self, frac, t)
    monkeypatch.setattr(_progress.Run, "update", stop_late)
    with pytest.raises(KeyboardInterrupt, match="animate") as err:
        qdot.Model(OSCILLATOR_DRAWN).animate(100, rtol=1e-12)
    a = err.value.result
    t = np.asarray(a.json["t"])
    assert 2 < t[-1] < 3 and t[0] == 0     # 100 s asked, stopped past t = 2
    x = np.asarray(a.json["pos"]).reshape(len(t), 3)[:, 0]   # the page's 7 digits
    assert np.max(np.abs(x - (0.1 * np.cos(3 * t) + 0.2 / 3 * np.sin(3 * t)))) < 1e-6
    assert "<html" in a.html.lower()


# a potential whose equilibria have no closed form: the library's
# multistart finds them (cos x + x^2/10: three in x, y = 0 the minimum)
MULTISTART = ("coordinates x, y\nT = (x'^2 + y'^2)/2\n"
              "V = cos(x) + x^2/10 + cos(y)*y^2/50 + y^2/7\n")


@pytest.fixture
def counted():
    """qdot.set_progress with a function that counts each call's reports
    (and checks each is a fraction 0..1)."""
    calls = {}

    def count(what, frac, value):
        seen = calls.setdefault(what, [])
        assert 0.0 <= frac <= 1.0, (what, frac)
        seen.append(frac)
    old = qdot.set_progress(count)
    yield calls
    qdot.set_progress(old)


def test_every_long_call_reports_its_progress(counted):
    osc = qdot.Model(OSCILLATOR)
    r = osc.simulate(10, rtol=1e-10, dt=0.5)
    osc.poincare("x = 0, x' > 0", 5, rtol=1e-10)
    osc.sweep(1, "final", grid="k=1:3:5", threads=1)
    osc.lyapunov(20, renorm=1)
    qdot.Model(OSCILLATOR_DRAWN).animate(2)
    ms = qdot.Model(MULTISTART)
    eqs = ms.equilibria()
    ms.modes()
    assert eqs.method == "multistart" and len(eqs) == 3
    for what in ("simulate", "poincare", "sweep", "lyapunov", "animate",
                 "equilibria: multistart"):
        assert counted.get(what), (what, sorted(counted))
    assert counted["sweep"][-1] == 1.0            # the fifth run of five
    assert len(counted["equilibria: multistart"]) >= 2 * 2   # one a start, modes' too
    # the rows are the motion whatever is drawn: x = cos(w t), w = sqrt(k/m)
    assert r["x"] == pytest.approx(np.cos(math.sqrt(1.5) * r.t), abs=1e-8)


def test_a_progress_function_stops_the_call():
    old = qdot.set_progress(lambda what, frac, value: frac > 0.3)
    try:
        with pytest.raises(KeyboardInterrupt, match="simulate") as err:
            qdot.Model(OSCILLATOR).simulate(100, rtol=1e-12, dt=0.5)
        r = err.value.result
        assert 30 <= r.t[-1] < 100                     # the rows up to the stop
        assert r["x"] == pytest.approx(np.cos(math.sqrt(1.5) * r.t), abs=1e-7)
        with pytest.raises(KeyboardInterrupt, match="equilibria: multistart"):
            qdot.Model(MULTISTART).equilibria()        # the library told to stop
        # the context works on: the same search, not stopped, is whole
        qdot.set_progress(None)
        assert len(qdot.Model(MULTISTART).equilibria()) == 3
    finally:
        qdot.set_progress(old)

    def broken(what, frac, value):
        raise RuntimeError("from the progress function")
    old = qdot.set_progress(broken)
    try:
        with pytest.raises(RuntimeError, match="from the progress function"):
            qdot.Model(OSCILLATOR).simulate(10, dt=0.5)
    finally:
        qdot.set_progress(old)
    with pytest.raises(TypeError):
        qdot.set_progress(3)


def test_sigint_stops_the_multistart_search():
    """Ctrl-C during the multistart (the handler's flag, seen by the
    context's progress function) stops the library at its next start:
    KeyboardInterrupt, the handler restored, the model usable after."""
    def press(what, frac, value):  # Ctrl-C once, a few starts in
        if frac > 0.05 and not press.sent:
            press.sent = True
            signal.raise_signal(signal.SIGINT)
        press.after += press.sent
    press.sent, press.after = False, 0
    old = qdot.set_progress(press)
    try:
        m = qdot.Model(MULTISTART)
        with pytest.raises(KeyboardInterrupt, match="equilibria: multistart"):
            m.equilibria()
        assert press.sent and press.after <= 2          # stopped at the next step
        assert signal.getsignal(signal.SIGINT) is signal.default_int_handler
    finally:
        qdot.set_progress(old)
    assert len(m.equilibria()) == 3


def test_notebook_shows_an_updating_line(monkeypatch):
    """In an IPython kernel (stderr no terminal) the bar is one display,
    updated in place and cleared at the end; IPython is only imported
    there, so a fake kernel stands for Jupyter here."""
    import types
    shown = []

    class Handle:
        def update(self, obj):
            shown.append(("update", obj.data))

    def display(obj, display_id=False):
        assert display_id is True
        shown.append(("display", obj.data))
        return Handle()

    class HTML:
        def __init__(self, data):
            self.data = data
    kernel = types.SimpleNamespace(kernel=object())
    ipy = types.ModuleType("IPython")
    ipy.get_ipython = lambda: kernel
    ipd = types.ModuleType("IPython.display")
    ipd.display, ipd.HTML = display, HTML
    ipy.display = ipd
    monkeypatch.setitem(sys.modules, "IPython", ipy)
    monkeypatch.setitem(sys.modules, "IPython.display", ipd)
    monkeypatch.setenv("QDOT_PROGRESS_DELAY", "0")
    qdot.Model(OSCILLATOR).poincare("x = 0, x' > 0", 50, rtol=1e-12)
    assert shown[0][0] == "display" and len(shown) >= 3
    assert all(kind == "update" for kind, _ in shown[1:])
    assert "<progress" in shown[1][1] and "qdot: poincare" in shown[1][1]
    assert shown[-1] == ("update", "")                  # cleared at the end
    values = [float(re.search(r'value="([0-9.]+)"', d).group(1)) for _, d in shown[:-1]]
    assert values == sorted(values) and values[-1] <= 1


CHILD = r"""
import sys, qdot
def force(t, y):
    if not force.told:
        force.told = True
        print("running", flush=True)
    return 0.0
force.told = False
qdot.Model(sys.argv[1]).simulate(1e7, inputs={"F": force}, dt=1.0, rtol=1e-13)
print("finished", flush=True)
"""


def test_sigint_to_a_long_run_raises_keyboard_interrupt():
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(p for p in sys.path if p),
               QDOT_PROGRESS_DELAY="0")
    child = subprocess.Popen([sys.executable, "-c", CHILD, OSC], stdout=subprocess.PIPE,
                             stderr=subprocess.PIPE, text=True, env=env)
    try:
        assert child.stdout.readline() == "running\n"  # inside the run
        child.send_signal(signal.SIGINT)
        out, errs = child.communicate(timeout=120)      # a guard against a hang, no timing
    finally:
        child.kill()
    assert "finished" not in out
    assert child.returncode in (-signal.SIGINT, 130, 1), errs
    assert "KeyboardInterrupt: qdot: simulate: interrupted" in errs
    assert "Exception ignored" not in errs and "Sanitizer" not in errs
    assert "qdot: simulate [" not in errs             # stderr not a terminal: no bar


def test_progress_bar_on_a_terminal():
    import pty
    master, slave = pty.openpty()
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(p for p in sys.path if p),
               QDOT_PROGRESS_DELAY="0")
    code = ("import qdot; qdot.Model(%r).poincare(\"x = 0, x' > 0\", 200, rtol=1e-12)"
            % OSCILLATOR)
    child = subprocess.Popen([sys.executable, "-c", code], stderr=slave, env=env)
    os.close(slave)
    seen = b""
    while True:
        try:
            chunk = os.read(master, 4096)
        except OSError:  # the child closed its end
            break
        if not chunk:
            break
        seen += chunk
    os.close(master)
    assert child.wait(timeout=120) == 0, seen
    assert b"qdot: poincare [" in seen and b"%" in seen
    assert seen.endswith(b"\r")  # the bar cleared at the end, as the CLI clears it


def cli_error(*args):
    exe = os.path.join(BUILD, "qdot")
    if not os.access(exe, os.X_OK):
        pytest.skip("no build/qdot to compare with")
    run = subprocess.run([exe, *args], capture_output=True, text=True)
    assert run.returncode == 2, run.stderr
    return run.stderr.strip()


@pytest.mark.parametrize("call, args, option", [
    (lambda m: m.sweep(5, "final, poincare-count", grid="x=0:1:3"),
     ["sweep", "--grid", "x=0:1:3", "--t-end", "5", "--measure", "final, poincare-count"],
     "section"),
    (lambda m: m.lyapunov(5, exponents=3), ["lyapunov", "--t-end", "5", "--exponents", "3"],
     "exponents"),
])
def test_refusals_are_the_clis(tmp_path, call, args, option):
    path = model_file(tmp_path, OSCILLATOR)
    with pytest.raises(ValueError) as err:   # a qdot.ArgumentError
        call(qdot.Model.load(path))
    assert isinstance(err.value, qdot.Error)
    said = cli_error(args[0], path, *args[1:])
    assert said.startswith("qdot: error: ") and said.endswith(" (--%s)" % option)
    assert str(err.value) == "%s (the argument %s)" % (said[13:-len(" (--%s)" % option)], option)

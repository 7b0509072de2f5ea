# python/qdot/_progress.py - what a long run from Python shows and how it is
# stopped (issue 32), as cli/progress.c and cli/out.c do for the CLI: a bar
# on stderr only when it is a terminal and only past a second (so tests,
# logs and notebooks get nothing; QDOT_PROGRESS_DELAY replaces the second),
# and Ctrl-C turned into a flag the library's callbacks read.  A cffi
# callback must not raise through C, so the first SIGINT only sets the flag
# (the callback then asks the library to stop after a whole row) and the
# KeyboardInterrupt is raised once the library has returned; a second one
# gets the previous handler, as the CLI's SA_RESETHAND does.
#
# In a notebook (an IPython kernel: stderr is no terminal there) the bar is
# an updating display of its own (IPython.display's display_id, only
# imported when IPython is running: no new dependency), cleared at the end.
# qdot.set_progress(fn) replaces both with fn(what, fraction, value), which
# stops the call as Ctrl-C does when it returns true.  The library's long
# searches without a callback parameter of their own (the multistart of
# equilibria, modes and stability) report through qd_ctx_set_progress:
# watch(core, what) hands those steps to the same Run.
"""Progress bars and Ctrl-C for long runs (internal module)."""

import os
import signal
import sys
import threading
import time

_WIDTH = 30
_REDRAW = 0.1
_hook = None  # qdot.set_progress's function, or None: the bar


def set_progress(fn):
    """Show the progress of long calls (simulate, poincare, lyapunov, sweep,
    animate, the multistart searches of equilibria, modes and stability)
    through fn(what, fraction, value) instead of the bar (on a terminal) or
    the updating line (in a notebook): what names the call ("simulate",
    "equilibria: multistart"), fraction is 0..1 of the work, value the
    quantity the bar shows (t, the runs done, the steps done).  fn returning
    true stops the call as Ctrl-C does (KeyboardInterrupt, with .result the
    part done where the call keeps one); an exception fn raises ends the
    call and is raised from it.  fn None restores the bar.  Returns the
    previous fn."""
    global _hook
    if fn is not None and not callable(fn):
        raise TypeError("set_progress: a callable fn(what, fraction, value) or None, not %s"
                        % type(fn).__name__)
    old, _hook = _hook, fn
    return old


def _notebook():
    """True in an IPython kernel (Jupyter), where stderr is no terminal."""
    ip = sys.modules.get("IPython")
    try:
        shell = ip.get_ipython() if ip is not None else None
    except Exception:  # noqa: BLE001 (an IPython that cannot say: no notebook)
        return False
    return shell is not None and getattr(shell, "kernel", None) is not None


def _delay():
    v = os.environ.get("QDOT_PROGRESS_DELAY")
    try:
        d = float(v) if v else 1.0
    except ValueError:
        d = -1.0
    return d if d >= 0 else 1.0


class Run:
    """One long call: `with Run("poincare") as r:` around the library call;
    r.update(frac, t) from its progress callback draws the bar, r.stop
    (bool) says Ctrl-C was pressed.  On leaving, the bar is cleared, the
    handler restored, and a KeyboardInterrupt raised when r.stop is set
    (r.partial, when the caller set it, is the exception's .result)."""

    def __init__(self, what, label="t"):
        self.what, self.label = what, label
        self.stop = False
        self.partial = None
        self.error = None  # what the hook raised
        self._old = None
        self._hook = _hook
        tty = sys.stderr is not None and hasattr(sys.stderr, "isatty") and sys.stderr.isatty()
        self._on = self._hook is None and tty
        self._nb = self._hook is None and not tty and _notebook()
        self._handle = None
        self._delay = _delay()
        self._shown = self._estimated = False

    def _sigint(self, _sig, _frame):
        self.stop = True
        signal.signal(signal.SIGINT, self._old)  # a second ^C: the previous handler

    def __enter__(self):
        self._start = self._last = time.monotonic()
        if threading.current_thread() is threading.main_thread():
            self._old = signal.signal(signal.SIGINT, self._sigint)
        return self

    def __exit__(self, etype, _value, _tb):
        if self._old is not None and signal.getsignal(signal.SIGINT) == self._sigint:
            signal.signal(signal.SIGINT, self._old)
        if self._shown and self._handle is not None:
            self._handle.update(_html(""))
        elif self._shown:
            sys.stderr.write("\r%90s\r" % "")
            sys.stderr.flush()
        if self.error is not None:
            raise self.error
        # stopped: the library returns whole (or fails with "stopped", the
        # multistart searches): the interrupt is what the caller sees
        if self.stop and (etype is None or issubclass(etype, Exception)):
            err = KeyboardInterrupt("qdot: %s: interrupted%s" % (
                self.what, "; the rows kept are whole" if self.partial is not None else ""))
            err.result = self.partial
            err.__suppress_context__ = True  # the library's "stopped" is this interrupt
            raise err
        return False

    def update(self, frac, t):
        """The bar at frac (0..1) of the work, t the quantity shown."""
        if self._hook is not None:
            try:
                if self._hook(self.what, min(max(frac, 0.0), 1.0), t):
                    self.stop = True
            except BaseException as err:  # noqa: B036 (a C callback: raised on leaving)
                self.error, self.stop = err, True
            return
        if not (self._on or self._nb):
            return
        now = time.monotonic()
        wall = now - self._start
        frac = min(max(frac, 0.0), 1.0)
        first_estimate = frac > 0 and not self._estimated
        if wall < self._delay or (self._shown and not first_estimate and
                                  now - self._last < _REDRAW):
            return
        self._last, self._estimated = now, self._estimated or frac > 0
        left = "?"
        if frac > 0:
            n = int(wall * (1 - frac) / frac + 0.5)
            left = "%dm%02ds" % (n // 60, n % 60) if n >= 60 else "%ds" % n
        line = "qdot: %s %3.0f%%  %s = %.4g  %s left" % (self.what, 100 * frac, self.label, t,
                                                         left)
        if self._nb:
            self._notebook_line(frac, line)
        else:
            sys.stderr.write("\rqdot: %s [%-*s] %3.0f%%  %s = %-10.4g  %s left   " % (
                self.what, _WIDTH, "#" * int(frac * _WIDTH), 100 * frac, self.label, t, left))
            sys.stderr.flush()
        self._shown = True

    def _notebook_line(self, frac, line):
        """The notebook's bar: an HTML progress element and the line, one
        display updated in place."""
        import html
        body = _html('<progress value="%.4f" max="1" style="width:20em"></progress> '
                     '<code>%s</code>' % (frac, html.escape(line)))
        if self._handle is None:
            from IPython.display import display
            self._handle = display(body, display_id=True)
        else:
            self._handle.update(body)


def _html(text):
    from IPython.display import HTML
    return HTML(text)


class watch:
    """`with watch(core, "equilibria"):` around a library call that reports
    its multistart steps through the context (qd_ctx_set_progress): the
    steps drawn by a Run, a stop (Ctrl-C, the hook) returned to the library
    as nonzero, the callback removed on leaving."""

    def __init__(self, core, what):
        from ._lib import ffi, lib
        self._core, self._lib, self._ffi = core, lib, ffi
        self.run = Run(what, "step")

        def progress(_data, name, done, total):
            self.run.what = ffi.string(name).decode() if name else what
            self.run.update(done / total if total else 0.0, done)
            return 1 if self.run.stop else 0
        self._cb = ffi.callback("qd_progress_fn", progress, error=1)

    def __enter__(self):
        self.run.__enter__()
        self._lib.qd_ctx_set_progress(self._core.ctx, self._cb, self._ffi.NULL)
        return self.run

    def __exit__(self, etype, value, tb):
        self._lib.qd_ctx_set_progress(self._core.ctx, self._ffi.NULL, self._ffi.NULL)
        return self.run.__exit__(etype, value, tb)

# python/qdot/_progress.py - what a long run from Python shows and how it is
# stopped (issue 32), as cli/progress.c and cli/out.c do for the CLI: a bar
# on stderr only when it is a terminal and only past a second (so tests,
# logs and notebooks get nothing; QDOT_PROGRESS_DELAY replaces the second),
# and Ctrl-C turned into a flag the library's callbacks read.  A cffi
# callback must not raise through C, so the first SIGINT only sets the flag
# (the callback then asks the library to stop after a whole row) and the
# KeyboardInterrupt is raised once the library has returned; a second one
# gets the previous handler, as the CLI's SA_RESETHAND does.
"""Progress bars and Ctrl-C for long runs (internal module)."""

import os
import signal
import sys
import threading
import time

_WIDTH = 30
_REDRAW = 0.1


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
        self._old = None
        self._on = sys.stderr is not None and hasattr(sys.stderr, "isatty") and \
            sys.stderr.isatty()
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
        if self._shown:
            sys.stderr.write("\r%90s\r" % "")
            sys.stderr.flush()
        if self.stop and etype is None:
            err = KeyboardInterrupt("qdot: %s: interrupted; the rows kept are whole" % self.what)
            err.result = self.partial
            raise err
        return False

    def update(self, frac, t):
        """The bar at frac (0..1) of the work, t the quantity shown."""
        if not self._on:
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
        sys.stderr.write("\rqdot: %s [%-*s] %3.0f%%  %s = %-10.4g  %s left   " % (
            self.what, _WIDTH, "#" * int(frac * _WIDTH), 100 * frac, self.label, t, left))
        sys.stderr.flush()
        self._shown = True

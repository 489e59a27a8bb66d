"""One progress bar for long runs: a line on stderr redrawn in place, quiet-able.

Every long call of the library takes a ``progress`` callable; :class:`ProgressBar` is the
one the command line passes to all of them.  It accepts the three shapes those callables
are called with: a fraction in [0, 1] (``simulate``, ``simulate_coulomb``,
``run_euler_disk``), ``(done, total)`` (``basin_sweep``) and ``(done, total, rate, eta)``
(``run_sweep``); :meth:`ProgressBar.note` prints a line of its own (``paper_figures``).
"""

from __future__ import annotations

import math
import sys
import time

__all__ = ["ProgressBar"]


class ProgressBar:
    """A plain text bar ``label [####....]  45.0%`` redrawn in place on ``stream``.

    Parameters
    ----------
    stream : file-like, optional
        Where to draw (default ``sys.stderr``, looked up at each call).
    label : str
        The word before the bar.
    delay : float
        Seconds before the bar first appears (a short run shows nothing).
    width : int
        Characters of the bar.
    quiet : bool
        Draw nothing at all (notes included).
    interval : float
        Least seconds between two redraws (the last one, at 100 %, is always drawn).

    Examples
    --------
    >>> import io
    >>> buf = io.StringIO()
    >>> bar = ProgressBar(buf, label="run", delay=0.0, width=4)
    >>> bar(3, 4); bar.close()
    >>> buf.getvalue()
    '\\rrun [###.]  75.0% 3/4\\n'
    """

    def __init__(self, stream=None, *, label: str = "simulating", delay: float = 1.0,
                 width: int = 40, quiet: bool = False, interval: float = 0.0):
        self._stream = stream
        self.label, self.delay, self.width = label, float(delay), int(width)
        self.quiet, self.interval = bool(quiet), float(interval)
        self.start = time.monotonic()
        self.shown = False
        self._last = -math.inf

    @property
    def stream(self):
        return sys.stderr if self._stream is None else self._stream

    def __call__(self, done: float, total: float | None = None, rate: float | None = None,
                 eta: float | None = None) -> None:
        """Redraw: ``done`` a fraction, or ``done`` of ``total`` at ``rate`` per second."""
        if self.quiet:
            return
        now = time.monotonic()
        if not self.shown and now - self.start < self.delay:
            return
        fraction = done / total if total else done
        fraction = min(max(float(fraction), 0.0), 1.0) if math.isfinite(fraction) else 0.0
        if fraction < 1.0 and now - self._last < self.interval:
            return
        self._last = now
        self.shown = True
        n = int(round(self.width * fraction))
        text = f"\r{self.label} [{'#' * n}{'.' * (self.width - n)}] {100 * fraction:5.1f}%"
        if total:
            text += f" {done}/{total}"
        if rate is not None and math.isfinite(rate):
            text += f" ({rate:.0f}/s"
            text += f", ETA {eta:.0f} s)" if eta is not None and math.isfinite(eta) else ")"
        self.stream.write(text)
        self.stream.flush()

    def note(self, line: str) -> None:
        """A line of its own (the bar, if drawn, is ended first)."""
        if self.quiet:
            return
        self.close()
        self.stream.write(f"{line}\n")
        self.stream.flush()

    def close(self) -> None:
        """End the bar's line (nothing if it was never drawn)."""
        if self.shown:
            self.stream.write("\n")
            self.stream.flush()
            self.shown = False

"""The console script's entry (the command line itself is :mod:`rollingdisk.cli.app`).

:func:`main` is the console script's entry: it installs the signal handlers, then imports the
command line.  ``import rollingdisk`` imports no numeric module (its names load on first
use), so a Ctrl-C or SIGTERM from the first instant is reported as every other one: one
line, exit status 130 (Ctrl-C) or 143 (SIGTERM), never a traceback.
"""

import signal
import sys

__all__ = ["main"]


class _Stop(BaseException):  # noqa: N818 - a signal, like KeyboardInterrupt
    def __init__(self, signum: int):
        super().__init__(signum)
        self.signum = signum


def _early(signum, frame):
    raise _Stop(signum)


def main(argv=None) -> int:
    """Install the signal handlers, import the command line and run it; the exit status."""
    try:
        signal.signal(signal.SIGINT, _early)
        signal.signal(signal.SIGTERM, _early)
    except ValueError:  # not the main thread: leave the signals alone
        pass
    try:
        from rollingdisk.cli.app import main as run

        return run(argv)
    except (_Stop, KeyboardInterrupt) as stop:
        interrupted = getattr(stop, "signum", signal.SIGINT) == signal.SIGINT
        sys.stderr.write("rollingdisk: interrupted\n" if interrupted
                         else "rollingdisk: terminated\n")
        sys.stderr.flush()
        return 130 if interrupted else 143



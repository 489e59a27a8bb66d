"""The ``rollingdisk`` console script: signal handlers first, then the package.

``import rollingdisk`` takes about 0.4 s (numpy, scipy); a Ctrl-C or SIGTERM in that time
would otherwise end in a ``KeyboardInterrupt`` traceback or a silent death.  This module,
outside the package so that importing it imports nothing else, installs the handlers
before the import and reports such an early signal as every other one: one line, exit
status 130 (Ctrl-C) or 143 (SIGTERM).  ``python -m rollingdisk`` does the same once the
package is imported (:mod:`rollingdisk.__main__`).
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
        from rollingdisk.cli.main import main as run

        return run(argv)
    except (_Stop, KeyboardInterrupt) as stop:
        interrupted = getattr(stop, "signum", signal.SIGINT) == signal.SIGINT
        sys.stderr.write("rollingdisk: interrupted\n" if interrupted
                         else "rollingdisk: terminated\n")
        sys.stderr.flush()
        return 130 if interrupted else 143


if __name__ == "__main__":
    sys.exit(main())

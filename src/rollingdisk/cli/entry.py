"""The console script's entry (the command line itself is :mod:`rollingdisk.cli.app`).

:func:`main` is the console script's entry: it installs the signal handlers, then imports the
command line.  ``import rollingdisk`` imports no numeric module (its names load on first
use), so a Ctrl-C or SIGTERM from the first instant is reported as every other one: one
line, exit status 130 (Ctrl-C) or 143 (SIGTERM), never a traceback.
"""

import contextlib
import os
import signal
import sys

__all__ = ["main"]


class _Stop(BaseException):  # noqa: N818 - a signal, like KeyboardInterrupt
    def __init__(self, signum: int):
        super().__init__(signum)
        self.signum = signum


#: Set once an interruption was reported (one line per process).
_REPORTED: list = []
#: Signals received after the command was done (see _last_word).
_LATE: list = []


def _early(signum, frame):
    raise _Stop(signum)


def main(argv=None) -> int:
    """Install the signal handlers, import the command line and run it; the exit status.

    With ``argv`` None (the console script, ``python -m rollingdisk``: this process is the
    command) the signals stay covered to the last instant: once the command is done a
    Ctrl-C or SIGTERM is only recorded (the interpreter's shutdown takes a moment), and
    :func:`_last_word`, after every other exit handler, ignores both from then on and
    reports a recorded one as one line with exit status 130 / 143, instead of the
    process dying silently (at shutdown Python gives its signals back their default
    action).
    """
    try:
        signal.signal(signal.SIGINT, _early)
        signal.signal(signal.SIGTERM, _early)
        if argv is None:
            import atexit

            atexit.register(_last_word)  # the first registered, so the last to run
    except ValueError:  # not the main thread: leave the signals alone
        pass
    status = None
    try:
        from rollingdisk.cli.app import main as run

        status = run(argv)
        if argv is None:  # done: a signal from now on is reported by _last_word
            with contextlib.suppress(ValueError):
                signal.signal(signal.SIGINT, _late)
                signal.signal(signal.SIGTERM, _late)
    except (_Stop, KeyboardInterrupt) as stop:
        interrupted = getattr(stop, "signum", signal.SIGINT) == signal.SIGINT
        if status is not None:  # after the command: its outputs are named
            return _say_stopped(interrupted)
        sys.stderr.write("rollingdisk: interrupted\n" if interrupted
                         else "rollingdisk: terminated\n")
        sys.stderr.flush()
        _REPORTED.append(True)
        code = 130 if interrupted else 143
        if argv is None:
            _exit_now(code)
        return code
    if status in (130, 143):  # the command reported its interruption
        _REPORTED.append(True)
    return status


def _say_stopped(interrupted: bool) -> int:
    """The one line of a signal that came after the command was done (naming the outputs
    it completed); 130 or 143."""
    try:
        from rollingdisk.cli.app import stop_line
        from rollingdisk.util.files import committed

        line = stop_line(interrupted, committed())
    except Exception:  # noqa: BLE001 - the line must come out whatever happened
        line = "rollingdisk: interrupted" if interrupted else "rollingdisk: terminated"
    with contextlib.suppress(Exception):
        sys.stdout.flush()
    sys.stderr.write(line + "\n")
    sys.stderr.flush()
    _REPORTED.append(True)
    return 130 if interrupted else 143


def _exit_now(code: int) -> None:
    """End this process with ``code`` after an interrupted command: the exit handlers run
    (helper processes are joined, journals closed; outputs were already completed or
    removed as the interruption unwound), then the process ends without the interpreter's
    teardown.  The teardown finalises whatever the interruption left half built (a
    compilation stopped midway), and under load that has ended the process with SIGSEGV
    after its one line."""
    import atexit

    with contextlib.suppress(Exception):
        sys.stdout.flush()
    with contextlib.suppress(Exception):
        atexit._run_exitfuncs()
    os._exit(code)


def _late(signum, frame):
    _LATE.append(signum)


def _last_word() -> None:
    """At exit, after every other exit handler: SIGINT and SIGTERM are ignored from now on
    (Python would give them back their default action, a silent death, during its
    shutdown), and one received since the command was done is reported in one line, the
    process ending with status 130 / 143 now."""
    with contextlib.suppress(Exception):
        signal.signal(signal.SIGINT, signal.SIG_IGN)
        signal.signal(signal.SIGTERM, signal.SIG_IGN)
    if _LATE and not _REPORTED:
        with contextlib.suppress(Exception):
            os._exit(_say_stopped(_LATE[0] == signal.SIGINT))

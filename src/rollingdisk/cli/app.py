"""The ``rollingdisk`` command line: the parser, built from :data:`COMMANDS`, and the one
place that turns what happened into an exit status.

Exit status and messages (every command, the same way):

* 0: done;
* 2: bad input or an impossible request, exactly one line on stderr and no traceback: a
  usage error of the command line (:class:`~rollingdisk.cli._args.CLIError`), an input
  error of the library (:data:`rollingdisk.util.errors.INPUT_ERRORS`: a value out of its
  range, a wrong type, an impossible request), or an output path that cannot be written;
  every number is checked when the command line is read, before any work;
* 1: anything else is a bug in rollingdisk: the traceback, then one line saying so;
* 130 (Ctrl-C) and 143 (SIGTERM): one line, "rollingdisk: interrupted" / "terminated"
  (naming the outputs that were already complete, if any), and no partial file: every
  output is written under a temporary name and renamed when complete
  (:mod:`rollingdisk.util.files`); the handlers are in before any numeric module is
  imported (:func:`rollingdisk.cli.entry.main`).

JSON output is strict (``allow_nan=False``).  Each command is a module with
``configure(subparsers)`` and ``run(args)``, which calls the library and only formats.
"""

from __future__ import annotations

import argparse
import contextlib
import importlib
import os
import re
import signal
import sys
from collections.abc import Sequence

from rollingdisk.cli._args import CLIError
from rollingdisk.util.errors import INPUT_ERRORS
from rollingdisk.util.files import (
    Terminated,
    check_signals,
    committed,
    pending_signal,
    quiet_forked_children,
    terminate_as_exception,
)

__all__ = ["main", "build_parser", "COMMANDS"]

#: The commands: (name, module, one-line help), in the order ``--help`` lists them.  A
#: module that cannot be imported is left out only if it is marked optional (the explorer
#: lives outside this package).
COMMANDS = (
    ("atlas", "rollingdisk.cli.atlas", "the atlas of one disk: thresholds, maps, two "
     "simulated steady motions with animations, index.html"),
    ("steady", "rollingdisk.cli.steady",
     "a steady motion (straight line, circle, spin) and its stability"),
    ("thresholds", "rollingdisk.cli.thresholds",
     "critical squared speeds for a disk (eqs. 42, 43, 53, 57)"),
    ("simulate", "rollingdisk.cli.simulate",
     "simulate the disk from a perturbed steady motion or any state"),
    ("euler-disk", "rollingdisk.cli.euler_disk",
     "Euler's disk: the toy spun up and run to its end"),
    ("exact", "rollingdisk.cli.exact",
     "the exact motion by quadrature: turning points, period, delta psi"),
    ("sweep", "rollingdisk.cli.sweep", "integrate perturbed steady motions over a parameter "
     "grid"),
    ("figures", "rollingdisk.cli.figures", "recompute the paper's Figures 4-8 as PNG files"),
    ("map", "rollingdisk.cli.map", "existence / stability map or varpi^2 = 0 surface"),
    ("animate", "rollingdisk.cli.animate", "simulate a steady motion from a small tilt "
     "perturbation and write a 3D animation (.gif, or .mp4 with ffmpeg)"),
    ("derive", "rollingdisk.cli.derive", "derive the equations of motion with sympy and "
     "check every printed equation of the paper against the derivation"),
    ("toss", "rollingdisk.cli.toss", "toss a disk many times: heads, tails or edge, with "
     "flight, impacts, rolling and sliding to the end"),
    ("edge-odds", "rollingdisk.cli.edge_odds", "heads, tails and edge of hand tosses on a "
     "table against the coin's thickness t/d"),
    ("explore", "rollingdisk.explore.command",
     "interactive explorer in the web browser: maps, steady motions, 3D"),
)
#: Commands whose module may be absent (an optional part of the package).
OPTIONAL = frozenset({"explore"})


class _Exit(Exception):  # noqa: N818 - argparse's exit (--help), as a return value
    def __init__(self, status: int):
        super().__init__(status)
        self.status = status


class _Parser(argparse.ArgumentParser):
    """argparse that reports usage errors as one line (exit status 2), returns from
    ``--help`` instead of exiting the interpreter and takes no abbreviation.  A value that
    starts with a minus and a digit (``--mass -1g``, ``--theta0 -30deg``) is a value, not
    an option: the option's own check then refuses or takes it."""

    def __init__(self, *args, **kw):
        super().__init__(*args, **(kw | {"allow_abbrev": False}))  # --h is not --help
        self._negative_number_matcher = re.compile(r"^-\.?\d")

    def error(self, message: str):  # noqa: D401 - argparse API
        raise CLIError(f"{self.prog}: error: {message}")

    def exit(self, status=0, message=None):  # noqa: D401 - argparse API
        if message:
            sys.stderr.write(message)
        raise _Exit(status)


class _Subparsers:
    """What a command's ``configure`` is given: ``add_parser`` with the table's help."""

    def __init__(self, sub, help: str):
        self._sub, self._help = sub, help
        self.parsers: list = []

    def add_parser(self, name, **kw):
        kw["help"] = self._help
        p = self._sub.add_parser(name, **kw)
        self.parsers.append(p)
        return p


def _version() -> str:
    from importlib.metadata import PackageNotFoundError, version

    try:
        return f"rollingdisk {version('rollingdisk')}"
    except PackageNotFoundError:
        return "rollingdisk (version unknown: not installed)"


def _command_module(name: str, module: str):
    try:
        return importlib.import_module(module)
    except ImportError as exc:
        if name in OPTIONAL and (exc.name or "").startswith(module.rpartition(".")[0]):
            return None
        raise


def build_parser(only: str | None = None) -> argparse.ArgumentParser:
    """The parser of the ``rollingdisk`` command line (one subparser per command of
    :data:`COMMANDS`; ``args.handler`` is the command's ``run``); with ``only`` (a command's
    name) that command's alone, so that no other command's module is imported (``main``
    does so when the first argument names a command)."""
    parser = _Parser(prog="rollingdisk", description="Dynamics of a rigid disk of finite "
                     "thickness on a horizontal plane (after M. Batista): steady motions, "
                     "stability, simulations, maps.")
    parser.add_argument("--version", action="version", version=_version(),
                        help="print the version of rollingdisk and exit")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", parser_class=_Parser)
    for name, module, text in COMMANDS:
        mod = _command_module(name, module) if only in (None, name) else None
        if mod is None:
            continue
        adder = _Subparsers(sub, text)
        mod.configure(adder)
        for p in adder.parsers:
            p.set_defaults(handler=mod.run)
    return parser


def main(argv: Sequence[str] | None = None) -> int:
    """Run the command line ``argv`` and return the exit status.

    Parameters
    ----------
    argv : sequence of str, optional
        The arguments (``sys.argv[1:]`` by default).

    Returns
    -------
    int
        0 done; 2 bad input (one line on stderr); 1 a bug (traceback and one line);
        130 interrupted (Ctrl-C); 143 terminated (SIGTERM).
    """
    args = None
    n_done = len(committed())
    try:
        with terminate_as_exception():  # first: a signal while the parser is built counts
            quiet_forked_children()  # helpers start with no handler of ours (atlas)
            first = next(iter(sys.argv[1:] if argv is None else argv), None)
            parser = build_parser(first if first in {c[0] for c in COMMANDS} else None)
            try:
                args = parser.parse_args(argv)
            except _Exit as done:  # --help, --version
                return done.status
            if not getattr(args, "handler", None):
                parser.print_help(sys.stderr)
                return 2
            status = int(args.handler(args) or 0)
            sys.stdout.flush()  # a reader that left (| head) is reported here, not at exit
            check_signals()  # a Ctrl-C whose exception Python swallowed still counts
            return status
    except KeyboardInterrupt:
        return _stopped(True, n_done)
    except Terminated:
        return _stopped(False, n_done)
    except Exception as exc:
        if pending_signal() is not None:  # the error came after Ctrl-C / SIGTERM: report that
            return _stopped(pending_signal() == signal.SIGINT, n_done)
        return _error_status(exc, args, n_done)


def _say(line: str) -> None:
    """One line on stderr (a message with line breaks is joined)."""
    print(" ".join(str(line).split("\n")), file=sys.stderr, flush=True)


def _prog(args) -> str:
    command = getattr(args, "command", None)
    return f"rollingdisk {command}" if command else "rollingdisk"


def stop_line(interrupted: bool, complete: Sequence = ()) -> str:
    """The one line of an interruption, naming the outputs that were already complete."""
    line = "rollingdisk: interrupted" if interrupted else "rollingdisk: terminated"
    if complete:
        line += (f" (already complete and kept: {', '.join(str(p) for p in complete)}; "
                 "nothing else was written)")
    return line


def _stopped(interrupted: bool, n_done: int = 0) -> int:
    """One line and exit status 130 (Ctrl-C) or 143 (SIGTERM)."""
    _say(stop_line(interrupted, committed()[n_done:]))
    if interrupted:
        # A KeyboardInterrupt that passed through an exec() of a string on its way here
        # (libraries build code that way) leaves CPython's _Py_UnhandledKeyboardInterrupt
        # set, and the interpreter would then exit by SIGINT (status -2) instead of 130.
        # Each exec() of a string clears that flag first (pythonrun.c, run_eval_code_obj).
        exec("pass")  # a constant string
    return 130 if interrupted else 143


#: errno values that mean the user's destination is full or read-only, whatever the file.
_DESTINATION_ERRNOS = {"ENOSPC", "EDQUOT", "EFBIG", "EROFS"}
#: The options that name an output of a command (their ``dest``).
_OUTPUT_OPTIONS = ("out", "sound", "animate", "results")


def _on_user_path(exc: OSError, args) -> bool:
    """Whether ``exc`` concerns an output the user named (``--out``, ``--sound``,
    ``--animate``, ``--results``): a full or read-only destination, whatever the file; its
    folder (or the folder a symbolic link leads to), the file or folder itself, or the
    temporary files written beside it."""
    import errno

    if errno.errorcode.get(exc.errno) in _DESTINATION_ERRNOS:
        return True
    folders = set()
    for key in _OUTPUT_OPTIONS:
        out = getattr(args, key, None)
        if isinstance(out, (str, os.PathLike)):
            folders |= {os.path.dirname(os.path.abspath(out)),
                        os.path.dirname(os.path.realpath(out))}
    for name in (exc.filename, exc.filename2):
        if name is None:
            continue
        try:
            path = os.path.abspath(os.fspath(name))
            if any(os.path.commonpath([path, f]) == f for f in folders):
                return True
        except (TypeError, ValueError):
            continue
    return False


def _error_status(exc: Exception, args, n_done: int) -> int:
    """The one line and exit status of an exception that ended a command (called in its
    ``except`` clause, so that a bug's traceback is the exception's own)."""
    if isinstance(exc, CLIError):
        _say(str(exc))
        return 2
    if isinstance(exc, INPUT_ERRORS):
        _say(f"{_prog(args)}: error: {exc}")
        return 2
    if isinstance(exc, BrokenPipeError):  # the reader of the output left (| head)
        with contextlib.suppress(OSError, ValueError):  # nothing more goes to it
            os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        _say(f"{_prog(args)}: error: the output was closed by its reader (a broken pipe)")
        return 2
    if isinstance(exc, OSError) and _on_user_path(exc, args):
        where = f"{exc.filename}: " if exc.filename else ""
        _say(f"{_prog(args)}: error: {where}{exc.strerror or exc}")
        return 2
    # an exception raised while cleaning up after Ctrl-C / SIGTERM: still an interruption
    context = exc.__context__
    while context is not None:
        if isinstance(context, (KeyboardInterrupt, Terminated)):
            return _stopped(isinstance(context, KeyboardInterrupt), n_done)
        context = context.__context__
    return _bug(args)


def _bug(args) -> int:
    import traceback

    traceback.print_exc()
    _say(f"{_prog(args)}: internal error: this is a bug in rollingdisk, not a problem with "
         "your input; please report it with the traceback above")
    return 1

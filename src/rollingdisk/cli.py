"""Command-line interface: a thin layer over the library, one subcommand per entry point.

Errors in the input (and physically impossible requests) end with exit status 2 and one
line on stderr, never a traceback.
"""

from __future__ import annotations

import argparse
import math
import sys
from collections.abc import Sequence

__all__ = ["main", "parse_angle"]


class CLIError(Exception):
    """A user error: printed as one line on stderr, exit status 2."""


def parse_angle(text: str) -> float:
    """An angle in radians, or in degrees with a ``deg`` suffix (``30deg``)."""
    s = str(text).strip().lower()
    try:
        if s.endswith("deg"):
            return math.radians(float(s[:-3]))
        if s.endswith("°"):
            return math.radians(float(s[:-1]))
        return float(s)
    except ValueError:
        raise argparse.ArgumentTypeError(
            f"invalid angle {text!r}: give radians (0.5) or degrees with a suffix (30deg)"
        ) from None


class _Parser(argparse.ArgumentParser):
    """argparse that reports usage errors as one line and exit status 2."""

    def error(self, message: str):  # noqa: D401 - argparse API
        raise CLIError(f"{self.prog}: {message}")


# ---------------------------------------------------------------------------- derive
def _add_derive(sub) -> None:
    p = sub.add_parser("derive", help="derive the equations of motion with sympy and check "
                       "the paper's equations (1)-(13), (37), (38), (49)")
    p.add_argument("--json", action="store_true", help="print the table as JSON")
    p.set_defaults(handler=_run_derive)


def _run_derive(args) -> int:
    from .symbolic import check_equations, format_table

    rows = check_equations(progress=not args.json)
    if args.json:
        import json

        print(json.dumps([row.as_dict() for row in rows], indent=2))
    else:
        print(format_table(rows))
    return 0


# ---------------------------------------------------------------------------- steady
def _add_steady(sub) -> None:
    """Registered by the steady-motion issue."""


# ---------------------------------------------------------------------------- thresholds
def _add_thresholds(sub) -> None:
    """Registered by the steady-motion issue."""


# ---------------------------------------------------------------------------- simulate
def _add_simulate(sub) -> None:
    """Registered by the simulation issue."""


# ---------------------------------------------------------------------------- figures, maps
def _add_figures(sub) -> None:
    """Registered by the figures issue (figures, map, animate, atlas)."""


# ---------------------------------------------------------------------------- main
def build_parser() -> argparse.ArgumentParser:
    parser = _Parser(prog="rollingdisk", description=__doc__.splitlines()[0])
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", parser_class=_Parser)
    for add in (_add_derive, _add_steady, _add_thresholds, _add_simulate, _add_figures):
        add(sub)
    return parser


def main(argv: Sequence[str] | None = None) -> int:
    """Run the command line ``argv`` (``sys.argv[1:]`` by default); return the exit status."""
    parser = build_parser()
    try:
        args = parser.parse_args(argv)
        if not getattr(args, "handler", None):
            parser.print_help(sys.stderr)
            return 2
        return int(args.handler(args) or 0)
    except CLIError as exc:
        print(str(exc), file=sys.stderr)
        return 2
    except ValueError as exc:
        print(f"rollingdisk: error: {exc}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        print("rollingdisk: interrupted", file=sys.stderr)
        return 130

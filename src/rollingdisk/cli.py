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
    """``rollingdisk steady``: one steady motion and its stability (sections 3, 4)."""
    p = sub.add_parser(
        "steady", help="a steady motion (straight line, circle, spin) and its stability",
        description="Steady motion of the disk (paper sections 3-4): give --theta0 and one of "
        "--Omega0, --rC, --rP for a circle, or --motion straight --omega0 W. Angles in "
        "radians or with a deg suffix; write negative angles as --theta0=-30deg.")
    p.add_argument("--ground", choices=("rough", "smooth"), default="rough",
                   help="rough (no slip, default) or smooth (no friction)")
    p.add_argument("--h", type=float, required=True, help="half-thickness / radius, h >= 0")
    p.add_argument("--theta0", type=parse_angle, help="inclination (radians, or e.g. 30deg)")
    p.add_argument("--motion", choices=("circle", "straight"), default=None,
                   help="circle (with spin in place) or straight; default from the options")
    g = p.add_mutually_exclusive_group()
    g.add_argument("--Omega0", type=float, help="spin rate d psi/dt of a circle")
    g.add_argument("--rC", type=float, help="signed radius of the circle of the centre C")
    g.add_argument("--rP", type=float, help="signed radius of the circle of the contact point")
    g.add_argument("--omega0", type=float, help="rolling rate of a straight line")
    p.add_argument("--json", action="store_true", help="print one JSON object")
    p.set_defaults(handler=_run_steady)


def _steady_record(motion, stab) -> dict:
    rec = motion.as_dict()
    rec["theta0_deg"] = math.degrees(motion.theta0)
    rec.update(varpi2=stab.varpi2, stable=bool(stab.stable),
               varpi=None if not stab.stable else stab.varpi, period=stab.period,
               growth_rate=stab.growth_rate)
    return rec


def _run_steady(args) -> int:
    from .disk import Disk
    from .stability import stability
    from .steady import steady_motion, straight_line

    disk = Disk(h=args.h)
    straight = args.motion == "straight" or (args.motion is None and args.omega0 is not None)
    if straight:
        if args.omega0 is None:
            raise CLIError("rollingdisk steady: --motion straight needs --omega0")
        motion = straight_line(disk, args.ground, args.omega0)
        if args.theta0 is not None and abs(abs(args.theta0) - motion.theta0) > 1e-9:
            raise CLIError(
                f"rollingdisk steady: a straight line is steady only at theta0 = arctan(h) = "
                f"{motion.theta0:.6g} rad ({math.degrees(motion.theta0):.4g}deg), "
                f"not {args.theta0:.6g}")
        if args.theta0 is not None and args.theta0 < 0:
            motion = straight_line(disk, args.ground, args.omega0, lean=-1)
    else:
        if args.omega0 is not None:
            raise CLIError("rollingdisk steady: --omega0 is for --motion straight; "
                           "circles take --Omega0, --rC or --rP")
        if args.theta0 is None:
            raise CLIError("rollingdisk steady: give --theta0 (e.g. 30deg) for a circle")
        if args.Omega0 is None and args.rC is None and args.rP is None:
            raise CLIError("rollingdisk steady: give one of --Omega0, --rC, --rP "
                           "(or --motion straight --omega0 W)")
        motion = steady_motion(disk, args.ground, args.theta0, Omega0=args.Omega0,
                               r_C=args.rC, r_P=args.rP)
    rec = _steady_record(motion, stability(motion))
    if args.json:
        import json

        print(json.dumps(rec))
        return 0
    labels = [
        ("ground", "ground"), ("h", "half-thickness / radius"), ("motion", "kind of motion"),
        ("theta0", "inclination [rad]"), ("theta0_deg", "inclination [deg]"),
        ("Omega0", "spin rate d psi/dt"), ("omega0", "rolling rate d phi/dt"),
        ("omega20", "angular velocity, omega2"), ("omega30", "angular velocity, omega3"),
        ("r_C", "radius of the circle of C"), ("r_P", "radius of the circle of P"),
        ("v_C", "speed of C"),
        ("F_y", "friction F_y = -r_C Omega0^2, points to the centre (eq. 27)"),
        ("varpi2", "varpi^2 of small oscillations"), ("stable", "stable (varpi^2 > 0)"),
        ("period", "period 2 pi / varpi"), ("growth_rate", "growth rate sqrt(-varpi^2)"),
    ]
    for key, text in labels:
        v = rec[key]
        if v is None:
            continue
        val = f"{v:.10g}" if isinstance(v, float) else str(v)
        print(f"{key:<12} {val:>18}   {text}")
    print("(dimensionless: m = a = g = 1, time unit sqrt(a/g))")
    return 0


# ---------------------------------------------------------------------------- thresholds
def _add_thresholds(sub) -> None:
    """``rollingdisk thresholds``: critical speeds of eqs. (42), (43), (53), (57)."""
    p = sub.add_parser("thresholds", help="critical squared speeds for a disk (eqs. 42, 43, "
                       "53, 57)")
    p.add_argument("--h", type=float, required=True, help="half-thickness / radius, h >= 0")
    p.add_argument("--json", action="store_true", help="print one JSON object")
    p.set_defaults(handler=_run_thresholds)


def _run_thresholds(args) -> int:
    from .stability import thresholds

    d = thresholds(args.h).as_dict()
    if args.json:
        import json

        print(json.dumps(d))
        return 0
    eqs = {("rough", "straight_line_omega20_sq"): "(42)",
           ("rough", "se_circle_omega30_sq"): "(43)",
           ("smooth", "straight_line_omega20_sq"): "(53)",
           ("smooth", "spin_omega30_sq"): "(57)"}
    print(f"stability thresholds for h = {args.h:g} (stable above):")
    for ground, rows in d.items():
        for key, v in rows.items():
            print(f"  {ground:<7} {key:<26} {v:.10g}   eq. {eqs[(ground, key)]}")
    return 0


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

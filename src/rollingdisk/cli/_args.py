"""Argument helpers shared by the commands: angles, checked numbers, the options that name
a steady motion, ``--state`` with ``--perturb`` / ``--kick``, tolerances and ``--out``.

Every number is checked when the command line is read, with the library's own checks (same
message), so that a bad value is refused before any work.
"""

from __future__ import annotations

import argparse
import math
import sys

from rollingdisk.model.disk import H_MAX
from rollingdisk.util.checks import check_int, check_real
from rollingdisk.util.errors import INPUT_ERRORS

__all__ = ["CLIError", "parse_angle", "real", "integer", "positive_int", "H", "T_END_MAX",
           "SIMULATE_T_END_MAX", "RTOL_RANGE", "add_motion_args", "add_state_arg",
           "add_perturbation_args", "add_tolerance_args", "motion_from_args",
           "start_from_args", "initial_state", "t_end_arg"]

#: Longest simulated time of ``sweep`` and ``animate`` (many runs; frames sampling one run).
T_END_MAX = 1e4
#: Longest simulated time of ``simulate``: larger, because its work is bounded by the step
#: budget (``--max-steps``) and its CSV streams (memory stays flat): a long run is its point.
SIMULATE_T_END_MAX = 1e6
#: Relative tolerances accepted: 100 machine epsilons (the integrators' floor) to 1e-2
#: (beyond it the error control no longer keeps a run on the motion; the hybrid Coulomb
#: integrator's interpolant leaves floating-point range at rtol 0.5).
RTOL_RANGE = (100 * sys.float_info.epsilon, 1e-2)
#: Absolute tolerances accepted.
ATOL_RANGE = (0.0, 1e-2)


class CLIError(Exception):
    """A usage error of the command line: printed as one line on stderr, exit status 2."""


def parse_angle(text: str) -> float:
    """An angle in radians, or in degrees with a ``deg`` suffix (``30deg``).

    Parameters
    ----------
    text : str
        ``"0.5"``, ``"30deg"`` or ``"30°"``.

    Returns
    -------
    float
        The angle in radians (not checked: ``inf`` and ``nan`` pass).

    Examples
    --------
    >>> parse_angle("90deg") == math.pi / 2
    True
    """
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


def real(name: str, *, angle: bool = False, **bounds):
    """An argparse type: a real number checked as the library checks it (same message);
    ``angle=True`` also takes a ``deg`` suffix."""
    def parse(text: str) -> float:
        try:
            value = parse_angle(text) if angle else float(text)
        except (ValueError, argparse.ArgumentTypeError):
            value = text  # check_real names the parameter and the range
        try:
            return check_real(name, value, **bounds)
        except INPUT_ERRORS as exc:
            raise argparse.ArgumentTypeError(str(exc)) from None

    return parse


def integer(name: str, low: int | None = None, high: int | None = None):
    """An argparse type: an integer checked as the library checks it (same message)."""
    def parse(text: str) -> int:
        try:
            value = int(text)
        except ValueError:
            value = text
        try:
            return check_int(name, value, low=low, high=high)
        except INPUT_ERRORS as exc:
            raise argparse.ArgumentTypeError(str(exc)) from None

    return parse


positive_int = integer("the value", low=1)
H = real("h", low=0.0, high=H_MAX)  # the half-thickness, as Disk checks it
_HALF_PI = math.pi / 2


def t_end_arg(p, *, high: float, default: float | None = None) -> None:
    """``--t-end`` in (0, high]."""
    kw = {"required": True} if default is None else {"default": default}
    p.add_argument("--t-end", dest="t_end", type=real("t_end", low=0.0, high=high,
                                                       low_open=True),
                   help=f"simulated time in (0, {high:g}] (units sqrt(a/g))"
                   + ("" if default is None else f" (default {default:g})"), **kw)


def add_perturbation_args(p, *, kick: float | None = 0.0, perturb: float | None = 0.0) -> None:
    """``--perturb`` (added to theta(0), |x| < pi/2) and ``--kick`` (added to omega1(0))."""
    p.add_argument("--perturb", default=perturb,
                   type=real("perturb", angle=True, low=-_HALF_PI, high=_HALF_PI,
                             low_open=True, high_open=True),
                   help="added to theta(0), in (-pi/2, pi/2) rad (or deg)"
                   + ("" if perturb is None else f" (default {perturb:g})"))
    p.add_argument("--kick", type=real("kick"), default=kick,
                   help="added to omega1(0) = d theta/dt"
                   + ("" if kick is None else f" (default {kick:g})"))


def add_tolerance_args(p) -> None:
    """``--rtol`` and ``--atol`` in the ranges every integrator honours."""
    lo, hi = RTOL_RANGE
    p.add_argument("--rtol", type=real("rtol", low=lo, high=hi), default=None,
                   help=f"relative tolerance in [{lo:.3g}, {hi:g}]")
    p.add_argument("--atol", type=real("atol", low=ATOL_RANGE[0], high=ATOL_RANGE[1],
                                       low_open=True), default=None,
                   help=f"absolute tolerance in (0, {ATOL_RANGE[1]:g}]")


def add_motion_args(p, *, h_default: float | None = None, coulomb: bool = False):
    """The arguments that name a steady motion (steady, simulate, exact, animate).

    Returns the mutually exclusive group of the free parameter, for commands that add an
    alternative to it (``--state``).  ``coulomb``: ``--ground coulomb`` is allowed (the
    steady motion is then the rough-ground one, started rolling).
    """
    if coulomb:
        p.add_argument("--ground", choices=("rough", "smooth", "coulomb"), default="rough",
                       help="rough (no slip, default), smooth (no friction) or coulomb "
                       "(friction --mu: rolling while it holds, sliding when it cannot)")
    else:
        p.add_argument("--ground", choices=("rough", "smooth"), default="rough",
                       help="rough (no slip, default) or smooth (no friction)")
    if h_default is None:
        p.add_argument("--h", type=H, required=True, help="half-thickness / radius, h >= 0")
    else:
        p.add_argument("--h", type=H, default=h_default,
                       help=f"half-thickness / radius, h >= 0 (default {h_default:g})")
    p.add_argument("--theta0", type=parse_angle,
                   help="steady inclination (radians, or e.g. 30deg; negative: --theta0=-30deg)")
    p.add_argument("--motion", choices=("circle", "straight"), default=None,
                   help="circle (spin in place included) or straight; default from the options")
    g = p.add_mutually_exclusive_group()
    g.add_argument("--Omega0", type=real("Omega0"), help="spin rate d psi/dt of a steady circle")
    g.add_argument("--rC", type=real("r_C"), help="signed radius of the circle of the centre C")
    g.add_argument("--rP", type=real("r_P"),
                   help="signed radius of the circle of the contact point")
    g.add_argument("--omega0", type=real("omega0"),
                   help="rolling rate d phi/dt of a straight line")
    return g


def add_state_arg(group, help: str) -> None:
    """``--state NAME=VALUE,...``, an alternative to the steady motion's free parameter."""
    group.add_argument("--state", type=str, metavar="NAME=VALUE,...", help=help)


def motion_from_args(args, command: str):
    """The steady motion the arguments of :func:`add_motion_args` ask for (section 3)."""
    import rollingdisk as rd

    disk = rd.Disk(h=args.h)
    ground = "rough" if args.ground == "coulomb" else args.ground
    straight = args.motion == "straight" or (args.motion is None and args.omega0 is not None)
    if straight:
        if args.omega0 is None:
            raise CLIError(f"rollingdisk {command}: error: --motion straight needs --omega0")
        return rd.straight_line(disk, ground, args.omega0, theta0=args.theta0)
    if args.omega0 is not None:
        raise CLIError(f"rollingdisk {command}: error: --omega0 is for --motion straight; "
                       "circles take --Omega0, --rC or --rP")
    if args.theta0 is None:
        raise CLIError(f"rollingdisk {command}: error: give --theta0 (e.g. 30deg) with one of "
                       "--Omega0, --rC, --rP, or --motion straight --omega0 W")
    if args.Omega0 is None and args.rC is None and args.rP is None:
        raise CLIError(f"rollingdisk {command}: error: give one of --Omega0, --rC, --rP "
                       "(or --motion straight --omega0 W)")
    return rd.steady_motion(disk, ground, args.theta0, Omega0=args.Omega0, r_C=args.rC,
                            r_P=args.rP)


def start_from_args(args, command: str):
    """The steady motion asked for, or None when ``--state`` gives the whole start."""
    if getattr(args, "state", None) is None:
        return motion_from_args(args, command)
    if args.theta0 is not None or args.motion is not None:
        raise CLIError(f"rollingdisk {command}: --state gives the whole initial state; "
                       "leave out --theta0 and --motion")
    return None


def _parse_state(text: str, layout: str, command: str) -> tuple[list[float], set[str]]:
    from rollingdisk.model.state import state_names

    names = state_names(layout)
    values = dict.fromkeys(names, 0.0)
    seen: set[str] = set()
    for item in filter(None, (part.strip() for part in text.split(","))):
        key, sep, val = item.partition("=")
        key = key.strip()
        if not sep or key not in values:
            raise CLIError(f"rollingdisk {command}: --state takes NAME=VALUE pairs with NAME "
                           f"in {', '.join(names)}, got {item!r}")
        if key in seen:
            raise CLIError(f"rollingdisk {command}: --state gives {key} twice")
        seen.add(key)
        try:
            values[key] = check_real(key, parse_angle(val))
        except (argparse.ArgumentTypeError, *INPUT_ERRORS):
            raise CLIError(f"rollingdisk {command}: --state {key}: not a finite number: "
                           f"{val!r}") from None
    if "theta" not in seen:
        raise CLIError(f"rollingdisk {command}: --state must give theta (e.g. theta=0.3)")
    return [values[n] for n in names], seen


def initial_state(args, layout: str, command: str) -> tuple[list[float], set[str]]:
    """``--state`` as a state vector of ``layout`` ("rough" or "smooth"), with ``--perturb``
    added to theta and ``--kick`` to omega1; also the names the user gave."""
    from rollingdisk.model.state import state_index

    y, named = _parse_state(args.state, layout, command)
    y[state_index(layout, "theta")] += args.perturb
    y[state_index(layout, "omega1")] += args.kick
    return y, named

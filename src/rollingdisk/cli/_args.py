"""Argument helpers shared by the commands: angles, checked numbers, the disk (``--h``,
``--disk``, ``--radius`` ...), the options that name a steady motion, ``--state`` with
``--perturb`` / ``--kick``, tolerances and ``--out``.

Every number is checked when the command line is read, with the library's own checks (same
message), so that a bad value is refused before any work.
"""

from __future__ import annotations

import argparse
import math
import sys

from rollingdisk.model.disk import DEFAULT_H, H_MAX
from rollingdisk.util.checks import check_int, check_real
from rollingdisk.util.errors import INPUT_ERRORS

__all__ = ["CLIError", "parse_angle", "real", "integer", "positive_int", "H", "T_END_MAX",
           "SIMULATE_T_END_MAX", "RTOL_RANGE", "add_motion_args", "add_state_arg",
           "add_perturbation_args", "add_tolerance_args", "motion_from_args",
           "start_from_args", "initial_state", "t_end_arg", "add_disk_options",
           "disk_from_args", "DISK_OPTIONS", "length_coefficient", "resolve_length"]

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
                   help="added to omega1(0) = d theta/dt (units sqrt(g/a))"
                   + ("" if kick is None else f" (default {kick:g})"))


def add_json_arg(p) -> None:
    """``--json``: one JSON object on stdout, with SI fields for a disk with a size."""
    p.add_argument("--json", action="store_true",
                   help="print one JSON object (for a disk with a physical size: SI values "
                   "as <name>_si fields and a \"units\" map)")


def add_tolerance_args(p) -> None:
    """``--rtol`` and ``--atol`` in the ranges every integrator honours."""
    lo, hi = RTOL_RANGE
    p.add_argument("--rtol", type=real("rtol", low=lo, high=hi), default=None,
                   help=f"relative tolerance in [{lo:.3g}, {hi:g}]")
    p.add_argument("--atol", type=real("atol", low=ATOL_RANGE[0], high=ATOL_RANGE[1],
                                       low_open=True), default=None,
                   help=f"absolute tolerance in (0, {ATOL_RANGE[1]:g}]")


#: The options of :func:`add_disk_options` other than ``--h`` (dest names).
DISK_OPTIONS = ("disk", "radius", "diameter", "thickness", "mass", "gravity")


def _disk_list() -> str:
    import rollingdisk as rd

    return "; ".join(f"{name}: {rd.DISKS[name].source}" for name in sorted(rd.DISKS))


def add_disk_options(p, *, required: bool = False, default_h: float | None = None,
                     h: bool = True):
    """The options that give the disk, as an argument group "the disk".

    ``--h H`` (dimensionless half-thickness / radius), ``--disk NAME`` (a key of
    :data:`rollingdisk.DISKS`), ``--radius`` or ``--diameter`` with ``--thickness`` (lengths
    with units, ``23.25mm``, ``0.9in``; plain numbers are metres), ``--mass`` (``7.5g``) and
    ``--gravity`` (``9.81m/s^2``; standard gravity by default).  Only ``--h`` is checked
    when the command line is read (the same message as the library's); the others are
    strings, combined and checked by :func:`disk_from_args` (with
    :func:`rollingdisk.disk_from_options`) before any work.

    Parameters
    ----------
    p : argparse.ArgumentParser
    required : bool
        The disk must be given (``--h``, ``--disk``, ``--radius`` or ``--diameter``).
    default_h : float, optional
        The ``h`` of a command given no size (``None``: :data:`rollingdisk.DEFAULT_H`).
    h : bool
        Add ``--h`` (``False`` for a command that adds its own, e.g. a range).

    Returns
    -------
    argparse._ArgumentGroup
        The group (a command may add to it).
    """
    g = p.add_argument_group(
        "the disk", "Give it one way: --h H alone (dimensionless: answers in the paper's "
        "units, m = a = g = 1), --disk NAME, or --radius/--diameter with --thickness (or "
        "with --h); --mass and --gravity may be added. With a physical size every answer "
        "is also given in SI units.")
    if h:
        if required:
            text = "half-thickness / radius, 0 <= h <= 1e8 (dimensionless)"
        else:
            dh = DEFAULT_H if default_h is None else default_h
            text = (f"half-thickness / radius, 0 <= h <= 1e8 (dimensionless; default "
                    f"{dh:g} when no size is given)")
        g.add_argument("--h", type=H, default=None, metavar="H", help=text)
    import rollingdisk as rd

    g.add_argument("--disk", choices=sorted(rd.DISKS), default=None, metavar="NAME",
                   help="a named disk, one of " + _disk_list())
    g.add_argument("--radius", default=None, metavar="LENGTH",
                   help="radius a, a length with a unit (11.625mm, 0.9in; a plain number "
                   "is in metres)")
    g.add_argument("--diameter", default=None, metavar="LENGTH",
                   help="diameter 2a instead of --radius (23.25mm)")
    g.add_argument("--thickness", default=None, metavar="LENGTH",
                   help="full thickness 2 h a (2.33mm), with --radius or --diameter")
    g.add_argument("--mass", default=None, metavar="MASS",
                   help="mass (7.5g, 0.45kg; a plain number is in kilograms): forces in N, "
                   "energies in J")
    g.add_argument("--gravity", default=None, metavar="ACCELERATION",
                   help="gravitational acceleration (9.81m/s^2, 1.62m/s^2; a plain number "
                   "is in m/s^2; default standard gravity 9.80665 m/s^2)")
    p.set_defaults(_disk_required=required, _disk_default_h=default_h)
    return g


def disk_from_args(args):
    """The :class:`~rollingdisk.Disk` the options of :func:`add_disk_options` give.

    Raises
    ------
    CLIError
        ``required`` and no size given.
    ParameterError
        Conflicting options or a bad value (:func:`rollingdisk.disk_from_options`; the
        command line's exit contract makes it one line and exit status 2).
    """
    import rollingdisk as rd

    opts = {k: getattr(args, k, None) for k in DISK_OPTIONS}
    h = getattr(args, "h", None)
    if isinstance(h, list):  # sweep's range: a physical disk takes a single value
        h = h[0] if len(h) == 1 else h
    sized = h is not None or any(opts[k] is not None for k in ("disk", "radius", "diameter",
                                                               "thickness"))
    if not sized:
        if getattr(args, "_disk_required", False):
            command = getattr(args, "command", None)
            prog = f"rollingdisk {command}" if command else "rollingdisk"
            raise CLIError(f"{prog}: error: give the disk: --h H (dimensionless), --disk "
                           "NAME, or --radius/--diameter with --thickness")
        h = getattr(args, "_disk_default_h", None)
    return rd.disk_from_options(**opts, h=h, option_prefix="--")


class _Length(float):
    """A length in metres given with a unit (see :func:`length_coefficient`)."""


def length_coefficient(name: str):
    """An argparse type: a length coefficient, a plain number in units of the radius ``a``
    or a length with a unit (``20um``) when the disk has a physical radius; checked
    ``>= 0`` here and converted by :func:`resolve_length` once the disk is known."""
    plain = real(name, low=0.0)

    def parse(text: str) -> float:
        try:
            float(text)
        except ValueError:
            pass
        else:
            return plain(text)
        import rollingdisk as rd

        try:
            return _Length(rd.parse_length(text, f"--{name.replace('_', '-')}"))
        except INPUT_ERRORS as exc:
            raise argparse.ArgumentTypeError(
                f"{exc} (or a plain number >= 0, in units of the radius)") from None

    return parse


def resolve_length(value, disk, option: str):
    """A value of :func:`length_coefficient` in units of the radius of ``disk``."""
    if not isinstance(value, _Length):
        return value
    if disk.radius is None:
        from rollingdisk.util.errors import ParameterError

        raise ParameterError(f"{option} {value:g} m is a length with a unit: it needs a disk "
                             "with a physical radius (--disk, --radius or --diameter); "
                             "without one give it in units of the radius, a plain number")
    return float(value) / disk.radius


def add_motion_args(p, *, h_default: float | None = None, coulomb: bool = False):
    """The arguments that name a steady motion (steady, simulate, exact, animate), with
    the disk (:func:`add_disk_options`: ``--h`` required unless ``h_default`` is given).

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
    add_disk_options(p, required=h_default is None, default_h=h_default)
    p.add_argument("--theta0", type=parse_angle,
                   help="steady inclination (radians, or e.g. 30deg; negative: --theta0=-30deg)")
    p.add_argument("--motion", choices=("circle", "straight"), default=None,
                   help="circle (spin in place included) or straight; default from the options")
    g = p.add_mutually_exclusive_group()
    g.add_argument("--Omega0", type=real("Omega0"),
                   help="spin rate d psi/dt of a steady circle (units sqrt(g/a))")
    g.add_argument("--rC", type=real("r_C"),
                   help="signed radius of the circle of the centre C (units of a)")
    g.add_argument("--rP", type=real("r_P"),
                   help="signed radius of the circle of the contact point (units of a)")
    g.add_argument("--omega0", type=real("omega0"),
                   help="rolling rate d phi/dt of a straight line (units sqrt(g/a); C moves "
                   "at omega0 sqrt(a g))")
    return g


def add_state_arg(group, help: str) -> None:
    """``--state NAME=VALUE,...``, an alternative to the steady motion's free parameter."""
    group.add_argument("--state", type=str, metavar="NAME=VALUE,...", help=help)


def motion_from_args(args, command: str):
    """The steady motion the arguments of :func:`add_motion_args` ask for (section 3)."""
    import rollingdisk as rd

    disk = disk_from_args(args)
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

"""Argument helpers shared by the commands: angles, checked numbers, dimensional values with
units, the disk (``--h``, ``--disk``, ``--radius`` ...), the options that name a steady
motion, ``--state`` with ``--perturb`` / ``--kick``, tolerances, progress and ``--out``.

Every number is checked when the command line is read, with the library's own checks (same
message), so that a bad value is refused before any work.  A dimensional value (a time, a
length, a speed, an angular speed: :func:`quantity`) is read then too, and converted to the
paper's units once the disk is known (:func:`resolve_inputs`, called by
:func:`disk_from_args`), by the rule of :mod:`rollingdisk.model.inputs` (:data:`UNITS_RULE`).
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
           "disk_from_args", "DISK_OPTIONS", "length_coefficient", "resolve_length", "quantity",
           "quantity_range", "resolve_inputs", "echo_inputs", "UNITS_RULE",
           "add_progress_args", "show_progress", "alias"]

#: The rule for dimensional values, as every --help states it (the disk group's text).
UNITS_RULE = ("Dimensional values (times, lengths, speeds, angular speeds): without a "
              "physical disk, plain numbers in the paper's units (m = a = g = 1); with one "
              "(--disk, --radius/--diameter), write the unit: SI or any unit pint reads "
              "(--t-end 2s, --rC 5cm, --Omega0 30rad/s, --omega0 0.3m/s), or the suffix a "
              "for the paper's units (--t-end 20a); a plain number is then refused as "
              "ambiguous. The text output echoes each conversion.")

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


class _Input(float):
    """A dimensional value as read from the command line, before the disk is known: its
    float value is the number typed (NaN for one with a unit), :func:`resolve_inputs` turns
    it into a plain float in the paper's units."""

    text: str
    kind: str
    name: str
    option: str
    how: str
    bounds: dict


def _make_input(value: float, text: str, kind: str, name: str, option: str, how: str,
                bounds: dict) -> _Input:
    x = _Input(value)
    x.text, x.kind, x.name, x.option, x.how, x.bounds = text, kind, name, option, how, bounds
    return x


def quantity(name: str, kind: str, option: str | None = None, **bounds):
    """An argparse type: a dimensional value (``kind``, a key of
    :data:`rollingdisk.model.inputs.INPUT_KINDS`), a plain number, a number with the
    suffix ``a`` (the paper's units) or a number with a unit (``2s``, ``5cm``, ``30rad/s``),
    checked when read (a plain number as :func:`real` checks it, same message) and
    converted by :func:`resolve_inputs` once the disk is known."""
    plain = real(name, **bounds)
    option = option or f"--{name.replace('_', '-')}"

    def parse(text: str) -> _Input:
        from rollingdisk.model.inputs import read_input

        try:
            float(text)
        except ValueError:
            pass
        else:
            return _make_input(plain(text), text, kind, name, option, "bare", bounds)
        try:
            how, x, _ = read_input(kind, text, option)
            if how == "paper":
                x = check_real(name, x, **bounds)
        except INPUT_ERRORS as exc:
            raise argparse.ArgumentTypeError(str(exc)) from None
        return _make_input(x if how == "paper" else math.nan, text, kind, name, option, how,
                           bounds)

    return parse


def _resolve_one(value, disk, echo: list):
    """One value of :func:`quantity` in the paper's units (anything else unchanged)."""
    if not isinstance(value, _Input):
        return value
    from rollingdisk.model.inputs import INPUT_KINDS, to_paper

    x = to_paper(disk, value.kind, value.text.strip(), value.option)
    if value.how == "si":
        try:
            x = check_real(value.name, x, **value.bounds)
        except INPUT_ERRORS as exc:
            raise type(exc)(f"{exc} (from {value.option} {value.text})") from None
        echo.append(f"{value.option} {value.text} = {x:.10g} {INPUT_KINDS[value.kind][3]}")
    return float(x)


def _resolve_state(text: str, disk, echo: list) -> str:
    """``--state`` with each dimensional component in the paper's units (angles as
    typed); a plain number of a dimensional component is refused for a physical disk."""
    from rollingdisk.model.inputs import INPUT_KINDS, to_paper

    kinds = {"X_C": "length", "Y_C": "length", "V_X": "speed", "V_Y": "speed",
             "omega1": "angular_speed", "omega2": "angular_speed", "omega3": "angular_speed"}
    items = []
    for item in filter(None, (part.strip() for part in text.split(","))):
        key, sep, val = item.partition("=")
        kind = kinds.get(key.strip())
        if sep and kind is not None:
            x = to_paper(disk, kind, val.strip(), f"--state {key.strip()}=")
            if not _is_plain_number(val):
                echo.append(f"--state {key.strip()}={val.strip()} = {x:.10g} "
                            f"{INPUT_KINDS[kind][3]}")
            val = repr(float(x))
        items.append(f"{key}{sep}{val}")
    return ",".join(items)


def _is_plain_number(text: str) -> bool:
    try:
        float(text)
    except ValueError:
        return False
    return True


def resolve_inputs(args, disk) -> list[str]:
    """Convert every dimensional value of ``args`` (:func:`quantity`, ranges of them,
    ``--state``) to the paper's units with ``disk``'s scale, in place; the conversions made,
    as lines to echo (``--t-end 2s = 58.09 sqrt(a/g)``).

    Raises
    ------
    ParameterError
        A plain number for a physical disk (the message names both spellings), a value with
        a unit for a disk without a physical size, or a converted value out of its range.
    """
    echo: list[str] = []
    for key, value in list(vars(args).items()):
        if isinstance(value, _Input):
            setattr(args, key, _resolve_one(value, disk, echo))
        elif isinstance(value, _Range):
            setattr(args, key, value.resolve(disk, echo))
    state = getattr(args, "state", None)
    if isinstance(state, str) and not getattr(args, "_state_resolved", False):
        args.state = _resolve_state(state, disk, echo)
        args._state_resolved = True
    return echo


class _Range:
    """``A:B:N`` of dimensional values (:func:`quantity_range`), resolved to a list."""

    def __init__(self, ends: list, n: int):
        self.ends, self.n = ends, n

    def resolve(self, disk, echo: list) -> list[float]:
        ends = [_resolve_one(x, disk, echo) for x in self.ends]
        if self.n == 1 or len(ends) == 1:
            return ends[:1]
        a, b = ends
        n = self.n
        return [a + (b - a) * i / (n - 1) for i in range(n - 1)] + [b]  # as np.linspace


def quantity_range(name: str, kind: str, option: str | None = None, *,
                   points_max: int = 100_000):
    """An argparse type: ``A:B:N`` (N points from A to B) or one value, A and B dimensional
    values as :func:`quantity` reads them (``10rad/s:30rad/s:5``)."""
    one = quantity(name, kind, option)

    def parse(text: str) -> _Range:
        parts = str(text).split(":")
        if len(parts) not in (1, 3):
            raise argparse.ArgumentTypeError(f"expected a value or A:B:N, got {text!r}")
        ends = [one(x) for x in parts[:2]]
        try:
            n = check_int("N", int(parts[2]), low=1, high=points_max) if len(parts) == 3 \
                else 1
        except (ValueError, *INPUT_ERRORS) as exc:
            why = str(exc) if isinstance(exc, INPUT_ERRORS) else "not a number"
            raise argparse.ArgumentTypeError(f"expected a value or A:B:N with finite A, B "
                                             f"and N >= 1, got {text!r} ({why})") from None
        return _Range(ends, n)

    return parse


def alias(p, old: str, new: str, **kw) -> None:
    """``old``, a spelling kept for scripts written before ``new`` became the one name: it
    still works and is hidden from --help (``kw``: as ``new``'s type, dest, action)."""
    p.add_argument(old, help=argparse.SUPPRESS, default=argparse.SUPPRESS, **kw)


def add_progress_args(p) -> None:
    """``--quiet`` (nothing on stderr but errors) and ``--progress`` (the progress bar even
    when stderr is not a terminal): by default progress is drawn only on a terminal."""
    g = p.add_mutually_exclusive_group()
    g.add_argument("--quiet", action="store_true",
                   help="no progress and no notes on stderr (default: progress only when "
                   "stderr is a terminal)")
    g.add_argument("--progress", action="store_true",
                   help="draw progress on stderr even when it is not a terminal (a log file)")


def show_progress(args) -> bool:
    """Whether a command draws progress: not with --quiet or --json; with --progress; else
    only when stderr is a terminal."""
    if getattr(args, "quiet", False) or getattr(args, "json", False):
        return False
    if getattr(args, "progress", False):
        return True
    try:
        return sys.stderr.isatty()
    except (AttributeError, ValueError):
        return False


positive_int = integer("the value", low=1)
H = real("h", low=0.0, high=H_MAX)  # the half-thickness, as Disk checks it
_HALF_PI = math.pi / 2


def t_end_arg(p, *, high: float, default: float | None = None) -> None:
    """``--t-end`` in (0, high]."""
    kw = {"required": True} if default is None else {"default": default}
    p.add_argument("--t-end", dest="t_end", type=quantity("t_end", "time", low=0.0, high=high,
                                                           low_open=True),
                   metavar="TIME",
                   help=f"simulated time in (0, {high:g}] sqrt(a/g) (with a physical disk a "
                   "time with a unit, 2s, or 20a in the paper's units)"
                   + ("" if default is None else f" (default {default:g} sqrt(a/g))"), **kw)


def add_perturbation_args(p, *, kick: float | None = 0.0, perturb: float | None = 0.0) -> None:
    """``--perturb`` (added to theta(0), |x| < pi/2) and ``--kick`` (added to omega1(0))."""
    p.add_argument("--perturb", default=perturb,
                   type=real("perturb", angle=True, low=-_HALF_PI, high=_HALF_PI,
                             low_open=True, high_open=True),
                   help="added to theta(0), in (-pi/2, pi/2) rad (or deg)"
                   + ("" if perturb is None else f" (default {perturb:g})"))
    p.add_argument("--kick", type=quantity("kick", "angular_speed"), default=kick,
                   metavar="RATE",
                   help="added to omega1(0) = d theta/dt (units sqrt(g/a); with a physical "
                   "disk an angular speed, 0.5rad/s)"
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
                     h: bool = True, positional: bool = False, h_range: tuple | None = None):
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
    positional : bool
        Also take the name of a disk as an optional positional argument
        (``rollingdisk thresholds euro-1``), the same as ``--disk``.
    h_range : (low, high), optional
        The range of ``--h`` when narrower than ``[0, H_MAX]`` (the explorer's).

    Returns
    -------
    argparse._ArgumentGroup
        The group (a command may add to it).
    """
    g = p.add_argument_group(
        "the disk", "Give it one way: --h H alone (dimensionless: answers in the paper's "
        "units, m = a = g = 1), --disk NAME, or --radius/--diameter with --thickness (or "
        "with --h); --mass and --gravity may be added. With a physical size every answer "
        "is also given in SI units. " + UNITS_RULE)
    import rollingdisk as rd

    if positional:
        g.add_argument("disk_name", nargs="?", default=None, choices=sorted(rd.DISKS),
                       metavar="DISK", help="a named disk, as --disk NAME")
    if h:
        lo, hi = (0.0, H_MAX) if h_range is None else h_range
        span = f"{lo:g} <= h <= {'1e8' if h_range is None else f'{hi:g}'}"
        if required:
            text = f"half-thickness / radius, {span} (dimensionless)"
        else:
            dh = DEFAULT_H if default_h is None else default_h
            text = (f"half-thickness / radius, {span} (dimensionless; default {dh:g} when "
                    "no size is given)")
        g.add_argument("--h", type=H if h_range is None else real("h", low=lo, high=hi),
                       default=None, metavar="H", help=text)

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
    named = getattr(args, "disk_name", None)
    if named is not None:
        if opts["disk"] is not None and opts["disk"] != named:
            raise CLIError(f"{_prog(args)}: error: two disks named: {named} and --disk "
                           f"{opts['disk']}; give one")
        opts["disk"] = named
    h = getattr(args, "h", None)
    if isinstance(h, list):  # sweep's range: a physical disk takes a single value
        h = h[0] if len(h) == 1 else h
    sized = h is not None or any(opts[k] is not None for k in ("disk", "radius", "diameter",
                                                               "thickness"))
    if not sized:
        if getattr(args, "_disk_required", False):
            raise CLIError(f"{_prog(args)}: error: give the disk: --h H (dimensionless), "
                           "--disk NAME, or --radius/--diameter with --thickness")
        h = getattr(args, "_disk_default_h", None)
    disk = rd.disk_from_options(**opts, h=h, option_prefix="--")
    echo_inputs(args, resolve_inputs(args, disk))
    return disk


def _prog(args) -> str:
    command = getattr(args, "command", None)
    return f"rollingdisk {command}" if command else "rollingdisk"


def echo_inputs(args, lines: list[str]) -> None:
    """Say how the dimensional values were read (``units: --t-end 2s = 58.09 sqrt(a/g)``):
    on stdout before the text output, on stderr for a command whose stdout is a path
    (``_echo_stderr``), not at all with --json or --quiet."""
    if not lines or getattr(args, "json", False):
        return
    stderr = getattr(args, "_echo_stderr", False)
    if stderr and getattr(args, "quiet", False):
        return
    print("units: " + "; ".join(lines) + " (the paper's units: m = a = g = 1)",
          file=sys.stderr if stderr else sys.stdout, flush=True)


def length_coefficient(name: str):
    """An argparse type: a length coefficient ``>= 0`` (rolling resistance, pivoting
    friction), in units of the radius ``a`` or, with a physical disk, a length with a unit
    (``20um``): a dimensional value as :func:`quantity` reads it."""
    return quantity(name, "length", low=0.0)


def resolve_length(value, disk, option: str):
    """A value of :func:`length_coefficient` in units of the radius of ``disk`` (already a
    float once :func:`resolve_inputs` ran)."""
    return _resolve_one(value, disk, [])


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
    g.add_argument("--Omega0", type=quantity("Omega0", "angular_speed", "--Omega0"),
                   metavar="RATE",
                   help="spin rate d psi/dt of a steady circle (units sqrt(g/a); with a "
                   "physical disk 30rad/s, 300rpm)")
    g.add_argument("--omega30", type=quantity("omega30", "angular_speed", "--omega30"),
                   metavar="RATE",
                   help="spin omega30 = Omega0 cos(theta0) of a steady circle, the axis of "
                   "the maps (units sqrt(g/a); with a physical disk 30rad/s)")
    g.add_argument("--rC", type=quantity("r_C", "length", "--rC"), metavar="LENGTH",
                   help="signed radius of the circle of the centre C (units of a; with a "
                   "physical disk 5cm)")
    g.add_argument("--rP", type=quantity("r_P", "length", "--rP"), metavar="LENGTH",
                   help="signed radius of the circle of the contact point (units of a; "
                   "with a physical disk 5cm)")
    g.add_argument("--omega0", type=quantity("omega0", "rolling_rate", "--omega0"),
                   metavar="RATE",
                   help="rolling rate d phi/dt of a straight line (units sqrt(g/a); C moves "
                   "at omega0 sqrt(a g); with a physical disk 20rad/s, or the speed of C, "
                   "0.3m/s)")
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
                       "circles take --Omega0, --omega30, --rC or --rP")
    if args.theta0 is None:
        raise CLIError(f"rollingdisk {command}: error: give --theta0 (e.g. 30deg) with one of "
                       "--Omega0, --omega30, --rC, --rP, or --motion straight --omega0 W")
    if args.Omega0 is None and args.rC is None and args.rP is None and args.omega30 is None:
        raise CLIError(f"rollingdisk {command}: error: give one of --Omega0, --omega30, --rC, "
                       "--rP (or --motion straight --omega0 W)")
    return rd.steady_motion(disk, ground, args.theta0, Omega0=args.Omega0, r_C=args.rC,
                            r_P=args.rP, omega30=args.omega30)


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

"""Command-line interface: a thin layer over the library, one subcommand per entry point.

Exit status and messages:

* 0: done;
* 2: bad input, one line on stderr and no traceback: a usage error of the command line, an
  input error of the library (:data:`rollingdisk.util.errors.INPUT_ERRORS`: a value out of its
  range, a wrong type, an impossible request), or an output path that cannot be written;
  every number is checked when the command line is read, before any work;
* 1: anything else is a bug in rollingdisk: the traceback, then one line saying so;
* 130 (Ctrl-C) and 143 (SIGTERM): "interrupted" / "terminated", and no partial file: every
  output is written under a temporary name and renamed when complete (:mod:`._files`).

JSON output is strict (no NaN or infinity: ``json.dumps(..., allow_nan=False)``).

One module of about 800 lines on purpose: the parser and the handler of every subcommand,
kept together so that the contract above visibly holds for all of them; each handler is a
thin call into the library.
"""

from __future__ import annotations

import argparse
import math
import os
import signal
import sys
from collections.abc import Sequence

from rollingdisk.model.disk import DEFAULT_H, H_MAX
from rollingdisk.util.checks import check_int, check_real
from rollingdisk.util.errors import INPUT_ERRORS, ParameterError
from rollingdisk.util.files import (
    Terminated,
    check_signals,
    check_writable,
    pending_signal,
    terminate_as_exception,
)

__all__ = ["main", "parse_angle", "build_parser"]

#: Longest simulated time of ``animate`` (the frames sample it uniformly; the integrator
#: would need minutes beyond it).
ANIMATE_T_END_MAX = 1e4


class CLIError(Exception):
    """A usage error of the command line: printed as one line on stderr, exit status 2."""


class _Exit(Exception):  # noqa: N818 - argparse's exit (--help), as a return value
    def __init__(self, status: int):
        super().__init__(status)
        self.status = status


def parse_angle(text: str) -> float:
    """An angle in radians, or in degrees with a ``deg`` suffix (``30deg``).

    Parameters
    ----------
    text : str
        ``"0.5"``, ``"30deg"`` or ``"30°"``.

    Returns
    -------
    float
        The angle in radians.

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


def _real(name: str, **bounds):
    """An argparse type: a real number checked as the library checks it (same message)."""
    def parse(text: str) -> float:
        try:
            value = float(text)
        except ValueError:
            value = text  # check_real names the parameter and the range
        try:
            return check_real(name, value, **bounds)
        except INPUT_ERRORS as exc:
            raise argparse.ArgumentTypeError(str(exc)) from None

    return parse


def _integer(name: str, low: int | None = None, high: int | None = None):
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


_positive_int = _integer("the value", low=1)


def _check_out_file(path: str, command: str) -> None:
    """Refuse, before any work, an output file that cannot be written."""
    check_writable(path, name="out")


class _Parser(argparse.ArgumentParser):
    """argparse that reports usage errors as one line (exit status 2) and returns from
    ``--help`` instead of exiting the interpreter."""

    def error(self, message: str):  # noqa: D401 - argparse API
        raise CLIError(f"{self.prog}: error: {message}")

    def exit(self, status=0, message=None):  # noqa: D401 - argparse API
        if message:
            sys.stderr.write(message)
        raise _Exit(status)


# ---------------------------------------------------------------------------- derive
def _add_derive(sub) -> None:
    p = sub.add_parser("derive", help="derive the equations of motion with sympy and check "
                       "every printed equation of the paper against the derivation")
    p.add_argument("--sections", choices=["all", "2"], default="all",
                   help="'2': eqs. (1)-(13), (37), (38), (49) only (fast); 'all' (default) "
                   "adds sections 3-4, eqs. (15)-(59) and the quoted numbers")
    p.add_argument("--json", action="store_true", help="print the table as JSON")
    p.set_defaults(handler=_run_derive)


def _run_derive(args) -> int:
    from rollingdisk.symbolic import check_equations, format_table

    rows = check_equations(progress=not args.json, sections=args.sections)
    if args.json:
        import json

        print(json.dumps([row.as_dict() for row in rows], indent=2, allow_nan=False))
    else:
        print(format_table(rows))
    return 0


# ---------------------------------------------------------------------------- steady motions
_H = _real("h", low=0.0, high=H_MAX)  # the half-thickness, as Disk checks it


def _add_motion_args(p, *, h_default: float | None = None, coulomb: bool = False):
    """The arguments that name a steady motion (shared by steady, simulate, animate).

    Returns the mutually exclusive group of the free parameter, for commands that add an
    alternative to it (``simulate --state``).  ``coulomb``: ``--ground coulomb`` is allowed
    (the steady motion is then the rough-ground one, started rolling).
    """
    if coulomb:
        p.add_argument("--ground", choices=("rough", "smooth", "coulomb"), default="rough",
                       help="rough (no slip, default), smooth (no friction) or coulomb "
                       "(friction --mu: rolling while it holds, sliding when it cannot)")
    else:
        p.add_argument("--ground", choices=("rough", "smooth"), default="rough",
                       help="rough (no slip, default) or smooth (no friction)")
    if h_default is None:
        p.add_argument("--h", type=_H, required=True, help="half-thickness / radius, h >= 0")
    else:
        p.add_argument("--h", type=_H, default=h_default,
                       help=f"half-thickness / radius, h >= 0 (default {h_default:g})")
    p.add_argument("--theta0", type=parse_angle,
                   help="steady inclination (radians, or e.g. 30deg; negative: --theta0=-30deg)")
    p.add_argument("--motion", choices=("circle", "straight"), default=None,
                   help="circle (spin in place included) or straight; default from the options")
    g = p.add_mutually_exclusive_group()
    g.add_argument("--Omega0", type=_real("Omega0"),
                   help="spin rate d psi/dt of a steady circle")
    g.add_argument("--rC", type=_real("r_C"), help="signed radius of the circle of the centre C")
    g.add_argument("--rP", type=_real("r_P"),
                   help="signed radius of the circle of the contact point")
    g.add_argument("--omega0", type=_real("omega0"),
                   help="rolling rate d phi/dt of a straight line")
    return g


def _motion_from_args(args, command: str):
    """The steady motion the arguments of :func:`_add_motion_args` ask for (section 3)."""
    from rollingdisk.model.disk import Disk
    from rollingdisk.theory.steady import steady_motion, straight_line

    disk = Disk(h=args.h)
    ground = "rough" if args.ground == "coulomb" else args.ground
    straight = args.motion == "straight" or (args.motion is None and args.omega0 is not None)
    if straight:
        if args.omega0 is None:
            raise CLIError(f"rollingdisk {command}: error: --motion straight needs --omega0")
        return straight_line(disk, ground, args.omega0, theta0=args.theta0)
    if args.omega0 is not None:
        raise CLIError(f"rollingdisk {command}: error: --omega0 is for --motion straight; "
                       "circles take --Omega0, --rC or --rP")
    if args.theta0 is None:
        raise CLIError(f"rollingdisk {command}: error: give --theta0 (e.g. 30deg) with one of "
                       "--Omega0, --rC, --rP, or --motion straight --omega0 W")
    if args.Omega0 is None and args.rC is None and args.rP is None:
        raise CLIError(f"rollingdisk {command}: error: give one of --Omega0, --rC, --rP "
                       "(or --motion straight --omega0 W)")
    return steady_motion(disk, ground, args.theta0, Omega0=args.Omega0, r_C=args.rC,
                         r_P=args.rP)


# ---------------------------------------------------------------------------- steady
def _add_steady(sub) -> None:
    """``rollingdisk steady``: one steady motion and its stability (sections 3, 4)."""
    p = sub.add_parser(
        "steady", help="a steady motion (straight line, circle, spin) and its stability",
        description="Steady motion of the disk (paper sections 3-4): give --theta0 and one of "
        "--Omega0, --rC, --rP for a circle, or --motion straight --omega0 W. Angles in "
        "radians or with a deg suffix; write negative angles as --theta0=-30deg.")
    _add_motion_args(p)
    p.add_argument("--json", action="store_true", help="print one JSON object")
    p.set_defaults(handler=_run_steady)


def _steady_record(motion, stab) -> dict:
    return {**motion.as_dict(), "theta0_deg": math.degrees(motion.theta0), **stab.as_dict()}


def _run_steady(args) -> int:
    from rollingdisk.theory.oscillations import stability

    motion = _motion_from_args(args, "steady")
    rec = _steady_record(motion, stability(motion))
    if args.json:
        import json

        print(json.dumps(rec, allow_nan=False))
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
    p.add_argument("--h", type=_H, required=True, help="half-thickness / radius, h >= 0")
    p.add_argument("--json", action="store_true", help="print one JSON object")
    p.set_defaults(handler=_run_thresholds)


def _run_thresholds(args) -> int:
    from rollingdisk.theory.oscillations import thresholds

    d = thresholds(args.h).as_dict()
    if args.json:
        import json

        print(json.dumps(d, allow_nan=False))
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
    """``rollingdisk simulate``: integrate from a (perturbed) steady motion or any state."""
    p = sub.add_parser(
        "simulate", help="simulate the disk from a perturbed steady motion or any state",
        description="Integrate the equations of motion (eqs. 1-13, 37, 38 / 49) with guard "
        "events: lift-off (F_z = 0), edge contact (theta = 0 with h > 0), falling flat. "
        "Start from a steady motion (--theta0 with one of --Omega0, --rC, --rP, or "
        "--motion straight --omega0 W), optionally perturbed (--perturb adds to theta), "
        "or from any state (--state theta=0.3,omega2=1.5,omega3=0.7; unnamed components "
        "are 0). Write negative angles as --theta0=-30deg. On --ground coulomb (friction "
        "--mu) the disk rolls while friction holds and slides when it cannot; a steady "
        "motion is the rough-ground one, started rolling.")
    g = _add_motion_args(p, coulomb=True)
    g.add_argument("--state", type=str, metavar="NAME=VALUE,...",
                   help="an arbitrary initial state by component names (X_C, Y_C, [V_X, "
                   "V_Y,] psi, theta, phi, omega1, omega2, omega3; angles may have a deg "
                   "suffix); unnamed components are 0, except on coulomb ground without "
                   "V_X, V_Y: then the velocity of C is the rolling one (eq. 37)")
    c = p.add_argument_group("coulomb ground (issue 10, docs/friction.md)")
    c.add_argument("--mu", type=_real("mu_s", low=0.0), default=None,
                   help="static friction coefficient mu_s >= 0 (needed for --ground coulomb)")
    c.add_argument("--mu-k", dest="mu_k", type=_real("mu_k", low=0.0), default=None,
                   help="kinetic coefficient, 0 <= mu_k <= mu_s (default mu_s)")
    c.add_argument("--rolling-resistance", dest="rolling_resistance",
                   type=_real("rolling_resistance", low=0.0), default=None,
                   help="rolling-resistance length c: |M_h| = c F_z")
    c.add_argument("--pivot", type=_real("pivot", low=0.0), default=None,
                   help="pivoting (drilling) friction length c: |M_z| = c F_z")
    c.add_argument("--air", type=_real("air", low=0.0), default=None,
                   help="air-film drag coefficient (Moffatt's model)")
    p.add_argument("--perturb", type=float, default=0.0, help="added to theta(0) (default 0)")
    p.add_argument("--kick", type=float, default=0.0,
                   help="added to omega1(0) = d theta/dt (default 0)")
    p.add_argument("--t-end", dest="t_end", type=float, required=True,
                   help="end time (units sqrt(a/g))")
    p.add_argument("--rtol", type=float, default=None, help="relative tolerance")
    p.add_argument("--atol", type=float, default=None, help="absolute tolerance")
    p.add_argument("--method", choices=("dop853", "taylor", "scipy"), default="dop853",
                   help="rollingdisk's DOP853 (default; compiled once a run is long enough "
                   "to be worth it), its Taylor-series method (compiled on first use; "
                   "fastest at tight tolerances) or scipy's DOP853")
    p.add_argument("--error-control", dest="error_control", choices=("full", "reduced"),
                   default="full", help="tolerances on the whole state (default) or on "
                   "(theta, omega1, omega2, omega3) only, the quadratures X_C, Y_C, psi, phi "
                   "riding along (fewer steps for the same energy drift)")
    p.add_argument("--max-steps", dest="max_steps", type=_positive_int, default=2_000_000,
                   help="step budget: stop with status step-budget after this many steps "
                   "(default 2000000, about 20 s)")
    p.add_argument("--out", type=str, default=None, metavar="FILE.csv",
                   help="write the trajectory as CSV (t, X_C, Y_C, psi, theta, phi, omega1, "
                   "omega2, omega3, X_P, Y_P, F_x, F_y, F_z, E; smooth and coulomb ground "
                   "add V_X, V_Y; coulomb ground adds mode: 0 rolling, 1 sliding)")
    p.add_argument("--json", action="store_true", help="print one JSON object")
    p.set_defaults(handler=_run_simulate)


def _parse_state(text: str, ground: str) -> list[float]:
    from rollingdisk.model.state import state_names

    names = state_names(ground)
    values = dict.fromkeys(names, 0.0)
    seen = set()
    for item in filter(None, (part.strip() for part in text.split(","))):
        key, sep, val = item.partition("=")
        key = key.strip()
        if not sep or key not in values:
            raise CLIError(f"rollingdisk simulate: --state takes NAME=VALUE pairs with NAME in "
                           f"{', '.join(names)} on {ground} ground, got {item!r}")
        if key in seen:
            raise CLIError(f"rollingdisk simulate: --state gives {key} twice")
        seen.add(key)
        try:
            values[key] = parse_angle(val)
        except argparse.ArgumentTypeError:
            raise CLIError(f"rollingdisk simulate: --state {key}: not a number: {val!r}") \
                from None
    if "theta" not in seen:
        raise CLIError("rollingdisk simulate: --state must give theta (e.g. theta=0.3)")
    return [values[n] for n in names]


def _simulate_motion(args):
    """The steady motion asked for, or None with --state."""
    if args.state is None:
        return _motion_from_args(args, "simulate")
    if args.theta0 is not None or args.motion is not None:
        raise CLIError("rollingdisk simulate: --state gives the whole initial state; "
                       "leave out --theta0 and --motion")
    return None


class _ProgressBar:
    """A plain text bar on stderr, shown only once a run has taken more than a second."""

    def __init__(self, stream, delay: float = 1.0, width: int = 40):
        import time

        self.stream, self.delay, self.width = stream, delay, width
        self.clock = time.monotonic
        self.start = self.clock()
        self.shown = False

    def __call__(self, fraction: float) -> None:
        if not self.shown and self.clock() - self.start < self.delay:
            return
        self.shown = True
        n = int(round(self.width * min(max(fraction, 0.0), 1.0)))
        self.stream.write(f"\rsimulating [{'#' * n}{'.' * (self.width - n)}] "
                          f"{100 * fraction:5.1f}%")
        self.stream.flush()

    def close(self) -> None:
        if self.shown:
            self.stream.write("\n")
            self.stream.flush()


class _RunSummary:
    """A ``sink`` for simulate(): streams the CSV (if a file is open), keeps running
    measures (energy drift, theta range) over the whole run and the first ``keep`` points
    for the frequency and growth measurements, so that memory stays flat."""

    def __init__(self, disk, ground, csv=None, keep: int = 200_000):
        self.disk, self.ground, self.csv, self.keep = disk, ground, csv, keep
        self.t, self.y = [], []
        self.n_kept = 0
        self.E0 = None
        self.dE = 0.0
        self.theta_min, self.theta_max = math.inf, -math.inf
        self.header = True

    def __call__(self, t, y) -> None:
        import numpy as np

        from rollingdisk.integrate.trajectory import Trajectory

        part = Trajectory(disk=self.disk, ground=self.ground, t=t, y=y, status="completed",
                          message="", n_steps=0, n_rhs=0)
        E = part.E
        if self.E0 is None:
            self.E0 = float(E[0])
        self.dE = max(self.dE, float(np.max(np.abs(E - self.E0))))
        self.theta_min = min(self.theta_min, float(np.min(part.theta)))
        self.theta_max = max(self.theta_max, float(np.max(part.theta)))
        if self.n_kept < self.keep:
            k = min(len(t), self.keep - self.n_kept)
            self.t.append(np.array(t[:k]))
            self.y.append(np.array(y[:, :k]))
            self.n_kept += k
        if self.csv is not None:
            cols = part.as_columns()
            np.savetxt(self.csv, np.column_stack(list(cols.values())), delimiter=",",
                       header=",".join(cols) if self.header else "", comments="",
                       fmt="%.17g")
            self.header = False

    def kept(self, traj):
        """``traj`` with the points kept (the whole run if it fitted)."""
        import dataclasses

        import numpy as np

        return dataclasses.replace(traj, t=np.concatenate(self.t),
                                   y=np.concatenate(self.y, axis=1))

    def energy_drift(self) -> float:
        return self.dE / max(abs(self.E0), 2.2250738585072014e-308)


def _finite_or_none(value):
    if isinstance(value, float) and not math.isfinite(value):
        return None
    return value


def _run_simulate(args) -> int:
    import contextlib
    import json

    from rollingdisk.integrate.measure import compare_with_theory, oscillation_frequency
    from rollingdisk.integrate.simulation import (
        DEFAULT_ATOL,
        DEFAULT_RTOL,
        simulate,
        simulate_steady,
    )
    from rollingdisk.model.disk import Disk
    from rollingdisk.theory.oscillations import stability
    from rollingdisk.util.files import atomic_file, check_writable

    disk = Disk(h=args.h)
    coulomb = _coulomb_ground(args)
    motion = _simulate_motion(args)
    if args.out is not None:
        _check_out_file(args.out, "simulate")
        check_writable(args.out, name="--out")
    if not (math.isfinite(args.t_end) and args.t_end > 0):
        raise ParameterError(f"t_end must be a finite number > 0, got {args.t_end!r}")
    if coulomb is not None:
        return _run_simulate_coulomb(args, disk, coulomb, motion)
    options = dict(rtol=DEFAULT_RTOL if args.rtol is None else args.rtol,
                   atol=DEFAULT_ATOL if args.atol is None else args.atol, method=args.method,
                   max_steps=args.max_steps, error_control=args.error_control)
    if motion is None:
        y0 = _parse_state(args.state, args.ground)
        from rollingdisk.model.state import state_index

        y0[state_index(args.ground, "theta")] += args.perturb
        y0[state_index(args.ground, "omega1")] += args.kick
    bar = None if args.json else _ProgressBar(sys.stderr)
    if bar is not None:
        options["progress"] = bar
    csv_cm = (atomic_file(args.out, "w", newline="") if args.out is not None
              else contextlib.nullcontext())
    try:
        with csv_cm as csv:
            summary = _RunSummary(disk, args.ground, csv)
            options["sink"] = summary
            if motion is not None:
                traj = simulate_steady(motion, args.t_end, perturb=args.perturb,
                                       kick=args.kick, **options)
            else:
                traj = simulate(disk, args.ground, (0.0, args.t_end), y0, **options)
    finally:
        if bar is not None:
            bar.close()
    kept = summary.kept(traj)
    stab = None if motion is None else stability(motion)
    varpi2 = None if stab is None else stab.varpi2
    theory = None if stab is None else compare_with_theory(kept, stab)
    record = {
        "status": traj.status,
        "message": traj.message,
        "ground": traj.ground,
        "h": disk.h,
        "t_end": float(traj.t[-1]),
        "n_steps": traj.n_steps,
        "n_rhs": traj.n_rhs,
        "energy_drift": summary.energy_drift(),
        "theta_min": summary.theta_min,
        "theta_max": summary.theta_max,
        "theta_frequency": oscillation_frequency(kept),
        "varpi": None if stab is None else stab.as_dict()["varpi"],
        "varpi2": varpi2,
        "growth_rate": theory.measured if theory is not None and theory.kind == "growth"
        else None,
        "wall_time_s": traj.wall_time,
        "method": traj.method,
    }
    record = {k: _finite_or_none(v) for k, v in record.items()}
    if args.out is not None:
        record["out"] = args.out
    if args.json:
        print(json.dumps(record, indent=2, allow_nan=False))
    else:
        print(traj.message)
        for key in ("t_end", "n_steps", "energy_drift", "theta_min", "theta_max",
                    "theta_frequency", "varpi", "growth_rate", "wall_time_s"):
            val = record[key]
            if val is None:
                continue
            print(f"  {key:16s} {val:.10g}" if isinstance(val, float) else
                  f"  {key:16s} {val}")
        if args.out is not None:
            print(f"  wrote {args.out}")
    return 0


def _coulomb_ground(args):
    """The :class:`~rollingdisk.friction.ground.Coulomb` ground the options ask for, or None."""
    extra = [f"--{n.replace('_', '-')}" for n in ("mu", "mu_k", "rolling_resistance", "pivot",
                                                 "air") if getattr(args, n) is not None]
    if args.ground != "coulomb":
        if extra:
            raise CLIError(f"rollingdisk simulate: {', '.join(extra)} need --ground coulomb")
        return None
    if args.mu is None:
        raise CLIError("rollingdisk simulate: --ground coulomb needs --mu (static friction "
                       "coefficient, e.g. --mu 0.3)")
    if args.method != "dop853" or args.error_control != "full":
        raise CLIError("rollingdisk simulate: --method and --error-control are for rough and "
                       "smooth ground; coulomb ground has its own hybrid integrator")
    from rollingdisk.friction.ground import Coulomb

    return Coulomb(args.mu, args.mu_k, rolling_resistance=args.rolling_resistance,
                   pivot=args.pivot, air=args.air)


def _coulomb_initial_state(args, disk, motion):
    from rollingdisk.friction.coulomb import rolling_state
    from rollingdisk.model.state import state_index

    if motion is not None:
        y = list(rolling_state(disk, motion.initial_state()))
    else:
        y = _parse_state(args.state, "smooth")
        named = {item.partition("=")[0].strip() for item in args.state.split(",")}
        if not {"V_X", "V_Y"} & named:  # the rolling velocity of C (eq. 37)
            rough = [y[0], y[1], y[4], y[5], y[6], y[7], y[8], y[9]]
            y = list(rolling_state(disk, rough))
    y[state_index("smooth", "theta")] += args.perturb
    y[state_index("smooth", "omega1")] += args.kick
    return y


def _run_simulate_coulomb(args, disk, ground, motion) -> int:
    """``simulate --ground coulomb``: the hybrid rolling/sliding run (issue 10)."""
    import json

    from rollingdisk.friction.hybrid import energy_balance, simulate_coulomb
    from rollingdisk.util.files import atomic_file

    y0 = _coulomb_initial_state(args, disk, motion)
    options = dict(max_steps=args.max_steps)
    if args.rtol is not None:
        options["rtol"] = args.rtol
    if args.atol is not None:
        options["atol"] = args.atol
    bar = None if args.json else _ProgressBar(sys.stderr)
    try:
        traj = simulate_coulomb(disk, ground, (0.0, args.t_end), y0, progress=bar, **options)
    finally:
        if bar is not None:
            bar.close()
    from rollingdisk.friction.coulomb import MODE_NAMES

    record = {
        "status": traj.status,
        "message": traj.message,
        "ground": "coulomb",
        **{k: v for k, v in ground.as_dict().items() if k != "ground"},
        "h": disk.h,
        "t_end": float(traj.t[-1]),
        "n_steps": traj.n_steps,
        "mode_end": MODE_NAMES[int(traj.mode[-1])],
        "transitions": [x.as_dict() for x in traj.transitions],
        "energy_balance": energy_balance(traj),
        "dissipated": {k: float(v[-1]) for k, v in traj.dissipated.items()},
        "theta_min": float(min(traj.theta)),
        "theta_max": float(max(traj.theta)),
        "wall_time_s": traj.wall_time,
        "method": traj.method,
    }
    record = {k: _finite_or_none(v) for k, v in record.items()}
    if args.out is not None:  # written last: a failure above leaves no file
        import numpy as np

        cols = traj.as_columns()
        with atomic_file(args.out, "w", newline="") as csv:
            np.savetxt(csv, np.column_stack(list(cols.values())), delimiter=",",
                       header=",".join(cols), comments="", fmt="%.17g")
        record["out"] = args.out
    if args.json:
        print(json.dumps(record, indent=2, allow_nan=False))
        return 0
    print(traj.message)
    for key in ("t_end", "n_steps", "mode_end", "energy_balance", "theta_min", "theta_max",
                "wall_time_s"):
        val = record[key]
        if val is not None:
            print(f"  {key:16s} {val:.10g}" if isinstance(val, float) else
                  f"  {key:16s} {val}")
    for x in record["transitions"][:20]:
        print(f"  t = {x['t']:.10g}: {x['from']} -> {x['to']}")
    if len(record["transitions"]) > 20:
        print(f"  ... {len(record['transitions']) - 20} more transitions")
    if args.out is not None:
        print(f"  wrote {args.out}")
    return 0


# ---------------------------------------------------------------------------- exact
def _add_exact(sub) -> None:
    """``rollingdisk exact``: the exact motion by quadrature (issue 11)."""
    p = sub.add_parser(
        "exact", help="the exact motion by quadrature: turning points, period, delta psi",
        description="The exact (integrable) motion on rough or smooth ground by quadrature: "
        "status (bounded, steady, lift-off, edge-contact, fell-flat), theta_min, theta_max, "
        "the nutation period and the precession delta_psi per period. Start from a steady "
        "motion (--theta0 with one of --Omega0, --rC, --rP, or --motion straight --omega0 "
        "W) with --kick / --perturb, or from any state (--state theta=0.3,omega3=2).")
    g = _add_motion_args(p)
    g.add_argument("--state", type=str, metavar="NAME=VALUE,...",
                   help="an arbitrary initial state by component names, as for simulate")
    p.add_argument("--perturb", type=_real("perturb"), default=0.0,
                   help="added to theta(0) (default 0)")
    p.add_argument("--kick", type=_real("kick"), default=0.0,
                   help="added to omega1(0) = d theta/dt (default 0)")
    p.add_argument("--periods", type=_integer("periods", 1, 1000), default=20,
                   help="periods of the rosette in --out (default 20)")
    p.add_argument("--out", type=str, default=None, metavar="FILE.png",
                   help="a figure: theta(t) over a period, the contact point's rosette, and "
                   "the backbone curve (frequency against amplitude) about the steady motion")
    p.add_argument("--json", action="store_true", help="print one JSON object")
    p.set_defaults(handler=_run_exact)


def _run_exact(args) -> int:
    import json

    from rollingdisk.model.disk import Disk
    from rollingdisk.theory import exact as exact
    from rollingdisk.theory.oscillations import stability

    disk = Disk(h=args.h)
    if args.state is None:
        motion = _motion_from_args(args, "exact")
    elif args.theta0 is not None or args.motion is not None:
        raise CLIError("rollingdisk exact: --state gives the whole initial state; "
                       "leave out --theta0 and --motion")
    else:
        motion = None
    if args.out is not None:
        from rollingdisk.plotting.plots import image_format
        from rollingdisk.util.files import check_writable

        image_format(args.out, "--out")
        check_writable(args.out, name="--out")
    if motion is not None:
        ex = exact.exact_steady(motion, perturb=args.perturb, kick=args.kick)
    else:
        from rollingdisk.model.state import state_index

        y0 = _parse_state(args.state, args.ground)
        y0[state_index(args.ground, "theta")] += args.perturb
        y0[state_index(args.ground, "omega1")] += args.kick
        ex = exact.exact_motion(disk, args.ground, y0)
    record = ex.as_dict()
    stab = None if motion is None else stability(motion)
    record["varpi"] = None if stab is None or not stab.stable else stab.varpi
    record["varpi2"] = None if stab is None else stab.varpi2
    record = {k: v if k == "drift" or not isinstance(v, float) else _finite_or_none(v)
              for k, v in record.items()}
    if args.out is not None:
        _exact_figure(ex, motion, args)
        record["out"] = args.out
    if args.json:
        print(json.dumps(record, indent=2, allow_nan=False))
        return 0
    print(f"status       {ex.status}")
    for key in ("theta_min", "theta_max", "amplitude", "period", "frequency", "varpi",
                "delta_psi", "delta_phi", "t_end", "theta_end", "E"):
        if record.get(key) is not None:
            print(f"{key:<12} {record[key]:>18.12g}")
    if record["drift"] is not None:
        print(f"{'drift':<12} {record['drift'][0]:>18.12g} {record['drift'][1]:.12g}"
              "   contact point's displacement over the first period (X, Y)")
    if ex.message:
        print(f"{'message':<12} {ex.message}")
    if args.out is not None:
        print(f"wrote {args.out}")
    return 0


def _exact_figure(ex, motion, args) -> None:
    import numpy as np
    from matplotlib.figure import Figure

    from rollingdisk.plotting.plots import plot_exact, save_figure
    from rollingdisk.theory import exact as exact
    from rollingdisk.theory.oscillations import stability

    if ex.status != "bounded":
        raise ParameterError(f"--out: the motion is {ex.status}; the figure (theta over a "
                             "period, rosette) needs a bounded motion")
    bb = None
    if motion is not None and stability(motion).varpi2 > 0:
        top = max(abs(args.kick), 1e-3) * 1.5
        kicks = np.linspace(top / 40, top, 24)
        bb = exact.backbone(motion, kicks)
    fig = Figure(figsize=(12.6 if bb is not None else 8.4, 4.0))
    plot_exact(ex, fig, backbone=bb, n_periods=args.periods,
               title=f"exact motion, {ex.ground} ground, h = {ex.disk.h:.4g}")
    save_figure(fig, args.out, dpi=110)


# ---------------------------------------------------------------------------- figures, maps
def _add_figures(sub) -> None:
    """``figures``, ``map``, ``animate``, ``atlas``: the pictures (edges over the core)."""
    from rollingdisk.plotting.animation import FPS_RANGE, FRAMES_RANGE
    from rollingdisk.plotting.figures import FIGURES, SCALE_MAX
    from rollingdisk.plotting.plots import DPI_RANGE, IMAGE_FORMATS

    def dpi_arg(p, default):
        p.add_argument("--dpi", type=_integer("dpi", *DPI_RANGE), default=default,
                       help=f"resolution, dots per inch in [{DPI_RANGE[0]}, {DPI_RANGE[1]}] "
                       f"(default {default})")

    p = sub.add_parser("figures", help="recompute the paper's Figures 4-8 as PNG files")
    p.add_argument("--out", required=True,
                   help="output folder (its parent must exist; replaced as a whole, so it "
                   "must be new, empty or written by this command)")
    p.add_argument("--scale", type=_real("scale", low=0.0, high=SCALE_MAX, low_open=True),
                   default=1.0, help=f"grid resolution factor in (0, {SCALE_MAX:g}] "
                   "(default 1; 0.2 for a quick look)")
    dpi_arg(p, 110)
    p.add_argument("--only", nargs="+", metavar="FIG", choices=tuple(FIGURES),
                   help=f"a subset of {' '.join(FIGURES)}")
    p.set_defaults(handler=_run_figures)

    p = sub.add_parser("map", help="existence / stability map or varpi^2 = 0 surface")
    p.add_argument("--ground", required=True, choices=("rough", "smooth"))
    p.add_argument("--h", type=_H, default=DEFAULT_H,
                   help=f"half-thickness (default {DEFAULT_H:g}; not used by --kind surface, "
                   "which spans h)")
    p.add_argument("--kind", required=True,
                   choices=("existence", "stability", "surface", "all-omega30", "nonlinear",
                            "basin"),
                   help="existence: (theta0, r_C) plane; stability: (theta0, omega30) "
                   "plane; surface: varpi^2 = 0 in (theta0, h, omega30); all-omega30: "
                   "(theta0, h) region stable for every omega30; nonlinear: simulated "
                   "stability of kicked steady circles in (theta0, omega30), T = 100 "
                   "(a 40 x 40 sweep); basin: the largest kick that stays bounded there "
                   "(8 bisection rounds)")
    p.add_argument("--out", required=True,
                   help=f"image file ({', '.join('.' + f for f in IMAGE_FORMATS)})")
    dpi_arg(p, 110)
    p.set_defaults(handler=_run_map)

    p = sub.add_parser("animate", help="simulate a steady motion from a small tilt "
                       "perturbation and write a 3D animation (.gif, or .mp4 with ffmpeg)")
    _add_motion_args(p, h_default=DEFAULT_H)
    p.add_argument("--perturb", type=_real("perturb"), default=0.0, help="added to theta(0)")
    p.add_argument("--kick", type=_real("kick"), default=0.01,
                   help="added to omega1(0) = dtheta/dt (default 0.01)")
    p.add_argument("--t-end", dest="t_end", default=20.0,
                   type=_real("t_end", low=0.0, high=ANIMATE_T_END_MAX, low_open=True),
                   help=f"simulated time in (0, {ANIMATE_T_END_MAX:g}] (default 20)")
    p.add_argument("--frames", type=_integer("frames", *FRAMES_RANGE), default=60,
                   help=f"number of frames in [{FRAMES_RANGE[0]}, {FRAMES_RANGE[1]}] "
                   "(default 60)")
    p.add_argument("--fps", type=_integer("fps", *FPS_RANGE), default=15,
                   help=f"frames per second in [{FPS_RANGE[0]}, {FPS_RANGE[1]}] (default 15)")
    dpi_arg(p, 70)
    p.add_argument("--out", required=True, help="motion.gif (or .mp4 when ffmpeg exists)")
    p.set_defaults(handler=_run_animate)

    p = sub.add_parser("atlas", help="the atlas of one disk: thresholds, maps, two simulated "
                       "steady motions with animations, index.html")
    p.add_argument("--h", type=_H, default=DEFAULT_H,
                   help=f"half-thickness (default {DEFAULT_H:g}, close to a commercial "
                   "Euler's disk)")
    p.add_argument("--out", default="atlas",
                   help="output folder (default ./atlas; replaced as a whole, so it must be "
                   "new, empty or an earlier atlas)")
    p.add_argument("--quick", action="store_true", help="coarse grids, short simulations")
    p.add_argument("--quiet", action="store_true", help="no progress lines on stderr")
    p.set_defaults(handler=_run_atlas)


def _agg() -> None:
    import matplotlib

    matplotlib.use("Agg")


def _run_figures(args) -> int:
    _agg()
    from rollingdisk.plotting.figures import paper_figures

    paths = paper_figures(args.out, scale=args.scale, dpi=args.dpi, only=args.only,
                          progress=lambda msg: print(msg, file=sys.stderr, flush=True))
    for path in paths:
        print(path)
    return 0


def _run_map(args) -> int:
    from rollingdisk.plotting.plots import image_format

    image_format(args.out)  # before any work
    check_writable(args.out, name="out")
    _agg()
    from rollingdisk.plotting import plots as plotting

    if args.kind == "existence":
        m = plotting.plot_existence_map(args.h, args.ground)
    elif args.kind == "stability":
        m = plotting.plot_stability_map(args.h, args.ground)
    elif args.kind == "surface":
        m = plotting.plot_varpi2_surface(args.ground)
    elif args.kind in ("nonlinear", "basin"):
        m = _sweep_map(args, plotting)
    else:
        m = plotting.plot_all_omega30_stable(args.ground, mark_h=args.h)
    fig = m["ax"].figure if isinstance(m, dict) else m.ax.figure
    fig.tight_layout()
    plotting.save_figure(fig, args.out, dpi=args.dpi)
    print(args.out)
    return 0


def _sweep_map(args, plotting) -> dict:
    """The nonlinear (or basin) map of ``rollingdisk map``: a 40 x 40 sweep of kicked
    steady circles over theta0 in (0.05, 1.5) rad and omega30 in (0.1, 3), T = 100."""
    import numpy as np

    from rollingdisk.sweep.runner import Perturbation, SweepGrid, basin_sweep, run_sweep

    grid = SweepGrid(args.ground, h=args.h, theta0=np.linspace(0.05, 1.5, 40),
                     omega30=np.linspace(0.1, 3.0, 40))
    bar = _SweepMapBar("trajectories" if args.kind == "nonlinear" else "bisection rounds")
    try:
        if args.kind == "nonlinear":
            ds = run_sweep(grid, 100.0, perturbation=Perturbation(kick=1e-3), progress=bar)
            return plotting.plot_nonlinear_map(ds)
        ds = basin_sweep(grid, 100.0, kick_max=0.5, rounds=8, progress=bar)
        return plotting.plot_basin_map(ds)
    finally:
        bar.close()


class _SweepMapBar:
    """One progress line on stderr for the sweep behind a map (``done/total what``)."""

    def __init__(self, what: str):
        self.what = what

    def __call__(self, done, total=None, *rest):
        total = f"/{total}" if total else ""
        print(f"\rmap: {done}{total} {self.what}", end="", file=sys.stderr, flush=True)

    def close(self):
        print(file=sys.stderr, flush=True)


def _run_animate(args) -> int:
    from rollingdisk.plotting.animation import check_animation, writer_for

    # everything that can be refused, before the simulation
    check_animation(args.frames, args.fps, args.dpi)
    writer_for(args.out, args.fps)
    check_writable(args.out, name="out")
    motion = _motion_from_args(args, "animate")
    _agg()
    import numpy as np

    from rollingdisk.integrate.simulation import simulate_steady
    from rollingdisk.plotting.animation import animate
    from rollingdisk.theory.oscillations import stability

    stab = stability(motion)
    traj = simulate_steady(motion, args.t_end, perturb=args.perturb, kick=args.kick,
                           t_eval=np.linspace(0.0, args.t_end, 1200))
    verdict = (f"stable, varpi^2 = {stab.varpi2:.4g}" if stab.stable
               else f"unstable, varpi^2 = {stab.varpi2:.4g}")
    print(f"{args.ground} ground, h = {args.h:g}, theta0 = {motion.theta0:.4g}, "
          f"Omega0 = {motion.Omega0:.4g}: {verdict}; simulation {traj.status}", file=sys.stderr)
    out = animate(traj, args.out, n_frames=args.frames, fps=args.fps, dpi=args.dpi)
    print(out)
    return 0


def _run_atlas(args) -> int:
    _agg()
    from rollingdisk.atlas.build import build_atlas

    result = build_atlas(args.h, args.out, quick=args.quick, progress=not args.quiet)
    print(result.index)
    return 0


# ---------------------------------------------------------------------------- sweep
def _sweep_range(text: str) -> list[float]:
    """``A:B:N`` (N >= 1 points from A to B, angles may carry a deg suffix) or one value."""
    import numpy as np

    parts = str(text).split(":")
    try:
        if len(parts) == 1:
            return [parse_angle(parts[0])]
        if len(parts) == 3:
            a, b, n = parse_angle(parts[0]), parse_angle(parts[1]), int(parts[2])
            if n >= 1:
                return [float(x) for x in np.linspace(a, b, n)]
    except (argparse.ArgumentTypeError, ValueError):
        pass
    raise argparse.ArgumentTypeError(f"expected a value or A:B:N with N >= 1, got {text!r}")


def _add_sweep(sub) -> None:
    """``rollingdisk sweep``: perturbed steady motions over a grid (issue 12)."""
    p = sub.add_parser(
        "sweep", help="integrate perturbed steady motions over a parameter grid",
        description="Integrate a perturbed steady motion from every point of a grid: "
        "circles theta0 x (omega30 | rC | Omega0) (x h), or straight lines h x omega0 (at "
        "the tilt arctan(h)), and store per-trajectory summaries next to the closed-form "
        "varpi^2 (docs/sweeps.md). Ranges as A:B:N.")
    p.add_argument("--ground", choices=("rough", "smooth"), required=True)
    p.add_argument("--h", type=_sweep_range, default=[0.17], help="H or A:B:N")
    p.add_argument("--theta0", type=_sweep_range, default=None,
                   help="A:B:N (radians or deg); required for circles, not with --omega0")
    g = p.add_mutually_exclusive_group(required=True)
    g.add_argument("--omega30", type=_sweep_range)
    g.add_argument("--rC", type=_sweep_range)
    g.add_argument("--Omega0", type=_sweep_range)
    g.add_argument("--omega0", type=_sweep_range,
                   help="straight lines rolling at omega20 = omega0 (A:B:N)")
    p.add_argument("--t-end", type=float, required=True, dest="t_end")
    p.add_argument("--kick", type=float, default=None, help="kick in omega1 (default 1e-3)")
    p.add_argument("--perturb", type=float, default=None, help="tilt added to theta0")
    p.add_argument("--basin", action="store_true",
                   help="largest bounded kick by bisection (--kick is the upper end)")
    p.add_argument("--rounds", type=_positive_int, default=10, help="bisection rounds")
    x = p.add_mutually_exclusive_group()
    x.add_argument("--workers", type=_positive_int, default=None, help="local cores")
    x.add_argument("--dask", default=None, metavar="ADDRESS|local")
    p.add_argument("--chunk", type=_positive_int, default=2048)
    p.add_argument("--method", choices=("taylor", "dop853"), default="taylor",
                   help="integrator (default taylor: the batch Taylor kernel)")
    p.add_argument("--out", required=True, help="FILE.zarr or FILE.nc")
    p.add_argument("--json", action="store_true", help="print one JSON object")
    p.set_defaults(handler=_run_sweep)


def _run_sweep(args) -> int:
    import json
    import time

    import numpy as np

    from rollingdisk.sweep.runner import Perturbation, SweepGrid, basin_sweep, run_sweep

    second = {k: getattr(args, k) for k in ("omega30", "Omega0", "omega0")}
    second["r_C"] = args.rC
    if args.omega0 is not None and args.theta0 is not None:
        raise CLIError("rollingdisk sweep: error: --omega0 (straight lines) fixes theta0 = "
                       "arctan(h); drop --theta0")
    if args.omega0 is None and args.theta0 is None:
        raise CLIError("rollingdisk sweep: error: --theta0 A:B:N is required with --omega30, "
                       "--rC or --Omega0")
    grid = SweepGrid(args.ground, h=args.h, theta0=args.theta0 or (), **second)
    start = time.perf_counter()
    last = [0.0]

    def bar(done, total, rate, eta):
        now = time.perf_counter()
        if now - last[0] < 0.5 and done < total:
            return
        last[0] = now
        print(f"\rsweep: {done}/{total} ({rate:.0f}/s, ETA {eta:.0f} s)   ", end="",
              file=sys.stderr, flush=True)

    executor = "dask" if args.dask else ("threads" if args.workers != 1 else "serial")
    if args.basin:
        if args.perturb is not None:
            raise CLIError("rollingdisk sweep: error: --basin bisects the kick; drop --perturb")
        ds = basin_sweep(grid, args.t_end, kick_max=args.kick or 1.0, rounds=args.rounds,
                         out=args.out, executor="serial" if executor == "serial" else
                         "threads", workers=args.workers, chunk=args.chunk,
                         method=args.method)
        n = int(ds.kick_basin.size) * (args.rounds + 1)
    else:
        kick = args.kick if args.kick is not None else (0.0 if args.perturb else 1e-3)
        pert = Perturbation(kick=kick, tilt=args.perturb or 0.0)
        ds = run_sweep(grid, args.t_end, perturbation=pert, out=args.out, executor=executor,
                       workers=args.workers,
                       dask_address=None if args.dask in (None, "local") else args.dask,
                       chunk=args.chunk, method=args.method, progress=bar)
        n = int(ds.varpi2.size)
        print("", file=sys.stderr)
    wall = time.perf_counter() - start
    m = np.abs(ds.varpi2.values) > 0.05
    agree = (float(np.mean(ds.stable_simulated.values[m] == ds.stable.values[m]))
             if not args.basin and m.any() else None)
    rec = {"n": n, "wall_time_s": wall, "trajectories_per_s": n / wall if wall > 0 else None,
           "agreement": agree, "out": args.out}
    if args.json:
        print(json.dumps(rec, allow_nan=False))
    else:
        print(f"{n} trajectories in {wall:.1f} s ({rec['trajectories_per_s']:.0f}/s); "
              f"agreement {agree}; {args.out}")
    return 0


# ---------------------------------------------------------------------------- main
# ---------------------------------------------------------------------------- euler-disk
#: Files ``rollingdisk euler-disk --out DIR`` writes (DIR is replaced as a whole).
EULER_DISK_FILES = ("euler_disk.png", "euler_disk.csv", "euler_disk.json")


def _add_euler_disk(sub) -> None:
    """``rollingdisk euler-disk``: the built-in Euler's disk run to its end (issue 10)."""
    from rollingdisk.friction.euler_disk import AIR_VISCOSITY, EulerDisk

    toy = EulerDisk()
    p = sub.add_parser(
        "euler-disk", help="Euler's disk: the toy spun up and run to its end",
        description="The commercial Euler's disk (radius 37.5 mm, thickness 12.7 mm, "
        "0.45 kg) started on its spin-in-place steady motion and run with creep friction "
        "and rolling resistance (and, with --air, Moffatt's air film) until it falls flat, "
        "lifts off or comes to rest; exponents near the end fitted and predicted "
        "(docs/friction.md).")
    p.add_argument("--out", default=None, metavar="DIR",
                   help="folder for " + ", ".join(EULER_DISK_FILES) + " (new, empty, or "
                   "written by this command before: it is replaced as a whole)")
    p.add_argument("--json", action="store_true", help="print the summary as JSON")
    p.add_argument("--air", action="store_true",
                   help=f"Moffatt's air film, air viscosity {AIR_VISCOSITY:g} Pa s")
    p.add_argument("--quiet", action="store_true", help="no progress bar on stderr")
    p.add_argument("--mu", type=_real("mu", low=0.0), default=toy.mu,
                   help=f"friction coefficient at saturation (default {toy.mu:g})")
    p.add_argument("--creep", type=_real("creep", low=0.0, low_open=True),
                   default=toy.creep, help=f"creep coefficient k (default {toy.creep:g})")
    p.add_argument("--rolling-resistance", dest="rolling_resistance",
                   type=_real("rolling_resistance", low=0.0), default=toy.rolling_resistance,
                   help=f"rolling-resistance length / a (default {toy.rolling_resistance:g})")
    p.add_argument("--alpha0", type=_real("alpha0", low=0.0, high=math.pi / 2, low_open=True,
                                          high_open=True),
                   default=toy.alpha0, help=f"initial tilt in rad (default {toy.alpha0:g})")
    p.add_argument("--max-steps", dest="max_steps", type=_positive_int, default=2_000_000,
                   help="step budget (default 2000000)")
    p.add_argument("--max-wall-time", dest="max_wall_time",
                   type=_real("max_wall_time", low=0.0, low_open=True), default=120.0,
                   help="wall-clock budget in seconds (default 120)")
    p.set_defaults(handler=_run_euler_disk)


def _run_euler_disk(args) -> int:
    import json

    from rollingdisk.friction.euler_disk import AIR_VISCOSITY, EulerDisk, run_euler_disk

    toy = EulerDisk(mu=args.mu, creep=args.creep, rolling_resistance=args.rolling_resistance,
                    alpha0=args.alpha0, air_viscosity=AIR_VISCOSITY if args.air else None)
    if args.out is not None:
        from rollingdisk.util.files import check_replaceable

        check_replaceable(args.out, EULER_DISK_FILES, name="--out")  # before the work
    bar = None if args.quiet else _ProgressBar(sys.stderr)
    try:
        result = run_euler_disk(toy, max_steps=args.max_steps,
                                max_wall_time=args.max_wall_time, progress=bar)
    finally:
        if bar is not None:
            bar.close()
    summary = result.summary()
    if args.out is not None:
        _write_euler_disk(result, summary, args.out)
        summary["out"] = args.out
    if args.json:
        print(json.dumps(summary, indent=2, allow_nan=False))
        return 0
    print(result.message)
    unit = result.toy.time_unit
    print(f"  end time       {result.t_end_s:.4g} s  (t = {result.t_end:.6g} sqrt(a/g); "
          f"adiabatic decay along the steady family: {result.predicted_t_end * unit:.4g} s)")
    print(f"  fitted t0      {result.t0_s:.4g} s  (alpha -> 0 of the power law; "
          f"adiabatic: {result.predicted_t0 * unit:.4g} s)")
    print(f"  exponents      fitted vs predicted, alpha in {result.fit_window}")
    for name in result.exponents:
        print(f"    {name:14s} {result.exponents[name]:+.4f}   {result.predicted[name]:+.4f}")
    print(f"  energy balance {result.energy_balance:.2g}")
    print(f"  steps          {result.n_steps}")
    print(f"  wall time      {result.wall_time:.2f} s")
    if args.out is not None:
        print(f"  wrote {args.out}")
    return 0


def _write_euler_disk(result, summary, out) -> None:
    """PNG, CSV and JSON into ``out``, which appears whole or not at all."""
    import json

    import numpy as np

    from rollingdisk.util.files import atomic_dir

    _agg()
    from matplotlib.figure import Figure  # no pyplot: the user's backend is left alone

    from rollingdisk.plotting.plots import plot_euler_disk

    with atomic_dir(out) as tmp:
        fig = Figure(figsize=(10.0, 4.2))
        plot_euler_disk(result, fig, title="Euler's disk: " + result.message)
        fig.savefig(tmp / EULER_DISK_FILES[0], dpi=90)
        cols = result.as_columns()
        with open(tmp / EULER_DISK_FILES[1], "w", newline="") as fh:
            np.savetxt(fh, np.column_stack(list(cols.values())), delimiter=",",
                       header=",".join(cols), comments="", fmt="%.12g")
        with open(tmp / EULER_DISK_FILES[2], "w") as fh:
            json.dump(summary, fh, indent=2, allow_nan=False)


def build_parser() -> argparse.ArgumentParser:
    """The parser of the ``rollingdisk`` command line (one subparser per subcommand).

    Returns
    -------
    argparse.ArgumentParser
    """
    parser = _Parser(prog="rollingdisk", description=__doc__.splitlines()[0])
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", parser_class=_Parser)
    for add in (_add_derive, _add_steady, _add_thresholds, _add_simulate, _add_exact,
                _add_figures, _add_sweep, _add_euler_disk):
        add(sub)
    return parser


def _say(line: str) -> None:
    """One line on stderr (a message with line breaks is joined)."""
    print(" ".join(str(line).split("\n")), file=sys.stderr, flush=True)


def _prog(args) -> str:
    command = getattr(args, "command", None)
    return f"rollingdisk {command}" if command else "rollingdisk"


#: errno values that mean the user's destination is full or read-only, whatever the file.
_DESTINATION_ERRNOS = {"ENOSPC", "EDQUOT", "EFBIG", "EROFS"}


def _on_user_path(exc: OSError, args) -> bool:
    """Whether ``exc`` concerns the output the user named (``--out``): its folder, the
    file or folder itself, or the temporary files written beside it."""
    import errno

    out = getattr(args, "out", None)
    if out is None:
        return False
    if errno.errorcode.get(exc.errno) in _DESTINATION_ERRNOS:
        return True
    target = os.path.abspath(out)
    folder = os.path.dirname(target)
    for name in (exc.filename, exc.filename2):
        if name is None:
            continue
        try:
            path = os.path.abspath(os.fspath(name))
            if os.path.commonpath([path, folder]) == folder:
                return True
        except (TypeError, ValueError):
            continue
    return False


def _bug(args) -> int:
    import traceback

    traceback.print_exc()
    _say(f"{_prog(args)}: internal error: this is a bug in rollingdisk, not a problem with "
         "your input; please report it with the traceback above")
    return 1


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
    parser = build_parser()
    args = None
    try:
        with terminate_as_exception():
            try:
                args = parser.parse_args(argv)
            except _Exit as done:  # --help
                return done.status
            if not getattr(args, "handler", None):
                parser.print_help(sys.stderr)
                return 2
            status = int(args.handler(args) or 0)
            check_signals()  # a Ctrl-C whose exception Python swallowed still counts
            return status
    except KeyboardInterrupt:
        return _stopped(True)
    except Terminated:
        return _stopped(False)
    except Exception as exc:
        if pending_signal() is not None:  # the error came after Ctrl-C / SIGTERM: report that
            return _stopped(pending_signal() == signal.SIGINT)
        return _error_status(exc, args)


def _stopped(interrupted: bool) -> int:
    """One line and exit status 130 (Ctrl-C) or 143 (SIGTERM)."""
    _say("rollingdisk: interrupted" if interrupted else "rollingdisk: terminated")
    if interrupted:
        # A KeyboardInterrupt that passed through an exec() of a string on its way here
        # (libraries build code that way) leaves CPython's _Py_UnhandledKeyboardInterrupt
        # set, and the interpreter would then exit by SIGINT (status -2) instead of 130.
        # Each exec() of a string clears that flag first (pythonrun.c, run_eval_code_obj).
        exec("pass")  # a constant string
    return 130 if interrupted else 143


def _error_status(exc: Exception, args) -> int:
    """The one line and exit status of an exception that ended a command (called in its
    ``except`` clause, so that a bug's traceback is the exception's own)."""
    if isinstance(exc, CLIError):
        _say(str(exc))
        return 2
    if isinstance(exc, INPUT_ERRORS):
        _say(f"{_prog(args)}: error: {exc}")
        return 2
    if isinstance(exc, OSError) and _on_user_path(exc, args):
        where = f"{exc.filename}: " if exc.filename else ""
        _say(f"{_prog(args)}: error: {where}{exc.strerror or exc}")
        return 2
    # an exception raised while cleaning up after Ctrl-C / SIGTERM: still an interruption
    context = exc.__context__
    while context is not None:
        if isinstance(context, (KeyboardInterrupt, Terminated)):
            return _stopped(isinstance(context, KeyboardInterrupt))
        context = context.__context__
    return _bug(args)

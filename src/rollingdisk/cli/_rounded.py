"""``--rim-radius`` on ``rollingdisk steady`` and ``rollingdisk simulate``: the disk with a
rounded rim (theory/rounded.py's steady motions, ivp/rounded.py's simulation).

    $ rollingdisk steady --h 0.2 --rim-radius 0.1 --theta0 0.4 --Omega0 2
    $ rollingdisk steady --disk euro-1 --rim-radius 0.3mm --theta0 30deg --Omega0 30rad/s
    $ rollingdisk simulate --h 0.2 --rim-radius 0.1 --theta0 0.4 --Omega0 2 --kick 0.01 \\
          --t-end 100
    $ rollingdisk simulate --h 0.2 --rim-radius 0.2 --state omega1=0.2,omega2=1.07,theta=0 \\
          --t-end 1000
"""

from __future__ import annotations

import json
import math

from rollingdisk.cli._args import initial_state, quantity
from rollingdisk.cli._format import disk_line, has_scale, si_text, with_si
from rollingdisk.util.errors import ParameterError

#: The rows of ``steady --rim-radius``: (field, kind of quantity or None, what it is).
STEADY_ROWS = (
    ("ground", None, "ground"), ("h", None, "half-thickness / radius"),
    ("rim_radius", "length", "rim radius rho / radius"),
    ("theta0", None, "inclination [rad]"), ("theta0_deg", None, "inclination [deg]"),
    ("Omega0", "angular_speed", "spin rate d psi/dt"),
    ("omega0", "angular_speed", "rolling rate d phi/dt"),
    ("omega20", "angular_speed", "angular velocity, omega2"),
    ("omega30", "angular_speed", "angular velocity, omega3"),
    ("r_C", "length", "radius of the circle of C"),
    ("r_P", "length", "radius of the circle of P"),
    ("varpi2", None, "varpi^2 of small oscillations [g/a]"),
    ("stable", None, "stable (varpi^2 > 0)"), ("period", "time", "period 2 pi / varpi"),
    ("growth_rate", "rate", "growth rate sqrt(-varpi^2)"),
)
_SI_UNITS = {"length": "m", "angular_speed": "rad/s", "time": "s", "rate": "1/s"}


def add_rim_radius(p) -> None:
    """``--rim-radius LENGTH`` (as ``rollingdisk thresholds`` has it)."""
    p.add_argument("--rim-radius", dest="rim_radius",
                   type=quantity("rim_radius", "length", "--rim-radius", low=0.0),
                   default=None, metavar="LENGTH",
                   help="radius rho of the rounded rim, 0 <= rho <= min(h, 1) a: a length with "
                   "a unit for a disk with a physical size (0.3mm), else in units of the "
                   "radius a; the rounded disk's steady motions (theory/rounded.py) and "
                   "simulation (ivp/rounded.py, docs/rounded.md)")


def rounded_disk(disk, rho):
    """The disk with its rim rounded to ``rho`` (units of a): the check and message of
    ``rollingdisk thresholds --rim-radius``."""
    from rollingdisk.cli.thresholds import _rounded

    return _rounded(disk, rho)


def rounded_motion(args, disk, command: str):
    """The rounded disk's steady circle the motion options ask for, or None with
    ``--state``; :class:`ParameterError` naming the option where the rounded theory has no
    such motion set up."""
    from rollingdisk.model.rim import rim_contact
    from rollingdisk.theory.rounded import rounded_steady_motion

    if getattr(args, "state", None) is not None:
        if args.theta0 is not None or args.motion is not None:
            raise ParameterError(f"rollingdisk {command}: --state gives the whole initial "
                                 "state; leave out --theta0 and --motion")
        return None
    if args.motion == "straight" or args.omega0 is not None:
        raise ParameterError("--rim-radius takes a steady circle (--theta0 with --Omega0, "
                             "--omega30, --rC or --rP) or --state; not --motion straight / "
                             "--omega0")
    if args.theta0 is None or all(getattr(args, k) is None
                                  for k in ("Omega0", "omega30", "rC", "rP")):
        raise ParameterError(f"rollingdisk {command}: give --theta0 (e.g. 30deg) with one of "
                             "--Omega0, --omega30, --rC, --rP (or --state)")
    Omega0, r_C = args.Omega0, args.rC
    if args.omega30 is not None:
        Omega0 = args.omega30 / math.cos(args.theta0)
    if args.rP is not None:  # r_P = r_C + y_P
        r_C = args.rP - float(rim_contact(disk.h, disk.rim_radius, args.theta0)[3])
    if r_C is not None and args.ground != "rough":
        raise ParameterError("--rC and --rP set a circle on rough ground (on smooth ground "
                             "r_C = 0): give --Omega0 or --omega30")
    return rounded_steady_motion(disk, args.ground, args.theta0, Omega0=Omega0, r_C=r_C)


def _steady_record(motion) -> dict:
    varpi2 = motion.varpi2
    return {"ground": motion.ground, "h": motion.disk.h, "rim_radius": motion.disk.rim_radius,
            "theta0": motion.theta0, "theta0_deg": math.degrees(motion.theta0),
            "Omega0": motion.Omega0, "omega0": motion.omega0, "omega20": motion.omega20,
            "omega30": motion.omega30, "r_C": motion.r_C, "r_P": motion.r_P,
            "varpi2": varpi2, "stable": motion.stable,
            "period": 2 * math.pi / math.sqrt(varpi2) if varpi2 > 0 else None,
            "growth_rate": math.sqrt(-varpi2) if varpi2 < 0 else None}


def _si(disk, kind, value):
    convert = {"length": disk.length_to_si, "angular_speed": disk.angular_speed_to_si,
               "time": disk.time_to_si, "rate": disk.angular_speed_to_si}  # rate: 1/time
    return float(convert[kind](value))


def run_steady(args, disk) -> int:
    """``rollingdisk steady --rim-radius``: the rounded disk's steady circle and its
    ``varpi^2`` (closed forms of theory/rounded.py), text or JSON; SI beside for a disk
    with a physical size."""
    disk = rounded_disk(disk, args.rim_radius)
    rec = _steady_record(rounded_motion(args, disk, "steady"))
    si = has_scale(disk)
    if si:
        view = {f"{k}_si": _si(disk, kind, rec[k]) for k, kind, _ in STEADY_ROWS
                if kind is not None and rec[k] is not None}
        view["units"] = {f"{k}_si": _SI_UNITS[kind] for k, kind, _ in STEADY_ROWS
                         if f"{k}_si" in view}
        rec = with_si(rec, view)
    if args.json:
        print(json.dumps(rec, allow_nan=False))
        return 0
    if si:
        print(disk_line(disk))
    print(f"rounded rim: rho = {disk.rim_radius:.6g} a (theory/rounded.py)")
    for key, _, text in STEADY_ROWS:
        v = rec[key]
        if v is None:
            continue
        val = f"{v:.10g}" if isinstance(v, float) else str(v)
        extra = rec.get(f"{key}_si")
        extra = "" if extra is None else si_text(extra, rec["units"][f"{key}_si"])
        print(f"{key:<12} {val:>18}   {extra:>20}   {text}" if si
              else f"{key:<12} {val:>18}   {text}")
    print("(dimensionless: m = a = g = 1, time unit sqrt(a/g)"
          + ("; SI in the third column)" if si else ")"))
    return 0


def run_simulate(args, disk) -> dict:
    """``rollingdisk simulate --rim-radius``: run the rounded disk (ivp/rounded.py) from a
    perturbed steady circle or ``--state`` and summarize it (the keys of the rough and
    smooth grounds' summary); ``--out`` writes its CSV."""
    import numpy as np

    from rollingdisk.ivp.rounded import rounded_frequency as frequency
    from rollingdisk.ivp.rounded import simulate_rounded, simulate_rounded_steady
    from rollingdisk.ivp.simulation import DEFAULT_ATOL, DEFAULT_RTOL
    from rollingdisk.results.stream import write_columns
    from rollingdisk.util.files import atomic_file

    if args.ground == "coulomb":
        raise ParameterError("--rim-radius runs on rough or smooth ground (--ground rough, "
                             "smooth); the rounded rim on Coulomb ground is not modelled")
    for name in ("until_rest", "animate"):
        if getattr(args, name, None):
            raise ParameterError(f"--{name.replace('_', '-')} is not available with "
                                 "--rim-radius (the rounded disk's run ends at its events)")
    if args.method not in ("auto", "dop853") or args.error_control != "full":
        raise ParameterError("--rim-radius runs the engine's DOP853 on the full state: leave "
                             "out --method and --error-control")
    disk = rounded_disk(disk, args.rim_radius)
    motion = rounded_motion(args, disk, "simulate")
    options = dict(rtol=DEFAULT_RTOL if args.rtol is None else args.rtol,
                   atol=DEFAULT_ATOL if args.atol is None else args.atol,
                   max_steps=2_000_000 if args.max_steps is None else args.max_steps)
    if motion is None:
        y0, _ = initial_state(args, args.ground, "simulate")
        traj = simulate_rounded(disk, args.ground, (0.0, args.t_end), y0, **options)
    else:
        if math.isfinite(motion.varpi2) and motion.varpi2 != 0.0:
            options["max_step"] = 0.05 / math.sqrt(abs(motion.varpi2))  # ~20 points/radian
        traj = simulate_rounded_steady(motion, args.t_end, perturb=args.perturb,
                                       kick=args.kick, **options)
    if args.out is not None:
        si = has_scale(disk)
        with atomic_file(args.out, "w", newline="") as fh:
            write_columns(fh, traj.as_columns(si=si),
                          units=traj.csv_header(si=True) if si else None)
    E = traj.E
    varpi2 = None if motion is None else motion.varpi2
    return {
        "status": traj.status, "message": traj.message, "ground": traj.ground, "h": disk.h,
        "rim_radius": disk.rim_radius, "t_end": float(traj.t[-1]), "n_steps": traj.n_steps,
        "n_rhs": traj.n_rhs,
        "energy_drift": float(np.max(np.abs(E - E[0])) / max(abs(E[0]), 1e-300)),
        "theta_min": float(traj.theta.min()), "theta_max": float(traj.theta.max()),
        "theta_frequency": frequency(traj), "varpi2": varpi2,
        "varpi": math.sqrt(varpi2) if varpi2 is not None and varpi2 > 0 else None,
        "growth_rate": None, "wall_time_s": traj.wall_time, "method": traj.method,
    }

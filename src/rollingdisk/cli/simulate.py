"""``rollingdisk simulate``: integrate the equations of motion from a (perturbed) steady
motion or any state, on rough, smooth or Coulomb ground.

    $ rollingdisk simulate --h 0.17 --theta0 30deg --Omega0 2 --kick 0.01 --t-end 100
    $ rollingdisk simulate --h 0.1 --state theta=0.3,omega2=1.5,omega3=0.7 --t-end 50 \\
          --out run.csv --json
    $ rollingdisk simulate --ground coulomb --mu 0.3 --h 0.1 --theta0 0.3 --Omega0 2 \\
          --t-end 20
    $ rollingdisk simulate --disk euro-1 --theta0 30deg --Omega0 30rad/s --t-end 2s --out c.csv
    $ rollingdisk simulate --h 0.2 --rim-radius 0.1 --theta0 0.4 --Omega0 2 --kick 0.01
"""

from __future__ import annotations

import contextlib
import json
import math

from rollingdisk.cli._args import (
    SIMULATE_T_END_MAX,
    add_json_arg,
    add_motion_args,
    add_perturbation_args,
    add_progress_args,
    add_state_arg,
    add_tolerance_args,
    alias,
    disk_from_args,
    initial_state,
    length_coefficient,
    positive_int,
    quantity,
    real,
    start_from_args,
    t_end_arg,
)
from rollingdisk.cli._coulomb import coulomb_ground, run_coulomb, run_until_rest
from rollingdisk.cli._format import (
    disk_fields,
    disk_line,
    finite_or_none,
    has_scale,
    numeric_warnings,
    print_record,
    progress_bar,
    with_si,
)
from rollingdisk.cli._rounded import add_rim_radius, run_simulate

#: The kind of quantity of each field of the summary (keys of rollingdisk.model.units.KINDS).
KINDS = {"h": "dimensionless", "t_end": "time", "energy_drift": "dimensionless",
         "theta_min": "angle", "theta_max": "angle", "theta_frequency": "angular_speed",
         "varpi": "angular_speed", "varpi2": "rate_sq", "growth_rate": "rate",
         "energy_balance": "dimensionless", "mu_s": "dimensionless",
         "mu_k": "dimensionless", "rolling_resistance": "length", "pivot": "length",
         "rim_radius": "length"}


def configure(sub):
    p = sub.add_parser(
        "simulate",
        description="Integrate the equations of motion (eqs. 1-13, 37, 38 / 49) with guard "
        "events: lift-off (F_z = 0), edge contact (theta = 0 with h > 0), falling flat. "
        "Start from a steady motion (--theta0 with one of --Omega0, --rC, --rP, or "
        "--motion straight --omega0 W), optionally perturbed (--perturb adds to theta), "
        "or from any state (--state theta=0.3,omega2=1.5,omega3=0.7; unnamed components "
        "are 0). Write negative angles as --theta0=-30deg. On --ground coulomb (friction "
        "--mu) the disk rolls while friction holds and slides when it cannot; a steady "
        "motion is the rough-ground one, started rolling.")
    g = add_motion_args(p, coulomb=True)
    add_state_arg(g, "an arbitrary initial state by component names (X_C, Y_C, [V_X, V_Y,] "
                  "psi, theta, phi, omega1, omega2, omega3; angles may have a deg suffix); "
                  "unnamed components are 0, except on coulomb ground without V_X, V_Y: "
                  "then the velocity of C is the rolling one (eq. 37)")
    c = p.add_argument_group("coulomb ground (docs/friction.md)")
    c.add_argument("--mu", type=real("mu_s", low=0.0), default=None,
                   help="static friction coefficient mu_s >= 0, dimensionless (needed for "
                   "--ground coulomb)")
    c.add_argument("--mu-k", dest="mu_k", type=real("mu_k", low=0.0), default=None,
                   help="kinetic coefficient, dimensionless, 0 <= mu_k <= mu_s (default mu_s)")
    c.add_argument("--rolling-resistance", dest="rolling_resistance",
                   type=length_coefficient("rolling_resistance"), default=None, metavar="C",
                   help="rolling-resistance length c >= 0: |M_h| = c F_z; in units of the "
                   "radius a, or a length with a unit (20um) for a disk with a physical size")
    c.add_argument("--pivot", type=length_coefficient("pivot"), default=None, metavar="C",
                   help="pivoting (drilling) friction length c >= 0: |M_z| = c F_z; in units "
                   "of a, or a length with a unit for a disk with a physical size")
    c.add_argument("--air", type=quantity("air", "moment_per_rate", low=0.0), default=None,
                   metavar="C",
                   help="air-film drag coefficient c >= 0 (the squeeze film under the disk: a "
                   "moment per angular speed, units m a^(3/2) g^(1/2); c = K mu_air a^(3/2) / "
                   "(m g^(1/2)) with K = 1.28113 derived, about 1.2e-7 for Euler's disk in "
                   "air; with a physical disk and a mass in kg*m^2/s)")
    c.add_argument("--until-rest", dest="until_rest", action="store_true",
                   help="go on past lift-off, edge contact and falling flat: flight, impacts "
                   "(restitution --restitution, friction --mu-k), rim changes and the flat "
                   "disk sliding, until the disk is at rest or --t-end (docs/motion.md); "
                   "JSON lists every phase change and impact and the energy balance")
    c.add_argument("--animate", default=None, metavar="FILE.gif",
                   help="with --until-rest: a 3D animation of the whole motion (flight, "
                   "bounces, rolling, the flat disk) to FILE.gif")
    c.add_argument("--restitution", type=real("restitution", low=0.0, high=1.0), default=None,
                   help="coefficient of restitution of the impacts, in [0, 1] (default 0.5); "
                   "only with --until-rest")
    add_rim_radius(p)
    add_perturbation_args(p)
    t_end_arg(p, high=SIMULATE_T_END_MAX)
    add_tolerance_args(p)
    p.add_argument("--method", choices=("auto", "dop853", "taylor", "scipy"), default="auto",
                   help="auto (default: the fastest method this process has for the "
                   "tolerance, see docs/simulation.md), rollingdisk's DOP853 (compiled once "
                   "the process has run uncompiled for long enough), its Taylor-series method "
                   "(compiled on first use; fastest at tight tolerances) or scipy's DOP853")
    p.add_argument("--error-control", dest="error_control", choices=("full", "reduced"),
                   default="full", help="tolerances on the whole state (default) or on "
                   "(theta, omega1, omega2, omega3) only, the quadratures X_C, Y_C, psi, phi "
                   "riding along (fewer steps for the same energy drift)")
    p.add_argument("--max-steps", dest="max_steps", type=positive_int, default=None,
                   help="step budget: stop with status step-budget after this many steps "
                   "(default 2000000 on the ideal grounds; 200000 on coulomb ground, whose "
                   "steps cost more)")
    p.add_argument("--max-wall-time", dest="max_wall_time",
                   type=real("max_wall_time", low=0.0, high=86400.0, low_open=True),
                   default=60.0, help="coulomb ground: wall-clock budget in seconds (default "
                   "60); a run that spends it stops with status time-budget and says so")
    alias(p, "--max-wall", "--max-wall-time", dest="max_wall_time",
          type=real("max_wall_time", low=0.0, high=86400.0, low_open=True))
    p.add_argument("--out", type=str, default=None, metavar="FILE.csv",
                   help="write the trajectory as CSV; with --until-rest the whole motion in "
                   "one layout for every phase (t, phase, X_C, Y_C, Z_C, psi, theta, phi, V_X, "
                   "V_Y, V_Z, omega1, omega2, omega3, E); else (t, X_C, Y_C, psi, theta, phi, "
                   "omega1, "
                   "omega2, omega3, X_P, Y_P, F_x, F_y, F_z, E; smooth and coulomb ground "
                   "add V_X, V_Y; coulomb ground adds mode: 0 rolling, 1 sliding, 2 and 3 the same "
                   "with the pivot stuck, 4-7 the first four with the rolling resistance "
                   "stuck); the "
                   "first line names the columns; in the paper's units, or for a disk with "
                   "a physical size in SI units (forces and energies only with --mass) with "
                   "a second line '# t [s],X_C [m],...' naming each column's unit")
    add_json_arg(p)
    add_progress_args(p)
    return p


#: Most points a run from a steady motion samples for its measured frequency.
SAMPLES_MAX = 1_000_000


def run(args) -> int:
    from rollingdisk.util.files import check_writable

    disk = disk_from_args(args)
    rounded = args.rim_radius is not None  # the rounded rim: ivp/rounded.py
    coulomb = None if rounded else coulomb_ground(args, disk)
    motion = None if rounded else start_from_args(args, "simulate")
    if args.out is not None:
        check_writable(args.out, name="--out")
    with numeric_warnings() as caught:  # said in the result, not printed
        if rounded:
            record, transitions = run_simulate(args, disk), []
            keys = ("t_end", "n_steps", "rim_radius", "energy_drift", "theta_min",
                    "theta_max", "theta_frequency", "varpi", "wall_time_s")
        elif coulomb is not None and args.until_rest:
            record, transitions = run_until_rest(args, disk, coulomb, motion)
            keys = ("t_end", "n_impacts", "energy_balance", "impact_loss",
                    "dissipated_total", "wall_time_s")
        elif coulomb is not None:
            record, transitions = run_coulomb(args, disk, coulomb, motion)
            keys = ("t_end", "n_steps", "mode_end", "energy_balance", "theta_min",
                    "theta_max", "wall_time_s")
        else:
            record, transitions = _run_ideal(args, disk, motion), []
            keys = ("t_end", "n_steps", "energy_drift", "theta_min", "theta_max",
                    "theta_frequency", "varpi", "growth_rate", "wall_time_s")
    if caught.lines:
        record["warnings"] = caught.lines
    if has_scale(disk):
        record = _with_si(record, disk)
        transitions = record.get("transitions", transitions)
    if args.out is not None:
        record["out"] = args.out
    if args.json:
        print(json.dumps(record, indent=2, allow_nan=False))
        return 0
    print(record["message"])
    if has_scale(disk):
        print(f"  {disk_line(disk)}")
    print_record(record, keys)
    for line in record.get("warnings", ()):
        print(f"  warning          {line}")
    for x in transitions[:20]:
        when = f" ({x['t_si']:.6g} s)" if x.get("t_si") is not None else ""
        print(f"  t = {x['t']:.10g}{when}: {x['from']} -> {x['to']}")
    if len(transitions) > 20:
        print(f"  ... {len(transitions) - 20} more transitions")
    if args.out is not None:
        print(f"  wrote {args.out}")
    return 0


def _with_si(record: dict, disk) -> dict:
    """The summary with SI values beside its dimensional fields, the dissipated energies
    (with a mass) and the transition times, and a ``"units"`` map."""
    from rollingdisk.model.units import can_convert, si_view

    view = si_view(disk, {k: v for k, v in record.items() if k in KINDS}, KINDS)
    out = with_si(record, view, disk_fields(disk))
    if out.get("air") is not None:
        out["units"]["air"] = "m a^(3/2) g^(1/2)"
    if "dissipated" in record:
        out["units"]["dissipated"] = "m g a"
        if can_convert(disk, "energy"):
            out["dissipated_si"] = {k: float(disk.energy_to_si(v))
                                    for k, v in record["dissipated"].items()}
            out["units"]["dissipated_si"] = "J"
    if "transitions" in record:
        out["transitions"] = [{**x, "t_si": float(disk.time_to_si(x["t"]))}
                              for x in record["transitions"]]
    out["units"]["wall_time_s"] = "s"
    return out


def _run_ideal(args, disk, motion) -> dict:
    """Rough or smooth ground: stream the run (CSV, measurements) and summarize it."""
    import numpy as np

    import rollingdisk as rd
    from rollingdisk.ivp.simulation import DEFAULT_ATOL, DEFAULT_RTOL
    from rollingdisk.results.measure import compare_with_theory, oscillation_frequency
    from rollingdisk.results.stream import StreamSummary
    from rollingdisk.util.files import atomic_file

    options = dict(rtol=DEFAULT_RTOL if args.rtol is None else args.rtol,
                   atol=DEFAULT_ATOL if args.atol is None else args.atol, method=args.method,
                   max_steps=2_000_000 if args.max_steps is None else args.max_steps,
                   error_control=args.error_control)
    if motion is None:
        y0, _ = initial_state(args, args.ground, "simulate")
    else:
        # the measured frequency or growth rate wants ~20 points per 1/|varpi|
        # (rollingdisk.results.measure): sampled from the dense output, so that the
        # steps stay as long as the tolerance allows
        varpi2 = rd.stability(motion).varpi2
        if math.isfinite(varpi2) and varpi2 != 0.0:
            dt = 0.05 / math.sqrt(abs(varpi2))
            if args.t_end / dt <= SAMPLES_MAX:
                options["t_eval"] = np.append(np.arange(0.0, args.t_end, dt), args.t_end)
            else:  # too many samples to hold: bound the step instead (the step budget
                options["max_step"] = dt  # then ends the run with its own status)
    bar = progress_bar(args)
    csv_cm = (atomic_file(args.out, "w", newline="") if args.out is not None
              else contextlib.nullcontext())
    try:
        with csv_cm as csv:
            summary = StreamSummary(disk, args.ground, csv, si=has_scale(disk))
            options.update(sink=summary, progress=bar)
            if motion is not None:
                traj = rd.simulate_steady(motion, args.t_end, perturb=args.perturb,
                                          kick=args.kick, **options)
            else:
                traj = rd.simulate(disk, args.ground, (0.0, args.t_end), y0, **options)
    finally:
        bar.close()
    kept = summary.kept(traj)
    stab = None if motion is None else rd.stability(motion)
    theory = None if stab is None else compare_with_theory(kept, stab)
    record = {
        "status": traj.status, "message": traj.message, "ground": traj.ground, "h": disk.h,
        "t_end": float(traj.t[-1]), "n_steps": traj.n_steps, "n_rhs": traj.n_rhs,
        "energy_drift": summary.energy_drift(), "theta_min": summary.theta_min,
        "theta_max": summary.theta_max, "theta_frequency": oscillation_frequency(kept),
        "varpi": None if stab is None else stab.as_dict()["varpi"],
        "varpi2": None if stab is None else stab.varpi2,
        "growth_rate": theory.measured if theory is not None and theory.kind == "growth"
        else None,
        "wall_time_s": traj.wall_time, "method": traj.method,
    }
    return {k: finite_or_none(v) for k, v in record.items()}

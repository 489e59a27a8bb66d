"""``rollingdisk euler-disk``: the commercial Euler's disk spun up and run to its end, with
the exponents near the end fitted and predicted (docs/friction.md).

    $ rollingdisk euler-disk
    $ rollingdisk euler-disk --air --out euler --json
    $ rollingdisk euler-disk --friction coulomb     # set-valued friction, no creep constant
    $ rollingdisk euler-disk --air boundary-layer   # Bildsten's law instead of the film
    $ rollingdisk euler-disk --sound chirp.wav --sound-speed 4   # the whirr, 4x faster
    $ rollingdisk euler-disk --disk euro-1          # a 1-euro coin spun like the toy
    $ rollingdisk euler-disk --radius 5cm --thickness 1cm --mass 600g --rolling-resistance 20um
"""

from __future__ import annotations

import json
import math

from rollingdisk.cli._args import (
    DISK_OPTIONS,
    UNITS_RULE,
    add_disk_options,
    add_progress_args,
    disk_from_args,
    echo_inputs,
    length_coefficient,
    positive_int,
    quantity,
    real,
    resolve_inputs,
    show_progress,
)
from rollingdisk.cli._format import disk_line, numeric_warnings, with_si


def configure(sub):
    from rollingdisk.plotting.reports import EULER_DISK_FILES
    from rollingdisk.plotting.sound import MAX_SECONDS, RATE
    from rollingdisk.scenarios.euler_disk import (
        AIR_DENSITY,
        AIR_LAWS,
        AIR_VISCOSITY,
        FRICTION_LAWS,
        EulerDisk,
    )

    toy = EulerDisk()
    p = sub.add_parser(
        "euler-disk",
        description="Euler's disk, by default the commercial toy (radius 37.5 mm, thickness "
        "12.7 mm, 0.45 kg; or any disk with a physical size and mass: --disk NAME, or "
        "--radius/--diameter with --thickness and --mass), started on its spin-in-place "
        "steady motion and run with creep friction (or, with --friction coulomb, set-valued "
        "Coulomb friction) and rolling resistance (and, with --air, "
        "air drag: Moffatt's squeeze film or Bildsten's boundary layer) until it falls "
        "flat, lifts off or comes to rest; exponents near the end fitted and predicted "
        "(docs/friction.md); --sound writes its whirr as a WAV file.")
    g = add_disk_options(p, positional=True)
    g.description = ("Default: the commercial Euler's Disk (--mass and --gravity alone "
                     "change only those). Any other disk needs a physical size and a mass: "
                     "--disk NAME, or --radius/--diameter with --thickness (or --h) and "
                     "--mass. Every disk here has a physical size: " + UNITS_RULE)
    for action in g._group_actions:
        if action.dest == "h":
            action.help = ("half-thickness / radius (dimensionless), with --radius or "
                           "--diameter")
    p.add_argument("--out", default=None, metavar="DIR",
                   help="folder for " + ", ".join(EULER_DISK_FILES) + " (new, empty, or "
                   "written by this command before: it is replaced as a whole)")
    p.add_argument("--json", action="store_true", help="print the summary as JSON")
    p.add_argument("--air", nargs="?", const="film", default=None, choices=AIR_LAWS,
                   metavar="{" + ",".join(AIR_LAWS) + "}",
                   help=f"air drag, air viscosity {AIR_VISCOSITY:g} Pa s: Moffatt's squeeze "
                   "film (bare --air, or --air film; Phi ~ Omega^2/alpha) or Bildsten's "
                   f"boundary layer (--air boundary-layer, density {AIR_DENSITY:g} kg/m^3; "
                   "Phi ~ Omega^(5/2), valid above alpha ~ 5e-3 for the toy)")
    p.add_argument("--sound", default=None, metavar="WAV",
                   help="write the whirr as a WAV file (16-bit mono): a tone at the contact "
                   "point's precession frequency Omega/2pi along the run")
    p.add_argument("--sound-speed", dest="sound_speed",
                   type=real("sound_speed", low=0.0, low_open=True), default=1.0,
                   metavar="FACTOR",
                   help="time compression of --sound (1: real time; 4: four times faster, "
                   "the pitch kept) (default 1)")
    p.add_argument("--sound-seconds", dest="sound_seconds",
                   type=real("sound_seconds", low=0.0, low_open=True), default=MAX_SECONDS,
                   metavar="S",
                   help=f"longest sound in seconds: a longer run keeps its end (default "
                   f"{MAX_SECONDS:g}; sample rate {RATE} Hz)")
    add_progress_args(p)
    p.add_argument("--mu", type=real("mu", low=0.0), default=toy.mu,
                   help=f"friction coefficient at saturation, dimensionless (default "
                   f"{toy.mu:g})")
    p.add_argument("--friction", choices=FRICTION_LAWS, default="creep",
                   help="contact friction: 'creep' (default), the creep law with --creep, "
                   "integrated by LSODA (seconds); 'coulomb', set-valued Coulomb friction "
                   "with no constant to choose, rolling and sliding with located "
                   "transitions (compiled DOP853; air: the film only). Its micro-slip near "
                   "the end costs many steps: the toy falls flat after 7.5e7 steps, about "
                   "8 minutes (docs/friction.md)")
    p.add_argument("--creep", type=quantity("creep", "inverse_speed", low=0.0, low_open=True),
                   default=toy.creep, help="creep coefficient k > 0: tangential force "
                   "-k F_z u at small slip speed u, u in units sqrt(a g) (so k in units "
                   f"1/sqrt(a g), written 50a; or in s/m, 5s/m) (default {toy.creep:g}a)")
    p.add_argument("--rolling-resistance", dest="rolling_resistance",
                   type=length_coefficient("rolling_resistance"),
                   default=toy.rolling_resistance, metavar="C",
                   help="rolling-resistance length c >= 0 (|M_h| = c F_z): a length with a "
                   "unit (20um) or in units of the radius a with the suffix a (5e-4a) "
                   f"(default {toy.rolling_resistance:g}a, "
                   f"{toy.rolling_resistance * toy.radius * 1e6:.3g} um on the toy)")
    p.add_argument("--alpha0", type=real("alpha0", low=0.0, high=math.pi / 2, low_open=True,
                                         high_open=True),
                   default=toy.alpha0, help=f"initial tilt in rad (default {toy.alpha0:g})")
    p.add_argument("--max-steps", dest="max_steps", type=positive_int, default=None,
                   help="step budget (default 2000000 with creep friction, 300000000 with "
                   "coulomb)")
    p.add_argument("--max-wall-time", dest="max_wall_time",
                   type=real("max_wall_time", low=0.0, low_open=True), default=None,
                   help="wall-clock budget in seconds (default 120 with creep friction, "
                   "1800 with coulomb)")
    return p


def run(args) -> int:
    from rollingdisk.plotting.reports import EULER_DISK_FILES, write_euler_disk
    from rollingdisk.plotting.sound import chirp, write_wav
    from rollingdisk.scenarios.euler_disk import AIR_VISCOSITY, run_euler_disk
    from rollingdisk.util.files import check_replaceable, check_writable
    from rollingdisk.util.progress import ProgressBar

    toy = _toy(args, dict(mu=args.mu, creep=args.creep, alpha0=args.alpha0,
                          air_viscosity=AIR_VISCOSITY if args.air else None,
                          air_law=args.air or "film", friction=args.friction))
    coulomb = args.friction == "coulomb"
    max_steps = args.max_steps or (300_000_000 if coulomb else 2_000_000)
    max_wall_time = args.max_wall_time or (1800.0 if coulomb else 120.0)
    if args.out is not None:
        check_replaceable(args.out, EULER_DISK_FILES, name="--out")  # before the work
    if args.sound is not None:
        check_writable(args.sound, name="--sound")  # before the work
    bar = ProgressBar(quiet=not show_progress(args))
    try:
        with numeric_warnings() as caught:  # said in the result, not printed
            result = run_euler_disk(toy, max_steps=max_steps, max_wall_time=max_wall_time,
                                    progress=bar)
            summary = _with_si(result.summary(), result.toy.disk)
    finally:
        bar.close()
    if caught.lines:
        summary["warnings"] = caught.lines
    if args.out is not None:
        write_euler_disk(result, args.out)
        summary["out"] = args.out
    if args.sound is not None:
        write_wav(args.sound, chirp(result, speed=args.sound_speed,
                                    max_seconds=args.sound_seconds))
        summary["sound"] = args.sound
    if args.json:
        print(json.dumps(summary, indent=2, allow_nan=False))
        return 0
    with numeric_warnings():  # NaN fields print as nan
        _print(result)
    for line in caught.lines:
        print(f"  warning        {line}")
    if args.out is not None:
        print(f"  wrote {args.out}")
    if args.sound is not None:
        print(f"  wrote {args.sound}")
    return 0


def _with_si(summary: dict, disk) -> dict:
    """The summary with ``<name>_si`` fields (times in s, the final precession rate in
    rad/s, dissipated energies in J) and a ``"units"`` map of the fields with a unit."""
    from rollingdisk.model.units import si_view

    kinds = {"t_end": "time", "t0": "time", "alpha_end": "angle", "Omega_end": "angular_speed",
             "energy_balance": "dimensionless"}
    out = with_si(summary, si_view(disk, {k: summary[k] for k in kinds}, kinds))
    out["dissipated_si"] = {k: float(disk.energy_to_si(v))
                            for k, v in summary["dissipated"].items()}
    out["units"].update(dissipated="m g a", dissipated_si="J", t_end_s="s", t0_s="s",
                        predicted_t_end_s="s", predicted_t0_s="s", wall_time_s="s")
    return out


def _toy(args, parameters: dict):
    """The toy the options give: the commercial Euler's Disk unless a disk is named or
    sized (which must have a mass); ``--mass``/``--gravity`` alone change only those."""
    from rollingdisk.scenarios.euler_disk import EulerDisk
    from rollingdisk.util.errors import ParameterError

    sized = args.h is not None or any(getattr(args, k) is not None for k in DISK_OPTIONS
                                      if k not in ("mass", "gravity"))
    if not sized:
        base = EulerDisk()
        if args.mass is not None or args.gravity is not None:
            import rollingdisk as rd

            d = rd.disk_from_options(disk="euler-disk", mass=args.mass, gravity=args.gravity,
                                     option_prefix="--")
            base = EulerDisk(mass=d.mass, gravity=d.gravity)
        _resolve(args, base.disk, parameters)
        return EulerDisk(radius=base.radius, thickness=base.thickness, mass=base.mass,
                         gravity=base.gravity, rolling_resistance=args.rolling_resistance,
                         **parameters)
    disk = disk_from_args(args)
    if disk.radius is None or disk.mass is None:
        raise ParameterError("euler-disk needs a disk with a physical size and a mass: "
                             "--disk NAME, or --radius/--diameter with --thickness (or --h) "
                             "and --mass (without any, the commercial Euler's Disk)")
    _resolve(args, disk, parameters)
    return EulerDisk.from_disk(disk, rolling_resistance=args.rolling_resistance, **parameters)


def _resolve(args, disk, parameters: dict) -> None:
    """The dimensional options (--rolling-resistance, --creep) in the paper's units of the
    toy's disk, which always has a physical size (a plain number is refused)."""
    echo_inputs(args, resolve_inputs(args, disk))
    parameters["creep"] = args.creep


def _print(result) -> None:
    unit = result.toy.time_unit
    print(result.message)
    print(f"  {disk_line(result.toy.disk)}")
    print(f"  end time       {result.t_end_s:.4g} s  (t = {result.t_end:.6g} sqrt(a/g); "
          f"adiabatic decay along the steady family: {result.predicted_t_end * unit:.4g} s)")
    print(f"  fitted t0      {result.t0_s:.4g} s  (alpha -> 0 of the power law; "
          f"adiabatic: {result.predicted_t0 * unit:.4g} s)")
    print(f"  exponents      fitted vs predicted, alpha in {result.fit_window}")
    for name in result.exponents:
        print(f"    {name:14s} {result.exponents[name]:+.4f}   {result.predicted[name]:+.4f}")
    if "transitions" in result.extra:
        print(f"  transitions    {len(result.extra['transitions'])} (rolling <-> sliding)")
    print(f"  energy balance {result.energy_balance:.2g}")
    print(f"  steps          {result.n_steps}")
    print(f"  wall time      {result.wall_time:.2f} s")

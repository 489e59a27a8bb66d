"""``rollingdisk euler-disk``: the commercial Euler's disk spun up and run to its end, with
the exponents near the end fitted and predicted (docs/friction.md).

    $ rollingdisk euler-disk
    $ rollingdisk euler-disk --air --out euler --json
"""

from __future__ import annotations

import json
import math

from rollingdisk.cli._args import positive_int, real


def configure(sub):
    from rollingdisk.friction.euler_disk import AIR_VISCOSITY, EulerDisk
    from rollingdisk.plotting.reports import EULER_DISK_FILES

    toy = EulerDisk()
    p = sub.add_parser(
        "euler-disk",
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
    p.add_argument("--mu", type=real("mu", low=0.0), default=toy.mu,
                   help=f"friction coefficient at saturation (default {toy.mu:g})")
    p.add_argument("--creep", type=real("creep", low=0.0, low_open=True),
                   default=toy.creep, help=f"creep coefficient k (default {toy.creep:g})")
    p.add_argument("--rolling-resistance", dest="rolling_resistance",
                   type=real("rolling_resistance", low=0.0), default=toy.rolling_resistance,
                   help=f"rolling-resistance length / a (default {toy.rolling_resistance:g})")
    p.add_argument("--alpha0", type=real("alpha0", low=0.0, high=math.pi / 2, low_open=True,
                                         high_open=True),
                   default=toy.alpha0, help=f"initial tilt in rad (default {toy.alpha0:g})")
    p.add_argument("--max-steps", dest="max_steps", type=positive_int, default=2_000_000,
                   help="step budget (default 2000000)")
    p.add_argument("--max-wall-time", dest="max_wall_time",
                   type=real("max_wall_time", low=0.0, low_open=True), default=120.0,
                   help="wall-clock budget in seconds (default 120)")
    return p


def run(args) -> int:
    from rollingdisk.friction.euler_disk import AIR_VISCOSITY, EulerDisk, run_euler_disk
    from rollingdisk.plotting.reports import EULER_DISK_FILES, write_euler_disk
    from rollingdisk.util.files import check_replaceable
    from rollingdisk.util.progress import ProgressBar

    toy = EulerDisk(mu=args.mu, creep=args.creep, rolling_resistance=args.rolling_resistance,
                    alpha0=args.alpha0, air_viscosity=AIR_VISCOSITY if args.air else None)
    if args.out is not None:
        check_replaceable(args.out, EULER_DISK_FILES, name="--out")  # before the work
    bar = ProgressBar(quiet=args.quiet)
    try:
        result = run_euler_disk(toy, max_steps=args.max_steps,
                                max_wall_time=args.max_wall_time, progress=bar)
    finally:
        bar.close()
    summary = result.summary()
    if args.out is not None:
        write_euler_disk(result, args.out)
        summary["out"] = args.out
    if args.json:
        print(json.dumps(summary, indent=2, allow_nan=False))
        return 0
    _print(result)
    if args.out is not None:
        print(f"  wrote {args.out}")
    return 0


def _print(result) -> None:
    unit = result.toy.time_unit
    print(result.message)
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

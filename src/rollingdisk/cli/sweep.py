"""``rollingdisk sweep``: integrate perturbed steady motions over a parameter grid and store
per-trajectory summaries next to the closed-form varpi^2 (docs/sweeps.md).

    $ rollingdisk sweep --ground rough --h 0.17 --theta0 0.3:1.2:20 --omega30=-5:5:20 \\
          --t-end 100 --out s.zarr
    $ rollingdisk sweep --ground smooth --h 0:0.5:6 --omega0 0.3:2:10 --t-end 50 --out s.nc
    $ rollingdisk sweep --ground rough --theta0 0.5 --omega30 1:3:5 --t-end 100 --basin \\
          --kick 0.5 --out basin.zarr
    $ rollingdisk sweep --ground rough --disk euro-1 --theta0 0.3:1.2:20 \\
          --omega30 30rad/s:90rad/s:20 --t-end 3s --out coin.zarr
"""

from __future__ import annotations

import argparse
import json
import math
import time

from rollingdisk.cli._args import (
    DISK_OPTIONS,
    T_END_MAX,
    CLIError,
    add_disk_options,
    add_progress_args,
    disk_from_args,
    parse_angle,
    positive_int,
    quantity,
    quantity_range,
    real,
    resolve_inputs,
    show_progress,
    t_end_arg,
)
from rollingdisk.cli._format import disk_fields, disk_line, has_scale, with_si
from rollingdisk.model.disk import DEFAULT_H
from rollingdisk.util.checks import check_int, check_real
from rollingdisk.util.errors import INPUT_ERRORS

#: Most points of one A:B:N range.
RANGE_POINTS_MAX = 100_000
#: Most runs of one sweep (grid points, times the bisection rounds + 1 of a basin sweep):
#: about 1 GB of store (~100 bytes a run) and, at ~10^4 runs/s, 20 min for t_end = 100.
SWEEP_RUNS_MAX = 10_000_000


def sweep_range(text: str) -> list[float]:
    """``A:B:N`` (N points from A to B, angles may carry a deg suffix) or one value; A and B
    finite and N in [1, RANGE_POINTS_MAX], checked before numpy sees them."""
    parts = str(text).split(":")
    if len(parts) not in (1, 3):
        raise argparse.ArgumentTypeError(f"expected a value or A:B:N, got {text!r}")
    try:
        ends = [check_real("range end", parse_angle(x)) for x in parts[:2]]
        n = check_int("N", int(parts[2]), low=1, high=RANGE_POINTS_MAX) if len(parts) == 3 \
            else 1
    except (argparse.ArgumentTypeError, ValueError, *INPUT_ERRORS) as exc:
        why = str(exc) if isinstance(exc, INPUT_ERRORS) else "not a number"
        raise argparse.ArgumentTypeError(f"expected a value or A:B:N with finite A, B and "
                                         f"N >= 1, got {text!r} ({why})") from None
    if n == 1 or len(ends) == 1:
        return ends[:1]
    a, b = ends
    return [a + (b - a) * i / (n - 1) for i in range(n - 1)] + [b]  # as np.linspace


def configure(sub):
    p = sub.add_parser(
        "sweep",
        description="Integrate a perturbed steady motion from every point of a grid: "
        "circles theta0 x (omega30 | rC | Omega0) (x h), or straight lines h x omega0 (at "
        "the tilt arctan(h)), and store per-trajectory summaries next to the closed-form "
        "varpi^2 (docs/sweeps.md). Ranges as A:B:N.")
    p.add_argument("--ground", choices=("rough", "smooth"), required=True,
                   help="rough (no slip) or smooth (no friction)")
    g = add_disk_options(p, h=False)
    g.add_argument("--h", type=sweep_range, default=None, metavar="H|A:B:N",
                   help=f"half-thickness / radius (dimensionless), one value or a range A:B:N "
                   f"(default {DEFAULT_H:g}); a physical disk (--disk, --radius ...) has "
                   "one h")
    p.add_argument("--theta0", type=sweep_range, default=None,
                   help="A:B:N (radians or deg); required for circles, not with --omega0")
    g = p.add_mutually_exclusive_group(required=True)
    g.add_argument("--omega30", type=_range("omega30", "angular_speed"),
                   help="spin omega30 of the circles (A:B:N; with a physical disk "
                   "10rad/s:30rad/s:5)")
    g.add_argument("--rC", type=_range("r_C", "length", "--rC"),
                   help="radius r_C of the circles of C (A:B:N; with a physical disk "
                   "1cm:5cm:5)")
    g.add_argument("--Omega0", type=_range("Omega0", "angular_speed", "--Omega0"),
                   help="precession rate Omega0 (A:B:N; with a physical disk rad/s)")
    g.add_argument("--omega0", type=_range("omega0", "rolling_rate", "--omega0"),
                   help="straight lines rolling at omega20 = omega0 (A:B:N; with a physical "
                   "disk rad/s, or m/s for the speed of C)")
    t_end_arg(p, high=T_END_MAX)
    p.add_argument("--kick", type=quantity("kick", "angular_speed"), default=None,
                   help="kick in omega1, units sqrt(g/a) (default 1e-3; with --basin the "
                   "largest kick, default 1; with a physical disk 0.5rad/s)")
    p.add_argument("--perturb", type=real("perturb", angle=True, low=-math.pi / 2,
                                          high=math.pi / 2, low_open=True, high_open=True),
                   default=None, help="tilt added to theta0, in (-pi/2, pi/2)")
    p.add_argument("--basin", action="store_true",
                   help="largest bounded kick by bisection (--kick is the upper end)")
    p.add_argument("--rounds", type=positive_int, default=10, help="bisection rounds")
    x = p.add_mutually_exclusive_group()
    x.add_argument("--workers", type=positive_int, default=None,
                   help="local cores (numba threads, at most NUMBA_NUM_THREADS: the CPUs)")
    x.add_argument("--dask", default=None, metavar="ADDRESS|local",
                   help="run on a Dask cluster (its scheduler's address, or local)")
    p.add_argument("--chunk", type=positive_int, default=2048,
                   help="trajectories per batch (default 2048)")
    p.add_argument("--method", choices=("taylor", "dop853"), default="taylor",
                   help="integrator (default taylor: the batch Taylor kernel)")
    p.add_argument("--out", required=True, help="FILE.zarr or FILE.nc")
    p.add_argument("--json", action="store_true", help="print one JSON object")
    add_progress_args(p)
    return p


def _range(name: str, kind: str, option: str | None = None):
    """A range of a dimensional value (``A:B:N``, units on A and B with a physical disk)."""
    return quantity_range(name, kind, option, points_max=RANGE_POINTS_MAX)


def _grid(args):
    from rollingdisk.sweep import SweepGrid

    h = _h_values(args)  # with a physical disk, also its scale converts the values with units
    if not _physical(args):
        resolve_inputs(args, None)
    if args.omega0 is not None and args.theta0 is not None:
        raise CLIError("rollingdisk sweep: error: --omega0 (straight lines) fixes theta0 = "
                       "arctan(h); drop --theta0")
    if args.omega0 is None and args.theta0 is None:
        raise CLIError("rollingdisk sweep: error: --theta0 A:B:N is required with --omega30, "
                       "--rC or --Omega0")
    if args.basin and args.perturb is not None:
        raise CLIError("rollingdisk sweep: error: --basin bisects the kick; drop --perturb")
    second = {k: getattr(args, k) for k in ("omega30", "Omega0", "omega0")}
    return SweepGrid(args.ground, h=h, theta0=args.theta0 or (), r_C=args.rC,
                     **second)


def _physical(args) -> bool:
    """Whether a disk option other than --h was given (then one disk, one h)."""
    return any(getattr(args, k) is not None for k in DISK_OPTIONS)


def _h_values(args) -> list[float]:
    """The h of the grid: --h (a value or a range) for a dimensionless sweep, else the one
    h of the disk the options give."""
    if not _physical(args):
        return [DEFAULT_H] if args.h is None else args.h
    if args.h is not None and len(args.h) > 1:
        raise CLIError("rollingdisk sweep: error: --h A:B:N sweeps dimensionless disks; a "
                       "physical disk (--disk, --radius, --diameter, --thickness, --mass, "
                       "--gravity) has one h: give --h as one value or drop the range")
    return [disk_from_args(args).h]


def _check_size(grid, args) -> None:
    """Refuse, before any work, a sweep of more than :data:`SWEEP_RUNS_MAX` runs, saying
    what would fit."""
    shape = [k for k in grid.shape if k > 1] or [1]
    rounds = args.rounds + 1 if args.basin else 1
    runs = math.prod(shape) * rounds
    if runs <= SWEEP_RUNS_MAX:
        return
    per = int((SWEEP_RUNS_MAX // rounds) ** (1.0 / len(shape)))
    what = " x ".join(str(k) for k in shape) + (f" x {rounds} rounds" if rounds > 1 else "")
    raise CLIError(f"rollingdisk sweep: error: {what} = {runs} runs is more than one sweep "
                   f"may do ({SWEEP_RUNS_MAX}, about 1 GB of store); give at most "
                   f"{per} points on each of the {len(shape)} ranges, or split the sweep")


def run(args) -> int:
    from rollingdisk.sweep import Perturbation, basin_sweep, run_sweep
    from rollingdisk.sweep.summary import stability_agreement
    from rollingdisk.util.progress import ProgressBar

    grid = _grid(args)
    _check_size(grid, args)
    disk = disk_from_args(args) if _physical(args) else None
    start = time.perf_counter()
    executor = "dask" if args.dask else ("threads" if args.workers != 1 else "serial")
    bar = ProgressBar(label="sweep", delay=0.0, interval=0.5, quiet=not show_progress(args))
    try:
        if args.basin:
            ds = basin_sweep(grid, args.t_end, kick_max=1.0 if args.kick is None else args.kick,
                             rounds=args.rounds, out=args.out, executor=executor,
                             workers=args.workers, chunk=args.chunk, method=args.method,
                             progress=bar)
            n = int(ds.kick_basin.size) * (args.rounds + 1)
        else:
            kick = args.kick if args.kick is not None else (0.0 if args.perturb else 1e-3)
            ds = run_sweep(grid, args.t_end, out=args.out, executor=executor,
                           perturbation=Perturbation(kick=kick, tilt=args.perturb or 0.0),
                           workers=args.workers,
                           dask_address=None if args.dask in (None, "local") else args.dask,
                           chunk=args.chunk, method=args.method, progress=bar)
            n = int(ds.varpi2.size)
    finally:
        bar.close()
    wall = time.perf_counter() - start
    agree = None if args.basin else stability_agreement(ds)
    computed = int(ds.attrs.get("n_computed", n))  # a resumed sweep computed only the rest
    rate = computed / wall if wall > 0 else None
    rec = {"n": n, "n_computed": computed, "wall_time_s": wall, "trajectories_per_s": rate,
           "agreement": agree, "out": args.out}
    if has_scale(disk):  # the dataset stays in the paper's units; its scale beside
        rec.update(h=disk.h, t_end=args.t_end)
        rec = with_si(rec, {"t_end_si": float(disk.time_to_si(args.t_end)),
                            "time_unit_si": disk.time_unit,
                            "units": {"t_end": "sqrt(a/g)", "t_end_si": "s",
                                      "time_unit_si": "s", "h": "1"}}, disk_fields(disk))
    if args.json:
        print(json.dumps(rec, allow_nan=False))
    else:
        if has_scale(disk):
            print(f"{disk_line(disk)}; each run {args.t_end:g} sqrt(a/g) = "
                  f"{rec['t_end_si']:.6g} s; the dataset is in the paper's units "
                  f"(time unit sqrt(a/g) = {disk.time_unit:.6g} s)")
        print(f"{n} trajectories in {wall:.1f} s ({rate or 0:.0f}/s); agreement {agree}; "
              f"{args.out}")
    return 0

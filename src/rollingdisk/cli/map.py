"""``rollingdisk map``: a map for any disk: existence or stability of steady circles, the
surface varpi^2 = 0, or simulated stability from a sweep.

    $ rollingdisk map --ground rough --h 0.17 --kind stability --out stability.png
    $ rollingdisk map --ground smooth --kind surface --out surface.pdf
    $ rollingdisk map --ground rough --kind nonlinear --out nonlinear.png
    $ rollingdisk map --ground rough --disk euro-1 --kind stability --out coin.png
"""

from __future__ import annotations

import sys

from rollingdisk.cli._args import add_disk_options, add_progress_args, disk_from_args, show_progress
from rollingdisk.cli._format import agg, disk_line, has_scale
from rollingdisk.cli.figures import dpi_arg
from rollingdisk.model.disk import DEFAULT_H

KINDS = ("existence", "stability", "surface", "all-omega30", "nonlinear", "basin")


def configure(sub):
    from rollingdisk.plotting.plots import IMAGE_FORMATS

    p = sub.add_parser(
        "map", description="A map for any disk, in the paper's units (angular speeds in "
        "sqrt(g/a), radii in units of a): only the disk's h = thickness / (2 radius) "
        "matters; --kind surface spans h and takes no disk.")
    p.add_argument("--ground", required=True, choices=("rough", "smooth"),
                   help="rough (no slip) or smooth (no friction)")
    add_disk_options(p, default_h=DEFAULT_H)
    p.add_argument("--kind", required=True, choices=KINDS,
                   help="existence: (theta0, r_C) plane; stability: (theta0, omega30) "
                   "plane; surface: varpi^2 = 0 in (theta0, h, omega30); all-omega30: "
                   "(theta0, h) region stable for every omega30; nonlinear: simulated "
                   "stability of kicked steady circles in (theta0, omega30), T = 100 "
                   "(a 40 x 40 sweep); basin: the largest kick that stays bounded there "
                   "(8 bisection rounds)")
    p.add_argument("--out", required=True,
                   help=f"image file ({', '.join('.' + f for f in IMAGE_FORMATS)})")
    dpi_arg(p, 110)
    add_progress_args(p)
    return p


def run(args) -> int:
    from rollingdisk.plotting.plots import image_format
    from rollingdisk.util.files import check_writable

    image_format(args.out)  # before any work
    check_writable(args.out, name="out")
    disk = disk_from_args(args)
    args.h = disk.h
    agg()
    from rollingdisk.plotting import plots

    if args.kind == "existence":
        m = plots.plot_existence_map(args.h, args.ground)
    elif args.kind == "stability":
        m = plots.plot_stability_map(args.h, args.ground)
    elif args.kind == "surface":
        m = plots.plot_varpi2_surface(args.ground)
    elif args.kind in ("nonlinear", "basin"):
        m = _sweep_map(args, plots)
    else:
        m = plots.plot_all_omega30_stable(args.ground, mark_h=args.h)
    fig = m["ax"].figure if isinstance(m, dict) else m.ax.figure
    fig.tight_layout()
    plots.save_figure(fig, args.out, dpi=args.dpi)
    if has_scale(disk):
        print(f"{disk_line(disk)}; the map is in the paper's units (omega in sqrt(g/a) = "
              f"{1.0 / disk.time_unit:.6g} rad/s, lengths in a = {disk.radius:.6g} m)",
              file=sys.stderr)
    print(args.out)
    return 0


def _sweep_map(args, plots) -> dict:
    from rollingdisk.sweep.maps import map_sweep
    from rollingdisk.util.progress import ProgressBar

    what = "trajectories" if args.kind == "nonlinear" else "bisection rounds"
    bar = ProgressBar(label=f"map: {what}", delay=0.0, interval=0.5,
                      quiet=not show_progress(args))
    try:
        ds = map_sweep(args.ground, args.h, args.kind, progress=bar)
    finally:
        bar.close()
    if args.kind == "nonlinear":
        return plots.plot_nonlinear_map(ds)
    return plots.plot_basin_map(ds)

"""``rollingdisk atlas``: everything about one disk in ``DIR/index.html``: thresholds, maps,
two simulated steady motions with their animations.

    $ rollingdisk atlas --h 0.17 --out atlas
    $ rollingdisk atlas --quick --quiet --out /tmp/quick-atlas
    $ rollingdisk atlas --disk euro-1 --out coin-atlas
"""

from __future__ import annotations

from rollingdisk.cli._args import (
    add_disk_options,
    add_progress_args,
    disk_from_args,
    show_progress,
)
from rollingdisk.cli._format import agg
from rollingdisk.model.disk import DEFAULT_H


def configure(sub):
    p = sub.add_parser(
        "atlas", description="Everything about one disk in DIR/index.html. The default disk "
        f"is dimensionless with h = {DEFAULT_H:g} (close to a commercial Euler's disk); a "
        "disk with a physical size (--disk euro-1, --radius/--diameter with --thickness) "
        "adds SI values to thresholds.json, and with a mass it is also the disk run as "
        "Euler's disk (otherwise the commercial toy).")
    add_disk_options(p, default_h=DEFAULT_H, positional=True)
    p.add_argument("--out", default="atlas",
                   help="output folder (default ./atlas; replaced as a whole, so it must be "
                   "new, empty or an earlier atlas)")
    p.add_argument("--quick", action="store_true", help="coarse grids, short simulations")
    add_progress_args(p)
    return p


def run(args) -> int:
    disk = disk_from_args(args)
    agg()
    from rollingdisk.atlas import build

    plain = disk.radius is None and disk.mass is None  # dimensionless: its h
    result = build.build_atlas(disk.h if plain else disk, args.out, quick=args.quick,
                               progress=show_progress(args))
    print(result.index)
    return 0

"""``rollingdisk atlas``: everything about one disk in ``DIR/index.html``: thresholds, maps,
two simulated steady motions with their animations.

    $ rollingdisk atlas --h 0.17 --out atlas
    $ rollingdisk atlas --quick --quiet --out /tmp/quick-atlas
"""

from __future__ import annotations

from rollingdisk.cli._args import H
from rollingdisk.cli._format import agg
from rollingdisk.model.disk import DEFAULT_H


def configure(sub):
    p = sub.add_parser("atlas")
    p.add_argument("--h", type=H, default=DEFAULT_H,
                   help=f"half-thickness (default {DEFAULT_H:g}, close to a commercial "
                   "Euler's disk)")
    p.add_argument("--out", default="atlas",
                   help="output folder (default ./atlas; replaced as a whole, so it must be "
                   "new, empty or an earlier atlas)")
    p.add_argument("--quick", action="store_true", help="coarse grids, short simulations")
    p.add_argument("--quiet", action="store_true", help="no progress lines on stderr")
    return p


def run(args) -> int:
    agg()
    from rollingdisk.atlas import build

    result = build.build_atlas(args.h, args.out, quick=args.quick, progress=not args.quiet)
    print(result.index)
    return 0

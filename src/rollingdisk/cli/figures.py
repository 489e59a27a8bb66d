"""``rollingdisk figures``: recompute the paper's Figures 4-8 as PNG files.

    $ rollingdisk figures --out figs
    $ rollingdisk figures --out figs --scale 0.2 --only fig4 fig8
"""

from __future__ import annotations

from rollingdisk.cli._args import add_progress_args, integer, real, show_progress
from rollingdisk.cli._format import agg


def dpi_arg(p, default: int) -> None:
    """``--dpi`` in the range every image writer accepts."""
    from rollingdisk.plotting.plots import DPI_RANGE

    p.add_argument("--dpi", type=integer("dpi", *DPI_RANGE), default=default,
                   help=f"resolution, dots per inch in [{DPI_RANGE[0]}, {DPI_RANGE[1]}] "
                   f"(default {default})")


def configure(sub):
    from rollingdisk.plotting.figures import FIGURES, SCALE_MAX

    p = sub.add_parser("figures")
    p.add_argument("--out", required=True,
                   help="output folder (its parent must exist; replaced as a whole, so it "
                   "must be new, empty or written by this command)")
    p.add_argument("--scale", type=real("scale", low=0.0, high=SCALE_MAX, low_open=True),
                   default=1.0, help=f"grid resolution factor in (0, {SCALE_MAX:g}] "
                   "(default 1; 0.2 for a quick look)")
    dpi_arg(p, 110)
    p.add_argument("--only", nargs="+", metavar="FIG", choices=tuple(FIGURES),
                   help=f"a subset of {' '.join(FIGURES)}")
    add_progress_args(p)
    return p


def run(args) -> int:
    agg()
    from rollingdisk.plotting.figures import paper_figures
    from rollingdisk.util.progress import ProgressBar

    bar = ProgressBar(quiet=not show_progress(args))
    paths = paper_figures(args.out, scale=args.scale, dpi=args.dpi, only=args.only,
                          progress=bar.note)
    for path in paths:
        print(path)
    return 0

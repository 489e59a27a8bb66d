"""``rollingdisk edge-odds``: heads, tails and edge of hand tosses landing on a table against
the coin's thickness ``t/d`` (:func:`rollingdisk.edge_odds`; docs/motion.md, "Edge odds").

The launch is the hand toss of ``rollingdisk toss --table`` in the paper's units (``a``,
``sqrt(a g)``, ``sqrt(g/a)``: the coins of one curve share their radius).  A long job: with
``--results DIR`` each thickness's tosses are journaled and an interrupted curve resumes.

Examples::

    $ rollingdisk edge-odds --n 200 --ratios 0.05,0.3,0.6
    $ rollingdisk edge-odds --n 20000 --workers 2 --results curve/ --out edge-odds.nc \
          --plot edge-odds.png
"""

from __future__ import annotations

import json
import math
import os
import sys

from rollingdisk.cli._args import CLIError, add_progress_args, integer, real, show_progress

__all__ = ["configure", "run"]

#: (option, attribute, low, help) of the launch values, plain numbers in the paper's units.
_LAUNCH = (
    ("--height", "height", 0.0, "height of the centre at release above the table [a] "
     "(default 1.5; at least the largest ratio)"),
    ("--upward-speed", "upward_speed", None, "vertical speed at release [sqrt(a g)] "
     "(default 7)"),
    ("--upward-speed-spread", "upward_speed_spread", 0.0, "half-width of its uniform spread "
     "(default 1)"),
    ("--flip-rate", "flip_rate", 0.0, "angular speed |omega| at release [sqrt(g/a)] "
     "(default 8)"),
    ("--flip-rate-spread", "flip_rate_spread", 0.0, "half-width of its uniform spread "
     "(default 2)"),
)


def _ratios(text: str) -> tuple:
    """``--ratios``: comma-separated thicknesses t/d, each in (0, 1]."""
    import argparse

    try:
        values = tuple(float(x) for x in text.split(","))
    except ValueError:
        values = ()
    if not values or not all(0.0 < v <= 1.0 for v in values):
        raise argparse.ArgumentTypeError(f"ratios must be comma-separated thicknesses t/d in "
                                         f"(0, 1], got {text!r}")
    return values


def configure(subparsers):
    """Add the ``edge-odds`` subcommand to ``subparsers`` and return its parser."""
    p = subparsers.add_parser(
        "edge-odds", description="Heads, tails and edge of hand tosses landing on a table "
        "against the thickness t/d, with 95% Wilson intervals, beside the no-bounce edge "
        "probabilities (docs/motion.md, 'Edge odds').")
    p.add_argument("--ratios", type=_ratios, default=None,
                   help="comma-separated thicknesses t/d in (0, 1] (default: 12 from 0.02 to "
                   "1, with 0.0919 (a nickel), 0.354 and 0.577)")
    p.add_argument("--n", type=integer("n", 1, 10_000_000), default=20_000,
                   help="tosses per thickness, >= 1 (default 20000)")
    p.add_argument("--seed", type=integer("seed", 0, 2**63 - 1), default=0,
                   help="random seed of the launches, the same for every thickness (default 0)")
    p.add_argument("--restitution", dest="e", type=real("restitution", low=0.0, high=1.0),
                   default=0.5, help="coefficient of restitution, in [0, 1] (default 0.5)")
    p.add_argument("--mu", type=real("mu", low=0.0, high=1e6), default=0.5,
                   help="Coulomb friction coefficient, in [0, 1e6] (default 0.5)")
    p.add_argument("--max-wall-time", dest="max_wall", default=20.0,
                   type=real("max_wall_time", low=0.0, high=3600.0, low_open=True),
                   help="wall-clock budget of one toss in seconds (default 20); beyond it "
                   "the toss counts as undecided")
    p.add_argument("--workers", type=integer("workers", 1, 256), default=1,
                   help="processes (default 1), at most the CPUs this process may use")
    p.add_argument("--results", default=None, metavar="DIR",
                   help="a folder of per-thickness toss journals: an interrupted curve "
                   "resumes from it with the same counts")
    p.add_argument("--out", default=None, metavar="FILE.nc",
                   help="the curve as a CF-attributed netCDF file")
    p.add_argument("--plot", default=None, metavar="FILE.png",
                   help="the curve drawn beside the no-bounce probabilities")
    p.add_argument("--json", action="store_true", help="print one JSON object")
    g = p.add_argument_group("launch (the hand toss, paper units; docs/motion.md)")
    for opt, dest, low, text in _LAUNCH:
        g.add_argument(opt, dest=dest, type=real(dest, low=low), default=None, help=text)
    g.add_argument("--psi", type=real("psi", angle=True, low=0.0, high=math.pi / 2),
                   default=None, help="angle between the angular momentum and the normal, "
                   "in [0, pi/2] (radians, or 80deg) (default pi/2)")
    g.add_argument("--psi-spread", dest="psi_spread", default=None,
                   type=real("psi_spread", angle=True, low=0.0),
                   help="standard deviation of psi (radians or deg) (default 10deg)")
    add_progress_args(p)
    return p


def run(args) -> int:
    """Run the curve, print it (and write its file and plot); 0 when done."""
    from rollingdisk.scenarios.hand_toss import HandLaunch
    from rollingdisk.scenarios.odds import EDGE_RATIOS, edge_odds
    from rollingdisk.scenarios.toss import TOSS_OUTCOMES
    from rollingdisk.util.files import check_writable
    from rollingdisk.util.progress import ProgressBar

    for dest, name in (("out", "out"), ("plot", "plot")):
        if getattr(args, dest):
            check_writable(getattr(args, dest), name=name)
    ratios = args.ratios or EDGE_RATIOS
    launch = HandLaunch(**{dest: getattr(args, dest) for dest in
                           [d for _, d, _, _ in _LAUNCH] + ["psi", "psi_spread"]
                           if getattr(args, dest) is not None})
    if launch.height < max(ratios):
        raise CLIError(f"rollingdisk edge-odds: error: --height {launch.height:g} is below the "
                       f"largest ratio {max(ratios):g} (the flat coin would start inside the "
                       "table)")
    bar = ProgressBar(label="tosses", delay=0.0, interval=0.5, quiet=not show_progress(args))
    try:
        odds = edge_odds(ratios, args.n, args.seed, launch=launch, e=args.e, mu=args.mu,
                         workers=args.workers, results=args.results, max_wall=args.max_wall,
                         progress=bar)
    finally:
        bar.close()
    if args.out:
        odds.save(args.out)
    if args.plot:
        _plot(odds, args.plot)
    if args.json:
        print(json.dumps(odds.as_dict(), allow_nan=False))
        return 0
    print(f"{'t/d':>8s} " + " ".join(f"{k:>22s}" for k in TOSS_OUTCOMES))
    cols = {k: (odds.probability(k), *odds.interval(k)) for k in TOSS_OUTCOMES}
    for i, r in enumerate(odds.ratio):
        cells = [f"{p[i]:.4f} [{lo[i]:.4f},{hi[i]:.4f}]" for p, lo, hi in cols.values()]
        print(f"{r:8.4f} " + " ".join(f"{c:>22s}" for c in cells))
    print(f"model: {odds.model}")
    if not args.quiet:
        print(f"{odds.n} tosses a thickness, seed {odds.seed}, {odds.wall_time:.1f} s",
              file=sys.stderr)
        for path in (args.out, args.plot):
            if path:
                print(f"wrote {os.fspath(path)}", file=sys.stderr)
    return 0


def _plot(odds, path) -> None:
    from matplotlib.figure import Figure  # no pyplot: the user's backend is left alone

    from rollingdisk.plotting import plot_edge_odds
    from rollingdisk.util.files import atomic_file

    fig = Figure(figsize=(7.0, 4.6))
    plot_edge_odds(odds, fig.subplots())
    fig.tight_layout()
    with atomic_file(path, "wb") as f:
        fig.savefig(f, format="png")

"""``rollingdisk toss``: heads, tails or edge over random tosses of one disk.

Each toss runs through flight, impacts, rolling and sliding
(:func:`rollingdisk.phases.motion.simulate_to_rest`) until its outcome is certain (the
energy below the balancing barrier) or the disk is at rest; docs/motion.md.

Examples::

    $ rollingdisk toss --h 0.1 --n 20 --seed 1
    $ rollingdisk toss --disk us-quarter --n 50 --workers 2 --results tosses.jsonl --json
    $ rollingdisk toss --h 0.3 --n 20 --out toss.png
    $ rollingdisk toss --disk euro-1 --n 1000000 --catch --flip-rate 38rev/s --psi-spread 8deg
"""

from __future__ import annotations

import json
import os
import sys

from rollingdisk.cli._args import (
    add_disk_options,
    add_progress_args,
    alias,
    disk_from_args,
    integer,
    real,
    show_progress,
)
from rollingdisk.cli._launch import (
    add_launch_options,
    hand_launch_from_args,
    launch_fields,
    run_caught,
    uses_hand_launch,
)

__all__ = ["configure", "run"]


def configure(subparsers):
    """Add the ``toss`` subcommand to ``subparsers`` and return its parser."""
    p = subparsers.add_parser(
        "toss", description="Random tosses of one disk (launch conditions: docs/motion.md): "
        "each runs through flight, impacts, rolling and sliding until its outcome is "
        "certain or the disk is at rest. Prints the frequency of heads, tails, edge and "
        "undecided (a toss that spent its wall-clock budget) with 95% Wilson intervals.")
    add_disk_options(p, required=True, positional=True)
    p.add_argument("--n", type=integer("n", 1, 1_000_000), default=20,
                   help="number of tosses, >= 1 (default 20)")
    p.add_argument("--seed", type=integer("seed", 0, 2**63 - 1), default=0,
                   help="random seed of the launch conditions (default 0)")
    restitution = real("restitution", low=0.0, high=1.0)
    p.add_argument("--restitution", dest="e", type=restitution, default=0.5,
                   help="coefficient of restitution of the impacts, in [0, 1] (default 0.5)")
    alias(p, "--e", "--restitution", dest="e", type=restitution)
    p.add_argument("--mu", type=real("mu", low=0.0, high=1e6), default=0.5,
                   help="Coulomb friction coefficient at the contact, dimensionless, in "
                   "[0, 1e6] (default 0.5)")
    budget = real("max_wall_time", low=0.0, high=3600.0, low_open=True)
    p.add_argument("--max-wall-time", dest="max_wall", type=budget, default=20.0,
                   help="wall-clock budget of one toss in seconds (default 20); a toss "
                   "that spends it counts as undecided")
    alias(p, "--max-wall", "--max-wall-time", dest="max_wall", type=budget)
    p.add_argument("--workers", type=integer("workers", 1, 256), default=1,
                   help="processes (default 1), at most the CPUs this process may use")
    p.add_argument("--results", default=None, metavar="FILE.jsonl",
                   help="one JSON line per toss, appended as each ends; an interrupted "
                   "ensemble resumes from it (one writer at a time; a file that is not "
                   "a toss-results file is refused)")
    p.add_argument("--json", action="store_true", help="print one JSON object")
    p.add_argument("--out", default=None, metavar="FILE.png",
                   help="a bar chart of the outcome probabilities with their intervals")
    add_launch_options(p)
    add_progress_args(p)
    return p


def run(args) -> int:
    """Run the ensemble, print (and plot) its frequencies; 0 when done."""
    from rollingdisk.scenarios.toss import TOSS_OUTCOMES, toss_ensemble
    from rollingdisk.util.files import check_writable
    from rollingdisk.util.progress import ProgressBar

    disk = disk_from_args(args)
    hand = uses_hand_launch(args)
    if args.ending == "caught":
        return run_caught(args, disk)
    if args.out:
        check_writable(args.out, name="out")
    launch = hand_launch_from_args(args, disk) if hand else None
    bar = ProgressBar(label="tosses", delay=0.0, interval=0.5, quiet=not show_progress(args))
    try:
        if launch is None:
            res = toss_ensemble(disk, args.n, args.seed, e=args.e, mu=args.mu,
                                workers=args.workers, results=args.results,
                                max_wall=args.max_wall, progress=bar)
        else:
            from rollingdisk.scenarios.hand_toss import table_ensemble

            res = table_ensemble(disk, launch, args.n, args.seed, e=args.e, mu=args.mu,
                                 workers=args.workers, results=args.results,
                                 max_wall=args.max_wall, progress=bar)
    finally:
        bar.close()
    if args.json:
        print(json.dumps(res.as_dict() | launch_fields(args, disk, launch), allow_nan=False))
    else:
        for k in TOSS_OUTCOMES:
            lo, hi = res.interval(k)
            print(f"{k:10s} {res.counts[k]:6d}  p = {res.counts[k] / res.n:.4f}  "
                  f"95% [{lo:.4f}, {hi:.4f}]")
        print("; ".join(f"{k} = {v}" for k, v in launch_fields(args, disk, launch).items()))
        if not args.quiet:
            print(f"h = {res.h:g}, n = {res.n}, seed = {res.seed}, {res.wall_time:.1f} s",
                  file=sys.stderr)
    if args.out:
        _plot(res, args, "hand" if hand else "uniform")
    return 0


def _plot(res, args, launch: str) -> None:
    from matplotlib.figure import Figure  # no pyplot: the user's backend is left alone

    from rollingdisk.scenarios.toss import TOSS_OUTCOMES
    from rollingdisk.util.files import atomic_file

    fig = Figure(figsize=(5, 3.5))
    ax = fig.subplots()
    p = [res.counts[k] / res.n for k in TOSS_OUTCOMES]
    err = [[pk - res.interval(k)[0] for k, pk in zip(TOSS_OUTCOMES, p)],
           [res.interval(k)[1] - pk for k, pk in zip(TOSS_OUTCOMES, p)]]
    ax.bar(TOSS_OUTCOMES, p, yerr=err, capsize=4, color="0.6")
    ax.set_ylabel("probability (95 % Wilson interval)")
    ax.set_title(f"coin toss, h = {res.h:g}, n = {res.n}, e = {args.e:g}, mu = {args.mu:g}, "
                 f"{launch} launch")
    fig.tight_layout()
    with atomic_file(args.out, "wb") as f:
        fig.savefig(f, format="png")
    if not args.json and not args.quiet:
        print(f"wrote {os.fspath(args.out)}", file=sys.stderr)

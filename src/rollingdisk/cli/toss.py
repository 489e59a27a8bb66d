"""``rollingdisk toss``: heads, tails or edge over random tosses of one disk.

Thin: parses, calls :func:`rollingdisk.friction.toss.toss_ensemble`, prints and plots.
Register with ``configure(subparsers)``; ``run(args) -> int``.
"""

from __future__ import annotations

import argparse
import json
import os
import sys

__all__ = ["configure", "run"]


def configure(subparsers) -> argparse.ArgumentParser:
    """Add the ``toss`` subcommand to ``subparsers`` and return its parser."""
    p = subparsers.add_parser(
        "toss", help="toss a coin of half-thickness h many times: heads, tails, edge",
        description="Random tosses (docs/motion.md): each runs through flight, impacts, "
                    "rolling and sliding until the outcome is certain (energy below the "
                    "balancing barrier) or the disk is at rest.")
    p.add_argument("--h", type=float, required=True, help="half-thickness / radius, >= 0")
    p.add_argument("--n", type=int, default=200, help="number of tosses (default 200)")
    p.add_argument("--seed", type=int, default=0, help="random seed (default 0)")
    p.add_argument("--e", type=float, default=0.5, help="restitution in [0, 1]")
    p.add_argument("--mu", type=float, default=0.5, help="friction coefficient >= 0")
    p.add_argument("--workers", type=int, default=1, help="processes (default 1)")
    p.add_argument("--results", help="JSON-lines file of each toss; resumes if present")
    p.add_argument("--json", action="store_true", help="print the result as JSON")
    p.add_argument("--out", help="PNG plot of the outcome probabilities")
    p.set_defaults(handler=run)
    return p


def run(args) -> int:
    """Run the ensemble; 0 done (library input errors propagate to the caller's handler)."""
    import rollingdisk as rd
    from rollingdisk.friction.toss import TOSS_OUTCOMES, toss_ensemble
    from rollingdisk.util.files import atomic_file, check_writable

    disk = rd.Disk(h=args.h)
    if args.out:
        check_writable(args.out, name="out")
    res = toss_ensemble(disk, args.n, args.seed, e=args.e, mu=args.mu,
                        workers=args.workers, results=args.results)
    if args.json:
        print(json.dumps(res.as_dict(), allow_nan=False))
    else:
        for k in TOSS_OUTCOMES:
            lo, hi = res.interval(k)
            print(f"{k:10s} {res.counts[k]:6d}  p = {res.counts[k] / res.n:.4f}  "
                  f"95% [{lo:.4f}, {hi:.4f}]")
        print(f"h = {res.h:g}, n = {res.n}, seed = {res.seed}, {res.wall_time:.1f} s",
              file=sys.stderr)
    if args.out:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt

        fig, ax = plt.subplots(figsize=(5, 3.5))
        p = [res.counts[k] / res.n for k in TOSS_OUTCOMES]
        err = [[pk - res.interval(k)[0] for k, pk in zip(TOSS_OUTCOMES, p)],
               [res.interval(k)[1] - pk for k, pk in zip(TOSS_OUTCOMES, p)]]
        ax.bar(TOSS_OUTCOMES, p, yerr=err, capsize=4, color="0.6")
        ax.set_ylabel("probability (95 % Wilson interval)")
        ax.set_title(f"coin toss, h = {res.h:g}, n = {res.n}, e = {args.e:g}, "
                     f"mu = {args.mu:g}")
        fig.tight_layout()
        with atomic_file(args.out, "wb") as f:
            fig.savefig(f, format="png")
        plt.close(fig)
        if not args.json:
            print(f"wrote {os.fspath(args.out)}", file=sys.stderr)
    return 0

"""Command-line interface: a thin layer over the library, one subcommand per entry point.

Errors in the input (and physically impossible requests) end with exit status 2 and one
line on stderr, never a traceback.
"""

from __future__ import annotations

import argparse
import math
import sys
from collections.abc import Sequence

__all__ = ["main", "parse_angle"]


class CLIError(Exception):
    """A user error: printed as one line on stderr, exit status 2."""


def parse_angle(text: str) -> float:
    """An angle in radians, or in degrees with a ``deg`` suffix (``30deg``)."""
    s = str(text).strip().lower()
    try:
        if s.endswith("deg"):
            return math.radians(float(s[:-3]))
        if s.endswith("°"):
            return math.radians(float(s[:-1]))
        return float(s)
    except ValueError:
        raise argparse.ArgumentTypeError(
            f"invalid angle {text!r}: give radians (0.5) or degrees with a suffix (30deg)"
        ) from None


class _Parser(argparse.ArgumentParser):
    """argparse that reports usage errors as one line and exit status 2."""

    def error(self, message: str):  # noqa: D401 - argparse API
        raise CLIError(f"{self.prog}: {message}")


# ---------------------------------------------------------------------------- derive
def _add_derive(sub) -> None:
    p = sub.add_parser("derive", help="derive the equations of motion with sympy and check "
                       "the paper's equations (1)-(13), (37), (38), (49)")
    p.add_argument("--json", action="store_true", help="print the table as JSON")
    p.set_defaults(handler=_run_derive)


def _run_derive(args) -> int:
    from .symbolic import check_equations, format_table

    rows = check_equations(progress=not args.json)
    if args.json:
        import json

        print(json.dumps([row.as_dict() for row in rows], indent=2))
    else:
        print(format_table(rows))
    return 0


# ---------------------------------------------------------------------------- steady
def _add_steady(sub) -> None:
    """Registered by the steady-motion issue."""


# ---------------------------------------------------------------------------- thresholds
def _add_thresholds(sub) -> None:
    """Registered by the steady-motion issue."""


# ---------------------------------------------------------------------------- simulate
def _add_simulate(sub) -> None:
    """Registered by the simulation issue."""


# ---------------------------------------------------------------------------- figures, maps
def _add_figures(sub) -> None:
    """Registered by the figures issue (figures, map, animate, atlas)."""
    p = sub.add_parser("figures", help="recompute the paper's Figures 4-8 as PNG files")
    p.add_argument("--out", required=True, help="output folder")
    p.add_argument("--scale", type=float, default=1.0,
                   help="grid resolution factor (default 1; 0.2 for a quick look)")
    p.add_argument("--dpi", type=int, default=110)
    p.add_argument("--only", nargs="+", metavar="FIG",
                   help="a subset of fig4 fig5 fig6 fig7 fig8")
    p.set_defaults(handler=_run_figures)

    p = sub.add_parser("map", help="existence / stability map or varpi^2 = 0 surface")
    p.add_argument("--ground", required=True, choices=("rough", "smooth"))
    p.add_argument("--h", type=float, default=0.17, help="half-thickness (default 0.17)")
    p.add_argument("--kind", required=True,
                   choices=("existence", "stability", "surface", "all-omega30"),
                   help="existence: (theta0, r_C) plane; stability: (theta0, omega30) "
                   "plane; surface: varpi^2 = 0 in (theta0, h, omega30); all-omega30: "
                   "(theta0, h) region stable for every omega30")
    p.add_argument("--out", required=True, help="image file (.png, .pdf, .svg)")
    p.add_argument("--dpi", type=int, default=110)
    p.set_defaults(handler=_run_map)

    p = sub.add_parser("animate", help="simulate a steady motion from a small tilt "
                       "perturbation and write a 3D animation (.gif, or .mp4 with ffmpeg)")
    p.add_argument("--ground", default="rough", choices=("rough", "smooth"))
    p.add_argument("--h", type=float, default=0.17, help="half-thickness (default 0.17)")
    p.add_argument("--theta0", type=parse_angle, required=True,
                   help="steady tilt, radians or e.g. 30deg")
    g = p.add_mutually_exclusive_group(required=True)
    g.add_argument("--Omega0", type=float, help="spin rate about the vertical")
    g.add_argument("--r-C", dest="r_C", type=float, help="signed radius of C's circle")
    g.add_argument("--r-P", dest="r_P", type=float, help="signed radius of P's circle")
    p.add_argument("--perturb", type=float, default=0.0, help="added to theta(0)")
    p.add_argument("--kick", type=float, default=0.01, help="added to omega1(0) = dtheta/dt")
    p.add_argument("--t-end", type=float, default=20.0, help="simulated time")
    p.add_argument("--frames", type=int, default=60)
    p.add_argument("--fps", type=int, default=15)
    p.add_argument("--dpi", type=int, default=70)
    p.add_argument("--out", required=True, help="motion.gif (or .mp4 when ffmpeg exists)")
    p.set_defaults(handler=_run_animate)

    p = sub.add_parser("atlas", help="the atlas of one disk: thresholds, maps, two simulated "
                       "steady motions with animations, index.html")
    p.add_argument("--h", type=float, default=None, help="half-thickness (default 0.17)")
    p.add_argument("--out", default="atlas", help="output folder (default ./atlas)")
    p.add_argument("--quick", action="store_true", help="coarse grids, short simulations")
    p.add_argument("--quiet", action="store_true", help="no progress lines on stderr")
    p.set_defaults(handler=_run_atlas)


def _agg() -> None:
    import matplotlib

    matplotlib.use("Agg")


def _run_figures(args) -> int:
    _agg()
    from .figures import paper_figures

    paths = paper_figures(args.out, scale=args.scale, dpi=args.dpi, only=args.only,
                          progress=lambda msg: print(msg, file=sys.stderr, flush=True))
    for path in paths:
        print(path)
    return 0


def _run_map(args) -> int:
    _agg()
    from . import plotting

    if args.kind == "existence":
        m = plotting.plot_existence_map(args.h, args.ground)
    elif args.kind == "stability":
        m = plotting.plot_stability_map(args.h, args.ground)
    elif args.kind == "surface":
        m = plotting.plot_varpi2_surface(args.ground)
    else:
        m = plotting.plot_all_omega30_stable(args.ground, mark_h=args.h)
    fig = m.ax.figure
    fig.tight_layout()
    fig.savefig(args.out, dpi=args.dpi)
    print(args.out)
    return 0


def _run_animate(args) -> int:
    _agg()
    from .animation import animate, writer_for
    from .atlas import steady_trajectory

    writer_for(args.out, args.fps)  # a bad file name fails before the simulation
    motion, stab, traj = steady_trajectory(
        args.h, args.ground, args.theta0, Omega0=args.Omega0, r_C=args.r_C, r_P=args.r_P,
        perturb=args.perturb, kick=args.kick, t_end=args.t_end)
    verdict = (f"stable, varpi^2 = {stab.varpi2:.4g}" if stab.stable
               else f"unstable, varpi^2 = {stab.varpi2:.4g}")
    print(f"{args.ground} ground, h = {args.h:g}, theta0 = {motion.theta0:.4g}, "
          f"Omega0 = {motion.Omega0:.4g}: {verdict}; simulation "
          f"{getattr(traj, 'status', 'completed')}", file=sys.stderr)
    out = animate(traj, args.out, n_frames=args.frames, fps=args.fps, dpi=args.dpi)
    print(out)
    return 0


def _run_atlas(args) -> int:
    from .atlas import DEFAULT_H, build_atlas

    h = DEFAULT_H if args.h is None else args.h
    result = build_atlas(h, args.out, quick=args.quick, progress=not args.quiet)
    print(result.index)
    return 0


# ---------------------------------------------------------------------------- main
def build_parser() -> argparse.ArgumentParser:
    parser = _Parser(prog="rollingdisk", description=__doc__.splitlines()[0])
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", parser_class=_Parser)
    for add in (_add_derive, _add_steady, _add_thresholds, _add_simulate, _add_figures):
        add(sub)
    return parser


def main(argv: Sequence[str] | None = None) -> int:
    """Run the command line ``argv`` (``sys.argv[1:]`` by default); return the exit status."""
    parser = build_parser()
    try:
        args = parser.parse_args(argv)
        if not getattr(args, "handler", None):
            parser.print_help(sys.stderr)
            return 2
        return int(args.handler(args) or 0)
    except CLIError as exc:
        print(str(exc), file=sys.stderr)
        return 2
    except ValueError as exc:
        print(f"rollingdisk: error: {exc}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        print("rollingdisk: interrupted", file=sys.stderr)
        return 130

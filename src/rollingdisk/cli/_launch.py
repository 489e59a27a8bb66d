"""The launch options of ``rollingdisk toss``: the ending (``--catch`` / ``--table``), the
launch model (``--launch uniform|hand``) and the hand toss's variables with units.

A launch value is a plain number in the paper's units (``a``, ``sqrt(a g)``, ``sqrt(g/a)``)
or, with a physical disk (``--disk``, ``--radius``), a number with a unit: ``--height
0.3m``, ``--upward-speed 2.4m/s``, ``--flip-rate 38rev/s`` (``rad/s``, ``Hz``, ``rpm``).
The model: :mod:`rollingdisk.scenarios.hand_toss`; docs/motion.md, "The hand toss".
"""

from __future__ import annotations

import argparse
import json
import math
import re
import sys

from rollingdisk.cli._args import CLIError, real

__all__ = ["add_launch_options", "uses_hand_launch", "hand_launch_from_args", "run_caught",
           "launch_fields"]

#: Units a launch value may carry: factor to SI (m, m/s, rad/s).
_UNITS = {
    "length": {"m": 1.0, "cm": 1e-2, "mm": 1e-3, "in": 0.0254},
    "speed": {"m/s": 1.0, "cm/s": 1e-2, "km/h": 1.0 / 3.6},
    "rate": {"rad/s": 1.0, "1/s": 1.0, "rev/s": 2.0 * math.pi, "hz": 2.0 * math.pi,
             "rpm": 2.0 * math.pi / 60.0},
}
_PAPER = {"length": "a", "speed": "sqrt(a g)", "rate": "sqrt(g/a)"}
_NUMBER = re.compile(r"^\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*(\S.*?)?\s*$")
#: (option, attribute, kind, low, help)
_VALUES = (
    ("--height", "height", "length", 0.0, "height of the centre at release (above the table "
     "for --table) [a, or e.g. 0.3m with a physical disk] (default 1.5 a)"),
    ("--catch-height", "catch_height", "length", 0.0, "height of the centre at the catch "
     "(--catch) (default: the release height)"),
    ("--upward-speed", "upward_speed", "speed", None, "vertical speed at release [sqrt(a g), "
     "or e.g. 2.4m/s] (default 7)"),
    ("--upward-speed-spread", "upward_speed_spread", "speed", 0.0, "half-width of its "
     "uniform spread (default 1)"),
    ("--flip-rate", "flip_rate", "rate", 0.0, "angular speed |omega| at release [sqrt(g/a), "
     "or e.g. 38rev/s, 240rad/s] (default 8)"),
    ("--flip-rate-spread", "flip_rate_spread", "rate", 0.0, "half-width of its uniform "
     "spread (default 2)"),
)


class _SI(float):
    """A launch value given with a unit, in SI; converted once the disk is known."""

    kind = "length"


def _value(name: str, kind: str, low):
    plain = real(name, low=low)

    def parse(text: str):
        try:
            float(text)
        except ValueError:
            pass
        else:
            return plain(text)
        m = _NUMBER.match(str(text))
        unit = (m.group(2) or "").replace(" ", "").lower() if m else ""
        if not m or unit not in _UNITS[kind]:
            raise argparse.ArgumentTypeError(
                f"{name} must be a plain number (units of {_PAPER[kind]}) or a number with "
                f"one of the units {', '.join(_UNITS[kind])}, got {text!r}")
        x = plain(m.group(1)) * _UNITS[kind][unit]
        out = _SI(x)
        out.kind = kind
        return out

    return parse


def add_launch_options(p) -> None:
    """The hand toss's options of ``rollingdisk toss`` (one argument group)."""
    g = p.add_argument_group("launch (docs/motion.md, 'The hand toss')")
    end = g.add_mutually_exclusive_group()
    end.add_argument("--catch", dest="ending", action="store_const", const="caught",
                     help="catch the coin in the hand: the side up at the catch, from free "
                     "flight alone (the hand launch); prints the same-side probability")
    end.add_argument("--table", dest="ending", action="store_const", const="table",
                     help="let it land on the table: bounces, rolling, rest (the default)")
    g.add_argument("--launch", choices=("uniform", "hand"), default=None,
                   help="launch model: uniform (independent uniform launch variables, the "
                   "default on the table) or hand (the variables below; implied by --catch "
                   "or by any of them)")
    for opt, dest, kind, low, text in _VALUES:
        g.add_argument(opt, dest=dest, type=_value(dest, kind, low), default=None, help=text)
    g.add_argument("--psi", type=real("psi", angle=True, low=0.0, high=math.pi / 2),
                   default=None, help="angle between the angular momentum and the coin's "
                   "normal, in [0, pi/2] (radians, or 80deg) (default pi/2, a pure flip)")
    g.add_argument("--psi-spread", dest="psi_spread", type=real("psi_spread", angle=True,
                                                                  low=0.0), default=None,
                   help="standard deviation of psi (radians or deg), folded into [0, pi/2] "
                   "(default 10deg, an assumption)")


def uses_hand_launch(args) -> bool:
    """Whether the command line asks for the hand launch (``CLIError`` if contradictory)."""
    given = [opt for opt, dest, *_ in _VALUES if getattr(args, dest) is not None]
    given += [o for o, d in (("--psi", "psi"), ("--psi-spread", "psi_spread"))
              if getattr(args, d) is not None]
    if args.launch == "uniform" and (given or args.ending == "caught"):
        what = "--catch" if args.ending == "caught" else ", ".join(given)
        raise CLIError(f"rollingdisk toss: error: {what} needs the hand launch, not "
                       "--launch uniform")
    if args.ending != "caught" and args.catch_height is not None:
        raise CLIError("rollingdisk toss: error: --catch-height is for --catch")
    return args.launch == "hand" or args.ending == "caught" or bool(given)


def hand_launch_from_args(args, disk):
    """The :class:`~rollingdisk.scenarios.hand_toss.HandLaunch` of the options, in the
    paper's units (values with units converted through the disk's radius and gravity)."""
    from rollingdisk.scenarios.hand_toss import HandLaunch

    kw = {}
    for opt, dest, kind, _low, _text in _VALUES:
        x = getattr(args, dest)
        if isinstance(x, _SI):
            if disk.radius is None:
                raise CLIError(f"rollingdisk toss: error: {opt} with a unit needs a disk with "
                               "a physical radius (--disk, --radius or --diameter); without "
                               f"one give a plain number in units of {_PAPER[kind]}")
            scale = {"length": disk.radius, "speed": math.sqrt(disk.radius * disk.gravity),
                     "rate": 1.0 / disk.time_unit}[kind]
            x = float(x) / scale
        if x is not None:
            kw[dest] = x
    for dest in ("psi", "psi_spread"):
        if getattr(args, dest) is not None:
            kw[dest] = getattr(args, dest)
    return HandLaunch(**kw)


def _si_line(launch, disk) -> str | None:
    if disk.radius is None:
        return None
    a, tu = disk.radius, disk.time_unit
    return (f"  in SI: height {launch.height * a:.4g} m, upward speed "
            f"{launch.upward_speed * a / tu:.4g} +- {launch.upward_speed_spread * a / tu:.3g}"
            f" m/s, flip rate {launch.flip_rate / tu / (2 * math.pi):.4g} +- "
            f"{launch.flip_rate_spread / tu / (2 * math.pi):.3g} rev/s")


def launch_fields(args, disk, launch=None) -> dict:
    """What every output of ``toss`` states: the launch model, e and mu (JSON-ready)."""
    if launch is None:
        return {"launch_model": "uniform: independent uniform launch variables "
                "(TossDistribution, docs/motion.md)", "e": args.e, "mu": args.mu}
    out = {"launch_model": launch.describe(args.ending or "table"), "e": args.e, "mu": args.mu}
    si = _si_line(launch, disk)
    if si:
        out["launch_si"] = si.strip()
    return out


def run_caught(args, disk) -> int:
    """``toss --catch``: caught hand tosses, the same-side probability and the exact map."""
    from rollingdisk.scenarios.hand_toss import caught_ensemble

    for opt, dest in (("--out", "out"), ("--results", "results")):
        if getattr(args, dest, None) is not None:
            raise CLIError(f"rollingdisk toss: error: {opt} is for the table; --catch prints "
                           "its result (--json for one JSON object)")
    launch = hand_launch_from_args(args, disk)
    res = caught_ensemble(disk, launch, args.n, args.seed)
    if args.json:
        print(json.dumps(res.as_dict() | {k: v for k, v in launch_fields(args, disk, launch)
                                          .items() if k not in ("e", "mu")},
                         allow_nan=False))
        return 0
    lo, hi = res.interval()
    print(f"same side  {res.same_side:9d}  p = {res.probability:.5f}  95% [{lo:.5f}, {hi:.5f}]")
    print(f"exact map  mean of p(psi) = 1/2 + arcsin(cot^2 psi)/pi over the drawn psi: "
          f"{res.mean_exact:.5f} (long-flight limit)")
    print(f"launch: {launch.describe()}")
    si = _si_line(launch, disk)
    if si:
        print(si)
    print("e, mu: not used (caught in the hand: free flight alone, no impact)")
    print(f"h = {res.h:g}, n = {res.n}, seed = {res.seed}, {res.wall_time:.1f} s",
          file=sys.stderr)
    return 0

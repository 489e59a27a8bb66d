"""``rollingdisk steady``: one steady motion (straight line, circle, spin) and its stability
(paper sections 3-4).

    $ rollingdisk steady --h 0.17 --theta0 30deg --Omega0 2
    $ rollingdisk steady --ground smooth --h 0.3 --theta0 0.5 --rP 0.4 --json
    $ rollingdisk steady --h 0.1 --motion straight --omega0 2
    $ rollingdisk steady --disk euro-1 --theta0 30deg --Omega0 60rad/s   # SI beside
    $ rollingdisk steady --disk euro-1 --motion straight --omega0 0.3m/s
    $ rollingdisk steady --h 0.2 --rim-radius 0.1 --theta0 0.4 --Omega0 2
"""

from __future__ import annotations

import json
import math

from rollingdisk.cli._args import add_motion_args, disk_from_args, motion_from_args
from rollingdisk.cli._format import disk_fields, disk_line, has_scale, si_text, with_si
from rollingdisk.cli._rounded import add_rim_radius, run_steady

LABELS = [
    ("ground", "ground"), ("h", "half-thickness / radius"), ("motion", "kind of motion"),
    ("theta0", "inclination [rad]"), ("theta0_deg", "inclination [deg]"),
    ("Omega0", "spin rate d psi/dt"), ("omega0", "rolling rate d phi/dt"),
    ("omega20", "angular velocity, omega2"), ("omega30", "angular velocity, omega3"),
    ("r_C", "radius of the circle of C"), ("r_P", "radius of the circle of P"),
    ("v_C", "speed of C"),
    ("F_y", "friction F_y = -r_C Omega0^2, points to the centre (eq. 27)"),
    ("varpi2", "varpi^2 of small oscillations"), ("stable", "stable (varpi^2 > 0)"),
    ("period", "period 2 pi / varpi"), ("growth_rate", "growth rate sqrt(-varpi^2)"),
]


def configure(sub):
    p = sub.add_parser(
        "steady",
        description="Steady motion of the disk (paper sections 3-4): give --theta0 and one of "
        "--Omega0, --rC, --rP for a circle, or --motion straight --omega0 W. Angles in "
        "radians or with a deg suffix; write negative angles as --theta0=-30deg.")
    add_motion_args(p)
    add_rim_radius(p)
    p.add_argument("--json", action="store_true", help="print one JSON object")
    return p


def run(args) -> int:
    import rollingdisk as rd

    disk = disk_from_args(args)
    if args.rim_radius is not None:  # the rounded rim: theory/rounded.py
        return run_steady(args, disk)
    motion = motion_from_args(args, "steady")
    stab = rd.stability(motion)
    rec = {**motion.as_dict(), "theta0_deg": math.degrees(motion.theta0), **stab.as_dict()}
    si = has_scale(disk)
    if si:  # SI beside every dimensional field, and the units of each
        rec = with_si(rec, motion.to_si(), stab.to_si(disk), disk_fields(disk))
    if args.json:
        print(json.dumps(rec, allow_nan=False))
        return 0
    if si:
        print(disk_line(disk))
    for key, text in LABELS:
        v = rec[key]
        if v is None:
            continue
        val = f"{v:.10g}" if isinstance(v, float) else str(v)
        if si:
            extra = rec.get(f"{key}_si")
            extra = "" if extra is None else si_text(extra, rec["units"][f"{key}_si"])
            print(f"{key:<12} {val:>18}   {extra:>20}   {text}")
        else:
            print(f"{key:<12} {val:>18}   {text}")
    print("(dimensionless: m = a = g = 1, time unit sqrt(a/g)"
          + ("; SI in the third column)" if si else ")"))
    return 0

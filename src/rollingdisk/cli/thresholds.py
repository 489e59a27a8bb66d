"""``rollingdisk thresholds``: the critical squared speeds of eqs. (42), (43), (53), (57);
for a disk with a physical size, the critical speeds in SI units beside them.

    $ rollingdisk thresholds --h 0.17
    $ rollingdisk thresholds --h 0.5 --json
    $ rollingdisk thresholds --disk euro-1
    $ rollingdisk thresholds euro-1
    $ rollingdisk thresholds --diameter 23.25mm --thickness 2.33mm --json
"""

from __future__ import annotations

import json
import math

from rollingdisk.cli._args import add_disk_options, add_json_arg, disk_from_args
from rollingdisk.cli._format import disk_fields, disk_line, has_scale, with_si

EQUATIONS = {("rough", "straight_line_omega20_sq"): "(42)",
             ("rough", "se_circle_omega30_sq"): "(43)",
             ("smooth", "straight_line_omega20_sq"): "(53)",
             ("smooth", "spin_omega30_sq"): "(57)"}

#: The rows of the SI table: (ground, key of as_dict, what crosses the threshold, field of
#: Thresholds.to_si() that gives it as a speed).
SI_ROWS = (
    ("rough", "straight_line_omega20_sq", "straight line: speed of C",
     "rough_straight_line_speed"),
    ("rough", "se_circle_omega30_sq", "SE-tilt circle: spin omega30",
     "rough_se_circle_omega30"),
    ("smooth", "straight_line_omega20_sq", "straight line: rolling rate omega20",
     "smooth_straight_line_omega20"),
    ("smooth", "spin_omega30_sq", "spin in place: spin omega30", "smooth_spin_omega30"),
)


def configure(sub):
    p = sub.add_parser(
        "thresholds",
        description="The stability thresholds of straight rolling, the circles at the "
        "static-equilibrium tilt and the spin in place (eqs. 42, 43, 53, 57): stable above. "
        "Dimensionless, as squared angular speeds in units g/a (m = a = g = 1); for a disk "
        "with a physical size (--disk, --radius/--diameter with --thickness) also as speeds "
        "in SI units: the straight-rolling threshold as the speed of C in m/s.")
    add_disk_options(p, required=True, positional=True)
    add_json_arg(p)
    return p


def run(args) -> int:
    from rollingdisk.theory import oscillations

    disk = disk_from_args(args)
    thr = oscillations.thresholds(disk)
    d = thr.as_dict()
    si = has_scale(disk)
    if args.json:
        if si:
            view = thr.to_si()
            d = with_si({**d, **{k: v for k, v in view.items()
                                 if k != "units" and not k.endswith("_si")}},
                        view, disk_fields(disk))
        print(json.dumps(d, allow_nan=False))
        return 0
    if not si:
        print(f"stability thresholds for h = {disk.h:g} (stable above):")
        for ground, rows in d.items():
            for key, v in rows.items():
                print(f"  {ground:<7} {key:<26} {v:.10g}   eq. {EQUATIONS[(ground, key)]}")
        return 0
    view = thr.to_si()
    print(disk_line(disk))
    print("stability thresholds (stable above):")
    for ground, key, what, name in SI_ROWS:
        sq = d[ground][key]
        unit = view["units"][f"{name}_si"]
        paper = view["units"][name]
        print(f"  {ground:<6} {what:<36} {view[f'{name}_si']:>10.6g} {unit:<6} "
              f"({math.sqrt(sq):.6g} {paper}; squared {sq:.10g} g/a, "
              f"eq. {EQUATIONS[(ground, key)]})")
    return 0

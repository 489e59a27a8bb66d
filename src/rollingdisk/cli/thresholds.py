"""``rollingdisk thresholds``: the critical squared speeds of eqs. (42), (43), (53), (57).

    $ rollingdisk thresholds --h 0.17
    $ rollingdisk thresholds --h 0.5 --json
"""

from __future__ import annotations

import json

from rollingdisk.cli._args import H

EQUATIONS = {("rough", "straight_line_omega20_sq"): "(42)",
             ("rough", "se_circle_omega30_sq"): "(43)",
             ("smooth", "straight_line_omega20_sq"): "(53)",
             ("smooth", "spin_omega30_sq"): "(57)"}


def configure(sub):
    p = sub.add_parser("thresholds")
    p.add_argument("--h", type=H, required=True, help="half-thickness / radius, h >= 0")
    p.add_argument("--json", action="store_true", help="print one JSON object")
    return p


def run(args) -> int:
    from rollingdisk.theory import oscillations

    d = oscillations.thresholds(args.h).as_dict()
    if args.json:
        print(json.dumps(d, allow_nan=False))
        return 0
    print(f"stability thresholds for h = {args.h:g} (stable above):")
    for ground, rows in d.items():
        for key, v in rows.items():
            print(f"  {ground:<7} {key:<26} {v:.10g}   eq. {EQUATIONS[(ground, key)]}")
    return 0

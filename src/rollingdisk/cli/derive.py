"""``rollingdisk derive``: derive the equations of motion with sympy and check every printed
equation of the paper against the derivation.

    $ rollingdisk derive --sections 2
    $ rollingdisk derive --json > table.json
"""

from __future__ import annotations

import json

from rollingdisk.cli._args import add_progress_args, show_progress


def configure(sub):
    p = sub.add_parser("derive")
    p.add_argument("--sections", choices=["all", "2"], default="all",
                   help="'2': eqs. (1)-(13), (37), (38), (49) only (fast); 'all' (default) "
                   "adds sections 3-4, eqs. (15)-(59) and the quoted numbers")
    p.add_argument("--json", action="store_true", help="print the table as JSON")
    add_progress_args(p)
    return p


def run(args) -> int:
    from rollingdisk.symbolic import check_equations, format_table

    rows = check_equations(progress=show_progress(args), sections=args.sections)
    if args.json:
        print(json.dumps([row.as_dict() for row in rows], indent=2, allow_nan=False))
    else:
        print(format_table(rows))
    return 0

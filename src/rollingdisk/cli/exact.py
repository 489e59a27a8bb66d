"""``rollingdisk exact``: the exact (integrable) motion by quadrature: status, turning
points, nutation period, precession per period, and optionally its figure.

    $ rollingdisk exact --h 0.1 --theta0 0.4 --Omega0 3 --kick 0.3
    $ rollingdisk exact --ground smooth --h 0.1 --state theta=0.3,omega3=2 --json
    $ rollingdisk exact --h 0.1 --theta0 0.4 --Omega0 3 --kick 0.3 --out exact.png
    $ rollingdisk exact --disk us-quarter --theta0 0.4 --Omega0 80rad/s --kick 2rad/s  # SI beside
"""

from __future__ import annotations

import json

from rollingdisk.cli._args import (
    add_json_arg,
    add_motion_args,
    add_perturbation_args,
    add_state_arg,
    disk_from_args,
    initial_state,
    integer,
    start_from_args,
)
from rollingdisk.cli._format import (
    disk_fields,
    disk_line,
    finite_or_none,
    has_scale,
    si_text,
    with_si,
)

KEYS = ("theta_min", "theta_max", "amplitude", "period", "frequency", "varpi", "delta_psi",
        "delta_phi", "t_end", "theta_end", "E")


def configure(sub):
    p = sub.add_parser(
        "exact",
        description="The exact (integrable) motion on rough or smooth ground by quadrature: "
        "status (bounded, steady, lift-off, edge-contact, fell-flat), theta_min, theta_max, "
        "the nutation period and the precession delta_psi per period. Start from a steady "
        "motion (--theta0 with one of --Omega0, --rC, --rP, or --motion straight --omega0 "
        "W) with --kick / --perturb, or from any state (--state theta=0.3,omega3=2).")
    g = add_motion_args(p)
    add_state_arg(g, "an arbitrary initial state by component names, as for simulate")
    add_perturbation_args(p)
    p.add_argument("--periods", type=integer("periods", 1, 1000), default=20,
                   help="periods of the rosette in --out (default 20)")
    p.add_argument("--out", type=str, default=None, metavar="FILE.png",
                   help="a figure: theta(t) over a period, the contact point's rosette, and "
                   "the backbone curve (frequency against amplitude) about the steady motion")
    add_json_arg(p)
    return p


def run(args) -> int:
    import rollingdisk as rd
    from rollingdisk.theory import exact

    disk = disk_from_args(args)
    motion = start_from_args(args, "exact")
    if args.out is not None:  # refused before the work
        from rollingdisk.plotting.plots import image_format
        from rollingdisk.util.files import check_writable

        image_format(args.out, "--out")
        check_writable(args.out, name="--out")
    if motion is not None:
        ex = exact.exact_steady(motion, perturb=args.perturb, kick=args.kick)
    else:
        ex = exact.exact_motion(disk, args.ground, initial_state(args, args.ground, "exact")[0])
    record = ex.as_dict()
    stab = None if motion is None else rd.stability(motion)
    record["varpi"] = None if stab is None or not stab.stable else stab.varpi
    record["varpi2"] = None if stab is None else stab.varpi2
    record = {k: v if k == "drift" or not isinstance(v, float) else finite_or_none(v)
              for k, v in record.items()}
    si = has_scale(disk)
    if si:
        linear = {} if stab is None else stab.to_si(disk)  # only varpi, varpi2 from it
        linear = {k: v for k, v in linear.items() if k in ("varpi_si", "varpi2_si")}
        linear["units"] = {"varpi": "sqrt(g/a)", "varpi_si": "rad/s", "varpi2": "g/a",
                           "varpi2_si": "1/s^2"}
        record = with_si(record, ex.to_si(), linear, disk_fields(disk))
        if record["varpi"] is None:  # unstable: no frequency
            record["varpi_si"] = None
    if args.out is not None:
        from rollingdisk.plotting.reports import save_exact_figure

        save_exact_figure(ex, args.out, motion=motion, kick=args.kick,
                          n_periods=args.periods)
        record["out"] = args.out
    if args.json:
        print(json.dumps(record, indent=2, allow_nan=False))
        return 0
    if si:
        print(disk_line(disk))
    print(f"status       {ex.status}")
    for key in KEYS:
        if record.get(key) is not None:
            extra = record.get(f"{key}_si") if si else None
            extra = "" if extra is None else \
                f"   {si_text(extra, record['units'][f'{key}_si']):>20}"
            print(f"{key:<12} {record[key]:>18.12g}{extra}")
    if record["drift"] is not None:
        print(f"{'drift':<12} {record['drift'][0]:>18.12g} {record['drift'][1]:.12g}"
              "   contact point's displacement over the first period (X, Y)")
        if si and record.get("drift_si") is not None:
            x, y = record["drift_si"]
            print(f"{'drift_si':<12} {x:>18.6g} {y:.6g}   (m)")
    if si:
        print("(dimensionless: m = a = g = 1, time unit sqrt(a/g); SI in the third column)")
    if ex.message:
        print(f"{'message':<12} {ex.message}")
    if args.out is not None:
        print(f"wrote {args.out}")
    return 0

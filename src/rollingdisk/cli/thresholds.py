"""``rollingdisk thresholds``: the critical squared speeds of eqs. (42), (43), (53), (57);
for a disk with a physical size, the critical speeds in SI units beside them.

    $ rollingdisk thresholds --h 0.17
    $ rollingdisk thresholds --h 0.5 --json
    $ rollingdisk thresholds --disk euro-1
    $ rollingdisk thresholds euro-1
    $ rollingdisk thresholds --diameter 23.25mm --thickness 2.33mm --json
    $ rollingdisk thresholds --disk euro-1 --rim-radius 0.3mm
    $ rollingdisk thresholds --h 0.2 --rim-radius 0.05 --json
"""

from __future__ import annotations

import json
import math

from rollingdisk.cli._args import add_disk_options, add_json_arg, disk_from_args, quantity
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
    g = add_disk_options(p, required=True, positional=True)
    g.add_argument("--rim-radius", type=quantity("rim_radius", "length", "--rim-radius",
                                                 low=0.0),
                   default=None, metavar="LENGTH",
                   help="radius rho of the rounded rim, 0 <= rho <= min(h, 1) a: a length with "
                   "a unit for a disk with a physical size (0.3mm), else in units of the radius a; "
                   "the thresholds of the rounded disk (theory/rounded.py) at its static tilt")
    add_json_arg(p)
    return p


def _rounded(disk, rho):
    """The disk with its rim rounded to ``rho`` (units of a), or one line naming the
    option and its range."""
    import dataclasses

    from rollingdisk.util.errors import ParameterError

    high = min(disk.h, 1.0)
    if not rho <= high:
        size = f" = {1e3 * high * disk.radius:.6g} mm" if has_scale(disk) else ""
        raise ParameterError(f"--rim-radius must lie in [0, min(h, 1)] = [0, {high:.6g}]{size} "
                             f"(at most half the thickness and the radius), got {rho:.6g} "
                             "(units of a)")
    return dataclasses.replace(disk, rim_radius=rho)


def _run_rounded(args, disk) -> int:
    """The thresholds of the rounded disk: text or JSON, the rim radius stated."""
    from rollingdisk.theory.rounded import rounded_thresholds

    thr = rounded_thresholds(disk)
    d = thr.as_dict()
    si = has_scale(disk)
    speeds = {"rough_straight_line_speed": ("speed", thr.rough_straight_line_speed_sq),
              "rough_se_circle_omega30": ("angular_speed", thr.rough_se_circle_omega30_sq),
              "smooth_straight_line_omega20": ("angular_speed",
                                               thr.smooth_straight_line_omega20_sq),
              "smooth_spin_omega30": ("angular_speed", thr.smooth_spin_omega30_sq)}
    if si:
        view = {k: (disk.speed_to_si if kind == "speed" else disk.angular_speed_to_si)(
            math.sqrt(sq)) for k, (kind, sq) in speeds.items()}
        units = {k: ("m/s" if speeds[k][0] == "speed" else "rad/s") for k in view}
    if args.json:
        if si:
            d = with_si({**d, "rim_radius_si": disk.rim_radius * disk.radius,
                         **{f"{k}_si": v for k, v in view.items()},
                         "units": {"rim_radius_si": "m",
                                   **{f"{k}_si": u for k, u in units.items()}}},
                        disk_fields(disk))
        print(json.dumps(d, allow_nan=False))
        return 0
    if si:
        print(disk_line(disk))
    rim = f" = {disk.rim_radius * disk.radius * 1e3:.6g} mm" if si else ""
    print(f"rounded rim: rho = {disk.rim_radius:.6g} a{rim}; static tilt "
          f"{math.degrees(thr.static_tilt):.6g} deg")
    print(f"stability thresholds for h = {disk.h:g}, rho = {disk.rim_radius:.6g} "
          "(stable above; eqs. 42, 43, 53, 57 for a rounded rim):")
    for ground in ("rough", "smooth"):
        for key, v in d[ground].items():
            print(f"  {ground:<7} {key:<26} {v:.10g}")
    if si:
        for k, v in view.items():
            print(f"  {k:<34} {v:.6g} {units[k]}")
    return 0


def run(args) -> int:
    from rollingdisk.theory import oscillations

    disk = disk_from_args(args)
    if args.rim_radius is not None:
        return _run_rounded(args, _rounded(disk, args.rim_radius))
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

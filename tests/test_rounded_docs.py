"""docs/rounded.md: its table of the 1-euro coin's thresholds is what the code computes."""

from __future__ import annotations

import math
from pathlib import Path

from rollingdisk import Disk
from rollingdisk.theory.rounded import rounded_thresholds

DOC = Path(__file__).resolve().parents[1] / "docs" / "rounded.md"
RIMS_MM = (0.0, 0.1, 0.2, 0.3, 0.5, 0.8, 1.165)


def table() -> list[str]:
    """The table's rows, from rounded_thresholds."""
    out = ["| rim radius [mm] | ρ [a] | static tilt [deg] | rough: straight rolling, speed of C "
           "[m/s] | rough: circle at the static tilt, ω₃₀ [rad/s] | smooth: straight, ω₂₀ "
           "[rad/s] | smooth: spin in place, ω₃₀ [rad/s] |",
           "|---|---|---|---|---|---|---|"]
    for mm in RIMS_MM:
        d = Disk.from_dimensions("11.625mm", "2.33mm", rim_radius=f"{mm}mm")
        t = rounded_thresholds(d)
        v = d.speed_to_si(math.sqrt(t.rough_straight_line_speed_sq))
        w = [d.angular_speed_to_si(math.sqrt(x)) for x in (
            t.rough_se_circle_omega30_sq, t.smooth_straight_line_omega20_sq,
            t.smooth_spin_omega30_sq)]
        out.append(f"| {mm:g} | {d.rim_radius:.4f} | {math.degrees(t.static_tilt):.3f} | "
                   f"{v:.4f} | {w[0]:.3f} | {w[1]:.3f} | {w[2]:.3f} |")
    return out


def test_the_table_is_computed():
    text = DOC.read_text()
    block = text.split("<!-- rounded-table -->")[1].split("<!-- /rounded-table -->")[0]
    assert block.strip().splitlines() == table()

"""The prose about Figure 4 (after eq. 47) against the library, the linearization and simulation.

The paper: "for a given h when inclination is theta0 < arctan h and the disk is leaning toward
centre point A then r_C < r_C* and the motion is stable. When the disk is leaning away from
point A the radius r_C is unlimited but the motion becomes unstable with a larger r_C. When
theta0 > arctan h and the disk is leaning toward point A the radius r_C is unlimited and the
motion is stable except for the regions near theta0 = arctan h, which become narrow with a
larger r_C. When the disk is leaning toward point A then r_C > r_C* and the motion is stable."

What holds (docs/errata.md, "Prose about Figure 4"): the last sentence must say *away*; the
instability when leaning away holds for moderate radii only — very large circles approach
straight-line rolling, stable above the threshold (42); the unstable bands next to
theta0 = arctan h first widen (up to |r_C| ~ 1) and only then narrow.
"""

import math

import numpy as np
import pytest

import rollingdisk as rd
from rollingdisk import oscillation_frequency, varpi2_rough_rC
from rollingdisk.theory.steady import r_C_star

H = 0.17
TH_SE = math.atan(H)


def _varpi2_both(theta0, r_C):
    m = rd.steady_motion(rd.Disk(H), "rough", theta0, r_C=r_C)
    a, b = rd.stability(m).varpi2, rd.varpi2_linearized(m)
    assert a == pytest.approx(b, rel=1e-8, abs=1e-10)
    return m, a


def test_leaning_away_beyond_the_se_tilt_is_stable():
    """theta0 > arctan h with r_C* < r_C < 0 (leaning away): stable (the paper says 'toward')."""
    th = np.linspace(TH_SE + 1e-3, math.pi / 2 - 1e-3, 300)[:, None]
    rs = r_C_star(H, th)
    assert np.all(rs[th[:, 0] > 0.32] < 0)  # zero of r_C* at arctan(6h/(3+4h^2)) = 0.316
    r_C = np.linspace(0.01, 0.99, 60)[None, :] * np.minimum(rs, 0.0)
    inside = np.broadcast_to(rs < 0, r_C.shape)
    assert np.all(varpi2_rough_rC(H, th, r_C)[inside] > 0)
    _, v = _varpi2_both(0.5, -0.02)
    assert v > 0


def test_leaning_away_unstable_at_moderate_radii_stable_again_at_large_ones():
    _, v_mid = _varpi2_both(0.05, -0.5)
    assert v_mid < 0
    m, v_far = _varpi2_both(0.05, -50.0)
    assert v_far > 0
    # a large circle is nearly a straight line: omega20^2 far above the threshold (42)
    assert m.omega20 ** 2 > rd.thresholds(H).rough_straight_line_omega20_sq
    # and the simulation oscillates at the predicted frequency
    tr = rd.simulate_steady(m, 30.0, kick=1e-7, method="dop853")  # DOP853's dense points
    assert tr.status == "completed"
    assert oscillation_frequency(tr) == pytest.approx(math.sqrt(v_far), rel=1e-5)


def test_unstable_bands_next_to_the_se_tilt_widen_then_narrow():
    th = np.linspace(TH_SE + 1e-3, math.pi / 2 - 1e-3, 400)[:, None]

    def unstable_share(lo, hi):
        v = varpi2_rough_rC(H, th, np.geomspace(lo, hi, 60)[None, :])
        return float(np.mean(v < 0))

    small, mid, large = unstable_share(0.01, 0.1), unstable_share(0.1, 1), unstable_share(10, 100)
    assert mid > 3 * small and mid > 3 * large

"""Every number quoted in sections 3-4 of the paper, next to the value the library computes.

Each row: (what, library value, paper value, tolerance).  Where the paper is wrong the test
asserts the correct value and says so in a comment (see docs/errata.md).
The library values come from the corrected closed forms, which tests/test_stability.py
checks against a numerical linearization of the derived equations and against simulation.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp
from scipy.optimize import brentq, minimize_scalar

from rollingdisk import (
    Disk,
    circle_coefficients,
    critical_omega30_sq,
    equations_of_motion,
    stability,
    thresholds,
    varpi2_circle,
    varpi2_linearized,
)
from rollingdisk.theory.steady import Omega0_sq, r_C_star, se_circle_radius, steady_motion

EPS = 1e-12


def all_stable(ground, h, t):
    """P1 >= 0 or Delta < 0 (regions (46), (59)) as a float in {0, 1}."""
    P0, P1, P2, _ = circle_coefficients(h, ground, t)
    return float((P1 >= 0) or (P1 * P1 - 4 * P0 * P2 < 0))


def right_boundary(ground, h):
    """Largest theta0 below which some omega30 is unstable (right edge of Fig. 5 / 7)."""
    th = np.linspace(1e-6, math.pi / 2 - 1e-10, 100001)
    P0, P1, P2, _ = circle_coefficients(h, ground, th)
    ok = (P1 >= 0) | (P1 * P1 - 4 * P0 * P2 < 0)
    i = np.nonzero(~ok)[0].max()
    return brentq(lambda t: all_stable(ground, h, t) - 0.5, th[i], th[i + 1], xtol=1e-15)


def sup_critical_omega30_sq(ground):
    """Largest omega30^2 on the varpi^2 = 0 surface over h in [0, 1e4], theta0 in (0, pi/2)."""
    H = np.concatenate([np.linspace(0, 5, 501), np.geomspace(5, 1e4, 200)])[:, None]
    T = np.concatenate([[1e-9], np.linspace(1e-4, math.pi / 2 - 1e-4, 1500)])[None, :]
    lo, hi = critical_omega30_sq(H, ground, T)
    return float(np.nanmax(hi))


def max_se_radius():
    res = minimize_scalar(lambda h: -se_circle_radius(h), bounds=(0, math.sqrt(3) / 2),
                          method="bounded", options={"xatol": 1e-12})
    return res.x, -res.fun


h_max, r_max = max_se_radius()
t_rough = thresholds(0.0)
t_half = thresholds(math.sqrt(3) / 2)
theta_186 = brentq(lambda t: all_stable("rough", 0.0, t) - 0.5, 0.1, 0.6, xtol=1e-15)
theta_215 = brentq(lambda t: all_stable("smooth", 0.0, t) - 0.5, 0.1, 0.6, xtol=1e-15)
_, hi_215 = critical_omega30_sq(0.0, "smooth", theta_215 - 1e-9)
_, hi_half = critical_omega30_sq(0.5, "smooth", 0.0)  # theta0 = 0 means 0+ in maps
_, hi_h0 = critical_omega30_sq(0.0, "smooth", 0.0)
_, hi_rough_h0 = critical_omega30_sq(0.0, "rough", 0.0)

# (what, library, paper, abs tolerance)
ROWS = [
    ("(42) h=0: rough straight line omega20^2 >", t_rough.rough_straight_line_omega20_sq,
     1 / 3, EPS),
    ("(43) h=0: rough SE circle omega30^2 >", t_rough.rough_se_circle_omega30_sq, 4 / 5, EPS),
    ("(43) h=sqrt(3)/2: spin |omega30| >", math.sqrt(t_half.rough_se_circle_omega30_sq),
     0.580, 5e-4),
    ("(43) h=sqrt(3)/2: spin |omega30| > sqrt(8 sqrt7/63)",
     math.sqrt(t_half.rough_se_circle_omega30_sq), math.sqrt(8 * math.sqrt(7) / 63), EPS),
    ("(46) h=0: all-omega30 stable above theta0 [deg]", math.degrees(theta_186), 18.6, 0.05),
    ("(46) h=0: ... [rad]", theta_186, 0.325, 5e-4),
    ("(46) h=0: tan theta0 = sqrt(198 sqrt5 - 429)/11", math.tan(theta_186),
     math.sqrt(198 * math.sqrt(5) - 429) / 11, 1e-10),
    ("(30) max r_C for h < sqrt(3)/2", r_max, 0.0442, 5e-5),
    ("(30) ... at h", h_max, 0.425, 5e-4),
    ("(30) ... h = sqrt(33 sqrt93 - 231)/22", h_max,
     math.sqrt(33 * math.sqrt(93) - 231) / 22, 1e-7),
    ("(30) ... at theta0 [deg]", math.degrees(math.atan(h_max)), 23.0, 0.05),
    ("(30) r_C as h -> inf", se_circle_radius(1e7), -1 / 3, 1e-6),
    ("(30) r_C = 0 at h =", brentq(se_circle_radius, 0.5, 1.0, xtol=1e-15),
     math.sqrt(3) / 2, 1e-12),
    ("(30) spin in place at theta0 [deg]", math.degrees(math.atan(math.sqrt(3) / 2)),
     40.893, 5e-4),
    ("(30) spin in place at theta0 [rad]", math.atan(math.sqrt(3) / 2), 0.714, 5e-4),
    ("(53) h=0: smooth straight line omega20^2 >",
     t_rough.smooth_straight_line_omega20_sq, 1.0, EPS),
    ("(57) h=0: smooth spin omega30^2 >", t_rough.smooth_spin_omega30_sq, 4.0, EPS),
    ("(59) h=0: all-omega30 stable above theta0 [deg]", math.degrees(theta_215), 21.5, 0.05),
    ("(59) h=0: ... [rad]", theta_215, 0.375, 5e-4),
    ("(59) h=0: tan theta0 = sqrt(6 sqrt3 - 9)/3", math.tan(theta_215),
     math.sqrt(6 * math.sqrt(3) - 9) / 3, 1e-10),
    ("(59) h=0: limit omega30 at that angle", math.sqrt(hi_215), 1.167, 5e-4),
    ("Fig. 8: theta0=0, h=0: omega30 on varpi^2=0", math.sqrt(hi_h0), 2.0, 1e-9),
    ("Fig. 8: theta0=0, h=1/2: omega30 on varpi^2=0", math.sqrt(hi_half), math.sqrt(1.5),
     1e-6),
    ("Fig. 6: theta0=0, h=0: omega30 on varpi^2=0", math.sqrt(hi_rough_h0), math.sqrt(0.8),
     1e-9),
    ("(32) max r_C* = h/3 at theta0 = 0 (h = 0.7)", float(r_C_star(0.7, 0.0)), 0.7 / 3, EPS),
    ("(32) min r_C* at h=0 (theta0 -> pi/2)", float(r_C_star(0.0, math.pi / 2 - 1e-9)),
     -1 / 6, 1e-9),
    ("(32) zero of r_C* at arctan(6h/(3+4h^2)) (h = 0.7)",
     brentq(lambda t: float(r_C_star(0.7, t)), 0.01, 1.5, xtol=1e-15),
     math.atan(6 * 0.7 / (3 + 4 * 0.49)), 1e-12),
    ("(46) asymptote: tan(theta0)/h at h = 1e4", math.tan(right_boundary("rough", 1e4)) / 1e4,
     1.5, 1e-3),
    ("(59) asymptote: tan(theta0)/h at h = 1e4", math.tan(right_boundary("smooth", 1e4)) / 1e4,
     4 / 3, 1e-3),
]


@pytest.mark.parametrize("what,library,paper,tol", ROWS, ids=[r[0] for r in ROWS])
def test_quoted_number(what, library, paper, tol):
    assert library == pytest.approx(paper, abs=tol)


def test_r_C_star_minimum_tends_to_minus_h_over_3():
    """Text after (32): min r_C* -> -h/3 for great h (slowly: the ratio is ~0.9997 at 1e6)."""
    ratios = []
    for h in (1e2, 1e4, 1e6):
        t = np.linspace(1e-9, math.pi / 2 - 1e-12, 400001)
        ratios.append(float(np.min(r_C_star(h, t))) / (-h / 3))
    assert ratios[0] < ratios[1] < ratios[2] < 1.0
    assert ratios[2] == pytest.approx(1.0, abs=1e-3)


def test_omega0_asymptotes_after_33():
    """Omega0^2 ~ 12 tan(theta0)/(3 + 4h^2) for r_C = 0 and -> 1/(h r_C) otherwise."""
    h, t = 0.3, math.pi / 2 - 1e-7
    assert float(Omega0_sq(h, t, 0.0)) == pytest.approx(12 * math.tan(t) / (3 + 4 * h * h),
                                                        rel=1e-5)
    assert float(Omega0_sq(h, t, 0.5)) == pytest.approx(1 / (h * 0.5), rel=1e-5)


def test_rough_large_h_limit_at_theta0_zero():
    """Text before Fig. 6: for h -> inf at theta0 = 0, varpi^2 -> (omega30^2 - 1)/2."""
    w = 1.3
    assert float(varpi2_circle(1e6, "rough", 1e-15, w)) == pytest.approx(0.5 * (w * w - 1),
                                                                           rel=1e-5)


def test_eq48_asymptote_is_misprinted():
    """(48) prints varpi^2 ~ 2 omega30^2 (3+16h^2)/(15+16h^2) tan^2 theta0.

    Derived (and confirmed by linearization): the factor 2 is wrong; for h > 0 the limit of
    varpi^2 / (omega30^2 tan^2 theta0) is (3+16h^2)/(15+16h^2), and for h = 0 it is 1/3.
    """
    w = 0.7
    t = math.pi / 2 - 1e-7
    for h in (0.5, 2.0):
        ratio = float(varpi2_circle(h, "rough", t, w)) / (w * w * math.tan(t) ** 2)
        assert ratio == pytest.approx((3 + 16 * h * h) / (15 + 16 * h * h), rel=1e-3)
        assert ratio != pytest.approx(2 * (3 + 16 * h * h) / (15 + 16 * h * h), rel=0.1)
    ratio0 = float(varpi2_circle(0.0, "rough", t, w)) / (w * w * math.tan(t) ** 2)
    assert ratio0 == pytest.approx(1 / 3, rel=1e-3)
    m = steady_motion(Disk(h=2.0), "rough", 1.5, Omega0=w / math.cos(1.5))
    assert varpi2_linearized(m) == pytest.approx(stability(m).varpi2, rel=1e-8)


def test_conclusion_rough_omega30_sq_above_1():
    """Conclusion, rough ground: omega30^2 > 1 is stable for every h, theta0 (confirmed).

    The varpi^2 = 0 surface stays below 1 and approaches it as h -> inf at theta0 -> 0.
    """
    sup = sup_critical_omega30_sq("rough")
    assert 0.999 < sup <= 1.0


def test_conclusion_smooth_omega30_sq_above_2_is_wrong():
    """Conclusion, smooth ground: the paper says omega30^2 > 2 suffices.  It does not.

    The varpi^2 = 0 surface reaches omega30^2 = 4 at h = 0, theta0 -> 0 (the paper's own
    (57) at h = 0), and exceeds 2 for every h < 0.948; correct: omega30^2 > 4 suffices.
    Counterexample confirmed by simulation: h = 0.1, theta0 = 3 deg, omega30^2 = 3.
    """
    sup = sup_critical_omega30_sq("smooth")
    assert sup == pytest.approx(4.0, abs=1e-6)  # paper: 2
    h, t, w = 0.1, math.radians(3.0), math.sqrt(3.0)
    m = steady_motion(Disk(h=h), "smooth", t, Omega0=w / math.cos(t))
    s = stability(m)
    assert not s.stable
    assert varpi2_linearized(m) == pytest.approx(s.varpi2, rel=1e-8)
    y0 = m.initial_state()
    y0[5] += 1e-8
    T = math.log(1e4) / s.growth_rate
    sol = solve_ivp(equations_of_motion(Disk(h=h), "smooth"), (0, T), y0, method="DOP853",
                    rtol=1e-12, atol=1e-14)
    assert abs(sol.y[5, -1] - t) > 1e-5  # grew by > 1e3

"""Steady motions (section 3) checked against the derived equations of motion.

Source of truth: the reduced equations (38) / (49) in ``rollingdisk.model.equations`` (confirmed
against a Newton-Euler derivation), the kinematics (1)-(2), the contact force (8), (11),
and direct integration with scipy's ``solve_ivp``.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.integrate import solve_ivp

from conftest import SIGN, THETA, H
from rollingdisk import Disk, contact_force, contact_point, equations_of_motion, omega_dot
from rollingdisk.theory.steady import (
    NoSteadyMotion,
    Omega0_sq,
    SteadyMotion,
    r_C_star,
    se_circle_radius,
    steady_motion,
    straight_line,
)


def residual_scale(m: SteadyMotion) -> float:
    """Size of the individual terms of d omega1/dt, to make the 1e-10 test relative."""
    h, t, w2, w3 = m.h, m.theta0, m.omega20, m.omega30
    ht = m.h_tilde
    p = math.tan(t)
    if m.ground == "rough":
        terms = (abs(6 * (3 + 2 * ht * p) * w2 * w3),
                 abs(((3 + 16 * h * h) * p + 12 * ht) * w3 ** 2),
                 12 * abs(math.sin(t)) + 12 * h)
    else:
        k1 = 0.25 + h * h / 3
        terms = (abs(0.5 * w2 * w3), abs(k1 * w3 * w3 * p), 1 + h)
    return 1.0 + max(terms)


def assert_steady(m: SteadyMotion, tol: float = 1e-10) -> None:
    disk = Disk(h=m.h)
    d = omega_dot(disk, m.ground, m.theta0, 0.0, m.omega20, m.omega30)
    scale = residual_scale(m)
    assert all(abs(float(x)) <= tol * scale for x in d), (d, scale, m)
    y = m.initial_state()
    f = equations_of_motion(disk, m.ground)(0.0, y)
    names = ("theta", "omega1", "omega2", "omega3")
    idx = (3, 5, 6, 7) if m.ground == "rough" else (5, 7, 8, 9)
    for n, i in zip(names, idx, strict=True):
        assert abs(f[i]) <= tol * scale, (n, f[i])
    # psi' = Omega0, phi' = omega0 (eq. 15)
    ipsi, iphi = (2, 4) if m.ground == "rough" else (4, 6)
    assert f[ipsi] == pytest.approx(m.Omega0, rel=1e-12, abs=1e-12)
    assert f[iphi] == pytest.approx(m.omega0, rel=1e-12, abs=1e-12 * scale)
    # C moves on the circle of radius r_C about the origin A: dC/dt = Omega0 z x (C - A)
    if m.motion != "straight":
        X, Y = y[0], y[1]
        assert f[0] == pytest.approx(-m.Omega0 * Y, rel=1e-10, abs=1e-10 * scale)
        assert f[1] == pytest.approx(m.Omega0 * X, rel=1e-10, abs=1e-10 * scale)
        assert math.hypot(X, Y) == pytest.approx(abs(m.r_C), abs=1e-15)
        XP, YP = contact_point(disk, m.ground, y)
        assert math.hypot(XP, YP) == pytest.approx(abs(m.r_P), rel=1e-12, abs=1e-12)
        assert m.v_C == pytest.approx(abs(m.r_C * m.Omega0), rel=1e-12, abs=1e-14)
    # eqs. (19), (27): F_x = 0, F_y = -r_C Omega0^2 (0 on smooth ground), F_z = 1
    Fx, Fy, Fz = contact_force(disk, m.ground, y)
    assert abs(Fx) <= tol * scale
    assert Fy == pytest.approx(m.F_y, rel=1e-9, abs=tol * scale)
    assert Fz == pytest.approx(1.0, abs=tol * scale)


# ------------------------------------------------------------------ property tests
@settings(max_examples=150, deadline=None)
@given(h=H, theta0=THETA, lnW=st.floats(-3.0, 3.0), sgn=SIGN, lean=SIGN,
       ground=st.sampled_from(["rough", "smooth"]))
def test_circle_from_Omega0_is_steady(h, theta0, lnW, sgn, lean, ground):
    m = steady_motion(Disk(h=h), ground, lean * theta0, Omega0=sgn * math.exp(lnW))
    assert_steady(m)


@settings(max_examples=150, deadline=None)
@given(h=H, theta0=THETA, lnr=st.floats(-6.0, 3.0), lean=SIGN, use_rP=st.booleans())
def test_rough_circle_from_radius_is_steady(h, theta0, lnr, lean, use_rP):
    theta0 *= lean
    disk = Disk(h=h)
    star = float(r_C_star(h, theta0))
    ht = h * lean
    if abs(math.tan(theta0) - ht) < 1e-6:
        return
    side = 1.0 if (math.tan(theta0) - ht) > 0 else -1.0  # eq. (32): which side is allowed
    r_C = star + side * math.exp(lnr)
    if use_rP:
        y_P = math.sin(theta0) - ht * math.cos(theta0)
        m = steady_motion(disk, "rough", theta0, r_P=r_C + y_P)
    else:
        m = steady_motion(disk, "rough", theta0, r_C=r_C)
    assert m.r_C == pytest.approx(r_C, rel=1e-9, abs=1e-12)
    assert m.Omega0 > 0
    assert float(Omega0_sq(h, theta0, r_C)) == pytest.approx(m.Omega0 ** 2, rel=1e-12)
    assert_steady(m)
    # on the wrong side of r_C* there is no steady circle
    with pytest.raises(NoSteadyMotion, match="need r_"):
        steady_motion(disk, "rough", theta0, r_C=star - side * math.exp(lnr))


@settings(max_examples=60, deadline=None)
@given(h=H, omega0=st.floats(-10, 10), ground=st.sampled_from(["rough", "smooth"]),
       lean=st.sampled_from([1, -1]))
def test_straight_line_is_steady(h, omega0, ground, lean):
    m = straight_line(Disk(h=h), ground, omega0, lean=lean)
    assert m.theta0 == pytest.approx(lean * math.atan(h))
    assert m.v_C == pytest.approx(abs(omega0))
    assert_steady(m)


@settings(max_examples=60, deadline=None)
@given(h=H, theta0=THETA, W=st.floats(0.1, 10.0), ground=st.sampled_from(["rough", "smooth"]))
def test_mirror_symmetry(h, theta0, W, ground):
    """theta0 -> -theta0: Omega0, omega30 and r_C change sign, omega20 and omega0 do not."""
    a = steady_motion(Disk(h=h), ground, theta0, Omega0=W)
    b = steady_motion(Disk(h=h), ground, -theta0, Omega0=-W)
    assert b.omega20 == pytest.approx(a.omega20, rel=1e-12, abs=1e-12)
    assert b.omega0 == pytest.approx(a.omega0, rel=1e-12, abs=1e-12)
    assert b.omega30 == pytest.approx(-a.omega30)
    assert b.r_C == pytest.approx(-a.r_C, rel=1e-12, abs=1e-12)
    assert b.r_P == pytest.approx(-a.r_P, rel=1e-12, abs=1e-12)


# ------------------------------------------------------------------ special cases
@pytest.mark.parametrize("h", [0.0, 0.2, math.sqrt(3) / 2, 1.5, 4.0])
def test_se_circles(h):
    """At tan(theta0) = h every Omega0 gives r_C = r_P = eq. (30)."""
    disk = Disk(h=h)
    theta0 = math.atan(h)
    r = se_circle_radius(h)
    for W in (0.3, -2.0, 7.0):
        m = steady_motion(disk, "rough", theta0, Omega0=W)
        assert m.r_C == pytest.approx(r, abs=1e-12)
        assert m.r_P == pytest.approx(r, abs=1e-12)
        assert m.omega0 == pytest.approx(-r * W, abs=1e-12)  # eq. (30)_1
        assert_steady(m)
    if h not in (0.0, math.sqrt(3) / 2):
        assert m.motion == "circle"
        with pytest.raises(NoSteadyMotion, match="eq. 30"):
            steady_motion(disk, "rough", theta0, r_C=r + 0.1)
        with pytest.raises(ValueError, match="give Omega0"):
            steady_motion(disk, "rough", theta0, r_C=r)
    else:
        assert m.motion == "spin"


def test_spin_in_place():
    """Rough: spinning in place at h = sqrt(3)/2, theta0 = 40.893 deg; smooth: any h at SE."""
    h = math.sqrt(3) / 2
    m = steady_motion(Disk(h=h), "rough", math.atan(h), Omega0=3.0)
    assert m.motion == "spin" and m.omega0 == pytest.approx(0.0, abs=1e-12)
    for hh in (0.0, 0.4, 2.0):
        s = steady_motion(Disk(h=hh), "smooth", math.atan(hh), Omega0=2.0)
        assert s.motion == "spin"
        # text after (35): omega0 = -(1/2 - 2h^2/3) Omega0 sin(theta0)
        assert s.omega0 == pytest.approx(-(0.5 - 2 * hh * hh / 3) * 2.0 * math.sin(s.theta0))
        assert_steady(s)


def test_rough_rC_zero_uses_corrected_eq33():
    """r_C = 0: Omega0^2 = 12 (p - h) / ((3 + 4h^2) sin - 6h cos); the printed 12h is wrong."""
    h, t = 0.3, 1.0
    m = steady_motion(Disk(h=h), "rough", t, r_C=0.0)
    expect = 12 * (math.tan(t) - h) / ((3 + 4 * h * h) * math.sin(t) - 6 * h * math.cos(t))
    assert m.Omega0 ** 2 == pytest.approx(expect, rel=1e-12)
    printed = 12 * (math.tan(t) - h) / ((3 + 4 * h * h) * math.sin(t) - 12 * h * math.cos(t))
    assert abs(m.Omega0 ** 2 - printed) > 0.1
    assert m.F_y == pytest.approx(0.0, abs=1e-14) and m.r_P == pytest.approx(m.y_P0)
    assert_steady(m)


def test_errors():
    d = Disk(h=0.3)
    with pytest.raises(ValueError, match="exactly one"):
        steady_motion(d, "rough", 0.5)
    with pytest.raises(ValueError, match="exactly one"):
        steady_motion(d, "rough", 0.5, Omega0=1.0, r_C=1.0)
    with pytest.raises(ValueError, match="theta0"):
        steady_motion(d, "rough", 2.0, Omega0=1.0)
    with pytest.raises(ValueError, match="line"):
        steady_motion(d, "rough", 0.0, Omega0=1.0)
    with pytest.raises(ValueError, match="ground"):
        steady_motion(d, "icy", 0.5, Omega0=1.0)
    with pytest.raises(NoSteadyMotion, match="arctan"):
        steady_motion(d, "rough", 0.5, Omega0=0.0)
    with pytest.raises(NoSteadyMotion, match="r_C = 0"):
        steady_motion(d, "smooth", 0.5, r_C=1.0)
    with pytest.raises(NoSteadyMotion, match="v_Cx0 = omega0"):
        straight_line(d, "rough", 1.0, v_Cx0=2.0)
    # theta0 = 0.2 < arctan(0.3): circles need r_C < r_C*
    star = float(r_C_star(0.3, 0.2))
    with pytest.raises(NoSteadyMotion, match=f"r_C < {star:.6g}"):
        steady_motion(d, "rough", 0.2, r_C=star + 1.0)
    with pytest.raises(NoSteadyMotion):
        steady_motion(d, "rough", 0.2, r_C=star)
    # a thin upright disk (h = 0, theta0 = 0) may spin in place
    assert steady_motion(Disk(h=0.0), "rough", 0.0, Omega0=2.0).motion == "spin"


def test_smooth_straight_line_any_velocity():
    m = straight_line(Disk(h=0.5), "smooth", 1.0, v_Cx0=0.3, v_Cy0=-2.0)
    y = m.initial_state(psi0=0.4)
    f = equations_of_motion(Disk(h=0.5), "smooth")(0.0, y)
    assert np.allclose(f[5:], [0, 1.0, 0, 0, 0], atol=1e-14)
    assert np.hypot(f[0], f[1]) == pytest.approx(m.v_C)


def test_vectorized_maps():
    th = np.linspace(-1.5, 1.5, 8)[:, None]
    rc = np.linspace(-2, 2, 5)[None, :]
    Om = Omega0_sq(0.4, th, rc)
    assert Om.shape == (8, 5)
    for i in range(7):
        for j in range(5):
            if Om[i, j] > 0:
                m = steady_motion(Disk(h=0.4), "rough", float(th[i, 0]), r_C=float(rc[0, j]))
                assert m.Omega0 ** 2 == pytest.approx(Om[i, j], rel=1e-12)
                assert_steady(m)  # the derived equations vanish there: the map is right
                assert m.r_C == pytest.approx(float(rc[0, j]), rel=1e-12, abs=1e-14)
            elif np.isfinite(Om[i, j]):
                with pytest.raises(NoSteadyMotion):
                    steady_motion(Disk(h=0.4), "rough", float(th[i, 0]), r_C=float(rc[0, j]))
    # outside the domain and at the SE tilt: NaN on a map, refused at a single point
    assert np.isnan(Omega0_sq(0.4, np.array([2.0]), 1.0)[0])
    assert np.isnan(r_C_star(np.array([-1.0]), 0.3)[0])
    assert np.isnan(Omega0_sq(0.4, np.array([math.atan(0.4)]), 1.0)[0])
    with pytest.raises(ValueError, match="theta0 must lie in"):
        Omega0_sq(0.4, 2.0, 1.0)
    with pytest.raises(ValueError, match="h must lie in"):
        r_C_star(-1.0, 0.3)
    with pytest.raises(ValueError, match="static-equilibrium tilt"):
        Omega0_sq(0.4, math.atan(0.4), 1.0)


def test_single_point_validation():
    disk = Disk(h=0.3)
    with pytest.raises(ValueError, match=r"theta0 must lie in \(-pi/2, 0\) or \(0, pi/2\)"):
        steady_motion(disk, "rough", 0.0, Omega0=1.0)
    with pytest.raises(ValueError, match="lean must be 1 or -1"):
        straight_line(disk, "rough", 1.0, lean=True)
    with pytest.raises(NoSteadyMotion, match="static-equilibrium tilt"):
        straight_line(disk, "rough", 1.0, theta0=0.5)
    assert straight_line(disk, "rough", 1.0, theta0=-math.atan(0.3)).theta0 < 0
    with pytest.raises(ValueError, match="h must"):
        se_circle_radius(-1.0)
    with pytest.raises(ValueError, match="exactly one of Omega0, r_C, r_P"):
        steady_motion(disk, "rough", 0.3, Omega0=1.0, r_C=1.0)
    with pytest.raises(NoSteadyMotion, match="floating-point range"):
        steady_motion(disk, "rough", 0.5, Omega0=1e-300)


def test_as_dict_round_trip():
    m = steady_motion(Disk(h=0.3), "rough", 0.6, r_C=1.5)
    d = m.as_dict()
    d.pop("mu_required")  # derived from the fields, not a field
    assert d["h"] == 0.3 and "disk" not in d
    assert SteadyMotion(disk=m.disk, **{k: v for k, v in d.items() if k != "h"}) == m
    assert straight_line(Disk(h=0.3), "rough", 2.0).as_dict()["r_C"] is None


# ------------------------------------------------------------------ simulation
@pytest.mark.parametrize("ground,h,theta0,kw", [
    ("rough", 0.3, 0.6, {"r_C": 1.5}),
    ("rough", 0.1, -0.4, {"Omega0": -2.5}),
    ("smooth", 0.5, 0.9, {"Omega0": 3.0}),
])
def test_simulated_path_is_the_predicted_circle(ground, h, theta0, kw):
    m = steady_motion(Disk(h=h), ground, theta0, **kw)
    f = equations_of_motion(Disk(h=h), ground)
    T = 2 * 2 * math.pi / abs(m.Omega0)
    sol = solve_ivp(f, (0, T), m.initial_state(psi0=0.3), rtol=1e-11, atol=1e-12,
                    dense_output=True)
    t = np.linspace(0, T, 50)
    y = sol.sol(t)
    assert np.allclose(np.hypot(y[0], y[1]), abs(m.r_C), atol=1e-7)
    XP, YP = contact_point(Disk(h=h), ground, y)
    assert np.allclose(np.hypot(XP, YP), abs(m.r_P), atol=1e-7)
    itheta = 3 if ground == "rough" else 5
    assert np.allclose(y[itheta], m.theta0, atol=1e-8)

"""The rounded rim (issue 34): the Disk field, the contact geometry, the kernels.

Independent checks: at rho = 0 the kernels are the library's sharp-disk equations (38),
(49); the centre height's derivative is -y_P (the contact is the lowest point); energy is
conserved along the kernels (complex-step derivative of E along the flow); a sphere
(h = rho = 1) keeps its angular velocity in the inertial frame (its closed form). The
sympy derivations are held against the kernels in tests/test_rounded_derivation.py.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from rollingdisk import Disk
from rollingdisk.model.equations import rough_omega_dot, smooth_omega_dot
from rollingdisk.model.geometry import contact_geometry, inertia
from rollingdisk.model.rim import (
    centre_height,
    contact_part,
    rim_contact,
    rim_inertia,
    rounded_energy,
    rounded_normal_force,
    rounded_omega_dot,
)
from rollingdisk.util.errors import ParameterError


def _random(rng, n, h_max=2.0):
    for _ in range(n):
        h = rng.uniform(0.0, h_max)
        yield (h, rng.uniform(0.0, min(h, 1.0)), rng.uniform(-1.4, 1.4) or 0.3,
               *rng.normal(scale=1.5, size=3))


# -- the Disk field -----------------------------------------------------------------------
def test_disk_default_rim_is_sharp_and_repr_unchanged():
    d = Disk(0.17)
    assert d.rim_radius == 0.0
    assert repr(d) == "Disk(h=0.17, radius=None, mass=None, gravity=9.80665)"
    assert "rim_radius=0.05" in repr(Disk(0.17, rim_radius=0.05))
    assert Disk(0.17, rim_radius=0.05) != d


@pytest.mark.parametrize("bad", [-0.01, 0.2, float("nan")])
def test_disk_rim_radius_range(bad):
    with pytest.raises(ParameterError, match=r"rim_radius.*\[0, "):
        Disk(0.17, rim_radius=bad)
    with pytest.raises(ParameterError, match=r"rim_radius must lie in \[0, min\(h, 1\)\]"):
        Disk(0.17, rim_radius=0.2)
    with pytest.raises(ParameterError, match=r"= \[0, 1\]"):  # the arcs fit in the radius
        Disk(3.0, rim_radius=1.5)
    assert Disk(3.0, rim_radius=1.0).rim_radius == 1.0


def test_disk_rim_radius_with_units():
    coin = Disk(h=0.1, radius="11.625mm", rim_radius="0.3mm")
    assert coin.rim_radius == pytest.approx(0.3 / 11.625, rel=1e-12)
    with pytest.raises(ParameterError, match="rim_radius.*radius"):
        Disk(h=0.1, rim_radius="0.3mm")
    with pytest.raises(ParameterError, match="rim_radius"):
        Disk(h=0.1, radius="11.625mm", rim_radius="2mm")  # > h a
    d = Disk.from_dimensions("23.25mm", "2.33mm", rim_radius="0.3mm")
    assert d.rim_radius == pytest.approx(0.3 / 23.25, rel=1e-12)
    assert Disk(0.1, radius=0.01, rim_radius="0.05a").rim_radius == 0.05  # units of a
    assert Disk(0.1, radius=0.01, rim_radius="0mm").rim_radius == 0.0
    pint = pytest.importorskip("pint")
    q = pint.UnitRegistry().Quantity(0.3, "mm")
    assert Disk(0.1, radius="11.625mm", rim_radius=q).rim_radius == pytest.approx(0.3 / 11.625)
    with pytest.raises(ParameterError, match="rim_radius must be a length"):
        Disk(0.1, radius="11.625mm", rim_radius="0.3 s")


# -- geometry --------------------------------------------------------------------------------
def test_rho_zero_is_eq_4_and_eq_10_exactly():
    for h in (0.0, 0.17, 0.5, 3.0):
        assert rim_inertia(h, 0.0) == inertia(h)
        for th in (-1.2, -0.3, 0.0, 0.4, 1.5):
            ht, s, c, p, y_P, z_P = contact_geometry(h, th)
            hp, A, H, y, z = rim_contact(h, 0.0, th)
            assert (hp, A, H) == (ht, 1.0, ht)
            assert y == pytest.approx(y_P, abs=1e-16) and z == pytest.approx(z_P, abs=1e-16)


def test_contact_is_lowest_point_and_continuous():
    rng = np.random.default_rng(3)
    for h, rho, th, *_ in _random(rng, 200):
        # dZ_C/dtheta = -y_P by complex step: the contact point has no vertical velocity
        dz = centre_height(h, rho, th + 1e-30j).imag / 1e-30
        assert dz == pytest.approx(-rim_contact(h, rho, th)[3], abs=1e-13)
        # the contact is below every other point of the rim arcs and the tread
        hp, A, H, y_P, z_P = rim_contact(h, rho, th)
        b = np.linspace(0.0, math.pi / 2, 101)
        for side in (1.0, -1.0):
            eta = side * ((h - rho) + rho * np.sin(b))  # arc points in (radial, axial)
            r = (1.0 - rho) + rho * np.cos(b)
            height = -(r * math.cos(th)) + eta * math.sin(th)  # below C is negative
            assert np.all(height >= z_P - 1e-12)
    # at rho = h the contact moves continuously through theta = 0
    y0 = [rim_contact(0.3, 0.3, t)[3] for t in (-1e-9, 1e-9)]
    assert abs(y0[0] - y0[1]) < 1e-8
    assert contact_part(0.3, 0.1, 0.2) == "arc" and contact_part(0.3, 0.1, 0.0) == "tread"
    assert contact_part(0.3, 0.0, 0.2) == "edge" and contact_part(0.3, 0.3, 0.0) == "arc"
    assert contact_part(0.3, 0.1, math.pi / 2) == "face"


def test_inertia_limits():
    assert rim_inertia(1.0, 1.0) == pytest.approx((0.4, 0.4), abs=1e-14)  # the sphere
    # a small rim changes eq. (10) by O(rho^2); rounding takes mass from the rim
    k1, k2 = rim_inertia(0.2, 1e-4)
    assert abs(k2 - 0.5) < 1e-7 and k2 < 0.5 and abs(k1 - inertia(0.2)[0]) < 1e-7


# -- equations of motion --------------------------------------------------------------------
def test_rho_zero_kernels_are_the_sharp_equations():
    rng = np.random.default_rng(7)
    for h, _, th, w1, w2, w3 in _random(rng, 500):
        k1, k2 = rim_inertia(h, 0.0)
        for rough, sharp in ((True, rough_omega_dot), (False, smooth_omega_dot)):
            a = np.array(rounded_omega_dot(rough, h, 0.0, k1, k2, th, w1, w2, w3))
            b = np.array(sharp(h, th, w1, w2, w3))
            assert np.max(np.abs(a - b)) <= 4e-15 * max(1.0, np.max(np.abs(b)))


@pytest.mark.parametrize("rough", [True, False])
def test_energy_is_conserved_along_the_kernels(rough):
    rng = np.random.default_rng(11)
    for h, rho, th, w1, w2, w3 in _random(rng, 300):
        k1, k2 = rim_inertia(h, rho)
        d = rounded_omega_dot(rough, h, rho, k1, k2, th, w1, w2, w3)
        eps = 1e-30
        rate = 0.0
        for i, dx in enumerate((w1, *d)):  # d/dtheta, d/domega_i by complex step
            x = [th, w1, w2, w3]
            x[i] = x[i] + 1j * eps
            rate += rounded_energy(rough, h, rho, k1, k2, *x).imag / eps * dx
        assert abs(rate) <= 1e-12 * (1.0 + w1 * w1 + w2 * w2 + w3 * w3) ** 1.5


@pytest.mark.parametrize("rough", [True, False])
def test_sphere_keeps_its_angular_velocity(rough):
    """h = rho = 1 is a homogeneous sphere: the contact force passes through C, so the
    angular velocity is constant in the inertial frame (and, rolling, so is v_C)."""
    rng = np.random.default_rng(5)
    k1, k2 = rim_inertia(1.0, 1.0)
    for _ in range(200):
        th = rng.uniform(-1.4, 1.4)
        w = rng.normal(size=3)
        d = np.array(rounded_omega_dot(rough, 1.0, 1.0, k1, k2, th, *w))
        # d/dt of the inertial omega, in C xi eta zeta: d omega + omega_frame x omega,
        # the frame turning at (omega1, Omega sin, Omega cos), Omega = omega3 / cos
        wf = np.array([w[0], w[2] * math.tan(th), w[2]])
        assert np.max(np.abs(d + np.cross(wf, w))) < 1e-13
        assert rounded_normal_force(rough, 1.0, 1.0, k1, k2, th, *w) == pytest.approx(1.0)


def test_sharp_disk_functions_refuse_a_rounded_rim():
    """The paper's closed forms do not describe a rounded rim: they say so instead of
    answering for the sharp disk (rd.simulate runs a rounded rim through ivp/rounded.py,
    tests/test_rounded_motion.py)."""
    import rollingdisk as rd

    d = Disk(0.1, rim_radius=0.02)
    for call in (lambda: rd.thresholds(d), lambda: rd.varpi2_closed_form(d, "rough", 0.3, 1, 1),
                 lambda: rd.steady_motion(d, "rough", 0.3, Omega0=2.0),
                 lambda: rd.straight_line(d, "rough", 2.0)):
        with pytest.raises(ParameterError, match="rounded rim.*rim_radius = 0.02"):
            call()
    assert rd.thresholds(Disk(0.1, rim_radius=0.0)) == rd.thresholds(Disk(0.1))

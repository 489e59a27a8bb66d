"""The flat disk's friction in closed form (phases/flat.py) against its definition.

Source of truth: the force and torque of Coulomb friction under uniform pressure, written
in polar coordinates about the instantaneous centre of the slip field (an exact rewriting
of the area integrals, derived in phases/flat.py's notes) and integrated by mpmath at 30
digits; a brute-force midpoint rule over the disk in Cartesian coordinates; the classic
limits (pure sliding f = 1; pure spin tau = 2/3) and their asymptotes.
"""

import math

import mpmath as mp
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from rollingdisk.phases.flat import flat_friction


def _by_quadrature(eps):
    """``(f, tau)`` at ``V = eps``, ``Omega = 1`` from the alpha-integrals (mpmath)."""
    with mp.workdps(30):
        k = mp.mpf(eps)

        def q(a):
            return mp.sqrt(max(mp.mpf(0), 1 - k ** 2 * mp.sin(a) ** 2))

        if k < 1:  # the instantaneous centre inside the disk: every ray leaves it once
            pts = [0, mp.pi / 2, mp.pi, 3 * mp.pi / 2, 2 * mp.pi]
            f = k / mp.pi * mp.quad(lambda a: mp.cos(a) ** 2 * q(a), pts)
            tau = mp.quad(lambda a: q(a) ** 3, pts) / (3 * mp.pi)
        else:  # outside: the rays that cross the disk, a chord each
            b = mp.asin(1 / k)
            f = 2 * k / mp.pi * mp.quad(lambda a: mp.cos(a) ** 2 * q(a), [-b, 0, b])
            tau = 2 * mp.quad(lambda a: q(a) ** 3, [-b, 0, b]) / (3 * mp.pi)
        return float(f), float(tau)


@pytest.mark.parametrize("eps", [1e-8, 1e-3, 0.2, 0.5, 0.70710678, 0.9, 0.999999, 1.0,
                                 1.000001, 1.2, 1.41421357, 3.0, 50.0, 1e4, 1e7])
def test_closed_form_equals_the_integrals(eps):
    f, tau = flat_friction(eps, 1.0)
    qf, qtau = _by_quadrature(eps)
    assert f == pytest.approx(qf, rel=1e-13, abs=1e-15)
    assert tau == pytest.approx(qtau, rel=1e-13, abs=1e-15)


@settings(max_examples=60, deadline=None, derandomize=True)
@given(st.floats(1e-6, 1e6))
def test_closed_form_equals_the_integrals_anywhere(eps):
    f, tau = flat_friction(eps, 1.0)
    qf, qtau = _by_quadrature(eps)
    assert abs(f - qf) <= 1e-13 and abs(tau - qtau) <= 1e-13


def test_scaling_limits_and_asymptotes():
    # only eps = V / Omega matters
    assert flat_friction(0.6, 2.0) == flat_friction(0.3, 1.0)
    assert flat_friction(2.0, 0.0) == (1.0, 0.0)
    assert flat_friction(0.0, 3.0) == (0.0, 2.0 / 3.0)  # int r dA / pi
    assert flat_friction(1.0, 1.0) == pytest.approx((8 / (3 * math.pi), 8 / (9 * math.pi)),
                                                    rel=1e-15)
    f, tau = flat_friction(1e-9, 1.0)
    assert f == pytest.approx(1e-9, rel=1e-9) and tau == pytest.approx(2 / 3, rel=1e-15)
    f, tau = flat_friction(1e9, 1.0)
    assert f == pytest.approx(1.0, abs=1e-15) and tau == pytest.approx(0.25e-9, rel=1e-9)
    eps = np.linspace(0.01, 20.0, 400)
    ft = np.array([flat_friction(e, 1.0) for e in eps])
    assert np.all(np.diff(ft[:, 0]) > 0) and np.all(np.diff(ft[:, 1]) < 0)


def test_brute_force_over_the_disk():
    n = 1500
    x = (np.arange(n) + 0.5) / n * 2 - 1
    X, Y = np.meshgrid(x, x)
    inside = X ** 2 + Y ** 2 <= 1
    v, om = 0.7, 1.3
    wx, wy = v - om * Y, om * X
    nw = np.hypot(wx, wy)
    dA = (2.0 / n) ** 2 / math.pi
    f = np.sum((wx / nw)[inside]) * dA
    tau = np.sum(((X * wy - Y * wx) / nw)[inside]) * dA
    got = flat_friction(v, om)
    assert got[0] == pytest.approx(f, abs=2e-3)
    assert got[1] == pytest.approx(tau, abs=2e-3)

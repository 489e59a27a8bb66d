"""Coulomb's bound as a law of the impact law: no friction impulse exceeds mu x its normal one.

Sources of truth: the Coulomb cone itself (``|Lam_T| <= mu Lam_N``, ``Lam_N >= 0``), checked
on the impulse the law returns, and the energy of the free body before and after
(:func:`rollingdisk.phases.flight.free_energy`, which knows nothing of the law): no impact
creates energy.  The check inside the law is shown to refuse a broken impulse instead of
passing it on.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import rollingdisk as rd
from rollingdisk.phases import impact as im

_speed = st.floats(-6.0, 6.0, allow_nan=False)
_rate = st.floats(-25.0, 25.0, allow_nan=False)
#: speeds down to the smallest floats (grazing and vanishing approach) are included;
#: mu over twelve decades and the frictionless law, e over [0, 1], h from thin to tall
_mu = st.one_of(st.just(0.0), st.floats(1e-9, 1e-3), st.floats(1e-3, 20.0))


@settings(max_examples=400, deadline=None)
@given(h=st.floats(0.0, 2.0), theta=st.floats(-1.55, 1.55), psi=st.floats(-3.0, 3.0),
       phi=st.floats(-3.0, 3.0), v=st.tuples(_speed, _speed, _speed),
       w=st.tuples(_rate, _rate, _rate), e=st.floats(0.0, 1.0), mu=_mu,
       lowest=st.booleans())
def test_no_impulse_leaves_the_coulomb_cone_and_no_impact_creates_energy(
        h, theta, psi, phi, v, w, e, mu, lowest):
    disk = rd.Disk(h)
    s = np.array([0.0, 0.0, 3.0, psi, theta, phi, *v, *w])
    side = (1 if theta >= 0.0 else -1) if lowest else (-1 if theta >= 0.0 else 1)
    res = im.impact(disk, s, side, e, mu)
    P_n = res.impulse_normal
    P_t = math.hypot(*res.impulse_tangential)
    assert P_n >= 0.0
    assert P_t <= mu * P_n * (1.0 + 1e-12), (P_t, mu * P_n)
    # energy, from the free body alone: T+ <= T- (positions do not jump)
    E0, E1 = im.free_energy(disk, s), im.free_energy(disk, res.post_state)
    scale = 1.0 + E0
    assert E1 <= E0 + 1e-12 * scale, (E0, E1)
    assert res.energy_lost >= -1e-12 * scale
    assert abs((E0 - E1) - res.energy_lost) <= 1e-10 * scale


def test_frictionless_elastic_impact_keeps_the_energy():
    """``e = 1, mu = 0``: the law's one case of equality (docs/impacts.md)."""
    disk = rd.Disk(0.3)
    s = np.array([0.0, 0.0, 3.0, 0.4, 0.7, 0.1, 0.5, -0.2, -2.0, 1.0, 3.0, -0.5])
    res = im.impact(disk, s, 1, 1.0, 0.0)
    assert res.impulse_normal > 0.0 and np.all(res.impulse_tangential == 0.0)
    assert im.free_energy(disk, res.post_state) == pytest.approx(im.free_energy(disk, s),
                                                                  rel=1e-13)


@pytest.mark.parametrize("over", [1.0 + 1e-9, 2.0])
def test_the_check_refuses_an_impulse_outside_the_cone(monkeypatch, over):
    """A law that returned a friction impulse beyond mu x normal is an internal error."""
    mu = 0.5

    def broken(W, gamma, e_n, e_t, m):
        return np.array([mu * over, 0.0, 1.0]), False

    monkeypatch.setattr(im, "_solve_law", broken)
    s = np.array([0.0, 0.0, 3.0, 0.0, 0.3, 0.0, 0.0, 0.0, -1.0, 0.0, 0.0, 0.0])
    with pytest.raises(RuntimeError, match="Coulomb's bound"):
        im.impact(rd.Disk(0.1), s, 1, 0.5, mu)


def test_the_check_refuses_a_pulling_normal_impulse(monkeypatch):
    monkeypatch.setattr(im, "_solve_law", lambda *a: (np.array([0.0, 0.0, -1e-3]), False))
    s = np.array([0.0, 0.0, 3.0, 0.0, 0.3, 0.0, 0.0, 0.0, -1.0, 0.0, 0.0, 0.0])
    with pytest.raises(RuntimeError, match="Coulomb's bound"):
        im.impact(rd.Disk(0.1), s, 1, 0.5, 0.5)


@pytest.mark.parametrize("k", [17, 50, 300])
def test_grazing_impact_slides_with_the_bound(k):
    """Approach ``1e-k`` of the sliding speed (hypothesis's find): the sliding direction's root
    lay between the scan's last sample and 2 pi, where sin(2 pi) != 0 hid it."""
    s = np.array([0.0, 0.0, 3.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -10.0 ** -k, 0.0, -1.0])
    res = im.impact(rd.Disk(1.0), s, -1, 0.0, 0.5)
    assert res.mode == "sliding" and res.law_residual <= 1e-14
    assert math.hypot(*res.impulse_tangential) <= 0.5 * res.impulse_normal * (1.0 + 1e-12)


@pytest.mark.parametrize("w1", [-1e-160, -1e-300])
def test_vanishing_approach_is_solved_without_underflow(w1):
    """The law is homogeneous of degree one in the contact velocity: a tiny approach gives
    the impulse of a unit one scaled (the scan compared signs by products, which underflow)."""
    s = np.array([0.0, 0.0, 3.0, 0.0, 0.3, 0.0, 0.0, 0.0, 0.0, w1, 0.0, 0.0])
    unit = im.impact(rd.Disk(0.0), s * np.r_[np.ones(9), 1.0 / abs(w1), 1, 1], 1, 0.0, 1e-9)
    res = im.impact(rd.Disk(0.0), s, 1, 0.0, 1e-9)
    assert res.impulse_normal == pytest.approx(unit.impulse_normal * abs(w1), rel=1e-12)

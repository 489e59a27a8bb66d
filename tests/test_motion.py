"""The whole motion (rollingdisk.phases.motion) and the coin toss (friction.toss).

Sources of truth: conservation of energy (e = 1, mu = 0 impacts conserve it; otherwise
E + dissipated + impact losses is constant), the closed-form rocking ratio of an upright
disk (Housner's law with the disk's inertia), the classic sliding and spinning flat disk
(stops at v0/(mu g); torque 2 mu m g a/3), the statuses of simulate_coulomb itself for
stop_at, and a brute-force quadrature for the friction of the flat disk.
"""

from __future__ import annotations

import json
import math

import numpy as np
import pytest

import rollingdisk as rd
from rollingdisk.phases.impact import rim_change_ratio
from rollingdisk.phases.motion import (
    FlatSegment,
    FlightSegment,
    simulate_to_rest,
)
from rollingdisk.scenarios.toss import (
    TossDistribution,
    energy_barrier,
    toss,
    toss_ensemble,
)
from rollingdisk.util.errors import ParameterError


def test_dropped_disk_settles_at_rest_and_energy_closes():
    s0 = [0, 0, 2.0, 0, 0.4, 0, 0, 0, 0, 0, 0, 0]  # tilted, dropped from rest
    res = simulate_to_rest(rd.Disk(0.1), rd.Coulomb(0.5), (0, 200), s0, e=0.3)
    assert res.status == "at-rest"
    assert res.energy_balance <= 1e-9
    # at rest flat: energy h, everything else dissipated or lost in impacts
    assert res.energy_final == pytest.approx(0.1, abs=1e-12)
    assert res.energy_initial - res.dissipated - res.impact_loss == pytest.approx(0.1,
                                                                                  abs=1e-9)
    assert any(isinstance(s, FlightSegment) for s in res.segments)
    assert isinstance(res.segments[-1], FlatSegment)
    assert res.transitions[-1].to_phase == "rest"
    assert all(i.energy_lost >= -1e-13 for i in res.impacts)
    assert "at-rest" in repr(res) and len(repr(res)) < 160


def test_elastic_frictionless_bounces_conserve_energy():
    s0 = [0, 0, 1.5, 0, 0.5, 0, 0.3, 0, 0, 0.7, 0.4, 0.2]
    res = simulate_to_rest(rd.Disk(0.2), rd.Coulomb(0.0), (0, 40), s0, e=1.0,
                           mu_impact=0.0)
    assert len(res.impacts) >= 20
    assert all(i.restitution == 1.0 for i in res.impacts)  # no Zeno capture
    assert abs(res.energy_final - res.energy_initial) <= 1e-9
    assert res.energy_balance <= 1e-9


def test_elastic_frictionless_conserves_energy_over_100_bounces():
    """The issue's done-when: e = 1, mu = 0 keeps the energy to 1e-9 over >= 100 impacts
    (no Zeno capture, no impact loses anything, the balance is the energy itself)."""
    s0 = [0, 0, 1.5, 0, 0.5, 0, 0.3, 0, 0, 0.7, 0.4, 0.2]
    res = simulate_to_rest(rd.Disk(0.2), rd.Coulomb(0.0), (0, 150), s0, e=1.0,
                           mu_impact=0.0)
    assert res.status == "completed"
    assert len(res.impacts) >= 100
    assert all(i.restitution == 1.0 for i in res.impacts)
    assert max(abs(i.energy_lost) for i in res.impacts) <= 1e-12
    assert res.dissipated == 0.0
    assert abs(res.energy_final - res.energy_initial) <= 1e-9
    assert res.energy_balance <= 1e-9


def test_rocking_upright_disk_follows_rim_change_ratio():
    h = 0.5
    y0 = [0, 0, 0, 0, 0, 0.2, 0, 0, 0, 0]  # tilted below arctan h, at rest: rocks
    res = simulate_to_rest(rd.Disk(h), rd.Coulomb(10.0), (0, 50), y0, e=0.0)
    contact = [s for s in res.segments if hasattr(s, "y")]
    ratios = [b.y[7, 0] / a.y[7, -1] for a, b in zip(contact[:-1], contact[1:])]
    assert len(ratios) >= 10
    assert np.max(np.abs(np.array(ratios) - rim_change_ratio(h))) <= 1e-9
    assert res.status == "at-rest"
    assert res.final_state[4] == 0.0 and res.final_state[2] == 1.0  # on its tread
    assert res.energy_balance <= 1e-9


def _state(d, th, w1=0.0, w3=0.0):
    return rd.rolling_state(d, [0, 0, 0, th, 0, w1, 0, w3])


@pytest.mark.parametrize("y, guard", [pytest.param((0.2, 1.0, 0.0, 3.0, 0.8), "lift-off",
                                                   marks=pytest.mark.slow),
                                      ((0.2, 0.6, -1.0, 0.0, 0.8), "edge-contact"),
                                      ((0.2, 1.0, 0.0, 0.0, 0.8), "fell-flat")])
def test_old_guards_continue_and_stop_at_restores_them(y, guard):
    h, th, w1, w3, mu = y
    d, g = rd.Disk(h), rd.Coulomb(mu)
    y0 = _state(d, th, w1, w3)
    old = rd.simulate_coulomb(d, g, (0, 5), y0, rtol=1e-10, atol=1e-12, slip_tol=1e-9,
                              alpha_min=1e-3)
    assert old.status == guard
    stopped = simulate_to_rest(d, g, (0, 5), y0, stop_at=(guard,))
    assert stopped.status == guard
    assert stopped.t_end == pytest.approx(old.t_event, abs=1e-9)
    go_on = simulate_to_rest(d, g, (0, old.t_event + 0.05), y0, max_wall=20.0)
    assert go_on.status != guard
    assert go_on.t_end > old.t_event
    assert go_on.energy_balance <= 1e-8
    kinds = {"lift-off": "flight", "edge-contact": None, "fell-flat": "flat"}
    if kinds[guard]:
        assert kinds[guard] in {m.to_phase for m in go_on.transitions}
    else:
        assert any(i.kind == "rim-change" for i in go_on.impacts)


def test_flat_sliding_disk_stops_at_classic_time():
    # dropped flat from 0.3 above with horizontal speed 1: lands at sqrt(0.6), then slides
    # to rest at v0/mu, no spin (the classic result); the fall is lost in the face impact
    h, mu, v0 = 0.1, 0.4, 1.0
    s0 = [0, 0, h + 0.3, 0, 0.5 * math.pi, 0, v0, 0, 0, 0, 0, 0]
    res = simulate_to_rest(rd.Disk(h), rd.Coulomb(mu), (0, 50), s0)
    assert res.status == "at-rest"
    assert res.t_end == pytest.approx(math.sqrt(0.6) + v0 / mu, rel=1e-12)
    assert res.final_state[0] == pytest.approx(v0 * math.sqrt(0.6) + v0 ** 2 / (2 * mu),
                                               rel=1e-12)
    assert res.impacts[0].kind == "face"
    assert res.impacts[0].energy_lost == pytest.approx(0.3, rel=1e-12)
    assert res.energy_balance <= 1e-12


def test_bad_input_named():
    d, g = rd.Disk(0.1), rd.Coulomb(0.5)
    s0 = [0, 0, 2.0, 0, 0.4, 0, 0, 0, 0, 0, 0, 0]
    with pytest.raises(ParameterError, match=r"^e must"):
        simulate_to_rest(d, g, (0, 1), s0, e=-0.1)
    with pytest.raises(ParameterError, match=r"^e must"):
        simulate_to_rest(d, g, (0, 1), s0, e=1.5)
    inside = [0, 0, 0.5, 0, 0.4, 0, 0, 0, 0, 0, 0, 0]
    with pytest.raises(ParameterError, match=r"^y0: the disk is inside the plane"):
        simulate_to_rest(d, g, (0, 1), inside)
    with pytest.raises(ParameterError, match="stop_at"):
        simulate_to_rest(d, g, (0, 1), s0, stop_at=("landed",))
    with pytest.raises(ParameterError, match=r"^height must"):
        toss(d, 0.5, 1.0, 1.0, 0.4)
    with pytest.raises(ParameterError, match=r"^e must"):
        toss(d, 3.0, 1.0, 1.0, 0.4, e=2.0)


def test_energy_trap_decides_and_agrees_with_rest():
    d = rd.Disk(0.1)
    early = toss(d, 3.0, 2.0, 5.0, 0.3, e=0.3)
    assert early.decided_by == "energy"
    assert early.motion.energy_final < energy_barrier(0.1)
    full = toss(d, 3.0, 2.0, 5.0, 0.3, e=0.3, early=False)
    assert full.decided_by == "rest"
    assert full.outcome == early.outcome


def test_energy_barrier_is_the_balancing_height():
    for h in (0.0, 0.3, 1.2):
        th = math.atan(h)  # centre straight above the rim edge
        assert energy_barrier(h) == pytest.approx(math.cos(th) + h * math.sin(th), 1e-15)


@pytest.mark.parametrize("h, c", [(0.1, 0.01), (0.3, 0.05), (1.0, 0.2)])
def test_energy_barrier_is_the_lowest_height_rolling_resistance_holds(h, c):
    """At rest on a rim edge the arm of gravity about the edge, ``h cos theta - sin
    theta`` (the centre's horizontal offset from the edge), is held by rolling resistance
    while it is at most ``c``; the centre is then at ``Z_C = cos theta + h sin theta``
    (eq. 7).  The least such height, by root finding on the arm, is the barrier."""
    from scipy.optimize import brentq

    th_b = math.atan(h)
    ends = [brentq(lambda t, s=s: h * math.cos(t) - math.sin(t) - s * c, th_b - 1.0, th_b + 1.0,
                   xtol=1e-15) for s in (1.0, -1.0)]
    lowest = min(math.cos(t) + h * math.sin(t) for t in ends)
    assert energy_barrier(h, c) == pytest.approx(lowest, rel=1e-14)
    with pytest.raises(ParameterError, match="rolling_resistance"):
        energy_barrier(h, math.sqrt(1.0 + h * h))


@pytest.mark.parametrize("arm", [0.005, -0.005, 0.0099])
def test_a_disk_held_on_its_rim_edge_rests_there_and_is_an_edge(arm):
    """A coin standing still on a rim edge just past (or before) its balance tilt, held by
    rolling resistance (arm of gravity ``|arm| < c``): at rest on the edge, the outcome
    ``edge``; the energy rule must not call it (its energy is below sqrt(1 + h^2))."""
    from rollingdisk.scenarios.toss import _classify, _trap

    h, c = 0.1, 0.01
    R = math.sqrt(1.0 + h * h)
    theta = math.atan(h) + math.asin(arm / R)
    y0 = [0.0, 0.0, 0.0, 0.0, 0.0, theta, 0.0, 0.0, 0.0, 0.0]  # at rest on rim edge +1
    assert math.cos(theta) + h * math.sin(theta) < energy_barrier(h)
    res = simulate_to_rest(rd.Disk(h), rd.Coulomb(0.5, rolling_resistance=c), (0.0, 50.0),
                           y0, decide=_trap(h, c), max_wall=20.0)
    assert res.status == "at-rest" and "held by rolling resistance" in res.message
    assert _classify(h, res) == ("edge", "rest")


_QUICK = TossDistribution(lift=(0.2, 0.6), velocity=(0.0, 0.5), spin=(-3.0, 3.0),
                          axial_spin=(0.0, 0.0), precession=(0.0, 0.0),
                          horizontal_velocity=(0.0, 0.0))


def test_ensemble_reproducible_and_resumable(tmp_path):
    d = rd.Disk(0.3)
    a = toss_ensemble(d, 4, 7, distribution=_QUICK, e=0.2, max_wall=5.0)
    b = toss_ensemble(d, 4, 7, distribution=_QUICK, e=0.2, max_wall=5.0)
    assert a.outcomes == b.outcomes and sum(a.counts.values()) == 4
    assert np.array_equal(_QUICK.draw(4, 7), _QUICK.draw(4, 7))
    path = tmp_path / "tosses.jsonl"
    c = toss_ensemble(d, 4, 7, distribution=_QUICK, e=0.2, max_wall=5.0, results=path)
    assert c.outcomes == a.outcomes
    lines = path.read_text().splitlines()
    assert len(lines) == 5
    path.write_text("\n".join(lines[:3]) + "\n" + lines[3][:7])  # interrupted mid-line
    seen = []
    r = toss_ensemble(d, 4, 7, distribution=_QUICK, e=0.2, max_wall=5.0, results=path,
                      progress=lambda k, n: seen.append(k))
    assert r.outcomes == a.outcomes
    assert seen == [3, 4]  # two tosses run again, two read back
    with pytest.raises(ParameterError, match="another ensemble"):
        toss_ensemble(d, 4, 8, distribution=_QUICK, results=path)
    assert json.loads(path.read_text().splitlines()[0])["ensemble"]["seed"] == 7


def test_a_disk_rolling_upright_on_its_tread_rolls_to_rest_at_the_closed_form_time():
    """Upright (theta = 1e-9) and rolling (omega2 = V = 1) with a whisker of rocking: the
    contact jumps from rim edge to rim edge and the rim changes accumulate.  The disk then
    enters line contact and rolls on its tread, where the rolling-resistance moment c F_z
    (F_z = 1) gives d(3/4 omega2^2)/dt = -c omega2: it stops at t = 1.5 / c, having rolled
    0.75 / c (closed form; the rocking and the impacts change this by about 1e-4)."""
    c = 0.05
    r = simulate_to_rest(rd.Disk(0.3), rd.Coulomb(0.5, rolling_resistance=c), (0, 100),
                         [0, 0, 1.0, 0, 0, 1e-9, 0, 1e-3, 1.0, 0.0], e=0.5, mu_impact=0.5)
    assert r.status == "at-rest" and "tread" in r.message
    kinds = [x.kind for x in r.impacts]
    assert kinds.count("tread") == 1 and kinds[-2:] == ["tread", "tread-slip"]
    assert all(x.energy_lost >= 0.0 for x in r.impacts)
    assert r.t_end == pytest.approx(1.5 / c, rel=1e-3)
    assert r.final_state[0] == pytest.approx(0.75 / c, rel=1e-3)
    assert abs(r.final_state[4]) == 0.0 and not np.any(r.final_state[6:12])
    assert r.energy_balance <= 1e-9

"""``simulate_coulomb(method="lsoda")``: scipy's LSODA through the same hybrid driver, held
to the closed forms and to the explicit paths.  Its interpolant does not pass through a
step's start, so events are looked for from the interpolant's start (and one that lies
between the accepted state and it is an event at the step's start)."""

from __future__ import annotations

import math

import numpy as np
import pytest

import rollingdisk as rd
from rollingdisk.scenarios.euler_disk import EulerDisk, run_euler_disk


def test_stiff_sliding_disk_rolls_at_the_closed_form_time():
    """h = 0, upright, V = 1, mu = 0.2: u = 1 - 3 mu t vanishes at t* = 5/3 with V = 2/3;
    the slip dissipates 1/6 (tests/test_coulomb_compiled.py derives it)."""
    tr = rd.simulate_coulomb(rd.Disk(0.0), rd.Coulomb(0.2), (0, 2),
                             [0, 0, 1, 0, 0, 0, 0, 0, 0, 0], method="lsoda")
    assert tr.method == "lsoda" and tr.status == "completed"
    (x,) = tr.transitions
    assert (x.from_mode, x.to_mode) == ("sliding", "rolling")
    assert abs(x.t - 5.0 / 3.0) <= 1e-8
    assert tr.y[2, -1] == pytest.approx(2.0 / 3.0, abs=1e-9)
    assert tr.dissipated["slip"][-1] == pytest.approx(1.0 / 6.0, abs=1e-9)
    assert rd.energy_balance(tr) <= 1e-9


def _circle():
    """A steady circle nudged off (omega1 + 0.05) on mu = 1.02 times what it needs: it
    rolls, then slides from t = 0.2416 with a slip of a few 1e-6 (micro-slip)."""
    disk = rd.Disk(0.3)
    m = rd.steady_motion(disk, "rough", 0.9, r_C=1.0)
    yr = [float(v) for v in m.initial_state()]
    yr[5] += 0.05
    return disk, rd.Coulomb(1.02 * m.mu_required), rd.rolling_state(disk, yr)


def test_stiff_and_explicit_paths_agree_through_micro_slip():
    """Two integrators, one model: scipy's DOP853 and LSODA end at the same state (before
    the friction direction was made continuous at |u| = u_eps they converged to states
    3.4e-7 apart, and DOP853 took 15,167 steps instead of about 1000)."""
    disk, g, y0 = _circle()
    a = rd.simulate_coulomb(disk, g, (0, 0.25), y0, method="scipy", rtol=1e-10,
                            atol=1e-12)
    b = rd.simulate_coulomb(disk, g, (0, 0.25), y0, method="lsoda", rtol=1e-11,
                            atol=1e-13)
    assert [x.to_mode for x in a.transitions] == [x.to_mode for x in b.transitions] == [
        "sliding"]
    assert abs(a.transitions[0].t - b.transitions[0].t) <= 1e-9
    assert np.abs(a.y[:, -1] - b.y[:, -1]).max() <= 1e-9  # measured 6.9e-11
    assert a.n_steps < 3000  # measured 1052
    for tr in (a, b):
        assert rd.energy_balance(tr) <= 1e-9


def test_stiff_converges_with_its_tolerance_over_a_long_slide():
    disk, g, y0 = _circle()
    ends = [rd.simulate_coulomb(disk, g, (0, 3), y0, method="lsoda", rtol=tol,
                                atol=tol * 1e-2) for tol in (1e-10, 1e-11)]
    for tr in ends:
        assert tr.status == "completed" and tr.n_steps < 2000  # measured 421, 544
        assert rd.energy_balance(tr) <= 1e-9
    assert np.abs(ends[0].y[:, -1] - ends[1].y[:, -1]).max() <= 1e-7


def test_friction_direction_turns_continuously_into_the_slip_direction():
    """``e`` is ``ref`` at u = 0 and ``sgn(u . ref) u/|u|`` from |u| = u_eps on, with no
    jump at u_eps (random states of the disk: u from eq. 6)."""
    from rollingdisk.model.coulomb import _friction_direction, _slip_velocity

    rng = np.random.default_rng(7)
    for _ in range(200):
        y = rng.uniform(-1.0, 1.0, 10)
        h = rng.uniform(0.0, 0.5)
        ref = rng.normal(size=2)
        ref /= np.linalg.norm(ref)
        n = math.hypot(*_slip_velocity(h, y))
        below = np.array(_friction_direction(h, y, *ref, n * (1.0 + 1e-10))[2:])
        above = np.array(_friction_direction(h, y, *ref, n * (1.0 - 1e-10))[2:])
        assert np.abs(below - above).max() <= 1e-8
        assert abs(np.linalg.norm(below) - 1.0) <= 1e-12
        far = np.array(_friction_direction(h, y, *ref, n * 1e12)[2:])  # u ~ 0 against u_eps
        psi = y[4]
        r_xyz = (ref[0] * math.cos(psi) + ref[1] * math.sin(psi),
                 -ref[0] * math.sin(psi) + ref[1] * math.cos(psi))
        assert np.abs(far - r_xyz).max() <= 1e-9


@pytest.mark.slow
def test_stiff_runs_the_micro_slip_of_an_euler_disk_to_its_fall():
    """mu = 2, alpha0 = 0.1, c = 5e-3: rolling, then micro-slip (23 transitions) to the
    fall; compiled DOP853 needs 4,964,713 steps (docs/friction.md), LSODA tens of
    thousands, and both end at the same time."""
    from rollingdisk.scenarios.euler_kernels import _kicked_state

    toy = EulerDisk(alpha0=0.1, mu=2.0, rolling_resistance=5e-3, friction="coulomb")
    x0 = _kicked_state(toy, 0.0)
    y0 = [0.0, 0.0, x0[0], x0[1], 0.0, x0[2], 0.0, x0[3], x0[4], x0[5]]
    tr = rd.simulate_coulomb(rd.Disk(toy.h), rd.Coulomb(2.0, rolling_resistance=5e-3),
                             (0, 200), y0, rtol=1e-10, atol=1e-12, method="lsoda",
                             alpha_min=1e-3, max_steps=10**6, max_wall_time=300)
    assert tr.status == "fell-flat", tr.message
    assert tr.n_steps < 100_000
    assert len(tr.transitions) > 10
    assert rd.energy_balance(tr) <= 1e-8
    creep = run_euler_disk(EulerDisk(alpha0=0.1, mu=2.0, rolling_resistance=5e-3,
                                     creep=1e5), predict=False)
    # the creep law's end lies above it and tends to it as k grows (0.096 at k = 1e5)
    assert 0.0 < creep.t_end - tr.t[-1] < 0.2

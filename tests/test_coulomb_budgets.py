"""Coulomb ground: the work of a run is bounded in steps, wall-clock time and memory, and an
absurd friction coefficient is refused (issue 18, item 4).

Each case reproduces a run of the issue with a small budget, so the test stays fast; no
assertion is about timing, only about the status and the message a spent budget gives.
"""

import inspect
import math

import numpy as np
import pytest

import rollingdisk as rd

DISK = rd.Disk(0.17)
CIRCLE = rd.steady_motion(DISK, "rough", theta0=math.radians(30), r_C=0.5)
Y = rd.rolling_state(DISK, CIRCLE.initial_state())


def test_default_budgets_match_the_cost_of_the_path():
    """At 0.1-1 ms a step the old default of 2e6 steps was up to half an hour; the defaults
    are now a step budget of at most 2e5 and a finite wall-clock budget."""
    params = inspect.signature(rd.simulate_coulomb).parameters
    assert params["max_steps"].default <= 200_000
    assert 0 < params["max_wall_time"].default < math.inf


def test_wall_clock_budget_ends_the_run_with_its_own_status():
    # simulate --ground coulomb --mu 0.3 --air 0.1 --h 0.17 --theta0 30deg --rC 0.5 --t-end 5
    g = rd.Coulomb(0.3, air=0.1)
    tr = rd.simulate_coulomb(DISK, g, (0.0, 5.0), Y, max_wall_time=1e-9)
    assert tr.status == "time-budget" and not tr.success
    assert "max_wall_time" in tr.message and "raise max_wall_time" in tr.message
    assert tr.t[-1] < 5.0
    assert rd.energy_balance(tr) < 1e-9  # what was stored is a valid run
    with pytest.raises(rd.ParameterError, match="max_wall_time"):
        rd.simulate_coulomb(DISK, g, (0.0, 5.0), Y, max_wall_time=0.0)


def test_step_budget_ends_the_run_with_its_own_status():
    # simulate --ground coulomb --mu 0.3 --pivot 1e-3 --h 0.17 --theta0 30deg --rC 0.5 (11 steps)
    # (the issue-18 case, a straight line with pivot friction chattering at omega_z = 0,
    # now sticks and ends in 4 steps: tests/test_pivot_stick.py)
    tr = rd.simulate_coulomb(DISK, rd.Coulomb(0.3, pivot=1e-3), (0.0, 5.0), Y, max_steps=5)
    assert tr.status == "step-budget" and tr.n_steps == 5
    assert "raise max_steps" in tr.message


def test_stored_points_are_capped_by_thinning():
    """Beyond max_points every other regular step is dropped; the first and last points and
    the mode events stay, and the message says so."""
    g = rd.Coulomb(0.2, 0.15)  # slides at t = 0, rolls again at t = 4.97
    full = rd.simulate_coulomb(DISK, g, (0.0, 8.0), Y)
    thin = rd.simulate_coulomb(DISK, g, (0.0, 8.0), Y, max_points=16)
    assert full.t.size > 64
    assert thin.t.size <= 16 + len(thin.transitions) + 2
    assert thin.status == full.status == "completed" and "max_points" in thin.message
    assert thin.t[0] == full.t[0] and thin.t[-1] == full.t[-1]
    np.testing.assert_array_equal(thin.y[:, -1], full.y[:, -1])  # the same run, thinned
    assert thin.transitions == full.transitions
    assert set(thin.t) <= set(full.t)
    assert all(x.t in set(thin.t) for x in thin.transitions)
    with pytest.raises(rd.ParameterError, match="max_points"):
        rd.simulate_coulomb(DISK, g, (0.0, 1.0), Y, max_points=3)


@pytest.mark.parametrize("kw", [{"mu_s": 1e308}, {"mu_s": 1e7}, {"mu_s": 1e308, "mu_k": 1e7}])
def test_absurd_friction_coefficient_is_refused(kw):
    # simulate --ground coulomb --mu 1e308 ... ran 12 minutes with memory rising
    with pytest.raises(rd.ParameterError, match="mu_"):
        rd.Coulomb(**kw)


def test_largest_friction_coefficient_is_the_rough_limit():
    assert rd.Coulomb(1e6).mu_s == 1e6  # the rough limit the tests use stays allowed

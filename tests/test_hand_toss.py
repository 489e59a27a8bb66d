"""The hand toss (:mod:`rollingdisk.scenarios.hand_toss`) against independent truths.

Sources of truth: Euler's equations of the torque-free axisymmetric body with the inertia of
eq. (10), solved in sympy (the precession (H1) and the flip rate (H2)); the library's own
free flight (:func:`rollingdisk.phases.flight.free_flight`, rotation matrices, no precession
formula); the time the normal spends up, measured by root finding on the flight; the law of
Diaconis, Holmes & Montgomery (SIAM Rev. 49 (2007) 211), ``1/2 + arcsin(cot^2 psi)/pi``;
binomial statistics for the ensembles.
"""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
import sympy as sp
from scipy.optimize import brentq

import rollingdisk as rd
from rollingdisk.cli.app import main
from rollingdisk.phases.flight import angular_momentum, free_flight
from rollingdisk.scenarios import hand_toss as ht
from rollingdisk.util.errors import ParameterError


def _dhm(psi):
    """DHM's printed law, written here once and used only as the thing compared with."""
    psi = np.asarray(psi, dtype=float)
    c2 = (np.cos(psi) / np.sin(psi)) ** 2
    return np.where(psi < math.pi / 4, 1.0, 0.5 + np.arcsin(np.minimum(c2, 1.0)) / math.pi)


# ------------------------------------------------------------------ the free flight
def test_precession_and_flip_rate_follow_from_eulers_equations():
    """n(t) precessing about L at |L|/k1^2 solves dn/dt = (J^-1 L) x n for J of eq. (10);
    n_Z(t) is (H1) and |omega| is (H2)."""
    k1s, k2s, L, psi, t = sp.symbols("k1s k2s L psi t", positive=True)
    h = sp.symbols("h", nonnegative=True)
    k1s_10 = sp.Rational(1, 4) + h ** 2 / 3  # eq. (10)
    Lhat = sp.Matrix([sp.sin(psi), 0, sp.cos(psi)])
    e1 = sp.Matrix([-sp.cos(psi), 0, sp.sin(psi)])
    e2 = Lhat.cross(e1)
    Om = L / k1s
    n = sp.cos(psi) * Lhat + sp.sin(psi) * (sp.cos(Om * t) * e1 + sp.sin(Om * t) * e2)
    assert sp.simplify(n.subs(t, 0) - sp.Matrix([0, 0, 1])) == sp.zeros(3, 1)
    J_inv = (sp.eye(3) - n * n.T) / k1s + n * n.T / k2s
    omega = J_inv * (L * Lhat)
    res = sp.simplify(n.diff(t) - omega.cross(n))
    assert res == sp.zeros(3, 1)
    assert sp.simplify(n[2] - (sp.cos(psi) ** 2 + sp.sin(psi) ** 2 * sp.cos(Om * t))) == 0
    w2 = sp.simplify((omega.T * omega)[0])
    assert sp.simplify(w2 - L ** 2 * (sp.sin(psi) ** 2 / k1s ** 2
                                      + sp.cos(psi) ** 2 / k2s ** 2)) == 0
    # the library's Omega_p from |omega| (H2), eq. (10) inertia, at a few points
    for hv, wv, pv in ((0.0, 3.0, 0.4), (0.3, 7.0, 1.2), (1.1, 2.0, math.pi / 2)):
        per_L = sp.sqrt(w2 / L ** 2).subs({k1s: k1s_10, k2s: sp.Rational(1, 2)})  # |omega|/|L|
        want = float((wv / per_L / k1s_10).subs({h: hv, psi: pv}))
        assert ht.precession_rate(rd.Disk(hv), wv, pv) == pytest.approx(want, rel=1e-13)


@pytest.mark.parametrize("seed", range(4))
def test_normal_z_and_launch_match_the_library_free_flight(seed):
    rng = np.random.default_rng(seed)
    h, psi, w = rng.uniform(0, 1.5), rng.uniform(0, math.pi / 2), rng.uniform(0.5, 12)
    disk = rd.Disk(h)
    s = ht.launch_state(disk, 3.0, 2.0, w, psi)
    assert np.linalg.norm(s[9:12]) == pytest.approx(w, rel=1e-14)  # |omega| = flip rate
    L = angular_momentum(disk, s)
    assert math.acos(L[2] / np.linalg.norm(L)) == pytest.approx(psi, abs=1e-12)  # n(0) = Z
    for t in rng.uniform(0.0, 40.0, 6):
        eta_z = math.sin(free_flight(disk, s, t)[4])
        assert ht.normal_z(disk, w, psi, t) == pytest.approx(eta_z, abs=1e-11)


# ------------------------------------------------------------------ DHM's law
def _time_up_fraction(nz, period):
    """Fraction of one precession period with n_Z > 0 (n_Z decreases on [0, period/2])."""
    if nz(0.5 * period) >= 0.0:
        return 1.0
    return 2.0 * brentq(nz, 0.0, 0.5 * period, xtol=1e-15, rtol=1e-15) / period


def test_exact_outcome_map_reproduces_dhm_over_pi_4_to_pi_2():
    disk, w = rd.Disk(0.06), 6.0
    psis = np.linspace(math.pi / 4, math.pi / 2, 401)
    got = []
    for psi in psis:
        P = 2 * math.pi / ht.precession_rate(disk, w, psi)
        got.append(_time_up_fraction(lambda t, p=psi: ht.normal_z(disk, w, p, t), P))
    err = np.max(np.abs(np.array(got) - _dhm(psis)))
    assert err <= 1e-4, err
    assert err <= 1e-10  # what the measurement gives
    assert np.max(np.abs(ht.same_side_probability(psis) - _dhm(psis))) <= 1e-13
    assert ht.same_side_probability(0.3) == 1.0 and ht.same_side_probability(0.0) == 1.0
    assert ht.same_side_probability(math.pi / 2) == pytest.approx(0.5, abs=1e-15)


@pytest.mark.parametrize("psi", [0.85, 1.05, 1.3])
def test_time_up_on_the_library_free_flight_is_dhm(psi):
    disk, w = rd.Disk(0.3), 5.0
    s = ht.launch_state(disk, 10.0, 0.0, w, psi)
    P = 2 * math.pi / ht.precession_rate(disk, w, psi)
    frac = _time_up_fraction(lambda t: math.sin(free_flight(disk, s, t)[4]), P)
    assert frac == pytest.approx(float(_dhm(psi)), abs=1e-9)


@pytest.mark.parametrize("psi", [0.9, 1.2, math.pi / 2])
def test_uniform_flight_times_give_dhm_statistically(psi):
    rng = np.random.default_rng(7)
    n = 100_000
    up = ht.normal_z(rd.Disk(0.1), 5.0, psi, rng.uniform(0.0, 2000.0, n)) > 0.0
    p = float(_dhm(psi))
    assert abs(up.mean() - p) <= 4.5 * math.sqrt(p * (1 - p) / n) + 1e-12


def test_free_flight_ensemble_gives_dhm_statistically():
    disk, psi, n = rd.Disk(0.2), 1.0, 400
    s = ht.launch_state(disk, 10.0, 0.0, 4.0, psi)
    ts = np.random.default_rng(3).uniform(0.0, 500.0, n)
    up = np.mean([math.sin(free_flight(disk, s, t)[4]) > 0.0 for t in ts])
    p = float(_dhm(psi))
    assert abs(up - p) <= 4.5 * math.sqrt(p * (1 - p) / n)


# ------------------------------------------------------------------ the ensembles
def test_caught_ensemble_reproducible_and_limits():
    disk = rd.Disk(0.06)
    a = ht.caught_ensemble(disk, ht.HandLaunch(), 20_000, 5)
    b = ht.caught_ensemble(disk, ht.HandLaunch(), 20_000, 5)
    assert a.same_side == b.same_side
    p, n = a.mean_exact, a.n
    assert abs(a.probability - p) <= 4.5 * math.sqrt(p * (1 - p) / n)
    steep = ht.caught_ensemble(disk, ht.HandLaunch(psi=0.6, psi_spread=0.0), 5000, 1)
    assert steep.same_side == 5000  # psi < pi/4: the normal never turns down
    flip = ht.caught_ensemble(disk, ht.HandLaunch(psi_spread=0.0), 100_000, 2)
    assert flip.mean_exact == 0.5
    assert abs(flip.probability - 0.5) <= 4.5 * 0.5 / math.sqrt(100_000)
    d = json.loads(json.dumps(a.as_dict(), allow_nan=False))
    assert d["ending"] == "caught" and "hand toss" in d["launch_model"] and d["e"] is None


def test_psi_draws_stay_in_range_and_keep_the_symmetry():
    psi, w, v = ht.HandLaunch(psi=1.5, psi_spread=2.0).draw(50_000, np.random.default_rng(1))
    assert psi.min() >= 0.0 and psi.max() <= math.pi / 2 and w.min() >= 0.0


def test_table_rows_are_the_launch_state():
    disk, launch = rd.Disk(0.2), ht.HandLaunch(psi=1.3)
    rows = ht.HandTossDistribution(launch=launch, h=disk.h).draw(5, 11)
    psi, w, v = launch.draw(5, np.random.default_rng(11))
    for k in range(5):
        lift, vz, w1, tilt, w2, w3, vx = rows[k]
        s = np.array([0, 0, 1 + disk.h + lift, 0, tilt, 0, vx, 0, vz, w1, w2, w3])
        ref = ht.launch_state(disk, launch.height, v[k], w[k], psi[k])
        assert np.allclose(s, ref, rtol=1e-14, atol=1e-14)


def test_table_ensemble_runs_through_the_toss_machinery(tmp_path):
    launch = ht.HandLaunch(height=1.2, upward_speed=1.0, upward_speed_spread=0.0,
                           flip_rate=2.0, flip_rate_spread=0.0, psi=1.2, psi_spread=0.0)
    res = ht.table_ensemble(rd.Disk(0.3), launch, 1, 0, e=0.3, mu=0.5, max_wall=20.0,
                            results=tmp_path / "t.jsonl")
    assert sum(res.counts.values()) == 1
    assert res.params["distribution"]["launch"]["psi"] == 1.2


@pytest.mark.parametrize("kw", [{"psi": 1.6}, {"psi": -0.1}, {"height": -1.0},
                                {"flip_rate": -1.0}, {"psi_spread": -0.1}])
def test_bad_launch_is_refused(kw):
    with pytest.raises(ParameterError, match=next(iter(kw))):
        ht.HandLaunch(**kw)


def test_bad_table_and_catch_input_is_refused():
    with pytest.raises(ParameterError, match="e must"):
        ht.table_ensemble(rd.Disk(0.1), ht.HandLaunch(), 1, 0, e=1.5)
    with pytest.raises(ParameterError, match="height"):
        ht.table_ensemble(rd.Disk(0.5), ht.HandLaunch(height=0.2), 1, 0)
    with pytest.raises(ParameterError, match="upward_speed"):
        ht.caught_ensemble(rd.Disk(0.1), ht.HandLaunch(upward_speed=0.5), 10, 0)
    with pytest.raises(ParameterError, match="psi"):
        ht.same_side_probability(2.0)


# ------------------------------------------------------------------ the command line
def test_cli_catch_states_model_e_mu(capsys):
    assert main(["toss", "--h", "0.06", "--n", "2000", "--seed", "1", "--catch"]) == 0
    out = capsys.readouterr().out
    assert "same side" in out and "launch: hand toss" in out and "e, mu: not used" in out
    assert main(["toss", "--disk", "euro-1", "--n", "100", "--catch", "--json",
                 "--flip-rate", "38rev/s", "--upward-speed", "2.4m/s", "--psi", "80deg"]) == 0
    d = json.loads(capsys.readouterr().out)
    assert d["launch"]["psi"] == pytest.approx(math.radians(80))
    assert "38 +-" in d["launch_si"] and d["e"] is None and "e_mu_note" in d


def test_cli_default_json_states_model_e_mu(capsys):
    assert main(["toss", "--h", "0.1", "--n", "1", "--seed", "0", "--max-wall", "5",
                 "--json"]) == 0
    d = json.loads(capsys.readouterr().out)
    assert d["launch_model"].startswith("uniform") and d["e"] == 0.5 and d["mu"] == 0.5


@pytest.mark.parametrize("bad", [["--psi", "2"], ["--psi", "-0.1"], ["--height", "-1"],
                                 ["--e", "1.5"], ["--height", "0.3m"],
                                 ["--catch", "--launch", "uniform"], ["--catch-height", "3"],
                                 ["--flip-rate", "3furlongs"], ["--catch", "--out", "x.png"],
                                 ["--catch", "--table"]])
def test_cli_bad_launch_one_line_exit_2(capsys, bad):
    assert main(["toss", "--h", "0.06", "--n", "10", *bad]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith("rollingdisk toss"), err

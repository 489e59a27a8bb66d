"""Set-valued pivoting friction on Coulomb ground (issue 22): the pivot sticks when the
vertical spin omega_z stops and slips again when the moment holding it reaches c F_z.

Truth: the stuck kernels against the sympy derivation (the constraint d omega_z/dt = 0 with the
extra unknown M_piv, rollingdisk.symbolic.coulomb.derive_pivot_stuck); the stop of an upright
thin disk spinning about its vertical diameter against its closed form; the stop, the slip
and the end of a thick disk against independent solves of the same reduced problems (the
lambdified sympy equations, integrated by scipy at rtol 1e-13, zeros by brentq on the dense
output); the energy balance (eq. 12) through the transitions.
"""

import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp
from scipy.optimize import brentq

import rollingdisk as rd
from conftest import random_states
from rollingdisk.model import coulomb as eq

N = 60
DISK = rd.Disk(0.17)


@pytest.fixture(scope="module")
def sym():
    from rollingdisk.symbolic.coulomb import lambdified_coulomb, lambdified_pivot_stuck

    return {"free": lambdified_coulomb(), "stuck": lambdified_pivot_stuck()}


def _close(a, b, rel=1e-12):
    a, b = np.asarray(a, float), np.asarray(b, float)
    assert np.all(np.abs(a - b) <= rel * (1.0 + np.abs(b))), (a, b)


def _omega_z(y):
    return y[8] * math.sin(y[5]) + y[9] * math.cos(y[5])


def test_stuck_kernels_equal_the_derivation(sym):
    rng = np.random.default_rng(22)
    for disk, y in random_states("smooth", N, seed=22):
        th, w1, w2, w3 = y[5], y[7], y[8], y[9]
        M = rng.uniform(-1, 1, 6) * rng.choice([0.0, 1.0])
        mu = rng.uniform(0, 1.5)
        a = rng.uniform(0, 2 * math.pi)
        e = (math.cos(a), math.sin(a))
        hk = disk.h_tilde(th)
        _close(eq._rolling_stuck_solve(disk.h, th, w1, w2, w3, *M),
               sym["stuck"]["rolling"](hk, th, w1, w2, w3, *M))
        v = (0.3, -0.2)  # the sliding accelerations of omega and F do not involve v_C
        ref = sym["stuck"]["sliding"](hk, th, w1, w2, w3, *v, mu, *e, *M)
        _close(eq._sliding_stuck_solve(disk.h, mu, *e, th, w1, w2, w3, *M), ref[:7])


def test_stuck_modes_hold_omega_z_and_do_no_work():
    g = rd.Coulomb(0.4, pivot=0.05, rolling_resistance=0.01, air=0.02)
    for disk, y in random_states("smooth", 20, seed=3):
        y = y.copy()
        y[8], y[9] = y[8] - _omega_z(y) * math.sin(y[5]), y[9] - _omega_z(y) * math.cos(y[5])
        for mode in ("rolling, pivot stuck", "sliding, pivot stuck"):
            dy = rd.coulomb_rhs(disk, g, mode, y)
            dwz = (dy[8] * math.sin(y[5]) + dy[9] * math.cos(y[5])
                   + y[7] * (y[8] * math.cos(y[5]) - y[9] * math.sin(y[5])))
            assert abs(dwz) <= 1e-12 * (1.0 + np.abs(dy[7:]).max())
            assert abs(rd.coulomb_contact(disk, g, mode, y)["power_pivot"]) <= 1e-12
    assert rd.MODE_NAMES[:2] == ("rolling", "sliding")
    with pytest.raises(rd.ParameterError, match="mode"):
        rd.coulomb_rhs(DISK, g, "pivot stuck", y)


def test_upright_thin_disk_stops_at_the_closed_form_and_stays_stuck():
    """h = 0, theta = 0, omega = Omega0 e_z: theta = omega1 = omega2 = 0 is invariant, F_z = 1
    and (9)_3 reads k1^2 d omega3/dt = -c, so omega_z = Omega0 - 4 c t stops at
    t* = Omega0 / (4 c); then nothing needs a moment, the pivot sticks, the disk rests."""
    disk, Om0, c = rd.Disk(0.0), 0.7, 0.03
    y0 = [0, 0, 0, 0, 0, 0, 0, 0, 0, Om0]
    tr = rd.simulate_coulomb(disk, rd.Coulomb(0.5, pivot=c), (0.0, 10.0), y0)
    assert tr.status == "completed" and tr.n_steps < 100
    (x,) = tr.transitions
    assert (x.from_mode, x.to_mode) == ("rolling", "rolling, pivot stuck")
    assert abs(x.t - Om0 / (4 * c)) <= 1e-9
    assert rd.MODE_NAMES[tr.mode[-1]] == "rolling, pivot stuck"
    assert np.abs(tr.y[9, -1]) <= 1e-12
    assert tr.dissipated["pivot"][-1] == pytest.approx(0.125 * Om0 ** 2, rel=1e-12)
    assert rd.energy_balance(tr) <= 1e-9


def test_straight_line_with_pivot_friction_no_longer_chatters():
    # issue 18's case: it spent any step budget at the stop of omega_z (t = 0.0441)
    line = rd.straight_line(DISK, "rough", 1e-3)
    y = rd.rolling_state(DISK, line.initial_state())
    tr = rd.simulate_coulomb(DISK, rd.Coulomb(0.0, pivot=1e-3), (0.0, 0.5), y, max_steps=50)
    assert tr.status == "completed"
    assert [x.to_mode for x in tr.transitions] == ["sliding", "sliding, pivot stuck"]
    assert rd.energy_balance(tr) <= 1e-9


# ---------------------------------------------------- independent solves (sympy + scipy)
def _reduced(sym, h, c, stuck, sz=1.0):
    """``d/dt (theta, omega1, omega2, omega3)`` rolling with the pivot moment ``-c F_z sz``
    (or stuck) from the lambdified sympy equations; also the event quantities."""
    M = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0 if stuck else -c * sz)
    f = sym["stuck" if stuck else "free"]["rolling"]

    def out(q):
        th, w1, w2, w3 = q
        return f(h * math.copysign(1.0, th), th, w1, w2, w3, *M)

    def rhs(t, q):
        r = out(q)
        return [q[1], r[0], r[1], r[2]]
    return rhs, out


def _solve(rhs, q0, t1):
    return solve_ivp(rhs, (0.0, t1), q0, method="DOP853", rtol=1e-13, atol=1e-15,
                     dense_output=True)


def _zero(fun, sol, t1, n=400):
    ts = np.linspace(0.0, t1, n)
    vals = [fun(sol.sol(t)) for t in ts]
    i = next(i for i in range(1, n) if vals[i - 1] > 0.0 >= vals[i])
    return brentq(lambda t: fun(sol.sol(t)), ts[i - 1], ts[i], xtol=1e-15, rtol=8.9e-16)


def test_spin_in_place_stops_sticks_and_falls_against_independent_solves(sym):
    """Disk(0.17) in its spin-in-place steady motion (r_C = 0) at theta0 = 0.165, just below
    the tilt atan(h) where C lies above P: Omega0 = 0.29.  Pivot friction c = 0.05 stops
    omega_z at t* = 1.544 (without the stuck mode the run spent its step budget there);
    stuck, the disk tips over onto its other rim edge at t = 5.865."""
    c = 0.05
    s = rd.steady_motion(DISK, "rough", theta0=0.165, r_C=0.0)
    y0 = rd.rolling_state(DISK, s.initial_state())
    tr = rd.simulate_coulomb(DISK, rd.Coulomb(0.5, pivot=rd.PivotFriction(c)), (0.0, 20.0),
                             y0, max_steps=2000)
    assert tr.status == "edge-contact" and tr.n_steps < 200
    (x,) = tr.transitions
    assert (x.from_mode, x.to_mode) == ("rolling", "rolling, pivot stuck")
    assert rd.energy_balance(tr) <= 1e-9

    rhs, _ = _reduced(sym, DISK.h, c, stuck=False)
    q0 = [y0[5], y0[7], y0[8], y0[9]]
    sol = _solve(rhs, q0, 2.0)
    t_stop = _zero(lambda q: q[2] * math.sin(q[0]) + q[3] * math.cos(q[0]), sol, 2.0)
    assert abs(x.t - t_stop) <= 1e-9

    stuck = tr.t >= x.t
    wz = tr.y[8, stuck] * np.sin(tr.y[5, stuck]) + tr.y[9, stuck] * np.cos(tr.y[5, stuck])
    assert np.abs(wz).max() <= 1e-12
    piv = tr.dissipated["pivot"]
    assert np.ptp(piv[stuck]) <= 1e-14  # the stuck pivot does no work
    g = tr.ground
    for i in np.flatnonzero(stuck):
        r = rd.coulomb_contact(DISK, g, rd.MODE_NAMES[tr.mode[i]], tr.y[:, i])
        assert abs(r["M_pivot"]) <= c * r["F_z"]

    rhs, _ = _reduced(sym, DISK.h, c, stuck=True)
    ys = tr.y[:, stuck][:, 0]
    sol = _solve(rhs, [ys[5], ys[7], ys[8], ys[9]], 5.0)
    t_edge = x.t + _zero(lambda q: q[0], sol, 5.0)
    assert abs(tr.t_event - t_edge) <= 1e-8


def test_stuck_pivot_slips_when_the_moment_reaches_its_bound(sym):
    """Disk(0.17) rolling at theta = 0.5 with omega_z = 0 (omega3 = -omega2 tan theta) starts
    stuck; as it tips, the moment holding omega_z grows to c F_z at t = 0.0149 and the pivot
    slips, omega_z turning against the moment's sign (friction opposes the new spin)."""
    c, th, w2 = 0.01, 0.5, 2.0
    y0 = np.array([0, 0, 0, 0, 0, th, 0, 0, w2, -w2 * math.tan(th)])
    y0[2:4] = rd.rolling_state(DISK, y0[[0, 1, 4, 5, 6, 7, 8, 9]])[2:4]
    tr = rd.simulate_coulomb(DISK, rd.Coulomb(0.5, pivot=c), (0.0, 0.1), y0)
    assert tr.status == "completed"
    assert rd.MODE_NAMES[tr.mode[0]] == "rolling, pivot stuck"
    (x,) = tr.transitions
    assert (x.from_mode, x.to_mode) == ("rolling, pivot stuck", "rolling")
    assert rd.energy_balance(tr) <= 1e-9

    rhs, out = _reduced(sym, DISK.h, c, stuck=True)
    sol = _solve(rhs, [th, 0.0, w2, -w2 * math.tan(th)], 0.05)
    t_slip = _zero(lambda q: c * out(q)[5] - abs(out(q)[6]), sol, 0.05)
    assert abs(x.t - t_slip) <= 1e-9
    i = np.flatnonzero(tr.t == x.t)[-1]
    M = rd.coulomb_contact(DISK, tr.ground, "rolling, pivot stuck", tr.y[:, i])["M_pivot"]
    wz_end = _omega_z(tr.y[:, -1])
    assert wz_end != 0.0 and math.copysign(1.0, wz_end) == -math.copysign(1.0, M)

"""Set-valued rolling resistance on Coulomb ground: the rolling resistance sticks when the
horizontal angular velocity omega_h stops and the moment holding it fits in c F_z, and its
moment flips when it does not.

Truth: the roll-stuck kernels against the sympy derivation (omega_h held at zero with the
extra unknowns M_hx, M_hy, rollingdisk.symbolic.coulomb.derive_roll_stuck); the stop of an
upright thin disk rolling straight against its closed form; the static balance of a thick
disk on one rim edge (gravity lever arm |y_P| = |sin theta - h cos theta|, eq. 4, against
c); the stop of its rocking against an independent solve (the lambdified sympy rolling
equations integrated by scipy at rtol 1e-13, the zero by brentq on the dense output); the
energy balance (eq. 12) through the transitions.

Before the stuck mode (the moment a sign function of omega_h), the upright run of
``test_upright_rolling_stops_at_the_closed_form_and_rests`` chattered at t* = 30: scipy
path 60 000 steps in 30 s without passing t = 30.00004 (time budget), compiled path 200 000
steps (step budget) by t = 30.0001.
"""

import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp

import rollingdisk as rd
from conftest import random_states
from rollingdisk.ivp import fastsegment as fs
from rollingdisk.model import coulomb as eq

N = 40
METHODS = ["scipy", pytest.param("dop853", marks=pytest.mark.skipif(
    not fs.available(), reason="numba not installed"))]


@pytest.fixture(scope="module")
def sym():
    from rollingdisk.symbolic.coulomb import lambdified_coulomb, lambdified_roll_stuck

    return {"free": lambdified_coulomb(), "stuck": lambdified_roll_stuck()}


def _close(a, b, rel=1e-12):
    a, b = np.asarray(a, float), np.asarray(b, float)
    assert np.all(np.abs(a - b) <= rel * (1.0 + np.abs(b))), (a, b)


def _y_P(h, theta):
    return math.sin(theta) - h * math.copysign(1.0, theta) * math.cos(theta)  # eq. (4)


@pytest.mark.slow  # the sympy derivation of the stuck kernels: about 20 s
def test_roll_stuck_kernels_equal_the_derivation(sym):
    rng = np.random.default_rng(41)
    for disk, y in random_states("smooth", N, seed=41):
        th, w1, w2, w3 = y[5], y[7], y[8], y[9]
        M = rng.uniform(-1, 1, 6) * rng.choice([0.0, 1.0])
        mu = rng.uniform(0, 1.5)
        a = rng.uniform(0, 2 * math.pi)
        e = (math.cos(a), math.sin(a))
        hk = disk.h_tilde(th)
        v = (0.3, -0.2)  # the sliding accelerations of omega and F do not involve v_C
        for pivot in (False, True):
            n = 9 if pivot else 8
            key = "_pivot" if pivot else ""
            _close(eq._rolling_roll_stuck_solve(disk.h, th, w1, w2, w3, *M, pivot)[:n],
                   sym["stuck"]["rolling" + key](hk, th, w1, w2, w3, *M))
            ref = sym["stuck"]["sliding" + key](hk, th, w1, w2, w3, *v, mu, *e, *M)
            _close(eq._sliding_roll_stuck_solve(disk.h, mu, *e, th, w1, w2, w3, *M, pivot)[:n],
                   ref[:n])


def test_roll_stuck_modes_hold_omega_h_and_do_no_work():
    g = rd.Coulomb(0.4, pivot=0.05, rolling_resistance=0.01, air=0.02)
    for disk, y in random_states("smooth", 20, seed=4):
        y = y.copy()
        th = y[5]
        wz = y[8] * math.sin(th) + y[9] * math.cos(th)
        y[7], y[8], y[9] = 0.0, wz * math.sin(th), wz * math.cos(th)  # omega_h = 0
        for mode in rd.MODE_NAMES[4:]:
            dy = rd.coulomb_rhs(disk, g, mode, y)
            dwy = dy[8] * math.cos(th) - dy[9] * math.sin(th) - y[7] * wz
            scale = 1.0 + np.abs(dy[7:]).max()
            assert abs(dy[7]) <= 1e-12 * scale and abs(dwy) <= 1e-12 * scale
            if "pivot stuck" in mode:
                dwz = dy[8] * math.sin(th) + dy[9] * math.cos(th)
                assert abs(dwz) <= 1e-12 * scale
            c = rd.coulomb_contact(disk, g, mode, y)
            assert abs(c["power_rolling_resistance"]) <= 1e-12
    assert rd.MODE_NAMES[:4] == ("rolling", "sliding", "rolling, pivot stuck",
                                 "sliding, pivot stuck")


@pytest.mark.parametrize("method", METHODS)
@pytest.mark.parametrize("w0", [1.0, -0.6])
def test_upright_rolling_stops_at_the_closed_form_and_rests(method, w0):
    """h = 0, theta = omega1 = omega3 = 0, omega2 = w0, rolling: the motion stays upright and
    straight, F_z = 1, and (9)_2 with F_x = d omega2/dt (eq. 8, no slip) gives
    (1 + k2) d omega2/dt = -c sgn(omega2), k2 = 1/2: omega2 stops at t* = 1.5 |w0| / c.
    Then nothing needs a moment: the rolling resistance sticks and the disk rests."""
    disk, c = rd.Disk(0.0), 0.05
    y0 = rd.rolling_state(disk, [0, 0, 0, 0, 0, 0, w0, 0])
    t_star = 1.5 * abs(w0) / c
    tr = rd.simulate_coulomb(disk, rd.Coulomb(0.5, rolling_resistance=c),
                             (0.0, t_star + 10.0), y0, method=method)
    assert tr.status == "completed" and tr.n_steps < 100
    (x,) = tr.transitions
    assert (x.from_mode, x.to_mode) == ("rolling", "rolling, roll stuck")
    assert abs(x.t - t_star) <= 1e-9
    after = tr.t >= x.t
    assert np.all(tr.mode[tr.t > x.t] == rd.MODE_NAMES.index("rolling, roll stuck"))
    assert np.abs(tr.y[7:10, after]).max() <= 1e-12
    assert np.abs(tr.y[2:4, after]).max() <= 1e-12
    assert np.ptp(tr.y[0, after]) <= 1e-12  # at rest
    assert tr.dissipated["rolling_resistance"][-1] == pytest.approx(0.75 * w0 ** 2,
                                                                     rel=1e-12)
    assert rd.energy_balance(tr) <= 1e-9


# ---------------------------------------------------- a thick disk on one rim edge
H, C = 0.5, 0.02
DISK = rd.Disk(H)
TE = math.atan(H)  # C above P: y_P = 0


@pytest.mark.parametrize("ratio", [-1.5, -0.9, -0.3, 0.5, 0.95, 1.05, 2.0])
def test_released_on_a_rim_edge_sticks_iff_the_static_balance_allows(ratio):
    """Released at rest (omega = 0) at a tilt where the gravity lever arm about the contact
    is y_P = ratio c: the static balance needs the horizontal moment y_P F_z with F_z = 1,
    so the rolling resistance holds the disk iff |y_P| <= c; else it tips."""
    th = TE + math.asin(ratio * C / math.hypot(1.0, H))  # sin th - h cos th = ratio c
    assert _y_P(H, th) == pytest.approx(ratio * C, rel=1e-12)
    y0 = rd.rolling_state(DISK, [0, 0, 0, th, 0, 0, 0, 0])
    tr = rd.simulate_coulomb(DISK, rd.Coulomb(0.8, rolling_resistance=C), (0.0, 1.0), y0)
    assert rd.energy_balance(tr) <= 1e-9
    if abs(ratio) <= 1.0:
        assert tr.status == "completed" and not tr.transitions
        assert np.all(tr.mode == rd.MODE_NAMES.index("rolling, roll stuck"))
        assert np.ptp(tr.y[5]) <= 1e-12
        M = rd.coulomb_contact(DISK, tr.ground, "rolling, roll stuck", y0)
        assert M["M_roll_x"] == pytest.approx(-ratio * C, rel=1e-9)
    else:
        assert rd.MODE_NAMES[tr.mode[0]] == "rolling"
        assert math.copysign(1.0, tr.y[5, -1] - th) == math.copysign(1.0, ratio)  # tips


def _rocking(sym, c):
    """d/dt (theta, omega1) of the planar rocking (omega2 = omega3 = 0) with the moment
    -c F_z sgn(omega1) e_x, from the lambdified sympy rolling equations."""
    f = sym["free"]["rolling"]

    def rhs(t, q):
        th, w1 = q
        r = f(H * math.copysign(1.0, th), th, w1, 0.0, 0.0, 0, 0, 0,
              -c * math.copysign(1.0, w1), 0.0, 0.0)
        return [w1, r[0]]
    return rhs


def _stop(sym, th0, w1, t1):
    """The first zero of omega1 of the independent rocking solve, integrated up to it (past
    it the sign function would chatter in solve_ivp); solve_ivp locates it by brentq on
    the dense output."""
    def zero(t, q):
        return q[1]
    zero.terminal = True
    sol = solve_ivp(_rocking(sym, C), (0.0, t1), [th0, w1], method="DOP853", rtol=1e-13,
                    atol=1e-15, dense_output=True, events=zero)
    (t_stop,) = sol.t_events[0]
    return t_stop, sol


@pytest.mark.parametrize("method", METHODS)
def test_rocking_up_to_the_balance_sticks_where_it_stops(sym, method):
    """Rocking up towards y_P = 0 from y_P = 0.112 > c with omega1 = -0.0975: it stops at
    y_P = 0.0024 (|y_P| <= c), where the rolling resistance holds it; the stop time against
    the independent solve, the hold against the static balance."""
    th0, w1 = TE + 0.1, -0.0975
    y0 = rd.rolling_state(DISK, [0, 0, 0, th0, 0, w1, 0, 0])
    tr = rd.simulate_coulomb(DISK, rd.Coulomb(0.8, rolling_resistance=C), (0.0, 6.0), y0,
                             method=method)
    assert tr.status == "completed"
    (x,) = tr.transitions
    assert (x.from_mode, x.to_mode) == ("rolling", "rolling, roll stuck")
    assert rd.energy_balance(tr) <= 1e-9
    t_stop, sol = _stop(sym, th0, w1, 4.0)
    assert abs(x.t - t_stop) <= 1e-9
    th_stop = sol.sol(t_stop)[0]
    assert abs(_y_P(H, th_stop)) <= C  # the static balance holds it
    after = tr.t >= x.t
    assert np.abs(tr.y[5, after] - th_stop).max() <= 1e-9
    assert np.abs(tr.y[7, after]).max() <= 1e-12


@pytest.mark.parametrize("method", METHODS)
def test_rocking_that_stops_beyond_the_bound_flips_and_falls_back(sym, method):
    """Rocking up with omega1 = -0.08 it stops at y_P = 0.058 > c: the rolling resistance
    cannot hold it, its moment flips and the disk falls back (no transition, omega1 turns
    positive), against the independent solve."""
    th0, w1 = TE + 0.1, -0.08
    y0 = rd.rolling_state(DISK, [0, 0, 0, th0, 0, w1, 0, 0])
    tr = rd.simulate_coulomb(DISK, rd.Coulomb(0.8, rolling_resistance=C), (0.0, 3.0), y0,
                             method=method)
    assert tr.status == "completed" and not tr.transitions
    assert rd.energy_balance(tr) <= 1e-9
    t_stop, sol = _stop(sym, th0, w1, 2.0)
    assert abs(_y_P(H, sol.sol(t_stop)[0])) > C  # the static balance cannot hold it
    stop = np.flatnonzero(np.abs(tr.t - t_stop) <= 1e-9)
    assert stop.size >= 1 and abs(tr.y[7, stop[0]]) <= 1e-12  # located, omega1 = 0 there
    assert tr.y[7, -1] > 0.0 and tr.y[5, -1] > sol.sol(t_stop)[0]
    q = solve_ivp(_rocking(sym, C), (t_stop, 3.0), [sol.sol(t_stop)[0], 1e-300],
                  method="DOP853", rtol=1e-13, atol=1e-15).y[:, -1]
    assert tr.y[5, -1] == pytest.approx(q[0], abs=1e-8)
    assert tr.y[7, -1] == pytest.approx(q[1], abs=1e-8)

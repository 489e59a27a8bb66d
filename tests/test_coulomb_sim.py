"""Hybrid rolling/sliding simulation on Coulomb ground (rollingdisk.ivp.hybrid)."""

import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp

import rollingdisk as rd
from rollingdisk.ivp.hybrid import energy_balance, simulate_coulomb, slip_direction
from rollingdisk.model.ground import Coulomb
from rollingdisk.util.errors import ParameterError

ROUGH_IN_COULOMB = [0, 1, 4, 5, 6, 7, 8, 9]


@pytest.mark.parametrize("v0,mu", [(1.0, 0.2), (2.5, 0.35), (0.7, 1.0)])
def test_classic_transition_upright_thin_disk(v0, mu):
    """Upright thin disk sliding with V_X = v0, no rotation (m = a = g = 1).

    F_z = 1 (theta = omega = 0 throughout, eq. 11), friction -mu in x: dV_X/dt = -mu and,
    from (9)_2 with a = 1 and k2^2 = 1/2, d omega2/dt = F_x... with F_x = -mu: k2^2
    d omega2/dt = -a F_x = mu, so omega2 = 2 mu t.  The slip u_x = V_X - omega2 = v0 - 3 mu t
    (eq. 6) vanishes at t* = v0/(3 mu), where V_X = 2 v0/3 = omega2: rolling from then on
    (rolling needs no friction: F_t = 0 inside the cone).  The same result comes out of the
    sympy derivation, see rollingdisk.symbolic.coulomb.classic_transition."""
    tr = simulate_coulomb(rd.Disk(0.0), Coulomb(mu), (0, 2 * v0 / (3 * mu)),
                          [0, 0, v0, 0, 0, 0, 0, 0, 0, 0])
    assert tr.status == "completed"
    assert len(tr.transitions) == 1
    tt = tr.transitions[0]
    assert (tt.from_mode, tt.to_mode) == ("sliding", "rolling")
    assert tt.as_dict() == {"t": tt.t, "from": "sliding", "to": "rolling"}
    assert abs(tt.t - v0 / (3 * mu)) <= 1e-9
    i = int(np.searchsorted(tr.t, tt.t))
    assert abs(tr.V_X[i] - 2 * v0 / 3) <= 1e-9
    assert abs(tr.V_X[-1] - 2 * v0 / 3) <= 1e-9 and abs(tr.omega2[-1] - 2 * v0 / 3) <= 1e-9
    assert set(tr.mode[tr.t < tt.t]) == {1} and set(tr.mode[tr.t > tt.t]) == {0}
    assert energy_balance(tr) <= 1e-9
    # energy dissipated by slip: v0^2/2 - (V^2/2 + k2 omega2^2/2) = v0^2/6
    assert abs(tr.dissipated["slip"][-1] - v0 * v0 / 6) <= 1e-9


def _perturbed(h, theta, Omega0, eps=0.02):
    m = rd.steady_motion(rd.Disk(h), "rough", theta, Omega0=Omega0)
    yr = m.initial_state(psi0=0.3)
    yr[3] += eps
    yr[5] += eps / 2
    return m, yr


def _random_cases(n, seed):
    rng = np.random.default_rng(seed)
    out = []
    while len(out) < n:
        h = 0.0 if len(out) % 4 == 0 else rng.uniform(0.0, 1.5)
        th = rng.choice([-1.0, 1.0]) * rng.uniform(0.2, 1.2)
        Om = rng.choice([-1.0, 1.0]) * rng.uniform(1.0, 4.0)
        out.append((h, th, Om))
    return out


def _check_limits(h, th, Om, t_end):
    disk = rd.Disk(h)
    m, yr = _perturbed(h, th, Om)
    kw = dict(rtol=1e-12, atol=1e-13)
    rough = rd.simulate(disk, "rough", (0, t_end), yr, **kw)
    coul = simulate_coulomb(disk, Coulomb(1e6), (0, t_end), rd.rolling_state(disk, yr), **kw)
    if rough.status != "completed":
        return False
    assert coul.status == "completed" and coul.transitions == ()
    assert np.max(np.abs(rough.y[:, -1] - coul.y[ROUGH_IN_COULOMB, -1])) <= 1e-8
    assert energy_balance(coul) <= 1e-9
    ys = rd.steady_motion(disk, "smooth", th, Omega0=Om).initial_state(psi0=0.3)
    ys[5] += 0.02
    ys[7] += 0.01
    ys[2] += 0.1
    smooth = rd.simulate(disk, "smooth", (0, t_end), ys, **kw)
    free = simulate_coulomb(disk, Coulomb(0.0), (0, t_end), ys, **kw)
    if smooth.status == "completed":
        assert free.status == "completed" and free.transitions == ()
        assert np.max(np.abs(smooth.y[:, -1] - free.y[:, -1])) <= 1e-8
        assert energy_balance(free) <= 1e-9
    return True


@pytest.mark.parametrize("h,th,Om", [(0.4, -0.6, -1.5)])
def test_limits_rough_and_smooth_fast(h, th, Om):
    assert _check_limits(h, th, Om, 100.0)


@pytest.mark.slow
def test_limits_rough_and_smooth_random():
    """>= 20 random perturbed steady motions, thin and thick, both signs of theta, 100 time
    units: mu_s huge == rough, mu = 0 == smooth, to 1e-8."""
    done = sum(_check_limits(h, th, Om, 100.0) for h, th, Om in _random_cases(24, seed=4))
    assert done >= 20


@pytest.mark.parametrize("h,theta0,r_C", [(0.0, 0.6, 2.0), (0.3, 0.9, 1.0), (1.0, -0.7, 0.5)])
def test_steady_circle_around_mu_required(h, theta0, r_C):
    disk = rd.Disk(h)
    m = rd.steady_motion(disk, "rough", theta0, r_C=r_C)
    y = rd.rolling_state(disk, m.initial_state())
    keep = simulate_coulomb(disk, Coulomb(1.01 * m.mu_required), (0, 20), y)
    assert keep.status == "completed" and keep.transitions == ()
    assert set(keep.mode) == {0}
    assert np.max(np.abs(keep.theta - theta0)) < 1e-8
    slip = simulate_coulomb(disk, Coulomb(0.99 * m.mu_required), (0, 1), y)
    assert slip.transitions[0].t == 0.0
    assert (slip.transitions[0].from_mode, slip.transitions[0].to_mode) == ("rolling",
                                                                              "sliding")
    assert slip.mode[0] == 1
    assert energy_balance(slip) <= 1e-9
    # the slip starts outward: friction was pulling C towards A (eq. 27), the disk slides away
    d = slip_direction(disk, Coulomb(0.99 * m.mu_required), y)
    assert d is not None and d[1] * m.F_y < 0


def _independent_sliding_transition(h, mu, y0, t_max, eps=2e-7):
    """The derived sliding equations (sympy, lambdified, friction -mu F_z u/|u|) integrated
    with solve_ivp at tight tolerance in the Cxyz components (v_Cx, v_Cy, theta,
    omega1..3), until |u| = eps (found by bisection on the dense output).  Near the stick
    time |u| falls linearly, t* = t_eps + eps/|d|u|/dt| + O(eps^2); done for eps and eps/2
    and extrapolated (Richardson)."""
    from rollingdisk.symbolic.coulomb import lambdified_coulomb

    f = lambdified_coulomb()["sliding"]
    psi = y0[4]
    v = [y0[2] * math.cos(psi) + y0[3] * math.sin(psi),
         -y0[2] * math.sin(psi) + y0[3] * math.cos(psi)]
    x0 = np.array([*v, y0[5], y0[7], y0[8], y0[9]])

    def geo(x):
        th = x[2]
        ht = h * math.copysign(1.0, th)
        return ht, math.sin(th) - ht * math.cos(th), -(math.cos(th) + ht * math.sin(th))

    def slip(x):
        ht, y_P, z_P = geo(x)
        return np.array([x[0] - x[4] + ht * x[5], x[1] - x[3] * z_P])  # eq. (6)

    def accel(x):
        u = slip(x)
        e = u / np.linalg.norm(u)
        ht = geo(x)[0]
        return f(ht, x[2], x[3], x[4], x[5], x[0], x[1], mu, e[0], e[1], *[0.0] * 6)

    def rhs(t, x):
        r = accel(x)
        return [r[6], r[7], x[3], r[0], r[1], r[2]]

    def speed_rate(x):  # d|u|/dt; the turning of Cxyz is normal to u
        r = accel(x)
        ht, y_P, z_P = geo(x)
        du = np.array([r[6] - r[1] + ht * r[2], r[7] - r[0] * z_P - x[3] ** 2 * y_P])
        u = slip(x)
        return u @ du / np.linalg.norm(u)

    def small(t, x):
        return np.linalg.norm(slip(x)) - eps / 2

    small.terminal = True
    sol = solve_ivp(rhs, (0, t_max), x0, method="DOP853", rtol=1e-13, atol=1e-14,
                    dense_output=True, events=small)
    est = []
    for ep in (eps, eps / 2):
        a, b = 0.0, sol.t[-1]
        for _ in range(80):
            c = 0.5 * (a + b)
            a, b = (c, b) if np.linalg.norm(slip(sol.sol(c))) > ep else (a, c)
        te = 0.5 * (a + b)
        est.append(te + ep / -speed_rate(sol.sol(te)))
    return (4 * est[1] - est[0]) / 3


@pytest.mark.parametrize("h,theta,Omega0,slip", [(0.4, 0.5, 2.0, (0.3, 0.2)),
                                                 (1.0, -0.8, -1.5, (-0.2, 0.25))])
def test_thick_disk_transition_against_independent_integration(h, theta, Omega0, slip):
    """A steady circle kicked into sliding sticks again; the stick time equals that of an
    independent integration of the derived sliding equations to 1e-9."""
    disk = rd.Disk(h)
    mu = 0.5
    m = rd.steady_motion(disk, "rough", theta, Omega0=Omega0)
    y = rd.rolling_state(disk, m.initial_state(psi0=0.4))
    y[2] += slip[0]
    y[3] += slip[1]
    tr = simulate_coulomb(disk, Coulomb(mu), (0, 3), y)
    assert tr.transitions and tr.transitions[0].from_mode == "sliding"
    t_ref = _independent_sliding_transition(h, mu, y, 1.5 * tr.transitions[0].t)
    assert abs(tr.transitions[0].t - t_ref) <= 1e-9
    assert energy_balance(tr) <= 1e-9


def test_dissipation_energy_balance_and_monotone():
    """All terms on: E + dissipated = const to 1e-9, E never increases (eq. 14)."""
    disk = rd.Disk(0.1)
    g = Coulomb(0.4, 0.3, rolling_resistance=0.005, pivot=0.01, air=0.002)
    m = rd.steady_motion(disk, "rough", 0.5, Omega0=3.0)
    y = rd.rolling_state(disk, m.initial_state())
    y[2] += 0.05
    tr = simulate_coulomb(disk, g, (0, 10), y)
    assert tr.success
    assert energy_balance(tr) <= 1e-9
    assert np.all(np.diff(tr.E) <= 1e-12)
    assert all(np.all(np.diff(d) >= -1e-15) for d in tr.dissipated.values())
    assert tr.dissipated["air"][-1] > 0 and tr.dissipated["pivot"][-1] > 0
    cols = tr.as_columns()
    assert "mode" in cols and "V_X" in cols


def test_budget_and_arguments():
    disk = rd.Disk(0.0)
    y = [0, 0, 1, 0, 0, 0.5, 0, 0, 0, 0]
    tr = simulate_coulomb(disk, Coulomb(0.2), (0, 100), y, max_steps=3)
    assert tr.status == "step-budget" and "step budget" in tr.message
    with pytest.raises(ParameterError, match="ground"):
        simulate_coulomb(disk, "rough", (0, 1), y)
    with pytest.raises(ParameterError, match="t_span"):
        simulate_coulomb(disk, Coulomb(0.2), (1, 0), y)
    with pytest.raises(ParameterError, match="y0"):
        simulate_coulomb(disk, Coulomb(0.2), (0, 1), y[:8])
    with pytest.raises(ParameterError, match="max_steps"):
        simulate_coulomb(disk, Coulomb(0.2), (0, 1), y, max_steps=0)


def test_falls_flat_is_terminal():
    disk = rd.Disk(0.0)
    tr = simulate_coulomb(disk, Coulomb(0.5), (0, 50), [0, 0, 0, 0, 0, 0.3, 0, 0, 0, 0])
    assert tr.status in ("fell-flat", "lift-off")
    assert tr.t_event == tr.t[-1] and tr.t[-1] < 50


def test_nonfinite_and_alpha_min_arguments():
    disk = rd.Disk(0.0)
    y = [0, 0, 1, 0, 0, 0.5, 0, 0, 0, 0]
    with pytest.raises(ParameterError, match="alpha_min"):
        simulate_coulomb(disk, Coulomb(0.2), (0, 1), y, alpha_min=-1.0)
    tr = simulate_coulomb(disk, Coulomb(0.5), (0, 50), [0, 0, 0, 0, 0, 0.3, 0, 0, 0, 0],
                          alpha_min=0.2)
    assert tr.status == "fell-flat"
    assert abs(0.5 * math.pi - abs(tr.theta[-1]) - 0.2) < 1e-12

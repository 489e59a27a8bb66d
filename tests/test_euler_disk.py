"""Euler's disk (rollingdisk.scenarios.euler_disk), grouped by source of truth:

* the sympy derivation (sliding system with a general friction force) vs the creep
  right-hand side at random states; the creep law's shape derived with sympy;
* the steady family written in alpha vs :func:`rollingdisk.steady_motion`;
* closed-form asymptotics of the adiabatic decay (2, -1, -1 and Moffatt's 1/3, -1/6);
* energy balance (eq. 12), chain rule on eq. (13) vs the powers, dE/dt <= 0;
* limits: large creep coefficient -> the hybrid rolling run; mu = 0 -> the smooth ground;
* the toy run to its end: end kind, exponents vs the independent prediction;
* bounded work and invalid input.
"""

import math

import numpy as np
import pytest

import rollingdisk as rd
from rollingdisk.model import geometry as eq
from rollingdisk.model.air_models import BoundaryLayerAirDrag
from rollingdisk.scenarios.euler_disk import (
    AIR_VISCOSITY,
    FIT_WINDOW_AIR,
    EulerDisk,
    creep_factor,
    predicted_exponents,
    run_euler_disk,
)
from rollingdisk.scenarios.euler_kernels import _energy, _rhs
from rollingdisk.scenarios.euler_predict import _family
from rollingdisk.util.errors import ParameterError


@pytest.fixture(scope="module")
def toy_run():
    return run_euler_disk(EulerDisk())


def _random_reduced(rng, h):
    theta = rng.choice([-1.0, 1.0]) * rng.uniform(0.05, 1.5)
    v = rng.uniform(-1, 1, 2)
    w = rng.uniform(-3, 3, 3)
    return np.array([*v, theta, *w, 0.0, 0.0, 0.0])


# ------------------------------------------------------------------ derivation
def test_creep_rhs_equals_sympy_sliding_system():
    """The reduced right-hand side against the derived sliding system with the friction
    force ``-mu F_z e``, ``e`` the creep vector (the derivation is linear in ``mu e``), and
    the moments of the air film and the smoothed rolling resistance."""
    from rollingdisk.symbolic.coulomb import lambdified_coulomb

    sliding = lambdified_coulomb()["sliding"]
    rng = np.random.default_rng(3)
    for i in range(60):
        h = 0.0 if i % 10 == 0 else rng.uniform(0, 2)
        mu = rng.uniform(0, 1)
        u_s = rng.choice([1e-3, 0.1, 10.0])
        c_roll, c_air, eps = rng.uniform(0, 0.1), rng.uniform(0, 0.1), 1e-6
        x = _random_reduced(rng, h)
        v_Cx, v_Cy, th, w1, w2, w3 = x[:6]
        ht, s, c, p, y_P, z_P = eq.contact_geometry(h, th)
        u = np.array([v_Cx - w2 + ht * w3, v_Cy - w1 * z_P])  # eq. (6)
        e = creep_factor(np.hypot(*u), u_s) * u
        # the library's moment models: AirDrag, and RollingResistance with |omega_h|
        # replaced by sqrt(|omega_h|^2 + eps^2)
        wx, wy, _ = rd.angular_velocity_xyz(th, w1, w2, w3)
        r = math.hypot(wx, wy)
        M1 = rd.RollingResistance(c_roll).moment(th, w1, w2, w3, 1.0)
        M1 = tuple(m * r / math.sqrt(r * r + eps * eps) for m in M1)
        M = (*rd.AirDrag(c_air).moment(th, w1, w2, w3), *M1)
        ref = sliding(ht, th, w1, w2, w3, v_Cx, v_Cy, mu, *e, *M)
        dx, F_z, _ = _rhs(h, mu, u_s, c_roll, c_air, eps, x)
        want = [ref[6], ref[7], w1, ref[0], ref[1], ref[2]]  # dv_Cx, dv_Cy, theta', dw
        np.testing.assert_allclose(dx[:6], want, rtol=1e-10, atol=1e-10)
        np.testing.assert_allclose(F_z, ref[5], rtol=1e-10, atol=1e-12)
        # the element-wise path (recorded steps) equals the integrator's scalar path
        dx2, F_z2, n2 = _rhs(h, mu, u_s, c_roll, c_air, eps, np.stack([x, x], axis=1))
        np.testing.assert_allclose(dx2[:, 1], dx, rtol=1e-14, atol=1e-300)
        assert F_z2[0] == F_z


def test_boundary_layer_rhs_equals_sympy_sliding_system():
    """The right-hand side with c_bl against the derived sliding system with the moment of
    BoundaryLayerAirDrag (plus the smoothed rolling resistance)."""
    from rollingdisk.symbolic.coulomb import lambdified_coulomb

    sliding = lambdified_coulomb()["sliding"]
    rng = np.random.default_rng(11)
    for i in range(40):
        h = 0.0 if i % 10 == 0 else rng.uniform(0, 2)
        mu, u_s = rng.uniform(0, 1), rng.choice([1e-3, 0.1, 10.0])
        c_roll, c_bl, eps = rng.uniform(0, 0.1), rng.uniform(0, 0.1), 1e-6
        x = _random_reduced(rng, h)
        v_Cx, v_Cy, th, w1, w2, w3 = x[:6]
        ht, s, c, p, y_P, z_P = eq.contact_geometry(h, th)
        u = np.array([v_Cx - w2 + ht * w3, v_Cy - w1 * z_P])
        e = creep_factor(np.hypot(*u), u_s) * u
        wx, wy, _ = rd.angular_velocity_xyz(th, w1, w2, w3)
        r = math.hypot(wx, wy)
        M1 = rd.RollingResistance(c_roll).moment(th, w1, w2, w3, 1.0)
        M1 = tuple(m * r / math.sqrt(r * r + eps * eps) for m in M1)
        M = (*BoundaryLayerAirDrag(c_bl).moment(th, w1, w2, w3), *M1)
        ref = sliding(ht, th, w1, w2, w3, v_Cx, v_Cy, mu, *e, *M)
        dx, F_z, _ = _rhs(h, mu, u_s, c_roll, 0.0, eps, x, c_bl=c_bl)
        np.testing.assert_allclose(dx[:6], [ref[6], ref[7], w1, ref[0], ref[1], ref[2]],
                                   rtol=1e-10, atol=1e-10)
        np.testing.assert_allclose(F_z, ref[5], rtol=1e-10, atol=1e-12)
        # the air term's power is the model's: -c |Omega|^(5/2)
        assert dx[8] == pytest.approx(-BoundaryLayerAirDrag(c_bl).power(th, w1, w2, w3),
                                      rel=1e-12, abs=1e-300)
        dx2, F_z2, _ = _rhs(h, mu, u_s, c_roll, 0.0, eps, np.stack([x, x], axis=1),
                            c_bl=c_bl)
        np.testing.assert_allclose(dx2[:, 0], dx, rtol=1e-14, atol=1e-300)


def test_creep_law_shape_derived():
    """f(s) = 1 - (1 - s)^3: f(0) = 0, slope 3 (so k = 3 mu / u_s), and f = 1, f' = f'' = 0
    at saturation (a C^2 join to Coulomb's mu F_z); creep_factor * |u| is f."""
    import sympy as sp

    s = sp.symbols("s")
    f = 1 - (1 - s) ** 3
    assert f.subs(s, 0) == 0 and sp.diff(f, s).subs(s, 0) == 3
    assert f.subs(s, 1) == 1 and sp.diff(f, s).subs(s, 1) == 0
    assert sp.diff(f, s, 2).subs(s, 1) == 0
    u_s = 0.02
    slip = np.array([0.0, 1e-9, 0.005, 0.0199, 0.02, 0.5])
    fs = sp.lambdify(s, sp.expand(f))(np.minimum(slip / u_s, 1.0))
    np.testing.assert_allclose(creep_factor(slip, u_s) * slip, fs, rtol=1e-13, atol=1e-300)
    assert creep_factor(0.0, u_s) == pytest.approx(3.0 / u_s)


def test_family_in_alpha_equals_steady_motion():
    h = EulerDisk().h
    for alpha in (1e-3, 0.01, 0.1, 0.3, 0.6):
        E, Om, wh, w3, y_P = _family(h, alpha)
        m = rd.steady_motion(rd.Disk(h), "rough", math.pi / 2 - alpha, r_C=0.0)
        y = rd.rolling_state(rd.Disk(h), m.initial_state())
        assert Om == pytest.approx(m.Omega0, rel=1e-12)
        assert w3 == pytest.approx(m.omega30, rel=1e-12)
        assert y_P == pytest.approx(m.y_P0, rel=1e-12)
        assert E == pytest.approx(rd.coulomb_energy(rd.Disk(h), y), rel=1e-12)
        wx, wy, wz = rd.angular_velocity_xyz(m.theta0, 0.0, m.omega20, m.omega30)
        assert wh == pytest.approx(math.hypot(wx, wy), rel=1e-10)


def test_predicted_exponents_tend_to_closed_forms():
    """Near alpha = 0 the family has E - E_inf ~ alpha, |omega_h| ~ alpha^(1/2), Omega ~
    alpha^(-1/2); with rolling resistance (P ~ |omega_h|) that gives alpha ~ tau^2, Omega ~
    tau^(-1); with Moffatt's film (P ~ Omega^2/alpha) alpha ~ tau^(1/3), Omega ~ tau^(-1/6)."""
    rr = predicted_exponents(EulerDisk(), window=(1e-7, 1e-6))
    assert rr["alpha"] == pytest.approx(2.0, abs=2e-3)
    assert rr["Omega"] == pytest.approx(-1.0, abs=2e-3)
    assert rr["contact_speed"] == pytest.approx(-1.0, abs=2e-3)
    air = predicted_exponents(EulerDisk(rolling_resistance=0.0, air_viscosity=AIR_VISCOSITY),
                              window=(1e-7, 1e-6))
    assert air["alpha"] == pytest.approx(1 / 3, abs=1e-3)
    assert air["Omega"] == pytest.approx(-1 / 6, abs=1e-3)
    assert air["contact_speed"] == pytest.approx(-1 / 6, abs=1e-3)


# ------------------------------------------------------------------ energy
def test_energy_rate_equals_powers_and_is_negative():
    """dE/dt by the chain rule on eq. (13) (complex step along the right-hand side) equals
    minus the dissipated powers, and each power is <= 0 (eq. 14) while F_z >= 0."""
    rng = np.random.default_rng(8)
    for _ in range(60):
        h = rng.uniform(0, 1)
        mu, u_s = rng.uniform(0, 1), rng.choice([1e-3, 0.1])
        c_roll, c_air = rng.uniform(0, 0.05), rng.uniform(0, 0.05)
        x = _random_reduced(rng, h)
        dx, F_z, _ = _rhs(h, mu, u_s, c_roll, c_air, 1e-6, x)
        d = 1e-30
        rate = np.imag(_energy(h, x + 1j * d * dx)) / d
        assert rate == pytest.approx(-dx[6:].sum(), rel=1e-9, abs=1e-12)
        if F_z >= 0:
            assert np.all(dx[6:] >= -1e-15)


def test_toy_energy_balance_and_decay(toy_run):
    r = toy_run
    assert r.energy_balance <= 1e-9
    assert np.all(np.diff(r.E) <= 1e-10 * abs(r.E[0]))  # dE/dt <= 0 step by step
    for v in r.dissipated.values():
        assert np.all(np.diff(v) >= -1e-14)
    assert r.dissipated["air"][-1] == 0.0


# ------------------------------------------------------------------ limits
def _kicked_rolling_start(h, alpha0, kick):
    d = rd.Disk(h)
    m = rd.steady_motion(d, "rough", math.pi / 2 - alpha0, r_C=0.0)
    yr = m.initial_state()
    yr[5] += kick
    return d, rd.rolling_state(d, yr)


def test_large_creep_coefficient_is_rolling():
    """k -> inf: the creep run tends to the hybrid (DOP853, kept rolling with mu_s = 1e6)
    run with the same rolling resistance, at rate 1/k."""
    T, kick, c = 20.0, 0.05, 0.01
    d, y0 = _kicked_rolling_start(EulerDisk().h, 0.5, kick)
    tr = rd.simulate_coulomb(d, rd.Coulomb(1e6, rolling_resistance=c), (0, T), y0)
    assert tr.status == "completed" and len(tr.transitions) == 0
    th, w3 = tr.component("theta")[-1], tr.component("omega3")[-1]
    err = []
    for k in (1e5, 1e6):
        r = run_euler_disk(EulerDisk(creep=k, rolling_resistance=c, alpha0=0.5), t_max=T,
                           kick=kick, rtol=1e-11, atol=1e-13, predict=False)
        assert r.t[-1] == T and r.end is None and "t_max" in r.message
        err.append((abs(math.pi / 2 - th - r.alpha[-1]), abs(w3 / math.cos(th) - r.Omega[-1])))
    assert err[1][0] < 1e-5 and err[1][1] < 1e-4
    for a, b in zip(*err):
        assert 7 < a / b < 13  # first order in 1/k


def test_mu_zero_is_smooth_ground():
    T, kick = 20.0, 0.05
    d, y0 = _kicked_rolling_start(EulerDisk().h, 0.5, kick)
    tr = rd.simulate(d, "smooth", (0, T), y0, rtol=1e-12, atol=1e-13)
    th, w3 = tr.component("theta")[-1], tr.component("omega3")[-1]
    r = run_euler_disk(EulerDisk(mu=0.0, rolling_resistance=0.0, alpha0=0.5), t_max=T,
                       kick=kick, rtol=1e-11, atol=1e-13, predict=False)
    assert abs(math.pi / 2 - th - r.alpha[-1]) < 1e-9
    assert abs(w3 / math.cos(th) - r.Omega[-1]) < 1e-8
    assert r.alpha.max() - r.alpha.min() > 0.01  # it did nutate
    assert all(v[-1] == 0.0 for v in r.dissipated.values())
    assert r.energy_balance < 1e-10


# ------------------------------------------------------------------ the toy
def test_toy_falls_flat_with_predicted_exponents(toy_run):
    r = toy_run
    assert r.status == "completed" and r.end == "fell-flat", r.message
    assert r.alpha[-1] == pytest.approx(1e-3, rel=1e-9) and r.alpha[-2] > 1e-3  # located
    assert 90.0 < r.t_end_s < 110.0  # the toy's quoted spin time, ~100 s (chosen c)
    assert r.t0 > r.t_end  # the power law's alpha = 0 lies beyond alpha_end
    # the end and t0 against the adiabatic decay along the steady family (independent:
    # quadrature of E'/|P| on the family; the run ends a little earlier, slip also
    # dissipates, 0.7 % of the loss)
    assert r.predicted_t_end * 0.99 < r.t_end < r.predicted_t_end
    assert r.t0 == pytest.approx(r.predicted_t0, rel=0.01)
    for name in ("alpha", "Omega", "contact_speed"):
        assert r.exponents[name] == pytest.approx(r.predicted[name], abs=5e-3), name
    assert r.F_z.min() > 0.9
    assert r.wall_time < 60.0


def test_lift_off_located():
    """A hard kick (omega1 = 2) lifts the toy: F_z (eq. 11) reaches 0, located on the
    step's dense output; a harder one (4) needs a pull from the plane at t = 0."""
    r = run_euler_disk(kick=2.0, t_max=50.0, predict=False)
    assert r.status == "completed" and r.end == "lift-off", r.message
    assert abs(r.F_z[-1]) < 1e-9 and np.all(r.F_z[:-1] > 0)
    r = run_euler_disk(kick=4.0, t_max=50.0, predict=False)
    assert r.end == "lift-off" and "at the start" in r.message and r.t.size == 1
    assert r.F_z[0] < 0


@pytest.mark.slow
def test_toy_with_air_film():
    """The squeeze film (the derived constant K = 1.28113, docs/errata-models.md): alone, the
    exponents tend to 1/3, -1/6 (Moffatt's) on the window where the disk still follows the
    steady family (it leaves it below alpha ~ 0.01, see docs/friction.md); with the toy's
    rolling resistance beside it, the end time is the adiabatic prediction's."""
    alone = run_euler_disk(EulerDisk(air_viscosity=AIR_VISCOSITY, rolling_resistance=0.0),
                           fit_window=FIT_WINDOW_AIR)
    assert alone.status == "completed" and alone.end == "fell-flat", alone.message
    assert alone.energy_balance <= 1e-9
    assert alone.exponents["alpha"] == pytest.approx(alone.predicted["alpha"], abs=0.01)
    assert alone.exponents["Omega"] == pytest.approx(alone.predicted["Omega"], abs=0.01)
    assert alone.predicted["alpha"] == pytest.approx(1 / 3, abs=0.01)
    r = run_euler_disk(EulerDisk(air_viscosity=AIR_VISCOSITY))
    assert r.status == "completed" and r.end == "fell-flat", r.message
    assert r.energy_balance <= 1e-9
    assert r.dissipated["air"][-1] > 0.05
    assert r.t_end == pytest.approx(r.predicted_t_end, rel=0.02)


# ------------------------------------------------------------------ bounded work, input
def test_bounded_work_statuses():
    r = run_euler_disk(max_steps=10, predict=False)
    assert r.status == "failed" and r.end is None and r.n_steps == 10
    assert "step budget" in r.message
    r = run_euler_disk(max_wall_time=1e-3, predict=False)
    assert r.status == "failed" and "wall-clock" in r.message
    r = run_euler_disk(t_max=1.0, predict=False)
    assert r.status == "failed" and "t_max" in r.message and r.t[-1] == 1.0
    assert all(math.isnan(v) for v in r.exponents.values())


def test_collapsing_steps_are_a_status(monkeypatch):
    """A right-hand side no step can resolve (v_Cx pushed back across 0 with +-1e3, a
    chattering switch): the run stops with "step sizes collapsed", it does not hang."""
    import rollingdisk.scenarios.euler_disk as ed

    rhs = ed._rhs

    def chatter(*args, **kw):
        dx, F_z, n = rhs(*args, **kw)
        x = args[-1]
        if np.ndim(x[0]) == 0:
            dx = dx.copy()
            dx[0] = -1e3 if x[0] > 0 else 1e3
        return dx, F_z, n

    monkeypatch.setattr(ed, "_rhs", chatter)
    r = ed.run_euler_disk(predict=False, max_wall_time=30.0)
    assert r.status == "failed" and "collapsed" in r.message and r.n_steps < 1000


def test_progress_fractions():
    seen = []
    r = run_euler_disk(EulerDisk(alpha0=0.05), predict=False, progress=seen.append)
    assert r.end == "fell-flat"
    assert seen[-1] == 1.0 and len(seen) < 400
    assert all(0.0 <= a <= b <= 1.0 for a, b in zip(seen, seen[1:]))


@pytest.mark.parametrize("kw, name", [
    ({"mu": -1}, "mu"), ({"radius": 0}, "radius"), ({"creep": 0}, "creep"),
    ({"alpha0": 2.0}, "alpha0"), ({"rolling_resistance": math.nan}, "rolling_resistance"),
    ({"air_viscosity": -1e-5}, "air_viscosity"),
])
def test_bad_toy_parameters(kw, name):
    with pytest.raises(ParameterError, match=name):
        EulerDisk(**kw)


@pytest.mark.parametrize("kw, name", [
    ({"alpha_end": 0.0}, "alpha_end"), ({"max_steps": 0}, "max_steps"),
    ({"fit_window": (0.1, 0.05)}, "fit_window"), ({"rtol": 1.0}, "rtol"),
    ({"max_wall_time": -1}, "max_wall_time"), ({"toy": 3}, "toy"),
])
def test_bad_run_arguments(kw, name):
    with pytest.raises(ValueError, match=name):
        run_euler_disk(**kw)


def test_plot_draws_fitted_and_predicted_slopes():
    import matplotlib

    matplotlib.use("Agg")
    from matplotlib.figure import Figure

    from rollingdisk.plotting.plots import plot_euler_disk

    r = run_euler_disk(EulerDisk(alpha0=0.05))
    out = plot_euler_disk(r, Figure())
    for name in ("alpha", "Omega", "contact_speed"):
        for kind, p in (("fit", r.exponents[name]), ("predicted", r.predicted[name])):
            x, y = out["lines"][f"{name}_{kind}"].get_data()
            slope = np.polyfit(np.log(x), np.log(y), 1)[0]
            assert slope == pytest.approx(p, rel=1e-9)

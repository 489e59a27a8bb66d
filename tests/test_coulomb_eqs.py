"""Coulomb ground, equations: kernels against the sympy derivation, limits, energy rate,
ground values (rollingdisk.model.ground, rollingdisk.symbolic.coulomb)."""

import math

import numpy as np
import pytest

import rollingdisk as rd
from conftest import random_states
from rollingdisk.model import coulomb as eq
from rollingdisk.model.ground import (
    AirDrag,
    Coulomb,
    PivotFriction,
    RollingResistance,
    angular_velocity_xyz,
    check_any_ground,
)
from rollingdisk.util.errors import ParameterError, ParameterTypeError

N = 60


@pytest.fixture(scope="module")
def coulomb_sym():
    from rollingdisk.symbolic.coulomb import lambdified_coulomb

    return lambdified_coulomb()


def _close(a, b, rel=1e-11):
    a, b = np.asarray(a, float), np.asarray(b, float)
    assert np.all(np.abs(a - b) <= rel * (1.0 + np.abs(b))), (a, b)


def _cxyz_velocity(y):
    V_X, V_Y, psi = y[2], y[3], y[4]
    return (V_X * math.cos(psi) + V_Y * math.sin(psi), -V_X * math.sin(psi) + V_Y * math.cos(psi))


def test_rolling_and_sliding_kernels_equal_derivation(coulomb_sym):
    rng = np.random.default_rng(11)
    for disk, y in random_states("smooth", N, seed=5):
        th, w1, w2, w3 = y[5], y[7], y[8], y[9]
        M = rng.uniform(-1, 1, 6) * rng.choice([0.0, 1.0])
        mu = rng.uniform(0, 1.5)
        a = rng.uniform(0, 2 * math.pi)
        e = (math.cos(a), math.sin(a))
        hk = disk.h_tilde(th)
        _close(eq._rolling_solve(disk.h, th, w1, w2, w3, *M),
               coulomb_sym["rolling"](hk, th, w1, w2, w3, *M))
        v = _cxyz_velocity(y)
        ref = coulomb_sym["sliding"](hk, th, w1, w2, w3, *v, mu, *e, *M)
        _close(eq._sliding_solve(disk.h, mu, *e, th, w1, w2, w3, *M), ref[:6])
        # the translational part of the numeric rhs: dV = R(psi) F, i.e. (8)_1,2
        g = Coulomb(mu)
        u = eq._slip_velocity(disk.h, y)
        if abs(u[0]) + abs(u[1]) > 1e-9:
            out = eq._coulomb_sliding(disk.h, mu, 0.0, 0.0, 0.0, y, *eq._to_inertial(y[4], *u))
            _, F_x, F_y = out[0], out[1], out[2]
            n = math.hypot(*u)
            r = coulomb_sym["sliding"](hk, th, w1, w2, w3, *v, mu, u[0] / n, u[1] / n, *[0] * 6)
            _close([F_x, F_y], r[3:5])
            dy = rd.coulomb_rhs(disk, g, "sliding", y)
            Om = w3 / math.cos(th)
            ps = y[4]
            # inertial acceleration from the rotating-frame derivatives (transport theorem)
            ax = r[6] - v[1] * Om
            ay = r[7] + v[0] * Om
            _close(dy[2:4], [ax * math.cos(ps) - ay * math.sin(ps),
                             ax * math.sin(ps) + ay * math.cos(ps)])


def test_limits_smooth_and_rough():
    """mu_k = 0 sliding == smooth (49); rolling without moments == rough (37), (38)."""
    g0 = Coulomb(0.0)
    for disk, y in random_states("smooth", N, seed=6):
        _close(rd.coulomb_rhs(disk, g0, "sliding", y),
               rd.equations_of_motion(disk, "smooth")(0.0, y), rel=1e-14)
    g = Coulomb(1.0)
    for disk, yr in random_states("rough", N, seed=7):
        y = rd.rolling_state(disk, yr)
        dy = rd.coulomb_rhs(disk, g, "rolling", y)
        dr = rd.equations_of_motion(disk, "rough")(0.0, yr)
        _close(dy[[0, 1, 4, 5, 6, 7, 8, 9]], dr)
        c = rd.coulomb_contact(disk, g, "rolling", y)
        _close([c["F_x"], c["F_y"], c["F_z"]], rd.contact_force(disk, "rough", yr))
        assert abs(c["u_x"]) + abs(c["u_y"]) < 1e-12
        _close(rd.coulomb_energy(disk, y), rd.energy(disk, "rough", yr), rel=1e-13)


@pytest.mark.parametrize("mode", ["rolling", "sliding"])
def test_energy_rate_is_the_sum_of_powers(mode):
    """dE/dt along the numeric rhs (chain rule on eq. 13) == v_P.F_t + sum omega.M (eq. 12),
    each power <= 0 (eq. 14)."""
    g = Coulomb(0.6, 0.4, rolling_resistance=0.02, pivot=0.03, air=0.05)
    for disk, y in random_states("smooth", N, seed=8):
        if mode == "rolling":
            y = y.copy()
            y[2], y[3] = eq._rolling_velocity(disk.h, y)
        dy = rd.coulomb_rhs(disk, g, mode, y)
        c = rd.coulomb_contact(disk, g, mode, y)
        th, w1, w2, w3 = y[5], y[7], y[8], y[9]
        y_P, z_P = disk.contact_point_xyz(th)
        k1 = disk.k1_sq
        v_Cz = -w1 * y_P
        dv_Cz = -dy[7] * y_P + w1 * w1 * z_P  # d y_P/d theta = -z_P
        dE = (y[2] * dy[2] + y[3] * dy[3] + v_Cz * dv_Cz + k1 * (w1 * dy[7] + w3 * dy[9])
              + 0.5 * w2 * dy[8] - y_P * w1)  # d(-z_P)/dt = -y_P omega1
        powers = [c["power_slip"], c["power_rolling_resistance"], c["power_pivot"],
                  c["power_air"]]
        if c["F_z"] >= 0:
            assert all(p <= 0 for p in powers)
        _close(dE, sum(powers), rel=1e-10)


def test_models_moment_and_power():
    rng = np.random.default_rng(3)
    for _ in range(50):
        th = rng.uniform(-1.5, 1.5)
        w = rng.uniform(-3, 3, 3)
        F_z = rng.uniform(0, 2)
        om = np.array(angular_velocity_xyz(th, *w))
        for m in (RollingResistance(0.1), PivotFriction(0.2), AirDrag(0.3)):
            M = np.array(m.moment(th, *w, F_z))
            _close(om @ M, m.power(th, *w, F_z), rel=1e-13)
            assert m.power(th, *w, F_z) <= 0
        M0x, M0y, M0z, M1x, M1y, M1z = eq._coulomb_moments(0.1, 0.2, 0.3, th, *w)
        tot = sum(np.array(m.moment(th, *w, F_z)) for m in
                  (RollingResistance(0.1), PivotFriction(0.2), AirDrag(0.3)))
        _close([M0x + F_z * M1x, M0y + F_z * M1y, M0z + F_z * M1z], tot, rel=1e-13)


def test_coulomb_validation():
    g = Coulomb(0.5)
    assert g.mu_k == 0.5 and not g.dissipative and check_any_ground(g) is g
    g = Coulomb(0.5, 0.3, rolling_resistance=0.01, air=AirDrag(1e-4))
    assert g.dissipative and g.coefficients == (0.01, 0.0, 1e-4)
    assert g.as_dict()["ground"] == "coulomb"
    assert Coulomb(0.2, pivot=0).pivot is None
    for bad, name in (((-0.1,), "mu_s"), ((math.nan,), "mu_s"), ((0.3, 0.4), "mu_k"),
                      ((0.3, -1.0), "mu_k"), ((0.3, None, -1.0), "rolling_resistance")):
        with pytest.raises(ParameterError, match=name):
            Coulomb(*bad)
    with pytest.raises(ParameterError, match="pivot"):
        Coulomb(0.3, pivot=math.inf)
    with pytest.raises(ParameterTypeError, match="mu_s"):
        Coulomb("0.3")
    with pytest.raises(ParameterTypeError, match="air"):
        Coulomb(0.3, air="x")
    assert check_any_ground("rough") == "rough"
    with pytest.raises(ParameterError):
        check_any_ground("icy")
    with pytest.raises(ParameterTypeError):
        check_any_ground(3)


def test_classic_transition_derived():
    import sympy as sp

    from rollingdisk.symbolic.coulomb import classic_transition

    v0, mu = sp.symbols("v0 mu", positive=True)
    t_star, V_star, w2_star = classic_transition()
    assert sp.simplify(t_star.subs(sp.Symbol("v0", positive=True), v0)
                       - v0 / (3 * sp.Symbol("mu", real=True))) == 0
    assert sp.simplify(V_star - 2 * sp.Symbol("v0", positive=True) / 3) == 0

"""Line contact: the upright disk on its tread under set-valued Coulomb friction.

The equations come from :mod:`rollingdisk.symbolic.line_contact` (Newton-Euler), checked
here against Lagrange's equations of the free body with the corners held down; the numeric
phase (:mod:`rollingdisk.phases.line_contact`) is checked against them, against closed forms
(spin in place, straight rolling) and against Coulomb's cone at every stored point.
"""

import math

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import rollingdisk as rd
from rollingdisk.phases import line_contact as lc
from rollingdisk.phases.motion import simulate_to_rest

sym = pytest.importorskip("rollingdisk.symbolic.line_contact")
sp = pytest.importorskip("sympy")


def _random_inputs(rng, n):
    out = []
    for _ in range(n):
        h = rng.uniform(0.02, 1.0)
        vals = {sym.h: h, sym.k1: 0.25 + h * h / 3.0, sym.k2: 0.5}
        for x in (sym.vx, sym.vy, sym.w2, sym.w3, *sym.F, sym.Mx, sym.My, sym.Mz):
            vals[x] = rng.uniform(-2.0, 2.0)
        out.append(vals)
    return out


@pytest.mark.slow
def test_newton_euler_agrees_with_lagrange_at_random_states():
    """Two routes: balances in the turning frame vs Lagrange's equations in the inertial
    frame and angles; equal symbolically and to 1e-12 at 50 random states."""
    ne, la = sym.newton_euler().solution, sym.lagrange().solution
    for k in sym.UNKNOWNS:
        assert sp.simplify(ne[k] - la[k]) == 0
    f_ne = sp.lambdify(sym.INPUTS, [ne[k] for k in sym.UNKNOWNS])
    f_la = sp.lambdify(sym.INPUTS, [la[k] for k in sym.UNKNOWNS])
    for vals in _random_inputs(np.random.default_rng(1), 50):
        args = [vals[x] for x in sym.INPUTS]
        assert np.allclose(f_ne(*args), f_la(*args), rtol=0, atol=1e-12)


def test_the_line_is_never_left_into_flight_and_the_energy_rate_is_the_friction_power():
    sub = sym.sub_phases()
    assert sub.normal_sum == 1
    assert sub.energy_rate == 0
    # leaving: lambda_-s = 0 where s G = h
    G = sp.Symbol("G", real=True)
    assert sp.simplify(sub.leave[sym.lam_m].subs(G, sym.h)) == 0
    assert sp.simplify(sub.leave[sym.lam_p].subs(G, -sym.h)) == 0


def test_spin_in_place_decays_at_mu_h_over_k1_and_no_faster_in_general():
    """Spinning in place the friction moment is mu h (lambda_+ + lambda_-) = mu h; the
    vertical moment of inertia (eq. 10, integrated over the cylinder) is k1^2."""
    from rollingdisk.symbolic import impact

    k1_sq = impact.inertia()[0].subs(impact.h, sym.h)
    sub = sym.sub_phases()
    sigma = sp.Symbol("sigma", real=True)
    assert sp.simplify(sub.spin_rate + sym.mu * sym.h * sigma / sym.k1) == 0
    assert sp.simplify(k1_sq - (sp.Rational(1, 4) + sym.h ** 2 / 3)) == 0
    # the friction moment is -sum_s y_s F_sx: |.| <= h (|F_+| + |F_-|) <= mu h
    assert sp.expand(sub.friction_moment - sym.h * (sym.F[0] - sym.F[2])) == 0


def test_rolling_needs_no_spin_and_decelerates_by_the_rolling_resistance():
    sub = sym.sub_phases()
    assert sub.rolling[sym.lam_p] == sp.Rational(1, 2) == sub.rolling[sym.lam_m]
    assert sp.simplify(sub.rolling[sym.dw2] - sym.My / (1 + sym.k2)) == 0
    assert sub.rolling[sym.dvy] == 0


def test_numeric_forces_agree_with_the_derived_solution():
    """line_forces (an 11 x 11 linear solve per mode) against newton_euler's closed form,
    with the friction forces it returns, to 1e-12 at random states and every mode."""
    ne = sym.newton_euler().solution
    f = sp.lambdify(sym.INPUTS, [ne[k] for k in sym.UNKNOWNS])
    rng = np.random.default_rng(3)
    for _ in range(60):
        h = rng.uniform(0.05, 1.0)
        y = np.r_[0.0, 0.0, rng.uniform(-3, 3), 0.0, rng.uniform(-1, 1, 4), 0.0]
        mode = int(rng.integers(0, 4)) | (lc.ROLL_STUCK if rng.random() < 0.3 else 0)
        p = lc.line_params(h, 0.5, 0.4, 0.02, 0.01, 0.03, mode)
        acc, lp, lm, Fp, Fm, M = lc.line_forces(y, p)
        want = f(h, 0.25 + h * h / 3, 0.5, *y[4:8], *Fp, *Fm, *M)
        assert np.allclose([*acc, lp, lm], want, rtol=0, atol=1e-12)


def test_coin_spun_upright_spins_as_long_as_coulomb_friction_needs():
    """The issue's done-when: h = 0.1, omega3 = 3, mu = 0.5 upright on its tread.  The
    friction moment is at most mu g h m (two corners, lever arm h each), the moment of
    inertia about the vertical k1^2 m = (1/4 + h^2/3) m, so the spin cannot stop before
    k1^2 omega3/(mu h) = 15.2 (and in the two-corner model stops exactly then, less the
    1e-9 slip floor); the energy 1/2 k1^2 omega3^2 = 1.14 is dissipated by friction."""
    h, w3, mu = 0.1, 3.0, 0.5
    k1 = 0.25 + h * h / 3.0
    bound = k1 * w3 / (mu * h)
    s0 = [0, 0, 1.0, 0, 0, 0, 0, 0, 0, 0, 0, w3]
    r = simulate_to_rest(rd.Disk(h), rd.Coulomb(mu, rolling_resistance=0.01), (0, 100),
                         s0, e=0.5)
    assert r.status == "at-rest" and "tread" in r.message
    assert r.t_end >= bound * (1.0 - 1e-7)
    assert r.t_end == pytest.approx(bound, rel=1e-7)
    assert r.impacts == ()  # nothing taken by an impulse
    assert r.dissipated == pytest.approx(0.5 * k1 * w3 * w3, rel=1e-12)
    assert r.energy_balance <= 1e-9
    # the spin decays no faster than the bound at every stored point
    for g in r.segments:
        if isinstance(g, lc.LineSegment) and g.t.size > 1:
            rate = -np.diff(g.states[7]) / np.diff(g.t)
            assert np.all(rate <= mu * h / k1 * (1 + 1e-9))


def test_disk_rolling_upright_keeps_its_speed_without_resistance():
    """Straight rolling on the tread needs no friction (sub_phases().rolling: F_x =
    M_y/(2(1 + k2^2)) = 0): the speed stays, C goes straight, phi turns with it."""
    v = 0.7
    s0 = [0, 0, 1.0, 0.3, 0, 0, v * math.cos(0.3), v * math.sin(0.3), 0, 0, v, 0]
    r = simulate_to_rest(rd.Disk(0.2), rd.Coulomb(0.5), (0, 40), s0)
    assert r.status == "completed"
    s = r.final_state
    assert math.hypot(s[6], s[7]) == pytest.approx(v, abs=1e-12)
    assert s[10] == pytest.approx(v, abs=1e-12) and s[11] == 0.0
    assert s[0] == pytest.approx(40 * v * math.cos(0.3), abs=1e-9)
    assert s[1] == pytest.approx(40 * v * math.sin(0.3), abs=1e-9)
    assert r.dissipated == 0.0 and r.energy_balance <= 1e-12


def test_disk_rolling_upright_stops_at_the_closed_form_time():
    """With rolling resistance c: d omega2/dt = -c/(1 + k2^2) = -c/1.5, rest at 1.5 v/c
    having rolled 0.75 v^2/c."""
    v, c = 1.0, 0.05
    s0 = [0, 0, 1.0, 0, 0, 0, v, 0, 0, 0, v, 0]
    r = simulate_to_rest(rd.Disk(0.3), rd.Coulomb(0.5, rolling_resistance=c), (0, 100), s0)
    assert r.status == "at-rest"
    assert r.t_end == pytest.approx(1.5 * v / c, rel=1e-9)
    assert r.final_state[0] == pytest.approx(0.75 * v * v / c, rel=1e-9)
    assert r.energy_balance <= 1e-9


def test_rolling_and_turning_tips_onto_the_inner_edge():
    """G = k2^2 omega2 omega3 + F_y > h: lambda_- < 0, the disk leaves the line onto corner
    + (theta > 0), as a turning coin leans into its turn."""
    h = 0.1
    s = np.array([0, 0, 1.0, 0, 0, 0, 1.0, 0, 0, 0, 1.0, 0.5])
    segs, out = lc.run_line_contact(h, rd.Coulomb(0.5), 0.0, 10.0, s)
    assert out.status == "rocking" and out.side == 1


def test_rolling_upright_with_a_whisker_of_rocking_rolls_to_rest_on_the_line():
    """A rocking disk whose rim changes accumulate enters the line; the residual rocking
    and slips are captured, then it rolls to rest at the closed form's time."""
    c = 0.05
    r = simulate_to_rest(rd.Disk(0.3), rd.Coulomb(0.5, rolling_resistance=c), (0, 100),
                         [0, 0, 1.0, 0, 0, 1e-9, 0, 1e-3, 1.0, 0.0], e=0.5, mu_impact=0.5)
    assert r.status == "at-rest" and "tread" in r.message
    assert r.t_end == pytest.approx(1.5 / c, rel=1e-3)
    for x in r.impacts:
        assert x.energy_lost >= 0.0
        assert math.hypot(*x.impulse[:2]) <= 0.5 * abs(x.impulse[2]) * (1 + 1e-9)
    assert r.energy_balance <= 1e-9


def test_disk_held_on_a_rim_edge_by_rolling_resistance_ends_at_rest():
    """Just past the balance tilt arctan h the gravity moment about the contact point,
    sin(theta) - h cos(theta) ~ 0.005, is less than c F_z = 0.01: it stays, at rest."""
    h = 0.3
    y0 = [0, 0, 0, 0, 0, math.atan(h) + 0.005, 0, 0.01, 0, 0]
    r = simulate_to_rest(rd.Disk(h), rd.Coulomb(0.5, rolling_resistance=0.01), (0, 50),
                         y0, chunk=1.0)
    assert r.status == "at-rest" and "rim edge" in r.message
    assert r.t_end < 5.0 and not np.any(r.final_state[6:12])


@pytest.mark.slow
@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(h=st.floats(0.05, 0.8), mu=st.floats(0.1, 1.0), vx=st.floats(-1, 1),
       vy=st.floats(-0.3, 0.3), w2=st.floats(-1, 1), w3=st.floats(-3, 3),
       c=st.sampled_from([0.0, 0.01, 0.05]))
def test_no_line_contact_step_leaves_the_cone(h, mu, vx, vy, w2, w3, c):
    """Every stored point of every sub-phase: lambda_s >= 0 and |F_s| <= mu lambda_s
    (stick: mu_s, slide: mu_k = mu_s here) to 1e-9, the tolerance to which the events
    are located (a pivoting corner's force meets the cone as the spin stops); the energy
    balance closes."""
    g = rd.Coulomb(mu, rolling_resistance=c)
    s = np.array([0, 0, 1.0, 0, 0, 0, vx, vy, 0, 0, w2, w3])
    segs, out = lc.run_line_contact(h, g, 0.0, 3.0, s)
    assert out.status in ("rest", "rocking", "end", "failed")
    for seg in segs:
        assert np.all(seg.normal >= -1e-9)  # a corner's lift-off is located to 1e-9
        # the instant a pivot stops is stored by the sub-phase the set-valued law chooses
        assert np.all(seg.friction <= mu * seg.normal + 1e-9)
    E0 = lc.line_energy(h, lc.line_from_free(s))
    E1 = lc.line_energy(h, lc.line_from_free(out.state))
    assert abs(E1 + out.dissipated - E0) <= 1e-9

"""The rounded disk in motion (ivp/rounded.py), through the engine's contract, held to
independent truths: energy conservation over a long rocking across theta = 0, the sharp
disk's own simulation as rho -> 0, the closed-form steady motions and varpi^2 of
theory/rounded.py, Newton's law for C (the contact force against the measured
acceleration), and compiled = uncompiled."""

import math

import numpy as np
import pytest

import rollingdisk as rd
from rollingdisk.ivp.rounded import (
    ROUNDED_ROUGH,
    rounded_frequency,
    rounded_parameters,
    simulate_rounded,
    simulate_rounded_steady,
)
from rollingdisk.theory.rounded import rounded_steady_motion, rounded_thresholds
from rollingdisk.util.errors import ParameterError, ParameterTypeError


def _crossing_run(t_end, compiled=False, rtol=1e-11, atol=1e-12):
    """rho = h = 0.2, rolling upright at twice the straight-rolling threshold speed, kicked
    sideways: the tilt oscillates across theta = 0 over the half-circle tread."""
    disk = rd.Disk(0.2, rim_radius=0.2)
    w2 = 2.0 * math.sqrt(rounded_thresholds(disk).rough_straight_line_omega20_sq)
    y0 = [0.0, 0.0, 0.0, 0.0, 0.0, 0.2, w2, 0.0]
    return simulate_rounded(disk, "rough", (0.0, t_end), y0, rtol=rtol, atol=atol,
                            compiled=compiled)


def test_a_fully_rounded_disk_rocks_across_zero_and_conserves_energy():
    """The issue's done-when: no impact at theta = 0 when rho = h, energy conserved to
    1e-9 over 1000 time units on rough ground (measured: 7e-11 at the default
    tolerances), the contact held (F_z > 0) throughout."""
    tr = _crossing_run(1000.0)
    assert tr.status == "completed", tr.message
    assert tr.t[-1] == 1000.0 and tr.t_event is None
    crossings = np.count_nonzero(np.diff(np.sign(tr.theta)))
    assert crossings > 400  # about 450: it rocks across theta = 0, and on
    assert np.max(np.abs(tr.E - tr.E[0])) <= 1e-9 * abs(tr.E[0])
    assert tr.F_z.min() > 0.5
    assert np.max(np.abs(tr.theta)) < 0.2


def test_a_partly_rounded_disk_ends_at_the_tread():
    """rho < h: theta = 0 puts the flat tread on the plane (the contact jumps from arc to
    arc): the run ends there with status edge-contact, theta = 0 to round-off, and the
    lift-off function (of the starting side) did not fire at the jump."""
    disk = rd.Disk(0.2, rim_radius=0.1)
    tr = simulate_rounded(disk, "rough", (0.0, 50.0), [0, 0, 0, 0.05, 0, -0.3, 1.5, 0.0])
    assert tr.status == "edge-contact", tr.message
    assert "tread-contact" in tr.message and tr.t_event == tr.t[-1]
    assert abs(tr.theta[-1]) <= 1e-12
    assert tr.F_z[-1] > 0


def test_release_at_rest_falls_flat_or_lifts_off():
    """At rest beyond its static tilt the rounded disk tips over: fell-flat (a
    half-rounded disk lifts off first, as its F_z of eq. 11 says)."""
    tr = simulate_rounded(rd.Disk(0.2, rim_radius=0.2), "rough", (0.0, 20.0),
                          [0, 0, 0, 0.3, 0, 0, 0, 0])
    assert tr.status == "fell-flat" and abs(abs(tr.theta[-1]) - 0.5 * math.pi) < 1e-10
    assert np.max(np.abs(tr.E - tr.E[0])) < 1e-9


@pytest.mark.parametrize("ground, y0", [
    ("rough", [0.1, -0.2, 0.3, 0.6, 0.0, 0.2, 1.3, 0.8]),
    ("smooth", [0.1, -0.2, 0.05, -0.03, 0.3, 0.6, 0.0, 0.2, 1.3, 0.8]),
])
@pytest.mark.parametrize("rho", [0.0, 1e-12])
def test_rho_to_zero_is_the_sharp_disk(ground, y0, rho):
    """At rho = 0 (and 1e-12) the rounded model follows the sharp disk's own simulate
    (eqs. 1, 2, 37, 38 / 49, a separate code) to 1e-9; its contact point, forces and
    energy are the sharp disk's; both end the same way at the same time."""
    h = 0.15
    tr = simulate_rounded(rd.Disk(h, rim_radius=rho), ground, (0.0, 8.0), y0, rtol=1e-12,
                          atol=1e-13, compiled=False)
    ref = rd.simulate(rd.Disk(h), ground, (0.0, 8.0), y0, method="dop853", rtol=1e-12,
                      atol=1e-13, t_eval=tr.t[tr.t < tr.t[-1]])
    assert tr.status == ref.status
    if ref.t_event is not None:
        assert abs(tr.t_event - ref.t_event) <= 1e-9
    n = ref.t.size - (ref.t_event is not None)
    np.testing.assert_allclose(tr.y[:, :n], ref.y[:, :n], rtol=0, atol=1e-9)
    for name in ("X_P", "Y_P", "F_x", "F_y", "F_z", "E"):
        np.testing.assert_allclose(getattr(tr, name)[:n], getattr(ref, name)[:n], rtol=0,
                                   atol=1e-8, err_msg=name)


def test_the_contact_force_is_newtons_law_for_C():
    """m a_C = F + m g: the horizontal force of RoundedTrajectory (its own derivation,
    with A' = -rho sin, H' = rho cos) against the acceleration of C measured by central
    differences of the velocity the state gives (X_C, Y_C rates of the model), turned
    into the inertial frame, on a finely stored run."""
    disk = rd.Disk(0.25, rim_radius=0.15)
    motion = rounded_steady_motion(disk, "rough", 0.5, Omega0=2.0)
    tr = simulate_rounded_steady(motion, 6.0, kick=0.3, rtol=1e-13, atol=1e-14,
                                 max_step=2e-3, compiled=False)
    assert tr.status == "completed", tr.message
    p = rounded_parameters(disk, 0.5)
    V = np.empty((2, tr.t.size))
    out = np.empty(8)
    for j in range(tr.t.size):
        ROUNDED_ROUGH.rhs(tr.t[j], np.ascontiguousarray(tr.y[:, j]), p, out)
        V[:, j] = out[:2]
    h0, h1 = np.diff(tr.t)[:-1], np.diff(tr.t)[1:]  # second-order on uneven steps
    a = ((V[:, 2:] - V[:, 1:-1]) * h0 / h1 + (V[:, 1:-1] - V[:, :-2]) * h1 / h0) / (h0 + h1)
    mid = slice(1, -1)
    cp, sp = np.cos(tr.psi[mid]), np.sin(tr.psi[mid])
    F_X = tr.F_x[mid] * cp - tr.F_y[mid] * sp
    F_Y = tr.F_x[mid] * sp + tr.F_y[mid] * cp
    assert np.max(np.hypot(F_X, F_Y)) > 0.1  # a force worth checking (about 0.17)
    ok = np.minimum(h0, h1) > 1e-4  # not across the short last step (round-off / h)
    assert ok.sum() >= ok.size - 2
    np.testing.assert_allclose(a[0][ok], F_X[ok], rtol=0, atol=1e-5)
    np.testing.assert_allclose(a[1][ok], F_Y[ok], rtol=0, atol=1e-5)


@pytest.mark.parametrize("ground, theta0, Omega0", [("rough", 0.4, 2.0),
                                                     ("smooth", 0.5, 2.5)])
def test_a_steady_motion_stays_steady_and_a_kicked_one_oscillates_at_varpi(ground, theta0,
                                                                           Omega0):
    """theory/rounded.py's steady motion (closed form) stays steady in simulation, theta
    constant to 1e-9 over 100 time units; kicked by 1e-4 it oscillates at
    sqrt(varpi^2) of the closed form, to 1e-4."""
    disk = rd.Disk(0.2, rim_radius=0.1)
    motion = rounded_steady_motion(disk, ground, theta0, Omega0=Omega0)
    assert motion.stable
    tr = simulate_rounded_steady(motion, 100.0, rtol=1e-12, atol=1e-13, compiled=False)
    assert tr.status == "completed" and tr.theta_ref == theta0
    assert np.max(np.abs(tr.theta - theta0)) <= 1e-9
    varpi = math.sqrt(motion.varpi2)
    tr = simulate_rounded_steady(motion, 100.0, kick=1e-4, rtol=1e-12, atol=1e-13,
                                 max_step=0.05 * 2 * math.pi / varpi, compiled=False)
    measured = rounded_frequency(tr)
    assert abs(measured / varpi - 1.0) <= 1e-4, (measured, varpi)


def test_simulate_takes_a_rounded_disk():
    """rollingdisk.simulate hands a disk with rim_radius > 0 to the rounded model and
    refuses, by name, the options the engine's DOP853 does not take."""
    disk = rd.Disk(0.2, rim_radius=0.2)
    y0 = [0, 0, 0, 0.05, 0, 0.0, 1.5, 0.3]
    tr = rd.simulate(disk, "rough", (0.0, 5.0), y0)
    ref = simulate_rounded(disk, "rough", (0.0, 5.0), y0, compiled=False)
    assert isinstance(tr, rd.ivp.RoundedTrajectory)
    np.testing.assert_array_equal(tr.y, ref.y)
    for bad in ({"method": "taylor"}, {"t_eval": [0.0, 1.0]}, {"sink": print},
                {"error_control": "reduced"}):
        with pytest.raises(ParameterError, match=next(iter(bad))):
            rd.simulate(disk, "rough", (0.0, 5.0), y0, **bad)


def test_bad_input_is_named():
    disk = rd.Disk(0.2, rim_radius=0.1)
    with pytest.raises(ParameterError, match="tread"):
        simulate_rounded(disk, "rough", (0, 1), [0, 0, 0, 0.0, 0, 0, 1, 0])
    with pytest.raises(ParameterError, match="pi/2"):
        simulate_rounded(disk, "rough", (0, 1), [0, 0, 0, 2.0, 0, 0, 1, 0])
    with pytest.raises(ParameterError, match="y0"):
        simulate_rounded(disk, "rough", (0, 1), [0, 0, 0, 0.3])
    with pytest.raises(ParameterTypeError, match="disk"):
        simulate_rounded("coin", "rough", (0, 1), [0, 0, 0, 0.3, 0, 0, 1, 0])
    with pytest.raises(ParameterError, match="ground"):
        simulate_rounded(disk, "ice", (0, 1), [0, 0, 0, 0.3, 0, 0, 1, 0])
    with pytest.raises(ParameterTypeError, match="RoundedSteadyMotion"):
        simulate_rounded_steady("circle", 1.0)


@pytest.mark.slow
def test_compiled_and_uncompiled_take_the_same_steps():
    """The contract's promise on a real model: the same steps, counts and events, the
    states equal to round-off, compiled (numba, the one loop) or not."""
    disk = rd.Disk(0.2, rim_radius=0.1)
    y0 = [0, 0, 0, 0.05, 0, -0.3, 1.5, 0.0]
    a = simulate_rounded(disk, "rough", (0.0, 50.0), y0, compiled=False)
    b = simulate_rounded(disk, "rough", (0.0, 50.0), y0, compiled=True)
    assert (a.n_steps, a.n_rhs, a.status) == (b.n_steps, b.n_rhs, b.status)
    assert a.status == "edge-contact"
    np.testing.assert_allclose(b.t, a.t, rtol=1e-14, atol=1e-15)
    np.testing.assert_allclose(b.y, a.y, rtol=1e-13, atol=1e-14)
    c = _crossing_run(60.0, compiled=False)
    d = _crossing_run(60.0, compiled=True)
    assert (c.n_steps, c.n_rhs) == (d.n_steps, d.n_rhs)
    np.testing.assert_allclose(d.y, c.y, rtol=1e-13, atol=1e-14)
    y0 = [0.1, -0.2, 0.05, -0.03, 0.3, 0.6, 0.0, 0.2, 1.3, 0.8]
    e = simulate_rounded(disk, "smooth", (0.0, 20.0), y0, compiled=False)
    f = simulate_rounded(disk, "smooth", (0.0, 20.0), y0, compiled=True)
    assert (e.n_steps, e.n_rhs, e.status) == (f.n_steps, f.n_rhs, f.status)
    np.testing.assert_allclose(f.y, e.y, rtol=1e-13, atol=1e-14)
    from rollingdisk.engine import steploop_numba

    assert len(steploop_numba.loop().signatures) == 1  # the one loop of every model


@pytest.mark.parametrize("theta", [-0.1, -0.0, 0.0, 0.1])
@pytest.mark.parametrize("side", [-1.0, 1.0])
def test_the_lift_off_guard_keeps_the_starting_side(theta, side):
    """The lift-off function is F_z with hp = (h - rho) side on both sides of theta = 0
    (the jump of hp at the tread is no lift-off): the rim_contact it evaluates has that
    hp; and it is symmetric under theta -> -theta (omega1, omega3 and the side mirrored)."""
    from rollingdisk.ivp.rounded import _side_h
    from rollingdisk.model.rim import rim_contact

    h, rho = 0.2, 0.1
    assert rim_contact(_side_h(h, rho, side, theta), rho, theta)[0] == (h - rho) * side
    disk = rd.Disk(h, rim_radius=rho)
    p = rounded_parameters(disk, side)
    g = np.empty(3)
    y = np.array([0, 0, 0, 0.3 * side, 0, 0.2, 1.1, 0.7])
    ROUNDED_ROUGH.events(0.0, y, p, g)
    f_start = g[1]
    y_other = y * np.array([1, 1, 1, -1, 1, -1, 1, -1])  # theta, omega1, omega3 mirrored
    p_other = rounded_parameters(disk, -side)
    ROUNDED_ROUGH.events(0.0, y_other, p_other, g)
    assert g[1] == pytest.approx(f_start, rel=1e-14)  # the mirror symmetry theta -> -theta


def test_a_sphere_rolls_as_a_sphere():
    """h = rho = 1 is a homogeneous sphere: no moment about C, so its angular velocity is
    constant in the inertial frame, C moves in a straight line at constant speed on rough
    ground (the friction force vanishes), and rough and smooth ground give the same
    rotation (theta, omega1..3 at the end agree)."""
    sphere = rd.Disk(1.0, rim_radius=1.0)
    w = [0.2, 2.0, 0.3]
    rough = simulate_rounded(sphere, "rough", (0.0, 30.0), [0, 0, 0, 0.1, 0, *w], rtol=1e-12,
                             atol=1e-13, compiled=False)
    smooth = simulate_rounded(sphere, "smooth", (0.0, 30.0), [0, 0, 0, 0, 0, 0.1, 0, *w],
                              rtol=1e-12, atol=1e-13, compiled=False)
    assert rough.status == smooth.status == "completed"
    assert np.ptp(rough.theta) > 0.3  # the axis wobbles: a real test of the rotation
    for X in (rough.X_C, rough.Y_C):
        line = np.polyfit(rough.t, X, 1)
        assert np.max(np.abs(np.polyval(line, rough.t) - X)) <= 1e-9
    assert np.max(np.abs(np.hypot(rough.F_x, rough.F_y))) <= 1e-9
    np.testing.assert_allclose(rough.y[3:, -1], smooth.y[5:, -1], rtol=0, atol=1e-9)

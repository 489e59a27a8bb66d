"""Steady motions and stability of the rounded disk (rollingdisk.theory.rounded).

Independent checks: at rho = 0 the library's closed forms of sections 3-4 (eqs. 31, 32,
40, 42, 43, 51, 53, 57); for rho > 0 the closed-form varpi^2 against a complex-step
linearization of the rounded equations at 1000 random steady motions, and against the
frequency of a simulated oscillation; steady motions are equilibria of the equations; a
sphere's steady motions are spins about the vertical, whose axis cones at the spin rate.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from rollingdisk import Disk
from rollingdisk.model.rim import rim_inertia, rounded_reduced_rhs
from rollingdisk.theory.oscillations import thresholds, varpi2_closed_form
from rollingdisk.theory.rounded import (
    rounded_Omega0_sq,
    rounded_r_C_star,
    rounded_static_tilt,
    rounded_steady_motion,
    rounded_thresholds,
    rounded_varpi2,
    rounded_varpi2_linearized,
)
from rollingdisk.theory.steady import Omega0_sq, r_C_star
from rollingdisk.util.errors import ParameterError


def _motions(rng, n, rho_zero=False):
    for i in range(n):
        h = rng.uniform(0.0, 2.0)
        rho = 0.0 if rho_zero else rng.uniform(0.0, min(h, 1.0))
        th = rng.uniform(0.02, 1.5)
        ground = "rough" if i % 2 else "smooth"
        yield Disk(h, rim_radius=rho), ground, th, rng.normal(scale=3.0) or 1.0


def test_rho_zero_reproduces_the_closed_forms():
    rng = np.random.default_rng(1)
    for disk, ground, th, Om in _motions(rng, 400, rho_zero=True):
        m = rounded_steady_motion(disk, ground, th, Omega0=Om)
        ref = varpi2_closed_form(disk.h, ground, th, m.omega20, m.omega30)
        assert m.varpi2 == pytest.approx(ref, rel=1e-12, abs=1e-12)
        r_C = rng.normal()
        assert rounded_Omega0_sq(disk, th, r_C) == pytest.approx(
            float(Omega0_sq(disk.h, th, r_C)), rel=1e-12, abs=1e-12)
        assert rounded_r_C_star(disk, th) == pytest.approx(float(r_C_star(disk.h, th)),
                                                           rel=1e-12, abs=1e-14)
    for h in (0.0, 0.08, 0.17, 0.866, 5.0):
        want, got = thresholds(h).as_dict(), rounded_thresholds(Disk(h)).as_dict()
        for ground in ("rough", "smooth"):
            for key, v in want[ground].items():
                assert got[ground][key] == pytest.approx(v, rel=1e-13)
        assert rounded_static_tilt(Disk(h)) == math.atan(h)


def test_steady_motions_are_equilibria():
    rng = np.random.default_rng(2)
    for disk, ground, th, Om in _motions(rng, 300):
        m = rounded_steady_motion(disk, ground, th, Omega0=Om)
        k1, k2 = rim_inertia(disk.h, disk.rim_radius)
        f = rounded_reduced_rhs(ground == "rough", disk.h, disk.rim_radius, k1, k2,
                                m.initial_state())
        assert np.max(np.abs(f)) <= 1e-12 * (1.0 + Om * Om)
        if ground == "rough":  # the r_C route gives the same motion back
            again = rounded_steady_motion(disk, ground, th, r_C=m.r_C)
            assert abs(again.Omega0) == pytest.approx(abs(Om), rel=1e-9)


def test_closed_form_varpi2_agrees_with_the_linearization():
    """1000 random steady motions with rho > 0, both grounds: <= 1e-10 (relative to
    max(1, |varpi^2|))."""
    rng = np.random.default_rng(3)
    worst = 0.0
    for disk, ground, th, Om in _motions(rng, 1000):
        m = rounded_steady_motion(disk, ground, th, Omega0=Om)
        lin = rounded_varpi2_linearized(disk, ground, th, m.omega20, m.omega30)
        worst = max(worst, abs(lin - m.varpi2) / max(1.0, abs(m.varpi2)))
    assert worst <= 1e-10


def _simulated_varpi(disk, m, eps=1e-6):
    """The angular frequency of theta in a run from the steady state with theta0 + eps,
    from the mean spacing of the upward crossings of theta's mean (rtol 1e-12).  The kick
    moves the motion onto a neighbouring steady motion whose varpi differs by O(eps): with
    eps = 1e-6 the measured frequencies agree to about 5e-7."""
    k1, k2 = rim_inertia(disk.h, disk.rim_radius)
    rough = m.ground == "rough"
    x0 = m.initial_state()
    x0[0] += eps
    T = 2.0 * math.pi / math.sqrt(m.varpi2)
    sol = solve_ivp(lambda t, x: rounded_reduced_rhs(rough, disk.h, disk.rim_radius, k1, k2, x),
                    (0.0, 20.5 * T), x0, method="DOP853", rtol=1e-12, atol=1e-14,
                    dense_output=True)
    t = np.linspace(0.0, sol.t[-1], 200001)
    th = sol.sol(t)[0]
    mid = 0.5 * (th.max() + th.min())
    up = np.nonzero((th[:-1] < mid) & (th[1:] >= mid))[0]
    # crossing times by linear interpolation refined on the dense output
    times = []
    for i in up:
        a, b = t[i], t[i + 1]
        for _ in range(60):
            c = 0.5 * (a + b)
            if sol.sol(c)[0] < mid:
                a = c
            else:
                b = c
        times.append(0.5 * (a + b))
    period = (times[-1] - times[0]) / (len(times) - 1)
    return 2.0 * math.pi / period


@pytest.mark.parametrize("h, rho, ground, theta0, Omega0", [
    (0.1, 0.05, "rough", 0.4, 3.0),
    (0.3, 0.3, "rough", 0.8, -2.0),
    (0.5, 0.2, "smooth", 0.6, 4.0),
    (1.0, 0.6, "rough", 1.1, 5.0),
])
def test_simulated_frequency(h, rho, ground, theta0, Omega0):
    disk = Disk(h, rim_radius=rho)
    m = rounded_steady_motion(disk, ground, theta0, Omega0=Omega0)
    assert m.stable
    assert _simulated_varpi(disk, m) == pytest.approx(math.sqrt(m.varpi2), rel=1e-4)


def test_sphere_steady_motions_are_neutral_spins():
    """h = rho = 1: the steady motions are spins about the vertical (omega = 0 relative to
    the frame, C at rest), at any tilt of the body axis.  A small perturbation tilts the
    (constant) angular velocity off the vertical, and the body axis then turns about it
    at the rate |omega| = |Omega0|: varpi^2 = Omega0^2, the rigid rotation's closed form."""
    sphere = Disk(1.0, rim_radius=1.0)
    assert rounded_static_tilt(sphere) == 0.0
    for ground in ("rough", "smooth"):
        for th in (0.0, 0.3, 1.2):
            m = rounded_steady_motion(sphere, ground, th, Omega0=2.5)
            assert abs(m.omega0) < 1e-14 and abs(m.r_C) < 1e-14
            assert m.varpi2 == pytest.approx(2.5**2, rel=1e-13)


def test_rounded_theory_refuses_bad_input():
    disk = Disk(0.2, rim_radius=0.1)
    with pytest.raises(ParameterError, match="theta0"):
        rounded_varpi2(disk, "rough", 0.0, 1.0, 1.0)
    with pytest.raises(ParameterError, match="theta0"):
        rounded_varpi2(disk, "rough", 2.0, 1.0, 1.0)
    with pytest.raises(ParameterError, match="Omega0 and r_C"):
        rounded_steady_motion(disk, "rough", 0.3)
    with pytest.raises(ParameterError, match="no steady circle"):
        rounded_steady_motion(disk, "rough", 0.05,
                              r_C=rounded_r_C_star(disk, 0.05) + 1.0)
    with pytest.raises(ParameterError, match="ground"):
        rounded_varpi2(disk, "icy", 0.3, 1.0, 1.0)


@pytest.mark.slow
def test_fully_rounded_disk_rocks_over_its_rim_and_conserves_energy():
    """rho = h: the tread is a half circle, so the contact moves smoothly through theta = 0.
    A disk rolling straight on rough ground, kicked sideways, rocks across theta = 0 with
    no impact (F_z > 0), its energy kept to <= 1e-9 over 1000 time units (about 7 s)."""
    from rollingdisk.model.rim import rounded_energy, rounded_normal_force

    h = rho = 0.2
    k1, k2 = rim_inertia(h, rho)
    sol = solve_ivp(lambda t, x: rounded_reduced_rhs(True, h, rho, k1, k2, x), (0.0, 1000.0),
                    [0.0, 0.2, 3.0, 0.0], method="DOP853", rtol=1e-13, atol=1e-13)
    assert sol.success
    E = rounded_energy(True, h, rho, k1, k2, *sol.y)
    assert np.max(np.abs(E - E[0])) <= 1e-9 * abs(E[0])
    assert np.min(rounded_normal_force(True, h, rho, k1, k2, *sol.y)) > 0.5
    assert np.count_nonzero(np.diff(np.sign(sol.y[0]))) > 1000  # crossings of theta = 0

"""The library's equations of motion against an independent Kane's-method derivation.

``kane_model`` derives the dynamics with ``sympy.physics.mechanics.KanesMethod`` without the
contact force (non-contributing), from an inertia integrated over the cylinder and a contact
point found as the lowest rim point.  Here it is compared with ``rollingdisk.model.equations``:
eqs. (4), (10), (13), (37), (38), (49) and the contact force of eqs. (8), (11).
"""

import numpy as np
import pytest
import sympy as sm

import rollingdisk
from kane_model import (
    contact_offset,
    h_sym,
    inertia_by_integration,
    kane_contact_force,
    kane_dependent_speeds,
    kane_energy,
    kane_energy_rate,
    kane_model,
    kane_omega_dot,
)
from rollingdisk import Disk

N_STATES = 120
TOL = 1e-12


def close(a, b, tol=TOL):
    """``|a - b| <= tol (1 + |a|)`` element-wise: relative for large, absolute for small."""
    a = np.asarray(a, dtype=float)
    b = np.asarray(b, dtype=float)
    return bool(np.all(np.abs(a - b) <= tol * (1.0 + np.abs(a))))


def random_states(seed, n=N_STATES):
    """``(h, theta, w1, w2, w3, vx, vy, X, Y, psi, phi)``: h in [0, 3] (h = 0 included),
    both signs of theta, |theta| < 1.4, omegas and horizontal speeds in [-5, 5]."""
    rng = np.random.default_rng(seed)
    out = []
    for i in range(n):
        h = 0.0 if i % 6 == 0 else float(rng.uniform(0.0, 3.0))
        theta = float(rng.uniform(0.02, 1.4)) * (1 if i % 2 else -1)
        w = rng.uniform(-5.0, 5.0, 3)
        v = rng.uniform(-5.0, 5.0, 2)
        X, Y = rng.uniform(-10.0, 10.0, 2)
        psi, phi = rng.uniform(-np.pi, np.pi, 2)
        out.append((h, theta, *w, *v, X, Y, psi, phi))
    return out


def rough_state(s):
    h, theta, w1, w2, w3, vx, vy, X, Y, psi, phi = s
    return np.array([X, Y, psi, theta, phi, w1, w2, w3])


def smooth_state(s):
    h, theta, w1, w2, w3, vx, vy, X, Y, psi, phi = s
    # (V_X, V_Y) inertial from (v_Cx, v_Cy) in Cxyz: rotation by psi
    VX = vx * np.cos(psi) - vy * np.sin(psi)
    VY = vx * np.sin(psi) + vy * np.cos(psi)
    return np.array([X, Y, VX, VY, psi, theta, phi, w1, w2, w3])


def kw(s):
    h, theta, w1, w2, w3, vx, vy, X, Y, psi, phi = s
    return {"vx": vx, "vy": vy, "X": X, "Y": Y, "psi": psi, "phi": phi}


# -- geometry and inertia -------------------------------------------------------------
def test_inertia_by_integration_is_eq_10():
    i_diam, i_axis = inertia_by_integration()
    assert sm.simplify(i_diam - (sm.Rational(1, 4) + h_sym**2 / 3)) == 0
    assert sm.simplify(i_axis - sm.Rational(1, 2)) == 0
    for h in (0.0, 0.17, 2.5):
        d = Disk(h)
        assert float(i_diam.subs(h_sym, h)) == pytest.approx(d.k1_sq, abs=1e-15)
        assert float(i_axis.subs(h_sym, h)) == pytest.approx(d.k2_sq, abs=1e-15)


@pytest.mark.parametrize("sign", [1, -1])
def test_lowest_rim_point_is_eq_4(sign):
    c_eta, c_zeta = contact_offset(sign)  # r_CP = c_eta eta + c_zeta zeta
    for h in (0.0, 0.4, 2.0):
        for theta in sign * np.linspace(0.05, 1.4, 7):
            ce = float(sm.sympify(c_eta).subs(h_sym, h))
            cz = float(sm.sympify(c_zeta).subs(h_sym, h))
            # eta = cos y + sin z, zeta = -sin y + cos z
            y_P = ce * np.cos(theta) - cz * np.sin(theta)
            z_P = ce * np.sin(theta) + cz * np.cos(theta)
            assert close((y_P, z_P), Disk(h).contact_point_xyz(theta), 1e-15)


@pytest.mark.parametrize("ground", ["rough", "smooth"])
@pytest.mark.parametrize("sign", [1, -1])
def test_contact_point_stays_on_plane(sign, ground):
    """v_P . Z = 0 identically: the coordinates satisfy the contact constraint, eq. (6)_3."""
    assert kane_model(sign, ground).vertical_slip == 0


def test_no_slip_gives_eq_37():
    for s in random_states(1):
        h, theta, w1, w2, w3 = s[:5]
        v = kane_dependent_speeds(h, theta, w1, w2, w3)
        lib = rollingdisk.velocity_of_C(Disk(h), "rough", rough_state(s))
        assert close(v, lib[:2])


# -- dynamics ---------------------------------------------------------------------------
@pytest.mark.parametrize("ground", ["rough", "smooth"])
def test_omega_dot_matches_kane(ground):
    """eq. (38) (rough) and eq. (49) (smooth) against Kane's equations."""
    worst = 0.0
    for s in random_states(2 if ground == "rough" else 3):
        h, theta, w1, w2, w3 = s[:5]
        kane = kane_omega_dot(ground, h, theta, w1, w2, w3, **kw(s))
        lib = rollingdisk.omega_dot(Disk(h), ground, theta, w1, w2, w3)
        err = np.abs(np.subtract(kane, lib)) / (1.0 + np.abs(kane))
        worst = max(worst, float(err.max()))
        assert close(kane, lib), (s, kane, lib)
    assert worst <= TOL


@pytest.mark.parametrize("ground", ["rough", "smooth"])
def test_contact_force_matches_kane(ground):
    """Contact force of eqs. (8), (11) against m a_C - m g with Kane's accelerations."""
    for s in random_states(4 if ground == "rough" else 5):
        h, theta, w1, w2, w3 = s[:5]
        kane = kane_contact_force(ground, h, theta, w1, w2, w3, **kw(s))
        y = rough_state(s) if ground == "rough" else smooth_state(s)
        lib = rollingdisk.contact_force(Disk(h), ground, y)
        assert close(kane, lib), (s, kane, lib)


@pytest.mark.parametrize("ground", ["rough", "smooth"])
def test_energy_matches_eq_13(ground):
    for s in random_states(6 if ground == "rough" else 7, n=40):
        h, theta, w1, w2, w3 = s[:5]
        kane = kane_energy(ground, h, theta, w1, w2, w3, **kw(s))
        y = rough_state(s) if ground == "rough" else smooth_state(s)
        assert close(kane, rollingdisk.energy(Disk(h), ground, y))


@pytest.mark.parametrize("ground", ["rough", "smooth"])
def test_kane_energy_is_conserved(ground):
    """dE/dt = 0 along Kane's equations (no work by the contact force, eq. 12)."""
    for s in random_states(8 if ground == "rough" else 9):
        h, theta, w1, w2, w3 = s[:5]
        rate, scale = kane_energy_rate(ground, h, theta, w1, w2, w3, **kw(s))
        assert abs(rate) <= TOL * (1.0 + scale), (s, rate, scale)


@pytest.mark.parametrize("ground", ["rough", "smooth"])
def test_library_energy_is_conserved_along_library_equations(ground):
    """The library's own E (eq. 13) is constant along its right-hand side: the chain rule
    with a central difference of E along f(t, y)."""
    for s in random_states(10 if ground == "rough" else 11, n=40):
        h = s[0]
        d = Disk(h)
        y = rough_state(s) if ground == "rough" else smooth_state(s)
        f = rollingdisk.equations_of_motion(d, ground)(0.0, y)
        eps = 1e-6
        rate = (rollingdisk.energy(d, ground, y + eps * f)
                - rollingdisk.energy(d, ground, y - eps * f)) / (2 * eps)
        assert abs(rate) <= 1e-7 * (1.0 + np.abs(f).max() ** 2), (s, rate)


# -- trajectories -----------------------------------------------------------------------
def _trajectory_difference(ground, h, x0, t_end):
    """Max difference between Kane's and the library's trajectories (library layout)."""
    from scipy.integrate import solve_ivp

    from kane_model import kane_rhs

    t = np.linspace(0.0, t_end, 201)
    opts = {"method": "DOP853", "t_eval": t, "rtol": 1e-12, "atol": 1e-12}
    kane = solve_ivp(kane_rhs(ground, h), (0.0, t_end), x0, **opts)
    assert kane.success
    K = kane.y
    assert np.all(np.abs(K[3]) > 0.05) and np.all(np.abs(K[3]) < 1.4)
    assert np.all(np.sign(K[3]) == np.sign(x0[3])), "no passage through theta = 0 (impact)"
    if ground == "rough":
        y0 = np.array(x0)
        kane_lib_layout = K
    else:
        X, Y, psi, theta, phi, w1, w2, w3, vx, vy = x0
        y0 = smooth_state((h, theta, w1, w2, w3, vx, vy, X, Y, psi, phi))
        VX = K[8] * np.cos(K[2]) - K[9] * np.sin(K[2])
        VY = K[8] * np.sin(K[2]) + K[9] * np.cos(K[2])
        kane_lib_layout = np.vstack([K[0], K[1], VX, VY, K[2:8]])
    lib = solve_ivp(rollingdisk.equations_of_motion(Disk(h), ground), (0.0, t_end), y0, **opts)
    assert lib.success
    return float(np.abs(kane_lib_layout - lib.y).max())


THICK_CASES = [
    ("rough", 0.5, [0.2, -0.1, 0.3, 0.6, 0.0, 0.3, 3.0, 0.8]),
    ("rough", 1.2, [0.0, 0.0, 0.0, -0.9, 0.0, -0.2, 2.5, -1.0]),
    ("smooth", 0.3, [0.1, 0.2, 0.0, 0.5, 0.0, 0.2, 3.0, 1.0, 0.4, -0.3]),
    ("smooth", 0.8, [0.0, 0.0, 1.0, -0.7, 0.0, 0.1, -2.0, 0.5, -1.0, 0.2]),
]


@pytest.mark.parametrize(("ground", "h", "x0"), THICK_CASES)
def test_trajectory_matches_kane(ground, h, x0):
    """Integrated with both right-hand sides (solve_ivp DOP853, tol 1e-12) for 5 time units."""
    assert _trajectory_difference(ground, h, x0, 5.0) <= 1e-8


@pytest.mark.slow
@pytest.mark.parametrize(("ground", "h", "x0"), THICK_CASES)
def test_trajectory_matches_kane_long(ground, h, x0):
    assert _trajectory_difference(ground, h, x0, 20.0) <= 1e-8

"""Invariants of the equations of motion: mirror symmetry and time reversal (hypothesis).

Mirror symmetry (reflection in the plane through C normal to the horizontal axis x): a motion
with (theta, omega1, omega2, omega3) is the mirror image of one with
(-theta, -omega1, omega2, -omega3); the disk's other rim edge touches the plane, which is why the
paper can restrict itself to theta0 >= 0 (section 3.2).  Time reversal: the equations are
quadratic in the angular velocities, so reversing all of them reverses the motion.
"""

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

import rollingdisk as rd

h_s = st.floats(0.0, 5.0)
theta_s = st.floats(0.01, 1.5)
w_s = st.floats(-10.0, 10.0)
grounds = st.sampled_from(["rough", "smooth"])


@settings(max_examples=200, deadline=None)
@given(grounds, h_s, theta_s, w_s, w_s, w_s)
def test_mirror_symmetry(ground, h, theta, w1, w2, w3):
    disk = rd.Disk(h)
    d = np.array(rd.omega_dot(disk, ground, theta, w1, w2, w3), float)
    m = np.array(rd.omega_dot(disk, ground, -theta, -w1, w2, -w3), float)
    scale = 1.0 + np.abs(d).max()
    assert np.allclose(m, [-d[0], d[1], -d[2]], rtol=0, atol=1e-12 * scale)


@settings(max_examples=200, deadline=None)
@given(grounds, h_s, theta_s, w_s, w_s, w_s)
def test_time_reversal(ground, h, theta, w1, w2, w3):
    disk = rd.Disk(h)
    d = np.array(rd.omega_dot(disk, ground, theta, w1, w2, w3), float)
    r = np.array(rd.omega_dot(disk, ground, theta, -w1, -w2, -w3), float)
    assert np.allclose(r, d, rtol=0, atol=1e-12 * (1.0 + np.abs(d).max()))


@settings(max_examples=100, deadline=None)
@given(h_s, theta_s, w_s, w_s, w_s)
def test_mirror_symmetry_of_contact_force_and_energy(h, theta, w1, w2, w3):
    """F_z and E are mirror invariant; F_y (toward the side of the lean) flips sign."""
    disk = rd.Disk(h)
    y = np.array([0.0, 0.0, 0.3, theta, 0.0, w1, w2, w3])
    ym = np.array([0.0, 0.0, 0.3, -theta, 0.0, -w1, w2, -w3])
    F = np.array(rd.contact_force(disk, "rough", y))
    Fm = np.array(rd.contact_force(disk, "rough", ym))
    tol = 1e-12 * (1.0 + np.abs(F).max())
    assert np.allclose(Fm, [F[0], -F[1], F[2]], rtol=0, atol=tol)
    E, Em = rd.energy(disk, "rough", y), rd.energy(disk, "rough", ym)
    assert abs(E - Em) <= 1e-12 * (1 + abs(E))

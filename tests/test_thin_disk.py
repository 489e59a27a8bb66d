"""rollingdisk at h = 0 against the classical thin rolling disc of sympy's documentation.

The thin disc of ``thin_disk_kane`` (sympy's Kane example, plus the contact-point position)
is a third, independent model: its ω-dots and whole trajectories must agree with the
library's rough-ground equations (eqs. 1, 2, 37, 38 with h = 0) after the coordinate mapping
documented in ``thin_disk_kane``.
"""

import numpy as np
import pytest
from scipy.integrate import solve_ivp

import rollingdisk
from rollingdisk import Disk
from thin_disk_kane import integrate_thin_disk, rough_to_thin, thin_disk, thin_rhs, thin_to_rough

TOL = 1e-12


def random_rough_states(seed, n=100):
    rng = np.random.default_rng(seed)
    y = np.empty((n, 8))
    y[:, 0:2] = rng.uniform(-10.0, 10.0, (n, 2))
    y[:, 2] = rng.uniform(-np.pi, np.pi, n)
    y[:, 3] = rng.uniform(-1.4, 1.4, n)
    y[0, 3] = 0.0  # upright: allowed for the thin disk
    y[:, 4] = rng.uniform(-np.pi, np.pi, n)
    y[:, 5:8] = rng.uniform(-5.0, 5.0, (n, 3))
    return y


def test_mapping_round_trip_and_centre():
    """The mapping puts the centre where the sympy model's vectors put it (x, y, and the
    height cos(theta) = -z_P, eq. 7), and inverts exactly."""
    _, centre = thin_disk()
    for y in random_rough_states(1):
        x = rough_to_thin(y)
        assert np.allclose(thin_to_rough(x), y, rtol=0, atol=1e-12)
        cx, cy, cz = centre(*x[:5])
        assert abs(cx - y[0]) <= 1e-12 * (1 + abs(y[0]))
        assert abs(cy - y[1]) <= 1e-12 * (1 + abs(y[1]))
        assert abs(cz + Disk(0.0).contact_point_xyz(y[3])[1]) <= 1e-14


def test_state_derivatives_agree():
    """All eight rates (positions, angles, ω-dots) agree after the mapping, at 100 states."""
    f = rollingdisk.equations_of_motion(Disk(0.0), "rough")
    for y in random_rough_states(2):
        x = rough_to_thin(y)
        dx = thin_rhs(0.0, x)
        dy = f(0.0, y)
        # omega-dots and angle rates map one to one
        assert np.all(np.abs(dx[5:] - dy[5:]) <= TOL * (1 + np.abs(dx[5:]))), (y, dx, dy)
        assert np.all(np.abs(dx[:3] - dy[2:5]) <= TOL * (1 + np.abs(dx[:3])))
        # the contact point's velocity from the library's state derivative, eq. (5)
        eps = 1e-7
        xp = rough_to_thin(y + eps * dy)
        xm = rough_to_thin(y - eps * dy)
        assert np.allclose((xp[3:5] - xm[3:5]) / (2 * eps), dx[3:5], rtol=1e-7, atol=1e-7)


def _compare_trajectories(y0, t_end=20.0):
    t = np.linspace(0.0, t_end, 401)
    thin = integrate_thin_disk(y0, t)
    lib = solve_ivp(rollingdisk.equations_of_motion(Disk(0.0), "rough"), (0.0, t_end), y0,
                    method="DOP853", t_eval=t, rtol=1e-12, atol=1e-12)
    assert lib.success
    assert np.all(np.abs(lib.y[3]) < 1.45), "initial condition must keep the disk off the floor"
    return np.abs(thin - lib.y.T).max()


@pytest.mark.parametrize("y0", [
    [0.3, -0.2, 0.4, 0.3, 0.1, 0.2, 3.0, 0.5],  # rolling on a wobbling circle
    [0.0, 0.0, 0.0, 0.05, 0.0, 0.6, 4.0, -0.3],  # passes through the upright theta = 0
])
def test_trajectories_agree(y0):
    assert _compare_trajectories(np.array(y0)) <= 1e-8


@pytest.mark.slow
def test_trajectories_agree_random():
    rng = np.random.default_rng(3)
    done = 0
    while done < 10:
        y0 = np.concatenate([rng.uniform(-1, 1, 3), [rng.uniform(-0.8, 0.8)],
                             [0.0], rng.uniform(-1, 1, 1), [rng.uniform(2.5, 5.0)],
                             rng.uniform(-1.5, 1.5, 1)])
        # skip initial conditions after which the disk falls flat within 20 time units
        lib = solve_ivp(rollingdisk.equations_of_motion(Disk(0.0), "rough"), (0.0, 20.0), y0,
                        method="DOP853", rtol=1e-10, atol=1e-10)
        if not lib.success or np.abs(lib.y[3]).max() > 1.3:
            continue
        assert _compare_trajectories(y0) <= 1e-8, y0
        done += 1

"""Steady motions and their varpi^2 found numerically, independently of the steady/stability
modules: the steady omega20 solves d omega1/dt = 0 (affine in omega2 when omega1 = 0), and
varpi^2 comes from a central-difference Jacobian J of the reduced system
(theta, omega1, omega2, omega3): its eigenvalues are 0, 0, +-i varpi, so
varpi^2 = -trace(J^2) / 2."""

from __future__ import annotations

import numpy as np

from rollingdisk import Disk
from rollingdisk.model.equations import omega_dot


def steady_omega20(h, ground, theta0, omega30):
    """omega20 making (theta0, 0, omega20, omega30) a steady state (d omega1/dt = 0)."""
    disk = Disk(h=h)
    a = omega_dot(disk, ground, theta0, 0.0, 0.0, omega30)[0]
    b = omega_dot(disk, ground, theta0, 0.0, 1.0, omega30)[0]
    return -a / (b - a)


def steady_state(h, ground, theta0, omega30, omega20=None):
    """Full initial state of the steady motion (C at rest on smooth ground)."""
    w2 = steady_omega20(h, ground, theta0, omega30) if omega20 is None else omega20
    if ground == "rough":
        return np.array([0.0, 0.0, 0.0, theta0, 0.0, 0.0, w2, omega30])
    return np.array([0.0, 0.0, 0.0, 0.0, 0.0, theta0, 0.0, 0.0, w2, omega30])


def reduced_rhs(disk, ground, x):
    th, w1, w2, w3 = x
    d1, d2, d3 = omega_dot(disk, ground, th, w1, w2, w3)
    return np.array([w1, d1, d2, d3], dtype=float)


def varpi2_numeric(h, ground, theta0, omega20, omega30, step=1e-5):
    disk = Disk(h=h)
    x0 = np.array([theta0, 0.0, omega20, omega30])
    J = np.empty((4, 4))
    for j in range(4):
        e = np.zeros(4)
        e[j] = step * max(1.0, abs(x0[j]))
        # 4th-order central difference
        J[:, j] = (-reduced_rhs(disk, ground, x0 + 2 * e) + 8 * reduced_rhs(disk, ground, x0 + e)
                   - 8 * reduced_rhs(disk, ground, x0 - e)
                   + reduced_rhs(disk, ground, x0 - 2 * e)) / (12 * e[j])
    return -np.trace(J @ J) / 2

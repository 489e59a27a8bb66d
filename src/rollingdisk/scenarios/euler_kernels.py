"""The equations of Euler's disk on the reduced state ``x = [v_Cx, v_Cy, theta, omega1,
omega2, omega3, D_slip, D_roll, D_air]``: the creep law, the right-hand side with rolling
resistance and air, the energy (eq. 13), the observables, and the state a run starts from.
"""

from __future__ import annotations

import math

import numpy as np

from rollingdisk.model import coulomb as _cl
from rollingdisk.model.disk import Disk
from rollingdisk.model.geometry import contact_geometry
from rollingdisk.scenarios.euler_toy import EulerDisk
from rollingdisk.util.checks import check_real, real_array

__all__ = ["creep_factor"]


def creep_factor(slip, u_s):
    """``f(|u|/u_s)/|u|`` of the creep law (Vermeulen & Johnson's cubic), so that
    ``F_t = -mu F_z f u/|u|`` is ``-mu F_z (creep_factor) u``.  Element-wise.

    ``f(s) = 1 - (1 - s)^3`` for ``s < 1`` and 1 beyond: ``f(s)/s = (3 - 3 s + s^2)`` /
    ``u_s`` below saturation (finite at ``u = 0``, slope ``3/u_s = k/mu``), ``1/|u|`` above.
    """
    slip = real_array("slip", slip)
    u_s = check_real("u_s", u_s, low=0.0, low_open=True)
    s = slip / u_s
    return np.where(s < 1.0, (3.0 - 3.0 * s + s * s) / u_s,
                    1.0 / np.where(s < 1.0, 1.0, slip))[()]


def _rhs(h, mu, u_s, c_roll, c_air, eps, x, c_bl=0.0):
    """Right-hand side on the reduced state ``x = [v_Cx, v_Cy, theta, omega1, omega2,
    omega3, D_slip, D_roll, D_air]``; returns ``(dx, F_z, |u|)``.  ``c_air``: the squeeze
    film's coefficient, ``c_bl``: the boundary layer's (at most one of them non-zero).

    ``v_Cx, v_Cy``: velocity of C in Cxyz; ``D_*``: energy dissipated by each term.
    Element-wise: ``x`` may be a (9,) vector (the integrator) or a (9, N) array (the
    recorded steps, in one call)."""
    v_Cx, v_Cy, theta, w1, w2, w3 = x[0], x[1], x[2], x[3], x[4], x[5]
    ht, s, c, p, y_P, z_P = contact_geometry(h, theta)
    u_x = v_Cx - w2 + ht * w3  # eq. (6)
    u_y = v_Cy - w1 * z_P
    n = np.sqrt(u_x * u_x + u_y * u_y)
    if np.ndim(n) == 0:  # the integrator's scalar path: creep_factor without np.where
        sn = n / u_s
        f = (3.0 - 3.0 * sn + sn * sn) / u_s if sn < 1.0 else 1.0 / n
    else:
        f = creep_factor(n, u_s)
    # air film, rollingdisk.AirDrag: M = -c omega3 e_zeta / cos^3(theta), e_zeta =
    # (0, -sin theta, cos theta); rolling resistance, rollingdisk.RollingResistance
    # smoothed: M1_h = -c omega_h / sqrt(|omega_h|^2 + eps^2)
    # boundary layer, BoundaryLayerAirDrag: M = -c |Omega|^(1/2) Omega e_zeta / cos(theta)
    if c_bl:
        Om = w3 / c  # eq. (2)
        ka = -c_bl * np.sqrt(np.abs(Om)) * Om / c
    else:
        ka = -c_air * w3 / (c * c * c)
    wx = w1
    wy = w2 * c - w3 * s
    nh2 = wx * wx + wy * wy
    kr = -c_roll / np.sqrt(nh2 + eps * eps)
    # the sliding kernel with friction -mu F_z e, e = f u (not a unit vector: linear in mu e)
    d1, d2, d3, F_x, F_y, F_z = _cl.sliding_solve(h, mu, f * u_x, f * u_y, theta, w1, w2, w3,
                                                   0.0 * ka, -ka * s, ka * c,
                                                   kr * wx, kr * wy, 0.0)
    Om = w3 / c  # eq. (2)
    P_slip = F_x * u_x + F_y * u_y
    P_roll = kr * F_z * nh2
    P_air = ka * w3  # omega . M = -c omega3^2 / cos^3(theta) (film), -c |Omega|^(5/2) (layer)
    dx = np.array([F_x + v_Cy * Om,  # eq. (8)_1 in the turning frame Cxyz
                   F_y - v_Cx * Om,  # eq. (8)_2
                   w1, d1, d2, d3,  # eq. (2), (9)
                   -P_slip, -P_roll, -P_air])
    return dx, F_z, n


def _energy(h, x):
    """Energy (eq. 13) of a reduced state (``|v_C|`` does not depend on the frame).
    Element-wise over the columns of ``x``."""
    z = 0.0 * x[0]
    y = (z, z, x[0], x[1], z, x[2], z, x[3], x[4], x[5])
    return _cl.coulomb_energy_kernel(h, y)


def _observables(h, x):
    """``alpha, Omega, contact-point speed`` of reduced states (element-wise)."""
    v_Cx, v_Cy, theta, w1, w2, w3 = x[:6]
    ht, s, c, p, y_P, z_P = contact_geometry(h, theta)
    Om = w3 / c
    # contact point (eq. 5) X_P = X_C - y_P sin psi, Y_P = Y_C + y_P cos psi, d y_P/d theta
    # = -z_P: velocity (v_Cx - y_P Omega, v_Cy - z_P omega1) in Cxyz
    vp = np.hypot(v_Cx - y_P * Om, v_Cy - z_P * w1)
    return np.pi / 2 - np.abs(theta), np.abs(Om), vp


def _initial_state(toy: EulerDisk) -> np.ndarray:
    """The spin-in-place steady motion (rough ground, ``r_C = 0``) at ``alpha0``."""
    from rollingdisk.theory.steady import steady_motion

    m = steady_motion(Disk(toy.h), "rough", math.pi / 2 - toy.alpha0, r_C=0.0)
    return np.array([m.v_Cx0, m.v_Cy0, m.theta0, 0.0, m.omega20, m.omega30, 0.0, 0.0, 0.0])


def _kicked_state(toy: EulerDisk, kick: float) -> np.ndarray:
    """:func:`_initial_state` with ``omega1`` raised by ``kick`` and ``v_Cy = omega1 z_P``,
    so that the disk still rolls (eq. 6)."""
    x0 = _initial_state(toy)
    x0[3] += kick
    x0[1] = kick * contact_geometry(toy.h, x0[2])[5]
    return x0

"""Coulomb ground: the rolling and sliding equations of motion with contact moments.

Derived in :mod:`rollingdisk.symbolic.coulomb` and checked against it by
``tests/test_coulomb_eqs.py``.
"""

from __future__ import annotations

import numpy as np

from rollingdisk.model.disk import Disk
from rollingdisk.model.equations import _check_disk
from rollingdisk.model.geometry import _geometry, _inertia
from rollingdisk.model.ground import Coulomb, _coulomb_moments, _coulomb_powers
from rollingdisk.model.state import SMOOTH_STATE, _as_state
from rollingdisk.util.errors import ParameterError, ParameterTypeError

__all__ = ["COULOMB_STATE", "MODE_NAMES", "coulomb_rhs", "coulomb_contact", "coulomb_energy",
           "rolling_state"]



# =======================================================================================
# Coulomb ground: rolling and sliding modes with friction and contact moments
# =======================================================================================
# Derived in rollingdisk.symbolic.coulomb and checked against it by tests/test_coulomb_eqs.py.
# State: the smooth one, y = [X_C, Y_C, V_X, V_Y, psi, theta, phi, omega1, omega2, omega3],
# V_X, V_Y the inertial horizontal velocity of C (no longer constant).  Contact moments are
# affine in the normal force, M = M0 + F_z M1 (components in Cxyz), see rollingdisk.model.ground.
#: Names of the Coulomb-ground state components (the smooth layout).
COULOMB_STATE = SMOOTH_STATE


#: Integer codes of the modes of a Coulomb run (``Trajectory.mode``): the contact rolls or
#: slides (bit 0); bit 1 (:data:`PIVOT_STUCK`) is set while the pivot sticks, the vertical
#: spin ``omega_z`` held at 0 by the pivoting-friction moment (issue 22); bit 2
#: (:data:`ROLL_STUCK`) while the rolling resistance sticks, the horizontal angular velocity
#: ``omega_h`` held at 0 by the rolling-resistance moment.
ROLLING, SLIDING = 0, 1
PIVOT_STUCK = 2
ROLLING_PIVOT_STUCK, SLIDING_PIVOT_STUCK = ROLLING | PIVOT_STUCK, SLIDING | PIVOT_STUCK
ROLL_STUCK = 4


#: Mode code -> name (codes 0, 1 as before; 2, 3 the pivot-stuck sub-modes; 4-7 the same
#: four with the rolling resistance stuck).
MODE_NAMES = ("rolling", "sliding", "rolling, pivot stuck", "sliding, pivot stuck",
              "rolling, roll stuck", "sliding, roll stuck", "rolling, pivot stuck, roll stuck",
              "sliding, pivot stuck, roll stuck")


def _rolling_solve(h, theta, w1, w2, w3, M0x, M0y, M0z, M1x, M1y, M1z):
    """Rolling (no slip) with a contact moment ``M = M0 + F_z M1``: eqs. (8), (9), (11) with
    the constraint (37).  Returns ``(dw1, dw2, dw3, F_x, F_y, F_z)`` (forces in Cxyz)."""
    ht, s, c, p, y_P, z_P = _geometry(h, theta)
    k1 = _inertia(h)[0]  # eq. (10)
    k2 = 0.5
    Om = w3 / c  # eq. (2)
    v_Cx = w2 - ht * w3  # eq. (37)
    v_Cy = w1 * z_P
    G1 = (k2 * w2 - k1 * w3 * p) * w3
    G3 = (-k2 * w2 + k1 * w3 * p) * w1
    # (9)_1 with F_y from (8)_2 and F_z from (11): the omega1^2 terms cancel
    d1 = ((G1 - z_P * v_Cx * Om + y_P + M0x + M1x * (1.0 + z_P * w1 * w1))
          / (k1 + z_P * z_P + y_P * y_P + y_P * M1x))
    F_z = 1.0 + z_P * w1 * w1 - y_P * d1  # eq. (11)
    My = M0y + F_z * M1y
    Mz = M0z + F_z * M1z
    Meta = c * My + s * Mz
    Mzeta = -s * My + c * Mz
    # (9)_2, (9)_3 with F_x = d v_Cx/dt - v_Cy Omega, d v_Cx/dt = dw2 - h~ dw3
    a11 = k2 + 1.0
    a22 = k1 + ht * ht
    b1 = v_Cy * Om + Meta
    b2 = G3 - ht * v_Cy * Om + Mzeta
    det = a11 * a22 - ht * ht
    d2 = (b1 * a22 + ht * b2) / det
    d3 = (a11 * b2 + ht * b1) / det
    F_x = d2 - ht * d3 - v_Cy * Om  # eq. (8)_1
    F_y = z_P * d1 + y_P * w1 * w1 + v_Cx * Om  # eq. (8)_2
    return d1, d2, d3, F_x, F_y, F_z


def _sliding_solve(h, mu, e_x, e_y, theta, w1, w2, w3, M0x, M0y, M0z, M1x, M1y, M1z):
    """Sliding with friction ``F_t = -mu F_z e`` (``e`` a unit vector in Cxyz) and a contact
    moment ``M = M0 + F_z M1``: (9) with ``F_z`` from (11), solved jointly with
    ``d omega1/dt``.  Returns ``(dw1, dw2, dw3, F_x, F_y, F_z)`` (forces in Cxyz)."""
    ht, s, c, p, y_P, z_P = _geometry(h, theta)
    k1 = _inertia(h)[0]  # eq. (10)
    k2 = 0.5
    G1 = (k2 * w2 - k1 * w3 * p) * w3
    G3 = (-k2 * w2 + k1 * w3 * p) * w1
    q = mu * z_P * e_y + y_P + M1x  # (9)_1 = G1 + q F_z + M0x
    d1 = (G1 + M0x + q * (1.0 + z_P * w1 * w1)) / (k1 + y_P * q)
    F_z = 1.0 + z_P * w1 * w1 - y_P * d1  # eq. (11)
    F_x = -mu * F_z * e_x
    F_y = -mu * F_z * e_y
    My = M0y + F_z * M1y
    Mz = M0z + F_z * M1z
    d2 = (-F_x + c * My + s * Mz) / k2  # eq. (9)_2
    d3 = (G3 + ht * F_x - s * My + c * Mz) / k1  # eq. (9)_3
    return d1, d2, d3, F_x, F_y, F_z


def _slip_velocity(h, y):
    """Slip velocity of the contact point ``(u_x, u_y)`` in Cxyz (eq. 6), Coulomb state."""
    V_X, V_Y, psi, theta, w1, w2, w3 = y[2], y[3], y[4], y[5], y[7], y[8], y[9]
    ht, s, c, p, y_P, z_P = _geometry(h, theta)
    cp = np.cos(psi)
    sp = np.sin(psi)
    v_Cx = V_X * cp + V_Y * sp
    v_Cy = -V_X * sp + V_Y * cp
    return v_Cx - w2 + ht * w3, v_Cy - w1 * z_P  # eq. (6)


def _coulomb_rolling(h, c_roll, c_pivot, c_air, y):
    """Rolling mode at a Coulomb state: ``(dy[0:10], F_x, F_y, F_z, P_roll, P_pivot,
    P_air)``; ``X_C, Y_C`` move with the no-slip velocity (37), ``V_X, V_Y`` with the force."""
    psi, theta, w1, w2, w3 = y[4], y[5], y[7], y[8], y[9]
    ht, s, c, p, y_P, z_P = _geometry(h, theta)
    M0x, M0y, M0z, M1x, M1y, M1z = _coulomb_moments(c_roll, c_pivot, c_air, theta, w1, w2, w3)
    d1, d2, d3, F_x, F_y, F_z = _rolling_solve(h, theta, w1, w2, w3,
                                               M0x, M0y, M0z, M1x, M1y, M1z)
    cp = np.cos(psi)
    sp = np.sin(psi)
    v_Cx = w2 - ht * w3  # eq. (37)
    v_Cy = w1 * z_P
    P1, P2, P3 = _coulomb_powers(c_roll, c_pivot, c_air, theta, w1, w2, w3, F_z)
    dy = (v_Cx * cp - v_Cy * sp, v_Cx * sp + v_Cy * cp,  # eq. (1)
          F_x * cp - F_y * sp, F_x * sp + F_y * cp,  # eq. (8), inertial components
          w3 / c, w1, w2 - w3 * p, d1, d2, d3)  # eq. (2)
    return dy, F_x, F_y, F_z, P1, P2, P3


def _coulomb_sliding(h, mu_k, c_roll, c_pivot, c_air, y, ref_X, ref_Y, u_eps=0.0):
    """Sliding mode at a Coulomb state: ``(dy[0:10], F_x, F_y, F_z, P_slip, P_roll,
    P_pivot, P_air)``.

    The friction direction is ``e = sigma u/|u|`` with ``sigma = sgn(u . ref)`` for the
    inertial reference direction ``ref`` (the slip direction when the step began): equal
    to ``u/|u|`` while the slip keeps its direction, and the smooth continuation of the
    sliding solution through ``u = 0``, where the hybrid driver stops it (an event).  Where
    ``|u| <= u_eps`` (the slip just started from rest, its direction not yet resolved
    above rounding), ``e = ref``."""
    psi, theta, w1, w2, w3 = y[4], y[5], y[7], y[8], y[9]
    ht, s, c, p, y_P, z_P = _geometry(h, theta)
    cp = np.cos(psi)
    sp = np.sin(psi)
    u_x, u_y, e_x, e_y = _friction_direction(h, y, ref_X, ref_Y, u_eps)
    M0x, M0y, M0z, M1x, M1y, M1z = _coulomb_moments(c_roll, c_pivot, c_air, theta, w1, w2, w3)
    d1, d2, d3, F_x, F_y, F_z = _sliding_solve(h, mu_k, e_x, e_y, theta, w1, w2, w3,
                                               M0x, M0y, M0z, M1x, M1y, M1z)
    P1, P2, P3 = _coulomb_powers(c_roll, c_pivot, c_air, theta, w1, w2, w3, F_z)
    dy = (y[2], y[3],  # eq. (1)
          F_x * cp - F_y * sp, F_x * sp + F_y * cp,  # eq. (8), inertial components
          w3 / c, w1, w2 - w3 * p, d1, d2, d3)  # eq. (2)
    return dy, F_x, F_y, F_z, F_x * u_x + F_y * u_y, P1, P2, P3


def _friction_direction(h, y, ref_X, ref_Y, u_eps):
    """``(u_x, u_y, e_x, e_y)``: the slip velocity and the friction direction ``e`` (Cxyz)
    of :func:`_coulomb_sliding`: ``sgn(u . ref) u/|u|`` where ``|u| >= u_eps``; below,
    the direction of ``sgn(u . ref) u + (u_eps - |u|) ref``, which is ``ref`` at ``u = 0``
    and turns continuously into ``u/|u|`` at ``|u| = u_eps`` (a jump of ``e`` there made
    the solution depend on how an integrator steps across it: 3e-7 between DOP853 and
    LSODA at ``u_eps`` = 1e-6; ``sgn(u . ref) u . ref >= 0`` keeps the sum from 0)."""
    psi = y[4]
    cp = np.cos(psi)
    sp = np.sin(psi)
    u_x, u_y = _slip_velocity(h, y)
    n = np.sqrt(u_x * u_x + u_y * u_y)
    r_x = ref_X * cp + ref_Y * sp  # ref in Cxyz
    r_y = -ref_X * sp + ref_Y * cp
    if n > 0.0:
        sig = 1.0
        if u_x * r_x + u_y * r_y < 0.0:
            sig = -1.0
        if n >= u_eps:
            return u_x, u_y, sig * u_x / n, sig * u_y / n
        w_x = sig * u_x + (u_eps - n) * r_x
        w_y = sig * u_y + (u_eps - n) * r_y
        m = np.sqrt(w_x * w_x + w_y * w_y)
        return u_x, u_y, w_x / m, w_y / m
    return u_x, u_y, r_x, r_y


def _coulomb_energy(h, y):
    """Energy (eq. 13) at a Coulomb state: ``V_X, V_Y`` from the state, ``v_Cz`` from (7)."""
    V_X, V_Y, theta, w1, w2, w3 = y[2], y[3], y[5], y[7], y[8], y[9]
    ht, s, c, p, y_P, z_P = _geometry(h, theta)
    k1 = _inertia(h)[0]  # eq. (10)
    v_Cz = -w1 * y_P
    return (0.5 * (V_X * V_X + V_Y * V_Y + v_Cz * v_Cz) + 0.5 * k1 * (w1 * w1 + w3 * w3)
            + 0.25 * w2 * w2 - z_P)


def _rolling_velocity(h, y):
    """Inertial ``(V_X, V_Y)`` of C that rolling (no slip, eq. 37) implies at state ``y``."""
    psi, theta, w1, w2, w3 = y[4], y[5], y[7], y[8], y[9]
    ht, s, c, p, y_P, z_P = _geometry(h, theta)
    v_Cx = w2 - ht * w3
    v_Cy = w1 * z_P
    cp = np.cos(psi)
    sp = np.sin(psi)
    return v_Cx * cp - v_Cy * sp, v_Cx * sp + v_Cy * cp


# ----------------------------------------------------- set-valued pivoting friction (issue 22)
# The pivot moment -c F_z sgn(omega_z) is set-valued at omega_z = 0: there it is whatever
# keeps omega_z = 0, as long as |M_piv| <= c F_z ("pivot stuck", rollingdisk.symbolic.coulomb.
# derive_pivot_stuck).  The kernels take a pivot state ``sz``: +1 or -1, the moment
# -c F_z sz (the smooth continuation of -c F_z sgn(omega_z) through omega_z = 0, on which the
# hybrid driver locates the zero), or 0, stuck.
def _omega_z(theta, w2, w3):
    """Vertical component of the angular velocity (Cxyz), ``omega2 sin + omega3 cos``."""
    return w2 * np.sin(theta) + w3 * np.cos(theta)


def _stuck_correction(theta, w1, w2, w3, d2, d3, r2, r3):
    """The pivot moment ``M_piv`` that makes ``d omega_z/dt = 0`` when a unit vertical
    moment changes ``(domega2, domega3)`` by ``(r2, r3)``: ``d omega_z/dt = domega2 sin +
    domega3 cos + omega1 (omega2 cos - omega3 sin)`` is affine in ``M_piv``."""
    s = np.sin(theta)
    c = np.cos(theta)
    dwz = d2 * s + d3 * c + w1 * (w2 * c - w3 * s)
    return -dwz / (r2 * s + r3 * c)


def _rolling_stuck_solve(h, theta, w1, w2, w3, M0x, M0y, M0z, M1x, M1y, M1z):
    """Rolling with the pivot stuck: :func:`_rolling_solve` with the extra vertical moment
    ``M_piv`` that holds ``d omega_z/dt = 0``.  ``d omega1/dt``, ``F_y`` and ``F_z`` do not
    depend on ``M_z``; ``(domega2, domega3)`` respond to it by ``(s a22 + h~ c, a11 c +
    h~ s)/det`` (the 2x2 system of (9)_2,3, whose right sides get ``(s, c) M_z``).
    Returns ``(dw1, dw2, dw3, F_x, F_y, F_z, M_piv)``."""
    d1, d2, d3, F_x, F_y, F_z = _rolling_solve(h, theta, w1, w2, w3,
                                               M0x, M0y, M0z, M1x, M1y, M1z)
    ht, s, c, p, y_P, z_P = _geometry(h, theta)
    k1 = _inertia(h)[0]
    a11 = 1.5  # k2 + 1
    a22 = k1 + ht * ht
    det = a11 * a22 - ht * ht
    r2 = (s * a22 + ht * c) / det
    r3 = (a11 * c + ht * s) / det
    L = _stuck_correction(theta, w1, w2, w3, d2, d3, r2, r3)
    return d1, d2 + r2 * L, d3 + r3 * L, F_x + (r2 - ht * r3) * L, F_y, F_z, L


def _sliding_stuck_solve(h, mu, e_x, e_y, theta, w1, w2, w3, M0x, M0y, M0z, M1x, M1y, M1z):
    """Sliding with the pivot stuck: :func:`_sliding_solve` with the extra vertical moment
    ``M_piv`` that holds ``d omega_z/dt = 0`` (``F`` and ``d omega1/dt`` do not depend on
    ``M_z``; ``(domega2, domega3)`` respond by ``(s/k2, c/k1)``).  Returns ``(dw1, dw2,
    dw3, F_x, F_y, F_z, M_piv)``."""
    d1, d2, d3, F_x, F_y, F_z = _sliding_solve(h, mu, e_x, e_y, theta, w1, w2, w3,
                                               M0x, M0y, M0z, M1x, M1y, M1z)
    s = np.sin(theta)
    c = np.cos(theta)
    r2 = s / 0.5
    r3 = c / _inertia(h)[0]
    L = _stuck_correction(theta, w1, w2, w3, d2, d3, r2, r3)
    return d1, d2 + r2 * L, d3 + r3 * L, F_x, F_y, F_z, L


def _pivot_moments(c_roll, c_pivot, c_air, theta, w1, w2, w3, sz):
    """``M0, M1`` of :func:`_coulomb_moments` with the pivot term ``-c sz`` (``sz = 0``:
    none, the stuck pivot's moment is an unknown)."""
    M0x, M0y, M0z, M1x, M1y, _ = _coulomb_moments(c_roll, 0.0, c_air, theta, w1, w2, w3)
    return M0x, M0y, M0z, M1x, M1y, -c_pivot * sz


# ----------------------------------------------------- set-valued rolling resistance
# The rolling-resistance moment -c F_z omega_h/|omega_h| is set-valued at omega_h = 0: there
# it is whatever keeps omega_h = 0, as long as |M_h| <= c F_z ("roll stuck",
# rollingdisk.symbolic.coulomb.derive_roll_stuck).  Outside it the kernels take an inertial
# reference direction ``rr`` (the direction of omega_h when the step began) and use the
# direction sgn(omega_h . rr) omega_h/|omega_h| (``rr`` itself where |omega_h| <= w_eps): the
# smooth continuation through omega_h = 0, on which the hybrid driver locates the zero, as
# the slip reference does for sliding.
def _roll_direction(theta, psi, w1, w2, w3, rr_X, rr_Y, w_eps):
    """``(omega_x, omega_y, e_x, e_y)``: the horizontal angular velocity and the direction
    ``e`` (Cxyz) of the rolling-resistance moment ``-c F_z e``: ``sgn(omega_h . rr)
    omega_h/|omega_h|``, or ``rr`` (inertial, turned into Cxyz) where ``|omega_h| <=
    w_eps``."""
    wx = w1
    wy = w2 * np.cos(theta) - w3 * np.sin(theta)
    cp = np.cos(psi)
    sp = np.sin(psi)
    r_x = rr_X * cp + rr_Y * sp
    r_y = -rr_X * sp + rr_Y * cp
    n = np.sqrt(wx * wx + wy * wy)
    if n > w_eps and n > 0.0:
        sig = 1.0
        if wx * r_x + wy * r_y < 0.0:
            sig = -1.0
        return wx, wy, sig * wx / n, sig * wy / n
    return wx, wy, r_x, r_y


def _mode_moments(c_roll, c_pivot, c_air, theta, e_x, e_y, w3, sz, roll_stuck):
    """``M0, M1`` (Cxyz) of a mode: air, rolling resistance ``-c F_z e`` (none while
    ``roll_stuck``: an unknown), pivot ``-c F_z sz`` (``sz = 0``: stuck, an unknown)."""
    M0x, M0y, M0z, _, _, _ = _coulomb_moments(0.0, 0.0, c_air, theta, 0.0, 0.0, w3)
    if roll_stuck:
        return M0x, M0y, M0z, 0.0, 0.0, -c_pivot * sz
    return M0x, M0y, M0z, -c_roll * e_x, -c_roll * e_y, -c_pivot * sz


def _hold_h(theta, w1, w2, w3, d2, d3, r2y, r3y, r2z, r3z, pivot_stuck):
    """The moments ``(M_hy, M_piv)`` that make ``d omega_y/dt = 0`` (and ``d omega_z/dt = 0``
    if ``pivot_stuck``; else ``M_piv = 0``), when unit moments ``M_y``, ``M_z`` change
    ``(domega2, domega3)`` by ``(r2y, r3y)``, ``(r2z, r3z)``."""
    s = np.sin(theta)
    c = np.cos(theta)
    gy = d2 * c - d3 * s - w1 * (w2 * s + w3 * c)  # d omega_y/dt
    ay = r2y * c - r3y * s
    if not pivot_stuck:
        return -gy / ay, 0.0
    gz = d2 * s + d3 * c + w1 * (w2 * c - w3 * s)  # d omega_z/dt
    az = r2z * c - r3z * s
    by = r2y * s + r3y * c
    bz = r2z * s + r3z * c
    det = ay * bz - az * by
    return (az * gz - gy * bz) / det, (gy * by - ay * gz) / det


def _rolling_response(ht, s, c, k1, My, Mz):
    """Change of ``(domega2, domega3)`` in rolling when ``(M_y, M_z)`` grow by ``(My, Mz)``
    (the 2x2 system of (9)_2,3 in :func:`_rolling_solve`)."""
    a11 = 1.5  # k2 + 1
    a22 = k1 + ht * ht
    det = a11 * a22 - ht * ht
    Meta = c * My + s * Mz
    Mzeta = -s * My + c * Mz
    return (Meta * a22 + ht * Mzeta) / det, (a11 * Mzeta + ht * Meta) / det


def _rolling_roll_stuck_solve(h, theta, w1, w2, w3, M0x, M0y, M0z, M1x, M1y, M1z,
                              pivot_stuck):
    """Rolling with the rolling resistance stuck: :func:`_rolling_solve` with the extra
    horizontal moment ``(M_hx, M_hy)`` that holds ``d omega_h/dt = 0`` (and, if
    ``pivot_stuck``, the vertical ``M_piv`` that holds ``d omega_z/dt = 0``).
    ``d omega1/dt`` depends on ``M_x`` alone (numerator of (9)_1), so ``M_hx`` cancels it;
    then ``F_z = 1 + z_P omega1^2`` (eq. 11), and ``(M_hy, M_piv)`` follow from the 2x2
    system of (9)_2,3.  Returns ``(dw1, dw2, dw3, F_x, F_y, F_z, M_hx, M_hy, M_piv)``."""
    d1, d2, d3, F_x, F_y, F_z = _rolling_solve(h, theta, w1, w2, w3,
                                               M0x, M0y, M0z, M1x, M1y, M1z)
    ht, s, c, p, y_P, z_P = _geometry(h, theta)
    k1 = _inertia(h)[0]
    D1 = k1 + z_P * z_P + y_P * y_P + y_P * M1x  # d d1 / d M_x = 1/D1
    Lx = -d1 * D1
    dFz = y_P * d1  # F_z = 1 + z_P w1^2 - y_P d1 (eq. 11), d1 -> 0
    F_z = F_z + dFz
    F_y = F_y - z_P * d1
    e2, e3 = _rolling_response(ht, s, c, k1, M1y * dFz, M1z * dFz)
    d2 += e2
    d3 += e3
    r2y, r3y = _rolling_response(ht, s, c, k1, 1.0, 0.0)
    r2z, r3z = _rolling_response(ht, s, c, k1, 0.0, 1.0)
    Ly, Lz = _hold_h(theta, w1, w2, w3, d2, d3, r2y, r3y, r2z, r3z, pivot_stuck)
    d2 += r2y * Ly + r2z * Lz
    d3 += r3y * Ly + r3z * Lz
    Om = w3 / c
    F_x = d2 - ht * d3 - w1 * z_P * Om  # eq. (8)_1
    return 0.0, d2, d3, F_x, F_y, F_z, Lx, Ly, Lz


def _sliding_roll_stuck_solve(h, mu, e_x, e_y, theta, w1, w2, w3, M0x, M0y, M0z, M1x, M1y,
                              M1z, pivot_stuck):
    """Sliding with the rolling resistance stuck: :func:`_sliding_solve` with the extra
    ``(M_hx, M_hy)`` (and ``M_piv`` if ``pivot_stuck``) that hold ``omega_h`` (and
    ``omega_z``).  ``d omega1/dt`` depends on ``M_x`` alone, ``M_hx`` cancels it; ``F_z``
    (eq. 11), ``F_t = -mu F_z e`` follow; ``(domega2, domega3)`` respond to ``M_y``,
    ``M_z`` by ``(c, -s)/(k2, k1)``, ``(s, c)/(k2, k1)``.  Returns ``(dw1, dw2, dw3, F_x,
    F_y, F_z, M_hx, M_hy, M_piv)``."""
    ht, s, c, p, y_P, z_P = _geometry(h, theta)
    k1 = _inertia(h)[0]
    k2 = 0.5
    G1 = (k2 * w2 - k1 * w3 * p) * w3
    q = mu * z_P * e_y + y_P + M1x
    Lx = -(G1 + M0x + q * (1.0 + z_P * w1 * w1))  # cancels the numerator of d1 in it
    _, d2, d3, F_x, F_y, F_z = _sliding_solve(h, mu, e_x, e_y, theta, w1, w2, w3, M0x + Lx,
                                              M0y, M0z, M1x, M1y, M1z)
    r2y, r3y = c / k2, -s / k1
    r2z, r3z = s / k2, c / k1
    Ly, Lz = _hold_h(theta, w1, w2, w3, d2, d3, r2y, r3y, r2z, r3z, pivot_stuck)
    return (0.0, d2 + r2y * Ly + r2z * Lz, d3 + r3y * Ly + r3z * Lz, F_x, F_y, F_z, Lx, Ly,
            Lz)


def _coulomb_rolling_full(h, c_roll, c_pivot, c_air, y, sz, rr_X, rr_Y, w_eps, roll_stuck):
    """Rolling mode with pivot state ``sz`` (+1, -1: moment ``-c F_z sz``; 0: stuck) and
    rolling-resistance state (``roll_stuck``, else the direction of :func:`_roll_direction`
    with reference ``rr``): ``(dy[0:10], F_x, F_y, F_z, P_roll, P_pivot, P_air, M_piv,
    M_hx, M_hy)``, the powers ``omega . M`` of each moment (0 while stuck, up to the
    integration error of ``omega_h = 0``, ``omega_z = 0``)."""
    psi, theta, w1, w2, w3 = y[4], y[5], y[7], y[8], y[9]
    ht, s, c, p, y_P, z_P = _geometry(h, theta)
    wx, wy, e_x, e_y = _roll_direction(theta, psi, w1, w2, w3, rr_X, rr_Y, w_eps)
    M = _mode_moments(c_roll, c_pivot, c_air, theta, e_x, e_y, w3, sz, roll_stuck)
    if roll_stuck:
        d1, d2, d3, F_x, F_y, F_z, Lx, Ly, L = _rolling_roll_stuck_solve(
            h, theta, w1, w2, w3, M[0], M[1], M[2], M[3], M[4], M[5], sz == 0.0)
    else:
        if sz == 0.0:
            d1, d2, d3, F_x, F_y, F_z, L = _rolling_stuck_solve(h, theta, w1, w2, w3, *M)
        else:
            d1, d2, d3, F_x, F_y, F_z = _rolling_solve(h, theta, w1, w2, w3, *M)
            L = M[5] * F_z
        Lx = M[3] * F_z
        Ly = M[4] * F_z
    cp = np.cos(psi)
    sp = np.sin(psi)
    v_Cx = w2 - ht * w3  # eq. (37)
    v_Cy = w1 * z_P
    P3 = _coulomb_powers(0.0, 0.0, c_air, theta, w1, w2, w3, F_z)[2]
    dy = (v_Cx * cp - v_Cy * sp, v_Cx * sp + v_Cy * cp,  # eq. (1)
          F_x * cp - F_y * sp, F_x * sp + F_y * cp,  # eq. (8), inertial components
          w3 / c, w1, w2 - w3 * p, d1, d2, d3)  # eq. (2)
    return dy, F_x, F_y, F_z, wx * Lx + wy * Ly, _omega_z(theta, w2, w3) * L, P3, L, Lx, Ly


def _coulomb_sliding_full(h, mu_k, c_roll, c_pivot, c_air, y, ref_X, ref_Y, u_eps, sz, rr_X,
                          rr_Y, w_eps, roll_stuck):
    """Sliding mode (friction direction as :func:`_coulomb_sliding`) with the pivot and
    rolling-resistance states of :func:`_coulomb_rolling_full`: ``(dy[0:10], F_x, F_y,
    F_z, P_slip, P_roll, P_pivot, P_air, M_piv, M_hx, M_hy)``."""
    psi, theta, w1, w2, w3 = y[4], y[5], y[7], y[8], y[9]
    ht, s, c, p, y_P, z_P = _geometry(h, theta)
    u_x, u_y, e_x, e_y = _friction_direction(h, y, ref_X, ref_Y, u_eps)
    wx, wy, r_x, r_y = _roll_direction(theta, psi, w1, w2, w3, rr_X, rr_Y, w_eps)
    M = _mode_moments(c_roll, c_pivot, c_air, theta, r_x, r_y, w3, sz, roll_stuck)
    if roll_stuck:
        d1, d2, d3, F_x, F_y, F_z, Lx, Ly, L = _sliding_roll_stuck_solve(
            h, mu_k, e_x, e_y, theta, w1, w2, w3, M[0], M[1], M[2], M[3], M[4], M[5],
            sz == 0.0)
    else:
        if sz == 0.0:
            d1, d2, d3, F_x, F_y, F_z, L = _sliding_stuck_solve(h, mu_k, e_x, e_y, theta,
                                                                w1, w2, w3, *M)
        else:
            d1, d2, d3, F_x, F_y, F_z = _sliding_solve(h, mu_k, e_x, e_y, theta, w1, w2, w3,
                                                       *M)
            L = M[5] * F_z
        Lx = M[3] * F_z
        Ly = M[4] * F_z
    cp = np.cos(psi)
    sp = np.sin(psi)
    P3 = _coulomb_powers(0.0, 0.0, c_air, theta, w1, w2, w3, F_z)[2]
    dy = (y[2], y[3],  # eq. (1)
          F_x * cp - F_y * sp, F_x * sp + F_y * cp,  # eq. (8), inertial components
          w3 / c, w1, w2 - w3 * p, d1, d2, d3)  # eq. (2)
    return (dy, F_x, F_y, F_z, F_x * u_x + F_y * u_y, wx * Lx + wy * Ly,
            _omega_z(theta, w2, w3) * L, P3, L, Lx, Ly)


# ------------------------------------------------------------------- public wrappers
def check_coulomb(ground, name: str = "ground"):
    """``ground`` if it is a :class:`Coulomb` value; a ground's name (``"rough"``) is the
    wrong value (:class:`ParameterError`), anything else the wrong type."""
    if not isinstance(ground, Coulomb):
        error = ParameterError if isinstance(ground, str) else ParameterTypeError
        raise error(f"{name} must be a rollingdisk.Coulomb(...) value here, got "
                    f"{type(ground).__name__} {ground!r}")
    return ground


_check_coulomb = check_coulomb  # the name this module's kernels use


def _check_mode(mode) -> int:
    """The code of ``mode``: a name of :data:`MODE_NAMES` or its index."""
    if not isinstance(mode, bool):
        for code, name in enumerate(MODE_NAMES):
            if isinstance(mode, str) and mode == name:
                return code
            if isinstance(mode, (int, np.integer)) and mode == code:
                return code
    raise ParameterError(f"mode must be one of {MODE_NAMES} (or its index), got {mode!r}")


def coulomb_rhs(disk: Disk, ground, mode, y, slip_reference=None) -> np.ndarray:
    """``dy/dt`` on Coulomb ground in one mode, state layout :data:`COULOMB_STATE`.

    Parameters
    ----------
    disk : Disk
    ground : Coulomb
    mode : str or int
        A name of :data:`MODE_NAMES` (or its code).  Rolling: no slip, the contact force
        follows from the constraint (eqs. 8, 9, 11, 37) with the contact moments of
        ``ground``; ``X_C, Y_C`` move with the no-slip velocity.  Sliding: ``F_t = -mu_k
        F_z u/|u|`` (``u`` from eq. 6), ``F_z`` from eq. (11).  "pivot stuck": the
        pivoting-friction moment is the one that holds the vertical spin ``omega_z``
        constant (``d omega_z/dt = 0``; it sticks at ``omega_z = 0``), derived in
        :func:`rollingdisk.symbolic.coulomb.derive_pivot_stuck`, whatever its size.  "roll
        stuck": the rolling-resistance moment is the horizontal one that holds ``omega_h``
        constant (it sticks at ``omega_h = 0``), derived in
        :func:`rollingdisk.symbolic.coulomb.derive_roll_stuck`, whatever its size.
        Outside the stuck modes the moments are ``-c F_z omega_h/|omega_h|`` (0 at
        ``omega_h = 0``) and ``-c F_z sgn(omega_z)``.
    y : array_like, shape (10,)
    slip_reference : (float, float), optional
        Sliding only: the inertial direction used when ``u = 0`` (default: ``(1, 0)``).

    Returns
    -------
    ndarray, shape (10,)
    """
    _check_disk(disk)
    g = _check_coulomb(ground)
    y = _as_state("smooth", y)
    return np.array(_mode_solve(disk.h, g, _check_mode(mode), y, slip_reference)[0])


def _mode_solve(h, g, code, y, slip_reference=None):
    """The kernel of mode ``code`` at ``y`` for the public functions: ``(dy, F_x, F_y, F_z,
    P_slip, P_roll, P_pivot, P_air, M_piv, M_hx, M_hy)``; free moments along
    ``omega_h/|omega_h|`` and ``sgn(omega_z)`` (none where these vanish)."""
    cr, cpv, ca = g.coefficients
    sz = 0.0
    if not code & PIVOT_STUCK:
        sz = float(np.sign(_omega_z(y[5], y[8], y[9])))
        if sz == 0.0:  # sgn(0) = 0: no pivot moment
            sz, cpv = 1.0, 0.0
    rs = bool(code & ROLL_STUCK)
    if code & 1 == ROLLING:
        dy, F_x, F_y, F_z, P1, P2, P3, L, Lx, Ly = _coulomb_rolling_full(
            h, cr, cpv, ca, y, sz, 0.0, 0.0, 0.0, rs)
        return dy, F_x, F_y, F_z, 0.0, P1, P2, P3, L, Lx, Ly
    u = _slip_velocity(h, y)
    rx, ry = (1.0, 0.0) if slip_reference is None else slip_reference
    if slip_reference is None and (u[0] or u[1]):
        rx, ry = _to_inertial(y[4], *u)
    return _coulomb_sliding_full(h, g.mu_k, cr, cpv, ca, y, rx, ry, 0.0, sz, 0.0, 0.0, 0.0,
                                 rs)


def _to_inertial(psi, ax, ay):
    cp, sp = np.cos(psi), np.sin(psi)
    return ax * cp - ay * sp, ax * sp + ay * cp


def coulomb_contact(disk: Disk, ground, mode, y) -> dict:
    """Contact quantities on Coulomb ground in one mode at state ``y`` (shape (10,)).

    Returns
    -------
    dict
        ``F_x, F_y, F_z`` (contact force in Cxyz, units ``m g``), ``F_t = |(F_x, F_y)|``,
        ``u_x, u_y`` (slip velocity, eq. 6), ``power_slip`` (``v_P . F_t``), and the
        powers ``power_rolling_resistance``, ``power_pivot``, ``power_air`` (``omega . M``
        of each moment; all powers ``<= 0``, eq. 14), ``M_pivot``, the pivoting-friction
        moment about the vertical (``-c F_z sgn(omega_z)``; in a "pivot stuck" mode the
        moment that holds ``omega_z``, ``|M_pivot| <= c F_z`` while the pivot sticks), and
        ``M_roll_x, M_roll_y``, the rolling-resistance moment in Cxyz (``-c F_z
        omega_h/|omega_h|``; in a "roll stuck" mode the moment that holds ``omega_h``,
        ``|M_roll| <= c F_z`` while it sticks), units ``m g a``.
    """
    _check_disk(disk)
    g = _check_coulomb(ground)
    y = _as_state("smooth", y)
    u_x, u_y = _slip_velocity(disk.h, y)
    code = _check_mode(mode)
    _, F_x, F_y, F_z, P0, P1, P2, P3, L, Lx, Ly = _mode_solve(disk.h, g, code, y)
    return {"F_x": F_x, "F_y": F_y, "F_z": F_z, "F_t": float(np.hypot(F_x, F_y)),
            "u_x": u_x, "u_y": u_y, "power_slip": P0, "power_rolling_resistance": P1,
            "power_pivot": P2, "power_air": P3, "M_pivot": L, "M_roll_x": Lx,
            "M_roll_y": Ly}


def coulomb_energy(disk: Disk, y):
    """Total mechanical energy (eq. 13) at a Coulomb state (layout :data:`COULOMB_STATE`)."""
    _check_disk(disk)
    y = _as_state("smooth", y)
    return _coulomb_energy(disk.h, y)


def rolling_state(disk: Disk, y_rough) -> np.ndarray:
    """The Coulomb (smooth-layout) state of a rough-ground state: ``V_X, V_Y`` from the
    no-slip condition (eq. 37) rotated into OXYZ (eq. 1)."""
    _check_disk(disk)
    y_rough = _as_state("rough", y_rough)
    X_C, Y_C, psi, theta, phi, w1, w2, w3 = y_rough
    y = np.array([X_C, Y_C, 0.0, 0.0, psi, theta, phi, w1, w2, w3])
    y[2], y[3] = _rolling_velocity(disk.h, y)
    return y


# The kernels the Coulomb driver, its compiled loop, the phases and the scenarios call, under
# public names (plain float arithmetic, numba-compilable; the compiled loops bind them by the
# names they are defined with, so both names stay).
to_inertial = _to_inertial
omega_z = _omega_z
slip_velocity = _slip_velocity
rolling_velocity = _rolling_velocity
sliding_solve = _sliding_solve
sliding_stuck_solve = _sliding_stuck_solve
pivot_moments = _pivot_moments
coulomb_moments = _coulomb_moments
coulomb_sliding = _coulomb_sliding
coulomb_rolling_full = _coulomb_rolling_full
coulomb_sliding_full = _coulomb_sliding_full
coulomb_energy_kernel = _coulomb_energy

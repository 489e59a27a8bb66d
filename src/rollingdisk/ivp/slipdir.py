"""The direction in which a rolling disk starts to slide on Coulomb ground (and the angle
scan that also gives the direction in which a stuck rolling resistance lets go), used by
:mod:`rollingdisk.ivp.hybrid` at its transitions."""

from __future__ import annotations

import math

import numpy as np

from rollingdisk.ivp import fastsegment as _fs
from rollingdisk.model import coulomb as _cl
from rollingdisk.model import equations as _eq
from rollingdisk.model import geometry as _geo
from rollingdisk.model import state as _st
from rollingdisk.model.disk import Disk
from rollingdisk.model.ground import Coulomb

__all__ = ["slip_direction"]


def _slip_accel(h, mu_k, coeffs, y, e_x, e_y, sz=None):
    """Slip acceleration ``du/dt`` (Cxyz) at a state with ``u = 0``, sliding with friction
    ``-mu_k F_z e`` (``e`` in Cxyz): eq. (6) differentiated along (8), (9), (11).  ``sz``:
    the pivot state (+1, -1, or 0 stuck; ``None``: ``sgn(omega_z)``)."""
    theta, w1, w2, w3 = y[5], y[7], y[8], y[9]
    ht, s, c, p, y_P, z_P = _geo.contact_geometry(h, theta)
    if sz is None:
        M = _cl.coulomb_moments(*coeffs, theta, w1, w2, w3)
        d1, d2, d3, F_x, F_y, F_z = _cl.sliding_solve(h, mu_k, e_x, e_y, theta, w1, w2, w3,
                                                       *M)
    else:
        M = _cl.pivot_moments(*coeffs, theta, w1, w2, w3, sz)
        solve = _cl.sliding_stuck_solve if sz == 0.0 else _cl.sliding_solve
        d1, d2, d3, F_x, F_y, F_z = solve(h, mu_k, e_x, e_y, theta, w1, w2, w3, *M)[:6]
    Om = w3 / c
    v_Cx = w2 - ht * w3  # u = 0
    v_Cy = w1 * z_P
    dv_Cx = F_x + v_Cy * Om  # eq. (8)_1: rate of the Cxyz component
    dv_Cy = F_y - v_Cx * Om  # eq. (8)_2
    # u_x = v_Cx - w2 + h~ w3, u_y = v_Cy - w1 z_P; d z_P/d theta = y_P; at u = 0 the
    # turning of Cxyz adds nothing to du/dt
    return dv_Cx - d2 + ht * d3, dv_Cy - d1 * z_P - w1 * w1 * y_P


def slip_direction(disk: Disk, ground: Coulomb, y) -> tuple[float, float] | None:
    """The direction in which a rolling disk at state ``y`` (``u = 0``) starts to slide.

    The unit vector ``d`` (Cxyz components) such that, sliding with friction
    ``-mu_k F_z d``, the slip acceleration ``du/dt`` is along ``+d`` (so that the slip
    grows in the direction friction assumed).  Found by scanning the angle of ``d`` and
    ``brentq`` on ``d x du/dt = 0``; among the roots with ``d . du/dt > 0`` the one of
    largest slip acceleration.  ``None`` if there is none (the disk can keep rolling).
    """
    h = _eq.check_disk(disk).h
    mu_k = _cl.check_coulomb(ground).mu_k
    return _slip_direction(h, mu_k, ground.coefficients, _st.as_state("smooth", y))


def _slip_direction(h, mu_k, coeffs, y, sz=None):
    """:func:`slip_direction` with the pivot state ``sz`` of :func:`_slip_accel`.  Once the
    compiled Coulomb loop is loaded, the same scan runs compiled
    (:func:`rollingdisk.ivp.fastsegment.slip_scan`; roots by bisection to round-off
    instead of ``brentq`` to 1e-15: the two agree to about 1e-15)."""
    if _fs.loaded():
        a = _fs.compiled()["slip_scan"](
            float(h), float(mu_k), float(coeffs[0]), float(coeffs[1]), float(coeffs[2]),
            np.ascontiguousarray(y[:10], dtype=float), 0.0 if sz is None else float(sz),
            sz is None, 145)
        return None if a != a else (math.cos(a), math.sin(a))

    def parts(a):
        ex, ey = math.cos(a), math.sin(a)
        ax, ay = _slip_accel(h, mu_k, coeffs, y, ex, ey, sz)
        return ex * ay - ey * ax, ex * ax + ey * ay

    a = _direction_scan(parts)
    return None if a is None else (math.cos(a), math.sin(a))


def _direction_scan(parts):
    """The angle ``a`` of the direction ``d = (cos a, sin a)`` in which a rate starts to
    grow along ``+d`` from 0: ``parts(a)`` gives ``(d x rate, d . rate)``; a scan of 144
    intervals, ``brentq`` on ``d x rate = 0`` in each sign change, and among the roots
    with ``d . rate > 0`` the one of largest rate.  ``None`` if there is none.  (The slip
    direction at a rolling -> sliding transition, and the direction in which the rolling
    resistance lets ``omega_h`` go.)"""
    from scipy.optimize import brentq

    grid = np.linspace(0.0, 2.0 * math.pi, 145)
    vals = [parts(a)[0] for a in grid]
    best = None
    for i in range(grid.size - 1):
        f0, f1 = vals[i], vals[i + 1]
        if f0 == 0.0:
            a = grid[i]
        elif f0 * f1 < 0.0:
            a = brentq(lambda x: parts(x)[0], grid[i], grid[i + 1], xtol=1e-15, rtol=8.9e-16)
        else:
            continue
        along = parts(a)[1]
        if along > 0.0 and (best is None or along > best[1]):
            best = (a, along)
    return None if best is None else best[0]

"""The free body: its state, free flight, energy, angular momentum, lowest point and touchdown.

Pure functions on a free body (no contact; the impact law is
:mod:`rollingdisk.phases.impact`); derived in :mod:`rollingdisk.symbolic.impact`
and explained in ``docs/impacts.md``.  Dimensionless units m = a = g = 1 (see
:mod:`rollingdisk.disk`); numpy and scipy only.

Free-body state
---------------
12 components (:data:`FREE_STATE`)::

    s = [X_C, Y_C, Z_C, psi, theta, phi, V_X, V_Y, V_Z, omega1, omega2, omega3]

``(X_C, Y_C, Z_C)`` the centre C and ``(V_X, V_Y, V_Z)`` its velocity in OXYZ; ``psi,
theta, phi`` the library's spin, inclination and rotation angles (body frame
``R = R_Z(psi) R_x(theta) R_eta(phi)``, ``docs/notation.md``); ``omega1..3`` the angular
velocity in C xi eta zeta, as in the rolling states (eq. 2).  In flight ``theta`` may leave
``(-pi/2, pi/2)``: the angles returned by :func:`free_flight` keep the sign of ``cos theta``
of the start and lie within ``pi`` of the starting ``psi`` and ``phi``.

Contact and impact quantities are written in the frame Cxyz (``x = xi`` horizontal, ``z``
up): the contact normal is ``z``, the tangent plane ``(x, y)``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from rollingdisk.model.disk import Disk
from rollingdisk.model.geometry import inertia
from rollingdisk.util.checks import check_real, real_array
from rollingdisk.util.errors import ParameterError, ParameterTypeError

__all__ = ["FREE_STATE", "CONTACT_KINDS", "IMPACT_MODES", "LowestPoint", "free_flight",
           "free_energy", "angular_momentum", "lowest_point", "touchdown_time"]

#: Names of the free-body state components, in order.
FREE_STATE = ("X_C", "Y_C", "Z_C", "psi", "theta", "phi", "V_X", "V_Y", "V_Z",
              "omega1", "omega2", "omega3")
#: What touches the plane at the lowest point: one point of a rim edge, the whole tread
#: line (``theta = 0``, ``h > 0``) or the whole face (``|theta| = pi/2``).
CONTACT_KINDS = ("rim", "tread", "face")
#: What the post-impact contact velocity suggests: rolling (contact point at rest), sliding
#: (it moves in the plane), flight (it leaves the plane).
IMPACT_MODES = ("rolling", "sliding", "flight")



# ---------------------------------------------------------------------------- helpers
def _check_disk(disk) -> Disk:
    if not isinstance(disk, Disk):
        raise ParameterTypeError(f"disk must be a rollingdisk.Disk, got "
                                    f"{type(disk).__name__} {disk!r}")
    return disk


def _as_free_state(state, name: str = "state") -> np.ndarray:
    s = real_array(name, state)
    if s.shape != (12,):
        raise ParameterError(f"{name} must have 12 components ({', '.join(FREE_STATE)}), "
                                f"got shape {s.shape}")
    if not np.all(np.isfinite(s)):
        raise ParameterError(f"{name} must be finite (no NaN or infinity)")
    return s


def _rot_z(a):
    c, s = math.cos(a), math.sin(a)
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])


def _cross(a, b):
    """``a x b`` of two 3-vectors (numpy's cross costs 30 us a call, this 2 us)."""
    return np.array([a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
                     a[0] * b[1] - a[1] * b[0]])


def _rot_x(a):
    c, s = math.cos(a), math.sin(a)
    return np.array([[1.0, 0.0, 0.0], [0.0, c, -s], [0.0, s, c]])


def _rot_y(a):
    c, s = math.cos(a), math.sin(a)
    return np.array([[c, 0.0, s], [0.0, 1.0, 0.0], [-s, 0.0, c]])


def _frame(psi, theta) -> np.ndarray:
    """Columns ``xi, eta, zeta`` of C xi eta zeta in OXYZ: ``R_Z(psi) R_x(theta)``."""
    return _rot_z(psi) @ _rot_x(theta)


def _axis_rotation(u, a) -> np.ndarray:
    """Rotation by angle ``a`` about the unit vector ``u`` (Rodrigues)."""
    ux, uy, uz = u
    K = np.array([[0.0, -uz, uy], [uz, 0.0, -ux], [-uy, ux, 0.0]])
    return np.eye(3) + math.sin(a) * K + (1.0 - math.cos(a)) * (K @ K)


def _wrap_near(a, ref):
    """``a`` plus the multiple of ``2 pi`` that brings it within ``pi`` of ``ref``."""
    return ref + math.remainder(a - ref, 2.0 * math.pi)


def _angles(R, psi_ref, theta_ref, phi_ref):
    """``(psi, theta, phi)`` of ``R = R_Z(psi) R_x(theta) R_y(phi)``, on the branch of
    ``sgn cos theta_ref`` and near ``psi_ref, phi_ref``."""
    sig = 1.0 if math.cos(theta_ref) >= 0.0 else -1.0
    st = R[2, 1]
    ct = sig * math.hypot(R[0, 1], R[1, 1])
    theta = math.atan2(st, ct)
    if math.hypot(R[0, 1], R[1, 1]) > 1e-300:
        psi = math.atan2(-sig * R[0, 1], sig * R[1, 1])
        phi = math.atan2(-sig * R[2, 0], sig * R[2, 2])
    else:  # axis vertical: only psi + phi (or psi - phi) is defined; keep psi
        psi = psi_ref
        Rp = _rot_x(theta).T @ _rot_z(psi).T @ R
        phi = math.atan2(Rp[0, 2], Rp[0, 0])
    theta = _wrap_near(theta, theta_ref) if sig < 0 else theta
    return _wrap_near(psi, psi_ref), theta, _wrap_near(phi, phi_ref)


# ------------------------------------------------------------------------ free flight
def _flight_constants(h, s):
    """Space-fixed quantities of the torque-free motion: ``L`` (angular momentum about C,
    OXYZ), the precession rate ``Omega_p = |L|/k1^2`` about ``L`` and the body spin rate
    ``nu = (k1^2 - k2^2)/k1^2 omega2`` about the axis."""
    k1, k2 = inertia(h)
    psi, theta = s[3], s[4]
    w = s[9:12]
    Q = _frame(psi, theta)
    L = Q @ np.array([k1 * w[0], k2 * w[1], k1 * w[2]])
    return L, float(np.linalg.norm(L)) / k1, (k1 - k2) / k1 * w[1], Q


def _flight_one(h, s, t):
    psi0, theta0, phi0 = s[3], s[4], s[5]
    L, Om_p, nu, Q0 = _flight_constants(h, s)
    nL = np.linalg.norm(L)
    A = _axis_rotation(L / nL, Om_p * t) if nL > 0.0 else np.eye(3)
    R = A @ _rot_z(psi0) @ _rot_x(theta0) @ _rot_y(phi0 + nu * t)
    psi, theta, phi = _angles(R, psi0, theta0, phi0)
    Q = _frame(psi, theta)
    # omega in space: Omega_p L^ + nu eta (the symmetric top), then in C xi eta zeta
    k1, _ = inertia(h)
    w_space = L / k1 + nu * R[:, 1]
    w = Q.T @ w_space
    X = s[0:3] + s[6:9] * t + np.array([0.0, 0.0, -0.5 * t * t])
    V = s[6:9] + np.array([0.0, 0.0, -t])
    return np.concatenate([X, [psi, theta, phi], V, w])


def free_flight(disk: Disk, state, t):
    """Exact free flight: ballistic centre, torque-free symmetric top.

    Parameters
    ----------
    disk : Disk
    state : array_like, shape (12,)
        Free-body state at time 0 (layout :data:`FREE_STATE`).
    t : float or array_like
        Time(s) [units of ``sqrt(a/g)``], any sign.

    Returns
    -------
    ndarray, shape (12,) or (12, k)
        The state at ``t``.

    Notes
    -----
    ``R_C(t) = R_C + V t - t^2/2 Z``; the angular momentum about C, ``L``, is fixed in space;
    the body turns about ``L`` at ``Omega_p = |L|/k1^2`` and about its own axis at
    ``nu = (k1^2 - k2^2)/k1^2 omega2``: ``R(t) = Rot(L, Omega_p t) R(0) R_eta(nu t)``, so
    ``omega2`` is constant and the transverse part of omega turns in the body at
    ``(k2^2 - k1^2)/k1^2 omega2`` (derived in :func:`rollingdisk.symbolic.impact.free_flight`).

    Examples
    --------
    >>> s = free_flight(Disk(h=0.1), [0, 0, 2, 0, 0.3, 0, 1, 0, 0, 0.5, 3, 0], 0.5)
    >>> round(float(s[2]), 6)  # Z_C = 2 - 0.5^2/2
    1.875
    """
    h = _check_disk(disk).h
    s = _as_free_state(state)
    ts = real_array("t", t)
    if not np.all(np.isfinite(ts)):
        raise ParameterError("t must be finite")
    if ts.ndim == 0:
        return _flight_one(h, s, float(ts))
    return np.stack([_flight_one(h, s, float(x)) for x in ts.ravel()], axis=1)


def free_energy(disk: Disk, state) -> float:
    """Total energy of a free body, units ``m g a``: ``|V|^2/2 + omega.J omega/2 + Z_C``."""
    return _state_energy(_check_disk(disk).h, _as_free_state(state))


def _state_energy(h, s):
    """:func:`free_energy` of the free-body state ``s`` (an array) of half-thickness ``h``,
    unchecked."""
    k1, k2 = inertia(h)
    w1, w2, w3 = s[9:12]
    return float(0.5 * s[6:9] @ s[6:9] + 0.5 * (k1 * (w1 * w1 + w3 * w3) + k2 * w2 * w2)
                 + s[2])


def angular_momentum(disk: Disk, state, about=None) -> np.ndarray:
    """Angular momentum in OXYZ about C (default) or about the fixed point ``about``."""
    h = _check_disk(disk).h
    s = _as_free_state(state)
    L = _flight_constants(h, s)[0]
    if about is None:
        return L
    o = real_array("about", about)
    if o.shape != (3,) or not np.all(np.isfinite(o)):
        raise ParameterError(f"about must be a finite point (X, Y, Z), got {about!r}")
    return L + _cross(s[0:3] - o, s[6:9])


# ------------------------------------------------------------------ lowest point
@dataclass(frozen=True)
class LowestPoint:
    """The lowest point of the disk above the plane.

    Attributes
    ----------
    height : float
        ``Z`` of the lowest point [units of ``a``]; ``< 0``: the disk is inside the plane.
    kind : {"rim", "tread", "face"}
        One point of a rim edge; the tread line (``sin theta = 0``, ``h > 0``); the face.
    side : int
        ``+1`` / ``-1``: the rim edge on the face ``-side h eta`` (``h~ = side h`` of eq. 4);
        ``0`` for the tread line.
    point : ndarray, shape (3,)
        The lowest point in OXYZ (for a tread or face: the middle of what touches).
    r : ndarray, shape (3,)
        ``point - C`` in Cxyz.
    """

    height: float
    kind: str
    side: int
    point: np.ndarray
    r: np.ndarray

    def __repr__(self) -> str:
        return f"LowestPoint(height={self.height:.6g}, kind={self.kind!r}, side={self.side})"


def _lowest_height(h, Z_C, theta):
    """``Z_C - |cos theta| - h |sin theta|``: the lowest point's height (derived in
    :func:`rollingdisk.symbolic.impact.lowest_point`)."""
    return Z_C - abs(math.cos(theta)) - h * abs(math.sin(theta))


def _r_xyz(h, theta, side, sig_c):
    """``P - C`` in Cxyz for the rim point on face ``-side h eta`` lowest on its circle:
    ``P - C = -side h eta - sgn(cos theta) zeta`` (eq. 4 for ``|theta| < pi/2``)."""
    s, c = math.sin(theta), math.cos(theta)
    return np.array([0.0, -side * h * c + sig_c * s, -side * h * s - sig_c * c])


def lowest_point(disk: Disk, state, tol: float = 1e-12) -> LowestPoint:
    """The lowest point of the disk and what touches there.

    Parameters
    ----------
    disk : Disk
    state : array_like, shape (12,)
        Free-body state (:data:`FREE_STATE`); only ``Z_C, psi, theta`` (and ``X_C, Y_C``)
        enter.
    tol : float
        ``|sin theta| <= tol`` counts as the tread line (``h > 0``), ``|cos theta| <= tol``
        as the face.

    Returns
    -------
    LowestPoint
        ``height = Z_C - |cos theta| - h |sin theta|``.

    Examples
    --------
    >>> lp = lowest_point(Disk(h=0.2), [0, 0, 1.5, 0, 0.0, 0, 0, 0, 0, 0, 0, 0])
    >>> lp.kind, round(lp.height, 12)
    ('tread', 0.5)
    """
    h = _check_disk(disk).h
    s = _as_free_state(state)
    tol = check_real("tol", tol, low=0.0, high=0.1)
    psi, theta = s[3], s[4]
    sn, cs = math.sin(theta), math.cos(theta)
    sig_c = 1.0 if cs >= 0.0 else -1.0
    if abs(cs) <= tol:
        kind, side = "face", (1 if sn >= 0.0 else -1)
        r = np.array([0.0, -side * h * cs, -side * h * sn])  # centre of the lower face
    elif abs(sn) <= tol and h > 0.0:
        kind, side = "tread", 0
        r = _r_xyz(h, theta, 0, sig_c)
    else:
        kind, side = "rim", (1 if sn >= 0.0 else -1)
        r = _r_xyz(h, theta, side, sig_c)
    point = s[0:3] + _rot_z(psi) @ r
    return LowestPoint(float(_lowest_height(h, s[2], theta)), kind, side, point, r)


def _inside_error(height) -> ParameterError:
    return ParameterError(f"state: the disk is inside the plane (lowest point at "
                             f"Z = {height:.3g} < 0); a launch state needs Z_C >= "
                             f"|cos theta| + h |sin theta|")


def touchdown_time(disk: Disk, state, *, inside_tol: float = 1e-12) -> float:
    """First time ``t >= 0`` at which the freely flying disk touches the plane.

    Parameters
    ----------
    disk : Disk
    state : array_like, shape (12,)
        Launch state (:data:`FREE_STATE`), disk above (or on) the plane.
    inside_tol : float
        A lowest point below ``-inside_tol`` is refused.

    Returns
    -------
    float
        The touchdown time [units of ``sqrt(a/g)``]; ``0.0`` if the disk touches at
        ``t = 0`` with its lowest point moving down.

    Raises
    ------
    ParameterError
        If the disk starts inside the plane (names ``state``).

    Notes
    -----
    The height ``H(t) = Z_C(t) - sqrt(1 - eta_Z^2) - h |eta_Z|`` is closed-form: the axis
    eta precesses uniformly about the fixed angular momentum.  It falls at most at speed
    ``max(0, -V_Z) + t' + Omega_p (1 + h)``, so a step of ``-B + sqrt(B^2 + 2H)`` cannot
    pass a contact (conservative advancement); a probe one step further brackets the first
    root, which the Illinois rule (:mod:`rollingdisk.engine.roots`) then refines to
    round-off (:func:`rollingdisk.ivp.fastsegment.touchdown_scan`).
    """
    h = _check_disk(disk).h
    s = _as_free_state(state)
    inside_tol = check_real("inside_tol", inside_tol, low=0.0, high=1e-3)
    L, Om_p, _nu, Q0 = _flight_constants(h, s)
    eta0 = Q0[:, 1]
    nL = float(np.linalg.norm(L))
    u = L / nL if nL > 0.0 else np.array([0.0, 0.0, 1.0])
    par = (u @ eta0) * u[2]
    per = eta0[2] - par
    crs = u[0] * eta0[1] - u[1] * eta0[0]  # (u x eta0)_Z
    Z0, VZ0 = s[2], s[8]

    def H(t):
        ez = par + per * math.cos(Om_p * t) + crs * math.sin(Om_p * t)
        ez = min(1.0, max(-1.0, ez))
        return Z0 + VZ0 * t - 0.5 * t * t - math.sqrt(1.0 - ez * ez) - h * abs(ez)

    H0 = H(0.0)
    if H0 < -inside_tol:
        raise _inside_error(H0)
    t = 0.0
    Ht = max(H0, 0.0)
    if Ht == 0.0:  # touching: touchdown now if the lowest point moves down
        dt = 1e-9 * max(1.0, abs(VZ0) + Om_p)
        if H(dt) <= 0.0:
            return 0.0
        t, Ht = dt, H(dt)
    from rollingdisk.ivp import fastsegment as _fs

    # the one advancement, compiled once the Coulomb loop is loaded (a toss rolling on its
    # tread: 9M heights, 14 s -> 0.3 s), else the same function in Python
    scan = _fs.compiled()["touchdown_scan"] if _fs.loaded() else _fs.touchdown_scan
    tc = scan(float(Z0), float(VZ0), float(par), float(per), float(crs), float(Om_p),
              float(h), float(t), float(Ht))
    if tc < 0.0:
        raise RuntimeError("touchdown_time: no bracket after 100000 steps (grazing contact)")
    return float(tc)


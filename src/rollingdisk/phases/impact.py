"""Free flight, touchdown and the impact law of a disk of finite thickness.

Pure functions on a free body (no contact); derived in :mod:`rollingdisk.symbolic.impact`
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

from rollingdisk.model.disk import Disk, check_ground
from rollingdisk.model.geometry import inertia
from rollingdisk.model.state import state_index, state_names
from rollingdisk.util.checks import check_real, check_sign, real_array
from rollingdisk.util.errors import ParameterError, ParameterTypeError

__all__ = ["FREE_STATE", "CONTACT_KINDS", "IMPACT_MODES", "LowestPoint", "ImpactResult",
           "free_flight", "free_energy", "angular_momentum", "lowest_point", "touchdown_time",
           "contact_delassus", "impact", "rim_change_ratio", "free_state_from_rolling",
           "rolling_state_from_free"]

#: Names of the free-body state components, in order.
FREE_STATE = ("X_C", "Y_C", "Z_C", "psi", "theta", "phi", "V_X", "V_Y", "V_Z",
              "omega1", "omega2", "omega3")
#: What touches the plane at the lowest point: one point of a rim edge, the whole tread
#: line (``theta = 0``, ``h > 0``) or the whole face (``|theta| = pi/2``).
CONTACT_KINDS = ("rim", "tread", "face")
#: What the post-impact contact velocity suggests: rolling (contact point at rest), sliding
#: (it moves in the plane), flight (it leaves the plane).
IMPACT_MODES = ("rolling", "sliding", "flight")

#: Largest ``h`` for which the single-edge rocking law gives a non-negative ratio.
H_ROCK_MAX = math.sqrt(15.0 / 8.0)


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
    h = _check_disk(disk).h
    s = _as_free_state(state)
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


# ------------------------------------------------------------------------- impacts
def _jacobian_parts(h, theta, r):
    """``J^-1`` (Cxyz) and the cross matrix ``[r]`` of ``r``."""
    k1, k2 = inertia(h)
    Qx = _rot_x(theta)  # columns xi, eta, zeta in Cxyz
    Jinv = Qx @ np.diag([1.0 / k1, 1.0 / k2, 1.0 / k1]) @ Qx.T
    rx, ry, rz = r
    Rx = np.array([[0.0, -rz, ry], [rz, 0.0, -rx], [-ry, rx, 0.0]])
    return Jinv, Rx


def contact_delassus(disk: Disk, theta, side: int = 1, cos_sign: int = 1) -> np.ndarray:
    """Delassus matrix ``W = (1/m) I + [r]^T J^-1 [r]`` of a rim contact point, in Cxyz.

    Parameters
    ----------
    disk : Disk
    theta : float
        Inclination [rad].
    side : {+1, -1}
        The rim edge: ``r = P - C = -side h eta - cos_sign zeta`` (``side = sgn theta``
        for the lowest point, eq. 4).
    cos_sign : {+1, -1}
        ``sgn cos theta`` (``+1`` for ``|theta| < pi/2``).

    Returns
    -------
    ndarray, shape (3, 3)
        ``W`` maps an impulse at P to the jump of P's velocity (both in Cxyz), symmetric
        positive definite (derived in :func:`rollingdisk.symbolic.impact.delassus`).

    Examples
    --------
    >>> W = contact_delassus(Disk(h=0.0), 0.0)
    >>> [round(float(x), 12) for x in np.diag(W)]  # 1 + 1/k2^2, 1 + 1/k1^2, 1
    [3.0, 5.0, 1.0]
    """
    h = _check_disk(disk).h
    theta = check_real("theta", theta)
    side = check_sign("side", side)
    cos_sign = check_sign("cos_sign", cos_sign)
    r = _r_xyz(h, theta, side, float(cos_sign))
    Jinv, Rx = _jacobian_parts(h, theta, r)
    return np.eye(3) + Rx.T @ Jinv @ Rx


def _prox_residual(W, gamma, Lam, e_n, e_t, mu):
    """Residual of ``Lam = prox_C(Lam - (W Lam + xi_0))`` scaled by ``|Lam| + |xi|``:
    the Newton-Coulomb law in proximal-point form (r = 1/max diag W)."""
    xi = W @ Lam + np.array([(1.0 + e_t) * gamma[0], (1.0 + e_t) * gamma[1],
                             (1.0 + e_n) * gamma[2]])
    rr = 1.0 / np.max(np.diag(W))
    z = Lam - rr * xi
    n = max(z[2], 0.0)
    t = z[:2]
    nt = math.hypot(*t)
    if nt > mu * n:
        t = t * (mu * n / nt) if nt > 0.0 else t
    p = np.array([t[0], t[1], n])
    scale = np.linalg.norm(Lam) + rr * np.linalg.norm(xi) + 1e-300
    return float(np.linalg.norm(Lam - p) / scale)


def _solve_law(W, gamma, e_n, e_t, mu):
    """The impulse ``Lam`` (Cxyz) of the Newton-Coulomb law at one contact.

    ``xi = gamma+ + E gamma-`` with ``E = diag(e_t, e_t, e_n)``, ``gamma+ = gamma- + W Lam``:
    ``Lam_N >= 0, xi_N >= 0, Lam_N xi_N = 0``; ``|Lam_T| <= mu Lam_N``, ``Lam_T = -mu Lam_N
    xi_T/|xi_T|`` where ``xi_T != 0``.  Returns ``(Lam, stick)``.
    """
    b = np.array([(1.0 + e_t) * gamma[0], (1.0 + e_t) * gamma[1], (1.0 + e_n) * gamma[2]])
    if gamma[2] >= 0.0:  # not approaching: no impulse
        return np.zeros(3), False
    Lam = -np.linalg.solve(W, b)  # stick: xi = 0
    if Lam[2] > 0.0 and math.hypot(Lam[0], Lam[1]) <= mu * Lam[2] * (1.0 + 1e-14):
        return Lam, True
    if mu == 0.0 or math.hypot(b[0], b[1]) == 0.0 and W[0, 2] == 0.0 and W[1, 2] == 0.0:
        return np.array([0.0, 0.0, -b[2] / W[2, 2]]), False
    WT, WTN, WNT = W[:2, :2], W[:2, 2], W[2, :2]

    def parts(beta):
        tv = np.array([math.cos(beta), math.sin(beta)])
        den = W[2, 2] - mu * (WNT @ tv)
        LN = -b[2] / den
        xiT = b[:2] + LN * (WTN - mu * (WT @ tv))
        return tv, den, LN, xiT

    def g(beta):
        tv, den, LN, xiT = parts(beta)
        return tv[0] * xiT[1] - tv[1] * xiT[0]

    n = 720
    betas = np.linspace(0.0, 2.0 * math.pi, n + 1)
    # parts() at every beta at once (the scan; the roots are refined by parts() itself)
    cb, sb = np.cos(betas % (2.0 * math.pi)), np.sin(betas % (2.0 * math.pi))  # closed: 2pi as 0
    dens = W[2, 2] - mu * (WNT[0] * cb + WNT[1] * sb)
    with np.errstate(divide="ignore", invalid="ignore"):
        LNs = -b[2] / dens
        xi0 = b[0] + LNs * (WTN[0] - mu * (WT[0, 0] * cb + WT[0, 1] * sb))
        xi1 = b[1] + LNs * (WTN[1] - mu * (WT[1, 0] * cb + WT[1, 1] * sb))
    gs = cb * xi1 - sb * xi0
    roots = []
    for i in np.flatnonzero((dens[:-1] > 0.0) & (dens[1:] > 0.0)
                            & ((gs[:-1] == 0.0) | (np.sign(gs[:-1]) * np.sign(gs[1:]) < 0.0))):
        ga, gb = g(betas[i]), g(betas[i + 1])
        if np.sign(ga) * np.sign(gb) < 0.0:  # signs: a product of tiny g underflows
            from scipy.optimize import brentq  # not at import: `import rollingdisk` is lean

            beta = brentq(g, betas[i], betas[i + 1], xtol=1e-16, rtol=8.9e-16)
        else:  # a zero at an end (or the scan's and g's rounding disagree there)
            beta = betas[i] if abs(ga) <= abs(gb) else betas[i + 1]
        tv, den, LN, xiT = parts(beta)
        if tv @ xiT > 0.0 and LN > 0.0:
            roots.append((beta, LN))
    if not roots:
        raise RuntimeError("impact law: no sliding solution found (please report)")
    beta, LN = max(roots, key=lambda x: x[1])
    tv = np.array([math.cos(beta), math.sin(beta)])
    Lam = np.array([-mu * LN * tv[0], -mu * LN * tv[1], LN])
    # Newton polish on F = [xi_N, Lam_T + mu Lam_N xi_T/|xi_T|]
    for _ in range(8):
        xi = b + W @ Lam
        xT = xi[:2]
        nx = math.hypot(*xT)
        F = np.array([Lam[0] + mu * Lam[2] * xT[0] / nx, Lam[1] + mu * Lam[2] * xT[1] / nx,
                      xi[2]])
        if np.linalg.norm(F) <= 1e-16 * (np.linalg.norm(Lam) + np.linalg.norm(b)):
            break
        P = (np.eye(2) - np.outer(xT, xT) / (nx * nx)) / nx
        Jf = np.zeros((3, 3))
        Jf[:2, :2] = np.eye(2)
        Jf[:2, :] += mu * Lam[2] * P @ W[:2, :]
        Jf[:2, 2] += mu * xT / nx
        Jf[2, :] = W[2, :]
        step = np.linalg.solve(Jf, -F)
        Lam = Lam + step
        if np.linalg.norm(step) <= 1e-17 * np.linalg.norm(Lam):
            break
    return Lam, False


@dataclass(frozen=True)
class ImpactResult:
    """Outcome of one impact.

    Attributes
    ----------
    impulse_normal : float
        ``Lam_N >= 0`` [units ``m sqrt(a g)``].
    impulse_tangential : ndarray, shape (2,)
        ``Lam_T`` in Cxyz (``x, y``), ``|Lam_T| <= mu Lam_N``.
    post_state : ndarray, shape (12,)
        Free-body state just after the impact (positions unchanged).
    contact_velocity_pre, contact_velocity_post : ndarray, shape (3,)
        Velocity of the contact point in Cxyz before and after.
    energy_lost : float
        ``T- - T+ = -Lam.(gamma- + gamma+)/2 >= 0`` [units ``m g a``].
    stick : bool
        The sticking branch of the law (``xi = 0``) holds.
    mode : {"rolling", "sliding", "flight"}
        Suggested by the post-impact contact velocity.
    law_residual : float
        ``|Lam - prox_C(Lam - r xi)|`` relative to ``|Lam| + r |xi|``: how well the law
        holds (about 1e-16; the tests demand 1e-14).
    """

    impulse_normal: float
    impulse_tangential: np.ndarray
    post_state: np.ndarray
    contact_velocity_pre: np.ndarray
    contact_velocity_post: np.ndarray
    energy_lost: float
    stick: bool
    mode: str
    law_residual: float

    def __repr__(self) -> str:
        t = self.impulse_tangential
        return (f"ImpactResult(mode={self.mode!r}, Lam_N={self.impulse_normal:.6g}, "
                f"|Lam_T|={math.hypot(t[0], t[1]):.6g}, energy_lost={self.energy_lost:.6g})")


def _contact_of(h, s, contact):
    theta = s[4]
    sig_c = 1.0 if math.cos(theta) >= 0.0 else -1.0
    if isinstance(contact, LowestPoint):
        if contact.kind == "face":
            raise ParameterError("contact: a face landing is a distributed impact, outside "
                                    "the single-point law; give side=+1 or -1 of a rim edge")
        if contact.kind == "tread":
            raise ParameterError("contact: on the tread line give the rim edge that "
                                    "strikes, contact=+1 or -1")
        side = contact.side
    else:
        side = check_sign("contact (a LowestPoint or a rim edge)", contact)
    return _r_xyz(h, theta, side, sig_c)


def _impact(h, s, r, e_n, e_t, mu, mode_tol):
    psi, theta = s[3], s[4]
    k1, k2 = inertia(h)
    Rz = _rot_z(psi)
    Qx = _rot_x(theta)
    V = Rz.T @ s[6:9]  # Cxyz
    w = Qx @ s[9:12]  # Cxyz
    gam = V + _cross(w, r)
    Jinv, Rx = _jacobian_parts(h, theta, r)
    W = np.eye(3) + Rx.T @ Jinv @ Rx
    Lam, stick = _solve_law(W, gam, e_n, e_t, mu)
    if not (Lam[2] >= 0.0 and math.hypot(Lam[0], Lam[1]) <= mu * Lam[2] * (1.0 + 1e-12)):
        raise RuntimeError(f"impact law broke Coulomb's bound: Lam = {Lam.tolist()!r}, "
                           f"mu = {mu!r} (|Lam_T| <= mu Lam_N, Lam_N >= 0; please report)")
    V2 = V + Lam
    w2 = w + Jinv @ _cross(r, Lam)
    gam2 = V2 + _cross(w2, r)
    post = s.copy()
    post[6:9] = Rz @ V2
    post[9:12] = Qx.T @ w2
    lost = -0.5 * float(Lam @ (gam + gam2))
    scale = mode_tol * max(1.0, float(np.linalg.norm(gam)))
    mode = ("flight" if gam2[2] > scale
            else "sliding" if math.hypot(gam2[0], gam2[1]) > scale else "rolling")
    resid = _prox_residual(W, gam, Lam, e_n, e_t, mu)
    return ImpactResult(float(Lam[2]), Lam[:2].copy(), post, gam, gam2, lost, stick, mode,
                        resid)


def impact(disk: Disk, pre_state, contact, e: float, mu: float, *,
           mode_tol: float = 1e-9) -> ImpactResult:
    """Impact of the disk on the plane at one rim point: Newton-Coulomb law (Glocker).

    Parameters
    ----------
    disk : Disk
    pre_state : array_like, shape (12,)
        Free-body state just before the impact (:data:`FREE_STATE`).
    contact : LowestPoint or {+1, -1}
        The rim point that strikes: a :class:`LowestPoint` of kind ``"rim"`` (from
        :func:`lowest_point`), or the rim edge ``side`` (the point ``-side h eta - zeta``).
    e : float
        Restitution coefficient in ``[0, 1]``, normal and tangential alike.
    mu : float
        Coefficient of friction, ``>= 0``.
    mode_tol : float
        Relative size below which a post-impact contact velocity counts as zero.

    Returns
    -------
    ImpactResult

    Notes
    -----
    With ``gamma-`` the contact velocity before, ``W`` the Delassus matrix
    (:func:`contact_delassus`) and ``xi = gamma+ + e gamma-``, ``gamma+ = gamma- + W Lam``,
    the law is the normal cone inclusion of Glocker (2001) in proximal form
    ``Lam = prox_C(Lam - r xi)``, ``C = {Lam_N >= 0, |Lam_T| <= mu Lam_N}``.  It never
    creates energy: ``T+ - T- = (Lam.xi - (1-e) Lam.W Lam/2)/(1+e) <= 0``, with equality
    for ``e = 1, mu = 0``; it needs the same ``e`` for the normal and the tangential
    velocity (``docs/impacts.md``).  Solved exactly: the sticking impulse
    ``-(1+e) W^-1 gamma-`` if it lies in ``C``, else the sliding direction by bracketed
    root finding on its angle, polished by Newton's method; the impulse found is checked:
    ``|Lam_T| <= mu Lam_N (1 + 1e-12)`` (``RuntimeError``, an internal error, if not).

    Examples
    --------
    >>> s = [0, 0, 1.0, 0, 0.0, 0, 0, 0, -1.0, 0, 0, 0]  # thin disk upright, falling
    >>> res = impact(Disk(h=0.0), s, +1, e=0.5, mu=0.3)
    >>> res.mode, round(res.impulse_normal, 12), round(float(res.post_state[8]), 12)
    ('flight', 1.5, 0.5)
    """
    h = _check_disk(disk).h
    s = _as_free_state(pre_state, "pre_state")
    e = check_real("e", e, low=0.0, high=1.0)
    mu = check_real("mu", mu, low=0.0)
    mode_tol = check_real("mode_tol", mode_tol, low=0.0, high=1.0)
    r = _contact_of(h, s, contact)
    return _impact(h, s, r, e, e, mu, mode_tol)


# --------------------------------------------------------------------- rocking
def rim_change_ratio(h) -> float:
    """``omega+/omega-`` when an upright disk rocking without spin changes rim edge.

    Parameters
    ----------
    h : float
        Half-thickness, ``0 <= h <= sqrt(15/8)``.

    Returns
    -------
    float
        ``(15 - 8 h^2)/(15 + 16 h^2)``.

    Notes
    -----
    The disk rocks about one rim edge (rotation about the diameter xi) and lands on the
    other, ``2h`` away, with a perfectly inelastic, sticking impact: angular momentum about
    the new edge is conserved, ``(k1^2 + R^2) omega+ = (k1^2 + R^2 cos 2 alpha) omega-`` with
    ``R^2 = 1 + h^2``, ``tan alpha = h``, ``k1^2 = 1/4 + h^2/3`` (eq. 10): Housner's
    ``1 - (m R^2/I_O)(1 - cos 2 alpha)`` with the disk's own inertia
    (:func:`rollingdisk.symbolic.impact.rocking_ratio`).  Beyond ``h^2 = 15/8`` the ratio
    would be negative: one edge cannot take the impact alone.

    Examples
    --------
    >>> rim_change_ratio(0.0), round(rim_change_ratio(0.5), 12)
    (1.0, 0.684210526316)
    """
    h = check_real("h", h, low=0.0, high=H_ROCK_MAX)
    return (15.0 - 8.0 * h * h) / (15.0 + 16.0 * h * h)


# ---------------------------------------------------------- rolling <-> free states
def free_state_from_rolling(disk: Disk, ground: str, y) -> np.ndarray:
    """The free-body state of a state of the library's rolling layouts.

    Parameters
    ----------
    disk : Disk
    ground : {"rough", "smooth"}
        Layout of ``y``: rough (8 components, velocity of C from no slip, eq. 37) or smooth
        (10 components, also the Coulomb layout, ``V_X, V_Y`` in the state).
    y : array_like

    Returns
    -------
    ndarray, shape (12,)
        ``Z_C = -z_P`` (eq. 7), ``V_Z = -omega1 y_P`` (eq. 7).
    """
    disk = _check_disk(disk)
    names = state_names(ground)
    y = real_array("y", y)
    if y.shape != (len(names),):
        raise ParameterError(f"y must have {len(names)} components on {ground} ground "
                                f"({', '.join(names)}), got shape {y.shape}")
    if not np.all(np.isfinite(y)):
        raise ParameterError("y must be finite (no NaN or infinity)")
    g = {n: y[state_index(ground, n)] for n in names}
    psi, theta = g["psi"], g["theta"]
    if not abs(theta) < math.pi / 2:
        raise ParameterError(f"y: theta must lie in (-pi/2, pi/2) on a rim edge, got "
                                f"{theta!r}")
    w1, w2, w3 = g["omega1"], g["omega2"], g["omega3"]
    y_P, z_P = disk.contact_point_xyz(theta)  # eq. (4)
    if ground == "rough":
        ht = disk.h_tilde(theta)
        vx, vy = w2 - ht * w3, w1 * z_P  # eq. (37)
        V_X = vx * math.cos(psi) - vy * math.sin(psi)  # eq. (1)
        V_Y = vx * math.sin(psi) + vy * math.cos(psi)
    else:
        V_X, V_Y = g["V_X"], g["V_Y"]
    return np.array([g["X_C"], g["Y_C"], -z_P, psi, theta, g["phi"], V_X, V_Y, -w1 * y_P,
                     w1, w2, w3])


def rolling_state_from_free(disk: Disk, ground: str, state, atol: float = 1e-9
                            ) -> np.ndarray:
    """The rolling-layout state of a free-body state that touches the plane.

    Parameters
    ----------
    disk : Disk
    ground : {"rough", "smooth"}
        Target layout (``"smooth"`` is also the Coulomb layout).
    state : array_like, shape (12,)
    atol : float
        Tolerance on the height of the lowest point, on the normal velocity of the contact
        point and (rough) on its slip.

    Raises
    ------
    ParameterError
        If the disk does not touch with one rim edge, ``|theta| >= pi/2``, the contact
        point leaves or enters the plane, or (rough) slips.
    """
    disk = _check_disk(disk)
    check_ground(ground)
    s = _as_free_state(state)
    atol = check_real("atol", atol, low=0.0)
    h = disk.h
    psi, theta = s[3], s[4]
    if not abs(theta) < math.pi / 2:
        raise ParameterError(f"state: theta must lie in (-pi/2, pi/2), got {theta!r}")
    H = _lowest_height(h, s[2], theta)
    if abs(H) > atol:
        raise ParameterError(f"state: the disk does not touch the plane (lowest point "
                                f"at Z = {H:.3g})")
    side = 1 if theta >= 0.0 else -1  # h~ = h sgn(theta), theta = 0 counts as 0+
    r = _r_xyz(h, theta, side, 1.0)
    V = _rot_z(psi).T @ s[6:9]
    gam = V + _cross(_rot_x(theta) @ s[9:12], r)
    if abs(gam[2]) > atol * max(1.0, float(np.linalg.norm(V))):
        raise ParameterError(f"state: the contact point moves off the plane (normal "
                                f"velocity {gam[2]:.3g})")
    if ground == "rough":
        if math.hypot(gam[0], gam[1]) > atol * max(1.0, float(np.linalg.norm(V))):
            raise ParameterError(f"state: the contact point slips (|u| = "
                                    f"{math.hypot(gam[0], gam[1]):.3g}); rough ground "
                                    f"needs rolling")
        return np.array([s[0], s[1], psi, theta, s[5], s[9], s[10], s[11]])
    return np.array([s[0], s[1], s[6], s[7], psi, theta, s[5], s[9], s[10], s[11]])

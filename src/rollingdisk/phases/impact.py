"""The impact law of a disk of finite thickness (Glocker's Newton-Coulomb law), rim changes
and the map between the rolling and free-body states.

Derived in :mod:`rollingdisk.symbolic.impact` and explained in ``docs/impacts.md``.
Dimensionless units m = a = g = 1; numpy and scipy only.  The free-body state
(:data:`FREE_STATE`), free flight and touchdown are :mod:`rollingdisk.phases.flight`, whose
names this module also offers.  Contact and impact quantities are written in the frame Cxyz
(``x = xi`` horizontal, ``z`` up): the contact normal is ``z``, the tangent plane ``(x, y)``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from rollingdisk.model.disk import Disk, check_ground
from rollingdisk.model.geometry import inertia
from rollingdisk.model.state import state_index, state_names
from rollingdisk.phases.flight import (  # noqa: F401 - the free body's names, offered here too
    CONTACT_KINDS,
    FREE_STATE,
    IMPACT_MODES,
    LowestPoint,
    _as_free_state,
    _check_disk,
    _cross,
    _lowest_height,
    _r_xyz,
    _rot_x,
    _rot_z,
    angular_momentum,
    free_energy,
    free_flight,
    lowest_point,
    touchdown_time,
)
from rollingdisk.util.checks import check_real, check_sign, real_array
from rollingdisk.util.errors import ParameterError

__all__ = ["ImpactResult", "contact_delassus", "impact", "rim_change_ratio",
           "free_state_from_rolling", "rolling_state_from_free"]


#: Largest ``h`` for which the single-edge rocking law gives a non-negative ratio.
H_ROCK_MAX = math.sqrt(15.0 / 8.0)


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

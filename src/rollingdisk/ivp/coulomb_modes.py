"""The modes of a run on Coulomb ground: their right-hand sides and event functions
(:class:`_Run`), how a slip or a turn of the rolling resistance starts, and where an event
lies on a step's dense output.  :mod:`rollingdisk.ivp.coulomb_driver` steps through them;
:func:`rollingdisk.ivp.hybrid.simulate_coulomb` is the front door.
"""

from __future__ import annotations

import functools
import math

import numpy as np

from rollingdisk.ivp import fastsegment as _fs
from rollingdisk.ivp.slipdir import _direction_scan, _slip_direction
from rollingdisk.model import coulomb as _cl

#: Names of the dissipation terms recorded in :attr:`Trajectory.dissipated`.
DISSIPATION_TERMS = ("slip", "rolling_resistance", "pivot", "air")

ROLLING, SLIDING, PIVOT_STUCK, ROLL_STUCK = (_cl.ROLLING, _cl.SLIDING, _cl.PIVOT_STUCK,
                                             _cl.ROLL_STUCK)
_NAMES = _cl.MODE_NAMES
_N_SAMPLE = 9  # points of the dense output at which events are looked for, per step
#: Slip speed below which sliding keeps the reference direction (the solved initial slip
#: direction, or the last resolved one): below it u/|u| is rounding noise.
U_EPS = 1e-8
#: Slip speed (relative to 1 + |V|) above which a zero of ``u . u_ref`` is a turn of the slip
#: direction, not the slip coming to rest.
STICK_TOL = 1e-6
#: ``|omega_h|`` below which the rolling resistance keeps its reference direction (as
#: :data:`U_EPS` for the slip).
W_EPS = 1e-8


class _Singular(ArithmeticError):
    """The right-hand side left floating-point range (scipy's DOP853 would loop on NaN)."""


def _finite(t, out):
    if not np.all(np.isfinite(out)):
        raise _Singular(f"t = {t:.12g}")
    return out


class _Run:
    """One hybrid run: the right-hand sides and event functions of the modes.

    A mode is ``ROLLING`` or ``SLIDING``, with the bit ``PIVOT_STUCK`` while the pivot
    sticks and ``ROLL_STUCK`` while the rolling resistance sticks.  Outside them the pivot
    moment is ``-c F_z sz`` with ``sz`` (``self.sz``) the sign of ``omega_z`` on the
    current segment, the rolling-resistance moment ``-c F_z sgn(omega_h . rref)
    omega_h/|omega_h|`` with ``rref`` (``self.rref``, inertial) the direction of ``omega_h``
    at the last step: the smooth continuations through ``omega_z = 0``, ``omega_h = 0``,
    where the driver stops (events), as the slip reference does for sliding."""

    def __init__(self, disk, ground, alpha_min=0.0):
        self.alpha_min = alpha_min
        self.side = 1.0  # sgn(theta) on the current segment (edge-contact event)
        self.h = disk.h
        self.g = ground
        self.coeffs = ground.coefficients
        self.c_roll, self.c_pivot = self.coeffs[0], self.coeffs[1]
        self.ref = (1.0, 0.0)  # inertial slip reference direction (sliding)
        # a slip started from u = 0 is resolved once |u| passes a floor (_start_sliding):
        # until then its end is not looked for and the friction keeps the direction ref
        self.armed = True
        self.u_eps = U_EPS  # |u| below which the friction direction is ref
        self.floor = 0.0
        self.sz = 1.0  # sgn(omega_z) on the segment (pivot not stuck)
        self.rref = (0.0, 0.0)  # inertial direction of omega_h (rolling resistance)
        self.n_rhs = 0
        self.u_qs = 0.0  # simulate_coulomb's quasi_static_slip

    def pivot_state(self, mode):
        """``sz`` of the kernels: 0 while the pivot sticks, else the segment's sign."""
        return 0.0 if mode & PIVOT_STUCK else self.sz

    def solve(self, mode, z, rref=None, w_eps=W_EPS):
        """The mode's kernel at ``z``: ``(dy, F_x, F_y, F_z, P_slip, P_roll, P_pivot,
        P_air, M_piv, M_hx, M_hy)`` (``rref``: another rolling-resistance reference)."""
        h, cf, sz = self.h, self.coeffs, self.pivot_state(mode)
        rx, ry = self.rref if rref is None else rref
        rs = bool(mode & ROLL_STUCK)
        if mode & 1 == ROLLING:
            dy, F_x, F_y, F_z, P1, P2, P3, L, Lx, Ly = _cl.coulomb_rolling_full(
                h, *cf, z, sz, rx, ry, w_eps, rs)
            return dy, F_x, F_y, F_z, 0.0, P1, P2, P3, L, Lx, Ly
        ref_X, ref_Y, u_eps = self.ref[0], self.ref[1], self.u_eps
        if self.u_qs > 0.0:
            p = np.array([mode, self.g.mu_k, self.g.mu_s, *cf, ref_X, ref_Y, u_eps, sz, 0.0,
                          0.0, 0.0, 0.0, 0.0, self.u_qs])
            ref_X, ref_Y, u_eps = _quasi_static_ref()(p, h, z, sz)
        return _cl.coulomb_sliding_full(h, self.g.mu_k, *cf, z, ref_X, ref_Y, u_eps, sz, rx,
                                         ry, w_eps, rs)

    def rhs(self, mode):
        def f(t, z):
            self.n_rhs += 1
            dy, F_x, F_y, F_z, P0, P1, P2, P3, *_ = self.solve(mode, z)
            return _finite(t, np.array([*dy, -P0, -P1, -P2, -P3]))
        return f

    def contact(self, mode, z):
        """``(F_t, F_z, u_ref_component, M_piv, M_hx, M_hy)`` at ``z`` in ``mode``."""
        _, F_x, F_y, F_z, *_, L, Lx, Ly = self.solve(mode, z)
        if mode & 1 == ROLLING:
            return math.hypot(F_x, F_y), F_z, 0.0, L, Lx, Ly
        U_X, U_Y = _inertial_slip(self.h, z)
        return math.hypot(F_x, F_y), F_z, U_X * self.ref[0] + U_Y * self.ref[1], L, Lx, Ly

    def events(self, mode, z):
        """Event functions, each crossing from > 0 to <= 0:
        ``[mode end, pivot, lift-off, edge contact, fell flat, roll]``; pivot: ``omega_z``
        reaches 0 (``sz omega_z``), or, while stuck, the moment holding it reaches
        ``c F_z``; roll: ``omega_h`` turns across ``rref`` (``omega_h . rref``, inertial),
        or, while stuck, the moment holding it reaches ``c F_z``."""
        F_t, F_z, along, L, Lx, Ly = self.contact(mode, z)
        end = self.g.mu_s * F_z - F_t if mode & 1 == ROLLING else along
        theta = z[5]
        if mode & PIVOT_STUCK:
            pivot = self.c_pivot * F_z - abs(L)
        else:
            pivot = self.sz * _cl.omega_z(theta, z[8], z[9])
        if mode & ROLL_STUCK:
            roll = self.c_roll * F_z - math.hypot(Lx, Ly)
        else:
            W_X, W_Y = _inertial_omega_h(z)
            roll = W_X * self.rref[0] + W_Y * self.rref[1]
        return [end, pivot, F_z, theta * self.side if self.h > 0 else 1.0,
                0.5 * math.pi - abs(theta) - self.alpha_min, roll]


@functools.cache
def _quasi_static_ref():
    """:func:`rollingdisk.ivp.fastsegment._quasi_static_ref`, uncompiled (the scipy and
    LSODA paths)."""
    return _fs.namespace()["_quasi_static_ref"]


def _DOP853():
    """scipy's DOP853 class, imported when a Coulomb run starts (``import rollingdisk``
    must not load ``scipy.integrate``, 0.3 s)."""
    from scipy.integrate import DOP853

    return DOP853


def _LSODA():
    """scipy's LSODA class (``method="lsoda"``), imported when such a run starts."""
    from scipy.integrate import LSODA

    return LSODA


def _inertial_slip(h, z):
    u_x, u_y = _cl.slip_velocity(h, z)
    return _cl.to_inertial(z[4], u_x, u_y)


def _inertial_omega_h(z):
    """Horizontal angular velocity ``omega_h`` in OXYZ (``(omega_x, omega_y)`` of Cxyz
    turned by ``psi``)."""
    theta, w1, w2, w3 = z[5], z[7], z[8], z[9]
    return _cl.to_inertial(z[4], w1, w2 * math.cos(theta) - w3 * math.sin(theta))



class _DenseStep:
    """The DOP853 interpolant of one step of the compiled loop, ``sol(t)`` as scipy's
    dense output (:func:`rollingdisk.engine.dop853._dense_value`)."""

    def __init__(self, value, t_old, t, y_old, F):
        self.value, self.t_old, self.dt, self.y_old, self.F = value, t_old, t - t_old, y_old, F

    def __call__(self, t):
        out = np.empty(self.y_old.shape[0])
        self.value(self.y_old, self.F, (t - self.t_old) / self.dt, out)
        return out


def _start_sliding(run, disk, ground, z, stuck=0):
    """Switch to sliding at a state with ``u = 0``: the slip direction is solved (with the
    pivot as it is: stuck if ``stuck`` has ``PIVOT_STUCK``, else the segment's ``sz``; with
    the rolling resistance stuck its moment, set-valued there, is left out of this solve).
    Returns ``SLIDING`` (the caller keeps the stuck bits)."""
    sz = run.pivot_state(stuck)
    coeffs = ground.coefficients
    if stuck & ROLL_STUCK:
        coeffs = (0.0, coeffs[1], coeffs[2])
    d = _slip_direction(disk.h, ground.mu_k, coeffs, z[:10], sz)
    if d is None:  # no consistent slip direction: oppose the rolling friction force
        _, F_x, F_y, *_ = run.solve(ROLLING | stuck, z)
        n = math.hypot(F_x, F_y) or 1.0
        d = (-F_x / n, -F_y / n)
    run.ref = _cl.to_inertial(z[4], d[0], d[1])
    run.armed = False  # the slip's end is looked for once |u| passes the floor (_arms)
    run.floor = run.u_eps = STICK_TOL * (1.0 + math.hypot(z[2], z[3]))
    return SLIDING


def _roll_turn(run, mode, z):
    """The inertial direction ``d`` along which ``omega_h`` starts to grow from 0 in
    ``mode`` (not roll stuck) when the rolling resistance cannot hold it: with the moment
    ``-c F_z d``, ``d omega_h/dt`` is along ``+d`` (the Cxyz rates of (9), ``d omega_y/dt =
    domega2 cos - domega3 sin - omega1 omega_z``).  Found as :func:`slip_direction`
    finds the slip direction: a scan of the angle, ``brentq`` on ``d x d omega_h/dt = 0``,
    among the roots with ``d . d omega_h/dt > 0`` the one of largest rate; ``None`` if
    there is none."""
    psi, theta, w1, w2, w3 = z[4], z[5], z[7], z[8], z[9]
    s, c = math.sin(theta), math.cos(theta)
    wz = w2 * s + w3 * c

    def parts(a):
        ex, ey = math.cos(a), math.sin(a)  # Cxyz
        dy = run.solve(mode, z, _cl.to_inertial(psi, ex, ey), math.inf)[0]
        ax, ay = dy[7], dy[8] * c - dy[9] * s - w1 * wz
        return ex * ay - ey * ax, ex * ax + ey * ay

    a = _direction_scan(parts)
    return None if a is None else _cl.to_inertial(psi, math.cos(a), math.sin(a))


def _active(run, mode, edge, guards):
    """Which of :meth:`_Run.events` are looked for: the mode's end (in sliding once the
    slip passed its floor), the pivot's and the rolling resistance's if on, the guards."""
    return [run.armed or mode & 1 == ROLLING, run.c_pivot > 0.0, guards, edge, guards,
            run.c_roll > 0.0]


def _start_event(run, mode, sol, ta, g_old, edge, guards):
    """An event at the very start ``ta`` of a step whose interpolant does not pass through
    the accepted state (LSODA's): one that is ``> 0`` at the accepted state and ``<= 0`` on
    the interpolant at ``ta``, as ``(index, ta)``; else None."""
    active = _active(run, mode, edge, guards)
    g0 = run.events(mode, np.asarray(sol(ta)))
    for k in range(len(g0)):
        if active[k] and g_old[k] > 0.0 and g0[k] <= 0.0:
            return k, ta
    return None


def _first_event(run, mode, sol, ta, tb, g_old, edge, guards):
    """The first event in ``(ta, tb]`` on the dense output ``sol``: ``(index, time)``."""
    from scipy.optimize import brentq

    active = _active(run, mode, edge, guards)
    ts = np.linspace(ta, tb, _N_SAMPLE)
    prev = g_old
    best = None
    for i in range(1, ts.size):
        gi = run.events(mode, np.asarray(sol(ts[i])))
        for k in range(6):
            if active[k] and prev[k] > 0.0 and gi[k] <= 0.0:
                def fk(s, k=k):
                    return run.events(mode, np.asarray(sol(s)))[k]
                te = ts[i] if gi[k] == 0.0 else brentq(fk, ts[i - 1], ts[i], xtol=1e-15,
                                                        rtol=8.9e-16, maxiter=200)
                if best is None or te < best[1]:
                    best = (k, te)
        if best is not None:
            k, te = best
            if k != 3 and active[3] and prev[3] > 0.0 and gi[3] <= 0.0:
                # theta crossing 0 flips h~ and makes u and F jump: an event of the mode
                # found at that jump is the edge contact itself
                te2 = ts[i] if gi[3] == 0.0 else brentq(
                    lambda s: run.events(mode, np.asarray(sol(s)))[3], ts[i - 1], ts[i],
                    xtol=1e-15, rtol=8.9e-16, maxiter=200)
                if te2 - te <= 1e-9 * (1.0 + abs(te2)):
                    return 3, te2
            return best
        prev = gi
    return None


def _message(status, t, h):
    if status == "lift-off":
        return (f"lift-off at t = {t:.12g}: the normal force F_z (eq. 11) reached 0 and the "
                "disk leaves the plane; the model ends here")
    if status == "edge-contact":
        return (f"edge contact at t = {t:.12g}: theta reached 0 with h = {h:g} > 0, the disk "
                "lands on its other rim edge (an impact, outside the model)")
    return (f"fell flat at t = {t:.12g}: the tilt pi/2 - |theta| reached alpha_min, the disk "
            "lies on the plane")

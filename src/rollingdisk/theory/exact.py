"""Exact motions by quadrature: the integrable disk at finite amplitude.

On both ideal grounds the reduced system (theta, omega1, omega2, omega3) of eq. (38)
(rough) or (49) (smooth) has ``d omega2/dt`` and ``d omega3/dt`` proportional to
``omega1 = d theta/dt``, and ``d omega1/dt`` affine in ``omega1^2``.  Along a motion
``omega2``, ``omega3`` and ``q = omega1^2`` are therefore functions of ``theta`` alone,
solving the *linear* system (``' = d/d theta``)::

    omega2' = D2(theta, omega2, omega3),   omega3' = D3(theta, omega2, omega3),
    q'      = 2 D1(theta, q, omega2, omega3),

where ``D2, D3`` are eq. (38)/(49)'s ``d omega2/dt, d omega3/dt`` at ``omega1 = 1`` and
``D1 = d omega1/dt`` (rough: ``D1`` is free of ``omega1``; smooth: affine in ``q``).  The
coefficients are taken from the very kernels of :mod:`rollingdisk.model.equations` (checked
against the sympy derivation); that they are proportional to ``omega1`` is checked against
the derivation by ``tests/test_exact.py``.  Integrating ``q`` rather than taking it from
the energy integral (13) avoids the cancellation of two O(1) energies at small amplitude;
eq. (13) is then an independent check.

How the quadratures are done
----------------------------
1. The linear system is integrated in ``theta`` from ``theta(0)`` both ways (scipy's DOP853,
   ``rtol = 1e-13``) to the first zero of ``q`` (a turning point, located on the dense
   output), to ``theta = 0`` (h > 0: the other rim edge touches) or to ``|theta| = pi/2``.
2. On the range ``[a, b]`` so found, ``omega2, omega3, q`` are Chebyshev series in
   ``x = (theta - m)/d`` (``m, d`` the midpoint and half-width), to the noise floor, and
   ``q = d^2 (1 + x)(1 - x) H(x)`` is divided exactly by its simple zeros at the turning
   points (Chebyshev division), leaving a smooth positive ``H``.
3. The substitution ``x = sin u`` (both ends turning) turns ``dt = d theta / omega1`` into
   ``dt = du / sqrt(H(sin u))``: no singularity at the turning points, and over a period
   (``u`` from 0 to 2 pi) the integrand is periodic and analytic, so the trapezoidal rule
   (an FFT) converges exponentially.  ``t(u)``, ``psi(u)``, ``phi(u)`` and the centre's
   path ``X_C + i Y_C`` (rough ground: ``dZ_C/du = e^{i psi} (v_Cx + i v_Cy) dt/du``,
   eqs. 1 and 37) are then Fourier series integrated term by term.  An orbit that ends
   is timed leg by leg with Gauss-Legendre after ``x = -cos w`` / ``x = cos w`` at its
   one turning point.

What ends a motion
------------------
``"bounded"`` (both ends are turning points and ``F_z > 0`` over ``[a, b]``), or the first
along the motion of: ``"lift-off"`` (``F_z`` of eq. 11, a function of ``theta`` on the
orbit, reaches 0), ``"edge-contact"`` (h > 0, ``theta`` reaches 0), ``"fell-flat"``
(``|theta|`` reaches pi/2) -- the guards of :mod:`rollingdisk.integrate.events`, with the time and
``theta`` where it happens.  A state exactly on a steady motion is ``"steady"``.

For ``h = 0`` on rough ground ``omega3(theta)`` is a Legendre-type function: see
:func:`thin_disk_omega3` and ``docs/exact.md``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from rollingdisk.model.disk import Disk
from rollingdisk.model.equations import (
    _check_disk,
    _normal_force,
    _rough_omega_dot,
    _smooth_omega_dot,
)
from rollingdisk.model.geometry import _geometry
from rollingdisk.model.outcomes import BOUNDED, EDGE_CONTACT, FELL_FLAT, LIFT_OFF, STEADY, names
from rollingdisk.model.state import _as_state, state_index
from rollingdisk.util.checks import check_real
from rollingdisk.util.errors import ParameterError, ParameterTypeError

__all__ = ["ExactMotion", "exact_motion", "exact_steady", "Backbone", "backbone",
           "thin_disk_omega3", "EXACT_STATUSES"]

#: Possible values of :attr:`ExactMotion.status`.
EXACT_STATUSES = names(BOUNDED, STEADY, LIFT_OFF, EDGE_CONTACT, FELL_FLAT)

_RTOL = 1e-13  # the theta-ODE's tolerance
_FLAT = 0.5 * math.pi - 1e-9  # |theta| where the theta-ODE stops: the disk lies flat
_TINY = 1e-300  # theta "= 0" on the side of the motion (h~ keeps its sign)


# ---------------------------------------------------------------------------------------
# the linear system in theta
# ---------------------------------------------------------------------------------------
def _theta_coefficients(rough: bool, h: float, theta, w2, w3):
    """``(D1 at q=0, dD1/dq, D2, D3)``: eq. (38)/(49) at ``omega1 = 0`` and ``1``."""
    kernel = _rough_omega_dot if rough else _smooth_omega_dot
    a1 = kernel(h, theta, 0.0 * theta, w2, w3)[0]
    b1, b2, b3 = kernel(h, theta, 1.0 + 0.0 * theta, w2, w3)
    return a1, b1 - a1, b2, b3


def _theta_rhs(rough: bool, h: float):
    def f(theta, z):
        w2, w3, q = z
        a1, c1, d2, d3 = _theta_coefficients(rough, h, theta, w2, w3)
        return [d2, d3, 2.0 * (a1 + c1 * q)]
    return f


def _q_event(theta, z):
    return z[2]


_q_event.terminal = True
_q_event.direction = -1.0


def _sweep(rough, h, theta0, z0, end):
    """Integrate the theta-ODE from ``theta0`` to ``end``, stopping where ``q`` falls to 0.

    Returns ``(theta_reached, kind, sol)``; ``kind`` is ``"turn"`` or ``"end"``."""
    from scipy.integrate import solve_ivp

    if theta0 == end:
        return theta0, "end", None
    sol = solve_ivp(_theta_rhs(rough, h), (theta0, end), z0, method="DOP853", rtol=_RTOL,
                    atol=1e-30, dense_output=True, events=_q_event)
    if sol.status < 0:
        raise ParameterError(f"the quadrature in theta failed ({sol.message}); the state "
                             "is outside what the exact solution can follow")
    if sol.status == 1:
        return float(sol.t_events[0][0]), "turn", sol.sol
    return float(sol.t[-1]), "end", sol.sol


# ---------------------------------------------------------------------------------------
# results
# ---------------------------------------------------------------------------------------
@dataclass(frozen=True)
class ExactMotion:
    """The exact motion of the disk from one initial state, on rough or smooth ground.

    Attributes
    ----------
    disk : Disk
    ground : {"rough", "smooth"}
    status : str
        ``"bounded"`` (periodic nutation between turning points), ``"steady"`` (the state
        is a steady motion), or what ends it: ``"lift-off"``, ``"edge-contact"``,
        ``"fell-flat"`` (see :data:`EXACT_STATUSES`).
    E : float
        Energy, eq. (13).
    theta_min, theta_max : float
        Range of ``theta`` the motion covers (turning points when bounded; up to the end
        otherwise).
    period : float or None
        Nutation period: time from ``theta_max`` back to ``theta_max``; None if the motion
        ends.  For ``"steady"`` the small-amplitude limit ``2 pi / varpi`` (None if the
        steady motion is unstable).
    delta_psi : float or None
        Angle ``psi`` advances in one period.
    delta_phi : float or None
        Angle ``phi`` advances in one period.
    drift : tuple of float or None
        ``(dX, dY)``: displacement of the contact point P over the first period (eq. 5).
    t_end, theta_end : float or None
        When and where the motion ends (None when bounded or steady).
    y0 : numpy.ndarray
        The initial state (layout of :mod:`rollingdisk.model.equations`).
    """

    disk: Disk
    ground: str
    status: str
    E: float
    theta_min: float
    theta_max: float
    period: float | None
    delta_psi: float | None
    delta_phi: float | None
    drift: tuple[float, float] | None
    t_end: float | None
    theta_end: float | None
    y0: np.ndarray = field(repr=False, compare=False)
    _fit: object = field(default=None, repr=False, compare=False)
    _orbit: object = field(default=None, repr=False, compare=False)

    @property
    def amplitude(self) -> float:
        """Half the range of ``theta``: ``(theta_max - theta_min) / 2``."""
        return 0.5 * (self.theta_max - self.theta_min)

    @property
    def frequency(self) -> float | None:
        """Nutation frequency ``2 pi / period`` (compare with ``varpi``, eq. 39)."""
        return None if not self.period else 2.0 * math.pi / self.period

    @property
    def ends(self) -> bool:
        """True when a guard ends the motion (lift-off, edge contact, fell flat)."""
        return self.t_end is not None

    def state(self, t):
        """State vector(s) at time(s) ``t`` (layout of :mod:`rollingdisk.model.equations`).

        ``t`` a float (returns shape ``(k,)``) or an array (returns ``(n, k)``).  Bounded
        and steady motions only: for all ``t``; an orbit that ends raises.
        """
        if self._orbit is None:
            raise ParameterError(f"state(t) needs a bounded or steady motion; this one "
                                 f"ends ({self.status} at t = {self.t_end:.10g})")
        return self._orbit.state(t)

    def theta(self, t):
        """``theta(t)`` (bounded and steady motions)."""
        y = self.state(t)
        return y[..., state_index(self.ground, "theta")]

    def contact_path(self, t):
        """Contact point ``(X_P, Y_P)`` at time(s) ``t`` (eq. 5)."""
        from rollingdisk.model.equations import contact_point

        return contact_point(self.disk, self.ground, np.asarray(self.state(t)).T)

    def omega23(self, theta):
        """``(omega2, omega3)`` as functions of ``theta`` on this orbit (``theta`` within
        ``[theta_min, theta_max]``)."""
        return self._functions(theta)[:2]

    def omega1_sq(self, theta):
        """``omega1^2`` as a function of ``theta`` on this orbit."""
        return self._functions(theta)[2]

    def normal_force(self, theta):
        """``F_z`` of eq. (11) along the orbit, as a function of ``theta``."""
        w2, w3, q = self._functions(theta)
        return _orbit_normal_force(self.ground == "rough", self.disk.h,
                                   np.asarray(theta, float), w2, w3, q)

    def _functions(self, theta):
        theta = np.asarray(theta, dtype=float)
        if self._fit is None:  # steady: constants
            it = state_index(self.ground, "theta")
            w2, w3 = self.y0[it + 3], self.y0[it + 4]
            return w2 + 0.0 * theta, w3 + 0.0 * theta, 0.0 * theta
        return self._fit.functions(theta)

    def as_dict(self) -> dict:
        """Plain floats for JSON (None where a value does not exist)."""
        return {"ground": self.ground, "h": self.disk.h, "status": self.status,
                "E": self.E, "theta_min": self.theta_min, "theta_max": self.theta_max,
                "amplitude": self.amplitude, "period": self.period,
                "frequency": self.frequency, "delta_psi": self.delta_psi,
                "delta_phi": self.delta_phi,
                "drift": None if self.drift is None else list(self.drift),
                "t_end": self.t_end, "theta_end": self.theta_end}

    # -- SI view and notebooks ----------------------------------------------
    _KINDS = {"h": "dimensionless", "E": "energy", "theta_min": "angle",
              "theta_max": "angle", "amplitude": "angle", "period": "time",
              "frequency": "angular_speed", "delta_psi": "angle", "delta_phi": "angle",
              "t_end": "time", "theta_end": "angle"}

    def to_si(self, disk: Disk | None = None) -> dict:
        """:meth:`as_dict` with SI values beside it (``period_si`` [s], ``frequency_si``
        [rad/s], ``E_si`` [J] when the disk has a mass, ``t_end_si`` [s], ``drift_si`` [m])
        and a ``"units"`` map; through ``disk`` (default: this motion's disk)."""
        from rollingdisk.model.units import si_view

        disk = self.disk if disk is None else disk
        disk._need("radius")
        out = si_view(disk, self.as_dict(), self._KINDS)
        if self.drift is not None:
            out["drift_si"] = [float(disk.length_to_si(d)) for d in self.drift]
            out["units"].update(drift="a", drift_si="m")
        return out

    def __repr__(self) -> str:
        from rollingdisk.util.display import short_repr

        d = self.as_dict()
        return short_repr("ExactMotion", {k: d[k] for k in (
            "ground", "h", "status", "theta_min", "theta_max", "period", "delta_psi",
            "t_end") if d[k] is not None or k == "period"})

    def _repr_html_(self) -> str:
        from rollingdisk.model.units import result_html

        return result_html(f"ExactMotion on {self.ground} ground", self.disk,
                           self.as_dict(), self._KINDS)


def _orbit_normal_force(rough, h, theta, w2, w3, q):
    a1, c1, _, _ = _theta_coefficients(rough, h, theta, w2, w3)
    y_P, z_P = _geometry(h, theta)[4:6]
    return 1.0 + z_P * q - y_P * (a1 + c1 * q)  # eq. (11)


# ---------------------------------------------------------------------------------------
# Chebyshev representation of omega2, omega3, q on [a, b]
# ---------------------------------------------------------------------------------------
class _Fit:
    """``omega2, omega3, q`` on ``[a, b]`` as Chebyshev series in ``x = (theta - m)/d``,
    and ``H = q / (d^2 (1 + x)^ra (1 - x)^rb)`` with the turning points divided out."""

    def __init__(self, rough, h, a, b, ra, rb, evaluate):
        from numpy.polynomial import chebyshev as C

        self.rough, self.h, self.a, self.b, self.ra, self.rb = rough, h, a, b, ra, rb
        self.m, self.d = 0.5 * (a + b), 0.5 * (b - a)
        prev = None
        for deg in (24, 48, 96, 192, 384):
            x = np.cos(np.pi * (np.arange(deg + 1) + 0.5) / (deg + 1))  # first kind
            z = evaluate(self.m + self.d * x)
            coef = [C.chebfit(x, zi, deg) for zi in z]
            tails = [_tail(c) for c in coef]
            if max(tails) <= 1e-13:
                break
            if prev is not None and max(prev[1]) < 1e-10 and all(
                    t > 0.3 * p for t, p in zip(tails, prev[1]) if p > 1e-13):
                coef = prev[0]  # a noise plateau (rounding in q' = 2 D1): keep the lower degree
                break
            prev = (coef, tails)
        else:
            raise ParameterError("omega2, omega3 and omega1^2 along this orbit are not "
                                 "resolved by a Chebyshev series of degree 384 (the orbit "
                                 "comes too close to |theta| = pi/2)")
        self.c2, self.c3, self.cq = (_chop(c) for c in coef)
        divisor = np.array([1.0])
        if ra:
            divisor = C.chebmul(divisor, [1.0, 1.0])
        if rb:
            divisor = C.chebmul(divisor, [1.0, -1.0])
        quot, rem = C.chebdiv(self.cq, divisor)
        self.cH = quot / (self.d * self.d)
        self.remainder = float(np.max(np.abs(rem))) / max(float(np.max(np.abs(self.cq))),
                                                          1e-300)
        xs = np.linspace(-1.0, 1.0, 2001)
        if np.min(C.chebval(xs, self.cH)) <= 0.0:
            raise ParameterError("omega1^2 vanishes inside the range of theta: the orbit is "
                                 "too close to a steady motion or a separatrix to be "
                                 "followed by quadrature")

    def x(self, theta):
        return (theta - self.m) / self.d

    def H(self, x):
        from numpy.polynomial import chebyshev as C

        return C.chebval(x, self.cH)

    def functions(self, theta):
        from numpy.polynomial import chebyshev as C

        x = self.x(theta)
        return C.chebval(x, self.c2), C.chebval(x, self.c3), C.chebval(x, self.cq)


def _chop(c):
    """Drop the coefficients at the noise floor (estimated from the last quarter): noise
    in high coefficients of ``q`` would be amplified by the division by ``1 - x^2``."""
    noise = float(np.max(np.abs(c[-max(4, c.size // 4):])))
    big = np.nonzero(np.abs(c) > 10.0 * noise)[0]
    return c[:big[-1] + 1] if big.size else c[:1]


def _tail(c) -> float:
    """Size of the last four Chebyshev coefficients relative to the largest."""
    scale = max(float(np.max(np.abs(c))), 1e-300)
    return float(np.max(np.abs(c[-4:]))) / scale


# ---------------------------------------------------------------------------------------
# a bounded orbit as Fourier series in u (theta = m + d sin u)
# ---------------------------------------------------------------------------------------
class _Orbit:
    """The bounded motion as a function of ``u``: ``theta = m + d sin u``,
    ``dt/du = 1/sqrt(H)``; everything periodic in ``u`` except the secular parts of
    ``t``, ``psi``, ``phi`` and the rotation of the centre's path."""

    def __init__(self, fit, rough, h, y0, ground):
        self.fit, self.rough, self.h, self.ground = fit, rough, h, ground
        iy = {n: state_index(ground, n) for n in ("theta", "omega1", "psi", "phi")}
        theta0, w10 = y0[iy["theta"]], y0[iy["omega1"]]
        x0 = min(1.0, max(-1.0, fit.x(theta0)))
        u0 = math.asin(x0)
        if w10 < 0.0 or (w10 == 0.0 and x0 > 0.0):
            u0 = math.pi - u0
        self.u0 = u0
        self.psi0, self.phi0 = float(y0[iy["psi"]]), float(y0[iy["phi"]])
        self.Z0 = complex(y0[0], y0[1])
        self.V = complex(y0[2], y0[3]) if not rough else 0j
        self.y_layout = iy
        M = 64
        prev = None
        while True:
            res = self._series(M)
            if prev is not None and all(abs(r - p) <= 2e-15 * max(1.0, abs(p))
                                        for r, p in zip(res[:3], prev[:3])) \
                    and self._tail_small():
                break
            if M >= 1 << 15:
                raise ParameterError("the orbit's period does not converge (the orbit is "
                                     "too close to a separatrix)")
            prev, M = res, 2 * M
        self.T, self.dpsi, self.dphi = res[:3]

    # per-u quantities --------------------------------------------------------------
    def _local(self, u):
        fit = self.fit
        x = np.sin(u)
        theta = fit.m + fit.d * x
        w2, w3, _ = fit.functions(theta)
        H = fit.H(x)
        F = 1.0 / np.sqrt(H)  # dt/du
        w1 = fit.d * np.cos(u) * np.sqrt(H)  # d theta/dt
        c = np.cos(theta)
        return theta, w1, w2, w3, F, w3 / c, w2 - w3 * np.tan(theta)  # eqs. (2)

    def _series(self, M):
        u = 2.0 * np.pi * np.arange(M) / M
        theta, w1, w2, w3, F, Om, ph = self._local(u)
        n = np.fft.fftfreq(M, 1.0 / M)
        self.n = n
        cF = np.fft.fft(F) / M
        cOm = np.fft.fft(Om * F) / M
        cph = np.fft.fft(ph * F) / M
        self.cF, self.cOm, self.cph = cF, cOm, cph
        T = 2.0 * np.pi * cF[0].real
        dpsi = 2.0 * np.pi * cOm[0].real
        dphi = 2.0 * np.pi * cph[0].real
        self.kappa = dpsi / (2.0 * np.pi)
        if self.rough:
            ht, s, cc, p, y_P, z_P = _geometry(self.h, theta)
            w = (w2 - ht * w3) * F + 1j * (w1 * z_P) * F  # (v_Cx + i v_Cy) dt/du, eq. (37)
            psi_per = self._periodic(cOm, u)
            self.cG = np.fft.fft(w * np.exp(1j * psi_per)) / M
        self.M = M
        return T, dpsi, dphi

    def _tail_small(self):
        M = self.M
        k = np.abs(self.n) > M // 4
        tail = max(float(np.max(np.abs(self.cF[k]))), float(np.max(np.abs(self.cOm[k]))))
        scale = float(abs(self.cF[0]) + abs(self.cOm[0]))
        return tail <= 1e-15 * scale

    def _periodic(self, c, u):
        """The zero-mean antiderivative of the Fourier series ``c`` at ``u``."""
        n = self.n
        nz = n != 0
        u = np.atleast_1d(np.asarray(u, float))
        return (np.exp(1j * np.outer(u, n[nz])) @ (c[nz] / (1j * n[nz]))).real

    def _t(self, u):
        return self.cF[0].real * (u - self.u0) + self._periodic(self.cF, u) \
            - self._periodic(self.cF, self.u0)

    def _u_of_t(self, t):
        t = np.atleast_1d(np.asarray(t, float))
        u = self.u0 + 2.0 * np.pi * t / self.T
        for _ in range(50):
            F = self._local(u)[4]
            du = (t - self._t(u)) / F
            u = u + du
            if np.max(np.abs(du)) <= 1e-15 * max(1.0, float(np.max(np.abs(u)))):
                break
        return u

    def _psi(self, u):
        return self.psi0 + self.cOm[0].real * (u - self.u0) + self._periodic(self.cOm, u) \
            - self._periodic(self.cOm, self.u0)

    def _phi(self, u):
        return self.phi0 + self.cph[0].real * (u - self.u0) + self._periodic(self.cph, u) \
            - self._periodic(self.cph, self.u0)

    def _Z(self, u, t):
        """Centre C as ``X_C + i Y_C``."""
        if not self.rough:
            return self.Z0 + self.V * t  # smooth ground: V constant (eq. 8, F_x = F_y = 0)
        n, cG, kap = self.n, self.cG, self.kappa
        # psi(u) = psi_c + kappa u + psi_per(u), psi_c fixed by psi(u0) = psi0
        psi_c = self.psi0 - kap * self.u0 - self._periodic(self.cOm, self.u0)[0]
        k = n + kap
        res = np.abs(k) < 1e-12
        u = np.atleast_1d(u)
        ks = np.where(res, 1.0, k)
        E1 = np.exp(1j * np.outer(u, ks))
        E0 = np.exp(1j * ks * self.u0)
        terms = (E1 - E0) * (cG / (1j * ks))
        terms = np.where(res, np.outer(u - self.u0, cG), terms)
        return self.Z0 + np.exp(1j * psi_c) * terms.sum(axis=1)

    def state(self, t):
        scalar = np.ndim(t) == 0
        t = np.atleast_1d(np.asarray(t, float))
        out = np.empty((t.size, 8 if self.rough else 10))
        for i0 in range(0, t.size, 2048):  # bounded memory for the Fourier sums
            tt = t[i0:i0 + 2048]
            u = self._u_of_t(tt)
            theta, w1, w2, w3 = self._local(u)[:4]
            Z = self._Z(u, tt)
            cols = {"X_C": Z.real, "Y_C": Z.imag, "psi": self._psi(u), "theta": theta,
                    "phi": self._phi(u), "omega1": w1, "omega2": w2, "omega3": w3}
            if not self.rough:
                cols["V_X"] = np.full(tt.size, self.V.real)
                cols["V_Y"] = np.full(tt.size, self.V.imag)
            from rollingdisk.model.state import state_names

            for j, name in enumerate(state_names(self.ground)):
                out[i0:i0 + 2048, j] = cols[name]
        return out[0] if scalar else out


class _SteadyOrbit:
    """A steady motion: the state at any time in closed form (eqs. 15, 25)."""

    def __init__(self, rough, h, y0, ground):
        self.rough, self.ground, self.y0 = rough, ground, np.array(y0, float)
        it = state_index(ground, "theta")
        theta0, w2, w3 = y0[it], y0[it + 3], y0[it + 4]
        self.Omega, self.omega = w3 / math.cos(theta0), w2 - w3 * math.tan(theta0)
        if rough:
            ht, s, c, p, y_P, z_P = _geometry(h, theta0)
            self.v = complex(w2 - ht * w3, 0.0)  # eq. (37) with omega1 = 0
        self.fit = None

    def state(self, t):
        scalar = np.ndim(t) == 0
        t = np.atleast_1d(np.asarray(t, float))
        y = np.tile(self.y0, (t.size, 1))
        ip = state_index(self.ground, "psi")
        psi = self.y0[ip] + self.Omega * t
        y[:, ip] = psi
        y[:, ip + 2] = self.y0[ip + 2] + self.omega * t
        if self.rough:
            Z0 = complex(self.y0[0], self.y0[1])
            if abs(self.Omega) > 0.0:
                Z = Z0 + self.v * (np.exp(1j * psi) - np.exp(1j * self.y0[ip])) \
                    / (1j * self.Omega)
            else:
                Z = Z0 + self.v * np.exp(1j * self.y0[ip]) * t
        else:
            Z = complex(self.y0[0], self.y0[1]) + complex(self.y0[2], self.y0[3]) * t
        y[:, 0], y[:, 1] = Z.real, Z.imag
        return y[0] if scalar else y


# ---------------------------------------------------------------------------------------
# time along monotone legs of an orbit that ends
# ---------------------------------------------------------------------------------------
def _leg_time(fit: _Fit, th1: float, th2: float) -> float:
    """Time to go from ``th1`` to ``th2`` (one monotone leg inside ``[a, b]``)."""
    ra, rb = fit.ra, fit.rb
    x1, x2 = sorted((min(1.0, max(-1.0, fit.x(th1))), min(1.0, max(-1.0, fit.x(th2)))))
    if ra and rb:
        def to_w(x):
            return math.asin(x)

        def rate(w):
            return 1.0 / np.sqrt(fit.H(np.sin(w)))
    elif ra:  # x = -cos w, w = 0 at the turning point x = -1
        def to_w(x):
            return math.acos(-x)

        def rate(w):
            return math.sqrt(2.0) * np.cos(0.5 * w) / np.sqrt(fit.H(-np.cos(w)))
    elif rb:  # x = cos w, w = 0 at the turning point x = 1
        def to_w(x):
            return math.acos(x)

        def rate(w):
            return math.sqrt(2.0) * np.cos(0.5 * w) / np.sqrt(fit.H(np.cos(w)))
    else:
        def to_w(x):
            return x

        def rate(w):
            return 1.0 / np.sqrt(fit.H(w))
    w1, w2 = sorted((to_w(x1), to_w(x2)))
    xg, wg = np.polynomial.legendre.leggauss(40)
    edges = np.linspace(w1, w2, 9)
    total = 0.0
    for lo, hi in zip(edges[:-1], edges[1:]):
        ww = 0.5 * (hi - lo) * xg + 0.5 * (hi + lo)
        total += 0.5 * (hi - lo) * float(np.sum(wg * rate(ww)))
    return total


# ---------------------------------------------------------------------------------------
# public API
# ---------------------------------------------------------------------------------------
def exact_motion(disk: Disk, ground: str, y0) -> ExactMotion:
    """The exact motion from the state ``y0``, by quadrature (module docstring).

    Parameters
    ----------
    disk : Disk
    ground : {"rough", "smooth"}
        The ideal grounds of the paper (eqs. 38, 49); the Coulomb ground is not integrable.
    y0 : array_like
        Initial state, layout of :mod:`rollingdisk.model.equations` (8 components on rough,
        10 on smooth ground).

    Returns
    -------
    ExactMotion
        Status, turning points, period, ``delta_psi``, drift, or the end (time, theta).

    Raises
    ------
    ParameterError
        Non-finite state, ``|theta| >= pi/2``, ``theta = 0`` with ``h > 0``, ``F_z < 0``
        at the start (eq. 11), an orbit the quadrature cannot resolve.

    Examples
    --------
    >>> import rollingdisk as rd
    >>> from rollingdisk.theory.exact import exact_steady
    >>> m = rd.steady_motion(rd.Disk(h=0.1), "rough", 0.4, Omega0=3.0)
    >>> ex = exact_steady(m, kick=1e-3)
    >>> ex.status, round(ex.frequency / rd.stability(m).varpi, 6)
    ('bounded', 1.0)
    """
    disk = _check_disk(disk)
    if not isinstance(ground, str) or ground not in ("rough", "smooth"):
        raise ParameterError(f"ground must be 'rough' or 'smooth' for an exact motion "
                             f"(the Coulomb ground is not integrable), got {ground!r}")
    y0 = _as_state(ground, y0)
    if y0.ndim != 1:
        raise ParameterError("y0 must be one state vector")
    if not np.all(np.isfinite(y0)):
        raise ParameterError("y0 must be finite")
    rough = ground == "rough"
    h = disk.h
    it = state_index(ground, "theta")
    theta0, w10, w20, w30 = (float(y0[it]), float(y0[it + 2]), float(y0[it + 3]),
                             float(y0[it + 4]))
    if not abs(theta0) < 0.5 * math.pi:
        raise ParameterError(f"theta must lie in (-pi/2, pi/2), got {theta0!r}")
    if h > 0 and theta0 == 0.0:
        raise ParameterError("theta = 0 is outside the model for h > 0 (the disk stands "
                             "on its rim edge's line); start with theta != 0")
    F_z0 = float(_normal_force(rough, h, y0))
    if F_z0 < 0.0:
        raise ParameterError(f"the normal force F_z (eq. 11) is {F_z0:.6g} < 0 at the "
                             "start: the disk would lift off at once")
    from rollingdisk.model.equations import energy

    E = float(energy(disk, ground, y0))
    side = 1.0 if theta0 > 0 else -1.0
    lo = -_FLAT if (h == 0.0 or side < 0) else _TINY
    hi = _FLAT if (h == 0.0 or side > 0) else -_TINY
    if not lo < theta0 < hi:
        raise ParameterError(f"theta(0) = {theta0!r} is too close to pi/2 or to 0")
    q0 = w10 * w10
    a1, c1, _, _ = _theta_coefficients(rough, h, theta0, w20, w30)
    accel = a1 + c1 * q0  # d omega1/dt at the start
    base = dict(disk=disk, ground=ground, E=E, y0=np.array(y0, float))
    if q0 == 0.0 and abs(accel) <= 1e-14 * (1.0 + w20 * w20 + w30 * w30):
        return _steady_result(base, rough, h, theta0, w20, w30)

    z0 = [w20, w30, q0]
    if q0 == 0.0:  # theta0 is a turning point; the motion starts towards accel's sign
        if accel > 0:
            a, ka, fa = theta0, "turn", None
            b, kb, fb = _sweep(rough, h, theta0, z0, hi)
        else:
            b, kb, fb = theta0, "turn", None
            a, ka, fa = _sweep(rough, h, theta0, z0, lo)
    else:
        b, kb, fb = _sweep(rough, h, theta0, z0, hi)
        a, ka, fa = _sweep(rough, h, theta0, z0, lo)

    def evaluate(theta):
        theta = np.asarray(theta, float)
        out = np.empty((3, theta.size))
        up = theta >= theta0
        if fb is not None and np.any(up):
            out[:, up] = fb(np.clip(theta[up], theta0, b))
        if fa is not None and np.any(~up):
            out[:, ~up] = fa(np.clip(theta[~up], a, theta0))
        if fb is None and np.any(up):
            out[:, up] = fa(np.clip(theta[up], a, theta0))
        if fa is None and np.any(~up):
            out[:, ~up] = fb(np.clip(theta[~up], theta0, b))
        return out

    fit = _Fit(rough, h, a, b, ka == "turn", kb == "turn", evaluate)
    end_kind = {a: _end_kind(h, a, ka), b: _end_kind(h, b, kb)}

    # lift-off: zeros of F_z (eq. 11) on [a, b], the first one along the motion
    xs = np.cos(np.linspace(0.0, np.pi, 4001))[::-1]
    th = fit.m + fit.d * xs
    Fz = _orbit_normal_force(rough, h, th, *fit.functions(th))
    roots = []
    for i in np.nonzero(np.sign(Fz[:-1]) * np.sign(Fz[1:]) < 0)[0]:
        roots.append(_root(lambda s: float(_orbit_normal_force(
            rough, h, np.array(s), *fit.functions(np.array(s)))), th[i], th[i + 1]))
    s = 1.0 if (w10 > 0 or (w10 == 0 and accel > 0)) else -1.0
    near, far = (b, a) if s > 0 else (a, b)
    ahead = [r for r in roots if (r - theta0) * s > 0]
    behind = [r for r in roots if (r - theta0) * s <= 0]
    legs, status, theta_end = None, None, None
    if ahead:
        theta_end = min(ahead, key=lambda r: abs(r - theta0))
        legs, status = [(theta0, theta_end)], "lift-off"
    elif end_kind[near] != "turn":
        legs, status, theta_end = [(theta0, near)], end_kind[near], near
    elif behind:
        theta_end = min(behind, key=lambda r: abs(r - theta0))
        legs, status = [(theta0, near), (near, theta_end)], "lift-off"
    elif end_kind[far] != "turn":
        legs, status, theta_end = [(theta0, near), (near, far)], end_kind[far], far

    if legs is not None:
        t_end = float(sum(_leg_time(fit, p, r) for p, r in legs))
        visited = [0.0 if abs(p) == _TINY else p for leg in legs for p in leg]
        if status == "edge-contact":
            theta_end = 0.0
        elif status == "fell-flat":
            theta_end = math.copysign(0.5 * math.pi, theta_end)
        res = ExactMotion(status=status, theta_min=float(min(visited)),
                          theta_max=float(max(visited)),
                          period=None, delta_psi=None, delta_phi=None, drift=None,
                          t_end=t_end, theta_end=theta_end, _fit=fit, **base)
        return res

    orbit = _Orbit(fit, rough, h, np.array(y0, float), ground)
    # drift of the contact point over the first period (eq. 5)
    from rollingdisk.model.equations import contact_point

    P = contact_point(disk, ground, orbit.state(np.array([0.0, orbit.T])).T)
    drift = (float(P[0][1] - P[0][0]), float(P[1][1] - P[1][0]))
    return ExactMotion(status="bounded", theta_min=float(a), theta_max=float(b),
                       period=float(orbit.T), delta_psi=float(orbit.dpsi),
                       delta_phi=float(orbit.dphi), drift=drift, t_end=None,
                       theta_end=None, _fit=fit, _orbit=orbit, **base)


def _end_kind(h, theta, kind):
    if kind == "turn":
        return "turn"
    return "fell-flat" if abs(theta) > 1.0 else "edge-contact"


def _root(f, lo, hi):
    from scipy.optimize import brentq

    return float(brentq(f, lo, hi, xtol=1e-15, rtol=4 * np.finfo(float).eps))


def _steady_result(base, rough, h, theta0, w20, w30):
    from rollingdisk.theory.oscillations import varpi2_closed_form

    varpi2 = float(varpi2_closed_form(h, base["ground"], theta0, w20, w30))
    period = 2.0 * math.pi / math.sqrt(varpi2) if varpi2 > 0 else None
    orbit = _SteadyOrbit(rough, h, base["y0"], base["ground"])
    dpsi = None if period is None else orbit.Omega * period
    dphi = None if period is None else orbit.omega * period
    drift = None
    if period is not None:
        from rollingdisk.model.equations import contact_point

        P = contact_point(base["disk"], base["ground"], orbit.state(np.array([0.0, period])).T)
        drift = (float(P[0][1] - P[0][0]), float(P[1][1] - P[1][0]))
    return ExactMotion(status="steady", theta_min=theta0, theta_max=theta0, period=period,
                       delta_psi=dpsi, delta_phi=dphi, drift=drift, t_end=None,
                       theta_end=None, _orbit=orbit, **base)


def exact_steady(motion, *, perturb: float = 0.0, kick: float = 0.0, psi0: float = 0.0,
                 phi0: float = 0.0) -> ExactMotion:
    """The exact motion from a steady motion with ``theta(0)`` and/or ``omega1(0)``
    perturbed, exactly as :func:`rollingdisk.simulate_steady` starts it."""
    from rollingdisk.theory.steady import SteadyMotion

    if not isinstance(motion, SteadyMotion):
        raise ParameterTypeError(f"motion must be a SteadyMotion, got {type(motion).__name__}")
    perturb = check_real("perturb", perturb)
    kick = check_real("kick", kick)
    y0 = np.array(motion.initial_state(psi0, phi0), dtype=float)
    y0[state_index(motion.ground, "theta")] += perturb
    y0[state_index(motion.ground, "omega1")] += kick
    return exact_motion(motion.disk, motion.ground, y0)


@dataclass(frozen=True)
class Backbone:
    """Nutation period and frequency against amplitude about one steady motion.

    Attributes
    ----------
    kick : numpy.ndarray
        The ``omega1(0)`` kicks.
    amplitude, theta_min, theta_max, period, frequency : numpy.ndarray
        Per kick (``nan`` where the orbit is not bounded; see ``status``).
    status : tuple of str
    varpi : float
        Linear frequency of eq. (39)/(50) (nan if unstable): the limit of ``frequency``.
    """

    kick: np.ndarray
    amplitude: np.ndarray
    theta_min: np.ndarray
    theta_max: np.ndarray
    period: np.ndarray
    frequency: np.ndarray
    status: tuple
    varpi: float


def backbone(motion, kicks) -> Backbone:
    """Exact nutation period and frequency against amplitude (kicks ``omega1(0)``) about a
    steady motion: the backbone curve, which tends to ``varpi`` (eq. 39) at zero
    amplitude."""
    from rollingdisk.theory.oscillations import stability

    kicks = np.asarray(kicks, dtype=float).ravel()
    if kicks.size == 0 or not np.all(np.isfinite(kicks)):
        raise ParameterError("kicks must be a non-empty array of finite numbers")
    rows = [exact_steady(motion, kick=float(k)) for k in kicks]

    def col(name):
        return np.array([np.nan if getattr(r, name) is None else getattr(r, name)
                         for r in rows], float)

    ok = np.array([r.status == "bounded" for r in rows])
    amp = np.where(ok, [r.amplitude for r in rows], np.nan)
    return Backbone(kick=kicks, amplitude=amp, theta_min=np.where(ok, col("theta_min"), np.nan),
                    theta_max=np.where(ok, col("theta_max"), np.nan),
                    period=col("period"), frequency=np.where(ok, 2 * np.pi / col("period"),
                                                             np.nan),
                    status=tuple(r.status for r in rows),
                    varpi=float(stability(motion).varpi))


def thin_disk_omega3(theta, theta0: float, omega20: float, omega30: float):
    """``(omega2, omega3)(theta)`` of the thin disk (h = 0) on rough ground in closed form.

    With ``h = 0`` eq. (38) gives ``omega2' = -(2/3) omega3`` and
    ``omega3' = -2 omega2 + tan(theta) omega3`` (``' = d/d theta``).  Eliminating
    ``omega3 = -(3/2) omega2'`` and writing ``z = sin theta``::

        (1 - z^2) d^2 omega2/dz^2 - 2 z d omega2/dz - (4/3) omega2 = 0,

    Legendre's equation with ``nu (nu + 1) = -4/3`` (Appell 1900, Korteweg 1899; in this
    form Przybylska & Rauch-Wojciechowski, Regul. Chaotic Dyn. 21 (2016); for h > 0 Batista,
    Int. J. Non-Linear Mech. 41 (2006)).  Its even and odd solutions are
    ``y1 = 2F1(a, b; 1/2; z^2)`` and ``y2 = z 2F1(a + 1/2, b + 1/2; 3/2; z^2)`` with
    ``a + b = 1/2``, ``a b = 1/3``, i.e. ``a, b = 1/4 +- (i/2) sqrt(13/12)``; then
    ``omega2 = A y1 + B y2``, ``omega3 = -(3/2) cos(theta) (A y1' + B y2')`` (``' = d/dz``),
    ``A, B`` from the values at ``theta0``.  Evaluated with ``mpmath.hyp2f1`` (complex
    parameters); an independent check of the quadrature of :func:`exact_motion`
    (derived in ``docs/exact.md``).

    Returns
    -------
    (omega2, omega3) : numpy.ndarray
    """
    import mpmath

    theta = np.atleast_1d(np.asarray(theta, float))
    r = mpmath.sqrt(mpmath.mpf(13) / 12) / 2
    a, b = mpmath.mpf(1) / 4 + 1j * r, mpmath.mpf(1) / 4 - 1j * r

    def ys(th):
        z = mpmath.sin(th)
        z2 = z * z
        y1 = mpmath.hyp2f1(a, b, 0.5, z2)
        y2 = z * mpmath.hyp2f1(a + 0.5, b + 0.5, 1.5, z2)
        d1 = 2 * z * (a * b / 0.5) * mpmath.hyp2f1(a + 1, b + 1, 1.5, z2)
        d2 = (mpmath.hyp2f1(a + 0.5, b + 0.5, 1.5, z2)
              + 2 * z2 * ((a + 0.5) * (b + 0.5) / 1.5) * mpmath.hyp2f1(a + 1.5, b + 1.5,
                                                                      2.5, z2))
        c = mpmath.cos(th)
        return ([float(mpmath.re(y1)), float(mpmath.re(y2))],
                [float(mpmath.re(-1.5 * c * d1)), float(mpmath.re(-1.5 * c * d2))])

    (p1, p2), (q1, q2) = ys(theta0)
    A, B = np.linalg.solve([[p1, p2], [q1, q2]], [omega20, omega30])
    w2 = np.empty(theta.size)
    w3 = np.empty(theta.size)
    for i, th in enumerate(theta):
        (y1, y2), (d1, d2) = ys(float(th))
        w2[i] = A * y1 + B * y2
        w3[i] = A * d1 + B * d2
    return w2, w3

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
   eqs. 1 and 37) are then Fourier series integrated term by term (FFTs and blocked
   sums: memory O(M); M doubles until the tail is at its rounding floor, at most
   ``max_terms``; ``docs/exact.md``, "Edges").  An orbit that ends
   is timed leg by leg with Gauss-Legendre after ``x = -cos w`` / ``x = cos w`` at its
   one turning point.

What ends a motion
------------------
``"bounded"`` (both ends are turning points and ``F_z > 0`` over ``[a, b]``), or the first
along the motion of: ``"lift-off"`` (``F_z`` of eq. 11, a function of ``theta`` on the
orbit, reaches 0), ``"edge-contact"`` (h > 0, ``theta`` reaches 0), ``"fell-flat"``
(``|theta|`` reaches pi/2) -- the guards of :mod:`rollingdisk.model.events`, with the time and
``theta`` where it happens.  A state exactly on a steady motion is ``"steady"``.  A
quadrature that spends its work budget (``time_limit``, ``max_evals``, ``max_terms``)
first is ``"not-converged"``, with a ``message``.

For ``h = 0`` on rough ground ``omega3(theta)`` is a Legendre-type function: see
:func:`thin_disk_omega3` and ``docs/exact.md``.
"""

from __future__ import annotations

import math
import time
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
from rollingdisk.model.outcomes import (
    BOUNDED,
    EDGE_CONTACT,
    FELL_FLAT,
    LIFT_OFF,
    NOT_CONVERGED,
    STEADY,
    names,
)
from rollingdisk.model.state import state_index, state_names
from rollingdisk.util.checks import check_int, check_real
from rollingdisk.util.errors import ParameterError, ParameterTypeError

__all__ = ["ExactMotion", "exact_motion", "exact_steady", "Backbone", "backbone",
           "thin_disk_omega3", "EXACT_STATUSES", "NOT_CONVERGED_STATUS", "TIME_LIMIT",
           "MAX_EVALS", "MAX_TERMS"]

#: The answers :attr:`ExactMotion.status` can give (besides these, ``"not-converged"``:
#: the work budget was spent first, see :data:`NOT_CONVERGED_STATUS`).
EXACT_STATUSES = names(BOUNDED, STEADY, LIFT_OFF, EDGE_CONTACT, FELL_FLAT)
#: The status of a quadrature that spent its work budget before converging.
NOT_CONVERGED_STATUS = names(NOT_CONVERGED)[0]

#: Default work budget of one exact motion: wall-clock seconds, right-hand-side
#: evaluations of the theta-ODE, Fourier terms per period.
TIME_LIMIT, MAX_EVALS, MAX_TERMS = 5.0, 200_000, 1 << 17
#: Most points :func:`thin_disk_omega3` evaluates in one call.
THIN_DISK_MAX_POINTS = 2_000
_RATE_MAX = 1e50  # |omega_i| above this: the quadrature's products (q^2, ...) overflow
_EPS = float(np.finfo(float).eps)
_CHUNK = 1 << 18  # complex numbers per block of a Fourier sum (4 MiB)

_RTOL = 1e-13  # the theta-ODE's tolerance
_FLAT = 0.5 * math.pi - 1e-9  # |theta| where the theta-ODE stops: the disk lies flat
_TINY = 1e-300  # theta "= 0" on the side of the motion (h~ keeps its sign)


# ---------------------------------------------------------------------------------------
# the linear system in theta
# ---------------------------------------------------------------------------------------
def _theta_coefficients(rough: bool, h: float, theta, w2, w3):
    """``(D1 at q=0, dD1/dq, D2, D3)``: eq. (38)/(49) at ``omega1 = 0`` and ``1``.

    ``dD1/dq``, the coefficient of ``omega1^2`` in ``d omega1/dt``, depends on ``theta``
    alone (sympy: ``tests/test_exact_edges.py``), so it is taken at ``omega2 = omega3 = 0``:
    as the difference of the kernel at ``omega1 = 1`` and ``0`` with the orbit's rates it
    lost ``eps (omega2^2 + omega3^2)`` to cancellation, noise that (times ``q``) stalled the
    theta-ODE at rates ~1e5."""
    kernel = _rough_omega_dot if rough else _smooth_omega_dot
    zero, one = 0.0 * theta, 1.0 + 0.0 * theta
    a1 = kernel(h, theta, zero, w2, w3)[0]
    _, b2, b3 = kernel(h, theta, one, w2, w3)
    c1 = kernel(h, theta, one, zero, zero)[0] - kernel(h, theta, zero, zero, zero)[0]
    return a1, c1, b2, b3


class _BudgetSpent(Exception):
    """The work budget of one exact motion is spent (message says which part)."""


class _Budget:
    """Work budget of one exact motion: a wall-clock deadline, a number of right-hand-side
    evaluations of the theta-ODE and a largest Fourier length."""

    def __init__(self, time_limit: float, max_evals: int, max_terms: int):
        self.time_limit, self.max_evals, self.max_terms = time_limit, max_evals, max_terms
        self.deadline = time.monotonic() + time_limit
        self.evals = 0

    def clock(self, where: str) -> None:
        if time.monotonic() > self.deadline:
            raise _BudgetSpent(f"time_limit = {self.time_limit:g} s was spent in {where}")

    def count(self, theta: float) -> None:
        self.evals += 1
        if self.evals > self.max_evals:
            raise _BudgetSpent(f"max_evals = {self.max_evals} evaluations were spent in "
                               f"{self._where(theta)}")
        if self.evals % 64 == 0 and time.monotonic() > self.deadline:
            self.clock(self._where(theta))

    @staticmethod
    def _where(theta: float) -> str:
        return (f"the quadrature in theta (stuck at theta = {theta:.10g}, "
                f"{0.5 * math.pi - abs(theta):.3g} from flat)")


def _theta_rhs(rough: bool, h: float, budget: _Budget | None = None):
    def f(theta, z):
        if budget is not None:
            budget.count(float(theta))
        w2, w3, q = z
        a1, c1, d2, d3 = _theta_coefficients(rough, h, theta, w2, w3)
        return [d2, d3, 2.0 * (a1 + c1 * q)]
    return f


def _q_event(theta0: float):
    """``q``, the event that ends a sweep at a turning point; ``+1`` at ``theta0`` itself,
    so that a start exactly at a turning point (``q = 0``) is not taken for the end when
    the first step already passes the other one (an amplitude below the step)."""
    def event(theta, z):
        return 1.0 if theta == theta0 else z[2]
    event.terminal = True
    event.direction = -1.0
    return event


def _sweep(rough, h, theta0, z0, end, budget):
    """Integrate the theta-ODE from ``theta0`` to ``end``, stopping where ``q`` falls to 0.

    Returns ``(theta_reached, kind, sol)``; ``kind`` is ``"turn"`` or ``"end"``.

    The absolute tolerances sit just below the rounding floor of the right-hand side:
    ``D1`` is a sum of terms of size ``S = 1 + omega2^2 + omega3^2 + q`` that cancel near a
    steady motion, so it carries noise ``~ eps S``; an absolute tolerance of ``1e-30`` (with
    ``q ~ 1e-12`` at an amplitude of 1e-6) made the error estimate see that noise and cut
    the step to 1e-15 in theta, for ever.  With ``atol = 1e-6 eps S`` noise alone limits a
    step to ~1e-6, and the error accumulated over a sweep is the rounding floor itself."""
    from scipy.integrate import solve_ivp

    if theta0 == end:
        return theta0, "end", None
    S = 1.0 + z0[0] * z0[0] + z0[1] * z0[1] + z0[2]
    atol = [1e-6 * _EPS * math.sqrt(S)] * 2 + [1e-6 * _EPS * S]
    sol = solve_ivp(_theta_rhs(rough, h, budget), (theta0, end), z0, method="DOP853",
                    rtol=_RTOL, atol=atol, dense_output=True, events=_q_event(theta0))
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
        ``"fell-flat"`` (see :data:`EXACT_STATUSES`); or ``"not-converged"``: the work
        budget (``time_limit``, ``max_evals``, ``max_terms``) was spent before the
        quadrature reached its rounding floor (``message`` says where; what is known, the
        range of ``theta``, is filled in, the rest is None).
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
    message : str
        Why the quadrature stopped short (``"not-converged"`` only; empty otherwise).
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
    message: str = ""
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
            if self.status == NOT_CONVERGED_STATUS:
                raise ParameterError(f"state(t) needs a bounded or steady motion; this "
                                     f"quadrature is not-converged ({self.message})")
            raise ParameterError(f"state(t) needs a bounded or steady motion; this one "
                                 f"ends ({self.status} at t = {self.t_end:.10g})")
        try:
            t = np.asarray(t, dtype=float)
        except (TypeError, ValueError):
            raise ParameterTypeError(f"t must be a real number or an array of them, got "
                                     f"{type(t).__name__}") from None
        if not np.all(np.isfinite(t)):
            raise ParameterError("t must be finite")
        with np.errstate(all="ignore"):
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
        theta = _real_array("theta", theta)
        if self._fit is None and self.status == NOT_CONVERGED_STATUS:
            raise ParameterError(f"the quadrature is not-converged ({self.message})")
        if self._fit is None:  # steady: constants
            it = state_index(self.ground, "theta")
            w2, w3 = self.y0[it + 3], self.y0[it + 4]
            return w2 + 0.0 * theta, w3 + 0.0 * theta, 0.0 * theta
        fit = self._fit
        slack = 1e-9 * fit.d + 1e-15
        if not np.all((theta >= fit.a - slack) & (theta <= fit.b + slack)):
            raise ParameterError(f"theta must lie in the range of the orbit, "
                                 f"[{fit.a:.12g}, {fit.b:.12g}]")
        with np.errstate(all="ignore"):
            return fit.functions(theta)

    def as_dict(self) -> dict:
        """Plain floats for JSON (None where a value does not exist)."""
        return {"ground": self.ground, "h": self.disk.h, "status": self.status,
                "E": self.E, "theta_min": self.theta_min, "theta_max": self.theta_max,
                "amplitude": self.amplitude, "period": self.period,
                "frequency": self.frequency, "delta_psi": self.delta_psi,
                "delta_phi": self.delta_phi,
                "drift": None if self.drift is None else list(self.drift),
                "t_end": self.t_end, "theta_end": self.theta_end,
                "message": self.message}

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

    def __init__(self, rough, h, a, b, ra, rb, evaluate, S=1.0):
        from numpy.polynomial import chebyshev as C

        self.rough, self.h, self.a, self.b, self.ra, self.rb = rough, h, a, b, ra, rb
        self.m, self.d = 0.5 * (a + b), 0.5 * (b - a)
        # rounding floor of q: D1 carries noise ~ eps S, a step (<= the range) adds it up
        floors = (0.0, 0.0, 16.0 * _EPS * S * self.d)
        prev = None
        for deg in (24, 48, 96, 192, 384):
            x = np.cos(np.pi * (np.arange(deg + 1) + 0.5) / (deg + 1))  # first kind
            z = evaluate(self.m + self.d * x)
            coef = [C.chebfit(x, zi, deg) for zi in z]
            tails = [_tail(c) for c in coef]
            if all(t <= 1e-13 or t * float(np.max(np.abs(c))) <= f
                   for t, c, f in zip(tails, coef, floors)):
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

    def __init__(self, fit, rough, h, y0, ground, budget: _Budget):
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
            budget.clock(f"the Fourier series (length {M})")
            res, floors = self._series(M)
            if prev is not None and self._tail_small(floors) and all(
                    abs(r - p) <= 2.0 * math.pi * 2.0 * (f + g)
                    for r, p, f, g in zip(res, prev[0], floors, prev[1])):
                break
            if 2 * M > budget.max_terms:
                raise _BudgetSpent(
                    f"the Fourier series in u did not reach its rounding floor with "
                    f"max_terms = {budget.max_terms} terms (the orbit passes close to an "
                    f"unstable steady motion: a near-separatrix)")
            prev, M = (res, floors), 2 * M
        self.T, self.dpsi, self.dphi = res

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
        """Fourier coefficients of ``dt/du``, ``dpsi/du``, ``dphi/du`` (and on rough ground
        of the centre's velocity) from ``M`` samples: O(M) memory (FFTs only).

        Returns ``((T, dpsi, dphi), floors)``: the floors are the rounding noise of each
        series' coefficients, propagated from the evaluation errors of the samples (the
        Chebyshev sums, ``1/sqrt(H)`` steep where ``H`` is small) plus the FFT's own."""
        u = 2.0 * np.pi * np.arange(M) / M
        theta, w1, w2, w3, F, Om, ph = self._local(u)
        n = np.fft.fftfreq(M, 1.0 / M)
        self.n = n
        fit = self.fit
        dH = 8.0 * _EPS * float(np.sum(np.abs(fit.cH)))
        d2 = 8.0 * _EPS * float(np.sum(np.abs(fit.c2)))
        d3 = 8.0 * _EPS * float(np.sum(np.abs(fit.c3)))
        c = np.abs(np.cos(theta))
        dF = 0.5 * F ** 3 * dH + _EPS * F
        dOm = d3 / c + _EPS * np.abs(Om)
        dph = d2 + d3 * np.abs(np.tan(theta)) + _EPS * np.abs(ph)
        samples = (F, Om * F, ph * F)
        errors = (dF, np.abs(Om) * dF + dOm * F, np.abs(ph) * dF + dph * F)
        coefs, floors = [], []
        for f, df in zip(samples, errors):
            cf = np.fft.fft(f) / M
            coefs.append(cf)
            floors.append(max(256.0 * _EPS * float(np.max(np.abs(cf))),
                              4.0 * float(np.mean(df))
                              + 8.0 * _EPS * math.log2(M) * float(np.sqrt(np.mean(f * f)))))
        self.cF, self.cOm, self.cph = coefs
        self.floors = floors
        T = 2.0 * np.pi * self.cF[0].real
        dpsi = 2.0 * np.pi * self.cOm[0].real
        dphi = 2.0 * np.pi * self.cph[0].real
        self.kappa = dpsi / (2.0 * np.pi)
        if self.rough:
            ht, s, cc, p, y_P, z_P = _geometry(self.h, theta)
            w = (w2 - ht * w3) * F + 1j * (w1 * z_P) * F  # (v_Cx + i v_Cy) dt/du, eq. (37)
            psi_per = self._periodic_on_grid(self.cOm)
            self.cG = np.fft.fft(w * np.exp(1j * psi_per)) / M
        self.M = M
        return (T, dpsi, dphi), floors

    def _tail_small(self, floors):
        """The coefficients beyond ``M/4`` are at their rounding floor (all three)."""
        k = np.abs(self.n) > self.M // 4
        return all(float(np.max(np.abs(c[k]))) <= f
                   for c, f in zip((self.cF, self.cOm, self.cph), floors))

    def _periodic_on_grid(self, c):
        """The zero-mean antiderivative of the Fourier series ``c`` at the ``M`` grid
        points ``u_j = 2 pi j / M``: one inverse FFT."""
        n = self.n
        nz = n != 0
        b = np.zeros_like(c)
        b[nz] = c[nz] / (1j * n[nz])
        return (np.fft.ifft(b) * n.size).real

    def _periodic(self, c, u):
        """The zero-mean antiderivative of the Fourier series ``c`` at any ``u``: a direct
        sum, in blocks of at most ``_CHUNK`` terms (bounded memory)."""
        n = self.n
        nz = n != 0
        b, k = c[nz] / (1j * n[nz]), n[nz]
        u = np.atleast_1d(np.asarray(u, float))
        out = np.empty(u.size)
        step = max(1, _CHUNK // max(1, k.size))
        for i in range(0, u.size, step):
            out[i:i + step] = (np.exp(1j * np.outer(u[i:i + step], k)) @ b).real
        return out

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
        """Centre C as ``X_C + i Y_C`` (blocks of at most ``_CHUNK`` terms)."""
        if not self.rough:
            return self.Z0 + self.V * t  # smooth ground: V constant (eq. 8, F_x = F_y = 0)
        n, cG, kap = self.n, self.cG, self.kappa
        # psi(u) = psi_c + kappa u + psi_per(u), psi_c fixed by psi(u0) = psi0
        psi_c = self.psi0 - kap * self.u0 - self._periodic(self.cOm, self.u0)[0]
        k = n + kap
        res = np.abs(k) < 1e-12
        u = np.atleast_1d(u)
        ks = np.where(res, 1.0, k)
        E0 = np.exp(1j * ks * self.u0)
        coef = cG / (1j * ks)
        total = np.empty(u.size, complex)
        step = max(1, _CHUNK // max(1, ks.size))
        for i in range(0, u.size, step):
            uu = u[i:i + step]
            terms = (np.exp(1j * np.outer(uu, ks)) - E0) * coef
            terms = np.where(res, np.outer(uu - self.u0, cG), terms)
            total[i:i + step] = terms.sum(axis=1)
        return self.Z0 + np.exp(1j * psi_c) * total

    def state(self, t):
        scalar = np.ndim(t) == 0
        t = np.atleast_1d(np.asarray(t, float))
        out = np.empty((t.size, 8 if self.rough else 10))
        for i0 in range(0, t.size, 2048):
            tt = t[i0:i0 + 2048]
            u = self._u_of_t(tt)
            theta, w1, w2, w3 = self._local(u)[:4]
            Z = self._Z(u, tt)
            cols = {"X_C": Z.real, "Y_C": Z.imag, "psi": self._psi(u), "theta": theta,
                    "phi": self._phi(u), "omega1": w1, "omega2": w2, "omega3": w3}
            if not self.rough:
                cols["V_X"] = np.full(tt.size, self.V.real)
                cols["V_Y"] = np.full(tt.size, self.V.imag)
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
def exact_motion(disk: Disk, ground: str, y0, *, time_limit: float = TIME_LIMIT,
                 max_evals: int = MAX_EVALS, max_terms: int = MAX_TERMS) -> ExactMotion:
    """The exact motion from the state ``y0``, by quadrature (module docstring).

    Parameters
    ----------
    disk : Disk
    ground : {"rough", "smooth"}
        The ideal grounds of the paper (eqs. 38, 49); the Coulomb ground is not integrable.
    y0 : array_like
        Initial state, layout of :mod:`rollingdisk.model.equations` (8 components on rough,
        10 on smooth ground).  Rates ``|omega_i|`` up to ``1e50`` (units ``sqrt(g/a)``).
    time_limit : float, optional
        Wall-clock budget in seconds (> 0), default :data:`TIME_LIMIT` (5 s).
    max_evals : int, optional
        Budget of right-hand-side evaluations of the theta-ODE (>= 100), default
        :data:`MAX_EVALS`.
    max_terms : int, optional
        Largest Fourier length per period (128 to 2^20; memory O(max_terms)), default
        :data:`MAX_TERMS` (2^17).  When the budget is spent first the status is
        ``"not-converged"`` (with a ``message``), never a hang.

    Returns
    -------
    ExactMotion
        Status, turning points, period, ``delta_psi``, drift, or the end (time, theta).

    Raises
    ------
    ParameterError
        Non-finite state, rates beyond ``1e50``, ``|theta| >= pi/2``, ``theta = 0`` with
        ``h > 0``, ``F_z < 0`` at the start (eq. 11), an orbit the quadrature cannot
        resolve, a state whose arithmetic overflows.
    ParameterTypeError
        ``disk`` not a Disk, ``ground`` not a string, ``y0`` not an array of real numbers.

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
    ground = _check_ground(ground)
    y0 = _check_state(ground, y0)
    budget = _Budget(check_real("time_limit", time_limit, low=0.0, low_open=True),
                     check_int("max_evals", max_evals, low=100),
                     check_int("max_terms", max_terms, low=128, high=1 << 20))
    known = {}
    try:
        with np.errstate(over="raise", invalid="raise", divide="raise", under="ignore"):
            return _exact_motion(disk, ground, y0, budget, known)
    except (FloatingPointError, OverflowError) as exc:
        raise ParameterError(f"the state is out of the range the quadrature can follow: "
                             f"its arithmetic overflows ({exc})") from None
    except _BudgetSpent as exc:
        th = float(y0[state_index(ground, "theta")])
        return ExactMotion(status=NOT_CONVERGED_STATUS, theta_min=known.get("a", th),
                           theta_max=known.get("b", th), period=None, delta_psi=None,
                           delta_phi=None, drift=None, t_end=None, theta_end=None,
                           message=str(exc), _fit=known.get("fit"), **known["base"])


def _check_ground(ground) -> str:
    if not isinstance(ground, str):
        raise ParameterTypeError(f"ground must be the string 'rough' or 'smooth', got "
                                 f"{type(ground).__name__} {ground!r}")
    if ground not in ("rough", "smooth"):
        raise ParameterError(f"ground must be 'rough' or 'smooth' for an exact motion "
                             f"(the Coulomb ground is not integrable), got {ground!r}")
    return ground


def _check_state(ground: str, y0) -> np.ndarray:
    """``y0`` as one finite float state with rates in range, or a named error."""
    names_ = state_names(ground)
    y = _real_array("y0", y0)
    if y.shape != (len(names_),):
        raise ParameterError(f"y0 must be one state of {len(names_)} components "
                             f"({', '.join(names_)}) on {ground} ground, got shape {y.shape}")
    if not np.all(np.isfinite(y)):
        raise ParameterError("y0 must be finite (no NaN or infinity)")
    it = state_index(ground, "theta")
    rate = float(np.max(np.abs(y[it + 2:it + 5])))
    if rate > _RATE_MAX:
        raise ParameterError(f"y0 is out of range: rates |omega_i| up to {_RATE_MAX:g} "
                             f"sqrt(g/a) can be followed (beyond, omega^2 and its products "
                             f"overflow), got {rate:g}")
    return y


def _real_array(name: str, value, max_size: int = 1_000_000) -> np.ndarray:
    """``value`` as a float array: ParameterTypeError for anything but real numbers
    (strings, None, booleans, complex), ParameterError for ints beyond the float range."""
    try:
        raw = np.asarray(value)
    except (TypeError, ValueError):  # ragged nesting
        raise ParameterTypeError(f"{name} must be an array of real numbers, got "
                                 f"{type(value).__name__}") from None
    if raw.size > max_size:
        raise ParameterError(f"{name}: at most {max_size} values, got {raw.size}")
    if raw.dtype.kind == "O":
        flat = raw.ravel()
        for v in flat:
            if isinstance(v, bool) or not isinstance(v, (int, float, np.integer,
                                                         np.floating)):
                raise ParameterTypeError(f"{name} must be an array of real numbers, got an "
                                         f"element of type {type(v).__name__}")
        try:
            return np.array([float(v) for v in flat], dtype=float).reshape(raw.shape)
        except OverflowError:
            raise ParameterError(f"{name} must be finite: a value is beyond the "
                                 f"floating-point range (|value| > 1.8e308)") from None
    if raw.dtype.kind in "iuf":
        return raw.astype(float)
    raise ParameterTypeError(f"{name} must be an array of real numbers, got dtype "
                             f"{raw.dtype} ({type(value).__name__})")


def _exact_motion(disk, ground, y0, budget, known):
    rough = ground == "rough"
    h = disk.h
    theta0, w10, w20, w30, lo, hi = _start(disk, ground, y0)
    from rollingdisk.model.equations import energy

    q0 = w10 * w10
    a1, c1, _, _ = _theta_coefficients(rough, h, theta0, w20, w30)
    accel = a1 + c1 * q0  # d omega1/dt at the start
    base = dict(disk=disk, ground=ground, E=float(energy(disk, ground, y0)),
                y0=np.array(y0, float))
    known["base"] = base
    if q0 == 0.0 and abs(accel) <= 1e-14 * (1.0 + w20 * w20 + w30 * w30):
        return _steady_result(base, rough, h, theta0, w20, w30)
    (a, ka, fa), (b, kb, fb) = _turning_sweeps(rough, h, theta0, [w20, w30, q0], accel,
                                               lo, hi, budget)
    known.update(a=float(a), b=float(b))

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

    fit = _Fit(rough, h, a, b, ka == "turn", kb == "turn", evaluate,
               S=1.0 + w20 * w20 + w30 * w30 + q0)
    known["fit"] = fit
    budget.clock("the Chebyshev fit")
    s = 1.0 if (w10 > 0 or (w10 == 0 and accel > 0)) else -1.0
    ended = _open_end(fit, rough, h, theta0, s, {a: _end_kind(h, a, ka),
                                                  b: _end_kind(h, b, kb)}, a, b, base)
    if ended is not None:
        return ended
    orbit = _Orbit(fit, rough, h, np.array(y0, float), ground, budget)
    # drift of the contact point over the first period (eq. 5)
    from rollingdisk.model.equations import contact_point

    P = contact_point(disk, ground, orbit.state(np.array([0.0, orbit.T])).T)
    drift = (float(P[0][1] - P[0][0]), float(P[1][1] - P[1][0]))
    return ExactMotion(status="bounded", theta_min=float(a), theta_max=float(b),
                       period=float(orbit.T), delta_psi=float(orbit.dpsi),
                       delta_phi=float(orbit.dphi), drift=drift, t_end=None,
                       theta_end=None, _fit=fit, _orbit=orbit, **base)


def _start(disk, ground, y0):
    """``(theta0, omega1, omega2, omega3, lo, hi)`` of a start the model admits (``lo, hi``:
    the theta range an orbit may sweep), or ParameterError saying why not."""
    h = disk.h
    it = state_index(ground, "theta")
    theta0, w10, w20, w30 = (float(y0[it]), float(y0[it + 2]), float(y0[it + 3]),
                             float(y0[it + 4]))
    if not abs(theta0) < 0.5 * math.pi:
        raise ParameterError(f"theta must lie in (-pi/2, pi/2), got {theta0!r}")
    if h > 0 and theta0 == 0.0:
        raise ParameterError("theta = 0 is outside the model for h > 0 (the disk stands "
                             "on its rim edge's line); start with theta != 0")
    F_z0 = float(_normal_force(ground == "rough", h, y0))
    if F_z0 < 0.0:
        raise ParameterError(f"the normal force F_z (eq. 11) is {F_z0:.6g} < 0 at the "
                             "start: the disk would lift off at once")
    side = 1.0 if theta0 > 0 else -1.0
    lo = -_FLAT if (h == 0.0 or side < 0) else _TINY
    hi = _FLAT if (h == 0.0 or side > 0) else -_TINY
    if not lo < theta0 < hi:
        raise ParameterError(f"theta(0) = {theta0!r} is too close to pi/2 or to 0")
    return theta0, w10, w20, w30, lo, hi


def _turning_sweeps(rough, h, theta0, z0, accel, lo, hi, budget):
    """The sweeps from theta0 down and up to the turning points (or the range's ends):
    ``((a, kind, f), (b, kind, f))``; a start at a turning point sweeps one way only."""
    if z0[2] == 0.0:  # theta0 is a turning point; the motion starts towards accel's sign
        if accel > 0:
            return (theta0, "turn", None), _sweep(rough, h, theta0, z0, hi, budget)
        return _sweep(rough, h, theta0, z0, lo, budget), (theta0, "turn", None)
    return _sweep(rough, h, theta0, z0, lo, budget), _sweep(rough, h, theta0, z0, hi, budget)


def _open_end(fit, rough, h, theta0, s, end_kind, a, b, base):
    """The ExactMotion of an orbit that ends (lift-off: the first zero of F_z, eq. 11, along
    the motion; or an end of the range: edge contact, fell flat), or None if it is bounded.
    ``s``: the sign of the motion's start."""
    xs = np.cos(np.linspace(0.0, np.pi, 4001))[::-1]
    th = fit.m + fit.d * xs
    Fz = _orbit_normal_force(rough, h, th, *fit.functions(th))
    roots = [_root(lambda x: float(_orbit_normal_force(
        rough, h, np.array(x), *fit.functions(np.array(x)))), th[i], th[i + 1])
        for i in np.nonzero(np.sign(Fz[:-1]) * np.sign(Fz[1:]) < 0)[0]]
    near, far = (b, a) if s > 0 else (a, b)
    ahead = [r for r in roots if (r - theta0) * s > 0]
    behind = [r for r in roots if (r - theta0) * s <= 0]
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
    else:
        return None
    t_end = float(sum(_leg_time(fit, p, r) for p, r in legs))
    visited = [0.0 if abs(p) == _TINY else p for leg in legs for p in leg]
    if status == "edge-contact":
        theta_end = 0.0
    elif status == "fell-flat":
        theta_end = math.copysign(0.5 * math.pi, theta_end)
    return ExactMotion(status=status, theta_min=float(min(visited)),
                       theta_max=float(max(visited)), period=None, delta_psi=None,
                       delta_phi=None, drift=None, t_end=t_end, theta_end=theta_end,
                       _fit=fit, **base)


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
                 phi0: float = 0.0, **budget) -> ExactMotion:
    """The exact motion from a steady motion with ``theta(0)`` and/or ``omega1(0)``
    perturbed, exactly as :func:`rollingdisk.simulate_steady` starts it.

    ``perturb`` (rad) and ``kick`` (``sqrt(g/a)``) are added to ``theta(0)`` and
    ``omega1(0)``; ``psi0``, ``phi0`` (rad) start the angles; ``budget`` is
    ``time_limit``, ``max_evals``, ``max_terms`` of :func:`exact_motion`."""
    from rollingdisk.theory.steady import SteadyMotion

    if not isinstance(motion, SteadyMotion):
        raise ParameterTypeError(f"motion must be a SteadyMotion, got {type(motion).__name__}")
    _check_budget_keys(budget)
    perturb = check_real("perturb", perturb)
    kick = check_real("kick", kick)
    psi0 = check_real("psi0", psi0)
    phi0 = check_real("phi0", phi0)
    with np.errstate(all="ignore"):
        y0 = np.array(motion.initial_state(psi0, phi0), dtype=float)
        y0[state_index(motion.ground, "theta")] += perturb
        y0[state_index(motion.ground, "omega1")] += kick
    return exact_motion(motion.disk, motion.ground, y0, **budget)


def _check_budget_keys(budget: dict) -> None:
    extra = set(budget) - {"time_limit", "max_evals", "max_terms"}
    if extra:
        raise ParameterTypeError(f"unexpected keyword argument(s) {', '.join(sorted(extra))}"
                                 f"; the budget is time_limit, max_evals, max_terms")


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


def backbone(motion, kicks, **budget) -> Backbone:
    """Exact nutation period and frequency against amplitude (kicks ``omega1(0)``) about a
    steady motion: the backbone curve, which tends to ``varpi`` (eq. 39) at zero
    amplitude.  ``budget`` (``time_limit``, ``max_evals``, ``max_terms``) applies to each
    kick's exact motion; a kick whose quadrature is not-converged gets NaN."""
    from rollingdisk.theory.oscillations import stability
    from rollingdisk.theory.steady import SteadyMotion

    if not isinstance(motion, SteadyMotion):
        raise ParameterTypeError(f"motion must be a SteadyMotion, got {type(motion).__name__}")
    _check_budget_keys(budget)
    kicks = _real_array("kicks", kicks, max_size=10_000).ravel()
    if kicks.size == 0 or not np.all(np.isfinite(kicks)):
        raise ParameterError("kicks must be a non-empty array of finite numbers")
    rows = [exact_steady(motion, kick=float(k), **budget) for k in kicks]

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

    Parameters
    ----------
    theta : float or array_like
        Tilt(s) in rad, finite, ``|theta| < pi/2``; at most :data:`THIN_DISK_MAX_POINTS`
        values (each costs four hypergeometric sums in mpmath, ~30 ms).
    theta0, omega20, omega30 : float
        The point of the orbit that fixes ``A, B``: ``|theta0| < pi/2`` (rad) and the rates
        there (``sqrt(g/a)``), finite.

    Returns
    -------
    (omega2, omega3) : numpy.ndarray
        One-dimensional, one value per ``theta``.

    Raises
    ------
    ParameterTypeError, ParameterError
        Non-numbers; non-finite values, ``|theta| >= pi/2``, too many points.
    """
    import mpmath

    half = 0.5 * math.pi
    theta0 = check_real("theta0", theta0, low=-half, high=half, low_open=True, high_open=True)
    omega20 = check_real("omega20", omega20)
    omega30 = check_real("omega30", omega30)
    theta = np.atleast_1d(_real_array("theta", theta, max_size=THIN_DISK_MAX_POINTS)).ravel()
    if not np.all(np.isfinite(theta)) or np.any(np.abs(theta) >= half):
        raise ParameterError("theta must be finite and lie in (-pi/2, pi/2) (the closed "
                             "form has a logarithmic singularity at |theta| = pi/2)")
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
    with np.errstate(all="ignore"):
        A, B = np.linalg.solve([[p1, p2], [q1, q2]], [omega20, omega30])
    w2 = np.full(theta.size, np.nan)
    w3 = np.full(theta.size, np.nan)
    for i, th in enumerate(theta if math.isfinite(A) and math.isfinite(B) else ()):
        (y1, y2), (d1, d2) = ys(float(th))
        with np.errstate(all="ignore"):
            w2[i] = A * y1 + B * y2
            w3[i] = A * d1 + B * d2
    if not (np.all(np.isfinite(w2)) and np.all(np.isfinite(w3))):
        raise ParameterError("the closed form overflows at these values (theta or theta0 "
                             "too close to pi/2, or omega20, omega30 too large)")
    return w2, w3

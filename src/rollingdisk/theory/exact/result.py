"""What an exact motion is: :class:`ExactMotion`, its statuses, its state at any time and
its functions of ``theta`` along the orbit.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from rollingdisk.model.disk import Disk
from rollingdisk.model.outcomes import (
    BOUNDED,
    EDGE_CONTACT,
    FELL_FLAT,
    LIFT_OFF,
    NOT_CONVERGED,
    STEADY,
    names,
)
from rollingdisk.model.state import state_index
from rollingdisk.theory.exact.inputs import _real_array
from rollingdisk.theory.exact.orbit import _orbit_normal_force
from rollingdisk.util.errors import ParameterError, ParameterTypeError

__all__ = ["ExactMotion", "EXACT_STATUSES", "NOT_CONVERGED_STATUS"]

#: The answers :attr:`ExactMotion.status` can give (besides these, ``"not-converged"``:
#: the work budget was spent first, see :data:`NOT_CONVERGED_STATUS`).
EXACT_STATUSES = names(BOUNDED, STEADY, LIFT_OFF, EDGE_CONTACT, FELL_FLAT)
#: The status of a quadrature that spent its work budget before converging.
NOT_CONVERGED_STATUS = names(NOT_CONVERGED)[0]


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

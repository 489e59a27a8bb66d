"""What one run of Euler's disk returns (:class:`EulerDiskResult`): the observables along
the run, the energy balance, the fitted and predicted exponents, and the run as a summary,
CSV columns, an ``xarray.Dataset`` or a ``pandas.DataFrame``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from rollingdisk.scenarios.euler_toy import EulerDisk

__all__ = ["EulerDiskResult"]

#: Variables of :meth:`EulerDiskResult.to_xarray`: name -> (kind, long name).
EULER_VARIABLES = {
    "t": ("time", "time"),
    "alpha": ("angle", "tilt alpha = pi/2 - |theta|"),
    "Omega": ("angular_speed", "precession rate d psi/dt = omega3 / cos(theta) (eq. 2)"),
    "contact_speed": ("speed", "speed of the contact point along the plane (eq. 5)"),
    "slip_speed": ("speed", "slip speed |u| of the contact point (eq. 6)"),
    "F_z": ("force", "normal force F_z (eq. 11)"),
    "E": ("energy", "mechanical energy (eq. 13)"),
}


@dataclass(frozen=True)
class EulerDiskResult:
    """One run of :func:`run_euler_disk`.  Dimensionless units unless named ``_s``.

    Attributes
    ----------
    toy : EulerDisk
    t : ndarray
        Times (every accepted step), units ``sqrt(a/g)``.
    alpha : ndarray
        Tilt ``alpha = pi/2 - |theta|`` [rad].
    Omega : ndarray
        Precession rate ``d psi/dt = omega3 / cos(theta)`` (eq. 2), ``> 0``.
    contact_speed : ndarray
        Speed of the contact point along the plane, ``|(v_Cx - y_P Omega, v_Cy - z_P
        omega1)|`` (time derivative of eq. 5).
    slip_speed : ndarray
        ``|u|`` (eq. 6).
    F_z : ndarray
        Normal force (eq. 11), units ``m g``.
    E : ndarray
        Mechanical energy (eq. 13), units ``m g a``.
    dissipated : dict of str to ndarray
        Energy dissipated so far by ``"slip"``, ``"rolling_resistance"``, ``"air"``.
    t_end : float
        Time of the end (or where the run stopped).
    end : str or None
        One of :data:`END_KINDS`, ``None`` if the run stopped without reaching an end.
    status : {"completed", "failed"}
    message : str
    t0 : float
        Singular time fitted with the ``alpha`` exponent (``alpha -> 0``); ``nan`` if
        the window was not reached.
    exponents, predicted : dict of str to float
        Fitted (simulation) and predicted (steady family) exponents of ``alpha``,
        ``Omega``, ``contact_speed`` against ``t0 - t``.
    fit_window : (float, float)
        The ``alpha`` range of the fits.
    predicted_t_end, predicted_t0 : float
        The same end and ``t0`` by the adiabatic decay along the steady family
        (:func:`predicted_end_time`); ``nan`` when not predicted.
    energy_balance : float
        ``max |E + dissipated - E(0)| / max(|E(0)|, 1)`` (eq. 12).
    n_steps : int
    wall_time : float
        Seconds of wall clock.
    """

    toy: EulerDisk
    t: np.ndarray
    alpha: np.ndarray
    Omega: np.ndarray
    contact_speed: np.ndarray
    slip_speed: np.ndarray
    F_z: np.ndarray
    E: np.ndarray
    dissipated: dict
    t_end: float
    end: str | None
    status: str
    message: str
    t0: float
    exponents: dict
    predicted: dict
    fit_window: tuple
    predicted_t_end: float
    predicted_t0: float
    energy_balance: float
    n_steps: int
    wall_time: float
    extra: dict = field(default_factory=dict, repr=False)

    @property
    def t_end_s(self) -> float:
        """End time in seconds."""
        return self.t_end * self.toy.time_unit

    @property
    def t0_s(self) -> float:
        """Fitted singular time in seconds."""
        return self.t0 * self.toy.time_unit

    def summary(self) -> dict:
        """JSON-ready summary (no arrays)."""
        def fin(x):
            return float(x) if math.isfinite(x) else None

        return {"status": self.status, "end": self.end, "message": self.message,
                "t_end": fin(self.t_end), "t_end_s": fin(self.t_end_s), "t0": fin(self.t0),
                "t0_s": fin(self.t0_s),
                "alpha_end": fin(float(self.alpha[-1])),
                "Omega_end": fin(float(self.Omega[-1])),
                "predicted_t_end_s": fin(self.predicted_t_end * self.toy.time_unit),
                "predicted_t0_s": fin(self.predicted_t0 * self.toy.time_unit),
                "exponents": {k: fin(v) for k, v in self.exponents.items()},
                "predicted": {k: fin(v) for k, v in self.predicted.items()},
                "fit_window_alpha": list(self.fit_window),
                "energy_balance": fin(self.energy_balance),
                "dissipated": {k: float(v[-1]) for k, v in self.dissipated.items()},
                "n_steps": self.n_steps, "wall_time_s": self.wall_time,
                "n_transitions": (len(self.extra["transitions"])
                                  if "transitions" in self.extra else None),
                "parameters": self.toy.as_dict()}

    def as_columns(self, max_rows: int = 4000) -> dict:
        """Columns for a CSV, thinned to at most about ``max_rows`` rows: half evenly in
        ``t``, half evenly in ``log(t_end - t)`` (the log-log plot), plus the end."""
        n = self.t.size
        if n <= max_rows:
            idx = np.arange(n)
        else:
            lin = np.linspace(0.0, self.t[-1], max_rows // 2)
            gap = self.t[-1] - self.t[:-1]
            lo = max(float(gap[gap > 0].min()) if np.any(gap > 0) else 1e-9, 1e-12)
            log = self.t[-1] - np.geomspace(self.t[-1], lo, max_rows // 2)
            idx = np.unique(np.concatenate([np.searchsorted(self.t, lin),
                                            np.searchsorted(self.t, log), [n - 1]]))
            idx = idx[idx < n]
        cols = {"t": self.t, "t_s": self.t * self.toy.time_unit, "alpha": self.alpha,
                "Omega": self.Omega, "contact_speed": self.contact_speed,
                "slip_speed": self.slip_speed, "F_z": self.F_z, "E": self.E,
                **{f"dissipated_{k}": v for k, v in self.dissipated.items()}}
        return {k: np.asarray(v)[idx] for k, v in cols.items()}

    # -- data out and notebooks ------------------------------------------------------
    def _columns(self) -> dict:
        return {"t": self.t, "alpha": self.alpha, "Omega": self.Omega,
                "contact_speed": self.contact_speed, "slip_speed": self.slip_speed,
                "F_z": self.F_z, "E": self.E,
                **{f"dissipated_{k}": v for k, v in self.dissipated.items()}}

    def _attrs(self) -> dict:
        return {"status": self.status, "end": self.end, "message": self.message,
                "mu": self.toy.mu, "creep": self.toy.creep,
                "rolling_resistance": self.toy.rolling_resistance,
                "air_viscosity_si": self.toy.air_viscosity, "air_law": self.toy.air_law,
                "alpha0": self.toy.alpha0}

    def to_xarray(self, si: bool | None = None):
        """The run as an ``xarray.Dataset`` along ``t`` (every accepted step), ``units``
        and ``long_name`` on every variable, in SI by default (the toy has a scale;
        ``si=False``: the paper's units, named); the toy's parameters in ``attrs``."""
        from rollingdisk.results.dataout import to_xarray

        return to_xarray(self._columns(), self.toy.disk, si=si, table=EULER_VARIABLES,
                         attrs=self._attrs())

    def to_dataframe(self, si: bool | None = None):
        """The run as a ``pandas.DataFrame``, units and long names in ``df.attrs``; as
        :meth:`to_xarray`."""
        from rollingdisk.results.dataout import to_dataframe

        return to_dataframe(self._columns(), self.toy.disk, si=si, table=EULER_VARIABLES,
                            attrs=self._attrs())

    def __repr__(self) -> str:
        from rollingdisk.util.display import short_repr

        return short_repr("EulerDiskResult", {
            "status": self.status, "end": self.end, "t_end": self.t_end,
            "t_end_s": self.t_end_s, "points": int(self.t.size),
            "exponents": self.exponents, "energy_balance": self.energy_balance,
            "n_steps": self.n_steps})

    def _repr_html_(self) -> str:
        from rollingdisk.model.units import result_html

        values = {"status": self.status, "end": self.end, "t_end": self.t_end,
                  "t0": self.t0, "predicted_t_end": self.predicted_t_end,
                  "alpha_end": float(self.alpha[-1]), "Omega_end": float(self.Omega[-1]),
                  **{f"exponent_{k}": v for k, v in self.exponents.items()},
                  **{f"predicted_exponent_{k}": v for k, v in self.predicted.items()},
                  "energy_balance": self.energy_balance, "n_steps": self.n_steps}
        kinds = {"t_end": "time", "t0": "time", "predicted_t_end": "time",
                 "alpha_end": "angle", "Omega_end": "angular_speed",
                 "energy_balance": "dimensionless"}
        return result_html("Euler's disk run to its end", self.toy.disk, values, kinds,
                           note=self.message)

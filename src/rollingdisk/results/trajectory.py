"""The result of a simulation: :class:`Trajectory`, a frozen record of a motion.

Kept apart from the integrators (:mod:`rollingdisk.ivp.simulation`) and the measurements
(:mod:`rollingdisk.results.measure`): a trajectory is data (times, states, how the run ended) plus
the quantities derived from the states by :mod:`rollingdisk.model.equations` (contact point,
contact force, energy).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from functools import cached_property

import numpy as np

from rollingdisk.model.disk import Disk
from rollingdisk.model.equations import contact_force, contact_point, energy
from rollingdisk.model.state import state_index
from rollingdisk.util.checks import real_array

__all__ = ["Trajectory", "Transition"]


@dataclass(frozen=True)
class Transition:
    """A change of mode on Coulomb ground at time ``t``: ``from_mode -> to_mode``
    (names of :data:`rollingdisk.model.coulomb.MODE_NAMES`: ``"rolling"``, ``"sliding"``,
    ``"rolling, pivot stuck"``, ``"sliding, pivot stuck"``, and the same four with
    ``", roll stuck"``)."""

    t: float
    from_mode: str
    to_mode: str

    def as_dict(self) -> dict:
        """``{"t": t, "from": from_mode, "to": to_mode}``."""
        return {"t": self.t, "from": self.from_mode, "to": self.to_mode}


def _layout(ground) -> str:
    """The state layout of ``ground``: Coulomb ground uses the smooth one."""
    return ground if isinstance(ground, str) else "smooth"


@dataclass(frozen=True, eq=False)
class Trajectory:
    """A simulated motion of the disk (dimensionless units, m = a = g = 1).

    Attributes
    ----------
    disk : Disk
        The disk simulated.
    ground : {"rough", "smooth"} or Coulomb
        The ground: an ideal one by name, or the :class:`~rollingdisk.Coulomb` value of a
        run of :func:`~rollingdisk.simulate_coulomb` (a ``CoulombTrajectory``).
    t : ndarray, shape (n,)
        Times (time unit ``sqrt(a/g)``).  The last one is the event time if a guard fired.
    y : ndarray, shape (n_state, n)
        States, laid out as in :data:`rollingdisk.model.state.ROUGH_STATE` /
        :data:`~rollingdisk.model.state.SMOOTH_STATE`.
    status : str
        ``"completed"`` (reached the end of ``t_span``, or stopped by a terminal user
        event), ``"lift-off"`` (``F_z`` reached 0, eq. 11), ``"edge-contact"`` (``theta``
        reached 0 with ``h > 0``), ``"fell-flat"`` (``|theta|`` reached ``pi/2``),
        ``"step-budget"`` (``max_steps`` steps taken before the end), ``"time-budget"``
        (Coulomb ground: ``max_wall_time`` seconds spent before the end) or ``"failed"``
        (the integrator gave up; see ``message``).  See :mod:`rollingdisk.model.events`.
    message : str
        What happened, in words.
    n_steps, n_rhs : int
        Accepted integration steps and right-hand-side evaluations.
    method : str
        ``"dop853"`` (rollingdisk's DOP853, compiled or not), ``"taylor"``,
        ``"dop853+taylor"`` (``method="auto"`` switched when the compiled code was loaded)
        or ``"scipy"``.
    t_event : float or None
        Time of the guard event, if one fired.
    wall_time : float
        Seconds spent integrating (not counting compilation or post-processing).
    theta_ref : float or None
        The steady inclination ``theta0`` when started from a steady motion.
    motion : object or None
        The :class:`~rollingdisk.theory.steady.SteadyMotion` it was started from, if any.
    t_events, y_events : tuple
        For user events: per event, the times and states where it occurred.
    sol : callable or None
        With ``simulate(..., dense_output=True)``: ``sol(t)``, the DOP853 interpolant of
        the whole run (as ``solve_ivp``'s ``sol``), for ``t`` within ``[t[0], t[-1]]``.
    mode : ndarray of int8 or None
        Coulomb ground only: the mode at each stored point, codes
        :data:`rollingdisk.model.coulomb.MODE_NAMES` (0 rolling, 1 sliding, 2, 3
        the same with the pivot stuck, 4-7 the first four with the rolling resistance
        stuck); ``None`` for
        single-mode runs (rough, smooth).
    transitions : tuple of Transition
        Coulomb ground only: the mode changes ``(t, from_mode, to_mode)``, in time order.
    dissipated : dict or None
        Coulomb ground only: energy dissipated so far by each term at each stored point,
        ``{"slip", "rolling_resistance", "pivot", "air"}`` -> arrays (units ``m g a``);
        ``E + sum(dissipated) = const`` (eq. 12).
    """

    disk: Disk
    ground: object  # "rough" | "smooth" | Coulomb (friction layer, above this one)
    t: np.ndarray
    y: np.ndarray
    status: str
    message: str
    n_steps: int
    n_rhs: int
    method: str = "dop853"
    t_event: float | None = None
    wall_time: float = math.nan
    theta_ref: float | None = None
    motion: object = None
    t_events: tuple = field(default=())
    y_events: tuple = field(default=())
    sol: object = None
    mode: np.ndarray | None = None
    transitions: tuple = field(default=())
    dissipated: dict | None = None

    def __post_init__(self):
        for name in ("t", "y"):
            a = np.array(real_array(name, getattr(self, name)))
            a.setflags(write=False)
            object.__setattr__(self, name, a)
        if self.mode is not None:
            a = np.array(self.mode, dtype=np.int8)
            a.setflags(write=False)
            object.__setattr__(self, "mode", a)

    def __repr__(self) -> str:
        return (f"{type(self).__name__}(ground={self.ground!r}, h={self.disk.h:g}, "
                f"t=[{self.t[0]:g}, {self.t[-1]:g}], n={self.t.size}, status={self.status!r}, "
                f"n_steps={self.n_steps})")

    @property
    def success(self) -> bool:
        """True unless the integrator failed or ran out of steps or time (guard events count
        as success)."""
        return self.status not in ("failed", "step-budget", "time-budget")

    def component(self, name: str) -> np.ndarray:
        """The state component ``name`` (e.g. ``"theta"``) along the trajectory."""
        return self.y[state_index(_layout(self.ground), name)]

    # state components, named as in the paper
    X_C = property(lambda self: self.component("X_C"), doc="X_C, centre C in OXYZ.")
    Y_C = property(lambda self: self.component("Y_C"), doc="Y_C, centre C in OXYZ.")
    psi = property(lambda self: self.component("psi"), doc="Spin angle psi.")
    theta = property(lambda self: self.component("theta"), doc="Inclination theta.")
    phi = property(lambda self: self.component("phi"), doc="Rotation angle phi.")
    omega1 = property(lambda self: self.component("omega1"), doc="omega1 (eq. 2).")
    omega2 = property(lambda self: self.component("omega2"), doc="omega2 (eq. 3).")
    omega3 = property(lambda self: self.component("omega3"), doc="omega3 (eq. 3).")

    @property
    def V_X(self) -> np.ndarray:
        """V_X, inertial velocity of C (smooth ground only; constant there)."""
        return self.component("V_X")

    @property
    def V_Y(self) -> np.ndarray:
        """V_Y, inertial velocity of C (smooth ground only; constant there)."""
        return self.component("V_Y")

    @cached_property
    def _P(self):
        return contact_point(self.disk, _layout(self.ground), self.y)

    @cached_property
    def _F(self):
        # ideal grounds; a Coulomb run is a rollingdisk.ivp.coulomb_driver.CoulombTrajectory,
        # which takes each point's force from its mode
        return contact_force(self.disk, self.ground, self.y)

    @property
    def X_P(self) -> np.ndarray:
        """X_P, contact point on the plane (eq. 5)."""
        return np.asarray(self._P[0])

    @property
    def Y_P(self) -> np.ndarray:
        """Y_P, contact point on the plane (eq. 5)."""
        return np.asarray(self._P[1])

    @property
    def F_x(self) -> np.ndarray:
        """F_x, contact force in Cxyz, units of m g (eq. 8)."""
        return np.asarray(self._F[0])

    @property
    def F_y(self) -> np.ndarray:
        """F_y, contact force in Cxyz, units of m g (eq. 8)."""
        return np.asarray(self._F[1])

    @property
    def F_z(self) -> np.ndarray:
        """F_z, normal force, units of m g (eq. 11)."""
        return np.asarray(self._F[2])

    @cached_property
    def E(self) -> np.ndarray:
        """Total mechanical energy, units of m g a (eq. 13)."""
        return np.asarray(energy(self.disk, _layout(self.ground), self.y))

    def as_columns(self, si: bool = False) -> dict[str, np.ndarray]:
        """Columns ``t, X_C, Y_C, psi, theta, phi, omega1, omega2, omega3, X_P, Y_P, F_x,
        F_y, F_z, E`` (the CSV layout of ``rollingdisk simulate --out``), and on smooth
        ground ``V_X, V_Y`` after them, so that a smooth run can be restarted from a row.

        ``si=True``: in SI units where the disk's scale allows (:meth:`column_units`)."""
        if si:
            from rollingdisk.results.dataout import convert_columns

            return convert_columns(self.as_columns(), self.disk, True)
        cols = {"t": self.t, "X_C": self.X_C, "Y_C": self.Y_C, "psi": self.psi,
                "theta": self.theta, "phi": self.phi, "omega1": self.omega1,
                "omega2": self.omega2, "omega3": self.omega3, "X_P": self.X_P,
                "Y_P": self.Y_P, "F_x": self.F_x, "F_y": self.F_y, "F_z": self.F_z,
                "E": self.E}
        if _layout(self.ground) == "smooth":
            cols.update(V_X=self.V_X, V_Y=self.V_Y)
        if self.mode is not None:
            cols["mode"] = self.mode
        return cols

    # -- data out (rollingdisk.results.dataout) and notebooks -------------------------
    def _data_columns(self) -> dict[str, np.ndarray]:
        cols = self.as_columns()
        for k, v in (self.dissipated or {}).items():
            cols[f"dissipated_{k}"] = np.asarray(v)
        return cols

    def _data_attrs(self) -> dict:
        g = self.ground
        attrs = {"ground": g if isinstance(g, str) else getattr(g, "name", type(g).__name__),
                 "status": self.status, "message": self.message, "method": self.method,
                 "n_steps": int(self.n_steps)}
        if not isinstance(g, str) and hasattr(g, "as_dict"):
            attrs.update({f"ground_{k}": v for k, v in g.as_dict().items()
                          if k != "ground" and v is not None})
        return attrs

    def column_units(self, si: bool | None = False) -> dict[str, str]:
        """Column name -> unit of :meth:`as_columns` (``si=False``: the paper's units,
        ``"sqrt(a/g)"``, ``"a"``, ...; ``si=True``: SI where the disk's scale allows)."""
        from rollingdisk.results.dataout import column_units

        return column_units(self.as_columns(), self.disk, si)

    def csv_header(self, si: bool = False) -> str:
        """The CSV header of :meth:`as_columns` with units, ``t [sqrt(a/g)],X_C [a],...``
        (``si=True``: ``t [s],X_C [m],...``, for the values of ``as_columns(si=True)``)."""
        from rollingdisk.results.dataout import csv_header

        return csv_header(self.as_columns(), self.disk, si)

    def to_xarray(self, si: bool | None = None):
        """The run as an ``xarray.Dataset`` along ``t``: every column of :meth:`as_columns`
        (and the dissipated energies of a Coulomb run), ``units`` and ``long_name`` on
        each; SI when the disk has a physical scale (``si=None``), else the paper's units,
        named.  The disk, ground and how the run ended are in ``attrs``.

        Examples
        --------
        >>> import rollingdisk as rd
        >>> m = rd.steady_motion(rd.Disk.from_dimensions(0.0375, 0.0127, 0.45), "rough",
        ...                      0.5, Omega0=2.0)
        >>> ds = rd.simulate_steady(m, 1.0).to_xarray()
        >>> ds.theta.attrs["units"], ds.t.attrs["units"], ds.F_z.attrs["units"]
        ('rad', 's', 'N')
        """
        from rollingdisk.results.dataout import to_xarray

        return to_xarray(self._data_columns(), self.disk, si=si, attrs=self._data_attrs())

    def to_dataframe(self, si: bool | None = None):
        """The run as a ``pandas.DataFrame`` (one row per stored point), units and long
        names in ``df.attrs["units"]``, ``df.attrs["long_name"]``; as :meth:`to_xarray`."""
        from rollingdisk.results.dataout import to_dataframe

        return to_dataframe(self._data_columns(), self.disk, si=si, attrs=self._data_attrs())

    def _repr_html_(self) -> str:
        from rollingdisk.model.units import result_html

        g = self._data_attrs()["ground"]
        values = {"ground": g, "h": self.disk.h, "status": self.status,
                  "method": self.method, "points": int(self.t.size),
                  "n_steps": int(self.n_steps), "t_start": float(self.t[0]),
                  "t_end": float(self.t[-1]), "theta_start": float(self.theta[0]),
                  "theta_end": float(self.theta[-1]), "E_start": float(self.E[0]),
                  "E_end": float(self.E[-1])}
        if self.mode is not None:  # a Coulomb run: its mode changes
            values["transitions"] = len(self.transitions)
        kinds = {"t_start": "time", "t_end": "time", "theta_start": "angle",
                 "theta_end": "angle", "E_start": "energy", "E_end": "energy",
                 "h": "dimensionless"}
        return result_html(f"Trajectory on {g} ground", self.disk, values, kinds,
                           note=self.message)

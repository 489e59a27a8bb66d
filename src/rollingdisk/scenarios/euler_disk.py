"""Euler's disk, end to end: the toy spun up and run to its end with dissipation on.

The toy (a thick steel disk on a mirror base) starts on its spin-in-place steady motion
(section 3.2.1 with ``r_C = 0``) at the tilt ``alpha0 = pi/2 - |theta0|`` and runs until it
falls flat, lifts off or comes to rest.  Three dissipative terms:

* **creep friction** (regularized Coulomb): the tangential contact force is proportional to
  the slip at small slip and saturates at ``mu F_z``, in the cubic form of Vermeulen &
  Johnson, "Contact of nonspherical elastic bodies transmitting tangential forces",
  J. Appl. Mech. 31 (1964) 338, written in the slip velocity ``u`` of the contact point
  (eq. 6)::

      F_t = -mu F_z f(|u|/u_s) u/|u|,  f(s) = 1 - (1 - s)^3 (s < 1),  1 (s >= 1),
      u_s = 3 mu / k,

  so that ``F_t ~ -k F_z u`` for small slip (``k``, the creep coefficient) and
  ``|F_t| = mu F_z`` for ``|u| >= u_s``.  The micro-slip of the late stage is then a stiff
  but smooth ODE (no mode switching), integrated by LSODA (stiff/non-stiff switching);
* **rolling resistance** ``M_h = -c F_z omega_h / sqrt(|omega_h|^2 + eps^2)``: the model of
  :class:`rollingdisk.RollingResistance`, smoothed below ``|omega_h| ~ eps``;
* optionally **air**: Moffatt's squeeze film, :class:`rollingdisk.AirDrag` with ``c`` from
  the air viscosity (Moffatt, Nature 404 (2000) 833; the derived constant ``K = 1.28113``),
  or Bildsten's boundary layer, the moment of
  :class:`rollingdisk.model.air_models.BoundaryLayerAirDrag` (Phys. Rev. E 66 (2002)
  056309; ``c`` from the air's viscosity and density), chosen by ``EulerDisk.air_law``.

Equations: the sliding system of :mod:`rollingdisk.symbolic.coulomb` (the Newton-Euler
balances (8), (9) with (11)) with the friction force given: its kernel
:func:`rollingdisk.model.coulomb._sliding_solve` is linear in ``mu e``, so the creep force is
that kernel with the non-unit vector ``e = f(|u|/u_s) u/|u|``.  The velocity of C is
integrated in the turning frame Cxyz (``dv_Cx/dt = F_x + v_Cy Omega``, ``dv_Cy/dt = F_y -
v_Cx Omega``, (8)_1,2), where the spin-in-place family is an equilibrium; ``X_C, Y_C, psi,
phi`` are not needed (nothing depends on them) and are not integrated.  Both are checked
against the sympy derivation in ``tests/test_euler_disk.py``.

Predicted exponents: along the steady spin-in-place family (``F_z = 1``) the energy
``E(alpha)`` and the dissipated power ``P(alpha)`` are known, so the adiabatic decay is
``t0 - t = int_0^alpha E'(a)/|P(a)| da`` and the exponents are the slopes of ``log alpha``,
``log Omega`` and ``log v_P`` against ``log(t0 - t)`` over the fit window (computed, not
quoted).  Dimensionless units (m = a = g = 1); SI through the toy's radius and mass.
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np

from rollingdisk.model import coulomb as _cl
from rollingdisk.model.air_models import BoundaryLayerAirDrag, air_coefficient_derived
from rollingdisk.model.disk import STANDARD_GRAVITY, Disk
from rollingdisk.model.geometry import _geometry, _inertia
from rollingdisk.model.outcomes import AT_REST, EDGE_CONTACT, FELL_FLAT, LIFT_OFF, names
from rollingdisk.util.checks import check_int, check_real
from rollingdisk.util.errors import ParameterError

__all__ = ["EulerDisk", "EulerDiskResult", "run_euler_disk", "predicted_exponents",
           "creep_factor", "predicted_end_time", "END_KINDS", "AIR_VISCOSITY", "FIT_WINDOW",
           "FIT_WINDOW_AIR", "AIR_DENSITY", "AIR_LAWS", "FRICTION_LAWS", "dissipation_laws"]

#: Dynamic viscosity of air at 20 C [Pa s] (CRC Handbook), the default of ``--air``.
AIR_VISCOSITY = 1.81e-5
#: Density of air at 20 C and 1 atm [kg/m^3] (CRC Handbook), for the boundary-layer law.
AIR_DENSITY = 1.204
#: The air laws of :class:`EulerDisk`: Moffatt's squeeze film (``Phi ~ Omega^2 / alpha``)
#: and Bildsten's boundary layer (``Phi ~ Omega^(5/2)``), see ``docs/errata-models.md``.
AIR_LAWS = ("film", "boundary-layer")

#: Friction laws of :class:`EulerDisk`: the creep law (regularized Coulomb, smooth) or
#: set-valued Coulomb friction (rolling and sliding with located transitions).
FRICTION_LAWS = ("creep", "coulomb")
#: How a run can end (names of :mod:`rollingdisk.model.outcomes`): the three physical ends,
#: and edge contact (contact passes to the other rim edge, theta = 0, outside the model) --
#: each with status "completed".
END_KINDS = names(FELL_FLAT, LIFT_OFF, AT_REST, EDGE_CONTACT)
#: Quantities whose exponents are fitted and predicted.
EXPONENT_NAMES = ("alpha", "Omega", "contact_speed")
#: Default fit window (alpha range) of the exponents.
FIT_WINDOW = (2e-3, 2e-2)
#: Default fit window with Moffatt's air film (the run leaves the family below ~0.01).
FIT_WINDOW_AIR = (1e-2, 5e-2)
#: Dissipation terms recorded.
TERMS = ("slip", "rolling_resistance", "air")


@dataclass(frozen=True)
class EulerDisk:
    """The toy and its ground: physical parameters (with sources) and the contact model.

    Parameters
    ----------
    radius : float
        ``a`` [m], ``> 0``; 37.5 mm, the commercial Euler's Disk (75 mm diameter; popular
        accounts and Moffatt (2000), who quotes ``a ~ 3.8 cm``).
    thickness : float
        ``2 h a`` [m], ``> 0``; 12.7 mm (half an inch, the toy's stated thickness), so
        ``h = 0.169``.
    mass : float
        ``m`` [kg], ``> 0``; 0.45 kg (the toy is sold at about 0.4-0.45 kg; Moffatt uses 0.4).
    gravity : float
        ``g`` [m/s^2], ``> 0``; standard gravity, 9.80665 (the default of :class:`Disk`:
        one value of ``g`` in the library).
    mu : float
        Coulomb coefficient at saturation (dimensionless), ``>= 0``; 0.3, chosen for
        chrome-plated steel on a glass mirror (dry glass-on-metal lies between about 0.2
        and 0.6).
    creep : float
        Creep coefficient ``k > 0`` (units of ``1/sqrt(a g)``): ``F_t ~ -k F_z u`` at small
        slip, saturation at ``|u| = 3 mu/k``.  Chosen (1000: saturation at 0.9e-3 sqrt(a g)
        = 0.55 mm/s), not measured.
    rolling_resistance : float
        Rolling-resistance length ``c >= 0`` (units of ``a``).  Chosen (5e-4, i.e. 19 um)
        so that the toy runs for about 100 s, the spin time quoted for it; not measured
        from a ring-down.
    air_viscosity : float or None
        Air viscosity [Pa s] (``>= 0``); ``None`` (default) for no air.
    alpha0 : float
        Initial tilt ``alpha0 = pi/2 - theta0`` in ``(0, pi/2)`` rad; 0.3.
    omega_eps : float
        Smoothing ``eps > 0`` of the rolling resistance near ``omega_h = 0`` (units of
        ``sqrt(g/a)``); 1e-6.
    air_law : {"film", "boundary-layer"}
        With air on: Moffatt's squeeze film (:attr:`c_air`, ``|P| = c Omega^2 / sin
        alpha``; default) or Bildsten's boundary layer (:attr:`c_boundary_layer`, ``|P| = c
        |Omega|^(5/2)``, valid above the crossover tilt ``alpha_c``, 4.8e-3 for the toy).
    air_density : float
        Air density [kg/m^3], ``> 0``, for the boundary layer; 1.204 (air at 20 C).
    friction : {"creep", "coulomb"}
        ``"creep"`` (default): the creep law above with ``creep`` and the smoothed rolling
        resistance, integrated by LSODA.  ``"coulomb"``: set-valued Coulomb friction with
        no constant to choose (``creep`` and ``omega_eps`` unused): the disk rolls while
        ``|F_t| <= mu F_z`` and slides at ``mu F_z`` otherwise, the transitions located
        (:func:`rollingdisk.simulate_coulomb`, its compiled loop; the toy's late micro-slip
        takes 7.5e7 steps); rolling resistance ``-c F_z omega_h/|omega_h|``,
        set-valued; air: the squeeze film only.

    A toy of any other size: :meth:`from_disk` (e.g. a disk of
    :func:`rollingdisk.model.units.disk_from_options`).

    Examples
    --------
    >>> toy = EulerDisk()
    >>> round(toy.h, 4), round(toy.time_unit, 5)
    (0.1693, 0.06184)
    """

    radius: float = 0.0375
    thickness: float = 0.0127
    mass: float = 0.45
    gravity: float = STANDARD_GRAVITY
    mu: float = 0.3
    creep: float = 1000.0
    rolling_resistance: float = 5e-4
    air_viscosity: float | None = None
    alpha0: float = 0.3
    omega_eps: float = 1e-6
    air_law: str = "film"
    air_density: float = AIR_DENSITY
    friction: str = "creep"

    def __post_init__(self):
        for name in ("radius", "thickness", "mass", "gravity", "creep", "omega_eps",
                     "air_density"):
            object.__setattr__(self, name, check_real(name, getattr(self, name), low=0.0,
                                                      low_open=True))
        for name in ("mu", "rolling_resistance"):
            object.__setattr__(self, name, check_real(name, getattr(self, name), low=0.0))
        if self.air_viscosity is not None:
            object.__setattr__(self, "air_viscosity",
                               check_real("air_viscosity", self.air_viscosity, low=0.0))
        object.__setattr__(self, "alpha0", check_real("alpha0", self.alpha0, low=0.0,
                                                      high=math.pi / 2, low_open=True,
                                                      high_open=True))
        if not isinstance(self.air_law, str) or self.air_law not in AIR_LAWS:
            raise ParameterError(f"air_law must be one of {', '.join(AIR_LAWS)}, got "
                                 f"{self.air_law!r}")
        if not isinstance(self.friction, str) or self.friction not in FRICTION_LAWS:
            raise ParameterError(f"friction must be one of {', '.join(FRICTION_LAWS)}, got "
                                 f"{self.friction!r}")
        if self.friction == "coulomb" and self.air_viscosity and self.air_law != "film":
            raise ParameterError("friction 'coulomb' takes the squeeze-film air law only "
                                 f"(air_law='film'), got air_law={self.air_law!r}")

    @classmethod
    def from_disk(cls, disk: Disk, **parameters) -> EulerDisk:
        """The toy made of ``disk`` (radius, thickness ``2 h a``, mass and gravity from its
        physical scale), with the contact parameters (``mu``, ``creep``, ...) given or the
        defaults.

        Raises :class:`ParameterError` when the disk has no radius and mass.

        Examples
        --------
        >>> from rollingdisk.model.units import disk_from_options
        >>> EulerDisk.from_disk(disk_from_options(disk="euro-1")).thickness
        0.00233
        """
        if not isinstance(disk, Disk):
            raise ParameterError(f"disk must be a Disk, got {type(disk).__name__}")
        disk._need("radius", "mass")
        for name in ("radius", "thickness", "mass", "gravity"):
            if name in parameters:
                raise ParameterError(f"{name} comes from the disk; do not give it too")
        return cls(radius=disk.radius, thickness=2.0 * disk.h * disk.radius, mass=disk.mass,
                   gravity=disk.gravity, **parameters)

    @property
    def disk(self) -> Disk:
        """The :class:`Disk` (``h = thickness / (2 radius)``, with its physical scale)."""
        return Disk.from_dimensions(self.radius, self.thickness, self.mass, self.gravity)

    @property
    def h(self) -> float:
        """Half-thickness in units of the radius."""
        return self.thickness / (2.0 * self.radius)

    @property
    def time_unit(self) -> float:
        """``sqrt(a/g)`` [s]."""
        return math.sqrt(self.radius / self.gravity)

    @property
    def c_air(self) -> float:
        """Air-drag coefficient of :class:`rollingdisk.AirDrag`, ``K mu_air a^(3/2) /
        (m g^(1/2))`` with ``K`` = 1.28113, the squeeze film under the disk solved from the
        Reynolds equation (:data:`rollingdisk.model.air_models.FILM_CONSTANT`); Moffatt's
        shear estimate ``K = 2 pi`` is 4.90 times larger (``docs/errata-models.md``).  0
        without air or with the boundary-layer law."""
        if not self.air_viscosity or self.air_law != "film":
            return 0.0
        return air_coefficient_derived(self.air_viscosity, self.radius, self.mass,
                                       self.gravity)

    @property
    def c_boundary_layer(self) -> float:
        """Coefficient ``c`` of :class:`~rollingdisk.model.air_models.BoundaryLayerAirDrag`
        (``|P| = c |Omega|^(5/2)``), ``C sqrt(mu_air rho_air) a^(9/4) / (m g^(1/4))``, ``C =
        pi`` (:meth:`~rollingdisk.model.air_models.BoundaryLayerAirDrag.from_si`); 0
        without air or with the film law."""
        if not self.air_viscosity or self.air_law != "boundary-layer":
            return 0.0
        return BoundaryLayerAirDrag.from_si(self.air_viscosity, self.air_density, self.radius,
                                            self.mass, self.gravity).c

    def as_dict(self) -> dict:
        """The parameters, plus ``h``, ``time_unit_s``, ``c_air`` and
        ``c_boundary_layer``."""
        return {"radius_m": self.radius, "thickness_m": self.thickness, "mass_kg": self.mass,
                "gravity": self.gravity, "mu": self.mu, "creep": self.creep,
                "rolling_resistance": self.rolling_resistance,
                "air_viscosity": self.air_viscosity, "alpha0": self.alpha0,
                "omega_eps": self.omega_eps, "air_law": self.air_law,
                "air_density": self.air_density, "friction": self.friction,
                "h": self.h, "time_unit_s": self.time_unit,
                "c_air": self.c_air, "c_boundary_layer": self.c_boundary_layer}


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


def dissipation_laws(toy: EulerDisk | None = None) -> dict[str, EulerDisk]:
    """The same toy with each dissipation law alone, and its mix: ``"rolling resistance"``
    (the toy's, no air), ``"squeeze film"`` and ``"boundary layer"`` (air at 20 C, no
    rolling resistance) and ``"rolling resistance + film"`` (``--air``).  Creep friction
    stays on in all four (it dissipates little, see ``docs/friction.md``).

    Examples
    --------
    >>> list(dissipation_laws())[1]
    'squeeze film'
    """
    import dataclasses

    from rollingdisk.util.errors import ParameterTypeError

    toy = EulerDisk() if toy is None else toy
    if not isinstance(toy, EulerDisk):
        raise ParameterTypeError(f"toy must be an EulerDisk, got {type(toy).__name__}")
    c = toy.rolling_resistance
    air = toy.air_viscosity or AIR_VISCOSITY
    return {"rolling resistance": dataclasses.replace(toy, air_viscosity=None),
            "squeeze film": dataclasses.replace(toy, rolling_resistance=0.0,
                                                air_viscosity=air, air_law="film"),
            "boundary layer": dataclasses.replace(toy, rolling_resistance=0.0,
                                                  air_viscosity=air,
                                                  air_law="boundary-layer"),
            "rolling resistance + film": dataclasses.replace(toy, rolling_resistance=c,
                                                             air_viscosity=air,
                                                             air_law="film")}


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


# ------------------------------------------------------------------------- kernels
def creep_factor(slip, u_s):
    """``f(|u|/u_s)/|u|`` of the creep law (Vermeulen & Johnson's cubic), so that
    ``F_t = -mu F_z f u/|u|`` is ``-mu F_z (creep_factor) u``.  Element-wise.

    ``f(s) = 1 - (1 - s)^3`` for ``s < 1`` and 1 beyond: ``f(s)/s = (3 - 3 s + s^2)`` /
    ``u_s`` below saturation (finite at ``u = 0``, slope ``3/u_s = k/mu``), ``1/|u|`` above.
    """
    slip = np.asarray(slip, dtype=float)
    s = slip / u_s
    return np.where(s < 1.0, (3.0 - 3.0 * s + s * s) / u_s,
                    1.0 / np.where(s < 1.0, 1.0, slip))[()]


def _rhs(h, mu, u_s, c_roll, c_air, eps, x, c_bl=0.0):
    """Right-hand side on the reduced state ``x = [v_Cx, v_Cy, theta, omega1, omega2,
    omega3, D_slip, D_roll, D_air]``; returns ``(dx, F_z, |u|)``.  ``c_air``: the squeeze
    film's coefficient, ``c_bl``: the boundary layer's (at most one of them non-zero).

    ``v_Cx, v_Cy``: velocity of C in Cxyz; ``D_*``: energy dissipated by each term.
    Element-wise: ``x`` may be a (9,) vector (the integrator) or a (9, N) array (the
    recorded steps, in one call)."""
    v_Cx, v_Cy, theta, w1, w2, w3 = x[0], x[1], x[2], x[3], x[4], x[5]
    ht, s, c, p, y_P, z_P = _geometry(h, theta)
    u_x = v_Cx - w2 + ht * w3  # eq. (6)
    u_y = v_Cy - w1 * z_P
    n = np.sqrt(u_x * u_x + u_y * u_y)
    if np.ndim(n) == 0:  # the integrator's scalar path: creep_factor without np.where
        sn = n / u_s
        f = (3.0 - 3.0 * sn + sn * sn) / u_s if sn < 1.0 else 1.0 / n
    else:
        f = creep_factor(n, u_s)
    # air film, rollingdisk.AirDrag: M = -c omega3 e_zeta / cos^3(theta), e_zeta =
    # (0, -sin theta, cos theta); rolling resistance, rollingdisk.RollingResistance
    # smoothed: M1_h = -c omega_h / sqrt(|omega_h|^2 + eps^2)
    # boundary layer, BoundaryLayerAirDrag: M = -c |Omega|^(1/2) Omega e_zeta / cos(theta)
    if c_bl:
        Om = w3 / c  # eq. (2)
        ka = -c_bl * np.sqrt(np.abs(Om)) * Om / c
    else:
        ka = -c_air * w3 / (c * c * c)
    wx = w1
    wy = w2 * c - w3 * s
    nh2 = wx * wx + wy * wy
    kr = -c_roll / np.sqrt(nh2 + eps * eps)
    # the sliding kernel with friction -mu F_z e, e = f u (not a unit vector: linear in mu e)
    d1, d2, d3, F_x, F_y, F_z = _cl._sliding_solve(h, mu, f * u_x, f * u_y, theta, w1, w2, w3,
                                                   0.0 * ka, -ka * s, ka * c,
                                                   kr * wx, kr * wy, 0.0)
    Om = w3 / c  # eq. (2)
    P_slip = F_x * u_x + F_y * u_y
    P_roll = kr * F_z * nh2
    P_air = ka * w3  # omega . M = -c omega3^2 / cos^3(theta) (film), -c |Omega|^(5/2) (layer)
    dx = np.array([F_x + v_Cy * Om,  # eq. (8)_1 in the turning frame Cxyz
                   F_y - v_Cx * Om,  # eq. (8)_2
                   w1, d1, d2, d3,  # eq. (2), (9)
                   -P_slip, -P_roll, -P_air])
    return dx, F_z, n


def _energy(h, x):
    """Energy (eq. 13) of a reduced state (``|v_C|`` does not depend on the frame).
    Element-wise over the columns of ``x``."""
    z = 0.0 * x[0]
    y = (z, z, x[0], x[1], z, x[2], z, x[3], x[4], x[5])
    return _cl._coulomb_energy(h, y)


def _observables(h, x):
    """``alpha, Omega, contact-point speed`` of reduced states (element-wise)."""
    v_Cx, v_Cy, theta, w1, w2, w3 = x[:6]
    ht, s, c, p, y_P, z_P = _geometry(h, theta)
    Om = w3 / c
    # contact point (eq. 5) X_P = X_C - y_P sin psi, Y_P = Y_C + y_P cos psi, d y_P/d theta
    # = -z_P: velocity (v_Cx - y_P Omega, v_Cy - z_P omega1) in Cxyz
    vp = np.hypot(v_Cx - y_P * Om, v_Cy - z_P * w1)
    return np.pi / 2 - np.abs(theta), np.abs(Om), vp


def _initial_state(toy: EulerDisk) -> np.ndarray:
    """The spin-in-place steady motion (rough ground, ``r_C = 0``) at ``alpha0``."""
    from rollingdisk.theory.steady import steady_motion

    m = steady_motion(Disk(toy.h), "rough", math.pi / 2 - toy.alpha0, r_C=0.0)
    return np.array([m.v_Cx0, m.v_Cy0, m.theta0, 0.0, m.omega20, m.omega30, 0.0, 0.0, 0.0])


def _kicked_state(toy: EulerDisk, kick: float) -> np.ndarray:
    """:func:`_initial_state` with ``omega1`` raised by ``kick`` and ``v_Cy = omega1 z_P``,
    so that the disk still rolls (eq. 6)."""
    x0 = _initial_state(toy)
    x0[3] += kick
    x0[1] = kick * _geometry(toy.h, x0[2])[5]
    return x0


# ------------------------------------------------------------------ predictions
def _family(h, alpha):
    """The spin-in-place family at tilt ``alpha`` (``theta0 = pi/2 - alpha > 0``):
    ``(E, Omega, |omega_h|, omega3, y_P)``, written in ``alpha`` (so that small tilts keep
    their precision; complex ``alpha`` passes through for complex-step derivatives).

    ``r_C = 0`` in eq. (31): ``Omega^2 = 12 (s - h c) / (c [(3 + 4 h^2) s - 6 h c])`` with
    ``s = sin theta0 = cos alpha``, ``c = cos theta0 = sin alpha``; ``omega3 = Omega c``
    (eq. 3), ``omega2 = h omega3`` (``v_Cx0 = 0``, eqs. 24, 26); energy (13) with ``v_C =
    0``, ``omega1 = 0``; ``|omega_h| = |omega2 c - omega3 s|``; ``y_P = s - h c`` (eq. 4).
    Checked against :func:`rollingdisk.steady_motion` in the tests."""
    s, c = np.cos(alpha), np.sin(alpha)
    Om2 = 12.0 * (s - h * c) / (c * ((3.0 + 4.0 * h * h) * s - 6.0 * h * c))
    Om = np.sqrt(Om2)
    w3 = Om * c
    w2 = h * w3
    k1 = _inertia(h)[0]  # eq. (10)
    E = 0.5 * k1 * w3 * w3 + 0.25 * w2 * w2 + c + h * s  # -z_P = c + h s
    return E, Om, abs(w2 * c - w3 * s), w3, s - h * c


def _family_power(toy: EulerDisk, alpha):
    """Dissipated power ``|P|`` on the family (``F_z = 1``, no slip): rolling resistance
    ``c |omega_h|`` and air (the film's ``c Omega^2 / sin(alpha)`` or the boundary layer's
    ``c Omega^(5/2)``).

    The rolling resistance is taken unsmoothed: its smoothing changes the power by a
    factor ``1 - (eps/|omega_h|)^2/2``, less than 1e-8 in the toy's fit window, but it
    would switch the resistance off below ``alpha ~ (eps/2)^2`` and make ``t0`` (the
    integral down to ``alpha = 0``) diverge logarithmically."""
    E, Om, wh, w3, y_P = _family(toy.h, alpha)
    P = toy.rolling_resistance * wh
    if toy.c_air:  # omega3^2 / cos^3(theta) = Omega^2 / sin(alpha), no underflow
        P += toy.c_air * Om * Om / math.sin(alpha)
    if toy.c_boundary_layer:
        P += toy.c_boundary_layer * Om * Om * np.sqrt(Om)
    return P


def _decay_integrand(toy: EulerDisk):
    """``s -> 2 s E'(s^2) / |P(s^2)|``: ``d(t0 - t)/ds`` of the adiabatic decay with
    ``alpha = s^2`` (``E'`` by complex step, exact to rounding)."""
    h = toy.h

    def dE(a):
        return float(np.imag(_family(h, complex(a, 1e-30))[0]) / 1e-30)

    def integrand(s):
        a = s * s
        return 2.0 * s * dE(a) / _family_power(toy, a)

    return integrand


def _no_dissipation(toy: EulerDisk) -> bool:
    """True if the family loses no energy (no rolling resistance, no air)."""
    return toy.rolling_resistance == 0.0 and toy.c_air == 0.0 and toy.c_boundary_layer == 0.0


def predicted_end_time(toy: EulerDisk, alpha_end: float = 1e-3) -> tuple[float, float]:
    """The adiabatic decay along the steady family from ``alpha0``: the time it reaches
    ``alpha_end`` and the time ``t0`` it reaches ``alpha = 0`` (units ``sqrt(a/g)``).

    ``t(alpha) = int_alpha^alpha0 E'(a) / |P(a)| da`` (see :func:`predicted_exponents`);
    slip is not in ``P`` (no slip on the family), so a run with creep ends a little
    earlier.  ``(inf, inf)`` without dissipation."""
    from scipy.integrate import quad

    if _no_dissipation(toy):
        return math.inf, math.inf
    f = _decay_integrand(toy)
    tail = quad(f, 0.0, math.sqrt(alpha_end), epsabs=0.0, epsrel=1e-11, limit=400)[0]
    body = quad(f, math.sqrt(alpha_end), math.sqrt(toy.alpha0), epsabs=0.0, epsrel=1e-11,
                limit=400)[0]
    return body, body + tail


def predicted_exponents(toy: EulerDisk, window=(2e-3, 2e-2), n: int = 40) -> dict:
    """Exponents of ``alpha``, ``Omega`` and the contact-point speed against ``t0 - t``
    predicted by the adiabatic decay along the steady spin-in-place family.

    ``t0 - t(alpha) = int_0^alpha E'(a) / |P(a)| da`` (energy balance, eq. 12, with the
    family's energy ``E(alpha)`` and power ``P(alpha)``; substitution ``a = s^2`` for the
    ``a^(-1/2)`` end point of rolling resistance); the exponents are least-squares slopes
    over ``n`` tilts spaced evenly in ``log alpha`` across ``window``.  With rolling
    resistance alone they tend to ``2, -1, -1`` as the window shrinks to 0 (``E - E_inf ~
    alpha``, ``|omega_h| ~ alpha^(1/2)``), with Moffatt's film to ``1/3, -1/6, -1/6``, with
    Bildsten's boundary layer (``P ~ Omega^(5/2) ~ alpha^(-5/4)``) to ``4/9, -2/9, -2/9``.
    """
    from scipy.integrate import quad

    lo, hi = window
    if not (0.0 < lo < hi < toy.alpha0):
        raise ParameterError(f"window must satisfy 0 < lo < hi < alpha0 = {toy.alpha0:g}, "
                             f"got {window!r}")
    if _no_dissipation(toy):
        return {k: math.nan for k in EXPONENT_NAMES}
    h = toy.h
    integrand = _decay_integrand(toy)
    alphas = np.geomspace(lo, hi, n)
    edges = np.sqrt(np.concatenate([[0.0], alphas]))
    tau = np.cumsum([quad(integrand, edges[i], edges[i + 1], epsabs=0.0, epsrel=1e-11,
                          limit=200)[0] for i in range(n)])
    fam = [_family(h, a) for a in alphas]
    Om = np.array([f[1] for f in fam])
    vp = np.array([abs(f[4]) * f[1] for f in fam])  # contact point: |y_P| Omega
    lt = np.log(tau)
    return {"alpha": float(np.polyfit(lt, np.log(alphas), 1)[0]),
            "Omega": float(np.polyfit(lt, np.log(Om), 1)[0]),
            "contact_speed": float(np.polyfit(lt, np.log(vp), 1)[0])}


def _fit_exponents(t, alpha, Omega, vp, window):
    """Fit ``alpha = A (t0 - t)^p`` (``t0`` free) over ``alpha`` in ``window``; then the
    slopes of ``log Omega`` and ``log v_P`` against ``log(t0 - t)`` with that ``t0``."""
    from scipy.optimize import least_squares

    lo, hi = window
    w = (alpha > lo) & (alpha < hi)
    nan = {k: math.nan for k in EXPONENT_NAMES}
    if np.count_nonzero(w) < 20 or alpha[-1] > lo:
        return math.nan, nan
    tw, aw = t[w], np.log(alpha[w])
    span = tw[-1] - tw[0]
    t_last = tw[-1]

    def res(q):
        t0, p, b = q
        return aw - (b + p * np.log(np.maximum(t0 - tw, 1e-300)))

    best = None
    for guess in (1.0, 0.5, 0.3):  # a few starts: t0 beyond the window's last time
        tau0 = max(span * 0.1, 1e-9)
        q0 = [t_last + tau0 * guess * 10, 1.0, 0.0]
        r = least_squares(res, q0, bounds=([t_last + 1e-12 * (1 + t_last), -10, -1e3],
                                           [np.inf, 10, 1e3]), x_scale="jac")
        if best is None or r.cost < best.cost:
            best = r
    t0, p = float(best.x[0]), float(best.x[1])
    lt = np.log(t0 - tw)
    return t0, {"alpha": p, "Omega": float(np.polyfit(lt, np.log(Omega[w]), 1)[0]),
                "contact_speed": float(np.polyfit(lt, np.log(vp[w]), 1)[0])}


# ------------------------------------------------------------------------- driver
def _locate(dense, event, t_a, t_b):
    """Time and state in ``[t_a, t_b]`` where ``event(dense(t))`` changes sign (it is
    positive at ``t_a``, not at ``t_b``), by ``brentq`` on the step's interpolant."""
    from scipy.optimize import brentq

    if event(dense(t_a)) <= 0.0:  # nothing to locate (already there at the step start)
        return t_a, dense(t_a)
    t = brentq(lambda s: event(dense(s)), t_a, t_b, xtol=1e-14 * (1.0 + abs(t_b)),
               rtol=8.9e-16)
    return t, dense(t)


#: Tolerances of :func:`run_euler_disk` by friction law: LSODA's on the creep law,
#: DOP853's on Coulomb friction (energy balance 2.2e-9 over the toy's 7.5e7 steps,
#: docs/friction.md).
TOLERANCES = {"creep": (1e-9, 1e-11), "coulomb": (1e-10, 1e-12)}


def run_euler_disk(toy: EulerDisk | None = None, *, alpha_end: float = 1e-3,
                   t_max: float = 1e5, rtol: float | None = None, atol: float | None = None,
                   max_steps: int = 2_000_000, max_wall_time: float = 120.0,
                   fit_window: tuple | None = None, predict: bool = True, kick: float = 0.0,
                   progress: Callable[[float], None] | None = None) -> EulerDiskResult:
    """Spin the toy up on its spin-in-place steady motion and run it to its end.

    Parameters
    ----------
    toy : EulerDisk, optional
        The toy and its ground (default ``EulerDisk()``).
    alpha_end : float
        "Fell flat" when ``alpha <= alpha_end``, in ``(0, alpha0)``.
    t_max : float
        Stop (status ``"failed"``) at this time if no end came, ``> 0``.
    rtol, atol : float, optional
        Tolerances, ``rtol`` in ``[1e-13, 1e-3]``, ``atol > 0``: LSODA's on the creep law
        (default 1e-9, 1e-11), DOP853's on Coulomb friction (default 1e-10, 1e-12;
        :data:`TOLERANCES`).
    max_steps : int
        Step budget, ``>= 1`` (Coulomb friction: the toy's micro-slip near its end takes
        7.5e7 steps, about 8 minutes, so pass ``max_steps=3 * 10**8`` and a wall budget of
        half an hour; docs/friction.md).
    max_wall_time : float
        Wall-clock budget [s], ``> 0``.
    fit_window : (float, float), optional
        ``alpha`` range of the exponent fits (and of the prediction); default
        :data:`FIT_WINDOW`, or :data:`FIT_WINDOW_AIR` with air drag on (the air film
        drives the disk off the steady family below ``alpha ~ 0.01``, see
        ``docs/friction.md``; the boundary layer holds above ``alpha_c ~ 5e-3``).
    predict : bool
        Compute the predicted exponents (:func:`predicted_exponents`).
    kick : float
        Added to ``omega1`` at ``t = 0``, with ``v_Cy`` such that the disk still rolls
        (eq. 6): a nudge off the steady motion; 0 by default.
    progress : callable, optional
        Called with the fraction done, ``log(alpha0/alpha) / log(alpha0/alpha_end)``.

    Returns
    -------
    EulerDiskResult
        ``status == "completed"`` with ``end`` one of :data:`END_KINDS`; else
        ``"failed"`` (step budget, wall-clock budget, ``t_max``, step sizes collapsing,
        solver failure) with a message, never a hang.

    Notes
    -----
    Ends: fell flat (``alpha <= alpha_end``), lifted off (``F_z < 0``, eq. 11), came to
    rest (``|omega|`` and ``|v_C|`` below ``1e-10``), edge contact (``theta`` changes sign,
    ``h > 0``).  Events are checked at every accepted step and located on its dense output.
    With ``toy.friction == "coulomb"`` the run is :func:`rollingdisk.simulate_coulomb` (its
    compiled loop once loaded) from the same state, ``alpha_end`` its ``alpha_min``; the
    result's ``extra`` holds its ``"transitions"`` (rolling <-> sliding) as well.
    Step sizes collapsing: 50 accepted steps in a row shorter than ``1e-12 (1 + t)``.

    Examples
    --------
    >>> r = run_euler_disk(EulerDisk(alpha0=0.3), t_max=5.0, predict=False)
    >>> r.status, r.end
    ('failed', None)
    """
    toy, alpha_end, t_max, rtol, atol, max_steps, max_wall_time, kick, (lo, hi) = \
        _check_run_arguments(toy, alpha_end, t_max, rtol, atol, max_steps, max_wall_time,
                             kick, fit_window)
    if toy.friction == "coulomb":
        run = _CoulombToyRun(toy, alpha_end, t_max, rtol, atol, kick)
    else:
        run = _ToyRun(toy, alpha_end, t_max, rtol, atol, kick)
    run.integrate(max_steps, max_wall_time, progress)
    return _result(run, (lo, hi), predict)


def _check_run_arguments(toy, alpha_end, t_max, rtol, atol, max_steps, max_wall_time, kick,
                         fit_window):
    """The validated arguments of :func:`run_euler_disk`, ``fit_window`` as ``(lo, hi)``."""
    toy = EulerDisk() if toy is None else toy
    if not isinstance(toy, EulerDisk):
        raise ParameterError(f"toy must be an EulerDisk, got {type(toy).__name__}")
    alpha_end = check_real("alpha_end", alpha_end, low=0.0, high=toy.alpha0, low_open=True,
                           high_open=True)
    t_max = check_real("t_max", t_max, low=0.0, low_open=True)
    rtol = check_real("rtol", TOLERANCES[toy.friction][0] if rtol is None else rtol,
                      low=1e-13, high=1e-3)
    atol = check_real("atol", TOLERANCES[toy.friction][1] if atol is None else atol, low=0.0,
                      low_open=True)
    max_steps = check_int("max_steps", max_steps, low=1)
    max_wall_time = check_real("max_wall_time", max_wall_time, low=0.0, low_open=True)
    kick = check_real("kick", kick)
    if fit_window is None:
        fit_window = (FIT_WINDOW_AIR if toy.c_air > 0 or toy.c_boundary_layer > 0
                      else FIT_WINDOW)
    lo, hi = (check_real("fit_window[0]", fit_window[0], low=0.0, low_open=True),
              check_real("fit_window[1]", fit_window[1], low=0.0, low_open=True))
    if not lo < hi < toy.alpha0:
        raise ParameterError(f"fit_window must satisfy 0 < lo < hi < alpha0 = "
                             f"{toy.alpha0:g}, got {fit_window!r}")
    return toy, alpha_end, t_max, rtol, atol, max_steps, max_wall_time, kick, (lo, hi)


class _ToyRun:
    """One run of :func:`run_euler_disk`: the LSODA solver on the creep equations, the
    recorded steps, and how the run ended (``end``, ``status``, ``message``)."""

    def __init__(self, toy, alpha_end, t_max, rtol, atol, kick):
        from scipy.integrate import LSODA

        self.toy, self.alpha_end, self.t_max, self.rtol = toy, alpha_end, t_max, rtol
        self.start = time.monotonic()
        mu = toy.mu
        u_s = 3.0 * mu / toy.creep if mu > 0 else 1.0  # mu = 0: no friction at all
        self.params = (toy.h, mu, u_s, toy.rolling_resistance, toy.c_air, toy.omega_eps)
        self.c_bl = toy.c_boundary_layer
        self.last = [1.0]  # F_z of the latest evaluation (near the accepted point) for lift-off
        x0 = _kicked_state(toy, kick)
        self.solver = LSODA(self._f, 0.0, x0, t_max, rtol=rtol, atol=atol)
        self.ts, self.xs = [0.0], [x0.copy()]
        self.log_span = math.log(toy.alpha0 / alpha_end)
        self.end = None
        self.status, self.message = "failed", ""
        F_z0 = _rhs(*self.params, x0, c_bl=self.c_bl)[1]
        if F_z0 < 0.0:  # the kick asks for a pull from the plane: no motion in contact at all
            self.end, self.status = "lift-off", "completed"
            self.message = f"lifted off at the start: F_z(0) = {F_z0:.4g} < 0 (eq. 11)"
        self.n = 0
        self.n_short = 0
        self.shown = -1.0
        self.side = math.copysign(1.0, x0[2])

    def _f(self, t, x):
        dx, self.last[0], _ = _rhs(*self.params, x, c_bl=self.c_bl)
        return dx

    def forces(self, XT):
        """``(F_z, |u|)`` at the recorded states ``XT`` (9, N)."""
        return _rhs(*self.params, XT, c_bl=self.c_bl)[1:]

    def extra(self) -> dict:
        return {}

    def integrate(self, max_steps, max_wall_time, progress):
        """Step until an end, a budget, ``t_max`` or a failure (``message`` says which)."""
        solver = self.solver
        while self.end is None:
            if self._stopped(max_steps, max_wall_time):
                break
            t_old = solver.t
            msg = solver.step()
            self.n += 1
            if solver.status == "failed":
                self.message = f"LSODA failed at t = {solver.t:.6g}: {msg}"
                break
            x = solver.y
            if not math.isfinite(x.sum()):
                self.message = f"the state left floating-point range at t = {solver.t:.6g}"
                break
            self.ts.append(solver.t)
            self.xs.append(x.copy())
            if self._ended(x, t_old, progress):
                break
        if progress is not None:
            progress(1.0 if self.end is not None else self._done(
                math.pi / 2 - abs(self.xs[-1][2])))

    def _stopped(self, max_steps, max_wall_time):
        """True (message set) if the run reached ``t_max`` or spent a budget."""
        if self.solver.status == "finished":
            self.message = f"reached t_max = {self.t_max:g} before any end (alpha = " \
                           f"{math.pi / 2 - abs(self.xs[-1][2]):.3g})"
        elif self.n >= max_steps:
            self.message = f"step budget exhausted: max_steps = {max_steps} steps reached " \
                           f"at t = {self.ts[-1]:.6g} without an end"
        elif time.monotonic() - self.start > max_wall_time:
            self.message = f"wall-clock budget exhausted: max_wall_time = " \
                           f"{max_wall_time:g} s reached at t = {self.ts[-1]:.6g} without an end"
        else:
            return False
        return True

    def _done(self, alpha):
        """The fraction of the run done at tilt ``alpha``, on a log scale."""
        return min(max(math.log(self.toy.alpha0 / max(alpha, 1e-300)) / self.log_span, 0.0),
                   1.0)

    def _ended(self, x, t_old, progress):
        """Check the ends after an accepted step to state ``x``; True if the run ended
        (``end``, ``status``, ``message`` set, the end located on the step) or the step
        sizes collapsed."""
        solver, params, c_bl = self.solver, self.params, self.c_bl
        F_z = self.last[0]
        if F_z < 0.0:  # confirm at the accepted state itself
            F_z = _rhs(*params, x, c_bl=c_bl)[1]
        tiny = solver.t - t_old < 1e-12 * (1.0 + abs(solver.t))
        self.n_short = self.n_short + 1 if tiny else 0
        alpha = math.pi / 2 - abs(x[2])
        if progress is not None and self.n % 100 == 0:
            done = self._done(alpha)
            if done >= self.shown + 0.005:  # a few hundred updates per run, not one per step
                self.shown = done
                progress(done)
        event = None  # a function of the state that changes sign at the end
        alpha_end, side = self.alpha_end, self.side
        if alpha <= alpha_end:
            self.end, self.message = "fell-flat", f"fell flat: alpha = {alpha_end:g}"
            event = lambda z: math.pi / 2 - abs(z[2]) - alpha_end  # noqa: E731
        elif F_z < 0.0:
            self.end, self.message = "lift-off", "lifted off: F_z = 0 (eq. 11)"
            event = lambda z: _rhs(*params, z, c_bl=c_bl)[1]  # noqa: E731
        elif math.copysign(1.0, x[2]) != side:
            self.end, self.message = "edge-contact", "theta = 0: the other rim edge touches"
            event = lambda z: z[2] * side  # noqa: E731
        elif max(abs(v) for v in x[:2]) < 1e-10 and max(abs(v) for v in x[3:6]) < 1e-10:
            self.end, self.message = "at-rest", "came to rest: |omega|, |v_C| < 1e-10"
        if self.end is not None:
            if event is not None:  # locate it on the step's dense output
                self.ts[-1], self.xs[-1] = _locate(solver.dense_output(), event, t_old,
                                                   solver.t)
            self.status = "completed"
            self.message += f" at t = {self.ts[-1]:.6g} ({self.ts[-1] * self.toy.time_unit:.4g} s)"
            return True
        if self.n_short >= 50:
            self.message = f"step sizes collapsed (50 steps shorter than 1e-12 (1 + t)) at " \
                           f"t = {solver.t:.6g}: the model is too stiff here for rtol = " \
                           f"{self.rtol:g}"
            return True
        return False


def _result(run, window, predict):
    """The :class:`EulerDiskResult` of a finished :class:`_ToyRun` or
    :class:`_CoulombToyRun`: observables along the run, the energy balance, fitted and
    predicted exponents."""
    toy = run.toy
    h = toy.h
    t = np.array(run.ts)
    X = np.array(run.xs)
    XT = X.T  # (9, N): every recorded quantity in one element-wise call
    alpha, Omega, vp = _observables(h, XT)
    fz, us = run.forces(XT)
    E = _energy(h, XT)
    dissipated = {k: X[:, 6 + i] for i, k in enumerate(TERMS)}
    total = E + X[:, 6:].sum(axis=1)
    balance = float(np.max(np.abs(total - total[0])) / max(abs(total[0]), 1.0))
    t0, fitted = _fit_exponents(t, alpha, Omega, vp, window)
    predicted = (predicted_exponents(toy, window) if predict
                 else {k: math.nan for k in EXPONENT_NAMES})
    pred_end, pred_t0 = (predicted_end_time(toy, run.alpha_end) if predict
                         else (math.nan, math.nan))
    return EulerDiskResult(toy=toy, t=t, alpha=alpha, Omega=Omega, contact_speed=vp,
                           slip_speed=us, F_z=fz, E=E,
                           dissipated=dissipated, t_end=float(t[-1]), end=run.end,
                           status=run.status, message=run.message, t0=t0, exponents=fitted,
                           predicted=predicted, fit_window=window, predicted_t_end=pred_end,
                           predicted_t0=pred_t0, energy_balance=balance, n_steps=run.n,
                           wall_time=time.monotonic() - run.start,
                           extra={"state": X, **run.extra()})


class _CoulombToyRun:
    """One run of :func:`run_euler_disk` on Coulomb ground: :func:`rollingdisk.
    simulate_coulomb` from the toy's state, its trajectory in the reduced variables of
    :class:`_ToyRun` (``ts``, ``xs``; ``end``, ``status``, ``message``, ``n``)."""

    #: simulate_coulomb's statuses that are ends of the toy's run.
    ENDS = {"fell-flat": "fell-flat", "lift-off": "lift-off", "edge-contact": "edge-contact"}

    def __init__(self, toy, alpha_end, t_max, rtol, atol, kick):
        self.toy, self.alpha_end, self.t_max, self.rtol, self.atol = (toy, alpha_end, t_max,
                                                                      rtol, atol)
        self.start = time.monotonic()
        self.x0 = _kicked_state(toy, kick)
        self.end, self.status, self.message = None, "failed", ""
        self.n = 0
        self.traj = None
        self.ts, self.xs = [0.0], [self.x0.copy()]

    def ground(self):
        from rollingdisk.model.ground import Coulomb

        toy = self.toy
        return Coulomb(toy.mu, rolling_resistance=toy.rolling_resistance or None,
                       air=toy.c_air or None)

    def integrate(self, max_steps, max_wall_time, progress):
        from rollingdisk.ivp.hybrid import simulate_coulomb

        toy, x0 = self.toy, self.x0
        y0 = np.array([0.0, 0.0, x0[0], x0[1], 0.0, x0[2], 0.0, x0[3], x0[4], x0[5]])
        report = None
        if progress is not None:
            t_guess = max(predicted_end_time(toy, self.alpha_end)[0], 1.0)
            if not math.isfinite(t_guess):
                t_guess = self.t_max

            def report(fraction):  # fraction of (0, t_max) -> of the predicted end time
                progress(min(fraction * self.t_max / t_guess, 0.99))
        tr = simulate_coulomb(
            Disk(toy.h), self.ground(), (0.0, self.t_max), y0, rtol=self.rtol,
            atol=self.atol, max_steps=max_steps, max_transitions=max_steps,
            max_wall_time=max(max_wall_time - (time.monotonic() - self.start), 1e-3),
            max_points=COULOMB_POINTS, alpha_min=self.alpha_end, progress=report)
        self.traj, self.n = tr, tr.n_steps
        Y = tr.y
        cp, sp = np.cos(Y[4]), np.sin(Y[4])
        D = tr.dissipated
        self.ts = tr.t
        self.xs = np.column_stack([Y[2] * cp + Y[3] * sp, -Y[2] * sp + Y[3] * cp, Y[5],
                                   Y[7], Y[8], Y[9], D["slip"],
                                   D["rolling_resistance"] + D["pivot"], D["air"]])
        if tr.status in self.ENDS:
            self.end, self.status = self.ENDS[tr.status], "completed"
            self.message = tr.message
        elif tr.status == "completed":
            self.message = (f"reached t_max = {self.t_max:g} before any end (alpha = "
                            f"{math.pi / 2 - abs(Y[5, -1]):.3g})")
        else:
            self.message = tr.message
        if progress is not None and self.end is not None:
            progress(1.0)

    def forces(self, XT):
        """``(F_z, |u|)`` at the recorded points: the contact force of each point's mode."""
        tr = self.traj
        u_x, u_y = _cl._slip_velocity(self.toy.h, tr.y)
        return tr.F_z, np.hypot(u_x, u_y)

    def extra(self) -> dict:
        tr = self.traj
        return {"transitions": tr.transitions, "mode": tr.mode, "method": tr.method}


#: Most points :class:`_CoulombToyRun` stores (every k-th step beyond, and every
#: transition): a run through micro-slip takes millions of steps.
COULOMB_POINTS = 400_000

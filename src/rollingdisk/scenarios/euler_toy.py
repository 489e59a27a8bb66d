"""Euler's disk, the toy: its physical parameters with their sources and its contact model
(:class:`EulerDisk`), the laws it can dissipate by (friction, rolling resistance, air) and
the same toy under each law alone (:func:`dissipation_laws`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from rollingdisk.model.air_models import BoundaryLayerAirDrag, air_coefficient_derived
from rollingdisk.model.disk import STANDARD_GRAVITY, Disk
from rollingdisk.model.outcomes import AT_REST, EDGE_CONTACT, FELL_FLAT, LIFT_OFF, names
from rollingdisk.util.checks import check_real
from rollingdisk.util.errors import ParameterError

__all__ = ["EulerDisk", "dissipation_laws", "END_KINDS", "AIR_VISCOSITY", "FIT_WINDOW",
           "FIT_WINDOW_AIR", "AIR_DENSITY", "AIR_LAWS", "FRICTION_LAWS"]

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


"""rollingdisk: a rigid disk of finite thickness rolling or sliding on a horizontal plane.

Implements and checks M. Batista, "Steady Motion of a Rigid Disk of Finite Thickness on a
Horizontal Plane": equations of motion on rough and smooth ground (section 2), steady
motions (section 3) and their stability (section 4), and beyond the paper real ground
(Coulomb friction), exact motions by quadrature and sweeps.  Dimensionless units
m = a = g = 1.

The package is layered (``docs/architecture.md``); each layer imports only those below it::

    util < model < theory < integrate < friction < {sweep, plotting, symbolic} < atlas,
    explore < cli

This module re-exports the public API, name by name; ``import rollingdisk`` loads neither
numba, sympy nor matplotlib.
"""

from importlib.metadata import PackageNotFoundError
from importlib.metadata import version as _version

from rollingdisk.friction import (
    COULOMB_STATE as COULOMB_STATE,
)
from rollingdisk.friction import (
    DISSIPATION_TERMS as DISSIPATION_TERMS,
)
from rollingdisk.friction import (
    MODE_NAMES as MODE_NAMES,
)
from rollingdisk.friction import (
    AirDrag as AirDrag,
)
from rollingdisk.friction import (
    Coulomb as Coulomb,
)
from rollingdisk.friction import (
    PivotFriction as PivotFriction,
)
from rollingdisk.friction import (
    RollingResistance as RollingResistance,
)
from rollingdisk.friction import (
    angular_velocity_xyz as angular_velocity_xyz,
)
from rollingdisk.friction import (
    coulomb_contact as coulomb_contact,
)
from rollingdisk.friction import (
    coulomb_energy as coulomb_energy,
)
from rollingdisk.friction import (
    coulomb_rhs as coulomb_rhs,
)
from rollingdisk.friction import (
    energy_balance as energy_balance,
)
from rollingdisk.friction import (
    rolling_state as rolling_state,
)
from rollingdisk.friction import (
    simulate_coulomb as simulate_coulomb,
)
from rollingdisk.friction import (
    simulate_to_rest as simulate_to_rest,
)
from rollingdisk.friction import (
    slip_direction as slip_direction,
)
from rollingdisk.friction import (
    toss as toss,
)
from rollingdisk.friction import (
    toss_ensemble as toss_ensemble,
)
from rollingdisk.integrate import (
    DEFAULT_ATOL as DEFAULT_ATOL,
)
from rollingdisk.integrate import (
    DEFAULT_MAX_STEPS as DEFAULT_MAX_STEPS,
)
from rollingdisk.integrate import (
    DEFAULT_RTOL as DEFAULT_RTOL,
)
from rollingdisk.integrate import (
    GUARDS as GUARDS,
)
from rollingdisk.integrate import (
    LINEAR_RANGE as LINEAR_RANGE,
)
from rollingdisk.integrate import (
    MAX_T as MAX_T,
)
from rollingdisk.integrate import (
    STATUSES as STATUSES,
)
from rollingdisk.integrate import (
    EdgeContact as EdgeContact,
)
from rollingdisk.integrate import (
    FellFlat as FellFlat,
)
from rollingdisk.integrate import (
    GuardEvent as GuardEvent,
)
from rollingdisk.integrate import (
    LiftOff as LiftOff,
)
from rollingdisk.integrate import (
    TheoryComparison as TheoryComparison,
)
from rollingdisk.integrate import (
    Trajectory as Trajectory,
)
from rollingdisk.integrate import (
    Transition as Transition,
)
from rollingdisk.integrate import (
    compare_with_theory as compare_with_theory,
)
from rollingdisk.integrate import (
    energy_drift as energy_drift,
)
from rollingdisk.integrate import (
    fit_circle as fit_circle,
)
from rollingdisk.integrate import (
    growth_rate as growth_rate,
)
from rollingdisk.integrate import (
    guard_events as guard_events,
)
from rollingdisk.integrate import (
    jit_compile as jit_compile,
)
from rollingdisk.integrate import (
    oscillation_frequency as oscillation_frequency,
)
from rollingdisk.integrate import (
    simulate as simulate,
)
from rollingdisk.integrate import (
    simulate_steady as simulate_steady,
)
from rollingdisk.model import (
    DEFAULT_H as DEFAULT_H,
)
from rollingdisk.model import (
    GROUNDS as GROUNDS,
)
from rollingdisk.model import (
    H_MAX as H_MAX,
)
from rollingdisk.model import (
    ROUGH_STATE as ROUGH_STATE,
)
from rollingdisk.model import (
    SMOOTH_STATE as SMOOTH_STATE,
)
from rollingdisk.model import (
    Disk as Disk,
)
from rollingdisk.model import (
    contact_force as contact_force,
)
from rollingdisk.model import (
    contact_point as contact_point,
)
from rollingdisk.model import (
    energy as energy,
)
from rollingdisk.model import (
    equations_of_motion as equations_of_motion,
)
from rollingdisk.model import (
    omega_dot as omega_dot,
)
from rollingdisk.model import (
    state_index as state_index,
)
from rollingdisk.model import (
    state_names as state_names,
)
from rollingdisk.model import (
    velocity_of_C as velocity_of_C,
)
from rollingdisk.model.units import (
    DISKS as DISKS,
)
from rollingdisk.model.units import (
    NamedDisk as NamedDisk,
)
from rollingdisk.model.units import (
    disk_from_options as disk_from_options,
)
from rollingdisk.model.units import (
    parse_acceleration as parse_acceleration,
)
from rollingdisk.model.units import (
    parse_length as parse_length,
)
from rollingdisk.model.units import (
    parse_mass as parse_mass,
)
from rollingdisk.model.units import (
    si_fields as si_fields,
)
from rollingdisk.theory import (
    NO_MOTION as NO_MOTION,
)
from rollingdisk.theory import (
    STABLE as STABLE,
)
from rollingdisk.theory import (
    UNSTABLE as UNSTABLE,
)
from rollingdisk.theory import (
    ExactMotion as ExactMotion,
)
from rollingdisk.theory import (
    ExampleMotions as ExampleMotions,
)
from rollingdisk.theory import (
    NoSteadyMotion as NoSteadyMotion,
)
from rollingdisk.theory import (
    Omega0_sq as Omega0_sq,
)
from rollingdisk.theory import (
    Stability as Stability,
)
from rollingdisk.theory import (
    SteadyMotion as SteadyMotion,
)
from rollingdisk.theory import (
    Thresholds as Thresholds,
)
from rollingdisk.theory import (
    circle_coefficients as circle_coefficients,
)
from rollingdisk.theory import (
    critical_omega30_sq as critical_omega30_sq,
)
from rollingdisk.theory import (
    exact_motion as exact_motion,
)
from rollingdisk.theory import (
    exact_steady as exact_steady,
)
from rollingdisk.theory import (
    example_motions as example_motions,
)
from rollingdisk.theory import (
    existence_codes as existence_codes,
)
from rollingdisk.theory import (
    mu_required_map as mu_required_map,
)
from rollingdisk.theory import (
    r_C_star as r_C_star,
)
from rollingdisk.theory import (
    reduced_jacobian as reduced_jacobian,
)
from rollingdisk.theory import (
    se_circle_radius as se_circle_radius,
)
from rollingdisk.theory import (
    stability as stability,
)
from rollingdisk.theory import (
    stable_for_all_omega30 as stable_for_all_omega30,
)
from rollingdisk.theory import (
    steady_motion as steady_motion,
)
from rollingdisk.theory import (
    straight_line as straight_line,
)
from rollingdisk.theory import (
    thresholds as thresholds,
)
from rollingdisk.theory import (
    varpi2_circle as varpi2_circle,
)
from rollingdisk.theory import (
    varpi2_closed_form as varpi2_closed_form,
)
from rollingdisk.theory import (
    varpi2_linearized as varpi2_linearized,
)
from rollingdisk.theory import (
    varpi2_rough_rC as varpi2_rough_rC,
)
from rollingdisk.theory import (
    varpi2_zero_surface as varpi2_zero_surface,
)
from rollingdisk.util.errors import (
    ParameterError as ParameterError,
)
from rollingdisk.util.errors import (
    ParameterTypeError as ParameterTypeError,
)

try:
    __version__ = _version("rollingdisk")
except PackageNotFoundError:  # pragma: no cover - a source tree that was never installed
    __version__ = "0+unknown"

#: The public API: the names documented in the README and the API reference, no more.
__all__ = [
    "ParameterError",
    "ParameterTypeError",
    "Disk",
    "DEFAULT_H",
    "GROUNDS",
    "H_MAX",
    "ROUGH_STATE",
    "SMOOTH_STATE",
    "state_names",
    "state_index",
    "equations_of_motion",
    "omega_dot",
    "contact_force",
    "energy",
    "contact_point",
    "velocity_of_C",
    "parse_length",
    "parse_mass",
    "parse_acceleration",
    "NamedDisk",
    "DISKS",
    "disk_from_options",
    "si_fields",
    "NoSteadyMotion",
    "SteadyMotion",
    "steady_motion",
    "straight_line",
    "Omega0_sq",
    "r_C_star",
    "se_circle_radius",
    "mu_required_map",
    "Stability",
    "stability",
    "varpi2_closed_form",
    "varpi2_linearized",
    "reduced_jacobian",
    "varpi2_circle",
    "varpi2_rough_rC",
    "circle_coefficients",
    "critical_omega30_sq",
    "stable_for_all_omega30",
    "Thresholds",
    "thresholds",
    "NO_MOTION",
    "UNSTABLE",
    "STABLE",
    "existence_codes",
    "varpi2_zero_surface",
    "ExampleMotions",
    "example_motions",
    "ExactMotion",
    "exact_motion",
    "exact_steady",
    "Trajectory",
    "Transition",
    "GuardEvent",
    "LiftOff",
    "EdgeContact",
    "FellFlat",
    "GUARDS",
    "STATUSES",
    "guard_events",
    "DEFAULT_RTOL",
    "DEFAULT_ATOL",
    "DEFAULT_MAX_STEPS",
    "MAX_T",
    "simulate",
    "simulate_steady",
    "jit_compile",
    "energy_drift",
    "oscillation_frequency",
    "growth_rate",
    "fit_circle",
    "TheoryComparison",
    "compare_with_theory",
    "LINEAR_RANGE",
    "COULOMB_STATE",
    "MODE_NAMES",
    "coulomb_rhs",
    "coulomb_contact",
    "coulomb_energy",
    "rolling_state",
    "Coulomb",
    "RollingResistance",
    "PivotFriction",
    "AirDrag",
    "angular_velocity_xyz",
    "simulate_coulomb",
    "simulate_to_rest",
    "toss",
    "toss_ensemble",
    "slip_direction",
    "energy_balance",
    "DISSIPATION_TERMS",
]

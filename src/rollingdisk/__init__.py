"""rollingdisk: a rigid disk of finite thickness rolling, sliding, bouncing and coming to rest
on a horizontal plane.

Implements and checks M. Batista, "Steady Motion of a Rigid Disk of Finite Thickness on a
Horizontal Plane": equations of motion on rough and smooth ground (section 2), steady
motions (section 3) and their stability (section 4); beyond the paper real ground (Coulomb
friction), motion past the guards (flight, impacts, rest), exact motions by quadrature and
sweeps.  Dimensionless units m = a = g = 1 unless a disk carries a physical scale.

The package is layered (``docs/architecture.md``); each layer imports only those below it::

    util < model < theory < engine < results < ivp < phases < scenarios
         < {sweep, plotting, symbolic} < {atlas, explore} < cli

This module names the public API and where each name lives; a name is imported on first use
(PEP 562), so ``import rollingdisk`` loads neither numpy, scipy, numba, sympy nor matplotlib.
"""

import sys as _sys

from rollingdisk._moved import MOVED as _MOVED
from rollingdisk._moved import OLD_PACKAGES as _OLD_PACKAGES
from rollingdisk.util.lazy import MovedModules as _MovedModules
from rollingdisk.util.lazy import attach as _attach

#: Every public name -> the subpackage that names it in its own table, which says the module
#: that defines it (or, where no subpackage table names it, that module); the order is
#: ``__all__``'s.
_EXPORTS = {
    "ParameterError": "rollingdisk.util",
    "ParameterTypeError": "rollingdisk.util",
    "Disk": "rollingdisk.model",
    "DEFAULT_H": "rollingdisk.model",
    "GROUNDS": "rollingdisk.model",
    "H_MAX": "rollingdisk.model",
    "ROUGH_STATE": "rollingdisk.model",
    "SMOOTH_STATE": "rollingdisk.model",
    "state_names": "rollingdisk.model",
    "state_index": "rollingdisk.model",
    "equations_of_motion": "rollingdisk.model",
    "omega_dot": "rollingdisk.model",
    "contact_force": "rollingdisk.model",
    "energy": "rollingdisk.model",
    "contact_point": "rollingdisk.model",
    "velocity_of_C": "rollingdisk.model",
    "rounded_steady_motion": "rollingdisk.theory",
    "rounded_varpi2": "rollingdisk.theory",
    "rounded_thresholds": "rollingdisk.theory",
    "parse_length": "rollingdisk.model.units",
    "parse_mass": "rollingdisk.model.units",
    "parse_acceleration": "rollingdisk.model.units",
    "NamedDisk": "rollingdisk.model.units",
    "DISKS": "rollingdisk.model.units",
    "disk_from_options": "rollingdisk.model.units",
    "si_fields": "rollingdisk.model.units",
    "NoSteadyMotion": "rollingdisk.theory",
    "SteadyMotion": "rollingdisk.theory",
    "steady_motion": "rollingdisk.theory",
    "straight_line": "rollingdisk.theory",
    "Omega0_sq": "rollingdisk.theory",
    "r_C_star": "rollingdisk.theory",
    "se_circle_radius": "rollingdisk.theory",
    "mu_required_map": "rollingdisk.theory",
    "Stability": "rollingdisk.theory",
    "stability": "rollingdisk.theory",
    "varpi2_closed_form": "rollingdisk.theory",
    "varpi2_linearized": "rollingdisk.theory",
    "reduced_jacobian": "rollingdisk.theory",
    "varpi2_circle": "rollingdisk.theory",
    "varpi2_rough_rC": "rollingdisk.theory",
    "circle_coefficients": "rollingdisk.theory",
    "critical_omega30_sq": "rollingdisk.theory",
    "stable_for_all_omega30": "rollingdisk.theory",
    "Thresholds": "rollingdisk.theory",
    "thresholds": "rollingdisk.theory",
    "NO_MOTION": "rollingdisk.theory",
    "UNSTABLE": "rollingdisk.theory",
    "STABLE": "rollingdisk.theory",
    "existence_codes": "rollingdisk.theory",
    "varpi2_zero_surface": "rollingdisk.theory",
    "ExampleMotions": "rollingdisk.theory",
    "example_motions": "rollingdisk.theory",
    "ExactMotion": "rollingdisk.theory",
    "exact_motion": "rollingdisk.theory",
    "exact_steady": "rollingdisk.theory",
    "Trajectory": "rollingdisk.results",
    "Transition": "rollingdisk.results",
    "GuardEvent": "rollingdisk.model",
    "LiftOff": "rollingdisk.model",
    "EdgeContact": "rollingdisk.model",
    "FellFlat": "rollingdisk.model",
    "GUARDS": "rollingdisk.model",
    "STATUSES": "rollingdisk.model",
    "guard_events": "rollingdisk.model",
    "DEFAULT_RTOL": "rollingdisk.ivp",
    "DEFAULT_ATOL": "rollingdisk.ivp",
    "DEFAULT_MAX_STEPS": "rollingdisk.ivp",
    "MAX_T": "rollingdisk.ivp",
    "simulate": "rollingdisk.ivp",
    "simulate_steady": "rollingdisk.ivp",
    "jit_compile": "rollingdisk.engine",
    "energy_drift": "rollingdisk.results",
    "oscillation_frequency": "rollingdisk.results",
    "growth_rate": "rollingdisk.results",
    "fit_circle": "rollingdisk.results",
    "TheoryComparison": "rollingdisk.results",
    "compare_with_theory": "rollingdisk.results",
    "LINEAR_RANGE": "rollingdisk.results",
    "COULOMB_STATE": "rollingdisk.model",
    "MODE_NAMES": "rollingdisk.model",
    "coulomb_rhs": "rollingdisk.model",
    "coulomb_contact": "rollingdisk.model",
    "coulomb_energy": "rollingdisk.model",
    "rolling_state": "rollingdisk.model",
    "Coulomb": "rollingdisk.model",
    "RollingResistance": "rollingdisk.model",
    "PivotFriction": "rollingdisk.model",
    "AirDrag": "rollingdisk.model",
    "angular_velocity_xyz": "rollingdisk.model",
    "simulate_coulomb": "rollingdisk.ivp",
    "simulate_to_rest": "rollingdisk.phases",
    "toss": "rollingdisk.scenarios.toss",
    "toss_ensemble": "rollingdisk.scenarios",
    "edge_odds": "rollingdisk.scenarios",
    "slip_direction": "rollingdisk.ivp",
    "energy_balance": "rollingdisk.ivp",
    "DISSIPATION_TERMS": "rollingdisk.ivp",
}

__getattr__, __dir__, __all__ = _attach(__name__, _EXPORTS)
_lazy_getattr = __getattr__


def __getattr__(name):  # noqa: F811 - also reads the version from the metadata on first use
    if name == "__version__":
        from importlib.metadata import PackageNotFoundError, version

        try:
            value = version("rollingdisk")
        except PackageNotFoundError:  # a source tree that was never installed
            value = "0+unknown"
        globals()["__version__"] = value
        return value
    return _lazy_getattr(name)


if not any(isinstance(f, _MovedModules) for f in _sys.meta_path):
    _sys.meta_path.append(_MovedModules(_MOVED, _OLD_PACKAGES))

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

#: Every public name -> the module that defines it (the order is ``__all__``'s).
_EXPORTS = {
    "ParameterError": "rollingdisk.util.errors",
    "ParameterTypeError": "rollingdisk.util.errors",
    "Disk": "rollingdisk.model.disk",
    "DEFAULT_H": "rollingdisk.model.disk",
    "GROUNDS": "rollingdisk.model.disk",
    "H_MAX": "rollingdisk.model.disk",
    "ROUGH_STATE": "rollingdisk.model.state",
    "SMOOTH_STATE": "rollingdisk.model.state",
    "state_names": "rollingdisk.model.state",
    "state_index": "rollingdisk.model.state",
    "equations_of_motion": "rollingdisk.model.equations",
    "omega_dot": "rollingdisk.model.equations",
    "contact_force": "rollingdisk.model.equations",
    "energy": "rollingdisk.model.equations",
    "contact_point": "rollingdisk.model.equations",
    "velocity_of_C": "rollingdisk.model.equations",
    "parse_length": "rollingdisk.model.units",
    "parse_mass": "rollingdisk.model.units",
    "parse_acceleration": "rollingdisk.model.units",
    "NamedDisk": "rollingdisk.model.units",
    "DISKS": "rollingdisk.model.units",
    "disk_from_options": "rollingdisk.model.units",
    "si_fields": "rollingdisk.model.units",
    "NoSteadyMotion": "rollingdisk.theory.steady",
    "SteadyMotion": "rollingdisk.theory.steady",
    "steady_motion": "rollingdisk.theory.steady",
    "straight_line": "rollingdisk.theory.steady",
    "Omega0_sq": "rollingdisk.theory.steady",
    "r_C_star": "rollingdisk.theory.steady",
    "se_circle_radius": "rollingdisk.theory.steady",
    "mu_required_map": "rollingdisk.theory.steady",
    "Stability": "rollingdisk.theory.oscillations",
    "stability": "rollingdisk.theory.oscillations",
    "varpi2_closed_form": "rollingdisk.theory.oscillations",
    "varpi2_linearized": "rollingdisk.theory.oscillations",
    "reduced_jacobian": "rollingdisk.theory.oscillations",
    "varpi2_circle": "rollingdisk.theory.oscillations",
    "varpi2_rough_rC": "rollingdisk.theory.oscillations",
    "circle_coefficients": "rollingdisk.theory.oscillations",
    "critical_omega30_sq": "rollingdisk.theory.oscillations",
    "stable_for_all_omega30": "rollingdisk.theory.oscillations",
    "Thresholds": "rollingdisk.theory.oscillations",
    "thresholds": "rollingdisk.theory.oscillations",
    "NO_MOTION": "rollingdisk.theory.regions",
    "UNSTABLE": "rollingdisk.theory.regions",
    "STABLE": "rollingdisk.theory.regions",
    "existence_codes": "rollingdisk.theory.regions",
    "varpi2_zero_surface": "rollingdisk.theory.regions",
    "ExampleMotions": "rollingdisk.theory.regions",
    "example_motions": "rollingdisk.theory.regions",
    "ExactMotion": "rollingdisk.theory.exact",
    "exact_motion": "rollingdisk.theory.exact",
    "exact_steady": "rollingdisk.theory.exact",
    "Trajectory": "rollingdisk.results.trajectory",
    "Transition": "rollingdisk.results.trajectory",
    "GuardEvent": "rollingdisk.model.events",
    "LiftOff": "rollingdisk.model.events",
    "EdgeContact": "rollingdisk.model.events",
    "FellFlat": "rollingdisk.model.events",
    "GUARDS": "rollingdisk.model.events",
    "STATUSES": "rollingdisk.model.events",
    "guard_events": "rollingdisk.model.events",
    "DEFAULT_RTOL": "rollingdisk.ivp.simulation",
    "DEFAULT_ATOL": "rollingdisk.ivp.simulation",
    "DEFAULT_MAX_STEPS": "rollingdisk.ivp.simulation",
    "MAX_T": "rollingdisk.ivp.simulation",
    "simulate": "rollingdisk.ivp.simulation",
    "simulate_steady": "rollingdisk.ivp.simulation",
    "jit_compile": "rollingdisk.engine.jit",
    "energy_drift": "rollingdisk.results.measure",
    "oscillation_frequency": "rollingdisk.results.measure",
    "growth_rate": "rollingdisk.results.measure",
    "fit_circle": "rollingdisk.results.measure",
    "TheoryComparison": "rollingdisk.results.measure",
    "compare_with_theory": "rollingdisk.results.measure",
    "LINEAR_RANGE": "rollingdisk.results.measure",
    "COULOMB_STATE": "rollingdisk.model.coulomb",
    "MODE_NAMES": "rollingdisk.model.coulomb",
    "coulomb_rhs": "rollingdisk.model.coulomb",
    "coulomb_contact": "rollingdisk.model.coulomb",
    "coulomb_energy": "rollingdisk.model.coulomb",
    "rolling_state": "rollingdisk.model.coulomb",
    "Coulomb": "rollingdisk.model.ground",
    "RollingResistance": "rollingdisk.model.ground",
    "PivotFriction": "rollingdisk.model.ground",
    "AirDrag": "rollingdisk.model.ground",
    "angular_velocity_xyz": "rollingdisk.model.ground",
    "simulate_coulomb": "rollingdisk.ivp.hybrid",
    "simulate_to_rest": "rollingdisk.phases.motion",
    "toss": "rollingdisk.scenarios.toss",
    "toss_ensemble": "rollingdisk.scenarios.toss",
    "slip_direction": "rollingdisk.ivp.hybrid",
    "energy_balance": "rollingdisk.ivp.hybrid",
    "DISSIPATION_TERMS": "rollingdisk.ivp.hybrid",
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

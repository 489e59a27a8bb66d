"""The model of the disk (section 2 of the paper and the contact laws beyond it): the disk,
its state layouts, contact geometry, the equations of motion on the ideal grounds, the guards
where a phase of motion ends, the ground laws (Coulomb friction, rolling resistance, pivoting
friction, air) and their kernels, and how a run ends (``outcomes``).

The lowest layer of the physics: numpy only (no scipy, no numba).
"""

from rollingdisk.util.lazy import attach as _attach

__getattr__, __dir__, __all__ = _attach(__name__, {
    "Disk": "rollingdisk.model.disk",
    "DEFAULT_H": "rollingdisk.model.disk",
    "GROUNDS": "rollingdisk.model.disk",
    "H_MAX": "rollingdisk.model.disk",
    "STANDARD_GRAVITY": "rollingdisk.model.disk",
    "check_ground": "rollingdisk.model.disk",
    "check_h": "rollingdisk.model.disk",
    "ROUGH_STATE": "rollingdisk.model.state",
    "SMOOTH_STATE": "rollingdisk.model.state",
    "state_names": "rollingdisk.model.state",
    "state_index": "rollingdisk.model.state",
    "h_tilde": "rollingdisk.model.geometry",
    "equations_of_motion": "rollingdisk.model.equations",
    "omega_dot": "rollingdisk.model.equations",
    "contact_force": "rollingdisk.model.equations",
    "energy": "rollingdisk.model.equations",
    "contact_point": "rollingdisk.model.equations",
    "velocity_of_C": "rollingdisk.model.equations",
    "GuardEvent": "rollingdisk.model.events",
    "LiftOff": "rollingdisk.model.events",
    "EdgeContact": "rollingdisk.model.events",
    "FellFlat": "rollingdisk.model.events",
    "GUARDS": "rollingdisk.model.events",
    "STATUSES": "rollingdisk.model.events",
    "guard_events": "rollingdisk.model.events",
    "Coulomb": "rollingdisk.model.ground",
    "RollingResistance": "rollingdisk.model.ground",
    "PivotFriction": "rollingdisk.model.ground",
    "AirDrag": "rollingdisk.model.ground",
    "check_any_ground": "rollingdisk.model.ground",
    "ground_name": "rollingdisk.model.ground",
    "angular_velocity_xyz": "rollingdisk.model.ground",
    "COULOMB_STATE": "rollingdisk.model.coulomb",
    "MODE_NAMES": "rollingdisk.model.coulomb",
    "coulomb_rhs": "rollingdisk.model.coulomb",
    "coulomb_contact": "rollingdisk.model.coulomb",
    "coulomb_energy": "rollingdisk.model.coulomb",
    "rolling_state": "rollingdisk.model.coulomb",
})

"""rollingdisk: a rigid disk of finite thickness rolling or sliding on a horizontal plane.

Implements and checks M. Batista, "Steady Motion of a Rigid Disk of Finite Thickness on a
Horizontal Plane": equations of motion on rough and smooth ground (section 2), steady
motions (section 3) and their stability (section 4).  Dimensionless units m = a = g = 1.

The numeric core (``disk``, ``equations``, ``steady``, ``stability``, ``simulate``) imports
only numpy and scipy (and numba, lazily, when the integrator first runs); ``symbolic``,
``plotting``, ``figures``, ``animation``, ``atlas`` and ``cli`` are the edges that use it.
"""

from .disk import GROUNDS, Disk
from .equations import (
    ROUGH_STATE,
    SMOOTH_STATE,
    contact_force,
    contact_point,
    energy,
    equations_of_motion,
    omega_dot,
    state_index,
    state_names,
    velocity_of_C,
)
from .simulate import Trajectory, simulate, simulate_steady
from .stability import Stability, Thresholds, stability, thresholds, varpi2_linearized
from .steady import NoSteadyMotion, SteadyMotion, steady_motion, straight_line

__version__ = "0.1.0"

__all__ = [
    "Disk",
    "GROUNDS",
    "ROUGH_STATE",
    "SMOOTH_STATE",
    "contact_force",
    "contact_point",
    "energy",
    "equations_of_motion",
    "omega_dot",
    "state_index",
    "state_names",
    "velocity_of_C",
    "NoSteadyMotion",
    "SteadyMotion",
    "steady_motion",
    "straight_line",
    "Stability",
    "Thresholds",
    "stability",
    "thresholds",
    "varpi2_linearized",
    "Trajectory",
    "simulate",
    "simulate_steady",
]

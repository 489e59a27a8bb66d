"""Simulation: the integrators (DOP853 and Taylor, compiled or not), guard events, the
:class:`Trajectory` they return and the measurements made on it.

The only layer that imports numba (lazily: ``import rollingdisk`` does not load it).
"""

from rollingdisk.integrate.events import (
    GUARDS as GUARDS,
)
from rollingdisk.integrate.events import (
    STATUSES as STATUSES,
)
from rollingdisk.integrate.events import (
    EdgeContact as EdgeContact,
)
from rollingdisk.integrate.events import (
    FellFlat as FellFlat,
)
from rollingdisk.integrate.events import (
    GuardEvent as GuardEvent,
)
from rollingdisk.integrate.events import (
    LiftOff as LiftOff,
)
from rollingdisk.integrate.events import (
    guard_events as guard_events,
)
from rollingdisk.integrate.jit import (
    jit_compile as jit_compile,
)
from rollingdisk.integrate.measure import (
    LINEAR_RANGE as LINEAR_RANGE,
)
from rollingdisk.integrate.measure import (
    TheoryComparison as TheoryComparison,
)
from rollingdisk.integrate.measure import (
    compare_with_theory as compare_with_theory,
)
from rollingdisk.integrate.measure import (
    energy_drift as energy_drift,
)
from rollingdisk.integrate.measure import (
    fit_circle as fit_circle,
)
from rollingdisk.integrate.measure import (
    growth_rate as growth_rate,
)
from rollingdisk.integrate.measure import (
    oscillation_frequency as oscillation_frequency,
)
from rollingdisk.integrate.simulation import (
    DEFAULT_ATOL as DEFAULT_ATOL,
)
from rollingdisk.integrate.simulation import (
    DEFAULT_MAX_STEPS as DEFAULT_MAX_STEPS,
)
from rollingdisk.integrate.simulation import (
    DEFAULT_RTOL as DEFAULT_RTOL,
)
from rollingdisk.integrate.simulation import (
    MAX_T as MAX_T,
)
from rollingdisk.integrate.simulation import (
    simulate as simulate,
)
from rollingdisk.integrate.simulation import (
    simulate_steady as simulate_steady,
)
from rollingdisk.integrate.trajectory import (
    Trajectory as Trajectory,
)
from rollingdisk.integrate.trajectory import (
    Transition as Transition,
)

__all__ = [
    "DEFAULT_RTOL",
    "DEFAULT_ATOL",
    "DEFAULT_MAX_STEPS",
    "MAX_T",
    "simulate",
    "simulate_steady",
    "jit_compile",
    "GuardEvent",
    "LiftOff",
    "EdgeContact",
    "FellFlat",
    "GUARDS",
    "STATUSES",
    "guard_events",
    "Trajectory",
    "Transition",
    "energy_drift",
    "oscillation_frequency",
    "growth_rate",
    "fit_circle",
    "TheoryComparison",
    "compare_with_theory",
    "LINEAR_RANGE",
]

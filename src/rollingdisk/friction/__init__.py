"""Real ground: Coulomb friction with its contact moments, the hybrid rolling/sliding
simulation, and Euler's disk run to its end.
"""

from rollingdisk.friction.coulomb import (
    COULOMB_STATE as COULOMB_STATE,
)
from rollingdisk.friction.coulomb import (
    MODE_NAMES as MODE_NAMES,
)
from rollingdisk.friction.coulomb import (
    coulomb_contact as coulomb_contact,
)
from rollingdisk.friction.coulomb import (
    coulomb_energy as coulomb_energy,
)
from rollingdisk.friction.coulomb import (
    coulomb_rhs as coulomb_rhs,
)
from rollingdisk.friction.coulomb import (
    rolling_state as rolling_state,
)
from rollingdisk.friction.euler_disk import (
    AIR_VISCOSITY as AIR_VISCOSITY,
)
from rollingdisk.friction.euler_disk import (
    END_KINDS as END_KINDS,
)
from rollingdisk.friction.euler_disk import (
    FIT_WINDOW as FIT_WINDOW,
)
from rollingdisk.friction.euler_disk import (
    FIT_WINDOW_AIR as FIT_WINDOW_AIR,
)
from rollingdisk.friction.euler_disk import (
    EulerDisk as EulerDisk,
)
from rollingdisk.friction.euler_disk import (
    EulerDiskResult as EulerDiskResult,
)
from rollingdisk.friction.euler_disk import (
    creep_factor as creep_factor,
)
from rollingdisk.friction.euler_disk import (
    predicted_end_time as predicted_end_time,
)
from rollingdisk.friction.euler_disk import (
    predicted_exponents as predicted_exponents,
)
from rollingdisk.friction.euler_disk import (
    run_euler_disk as run_euler_disk,
)
from rollingdisk.friction.ground import (
    AirDrag as AirDrag,
)
from rollingdisk.friction.ground import (
    Coulomb as Coulomb,
)
from rollingdisk.friction.ground import (
    PivotFriction as PivotFriction,
)
from rollingdisk.friction.ground import (
    RollingResistance as RollingResistance,
)
from rollingdisk.friction.ground import (
    angular_velocity_xyz as angular_velocity_xyz,
)
from rollingdisk.friction.ground import (
    check_any_ground as check_any_ground,
)
from rollingdisk.friction.ground import (
    ground_name as ground_name,
)
from rollingdisk.friction.hybrid import (
    DISSIPATION_TERMS as DISSIPATION_TERMS,
)
from rollingdisk.friction.hybrid import (
    energy_balance as energy_balance,
)
from rollingdisk.friction.hybrid import (
    simulate_coulomb as simulate_coulomb,
)
from rollingdisk.friction.hybrid import (
    slip_direction as slip_direction,
)
from rollingdisk.friction.motion import (
    simulate_to_rest as simulate_to_rest,
)
from rollingdisk.friction.toss import (
    toss as toss,
)
from rollingdisk.friction.toss import (
    toss_ensemble as toss_ensemble,
)

__all__ = [
    "Coulomb",
    "RollingResistance",
    "PivotFriction",
    "AirDrag",
    "check_any_ground",
    "ground_name",
    "angular_velocity_xyz",
    "COULOMB_STATE",
    "MODE_NAMES",
    "coulomb_rhs",
    "coulomb_contact",
    "coulomb_energy",
    "rolling_state",
    "simulate_coulomb",
    "simulate_to_rest",
    "toss",
    "toss_ensemble",
    "slip_direction",
    "energy_balance",
    "DISSIPATION_TERMS",
    "EulerDisk",
    "EulerDiskResult",
    "run_euler_disk",
    "predicted_exponents",
    "creep_factor",
    "predicted_end_time",
    "END_KINDS",
    "AIR_VISCOSITY",
    "FIT_WINDOW",
    "FIT_WINDOW_AIR",
]

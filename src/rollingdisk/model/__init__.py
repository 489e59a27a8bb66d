"""Section 2 of the paper: the disk, its state layouts, contact geometry and equations of motion.

The lowest layer of the theory: numpy only (no scipy, no numba).
"""

from rollingdisk.model.disk import (
    DEFAULT_H as DEFAULT_H,
)
from rollingdisk.model.disk import (
    GROUNDS as GROUNDS,
)
from rollingdisk.model.disk import (
    H_MAX as H_MAX,
)
from rollingdisk.model.disk import (
    STANDARD_GRAVITY as STANDARD_GRAVITY,
)
from rollingdisk.model.disk import (
    Disk as Disk,
)
from rollingdisk.model.disk import (
    check_ground as check_ground,
)
from rollingdisk.model.disk import (
    check_h as check_h,
)
from rollingdisk.model.equations import (
    contact_force as contact_force,
)
from rollingdisk.model.equations import (
    contact_point as contact_point,
)
from rollingdisk.model.equations import (
    energy as energy,
)
from rollingdisk.model.equations import (
    equations_of_motion as equations_of_motion,
)
from rollingdisk.model.equations import (
    omega_dot as omega_dot,
)
from rollingdisk.model.equations import (
    velocity_of_C as velocity_of_C,
)
from rollingdisk.model.geometry import (
    h_tilde as h_tilde,
)
from rollingdisk.model.state import (
    ROUGH_STATE as ROUGH_STATE,
)
from rollingdisk.model.state import (
    SMOOTH_STATE as SMOOTH_STATE,
)
from rollingdisk.model.state import (
    state_index as state_index,
)
from rollingdisk.model.state import (
    state_names as state_names,
)

__all__ = [
    "Disk",
    "DEFAULT_H",
    "GROUNDS",
    "H_MAX",
    "STANDARD_GRAVITY",
    "check_ground",
    "check_h",
    "ROUGH_STATE",
    "SMOOTH_STATE",
    "state_names",
    "state_index",
    "h_tilde",
    "equations_of_motion",
    "omega_dot",
    "contact_force",
    "energy",
    "contact_point",
    "velocity_of_C",
]

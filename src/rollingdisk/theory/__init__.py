"""Sections 3 and 4 of the paper: steady motions, small oscillations and stability, the
regions where steady motions exist and are stable, and exact motions by quadrature.
"""

from rollingdisk.theory.exact import (
    EXACT_STATUSES as EXACT_STATUSES,
)
from rollingdisk.theory.exact import (
    Backbone as Backbone,
)
from rollingdisk.theory.exact import (
    ExactMotion as ExactMotion,
)
from rollingdisk.theory.exact import (
    backbone as backbone,
)
from rollingdisk.theory.exact import (
    exact_motion as exact_motion,
)
from rollingdisk.theory.exact import (
    exact_steady as exact_steady,
)
from rollingdisk.theory.exact import (
    thin_disk_omega3 as thin_disk_omega3,
)
from rollingdisk.theory.oscillations import (
    Stability as Stability,
)
from rollingdisk.theory.oscillations import (
    Thresholds as Thresholds,
)
from rollingdisk.theory.oscillations import (
    circle_coefficients as circle_coefficients,
)
from rollingdisk.theory.oscillations import (
    critical_omega30_sq as critical_omega30_sq,
)
from rollingdisk.theory.oscillations import (
    reduced_jacobian as reduced_jacobian,
)
from rollingdisk.theory.oscillations import (
    stability as stability,
)
from rollingdisk.theory.oscillations import (
    stable_for_all_omega30 as stable_for_all_omega30,
)
from rollingdisk.theory.oscillations import (
    thresholds as thresholds,
)
from rollingdisk.theory.oscillations import (
    varpi2_circle as varpi2_circle,
)
from rollingdisk.theory.oscillations import (
    varpi2_closed_form as varpi2_closed_form,
)
from rollingdisk.theory.oscillations import (
    varpi2_linearized as varpi2_linearized,
)
from rollingdisk.theory.oscillations import (
    varpi2_rough_rC as varpi2_rough_rC,
)
from rollingdisk.theory.regions import (
    NO_MOTION as NO_MOTION,
)
from rollingdisk.theory.regions import (
    STABLE as STABLE,
)
from rollingdisk.theory.regions import (
    UNSTABLE as UNSTABLE,
)
from rollingdisk.theory.regions import (
    ExampleMotions as ExampleMotions,
)
from rollingdisk.theory.regions import (
    example_motions as example_motions,
)
from rollingdisk.theory.regions import (
    existence_codes as existence_codes,
)
from rollingdisk.theory.regions import (
    varpi2_zero_surface as varpi2_zero_surface,
)
from rollingdisk.theory.steady import (
    NoSteadyMotion as NoSteadyMotion,
)
from rollingdisk.theory.steady import (
    Omega0_sq as Omega0_sq,
)
from rollingdisk.theory.steady import (
    SteadyMotion as SteadyMotion,
)
from rollingdisk.theory.steady import (
    mu_required_map as mu_required_map,
)
from rollingdisk.theory.steady import (
    r_C_star as r_C_star,
)
from rollingdisk.theory.steady import (
    se_circle_radius as se_circle_radius,
)
from rollingdisk.theory.steady import (
    steady_motion as steady_motion,
)
from rollingdisk.theory.steady import (
    straight_line as straight_line,
)

__all__ = [
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
    "Backbone",
    "backbone",
    "thin_disk_omega3",
    "EXACT_STATUSES",
]

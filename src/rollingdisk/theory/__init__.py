"""Sections 3 and 4 of the paper: steady motions, small oscillations and stability, the
regions where steady motions exist and are stable, and exact motions by quadrature.
"""

from rollingdisk.util.lazy import attach as _attach

__getattr__, __dir__, __all__ = _attach(__name__, {
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
    "Backbone": "rollingdisk.theory.exact",
    "backbone": "rollingdisk.theory.exact",
    "thin_disk_omega3": "rollingdisk.theory.exact",
    "EXACT_STATUSES": "rollingdisk.theory.exact",
})

"""The disk's initial-value problems on each ground: :func:`simulate` on rough and smooth
ground (the paper's equations, stopped at the guards) and :func:`simulate_coulomb` on
Coulomb ground (rolling and sliding, transitions located), with their drivers; the disk
with a rounded rim by :func:`simulate_rounded` (a model of the engine's contract).
"""

from rollingdisk.util.lazy import attach as _attach

__getattr__, __dir__, __all__ = _attach(__name__, {
    "DEFAULT_RTOL": "rollingdisk.ivp.simulation",
    "DEFAULT_ATOL": "rollingdisk.ivp.simulation",
    "DEFAULT_MAX_STEPS": "rollingdisk.ivp.simulation",
    "MAX_T": "rollingdisk.ivp.simulation",
    "simulate": "rollingdisk.ivp.simulation",
    "simulate_steady": "rollingdisk.ivp.simulation",
    "simulate_coulomb": "rollingdisk.ivp.hybrid",
    "simulate_rounded": "rollingdisk.ivp.rounded",
    "simulate_rounded_steady": "rollingdisk.ivp.rounded",
    "RoundedTrajectory": "rollingdisk.ivp.rounded",
    "energy_balance": "rollingdisk.ivp.hybrid",
    "DISSIPATION_TERMS": "rollingdisk.ivp.hybrid",
    "slip_direction": "rollingdisk.ivp.hybrid",
})

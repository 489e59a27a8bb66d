"""Motion past the guards: free flight, impacts (Glocker's Newton-Coulomb law), rim changes,
rocking, falling flat and the flat disk sliding to rest, chained by :func:`simulate_to_rest`.
"""

from rollingdisk.util.lazy import attach as _attach

__getattr__, __dir__, __all__ = _attach(__name__, {
    "simulate_to_rest": "rollingdisk.phases.motion",
})

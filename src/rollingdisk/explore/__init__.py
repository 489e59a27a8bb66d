"""An interactive explorer of steady motions in the web browser (``rollingdisk explore``).

A map of where steady circles exist and are stable (in the ``(theta0, omega30)``,
``(theta0, Omega0)`` or ``(theta0, r_C)`` plane), a click on it for the steady motion's
numbers (``Omega0, omega20, omega30, r_C, r_P, varpi^2``, period, the least friction to
roll), a friction slider showing where Coulomb ground with that ``mu`` lets the motion
roll, and a 3D view of the kicked motion simulated, playable and rotatable.

Served by the standard library's HTTP server from files shipped in the package: it works
offline and adds no dependency (see :mod:`.server` for why).

Examples
--------
>>> from rollingdisk.explore import explore
>>> explore(h=0.17, ground="rough")     # doctest: +SKIP
"""

from rollingdisk.util.lazy import attach as _attach

__getattr__, __dir__, __all__ = _attach(__name__, {
    "explore": "rollingdisk.explore.server",
    "make_server": "rollingdisk.explore.server",
    "ExplorerServer": "rollingdisk.explore.server",
})

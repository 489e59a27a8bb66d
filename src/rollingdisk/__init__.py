"""rollingdisk: a rigid disk of finite thickness rolling or sliding on a horizontal plane.

Implements and checks M. Batista, "Steady Motion of a Rigid Disk of Finite Thickness on a
Horizontal Plane": equations of motion on rough and smooth ground (section 2), steady
motions (section 3) and their stability (section 4).  Dimensionless units m = a = g = 1.

The numeric core (``disk``, ``equations``, ``steady``, ``_stability``, ``regions``,
``trajectory``, ``events``, ``_simulate``, ``measure``) imports only numpy and scipy (and
numba, lazily, when the integrator first runs); ``symbolic``, ``plotting``, ``figures``,
``animation``, ``atlas`` and ``cli`` are the edges that use it.
"""

from . import (
    _hybrid,
    _simulate,
    _stability,
    disk,
    equations,
    errors,
    events,
    ground,
    measure,
    regions,
    steady,
    trajectory,
)
from ._hybrid import *  # noqa: F403
from ._simulate import *  # noqa: F403
from ._stability import *  # noqa: F403
from .disk import *  # noqa: F403
from .equations import *  # noqa: F403
from .errors import *  # noqa: F403
from .events import *  # noqa: F403
from .ground import *  # noqa: F403
from .measure import *  # noqa: F403
from .regions import *  # noqa: F403
from .steady import *  # noqa: F403
from .trajectory import *  # noqa: F403

__version__ = "0.1.0"

__all__ = [*errors.__all__, *disk.__all__, *equations.__all__, *steady.__all__,
           *_stability.__all__, *regions.__all__, *trajectory.__all__, *events.__all__,
           *_simulate.__all__, *measure.__all__, *ground.__all__, *_hybrid.__all__]
del _simulate, _stability, _hybrid

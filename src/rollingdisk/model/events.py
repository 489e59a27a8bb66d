"""Guard events: where the model of a disk touching the plane at one rim point ends.

The equations of motion hold only while the disk touches the plane at one point of its
rim edge.  :func:`rollingdisk.simulate` stops, never integrates through, at the first of
these events (defined once here; the compiled integrator evaluates the same quantities by
the integer :attr:`GuardEvent.index`, and reports them by :attr:`GuardEvent.code`):

:class:`LiftOff` (``"lift-off"``)
    the normal force ``F_z`` of eq. (11) reaches 0: the disk leaves the plane;
:class:`EdgeContact` (``"edge-contact"``)
    ``theta`` reaches 0 while ``h > 0``: the disk lands on its other rim edge, an impact
    outside the model (for ``h = 0`` it passes through ``theta = 0`` smoothly and this guard
    is off);
:class:`FellFlat` (``"fell-flat"``)
    ``|theta|`` reaches ``pi/2``: the disk lies on the plane.

Each guard is a callable ``event(t, y)`` with ``terminal`` and ``direction`` attributes, as
:func:`scipy.integrate.solve_ivp` expects, positive while the motion is admissible.  Both
integrators locate guards on the DOP853 dense output inside every step (not only at step
ends), so a guard that dips below 0 and back within one step is still found.  When two
guards fire in one step the earliest wins; at the same instant an edge contact wins over
a lift-off (``F_z`` is evaluated with the ``h~`` of the side the motion started on, so the
jump of ``h~ = h sgn(theta)`` at ``theta = 0`` is no lift-off).

A later kind of event (a transition between contact modes) is another subclass with its
own ``index`` and ``code``.
"""

from __future__ import annotations

import math

import numpy as np

from rollingdisk.model.disk import Disk, check_ground
from rollingdisk.model.equations import _check_disk, _side_normal_force
from rollingdisk.model.outcomes import (  # noqa: F401 - the codes, for the kernels
    COMPLETED,
    EDGE_CONTACT,
    FAILED,
    FELL_FLAT,
    LIFT_OFF,
    RUNNING,
    STEP_BUDGET,
    TIME_BUDGET,
    names,
    outcome,
)
from rollingdisk.model.state import _reduced_state, state_index, state_names
from rollingdisk.util.checks import check_real, real_array
from rollingdisk.util.errors import ParameterError

__all__ = ["GuardEvent", "LiftOff", "EdgeContact", "FellFlat", "GUARDS", "STATUSES",
           "guard_events"]

#: Possible values of :attr:`rollingdisk.Trajectory.status` (see :mod:`rollingdisk.model.outcomes`).
STATUSES = names(COMPLETED, LIFT_OFF, EDGE_CONTACT, FELL_FLAT, FAILED, STEP_BUDGET,
                 TIME_BUDGET)
STATUS_OF_CODE = {outcome(s).code: s for s in STATUSES}


class GuardEvent:
    """A guard event of a disk on a ground (base class; use a subclass).

    Parameters
    ----------
    disk : Disk
        The disk.
    ground : {"rough", "smooth"}
        The ground.
    side : {1.0, -1.0}
        ``sgn(theta)`` on the side of ``theta = 0`` the motion starts on (default 1).

    Attributes
    ----------
    name : str
        The status of a run it ends (``"lift-off"``, ...).
    index : int
        Position of its value in the compiled guard vector (``_numba_core._guards``).
    code : int
        Status code of the compiled integrator.
    terminal : bool
        Always True: the model ends there.
    direction : float
        As in ``solve_ivp``: -1 (the value falls through 0) or 0 (either way).
    """

    name = ""
    index = -1
    code = -1
    terminal = True
    direction = -1.0

    def __init__(self, disk: Disk, ground: str, side: float = 1.0):
        self.disk = _check_disk(disk)
        self.ground = check_ground(ground)
        self.rough = self.ground == "rough"
        self.side = 1.0 if check_real("side", side) >= 0 else -1.0
        self.i_theta = state_index(self.ground, "theta")

    def __call__(self, t: float, y) -> float:
        """The guard's value at state ``y``: positive while the motion is admissible."""
        raise NotImplementedError

    @classmethod
    def message(cls, t: float, h: float) -> str:
        """What happened at time ``t`` to a disk of half-thickness ``h``, in words."""
        raise NotImplementedError

    def __repr__(self) -> str:
        return f"{type(self).__name__}(h={self.disk.h:g}, ground={self.ground!r})"

    @staticmethod
    def applies(disk: Disk) -> bool:
        """Whether this guard is on for ``disk``."""
        return True


class LiftOff(GuardEvent):
    """``F_z`` (eq. 11) reaches 0: the disk leaves the plane."""

    name, index, code, direction = "lift-off", 0, LIFT_OFF, -1.0

    def __call__(self, t, y):
        return float(_side_normal_force(self.rough, self.disk.h, np.asarray(y, dtype=float),
                                        self.side))

    @classmethod
    def message(cls, t, h):
        return (f"lift-off at t = {t:.12g}: the normal force F_z (eq. 11) reached 0 and the "
                "disk leaves the plane; the model ends here")


class EdgeContact(GuardEvent):
    """``theta`` reaches 0 with ``h > 0``: the disk lands on its other rim edge."""

    name, index, code, direction = "edge-contact", 1, EDGE_CONTACT, 0.0

    def __call__(self, t, y):
        return float(y[self.i_theta]) * self.side

    @classmethod
    def message(cls, t, h):
        return (f"edge contact at t = {t:.12g}: theta reached 0 with h = {h:g} > 0, "
                "the disk lands on its other rim edge (an impact, outside the model)")

    @staticmethod
    def applies(disk):
        return disk.h > 0


class FellFlat(GuardEvent):
    """``|theta|`` reaches ``pi/2``: the disk lies on the plane."""

    name, index, code, direction = "fell-flat", 2, FELL_FLAT, -1.0

    def __call__(self, t, y):
        return 0.5 * math.pi - abs(float(y[self.i_theta]))

    @classmethod
    def message(cls, t, h):
        return f"fell flat at t = {t:.12g}: |theta| reached pi/2, the disk lies on the plane"


#: The guard classes, in the order of the compiled guard vector.
GUARDS = (LiftOff, EdgeContact, FellFlat)


def guard_events(disk: Disk, ground: str, y0) -> list[GuardEvent]:
    """The guards that apply to ``disk`` started from state ``y0``, in the order of
    :data:`GUARDS` (ties between guards at one instant go to the edge contact).

    Parameters
    ----------
    disk : Disk
        The disk.
    ground : {"rough", "smooth"}
        The ground.
    y0 : array_like
        The initial state (its ``theta`` gives the side).

    Returns
    -------
    list of GuardEvent
        ``[LiftOff, EdgeContact, FellFlat]`` instances, ``EdgeContact`` only for ``h > 0``.
    """
    ground = check_ground(ground)
    y = real_array("y0", y0)
    n = len(state_names(ground))
    if y.shape[:1] not in ((n,), (4,)):
        raise ParameterError(f"y0 must have {n} components on {ground} ground (or the 4 of "
                             f"theta, omega1, omega2, omega3), got shape {y.shape}")
    theta = float(_reduced_state(ground == "rough", y)[0])
    side = 1.0 if theta >= 0 else -1.0
    return [g(disk, ground, side) for g in GUARDS if g.applies(disk)]


def event_message(code: int, t: float, h: float) -> str:
    """The message of the guard with status ``code`` firing at ``t`` (half-thickness ``h``)."""
    return next(g for g in GUARDS if g.code == code).message(t, h)

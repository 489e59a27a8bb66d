"""What a motion to rest returns (:func:`rollingdisk.phases.motion.simulate_to_rest`): its
result, the segments of flight and of the flat disk, the impacts and the mode changes.

Units m = a = g = 1.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from rollingdisk.model.disk import Disk
from rollingdisk.model.ground import Coulomb
from rollingdisk.phases.flight import (
    _state_energy,
    free_flight,
)

__all__ = ["MotionResult", "FlightSegment", "FlatSegment", "ModeChange", "ImpactRecord"]


@dataclass(frozen=True)
class ModeChange:
    """A change of phase at time ``t``: ``from_phase -> to_phase`` (names
    :data:`~rollingdisk.phases.motion.PHASES`)."""

    t: float
    from_phase: str
    to_phase: str

    def as_dict(self) -> dict:
        return {"t": self.t, "from": self.from_phase, "to": self.to_phase}


@dataclass(frozen=True)
class ImpactRecord:
    """One impact at time ``t``.

    Attributes
    ----------
    t : float
        Time [``sqrt(a/g)``].
    kind : {"rim", "rim-change", "face", "tread", "tread-slip"}
        A rim point landing from flight, the other rim edge of an upright disk, the face
        of a disk falling flat; entering line contact (:meth:`_Motion._line`): the residual
        rocking projected out (``"tread"``: impulse the vertical momentum removed, no
        friction), corner slips below ``v_capture`` stopped (``"tread-slip"``: tangential
        impulse ``P``, normal impulse ``sum |P_s|/mu``, inside Coulomb's cone).
    impulse : ndarray, shape (3,)
        ``(Lam_x, Lam_y, Lam_N)`` in Cxyz [``m sqrt(a g)``]; for a face impact the vertical
        momentum removed.
    energy_lost : float
        ``>= 0`` [``m g a``].
    restitution : float
        The ``e`` used (0 where the Zeno rule captured the bounce).
    """

    t: float
    kind: str
    impulse: np.ndarray
    energy_lost: float
    restitution: float

    def as_dict(self) -> dict:
        """``{"t", "kind", "impulse", "energy_lost", "restitution"}`` (JSON-ready)."""
        return {"t": float(self.t), "kind": self.kind,
                "impulse": [float(x) for x in self.impulse],
                "energy_lost": float(self.energy_lost), "restitution": float(self.restitution)}

    def __repr__(self) -> str:
        return (f"ImpactRecord(t={self.t:.6g}, kind={self.kind!r}, "
                f"Lam_N={self.impulse[2]:.4g}, energy_lost={self.energy_lost:.4g})")


@dataclass(frozen=True, eq=False)
class FlightSegment:
    """Free flight from ``t0`` to ``t1``: closed form (:func:`free_flight`).

    Attributes
    ----------
    disk : Disk
    t0, t1 : float
    state0, state1 : ndarray, shape (12,)
        Free-body states (:data:`~rollingdisk.phases.flight.FREE_STATE`) at both ends.
    """

    disk: Disk
    t0: float
    t1: float
    state0: np.ndarray
    state1: np.ndarray

    def state(self, t):
        """Free-body state(s) at time(s) ``t`` in ``[t0, t1]``."""
        return free_flight(self.disk, self.state0, np.asarray(t, dtype=float) - self.t0)

    def __repr__(self) -> str:
        return f"FlightSegment(t=[{self.t0:.6g}, {self.t1:.6g}])"


@dataclass(frozen=True, eq=False)
class FlatSegment:
    """The disk lying on a face, sliding and spinning with Coulomb friction.

    Attributes
    ----------
    t : ndarray
        Times [``sqrt(a/g)``].
    speed, spin : ndarray
        ``|V|`` of the centre [``sqrt(a g)``] and ``|Omega|`` about the vertical
        [``sqrt(g/a)``]; both reach 0 at the same time (uniform pressure).
    dissipated : ndarray
        Energy dissipated by friction since the start of the segment [``m g a``].
    state0, state1 : ndarray, shape (12,)
        Free-body states at both ends (``theta = +-pi/2``, ``Z_C = h``).
    face : int
        ``+1``: the axis eta points up (heads), ``-1`` down (tails).
    """

    t: np.ndarray
    speed: np.ndarray
    spin: np.ndarray
    dissipated: np.ndarray
    state0: np.ndarray
    state1: np.ndarray
    face: int

    def __repr__(self) -> str:
        return (f"FlatSegment(t=[{self.t[0]:.6g}, {self.t[-1]:.6g}], face={self.face:+d}, "
                f"dissipated={self.dissipated[-1]:.4g})")


@dataclass(frozen=True, eq=False)
class MotionResult:
    """A motion run through every phase (:func:`simulate_to_rest`).

    Attributes
    ----------
    disk : Disk
    ground : Coulomb
    segments : tuple
        In time order: :class:`~rollingdisk.Trajectory` (contact on a rim edge),
        :class:`FlightSegment`, :class:`FlatSegment`,
        :class:`~rollingdisk.phases.line_contact.LineSegment` (upright on the tread).
    transitions : tuple of ModeChange
        Every change of phase (rolling, sliding, flight, flat, rest), rolling/sliding
        changes inside contact segments included.
    impacts : tuple of ImpactRecord
    status : str
        An outcome name (:mod:`rollingdisk.model.outcomes`): ``"at-rest"``,
        ``"completed"`` (the end time, or the ``decide`` rule of :func:`toss`), a guard of
        ``stop_at``, ``"step-budget"`` (``max_segments`` spent), ``"time-budget"``
        (``max_wall`` spent) or
        ``"failed"``.
    message : str
    t_end : float
    final_state : ndarray, shape (12,)
        Free-body state at ``t_end``.
    energy_balance : float
        Largest ``|E + dissipated + impact losses - E(0)|`` along the run, relative to
        ``max(|E(0)|, 1)``.
    energy_initial : float
    dissipated : float
        Energy dissipated by friction and the contact moments [``m g a``].
    impact_loss : float
        Energy lost in impacts (and the Zeno captures) [``m g a``].
    """

    disk: Disk
    ground: Coulomb
    segments: tuple
    transitions: tuple
    impacts: tuple
    status: str
    message: str
    t_end: float
    final_state: np.ndarray
    energy_balance: float
    energy_initial: float
    dissipated: float
    impact_loss: float
    wall_time: float = field(default=math.nan)

    @property
    def energy_final(self) -> float:
        """Total energy at ``t_end`` [``m g a``]."""
        return _state_energy(self.disk.h, self.final_state)

    def __repr__(self) -> str:
        return (f"MotionResult(h={self.disk.h:g}, status={self.status!r}, "
                f"t_end={self.t_end:.6g}, segments={len(self.segments)}, "
                f"impacts={len(self.impacts)}, energy_balance={self.energy_balance:.2g})")



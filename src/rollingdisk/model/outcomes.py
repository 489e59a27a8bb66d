"""How a run ends: the one vocabulary of outcomes shared by every integrator, the exact
motions, the sweeps' status codes, Euler's disk and the command line's JSON.

Each outcome has an integer ``code`` (what the compiled kernels and the sweeps' datasets
store), a ``name`` (what a :class:`~rollingdisk.Trajectory`, an
:class:`~rollingdisk.ExactMotion`, a sweep's ``status_name`` and the JSON say) and a
``meaning`` in words.  The table is documented once, in ``docs/outcomes.md``; the guards
that produce the physical ends are in :mod:`rollingdisk.model.events`.
"""

from __future__ import annotations

from dataclasses import dataclass

__all__ = ["Outcome", "OUTCOMES", "outcome"]


@dataclass(frozen=True)
class Outcome:
    """One way a run can end.

    Attributes
    ----------
    code : int
        Integer code, stored by the compiled kernels and in sweep datasets (``status``).
    name : str
        The name used everywhere else (``Trajectory.status``, ``ExactMotion.status``, JSON).
    meaning : str
        What it means, in words.
    """

    code: int
    name: str
    meaning: str

    def __str__(self) -> str:
        return self.name


# integer codes, shared with the compiled integrators (numba reads them as globals)
RUNNING, COMPLETED, LIFT_OFF, EDGE_CONTACT, FELL_FLAT, FAILED, STEP_BUDGET = range(7)
BOUNDED, STEADY, AT_REST, NO_STEADY_MOTION, NOT_CONVERGED, TIME_BUDGET = 7, 8, 9, 10, 11, 12

#: Every outcome, by code.  ``running`` is the kernels' "not ended yet" and never a result.
OUTCOMES = (
    Outcome(RUNNING, "running", "still running (internal: never the status of a result)"),
    Outcome(COMPLETED, "completed", "reached the end time (or a terminal user event)"),
    Outcome(LIFT_OFF, "lift-off", "the normal force F_z reached zero (eq. 11): the disk "
            "would leave the plane"),
    Outcome(EDGE_CONTACT, "edge-contact", "theta reached 0 with h > 0: the disk stands "
            "upright on the line of its tread"),
    Outcome(FELL_FLAT, "fell-flat", "|theta| reached pi/2: the disk lies flat"),
    Outcome(FAILED, "failed", "the integrator gave up (the message says why)"),
    Outcome(STEP_BUDGET, "step-budget", "the step budget (max_steps) was spent before the "
            "end"),
    Outcome(BOUNDED, "bounded", "exact motion: theta oscillates between two turning "
            "points forever"),
    Outcome(STEADY, "steady", "exact motion: the state is a steady motion (theta "
            "constant)"),
    Outcome(AT_REST, "at-rest", "the disk came to rest"),
    Outcome(NO_STEADY_MOTION, "no-steady-motion", "a sweep's grid point where no steady "
            "motion has the parameters (e.g. Omega0^2 <= 0, eq. 31): nothing was integrated"),
    Outcome(NOT_CONVERGED, "not-converged", "exact motion: the quadrature did not reach its "
            "rounding floor within its work budget (theta-ODE steps, Fourier terms or "
            "wall-clock time); the message says which"),
    Outcome(TIME_BUDGET, "time-budget", "the wall-clock budget (max_wall_time) was spent "
            "before the end"),
)
_BY_NAME = {o.name: o for o in OUTCOMES}
_BY_CODE = {o.code: o for o in OUTCOMES}


def outcome(key: int | str) -> Outcome:
    """The :class:`Outcome` with code or name ``key``; ``ValueError`` if there is none."""
    found = _BY_CODE.get(key) if isinstance(key, int) and not isinstance(key, bool) \
        else _BY_NAME.get(key)
    if found is None:
        raise ValueError(f"no outcome {key!r}; known: {', '.join(_BY_NAME)}")
    return found


def names(*codes: int) -> tuple[str, ...]:
    """The names of the outcomes with ``codes``, in order."""
    return tuple(_BY_CODE[c].name for c in codes)

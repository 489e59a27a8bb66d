"""The engine's contract: what a model hands to the integrators, and what a run returns.

A model of any phase of motion is a :class:`Model`: its state layout (named components),
its right-hand side, its events (guards and mode switches), and where it has them its
impact map and its energy.  The integrators of :mod:`rollingdisk.engine.driver` take these
functions as explicit arguments (compiled with numba or run as plain Python, the same
functions either way), so a new phase needs no new step loop.  docs/architecture.md,
"Adding a model", states the contract in words; this module is its code.

The model's functions are plain Python on floats and float64 arrays (the numba-compilable
subset when they are to run compiled), with these fixed signatures (``n`` state
components, ``n_events`` events, ``p`` the model's parameter vector, float64, contiguous):

``rhs(t, y, p, out) -> None``
    Write ``dy/dt`` at time ``t`` and state ``y`` (shape ``(n,)``) into ``out`` (shape
    ``(n,)``).
``events(t, y, p, g) -> None``
    Write the ``n_events`` event functions into ``g`` (shape ``(n_events,)``).  Event ``k``
    occurs where ``g[k]`` changes sign in the sense of ``directions[k]``.
``impact(k, t, y, p, out) -> int``
    The state just after event ``k`` at ``(t, y)`` into ``out`` (shape ``(n,)``); returns
    :data:`CONTINUE` (0) to go on from ``(t, out)`` or the code of an outcome of
    :mod:`rollingdisk.model.outcomes` that ends the run there (e.g. ``AT_REST``).  It may
    update ``p`` (a mode switch).
``energy(t, y, p) -> float``
    The model's energy, evaluated by the driver before and after each event (not by the
    step loop).

Both the time ``t`` and the state carry the model's own units; the engine never scales.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np

from rollingdisk.util.errors import ParameterError, ParameterTypeError

__all__ = ["Model", "Solution", "RECORD", "TERMINAL", "IMPACT", "CONTINUE", "no_events",
           "no_impact"]

#: What an event does when it occurs (``Model.actions``): only recorded (the integration
#: goes on through it), ends the run (status ``completed``), or applies the impact map and
#: goes on from the state it returns.
RECORD, TERMINAL, IMPACT = 0, 1, 2
_ACTIONS = {"record": RECORD, "terminal": TERMINAL, "impact": IMPACT}

#: The value an impact map returns to let the run go on (the kernels' ``running``).
CONTINUE = 0


def no_events(t, y, p, g):
    """The event function of a model without events (writes nothing)."""
    return None


def no_impact(k, t, y, p, out):
    """The impact map of a model without one: the state unchanged, go on."""
    for i in range(y.shape[0]):
        out[i] = y[i]
    return 0


@dataclass(frozen=True)
class Model:
    """A phase of motion as the integrators take it: explicit functions, no globals.

    Parameters
    ----------
    name : str
        What the model is, for messages.
    state : tuple of str
        The names of the state components, in the order of the state vector (the state
        layout; :meth:`index` turns a name into its index).
    rhs : callable
        ``rhs(t, y, p, out)``: ``dy/dt`` into ``out`` (see the module docstring).
    events : callable, optional
        ``events(t, y, p, g)``: the event functions into ``g``; :func:`no_events` if the
        model has none.
    event_names : tuple of str
        One name per event function (their number is ``n_events``).
    directions : tuple of int
        Per event: ``-1`` occurs where ``g`` falls from ``> 0`` to ``<= 0``, ``+1`` where it
        rises from ``< 0`` to ``>= 0``, ``0`` either way (scipy's ``direction``).
    actions : tuple of str
        Per event: ``"record"``, ``"terminal"`` or ``"impact"`` (apply ``impact`` and go
        on).
    impact : callable, optional
        ``impact(k, t, y, p, out) -> int``: the state after event ``k``; needed if an
        action is ``"impact"``.
    energy : callable, optional
        ``energy(t, y, p) -> float``: evaluated before and after every event.
    helpers : tuple of callables
        Plain functions the model's functions call by global name: compiled with them
        (``numba.extending.register_jitable``) on the compiled path, plain calls otherwise.
    """

    name: str
    state: tuple
    rhs: Callable
    events: Callable = no_events
    event_names: tuple = ()
    directions: tuple = ()
    actions: tuple = ()
    impact: Callable = no_impact
    energy: Callable | None = None
    helpers: tuple = field(default=())

    def __post_init__(self):
        if not isinstance(self.state, tuple) or not self.state or not all(
                isinstance(s, str) for s in self.state):
            raise ParameterTypeError(f"state: a non-empty tuple of names, got {self.state!r}")
        if len(set(self.state)) != len(self.state):
            raise ParameterError(f"state: names must be distinct, got {self.state!r}")
        for name in ("rhs", "events", "impact"):
            if not callable(getattr(self, name)):
                raise ParameterTypeError(f"{name}: a function, got {getattr(self, name)!r}")
        n_ev = len(self.event_names)
        if len(self.directions) != n_ev or len(self.actions) != n_ev:
            raise ParameterError(
                f"directions and actions: one per event ({n_ev}: {self.event_names!r}), got "
                f"{len(self.directions)} and {len(self.actions)}")
        bad = [d for d in self.directions if d not in (-1, 0, 1)]
        if bad:
            raise ParameterError(f"directions: each -1, 0 or +1, got {bad!r}")
        bad = [a for a in self.actions if a not in _ACTIONS]
        if bad:
            raise ParameterError(f"actions: each one of {sorted(_ACTIONS)}, got {bad!r}")
        if "impact" in self.actions and self.impact is no_impact:
            raise ParameterError("impact: an event has the action 'impact' but the model "
                                 "has no impact map")

    @property
    def n_state(self) -> int:
        """The number of state components."""
        return len(self.state)

    @property
    def n_events(self) -> int:
        """The number of event functions."""
        return len(self.event_names)

    def index(self, name: str) -> int:
        """The index of the state component ``name``."""
        try:
            return self.state.index(name)
        except ValueError:
            raise ParameterError(f"name: one of {self.state!r}, got {name!r}") from None

    def direction_array(self) -> np.ndarray:
        """The directions as the step loop takes them (int64, shape ``(n_events,)``)."""
        return np.array(self.directions, dtype=np.int64).reshape(len(self.directions))

    def action_array(self) -> np.ndarray:
        """The actions as codes :data:`RECORD`, :data:`TERMINAL`, :data:`IMPACT` (int64)."""
        return np.array([_ACTIONS[a] for a in self.actions],
                        dtype=np.int64).reshape(len(self.actions))


@dataclass(frozen=True)
class Solution:
    """What :func:`rollingdisk.engine.driver.solve` returns.

    Attributes
    ----------
    t : ndarray, shape (m,)
        The start, the end of every accepted step and every event time (an event with an
        impact appears twice: the state before and the state after the map).
    y : ndarray, shape (m, n)
        The states at ``t``.
    event_t : ndarray, shape (k,)
        The times of the events that occurred, in order.
    event_index : ndarray of int, shape (k,)
        Which event function (its index in ``Model.event_names``).
    event_y : ndarray, shape (k, n)
        The state at each event, located on the dense output (before an impact map).
    event_y_after : ndarray, shape (k, n)
        The state the run went on from (the impact map's, else ``event_y``).
    energy_before, energy_after : ndarray, shape (k,)
        ``Model.energy`` at ``event_y`` and at ``event_y_after`` (``nan`` without one).
    status : str
        The outcome (:mod:`rollingdisk.model.outcomes`): ``completed`` (the end time or a
        terminal event), ``step-budget``, ``failed``, or an impact map's outcome.
    message : str
        Why the run ended, in words.
    n_steps : int
        Accepted steps.
    n_rhs : int
        Evaluations of the right-hand side.
    compiled : bool
        Whether the step loop ran compiled.
    """

    t: np.ndarray
    y: np.ndarray
    event_t: np.ndarray
    event_index: np.ndarray
    event_y: np.ndarray
    event_y_after: np.ndarray
    energy_before: np.ndarray
    energy_after: np.ndarray
    status: str
    message: str
    n_steps: int
    n_rhs: int
    compiled: bool

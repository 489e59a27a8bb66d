"""Nonlinear simulation of the disk, stopped at the guard events (:mod:`.events`).

The equations of motion of :mod:`rollingdisk.model.equations` (eqs. 1, 2, 37, 38 on rough ground;
2, 8, 49 on smooth ground) are integrated from any initial state by :func:`simulate`, or from
a perturbed steady motion by :func:`simulate_steady`.  Two drivers take the same steps:
``method="dop853"``, rollingdisk's Dormand-Prince 8(5,3) with scipy's step size
control (:mod:`rollingdisk.engine.dop853`; uncompiled while the process has integrated
little, compiled by numba once it is worth loading, see :mod:`rollingdisk.engine.jit`;
``method="auto"``, the default, goes on with the Taylor method then), run in chunks of at
most about 0.05 s so that progress is reported and Ctrl-C (``KeyboardInterrupt``) or SIGTERM
(:class:`rollingdisk.util.files.Terminated`) surfaces between chunks; and ``method="scipy"``,
scipy's own ``DOP853`` stepped one step at a time.  Both locate the guards on the dense
output inside every step, count steps against ``max_steps`` (status ``"step-budget"``), call
``progress`` and can hand the output to a ``sink`` chunk by chunk instead of keeping it
(streaming a long run to disk with flat memory).

The result type is :class:`rollingdisk.results.trajectory.Trajectory`; measurements on it live in
:mod:`rollingdisk.results.measure`.
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Callable, Sequence

import numpy as np

from rollingdisk.engine.methods import check_method
from rollingdisk.model import events as _ev
from rollingdisk.model.disk import Disk, check_ground
from rollingdisk.model.equations import check_disk, energy, equations_of_motion
from rollingdisk.model.state import state_index, state_names
from rollingdisk.results.trajectory import Trajectory
from rollingdisk.util.checks import check_real, check_span, real_array
from rollingdisk.util.errors import ParameterError, ParameterTypeError

__all__ = ["DEFAULT_RTOL", "DEFAULT_ATOL", "DEFAULT_MAX_STEPS", "MAX_T", "simulate",
           "simulate_steady"]

#: Default relative tolerance: keeps the relative energy drift below 1e-9 over 1000 time
#: units of a perturbed steady motion (checked by the tests).
DEFAULT_RTOL = 1e-11
#: Default absolute tolerance.
DEFAULT_ATOL = 1e-12
#: Default step budget of :func:`simulate` (status ``"step-budget"`` when spent): about
#: a minute of the compiled integrator.
DEFAULT_MAX_STEPS = 10_000_000
#: Largest ``|t|`` accepted in ``t_span`` (beyond it the step budget, not the end time,
#: would decide where any run stops).
MAX_T = 1e9
_RTOL_MIN = 100 * np.finfo(float).eps
_METHODS = ("auto", "dop853", "taylor", "scipy")
_ERROR_CONTROL = ("full", "reduced")
_CHUNK_SECONDS = 0.05  # wall time of one compiled chunk (interrupts surface between them)


# ---------------------------------------------------------------------------- validation
def _check_state(disk: Disk, ground: str, y0) -> np.ndarray:
    names = state_names(ground)
    try:
        y = np.array(real_array("y0", y0), dtype=float)  # 10**400: a ParameterError
    except ParameterTypeError:
        raise ParameterError(f"y0 must be a sequence of {len(names)} real numbers "
                             f"({', '.join(names)}), got {y0!r}") from None
    if y.shape != (len(names),):
        raise ParameterError(f"y0 must have {len(names)} components on {ground} ground "
                             f"({', '.join(names)}), got shape {y.shape}")
    if not np.all(np.isfinite(y)):
        raise ParameterError(f"y0 must be finite, got {y.tolist()}")
    theta = y[names.index("theta")]
    if abs(theta) >= 0.5 * math.pi:
        raise ParameterError(f"theta in y0 must lie in (-pi/2, pi/2) (|theta| = pi/2: the "
                             f"disk lies flat), got {theta!r}")
    if disk.h > 0 and theta == 0.0:
        raise ParameterError("theta in y0 must be nonzero for a disk of finite thickness "
                             "(h > 0): at theta = 0 it stands on a line of its rim, outside "
                             "the model")
    with np.errstate(all="ignore"):
        ok = (np.all(np.isfinite(equations_of_motion(disk, ground)(0.0, y)))
              and np.isfinite(energy(disk, ground, y)))
    if not ok:
        raise ParameterError("y0 is too large: its energy or rate of change overflows "
                             f"floating point, got {y.tolist()}")
    return y


def _check_tolerances(rtol, atol):
    rtol = check_real("rtol", rtol)
    if not _RTOL_MIN <= rtol <= 1.0:
        raise ParameterError(f"rtol must lie in [{_RTOL_MIN:.3g}, 1] (100 times the machine "
                             f"epsilon up to 1), got {rtol!r}")
    atol = check_real("atol", atol, low=0.0, low_open=True)
    return rtol, atol


def _check_t_eval(t_eval, t0, t1):
    if t_eval is None:
        return None
    t_eval = real_array("t_eval", t_eval).ravel()
    if (t_eval.size == 0 or not np.all(np.isfinite(t_eval)) or np.any(np.diff(t_eval) < 0)
            or t_eval[0] < t0 or t_eval[-1] > t1):
        raise ParameterError("t_eval must be a non-empty increasing sequence of times within "
                             f"t_span = ({t0:g}, {t1:g})")
    return t_eval


def _atol_vector(ground, atol, error_control):
    """``atol`` per state component; ``inf`` (left out of the error norm, as in scipy) for
    the quadratures when only the reduced system is controlled."""
    names = state_names(ground)
    v = np.full(len(names), float(atol))
    if error_control == "reduced":
        for i, name in enumerate(names):
            if name not in ("theta", "omega1", "omega2", "omega3"):
                v[i] = math.inf
    return v


# ---------------------------------------------------------------------------- output
class _Output:
    """Collects the output points of a run, or hands them to ``sink`` chunk by chunk and
    keeps only the first and the last point."""

    def __init__(self, sink):
        self.sink = sink
        self.t, self.y = [], []
        self.first = self.last = None

    def add(self, t, y):  # t: (k,), y: (k, n)
        if len(t) == 0:
            return
        t = np.asarray(t, dtype=float)
        y = np.asarray(y, dtype=float)
        if self.sink is None:
            self.t.append(t)
            self.y.append(y)
            return
        if self.first is None:
            self.first = (t[:1].copy(), y[:1].copy())
        self.last = (t[-1:].copy(), y[-1:].copy())
        self.sink(t, y.T)

    def arrays(self, n):
        if self.sink is None:
            if not self.t:
                return np.empty(0), np.empty((n, 0))
            return np.concatenate(self.t), np.concatenate(self.y).T
        if self.first is None:
            return np.empty(0), np.empty((n, 0))
        if self.last[0][0] == self.first[0][0]:
            return self.first[0], self.first[1].T
        return (np.concatenate([self.first[0], self.last[0]]),
                np.concatenate([self.first[1], self.last[1]]).T)


def _finish(disk, ground, method, out, code, t_last, n_steps, n_rhs, wall, max_steps, t1,
            **extra):
    n = len(state_names(ground))
    ts, ys = out.arrays(n)
    status = _ev.STATUS_OF_CODE[int(code)]
    t_event = None
    if status == "completed":
        message = extra.pop("message", None) or (
            f"completed: integrated to t = {t_last:.12g} in {n_steps} steps")
    elif status == "step-budget":
        message = (f"step-budget: max_steps = {max_steps} steps taken, stopped at t = "
                   f"{t_last:.12g} before t = {t1:.12g}; raise max_steps or shorten t_span")
    elif status == "failed":
        message = extra.pop("message", None) or (
            f"failed: the step size fell below the round-off limit (or the first step came "
            f"out 0) at t = {t_last:.12g} (singular or overflowing right-hand side?)")
    else:
        t_event = float(t_last)
        message = _ev.event_message(int(code), t_event, disk.h)
    extra.pop("message", None)
    return Trajectory(disk=disk, ground=ground, t=ts, y=ys, status=status, message=message,
                      n_steps=int(n_steps), n_rhs=int(n_rhs), method=method, t_event=t_event,
                      wall_time=wall, **extra)


# ---------------------------------------------------------------------------- simulate
def simulate(disk: Disk, ground: str, t_span: Sequence[float], y0, *, method: str = "auto",
             rtol: float = DEFAULT_RTOL, atol: float = DEFAULT_ATOL,
             max_step: float = math.inf, first_step: float | None = None, t_eval=None,
             dense_output: bool = False, events=None, guards: bool = True,
             max_steps: int = DEFAULT_MAX_STEPS, error_control: str = "full",
             progress: Callable[[float], None] | None = None,
             sink: Callable[[np.ndarray, np.ndarray], None] | None = None) -> Trajectory:
    """Integrate the equations of motion from ``y0`` over ``t_span``, with guard events.

    Shaped like :func:`scipy.integrate.solve_ivp` (``t_span`` before ``y0``).  Implements
    eqs. (1), (2), (37), (38) on rough and (2), (8), (49) on smooth ground via
    :mod:`rollingdisk.model.equations`, and stops at the first guard event of
    :mod:`rollingdisk.model.events`: ``F_z <= 0`` (eq. 11), ``theta = 0`` for ``h > 0``,
    ``|theta| = pi/2``, located on the dense output inside every step.  Every option means
    the same for both methods.

    Parameters
    ----------
    disk : Disk
        The disk (only ``disk.h`` enters; the trajectory keeps the disk given).  A disk
        with a rounded rim (``rim_radius > 0``) is run by
        :func:`rollingdisk.ivp.rounded.simulate_rounded` (the engine's DOP853; ``rtol``,
        ``atol``, ``max_step``, ``max_steps`` only) and returns its
        :class:`~rollingdisk.ivp.rounded.RoundedTrajectory`.
    ground : {"rough", "smooth"}
        Rolling without slip, or sliding without friction.
    t_span : (t0, t1)
        Interval of integration, ``t1 > t0``, ``|t0|, |t1| <= MAX_T`` (1e9).
    y0 : array_like, shape (8,) or (10,)
        Initial state, layout of :data:`~rollingdisk.model.state.ROUGH_STATE` or
        :data:`~rollingdisk.model.state.SMOOTH_STATE`; finite, ``|theta| < pi/2`` and
        ``theta != 0`` if ``h > 0``, energy and rates of change finite.
    method : {"auto", "dop853", "taylor", "scipy"}
        The words of :mod:`rollingdisk.engine.methods`.
        ``"auto"`` (default): the fastest method the process has for the tolerance at
        equal accuracy (:func:`rollingdisk.engine.jit.auto_method`; docs/simulation.md
        has the measured table): ``"scipy"`` with user ``events``, ``"dop853"`` with
        ``dense_output`` or ``first_step`` or on smooth ground; otherwise the compiled
        Taylor method at ``1e-3`` times ``rtol`` and ``atol`` (its energy drift there is no
        larger than DOP853's at the tolerance asked for), which starts as
        uncompiled DOP853 while the process has no compiled code (``traj.method`` then
        says ``"dop853"`` or ``"dop853+taylor"``).
        ``"dop853"``: rollingdisk's DOP853, uncompiled until the work is worth the
        compiled code (:mod:`rollingdisk.engine.jit`: counted in steps, so the same run
        takes the same path on every machine), then compiled (numba); the same steps
        either way.  ``"taylor"``: a compiled
        Taylor-series method of order ``ceil(-ln(tol)/2) + 1``
        (:mod:`rollingdisk.engine.taylor`; fewer, longer steps than DOP853 at equal energy
        drift; compiled on first use, no ``dense_output``, no
        ``first_step``; ``n_rhs`` counts its series, one per step).
        ``"scipy"``: scipy's ``DOP853`` stepped on the numpy right-hand side.
    rtol : float
        Relative tolerance, in ``[100 eps, 1]``.
    atol : float
        Absolute tolerance, ``> 0``.  The defaults keep the relative energy drift below
        1e-9 over 1000 time units of a perturbed steady motion.
    max_step : float
        Largest step, ``> 0``.
    first_step : float, optional
        Initial step, ``> 0``; chosen automatically by default.
    t_eval : array_like, optional
        Increasing times within ``t_span`` at which to store the state (from the dense
        output of DOP853); by default every accepted step is stored.  The event point, if
        a guard fires, is appended.
    dense_output : bool
        Keep the interpolant of every step: ``traj.sol(t)`` as ``solve_ivp``'s ``sol``.
    events : callable or list of callables, optional
        User events ``event(t, y)`` with optional ``terminal`` and ``direction``
        attributes, as in solve_ivp (scipy method only).  A terminal user event ends the
        run with status ``"completed"``; see ``t_events``/``y_events``.
    guards : bool
        Stop at the guard events (default).  ``False`` integrates blindly (for tests).
    max_steps : int
        Step budget: after this many steps the run stops with status ``"step-budget"``.
    error_control : {"full", "reduced"}
        Which components ``rtol`` and ``atol`` control.  ``"full"`` (default): the whole
        state, as ``solve_ivp``.  ``"reduced"``: only the reduced system ``(theta, omega1,
        omega2, omega3)`` (eq. 2 and eq. 38 / 49), which is autonomous and decides the
        energy, the contact force and the guards; ``X_C, Y_C, psi, phi`` (and ``V_X, V_Y``)
        are its quadratures, integrated through the same stages with their error left
        uncontrolled.  Fewer steps for the same energy drift (about 25 % fewer on a
        perturbed steady circle); positions then carry the error the reduced state
        passes on to them.
    progress : callable, optional
        ``progress(fraction)`` called as the run advances, at most about 100 times (after
        the first step past each hundredth of ``t_span``; the steps taken are the same).
    sink : callable, optional
        ``sink(t, y)`` receives the output in chunks (``t`` shape ``(k,)``, ``y`` shape
        ``(n_state, k)``) as the run advances, and the trajectory keeps only its first and
        last point: a long run streamed to disk takes flat memory.

    Returns
    -------
    Trajectory

    Raises
    ------
    ParameterTypeError
        If ``disk`` is not a :class:`Disk`.
    ParameterError
        For a state, interval, tolerance or option out of range (the message says which).

    Examples
    --------
    >>> from rollingdisk.results.measure import energy_drift
    >>> tr = simulate(Disk(h=0.1), "rough", (0, 10), [0, 0, 0, 0.3, 0, 0, 2.0, 0.5])
    >>> tr.status, bool(energy_drift(tr) < 1e-9)
    ('completed', True)
    """
    if isinstance(disk, Disk) and disk.rim_radius != 0.0:  # a rounded rim: ivp/rounded.py
        from rollingdisk.ivp.rounded import simulate_options

        return simulate_options(disk, ground, t_span, y0, method=method, rtol=rtol,
                                atol=atol, max_step=max_step, first_step=first_step,
                                t_eval=t_eval, dense_output=dense_output, events=events,
                                guards=guards, max_steps=max_steps,
                                error_control=error_control, progress=progress, sink=sink)
    check_disk(disk)
    ground = check_ground(ground)
    y = _check_state(disk, ground, y0)
    t0, t1 = check_span(t_span)
    if max(abs(t0), abs(t1)) > MAX_T:
        raise ParameterError(f"t_span must lie within [-{MAX_T:g}, {MAX_T:g}], got "
                             f"{t_span!r}")
    rtol, atol = _check_tolerances(rtol, atol)
    max_step = check_real("max_step", max_step, low=0.0, low_open=True) \
        if max_step != math.inf else math.inf
    first_step = None if first_step is None else check_real(
        "first_step", first_step, low=0.0, low_open=True)
    if isinstance(max_steps, bool) or not isinstance(max_steps, (int, np.integer)) \
            or max_steps < 1:
        raise ParameterError(f"max_steps must be an integer >= 1, got {max_steps!r}")
    method = check_method(method, _METHODS)
    if error_control not in _ERROR_CONTROL:
        raise ParameterError(f"error_control must be one of {_ERROR_CONTROL}, got "
                             f"{error_control!r}")
    for name, fn in (("progress", progress), ("sink", sink)):
        if fn is not None and not callable(fn):
            raise ParameterTypeError(f"{name} must be callable, got {fn!r}")
    t_eval = _check_t_eval(t_eval, t0, t1)
    if events is not None and callable(events):
        events = [events]
    if events is not None and len(events) == 0:
        events = None
    taylor_tol = None
    if method == "auto":
        from rollingdisk.engine.jit import auto_method

        method, t_rtol, t_atol = auto_method(ground, rtol, atol, events=events is not None,
                                             dense_output=bool(dense_output),
                                             first_step=first_step is not None)
        if method == "auto-taylor":
            taylor_tol = (t_rtol, _atol_vector(ground, t_atol, error_control))
    if method in ("dop853", "taylor") and events is not None:
        raise ParameterError(f"method={method!r} takes no user events; use method='scipy' "
                             "(or 'auto') for events")
    if method == "taylor" and dense_output:
        raise ParameterError("method='taylor' keeps no dense output; use method='dop853' "
                             "(or 'auto') with dense_output=True")
    if method == "taylor" and first_step is not None:
        raise ParameterError("method='taylor' chooses every step from the series; "
                             "first_step applies to 'dop853' and 'scipy'")
    use = [g for g in _ev.guard_events(disk, ground, y)] if guards else []
    from rollingdisk.ivp.drivers import run_compiled, run_scipy, run_taylor

    run = {"scipy": run_scipy, "dop853": run_compiled, "taylor": run_taylor}
    extra = {}
    if method == "auto-taylor":
        method, extra = "dop853", {"mode": "auto-taylor", "taylor_tol": taylor_tol}
    return run[method](disk, ground, y, t0, t1, rtol=rtol,
                       atol=_atol_vector(ground, atol, error_control), max_step=max_step,
                       first_step=first_step, t_eval=t_eval, dense_output=bool(dense_output),
                       events=events, guards=use, max_steps=int(max_steps),
                       progress=progress, out=_Output(sink), finish=_finish, **extra)


def simulate_steady(motion, t_end: float, *, perturb: float = 0.0, kick: float = 0.0,
                    psi0: float = 0.0, phi0: float = 0.0, **options) -> Trajectory:
    """Simulate from a steady motion, optionally with ``theta(0)`` or ``omega1(0)`` perturbed.

    Parameters
    ----------
    motion : SteadyMotion
        From :func:`rollingdisk.theory.steady.steady_motion` or
        :func:`~rollingdisk.theory.steady.straight_line`; its disk (with its physical scale, if it
        has one) is the trajectory's.
    t_end : float
        End time, ``0 < t_end <= MAX_T`` (the run starts at ``t = 0``); for a disk with a
        physical scale also a pint quantity or text with a unit (``"2 s"``), as ``kick``
        (``"0.1 rad/s"``) (:mod:`rollingdisk.model.inputs`).
    perturb : float
        Added to ``theta(0)``; all else stays at its steady value (eq. 36 with
        ``theta~(0) = perturb``, ``omega~_i(0) = 0``).  The linearized eq. (39) then has a
        constant right-hand side: the disk oscillates about a neighbouring steady motion.
    kick : float
        Added to ``omega1(0) = d theta/dt``: the oscillation stays centred on ``theta0``.
    psi0, phi0 : float
        Initial spin and rotation angles.
    **options
        Passed to :func:`simulate` (``rtol``, ``atol``, ``t_eval``, ``max_steps``, ...).

    Returns
    -------
    Trajectory
        With ``theta_ref = motion.theta0`` and ``motion`` set.

    Raises
    ------
    ParameterTypeError
        If ``motion`` is not a :class:`~rollingdisk.theory.steady.SteadyMotion`.
    """
    from rollingdisk.theory.steady import SteadyMotion

    if not isinstance(motion, SteadyMotion):
        raise ParameterTypeError(f"motion must be a SteadyMotion, got {type(motion).__name__}")
    disk = motion.disk
    if isinstance(t_end, str) or hasattr(t_end, "dimensionality"):
        t_end = disk.to_paper("time", t_end, "t_end")
    if isinstance(kick, str) or hasattr(kick, "dimensionality"):
        kick = disk.to_paper("angular_speed", kick, "kick")
    t_end = check_real("t_end", t_end, low=0.0, low_open=True)
    perturb = check_real("perturb", perturb)
    kick = check_real("kick", kick)
    i_theta = state_index(motion.ground, "theta")
    y0 = np.array(motion.initial_state(psi0, phi0), dtype=float)
    theta0 = float(y0[i_theta])
    theta = theta0 + perturb
    if abs(theta) >= 0.5 * math.pi or (disk.h > 0 and theta == 0.0):
        allowed = f"({-0.5 * math.pi - theta0:.6g}, {0.5 * math.pi - theta0:.6g})"
        if disk.h > 0:
            allowed += f" other than {-theta0:.6g} (theta = 0 is outside the model for h > 0)"
        raise ParameterError(f"perturb must lie in {allowed}, so that theta(0) = theta0 + "
                             f"perturb stays in (-pi/2, pi/2); got perturb = {perturb!r}, "
                             f"theta(0) = {theta!r}")
    y0[i_theta] = theta
    y0[state_index(motion.ground, "omega1")] += kick
    tr = simulate(disk, motion.ground, (0.0, t_end), y0, **options)
    return dataclasses.replace(tr, theta_ref=float(motion.theta0), motion=motion)
